/**
 * Internal helpers shared by the screen-space passes over the deep G-buffer
 * (vtkDeepAmbientObscurancePass, vtkDeepRadiosityPass): full-screen quads
 * with the shared GLSL substituted, float render targets, the scene-size
 * measure behind their automatic radii, projection and reprojection
 * uniforms, and counting a renderer's renders so that a temporal history is
 * only used by the frame that directly follows it. Not part of the public
 * API (a private header of the module).
 */
#ifndef vtkDeepScreenSpaceHelpers_h
#define vtkDeepScreenSpaceHelpers_h

#include "vtkActor.h"
#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkCallbackCommand.h"
#include "vtkDeepGIStageTimer.h"
#include "vtkOpenGLState.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkWeakPointer.h"

#include <map>    // for RendererStates
#include <memory> // for RendererStates
#include <string> // for NormalWeightSource

class vtkFieldData;
class vtkImageData;
class vtkOpenGLQuadHelper;
class vtkShaderProgram;
class vtkOpenGLRenderWindow;
class vtkWindow;

namespace vtkDeepScreenSpace
{
/// Number of spiral turns tau for N samples, the paper's Listing 3
/// (N = 1..98); 0 outside that range.
int SpiralTurns(int numberOfSamples);

/// Builds (first call) or readies a full-screen quad whose fragment shader
/// `source` may use //VTK::DeepGBuffer::Common and
/// //VTK::DeepScreenSpace::Common. True when the program compiled.
bool ReadyQuad(vtkOpenGLQuadHelper*& quad, vtkOpenGLRenderWindow* window, const char* source);

/**
 * GLSL of `float deepNormalWeight(float facing)`, facing^power with the
 * power compiled in: products (square and multiply) for a whole power, pow
 * for any other. On a CPU renderer (Mesa llvmpipe) pow, an exponential and
 * a logarithm on every tap, was 7-13 % of the bilateral filters' time,
 * where the default power 8 takes three products; a uniform choosing
 * between both forms would run both.
 */
std::string NormalWeightSource(double power);

/**
 * ReadyQuad for a bilateral filter's fragment shader `source`, whose
 * //VTK::DeepScreenSpace::NormalWeight becomes NormalWeightSource(power):
 * the quad is rebuilt when the power differs from `compiledPower`, the
 * power it was compiled for (updated here).
 */
bool ReadyBilateralQuad(vtkOpenGLQuadHelper*& quad, double& compiledPower,
  vtkOpenGLRenderWindow* window, const char* source, double power);

/// Releases and deletes a quad made by ReadyQuad (null is fine).
void ReleaseQuad(vtkOpenGLQuadHelper*& quad, vtkWindow* window);

/// Allocates (or resizes) a nearest-filtered, edge-clamped float texture
/// with 1, 2 or 4 components: 32-bit floats (R32F, RG32F, RGBA32F), or
/// 16-bit ones (R16F, RG16F, RGBA16F) with `halfFloat`. A texture keeps the
/// precision it was first allocated with.
bool AllocateTarget(vtkSmartPointer<vtkTextureObject>& texture, vtkOpenGLRenderWindow* window,
  int width, int height, int components, bool halfFloat = false);

/// The memory of a texture's level 0, in bytes (0 for null).
vtkTypeInt64 TextureBytes(const vtkSmartPointer<vtkTextureObject>& texture);

/// Releases a texture and clears the pointer (null is fine).
void ReleaseTarget(vtkSmartPointer<vtkTextureObject>& texture, vtkWindow* window);

/**
 * The one walk behind every "does the scene need effect X" question: calls
 * `visit(actor)` on each visible actor that `prop` draws (the prop itself,
 * or every actor on an assembly's paths) until it returns true, and returns
 * whether one did. AnyActor does the same over the renderer's visible props.
 */
template <typename Visitor>
bool AnyActorOf(vtkProp* prop, Visitor visit)
{
  if (!prop || !prop->GetVisibility())
  {
    return false;
  }
  prop->InitPathTraversal();
  while (vtkAssemblyPath* path = prop->GetNextPath())
  {
    vtkActor* actor = vtkActor::SafeDownCast(path->GetLastNode()->GetViewProp());
    if (actor && actor->GetVisibility() && visit(actor))
    {
      return true;
    }
  }
  return false;
}

template <typename Visitor>
bool AnyActor(vtkRenderer* renderer, Visitor visit)
{
  if (!renderer)
  {
    return false;
  }
  vtkCollectionSimpleIterator it;
  vtkPropCollection* props = renderer->GetViewProps();
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (AnyActorOf(prop, visit))
    {
      return true;
    }
  }
  return false;
}

