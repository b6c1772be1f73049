/**
 * @class   vtkDeepGIPass
 * @brief   Deep G-buffer GI: direct + AV * ambient + radiosity + reflections.
 *
 * The composite of Mara, McGuire, Nowrouzezahrai and Luebke, "Deep
 * G-Buffers for Stable Global Illumination Approximation" (HPG 2016),
 * sections 3.1-3.6, for any VTK scene in one line:
 *
 *   renderer->SetPass(gi);   // C++
 *   renderer.SetPass(gi)     # Python
 *
 * It owns one vtkDeepGBufferPass and the three effects that read it,
 * sharing it (GetGBufferPass, GetAmbientObscurancePass, GetRadiosityPass,
 * GetReflectionPass; tune them there). The G-buffer has a guard band of
 * vtkDeepRadiosityPass::DEFAULT_GUARD_BAND (0.1 of the height on each side,
 * section 3.5): the effects gather light and occluders just outside the
 * view. Each frame it renders the camera,
 * lights, the opaque props into the layers, the effects the scene needs
 * (UpdateAmbientVisibility, UpdateRadiosity, UpdateReflections), ONE
 * composite, then VTK's translucent, volumetric and overlay steps against
 * layer 0's depth (vtkDeepGBufferPass::RenderFrame), so translucent props,
 * volumes (vtkSmartVolumeMapper), 2D actors and FXAA compose as usual.
 *
 * Composition of layer 0 (floats, before the framebuffer's rounding):
 *
 *   colour = DIRECT + AV * AMBIENT + L_ind + REFLECTIVITY * L_r
 *
 * - DIRECT = RADIANCE - AMBIENT: VTK's shading under its lights (diffuse
 *   and specular highlights), G-buffer quantities of layer 0.
 * - AMBIENT: VTK's ambient term (Ambient x AmbientColor), the stand-in for
 *   light arriving from every direction. Ambient visibility AV (section
 *   3.1, eq. 1-2) is a visibility term for exactly that light, so it scales
 *   AMBIENT only; direct light has its own (shadow) visibility, and
 *   darkening it too (what vtkSSAOPass does) would double-shadow it.
 * - L_ind: the radiosity pass's outgoing indirect radiance (sections
 *   3.2-3.3, eq. 3-7, confidence fallback included when on). It is light
 *   that VTK's local shading does not contain, so it is added.
 * - REFLECTIVITY * L_r: mirror reflections (section 3.6), the reflected
 *   radiance weighted by the G-buffer's REFLECTIVITY, added like L_ind.
 * When no visible opaque actor has an ambient term (VTK's default actors:
 * Ambient 0) the obscurance pass's COMPOSITE_AUTOMATIC composition resolves
 * to COMPOSITE_MULTIPLY and the composite is
 *
 *   colour = AV * RADIANCE + L_ind + REFLECTIVITY * L_r
 *
 * VTK's lights then stand for all the light that arrives, which nearby
 * surfaces occlude (what vtkSSAOPass darkens); SetCompositionToAmbient() on
 * GetAmbientObscurancePass() keeps AV to the ambient term only. The model
 * and its ray-traced reference (vtkDeepGIReferenceImage) are in
 * Documentation/lighting-model.md.
 * Alpha is kept; pixels where layer 0 is empty keep the background.
 *
 * Model only what the scene requires. Each frame and per renderer:
 * - ambient obscurance runs when AmbientObscurance is on, unless the
 *   obscurance pass's composition is COMPOSITE_AMBIENT and no visible opaque
 *   actor has an ambient term (AV * AMBIENT would be 0);
 * - radiosity runs when Radiosity is on, a light is switched on and a
 *   visible opaque actor can reflect diffuse light (Diffuse > 0 and a
 *   non-black DiffuseColor, or colours from scalars or a texture);
 * - reflections run when Reflections is on and a visible prop reflects
 *   (vtkDeepReflectionPass::RendererReflects); otherwise the G-buffer does
 *   not even store REFLECTIVITY;
 * - the second layer is built when an effect runs and the scene has depth
 *   complexity: an occlusion query counts the layer-1 pixels (a full-screen
 *   quad that discards where layer 1 is empty) and is read back one or more
 *   frames later, never stalling. A count of 0 drops the renderer to one
 *   layer; it probes with two layers again after LayerProbeInterval frames,
 *   or at once when its camera or props change (the camera's position,
 *   focal point, view up, view angle, parallel scale and projection; the
 *   modification times of the prop collection and of each prop). The frame
 *   of a change is not measured: the single-pass oracles put newly visible
 *   geometry into layer 1 one frame late, so a moving camera keeps two
 *   layers.
 * When no effect runs the frame is exactly vtkDeepGBufferPass's (VTK's
 * image). GetLastFrameEffects() and PrintSelf tell what ran.
 *
 * Presets (SetPreset, one Modified(); the constructor sets BALANCED): AO
 * quality with the SOLID_ANGLE estimator (samples N, blur radius, MIP
 * threshold q: the shared G-buffer culls back faces in layer 1, so the
 * obscurance's default VISIBILITY_BITMASK cannot tell where a solid ends),
 * the radiosity pass's Table 2 preset, reflection march steps and
 * bisections:
 * | preset           | AO                 | radiosity        | reflections |
 * |------------------|--------------------|------------------|-------------|
 * | HIGH_PERFORMANCE | LOW (8, 2, 4)      | HIGH_PERFORMANCE | 32, 2       |
 * | BALANCED         | MEDIUM (16, 4, 8)  | BALANCED         | 64, 4       |
 * | HIGH_QUALITY     | HIGH (32, 6, 16)   | HIGH_QUALITY     | 128, 6      |
 * BALANCED is the sub-passes' default, except for the obscurance's samples,
 * blur radius and estimator.
 *
 * Still images: radiosity adds one bounce per frame and filters over time
 * (section 3.3), so a single frame shows one bounce. Converge(renderer, n)
 * renders n frames at a fixed camera, with the radiosity's temporal filter
 * off (TemporalAlpha 0 while it runs, which also fixes the spiral's
 * rotation): each frame then adds exactly one bounce, so the image
 * converges geometrically. Without the filter's average over rotations,
 * the noise of the spiral taps stays in the image, so the radiosity's
 * blur is widened by STILL_BLUR_SCALE meanwhile, and the obscurance's by
 * STILL_OBSCURANCE_BLUR_SCALE. Converge fires
 * vtkCommand::ProgressEvent (call
 * data: double progress in [0, 1]) after each. See Documentation/gi.md,
 * Documentation/performance.md and Apps/Benchmarks/deepgi_convergence.py.
 *
 * Its frames keep the layers and the ambient visibility of the frame before
 * while nothing they depend on changed (ConvergeReusesLayers). Afterwards,
 * until the camera, props, lights, the renderer's ambient colour,
 * background or two-sided lighting, or a setting of the passes change,
 * frames render as Converge's did and so show the converged image: a
 * re-render of the window (vtkWindowToImageFilter unless ShouldRerender
 * is off, VTK's regression tests, an expose event) does not fall back to
 * the interactive settings. Not after an aborted Converge.
 *
 * Converge stops between two frames when asked to, the way VTK's
 * rendering is aborted: the render window's AbortRender flag set (by a
 * ProgressEvent observer, or by an AbortCheckEvent observer of the window,
 * which Converge fires through vtkRenderWindow::CheckAbortStatus after each
 * frame), or SIGINT (Ctrl-C) received. It renders at most
 * MAXIMUM_CONVERGE_FRAMES frames. It finds this pass in the renderer's
 * pass also when wrapped (vtkOpenGLFXAAPass, vtkToneMappingPass and other
 * vtkImageProcessingPass, vtkSSAAPass, vtkCameraPass, vtkSequencePass).
 *
 * One render window at a time: the sub-passes' programs and textures
 * belong to the OpenGL context of the window they were made in. A pass
 * already rendering into one window refuses a renderer of another window
 * with one error per window and draws that renderer the plain VTK way
 * (no GI, no OpenGL error); ReleaseGraphicsResources(window) with the
 * window it renders into frees everything and frees the pass for another
 * window (with any other window it frees nothing: the objects are not that
 * context's). Give each window its own vtkDeepGIPass to have GI in both.
 *
 * Bad input: a non-positive frame count, a renderer that does not use this
 * pass, or a probe interval below 1 give a warning and no crash. When the
 * G-buffer is unsupported the frame is VTK's plain image, with one
 * warning.
 *
 * @sa vtkDeepGBufferPass vtkDeepAmbientObscurancePass vtkDeepRadiosityPass vtkDeepReflectionPass
 */

