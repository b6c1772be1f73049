/**
 * @class   vtkDeepGIReferenceIrradiance
 * @brief   ray-traced (Embree) ground truth of one- or multi-bounce
 *          diffuse indirect light on the pixels of a deep G-buffer capture
 *
 * The reference for the screen-space radiosity of the paper (section 3.2,
 * eq. 3-7): for the surface point X and normal n_X of each pixel of layer
 * `Layer` of a capture (vtkDeepGBufferPass::CaptureLayers, or built by hand
 * as for vtkDeepGIReferenceObscurance), it integrates the light that the
 * scene's directly lit diffuse surfaces send to X, by Monte Carlo ray casting
 * against ALL the scene's triangles (Intel Embree 3, through a
 * vtkDeepGIRayTracer: scene, pixels, random numbers and statistics as for
 * vtkDeepGIReferenceObscurance).
 *
 * ## Units and the quantity
 *
 * VTK's pixel colour is outgoing radiance. The direct diffuse radiance that
 * leaves a scene point Y (VTK's diffuse term, without ambient and specular) is
 *
 *   L_direct(Y) = rho_Y * sum_lights color_k * intensity_k * a_k(Y) * max(0, n_Y . l_k)
 *
 * with l_k the unit direction from Y to light k (minus the light's direction
 * for directional lights) and a_k VTK's positional attenuation
 * 1 / (c0 + c1 d + c2 d^2) times the spot factor (cos^Exponent inside
 * ConeAngle, 0 outside, only when ConeAngle < 90, as VTK 9.1's shader does);
 * a_k = 1 for directional lights. The albedo rho_Y is the hit triangle's
 * cell-data "Colors" (unsigned char scaled by 1/255; float or double taken as
 * they are; 1 component = grey; missing: white with a warning) times its
 * diffuse coefficient: cell-data "Diffuse" if the scene has it, else field
 * data "Diffuse", else DiffuseCoefficient. This is VTK's diffuseColor =
 * Diffuse * DiffuseColor, the value the G-buffer's Albedo_j stores.
 *
 * n_Y is the shading normal VTK would use: the scene's point normals
 * interpolated with the hit's barycentric weights and normalised, else its
 * cell normals, else the triangle's winding normal. Back faces: VTK 9.1's
 * OpenGL2 polydata shader flips the normal of every back-facing fragment
 * (gl_FrontFacing false; faces without normals are oriented towards the
 * viewer) whatever vtkRenderer::TwoSidedLighting says, so a back face is lit
 * like a front face with the flipped normal. With TwoSidedLighting on
 * (default) the reference does exactly that: a ray that hits a triangle from
 * behind sees n_Y flipped. With it off, a back face sends no light (L = 0),
 * the one-sided convention of the paper's optional n_Y test.
 *
 * ## Emitting surfaces
 *
 * A scene may carry the emitted radiance L_emitted of its triangles in a
 * cell array (EmissionArrayName, default "Emission"; RGB, or 1 component for
 * grey; float or double in the units of VTK's pixel colour, unsigned char
 * divided by 255 like "Colors"). That is what the G-buffer's
 * Radiance_j - Ambient_j holds on a prop marked vtkDeepGBufferPass::EMISSIVE()
 * beyond its diffuse term: VTK's ambient term Ambient * AmbientColor, which
 * the emitters of vtkDeepGISceneLoader (MTL Ke) draw as Ke / max(Ke).
 * A hit Y then leaves L(Y) = L_emitted(Y) + L_direct(Y). VTK 9.1 draws the
 * ambient term on both sides of a triangle (without a backface property the
 * back face uses the front's colours; measured in TestDeepGBufferEmissive:
 * RADIANCE - AMBIENT of an EMISSIVE panel's back face is its colour), so
 * with TwoSidedLighting on a back face emits like the front; with it off a
 * back face sends nothing, emission included. Without the array (or with
 * an empty name) nothing emits, silently. An array whose tuples do not
 * match the cells or whose component count is neither 1 nor 3 is ignored
 * with a warning; NaN, infinite and negative values are set to 0 with a
 * warning.
 *
 * Indirect irradiance at X, with Y(w) the first surface along X + t w:
 *
 *   E(X) = integral over the hemisphere of L(Y(w)) max(0, n_X . w) dw,
 *   L = L_emitted + L_direct
 *
 * (0 for rays that escape, and for hits farther than MaximumDistance from X
 * when it is finite). Directions are cosine-weighted (density cos / pi), so
 * each sample is pi * L(Y) and E is their mean; the reflected
 * one-bounce radiance is L_indirect(X) = rho_X * E(X) / pi with rho_X the
 * capture's Albedo_j (the diffuse BRDF rho / pi).
 *
 * ## Multiple bounces
 *
 * With NumberOfBounces k > 1 the radiance leaving a hit Y also carries the
 * light Y reflects after k - 1 bounces:
 *
 *   L_1(Y) = L_emitted(Y) + L_direct(Y)
 *   L_k(Y) = L_1(Y) + delta * rho_Y * E_{k-1}(Y) / pi
 *   E_k(X) = integral over the hemisphere of L_k(Y(w)) max(0, n_X . w) dw
 *
 * with delta = BounceDamping and E_{k-1}(Y) the same integral over the
 * hemisphere of Y's shading normal n_Y (flipped on back faces). E_1 is the
 * one-bounce irradiance above, and E_k = E_1 + delta K E_1 + ... +
 * delta^(k-1) K^(k-1) E_1 with K "reflect diffusely (rho / pi), then
 * gather": what vtkDeepRadiosityPass reaches after k still frames with
 * Damping delta and no colour boost (B_t(Y) = direct(Y) + delta
 * L_ind,t-1(Y), paper section 3.3); its converged result is k -> infinity.
 * Each E_{k-1}(Y) is estimated by diffuse path tracing: one cosine-weighted
 * continuation ray from Y per level and sample (random dimensions 2j and
 * 2j + 1 of the sample for the j-th continuation, so the result stays
 * independent of the thread count), so a sample is
 *
 *   pi (L_1(Y_1) + delta rho_1 L_1(Y_2) + delta^2 rho_1 rho_2 L_1(Y_3) + ...)
 *
 * and the standard error covers all bounces. A path ends where it escapes,
 * at a surface that sends no light (a back face with TwoSidedLighting off),
 * and where its continuation direction lies below the triangle of Y
 * (possible only where the shading normal departs from the triangle's).
 * MaximumDistance limits every segment of a path, not only the first: the
 * screen-space pass gathers each bounce within r around the surface that
 * receives it (the B(Y) it gathers at Y came itself from a gather within r
 * around Y), so with MaximumDistance = r both ignore light that travels
 * farther than r on any bounce.
 *
 * Shadows (default off): VTK's default rendering, and therefore the radiance
 * layers the screen-space pass gathers, has no shadows; with Shadows on a
 * shadow ray from Y to each light (to infinity for directional lights) must
 * be free for the light to count, which is physically right but no longer
 * what the screen-space input shows.
 *
 * ## Relation to the screen-space radiosity and where it differs
 *
 * This is eq. 3 of the paper with B(Y) / pi = L(Y): the paper's B is
 * radiosity, VTK's pixel is radiance L = B / pi, and eq. 6's reflected
 * B(X) = rho_X E(X) is the radiance rho_X E / pi (boost = 1). The screen-space
 * estimator (eq. 4-5) integrates the same E(X) from taps Y of the captured
 * layers, whose direct radiance is Radiance_j - Ambient_j (emission
 * included on EMISSIVE props). By design
 * it differs: it sees only the captured layers inside the frustum; it assumes
 * X and Y see each other (no first-hit test: a surface behind a nearer one
 * still counts there); the optional back-face test of eq. 5 drops taps with
 * n_Y . w >= 0 (compare with TwoSidedLighting off, where a back face sends no
 * light; with the test omitted a back-facing tap counts with its front-face
 * radiance, which neither setting reproduces); and it gathers only within a
 * world-space radius r: set MaximumDistance = r to remove that difference
 * (both then ignore light from farther than r), leave it infinite for the
 * true one-bounce irradiance.
 *
 * ## Pipeline and output
 *
 * A vtkDeepGIReferenceSampledEstimator: the capture on input port 0, the
 * scene on port 1, Layer (which also provides Albedo_j), RelativeOffset
 * (also for the rays from each hit of a path and the shadow rays),
 * SamplesPerPixel, Seed and the statistics are those of the base classes;
 * NumberOfRays counts the rays that leave X only. Output point
 * arrays (float, the capture's grid): "IndirectIrradiance" (RGB E, 0 where
 * the layer is empty), "IndirectIrradianceStandardError" (RGB),
 * "IndirectRadiance" and "IndirectRadianceStandardError" (RGB, rho_X E / pi;
 * only when the capture has Albedo_j, otherwise a warning) and "Valid".
 * GetMeanStandardError()/GetMaximumStandardError() use the largest of the
 * three irradiance standard errors per pixel. The update fails with an
 * error of the estimator and an empty output (no points) when the capture
 * has no such layer arrays or matrices, the scene no polygons, or
 * MaximumDistance is invalid.
 *
 * Typical use:
 * @code
 * vtkNew<vtkDeepGIReferenceIrradiance> reference;
 * reference->SetInputData(capture); // from vtkDeepGBufferPass::CaptureLayers
 * reference->SetSceneData(demoScene->GetScenePolyData()); // carries "Diffuse"
 * reference->SetLightsFromRenderer(renderer);
 * reference->SetSamplesPerPixel(256);
 * reference->Update();
 * vtkImageData* e = reference->GetOutput();
 * @endcode
 *
 * @sa vtkDeepGIReferenceSampledEstimator vtkDeepGIRayTracer vtkDeepGIReferenceObscurance
 *     vtkDeepGBufferPass
 */

