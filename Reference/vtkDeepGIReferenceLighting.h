/**
 * @class   vtkDeepGIReferenceLighting
 * @brief   VTK 9.1's diffuse light model on the triangles a
 *          vtkDeepGIRayTracer hits: the radiance that leaves a hit
 *
 * The part of vtkDeepGIReferenceIrradiance that says what a scene point Y
 * sends back along a ray (its class description gives the equations):
 * the lights resolved to world space the way VTK 9.1 places them, the
 * scene's per-cell albedo (cell "Colors" times Diffuse) and emission, its
 * shading normals (point normals, else cell normals, else the winding
 * normal; flipped on back faces) and the direct diffuse radiance
 * L_direct(Y) = rho_Y sum_k color_k intensity_k a_k(Y) max(0, n_Y . l_k),
 * with optional shadow rays.
 *
 * Not a VTK class: a private helper of the module (no header installed).
 * Prepare() runs before the rays, the radiance queries are const and
 * thread-safe.
 */

#ifndef vtkDeepGIReferenceLighting_h
#define vtkDeepGIReferenceLighting_h

#include "vtkDeepGIRayTracer.h" // for HitRecord

#include <string> // for the reason a light is skipped
#include <vector> // for the tables

class vtkCamera;
class vtkLight;
class vtkObject;
class vtkPolyData;
class vtkRenderer;

class vtkDeepGIReferenceLighting
{
public:
  /// A light resolved to world space, with the parameters VTK 9.1's
  /// polydata shader uses (vtkOpenGLRenderer::UpdateLightingUniforms and
  /// the //VTK::Light::Impl code of vtkOpenGLPolyDataMapper).
  struct Light
  {
    double Position[3];
    double Direction[3]; // unit, from position towards focal point
    double Color[3];     // diffuse colour times intensity
    bool Positional;
    double Attenuation[3];
    bool Spot; // VTK applies the cone only below 90 degrees
    double CosCone;
    double Exponent;
  };

  /// How a light's position and focal point are obtained.
  enum class Placement
  {
    FollowCamera, // VTK's UpdateLightsGeometryToFollowCamera with `camera`
    AsStored      // the light's transformed position/focal point as they are
  };

  /// Resolves `light`; false with `why` set (empty: a switched-off light,
  /// silently ignored).
  static bool Resolve(
    vtkLight* light, vtkCamera* camera, Placement placement, Light& out, std::string& why);

  /// Replaces the lights with those VTK 9.1 renders `renderer` with;
  /// skipped lights are warnings of `reporter`.
  void SetLightsFromRenderer(vtkRenderer* renderer, vtkObject* reporter);

  /// The settings and the tables of Prepare(), read by the radiance queries.
  struct Settings
  {
    bool Shadows;
    bool TwoSidedLighting;
    double DiffuseCoefficient;
    const char* EmissionArrayName;
  };

  /**
   * Reads the albedo, emission and normal tables of `scene` (warnings of
   * `reporter` for unusable arrays, and when nothing sends light) and keeps
   * `tracer` for shadow rays.
   */
  void Prepare(vtkPolyData* scene, const Settings& settings, const vtkDeepGIRayTracer* tracer,
    vtkObject* reporter);

  /// Radiance leaving the hit reached along w towards -w: emitted plus
  /// direct diffuse (L_emitted + L_direct).
  void OutgoingRadiance(const double y[3], const double w[3],
    const vtkDeepGIRayTracer::HitRecord& hit, double radiance[3]) const;

  /// VTK's shading normal at the hit reached along w, flipped on back
  /// faces; false where the hit sends no light (a back face with one-sided
  /// lighting) or the interpolated normal vanishes.
  bool ShadingNormal(
    const double w[3], const vtkDeepGIRayTracer::HitRecord& hit, double n[3]) const;

  /// rho of scene cell `cell` (RGB, Diffuse included).
  const float* GetAlbedo(vtkIdType cell) const { return &this->CellAlbedo[3 * cell]; }

  /// Prints the lights.
  void Print(ostream& os, vtkIndent indent) const;

  std::vector<Light> Lights;

private:
  void DirectRadiance(const double y[3], const double w[3],
    const vtkDeepGIRayTracer::HitRecord& hit, double radiance[3]) const;
  void PrepareAlbedo(vtkPolyData* scene, vtkObject* reporter);
  void PrepareEmission(vtkPolyData* scene, vtkObject* reporter);
  void PrepareNormals(vtkPolyData* scene);

  Settings Current = { false, true, 1.0, nullptr };
  const vtkDeepGIRayTracer* Tracer = nullptr;
  std::vector<float> CellAlbedo;   // rho per scene cell (RGB), Diffuse included
  std::vector<float> CellEmission; // L_emitted per scene cell (RGB), empty if none
  std::vector<float> PointNormals; // per scene point (xyz), empty if none
  std::vector<float> CellNormals;  // per scene cell (xyz), empty if none
};

#endif
