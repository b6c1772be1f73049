/**
 * @class   vtkDeepGIReferenceEstimator
 * @brief   abstract base of the ray-traced reference estimators: the
 *          capture and scene inputs, the layer, the ray offset, the
 *          statistics and the vtkDeepGIRayTracer that traces the rays
 *
 * A vtkImageAlgorithm: input port 0 is the capture (vtkImageData made by
 * vtkDeepGBufferPass::CaptureLayers, or built by hand: point arrays
 * "Depth_j", "Normal_j", "Valid_j" and field data "ViewMatrix"/
 * "ProjectionMatrix"), input port 1 the scene (vtkPolyData: all its
 * polygons, triangulated on the fly; lines and vertices ignored; world
 * space, the coordinates the capture was rendered with; SetSceneData or
 * SetSceneConnection).
 *
 * RequestData hands both inputs, Layer, RelativeOffset and the subclass's
 * random seed to the vtkDeepGIRayTracer, with the vtkDeepGIRayTracer::
 * Estimator the subclass makes (NewEstimator: what one sample of one pixel
 * is worth, and the subclass's output arrays). The tracer rebuilds the
 * Embree scene only when the vtkPolyData changed, reconstructs the surface
 * point X and normal n of each pixel of the layer and loops over the rows
 * with vtkSMPTools.
 *
 * The output (after Update()) has the capture's grid, the subclass's point
 * arrays and "Valid" (unsigned char). The update fails with an error of
 * the estimator and an empty output (no points) when the capture has no
 * such layer arrays or matrices, the scene no polygons, or a parameter of
 * the subclass is invalid; a missing input is the executive's error, as for
 * any VTK algorithm.
 *
 * Subclasses: vtkDeepGIReferenceReflection (one exact ray per pixel) and,
 * through vtkDeepGIReferenceSampledEstimator (Monte Carlo samples),
 * vtkDeepGIReferenceObscurance and vtkDeepGIReferenceIrradiance.
 *
 * @sa vtkDeepGIRayTracer vtkDeepGIReferenceSampledEstimator
 */

#ifndef vtkDeepGIReferenceEstimator_h
#define vtkDeepGIReferenceEstimator_h

#include "vtkDeepGIRayTracer.h"       // for vtkDeepGIRayTracer::Estimator
#include "vtkDeepGIReferenceModule.h" // for export macro
#include "vtkDeepGISetGet.h"          // for vtkDeepGISetClampMacro
#include "vtkImageAlgorithm.h"
#include "vtkNew.h" // for the tracer

#include <memory> // for std::unique_ptr

class vtkAlgorithmOutput;
class vtkPolyData;

class VTKDEEPGIREFERENCE_EXPORT vtkDeepGIReferenceEstimator : public vtkImageAlgorithm
{
public:
  vtkTypeMacro(vtkDeepGIReferenceEstimator, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The scene on input port 1 (see the class description). Without one the
   * update fails with an error.
   */
  void SetSceneData(vtkPolyData* scene);
  void SetSceneConnection(vtkAlgorithmOutput* output);
  ///@}

  ///@{
  /**
   * Which layer of the capture provides X and n (and the other arrays of
   * the layer an estimator reads, such as Albedo_j), [0, 7]; default 0.
   *
   * @range 0..7, clamped
   * @default 0
   */
  vtkSetClampMacro(Layer, int, 0, 7);
  vtkGetMacro(Layer, int);
  ///@}

  ///@{
  /**
   * Rays that leave a surface (from X, and the further rays an estimator
   * traces from its hits) start RelativeOffset * (scene diagonal +
   * |point - scene centre|) off it along its normal, to avoid
   * self-intersection; dimensionless, [0, 0.01]; default 1e-5.
   *
   * @range 0..0.01, clamped
   * @default 1e-5
   */
  vtkDeepGISetClampMacro(RelativeOffset, double, 0.0, 0.01);
  vtkGetMacro(RelativeOffset, double);
  ///@}

  ///@{
  /**
   * Statistics of the last update: pixels with a surface, rays that left X
   * (those pixels times the samples per pixel; continuation and shadow rays
   * not counted), wall time in seconds (BVH build included). Zero after a
   * failed update.
   */
  vtkIdType GetNumberOfValidPixels();
  vtkIdType GetNumberOfRays();
  double GetComputeTime();
  ///@}

  ///@{
  /**
   * @deprecated SetScene() is SetSceneData(), GetScene() the data on input
   * port 1 (removed in the next release).
   */
  void SetScene(vtkPolyData* scene) { this->SetSceneData(scene); }
  vtkPolyData* GetScene();
  ///@}

  /**
   * @deprecated Compute(capture) is SetInputData(capture) and Update();
   * returns whether the update succeeded (removed in the next release).
   */
  bool Compute(vtkImageData* capture);

protected:
  vtkDeepGIReferenceEstimator();
  ~vtkDeepGIReferenceEstimator() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  /**
   * The estimator's own work, which the tracer runs on the pixels of the
   * layer: one per update, made after the inputs were fetched (its
   * Prepare() checks the subclass's parameters).
   */
  virtual std::unique_ptr<vtkDeepGIRayTracer::Estimator> NewEstimator() = 0;

  /**
   * The seed of the tracer's random numbers (vtkDeepGIRayTracer::Random);
   * 0 for an estimator that draws none.
   */
  virtual unsigned int GetRandomSeed() { return 0; }

  int Layer;
  double RelativeOffset;

  vtkNew<vtkDeepGIRayTracer> Tracer;

private:
  vtkDeepGIReferenceEstimator(const vtkDeepGIReferenceEstimator&) = delete;
  void operator=(const vtkDeepGIReferenceEstimator&) = delete;
};

#endif
