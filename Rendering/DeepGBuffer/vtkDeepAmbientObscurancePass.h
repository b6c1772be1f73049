/**
 * @class   vtkDeepAmbientObscurancePass
 * @brief   Deep scalable ambient obscurance over the layers of a deep G-buffer.
 *
 * Implements section 3.1 (equations 1 and 2) and the spiral sampling of
 * section 3.4 of Mara, McGuire, Nowrouzezahrai and Luebke, "Deep G-Buffers
 * for Stable Global Illumination Approximation" (HPG 2016). Put it on a
 * renderer (`renderer->SetPass(pass)`) and it renders the whole frame:
 * camera, lights, the opaque props into the layers of an internal
 * vtkDeepGBufferPass (GetGBufferPass(), which keeps back faces in its deeper
 * layers because they occlude too; SetGBufferPass() shares one), the
 * ambient visibility AV, its bilateral reconstruction, the composite, then
 * the G-buffer pass's translucent, volumetric and overlay steps (VTK's own
 * by default), which compose against layer 0's depth.
 *
 * Ambient visibility at the layer-0 surface point X (camera space) with
 * normal n_X (paper eq. 1, with the Intensity exponent, see below; the
 * Estimator SOLID_ANGLE weights each tap by its solid angle instead of the
 * square root, and the default Estimator VISIBILITY_BITMASK integrates the
 * layers' solids over screen-space slices instead of spiral taps, see
 * SetEstimator):
 *
 *   AV(X) = max(0, 1 - sqrt(pi / N * sum_i max(0, A_i^0, A_i^1, ...)))^Intensity
 *   A_i^j = O(X, Y_i^j), Y_i^j the surface of layer j at spiral tap i,
 *   O(X, Y) = (1 - v.v / r^2) * max((v.n_X - beta) / sqrt(v.v + epsilon), 0),
 *   v = Y - X, and O = 0 where v.v >= r^2 (a tap beyond the radius).
 *
 * Taps (section 3.4): kappa_i = (i + 0.5) / N, h_i = r_p kappa_i pixels,
 * theta_i = 2 pi kappa_i tau(N) + phi, tap i at the texel containing
 * pixel centre + h_i (cos theta_i, sin theta_i). tau(N) is the paper's
 * Listing 3 (GetSpiralTurns). r_p is the world radius r projected at X's
 * depth: r_p = r * P11 * height / (2 w), w = -P32 * d + P33 the clip w of X
 * (w = d for perspective, 1 for parallel projection). Taps outside the
 * image or on empty texels contribute 0 (they still count in N).
 * phi, the per-pixel rotation, is 2 pi times Jimenez's interleaved gradient
 * noise of the integer pixel coordinates (x, y) (Jimenez, "Next Generation
 * Post Processing in Call of Duty: Advanced Warfare", SIGGRAPH 2014):
 *   phi = 2 pi fract(52.9829189 fract(0.06711056 x + 0.00583715 y)).
 * Camera-space positions come from each layer's DEPTH (distance d along
 * -z: z = -d) and the projection the layers were rasterised with.
 * Taps read the MIP pyramid of the layers' geometry key (section 3.4,
 * after SAO, McGuire, Mara and Luebke, HPG 2012): level 0 holds, per
 * texel, two layers' distance and Oct16 normal in one RGBA32F texel (one
 * fetch instead of four; one slice per two layers), level m + 1 texel
 * (x, y) is level m texel
 * (2x + (y & 1), 2y + (x & 1)) clamped to level m's size (SAO's rotated-grid
 * downsampling, SAO_minify.pix). Tap i reads level
 * m_i = clamp(floor(log2(h_i / q)), 0, L), q = MipThreshold pixels,
 * L = min(MaximumMipLevel, floor(log2(max(width, height)))). Its point is
 * reconstructed at the centre of the level-0 texel the rotated grid chose
 * for that coarse texel, so it is an exact surface point (up to 2^m - 1
 * pixels from the tap in each axis). MaximumMipLevel = 0 reads level 0
 * only and builds no coarser level.
 *
 * The reconstruction is a separable bilateral filter (horizontal, then
 * vertical), BlurRadius taps on each side with Gaussian spatial weights
 * (sigma = BlurRadius / 2), multiplied by a plane weight
 * max(0, 1 - |(Y - X).n_X| / (BlurPlaneTolerance d_X)) and a normal weight
 * max(0, n_X.n_Y)^BlurNormalPower, so it does not blur across depth or
 * normal discontinuities.
 *
 * Temporal accumulation (TemporalAlpha alpha > 0, off by default): the
 * filtered AV of this frame becomes mix(AV_now, AV_history, alpha) where the
 * history is valid, AV_now elsewhere. The history is the last frame's final
 * AV and layer-0 distance (RG32F, per renderer) with the view and projection
 * it was drawn with. Reprojection: the pixel's camera-space point from the
 * current distance and projection, to world with the inverse current view,
 * to the previous clip space with the previous view and projection, to the
 * nearest previous texel. Rejected (AV_now) when it is behind the previous
 * camera or outside the previous image, when the previous distance there
 * is 0, or when |d_prev - d_reprojected| > TEMPORAL_DISTANCE_TOLERANCE
 * (0.01) x d_reprojected. The history is reset on a resize, by
 * ReleaseGraphicsResources, while TemporalAlpha is 0, when the G-buffer is
 * unavailable, and when the renderer was rendered without this pass since
 * the history's frame (its StartEvents are counted). While accumulating,
 * phi gets a per-frame offset 2 pi fract(k / golden ratio) (k the frame
 * index since the reset), so successive frames sample other directions;
 * with TemporalAlpha 0 phi and the AV are bit-identical to no accumulation.
 *
 * Composition COMPOSITE_AMBIENT: layer 0's colour becomes
 * radiance - (1 - AV) * ambient, from the G-buffer's RADIANCE and AMBIENT
 * (float, before the framebuffer's 8-bit rounding), alpha kept.
 * Composition COMPOSITE_MULTIPLY: the G-buffer's
 * layer-0 image and depth are resolved into the renderer's framebuffer, then
 * the colour is multiplied by AV (alpha untouched), like vtkSSAOPass.
 * COMPOSITE_AUTOMATIC (default) is AMBIENT when the renderer's visible
 * opaque actors have an ambient term and MULTIPLY when none has (see
 * SetComposition).
 * Pixels where layer 0 is empty keep the background.
 *
 * Textures (each of the renderer's viewport size, per renderer):
 * | texture  | format | content                                    |
 * |----------|--------|--------------------------------------------|
 * | raw AV   | R32F   | eq. 1 before the filter (1 where empty)     |
 * | blur tmp | R32F   | after the horizontal pass                  |
 * | AV       | R32F   | after the vertical pass                    |
 * | history  | RG32F  | x2, accumulated AV + layer-0 distance (only with TemporalAlpha > 0) |
 * Reads: the G-buffer's DEPTH and NORMAL arrays (all layers) and its
 * layer-0 RADIANCE (through ResolveToFramebuffer). Writes: the renderer's
 * colour and depth.
 *
 * Bad input never crashes: a non-finite or negative radius, a sample count
 * outside 1..98 and a negative intensity are reported with vtkWarningMacro
 * and replaced by the nearest valid value. When the G-buffer is unsupported
 * (vtkDeepGBufferPass::RenderLayers returns false) a warning is given once
 * and the plain VTK image is shown.
 *
 * @sa vtkDeepGBufferPass vtkSSAOPass
 */

