#include "vtkDeepRadiosityPass.h"
#include "vtkDeepGICaptureNames.h"

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
#include "vtkTextureUnitManager.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWeakPointer.h"
#include "vtk_glew.h"

#include "vtkDeepGeometryKeyFS.h"
#include "vtkDeepRadiosityBlurFS.h"
#include "vtkDeepRadiosityBounceFS.h"
#include "vtkDeepRadiosityCompositeFS.h"
#include "vtkDeepRadiosityFS.h"
#include "vtkDeepRadiosityIncrementFS.h"
#include "vtkDeepRadiosityReduceFS.h"
#include "vtkDeepRadiosityTemporalFS.h"
#include "vtkDeepRadiosityUpsampleFS.h"
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

// The program of a stage that reads a texel's last frame, variants[1] for
// frames whose reprojection is the identity: its source with
// DEEP_STILL_CAMERA defined, where the shader reads the texel itself
// instead of reprojecting (deepLastFrameTexel): the same texels without
// the reprojection's arithmetic, which a CPU renderer, running both sides
// of a branch, would execute even where its result is not used.
bool ReadyVariant(vtkOpenGLQuadHelper* (&variants)[2], bool still, vtkOpenGLRenderWindow* window,
  const char* source)
{
  vtkOpenGLQuadHelper*& quad = variants[still ? 1 : 0];
  // ReadyQuad reads the source only to compile: compose it only then.
  std::string fs;
  if (!quad)
  {
    fs = source;
    if (still)
    {
      vtkShaderProgram::Substitute(
        fs, "//VTK::System::Dec", "//VTK::System::Dec\n#define DEEP_STILL_CAMERA");
    }
  }
  return ReadyQuad(quad, window, fs.c_str());
}

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

// What the gather, the filters, the temporal filter and the upsampling
// write where layer 0 holds no surface (ScopedBackgroundSkip): no
// irradiance, no history.
const float NoIrradiance[4] = { 0.0f, 0.0f, 0.0f, 0.0f };

// The G-buffer quantities the passes read.
const int GBufferQuantities[] = { vtkDeepGBufferPass::DEPTH, vtkDeepGBufferPass::NORMAL,
  vtkDeepGBufferPass::RADIANCE, vtkDeepGBufferPass::AMBIENT, vtkDeepGBufferPass::ALBEDO };

// Those the stages on a reduced grid read (filters, temporal filter,
// upsampling), with their formats in the G-buffer (vtkDeepGBufferPass,
// Table 1), which the reduced copy keeps.
constexpr int NumberOfReducedQuantities = 3;
const int ReducedQuantities[NumberOfReducedQuantities] = { vtkDeepGBufferPass::DEPTH,
  vtkDeepGBufferPass::NORMAL, vtkDeepGBufferPass::ALBEDO };
const GLenum ReducedFormats[NumberOfReducedQuantities] = { GL_R32F, GL_RG8, GL_RGBA8 };
const int ReducedBytes[NumberOfReducedQuantities] = { 4, 2, 4 };

// The geometry keys (vtkDeepGeometryKeyFS): the layers' (the gather's
// taps) and, on a reduced grid, the grid's (the filters).
enum GeometryKey
{
  LAYER_KEY = 0,
  GRID_KEY = 1,
  NUMBER_OF_KEYS = 2
};

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
  bool anySwitchedOn = false;
  while (vtkLight* light = lights->GetNextLight(it))
  {
    anySwitchedOn = anySwitchedOn || light->GetSwitch();
    if (light->GetSwitch() && light->GetIntensity() > 0.0)
    {
      return true;
    }
  }
  // With no light switched on VTK adds a headlight of intensity 1 in this
  // very frame (its lights step, after the passes chose what to compute)
  // unless AutomaticLightCreation is off: a new renderer's first frame.
  return !anySwitchedOn && renderer->GetAutomaticLightCreation();
}

//------------------------------------------------------------------------------
// The radiosity targets and history of one renderer.
struct vtkDeepRadiosityRendererState
{
  vtkWeakPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkTextureObject> Targets[NUMBER_OF_TARGETS][Layers];
  // Keys[LAYER_KEY] at the layers' size; Keys[GRID_KEY] at the grid's with
  // a divisor D > 1, otherwise released (the grid is the layers').
  vtkSmartPointer<vtkTextureObject> Keys[NUMBER_OF_KEYS];
  // Coverage[key]: where layer 0 holds a surface on the key's texels
  // (vtkDeepScreenSpace::ReadyCoverage), written with the key; null
  // while the G-buffer's SkipBackgroundTexels is off.
  vtkSmartPointer<vtkTextureObject> Coverage[NUMBER_OF_KEYS];
  // History[i][j]: (E_t, distance) of layer j; History[HistoryCurrent] is
  // the last frame's.
  vtkSmartPointer<vtkTextureObject> History[2][Layers];
  int HistoryCurrent = 0;
  bool HistoryValid = false;
  // With a resolution divisor D > 1: the G-buffer quantities at texels D q
  // (2-slot arrays, ReducedQuantities' order), what the filters, temporal
  // filter and upsampling read; RAW, BLUR_TEMP, FILTERED and the history
  // have the reduced size (Width x Height), BOUNCE and INDIRECT the
  // layers' (LayerWidth x LayerHeight).
  GLuint Reduced[NumberOfReducedQuantities] = { 0, 0, 0 };
  GLuint ReducedFramebuffer = 0;
  int ReducedSize[2] = { 0, 0 }; // of the reduced G-buffer's textures
  int Divisor = 1;
  int LayerWidth = 0;
  int LayerHeight = 0;
  double PreviousView[16];
  double PreviousProjection[16];
  vtkDeepScreenSpace::RenderCounter Renders;
  unsigned int FrameIndex = 0; // frames since the history was reset
  int Width = 0;               // of the gather's grid: the layers (frame and guard band) / Divisor
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
  // The mean |E_k - E_k-1| of layer 0 in the last four frames without the
  // temporal filter, oldest first (ExtrapolateBounces), and how many.
  double Increments[4] = { 0.0, 0.0, 0.0, 0.0 };
  int IncrementCount = 0;
  double Extrapolation = 0.0; // rho / (1 - rho) of the current frame
  // What the geometry keys and the reduced G-buffer were built from
  // (GeometryKeysCurrent): the G-buffer's layers (their GetLayersTime; 0:
  // not built) and the divisor.
  vtkMTimeType KeysLayersTime = 0;
  int KeysDivisor = 0;

  void ResetHistory()
  {
    this->HistoryValid = false;
    this->FrameIndex = 0;
    this->IncrementCount = 0;
  }

  void Attach(vtkRenderer* renderer)
  {
    this->Renderer = renderer;
    this->Renders.Observe(renderer);
  }