#ifndef vtkDeepGIPass_h
#define vtkDeepGIPass_h

#include "vtkDeepGIRenderingModule.h" // for export macro
#include "vtkRenderPass.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkDeepAmbientObscurancePass;
class vtkDeepGBufferPass;
class vtkDeepRadiosityPass;
class vtkDeepReflectionPass;
class vtkOpenGLRenderer;
class vtkRenderer;
struct vtkDeepGIRendererState;

class VTKDEEPGIRENDERING_EXPORT vtkDeepGIPass : public vtkRenderPass
{
public:
  static vtkDeepGIPass* New();
  vtkTypeMacro(vtkDeepGIPass, vtkRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Bits of GetLastFrameEffects(): the sub-passes that ran.
  enum Effect
  {
    AMBIENT_OBSCURANCE = 1,
    RADIOSITY = 2,
    REFLECTIONS = 4,
    SECOND_LAYER = 8 ///< the G-buffer had two layers
  };

  /// The most frames one Converge call renders; more are clamped, with a
  /// warning.
  static constexpr int MAXIMUM_CONVERGE_FRAMES = 10000;

  /// While Converge runs, the radiosity's BlurRadius is this times its own
  /// (rounded, at most 16; restored afterwards): with the temporal filter
  /// off nothing else averages the spiral's noise, which at the default
  /// gather radius leaves a low-frequency mottling on large uniform
  /// surfaces (BALANCED's 5 taps become 8; Documentation/gi.md).
  static constexpr double STILL_BLUR_SCALE = 1.6;

  /// While Converge runs, the obscurance's BlurRadius is this times its own
  /// (rounded, at most 16; restored afterwards). The obscurance has no
  /// temporal filter in this pass, so its taps' pattern stays in a still
  /// image: under an object resting on a floor, where the occluder is the
  /// thin band of the object's underside seen at a grazing angle, as a
  /// grain in the contact shadow that more taps do not remove. Converge
  /// computes the obscurance once and keeps it while nothing changes, so
  /// the wider blur costs one frame's. It cuts that grain to 0.4 in
  /// Examples/Cxx/OneLineRecipe.cxx (TestDeepGIOneLineRecipe) and moves the
  /// image benchmark's error by -4.7 % to +0.2 % (Documentation/gi.md).
  static constexpr double STILL_OBSCURANCE_BLUR_SCALE = 2.0;

  /// Quality presets (see the class description).
  enum Preset
  {
    HIGH_PERFORMANCE = 0,
    BALANCED = 1,
    HIGH_QUALITY = 2
  };

  ///@{
  /// The shared G-buffer and the effects, for tuning. Never null. The
  /// G-buffer's NumberOfLayers and WriteReflectivity are set by this pass
  /// every frame (1 or 2 layers, see AdaptiveLayers; reflectivity while a
  /// prop reflects); its other settings (oracle, dz, ...) are the user's.
  vtkGetObjectMacro(GBufferPass, vtkDeepGBufferPass);
  vtkGetObjectMacro(AmbientObscurancePass, vtkDeepAmbientObscurancePass);
  vtkGetObjectMacro(RadiosityPass, vtkDeepRadiosityPass);
  vtkGetObjectMacro(ReflectionPass, vtkDeepReflectionPass);
  ///@}

  ///@{
  /// Effect switch of the obscurance term (default on). It runs only when
  /// a visible opaque actor has an ambient term.
  ///
  /// @range on/off
  /// @default on
  vtkSetMacro(AmbientObscurance, bool);
  vtkGetMacro(AmbientObscurance, bool);
  vtkBooleanMacro(AmbientObscurance, bool);
  ///@}

  ///@{
  /// Effect switch of the radiosity (default on). It runs only with a
  /// light on and a visible opaque actor with a diffuse albedo.
  ///
  /// @range on/off
  /// @default on
  vtkSetMacro(Radiosity, bool);
  vtkGetMacro(Radiosity, bool);
  vtkBooleanMacro(Radiosity, bool);
  ///@}

  ///@{
  /// Effect switch of the reflections (default on). They run only when a
  /// visible prop reflects.
  ///
  /// @range on/off
  /// @default on
  vtkSetMacro(Reflections, bool);
  vtkGetMacro(Reflections, bool);
  vtkBooleanMacro(Reflections, bool);
  ///@}

  /**
   * Sets the three effect switches by name: a comma-separated list of
   * distinct "ao", "radiosity" and "reflections" (case-insensitive, spaces
   * ignored), or "all" or "none". An effect not named is switched off.
   * Returns false, with a warning and nothing changed, for anything else.
   *
   * @label SetEffects(const char*)
   * @type string
   * @range distinct ao, radiosity, reflections separated by commas, or all,
   * none; otherwise: warning, returns false, nothing changed
   * @default all (the three switches' defaults)
   */
  bool SetEffects(const char* names);

  /**
   * Parses such a list into a mask of AMBIENT_OBSCURANCE, RADIOSITY and
   * REFLECTIONS ("none": 0); false, `effects` untouched, when it is not one.
   */
  static bool ParseEffects(const char* names, int& effects);

  ///@{
  /**
   * Sets the three effects' presets at once (see the table in the class
   * description) with one Modified() of this pass. An unknown preset is
   * ignored with a warning. Default BALANCED (the sub-passes' defaults).
   * GetPresetFromString parses "high_performance", "balanced",
   * "high_quality" (case-insensitive, '-' or '_'); -1 if unknown.
   * SetPreset(name) sets a preset by that name (from Python:
   * gi.SetPreset("balanced")).
   * The presets set the obscurance preset, the radiosity preset and the reflection steps and
   * bisections (table in Documentation/gi.md). Also SetPresetToHighPerformance(), ...Balanced(),
   * ...HighQuality(); an unknown name is ignored with a warning.
   *
   * @type int (Preset)
   * @range HIGH_PERFORMANCE 0, BALANCED 1, HIGH_QUALITY 2; unknown: warning, ignored
   * @default BALANCED
   */
  void SetPreset(int preset);
  void SetPreset(const char* name);
  vtkGetMacro(Preset, int);
  void SetPresetToHighPerformance() { this->SetPreset(HIGH_PERFORMANCE); }
  void SetPresetToBalanced() { this->SetPreset(BALANCED); }
  void SetPresetToHighQuality() { this->SetPreset(HIGH_QUALITY); }
  static const char* GetPresetAsString(int preset);
  static int GetPresetFromString(const char* name);
  ///@}

  ///@{
  /**
   * Adaptive layer count (default on): one G-buffer layer while the
   * layer-1 coverage measured by the occlusion query is 0. Off: always two
   * layers (unless UseSecondLayer is off).
   *
   * @range on/off
   * @default on
   */
  vtkSetMacro(AdaptiveLayers, bool);
  vtkGetMacro(AdaptiveLayers, bool);
  vtkBooleanMacro(AdaptiveLayers, bool);
  ///@}

  ///@{
  /**
   * Whether the effects may look behind the visible surfaces (default on).
   * Off: the G-buffer always has one layer, which halves its geometry cost
   * and the effects' taps on layer 1, and loses what the second layer
   * gives: occluders and light sources hidden behind the first surface, and
   * the propagation of light through them (Documentation/lighting-model.md
   * measures the difference on the pixels that have a second layer).
   *
   * @range on/off
   * @default on
   */
  vtkSetMacro(UseSecondLayer, bool);
  vtkGetMacro(UseSecondLayer, bool);
  vtkBooleanMacro(UseSecondLayer, bool);
  ///@}

  ///@{
  /**
   * How many frames a renderer stays at one layer before it probes with
   * two again when its camera and props did not change (a camera or prop
   * change probes at once). Default 60; values below 1 become 1 with a
   * warning.
   *
   * @unit frames
   * @range >= 1; below: warning, 1
   * @default 60
   */
  void SetLayerProbeInterval(int frames);
  vtkGetMacro(LayerProbeInterval, int);
  ///@}

  ///@{
  /**
   * What the last frame rendered by this pass computed and composited: a
   * mask of Effect bits (AMBIENT_OBSCURANCE 1, RADIOSITY 2, REFLECTIONS 4,
   * SECOND_LAYER 8). GetEffectsAsString(mask) names the bits
   * ("AMBIENT_OBSCURANCE|RADIOSITY", "NONE").
   *
   * @readonly
   */
  vtkGetMacro(LastFrameEffects, int);
  static std::string GetEffectsAsString(int effects);
  ///@}

  /// The G-buffer's layer count in the last frame (0 when it was
  /// unsupported).
  ///
  /// @readonly
  vtkGetMacro(LastFrameNumberOfLayers, int);

  ///@{
  /**
   * Whether Converge's frames keep the G-buffer's layers and the ambient
   * visibility of the frame before instead of rendering them again
   * (default on): at a still camera only the radiosity's bounce changes
   * between them. A frame renders the layers again when the renderer's
   * or a light's modification time, a setting of the G-buffer or the
   * window size changed since the frame before, and when the camera (as
   * in the layer count's probe) or the modification time of a prop or of
   * the prop collection changed in it or in the frame before (e.g. by a
   * ProgressEvent observer; the single-pass oracles build layer 1 from the
   * frame before, so layers are kept after such a change only when they
   * were peeled). The ambient visibility is computed again when its
   * settings changed or its temporal filter is on. The radiosity keeps
   * what it derives from the layers alone (its geometry keys and, with a
   * resolution divisor, its reduced copy of the layers) while they are
   * kept. Renderers sharing the pass decide each for itself.
   * The images are the same as with it off, which renders everything every
   * frame; input the modification times do not show (a texture's or a
   * shader's changing input) needs it off.
   *
   * @range on/off
   * @default on
   */
  vtkSetMacro(ConvergeReusesLayers, bool);
  vtkGetMacro(ConvergeReusesLayers, bool);
  vtkBooleanMacro(ConvergeReusesLayers, bool);
  ///@}

  ///@{
  /**
   * Whether Converge shows each frame's radiosity with the bounces still
   * to come extrapolated from the last ones (vtkDeepRadiosityPass::
   * ExtrapolateBounces, default on): the bounces fall geometrically, by
   * about 0.4 per frame in a room, so once that decay is steady (from the
   * fourth frame when the radiosity starts without history) the image is
   * close to the fixed point, and a tolerance is met in fewer frames.
   * Starting is itself a large change of the image (the jump to the fixed
   * point), with a frame more after it, so with a tolerance Converge does
   * not start extrapolating while the image's next change, its last one
   * times the larger ratio of its last three, is expected within the
   * tolerance (as when Converge starts where an interactive camera
   * stopped, its radiosity nearly converged). The fixed point itself is unchanged. Off:
   * each frame shows the bounces gathered so far.
   *
   * @range on/off
   * @default on
   */
  vtkSetMacro(ConvergeExtrapolatesBounces, bool);
  vtkGetMacro(ConvergeExtrapolatesBounces, bool);
  vtkBooleanMacro(ConvergeExtrapolatesBounces, bool);
  ///@}

  /// Whether the last frame kept the layers of the frame before
  /// (ConvergeReusesLayers, while Converge runs).
  ///
  /// @readonly
  vtkGetMacro(LastFrameReusedLayers, bool);

  /// The layer-1 pixels counted by the newest occlusion query result; -1
  /// before the first.
  ///
  /// @readonly
  vtkGetMacro(LastLayerCoverage, long long);

  /**
   * Renders `renderer`'s window `frames` times without moving the camera,
   * so that the radiosity bounces settle (the radiosity's temporal filter
   * is off meanwhile: TemporalAlpha 0, its blur is STILL_BLUR_SCALE times
   * wider and the obscurance's STILL_OBSCURANCE_BLUR_SCALE times; all
   * restored afterwards), and
   * fires vtkCommand::ProgressEvent with a double progress (k / frames)
   * after frame k. The renderer should use this pass, directly or through
   * any wrapping passes (vtkOpenGLFXAAPass, vtkSSAAPass, vtkToneMappingPass,
   * ParaView's camera and IceT compositing passes, ...): a warning when the
   * first frame did not render this pass (the frames are rendered anyway). Interval probes of the
   * layer count are not started while converging (they would reset the radiosity history). Returns
   * the number of frames rendered (0 with a warning for a null renderer, a renderer without a
   * window or frames < 1; frames above MAXIMUM_CONVERGE_FRAMES are clamped with a warning).
   *
   * Interruption: after each frame and its ProgressEvent, Converge stops
   * when the render window's AbortRender flag is set (an observer calls
   * window->SetAbortRender(1); vtkRenderWindow::CheckAbortStatus is called,
   * so AbortCheckEvent observers of the window can set it too) or when
   * SIGINT arrived during the call; GetLastConvergenceAborted() then is
   * true. While Converge runs, SIGINT is caught (unless it is ignored);
   * afterwards the previous SIGINT action is restored and, if SIGINT
   * arrived, it is raised again for that action (Python then raises
   * KeyboardInterrupt, a C++ program without a handler ends). An exception
   * thrown by an observer leaves Converge (the pass and the signal
   * handling restored); Python observers cannot throw through VTK (their
   * exceptions are printed): they abort with SetAbortRender(1).
   */
  int Converge(vtkRenderer* renderer, int frames);

  /**
   * Converge until the image stops changing: renders at most
   * `maximumFrames` frames like Converge(renderer, frames) and stops early
   * after the first frame whose change from the previous one is at most
   * `tolerance`. The change is the mean absolute difference of the
   * renderer's viewport colour (RGB, 8 bits read back after each frame,
   * in units of the full scale, so 1/255 is one level) between two
   * consecutive frames. A tolerance of 0 renders all frames without
   * reading anything back; a negative or NaN tolerance is treated as 0
   * with a warning. ProgressEvent's progress is k / maximumFrames, and 1
   * when it stops early. Returns the number of frames rendered;
   * GetLastConvergenceChange() gives the last measured change (-1 when
   * none was measured) and GetLastConvergenceReached() whether the
   * tolerance was met.
   *
   * Without the temporal filter the change falls geometrically with the
   * bounces (deepgi-render's default tolerance 0.07/255 stops after 3
   * frames on the head and 6-8 in the bunny and the demo rooms;
   * Documentation/performance.md).
   */
  int Converge(vtkRenderer* renderer, int maximumFrames, double tolerance);

  /// The last change measured by Converge with a tolerance: the mean
  /// absolute RGB difference of two consecutive frames, full scale 1
  /// (1/255 per 8-bit level); -1 when none was measured.
  ///
  /// @readonly
  vtkGetMacro(LastConvergenceChange, double);

  /// Whether the last Converge with a tolerance stopped because a frame's
  /// change was at most the tolerance.
  ///
  /// @readonly
  vtkGetMacro(LastConvergenceReached, bool);

  /// Whether the last Converge call stopped because it was aborted
  /// (AbortRender or SIGINT, see Converge).
  ///
  /// @readonly
  vtkGetMacro(LastConvergenceAborted, bool);

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  /// The memory of the textures this pass holds for all renderers, in bytes:
  /// the G-buffer and every effect pass, i.e. the GPU memory this pass holds (the programs and
  /// quads aside). Proportional to the layers' pixels; 0 after ReleaseGraphicsResources.
  vtkTypeInt64 GetTextureBytes();

protected:
  vtkDeepGIPass();
  ~vtkDeepGIPass() override;

  /// The opaque step of the frame: layers, effects, composite.
  void RenderOpaque(const vtkRenderState* s);

  vtkDeepGBufferPass* GBufferPass = nullptr;
  vtkDeepAmbientObscurancePass* AmbientObscurancePass = nullptr;
  vtkDeepRadiosityPass* RadiosityPass = nullptr;
  vtkDeepReflectionPass* ReflectionPass = nullptr;
  bool AmbientObscurance = true;
  bool Radiosity = true;
  bool Reflections = true;
  int Preset = BALANCED;
  bool AdaptiveLayers = true;
  bool UseSecondLayer = true;
  int LayerProbeInterval = 60;
  int LastFrameEffects = 0;
  int LastFrameNumberOfLayers = 0;
  bool ConvergeReusesLayers = true;
  bool ConvergeExtrapolatesBounces = true;
  bool LastFrameReusedLayers = false;
  long long LastLayerCoverage = -1;
  double LastConvergenceChange = -1.0;
  bool LastConvergenceReached = false;
  bool LastConvergenceAborted = false;

private:
  vtkDeepGIPass(const vtkDeepGIPass&) = delete;
  void operator=(const vtkDeepGIPass&) = delete;

  // Converge's checks before the first frame (false: nothing to render).
  bool CheckConvergeArguments(vtkRenderer* renderer, int& maximumFrames, double& tolerance);
  // Converge's frames, with its still settings in place; returns how many.
  int RenderStillFrames(vtkRenderer* renderer, int maximumFrames, double tolerance);
  // Whether the next still frame may start extrapolating the bounces, from
  // the image's last three changes, oldest first (< 0: not measured).
  void HoldOffExtrapolation(const double changes[3], double tolerance);
  // Whether this frame holds the last Converge's still image (see Render).
  bool HoldsStillImage(vtkRenderer* renderer, vtkDeepGIRendererState& state);
  // The latest modification of this pass's settings and its sub-passes'.
  vtkMTimeType GetSettingsTime();
  // After the still settings were set and restored: the holds of the
  // settings' time `before` continue.
  void KeepHolds(vtkMTimeType before);

  // Whether `renderer` may be drawn with GI: its window is the one this
  // pass renders into (see the class description); otherwise one error.
  bool AcceptWindow(vtkRenderer* renderer);

  // The stages of Render and RenderOpaque, in order.
  struct vtkCompositeInputs;
  int WantedEffects(vtkRenderer* renderer) const;
  void UpdateLayerCount(vtkRenderer* renderer, vtkDeepGIRendererState& state);
  void RenderFrame(const vtkRenderState* s, vtkDeepGIRendererState& state, int wanted);
  void DecideLayerReuse(vtkRenderer* renderer, vtkDeepGIRendererState& state);
  int UpdateEffects(const vtkRenderState* s, bool layersReused);
  void QueryLayerCoverage(vtkOpenGLRenderer* renderer, int layers);
  int Composite(vtkOpenGLRenderer* renderer, int effects);
  int ActivateCompositeInputs(vtkOpenGLRenderer* renderer, int effects, vtkCompositeInputs& inputs);
  bool DrawComposite(vtkOpenGLRenderer* renderer, int composited, const vtkCompositeInputs& inputs);
  void DeactivateCompositeInputs(vtkOpenGLRenderer* renderer, const vtkCompositeInputs& inputs);

  friend class vtkDeepGIOpaqueStep;
  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
