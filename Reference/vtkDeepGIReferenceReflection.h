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
 * A vtkDeepGIReferenceEstimator: the capture on input port 0, the scene on
 * port 1, Layer, RelativeOffset and the statistics are those of the base
 * (NumberOfRays: one mirror ray per valid pixel). Output point
 * arrays (the capture's grid): "Hit" (unsigned char: 1 where the ray hits a
 * triangle within MaximumDistance), "HitDistance" (float, |Y - X| for the
 * hit point Y, world units; 0 where none), "HitPosition" (float RGB: Y in
 * world coordinates; 0 where none), "MirrorDirection" (float, d in world
 * coordinates; 0 where empty), "Valid" and "StandardError" (0: the value is
 * exact). The update fails with an error of the estimator and an empty
 * output (no points) when the capture has no such layer arrays or matrices,
 * the scene no polygons, or MaximumDistance is invalid.
 *
 * @code
 * vtkNew<vtkDeepGIReferenceReflection> reference;
 * reference->SetInputData(capture); // vtkDeepGBufferPass::CaptureLayers
 * reference->SetSceneData(demoScene->GetScenePolyData());
 * reference->Update();
 * @endcode
 *
 * @sa vtkDeepGIReferenceEstimator vtkDeepGIRayTracer vtkDeepGIReferenceObscurance
 *     vtkDeepGIReferenceIrradiance
 */

#ifndef vtkDeepGIReferenceReflection_h
#define vtkDeepGIReferenceReflection_h

#include "vtkDeepGIReferenceEstimator.h"
#include "vtkDeepGIReferenceModule.h" // for export macro

class VTKDEEPGIREFERENCE_EXPORT vtkDeepGIReferenceReflection : public vtkDeepGIReferenceEstimator
{
public:
  static vtkDeepGIReferenceReflection* New();
  vtkTypeMacro(vtkDeepGIReferenceReflection, vtkDeepGIReferenceEstimator);
  void PrintSelf(ostream& os, vtkIndent indent) override;

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

protected:
  vtkDeepGIReferenceReflection();
  ~vtkDeepGIReferenceReflection() override;

  std::unique_ptr<vtkDeepGIRayTracer::Estimator> NewEstimator() override;

  double MaximumDistance;

private:
  vtkDeepGIReferenceReflection(const vtkDeepGIReferenceReflection&) = delete;
  void operator=(const vtkDeepGIReferenceReflection&) = delete;

  struct Sampler;
};

#endif
