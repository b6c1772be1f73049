/**
 * @class   vtkDeepGBufferPass
 * @brief   Layered deep G-buffer with minimum separation, built in one geometry pass.
 *
 * Implements section 2 of Mara, McGuire, Nowrouzezahrai and Luebke, "Deep
 * G-Buffers for Stable Global Illumination Approximation" (HPG 2016). Put it
 * on a renderer (`renderer->SetPass(pass)`) and it renders the whole frame:
 * camera, lights, the opaque props into a k-layer G-buffer, layer 0 resolved
 * into the renderer's framebuffer (colour and depth, exactly what VTK would
 * have drawn), then VTK's own translucent, volumetric and overlay steps.
 *
 * Layer 0 holds, per pixel, the nearest opaque surface. Layer j > 0 holds the
 * nearest surface that lies at least MinimumSeparation (dz, world units)
 * behind layer j - 1. The minimum separation skips local structure (mouldings,
 * decals, thin panels, coincident duplicate faces) so that layer 1 sees the
 * radiometrically relevant surface behind it (paper section 2, Figure 2).
 *
 * Oracles (paper Listing 2) predict layer j - 1's depth while layer j is built
 * in the same pass:
 * - DEPTH_PEEL: two (k) geometry passes, the exact reference (Listing 1).
 * - PREVIOUS: last frame's layer j - 1 at the same pixel.
 * - REPROJECT: the separation test is done in the previous frame,
 *   with each prop's previous model matrix and the previous camera.
 * - PREDICT: camera and prop motion extrapolated from the last two frames.
 * - DELAY: exact, at the price of one frame of latency for the opaque layers.
 * - AUTOMATIC (default): DEPTH_PEEL on a CPU renderer (Mesa llvmpipe or
 *   softpipe), REPROJECT elsewhere. On llvmpipe the geometry shader costs more
 *   than the second geometry pass it saves: two layers of a 70k-triangle
 *   bunny count 634 million instructions per frame peeled against 727
 *   through the geometry shader, which also runs in the one thread that
 *   processes vertices (Documentation/performance.md). GetEffectiveOracle()
 *   reports the oracle a frame used.
 * All but DEPTH_PEEL submit the geometry ONCE: a geometry shader emits each
 * triangle to every layer (gl_Layer) of 2D array render targets.
 *
 * Props whose primitives a triangle geometry shader cannot route (points,
 * lines, wireframe, surfaces with edges, mappers with their own geometry
 * shader) are drawn with the DEPTH_PEEL path inside the same frame, so every
 * opaque prop appears in every layer. The first frame, and any frame after a
 * resize or a change of layer count, has no history and uses DEPTH_PEEL.
 *
 * Textures, each a GL_TEXTURE_2D_ARRAY of the renderer's viewport size plus
 * the guard band (SetGuardBand) on every side (layers 0..k-1, plus one
 * oracle layer for PREDICT and DELAY):
 * | quantity  | format            | bytes/px | content                               |
 * |-----------|-------------------|----------|---------------------------------------|
 * | RADIANCE  | RGBA16F           | 8        | direct radiance under VTK's lights    |
 * | ALBEDO    | RGBA8             | 4        | diffuse albedo after VTK's colouring  |
 * | NORMAL    | RG8 (Oct16)       | 2        | camera-space normal, paper Table 1    |
 * | DEPTH     | R32F              | 4        | camera-space distance, 0 = empty      |
 * | AMBIENT   | R11F_G11F_B10F    | 4        | the ambient part of RADIANCE (0 for EMISSIVE props)
 * | | REFLECTIVITY | RGBA8 (optional) | 4      | mirror reflectance, only while requested | |
 * (z-test)  | DEPTH_COMPONENT32F| 4        | hardware depth per layer              | Reads: nothing
 * but the props. Writes: the renderer's colour and depth. ALBEDO's alpha is
 * the surface's facing: 1 on a front face, 0 on a back face.
 *
 * Bad input never crashes: a non-finite or negative separation, an
 * unsupported layer count or an OpenGL without geometry shaders or array
 * textures is reported once with vtkWarningMacro and replaced by a safe
 * value (automatic separation, a clamped count, plain VTK rendering).
 *
 * @sa vtkRenderStepsPass vtkSSAOPass
 */

