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
 * ## Implementation and extension (one-bounce irradiance)
 *
 * Compute() rebuilds the Embree scene only when the vtkPolyData changed,
 * reconstructs X and n per pixel (ReconstructSurface), and loops over rows
 * with vtkSMPTools. For each pixel and sample the random numbers come from
 * a counter-based hash of (Seed, pixel index, sample index, dimension), so
 * results do not depend on the number of threads or on scheduling. Each
 * cosine-weighted direction is traced once (TraceRay) and handed, with its
 * hit, to the protected virtual EvaluateSample(), which returns
 * GetNumberOfSampleComponents() values; the driver accumulates their mean
 * and standard error and FinishPixel() turns them into output arrays.
 * vtkDeepGIReferenceIrradiance (one-bounce diffuse irradiance) overrides
 * these methods and the CheckParameters/PrepareCompute hooks: at the hit
 * (HitRecord gives the triangle id for the "Colors" albedo, the winding
 * normal, and the point ids and barycentric weights for point normals) it
 * traces shadow rays to the lights with IsOccluded and returns RGB values,
 * reusing scene, ray generation, threading and statistics unchanged.
 *
 * Scale robustness: the triangles are stored relative to the centre of
 * their bounds (so float precision follows the scene's size, not its
 * position) and ray origins are offset along n by
 * RelativeOffset * (scene diagonal + |X - centre|).
 *
 * Typical use:
 * @code
 * vtkNew<vtkDeepGIReferenceObscurance> reference;
 * reference->SetScene(demoScene->GetScenePolyData());
 * reference->SetRadius(1.0);
 * reference->SetSamplesPerPixel(256);
 * reference->Compute(capture); // from vtkDeepGBufferPass::CaptureLayers
 * vtkImageData* av = reference->GetOutput();
 * double noise = reference->GetMeanStandardError();
 * @endcode
 */

#ifndef vtkDeepGIReferenceObscurance_h
#define vtkDeepGIReferenceObscurance_h

#include "vtkDeepGIReferenceModule.h" // for export macro
#include "vtkDeepGISetGet.h"          // for vtkDeepGISetClampMacro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for ivars

#include <memory> // for std::unique_ptr

class vtkImageData;
class vtkPolyData;
class vtkUnsignedCharArray;