#ifndef vtkDeepAmbientObscurancePass_h
#define vtkDeepAmbientObscurancePass_h

#include "vtkDeepGIRenderingModule.h" // for export macro
#include "vtkDeepGISetGet.h"          // for vtkDeepGISetClampMacro
#include "vtkDeepGIShaderConstants.h" // for the enum values shared with GLSL
#include "vtkDeepScreenSpacePass.h"

#include <memory> // for std::unique_ptr

class vtkImageData;
class vtkOpenGLRenderWindow;
struct vtkDeepAmbientObscuranceRendererState;
class vtkRenderer;

class VTKDEEPGIRENDERING_EXPORT vtkDeepAmbientObscurancePass : public vtkDeepScreenSpacePass
{
public:
  static vtkDeepAmbientObscurancePass* New();
  vtkTypeMacro(vtkDeepAmbientObscurancePass, vtkDeepScreenSpacePass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// How AV is applied to the image.
  enum CompositionMode
  {
    /// layer-0 radiance (the whole colour) times AV, like vtkSSAOPass
    COMPOSITE_MULTIPLY = DEEP_COMPOSITE_MULTIPLY,
    /// only the ambient part: radiance - (1 - AV) ambient
    COMPOSITE_AMBIENT = DEEP_COMPOSITE_AMBIENT,
    /// AMBIENT when the scene has an ambient term, else MULTIPLY
    COMPOSITE_AUTOMATIC = DEEP_COMPOSITE_AUTOMATIC
  };

  /// Relative distance tolerance of the temporal reprojection test.
  static constexpr double TEMPORAL_DISTANCE_TOLERANCE = 0.01;

  /**
   * Number of spiral turns tau for N samples, the paper's Listing 3
   * (discrepancy-minimising, N = 1..98). Returns 0 for N outside 1..98: the
   * paper gives no value there (in particular none for N = 99).
   */
  static int GetSpiralTurns(int numberOfSamples);

  ///@{
  /**
   * World-space obscurance radius r. Setting a value switches
   * AutomaticRadius off. NaN and infinities are rejected with a warning
   * (the previous value stays); negative values are clamped to 0 with a
   * warning (r = 0 gives AV = 1).
   *
   * @unit world units
   * @range >= 0, finite; negative: warning, 0; NaN/inf: warning, ignored
   * @default 1 (unused while automatic)
   */
  void SetRadius(double radius);
  vtkGetMacro(Radius, double);
  ///@}

  ///@{
  /**
   * When on (default), r is AutomaticRadiusFraction times the diagonal of
   * the bounds of the renderer's visible props, every frame, so it follows
   * the scene's scale (0.67 in vtkDeepGIDemoScene's 10 x 4 x 8 room,
   * about SAO's 1 m in the paper's 30-40 m scenes).
   *
   * @range on/off
   * @default on
   */
  vtkSetMacro(AutomaticRadius, bool);
  vtkGetMacro(AutomaticRadius, bool);
  vtkBooleanMacro(AutomaticRadius, bool);
  ///@}

  ///@{
  /**
   * The fraction of the diagonal that gives the automatic r (default 0.05).
   *
   * @unit fraction of the diagonal
   * @range 0 to 1, clamped
   * @default 0.05
   */
  vtkDeepGISetClampMacro(AutomaticRadiusFraction, double, 0.0, 1.0);
  vtkGetMacro(AutomaticRadiusFraction, double);
  ///@}

  /// The radius r used by the last frame (world units).
  ///
  /// @unit world units
  /// @readonly
  vtkGetMacro(EffectiveRadius, double);

  ///@{
  /**
   * beta of eq. 2, relative to the radius: the bias in world units is
   * Bias * r. It keeps flat surfaces from obscuring themselves through
   * depth and normal quantisation. Default 0.01 (SAO's 1.2 cm at r = 1 m).
   * Clamped to [0, 1].
   *
   * @unit fraction of r
   * @range 0 to 1, clamped
   * @default 0.01
   */
  vtkDeepGISetClampMacro(Bias, double, 0.0, 1.0);
  vtkGetMacro(Bias, double);
  ///@}

  ///@{
  /**
   * epsilon of eq. 2, relative to the squared radius: epsilon in world
   * units squared is Epsilon * r^2. It keeps 1 / |v| (1 / |v|^2 for
   * SOLID_ANGLE) finite for taps very near X. Default 1e-4: larger values
   * discard the occluders nearest X, whose solid angle is largest (with
   * SOLID_ANGLE, 0.01, SAO's 0.01 m^2 at r = 1 m, leaves the obscurance
   * of a floor point beside a wall 0.22 too low; 1e-4, 0.12). Clamped to
   * [1e-6, 1].
   *
   * @unit fraction of r^2
   * @range 1e-6 to 1, clamped
   * @default 1e-4
   */
  vtkDeepGISetClampMacro(Epsilon, double, 1e-6, 1.0);
  vtkGetMacro(Epsilon, double);
  ///@}

  /// How the taps' eq. 2 values become AV.
  enum EstimatorType
  {
    /// the paper's eq. 1: AV = max(0, 1 - sqrt(pi / N sum_i O_i))
    EQUATION_1 = DEEP_AO_ESTIMATOR_EQUATION_1,
    /// each tap weighted by its solid angle: AV = 1 - A, the obscurance itself
    SOLID_ANGLE = DEEP_AO_ESTIMATOR_SOLID_ANGLE,
    /// the layers' solids over the sectors of screen-space slices: AV = 1 - A
    VISIBILITY_BITMASK = DEEP_AO_ESTIMATOR_VISIBILITY_BITMASK
  };

  ///@{
  /**
   * How the layers become AV. VISIBILITY_BITMASK (default) and SOLID_ANGLE
   * estimate the obscurance A of the ray-traced reference
   * (vtkDeepGIReferenceObscurance) itself, A = (1 / pi) x the integral over
   * the hemisphere of (1 - t^2 / r^2) cos, t the distance of the nearest
   * surface within r in each direction.
   *
   * VISIBILITY_BITMASK integrates A over max(1, N / 16) slices, the planes
   * through X's view ray and a screen direction at phi + pi k / slices, as
   * GTAO does (Jimenez et al., "Practical Realtime Strategies for Accurate
   * Indirect Occlusion", 2016), each split into 32 sectors of angle
   * (visibility bitmasks: Therrien, Levesque and Gilet, "Screen Space
   * Indirect Lighting with Visibility Bitmasks", 2023). N / (2 slices) taps
   * on each side of X, r_p ((j + jitter) / steps)^2 pixels away, read every
   * searched layer there. Each surface occupies a stretch of its tap's view
   * ray: from layer 2k to layer 2k + 1 where their facings differ (they
   * enter and leave one solid: the thickness that only a deep G-buffer
   * knows); dz, the G-buffer's minimum separation, behind a surface with a
   * layer of the same facing behind it (its far side, if any, is nearer than
   * dz); to infinity behind the last surface (a height field, as GTAO
   * assumes everywhere). The part of a stretch within r of X and above X's
   * tangent plane covers an interval of sectors (by the elevation of its
   * ends), a sector keeps the largest falloff 1 - t^2 / r^2 of the stretches
   * covering it (its nearest surface, in 1/8 steps), and
   *   A = (1 / slices) sum_slices |n projected| sum_sectors falloff
   *       x integral over the sector of cos(theta - gamma) |sin theta|
   * (theta from the view vector, gamma the projected normal's angle: GTAO's
   * cosine-weighted slice measure). A direction counts once, for its
   * nearest surface; no bias is needed (the tangent plane bounds the
   * sectors); a thin object in front of a wall does not darken the wall
   * behind it, as the height field alone would. Bias and Epsilon apply to
   * the other estimators only.
   *
   * SOLID_ANGLE weights each of N spiral taps by its solid angle:
   * the tap at kappa_i stands for the screen ring of area
   * 2 pi h_i r_p / N pixels, i.e. (w_Y / f)^2 / |n_Y . d_Y| of surface
   * per pixel, whose solid angle seen from X is that area times
   * |n_Y . v| / |v|^3 (n_Y the tap's normal, d_Y its view ray, w the clip
   * w, f the focal length in pixels). Weighting each tap's
   * (1 - v.v / r^2) max(0, v.n - beta) / |v| by it gives
   *   AV = max(0, 1 - (2 / N) sum_i max_j (1 - v.v / r^2) max(0, v.n - beta)
   *        r (w_Y / w_X) v.v / (v.v + epsilon)^2 |n_Y . v| / (|v| max(|n_Y . d_Y|, 0.1)))
   * (the floor 0.1 bounds surfaces seen edge-on by the camera).
   * EQUATION_1 is the paper's eq. 1, whose square root is a contrast
   * curve: small obscurance becomes a broad grey shadow, 2-4 times darker
   * than the reference (Documentation/ambient-obscurance.md).
   * Also SetEstimatorToEquation1(), SetEstimatorToSolidAngle(),
   * SetEstimatorToVisibilityBitmask().
   *
   * @type int (EstimatorType)
   * @range EQUATION_1 0, SOLID_ANGLE 1, VISIBILITY_BITMASK 2; clamped
   * @default VISIBILITY_BITMASK
   */
  vtkSetClampMacro(Estimator, int, EQUATION_1, VISIBILITY_BITMASK);
  vtkGetMacro(Estimator, int);
  void SetEstimatorToEquation1() { this->SetEstimator(EQUATION_1); }
  void SetEstimatorToSolidAngle() { this->SetEstimator(SOLID_ANGLE); }
  void SetEstimatorToVisibilityBitmask() { this->SetEstimator(VISIBILITY_BITMASK); }
  static const char* GetEstimatorAsString(int estimator);
  ///@}

  ///@{
  /**
   * Exponent applied to AV: AV = max(0, 1 - sqrt(...))^Intensity.
   * 1 (default) is exactly eq. 1, 0 disables obscurance (AV = 1), larger
   * values darken; AV stays in [0, 1]. Negative values are clamped to 0
   * with a warning; NaN and infinities are rejected with a warning (the
   * previous value stays).
   *
   * @range >= 0, finite; negative: warning, 0; NaN/inf: warning, ignored
   * @default 1
   */
  void SetIntensity(double intensity);
  vtkGetMacro(Intensity, double);
  ///@}

  ///@{
  /**
   * Number of taps N, 1 to MAXIMUM_NUMBER_OF_SAMPLES (98): spiral taps, or
   * for VISIBILITY_BITMASK the slices' taps (N / 16 slices, at least one).
   * Default 12 (BALANCED). Values outside are clamped with a warning; in
   * particular N = 99, which the paper's Figure 7 uses but Listing 3 does
   * not tabulate, becomes 98 with a warning.
   *
   * @unit taps
   * @range 1 to 98; outside: warning and clamp
   * @default 12
   */
  void SetNumberOfSamples(int samples);
  vtkGetMacro(NumberOfSamples, int);
  ///@}

  ///@{
  /**
   * When on (default), occluders come from every layer of the G-buffer
   * (eq. 1's max over A_i^0, A_i^1, ...). Off: layer 0 only, classic SAO
   * without its falloff terms.
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
   * Bilateral reconstruction: taps on each side of each separable pass
   * (0 to 16, default 3; 0 disables the filter).
   *
   * @unit pixels per side
   * @range 0 to 16, clamped
   * @default 3
   */
  vtkSetClampMacro(BlurRadius, int, 0, 16);
  vtkGetMacro(BlurRadius, int);
  ///@}

  ///@{
  /**
   * Plane weight of the bilateral filter: the tolerance as a fraction of
   * the centre pixel's distance (default 0.02).
   *
   * @unit fraction of depth
   * @range 1e-6 to 1, clamped
   * @default 0.02
   */
  vtkDeepGISetClampMacro(BlurPlaneTolerance, double, 1e-6, 1.0);
  vtkGetMacro(BlurPlaneTolerance, double);
  ///@}

  ///@{
  /**
   * Normal weight of the bilateral filter: its exponent (default 8). The
   * exponent is compiled into the filter's shader, which a new value
   * rebuilds: a whole exponent is computed with products (three for 8),
   * cheaper than pow on a CPU renderer.
   *
   * @unit exponent
   * @range 0 to 128, clamped
   * @default 8
   */
  vtkDeepGISetClampMacro(BlurNormalPower, double, 0.0, 128.0);
  vtkGetMacro(BlurNormalPower, double);
  ///@}

  ///@{
  /**
   * Fraction of the G-buffer's guard band (vtkDeepGBufferPass::SetGuardBand,
   * 0 by default: then this has no effect) for which AV is computed, 0 to 1,
   * default 0.5. The taps always read the whole guard band (occluders just
   * off-screen); the shaded part lets the filter and the temporal history
   * work across the frame's edges. With TemporalAlpha 0 only the filter
   * reads it, so at most BlurRadius pixels of the band are shaded (the
   * frame's AV is the same, for less work). NaN is ignored and values outside
   * [0, 1] are clamped, with a warning. A change resets the history.
   * Because the taps read the whole band, occluders just off-screen
   * darken the frame's edges (see Documentation/radiosity.md, "Guard
   * band").
   *
   * @unit fraction of the guard band
   * @range 0 to 1; outside: warning and clamp; NaN: warning, ignored
   * @default 0.5
   */
  void SetGuardBandShadedFraction(double fraction)
  {
    this->SetFraction("GuardBandShadedFraction", fraction, this->GuardBandShadedFraction);
  }
  vtkGetMacro(GuardBandShadedFraction, double);
  ///@}

  ///@{
  /**
   * MIP pyramid (see the class description): q, the screen radius in
   * pixels at which taps start reading coarser levels: taps with h_i >= 2q
   * read coarser levels (default 8, SAO's 2^LOG_MAX_OFFSET; clamped to
   * [1, 65536]).
   *
   * @unit pixels
   * @range 1 to 65536, clamped
   * @default 8
   */
  vtkDeepGISetClampMacro(MipThreshold, double, 1.0, 65536.0);
  vtkGetMacro(MipThreshold, double);
  ///@}

  ///@{
  /**
   * MIP pyramid: the coarsest level L (0 to 15, default 5 as SAO's
   * MAX_MIP_LEVEL; 0: taps read level 0 only).
   *
   * @unit level
   * @range 0 to 15, clamped
   * @default 5
   */
  vtkSetClampMacro(MaximumMipLevel, int, 0, 15);
  vtkGetMacro(MaximumMipLevel, int);
  ///@}

  ///@{
  /**
   * Temporal accumulation weight alpha of the reprojected history (see the
   * class description): 0 (default) turns accumulation off, the image is
   * then exactly the single-frame one; larger values average over more
   * frames (about (1 + alpha) / (1 - alpha) frames for a still camera) but
   * lag more behind changes. Clamped to [0, 0.99].
   *
   * @range 0 to 0.99, clamped
   * @default 0
   */
  vtkDeepGISetClampMacro(TemporalAlpha, double, 0.0, 0.99);
  vtkGetMacro(TemporalAlpha, double);
  ///@}

  /**
   * Copies the distances of level `level` of the pyramid of the last frame rendered
   * for `renderer` (the first renderer if null) into `output`, an image of
   * that level's size (max(1, width >> level) x max(1, height >> level), of
   * the G-buffer's layers: the frame and its guard band):
   * float point-data arrays "Distance_j" per layer j (0 = empty). Field
   * data "NumberOfMipLevels" (levels built, L + 1). Level 0 is available
   * even when MaximumMipLevel is 0. The context must be current. Returns
   * false with an error when the level does not exist.
   */
  bool CaptureDistancePyramid(int level, vtkImageData* output, vtkRenderer* renderer = nullptr);

  ///@{
  /**
   * How AV is applied (CompositionMode). Default COMPOSITE_AUTOMATIC.
   * Obscurance is a visibility term for light arriving from all directions,
   * so physically it scales only the ambient (indirect) light and leaves
   * direct light and its shadows alone (paper section 3.1).
   * COMPOSITE_AMBIENT does exactly that: it darkens VTK's ambient term (the
   * G-buffer's AMBIENT quantity: property Ambient x AmbientColor, times the
   * texture). COMPOSITE_MULTIPLY darkens the whole colour as vtkSSAOPass
   * does. COMPOSITE_AUTOMATIC chooses, each frame and per renderer,
   * COMPOSITE_AMBIENT when at least one visible opaque actor has an ambient
   * term (Ambient > 0 and a non-black AmbientColor), and COMPOSITE_MULTIPLY
   * otherwise: with VTK's default Ambient = 0 an ambient-only composition
   * would show no obscurance at all. In a scene that mixes both kinds of
   * actors, the actors without an ambient term are then not darkened.
   * GetEffectiveComposition() tells which one the last frame used. The
   * ambient composition applies when the G-buffer displays RADIANCE; for
   * its debug displays the pass multiplies. Also SetCompositionToMultiply(),
   * SetCompositionToAmbient(), SetCompositionToAutomatic().
   *
   * @type int (CompositionMode)
   * @range COMPOSITE_MULTIPLY 0, COMPOSITE_AMBIENT 1, COMPOSITE_AUTOMATIC 2; clamped
   * @default COMPOSITE_AUTOMATIC
   */
  vtkSetClampMacro(Composition, int, COMPOSITE_MULTIPLY, COMPOSITE_AUTOMATIC);
  vtkGetMacro(Composition, int);
  void SetCompositionToMultiply() { this->SetComposition(COMPOSITE_MULTIPLY); }
  void SetCompositionToAmbient() { this->SetComposition(COMPOSITE_AMBIENT); }
  void SetCompositionToAutomatic() { this->SetComposition(COMPOSITE_AUTOMATIC); }
  static const char* GetCompositionAsString(int composition);
  ///@}

  ///@{
  /// COMPOSITE_MULTIPLY or COMPOSITE_AMBIENT: what the last frame used.
  ///
  /// @readonly
  vtkGetMacro(EffectiveComposition, int);
  ///@}

  /// Presets, from low cost to high quality (the names of
  /// vtkDeepRadiosityPass's and vtkDeepGIPass's presets, whose
  /// HIGH_PERFORMANCE, BALANCED and HIGH_QUALITY use these).
  enum Preset
  {
    HIGH_PERFORMANCE = 0, ///< N 8, BlurRadius 2, MipThreshold 4, MaximumMipLevel 5
    BALANCED = 1,         ///< N 12, BlurRadius 3, MipThreshold 8, MaximumMipLevel 5 (the defaults)
    HIGH_QUALITY = 2,     ///< N 32, BlurRadius 3, MipThreshold 16, MaximumMipLevel 5
    /// @deprecated the names of an earlier release (removed in the next one)
    PRESET_LOW = HIGH_PERFORMANCE,
    PRESET_MEDIUM = BALANCED,
    PRESET_HIGH = HIGH_QUALITY
  };

  ///@{
  /**
   * Sets NumberOfSamples, BlurRadius, MipThreshold and MaximumMipLevel to a
   * preset's values (see Preset) with one Modified(). Fewer taps, a
   * narrower filter and coarser MIP levels (a smaller threshold q) cost
   * less; the other parameters keep their values. An unknown preset is
   * ignored with a warning.
   */
  void SetPreset(int preset);
  void SetPresetToHighPerformance() { this->SetPreset(HIGH_PERFORMANCE); }
  void SetPresetToBalanced() { this->SetPreset(BALANCED); }
  void SetPresetToHighQuality() { this->SetPreset(HIGH_QUALITY); }
  static const char* GetPresetAsString(int preset);
  ///@}

  ///@{
  /// @deprecated The names of an earlier release (removed in the next one):
  /// SetPreset and SetPresetTo....
  void SetQualityPreset(int preset) { this->SetPreset(preset); }
  void SetQualityToLow() { this->SetPreset(HIGH_PERFORMANCE); }
  void SetQualityToMedium() { this->SetPreset(BALANCED); }
  void SetQualityToHigh() { this->SetPreset(HIGH_QUALITY); }
  ///@}

  /**
   * Copies the ambient visibility of the last frame rendered for `renderer`
   * (the first renderer the pass rendered if null) into `output`, an image
   * of the viewport's size: float point-data arrays "AmbientVisibility"
   * (after the bilateral filter and, with TemporalAlpha > 0, the temporal
   * accumulation: the AV the image was composited with),
   * "RawAmbientVisibility" (eq. 1 before it),
   * both 1 where layer 0 is empty, and unsigned char "Valid" (1 where
   * layer 0 has a surface). Field data "Radius" (the effective r) and
   * "NumberOfSamples". The render window's context must be current (it is
   * right after Render()). Returns false with an error when there is
   * nothing to capture.
   */
  bool CaptureAmbientVisibility(vtkImageData* output, vtkRenderer* renderer = nullptr);

  /**
   * Computes this frame's ambient visibility (key pyramid, eq. 1-2,
   * bilateral filter and, with TemporalAlpha > 0, the temporal
   * accumulation) for the renderer of `s` from the layers GetGBufferPass()
   * has just built, without drawing into the renderer's framebuffer.
   * Render() calls it between RenderLayers and its composite; a pass that
   * composites AV itself (vtkDeepGIPass) calls it after its own
   * GetGBufferPass()->RenderLayers(s) returned true, then reads the result
   * with ActivateVisibilityTexture. The key pyramid and the gather are
   * those of the renderer's last frame when the G-buffer kept its layers
   * (vtkDeepGBufferPass::GetLayersTime) and every setting the gather reads
   * is the same, as when only the blur changed (vtkDeepGIPass::Converge
   * widens it); where the frame shades more of the guard band than that
   * gather covered, only the added texels are gathered. Returns false (with
   * an error) when the G-buffer has no layers for the renderer or the
   * targets or shaders are unavailable.
   */
  bool UpdateAmbientVisibility(const vtkRenderState* s);

  /**
   * Whether the ambient visibility of `renderer`'s last frame is this
   * frame's too, so that UpdateAmbientVisibility can be skipped, when the
   * G-buffer kept that frame's layers (vtkDeepGBufferPass::ReuseLayers):
   * it exists, was computed with this pass's current settings (its
   * modification time) and without temporal accumulation, whose rotation
   * changes every frame.
   */
  bool CanReuseAmbientVisibility(vtkRenderer* renderer);

  /**
   * Whether a visible actor of `renderer` with opaque geometry has an
   * ambient term (Ambient > 0 and a non-black AmbientColor), i.e. whether
   * the G-buffer's AMBIENT can be non-zero. False for null.
   */
  static bool RendererHasAmbientTerm(vtkRenderer* renderer);

  /**
   * The composition this pass's Composition means for `renderer` now:
   * COMPOSITE_AMBIENT or COMPOSITE_MULTIPLY (AUTOMATIC resolved with
   * RendererHasAmbientTerm). vtkDeepGIPass composes AV the same way.
   */
  int ResolveComposition(vtkRenderer* renderer) const;

  ///@{
  /**
   * Access for passes that composite AV themselves: binds the final AV of
   * the last frame computed for `renderer` (GL_TEXTURE_2D; AV in the red
   * channel, R32F, or RG32F with the layer-0 distance in green when the
   * temporal accumulation ran) to a free texture unit and returns the unit
   * (-1 if there is none). Release it with DeactivateVisibilityTexture.
   * GetVisibilityTextureHandle gives the OpenGL name (0 if none).
   */
  int ActivateVisibilityTexture(vtkRenderer* renderer);
  void DeactivateVisibilityTexture(vtkRenderer* renderer);
  unsigned int GetVisibilityTextureHandle(vtkRenderer* renderer);
  ///@}

  void ReleaseGraphicsResources(vtkWindow* w) override;

  /// The memory of the textures this pass holds for all renderers, in bytes:
  /// the obscurance targets, the temporal history and the key pyramid. Proportional to the
  /// layers' pixels; 0 after ReleaseGraphicsResources.
  vtkTypeInt64 GetTextureBytes();

protected:
  vtkDeepAmbientObscurancePass();
  ~vtkDeepAmbientObscurancePass() override;

  /// The opaque step of the frame: layers, AO, filter, composite.
  void RenderOpaque(const vtkRenderState* s) override;

  /// The texture units of the G-buffer quantities the geometry key reads.
  struct KeyUnits
  {
    int Distance;
    int Normal;
    int Facing; // ALBEDO, whose alpha is the facing
  };

  ///@{
  /// The geometry key and its pyramid, built, or kept from an earlier frame,
  /// and bound until UnbindKeyPyramid.
  bool BuildKeyPyramid(vtkDeepAmbientObscuranceRendererState& state, vtkOpenGLRenderWindow* window,
    const KeyUnits& units, int layers);
  bool BindKeyPyramid(vtkDeepAmbientObscuranceRendererState& state, vtkOpenGLRenderWindow* window);
  ///@}
  static void UnbindKeyPyramid(
    vtkDeepAmbientObscuranceRendererState& state, vtkOpenGLRenderWindow* window);

  ///@{
  /// The stages of UpdateAmbientVisibility, in order.
  bool PrepareTargets(
    const EffectFrame& frame, vtkDeepAmbientObscuranceRendererState& state, bool temporal);
  void ComputeRawVisibility(
    const EffectFrame& frame, vtkDeepAmbientObscuranceRendererState& state, bool extendRaw);
  void FilterVisibility(const EffectFrame& frame, vtkDeepAmbientObscuranceRendererState& state);
  void AccumulateVisibility(
    const EffectFrame& frame, vtkDeepAmbientObscuranceRendererState& state, int distanceUnit);
  ///@}

  double Radius = 1.0;
  bool AutomaticRadius = true;
  double AutomaticRadiusFraction = 0.05;
  double EffectiveRadius = 0.0;
  int Estimator = VISIBILITY_BITMASK;
  double Bias = 0.01;
  double Epsilon = 0.0001;
  double Intensity = 1.0;
  int NumberOfSamples = 12;
  bool UseSecondLayer = true;
  int BlurRadius = 3;
  double GuardBandShadedFraction = 0.5;
  double BlurPlaneTolerance = 0.02;
  double BlurNormalPower = 8.0;
  int Composition = COMPOSITE_AUTOMATIC;
  int EffectiveComposition = COMPOSITE_MULTIPLY;
  double MipThreshold = 8.0;
  int MaximumMipLevel = 5;
  double TemporalAlpha = 0.0;

private:
  vtkDeepAmbientObscurancePass(const vtkDeepAmbientObscurancePass&) = delete;
  void operator=(const vtkDeepAmbientObscurancePass&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
