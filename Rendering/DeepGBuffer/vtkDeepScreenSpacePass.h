/**
 * @class   vtkDeepScreenSpacePass
 * @brief   Abstract base of the passes that render a frame through a deep G-buffer.
 *
 * vtkDeepAmbientObscurancePass, vtkDeepRadiosityPass and vtkDeepReflectionPass
 * (sections 3.2-3.6 of Mara, McGuire, Nowrouzezahrai and Luebke, "Deep
 * G-Buffers for Stable Global Illumination Approximation", HPG 2016) all
 * render a whole frame the same way: vtkDeepGBufferPass::RenderFrame sets the
 * camera, clears, updates the lights and draws the translucent, volumetric
 * and overlay steps, while the opaque step is the subclass's: it builds the
 * layers, computes its screen-space quantity from them and composites it.
 * This class owns the G-buffer pass (one is created by default; Set shares
 * one, null is refused with a warning), hands RenderFrame an opaque step that
 * calls RenderOpaque, and validates the non-negative lengths the subclasses
 * expose with an automatic mode.
 *
 * @sa vtkDeepGBufferPass vtkDeepAmbientObscurancePass vtkDeepRadiosityPass
 * vtkDeepReflectionPass
 */

#ifndef vtkDeepScreenSpacePass_h
#define vtkDeepScreenSpacePass_h

#include "vtkDeepGIRenderingModule.h" // for export macro
#include "vtkRenderPass.h"

class vtkDeepGBufferPass;
class vtkDeepGIStageTimer;
class vtkOpenGLRenderWindow;
class vtkOpenGLRenderer;
class vtkOpenGLState;
class vtkRenderer;
class vtkShaderProgram;

