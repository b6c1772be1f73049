/**
 * @class   vtkDeepGIRayTracer
 * @brief   the Monte Carlo driver the reference estimators share: Intel
 *          Embree on a vtkPolyData, the pixels of one capture layer, the
 *          random numbers and the per-pixel statistics
 *
 * vtkDeepGIReferenceEstimator, the base of vtkDeepGIReferenceObscurance,
 * vtkDeepGIReferenceIrradiance and vtkDeepGIReferenceReflection, holds one
 * tracer and hands it the Estimator its subclass makes: what one sample of
 * one pixel is worth and where the pixel's result goes. Run() does the
 * rest:
 *
 * - reads layer `Layer` of the capture (point arrays Depth_j, Normal_j and
 *   optional Valid_j, field data ViewMatrix and ProjectionMatrix, named in
 *   vtkDeepGICaptureNames.h);
 * - builds the Embree scene from the polygons of the scene (fan-triangulated;
 *   rebuilt only when the vtkPolyData or its MTime changed), its points
 *   stored relative to the centre of their bounds so that float precision
 *   follows the scene's size, not its position;
 * - reconstructs per pixel the world-space surface point X and unit normal
 *   n, and the ray origin X + RelativeOffset * (scene diagonal +
 *   |X - centre|) * n (GetRayOffset) that keeps rays off their own surface;
 * - loops over the rows with vtkSMPTools, asks the estimator for
 *   GetNumberOfSamples() values of each pixel and hands it their mean and
 *   standard error (sample standard deviation / sqrt(samples));
 * - keeps the statistics of the run: valid pixels, rays, mean and maximum
 *   over valid pixels of the largest standard-error component (as stored,
 *   in float), wall time.
 *
 * Random(pixel, sample, dimension) is a counter-based hash of (Seed,
 * pixel, sample, dimension): results depend neither on the number of
 * threads nor on scheduling. Dimensions 0 and 1 of a sample are those of
 * its cosine-weighted ray from X (TraceCosineRay); an estimator that needs
 * more numbers per sample takes the next dimensions.
 *
 * The ray queries (TraceRay, IsOccluded, GetRayOffset, Random, the camera)
 * are thread-safe and valid from the estimator's Prepare() to the end of
 * Run(). The class is C++ only (not wrapped): its API passes structs.
 *
 * @sa vtkDeepGIReferenceEstimator vtkDeepGIReferenceObscurance
 *     vtkDeepGIReferenceIrradiance vtkDeepGIReferenceReflection
 */

#ifndef vtkDeepGIRayTracer_h
#define vtkDeepGIRayTracer_h

#include "vtkDeepGIReferenceModule.h" // for export macro
#include "vtkObject.h"

#include <memory> // for std::unique_ptr

class vtkImageData;
class vtkPolyData;

