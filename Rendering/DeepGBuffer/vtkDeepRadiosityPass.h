/**
 * @class   vtkDeepRadiosityPass
 * @brief   Screen-space radiosity (one diffuse bounce per frame) over a deep G-buffer.
 *
 * Implements sections 3.2, 3.3 and 3.5 (equations 3-7, Table 2) of Mara,
 * McGuire, Nowrouzezahrai and Luebke, "Deep G-Buffers for Stable Global
 * Illumination Approximation" (HPG 2016), with the spiral taps of section
 * 3.4. Put it on a renderer (`renderer->SetPass(pass)`) and it renders the
 * whole frame like vtkDeepAmbientObscurancePass: camera, lights, the opaque
 * props into the layers of a vtkDeepGBufferPass (GetGBufferPass();
 * SetGBufferPass() shares one), the indirect light, the composite, then the
 * G-buffer pass's translucent, volumetric and overlay steps.
 *
 * Quantities and units (those of the G-buffer): RADIANCE is VTK's outgoing
 * radiance L_o; the direct radiance of a surface is RADIANCE - AMBIENT; rho
 * is ALBEDO. For the surfaces X of layers 0 and 1 of every pixel:
 *
 *   E(X) ~= 2 pi / M sum_i B(Y_i) max(w_i . n_X, 0)        (eq. 4)
 *   L_ind(X) = rho_X boost(rho_X) E(X) / pi                 (eq. 6)
 *   boost(rho) = (max rho - min rho) / max rho  or 1        (eq. 7)
 *
 * E is the irradiance of eq. 3 with B / pi = L_o, i.e. the integral of the
 * incoming radiance times the cosine over the hemisphere, estimated from N
 * spiral taps (section 3.4: kappa_i = (i + u_i) / N, h_i = r_p kappa_i
 * pixels, theta_i = 2 pi kappa_i tau(N) + phi, phi the interleaved
 * gradient noise of the pixel as in vtkDeepAmbientObscurancePass, r_p the
 * world radius r projected at layer 0's depth; the same screen taps serve
 * both layers). u_i is 1/2 as in the paper, except at full resolution for
 * the taps after the first where the rings r_p / N are wider than a texel
 * of the minimum MIP level: there u_i = fract(2 phi / pi), an offset
 * across the ring that keeps a bright object's light from arriving in
 * steps (rings around it). At each tap the surfaces of both layers are candidates Y; a
 * candidate passes eq. 5 when |Y - X| < r, w.n_X > epsilon and, with
 * UseNormalTest, w.n_Y < -epsilon (w = (Y - X) / |Y - X|, epsilon =
 * COSINE_EPSILON, see below); the tap takes the passing candidate with the
 * larger contribution |B (w.n_X)| and is rejected when none passes (also
 * when it falls outside the G-buffer's layers, which include its guard
 * band: the G-buffer this pass creates has DEFAULT_GUARD_BAND). M counts the taps that were not
 * rejected; M = 0 gives E = 0. The confidence is M / N. SetEstimator
 * chooses eq. 4's division by M (ACCEPTED_TAPS) or an alternative
 * (ALL_TAPS: by N; SOLID_ANGLE, the default: each tap weighted by the solid
 * angle of its patch).
 *
 * Taps read MIP level m_i = clamp(floor(log2(h_i / q)), MinimumMipLevel,
 * MaximumMipLevel) of a rotated-grid pyramid (SAO's minification): the
 * pass reads the level-0 texel that level m stores at the tap's coarse
 * texel (the same texel vtkDeepAmbientObscurancePass's key pyramid
 * holds), so a coarse level moves the tap to a texel of a coarser grid
 * (more correlated taps, Table 2's trade) and every sample is an exact
 * surface point. With AverageFarTaps (the default) a tap above the minimum
 * level takes B as the mean over its coarse texel's block instead of that
 * one texel's; the bounce input is computed only at the texels of the
 * minimum level, the only ones the taps read.
 *
 * Multiple bounces (section 3.3): the radiosity of a tap is
 *   B(Y) = direct(Y) + delta L_ind,t-1(Y)
 * with L_ind,t-1 = rho boost E_t-1 / pi from the last frame's final
 * irradiance, reverse-reprojected to Y and taken from whichever of the last
 * frame's layers lies within the reprojection tolerance of it (0 where
 * none does). The comparison is made at the centre of the previous texel
 * the point falls into: Y's plane (its current normal) is met with that
 * texel's ray, so that a slanted surface is not rejected for the sub-pixel
 * offset of the reprojection (at grazing angles, |n.ray| < 0.05, Y's own
 * depth is used). Frame t therefore adds the t-th bounce (Figure 4) and
 * propagates light across both layers (Figure 5). delta = Damping.
 * Temporal filter: E_t = E (1 - alpha) + reproject(E_t-1) alpha where the
 * reprojected point lies within the tolerance of either previous layer,
 * else E_t = E; alpha = TemporalAlpha. While alpha > 0 the spiral rotation
 * phi gets a per-frame offset 2 pi fract(k / golden ratio) so that frames
 * sample other directions. History (per renderer) is reset on a resize, a
 * change of layer count, ReleaseGraphicsResources, when the G-buffer is
 * unavailable, and when the renderer was rendered without this pass.
 *
 * Reconstruction: a separable bilateral filter of E and the confidence
 * (BlurRadius taps on each side in each direction, Gaussian sigma = BlurRadius / 2,
 * times the plane and normal weights of vtkDeepAmbientObscurancePass), per
 * layer, before the temporal filter.
 *
 * Confidence fallback (off by default, section 3.2, Figure 9): the
 * outgoing indirect radiance becomes c L_ind + (1 - c) rho E_env / pi, c
 * the filtered confidence, E_env the environment irradiance (default
 * pi times the renderer's ambient colour, i.e. a uniform environment of
 * that radiance). It is not propagated to later bounces.
 *
 * Composite: layer 0's colour = RADIANCE + L_ind (float, alpha kept) when
 * the G-buffer displays RADIANCE; the G-buffer's image otherwise. Pixels
 * where layer 0 is empty keep the background.
 *
 * Textures (per renderer, viewport size, two of each: layers 0 and 1):
 * | texture   | format  | content                                            |
 * |-----------|---------|----------------------------------------------------|
 * | bounce    | RGBA16F | B of the taps (rgb)                                |
 * | raw       | RGBA16F | eq. 4 E (rgb) and confidence M / N (a)             |
 * | blur tmp  | RGBA16F | after the horizontal pass                          |
 * | filtered  | RGBA16F | after the vertical pass                            |
 * | history   | RGBA32F | x2 (ping-pong): E_t (rgb), layer distance (a)      |
 * | indirect  | RGBA16F | L_ind, fallback included (rgb), confidence (a)     |
 * Reads: the G-buffer's DEPTH, NORMAL, RADIANCE, AMBIENT and ALBEDO
 * arrays (layers 0 and 1). Writes: the renderer's colour and depth.
 * IRRADIANCE (history) and INDIRECT_RADIANCE are accessible through
 * ActivateTexture for a pass that composites them itself.
 *
 * Not implemented: the guard band of Table 2 (the G-buffer has none, so
 * the preset's guard-band fraction has nothing to act on), shadow maps
 * (the direct light is VTK's, unshadowed unless a shadow pass lit the
 * G-buffer), and visibility between X and Y (the paper assumes it too).
 *
 * Bad input never crashes: a non-finite or negative radius, tolerance or
 * environment irradiance, a sample count outside 1..98 and alpha or delta
 * outside [0, 1] are reported with vtkWarningMacro and replaced by the
 * nearest valid value; an empty scene (automatic radius 0) and a frame
 * without lights are reported once per renderer and give L_ind = 0 (VTK
 * draws props unlit at their full colour when no light is on; that colour
 * is not bounced).
 *
 * @sa vtkDeepGBufferPass vtkDeepAmbientObscurancePass
 */