#ifndef vtkDeepGIReferenceIrradiance_h
#define vtkDeepGIReferenceIrradiance_h

#include "vtkDeepGIReferenceModule.h" // for export macro
#include "vtkDeepGIReferenceSampledEstimator.h"
#include "vtkDeepGISetGet.h" // for vtkDeepGISetClampMacro

#include <memory> // for std::unique_ptr

class vtkCamera;
class vtkDeepGIReferenceLighting;
class vtkLight;
class vtkRenderer;

class VTKDEEPGIREFERENCE_EXPORT vtkDeepGIReferenceIrradiance
  : public vtkDeepGIReferenceSampledEstimator
{
public:
  static vtkDeepGIReferenceIrradiance* New();
  vtkTypeMacro(vtkDeepGIReferenceIrradiance, vtkDeepGIReferenceSampledEstimator);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Lights. The class keeps a copy of each light resolved to world space at
   * the time it is added (later changes to the vtkLight or the camera have
   * no effect until the lights are set again).
   *
   * SetLightsFromRenderer replaces the lights with the switched-on lights of
   * the renderer's vtkLightCollection, placed the way VTK 9.1 places them
   * for rendering: scene lights at their transformed position and focal
   * point; headlights at the active camera's position looking at its focal
   * point; camera lights through the camera's light transform (inverse view,
   * scaled by the camera distance, shifted by -1 along z). When the renderer's
   * LightFollowCamera is off, VTK does not move headlights and camera lights,
   * and neither does this. When no light is switched on and the renderer's
   * AutomaticLightCreation is on, VTK renders with an automatic white headlight
   * of intensity 1: it is added here too. A user light transform
   * (vtkOpenGLRenderer::SetUserLightTransform) is not applied.
   *
   * AddLight adds one light; headlights and camera lights are resolved with
   * `camera` (required for them: without it they are skipped with a warning).
   * Switched-off lights, and lights with non-finite values or a zero-length
   * direction, are skipped (the latter with a warning). Returns whether the
   * light was added.
   */
  void SetLightsFromRenderer(vtkRenderer* renderer);
  bool AddLight(vtkLight* light, vtkCamera* camera = nullptr);
  void RemoveAllLights();
  int GetNumberOfLights() const;
  ///@}

  ///@{
  /**
   * A resolved light (index in [0, GetNumberOfLights())): world position,
   * unit direction of the light (from position towards focal point), colour
   * times intensity, and whether it is positional. Out-of-range indices
   * return false.
   */
  bool GetLight(
    int index, double position[3], double direction[3], double color[3], bool& positional) const;
  ///@}

  /// What the update evaluates.
  enum QuantityType
  {
    INDIRECT_IRRADIANCE = 0,
    DIRECT_RADIANCE = 1
  };

  ///@{
  /**
   * INDIRECT_IRRADIANCE (default): the one-bounce quantities above.
   * DIRECT_RADIANCE: L = L_emitted + L_direct at each pixel's own surface
   * point as seen from the capture's camera (the ray from just in front of X
   * towards X gives the triangle, its emission, albedo and shading normal),
   * in the point array "DirectRadiance" (RGB; 0 where empty or where that ray
   * finds no triangle) with "Valid". One sample per pixel (the value is
   * exact, its standard error 0). It checks the light model against VTK's
   * rendering: a capture's Radiance_j - Ambient_j is VTK's diffuse (plus
   * specular) term, plus the ambient term on EMISSIVE props.
   *
   * @range INDIRECT_IRRADIANCE 0, DIRECT_RADIANCE 1; clamped
   * @default INDIRECT_IRRADIANCE
   */
  vtkSetClampMacro(Quantity, int, INDIRECT_IRRADIANCE, DIRECT_RADIANCE);
  vtkGetMacro(Quantity, int);
  void SetQuantityToIndirectIrradiance() { this->SetQuantity(INDIRECT_IRRADIANCE); }
  void SetQuantityToDirectRadiance() { this->SetQuantity(DIRECT_RADIANCE); }
  ///@}

  ///@{
  /**
   * Shadow rays from each hit point Y to each light. Default off (VTK's
   * default rendering, and so the screen-space input, has no shadows).
   *
   * @default off
   */
  vtkSetMacro(Shadows, bool);
  vtkGetMacro(Shadows, bool);
  vtkBooleanMacro(Shadows, bool);
  ///@}

  ///@{
  /**
   * Back faces hit by a ray are lit with the flipped normal (on, default:
   * what VTK 9.1's OpenGL2 renderer always does) or send no light (off).
   * With it on, back faces also emit like the front face; off, they send no light, emission
   * included.
   *
   * @default on
   */
  vtkSetMacro(TwoSidedLighting, bool);
  vtkGetMacro(TwoSidedLighting, bool);
  vtkBooleanMacro(TwoSidedLighting, bool);
  ///@}

  ///@{
  /**
   * Only surfaces within this distance of X count (world units; (0, inf];
   * default infinity: the full irradiance); with NumberOfBounces > 1 it
   * limits every segment of a path. Set it to the screen-space gather
   * radius r to compare with a gather limited to r.
   * The update fails with an error when it is NaN or not positive.
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
   * Bounces of light that reach X (see "Multiple bounces" in the class
   * description), [1, 16]; default 1: the one-bounce irradiance. Values
   * outside the range are clamped with a warning. The cost grows about
   * linearly with it (one continuation ray, plus shadow rays, per bounce);
   * NumberOfRays counts the rays that leave X only.
   * With k bounces the radiance leaving a hit is L_emitted + L_direct + delta rho E_{k-1} / pi,
   * E_{k-1} by diffuse path tracing (one continuation ray per bounce and sample).
   *
   * @unit bounces
   * @range [1, 16]; outside: clamped with a warning
   * @default 1
   */
  void SetNumberOfBounces(int bounces);
  vtkGetMacro(NumberOfBounces, int);
  ///@}

  ///@{
  /**
   * delta that multiplies each bounce beyond the first, the
   * vtkDeepRadiosityPass's Damping (paper section 3.3), [0, 1]; default 1
   * (undamped, the physical multi-bounce irradiance). Out-of-range values
   * are clamped and NaN is ignored, both with a warning. Has no effect with
   * NumberOfBounces 1.
   *
   * @range [0, 1]; outside: clamped with a warning; NaN: warning, ignored
   * @default 1
   */
  void SetBounceDamping(double delta);
  vtkGetMacro(BounceDamping, double);
  ///@}

  ///@{
  /**
   * Name of the scene's cell array of emitted radiance (see the class
   * description). Default "Emission"; nullptr or empty: nothing emits.
   * The array holds the emitted radiance L_emitted: RGB or 1 component (grey); float/double in
   * VTK's pixel-colour units (the Radiance - Ambient of an EMISSIVE prop), unsigned char divided by
   * 255. A hit leaves L_emitted + L_direct. A missing array means nothing emits (no warning); a
   * wrong tuple or component count: the array is ignored with a warning; NaN, infinite or negative
   * values: 0 with a warning.
   *
   * @default "Emission"
   */
  vtkSetStringMacro(EmissionArrayName);
  vtkGetStringMacro(EmissionArrayName);
  ///@}

  ///@{
  /**
   * Diffuse coefficient (VTK's vtkProperty::Diffuse) multiplied into the
   * "Colors" albedo when the scene carries no "Diffuse" cell or field array.
   * [0, 1]; default 1. The scene polydata of vtkDeepGIDemoScene and
   * vtkDeepGISceneLoader carry their actors' Diffuse as field data.
   * Those scenes carry their actors' 0.9.
   *
   * @range [0, 1], clamped
   * @default 1
   */
  vtkDeepGISetClampMacro(DiffuseCoefficient, double, 0.0, 1.0);
  vtkGetMacro(DiffuseCoefficient, double);
  ///@}

protected:
  vtkDeepGIReferenceIrradiance();
  ~vtkDeepGIReferenceIrradiance() override;

  std::unique_ptr<vtkDeepGIRayTracer::Estimator> NewEstimator() override;

  int Quantity;
  bool Shadows;
  bool TwoSidedLighting;
  double MaximumDistance;
  double DiffuseCoefficient;
  char* EmissionArrayName;
  int NumberOfBounces;
  double BounceDamping;

private:
  vtkDeepGIReferenceIrradiance(const vtkDeepGIReferenceIrradiance&) = delete;
  void operator=(const vtkDeepGIReferenceIrradiance&) = delete;

  struct Sampler;
  std::unique_ptr<vtkDeepGIReferenceLighting> Lighting;
};

#endif