/// Adds the frame's camera to a capture's field data: "ViewMatrix" (world
/// to camera) and "ProjectionMatrix" (camera to clip, z in [-1, 1]), 16
/// components each, row-major as vtkMatrix4x4 stores them.
void AddCameraFieldData(vtkFieldData* fd, const double view[16], const double projection[16]);

/**
 * The OpenGL state of an effect's offscreen stages (full-screen passes into
 * its own targets): viewport, scissor, blending and depth test saved, the
 * scissor test, blending and depth test off, the framebuffer bindings
 * pushed; all restored when it goes out of scope.
 */
class ScopedStageState
{
public:
  explicit ScopedStageState(vtkOpenGLState* state);
  ~ScopedStageState();
  ScopedStageState(const ScopedStageState&) = delete;
  void operator=(const ScopedStageState&) = delete;

private:
  vtkOpenGLState* State;
  vtkOpenGLState::ScopedglViewport Viewport;
  vtkOpenGLState::ScopedglEnableDisable ScissorTest;
  vtkOpenGLState::ScopedglScissor Scissor;
  vtkOpenGLState::ScopedglEnableDisable Blend;
  vtkOpenGLState::ScopedglEnableDisable DepthTest;
};

/**
 * Surface coverage: where layer 0 holds a surface, as a depth texture that
 * lets an effect's full-screen stages skip the rest.
 *
 * A CPU renderer (Mesa llvmpipe) shades 8 texels in lockstep and runs
 * every branch of a shader for all of them, so a texel that only writes
 * the background value costs nearly what a surface texel costs; what it
 * does skip is a block whose texels all fail an early depth test. The
 * effect's geometry key draw (vtkDeepGeometryKeyFS, which writes depth 0
 * where layer 0 holds a surface and 1 where it holds none) fills the
 * coverage under ScopedCoverageWrite; its later stages draw under
 * ScopedBackgroundSkip. A GPU's early and hierarchical depth tests skip
 * the same texels.
 *
 * The coverage is not the G-buffer's own depth: a surface can lie at
 * window depth 1 (the far plane of a very small near/far ratio), where
 * only the distance tells it from the background.
 *
 * ReadyCoverage keeps `coverage` a GL_DEPTH_COMPONENT32F texture of
 * width x height while `wanted` (the G-buffer's SkipBackgroundTexels),
 * released otherwise. A failed allocation releases it with a warning:
 * every texel is then shaded.
 */
void ReadyCoverage(vtkSmartPointer<vtkTextureObject>& coverage, vtkOpenGLRenderWindow* window,
  int width, int height, bool wanted);

/// Attaches a coverage texture (null: none) as the depth of `framebuffer`,
/// the draw framebuffer bound now, with the depth state a scope needs;
/// detaches it and restores the state when it goes out of scope.
class ScopedCoverageAttachment
{
protected:
  ScopedCoverageAttachment(
    vtkOpenGLState* state, unsigned int framebuffer, vtkTextureObject* coverage);
  ~ScopedCoverageAttachment();
  ScopedCoverageAttachment(const ScopedCoverageAttachment&) = delete;
  void operator=(const ScopedCoverageAttachment&) = delete;

  vtkOpenGLState* State;
  unsigned int Framebuffer;
  bool Attached;
  vtkOpenGLState::ScopedglEnableDisable DepthTest;
  vtkOpenGLState::ScopedglDepthFunc DepthFunc;
  vtkOpenGLState::ScopedglDepthMask DepthMask;
};

/// The geometry key's draw in scope writes `coverage` (null: nothing):
/// its depth, through GL_ALWAYS.
class ScopedCoverageWrite : private ScopedCoverageAttachment
{
public:
  ScopedCoverageWrite(vtkOpenGLState* state, unsigned int framebuffer, vtkTextureObject* coverage);
};

/**
 * The full-screen stages drawn with Draw in scope shade only the texels
 * `coverage` marks as surface (null: every texel): each quad is drawn at
 * depth 1 with GL_GREATER against it, read-only. Draw first clears the
 * stage's targets, within the scissor, to the value its shader writes
 * where layer 0 holds no surface, so they hold what they would hold with
 * every texel shaded (the same pixels). The colour attachments must have
 * the coverage's size.
 */
