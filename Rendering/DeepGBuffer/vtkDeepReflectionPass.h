/**
 * @class   vtkDeepReflectionPass
 * @brief   Screen-space mirror reflections traced through every layer of a deep G-buffer.
 *
 * Implements section 3.6 of Mara, McGuire, Nowrouzezahrai and Luebke, "Deep
 * G-Buffers for Stable Global Illumination Approximation" (HPG 2016). Put it
 * on a renderer (`renderer->SetPass(pass)`) and it renders the whole frame:
 * camera, lights, the opaque props into the layers of an internal
 * vtkDeepGBufferPass (GetGBufferPass(); SetGBufferPass() shares one), the
 * reflection rays, the composite, then the G-buffer pass's translucent,
 * volumetric and overlay steps (VTK's own by default).
 *
 * Which surfaces reflect, and how much, comes from VTK's material settings
 * through the G-buffer's optional REFLECTIVITY quantity (see
 * vtkDeepGBufferPass::SetWriteReflectivity): PBR props F0 (1 - roughness)^2,
 * F0 = mix(0.04, base colour, metallic); Phong/Gouraud/flat props
 * Specular x SpecularColor; unlit props 0. If no visible opaque prop can
 * reflect (PBR with Roughness 1 and no material texture, or Specular 0,
 * SpecularColor black or lighting off), no reflectivity is written and no
 * ray is traced: the frame is exactly vtkDeepGBufferPass's
 * (GetLastFrameTraced() is false).
 *
 * Rays (paper section 3.6). For each layer-0 pixel with reflectivity > 0:
 * X its camera-space point (from the DEPTH distance), n its normal (turned
 * to face the camera), v the view direction (X / |X|, or -z for a parallel
 * projection), r = reflect(v, n). The ray X + t r, t in (0, t_max], is
 * marched in camera space with a uniform step: t_max is MaximumDistance,
 * cut where the ray leaves the view frustum (solved exactly: the clip
 * coordinates are linear in t); the number of steps is
 * max(ceil(L / PixelStride), ceil(2 t_max |r.z| / dz)) clamped to
 * [1, NumberOfSteps], L the length in pixels of the ray's projection: a
 * step advances about PixelStride pixels on screen and at most dz / 2 in
 * depth (so no layer's band is stepped over), until the NumberOfSteps cap.
 * Each point Q is projected into the image; its distance s = -Q.z is compared
 * with every layer j of the G-buffer at Q's texel: a hit where
 * d_j <= s <= d_j + dz (dz = Thickness, by default the G-buffer's effective
 * minimum separation) and the surface faces the ray (n_j . r < 0, which
 * rejects the reflecting surface itself). Layers are tested in order, so
 * layer 0 wins where both qualify. After a hit, RefinementSteps bisections
 * between the last step without a hit and the hit locate the entry into
 * [d_j, d_j + dz]. The reflected radiance is that layer's RADIANCE at the
 * hit texel (mirror: outgoing = incoming radiance along r).
 *
 * Misses (the ray leaves the view frustum or reaches t_max without a hit)
 * take the environment, as VTK
 * defines it: the renderer's environment texture (vtkRenderer::
 * SetEnvironmentTexture) when set: a cube map, or an equirectangular 2D
 * texture (float textures keep their range) looked up like VTK's
 * image-based lighting: with w the world direction of r and the frame
 * (right, up, front = right x up) of the renderer's EnvironmentRight and
 * EnvironmentUp, e = (w.right, w.up, w.front), texture coordinate
 * (atan(e.z, e.x) / (2 pi) + 0.5, asin(e.y) / pi + 0.5); a cube map is
 * sampled along e. Without an environment texture, the background colour
 * (vtkViewport::GetBackground), or with GradientBackground on,
 * mix(Background, Background2, 0.5 + 0.5 r_y), r_y the camera-space up
 * component of r (VTK's gradient runs from Background at the bottom to
 * Background2 at the top).
 *
 * Composite (standalone use): where a ray was traced, layer 0's colour
 * becomes RADIANCE + REFLECTIVITY x L_r (floats, before the framebuffer's
 * rounding; the direct specular highlight of VTK's lights is already in
 * RADIANCE), alpha kept; elsewhere the resolved G-buffer image is left as
 * it is. It applies when the G-buffer displays RADIANCE.
 *
 * Textures (per renderer, the viewport's size; freed in frames that trace
 * nothing):
 * | texture   | format  | content                                          |
 * |-----------|---------|--------------------------------------------------|
 * | REFLECTED | RGBA16F | L_r (rgb, not weighted), a = 1 where traced       |
 * | HIT       | RG32F   | hit layer (-1: environment), hit distance t       |
 * Reads: the G-buffer's DEPTH, NORMAL, RADIANCE (all layers) and
 * REFLECTIVITY (layer 0), the environment texture. Writes: the renderer's
 * colour and depth. A composite pass adds REFLECTIVITY x REFLECTED; the
 * REFLECTED texture is reachable through ActivateReflectionTexture.
 *
 * Bad input never crashes: a non-finite or negative distance or thickness,
 * a step count outside 1..MAXIMUM_NUMBER_OF_STEPS and a non-positive pixel
 * stride are reported with vtkWarningMacro and replaced by the nearest
 * valid value. When the G-buffer is unsupported a warning is given once and
 * the plain VTK image is shown.
 *
 * Limitations: screen space only (what no layer holds cannot be
 * reflected); mirror reflections only (roughness only scales them); with
 * UseImageBasedLighting on, VTK's PBR shading already adds a prefiltered
 * environment reflection into RADIANCE, which this pass then adds again.
 *
 * @sa vtkDeepGBufferPass vtkDeepAmbientObscurancePass
 */

