/**
 * @class   vtkDeepGIReferenceObscurance
 * @brief   ray-traced (Embree) ground truth of ambient visibility on the
 *          pixels of a deep G-buffer capture
 *
 * Given a capture made by vtkDeepGBufferPass::CaptureLayers (or built by
 * hand: point arrays "Depth_j", "Normal_j", "Valid_j" and field data
 * "ViewMatrix"/"ProjectionMatrix") and the scene's triangles in world
 * space, computes per pixel of layer `Layer` the ambient visibility that
 * the screen-space estimator of the paper (eq. 1-2) approximates, by Monte
 * Carlo ray casting against ALL the scene's triangles with Intel Embree.
 *
 * ## The quantity
 *
 * Let X be the surface point of the pixel (reconstructed in world space from
 * Depth_j and the matrices), n its unit normal (Normal_j, camera space,
 * rotated to world space), r = Radius, beta = Bias, eps = Epsilon. For a
 * direction w in the hemisphere around n, let t(w) be the distance to the
 * FIRST scene surface hit by the ray X + t w (t(w) = infinity if none) and
 * cos = w . n. Equation 2 evaluated on that first hit Y = X + t w is
 *
 *   O(w) = (1 - t^2 / r^2)_+ * max(0, (t cos - beta) / sqrt(t^2 + eps))
 *
 * ((x)_+ = max(0, x), so O = 0 when nothing is hit within r). The class
 * computes
 *
 *   Obscurance(X)        A(X) = (1 / pi) * integral_{hemisphere} O(w) dw
 *   AmbientVisibility(X) AV(X) = 1 - A(X)                    (in [0, 1])
 *
 * With beta = eps = 0 this is A = (1/pi) int (1 - t^2/r^2)_+ cos dw: the
 * cosine-weighted (projected-solid-angle) average of the falloff of the
 * first occluder within r. An unoccluded point has AV = 1 exactly, a point
 * whose whole hemisphere is blocked at t -> 0 has AV = 0.
 *
 * Estimator: directions are drawn with density cos / pi (cosine-weighted
 * hemisphere), so each sample contributes O(w) / cos in [0, 1]; A is the
 * mean over SamplesPerPixel samples and "StandardError" is the sample
 * standard deviation divided by sqrt(SamplesPerPixel). Samples are
 * independent (not stratified), so the reported standard error is an
 * honest estimate of the noise.
 *
 * ## Relation to the screen-space estimator (eq. 1-2) and where it differs
 *
 * Both measure the same thing: the cosine-weighted, (1 - d^2/r^2)-attenuated
 * occlusion of X by surface points Y within the world-space radius r, with
 * the same beta/eps regularisation (eq. 2 is literally the integrand above
 * evaluated at Y). By design the screen-space estimator differs:
 * - it samples Y in a screen-space disc (area measure on the screen), not
 *   directions in solid angle, so its sum is only proportional to A; the
 *   pi / N factor is its normalisation ("intensity") and the sqrt in
 *   eq. 1 is a contrast curve, not part of the integral. Compare
 *   max(0, 1 - sqrt(A * k)) against eq. 1 after calibrating k, or compare
 *   the linear A;
 * - it sees only the captured layers (union of layers 0 and 1, max() of
 *   the two layers' O) inside the view frustum: occluders hidden behind both
 *   layers, outside the image or back faces culled in layer 1 are missed
 *   (the reference sees every triangle);
 * - it assumes visibility between X and every sample Y (no first-hit test):
 *   a far occluder behind a near one still counts there, here only the
 *   first hit along each ray does;
 * - its depth and normals are quantised (Oct16 normals, float depth); the
 *   reference uses the same captured X and n so that the comparison is per
 *   pixel, but intersects exact triangles.
 *
 * ## Pipeline and implementation
 *
 * A vtkDeepGIReferenceSampledEstimator: the capture on input port 0, the
 * scene on port 1, Layer, RelativeOffset, SamplesPerPixel, Seed and the
 * statistics are those of vtkDeepGIReferenceEstimator and
 * vtkDeepGIReferenceSampledEstimator. Its vtkDeepGIRayTracer draws each
 * cosine-weighted direction from a counter-based hash of (Seed, pixel
 * index, sample index, dimension), so that results do not depend on the
 * number of threads or on scheduling.
 *
 * The output (after Update()) has the capture's grid and the point arrays
 * "AmbientVisibility" (float, AV in [0, 1]; -1 where the layer has no
 * surface), "Obscurance" (float, A = 1 - AV; -1 where empty),
 * "StandardError" (float, per-pixel Monte Carlo standard error of AV and of
 * A; 0 where empty) and "Valid" (unsigned char). The update fails with an
 * error of the estimator and an empty output (no points) when the capture
 * has no such layer arrays or matrices, the scene no polygons, or the
 * radius is invalid.
 *
 * Scale robustness: the triangles are stored relative to the centre of
 * their bounds (so float precision follows the scene's size, not its
 * position) and ray origins are offset along n by
 * RelativeOffset * (scene diagonal + |X - centre|).
 *
 * Typical use:
 * @code
 * vtkNew<vtkXMLImageDataReader> capture; // a capture saved as .vti
 * vtkNew<vtkDeepGIReferenceObscurance> reference;
 * reference->SetInputConnection(capture->GetOutputPort());
 * reference->SetSceneData(demoScene->GetScenePolyData());
 * reference->SetRadius(1.0);
 * reference->SetSamplesPerPixel(256);
 * reference->Update();
 * vtkImageData* av = reference->GetOutput();
 * double noise = reference->GetMeanStandardError();
 * @endcode
 *
 * @sa vtkDeepGIReferenceSampledEstimator vtkDeepGIRayTracer vtkDeepGIReferenceIrradiance
 */