#ifndef vtkDeepGBufferPass_h
#define vtkDeepGBufferPass_h

#include "vtkDeepGIRenderingModule.h" // for export macro
#include "vtkDeepGISetGet.h"          // for vtkDeepGISetClampMacro
#include "vtkDeepGIShaderConstants.h" // for the enum values shared with GLSL
#include "vtkOpenGLRenderPass.h"

#include <memory> // for std::unique_ptr

class vtkDeepGBufferLayerExchange;
class vtkDeepGIStageTimer;
class vtkImageData;
class vtkInformationIntegerKey;
class vtkOpenGLRenderWindow;
class vtkOpenGLRenderer;
class vtkRenderPass;
class vtkRenderer;
class vtkShadowMapPass;
struct vtkDeepGBufferRendererState;

class VTKDEEPGIRENDERING_EXPORT vtkDeepGBufferPass : public vtkOpenGLRenderPass
{
public:
  static vtkDeepGBufferPass* New();
  vtkTypeMacro(vtkDeepGBufferPass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The paper's oracles for layer j - 1's depth while layer j is built.
  enum OracleType
  {
    DEPTH_PEEL = 0,
    PREVIOUS = 1,
    REPROJECT = 2,
    PREDICT = 3,
    DELAY = 4,
    AUTOMATIC = 5
  };

  /// The per-layer quantities of the G-buffer.
  enum Quantity
  {
    RADIANCE = DEEP_QUANTITY_RADIANCE,
    ALBEDO = DEEP_QUANTITY_ALBEDO,
    NORMAL = DEEP_QUANTITY_NORMAL,
    DEPTH = DEEP_QUANTITY_DEPTH,
    AMBIENT = DEEP_QUANTITY_AMBIENT,
    /// optional: allocated and written only with WriteReflectivity on
    REFLECTIVITY = DEEP_QUANTITY_REFLECTIVITY,
    NUMBER_OF_QUANTITIES = DEEP_NUMBER_OF_QUANTITIES
  };

  /// The largest layer count this class supports (the GPU may allow fewer).
  static constexpr int MAXIMUM_NUMBER_OF_LAYERS = 8;

  /// The largest guard band, as a fraction of the viewport's height per side
  /// (and, at render time, of its smaller side: see ComputeGuardBandPixels).
  static constexpr double MAXIMUM_GUARD_BAND = 0.5;

  /// The largest guard band in pixels per side, whatever the frame's size.
  static constexpr int MAXIMUM_GUARD_BAND_PIXELS = 1024;

  /// The guard band in pixels is a multiple of this: 8, the block of MIP
  /// level 3 (Table 2's coarsest minimum level).
  static constexpr int GUARD_BAND_ALIGNMENT = 8;

  ///@{
  /**
   * Oracle used to build layers j > 0 (see the class description).
   * Default AUTOMATIC: DEPTH_PEEL on a CPU renderer, REPROJECT on a GPU.
   * It predicts layer j - 1's depth while layer j is built. Also SetOracleToDepthPeel(),
   * ...Previous(), ...Reproject(), ...Predict(), ...Delay(), ...Automatic(). PREDICT and DELAY
   * with more than 2 layers use REPROJECT (warning once).
   *
   * @type int (OracleType)
   * @range DEPTH_PEEL 0, PREVIOUS 1, REPROJECT 2, PREDICT 3, DELAY 4, AUTOMATIC 5; clamped
   * @default AUTOMATIC
   */
  vtkSetClampMacro(Oracle, int, DEPTH_PEEL, AUTOMATIC);
  vtkGetMacro(Oracle, int);
  void SetOracleToDepthPeel() { this->SetOracle(DEPTH_PEEL); }
  void SetOracleToPrevious() { this->SetOracle(PREVIOUS); }
  void SetOracleToReproject() { this->SetOracle(REPROJECT); }
  void SetOracleToPredict() { this->SetOracle(PREDICT); }
  void SetOracleToDelay() { this->SetOracle(DELAY); }
  void SetOracleToAutomatic() { this->SetOracle(AUTOMATIC); }
  static const char* GetOracleAsString(int oracle);
  /// Parses "DEPTH_PEEL", "PREVIOUS", ... (case-insensitive); -1 if unknown.
  static int GetOracleFromString(const char* name);
  ///@}

  ///@{
  /**
   * Number of layers k, 1 to MAXIMUM_NUMBER_OF_LAYERS. Default 2.
   * Values outside the range are clamped with a warning; at render time the
   * count is also limited by what the GPU's geometry shaders and array
   * textures allow. PREDICT and DELAY predict one layer; with k > 2 they
   * fall back to REPROJECT with a warning.
   * The GPU limits are reported once as a warning.
   *
   * @unit layers
   * @range 1 to MAXIMUM_NUMBER_OF_LAYERS (8); out of range: warning and clamp
   * @default 2
   */
  void SetNumberOfLayers(int layers);
  vtkGetMacro(NumberOfLayers, int);
  ///@}

  ///@{
  /**
   * Minimum separation dz between consecutive layers, in world units.
   * Setting a value switches AutomaticMinimumSeparation off. NaN and
   * infinities are rejected with a warning (the previous setting stays);
   * negative values are clamped to 0 with a warning (dz = 0 is classic depth
   * peeling). A dz larger than the scene leaves layers j > 0 empty; that is
   * reported once as a warning.
   *
   * @unit world units
   * @range >= 0, finite; negative: warning, 0 is used; NaN/inf: warning, ignored
   * @default 0 (unused while automatic)
   */
  void SetMinimumSeparation(double dz);
  vtkGetMacro(MinimumSeparation, double);
  ///@}

  ///@{
  /**
   * When on (default), dz is AutomaticSeparationFraction times the diagonal
   * of the bounds of the renderer's visible props, every frame, so it
   * follows the scene's scale.
   *
   * @range on/off (...On(), ...Off())
   * @default on
   */
  vtkSetMacro(AutomaticMinimumSeparation, bool);
  vtkGetMacro(AutomaticMinimumSeparation, bool);
  vtkBooleanMacro(AutomaticMinimumSeparation, bool);
  ///@}

  ///@{
  /**
   * The fraction of the diagonal that gives the automatic dz. The paper uses
   * dz = 0.5 m in scenes about 30-40 m across, i.e. about 1.5 % of their
   * size; the default fraction is 0.015.
   *
   * @unit fraction of the diagonal
   * @range 0 to 1, clamped
   * @default 0.015
   */
  vtkDeepGISetClampMacro(AutomaticSeparationFraction, double, 0.0, 1.0);
  vtkGetMacro(AutomaticSeparationFraction, double);
  ///@}

  ///@{
  /**
   * When on (default), layers j > 0 keep only front-facing surfaces. The
   * back faces of a closed object lie inside it: without culling, layer 1
   * behind a column is the column's own far side instead of the banner
   * behind it (paper Figure 2, the Sponza tapestry), unless dz exceeds the
   * column's thickness. Turn it off for open surfaces whose back faces are
   * seen (e.g. a cut-open iso-surface). Layer 0 always draws what VTK draws.
   * vtkDeepAmbientObscurancePass turns it off on the G-buffer it creates:
   * every surface occludes, and what layer 0 hides next to a closed object
   * is its back faces.
   *
   * @range on/off
   * @default on
   */
  vtkSetMacro(DeepLayerBackfaceCulling, bool);
  vtkGetMacro(DeepLayerBackfaceCulling, bool);
  vtkBooleanMacro(DeepLayerBackfaceCulling, bool);
  ///@}

  ///@{
  /**
   * When on, the G-buffer also stores REFLECTIVITY (RGBA8 per layer): the
   * mirror reflectance of each surface, from VTK's material settings.
   * PBR interpolation: F0 (1 - roughness)^2 with
   * F0 = mix(vec3(base F0), albedo, metallic), base F0 the property's
   * reflectance of the base layer (0.04 for VTK's default base IOR 1.5),
   * roughness and metallic after the material texture. Phong, Gouraud and
   * flat: Specular x SpecularColor (0 for unlit props). Off by default: the
   * texture, its draw buffer and the shader output exist only while a
   * consumer (vtkDeepReflectionPass) turns this on, so other users of the
   * G-buffer pay nothing. Turning it on or off rebuilds the props' shaders
   * once.
   *
   * @range on/off
   * @default off
   */
  void SetWriteReflectivity(bool write);
  vtkGetMacro(WriteReflectivity, bool);
  vtkBooleanMacro(WriteReflectivity, bool);
  ///@}

  ///@{
  /**
   * When on, the effects that read these layers (obscurance, radiosity)
   * shade only the texels where layer 0 holds a surface in their
   * full-screen stages: an early depth test against a coverage texture
   * their geometry key writes (4 bytes per texel) skips the background,
   * whose texels get the value the stage writes there (the same pixels as
   * with it off). On a CPU renderer this takes those stages' cost down
   * roughly in proportion to the frame's background; off is for
   * comparisons.
   *
   * @range on/off
   * @default on
   */
  vtkSetMacro(SkipBackgroundTexels, bool);
  vtkGetMacro(SkipBackgroundTexels, bool);
  vtkBooleanMacro(SkipBackgroundTexels, bool);
  ///@}

  ///@{
  /**
   * Guard band (paper section 3.5): the layers extend beyond the frame by
   * round(GuardBand x viewport height) pixels on each side, rounded up to a
   * multiple of GUARD_BAND_ALIGNMENT so that the frame keeps its alignment
   * to the rotated-grid MIP blocks the screen-space passes read (their
   * pixels whose taps stay inside the frame then get the result they have
   * without a guard band, up to MIP level 3), rasterised with
   * the camera's frustum widened to match (clip x and y scaled by
   * frame / (frame + 2 x band)), so the frame's pixels are exactly those of
   * the camera and the band holds what lies just outside the view. The
   * screen-space passes gather from the band (light and occluders just
   * off-screen) and keep history there, so results near the frame's edges
   * are stable under camera motion. The layers cost (1 + 2 b a)(1 + 2 b)
   * times the frame's pixels (b the fraction, a the height/width ratio);
   * 0.1 at 16:9 is 1.34x. Default 0 (the layers are the frame); the
   * G-buffers that vtkDeepRadiosityPass and vtkDeepGIPass create use 0.1.
   * 0 to MAXIMUM_GUARD_BAND: values outside are clamped and NaN ignored,
   * with a warning. At render time the band is bounded by what the frame
   * needs (ComputeGuardBandPixels: at most MAXIMUM_GUARD_BAND of the frame's
   * smaller side, so that a tall, narrow frame does not get layers many
   * times its size, at most MAXIMUM_GUARD_BAND_PIXELS, and layers within
   * the GPU's largest texture), with one warning per pass the first time
   * a limit applies. The resolved image, the depth buffer and CaptureLayers
   * are the frame's.
   * For example an 8 x 4000 frame with 0.5 gets 8 pixels, not 2000.
   *
   * @unit fraction of the viewport height, per side
   * @range 0 to MAXIMUM_GUARD_BAND (0.5); outside: warning and clamp; NaN: warning, ignored
   * @default 0 (0.1 in the G-buffers vtkDeepRadiosityPass and vtkDeepGIPass create)
   */
  void SetGuardBand(double fraction);
  vtkGetMacro(GuardBand, double);
  ///@}

  /// The guard band of the last rendered frame, in pixels on each side.
  /// 0 before the first frame.
  ///
  /// @unit pixels per side
  /// @readonly
  vtkGetMacro(EffectiveGuardBand, int);

  /**
   * The guard band in pixels on each side for a frame of width x height
   * pixels: round(fraction x height) (fraction clamped to [0,
   * MAXIMUM_GUARD_BAND], 0 if not finite) rounded up to a multiple of
   * GUARD_BAND_ALIGNMENT, and at most the smallest of
   * - round(MAXIMUM_GUARD_BAND x min(width, height)) rounded up to the
   *   alignment (an 8 x 4000 frame with 0.5 gets 8 pixels, not 2000: its
   *   layers are 24 x 4016, not 4008 x 8000),
   * - MAXIMUM_GUARD_BAND_PIXELS,
   * - what keeps the layers within maximumTextureSize (GL_MAX_TEXTURE_SIZE),
   *   rounded down to the alignment.
   * `limited` (if not null) tells whether one of these limits applied.
   */
  static int ComputeGuardBandPixels(
    double fraction, int width, int height, int maximumTextureSize, bool* limited = nullptr);

  /// The dz used by the last rendered frame (world units).
  /// 0 before the first frame.
  ///
  /// @unit world units
  /// @readonly
  vtkGetMacro(EffectiveMinimumSeparation, double);

  /// The layer count used by the last rendered frame (after GPU limits).
  /// 0 before the first frame.
  ///
  /// @unit layers
  /// @readonly
  vtkGetMacro(EffectiveNumberOfLayers, int);

  /// The oracle used by the last frame for its single-pass props; DEPTH_PEEL
  /// when the frame had no history (first frame, resize) or one layer.
  /// A layout change also leaves the frame without history.
  ///
  /// @readonly
  vtkGetMacro(EffectiveOracle, int);

  /// Number of geometry submissions of the opaque props in the last frame:
  /// 1 for the single-pass oracles, k for DEPTH_PEEL, 1 + k when some props
  /// also take the per-layer path.
  /// 0 before the first frame.
  ///
  /// @unit submissions
  /// @readonly
  vtkGetMacro(LastGeometryPassCount, int);

  ///@{
  /**
   * Debug display: the quantity the pass draws into the framebuffer.
   * Default RADIANCE, i.e. the normal image. DEPTH is shown as
   * distance normalised to the camera's clipping range (near black, far
   * white), NORMAL as n * 0.5 + 0.5. REFLECTIVITY is shown while it is
   * written (WriteReflectivity), RADIANCE otherwise.
   * Empty pixels keep the renderer's background.
   *
   * @type int (Quantity)
   * @range RADIANCE 0, ALBEDO 1, NORMAL 2, DEPTH 3, AMBIENT 4, REFLECTIVITY 5; clamped
   * @default RADIANCE
   */
  vtkSetClampMacro(DisplayQuantity, int, RADIANCE, REFLECTIVITY);
  vtkGetMacro(DisplayQuantity, int);
  static const char* GetQuantityAsString(int quantity);
  ///@}

  ///@{
  /**
   * Debug display: the layer the pass draws into the framebuffer (default
   * 0). At draw time it is limited to the rendered layers.
   *
   * @unit layer index
   * @range 0 to 7, clamped; at draw time limited to the rendered layers
   * @default 0
   */
  vtkSetClampMacro(DisplayLayer, int, 0, MAXIMUM_NUMBER_OF_LAYERS - 1);
  vtkGetMacro(DisplayLayer, int);
  ///@}

  /**
   * Copies the layers of the last frame rendered for `renderer` (the first
   * renderer the pass rendered if null) into `output`: one point-data array
   * per quantity per layer, named "Radiance_j" (RGBA float), "Albedo_j" (RGB
   * float), "Normal_j" (decoded camera-space normal, float), "Depth_j"
   * (camera-space distance, float, 0 where empty), "Ambient_j" (RGB float:
   * the part of Radiance_j that VTK's ambient term contributes, so that
   * Radiance_j - Ambient_j is the direct radiance from the lights),
   * "Reflectivity_j" (RGB float, only while WriteReflectivity is on) and
   * "Valid_j" (unsigned char, 1 where layer j has a surface). Field data "MinimumSeparation",
   * "NumberOfLayers" and "Oracle" describe the frame; "ViewMatrix" and
   * "ProjectionMatrix" (16 components, row-major) are its camera, so that
   * pixel (i, j) at NDC ((i + 0.5) / w * 2 - 1, (j + 0.5) / h * 2 - 1) and
   * its depth give a world-space position. The render window's
   * context must be current (it is right after Render()). Returns false with
   * an error when there is nothing to capture.
   */
  bool CaptureLayers(vtkImageData* output, vtkRenderer* renderer = nullptr);

  ///@{
  /**
   * Access for passes that consume the G-buffer: binds the GL_TEXTURE_2D_ARRAY
   * of a quantity of the last frame rendered for `renderer` to a free texture
   * unit and returns the unit (-1 if there is none). Release the unit with
   * DeactivateTexture. GetTextureHandle gives the raw OpenGL name (0 if none).
   */
  int ActivateTexture(vtkRenderer* renderer, int quantity);
  void DeactivateTexture(vtkRenderer* renderer, int quantity);
  unsigned int GetTextureHandle(vtkRenderer* renderer, int quantity);
  ///@}

  /**
   * Builds the G-buffer layers for the renderer of `s` without drawing into
   * the renderer's framebuffer. Render() calls it; composite passes call it
   * to get the layers and then draw their own result. Returns false (after
   * drawing the opaque props the plain way) when the G-buffer is unsupported.
   */
  bool RenderLayers(const vtkRenderState* s);

  /**
   * Keeps the layers of the last frame rendered for the renderer of `s` as
   * this frame's, instead of RenderLayers, when they were rendered at this
   * window size with this pass's current settings (its modification time).
   * The caller vouches for the rest of what the layers depend on: camera,
   * props and lights unchanged since that frame (vtkDeepGIPass::Converge
   * checks them). Returns false, touching nothing, when the layers cannot be
   * kept: none yet, released, another size, changed settings, picking, or
   * composited layers (SetLayerExchange).
   */
  bool ReuseLayers(const vtkRenderState* s);

  /**
   * When the renderer's layers were last rendered: a modification time that
   * changes with every frame that renders them and stays while frames keep
   * them (ReuseLayers); 0 while the renderer has none. What a consumer
   * derives from the layers alone (vtkDeepRadiosityPass's geometry keys)
   * stays valid while it stays the same.
   */
  vtkMTimeType GetLayersTime(vtkRenderer* renderer) const;

  /**
   * Draws the displayed quantity (layer 0 radiance by default) and that
   * layer's depth into the framebuffer and viewport bound for the renderer.
   */
  void ResolveToFramebuffer(const vtkRenderState* s);

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  /// The memory of the textures this pass holds for all renderers, in bytes:
  /// the layers (every quantity and the depth buffer) and the oracle's history. Proportional to the
  /// layers' pixels; 0 after ReleaseGraphicsResources.
  vtkTypeInt64 GetTextureBytes();

  /**
   * Renders a whole frame the way Render() does, through VTK's
   * vtkRenderStepsPass (camera and clear in the renderer's viewport, lights,
   * the opaque step, then the translucent, volumetric and overlay steps
   * set on this pass), with the opaque step delegated to
   * `opaqueStep` when it is not null. Passes that consume the G-buffer
   * (vtkDeepAmbientObscurancePass) call RenderLayers from their opaque step
   * and draw their own result. With null, the opaque step is RenderLayers
   * followed by ResolveToFramebuffer, i.e. Render(s).
   *
   * Anti-aliasing: the layers have one sample per pixel, so a window's
   * multisampling cannot smooth the edges they draw. When the renderer's
   * UseFXAA is on, or the window asks for multisampling (MultiSamples > 1,
   * VTK's default on screen), the frame applies VTK's FXAA
   * (vtkOpenGLFXAAFilter with the renderer's FXAAOptions) to the colour
   * after the volumetric step and before the overlay, as VTK's renderer
   * does; on a multisampled window it reads a resolved copy of the colour
   * (VTK 9.1's own UseFXAA on such a window gives a black image).
   * GetLastFrameAntiAliased() tells whether it did.
   */
  void RenderFrame(const vtkRenderState* s, vtkRenderPass* opaqueStep);

  /// Whether the last RenderFrame applied FXAA (see RenderFrame).
  vtkGetMacro(LastFrameAntiAliased, bool);

  /**
   * The camera the layers of the last frame rendered for `renderer` were
   * rasterised with (the current camera, or the previous one for DELAY):
   * view and projection matrices, row-major as vtkMatrix4x4 stores them.
   * Returns the number of layers of that frame, 0 (matrices untouched) if
   * no G-buffer has been rendered for `renderer`.
   */
  int GetLayerCamera(vtkRenderer* renderer, double view[16], double projection[16]);

  /**
   * The size in texels of the layers of the last frame rendered for
   * `renderer` (the frame plus the guard band on both sides) and the guard
   * band in pixels per side; the frame's pixel (x, y) is texel
   * (x + guardBand, y + guardBand), and GetLayerCamera's projection maps the
   * layers' texels to NDC. False (arguments untouched) if no G-buffer has
   * been rendered for `renderer`.
   */
  bool GetLayerExtent(vtkRenderer* renderer, int size[2], int& guardBand);

  /**
   * Information key for a prop's PropertyKeys (vtkProp::SetPropertyKeys):
   * 1 marks VTK's ambient term of the prop (Ambient x AmbientColor) as light
   * the surface emits, e.g. a lamp drawn with Ambient 1, AmbientColor the
   * lamp's colour and Diffuse 0. Such a prop's ambient stays in RADIANCE but
   * is left out of AMBIENT (0 there), so RADIANCE - AMBIENT includes the
   * emission: vtkDeepRadiosityPass gathers it as the surface's B(Y), and
   * vtkDeepAmbientObscurancePass does not darken it. Without the key (or
   * 0) the ambient term is the environment's light, as VTK's lighting
   * treats it. Read at every draw: no shader rebuild when it changes. The
   * key is vtkDeepGIKeys::EMISSIVE() (DeepGI::Core), so that scene content
   * can set it without depending on rendering.
   */
  static vtkInformationIntegerKey* EMISSIVE();

  ///@{
  /**
   * VTK's shadow maps in the G-buffer. With a vtkShadowMapPass set, every
   * frame first lets its vtkShadowMapBakerPass (GetShadowMapBakerPass())
   * update the shadow maps of the renderer's shadowing lights, then draws the
   * layers *through* the shadow pass: for that draw the shadow pass's opaque
   * sequence is the G-buffer's own layer drawing (the pass's
   * OpaqueSequence is restored afterwards), so VTK's shadow shader hooks and
   * the G-buffer's hooks are both on the props (the render state's
   * RenderPasses key) and every layer's RADIANCE holds the shadowed direct
   * light. AMBIENT is not shadowed (VTK's ambient term is not), so
   * RADIANCE - AMBIENT is the shadowed direct radiance that
   * vtkDeepRadiosityPass gathers as B(Y). Lights cast shadows as VTK decides
   * (vtkShadowMapBakerPass::LightCreatesShadow: scene lights that are
   * directional or spot lights with a cone angle below 90 degrees), with
   * their vtkLight::GetShadowAttenuation. Null (default): no shadows, and the
   * G-buffer is exactly what it is without this feature. The same shadow
   * pass must not also be in the renderer's own pass pipeline.
   * See Documentation/radiosity.md.
   *
   * @range any vtkShadowMapPass or null
   * @default null
   */
  void SetShadowMapPass(vtkShadowMapPass* pass);
  vtkGetObjectMacro(ShadowMapPass, vtkShadowMapPass);
  ///@}

  ///@{
  /**
   * A timer of every stage of the frames that use this G-buffer: its layers,
   * resolve and FXAA, and the stages of the effect passes sharing it (see
   * vtkDeepGIStageTimer, which serializes each stage with glFinish). Null
   * (default): nothing is timed.
   */
  void SetStageTimer(vtkDeepGIStageTimer* timer);
  vtkGetObjectMacro(StageTimer, vtkDeepGIStageTimer);
  ///@}

  ///@{
  /**
   * Distributed rendering: with an exchange set, the layers are drawn one
   * geometry pass each (the oracle is DEPTH_PEEL whatever Oracle says) and
   * each layer, once drawn, is composited across the processes by the
   * exchange before the next layer is peeled against it (see
   * vtkDeepGBufferLayerExchange). Every layer is exchanged, also on a
   * process with nothing to draw. Null (default): each process's layers
   * are its own.
   */
  void SetLayerExchange(vtkDeepGBufferLayerExchange* exchange);
  vtkGetObjectMacro(LayerExchange, vtkDeepGBufferLayerExchange);
  ///@}

  ///@{
  /// The step drawn after the opaque layers (default a vtkTranslucentPass).
  /// Set to null to skip it.
  ///
  /// @range any pass or null (skip)
  /// @default a vtkTranslucentPass
  void SetTranslucentPass(vtkRenderPass* pass);
  vtkGetObjectMacro(TranslucentPass, vtkRenderPass);
  ///@}

  ///@{
  /// The step drawn after the translucent step (default a
  /// vtkVolumetricPass). Set to null to skip it.
  ///
  /// @range any pass or null (skip)
  /// @default a vtkVolumetricPass
  void SetVolumetricPass(vtkRenderPass* pass);
  vtkGetObjectMacro(VolumetricPass, vtkRenderPass);
  ///@}

  ///@{
  /// The step drawn last (default a vtkOverlayPass). Set to null to skip it.
  ///
  /// @range any pass or null (skip)
  /// @default a vtkOverlayPass
  void SetOverlayPass(vtkRenderPass* pass);
  vtkGetObjectMacro(OverlayPass, vtkRenderPass);
  ///@}

  ///@{
  /**
   * Octahedral normal encoding with 8 bits per component (Oct16, Cigolle et
   * al. 2014, the paper's Table 1), the same arithmetic as the GLSL used by
   * the G-buffer. Encode writes two bytes; Decode reads them back into a unit
   * vector.
   */
  static void EncodeOct16(const double normal[3], unsigned char encoded[2]);
  static void DecodeOct16(const unsigned char encoded[2], double normal[3]);
  ///@}

  // vtkOpenGLRenderPass hooks: shader replacements and per-draw uniforms.
  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;
  vtkMTimeType GetShaderStageMTime() override;

protected:
  vtkDeepGBufferPass();
  ~vtkDeepGBufferPass() override;

  int Oracle = AUTOMATIC;
  int NumberOfLayers = 2;
  double MinimumSeparation = 0.0;
  bool AutomaticMinimumSeparation = true;
  double AutomaticSeparationFraction = 0.015;
  bool DeepLayerBackfaceCulling = true;
  bool SkipBackgroundTexels = true;
  bool WriteReflectivity = false;
  double GuardBand = 0.0;
  int DisplayQuantity = RADIANCE;
  int DisplayLayer = 0;

  double EffectiveMinimumSeparation = 0.0;
  int EffectiveNumberOfLayers = 0;
  int EffectiveOracle = DEPTH_PEEL;
  int EffectiveGuardBand = 0;
  int LastGeometryPassCount = 0;

  vtkRenderPass* TranslucentPass = nullptr;
  vtkRenderPass* VolumetricPass = nullptr;
  vtkRenderPass* OverlayPass = nullptr;
  bool LastFrameAntiAliased = false;
  void ApplyFXAA(vtkOpenGLRenderer* renderer);
  vtkShadowMapPass* ShadowMapPass = nullptr;
  vtkDeepGIStageTimer* StageTimer = nullptr;
  vtkDeepGBufferLayerExchange* LayerExchange = nullptr;

private:
  vtkDeepGBufferPass(const vtkDeepGBufferPass&) = delete;
  void operator=(const vtkDeepGBufferPass&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;

  // The stages of RenderLayers, in order (vtkLayerFrame carries what one
  // frame decided from stage to stage).
  struct vtkLayerFrame;
  bool BeginLayerFrame(const vtkRenderState* s, vtkLayerFrame& frame);
  void CheckContext(vtkOpenGLRenderWindow* window);
  void BakeShadowMaps(vtkLayerFrame& frame);
  void ChooseLayout(vtkLayerFrame& frame);
  bool PrepareRendererState(vtkLayerFrame& frame);
  void UpdateCameras(vtkLayerFrame& frame);
  void ClassifyProps(vtkLayerFrame& frame);
  bool DrawFrame(vtkLayerFrame& frame);
  void DrawLayersWithShadows(vtkLayerFrame& frame);
  void DrawLayers(vtkLayerFrame& frame);
  bool PeelLayers(vtkLayerFrame& frame, int allOracleMask);
  void ExchangeLayer(vtkLayerFrame& frame, int layer);
  void RecordFrame(const vtkLayerFrame& frame);
  void ReportLayers(const vtkDeepGBufferRendererState& state);
};

#endif