class ScopedBackgroundSkip : private ScopedCoverageAttachment
{
public:
  ScopedBackgroundSkip(vtkOpenGLState* state, unsigned int framebuffer, vtkTextureObject* coverage);
  ~ScopedBackgroundSkip();

  /// Clears the draw buffers to `background`, then draws `quad`.
  void Draw(vtkOpenGLQuadHelper* quad, const float background[4]);

private:
  double DepthRange[2] = { 0.0, 1.0 };
  vtkOpenGLState::ScopedglClearColor ClearColor;
};

/// Times the enclosing block as `stage` on `timer` (null: nothing timed,
/// no glFinish), see vtkDeepGIStageTimer.
class ScopedStageTime
{
public:
  ScopedStageTime(vtkDeepGIStageTimer* timer, const char* stage)
    : Timer(timer)
  {
    if (this->Timer)
    {
      this->Timer->StartStage(stage);
    }
  }
  ~ScopedStageTime()
  {
    if (this->Timer)
    {
      this->Timer->StopStage();
    }
  }
  ScopedStageTime(const ScopedStageTime&) = delete;
  void operator=(const ScopedStageTime&) = delete;

private:
  vtkDeepGIStageTimer* Timer;
};

/**
 * The OpenGL state of a composite into the renderer's framebuffer: blending
 * on, the colour combined as (sourceFactor, destinationFactor) and the
 * framebuffer's alpha kept, depth test and depth writes off; all restored
 * when it goes out of scope. (GL_ONE, GL_ZERO) replaces the colour.
 */
class ScopedCompositeState
{
public:
  ScopedCompositeState(
    vtkOpenGLState* state, unsigned int sourceFactor, unsigned int destinationFactor);
  ScopedCompositeState(const ScopedCompositeState&) = delete;
  void operator=(const ScopedCompositeState&) = delete;

private:
  vtkOpenGLState::ScopedglEnableDisable Blend;
  vtkOpenGLState::ScopedglEnableDisable DepthTest;
  vtkOpenGLState::ScopedglDepthMask DepthMask;
  vtkOpenGLState::ScopedglBlendFuncSeparate BlendFunc;
};

/// The name of a preset of the deep passes, whose Preset enums share the
/// values HIGH_PERFORMANCE 0, BALANCED 1 and HIGH_QUALITY 2; "UNKNOWN" for
/// any other value.
const char* PresetName(int preset);

/// The scene size every automatic length is a fraction of: the diagonal of
/// vtkDeepGIKeys::SCENE_BOUNDS when the renderer's information has them (a
/// renderer that draws part of a distributed scene), else of the bounds of
/// the renderer's visible props; 0 when empty or not finite.
double SceneDiagonal(vtkRenderer* renderer);

/// The deepProjXY and deepProjT uniforms of vtkDeepScreenSpaceCommon.glsl
/// from a row-major projection matrix.
void ProjectionUniforms(const double projection[16], float projXY[4], float projT[4]);

/// The deepReproject uniforms (column-major for GLSL): V_prev * inverse(V)
/// computed in double, and the previous projection. Without history the
/// matrices are the identity and the current projection (unused).
void ReprojectionUniforms(const double view[16], const double projection[16], bool hasHistory,
  const double previousView[16], const double previousProjection[16], float toPrevious[16],
  float previousProjectionGL[16]);

/// Removes `guardBand` pixels from every side of `image` (all its point
/// arrays), leaving the frame: captures of layers that carry a guard band
/// (vtkDeepGBufferPass::SetGuardBand) report the frame only.
void CropGuardBand(vtkImageData* image, int guardBand);

/**
 * The part of layers of `size` texels with a guard band of `guardBand`
 * pixels that a pass shades (paper section 3.5, Table 2's "fraction of guard
 * band shaded"): the frame and `shadedFraction` of the guard band around it,
 * as (x0, y0, x1, y1), x1 and y1 exclusive.
 */
void ShadedRegion(const int size[2], int guardBand, double shadedFraction, int region[4]);

/**
 * Narrows a ShadedRegion to the frame and at most `reach` pixels of the
 * guard band around it: the shaded texels that a filter of that radius
 * reads for the frame's (with a pass's temporal filter off, nothing else
 * reads the band's result).
 */
void LimitShadedRegion(const int size[2], int guardBand, int reach, int region[4]);

/// Whether region `outer` (x0, y0, x1, y1) contains region `inner`.
bool RegionContains(const int outer[4], const int inner[4]);