#ifndef vtkDeepReflectionPass_h
#define vtkDeepReflectionPass_h

#include "vtkDeepGIRenderingModule.h" // for export macro
#include "vtkDeepGISetGet.h"          // for vtkDeepGISetClampMacro
#include "vtkDeepScreenSpacePass.h"

#include <memory> // for std::unique_ptr

class vtkImageData;
struct vtkDeepReflectionRendererState;
class vtkRenderer;

class VTKDEEPGIRENDERING_EXPORT vtkDeepReflectionPass : public vtkDeepScreenSpacePass
{
public:
  static vtkDeepReflectionPass* New();
  vtkTypeMacro(vtkDeepReflectionPass, vtkDeepScreenSpacePass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Largest number of ray-march steps per pixel.
  static constexpr int MAXIMUM_NUMBER_OF_STEPS = 1024;

  ///@{
  /**
   * Longest reflection ray t_max, world units. Setting a value switches
   * AutomaticMaximumDistance off. NaN is rejected with a warning (the
   * previous setting stays); negative values are clamped to 0 with a
   * warning (every reflection then shows the environment); +infinity is
   * accepted: the ray is still cut where it leaves the view frustum.
   *
   * @unit world units
   * @range >= 0; NaN: warning, ignored; negative: warning, 0; +inf accepted
   * @default 1 (unused while automatic)
   */
  void SetMaximumDistance(double distance);
  vtkGetMacro(MaximumDistance, double);
  ///@}

  ///@{
  /**
   * When on (default), t_max is AutomaticDistanceFraction times the
   * diagonal of the bounds of the renderer's visible props, every frame.
   *
   * @range on/off
   * @default on
   */
  vtkSetMacro(AutomaticMaximumDistance, bool);
  vtkGetMacro(AutomaticMaximumDistance, bool);
  vtkBooleanMacro(AutomaticMaximumDistance, bool);
  ///@}

  ///@{
  /**
   * The fraction of the diagonal that gives the automatic t_max (default
   * 0.5, clamped to [0, 10]).
   *
   * @unit fraction of the diagonal
   * @range 0 to 10, clamped
   * @default 0.5
   */
  vtkDeepGISetClampMacro(AutomaticDistanceFraction, double, 0.0, 10.0);
  vtkGetMacro(AutomaticDistanceFraction, double);
  ///@}

  ///@{
  /**
   * Hit thickness dz, world units: a ray point at distance s hits layer j
   * where d_j <= s <= d_j + dz. Setting a value switches AutomaticThickness
   * off. NaN and infinities are rejected with a warning; negative values
   * are clamped to 0 with a warning.
   *
   * @unit world units
   * @range >= 0, finite; negative: warning, 0; NaN/inf: warning, ignored
   * @default 0 (unused while automatic)
   */
  void SetThickness(double thickness);
  vtkGetMacro(Thickness, double);
  ///@}

  ///@{
  /**
   * When on (default), dz is the G-buffer's EffectiveMinimumSeparation of
   * the frame (the paper's choice), or 0.5 % of the scene's diagonal if
   * that is 0.
   *
   * @range on/off
   * @default on
   */
  vtkSetMacro(AutomaticThickness, bool);
  vtkGetMacro(AutomaticThickness, bool);
  vtkBooleanMacro(AutomaticThickness, bool);
  ///@}

  ///@{
  /**
   * Most ray-march steps per pixel, 1 to MAXIMUM_NUMBER_OF_STEPS. Default
   * 64. Values outside are clamped with a warning.
   *
   * @unit steps
   * @range 1 to MAXIMUM_NUMBER_OF_STEPS (1024); outside: warning, clamp
   * @default 64
   */
  void SetNumberOfSteps(int steps);
  vtkGetMacro(NumberOfSteps, int);
  ///@}

  ///@{
  /**
   * Wanted screen-space length of a step, pixels (> 0, default 2): a ray
   * whose projection is L pixels long takes at least ceil(L / PixelStride)
   * steps (more where its depth changes faster than dz / 2 per step), at
   * most NumberOfSteps. Non-finite or non-positive values are refused
   * with a warning; values below 0.01 become 0.01, with a warning.
   *
   * @unit pixels
   * @range >= 0.01; <= 0 or non-finite: warning, ignored; below 0.01: warning, 0.01
   * @default 2
   */
  void SetPixelStride(double pixels);
  vtkGetMacro(PixelStride, double);
  ///@}

  ///@{
  /**
   * Bisection steps refining a hit (0 to 16, default 4).
   * They locate a hit's entry into the band.
   *
   * @unit bisections
   * @range 0 to 16, clamped
   * @default 4
   */
  vtkSetClampMacro(RefinementSteps, int, 0, 16);
  vtkGetMacro(RefinementSteps, int);
  ///@}

  /// The t_max used by the last frame (world units, before the frustum
  /// cut).
  ///
  /// @unit world units
  /// @readonly
  vtkGetMacro(EffectiveMaximumDistance, double);

  /// The dz used by the last frame (world units).
  ///
  /// @unit world units
  /// @readonly
  vtkGetMacro(EffectiveThickness, double);

  /// Whether the last frame traced rays (false when no visible prop reflects).
  ///
  /// @readonly
  vtkGetMacro(LastFrameTraced, bool);

  /**
   * Copies the reflections of the last frame rendered for `renderer` (the
   * first renderer the pass rendered if null) into `output`, an image of
   * the viewport's size, float point-data arrays: "ReflectedRadiance" (RGB,
   * L_r), "HitLayer" (-1: environment or not traced, else the layer hit),
   * "HitDistance" (t of the hit, world units, 0 where none),
   * "Reflectivity" (RGB, layer 0's) and unsigned char "Valid" (1 where a
   * ray was traced). Field data "MaximumDistance", "Thickness" and "Traced"
   * (0 or 1), and the camera as vtkDeepGBufferPass::CaptureLayers gives it
   * ("ViewMatrix", "ProjectionMatrix"). The render window's context must be
   * current (it is right after Render()). Returns false with an error when
   * there is nothing to capture.
   */
  bool CaptureReflections(vtkImageData* output, vtkRenderer* renderer = nullptr);

  ///@{
  /**
   * Access for composite passes: binds the REFLECTED texture (GL_TEXTURE_2D,
   * RGBA16F: L_r, alpha 1 where traced) of the last frame rendered for
   * `renderer` to a free texture unit and returns it (-1 if there is none,
   * e.g. when the last frame traced nothing). DeactivateReflectionTexture
   * releases the unit; GetReflectionTextureHandle gives the OpenGL name.
   */
  int ActivateReflectionTexture(vtkRenderer* renderer);
  void DeactivateReflectionTexture(vtkRenderer* renderer);
  unsigned int GetReflectionTextureHandle(vtkRenderer* renderer);
  ///@}

  /**
   * Whether a visible prop of `renderer` (actors, also inside assemblies,
   * with opaque geometry) has a material that gives a non-zero
   * REFLECTIVITY (see the class description). False for null.
   */
  static bool RendererReflects(vtkRenderer* renderer);

  /**
   * Traces this frame's reflection rays (the REFLECTED and HIT targets) for
   * the renderer of `s` from the layers GetGBufferPass() has just built,
   * without drawing into the renderer's framebuffer. Render() calls it
   * between RenderLayers and its composite; a pass that composites the
   * reflections itself (vtkDeepGIPass) turns the G-buffer's
   * WriteReflectivity on before the frame, calls this after
   * GetGBufferPass()->RenderLayers(s) returned true, then reads L_r with
   * ActivateReflectionTexture. Rays are traced only when the G-buffer wrote
   * REFLECTIVITY and a prop of the frame reflects; otherwise the targets
   * are freed and ActivateReflectionTexture returns -1. Returns false
   * (with an error) when the G-buffer has no layers for the renderer or
   * the targets, shaders or texture units are unavailable.
   */
  bool UpdateReflections(const vtkRenderState* s);

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  /// The memory of the textures this pass holds for all renderers, in bytes:
  /// the reflection targets. Proportional to the layers' pixels; 0 after
  /// ReleaseGraphicsResources.
  vtkTypeInt64 GetTextureBytes();

protected:
  vtkDeepReflectionPass();
  ~vtkDeepReflectionPass() override;

  /// The opaque step of the frame: layers, rays, composite.
  void RenderOpaque(const vtkRenderState* s) override;

  double MaximumDistance = 1.0;
  bool AutomaticMaximumDistance = true;
  double AutomaticDistanceFraction = 0.5;
  double Thickness = 0.0;
  bool AutomaticThickness = true;
  int NumberOfSteps = 64;
  double PixelStride = 2.0;
  int RefinementSteps = 4;
  double EffectiveMaximumDistance = 0.0;
  double EffectiveThickness = 0.0;
  bool LastFrameTraced = false;

private:
  vtkDeepReflectionPass(const vtkDeepReflectionPass&) = delete;
  void operator=(const vtkDeepReflectionPass&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;

  // The stages of UpdateReflections, in order (vtkTraceFrame carries what
  // one frame decided from stage to stage).
  struct vtkTraceFrame;
  void ComputeRayLimits(vtkTraceFrame& frame);
  void BindEnvironment(vtkTraceFrame& frame);
  bool PrepareTargets(const vtkTraceFrame& frame, vtkDeepReflectionRendererState& state);
  bool ActivateLayers(vtkTraceFrame& frame);
  void TraceRays(const vtkTraceFrame& frame, vtkDeepReflectionRendererState& state);
  void SetTraceUniforms(vtkShaderProgram* program, const vtkTraceFrame& frame);
  void DeactivateLayers(const vtkTraceFrame& frame);
};

#endif
