#include "vtkDeepRadiosityPass.h"

#include "vtkDeepGBufferPass.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkRenderState.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWeakPointer.h"
#include "vtk_glew.h"

#include "vtkDeepRadiosityBlurFS.h"
#include "vtkDeepRadiosityBounceFS.h"
#include "vtkDeepRadiosityCompositeFS.h"
#include "vtkDeepRadiosityFS.h"
#include "vtkDeepRadiosityTemporalFS.h"
#include "vtkDeepScreenSpaceHelpers.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkDeepRadiosityPass);

namespace
{
using vtkDeepScreenSpace::AllocateTarget;
using vtkDeepScreenSpace::ReadyQuad;
using vtkDeepScreenSpace::ReleaseTarget;
constexpr int Layers = vtkDeepRadiosityPass::NUMBER_OF_LAYERS;

// Per-layer targets, in the order of the frame's passes.
enum Target
{
  BOUNCE = 0,
  RAW = 1,
  BLUR_TEMP = 2,
  FILTERED = 3,
  INDIRECT = 4,
  NUMBER_OF_TARGETS = 5
};

// The G-buffer quantities the passes read.
const int GBufferQuantities[] = { vtkDeepGBufferPass::DEPTH, vtkDeepGBufferPass::NORMAL,
  vtkDeepGBufferPass::RADIANCE, vtkDeepGBufferPass::AMBIENT, vtkDeepGBufferPass::ALBEDO };

}

//------------------------------------------------------------------------------
bool vtkDeepRadiosityPass::RendererHasLightOn(vtkRenderer* renderer)
{
  if (!renderer)
  {
    return false;
  }
  vtkLightCollection* lights = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (light->GetSwitch() && light->GetIntensity() > 0.0)
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
// The radiosity targets and history of one renderer.
struct vtkDeepRadiosityRendererState
{
  vtkWeakPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkTextureObject> Targets[NUMBER_OF_TARGETS][Layers];
  // History[i][j]: (E_t, distance) of layer j; History[HistoryCurrent] is
  // the last frame's.
  vtkSmartPointer<vtkTextureObject> History[2][Layers];
  int HistoryCurrent = 0;
  bool HistoryValid = false;
  double PreviousView[16];
  double PreviousProjection[16];
  vtkDeepScreenSpace::RenderCounter Renders;
  unsigned int FrameIndex = 0; // frames since the history was reset
  int Width = 0;               // of the G-buffer's layers (frame and guard band)
  int Height = 0;
  int GuardBand = 0;
  int ShadedRegion[4] = { 0, 0, 0, 0 }; // vtkDeepScreenSpace::ShadedRegion
  int LayerCount = 0;
  bool HasFrame = false;
  double Radius = 0.0;
  int NumberOfSamples = 0;
  double Tolerance = 0.0;
  double Environment[3] = { 0.0, 0.0, 0.0 };
  bool WarnedEmpty = false;
  bool WarnedNoLights = false;

  void ResetHistory()
  {
    this->HistoryValid = false;
    this->FrameIndex = 0;
  }

  void Attach(vtkRenderer* renderer)
  {
    this->Renderer = renderer;
    this->Renders.Observe(renderer);
  }

  vtkTypeInt64 TextureBytes() const
  {
    vtkTypeInt64 bytes = 0;
    for (const auto& perLayer : this->Targets)
    {
      for (const auto& t : perLayer)
      {
        bytes += vtkDeepScreenSpace::TextureBytes(t);
      }
    }
    for (const auto& ping : this->History)
    {
      for (const auto& t : ping)
      {
        bytes += vtkDeepScreenSpace::TextureBytes(t);
      }
    }
    return bytes;
  }

  void Release(vtkWindow* w)
  {
    for (auto& perLayer : this->Targets)
    {
      for (auto& t : perLayer)
      {
        ReleaseTarget(t, w);
      }
    }
    for (auto& ping : this->History)
    {
      for (auto& t : ping)
      {
        ReleaseTarget(t, w);
      }
    }
    this->ResetHistory();
    this->Width = this->Height = this->LayerCount = 0;
    this->HasFrame = false;
  }

  vtkTextureObject* Output(int quantity, int layer)
  {
    if (!this->HasFrame || layer < 0 || layer >= Layers)
    {
      return nullptr;
    }
    return quantity == vtkDeepRadiosityPass::IRRADIANCE ? this->History[this->HistoryCurrent][layer]
      : quantity == vtkDeepRadiosityPass::INDIRECT_RADIANCE ? this->Targets[INDIRECT][layer]
                                                            : nullptr;
  }
};

class vtkDeepRadiosityPass::vtkInternals
{
public:
  vtkDeepScreenSpace::RendererStates<vtkDeepRadiosityRendererState> States;
  vtkOpenGLFramebufferObject* Framebuffer = nullptr;
  vtkOpenGLQuadHelper* BounceQuad = nullptr;
  vtkOpenGLQuadHelper* GatherQuad = nullptr;
  vtkOpenGLQuadHelper* BlurQuad = nullptr;
  vtkOpenGLQuadHelper* TemporalQuad = nullptr;
  vtkOpenGLQuadHelper* CompositeQuad = nullptr;
  bool WarnedUnsupported = false;
};

//------------------------------------------------------------------------------
vtkDeepRadiosityPass::vtkDeepRadiosityPass()
  : Internals(new vtkInternals)
{
  // Indirect light reaches into the frame from surfaces just outside it
  // (paper section 3.5): the G-buffer this pass creates has a guard band.
  this->GBufferPass->SetGuardBand(DEFAULT_GUARD_BAND);
}

//------------------------------------------------------------------------------
vtkDeepRadiosityPass::~vtkDeepRadiosityPass()
{
  vtkInternals& in = *this->Internals;
  if (in.GatherQuad || in.Framebuffer || !in.States.Empty())
  {
    vtkWarningMacro("Destroyed without ReleaseGraphicsResources(); OpenGL objects are leaked "
                    "unless the context was destroyed first.");
  }
  for (vtkOpenGLQuadHelper* quad :
    { in.BounceQuad, in.GatherQuad, in.BlurQuad, in.TemporalQuad, in.CompositeQuad })
  {
    delete quad;
  }
  if (in.Framebuffer)
  {
    in.Framebuffer->Delete();
  }
}

//------------------------------------------------------------------------------
void vtkDeepRadiosityPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "AutomaticRadius: " << (this->AutomaticRadius ? "On" : "Off") << "\n";
  os << indent << "AutomaticRadiusFraction: " << this->AutomaticRadiusFraction << "\n";
  os << indent << "EffectiveRadius: " << this->EffectiveRadius << "\n";
  os << indent << "NumberOfSamples: " << this->NumberOfSamples << " (spiral turns "
     << vtkDeepScreenSpace::SpiralTurns(this->NumberOfSamples) << ")\n";
  os << indent << "UseNormalTest: " << (this->UseNormalTest ? "On" : "Off") << "\n";
  os << indent << "Estimator: " << GetEstimatorAsString(this->Estimator) << "\n";
  os << indent << "UseColorBoost: " << (this->UseColorBoost ? "On" : "Off") << "\n";
  os << indent << "FilterTaps: " << this->FilterTaps << "\n";
  os << indent << "GuardBandShadedFraction: " << this->GuardBandShadedFraction << "\n";
  os << indent << "BlurPlaneTolerance: " << this->BlurPlaneTolerance << "\n";
  os << indent << "BlurNormalPower: " << this->BlurNormalPower << "\n";
  os << indent << "MipThreshold: " << this->MipThreshold << "\n";
  os << indent << "MinimumMipLevel: " << this->MinimumMipLevel << "\n";
  os << indent << "MaximumMipLevel: " << this->MaximumMipLevel << "\n";
  os << indent << "Damping: " << this->Damping << "\n";
  os << indent << "TemporalAlpha: " << this->TemporalAlpha << "\n";
  os << indent << "ReprojectionTolerance: " << this->ReprojectionTolerance << "\n";
  os << indent
     << "AutomaticReprojectionTolerance: " << (this->AutomaticReprojectionTolerance ? "On" : "Off")
     << "\n";
  os << indent << "AutomaticReprojectionFraction: " << this->AutomaticReprojectionFraction << "\n";
  os << indent << "EffectiveReprojectionTolerance: " << this->EffectiveReprojectionTolerance
     << "\n";
  os << indent << "ConfidenceFallback: " << (this->ConfidenceFallback ? "On" : "Off") << "\n";
  os << indent << "EnvironmentIrradiance: (" << this->EnvironmentIrradiance[0] << ", "
     << this->EnvironmentIrradiance[1] << ", " << this->EnvironmentIrradiance[2] << ")\n";
  os << indent
     << "AutomaticEnvironmentIrradiance: " << (this->AutomaticEnvironmentIrradiance ? "On" : "Off")
     << "\n";
  os << indent << "EffectiveEnvironmentIrradiance: (" << this->EffectiveEnvironmentIrradiance[0]
     << ", " << this->EffectiveEnvironmentIrradiance[1] << ", "
     << this->EffectiveEnvironmentIrradiance[2] << ")\n";
}