/**
 * The texels of region `outer` outside region `inner`, which it contains
 * (RegionContains), as at most four disjoint rectangles (below and above
 * `inner` across the whole width, then left and right of it); returns how
 * many. A pass that extends a result to a larger region shades only these.
 */
int RegionRing(const int outer[4], const int inner[4], int rings[4][4]);

/// The projection of the frame alone from the projection of layers of
/// `size` texels with a guard band of `guardBand` pixels (row-major):
/// clip x and y scaled by layers / frame per axis.
void FrameProjection(
  const double layerProjection[16], const int size[2], int guardBand, double frame[16]);

/**
 * The projection (row-major) under which the texel centres of a grid
 * reduced `divisor` times per axis, of `reducedSize` texels, reconstruct the
 * positions of layer texels divisor * q of layers of `size` texels: with
 * NDC_t = k NDC_r + c per axis (k = divisor reducedSize / size,
 * c = k + (1 - divisor) / size - 1), clip rows x and y become
 * (row - c row_w) / k. Exact, so stages that reconstruct positions from the
 * reduced grid's texel centres (deepPositionFromDistance, deepReproject)
 * work unchanged on it.
 */
void ReducedProjection(const double projection[16], const int size[2], const int reducedSize[2],
  int divisor, double reduced[16]);

/// Sets the deepShadedMin and deepShadedMax uniforms of
/// vtkDeepScreenSpaceCommon.glsl on `program` where it uses them.
void SetShadedRegionUniforms(vtkShaderProgram* program, const int region[4]);

/**
 * The per-renderer states of a screen-space pass, so that renderers (or
 * viewports) sharing a pass never read each other's targets or history.
 * State provides Attach(vtkRenderer*) (called once, on creation), a bool
 * HasFrame (the state holds the renderer's last frame), Release(vtkWindow*)
 * and TextureBytes() (the memory of its textures).
 */
template <typename State>
class RendererStates
{
public:
  /// The state of `renderer`, created on its first frame. The first renderer
  /// drawn (while its state exists) is the default of Find.
  State& Get(vtkRenderer* renderer)
  {
    std::unique_ptr<State>& slot = this->States[renderer];
    if (!slot)
    {
      slot.reset(new State);
      slot->Attach(renderer);
    }
    if (!this->First || !this->States.count(this->First))
    {
      this->First = renderer;
    }
    return *slot;
  }

  /// The state of `renderer` (the first renderer drawn if null) when it
  /// holds a frame; null otherwise.
  State* Find(vtkRenderer* renderer)
  {
    State* state = this->Existing(renderer ? renderer : this->First);
    return state && state->HasFrame ? state : nullptr;
  }

  /// The state of `renderer` if it has one, with or without a frame.
  State* Existing(vtkRenderer* renderer)
  {
    auto it = this->States.find(renderer);
    return it == this->States.end() ? nullptr : it->second.get();
  }

  /// Releases the graphics resources of every state and forgets them.
  void Release(vtkWindow* window)
  {
    for (auto& entry : this->States)
    {
      entry.second->Release(window);
    }
    this->States.clear();
    this->First = nullptr;
  }

  bool Empty() const { return this->States.empty(); }

  /// The bytes of the textures of every state (State::TextureBytes()).
  vtkTypeInt64 TextureBytes() const
  {
    vtkTypeInt64 bytes = 0;
    for (const auto& entry : this->States)
    {
      bytes += entry.second->TextureBytes();
    }
    return bytes;
  }

private:
  std::map<vtkRenderer*, std::unique_ptr<State>> States;
  vtkRenderer* First = nullptr;
};

/// Counts a renderer's StartEvents. A temporal history is valid for the
/// next frame only when exactly one render of the renderer happened since
/// (Consecutive()): a render without the pass breaks the chain.
class RenderCounter
{
public:
  RenderCounter() = default;
  ~RenderCounter();
  RenderCounter(const RenderCounter&) = delete;
  RenderCounter& operator=(const RenderCounter&) = delete;
  void Observe(vtkRenderer* renderer);
  /// True when this render directly follows the last call's render.
  bool Consecutive();

private:
  static void Count(vtkObject*, unsigned long, void* clientData, void*);
  vtkWeakPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkCallbackCommand> Observer;
  unsigned long Tag = 0;
  unsigned long Renders = 0;
  unsigned long LastRenders = 0;
};
}

#endif