  vtkTypeInt64 TextureBytes() const
  {
    vtkTypeInt64 bytes = 0;
    for (int q = 0; q < NumberOfReducedQuantities; ++q)
    {
      bytes += this->Reduced[q]
        ? static_cast<vtkTypeInt64>(ReducedBytes[q]) * Layers * this->Width * this->Height
        : 0;
    }
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
    for (int key = 0; key < NUMBER_OF_KEYS; ++key)
    {
      bytes += vtkDeepScreenSpace::TextureBytes(this->Keys[key]) +
        vtkDeepScreenSpace::TextureBytes(this->Coverage[key]);
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
    for (int key = 0; key < NUMBER_OF_KEYS; ++key)
    {
      ReleaseTarget(this->Keys[key], w);
      ReleaseTarget(this->Coverage[key], w);
    }
    this->ReleaseReduced();
    this->ResetHistory();
    this->Width = this->Height = this->LayerCount = 0;
    this->HasFrame = false;
  }

  void ReleaseReduced()
  {
    for (GLuint& t : this->Reduced)
    {
      if (t)
      {
        glDeleteTextures(1, &t);
        t = 0;
      }
    }
    if (this->ReducedFramebuffer)
    {
      glDeleteFramebuffers(1, &this->ReducedFramebuffer);
      this->ReducedFramebuffer = 0;
    }
    this->ReducedSize[0] = this->ReducedSize[1] = 0;
  }

  // Texel `p` of the layers -> its texel of the gather's grid.
  size_t GridIndex(size_t p) const
  {
    const size_t x = p % this->LayerWidth, y = p / this->LayerWidth;
    return std::min<size_t>(y / this->Divisor, this->Height - 1) * this->Width +
      std::min<size_t>(x / this->Divisor, this->Width - 1);
  }

  vtkTextureObject* Output(int quantity, int layer)
  {
    if (!this->HasFrame || layer < 0 || layer >= Layers)
    {
      return nullptr;
    }
    if (quantity == vtkDeepRadiosityPass::IRRADIANCE)
    {
      return this->History[this->HistoryCurrent][layer];
    }
    return quantity == vtkDeepRadiosityPass::INDIRECT_RADIANCE ? this->Indirect(layer) : nullptr;
  }

  // The key of the gather's output grid (the filters', the temporal
  // filter's): the layers' own without a divisor.
  vtkTextureObject* GridKey()
  {
    return this->Divisor > 1 ? this->Keys[GRID_KEY] : this->Keys[LAYER_KEY];
  }

  // The coverage of the grid's texels (null: none).
  vtkTextureObject* GridCoverage()
  {
    return this->Divisor > 1 ? this->Coverage[GRID_KEY] : this->Coverage[LAYER_KEY];
  }

  // L of a layer: INDIRECT, except layer 1 on a reduced grid, which stays
  // there (BLUR_TEMP, see UpsampleIrradiance).
  vtkTextureObject* Indirect(int layer)
  {
    return layer > 0 && this->Divisor > 1 ? this->Targets[BLUR_TEMP][layer]
                                          : this->Targets[INDIRECT][layer];
  }
};

class vtkDeepRadiosityPass::vtkInternals
{
public:
  vtkDeepScreenSpace::RendererStates<vtkDeepRadiosityRendererState> States;
  vtkOpenGLFramebufferObject* Framebuffer = nullptr;
  // The bounce input's and the temporal filter's programs, each also in a
  // variant for frames whose reprojection is the identity (index 1,
  // DEEP_STILL_CAMERA, see ReadyVariant).
  vtkOpenGLQuadHelper* BounceQuads[2] = { nullptr, nullptr };
  vtkOpenGLQuadHelper* GatherQuad = nullptr;
  vtkOpenGLQuadHelper* KeyQuad = nullptr;
  vtkOpenGLQuadHelper* BlurQuad = nullptr;
  double BlurQuadNormalPower = 0.0; // the BlurNormalPower BlurQuad was compiled for
  vtkOpenGLQuadHelper* TemporalQuads[2] = { nullptr, nullptr };
  vtkOpenGLQuadHelper* IncrementQuad = nullptr; // ExtrapolateBounces
  vtkOpenGLQuadHelper* CompositeQuad = nullptr;
  vtkOpenGLQuadHelper* ReduceQuad = nullptr;
  vtkOpenGLQuadHelper* UpsampleQuad = nullptr;
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
  for (vtkOpenGLQuadHelper* quad : { in.BounceQuads[0], in.BounceQuads[1], in.GatherQuad,
         in.KeyQuad, in.BlurQuad, in.TemporalQuads[0], in.TemporalQuads[1], in.IncrementQuad,
         in.CompositeQuad, in.ReduceQuad, in.UpsampleQuad })
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
  os << indent << "OuterSamples: " << this->OuterSamples << "\n";
  os << indent << "UseNormalTest: " << (this->UseNormalTest ? "On" : "Off") << "\n";
  os << indent << "Estimator: " << GetEstimatorAsString(this->Estimator) << "\n";
  os << indent << "UseColorBoost: " << (this->UseColorBoost ? "On" : "Off") << "\n";
  os << indent << "BlurRadius: " << this->BlurRadius << "\n";
  os << indent << "GuardBandShadedFraction: " << this->GuardBandShadedFraction << "\n";
  os << indent << "BlurPlaneTolerance: " << this->BlurPlaneTolerance << "\n";
  os << indent << "BlurNormalPower: " << this->BlurNormalPower << "\n";
  os << indent << "MipThreshold: " << this->MipThreshold << "\n";
  os << indent << "MinimumMipLevel: " << this->MinimumMipLevel << "\n";
  os << indent << "MaximumMipLevel: " << this->MaximumMipLevel << "\n";
  os << indent << "AverageFarTaps: " << (this->AverageFarTaps ? "On" : "Off") << "\n";
  os << indent << "ResolutionDivisor: " << this->ResolutionDivisor << "\n";
  os << indent << "Damping: " << this->Damping << "\n";
  os << indent << "TemporalAlpha: " << this->TemporalAlpha << "\n";
  os << indent << "TemporalInterleave: " << this->TemporalInterleave << "\n";
  os << indent
     << "SkipStillCameraReprojection: " << (this->SkipStillCameraReprojection ? "On" : "Off")
     << "\n";
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
  vtkDeepSetManualLengthMacro(Radius, radius, false, " (no indirect light)");
}

//------------------------------------------------------------------------------
void vtkDeepRadiosityPass::SetResolutionDivisor(int divisor)
{
  if (divisor < 1 || divisor > 2)
  {
    const int clamped = divisor < 1 ? 1 : 2;
    vtkWarningMacro(
      "ResolutionDivisor " << divisor << " is outside 1..2; using " << clamped << ".");
    divisor = clamped;
  }
  if (divisor != this->ResolutionDivisor)
  {
    this->ResolutionDivisor = divisor;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkDeepRadiosityPass::SetNumberOfSamples(int samples)
{
  this->SetSampleCount(samples, this->NumberOfSamples);
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
  vtkDeepSetManualLengthMacro(ReprojectionTolerance, tolerance, false, "");
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
  // Table 2 of the paper, and the resolution divisor: HIGH_PERFORMANCE
  // gathers for a quarter of the texels, at about a third of the
  // radiosity's time (Documentation/performance.md); on finely detailed
  // meshes the grid loses per-texel irradiance (BALANCED on the grid is up to
  // 47 % farther from the reference, Documentation/radiosity.md), so the
  // other presets keep every texel. BALANCED's minimum MIP level is 1, not
  // Table 2's 2: at level 2 the interiors' single-bounce irradiance came out
  // 2-11 % of the truth darker than at level 0, at level 1 within 0.3 %
  // (Documentation/radiosity.md), for a bounce input computed at one texel
  // in 4 instead of one in 16.
  struct Settings
  {
    int Samples;
    int BlurRadius;
    bool NormalTest;
    int MinimumMipLevel;
    double GuardBandShaded;
    int ResolutionDivisor;
  };
  static const Settings presets[] = { { 13, 4, false, 3, 0.1, 2 }, { 14, 5, true, 1, 0.5, 1 },
    { 30, 6, true, 0, 0.8, 1 } };
  if (preset < HIGH_PERFORMANCE || preset > HIGH_QUALITY)
  {
    vtkWarningMacro("Unknown preset " << preset << "; the settings are unchanged.");
    return;
  }
  const Settings& p = presets[preset];
  this->NumberOfSamples = p.Samples;
  this->BlurRadius = p.BlurRadius;
  this->UseNormalTest = p.NormalTest;
  this->MinimumMipLevel = p.MinimumMipLevel;
  this->GuardBandShadedFraction = p.GuardBandShaded;
  this->ResolutionDivisor = p.ResolutionDivisor;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkDeepRadiosityPass::SetFilterTaps(int taps)
{
  this->SetBlurRadius((std::min(std::max(taps, 1), 33) - 1) / 2);
}

//------------------------------------------------------------------------------
const char* vtkDeepRadiosityPass::GetPresetAsString(int preset)
{
  static_assert(HIGH_PERFORMANCE == 0 && BALANCED == 1 && HIGH_QUALITY == 2,
    "the presets of the deep passes share their values");
  return vtkDeepScreenSpace::PresetName(preset);
}

//------------------------------------------------------------------------------
void vtkDeepRadiosityPass::RenderOpaque(const vtkRenderState* s)
{
  vtkInternals& in = *this->Internals;
  vtkOpenGLRenderer* renderer = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  vtkDeepGBufferPass* gbuffer = this->GBufferPass;
  if (!this->RenderLayersOrWarn(s, "radiosity"))
  {
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
  int TapStride = 1; // TemporalInterleave while the temporal filter is on
  int TapPhase = 0;
  int Units[vtkDeepGBufferPass::NUMBER_OF_QUANTITIES]; // of the G-buffer's textures
  int MinimumMip = 0; // the coarsest level the taps use is MaximumMip
  int MaximumMip = 0;
  int BounceSize[2] = { 0, 0 }; // BOUNCE's texels: those of level MinimumMip
  int Previous = 0;             // History[Previous] is the last frame's, History[Next] this one's
  int Next = 1;
  float ToPrevious[16];
  float PreviousProjection[16];
  // Whether the bounce input and the temporal filter find a texel's last
  // frame at the texel itself (their DEEP_STILL_CAMERA variants): the
  // history is of this camera (the bounce input also needs it on the
  // layers' own grid, Divisor 1), or the temporal filter is off.
  bool StillBounce = false;
  bool StillTemporal = false;
  // The grid of the gather's output: with Divisor > 1, Size, Region,
  // Projection, ProjXY and ProjT are the reduced grid's and Units the
  // reduced G-buffer's (filters, temporal filter); the layers' own are kept
  // here for the bounce input, the gather's taps and the upsampling.
  int Divisor = 1;
  int LayerSize[2] = { 0, 0 };
  int LayerRegion[4] = { 0, 0, 0, 0 };
  float LayerProjXY[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
  float LayerProjT[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
  int LayerUnits[vtkDeepGBufferPass::NUMBER_OF_QUANTITIES];

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
  ReduceFrame(frame, this->ResolutionDivisor);
  if (!this->PrepareTargets(frame, state))
  {
    return false;
  }
  vtkDeepGBufferPass* gbuffer = this->GBufferPass;
  for (int q : GBufferQuantities)
  {
    frame.LayerUnits[q] = frame.Units[q] = gbuffer->ActivateTexture(frame.Renderer, q);
  }
  {
    vtkOpenGLState* ostate = frame.GL;
    vtkDeepScreenSpace::ScopedStageState stageState(ostate);
    // Frames that keep the G-buffer's layers (vtkDeepGIPass::Converge) keep
    // what is derived from them alone.
    const bool keysCurrent = this->GeometryKeysCurrent(frame, state);
    if (frame.Divisor > 1)
    {
      if (!keysCurrent)
      {
        this->ReduceLayers(frame, state);
      }
      BindReduced(frame, state);
    }
    this->Internals->Framebuffer->Bind();
    if (!keysCurrent)
    {
      this->BuildGeometryKeys(frame, state);
    }
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
    if (frame.Divisor > 1)
    {
      this->UpsampleIrradiance(frame, state);
    }
    for (int a = 0; a < 2 * Layers; ++a)
    {
      this->Internals->Framebuffer->RemoveColorAttachment(a);
    }
  }
  if (frame.Divisor > 1)
  {
    UnbindReduced(frame);
  }
  for (int q : GBufferQuantities)
  {
    if (frame.LayerUnits[q] >= 0)
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
  const double diagonal = vtkDeepScreenSpace::SceneDiagonal(renderer);
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
// The gather's grid for a resolution divisor D > 1 (see
// SetResolutionDivisor): ceil(size / D) texels, the shaded region's texels
// divided by D (rounded outwards), and the projection under which its texel
// centres stand at the layers' texels D q (ReducedProjection).
void vtkDeepRadiosityPass::ReduceFrame(vtkGatherFrame& frame, int divisor)
{
  frame.Divisor = divisor;
  std::copy(frame.Size, frame.Size + 2, frame.LayerSize);
  std::copy(frame.Region, frame.Region + 4, frame.LayerRegion);
  std::copy(frame.ProjXY, frame.ProjXY + 4, frame.LayerProjXY);
  std::copy(frame.ProjT, frame.ProjT + 4, frame.LayerProjT);
  if (divisor <= 1)
  {
    return;
  }
  for (int axis = 0; axis < 2; ++axis)
  {
    frame.Size[axis] = (frame.LayerSize[axis] + divisor - 1) / divisor;
    frame.Region[axis] = frame.LayerRegion[axis] / divisor;
    frame.Region[2 + axis] =
      std::min((frame.LayerRegion[2 + axis] + divisor - 1) / divisor, frame.Size[axis]);
  }
  double layerProjection[16];
  std::copy(frame.Projection, frame.Projection + 16, layerProjection);
  vtkDeepScreenSpace::ReducedProjection(
    layerProjection, frame.LayerSize, frame.Size, divisor, frame.Projection);
  vtkDeepScreenSpace::ProjectionUniforms(frame.Projection, frame.ProjXY, frame.ProjT);
}

//------------------------------------------------------------------------------
// The renderer's history (reset on a resize, a new layer count, shaded
// region or divisor, and when this renderer was rendered without this pass
// since the history's frame), this frame's rotation and MIP range, the
// targets, the reprojection and the programs.
bool vtkDeepRadiosityPass::PrepareTargets(
  vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state)
{
  vtkInternals& in = *this->Internals;
  vtkOpenGLRenderWindow* window = frame.Window;
  const int width = frame.Size[0], height = frame.Size[1];
  this->ChooseTapLevels(frame);
  if (!state.Renders.Consecutive() || state.Width != width || state.Height != height ||
    state.Divisor != frame.Divisor || state.LayerCount != frame.UsedLayers ||
    !std::equal(frame.Region, frame.Region + 4, state.ShadedRegion))
  {
    state.ResetHistory();
  }
  ++state.FrameIndex;
  frame.RotationOffset = this->TemporalAlpha > 0.0 ? RotationOffset(state.FrameIndex) : 0.0;
  frame.TapStride = this->TemporalAlpha > 0.0 ? this->TemporalInterleave : 1;
  frame.TapPhase = static_cast<int>(state.FrameIndex % static_cast<unsigned int>(frame.TapStride));
  if (!this->AllocateTargets(frame, state))
  {
    vtkErrorMacro("Could not allocate the radiosity targets.");
    return false;
  }
  state.Width = width;
  state.Height = height;
  state.Divisor = frame.Divisor;
  state.LayerWidth = frame.LayerSize[0];
  state.LayerHeight = frame.LayerSize[1];
  state.GuardBand = frame.GuardBand;
  std::copy(frame.Region, frame.Region + 4, state.ShadedRegion);
  state.LayerCount = frame.UsedLayers;
  if (!in.Framebuffer)
  {
    in.Framebuffer = vtkOpenGLFramebufferObject::New();
    in.Framebuffer->SetContext(window);
  }
  const bool stillCamera = this->SkipStillCameraReprojection && state.HistoryValid &&
    std::equal(frame.View, frame.View + 16, state.PreviousView) &&
    std::equal(frame.Projection, frame.Projection + 16, state.PreviousProjection);
  frame.StillBounce = stillCamera && frame.Divisor == 1;
  frame.StillTemporal =
    this->SkipStillCameraReprojection && (stillCamera || !(this->TemporalAlpha > 0.0));
  const bool ready =
    ReadyVariant(in.BounceQuads, frame.StillBounce, window, vtkDeepRadiosityBounceFS) &&
    ReadyQuad(in.GatherQuad, window, vtkDeepRadiosityFS) &&
    ReadyQuad(in.KeyQuad, window, vtkDeepGeometryKeyFS) &&
    vtkDeepScreenSpace::ReadyBilateralQuad(
      in.BlurQuad, in.BlurQuadNormalPower, window, vtkDeepRadiosityBlurFS, this->BlurNormalPower) &&
    ReadyVariant(in.TemporalQuads, frame.StillTemporal, window, vtkDeepRadiosityTemporalFS) &&
    ReadyQuad(in.CompositeQuad, window, vtkDeepRadiosityCompositeFS) &&
    (frame.Divisor == 1 ||
      (ReadyQuad(in.ReduceQuad, window, vtkDeepRadiosityReduceFS) &&
        ReadyQuad(in.UpsampleQuad, window, vtkDeepRadiosityUpsampleFS)));
  if (!ready)
  {
    vtkErrorMacro("The radiosity shaders failed to compile.");
    return false;
  }
  if (!this->AllocateReduced(frame, state))
  {
    return false;
  }
  vtkDeepScreenSpace::ReprojectionUniforms(frame.View, frame.Projection, state.HistoryValid,
    state.PreviousView, state.PreviousProjection, frame.ToPrevious, frame.PreviousProjection);
  frame.Previous = state.HistoryCurrent;
  frame.Next = 1 - state.HistoryCurrent;
  return true;
}

//------------------------------------------------------------------------------
// The MIP levels the taps read (Table 2's minimum to the coarsest level the
// layers have) and the size of the bounce input, which holds the texels of
// the minimum level.
void vtkDeepRadiosityPass::ChooseTapLevels(vtkGatherFrame& frame) const
{
  frame.MaximumMip = std::min(std::max(this->MaximumMipLevel, this->MinimumMipLevel),
    CoarsestMipLevel(frame.LayerSize[0], frame.LayerSize[1]));
  frame.MinimumMip = std::min(this->MinimumMipLevel, frame.MaximumMip);
  for (int axis = 0; axis < 2; ++axis)
  {
    frame.BounceSize[axis] = std::max(frame.LayerSize[axis] >> frame.MinimumMip, 1);
  }
}

//------------------------------------------------------------------------------
// The per-layer targets and the history, (re)allocated when their sizes
// change. Returns false when one could not be allocated.
bool vtkDeepRadiosityPass::AllocateTargets(
  vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state)
{
  vtkOpenGLRenderWindow* window = frame.Window;
  bool allocated = true;
  for (int target = 0; target < NUMBER_OF_TARGETS; ++target)
  {
    // BOUNCE holds the gather's sources (texels of the minimum MIP level);
    // INDIRECT, what the composites read, has every layer texel; on a
    // reduced grid only layer 0's INDIRECT exists.
    const int* size = target == BOUNCE ? frame.BounceSize
      : target == INDIRECT             ? frame.LayerSize
                                       : frame.Size;
    for (int layer = 0; layer < Layers; ++layer)
    {
      vtkSmartPointer<vtkTextureObject>& t = state.Targets[target][layer];
      if (target == INDIRECT && layer > 0 && frame.Divisor > 1)
      {
        ReleaseTarget(t, window);
        continue;
      }
      // Radiances and irradiances in half floats, like the G-buffer's
      // RADIANCE they start from (E is clamped to IRRADIANCE_LIMIT, the
      // largest half float): half the bytes of RGBA32F for every filter tap
      // and gather source. The history keeps 32-bit floats for the
      // distances its reprojection compares.
      allocated = allocated && AllocateTarget(t, window, size[0], size[1], 4, true);
      if (target == BOUNCE && t)
      {
        // With AverageFarTaps, levels MinimumMip..MaximumMip of the layers;
        // otherwise one level (a mipmapped texture whose levels are never
        // written would be incomplete and read as 0).
        const int coarserLevels = this->AverageFarTaps ? frame.MaximumMip - frame.MinimumMip : 0;
        t->SetMinificationFilter(
          coarserLevels > 0 ? vtkTextureObject::NearestMipmapNearest : vtkTextureObject::Nearest);
        t->SetMaxLevel(coarserLevels);
      }
    }
  }
  for (auto& ping : state.History)
  {
    for (auto& t : ping)
    {
      allocated = allocated && AllocateTarget(t, window, frame.Size[0], frame.Size[1], 4);
    }
  }
  allocated = allocated &&
    AllocateTarget(state.Keys[LAYER_KEY], window, frame.LayerSize[0], frame.LayerSize[1], 4);
  if (frame.Divisor > 1)
  {
    allocated =
      allocated && AllocateTarget(state.Keys[GRID_KEY], window, frame.Size[0], frame.Size[1], 4);
  }
  else
  {
    ReleaseTarget(state.Keys[GRID_KEY], window);
  }
  for (int key = 0; key < NUMBER_OF_KEYS; ++key)
  {
    const int* size = key == LAYER_KEY ? frame.LayerSize : frame.Size;
    vtkDeepScreenSpace::ReadyCoverage(state.Coverage[key], window, size[0], size[1],
      this->GBufferPass->GetSkipBackgroundTexels() && state.Keys[key]);
  }
  return allocated;
}

//------------------------------------------------------------------------------
// The reduced G-buffer's textures and framebuffer (divisor > 1; released
// otherwise), kept while the reduced size is unchanged.
bool vtkDeepRadiosityPass::AllocateReduced(
  vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state)
{
  if (frame.Divisor <= 1)
  {
    state.ReleaseReduced();
    return true;
  }
  if (state.ReducedFramebuffer && std::equal(frame.Size, frame.Size + 2, state.ReducedSize))
  {
    return true;
  }
  state.ReleaseReduced();
  bool allocated = true;
  for (int q = 0; q < NumberOfReducedQuantities; ++q)
  {
    GLint width = 0;
    glGenTextures(1, &state.Reduced[q]);
    glBindTexture(GL_TEXTURE_2D_ARRAY, state.Reduced[q]);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
    glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, ReducedFormats[q], frame.Size[0], frame.Size[1], Layers);
    // Whether the storage exists (glGetError may hold an older error).
    glGetTexLevelParameteriv(GL_TEXTURE_2D_ARRAY, 0, GL_TEXTURE_WIDTH, &width);
    allocated = allocated && width == frame.Size[0];
  }
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  glGenFramebuffers(1, &state.ReducedFramebuffer);
  if (!allocated)
  {
    vtkErrorMacro("Could not allocate the reduced G-buffer of the radiosity.");
    state.ReleaseReduced();
    return false;
  }
  std::copy(frame.Size, frame.Size + 2, state.ReducedSize);
  return true;
}

//------------------------------------------------------------------------------
// Step 0 (divisor > 1): the reduced G-buffer, texel q = the layers' texel
// D q, one draw per layer; the later stages read it instead of the layers.
void vtkDeepRadiosityPass::ReduceLayers(vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state)
{
  vtkInternals& in = *this->Internals;
  vtkDeepScreenSpace::ScopedStageTime time(this->GetStageTimer(), "radiosity: reduce");
  vtkOpenGLState* ostate = frame.GL;
  vtkShaderProgram* program = in.ReduceQuad->Program;
  frame.Window->GetShaderCache()->ReadyShaderProgram(program);
  const char* names[NumberOfReducedQuantities] = { "deepDistance", "deepNormal", "deepAlbedo" };
  for (int q = 0; q < NumberOfReducedQuantities; ++q)
  {
    program->SetUniformi(names[q], frame.LayerUnits[ReducedQuantities[q]]);
  }
  program->SetUniformi("deepDivisor", frame.Divisor);
  program->SetUniform2i("deepReducedSize", frame.Size);
  ostate->vtkglBindFramebuffer(GL_FRAMEBUFFER, state.ReducedFramebuffer);
  const GLenum drawBuffers[NumberOfReducedQuantities] = { GL_COLOR_ATTACHMENT0,
    GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2 };
  glDrawBuffers(NumberOfReducedQuantities, drawBuffers);
  ostate->vtkglViewport(0, 0, frame.Size[0], frame.Size[1]);
  for (int layer = 0; layer < frame.UsedLayers; ++layer)
  {
    for (int q = 0; q < NumberOfReducedQuantities; ++q)
    {
      glFramebufferTextureLayer(
        GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + q, state.Reduced[q], 0, layer);
    }
    program->SetUniformi("deepLayer", layer);
    in.ReduceQuad->Render();
  }
}

//------------------------------------------------------------------------------
// The later stages read the reduced G-buffer (ReduceLayers).
void vtkDeepRadiosityPass::BindReduced(
  vtkGatherFrame& frame, const vtkDeepRadiosityRendererState& state)
{
  vtkOpenGLState* ostate = frame.GL;
  vtkTextureUnitManager* units = frame.Window->GetTextureUnitManager();
  for (int q = 0; q < NumberOfReducedQuantities; ++q)
  {
    const int unit = units->Allocate();
    ostate->vtkglActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D_ARRAY, state.Reduced[q]);
    frame.Units[ReducedQuantities[q]] = unit;
  }
}

//------------------------------------------------------------------------------
// Frees the texture units of the reduced G-buffer (ReduceLayers).
void vtkDeepRadiosityPass::UnbindReduced(vtkGatherFrame& frame)
{
  vtkTextureUnitManager* units = frame.Window->GetTextureUnitManager();
  for (int q : GBufferQuantities)
  {
    if (frame.Units[q] >= 0 && frame.Units[q] != frame.LayerUnits[q])
    {
      frame.GL->vtkglActiveTexture(GL_TEXTURE0 + frame.Units[q]);
      glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
      units->Free(frame.Units[q]);
      frame.Units[q] = frame.LayerUnits[q];
    }
  }
}

//------------------------------------------------------------------------------
// Step 0b: the geometry keys (vtkDeepGeometryKeyFS) over the whole layers
// (the taps read the guard band too) and, on a reduced grid, over the
// grid (from the reduced G-buffer). Leaves the framebuffer without
// attachments.
void vtkDeepRadiosityPass::BuildGeometryKeys(
  vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state)
{
  vtkInternals& in = *this->Internals;
  vtkDeepScreenSpace::ScopedStageTime time(this->GetStageTimer(), "radiosity: geometry key");
  vtkShaderProgram* program = in.KeyQuad->Program;
  frame.Window->GetShaderCache()->ReadyShaderProgram(program);
  program->SetUniformi("deepLayers", frame.UsedLayers);
  program->SetUniformi("deepFirstLayer", 0);
  for (int key = 0; key < NUMBER_OF_KEYS; ++key)
  {
    vtkTextureObject* target = state.Keys[key];
    if (!target)
    {
      continue;
    }
    const int* units = key == LAYER_KEY ? frame.LayerUnits : frame.Units;
    const int size[2] = { static_cast<int>(target->GetWidth()),
      static_cast<int>(target->GetHeight()) };
    in.Framebuffer->AddColorAttachment(0, target);
    in.Framebuffer->ActivateDrawBuffers(1);
    frame.GL->vtkglViewport(0, 0, size[0], size[1]);
    program->SetUniformi("deepDistance", units[vtkDeepGBufferPass::DEPTH]);
    program->SetUniformi("deepNormal", units[vtkDeepGBufferPass::NORMAL]);
    program->SetUniformi("deepFacing", units[vtkDeepGBufferPass::ALBEDO]);
    program->SetUniformi("deepWithFacing", 0); // the radiosity does not read it
    program->SetUniform2i("deepKeySize", size);
    vtkDeepScreenSpace::ScopedCoverageWrite coverage(
      frame.GL, in.Framebuffer->GetFBOIndex(), state.Coverage[key]);
    in.KeyQuad->Render();
  }
  in.Framebuffer->RemoveColorAttachment(0);
  state.KeysLayersTime = this->GBufferPass->GetLayersTime(frame.Renderer);
  state.KeysDivisor = frame.Divisor;
}

//------------------------------------------------------------------------------
// Whether the geometry keys (and, with a divisor, the reduced G-buffer) are
// those of this frame's layers: built from the layers the G-buffer still
// holds (vtkDeepGBufferPass::GetLayersTime, which stays while a frame keeps
// them) on the same grid. The rest they depend on comes with the layers:
// their size and count, and the coverage, which follows the G-buffer's
// SkipBackgroundTexels (a changed G-buffer setting renders the layers
// again).
bool vtkDeepRadiosityPass::GeometryKeysCurrent(
  const vtkGatherFrame& frame, const vtkDeepRadiosityRendererState& state)
{
  return state.KeysLayersTime != 0 &&
    state.KeysLayersTime == this->GBufferPass->GetLayersTime(frame.Renderer) &&
    state.KeysDivisor == frame.Divisor;
}

//------------------------------------------------------------------------------
// The distance, normal and projection uniforms of the layers themselves
// (not the reduced grid's): the bounce input and the gather's taps.
void vtkDeepRadiosityPass::SetLayersUniforms(vtkShaderProgram* program, const vtkGatherFrame& frame)
{
  program->SetUniformi("deepDistance", frame.LayerUnits[vtkDeepGBufferPass::DEPTH]);
  program->SetUniformi("deepNormal", frame.LayerUnits[vtkDeepGBufferPass::NORMAL]);
  program->SetUniform4f("deepProjXY", frame.LayerProjXY);
  program->SetUniform4f("deepProjT", frame.LayerProjT);
}

//------------------------------------------------------------------------------
// The uniforms of eq. 6's outgoing radiance (deepOutgoingIndirect): the
// boost, the confidence fallback and the environment's irradiance.
void vtkDeepRadiosityPass::SetOutgoingUniforms(vtkShaderProgram* program)
{
  program->SetUniformi("deepBoost", this->UseColorBoost ? 1 : 0);
  program->SetUniformi("deepFallback", this->ConfidenceFallback ? 1 : 0);
  const float environment[3] = { static_cast<float>(this->EffectiveEnvironmentIrradiance[0]),
    static_cast<float>(this->EffectiveEnvironmentIrradiance[1]),
    static_cast<float>(this->EffectiveEnvironmentIrradiance[2]) };
  program->SetUniform3f("deepEnvironment", environment);
}

//------------------------------------------------------------------------------
// Step 1, bounce input B = direct + delta L_ind,t-1 (section 3.3), over the
// whole layers (the guard band's surfaces are sources for the gather), at
// the texels the gather reads: those level MinimumMip of the rotated-grid
// pyramid holds.
void vtkDeepRadiosityPass::ComputeBounceInput(
  vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state)
{
  vtkInternals& in = *this->Internals;
  vtkDeepScreenSpace::ScopedStageTime time(this->GetStageTimer(), "radiosity: bounce input");
  AttachLayerTextures(in.Framebuffer, state.Targets[BOUNCE]);
  frame.GL->vtkglViewport(0, 0, frame.BounceSize[0], frame.BounceSize[1]);
  vtkOpenGLQuadHelper* quad = in.BounceQuads[frame.StillBounce ? 1 : 0];
  vtkShaderProgram* program = quad->Program;
  frame.Window->GetShaderCache()->ReadyShaderProgram(program);
  // The history's texels, on the gather's output grid, are the ones shaded.
  vtkDeepScreenSpace::SetShadedRegionUniforms(program, frame.Region);
  const float historySize[2] = { static_cast<float>(frame.Size[0]),
    static_cast<float>(frame.Size[1]) };
  program->SetUniform2f("deepHistorySize", historySize);
  SetLayersUniforms(program, frame);
  program->SetUniformi("deepRadiance", frame.LayerUnits[vtkDeepGBufferPass::RADIANCE]);
  program->SetUniformi("deepAmbient", frame.LayerUnits[vtkDeepGBufferPass::AMBIENT]);
  program->SetUniformi("deepAlbedo", frame.LayerUnits[vtkDeepGBufferPass::ALBEDO]);
  BindLayerTextures(program, "deepHistory", state.History[frame.Previous]);
  program->SetUniformi("deepLayers", frame.UsedLayers);
  program->SetUniformi("deepHasHistory", state.HistoryValid ? 1 : 0);
  program->SetUniformMatrix4x4("deepToPrevious", frame.ToPrevious);
  program->SetUniformMatrix4x4("deepPrevProjection", frame.PreviousProjection);
  program->SetUniformf("deepTolerance", static_cast<float>(frame.Tolerance));
  program->SetUniformf("deepDamping", static_cast<float>(this->Damping));
  program->SetUniformf("deepIrradianceLimit", static_cast<float>(IRRADIANCE_LIMIT));
  program->SetUniformi("deepBoost", this->UseColorBoost ? 1 : 0);
  program->SetUniformi("deepHasLights", frame.HasLights ? 1 : 0);
  program->SetUniformi("deepSourceLevel", frame.MinimumMip);
  program->SetUniform2i("deepBounceSize", frame.BounceSize);
  quad->Render();
  UnbindLayerTextures(state.History[frame.Previous]);
  if (this->AverageFarTaps && frame.MaximumMip > frame.MinimumMip)
  {
    // The coarser levels: box-filtered (B coverage, coverage), so that
    // rgb / a is the block's mean B over its surfaces.
    for (int a = 0; a < Layers; ++a)
    {
      in.Framebuffer->RemoveColorAttachment(a);
    }
    for (auto& t : state.Targets[BOUNCE])
    {
      t->Activate();
      glGenerateMipmap(GL_TEXTURE_2D);
      t->Deactivate();
    }
  }
  frame.GL->vtkglViewport(0, 0, frame.Size[0], frame.Size[1]);
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
  // Receivers on the output grid, taps and sources in the layers.
  state.Keys[LAYER_KEY]->Activate();
  SetKeyUniforms(
    program, state.Keys[LAYER_KEY]->GetTextureUnit(), frame.LayerProjXY, frame.LayerProjT);
  program->SetUniform2i("deepReceiverGrid", frame.Size);
  program->SetUniformi("deepDivisor", frame.Divisor);
  BindLayerTextures(program, "deepBounce", state.Targets[BOUNCE]);
  program->SetUniformi("deepSamples", this->NumberOfSamples);
  program->SetUniformf(
    "deepTurns", static_cast<float>(vtkDeepScreenSpace::SpiralTurns(this->NumberOfSamples)));
  program->SetUniformf("deepRadius", static_cast<float>(frame.Radius));
  program->SetUniformi("deepOuterSamples", this->OuterSamples);
  program->SetUniformf("deepOuterScale", static_cast<float>(OUTER_RADIUS_SCALE));
  program->SetUniformf("deepMipThreshold", static_cast<float>(this->MipThreshold));
  program->SetUniformi("deepMinMip", frame.MinimumMip);
  program->SetUniformi("deepMaxMip", frame.MaximumMip);
  program->SetUniformi("deepNormalTest", this->UseNormalTest ? 1 : 0);
  program->SetUniformi("deepAverageFarTaps", this->AverageFarTaps ? 1 : 0);
  program->SetUniformi("deepEstimator", this->Estimator);
  program->SetUniformf("deepIrradianceLimit", static_cast<float>(IRRADIANCE_LIMIT));
  program->SetUniformf("deepCosineEpsilon", static_cast<float>(COSINE_EPSILON));
  program->SetUniformf("deepRotationOffset", static_cast<float>(frame.RotationOffset));
  program->SetUniformi("deepTapStride", frame.TapStride);
  program->SetUniformi("deepTapPhase", frame.TapPhase);
  vtkDeepScreenSpace::ScopedBackgroundSkip skip(
    frame.GL, in.Framebuffer->GetFBOIndex(), state.GridCoverage());
  skip.Draw(in.GatherQuad, NoIrradiance);
  UnbindLayerTextures(state.Targets[BOUNCE]);
  state.Keys[LAYER_KEY]->Deactivate();
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
  vtkTextureObject* key = state.GridKey();
  key->Activate();
  vtkDeepScreenSpace::ScopedBackgroundSkip skip(
    frame.GL, in.Framebuffer->GetFBOIndex(), state.GridCoverage());
  for (const auto& pass : passes)
  {
    AttachLayerTextures(in.Framebuffer, state.Targets[pass[1]]);
    frame.Window->GetShaderCache()->ReadyShaderProgram(program);
    vtkDeepScreenSpace::SetShadedRegionUniforms(program, frame.Region);
    BindLayerTextures(program, "deepInput", state.Targets[pass[0]]);
    SetKeyUniforms(program, key->GetTextureUnit(), frame.ProjXY, frame.ProjT);
    const int axis[2] = { pass[2] == 0 ? 1 : 0, pass[2] == 0 ? 0 : 1 };
    program->SetUniform2i("deepAxis", axis);
    program->SetUniformi("deepBlurRadius", this->BlurRadius);
    program->SetUniformf("deepPlaneTolerance", static_cast<float>(this->BlurPlaneTolerance));
    skip.Draw(in.BlurQuad, NoIrradiance);
    UnbindLayerTextures(state.Targets[pass[0]]);
  }
  key->Deactivate();
}

//------------------------------------------------------------------------------
namespace
{
// The mean of a 2D RGBA32F target's colour over all its texels: the 1 x 1
// level of its box-filtered pyramid, read back (a stall, taken only while
// converging a still image).
double MeanColour(vtkTextureObject* texture)
{
  const unsigned int size = std::max(texture->GetWidth(), texture->GetHeight());
  int top = 0;
  while ((size >> top) > 1)
  {
    ++top;
  }
  float texel[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
  texture->SetMaxLevel(top); // level 0 alone is read everywhere else
  texture->Activate();
  glGenerateMipmap(GL_TEXTURE_2D);
  glGetTexImage(GL_TEXTURE_2D, top, GL_RGBA, GL_FLOAT, texel);
  texture->Deactivate();
  return (static_cast<double>(texel[0]) + texel[1] + texel[2]) / 3.0;
}
}

//------------------------------------------------------------------------------
// ExtrapolateBounces, step 1: the mean |E_k - E_k-1| of layer 0 (the
// filtered E is E_k without the temporal filter), drawn into BLUR_TEMP,
// free between the blur and the temporal filter and not captured.
double vtkDeepRadiosityPass::MeasureLastBounce(
  vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state)
{
  vtkInternals& in = *this->Internals;
  vtkTextureObject* increment = state.Targets[BLUR_TEMP][0];
  in.Framebuffer->AddColorAttachment(0, increment);
  for (int a = 1; a < 2 * Layers; ++a)
  {
    in.Framebuffer->RemoveColorAttachment(a);
  }
  in.Framebuffer->ActivateDrawBuffers(1);
  // The texels outside the shaded region count as 0.
  frame.GL->vtkglDisable(GL_SCISSOR_TEST);
  frame.GL->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
  frame.GL->vtkglClear(GL_COLOR_BUFFER_BIT);
  frame.GL->vtkglEnable(GL_SCISSOR_TEST);
  vtkShaderProgram* program = in.IncrementQuad->Program;
  frame.Window->GetShaderCache()->ReadyShaderProgram(program);
  vtkTextureObject* filtered = state.Targets[FILTERED][0];
  vtkTextureObject* history = state.History[frame.Previous][0];
  filtered->Activate();
  history->Activate();
  program->SetUniformi("deepInput0", filtered->GetTextureUnit());
  program->SetUniformi("deepHistory0", history->GetTextureUnit());
  program->SetUniformi("deepHasHistory", state.HistoryValid ? 1 : 0);
  in.IncrementQuad->Render();
  history->Deactivate();
  filtered->Deactivate();
  in.Framebuffer->RemoveColorAttachment(0);
  return MeanColour(increment);
}

//------------------------------------------------------------------------------
// ExtrapolateBounces, step 2: rho / (1 - rho) from the last four means of
// the last bounce, or 0.
double vtkDeepRadiosityPass::EstimateBounceExtrapolation(
  vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state)
{
  if (!this->ExtrapolateBounces || this->TemporalAlpha > 0.0)
  {
    state.IncrementCount = 0;
    return 0.0;
  }
  if (!ReadyQuad(this->Internals->IncrementQuad, frame.Window, vtkDeepRadiosityIncrementFS))
  {
    vtkErrorMacro("The radiosity's increment shader failed to compile; no extrapolation.");
    return 0.0;
  }
  vtkDeepScreenSpace::ScopedStageTime time(this->GetStageTimer(), "radiosity: extrapolation");
  double* means = state.Increments;
  std::copy(means + 1, means + 4, means);
  means[3] = this->MeasureLastBounce(frame, state);
  state.IncrementCount = std::min(state.IncrementCount + 1, 4);
  // rho over two frames, sqrt(m_k / m_k-2): the increments may also hold a
  // component that alternates from frame to frame (light going back and
  // forth between two surfaces), which a ratio of successive means
  // follows and one over two frames averages out. Extrapolated once the
  // series is seen to be geometric: the last two such ratios agree.
  if (state.IncrementCount < 4 || !(means[0] > 0.0) || !(means[1] > 0.0))
  {
    return 0.0;
  }
  const double before = std::sqrt(means[2] / means[0]), rho = std::sqrt(means[3] / means[1]);
  return rho <= MAXIMUM_EXTRAPOLATED_RATIO &&
      std::abs(rho - before) <= EXTRAPOLATION_RATIO_AGREEMENT
    ? rho / (1.0 - rho)
    : 0.0;
}

//------------------------------------------------------------------------------
// Step 4, the temporal filter and eq. 6 (with the confidence fallback):
// FILTERED + History[Previous] -> History[Next], INDIRECT (BLUR_TEMP, free
// by now, on a reduced grid: UpsampleIrradiance fills INDIRECT).
void vtkDeepRadiosityPass::AccumulateIrradiance(
  vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state)
{
  vtkInternals& in = *this->Internals;
  state.Extrapolation = this->EstimateBounceExtrapolation(frame, state);
  this->LastBounceExtrapolation = state.Extrapolation;
  vtkDeepScreenSpace::ScopedStageTime time(this->GetStageTimer(), "radiosity: temporal");
  AttachLayerTextures(in.Framebuffer, state.History[frame.Next],
    &state.Targets[frame.Divisor > 1 ? BLUR_TEMP : INDIRECT]);
  vtkOpenGLQuadHelper* quad = in.TemporalQuads[frame.StillTemporal ? 1 : 0];
  vtkShaderProgram* program = quad->Program;
  frame.Window->GetShaderCache()->ReadyShaderProgram(program);
  vtkDeepScreenSpace::SetShadedRegionUniforms(program, frame.Region);
  BindLayerTextures(program, "deepInput", state.Targets[FILTERED]);
  BindLayerTextures(program, "deepHistory", state.History[frame.Previous]);
  vtkTextureObject* key = state.GridKey();
  key->Activate();
  SetKeyUniforms(program, key->GetTextureUnit(), frame.ProjXY, frame.ProjT);
  program->SetUniformi("deepAlbedo", frame.Units[vtkDeepGBufferPass::ALBEDO]);
  program->SetUniformi("deepHasHistory", state.HistoryValid ? 1 : 0);
  program->SetUniformMatrix4x4("deepToPrevious", frame.ToPrevious);
  program->SetUniformMatrix4x4("deepPrevProjection", frame.PreviousProjection);
  program->SetUniformf("deepTolerance", static_cast<float>(frame.Tolerance));
  program->SetUniformf("deepAlpha", static_cast<float>(this->TemporalAlpha));
  program->SetUniformf("deepExtrapolation", static_cast<float>(state.Extrapolation));
  this->SetOutgoingUniforms(program);
  program->SetUniformf("deepIrradianceLimit", static_cast<float>(IRRADIANCE_LIMIT));
  vtkDeepScreenSpace::ScopedBackgroundSkip skip(
    frame.GL, in.Framebuffer->GetFBOIndex(), state.GridCoverage());
  skip.Draw(quad, NoIrradiance);
  key->Deactivate();
  UnbindLayerTextures(state.History[frame.Previous]);
  UnbindLayerTextures(state.Targets[FILTERED]);
}

//------------------------------------------------------------------------------
// Step 5 (divisor > 1): History[Next] and the reduced (L, c) in BLUR_TEMP of
// layer 0 -> INDIRECT of layer 0 at every shaded texel of the layers (joint
// bilateral upsampling, vtkDeepRadiosityUpsampleFS). Layer 1's outgoing
// radiance, composited nowhere, stays on the grid (BLUR_TEMP).
void vtkDeepRadiosityPass::UpsampleIrradiance(
  vtkGatherFrame& frame, vtkDeepRadiosityRendererState& state)
{
  vtkInternals& in = *this->Internals;
  vtkDeepScreenSpace::ScopedStageTime time(this->GetStageTimer(), "radiosity: upsample");
  // Only INDIRECT of layer 0, of the layers' size, may stay attached: a
  // framebuffer draws into the intersection of its attachments.
  for (int a = 1; a < 2 * Layers; ++a)
  {
    in.Framebuffer->RemoveColorAttachment(a);
  }
  in.Framebuffer->AddColorAttachment(0, state.Targets[INDIRECT][0]);
  in.Framebuffer->ActivateDrawBuffers(1);
  vtkOpenGLState* ostate = frame.GL;
  ostate->vtkglViewport(0, 0, frame.LayerSize[0], frame.LayerSize[1]);
  const int* region = frame.LayerRegion;
  ostate->vtkglScissor(region[0], region[1], region[2] - region[0], region[3] - region[1]);
  vtkShaderProgram* program = in.UpsampleQuad->Program;
  frame.Window->GetShaderCache()->ReadyShaderProgram(program);
  SetLayersUniforms(program, frame);
  program->SetUniformi("deepAlbedo", frame.LayerUnits[vtkDeepGBufferPass::ALBEDO]);
  program->SetUniformi("deepReducedNormal", frame.NormalUnit());
  program->SetUniformf("deepPlaneTolerance", static_cast<float>(this->BlurPlaneTolerance));
  vtkTextureObject* history = state.History[frame.Next][0];
  vtkTextureObject* previousHistory = state.History[frame.Previous][0];
  vtkTextureObject* reducedIndirect = state.Targets[BLUR_TEMP][0];
  history->Activate();
  previousHistory->Activate();
  reducedIndirect->Activate();
  program->SetUniformi("deepHistory0", history->GetTextureUnit());
  program->SetUniformi("deepPreviousHistory0", previousHistory->GetTextureUnit());
  program->SetUniformf("deepExtrapolation", static_cast<float>(state.Extrapolation));
  program->SetUniformf("deepIrradianceLimit", static_cast<float>(IRRADIANCE_LIMIT));
  program->SetUniformi("deepReducedIndirect0", reducedIndirect->GetTextureUnit());
  program->SetUniformi("deepDivisor", frame.Divisor);
  program->SetUniform2i("deepReducedMin", frame.Region);
  program->SetUniform2i("deepReducedMax", frame.Region + 2);
  this->SetOutgoingUniforms(program);
  vtkDeepScreenSpace::ScopedBackgroundSkip skip(
    ostate, in.Framebuffer->GetFBOIndex(), state.Coverage[LAYER_KEY]);
  skip.Draw(in.UpsampleQuad, NoIrradiance);
  reducedIndirect->Deactivate();
  previousHistory->Deactivate();
  history->Deactivate();
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
  for (vtkOpenGLQuadHelper** quad : { &in.BounceQuads[0], &in.BounceQuads[1], &in.GatherQuad,
         &in.KeyQuad, &in.BlurQuad, &in.TemporalQuads[0], &in.TemporalQuads[1], &in.IncrementQuad,
         &in.CompositeQuad, &in.ReduceQuad, &in.UpsampleQuad })
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
  addDoubles(vtkDeepGICaptureNames::Radius, { state.Radius });
  addDoubles(vtkDeepGICaptureNames::ReprojectionTolerance, { state.Tolerance });
  addDoubles(vtkDeepGICaptureNames::EnvironmentIrradiance,
    { state.Environment[0], state.Environment[1], state.Environment[2] });
  for (auto value : { std::make_pair(vtkDeepGICaptureNames::NumberOfSamples, state.NumberOfSamples),
         std::make_pair(vtkDeepGICaptureNames::NumberOfLayers, state.LayerCount),
         std::make_pair(vtkDeepGICaptureNames::Frames, static_cast<int>(state.FrameIndex)) })
  {
    vtkNew<vtkIntArray> array;
    array->SetName(value.first);
    array->InsertNextValue(value.second);
    fd->AddArray(array);
  }
}

// The arrays of layer j (CaptureIrradiance), one value per texel of the
// layers (those of a reduced grid repeated over the texels it stands for);
// 0 where the layer is empty.
void AddIrradianceArrays(vtkImageData* output, vtkDeepRadiosityRendererState& state,
  const std::vector<float>& distance, int slots, int j)
{
  const size_t pixels = static_cast<size_t>(state.LayerWidth) * state.LayerHeight;
  const size_t gridTexels = static_cast<size_t>(state.Width) * state.Height;
  const std::vector<float> irradiance =
    DownloadRGBA(state.History[state.HistoryCurrent][j], gridTexels);
  // On a reduced grid layer 1's L is the grid's (Indirect).
  const bool gridIndirect = j > 0 && state.Divisor > 1;
  const std::vector<float> indirect =
    DownloadRGBA(state.Indirect(j), gridIndirect ? gridTexels : pixels);
  const std::vector<float> filtered = DownloadRGBA(state.Targets[FILTERED][j], gridTexels);
  const std::vector<float> raw = DownloadRGBA(state.Targets[RAW][j], gridTexels);
  vtkPointData* pd = output->GetPointData();
  const std::string suffix = "_" + std::to_string(j);
  vtkFloatArray* e = AddFloatArray(pd, vtkDeepGICaptureNames::Irradiance + suffix, 3, pixels);
  vtkFloatArray* l = AddFloatArray(pd, vtkDeepGICaptureNames::IndirectRadiance + suffix, 3, pixels);
  vtkFloatArray* c = AddFloatArray(pd, vtkDeepGICaptureNames::Confidence + suffix, 1, pixels);
  vtkFloatArray* fe =
    AddFloatArray(pd, vtkDeepGICaptureNames::FilteredIrradiance + suffix, 3, pixels);
  vtkFloatArray* re = AddFloatArray(pd, vtkDeepGICaptureNames::RawIrradiance + suffix, 3, pixels);
  vtkFloatArray* rc = AddFloatArray(pd, vtkDeepGICaptureNames::RawConfidence + suffix, 1, pixels);
  vtkNew<vtkUnsignedCharArray> valid;
  valid->SetName((vtkDeepGICaptureNames::Valid + suffix).c_str());
  valid->SetNumberOfTuples(pixels);
  pd->AddArray(valid);
  for (size_t p = 0; p < pixels; ++p)
  {
    const bool isValid = j < state.LayerCount && j < slots && distance[j * pixels + p] > 0.0f;
    const size_t g = state.GridIndex(p);
    valid->SetValue(p, isValid ? 1 : 0);
    for (int k = 0; k < 3; ++k)
    {
      e->SetTypedComponent(p, k, isValid ? irradiance[4 * g + k] : 0.0f);
      l->SetTypedComponent(p, k, isValid ? indirect[4 * (gridIndirect ? g : p) + k] : 0.0f);
      re->SetTypedComponent(p, k, isValid ? raw[4 * g + k] : 0.0f);
      fe->SetTypedComponent(p, k, isValid ? filtered[4 * g + k] : 0.0f);
    }
    c->SetValue(p, isValid ? filtered[4 * g + 3] : 0.0f);
    rc->SetValue(p, isValid ? raw[4 * g + 3] : 0.0f);
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
  unsigned int distanceHandle = 0;
  vtkOpenGLState* ostate = this->BeginCapture(ren, "CaptureIrradiance", distanceHandle);
  if (!ostate)
  {
    return false;
  }
  ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);
  vtkOpenGLState::ScopedglActiveTexture savedUnit(ostate);
  GLint previous2D = 0, previousArray = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous2D);
  glGetIntegerv(GL_TEXTURE_BINDING_2D_ARRAY, &previousArray);
  const size_t pixels = static_cast<size_t>(state->LayerWidth) * state->LayerHeight;
  int slots = 1;
  const std::vector<float> distance = DownloadDistance(distanceHandle, pixels, slots);
  output->Initialize();
  output->SetDimensions(state->LayerWidth, state->LayerHeight, 1);
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