#ifndef vtkDeepGIReferenceObscurance_h
#define vtkDeepGIReferenceObscurance_h

#include "vtkDeepGIReferenceModule.h" // for export macro
#include "vtkDeepGIReferenceSampledEstimator.h"
#include "vtkDeepGISetGet.h" // for vtkDeepGISetClampMacro

class VTKDEEPGIREFERENCE_EXPORT vtkDeepGIReferenceObscurance
  : public vtkDeepGIReferenceSampledEstimator
{
public:
  static vtkDeepGIReferenceObscurance* New();
  vtkTypeMacro(vtkDeepGIReferenceObscurance, vtkDeepGIReferenceSampledEstimator);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * r of eq. 2: occluders farther than r do not count. World units,
   * (0, VTK_DOUBLE_MAX]; default 1. The update fails with an error when it
   * is not a positive finite number (NaN, infinity, <= 0).
   *
   * @unit world units
   * @range (0, max], finite
   * @default 1
   */
  vtkSetMacro(Radius, double);
  vtkGetMacro(Radius, double);
  ///@}

  ///@{
  /**
   * beta of eq. 2 (world units, >= 0; default 0): subtracted from t cos,
   * ignores occluders close to the tangent plane. Set it to the
   * screen-space pass's value when comparing with it.
   *
   * @unit world units
   * @range >= 0, clamped
   * @default 0
   */
  vtkDeepGISetClampMacro(Bias, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Bias, double);
  ///@}

  ///@{
  /**
   * eps of eq. 2 (world units squared, >= 0; default 0): regularises
   * 1 / |v| for very near occluders.
   *
   * @unit world units^2
   * @range >= 0, clamped
   * @default 0
   */
  vtkDeepGISetClampMacro(Epsilon, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Epsilon, double);
  ///@}

protected:
  vtkDeepGIReferenceObscurance();
  ~vtkDeepGIReferenceObscurance() override;

  std::unique_ptr<vtkDeepGIRayTracer::Estimator> NewEstimator() override;

  double Radius;
  double Bias;
  double Epsilon;

private:
  vtkDeepGIReferenceObscurance(const vtkDeepGIReferenceObscurance&) = delete;
  void operator=(const vtkDeepGIReferenceObscurance&) = delete;

  struct Sampler;
};

#endif