class VTKDEEPGIRENDERING_EXPORT vtkDeepScreenSpacePass : public vtkRenderPass
{
public:
  vtkTypeMacro(vtkDeepScreenSpacePass, vtkRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Largest spiral tap count of the effects: Listing 3 of the paper gives
  /// tau for N = 1..98.
  static constexpr int MAXIMUM_NUMBER_OF_SAMPLES = 98;

  ///@{
  /**
   * The G-buffer pass that builds the layers. One is created by default;
   * set one to share it with other deep passes. Null is refused with a
   * warning.
   *
   * @range non-null (null: warning, ignored)
   * @default a new vtkDeepGBufferPass per pass
   */
  void SetGBufferPass(vtkDeepGBufferPass* pass);
  vtkGetObjectMacro(GBufferPass, vtkDeepGBufferPass);
  ///@}

  /// Renders the frame with GetGBufferPass()->RenderFrame, whose opaque step
  /// is RenderOpaque.
  void Render(const vtkRenderState* s) override;

protected:
  vtkDeepScreenSpacePass();
  ~vtkDeepScreenSpacePass() override;

  /// The opaque step of the frame: layers, the subclass's effect, composite.
  virtual void RenderOpaque(const vtkRenderState* s) = 0;

  /**
   * Sets a non-negative length that has an automatic mode (a radius, a
   * tolerance, a distance): NaN, and infinities unless `allowInfinity`, keep
   * `value` with a warning; a negative `length` warns and becomes 0 (`atZero`
   * says what 0 means, appended to the warning). Setting switches
   * `automatic` off; Modified() when either changes.
   */
  void SetManualLength(const char* name, double length, double& value, bool& automatic,
    bool allowInfinity = false, const char* atZero = "");

/**
 * this->SetManualLength for property `property` of a subclass: the warnings
 * name the property as it is spelled in C++ (#property), its value is
 * this->property and its automatic mode this->Automatic<property>.
 */
#define vtkDeepSetManualLengthMacro(property, length, allowInfinity, atZero)                       \
  this->SetManualLength(                                                                           \
    #property, length, this->property, this->Automatic##property, allowInfinity, atZero)

  /**
   * Builds this frame's layers with the G-buffer. When the G-buffer is
   * unavailable (too old an OpenGL, an incomplete framebuffer) the opaque
   * props have been drawn the plain way instead: warns once per pass, not
   * while picking, that the frame is "rendering without `effect`", and
   * returns false.
   */
  bool RenderLayersOrWarn(const vtkRenderState* s, const char* effect);

  /**
   * The start of a capture method named `caller`: the OpenGL name of the
   * renderer's G-buffer distances (`distanceHandle`) and its window's
   * context made current with no pending OpenGL error. Null, with an error,
   * when the renderer's G-buffer is gone.
   */
  vtkOpenGLState* BeginCapture(
    vtkRenderer* renderer, const char* caller, unsigned int& distanceHandle);

  /**
   * Sets a spiral tap count N (NumberOfSamples of the obscurance and the
   * radiosity): outside 1..MAXIMUM_NUMBER_OF_SAMPLES it is clamped with a
   * warning; Modified() when it changes.
   */
  void SetSampleCount(int samples, int& value);

  /// The layers of a renderer's last G-buffer frame, as the subclasses read them.
  struct LayerFrame
  {
    double View[16];
    double Projection[16]; ///< of the layers (frame and guard band), row-major
    int Layers = 0;
    int Size[2] = { 0, 0 }; ///< of the layers, texels
    int GuardBand = 0;      ///< pixels on each side of the frame
  };

  /// Fills `frame` from GBufferPass (GetLayerCamera, GetLayerExtent); false,
  /// with an error naming `caller`, when it has no layers for `renderer`
  /// (its RenderLayers was not called).
  bool GetLayerFrame(vtkRenderer* renderer, const char* caller, LayerFrame& frame);

  /// What every effect's frame starts from: the renderer, its OpenGL window
  /// and state, the G-buffer's layers, the texels of them the effect shades
  /// and the projection terms of deepPositionFromDistance.
  struct EffectFrame : LayerFrame
  {
    const vtkRenderState* State = nullptr;
    vtkOpenGLRenderer* Renderer = nullptr;
    vtkOpenGLRenderWindow* Window = nullptr;
    vtkOpenGLState* GL = nullptr;
    int Region[4] = { 0, 0, 0, 0 }; ///< shaded texels [x0, x1) x [y0, y1) of the layers
    float ProjXY[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
    float ProjT[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
  };

  /// Fills `frame` for `s`'s renderer (see GetLayerFrame), shading the frame
  /// and `shadedFraction` of the guard band; false, with an error naming
  /// `caller`, when the G-buffer has no layers for it.
  bool BeginEffectFrame(
    const vtkRenderState* s, const char* caller, double shadedFraction, EffectFrame& frame);

  /**
   * The rotation of the spiral taps in frame `frameIndex`, in radians:
   * 2 pi fract(k / golden ratio), a low-discrepancy sequence, so that the
   * temporal filters average well-spread rotations (the paper's per-pixel
   * rotation of section 3.4, varied over frames). k is taken modulo the
   * prime 1000003 so that k times the golden ratio keeps its fraction
   * exact in double precision however long the pass runs.
   */
  static double RotationOffset(unsigned long long frameIndex);

  /// Sets the uniforms of a stage that reconstructs positions (and normals
  /// when `normalUnit` >= 0) from the layers: deepDistance, deepNormal,
  /// deepProjXY, deepProjT.
  static void SetLayerUniforms(
    vtkShaderProgram* program, const EffectFrame& frame, int distanceUnit, int normalUnit);

  /// Sets the uniforms of a stage that reads the geometry key
  /// (vtkDeepGeometryKeyFS) bound to `keyUnit`: deepKey, and the projection
  /// of its grid (deepProjXY, deepProjT) that turns distances into positions.
  static void SetKeyUniforms(
    vtkShaderProgram* program, int keyUnit, const float projXY[4], const float projT[4]);

  /// Sets a fraction in [0, 1]: NaN keeps `value` with a warning; values
  /// outside are clamped with a warning; Modified() when it changes.
  void SetFraction(const char* name, double fraction, double& value);

  /// The G-buffer's stage timer (vtkDeepGBufferPass::SetStageTimer), which
  /// the effects' stages report to; null when none is attached.
  vtkDeepGIStageTimer* GetStageTimer() const;

  vtkDeepGBufferPass* GBufferPass = nullptr;

private:
  vtkDeepScreenSpacePass(const vtkDeepScreenSpacePass&) = delete;
  void operator=(const vtkDeepScreenSpacePass&) = delete;

  class vtkOpaqueStep;
  vtkOpaqueStep* OpaqueStep = nullptr;
  bool WarnedLayersUnavailable = false;
};

#endif