class VTKDEEPGIREFERENCE_EXPORT vtkDeepGIRayTracer : public vtkObject
{
public:
  static vtkDeepGIRayTracer* New();
  vtkTypeMacro(vtkDeepGIRayTracer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// A shading point of the capture: world-space position X, unit normal n
  /// (world space), the ray origin (X offset along n) and its pixel.
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

  /// How the rays leave the capture: the layer that provides X and n, the
  /// seed of Random() and the relative ray offset (see the class description).
  struct Sampling
  {
    int Layer;
    unsigned int Seed;
    double RelativeOffset;
  };

  /// What an estimator computes on the pixels; see Run().
  class Estimator
  {
  public:
    virtual ~Estimator() = default;

    /// Called once per Run() after the capture was read, the scene built
    /// and `output` given the capture's grid, before any ray: checks the
    /// estimator's parameters, reads what it needs from the capture and the
    /// scene and adds its arrays (one tuple per pixel) to `output`. False
    /// (after the estimator reported an error) stops Run().
    virtual bool Prepare(vtkImageData* capture, vtkPolyData* scene, vtkImageData* output) = 0;

    /// Values per sample.
    virtual int GetNumberOfComponents() const = 0;

    /// Samples per pixel (the rays that leave X, for the ray count).
    virtual int GetNumberOfSamples() const = 0;

    /// Writes the GetNumberOfComponents() values of sample `sample` at x.
    /// Called from several threads at once.
    virtual void EvaluateSample(const SurfacePoint& x, int sample, double* values) const = 0;

    /// Stores the mean and standard error of `pixel` (nullptrs: the layer
    /// has no surface there). Called from several threads at once, for
    /// distinct pixels.
    virtual void FinishPixel(vtkIdType pixel, const double* mean, const double* standardError) = 0;
  };

  /**
   * Estimates every pixel of layer `sampling.Layer` of `capture` against
   * the polygons of `scene` into `output`: the capture's extent, spacing
   * and origin, the estimator's arrays and "Valid" (unsigned char, 1 where
   * the layer has a surface). Returns false with an empty output and zero
   * statistics when the capture or the scene is unusable (an error of
   * `reporter`, the estimator, so that its observers see it) or the
   * estimator's Prepare() failed.
   */
  bool Run(vtkImageData* capture, vtkPolyData* scene, const Sampling& sampling,
    Estimator& estimator, vtkImageData* output, vtkObject* reporter);

  /// Closest hit along origin + t * direction (unit), 0 < t < tmax.
  bool TraceRay(
    const double origin[3], const double direction[3], double tmax, HitRecord& hit) const;

  /// Whether any triangle lies along origin + t * direction (unit),
  /// 0 < t < tmax (a shadow ray: any hit, not the closest).
  bool IsOccluded(const double origin[3], const double direction[3], double tmax) const;

  /// The self-intersection offset for a ray leaving `point`: RelativeOffset
  /// * (scene diagonal + |point - scene centre|).
  double GetRayOffset(const double point[3]) const;

  /// Uniform random number in [0, 1) for (pixel, sample, dimension); a
  /// counter-based hash of Seed and the three indices.
  double Random(vtkIdType pixel, int sample, int dimension) const;

  /// Unit direction about the unit normal n with density cos / pi from two
  /// uniform numbers in [0, 1) (Malley's method).
  static void CosineDirection(const double n[3], double u1, double u2, double w[3]);

  /// Sample `sample`'s cosine-weighted direction w about x's normal (random
  /// dimensions 0 and 1), traced from x.Origin up to tmax.
  void TraceCosineRay(
    const SurfacePoint& x, int sample, double tmax, double w[3], HitRecord& hit) const;

  /// Unit direction v of the capture's viewing ray through `point` (the
  /// view direction for a parallel projection); returns the distance from
  /// the eye along it.
  double ViewRay(const double point[3], double v[3]) const;

  ///@{
  /// Statistics of the last Run(): valid pixels, rays that left X (valid
  /// pixels times samples), mean and maximum over valid pixels of the
  /// largest standard-error component, wall time in seconds (scene build
  /// included). Zero after a failed Run().
  vtkIdType GetNumberOfValidPixels() const;
  vtkIdType GetNumberOfRays() const;
  double GetMeanStandardError() const;
  double GetMaximumStandardError() const;
  double GetComputeTime() const;
  ///@}

protected:
  vtkDeepGIRayTracer();
  ~vtkDeepGIRayTracer() override;

private:
  vtkDeepGIRayTracer(const vtkDeepGIRayTracer&) = delete;
  void operator=(const vtkDeepGIRayTracer&) = delete;

  struct CaptureLayer;
  struct PixelEstimate;
  bool ReadCapture(vtkImageData* capture, int layer, vtkObject* reporter);
  bool BuildScene(vtkPolyData* scene, vtkObject* reporter);
  void PrepareOutput(vtkImageData* capture, vtkImageData* output);
  void EstimateRows(Estimator& estimator, vtkImageData* output);
  bool ReconstructSurface(vtkIdType row, int col, SurfacePoint& x) const;
  void EstimatePixel(const Estimator& estimator, const SurfacePoint& x, PixelEstimate& e) const;
  void GatherStatistics(vtkImageData* output, int samples);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
