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
 * Embree 3, through vtkDeepGIReferenceObscurance's scene and ray code) from
 * X (offset by the base class's RelativeOffset along n) up to
 * MaximumDistance. One ray per pixel: the result is exact for the given X
 * and n (n is the capture's decoded Oct16 normal, as the screen-space pass
 * uses it).
 *
 * Output point arrays (same dimensions as the capture): "Hit" (unsigned
 * char: 1 where the ray hits a triangle within MaximumDistance), "HitDistance"
 * (float, |Y - X| for the hit point Y, world units; 0 where none),
 * "HitPosition" (float RGB: Y in world coordinates; 0 where none),
 * "MirrorDirection" (float, d in world coordinates; 0 where empty), "Valid"
 * and "StandardError" (0: the value is exact). Radius, Bias, Epsilon and
 * SamplesPerPixel of the base class are not used.
 *
 * @code
 * vtkNew<vtkDeepGIReferenceReflection> reference;
 * reference->SetScene(demoScene->GetScenePolyData());
 * reference->Compute(capture); // vtkDeepGBufferPass::CaptureLayers
 * @endcode
 *
 * @sa vtkDeepGIReferenceObscurance vtkDeepGIReferenceIrradiance
 */

#ifndef vtkDeepGIReferenceReflection_h
#define vtkDeepGIReferenceReflection_h

#include "vtkDeepGIReferenceModule.h" // for export macro
#include "vtkDeepGIReferenceObscurance.h"

class VTKDEEPGIREFERENCE_EXPORT vtkDeepGIReferenceReflection : public vtkDeepGIReferenceObscurance
{
public:
  static vtkDeepGIReferenceReflection* New();
  vtkTypeMacro(vtkDeepGIReferenceReflection, vtkDeepGIReferenceObscurance);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Longest mirror ray (world units; (0, inf]; default infinity). Set it to
   * the reflection pass's maximum distance t_max to compare with a march
   * limited to it. Compute() fails with an error when it is NaN or not
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

  /// Values per pixel: hit (0 or 1), distance, hit position (3), direction (3).
  int GetNumberOfSampleComponents() const override { return 8; }
  void EvaluateSample(const SurfacePoint& x, const double direction[3], const HitRecord& hit,
    int sample, double* values) const override;
  void AllocateOutput(vtkImageData* output, vtkIdType pixels) override;
  void FinishPixel(vtkImageData* output, vtkIdType pixel, const double* mean,
    const double* standardError) override;
  /// 0: the base class's hemisphere ray is unused (EvaluateSample traces the mirror ray).
  double GetMaximumRayDistance() const override { return 0.0; }
  int GetNumberOfSamplesPerPixel() const override { return 1; }
  bool CheckParameters() override;
  bool PrepareCompute(vtkImageData* capture) override;

  double MaximumDistance;

private:
  vtkDeepGIReferenceReflection(const vtkDeepGIReferenceReflection&) = delete;
  void operator=(const vtkDeepGIReferenceReflection&) = delete;

  // The capture's camera, read by PrepareCompute.
  double Eye[3] = { 0, 0, 0 };
  double ViewDirection[3] = { 0, 0, -1 };
  bool Parallel = false;
};

#endif