//------------------------------------------------------------------------------
void vtkDeepRadiosityPass::SetRadius(double radius)
{
  this->SetManualLength(
    "Radius", radius, this->Radius, this->AutomaticRadius, false, " (no indirect light)");
}

//------------------------------------------------------------------------------
void vtkDeepRadiosityPass::SetNumberOfSamples(int samples)
{
  if (samples < 1 || samples > MAXIMUM_NUMBER_OF_SAMPLES)
  {
    const int clamped = std::min(std::max(samples, 1), static_cast<int>(MAXIMUM_NUMBER_OF_SAMPLES));
    vtkWarningMacro("NumberOfSamples "
      << samples << " is outside 1.." << MAXIMUM_NUMBER_OF_SAMPLES
      << " (the paper's Listing 3 gives spiral turns for N = 1..98); using " << clamped << ".");
    samples = clamped;
  }
  if (samples != this->NumberOfSamples)
  {
    this->NumberOfSamples = samples;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
namespace
{
// A value in [0, 1]: NaN keeps `current`, others are clamped; both warn.
bool UnitInterval(vtkObject* self, const char* name, double& value, double current)
{
  if (std::isnan(value))
  {
    vtkWarningWithObjectMacro(self, << name << " is NaN; keeping " << current << ".");
    return false;
  }
  if (value < 0.0 || value > 1.0)
  {
    const double clamped = std::min(std::max(value, 0.0), 1.0);
    vtkWarningWithObjectMacro(
      self, << name << " " << value << " is outside [0, 1]; using " << clamped << ".");
    value = clamped;
  }
  return true;
}
}

//------------------------------------------------------------------------------
void vtkDeepRadiosityPass::SetDamping(double delta)
{
  if (UnitInterval(this, "Damping", delta, this->Damping) && delta != this->Damping)
  {
    this->Damping = delta;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkDeepRadiosityPass::SetTemporalAlpha(double alpha)
{
  if (UnitInterval(this, "TemporalAlpha", alpha, this->TemporalAlpha) &&
    alpha != this->TemporalAlpha)
  {
    this->TemporalAlpha = alpha;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkDeepRadiosityPass::SetReprojectionTolerance(double tolerance)
{
  this->SetManualLength("ReprojectionTolerance", tolerance, this->ReprojectionTolerance,
    this->AutomaticReprojectionTolerance);
}

//------------------------------------------------------------------------------
void vtkDeepRadiosityPass::SetEnvironmentIrradiance(double r, double g, double b)
{
  double e[3] = { r, g, b };
  for (double& c : e)
  {
    if (!std::isfinite(c))
    {
      vtkWarningMacro("EnvironmentIrradiance (" << r << ", " << g << ", " << b
                                                << ") is not finite; keeping the previous value.");
      return;
    }
    if (c < 0.0)
    {
      vtkWarningMacro("EnvironmentIrradiance component " << c << " is negative; using 0.");
      c = 0.0;
    }
  }
  if (!std::equal(e, e + 3, this->EnvironmentIrradiance) || this->AutomaticEnvironmentIrradiance)
  {
    std::copy(e, e + 3, this->EnvironmentIrradiance);
    this->AutomaticEnvironmentIrradiance = false;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkDeepRadiosityPass::SetPreset(int preset)
{
  // Table 2 of the paper.
  struct Settings
  {
    int Samples;
    int FilterTaps;
    bool NormalTest;
    int MinimumMipLevel;
    double GuardBandShaded;
  };
  static const Settings presets[] = { { 13, 9, false, 3, 0.1 }, { 14, 11, true, 2, 0.5 },
    { 30, 13, true, 0, 0.8 } };
  if (preset < HIGH_PERFORMANCE || preset > HIGH_QUALITY)
  {
    vtkWarningMacro("Unknown preset " << preset << "; the settings are unchanged.");
    return;
  }
  const Settings& p = presets[preset];
  this->NumberOfSamples = p.Samples;
  this->FilterTaps = p.FilterTaps;
  this->UseNormalTest = p.NormalTest;
  this->MinimumMipLevel = p.MinimumMipLevel;
  this->GuardBandShadedFraction = p.GuardBandShaded;
  this->Modified();
}

//------------------------------------------------------------------------------
const char* vtkDeepRadiosityPass::GetPresetAsString(int preset)
{
  switch (preset)
  {
    case HIGH_PERFORMANCE:
      return "HIGH_PERFORMANCE";
    case BALANCED:
      return "BALANCED";
    case HIGH_QUALITY:
      return "HIGH_QUALITY";
    default:
      return "UNKNOWN";
  }
}

//------------------------------------------------------------------------------
void vtkDeepRadiosityPass::RenderOpaque(const vtkRenderState* s)
{
  vtkInternals& in = *this->Internals;
  vtkOpenGLRenderer* renderer = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  vtkDeepGBufferPass* gbuffer = this->GBufferPass;
  if (!gbuffer->RenderLayers(s))
  {
    // The opaque props have been drawn the plain way.
    if (!renderer->GetSelector() && !in.WarnedUnsupported)
    {
      in.WarnedUnsupported = true;
      vtkWarningMacro("The deep G-buffer is unavailable; rendering without radiosity.");
    }
    if (vtkDeepRadiosityRendererState* state = in.States.Existing(renderer))
    {
      state->HasFrame = false;
      state->ResetHistory();
    }
    return;
  }
  if (!this->UpdateRadiosity(s))
  {
    gbuffer->ResolveToFramebuffer(s);
    return;
  }

  // Composite: layer-0 image and depth, then colour = RADIANCE + L_ind.
  gbuffer->ResolveToFramebuffer(s);
  if (gbuffer->GetDisplayQuantity() != vtkDeepGBufferPass::RADIANCE)
  {
    return;
  }
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  vtkOpenGLState* ostate = window->GetState();
  vtkDeepRadiosityRendererState& state = *in.States.Existing(renderer);
  vtkDeepScreenSpace::ScopedStageTime time(this->GetStageTimer(), "radiosity: composite");
  // The colour is replaced, the framebuffer's alpha kept.
  vtkDeepScreenSpace::ScopedCompositeState compositeState(ostate, GL_ONE, GL_ZERO);
  vtkShaderProgram* program = in.CompositeQuad->Program;
  window->GetShaderCache()->ReadyShaderProgram(program);
  vtkTextureObject* indirect = state.Targets[INDIRECT][0];
  indirect->Activate();
  const int distanceUnit = gbuffer->ActivateTexture(renderer, vtkDeepGBufferPass::DEPTH);
  const int radianceUnit = gbuffer->ActivateTexture(renderer, vtkDeepGBufferPass::RADIANCE);
  program->SetUniformi("deepIndirect", indirect->GetTextureUnit());
  program->SetUniformi("deepDistance", distanceUnit);
  program->SetUniformi("deepRadiance", radianceUnit);
  program->SetUniformi("deepGuardBand", state.GuardBand);
  in.CompositeQuad->Render();
  gbuffer->DeactivateTexture(renderer, vtkDeepGBufferPass::RADIANCE);
  gbuffer->DeactivateTexture(renderer, vtkDeepGBufferPass::DEPTH);
  indirect->Deactivate();
  vtkOpenGLCheckErrorMacro("failed after the radiosity composite");
}

//------------------------------------------------------------------------------
// What one UpdateRadiosity call decides and carries from stage to stage.
struct vtkDeepRadiosityPass::vtkGatherFrame : vtkDeepScreenSpacePass::EffectFrame
{
  int UsedLayers = 0; // at most NUMBER_OF_LAYERS of the G-buffer's
  double Radius = 0.0;
  double Tolerance = 0.0; // reprojection tolerance, world units
  bool HasLights = false;
  double RotationOffset = 0.0;
  int Units[vtkDeepGBufferPass::NUMBER_OF_QUANTITIES]; // of the G-buffer's textures
  int MinimumMip = 0;
  int MaximumMip = 0;
  int Previous = 0; // History[Previous] is the last frame's, History[Next] this one's
  int Next = 1;
  float ToPrevious[16];
  float PreviousProjection[16];

  int DistanceUnit() const { return this->Units[vtkDeepGBufferPass::DEPTH]; }
  int NormalUnit() const { return this->Units[vtkDeepGBufferPass::NORMAL]; }
};

namespace
{
using LayerTextures = vtkSmartPointer<vtkTextureObject>[Layers];

// Binds one texture per layer and sets the sampler uniforms name0, name1.
void BindLayerTextures(vtkShaderProgram* program, const char* name, LayerTextures& textures)
{
  for (int j = 0; j < Layers; ++j)
  {
    textures[j]->Activate();
    program->SetUniformi((name + std::to_string(j)).c_str(), textures[j]->GetTextureUnit());
  }
}

void UnbindLayerTextures(LayerTextures& textures)
{
  for (auto& t : textures)
  {
    t->Deactivate();
  }
}

// Draws into the per-layer textures `a`, then `b` (if any), as consecutive
// colour attachments.
void AttachLayerTextures(
  vtkOpenGLFramebufferObject* framebuffer, LayerTextures& a, LayerTextures* b = nullptr)
{
  int n = 0;
  for (auto& t : a)
  {
    framebuffer->AddColorAttachment(n++, t);
  }
  if (b)
  {
    for (auto& t : *b)
    {
      framebuffer->AddColorAttachment(n++, t);
    }
  }
  framebuffer->ActivateDrawBuffers(n);
}

// floor(log2(max(width, height))): the index of the coarsest MIP level.
int CoarsestMipLevel(int width, int height)
{
  int level = 0;
  while ((std::max(width, height) >> (level + 1)) > 0)
  {
    ++level;
  }
  return level;
}
}

//------------------------------------------------------------------------------
bool vtkDeepRadiosityPass::UpdateRadiosity(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  vtkGatherFrame frame;
  if (!this->BeginEffectFrame(s, "UpdateRadiosity", this->GuardBandShadedFraction, frame))
  {
    return false;
  }
  frame.UsedLayers = std::min(frame.Layers, Layers);
  vtkDeepRadiosityRendererState& state = this->Internals->States.Get(frame.Renderer);
  state.HasFrame = false;
  this->ComputeSceneParameters(frame, state);
  if (!this->PrepareTargets(frame, state))
  {
    return false;
  }
  vtkDeepGBufferPass* gbuffer = this->GBufferPass;
  for (int q : GBufferQuantities)
  {
    frame.Units[q] = gbuffer->ActivateTexture(frame.Renderer, q);
  }
  {
    vtkOpenGLState* ostate = frame.GL;
    vtkDeepScreenSpace::ScopedStageState stageState(ostate);
    this->Internals->Framebuffer->Bind();
    ostate->vtkglViewport(0, 0, frame.Size[0], frame.Size[1]);
    this->ComputeBounceInput(frame, state);
    // The other stages shade the frame and GuardBandShadedFraction of the
    // guard band (Table 2's last column).
    ostate->vtkglEnable(GL_SCISSOR_TEST);
    const int* region = frame.Region;
    ostate->vtkglScissor(region[0], region[1], region[2] - region[0], region[3] - region[1]);
    this->Gather(frame, state);
    this->FilterIrradiance(frame, state);
    this->AccumulateIrradiance(frame, state);
    for (int a = 0; a < 2 * Layers; ++a)
    {
      this->Internals->Framebuffer->RemoveColorAttachment(a);
    }
  }
  for (int q : GBufferQuantities)
  {
    if (frame.Units[q] >= 0)
    {
      gbuffer->DeactivateTexture(frame.Renderer, q);
    }
  }
  this->RecordFrame(frame, state);
  vtkOpenGLCheckErrorMacro("failed after vtkDeepRadiosityPass");
  return true;
}

//------------------------------------------------------------------------------
// The scene-relative parameters of this frame: radius, reprojection
// tolerance, environment irradiance, and whether a light is on.
void vtkDeepRadiosityPass::ComputeSceneParameters(
  vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state)
{
  vtkRenderer* renderer = frame.Renderer;
  const double diagonal = vtkDeepScreenSpace::VisiblePropDiagonal(renderer);
  frame.Radius = this->AutomaticRadius ? this->AutomaticRadiusFraction * diagonal : this->Radius;
  this->EffectiveRadius = frame.Radius;
  if (this->AutomaticRadius && !(diagonal > 0.0) && !state.WarnedEmpty)
  {
    state.WarnedEmpty = true;
    vtkWarningMacro("The scene has no visible extent: the automatic radius is 0 and there is no "
                    "indirect light.");
  }
  frame.Tolerance = this->AutomaticReprojectionTolerance
    ? this->AutomaticReprojectionFraction * diagonal
    : this->ReprojectionTolerance;
  this->EffectiveReprojectionTolerance = frame.Tolerance;
  if (this->AutomaticEnvironmentIrradiance)
  {
    const double* ambient = renderer->GetAmbient();
    for (int c = 0; c < 3; ++c)
    {
      this->EffectiveEnvironmentIrradiance[c] =
        std::isfinite(ambient[c]) ? vtkMath::Pi() * std::max(ambient[c], 0.0) : 0.0;
    }
  }
  else
  {
    std::copy(this->EnvironmentIrradiance, this->EnvironmentIrradiance + 3,
      this->EffectiveEnvironmentIrradiance);
  }
  frame.HasLights = RendererHasLightOn(renderer);
  if (!frame.HasLights && !state.WarnedNoLights)
  {
    state.WarnedNoLights = true;
    vtkWarningMacro("The renderer has no light switched on: VTK draws the props unlit and there "
                    "is no direct light to bounce.");
  }
}

//------------------------------------------------------------------------------
// The renderer's history (reset on a resize, a new layer count or shaded
// region, and when this renderer was rendered without this pass since the
// history's frame), this frame's rotation and MIP range, the targets, the
// reprojection and the programs.
bool vtkDeepRadiosityPass::PrepareTargets(
  vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state)
{
  vtkInternals& in = *this->Internals;
  vtkOpenGLRenderWindow* window = frame.Window;
  const int width = frame.Size[0], height = frame.Size[1];
  if (!state.Renders.Consecutive() || state.Width != width || state.Height != height ||
    state.LayerCount != frame.UsedLayers ||
    !std::equal(frame.Region, frame.Region + 4, state.ShadedRegion))
  {
    state.ResetHistory();
  }
  ++state.FrameIndex;
  frame.RotationOffset = this->TemporalAlpha > 0.0 ? RotationOffset(state.FrameIndex) : 0.0;
  bool allocated = true;
  for (auto& perLayer : state.Targets)
  {
    for (auto& t : perLayer)
    {
      allocated = allocated && AllocateTarget(t, window, width, height, 4);
    }
  }
  for (auto& ping : state.History)
  {
    for (auto& t : ping)
    {
      allocated = allocated && AllocateTarget(t, window, width, height, 4);
    }
  }
  if (!allocated)
  {
    vtkErrorMacro("Could not allocate the radiosity targets.");
    return false;
  }
  state.Width = width;
  state.Height = height;
  state.GuardBand = frame.GuardBand;
  std::copy(frame.Region, frame.Region + 4, state.ShadedRegion);
  state.LayerCount = frame.UsedLayers;
  if (!in.Framebuffer)
  {
    in.Framebuffer = vtkOpenGLFramebufferObject::New();
    in.Framebuffer->SetContext(window);
  }
  const bool ready = ReadyQuad(in.BounceQuad, window, vtkDeepRadiosityBounceFS) &&
    ReadyQuad(in.GatherQuad, window, vtkDeepRadiosityFS) &&
    ReadyQuad(in.BlurQuad, window, vtkDeepRadiosityBlurFS) &&
    ReadyQuad(in.TemporalQuad, window, vtkDeepRadiosityTemporalFS) &&
    ReadyQuad(in.CompositeQuad, window, vtkDeepRadiosityCompositeFS);
  if (!ready)
  {
    vtkErrorMacro("The radiosity shaders failed to compile.");
    return false;
  }
  vtkDeepScreenSpace::ReprojectionUniforms(frame.View, frame.Projection, state.HistoryValid,
    state.PreviousView, state.PreviousProjection, frame.ToPrevious, frame.PreviousProjection);
  frame.MaximumMip = std::min(
    std::max(this->MaximumMipLevel, this->MinimumMipLevel), CoarsestMipLevel(width, height));
  frame.MinimumMip = std::min(this->MinimumMipLevel, frame.MaximumMip);
  frame.Previous = state.HistoryCurrent;
  frame.Next = 1 - state.HistoryCurrent;
  return true;
}

//------------------------------------------------------------------------------
// Step 1, bounce input B = direct + delta L_ind,t-1 (section 3.3), over the
// whole layers: the guard band's surfaces are sources for the gather.
void vtkDeepRadiosityPass::ComputeBounceInput(
  vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state)
{
  vtkInternals& in = *this->Internals;
  vtkDeepScreenSpace::ScopedStageTime time(this->GetStageTimer(), "radiosity: bounce input");
  AttachLayerTextures(in.Framebuffer, state.Targets[BOUNCE]);
  vtkShaderProgram* program = in.BounceQuad->Program;
  frame.Window->GetShaderCache()->ReadyShaderProgram(program);
  vtkDeepScreenSpace::SetShadedRegionUniforms(program, frame.Region);
  SetLayerUniforms(program, frame, frame.DistanceUnit(), frame.NormalUnit());
  program->SetUniformi("deepRadiance", frame.Units[vtkDeepGBufferPass::RADIANCE]);
  program->SetUniformi("deepAmbient", frame.Units[vtkDeepGBufferPass::AMBIENT]);
  program->SetUniformi("deepAlbedo", frame.Units[vtkDeepGBufferPass::ALBEDO]);
  BindLayerTextures(program, "deepHistory", state.History[frame.Previous]);
  program->SetUniformi("deepLayers", frame.UsedLayers);
  program->SetUniformi("deepHasHistory", state.HistoryValid ? 1 : 0);
  program->SetUniformMatrix4x4("deepToPrevious", frame.ToPrevious);
  program->SetUniformMatrix4x4("deepPrevProjection", frame.PreviousProjection);
  program->SetUniformf("deepTolerance", static_cast<float>(frame.Tolerance));
  program->SetUniformf("deepDamping", static_cast<float>(this->Damping));
  program->SetUniformi("deepBoost", this->UseColorBoost ? 1 : 0);
  program->SetUniformi("deepHasLights", frame.HasLights ? 1 : 0);
  in.BounceQuad->Render();
  UnbindLayerTextures(state.History[frame.Previous]);
}

//------------------------------------------------------------------------------
// Step 2, the gather: eq. 4-5 into RAW (E, M / N).
void vtkDeepRadiosityPass::Gather(vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state)
{
  vtkInternals& in = *this->Internals;
  vtkDeepScreenSpace::ScopedStageTime time(this->GetStageTimer(), "radiosity: gather");
  AttachLayerTextures(in.Framebuffer, state.Targets[RAW]);
  vtkShaderProgram* program = in.GatherQuad->Program;
  frame.Window->GetShaderCache()->ReadyShaderProgram(program);
  SetLayerUniforms(program, frame, frame.DistanceUnit(), frame.NormalUnit());
  BindLayerTextures(program, "deepBounce", state.Targets[BOUNCE]);
  program->SetUniformi("deepLayers", frame.UsedLayers);
  program->SetUniformi("deepSamples", this->NumberOfSamples);
  program->SetUniformf(
    "deepTurns", static_cast<float>(vtkDeepScreenSpace::SpiralTurns(this->NumberOfSamples)));
  program->SetUniformf("deepRadius", static_cast<float>(frame.Radius));
  program->SetUniformf("deepMipThreshold", static_cast<float>(this->MipThreshold));
  program->SetUniformi("deepMinMip", frame.MinimumMip);
  program->SetUniformi("deepMaxMip", frame.MaximumMip);
  program->SetUniformi("deepNormalTest", this->UseNormalTest ? 1 : 0);
  program->SetUniformi("deepEstimator", this->Estimator);
  program->SetUniformf("deepCosineEpsilon", static_cast<float>(COSINE_EPSILON));
  program->SetUniformf("deepRotationOffset", static_cast<float>(frame.RotationOffset));
  in.GatherQuad->Render();
  UnbindLayerTextures(state.Targets[BOUNCE]);
}

//------------------------------------------------------------------------------
// Step 3, separable bilateral reconstruction: RAW -> BLUR_TEMP -> FILTERED.
void vtkDeepRadiosityPass::FilterIrradiance(
  vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state)
{
  vtkInternals& in = *this->Internals;
  vtkDeepScreenSpace::ScopedStageTime time(this->GetStageTimer(), "radiosity: blur");
  const int passes[2][3] = { { RAW, BLUR_TEMP, 0 }, { BLUR_TEMP, FILTERED, 1 } };
  vtkShaderProgram* program = in.BlurQuad->Program;
  for (const auto& pass : passes)
  {
    AttachLayerTextures(in.Framebuffer, state.Targets[pass[1]]);
    frame.Window->GetShaderCache()->ReadyShaderProgram(program);
    vtkDeepScreenSpace::SetShadedRegionUniforms(program, frame.Region);
    BindLayerTextures(program, "deepInput", state.Targets[pass[0]]);
    SetLayerUniforms(program, frame, frame.DistanceUnit(), frame.NormalUnit());
    program->SetUniformi("deepLayers", frame.UsedLayers);
    const int axis[2] = { pass[2] == 0 ? 1 : 0, pass[2] == 0 ? 0 : 1 };
    program->SetUniform2i("deepAxis", axis);
    program->SetUniformi("deepBlurRadius", (this->FilterTaps - 1) / 2);
    program->SetUniformf("deepPlaneTolerance", static_cast<float>(this->BlurPlaneTolerance));
    program->SetUniformf("deepNormalPower", static_cast<float>(this->BlurNormalPower));
    in.BlurQuad->Render();
    UnbindLayerTextures(state.Targets[pass[0]]);
  }
}

//------------------------------------------------------------------------------
// Step 4, the temporal filter and eq. 6 (with the confidence fallback):
// FILTERED + History[Previous] -> History[Next], INDIRECT.
void vtkDeepRadiosityPass::AccumulateIrradiance(
  vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state)
{
  vtkInternals& in = *this->Internals;
  vtkDeepScreenSpace::ScopedStageTime time(this->GetStageTimer(), "radiosity: temporal");
  AttachLayerTextures(in.Framebuffer, state.History[frame.Next], &state.Targets[INDIRECT]);
  vtkShaderProgram* program = in.TemporalQuad->Program;
  frame.Window->GetShaderCache()->ReadyShaderProgram(program);
  vtkDeepScreenSpace::SetShadedRegionUniforms(program, frame.Region);
  BindLayerTextures(program, "deepInput", state.Targets[FILTERED]);
  BindLayerTextures(program, "deepHistory", state.History[frame.Previous]);
  SetLayerUniforms(program, frame, frame.DistanceUnit(), frame.NormalUnit());
  program->SetUniformi("deepAlbedo", frame.Units[vtkDeepGBufferPass::ALBEDO]);
  program->SetUniformi("deepLayers", frame.UsedLayers);
  program->SetUniformi("deepHasHistory", state.HistoryValid ? 1 : 0);
  program->SetUniformMatrix4x4("deepToPrevious", frame.ToPrevious);
  program->SetUniformMatrix4x4("deepPrevProjection", frame.PreviousProjection);
  program->SetUniformf("deepTolerance", static_cast<float>(frame.Tolerance));
  program->SetUniformf("deepAlpha", static_cast<float>(this->TemporalAlpha));
  program->SetUniformi("deepBoost", this->UseColorBoost ? 1 : 0);
  program->SetUniformi("deepFallback", this->ConfidenceFallback ? 1 : 0);
  const float environment[3] = { static_cast<float>(this->EffectiveEnvironmentIrradiance[0]),
    static_cast<float>(this->EffectiveEnvironmentIrradiance[1]),
    static_cast<float>(this->EffectiveEnvironmentIrradiance[2]) };
  program->SetUniform3f("deepEnvironment", environment);
  program->SetUniformf("deepIrradianceLimit", static_cast<float>(IRRADIANCE_LIMIT));
  in.TemporalQuad->Render();
  UnbindLayerTextures(state.History[frame.Previous]);
  UnbindLayerTextures(state.Targets[FILTERED]);
}

//------------------------------------------------------------------------------
// This frame's history becomes the last frame's; what captures report.
void vtkDeepRadiosityPass::RecordFrame(vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state)
{
  state.HistoryCurrent = frame.Next;
  state.HistoryValid = true;
  std::copy(frame.View, frame.View + 16, state.PreviousView);
  std::copy(frame.Projection, frame.Projection + 16, state.PreviousProjection);
  state.HasFrame = true;
  state.Radius = frame.Radius;
  state.NumberOfSamples = this->NumberOfSamples;
  state.Tolerance = frame.Tolerance;
  std::copy(this->EffectiveEnvironmentIrradiance, this->EffectiveEnvironmentIrradiance + 3,
    state.Environment);
}

//------------------------------------------------------------------------------
int vtkDeepRadiosityPass::ActivateTexture(vtkRenderer* renderer, int quantity, int layer)
{
  vtkDeepRadiosityRendererState* state = this->Internals->States.Find(renderer);
  vtkTextureObject* texture = state ? state->Output(quantity, layer) : nullptr;
  if (!texture)
  {
    return -1;
  }
  texture->Activate();
  return texture->GetTextureUnit();
}

//------------------------------------------------------------------------------
void vtkDeepRadiosityPass::DeactivateTexture(vtkRenderer* renderer, int quantity, int layer)
{
  vtkDeepRadiosityRendererState* state = this->Internals->States.Find(renderer);
  if (vtkTextureObject* texture = state ? state->Output(quantity, layer) : nullptr)
  {
    texture->Deactivate();
  }
}

//------------------------------------------------------------------------------
unsigned int vtkDeepRadiosityPass::GetTextureHandle(vtkRenderer* renderer, int quantity, int layer)
{
  vtkDeepRadiosityRendererState* state = this->Internals->States.Find(renderer);
  vtkTextureObject* texture = state ? state->Output(quantity, layer) : nullptr;
  return texture ? texture->GetHandle() : 0;
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkDeepRadiosityPass::GetTextureBytes()
{
  return this->Internals->States.TextureBytes();
}

//------------------------------------------------------------------------------
void vtkDeepRadiosityPass::ReleaseGraphicsResources(vtkWindow* w)
{
  vtkInternals& in = *this->Internals;
  in.States.Release(w);
  for (vtkOpenGLQuadHelper** quad :
    { &in.BounceQuad, &in.GatherQuad, &in.BlurQuad, &in.TemporalQuad, &in.CompositeQuad })
  {
    vtkDeepScreenSpace::ReleaseQuad(*quad, w);
  }
  if (in.Framebuffer)
  {
    in.Framebuffer->ReleaseGraphicsResources(w);
    in.Framebuffer->Delete();
    in.Framebuffer = nullptr;
  }
  this->GBufferPass->ReleaseGraphicsResources(w);
  this->Superclass::ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
namespace
{
std::vector<float> DownloadRGBA(vtkTextureObject* texture, size_t pixels)
{
  std::vector<float> values(pixels * 4);
  glBindTexture(GL_TEXTURE_2D, texture->GetHandle());
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, values.data());
  return values;
}

// The G-buffer's distance array (every slot); `slots` receives its depth.
std::vector<float> DownloadDistance(GLuint handle, size_t pixels, int& slots)
{
  glBindTexture(GL_TEXTURE_2D_ARRAY, handle);
  GLint depth = 1;
  glGetTexLevelParameteriv(GL_TEXTURE_2D_ARRAY, 0, GL_TEXTURE_DEPTH, &depth);
  slots = std::max(1, static_cast<int>(depth));
  std::vector<float> distance(pixels * slots);
  glGetTexImage(GL_TEXTURE_2D_ARRAY, 0, GL_RED, GL_FLOAT, distance.data());
  return distance;
}

vtkFloatArray* AddFloatArray(
  vtkPointData* pd, const std::string& name, int components, size_t pixels)
{
  vtkNew<vtkFloatArray> array;
  array->SetName(name.c_str());
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(static_cast<vtkIdType>(pixels));
  pd->AddArray(array);
  return array.GetPointer();
}

void AddIrradianceFieldData(vtkFieldData* fd, const vtkDeepRadiosityRendererState& state)
{
  auto addDoubles = [fd](const char* name, std::initializer_list<double> values)
  {
    vtkNew<vtkDoubleArray> array;
    array->SetName(name);
    for (double v : values)
    {
      array->InsertNextValue(v);
    }
    fd->AddArray(array);
  };
  addDoubles("Radius", { state.Radius });
  addDoubles("ReprojectionTolerance", { state.Tolerance });
  addDoubles(
    "EnvironmentIrradiance", { state.Environment[0], state.Environment[1], state.Environment[2] });
  for (auto value : { std::make_pair("NumberOfSamples", state.NumberOfSamples),
         std::make_pair("NumberOfLayers", state.LayerCount),
         std::make_pair("Frames", static_cast<int>(state.FrameIndex)) })
  {
    vtkNew<vtkIntArray> array;
    array->SetName(value.first);
    array->InsertNextValue(value.second);
    fd->AddArray(array);
  }
}

// The arrays of layer j (CaptureIrradiance); 0 where the layer is empty.
void AddIrradianceArrays(vtkImageData* output, vtkDeepRadiosityRendererState& state,
  const std::vector<float>& distance, int slots, int j)
{
  const size_t pixels = static_cast<size_t>(state.Width) * state.Height;
  const std::vector<float> irradiance =
    DownloadRGBA(state.History[state.HistoryCurrent][j], pixels);
  const std::vector<float> indirect = DownloadRGBA(state.Targets[INDIRECT][j], pixels);
  const std::vector<float> filtered = DownloadRGBA(state.Targets[FILTERED][j], pixels);
  const std::vector<float> raw = DownloadRGBA(state.Targets[RAW][j], pixels);
  vtkPointData* pd = output->GetPointData();
  const std::string suffix = "_" + std::to_string(j);
  vtkFloatArray* e = AddFloatArray(pd, "Irradiance" + suffix, 3, pixels);
  vtkFloatArray* l = AddFloatArray(pd, "IndirectRadiance" + suffix, 3, pixels);
  vtkFloatArray* c = AddFloatArray(pd, "Confidence" + suffix, 1, pixels);
  vtkFloatArray* fe = AddFloatArray(pd, "FilteredIrradiance" + suffix, 3, pixels);
  vtkFloatArray* re = AddFloatArray(pd, "RawIrradiance" + suffix, 3, pixels);
  vtkFloatArray* rc = AddFloatArray(pd, "RawConfidence" + suffix, 1, pixels);
  vtkNew<vtkUnsignedCharArray> valid;
  valid->SetName(("Valid" + suffix).c_str());
  valid->SetNumberOfTuples(pixels);
  pd->AddArray(valid);
  for (size_t p = 0; p < pixels; ++p)
  {
    const bool isValid = j < state.LayerCount && j < slots && distance[j * pixels + p] > 0.0f;
    valid->SetValue(p, isValid ? 1 : 0);
    for (int k = 0; k < 3; ++k)
    {
      e->SetTypedComponent(p, k, isValid ? irradiance[4 * p + k] : 0.0f);
      l->SetTypedComponent(p, k, isValid ? indirect[4 * p + k] : 0.0f);
      re->SetTypedComponent(p, k, isValid ? raw[4 * p + k] : 0.0f);
      fe->SetTypedComponent(p, k, isValid ? filtered[4 * p + k] : 0.0f);
    }
    c->SetValue(p, isValid ? filtered[4 * p + 3] : 0.0f);
    rc->SetValue(p, isValid ? raw[4 * p + 3] : 0.0f);
  }
}
}

//------------------------------------------------------------------------------
bool vtkDeepRadiosityPass::CaptureIrradiance(vtkImageData* output, vtkRenderer* renderer)
{
  vtkDeepRadiosityRendererState* state = this->Internals->States.Find(renderer);
  if (!output || !state || !state->Renderer)
  {
    vtkErrorMacro("CaptureIrradiance: no radiosity has been rendered for this renderer.");
    return false;
  }
  vtkRenderer* ren = state->Renderer;
  const GLuint distanceHandle = this->GBufferPass->GetTextureHandle(ren, vtkDeepGBufferPass::DEPTH);
  if (!distanceHandle)
  {
    vtkErrorMacro("CaptureIrradiance: the G-buffer of this renderer is gone.");
    return false;
  }
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  window->MakeCurrent();
  vtkOpenGLState* ostate = window->GetState();
  vtkOpenGLClearErrorMacro();
  ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);
  vtkOpenGLState::ScopedglActiveTexture savedUnit(ostate);
  GLint previous2D = 0, previousArray = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous2D);
  glGetIntegerv(GL_TEXTURE_BINDING_2D_ARRAY, &previousArray);
  const size_t pixels = static_cast<size_t>(state->Width) * state->Height;
  int slots = 1;
  const std::vector<float> distance = DownloadDistance(distanceHandle, pixels, slots);
  output->Initialize();
  output->SetDimensions(state->Width, state->Height, 1);
  output->SetSpacing(1.0, 1.0, 1.0);
  output->SetOrigin(0.0, 0.0, 0.0);
  for (int j = 0; j < Layers; ++j)
  {
    AddIrradianceArrays(output, *state, distance, slots, j);
  }
  glBindTexture(GL_TEXTURE_2D, previous2D);
  glBindTexture(GL_TEXTURE_2D_ARRAY, previousArray);
  ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, 4);
  vtkDeepScreenSpace::CropGuardBand(output, state->GuardBand);
  AddIrradianceFieldData(output->GetFieldData(), *state);
  vtkOpenGLCheckErrorMacro("failed after capturing the radiosity");
  return true;
}

//------------------------------------------------------------------------------
const char* vtkDeepRadiosityPass::GetEstimatorAsString(int estimator)
{
  switch (estimator)
  {
    case ACCEPTED_TAPS:
      return "ACCEPTED_TAPS";
    case ALL_TAPS:
      return "ALL_TAPS";
    case SOLID_ANGLE:
      return "SOLID_ANGLE";
    default:
      return "unknown";
  }
}