class VTKDEEPGIREFERENCE_EXPORT vtkDeepGIReferenceObscurance : public vtkObject
{
public:
  static vtkDeepGIReferenceObscurance* New();
  vtkTypeMacro(vtkDeepGIReferenceObscurance, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The scene: all its polygons (triangulated on the fly; lines, vertices
   * ignored), world space, the same coordinates the capture was rendered
   * with. Default nullptr (Compute() then fails with an error).
   *
   * @unit world units
   * @default null
   */
  void SetScene(vtkPolyData* scene);
  vtkPolyData* GetScene();
  ///@}

  ///@{
  /**
   * r of eq. 2: occluders farther than r do not count. World units,
   * (0, VTK_DOUBLE_MAX]; default 1. Compute() fails with an error when it
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

  ///@{
  /**
   * Monte Carlo samples (rays) per pixel, [1, 1048576]; default 256.
   * The noise (standard error) falls as 1 / sqrt(SamplesPerPixel).
   *
   * @unit rays
   * @range 1..1048576, clamped
   * @default 256
   */
  vtkSetClampMacro(SamplesPerPixel, int, 1, 1048576);
  vtkGetMacro(SamplesPerPixel, int);
  ///@}

  ///@{
  /**
   * Seed of the counter-based random sequence (any value; default 0). The
   * same seed, capture and scene give bit-identical results for any number
   * of threads.
   *
   * @range any
   * @default 0
   */
  vtkSetMacro(Seed, unsigned int);
  vtkGetMacro(Seed, unsigned int);
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
   * Ray origins are moved along n by RelativeOffset * (scene diagonal +
   * |X - scene centre|) to avoid self-intersection; dimensionless,
   * [0, 0.01]; default 1e-5.
   *
   * @range 0..0.01, clamped
   * @default 1e-5
   */
  vtkDeepGISetClampMacro(RelativeOffset, double, 0.0, 0.01);
  vtkGetMacro(RelativeOffset, double);
  ///@}

  /**
   * Computes the output for `capture`. Returns false with an error (and an
   * empty output) when the scene, capture, layer arrays or matrices are
   * missing or the radius is invalid.
   */
  bool Compute(vtkImageData* capture);

  /**
   * The result of the last Compute(): same dimensions as the capture, point
   * arrays "AmbientVisibility" (float, AV in [0, 1]; -1 where the layer has
   * no surface), "Obscurance" (float, A = 1 - AV; -1 where empty),
   * "StandardError" (float, per-pixel Monte Carlo standard error of AV and
   * of A; 0 where empty) and "Valid" (unsigned char).
   */
  vtkImageData* GetOutput();

  ///@{
  /**
   * Noise of the last Compute(): mean and maximum over valid pixels of the
   * per-pixel standard error (0 when no pixel was valid).
   */
  vtkGetMacro(MeanStandardError, double);
  vtkGetMacro(MaximumStandardError, double);
  ///@}

  ///@{
  /**
   * Statistics of the last Compute(): valid pixels, rays traced, wall time
   * in seconds (BVH build included).
   */
  vtkGetMacro(NumberOfValidPixels, vtkIdType);
  vtkGetMacro(NumberOfRays, vtkIdType);
  vtkGetMacro(ComputeTime, double);
  ///@}

protected:
  vtkDeepGIReferenceObscurance();
  ~vtkDeepGIReferenceObscurance() override;

  /// A shading point: world-space position, unit normal, offset origin.
  struct SurfacePoint
  {
    double Position[3];
    double Normal[3];
    double Origin[3];
    vtkIdType Pixel;
  };

  /// The first hit of a ray: distance from the origin, triangle (index into
  /// the scene's cells), unit geometric normal (world space, oriented by the
  /// triangle's winding: (p1 - p0) x (p2 - p0) of its fan triangle), the
  /// triangle's three scene point ids and the hit's barycentric weights of
  /// those points (for interpolating point data such as normals).
  struct HitRecord
  {
    bool Hit;
    double Distance;
    vtkIdType Cell;
    double Normal[3];
    vtkIdType PointIds[3];
    double Weights[3];
  };

  /// Closest hit along origin + t * direction (unit), 0 < t < tmax.
  /// Thread-safe; valid during Compute() only.
  bool TraceRay(
    const double origin[3], const double direction[3], double tmax, HitRecord& hit) const;

  /// Whether any triangle lies along origin + t * direction (unit),
  /// 0 < t < tmax (a shadow ray: any hit, not the closest). Thread-safe;
  /// valid during Compute() only.
  bool IsOccluded(const double origin[3], const double direction[3], double tmax) const;

  /// The self-intersection offset for a ray leaving `point`: RelativeOffset
  /// * (scene diagonal + |point - scene centre|). Valid during Compute() only.
  double GetRayOffset(const double point[3]) const;

  /// Checks the parameters before anything else; false (after an error)
  /// stops Compute(). Here: Radius must be positive and finite.
  virtual bool CheckParameters();

  /// Called once per Compute() after the capture was validated and the
  /// Embree scene built, before any ray: subclasses read what they need from
  /// the capture and the scene. False (after an error) stops Compute().
  virtual bool PrepareCompute(vtkImageData* capture);

  /// Output array whose per-pixel maximum over components is the pixel's
  /// standard error in GetMeanStandardError()/GetMaximumStandardError().
  virtual const char* GetStandardErrorArrayName() const { return "StandardError"; }

  /// Uniform random number in [0, 1) for (pixel, sample, dimension); a
  /// counter-based hash of Seed and the three indices.
  double Random(vtkIdType pixel, int sample, int dimension) const;

  /// Unit direction about the unit normal n with density cos / pi from two
  /// uniform numbers in [0, 1): the sampling of the rays from X.
  static void CosineDirection(const double n[3], double u1, double u2, double w[3]);

  /// Values EvaluateSample returns per sample (1 here: the obscurance).
  virtual int GetNumberOfSampleComponents() const { return 1; }

  /// Radiometric estimate of one cosine-weighted sample (direction w, its
  /// first hit within tmax = Radius) divided by the density cos / pi;
  /// writes GetNumberOfSampleComponents() values to `values`.
  virtual void EvaluateSample(const SurfacePoint& x, const double direction[3],
    const HitRecord& hit, int sample, double* values) const;

  /// Allocates the output arrays (called once per Compute).
  virtual void AllocateOutput(vtkImageData* output, vtkIdType pixels);

  /// Stores mean and standard error of a pixel (nullptrs for empty pixels).
  virtual void FinishPixel(
    vtkImageData* output, vtkIdType pixel, const double* mean, const double* standardError);

  /// Farthest distance a sample ray needs (Radius here).
  virtual double GetMaximumRayDistance() const { return this->Radius; }

  /// Samples Compute() takes per pixel (SamplesPerPixel here).
  virtual int GetNumberOfSamplesPerPixel() const { return this->SamplesPerPixel; }

  double Radius;
  double Bias;
  double Epsilon;
  int SamplesPerPixel;
  unsigned int Seed;
  int Layer;
  double RelativeOffset;

  double MeanStandardError;
  double MaximumStandardError;
  vtkIdType NumberOfValidPixels;
  vtkIdType NumberOfRays;
  double ComputeTime;

  vtkSmartPointer<vtkPolyData> Scene;
  vtkSmartPointer<vtkImageData> Output;

private:
  vtkDeepGIReferenceObscurance(const vtkDeepGIReferenceObscurance&) = delete;
  void operator=(const vtkDeepGIReferenceObscurance&) = delete;

  bool BuildScene();

  // The stages of Compute().
  struct CaptureLayer;
  struct PixelEstimate;
  void ResetResults();
  bool CheckInputs(vtkImageData* capture);
  bool ReadCapture(vtkImageData* capture, CaptureLayer& layer);
  vtkUnsignedCharArray* PrepareOutput(vtkImageData* capture, vtkIdType pixels);
  void EstimateRows(const CaptureLayer& layer, int spp, vtkUnsignedCharArray* valid);
  bool ReconstructSurface(const CaptureLayer& layer, vtkIdType row, int col, SurfacePoint& x) const;
  void EstimatePixel(const SurfacePoint& x, int spp, double tmax, PixelEstimate& estimate) const;
  void GatherStatistics(vtkUnsignedCharArray* valid, int spp);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
