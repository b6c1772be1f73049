/**
 * @class   vtkDeepGIReferenceReflection
 * @brief   ray-traced (Embree) first hits of the mirror rays of a deep
 *          G-buffer capture: the ground truth of screen-space reflections
 *
 * For the surface point X and shading normal n of each pixel of layer
 * `Layer` of a capture (vtkDeepGBufferPass::CaptureLayers), the mirror ray
 * of section 3.6 of Mara et al. (HPG 2016), d = v - 2 (v . n) n with v the
 * unit direction from the capture's eye to X (the view direction for a
 * parallel projection), is traced against ALL the scene's triangles (Intel
 * Embree 3, through a vtkDeepGIRayTracer) from X (offset by RelativeOffset
 * along n) up to MaximumDistance. One ray per pixel: the result is exact for
 * the given X and n (n is the capture's decoded Oct16 normal, as the
 * screen-space pass uses it).
 *
 * A vtkImageAlgorithm: input port 0 is the capture (vtkImageData), input
 * port 1 the scene (vtkPolyData, world space; SetSceneData or
 * SetSceneConnection), as for vtkDeepGIReferenceObscurance. Output point
 * arrays (the capture's grid): "Hit" (unsigned char: 1 where the ray hits a
 * triangle within MaximumDistance), "HitDistance" (float, |Y - X| for the
 * hit point Y, world units; 0 where none), "HitPosition" (float RGB: Y in
 * world coordinates; 0 where none), "MirrorDirection" (float, d in world
 * coordinates; 0 where empty), "Valid" and "StandardError" (0: the value is
 * exact). The update fails with an error of the estimator and an empty
 * output (no points) when the capture has no such layer arrays or matrices,
 * the scene no polygons, or MaximumDistance is invalid; a missing input is
 * the executive's error.
 *
 * @code
 * vtkNew<vtkDeepGIReferenceReflection> reference;
 * reference->SetInputData(capture); // vtkDeepGBufferPass::CaptureLayers
 * reference->SetSceneData(demoScene->GetScenePolyData());
 * reference->Update();
 * @endcode
 *
 * @sa vtkDeepGIRayTracer vtkDeepGIReferenceObscurance vtkDeepGIReferenceIrradiance
 */

#ifndef vtkDeepGIReferenceReflection_h
#define vtkDeepGIReferenceReflection_h

#include "vtkDeepGIReferenceModule.h" // for export macro
#include "vtkDeepGISetGet.h"          // for vtkDeepGISetClampMacro
#include "vtkImageAlgorithm.h"
#include "vtkNew.h" // for the tracer

class vtkAlgorithmOutput;
class vtkDeepGIRayTracer;
class vtkPolyData;

class VTKDEEPGIREFERENCE_EXPORT vtkDeepGIReferenceReflection : public vtkImageAlgorithm
{
public:
  static vtkDeepGIReferenceReflection* New();
  vtkTypeMacro(vtkDeepGIReferenceReflection, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The scene on input port 1. Without one the update fails with an error.
  void SetSceneData(vtkPolyData* scene);
  void SetSceneConnection(vtkAlgorithmOutput* output);
  ///@}

  ///@{
  /**
   * Longest mirror ray (world units; (0, inf]; default infinity). Set it to
   * the reflection pass's maximum distance t_max to compare with a march
   * limited to it. The update fails with an error when it is NaN or not
   * positive.
   * The length is |Y - X|; the pass's t_max is its EffectiveMaximumDistance.
   *
   * @unit world units
   * @range (0, inf]
   * @default inf
   */
  vtkSetMacro(MaximumDistance, double);
  vtkGetMacro(MaximumDistance, double);
  ///@}

  ///@{
  /**
   * Which layer of the capture provides X and n, [0, 7]; default 0.
   *
   * @range 0..7, clamped
   * @default 0
   */
  vtkSetClampMacro(Layer, int, 0, 7);
  vtkGetMacro(Layer, int);
  ///@}

  ///@{
  /**
   * Mirror rays start at X + RelativeOffset * (scene diagonal +
   * |X - scene centre|) * n, off their own surface; dimensionless,
   * [0, 0.01]; default 1e-5.
   *
   * @range 0..0.01, clamped
   * @default 1e-5
   */
  vtkDeepGISetClampMacro(RelativeOffset, double, 0.0, 0.01);
  vtkGetMacro(RelativeOffset, double);
  ///@}

  ///@{
  /// Statistics of the last update: pixels with a surface, mirror rays
  /// traced, wall time in seconds (BVH build included).
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
  vtkDeepGIReferenceReflection();
  ~vtkDeepGIReferenceReflection() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  double MaximumDistance;
  int Layer;
  double RelativeOffset;

  vtkNew<vtkDeepGIRayTracer> Tracer;

private:
  vtkDeepGIReferenceReflection(const vtkDeepGIReferenceReflection&) = delete;
  void operator=(const vtkDeepGIReferenceReflection&) = delete;

  struct Sampler;
};

#endif