#ifndef vtkDeepRadiosityPass_h
#define vtkDeepRadiosityPass_h

#include "vtkDeepGIRenderingModule.h" // for export macro
#include "vtkDeepGISetGet.h"          // for vtkDeepGISetClampMacro
#include "vtkDeepGIShaderConstants.h" // for the enum values shared with GLSL
#include "vtkDeepScreenSpacePass.h"

#include <memory> // for std::unique_ptr

class vtkImageData;
class vtkShaderProgram;
struct vtkDeepRadiosityRendererState;
class vtkRenderer;

class VTKDEEPGIRENDERING_EXPORT vtkDeepRadiosityPass : public vtkDeepScreenSpacePass
{
public:
  static vtkDeepRadiosityPass* New();
  vtkTypeMacro(vtkDeepRadiosityPass, vtkDeepScreenSpacePass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Layers that receive and send indirect light (G-buffer layers 0 and 1).
  static constexpr int NUMBER_OF_LAYERS = 2;

  /// Cosine threshold of eq. 5's tests: Oct16 normals are quantised to
  /// about 0.5 degree, so a tap on X's own plane has w.n_X of either sign
  /// within about 0.009; it is rejected rather than counted in M.
  static constexpr double COSINE_EPSILON = 0.01;

  /// With OuterSamples, the outer ring's taps lie between r_p and this
  /// times r_p, and every tap accepts surfaces within this times r.
  static constexpr double OUTER_RADIUS_SCALE = 1.5;

  /// Upper bound of E, B and L (irradiance and radiance units): the largest
  /// half float, the range of the G-buffer's RADIANCE and of the radiosity's
  /// RGBA16F targets. It keeps a divergent configuration (rho = 1, delta = 1
  /// in a closed room, whose true radiosity is infinite) finite.
  static constexpr double IRRADIANCE_LIMIT = 65504.0;

  /// The largest ratio of successive bounces that ExtrapolateBounces
  /// extrapolates (a factor rho / (1 - rho) of at most 4); a larger or
  /// negative ratio is not a converging series and is not extrapolated.
  static constexpr double MAXIMUM_EXTRAPOLATED_RATIO = 0.8;

  /// How closely the last two ratios of successive bounces must agree for
  /// ExtrapolateBounces to take the series as geometric.
  static constexpr double EXTRAPOLATION_RATIO_AGREEMENT = 0.1;

  /// The outputs accessible with ActivateTexture.
  enum Quantity
  {
    IRRADIANCE = 0,       ///< RGBA32F: E_t after both filters (rgb), layer distance (a)
    INDIRECT_RADIANCE = 1 ///< RGBA16F: L_ind with the fallback (rgb), confidence (a)
  };

  /// How the gathered taps are summed into E (see SetEstimator).
  enum Estimator
  {
    ACCEPTED_TAPS = DEEP_ESTIMATOR_ACCEPTED_TAPS, ///< eq. 4 as printed: 2 pi / M sum B (w.n_X)
    ALL_TAPS = DEEP_ESTIMATOR_ALL_TAPS,      ///< 2 pi / N sum B (w.n_X): rejected taps count as 0
    SOLID_ANGLE = DEEP_ESTIMATOR_SOLID_ANGLE ///< sum B (w.n_X) dOmega_i, each tap's solid angle
  };

  /// Table 2's parameter sets (BALANCED at minimum MIP level 1), with the resolution divisor of
  /// each.
  enum Preset
  {
    HIGH_PERFORMANCE = 0, ///< N 13, 9 filter taps, no n_Y test, minimum MIP level 3, 10 % of the
                          ///< guard band shaded, divisor 2
    BALANCED = 1,         ///< N 14, 11 filter taps, n_Y test, minimum MIP level 1, 50 %, divisor 1
                          ///< (defaults)
    HIGH_QUALITY = 2      ///< N 30, 13 filter taps, n_Y test, minimum MIP level 0, 80 %, divisor 1
  };

  /// The guard band (vtkDeepGBufferPass::SetGuardBand) of the G-buffer this
  /// pass creates: 0.1 of the viewport's height on each side.
  static constexpr double DEFAULT_GUARD_BAND = 0.1;

  ///@{
  /**
   * World-space gather radius r: taps farther than r from X are rejected.
   * Setting a value switches AutomaticRadius off. NaN and infinities are
   * rejected with a warning (the previous value stays); negative values
   * are clamped to 0 with a warning (r = 0 gives no indirect light).
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
   * the bounds of the renderer's visible props, every frame (6.7 in
   * vtkDeepGIDemoScene's 10 x 4 x 8 room, whose diagonal is 13.4).
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
   * The fraction of the diagonal that gives the automatic r (default 0.5,
   * clamped to [0, 1]). Half the diagonal reaches the light of the far
   * walls of an interior, which a smaller radius misses (the final image's
   * error against the reference falls by a factor 2-4 in interiors and on
   * every other benchmark scene from 0.1 to 0.5, Documentation/
   * lighting-model.md); the far taps read coarse MIP levels, so the cost
   * does not grow with r. The outer ring (OuterSamples) reaches 1.5 r,
   * the far walls of closed interiors; spreading the spiral itself over
   * 0.75 of the diagonal instead raises an object's error by up to 12 %
   * (fewer taps near X, where its own folds bounce most of its light;
   * Documentation/radiosity.md).
   *
   * @unit fraction of the diagonal
   * @range 0 to 1, clamped
   * @default 0.5
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
   * Number of spiral taps N, 1 to 98. Default 14 (BALANCED). Values
   * outside are clamped with a warning (N = 99 becomes 98: Listing 3 has
   * no tau for it).
   *
   * @unit taps
   * @range 1 to 98; outside: warning and clamp (99 -> 98)
   * @default 14
   */
  void SetNumberOfSamples(int samples);
  vtkGetMacro(NumberOfSamples, int);
  ///@}

  ///@{
  /**
   * Taps K in a ring beyond the spiral, from r_p to OUTER_RADIUS_SCALE x
   * r_p (default 4; 0: none, the paper's gather). With K > 0 every tap
   * accepts surfaces within
   * OUTER_RADIUS_SCALE x r, the spiral's N taps cover the disc of r_p as
   * without them, and the K taps, one in each K-th of the circle from the
   * spiral's rotation on, stand for the ring's area / K each (SOLID_ANGLE;
   * ACCEPTED_TAPS and ALL_TAPS count them like the spiral's, out of N + K).
   * In an interior they add the light of the far walls without spreading
   * the N taps over a larger disc, which costs an object the light of its
   * own folds. With 4 the image benchmark's error falls by 14-66 % in the
   * Cornell box and the stairs room and by 0-9 % on the other scenes, for
   * every preset (Documentation/radiosity.md). A tap that finds no surface
   * costs little: the gather takes 30-60 % longer in the stairs room and
   * no measurably longer for an object on a floor. SetPreset does not
   * change it.
   *
   * @unit taps
   * @range 0 to 32, clamped
   * @default 4
   */
  vtkDeepGISetClampMacro(OuterSamples, int, 0, 32);
  vtkGetMacro(OuterSamples, int);
  ///@}

  ///@{
  /**
   * The n_Y test of eq. 5 (w.n_Y < 0: Y faces X). On by default
   * (BALANCED). Off: less bandwidth and variance, more bias (light from
   * surfaces that face away from X is gathered).
   *
   * @range on/off
   * @default on
   */
  vtkSetMacro(UseNormalTest, bool);
  vtkGetMacro(UseNormalTest, bool);
  vtkBooleanMacro(UseNormalTest, bool);
  ///@}

  ///@{
  /**
   * The estimator of E from the taps (eq. 4 and alternatives in the
   * paper's framework; same taps, eq. 5 tests and confidence M / N):
   * - ACCEPTED_TAPS (the paper's eq. 4): 2 pi / M sum B (w.n_X).
   *   Dividing by the M accepted taps instead of N treats the rejected
   *   directions as if they saw the same light as the accepted ones: next
   *   to a single bright surface, where few taps pass, E is overestimated
   *   (on average 1.7x to 5.6x against the ray-traced reference limited
   *   to r, see Documentation/benchmark-radiosity.md).
   * - ALL_TAPS: 2 pi / N sum B (w.n_X): a rejected tap (beyond r, below
   *   X's horizon, facing away, off screen) contributes 0.
   * - SOLID_ANGLE: sum B (w.n_X) dOmega_i with dOmega_i the solid angle,
   *   seen from X, of the surface patch a tap stands for (its screen ring
   *   2 pi h_i r_p / N pixels^2, projected to Y's depth and tilt, times
   *   (-w.n_Y) / |Y - X|^2), with E at most 2 pi max B as with eq. 4: the
   *   form-factor sum of the visible surfaces; it reads n_Y even without
   *   UseNormalTest.
   * Default SOLID_ANGLE: against the ray-traced one-bounce irradiance
   * limited to r its RMSE is 2.6x to 6.4x lower than eq. 4's at BALANCED
   * and HIGH_QUALITY on the three scenes of
   * Documentation/benchmark-radiosity.md without emitters (1.2x to 1.4x on
   * the lamp-lit Cornell box), where eq. 4 is 2.4x to 5.6x too bright on
   * average. SetPreset does not change the estimator.
   * Values outside the enum are clamped.
   * See Documentation/radiosity.md and Documentation/benchmark-radiosity.md.
   *
   * @range ACCEPTED_TAPS 0, ALL_TAPS 1, SOLID_ANGLE 2; clamped
   * @default SOLID_ANGLE
   */
  vtkSetClampMacro(Estimator, int, ACCEPTED_TAPS, SOLID_ANGLE);
  vtkGetMacro(Estimator, int);
  void SetEstimatorToAcceptedTaps() { this->SetEstimator(ACCEPTED_TAPS); }
  void SetEstimatorToAllTaps() { this->SetEstimator(ALL_TAPS); }
  void SetEstimatorToSolidAngle() { this->SetEstimator(SOLID_ANGLE); }
  static const char* GetEstimatorAsString(int estimator);
  ///@}

  ///@{
  /**
   * Eq. 7's colour boost of the reflected light. Off by default: boost = 1
   * conserves energy (and the boost of a grey or white surface is 0, so
   * with it on only saturated surfaces reflect indirect light).
   *
   * @range on/off
   * @default off
   */
  vtkSetMacro(UseColorBoost, bool);
  vtkGetMacro(UseColorBoost, bool);
  vtkBooleanMacro(UseColorBoost, bool);
  ///@}

  ///@{
  /**
   * Separable bilateral reconstruction: taps on each side of each separable
   * pass, 0 to 16 (Table 2's 9, 11 and 13 taps are radii 4, 5 and 6); 0
   * disables the filter. Default 5.
   * SetFilterTaps(t) / GetFilterTaps() (taps per direction, 2 BlurRadius + 1) are the deprecated
   * names of an earlier release, removed in the next.
   *
   * @unit taps on each side
   * @range 0 to 16, clamped
   * @default 5
   */
  vtkSetClampMacro(BlurRadius, int, 0, 16);
  vtkGetMacro(BlurRadius, int);
  ///@}

  ///@{
  /**
   * Plane weight of the bilateral filter: the tolerance as a fraction of
   * the centre's distance (default 0.02), as in
   * vtkDeepAmbientObscurancePass.
   *
   * @unit fraction of the centre's distance
   * @range 1e-6 to 1, clamped
   * @default 0.02
   */
  vtkDeepGISetClampMacro(BlurPlaneTolerance, double, 1e-6, 1.0);
  vtkGetMacro(BlurPlaneTolerance, double);
  ///@}

  ///@{
  /**
   * Normal weight of the bilateral filter: the exponent (default 8),
   * compiled into the filter's shader as in vtkDeepAmbientObscurancePass.
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
   * @deprecated The filter's taps per direction, 2 BlurRadius + 1 (the name
   * of an earlier release; removed in the next one). SetFilterTaps(t) sets
   * BlurRadius (t - 1) / 2 (t clamped to 1..33).
   */
  void SetFilterTaps(int taps);
  int GetFilterTaps() { return 2 * this->BlurRadius + 1; }
  ///@}

  ///@{
  /**
   * Fraction of the G-buffer's guard band (vtkDeepGBufferPass::SetGuardBand)
   * for which indirect light is computed, 0 to 1 (Table 2's last column:
   * 0.1, 0.5, 0.8). Default 0.5. The gather always reads the whole guard
   * band (its direct light is an input); the shaded part also keeps its
   * result, so the next frame's bounce and temporal filter find history for
   * surfaces that move into the frame (section 3.5). Smaller is faster and
   * less robust under camera motion. A change resets the history. NaN is
   * ignored and values outside [0, 1] are clamped, with a warning.
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
   * MIP levels of the taps: q, the screen radius in pixels beyond which
   * taps read coarser levels (taps farther than 2q pixels use coarser
   * levels). Default 8, clamped to [1, 65536].
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
   * Minimum MIP level of the taps (0 to 15, default 1, BALANCED's; Table
   * 2's is 2, whose sources, one texel in 16, made the interiors' indirect
   * light 2-11 % darker); also limited by floor(log2(max(width, height))).
   *
   * @unit level
   * @range 0 to 15, clamped
   * @default 1
   */
  vtkSetClampMacro(MinimumMipLevel, int, 0, 15);
  vtkGetMacro(MinimumMipLevel, int);
  ///@}

  ///@{
  /**
   * The coarsest MIP level of the taps (0 to 15, default 5; the minimum
   * wins when larger); also limited by floor(log2(max(width, height))).
   *
   * @unit level
   * @range 0 to 15, clamped (the minimum wins when larger)
   * @default 5
   */
  vtkSetClampMacro(MaximumMipLevel, int, 0, 15);
  vtkGetMacro(MaximumMipLevel, int);
  ///@}

  ///@{
  /**
   * Whether a tap on a MIP level m above the minimum reads the mean
   * radiosity B of the 2^m x 2^m block of surfaces it stands for (a
   * box-filtered pyramid of B, weighted by coverage) instead of the B of
   * the one texel whose position it uses. On by default: a far tap then
   * estimates the light of its whole patch, which removes most of the
   * variance, and the low-frequency blotches, of a large radius. The
   * positions and normals of eq. 5 stay the rotated grid's point samples.
   *
   * @range on/off
   * @default on
   */
  vtkSetMacro(AverageFarTaps, bool);
  vtkGetMacro(AverageFarTaps, bool);
  vtkBooleanMacro(AverageFarTaps, bool);
  ///@}

  ///@{
  /**
   * The gather's resolution divisor D, 1 or 2: the gather computes E for
   * the layers' texels D q only (D^2 times fewer receivers; its taps and
   * their sources, the bounce input, stay the layers'), the filters and the
   * temporal filter run on that grid (the filter's taps span D times more
   * layer texels), and a joint bilateral upsampling (plane and normal
   * weights, vtkDeepRadiosityUpsampleFS) brings E back to layer 0's texels,
   * where eq. 6 applies each texel's own albedo. 1 (default) gathers at
   * every texel, as the paper does; HIGH_PERFORMANCE uses 2 (see SetPreset
   * and Documentation/performance.md for its cost and error). Other values
   * are clamped with a warning.
   * See Documentation/radiosity.md (section Resolution divisor).
   *
   * @range 1 or 2; outside: warning and clamp
   * @default 1 (HIGH_PERFORMANCE: 2)
   */
  void SetResolutionDivisor(int divisor);
  vtkGetMacro(ResolutionDivisor, int);
  ///@}

  ///@{
  /**
   * Damping delta of the propagated bounce (section 3.3), in [0, 1];
   * default 1: every bounce counts in full, as in the lighting model and
   * its reference (Documentation/lighting-model.md). 0 gives the single
   * bounce every frame. With eq. 4 (ACCEPTED_TAPS) the gathered estimate
   * can exceed the true irradiance by up to 2x (it divides by M, and
   * w.n_X <= 1), so with that estimator the bounces stay bounded for any
   * albedo only when 2 delta max(rho boost) < 1. The default SOLID_ANGLE
   * estimator weights each tap by the solid angle of its patch, which
   * follows the true irradiance instead; the image benchmark's scenes
   * (albedo up to 1) converge at delta 1 (Documentation/radiosity.md). NaN is rejected
   * and values outside [0, 1] are clamped, with a warning. delta is the
   * weight of last frame's L_ind in this frame's B.
   *
   * @range 0 to 1; outside: warning and clamp; NaN: warning, ignored
   * @default 1
   */
  void SetDamping(double delta);
  vtkGetMacro(Damping, double);
  ///@}

  ///@{
  /**
   * Temporal filter weight alpha of the reprojected history, in [0, 1];
   * default 0.85 (the paper's). 0 turns the filter off; 1 keeps the first
   * frame's E forever at a still camera. NaN is rejected and values
   * outside [0, 1] are clamped, with a warning.
   * The filter is E_t = E (1 - alpha) + reproject(E_t-1) alpha.
   *
   * @range 0 to 1; outside: warning and clamp; NaN: warning, ignored
   * @default 0.85
   */
  void SetTemporalAlpha(double alpha);
  vtkGetMacro(TemporalAlpha, double);
  ///@}

  ///@{
  /**
   * Frames S over which the gather's taps are spread while the temporal
   * filter is on (TemporalAlpha > 0; default 1: every tap in every frame).
   * In frame t receiver q gathers the taps i = t + q.x + q.y mod S of the
   * N + K, each standing for S taps: neighbouring receivers take different
   * shares, which the blur mixes, and the S frames of a cycle gather every
   * tap once, which the temporal filter averages (interleaved sampling).
   * With 2 the gather takes about 40 % less time (BALANCED, a bunny on a
   * floor, llvmpipe: 259 to 160 ms of a 630-770 ms frame), the image a
   * still camera settles to is as close to the ray-traced reference as with
   * 1 (within -1 to +3 % RMSE on seven scenes), and a moving camera's
   * indirect light changes by a third more from frame to frame
   * (Documentation/radiosity.md,
   * "Interleaved taps"). With TemporalAlpha 0 (Converge) every frame
   * gathers every tap. SetPreset does not change it.
   *
   * @unit frames
   * @range 1 to 8, clamped
   * @default 1
   */
  vtkDeepGISetClampMacro(TemporalInterleave, int, 1, 8);
  vtkGetMacro(TemporalInterleave, int);
  ///@}

  ///@{
  /**
   * When on, frames at a still camera (the view and projection of the
   * history's frame, as in vtkDeepGIPass::Converge) read a texel's last
   * frame at the texel itself: the bounce input (at ResolutionDivisor 1)
   * and the temporal filter (on any grid, and whenever TemporalAlpha is 0)
   * run variants of their shaders compiled without the reprojection, which
   * there finds that texel: the same pixels as with it off, without the
   * reprojection's arithmetic, which a CPU renderer (running both sides of
   * a branch) otherwise executes at every texel. Off is for comparisons.
   *
   * @range on/off
   * @default on
   */
  vtkSetMacro(SkipStillCameraReprojection, bool);
  vtkGetMacro(SkipStillCameraReprojection, bool);
  vtkBooleanMacro(SkipStillCameraReprojection, bool);
  ///@}

  ///@{
  /**
   * Bounce extrapolation for still images (default off; vtkDeepGIPass::
   * Converge turns it on). While TemporalAlpha is 0 each frame adds one
   * bounce, E_k = E_k-1 + T^k E_1, and the increments fall geometrically,
   * so the bounces still to come sum to about (E_k - E_k-1) rho / (1 - rho),
   * rho the ratio of successive increments (the "ambient term" of
   * progressive refinement radiosity, Cohen, Chen, Wallace and Greenberg
   * 1988). On: the outgoing radiance (INDIRECT_RADIANCE, what the composite
   * shows) is eq. 6 of E_k + (E_k - E_k-1) rho / (1 - rho) where the last
   * frame's irradiance is of the same surface. rho is measured over two
   * frames, sqrt(m_k / m_k-2), m_k the mean of |E_k - E_k-1| over layer 0
   * (a part of the increments can alternate from frame to frame), and used
   * when it is at most MAXIMUM_EXTRAPOLATED_RATIO and the same measure one
   * frame earlier agrees within EXTRAPOLATION_RATIO_AGREEMENT: from the
   * fourth frame with TemporalAlpha 0 when they start without history.
   * The bounces themselves (IRRADIANCE, the history the next bounce reads)
   * are not changed, so the fixed point is the same. GetLastBounceExtrapolation
   * gives the factor rho / (1 - rho) of the last frame (0 when none).
   *
   * @range on/off
   * @default off
   */
  vtkSetMacro(ExtrapolateBounces, bool);
  vtkGetMacro(ExtrapolateBounces, bool);
  vtkBooleanMacro(ExtrapolateBounces, bool);
  ///@}

  /// The factor rho / (1 - rho) ExtrapolateBounces applied in the last
  /// frame; 0 when none was.
  ///
  /// @readonly
  vtkGetMacro(LastBounceExtrapolation, double);

  ///@{
  /**
   * Reprojection tolerance (world units): history is used where the
   * reprojected point's camera depth is within it of either previous
   * layer. Setting a value switches AutomaticReprojectionTolerance off;
   * NaN and infinities are rejected, negative values become 0, with a
   * warning.
   *
   * @unit world units
   * @range >= 0, finite; negative: warning, 0; NaN/inf: warning, ignored
   * @default 0.01 (unused while automatic)
   */
  void SetReprojectionTolerance(double tolerance);
  vtkGetMacro(ReprojectionTolerance, double);
  ///@}

  ///@{
  /**
   * When on (default), the reprojection tolerance is
   * AutomaticReprojectionFraction times the scene diagonal.
   *
   * @range on/off
   * @default on
   */
  vtkSetMacro(AutomaticReprojectionTolerance, bool);
  vtkGetMacro(AutomaticReprojectionTolerance, bool);
  vtkBooleanMacro(AutomaticReprojectionTolerance, bool);
  ///@}

  ///@{
  /**
   * The fraction of the scene diagonal that gives the automatic
   * reprojection tolerance (default 2.5e-4, the paper's 1 cm in scenes
   * about 40 m across).
   *
   * @unit fraction of the diagonal
   * @range 0 to 1, clamped
   * @default 2.5e-4
   */
  vtkDeepGISetClampMacro(AutomaticReprojectionFraction, double, 0.0, 1.0);
  vtkGetMacro(AutomaticReprojectionFraction, double);
  ///@}

  /// The tolerance used by the last frame (world units).
  ///
  /// @unit world units
  /// @readonly
  vtkGetMacro(EffectiveReprojectionTolerance, double);

  ///@{
  /**
   * Confidence fallback (section 3.2, Figure 9): L = c L_ind + (1 - c) rho
   * E_env / pi. Off by default: VTK's default renderer ambient colour is
   * white, i.e. an environment as bright as a light of intensity 1 from
   * every direction, which would brighten every low-confidence pixel by
   * its full albedo; turn it on with an environment that matches the scene.
   *
   * @range on/off
   * @default off
   */
  vtkSetMacro(ConfidenceFallback, bool);
  vtkGetMacro(ConfidenceFallback, bool);
  vtkBooleanMacro(ConfidenceFallback, bool);
  ///@}

  ///@{
  /**
   * Environment irradiance E_env (RGB, irradiance units: pi times the
   * radiance of a uniform environment), used by ConfidenceFallback.
   * Setting a value switches AutomaticEnvironmentIrradiance off; NaN and
   * infinite components are rejected, negative ones become 0, with a
   * warning.
   *
   * @type double[3]
   * @unit irradiance (pi x radiance)
   * @range >= 0, finite per component; negative: warning, 0; NaN/inf: warning, ignored
   * @default (0, 0, 0) (unused while automatic)
   */
  void SetEnvironmentIrradiance(double r, double g, double b);
  void SetEnvironmentIrradiance(const double e[3])
  {
    this->SetEnvironmentIrradiance(e[0], e[1], e[2]);
  }
  vtkGetVector3Macro(EnvironmentIrradiance, double);
  ///@}

  ///@{
  /**
   * When on (default), E_env is pi times the renderer's ambient colour
   * (vtkRenderer::GetAmbient).
   *
   * @range on/off
   * @default on
   */
  vtkSetMacro(AutomaticEnvironmentIrradiance, bool);
  vtkGetMacro(AutomaticEnvironmentIrradiance, bool);
  vtkBooleanMacro(AutomaticEnvironmentIrradiance, bool);
  ///@}

  /// E_env used by the last frame.
  ///
  /// @unit irradiance
  /// @readonly
  vtkGetVector3Macro(EffectiveEnvironmentIrradiance, double);

  ///@{
  /**
   * Sets NumberOfSamples, BlurRadius, UseNormalTest, MinimumMipLevel and
   * GuardBandShadedFraction to Table 2's values (BALANCED's minimum MIP
   * level 1 instead of 2), and ResolutionDivisor (see Preset), with one
   * Modified(). An unknown preset is ignored with a warning.
   */
  void SetPreset(int preset);
  void SetPresetToHighPerformance() { this->SetPreset(HIGH_PERFORMANCE); }
  void SetPresetToBalanced() { this->SetPreset(BALANCED); }
  void SetPresetToHighQuality() { this->SetPreset(HIGH_QUALITY); }
  static const char* GetPresetAsString(int preset);
  ///@}

  ///@{
  /**
   * Access for passes that composite the radiosity themselves: binds the
   * GL_TEXTURE_2D of `quantity` (IRRADIANCE or INDIRECT_RADIANCE) of layer
   * `layer` (0 or 1) of the last frame rendered for `renderer` to a free
   * texture unit and returns it (-1 if there is none). Release it with
   * DeactivateTexture. GetTextureHandle gives the OpenGL name (0 if none).
   * With a ResolutionDivisor of 2, IRRADIANCE of both layers and
   * INDIRECT_RADIANCE of layer 1 have the gather's grid size (half the
   * layers' per axis, rounded up); INDIRECT_RADIANCE of layer 0 has the
   * layers' size.
   */
  int ActivateTexture(vtkRenderer* renderer, int quantity, int layer);
  void DeactivateTexture(vtkRenderer* renderer, int quantity, int layer);
  unsigned int GetTextureHandle(vtkRenderer* renderer, int quantity, int layer);
  ///@}

  /**
   * Copies the radiosity of the last frame rendered for `renderer` (the
   * first renderer the pass rendered if null) into `output`, an image of
   * the viewport's size, with float point-data arrays per layer j = 0, 1:
   * "Irradiance_j" (RGB, E_t after both filters), "IndirectRadiance_j"
   * (RGB, L_ind with the fallback when it is on), "Confidence_j" (filtered
   * M / N), "FilteredIrradiance_j" (RGB, this frame's E after the bilateral
   * filter, before the temporal one), "RawIrradiance_j" (RGB) and
   * "RawConfidence_j" (eq. 4 and M / N of this frame's gather before any
   * filter), all 0 where layer j is
   * empty, and unsigned char "Valid_j". Field data: "Radius",
   * "NumberOfSamples", "NumberOfLayers", "ReprojectionTolerance",
   * "EnvironmentIrradiance" (3) and "Frames" (frames since the history was
   * reset, 1 for a single bounce). The context must be current (it is right
   * after Render()). Returns false with an error when there is nothing.
   */
  bool CaptureIrradiance(vtkImageData* output, vtkRenderer* renderer = nullptr);

  /**
   * Computes this frame's radiosity textures (bounce input, gather,
   * filters, history, INDIRECT_RADIANCE) for the renderer of `s` from the
   * layers GetGBufferPass() has just built, without drawing into the
   * renderer's framebuffer. Render() calls it between RenderLayers and its
   * composite; a pass that composites the radiosity itself calls it after
   * its own GetGBufferPass()->RenderLayers(s) returned true, then reads the
   * textures with ActivateTexture. Returns false (with an error) when the
   * targets or shaders are unavailable.
   */
  bool UpdateRadiosity(const vtkRenderState* s);

  /// Whether `renderer` has a light that is switched on with a positive
  /// intensity (without one there is no direct light to bounce), or will
  /// have VTK's automatic headlight in this frame (no light switched on and
  /// AutomaticLightCreation on). False for null.
  static bool RendererHasLightOn(vtkRenderer* renderer);

  void ReleaseGraphicsResources(vtkWindow* w) override;

  /// The memory of the textures this pass holds for all renderers, in bytes:
  /// the radiosity targets and history of both layers. Proportional to the layers' pixels; 0 after
  /// ReleaseGraphicsResources.
  vtkTypeInt64 GetTextureBytes();

protected:
  vtkDeepRadiosityPass();
  ~vtkDeepRadiosityPass() override;

  /// The opaque step of the frame: layers, radiosity, filters, composite.
  void RenderOpaque(const vtkRenderState* s) override;

  double Radius = 1.0;
  bool AutomaticRadius = true;
  double AutomaticRadiusFraction = 0.5;
  double EffectiveRadius = 0.0;
  int NumberOfSamples = 14;
  int OuterSamples = 4;
  bool UseNormalTest = true;
  bool AverageFarTaps = true;
  int Estimator = SOLID_ANGLE;
  bool UseColorBoost = false;
  int BlurRadius = 5;
  double GuardBandShadedFraction = 0.5;
  double BlurPlaneTolerance = 0.02;
  double BlurNormalPower = 8.0;
  double MipThreshold = 8.0;
  int MinimumMipLevel = 1;
  int MaximumMipLevel = 5;
  int ResolutionDivisor = 1;
  double Damping = 1.0;
  double TemporalAlpha = 0.85;
  int TemporalInterleave = 1;
  bool SkipStillCameraReprojection = true;
  bool ExtrapolateBounces = false;
  double LastBounceExtrapolation = 0.0;
  double ReprojectionTolerance = 0.01;
  bool AutomaticReprojectionTolerance = true;
  double AutomaticReprojectionFraction = 2.5e-4;
  double EffectiveReprojectionTolerance = 0.0;
  bool ConfidenceFallback = false;
  double EnvironmentIrradiance[3] = { 0.0, 0.0, 0.0 };
  bool AutomaticEnvironmentIrradiance = true;
  double EffectiveEnvironmentIrradiance[3] = { 0.0, 0.0, 0.0 };

private:
  vtkDeepRadiosityPass(const vtkDeepRadiosityPass&) = delete;
  void operator=(const vtkDeepRadiosityPass&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;

  // The stages of UpdateRadiosity, in order (vtkGatherFrame carries what one
  // frame decided from stage to stage).
  struct vtkGatherFrame;
  void ComputeSceneParameters(vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state);
  static void ReduceFrame(vtkGatherFrame& frame, int divisor);
  bool PrepareTargets(vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state);
  void ChooseTapLevels(vtkGatherFrame& frame) const;
  bool AllocateTargets(vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state);
  bool AllocateReduced(vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state);
  bool GeometryKeysCurrent(const vtkGatherFrame& frame, const vtkDeepRadiosityRendererState& state);
  void ReduceLayers(vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state);
  static void BindReduced(vtkGatherFrame& frame, const vtkDeepRadiosityRendererState& state);
  void BuildGeometryKeys(vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state);
  void ComputeBounceInput(vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state);
  void Gather(vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state);
  void FilterIrradiance(vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state);
  double MeasureLastBounce(vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state);
  double EstimateBounceExtrapolation(vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state);
  void AccumulateIrradiance(vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state);
  void UpsampleIrradiance(vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state);
  static void SetLayersUniforms(vtkShaderProgram* program, const vtkGatherFrame& frame);
  void SetOutgoingUniforms(vtkShaderProgram* program);
  static void UnbindReduced(vtkGatherFrame& frame);
  void RecordFrame(vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state);
};

#endif
