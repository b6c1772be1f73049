#include "vtkDeepAmbientObscurancePass.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDeepGBufferPass.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkTextureUnitManager.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWeakPointer.h"
#include "vtk_glew.h"

#include "vtkDeepAmbientObscuranceBlurFS.h"
#include "vtkDeepAmbientObscuranceCompositeFS.h"
#include "vtkDeepAmbientObscuranceFS.h"
#include "vtkDeepAmbientObscuranceMinifyFS.h"
#include "vtkDeepAmbientObscuranceTemporalFS.h"
#include "vtkDeepGeometryKeyFS.h"
#include "vtkDeepScreenSpaceHelpers.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <map>
#include <string>
#include <tuple>
#include <vector>

vtkStandardNewMacro(vtkDeepAmbientObscurancePass);

namespace
{
enum Target
{
  RAW = 0,
  BLUR_TEMP = 1,
  FILTERED = 2,
  NUMBER_OF_TARGETS = 3
};

// What the gather, the filter and the temporal filter write where layer 0
// holds no surface (ScopedBackgroundSkip): AV 1, no distance.
const float FullVisibility[4] = { 1.0f, 0.0f, 0.0f, 1.0f };

// What the gather reads besides the layers: vtkDeepAmbientObscuranceFS's
// uniforms and what the key pyramid is built with. Over the same layers,
// the same inputs give the same raw AV.
struct GatherInputs
{
  int Estimator = -1;
  int Size[2] = { 0, 0 };
  int KeyLayers = 0;       // the layers the key pyramid holds
  int MaximumMipLevel = 0; // of the pyramid
  int Layers = 0;          // the layers the taps read
  int Samples = 0;
  float Turns = 0.0f;
  float Radius = 0.0f;
  float Bias = 0.0f;
  float Epsilon = 0.0f;
  float Intensity = 0.0f;
  float Thickness = 0.0f;
  float MipThreshold = 0.0f;
  float RotationOffset = 0.0f;
  std::array<float, 4> ProjXY = {};
  std::array<float, 4> ProjT = {};

  auto Tied() const
  {
    return std::tie(Estimator, Size[0], Size[1], KeyLayers, MaximumMipLevel, Layers, Samples, Turns,
      Radius, Bias, Epsilon, Intensity, Thickness, MipThreshold, RotationOffset, ProjXY, ProjT);
  }
  bool operator==(const GatherInputs& other) const { return this->Tied() == other.Tied(); }
};

GatherInputs GatherInputsOf(vtkDeepAmbientObscurancePass* pass, const int size[2], int layers,
  const float projXY[4], const float projT[4], double radius, double rotationOffset)
{
  GatherInputs inputs;
  inputs.Estimator = pass->GetEstimator();
  std::copy(size, size + 2, inputs.Size);
  inputs.KeyLayers = std::max(1, layers);
  inputs.MaximumMipLevel = pass->GetMaximumMipLevel();
  inputs.Layers = pass->GetUseSecondLayer() ? std::max(1, layers) : 1;
  inputs.Samples = pass->GetNumberOfSamples();
  inputs.Turns = static_cast<float>(vtkDeepAmbientObscurancePass::GetSpiralTurns(inputs.Samples));
  inputs.Radius = static_cast<float>(radius);
  inputs.Bias = static_cast<float>(pass->GetBias() * radius);
  inputs.Epsilon = static_cast<float>(std::max(pass->GetEpsilon() * radius * radius, 1e-30));
  inputs.Intensity = static_cast<float>(pass->GetIntensity());
  // VISIBILITY_BITMASK: a surface whose far side no layer holds is thinner
  // than the layers' separation dz.
  inputs.Thickness = static_cast<float>(pass->GetGBufferPass()->GetEffectiveMinimumSeparation());
  inputs.MipThreshold = static_cast<float>(pass->GetMipThreshold());
  inputs.RotationOffset = static_cast<float>(rotationOffset);
  std::copy(projXY, projXY + 4, inputs.ProjXY.begin());
  std::copy(projT, projT + 4, inputs.ProjT.begin());
  return inputs;
}
}

//------------------------------------------------------------------------------
// The AO targets of one renderer.
struct vtkDeepAmbientObscuranceRendererState
{
  vtkWeakPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkTextureObject> Targets[NUMBER_OF_TARGETS];
  // Where layer 0 holds a surface (vtkDeepScreenSpace::ReadyCoverage),
  // written with the key's level 0; null while the G-buffer's
  // SkipBackgroundTexels is off.
  vtkSmartPointer<vtkTextureObject> Coverage;
  int Width = 0; // of the G-buffer's layers (frame and guard band)
  int Height = 0;
  int GuardBand = 0;
  int ShadedRegion[4] = { 0, 0, 0, 0 }; // vtkDeepScreenSpace::ShadedRegion
  bool HasFrame = false;
  vtkMTimeType SettingsTime = 0; // the pass's modification time in that frame
  double Radius = 0.0;
  int NumberOfSamples = 0;
  // The geometry key's rotated-grid pyramid (vtkDeepGeometryKeyFS, then
  // vtkDeepAmbientObscuranceMinifyFS): GL_TEXTURE_2D_ARRAY RGBA32F, two of
  // the MipLayers layers per slice, MipLevels levels (1 when
  // MaximumMipLevel is 0).
  GLuint MipTexture = 0;
  GLuint MipFramebuffer = 0;
  int MipUnit = -1; // while bound (BuildKeyPyramid to UnbindKeyPyramid)
  int MipLevels = 0;
  int MipLayers = 0;
  int MipWidth = 0;
  int MipHeight = 0;
  // Temporal accumulation: ping-pong RG32F (AV, layer-0 distance) textures,
  // History[HistoryCurrent] is the last frame's; the camera it was drawn
  // with; the renderer's renders, to detect a render of this renderer that
  // did not go through this pass.
  vtkSmartPointer<vtkTextureObject> History[2];
  int HistoryCurrent = 0;
  bool HistoryValid = false;
  bool Temporal = false; // the last frame accumulated (AV is in History)
  double PreviousView[16];
  double PreviousProjection[16];
  vtkDeepScreenSpace::RenderCounter Renders;
  unsigned int FrameIndex = 0;
  double RotationOffset = 0.0; // of the spiral taps in the current frame, radians
  // What RAW and the key pyramid hold: the gather with RawInputs over
  // RawRegion of the layers of RawLayersTime (vtkDeepGBufferPass::
  // GetLayersTime; 0: nothing).
  vtkMTimeType RawLayersTime = 0;
  GatherInputs RawInputs;
  int RawRegion[4] = { 0, 0, 0, 0 };

  // Whether RAW holds the gather of these layers with these inputs, over
  // `region` or over a part of it (ComputeRawVisibility gathers the rest).
  bool RawExtends(vtkMTimeType layersTime, const GatherInputs& inputs, const int region[4]) const
  {
    return this->RawLayersTime != 0 && this->RawLayersTime == layersTime &&
      this->RawInputs == inputs &&
      (vtkDeepScreenSpace::RegionContains(region, this->RawRegion) ||
        vtkDeepScreenSpace::RegionContains(this->RawRegion, region));
  }

  void ResetHistory(vtkWindow* w)
  {
    for (auto& t : this->History)
    {
      if (t)
      {
        t->ReleaseGraphicsResources(w);
        t = nullptr;
      }
    }
    this->HistoryValid = false;
    this->Temporal = false;
    this->FrameIndex = 0;
  }

  // The pyramid's texture (bound to the active unit) and framebuffer for
  // `levels` levels of the layers' size and `layers` layers. Reallocated
  // when its slices change, not with every change of the layer count (the
  // adaptive count of vtkDeepGIPass alternates 1 and 2).
  void AllocateMip(int levels, int layers)
  {
    const int slices = (layers + 1) / 2;
    if (!this->MipTexture || this->MipLevels != levels || (this->MipLayers + 1) / 2 != slices ||
      this->MipWidth != this->Width || this->MipHeight != this->Height)
    {
      this->ReleaseMip();
      glGenTextures(1, &this->MipTexture);
      glBindTexture(GL_TEXTURE_2D_ARRAY, this->MipTexture);
      glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
      glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
      glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
      for (int m = 0; m < levels; ++m)
      {
        glTexImage3D(GL_TEXTURE_2D_ARRAY, m, GL_RGBA32F, std::max(1, this->Width >> m),
          std::max(1, this->Height >> m), slices, 0, GL_RGBA, GL_FLOAT, nullptr);
      }
      glGenFramebuffers(1, &this->MipFramebuffer);
      this->MipLevels = levels;
      this->MipWidth = this->Width;
      this->MipHeight = this->Height;
    }
    this->MipLayers = layers;
  }

  void ReleaseMip()
  {
    if (this->MipTexture)
    {
      glDeleteTextures(1, &this->MipTexture);
      this->MipTexture = 0;
    }
    if (this->MipFramebuffer)
    {
      glDeleteFramebuffers(1, &this->MipFramebuffer);
      this->MipFramebuffer = 0;
    }
    this->MipLevels = this->MipLayers = this->MipWidth = this->MipHeight = 0;
  }

  // The final AV of the last frame: the accumulated history when the
  // temporal filter ran, the bilateral filter's output otherwise.
  vtkTextureObject* Visibility()
  {
    return this->Temporal ? this->History[this->HistoryCurrent] : this->Targets[FILTERED];
  }

  void Attach(vtkRenderer* renderer)
  {
    this->Renderer = renderer;
    this->Renders.Observe(renderer);
  }

  vtkTypeInt64 TextureBytes() const
  {
    vtkTypeInt64 bytes = 0;
    for (const auto& t : this->Targets)
    {
      bytes += vtkDeepScreenSpace::TextureBytes(t);
    }
    for (const auto& t : this->History)
    {
      bytes += vtkDeepScreenSpace::TextureBytes(t);
    }
    bytes += vtkDeepScreenSpace::TextureBytes(this->Coverage);
    for (int m = 0; m < this->MipLevels; ++m) // RGBA32F, two layers per slice
    {
      bytes += 16LL * std::max(1, this->MipWidth >> m) * std::max(1, this->MipHeight >> m) *
        ((this->MipLayers + 1) / 2);
    }
    return bytes;
  }

  void Release(vtkWindow* w)
  {
    this->ReleaseMip();
    this->ResetHistory(w);
    for (auto& t : this->Targets)
    {
      vtkDeepScreenSpace::ReleaseTarget(t, w);
    }
    vtkDeepScreenSpace::ReleaseTarget(this->Coverage, w);
    this->Width = this->Height = 0;
    this->HasFrame = false;
    this->RawLayersTime = 0;
  }
};

class vtkDeepAmbientObscurancePass::vtkInternals
{
public:
  vtkDeepScreenSpace::RendererStates<vtkDeepAmbientObscuranceRendererState> States;
  vtkOpenGLFramebufferObject* Framebuffer = nullptr;
  // The gather, one program per estimator (DEEP_AO_ESTIMATOR), compiled
  // when first used.
  vtkOpenGLQuadHelper* GatherQuads[VISIBILITY_BITMASK + 1] = {};
  vtkOpenGLQuadHelper* BlurQuad = nullptr;
  double BlurQuadNormalPower = 0.0; // the BlurNormalPower BlurQuad was compiled for
  vtkOpenGLQuadHelper* CompositeQuad = nullptr;
  vtkOpenGLQuadHelper* MinifyQuad = nullptr;
  vtkOpenGLQuadHelper* KeyQuad = nullptr;
  vtkOpenGLQuadHelper* TemporalQuad = nullptr;
};

//------------------------------------------------------------------------------
vtkDeepAmbientObscurancePass::vtkDeepAmbientObscurancePass()
  : Internals(new vtkInternals)
{
  // Every surface within the radius occludes, whichever way it faces: the
  // occluders the first layer hides next to a closed object (the far half
  // of a sphere resting on a floor) are its back faces, which deeper layers
  // keep only without culling.
  this->GBufferPass->SetDeepLayerBackfaceCulling(false);
}

//------------------------------------------------------------------------------
vtkDeepAmbientObscurancePass::~vtkDeepAmbientObscurancePass()
{
  vtkInternals& in = *this->Internals;
  const bool gatherCompiled = std::any_of(std::begin(in.GatherQuads), std::end(in.GatherQuads),
    [](vtkOpenGLQuadHelper* quad) { return quad != nullptr; });
  if (gatherCompiled || in.Framebuffer || !in.States.Empty())
  {
    vtkWarningMacro("Destroyed without ReleaseGraphicsResources(); OpenGL objects are leaked "
                    "unless the context was destroyed first.");
  }
  for (vtkOpenGLQuadHelper* quad : in.GatherQuads)
  {
    delete quad;
  }
  delete in.BlurQuad;
  delete in.CompositeQuad;
  delete in.MinifyQuad;
  delete in.KeyQuad;
  delete in.TemporalQuad;
  if (in.Framebuffer)
  {
    in.Framebuffer->Delete();
  }
}

//------------------------------------------------------------------------------
void vtkDeepAmbientObscurancePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "AutomaticRadius: " << (this->AutomaticRadius ? "On" : "Off") << "\n";
  os << indent << "AutomaticRadiusFraction: " << this->AutomaticRadiusFraction << "\n";
  os << indent << "EffectiveRadius: " << this->EffectiveRadius << "\n";
  os << indent << "Bias: " << this->Bias << "\n";
  os << indent << "Epsilon: " << this->Epsilon << "\n";
  os << indent << "Intensity: " << this->Intensity << "\n";
  os << indent << "Estimator: " << GetEstimatorAsString(this->Estimator) << "\n";
  os << indent << "NumberOfSamples: " << this->NumberOfSamples << " (spiral turns "
     << GetSpiralTurns(this->NumberOfSamples) << ")\n";
  os << indent << "UseSecondLayer: " << (this->UseSecondLayer ? "On" : "Off") << "\n";
  os << indent << "BlurRadius: " << this->BlurRadius << "\n";
  os << indent << "GuardBandShadedFraction: " << this->GuardBandShadedFraction << "\n";
  os << indent << "BlurPlaneTolerance: " << this->BlurPlaneTolerance << "\n";
  os << indent << "BlurNormalPower: " << this->BlurNormalPower << "\n";
  os << indent << "Composition: " << GetCompositionAsString(this->Composition) << "\n";
  os << indent << "EffectiveComposition: " << GetCompositionAsString(this->EffectiveComposition)
     << "\n";
  os << indent << "MipThreshold: " << this->MipThreshold << "\n";
  os << indent << "MaximumMipLevel: " << this->MaximumMipLevel << "\n";
  os << indent << "TemporalAlpha: " << this->TemporalAlpha << "\n";
}

//------------------------------------------------------------------------------
int vtkDeepAmbientObscurancePass::GetSpiralTurns(int numberOfSamples)
{
  return vtkDeepScreenSpace::SpiralTurns(numberOfSamples);
}

//------------------------------------------------------------------------------
const char* vtkDeepAmbientObscurancePass::GetCompositionAsString(int composition)
{
  switch (composition)
  {
    case COMPOSITE_MULTIPLY:
      return "COMPOSITE_MULTIPLY";
    case COMPOSITE_AMBIENT:
      return "COMPOSITE_AMBIENT";
    case COMPOSITE_AUTOMATIC:
      return "COMPOSITE_AUTOMATIC";
    default:
      return "?";
  }
}

//------------------------------------------------------------------------------
void vtkDeepAmbientObscurancePass::SetRadius(double radius)
{
  vtkDeepSetManualLengthMacro(Radius, radius, false, "");
}

//------------------------------------------------------------------------------
const char* vtkDeepAmbientObscurancePass::GetEstimatorAsString(int estimator)
{
  return estimator == EQUATION_1      ? "EQUATION_1"
    : estimator == SOLID_ANGLE        ? "SOLID_ANGLE"
    : estimator == VISIBILITY_BITMASK ? "VISIBILITY_BITMASK"
                                      : "UNKNOWN";
}

//------------------------------------------------------------------------------
void vtkDeepAmbientObscurancePass::SetIntensity(double intensity)
{
  if (!std::isfinite(intensity))
  {
    vtkWarningMacro(
      "Intensity " << intensity << " is not finite; keeping " << this->Intensity << ".");
    return;
  }
  if (intensity < 0.0)
  {
    vtkWarningMacro("Intensity " << intensity << " is negative; using 0 (no obscurance).");
    intensity = 0.0;
  }
  if (intensity != this->Intensity)
  {
    this->Intensity = intensity;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkDeepAmbientObscurancePass::SetNumberOfSamples(int samples)
{
  this->SetSampleCount(samples, this->NumberOfSamples);
}

//------------------------------------------------------------------------------
void vtkDeepAmbientObscurancePass::SetPreset(int preset)
{
  struct Settings
  {
    int Samples;
    int BlurRadius;
    double MipThreshold;
    int MaximumMipLevel;
  };
  static const Settings presets[] = { { 8, 2, 4.0, 5 }, { 12, 3, 8.0, 5 }, { 32, 3, 16.0, 5 } };
  if (preset < HIGH_PERFORMANCE || preset > HIGH_QUALITY)
  {
    vtkWarningMacro("Unknown preset " << preset << "; the settings are unchanged.");
    return;
  }
  const Settings& p = presets[preset];
  this->NumberOfSamples = p.Samples;
  this->BlurRadius = p.BlurRadius;
  this->MipThreshold = p.MipThreshold;
  this->MaximumMipLevel = p.MaximumMipLevel;
  this->Modified();
}

//------------------------------------------------------------------------------
const char* vtkDeepAmbientObscurancePass::GetPresetAsString(int preset)
{
  static_assert(HIGH_PERFORMANCE == 0 && BALANCED == 1 && HIGH_QUALITY == 2,
    "the presets of the deep passes share their values");
  return vtkDeepScreenSpace::PresetName(preset);
}

using vtkDeepScreenSpace::AllocateTarget;
using vtkDeepScreenSpace::ReadyQuad;

namespace
{
// The gather for one estimator: the choice is compiled in, not a uniform,
// because a CPU renderer (Mesa llvmpipe) pays for the code of every
// estimator a uniform could select (about a tenth of the bitmask's gather).
bool ReadyGatherQuad(vtkOpenGLQuadHelper*& quad, vtkOpenGLRenderWindow* window, int estimator)
{
  // ReadyQuad reads the source only to compile: compose it only then, not
  // every frame.
  std::string fs;
  if (!quad)
  {
    fs = vtkDeepAmbientObscuranceFS;
    vtkShaderProgram::Substitute(fs, "//VTK::DeepAmbientObscurance::Estimator",
      "#define DEEP_AO_ESTIMATOR " + std::to_string(estimator));
  }
  return ReadyQuad(quad, window, fs.c_str());
}
}

//------------------------------------------------------------------------------
// True when a visible actor with opaque geometry has an ambient term, i.e.
// when the G-buffer's AMBIENT quantity can be non-zero somewhere.
bool vtkDeepAmbientObscurancePass::RendererHasAmbientTerm(vtkRenderer* renderer)
{
  return vtkDeepScreenSpace::AnyActor(renderer,
    [](vtkActor* actor)
    {
      vtkProperty* property = actor->GetProperty();
      const double* color = property->GetAmbientColor();
      return actor->HasOpaqueGeometry() && property->GetAmbient() > 0.0 &&
        std::max({ color[0], color[1], color[2] }) > 0.0;
    });
}

//------------------------------------------------------------------------------
int vtkDeepAmbientObscurancePass::ResolveComposition(vtkRenderer* renderer) const
{
  if (this->Composition != COMPOSITE_AUTOMATIC)
  {
    return this->Composition;
  }
  return RendererHasAmbientTerm(renderer) ? COMPOSITE_AMBIENT : COMPOSITE_MULTIPLY;
}

//------------------------------------------------------------------------------
void vtkDeepAmbientObscurancePass::RenderOpaque(const vtkRenderState* s)
{
  vtkInternals& in = *this->Internals;
  vtkOpenGLRenderer* renderer = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  vtkDeepGBufferPass* gbuffer = this->GBufferPass;
  if (!this->RenderLayersOrWarn(s, "ambient obscurance"))
  {
    if (vtkDeepAmbientObscuranceRendererState* state = in.States.Existing(renderer))
    {
      state->HasFrame = false;
      state->ResetHistory(renderer->GetRenderWindow());
    }
    return;
  }

  if (!this->UpdateAmbientVisibility(s))
  {
    gbuffer->ResolveToFramebuffer(s);
    return;
  }
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  vtkOpenGLState* ostate = window->GetState();
  vtkDeepAmbientObscuranceRendererState& state = *in.States.Existing(renderer);
  if (!ReadyQuad(in.CompositeQuad, window, vtkDeepAmbientObscuranceCompositeFS))
  {
    vtkErrorMacro("The ambient obscurance composite shader failed to compile.");
    gbuffer->ResolveToFramebuffer(s);
    return;
  }
  const int distanceUnit = gbuffer->ActivateTexture(renderer, vtkDeepGBufferPass::DEPTH);

  // Composite: layer-0 image and depth, then colour *= AV.
  gbuffer->ResolveToFramebuffer(s);
  {
    vtkDeepScreenSpace::ScopedStageTime time(this->GetStageTimer(), "obscurance: composite");
    vtkOpenGLState::ScopedglEnableDisable savedBlend(ostate, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable savedDepthTest(ostate, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglDepthMask savedDepthMask(ostate);
    vtkOpenGLState::ScopedglBlendFuncSeparate savedBlendFunc(ostate);
    const int composition = this->ResolveComposition(renderer);
    // COMPOSITE_AMBIENT needs the radiance on display (it rewrites it).
    const bool ambientOnly = composition == COMPOSITE_AMBIENT &&
      gbuffer->GetDisplayQuantity() == vtkDeepGBufferPass::RADIANCE;
    const int radianceUnit =
      ambientOnly ? gbuffer->ActivateTexture(renderer, vtkDeepGBufferPass::RADIANCE) : -1;
    const int ambientUnit =
      ambientOnly ? gbuffer->ActivateTexture(renderer, vtkDeepGBufferPass::AMBIENT) : -1;
    ostate->vtkglEnable(GL_BLEND);
    if (ambientOnly && radianceUnit >= 0 && ambientUnit >= 0)
    {
      // colour = radiance - (1 - AV) ambient (float), alpha kept.
      ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ZERO, GL_ZERO, GL_ONE);
    }
    else
    {
      ostate->vtkglBlendFuncSeparate(GL_ZERO, GL_SRC_COLOR, GL_ZERO, GL_ONE);
    }
    ostate->vtkglDisable(GL_DEPTH_TEST);
    ostate->vtkglDepthMask(GL_FALSE);
    vtkShaderProgram* program = in.CompositeQuad->Program;
    window->GetShaderCache()->ReadyShaderProgram(program);
    vtkTextureObject* visibility = state.Visibility();
    visibility->Activate();
    program->SetUniformi("deepVisibility", visibility->GetTextureUnit());
    program->SetUniformi("deepDistance", distanceUnit);
    const bool useAmbient = radianceUnit >= 0 && ambientUnit >= 0;
    this->EffectiveComposition = useAmbient ? COMPOSITE_AMBIENT : COMPOSITE_MULTIPLY;
    program->SetUniformi("deepMode", useAmbient ? COMPOSITE_AMBIENT : COMPOSITE_MULTIPLY);
    program->SetUniformi("deepRadiance", useAmbient ? radianceUnit : distanceUnit);
    program->SetUniformi("deepAmbient", useAmbient ? ambientUnit : distanceUnit);
    program->SetUniformi("deepGuardBand", state.GuardBand);
    in.CompositeQuad->Render();
    visibility->Deactivate();
    if (ambientUnit >= 0)
    {
      gbuffer->DeactivateTexture(renderer, vtkDeepGBufferPass::AMBIENT);
    }
    if (radianceUnit >= 0)
    {
      gbuffer->DeactivateTexture(renderer, vtkDeepGBufferPass::RADIANCE);
    }
  }
  gbuffer->DeactivateTexture(renderer, vtkDeepGBufferPass::DEPTH);
  vtkOpenGLCheckErrorMacro("failed after vtkDeepAmbientObscurancePass");
}

//------------------------------------------------------------------------------
bool vtkDeepAmbientObscurancePass::UpdateAmbientVisibility(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  EffectFrame frame;
  if (!this->BeginEffectFrame(s, "UpdateAmbientVisibility", this->GuardBandShadedFraction, frame))
  {
    return false;
  }
  const double radius = this->AutomaticRadius
    ? this->AutomaticRadiusFraction * vtkDeepScreenSpace::SceneDiagonal(frame.Renderer)
    : this->Radius;
  this->EffectiveRadius = radius;
  vtkDeepAmbientObscuranceRendererState& state = this->Internals->States.Get(frame.Renderer);
  state.HasFrame = false;
  const bool temporal = this->TemporalAlpha > 0.0 && frame.Layers > 0;
  if (!temporal)
  {
    // Without the temporal filter only the blur reads AV outside the frame,
    // BlurRadius texels deep: AV shaded beyond is read by nothing.
    vtkDeepScreenSpace::LimitShadedRegion(
      frame.Size, frame.GuardBand, this->BlurRadius, frame.Region);
  }
  if (!this->PrepareTargets(frame, state, temporal))
  {
    return false;
  }

  vtkDeepGBufferPass* gbuffer = this->GBufferPass;
  // The gather of the same layers with the same inputs is kept, as when
  // only the blur changed (vtkDeepGIPass::Converge widens it where the
  // camera stopped), and extended where this frame shades more of the band.
  const vtkMTimeType layersTime = gbuffer->GetLayersTime(frame.Renderer);
  const GatherInputs inputs = GatherInputsOf(
    this, frame.Size, frame.Layers, frame.ProjXY, frame.ProjT, radius, state.RotationOffset);
  const bool extendRaw = state.RawExtends(layersTime, inputs, frame.Region);
  if (!extendRaw)
  {
    state.RawLayersTime = 0;
    state.RawInputs = inputs;
  }
  const int distanceUnit = gbuffer->ActivateTexture(frame.Renderer, vtkDeepGBufferPass::DEPTH);
  const int normalUnit = gbuffer->ActivateTexture(frame.Renderer, vtkDeepGBufferPass::NORMAL);
  const int facingUnit = gbuffer->ActivateTexture(frame.Renderer, vtkDeepGBufferPass::ALBEDO);
  bool computed = false;
  {
    vtkOpenGLState* ostate = frame.GL;
    vtkDeepScreenSpace::ScopedStageState stageState(ostate);
    computed = extendRaw ? this->BindKeyPyramid(state, frame.Window)
                         : this->BuildKeyPyramid(state, frame.Window,
                             { distanceUnit, normalUnit, facingUnit }, frame.Layers);
    if (computed)
    {
      this->ComputeRawVisibility(frame, state, extendRaw);
      state.RawLayersTime = layersTime;
      this->FilterVisibility(frame, state);
      if (temporal)
      {
        this->AccumulateVisibility(frame, state, distanceUnit);
      }
      this->Internals->Framebuffer->RemoveColorAttachment(0);
      this->UnbindKeyPyramid(state, frame.Window);
    }
  }
  gbuffer->DeactivateTexture(frame.Renderer, vtkDeepGBufferPass::ALBEDO);
  gbuffer->DeactivateTexture(frame.Renderer, vtkDeepGBufferPass::NORMAL);
  gbuffer->DeactivateTexture(frame.Renderer, vtkDeepGBufferPass::DEPTH);
  if (!computed)
  {
    return false;
  }
  state.HasFrame = true;
  state.SettingsTime = this->GetMTime();
  state.Radius = radius;
  state.NumberOfSamples = this->NumberOfSamples;
  vtkOpenGLCheckErrorMacro("failed after the ambient obscurance");
  return true;
}

//------------------------------------------------------------------------------
bool vtkDeepAmbientObscurancePass::CanReuseAmbientVisibility(vtkRenderer* renderer)
{
  const vtkDeepAmbientObscuranceRendererState* state =
    renderer ? this->Internals->States.Find(renderer) : nullptr;
  return state && !state->Temporal && this->TemporalAlpha == 0.0 &&
    state->SettingsTime == this->GetMTime();
}

//------------------------------------------------------------------------------
// The renderer's history (reset when the temporal filter is off, on a
// resize or a new shaded region, and when this renderer was rendered
// without this pass since the history's frame), this frame's rotation, the
// targets and the programs.
bool vtkDeepAmbientObscurancePass::PrepareTargets(
  const EffectFrame& frame, vtkDeepAmbientObscuranceRendererState& state, bool temporal)
{
  vtkInternals& in = *this->Internals;
  vtkOpenGLRenderWindow* window = frame.Window;
  const int width = frame.Size[0], height = frame.Size[1];
  const bool consecutive = state.Renders.Consecutive();
  if (!temporal || !consecutive || state.Width != width || state.Height != height ||
    !std::equal(frame.Region, frame.Region + 4, state.ShadedRegion))
  {
    state.ResetHistory(window);
  }
  state.Temporal = false;
  state.RotationOffset = 0.0;
  if (temporal)
  {
    state.RotationOffset = RotationOffset(++state.FrameIndex);
  }
  for (auto& t : state.Targets)
  {
    if (!AllocateTarget(t, window, width, height, 1))
    {
      vtkErrorMacro("Could not allocate the ambient obscurance targets.");
      return false;
    }
  }
  vtkDeepScreenSpace::ReadyCoverage(
    state.Coverage, window, width, height, this->GBufferPass->GetSkipBackgroundTexels());
  state.Width = width;
  state.Height = height;
  state.GuardBand = frame.GuardBand;
  std::copy(frame.Region, frame.Region + 4, state.ShadedRegion);
  if (!in.Framebuffer)
  {
    in.Framebuffer = vtkOpenGLFramebufferObject::New();
    in.Framebuffer->SetContext(window);
  }
  const bool aoReady = ReadyGatherQuad(in.GatherQuads[this->Estimator], window, this->Estimator);
  const bool blurReady = vtkDeepScreenSpace::ReadyBilateralQuad(in.BlurQuad, in.BlurQuadNormalPower,
    window, vtkDeepAmbientObscuranceBlurFS, this->BlurNormalPower);
  const bool minifyReady = ReadyQuad(in.MinifyQuad, window, vtkDeepAmbientObscuranceMinifyFS) &&
    ReadyQuad(in.KeyQuad, window, vtkDeepGeometryKeyFS);
  const bool temporalReady =
    !temporal || ReadyQuad(in.TemporalQuad, window, vtkDeepAmbientObscuranceTemporalFS);
  if (!aoReady || !blurReady || !minifyReady || !temporalReady)
  {
    vtkErrorMacro("The ambient obscurance shaders failed to compile.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
// Equations 1-2 into RAW with state.RawInputs, for the frame and
// GuardBandShadedFraction of the guard band, at most BlurRadius texels of
// it without the temporal filter; the taps read the whole layers' geometry
// key, far ones from its coarser levels (section 3.4). With `extendRaw`,
// RAW already holds this gather over state.RawRegion, and only the texels
// of the frame's region outside it are gathered. Leaves the scissor on the
// frame's region, where the filters shade.
void vtkDeepAmbientObscurancePass::ComputeRawVisibility(
  const EffectFrame& frame, vtkDeepAmbientObscuranceRendererState& state, bool extendRaw)
{
  vtkInternals& in = *this->Internals;
  vtkOpenGLState* ostate = frame.GL;
  in.Framebuffer->Bind();
  ostate->vtkglViewport(0, 0, frame.Size[0], frame.Size[1]);
  ostate->vtkglEnable(GL_SCISSOR_TEST);
  const int* region = frame.Region;
  ostate->vtkglScissor(region[0], region[1], region[2] - region[0], region[3] - region[1]);
  // The rectangles to gather: the region, or where it exceeds state.RawRegion.
  int gathered[4][4];
  int count = 1;
  std::copy(region, region + 4, gathered[0]);
  if (extendRaw)
  {
    count = vtkDeepScreenSpace::RegionContains(state.RawRegion, region)
      ? 0
      : vtkDeepScreenSpace::RegionRing(region, state.RawRegion, gathered);
  }
  if (count == 0)
  {
    return;
  }
  std::copy(region, region + 4, state.RawRegion);
  vtkDeepScreenSpace::ScopedStageTime time(this->GetStageTimer(), "obscurance: gather");
  in.Framebuffer->AddColorAttachment(0, state.Targets[RAW]);
  in.Framebuffer->ActivateDrawBuffers(1);
  const GatherInputs& inputs = state.RawInputs;
  vtkOpenGLQuadHelper* gather = in.GatherQuads[inputs.Estimator];
  vtkShaderProgram* program = gather->Program;
  frame.Window->GetShaderCache()->ReadyShaderProgram(program);
  SetKeyUniforms(program, state.MipUnit, inputs.ProjXY.data(), inputs.ProjT.data());
  program->SetUniformi("deepMaxMip", state.MipLevels - 1);
  program->SetUniformi("deepLayers", inputs.Layers);
  program->SetUniformi("deepSamples", inputs.Samples);
  program->SetUniformf("deepTurns", inputs.Turns);
  program->SetUniformf("deepRadius", inputs.Radius);
  program->SetUniformf("deepBias", inputs.Bias);
  program->SetUniformf("deepEpsilon", inputs.Epsilon);
  program->SetUniformf("deepIntensity", inputs.Intensity);
  program->SetUniformf("deepThickness", inputs.Thickness);
  program->SetUniformf("deepMipThreshold", inputs.MipThreshold);
  program->SetUniformf("deepRotationOffset", inputs.RotationOffset);
  vtkDeepScreenSpace::ScopedBackgroundSkip skip(
    ostate, in.Framebuffer->GetFBOIndex(), state.Coverage);
  for (int i = 0; i < count; ++i)
  {
    const int* part = gathered[i];
    ostate->vtkglScissor(part[0], part[1], part[2] - part[0], part[3] - part[1]);
    skip.Draw(gather, FullVisibility);
  }
  ostate->vtkglScissor(region[0], region[1], region[2] - region[0], region[3] - region[1]);
}

//------------------------------------------------------------------------------
// Separable bilateral reconstruction (section 3.4): RAW -> BLUR_TEMP -> FILTERED.
void vtkDeepAmbientObscurancePass::FilterVisibility(
  const EffectFrame& frame, vtkDeepAmbientObscuranceRendererState& state)
{
  vtkInternals& in = *this->Internals;
  vtkDeepScreenSpace::ScopedStageTime time(this->GetStageTimer(), "obscurance: blur");
  const int passes[2][3] = { { RAW, BLUR_TEMP, 0 }, { BLUR_TEMP, FILTERED, 1 } };
  vtkShaderProgram* program = in.BlurQuad->Program;
  vtkDeepScreenSpace::ScopedBackgroundSkip skip(
    frame.GL, in.Framebuffer->GetFBOIndex(), state.Coverage);
  for (const auto& pass : passes)
  {
    in.Framebuffer->AddColorAttachment(0, state.Targets[pass[1]]);
    in.Framebuffer->ActivateDrawBuffers(1);
    frame.Window->GetShaderCache()->ReadyShaderProgram(program);
    vtkDeepScreenSpace::SetShadedRegionUniforms(program, frame.Region);
    vtkTextureObject* input = state.Targets[pass[0]];
    input->Activate();
    program->SetUniformi("deepInput", input->GetTextureUnit());
    SetKeyUniforms(program, state.MipUnit, frame.ProjXY, frame.ProjT);
    const int axis[2] = { pass[2] == 0 ? 1 : 0, pass[2] == 0 ? 0 : 1 };
    program->SetUniform2i("deepAxis", axis);
    program->SetUniformi("deepBlurRadius", this->BlurRadius);
    program->SetUniformf("deepPlaneTolerance", static_cast<float>(this->BlurPlaneTolerance));
    skip.Draw(in.BlurQuad, FullVisibility);
    input->Deactivate();
  }
}

//------------------------------------------------------------------------------
// Temporal accumulation: FILTERED + History[current] -> History[other], the
// history reprojected with the previous frame's camera.
void vtkDeepAmbientObscurancePass::AccumulateVisibility(
  const EffectFrame& frame, vtkDeepAmbientObscuranceRendererState& state, int distanceUnit)
{
  vtkInternals& in = *this->Internals;
  vtkDeepScreenSpace::ScopedStageTime time(this->GetStageTimer(), "obscurance: temporal");
  bool allocated = true;
  for (auto& t : state.History)
  {
    allocated = allocated && AllocateTarget(t, frame.Window, frame.Size[0], frame.Size[1], 2);
  }
  if (!allocated)
  {
    vtkErrorMacro("Could not allocate the temporal history; AV is not accumulated.");
    state.ResetHistory(frame.Window);
    return;
  }
  const int next = 1 - state.HistoryCurrent;
  in.Framebuffer->AddColorAttachment(0, state.History[next]);
  in.Framebuffer->ActivateDrawBuffers(1);
  vtkShaderProgram* program = in.TemporalQuad->Program;
  frame.Window->GetShaderCache()->ReadyShaderProgram(program);
  vtkDeepScreenSpace::SetShadedRegionUniforms(program, frame.Region);
  vtkTextureObject* input = state.Targets[FILTERED];
  vtkTextureObject* history = state.History[state.HistoryCurrent];
  input->Activate();
  history->Activate();
  float toPreviousGL[16], previousProjectionGL[16];
  vtkDeepScreenSpace::ReprojectionUniforms(frame.View, frame.Projection, state.HistoryValid,
    state.PreviousView, state.PreviousProjection, toPreviousGL, previousProjectionGL);
  program->SetUniformi("deepInput", input->GetTextureUnit());
  program->SetUniformi("deepHistory", history->GetTextureUnit());
  SetLayerUniforms(program, frame, distanceUnit, -1);
  program->SetUniformMatrix4x4("deepToPrevious", toPreviousGL);
  program->SetUniformMatrix4x4("deepPrevProjection", previousProjectionGL);
  program->SetUniformf("deepAlpha", static_cast<float>(this->TemporalAlpha));
  program->SetUniformi("deepHasHistory", state.HistoryValid ? 1 : 0);
  program->SetUniformf("deepTolerance", static_cast<float>(TEMPORAL_DISTANCE_TOLERANCE));
  vtkDeepScreenSpace::ScopedBackgroundSkip skip(
    frame.GL, in.Framebuffer->GetFBOIndex(), state.Coverage);
  skip.Draw(in.TemporalQuad, FullVisibility);
  history->Deactivate();
  input->Deactivate();
  state.HistoryCurrent = next;
  state.HistoryValid = true;
  state.Temporal = true;
  std::copy(frame.View, frame.View + 16, state.PreviousView);
  std::copy(frame.Projection, frame.Projection + 16, state.PreviousProjection);
}

//------------------------------------------------------------------------------
int vtkDeepAmbientObscurancePass::ActivateVisibilityTexture(vtkRenderer* renderer)
{
  vtkDeepAmbientObscuranceRendererState* state = this->Internals->States.Find(renderer);
  vtkTextureObject* texture = state ? state->Visibility() : nullptr;
  if (!texture)
  {
    return -1;
  }
  texture->Activate();
  return texture->GetTextureUnit();
}

//------------------------------------------------------------------------------
void vtkDeepAmbientObscurancePass::DeactivateVisibilityTexture(vtkRenderer* renderer)
{
  vtkDeepAmbientObscuranceRendererState* state = this->Internals->States.Find(renderer);
  if (vtkTextureObject* texture = state ? state->Visibility() : nullptr)
  {
    texture->Deactivate();
  }
}

//------------------------------------------------------------------------------
unsigned int vtkDeepAmbientObscurancePass::GetVisibilityTextureHandle(vtkRenderer* renderer)
{
  vtkDeepAmbientObscuranceRendererState* state = this->Internals->States.Find(renderer);
  vtkTextureObject* texture = state ? state->Visibility() : nullptr;
  return texture ? texture->GetHandle() : 0;
}

//------------------------------------------------------------------------------
// The geometry key of the layers (level 0; two layers per slice) and its
// rotated-grid pyramid, levels 1 to MaximumMipLevel (SAO's minification:
// each texel is one texel of the level below, a true surface's distance
// and normal), bound to a unit of its own (state.MipUnit) until
// UnbindKeyPyramid. Returns false, with an error, when it cannot be built.
bool vtkDeepAmbientObscurancePass::BuildKeyPyramid(vtkDeepAmbientObscuranceRendererState& state,
  vtkOpenGLRenderWindow* window, const KeyUnits& units, int layers)
{
  vtkDeepScreenSpace::ScopedStageTime time(this->GetStageTimer(), "obscurance: key pyramid");
  const int width = state.Width, height = state.Height;
  int finest = 0;
  while ((std::max(width, height) >> (finest + 1)) > 0)
  {
    ++finest; // floor(log2(max(width, height)))
  }
  const int levels = std::max(0, std::min(this->MaximumMipLevel, finest)) + 1;
  layers = std::max(1, layers);
  const int slices = (layers + 1) / 2;
  if (units.Distance < 0 || units.Normal < 0 || units.Facing < 0)
  {
    vtkErrorMacro("No texture unit for the G-buffer's layers; no ambient obscurance this frame.");
    return false;
  }
  if (!this->BindKeyPyramid(state, window))
  {
    return false;
  }
  // The pyramid's texture, (re)allocated on the unit just taken.
  vtkOpenGLState* ostate = window->GetState();
  state.AllocateMip(levels, layers);
  glBindTexture(GL_TEXTURE_2D_ARRAY, state.MipTexture);
  ostate->vtkglBindFramebuffer(GL_FRAMEBUFFER, state.MipFramebuffer);
  const GLenum drawBuffer = GL_COLOR_ATTACHMENT0;
  glDrawBuffers(1, &drawBuffer);
  vtkInternals& in = *this->Internals;
  for (int m = 0; m < levels; ++m)
  {
    const int target[2] = { std::max(1, width >> m), std::max(1, height >> m) };
    ostate->vtkglViewport(0, 0, target[0], target[1]);
    vtkOpenGLQuadHelper* quad = m == 0 ? in.KeyQuad : in.MinifyQuad;
    vtkShaderProgram* program = quad->Program;
    window->GetShaderCache()->ReadyShaderProgram(program);
    if (m == 0)
    {
      program->SetUniformi("deepDistance", units.Distance);
      program->SetUniformi("deepNormal", units.Normal);
      program->SetUniformi("deepFacing", units.Facing);
      // Only VISIBILITY_BITMASK reads the facing.
      program->SetUniformi("deepWithFacing", this->Estimator == VISIBILITY_BITMASK ? 1 : 0);
      program->SetUniformi("deepLayers", layers);
      program->SetUniform2i("deepKeySize", target);
    }
    else
    {
      // Level m reads level m - 1 of the pyramid itself, restricted to that
      // level (base = max = m - 1) so the level being written is outside
      // the sampled range (no feedback loop).
      ostate->vtkglActiveTexture(GL_TEXTURE0 + state.MipUnit);
      glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BASE_LEVEL, m - 1);
      glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, m - 1);
      program->SetUniformi("deepSource", state.MipUnit);
      program->SetUniform2i("deepTargetSize", target);
    }
    for (int slice = 0; slice < slices; ++slice)
    {
      glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, state.MipTexture, m, slice);
      program->SetUniformi(m == 0 ? "deepFirstLayer" : "deepLayer", m == 0 ? 2 * slice : slice);
      // Layer 0's key also marks the surface coverage.
      vtkDeepScreenSpace::ScopedCoverageWrite coverage(
        ostate, state.MipFramebuffer, m == 0 && slice == 0 ? state.Coverage.Get() : nullptr);
      quad->Render();
    }
  }
  glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, 0, 0, 0);
  ostate->vtkglActiveTexture(GL_TEXTURE0 + state.MipUnit);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, levels - 1);
  return true;
}

//------------------------------------------------------------------------------
// Binds the key pyramid the state holds to a unit of its own (state.MipUnit):
// taken first, since binding on the active unit would unbind the G-buffer
// texture the caller activated there. Returns false, with an error, when no
// unit is free.
bool vtkDeepAmbientObscurancePass::BindKeyPyramid(
  vtkDeepAmbientObscuranceRendererState& state, vtkOpenGLRenderWindow* window)
{
  state.MipUnit = window->GetTextureUnitManager()->Allocate();
  if (state.MipUnit < 0)
  {
    vtkErrorMacro("No texture unit for the geometry key; no ambient obscurance this frame.");
    return false;
  }
  window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + state.MipUnit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, state.MipTexture);
  return true;
}

//------------------------------------------------------------------------------
void vtkDeepAmbientObscurancePass::UnbindKeyPyramid(
  vtkDeepAmbientObscuranceRendererState& state, vtkOpenGLRenderWindow* window)
{
  window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + state.MipUnit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  window->GetTextureUnitManager()->Free(state.MipUnit);
  state.MipUnit = -1;
}

//------------------------------------------------------------------------------
bool vtkDeepAmbientObscurancePass::CaptureDistancePyramid(
  int level, vtkImageData* output, vtkRenderer* renderer)
{
  vtkDeepAmbientObscuranceRendererState* state = this->Internals->States.Find(renderer);
  if (!output || !state || !state->Renderer)
  {
    vtkErrorMacro("CaptureDistancePyramid: no ambient obscurance has been rendered for this "
                  "renderer.");
    return false;
  }
  const int levels = state->MipLevels;
  if (level < 0 || level >= levels || !state->MipTexture)
  {
    vtkErrorMacro(
      "CaptureDistancePyramid: level " << level << " does not exist (" << levels << " levels).");
    return false;
  }
  vtkOpenGLRenderWindow* window =
    vtkOpenGLRenderWindow::SafeDownCast(state->Renderer->GetRenderWindow());
  window->MakeCurrent();
  vtkOpenGLState* ostate = window->GetState();
  vtkOpenGLClearErrorMacro();
  vtkOpenGLState::ScopedglActiveTexture savedUnit(ostate);
  GLint previous = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D_ARRAY, &previous);
  glBindTexture(GL_TEXTURE_2D_ARRAY, state->MipTexture);
  GLint w = 0, h = 0, slices = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_2D_ARRAY, level, GL_TEXTURE_WIDTH, &w);
  glGetTexLevelParameteriv(GL_TEXTURE_2D_ARRAY, level, GL_TEXTURE_HEIGHT, &h);
  glGetTexLevelParameteriv(GL_TEXTURE_2D_ARRAY, level, GL_TEXTURE_DEPTH, &slices);
  const size_t pixels = static_cast<size_t>(w) * h;
  // Per slice s and texel: (distance 2s, normal 2s, distance 2s+1, normal 2s+1).
  std::vector<float> key(pixels * 4 * std::max(1, slices));
  ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_2D_ARRAY, level, GL_RGBA, GL_FLOAT, key.data());
  ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, 4);
  glBindTexture(GL_TEXTURE_2D_ARRAY, previous);

  output->Initialize();
  output->SetDimensions(w, h, 1);
  for (int j = 0; j < std::min(state->MipLayers, 2 * static_cast<int>(slices)); ++j)
  {
    vtkNew<vtkFloatArray> array;
    array->SetName((vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Distance, j)).c_str());
    array->SetNumberOfTuples(pixels);
    const float* slice = key.data() + (j / 2) * pixels * 4;
    for (size_t p = 0; p < pixels; ++p)
    {
      array->SetValue(static_cast<vtkIdType>(p), slice[4 * p + 2 * (j % 2)]);
    }
    output->GetPointData()->AddArray(array);
  }
  vtkNew<vtkIntArray> count;
  count->SetName(vtkDeepGICaptureNames::NumberOfMipLevels);
  count->InsertNextValue(levels);
  output->GetFieldData()->AddArray(count);
  vtkOpenGLCheckErrorMacro("failed after capturing the distance pyramid");
  return true;
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkDeepAmbientObscurancePass::GetTextureBytes()
{
  return this->Internals->States.TextureBytes();
}

//------------------------------------------------------------------------------
void vtkDeepAmbientObscurancePass::ReleaseGraphicsResources(vtkWindow* w)
{
  vtkInternals& in = *this->Internals;
  in.States.Release(w);
  for (vtkOpenGLQuadHelper*& quad : in.GatherQuads)
  {
    vtkDeepScreenSpace::ReleaseQuad(quad, w);
  }
  for (vtkOpenGLQuadHelper** quad :
    { &in.BlurQuad, &in.CompositeQuad, &in.MinifyQuad, &in.KeyQuad, &in.TemporalQuad })
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
bool vtkDeepAmbientObscurancePass::CaptureAmbientVisibility(
  vtkImageData* output, vtkRenderer* renderer)
{
  vtkDeepAmbientObscuranceRendererState* state = this->Internals->States.Find(renderer);
  if (!output || !state || !state->Renderer)
  {
    vtkErrorMacro("CaptureAmbientVisibility: no ambient obscurance has been rendered for this "
                  "renderer.");
    return false;
  }
  vtkRenderer* ren = state->Renderer;
  unsigned int distanceHandle = 0;
  vtkOpenGLState* ostate = this->BeginCapture(ren, "CaptureAmbientVisibility", distanceHandle);
  if (!ostate)
  {
    return false;
  }

  const int w = state->Width, h = state->Height;
  const size_t pixels = static_cast<size_t>(w) * h;
  std::vector<float> raw(pixels), filtered(pixels);
  ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);
  vtkOpenGLState::ScopedglActiveTexture savedUnit(ostate);
  GLint previous2D = 0, previousArray = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous2D);
  glGetIntegerv(GL_TEXTURE_BINDING_2D_ARRAY, &previousArray);
  glBindTexture(GL_TEXTURE_2D, state->Targets[RAW]->GetHandle());
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RED, GL_FLOAT, raw.data());
  // The accumulated AV when the last frame accumulated (R of the RG32F history).
  glBindTexture(GL_TEXTURE_2D,
    (state->Temporal ? state->History[state->HistoryCurrent] : state->Targets[FILTERED])
      ->GetHandle());
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RED, GL_FLOAT, filtered.data());
  glBindTexture(GL_TEXTURE_2D, previous2D);
  // The distance array holds every layer (and possibly an oracle layer):
  // ask for its depth first.
  glBindTexture(GL_TEXTURE_2D_ARRAY, distanceHandle);
  GLint arrayDepth = 1;
  glGetTexLevelParameteriv(GL_TEXTURE_2D_ARRAY, 0, GL_TEXTURE_DEPTH, &arrayDepth);
  std::vector<float> distance(pixels * std::max(1, arrayDepth));
  glGetTexImage(GL_TEXTURE_2D_ARRAY, 0, GL_RED, GL_FLOAT, distance.data());
  glBindTexture(GL_TEXTURE_2D_ARRAY, previousArray);
  ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, 4);

  output->Initialize();
  output->SetDimensions(w, h, 1);
  output->SetSpacing(1.0, 1.0, 1.0);
  output->SetOrigin(0.0, 0.0, 0.0);
  vtkNew<vtkFloatArray> av, rawAV;
  vtkNew<vtkUnsignedCharArray> valid;
  av->SetName(vtkDeepGICaptureNames::AmbientVisibility);
  av->SetNumberOfTuples(pixels);
  rawAV->SetName(vtkDeepGICaptureNames::RawAmbientVisibility);
  rawAV->SetNumberOfTuples(pixels);
  valid->SetName(vtkDeepGICaptureNames::Valid);
  valid->SetNumberOfTuples(pixels);
  for (size_t p = 0; p < pixels; ++p)
  {
    const bool isValid = distance[p] > 0.0f;
    valid->SetValue(p, isValid ? 1 : 0);
    av->SetValue(p, isValid ? filtered[p] : 1.0f);
    rawAV->SetValue(p, isValid ? raw[p] : 1.0f);
  }
  output->GetPointData()->AddArray(av);
  output->GetPointData()->AddArray(rawAV);
  output->GetPointData()->AddArray(valid);
  vtkDeepScreenSpace::CropGuardBand(output, state->GuardBand);
  vtkNew<vtkDoubleArray> radius;
  radius->SetName(vtkDeepGICaptureNames::Radius);
  radius->InsertNextValue(state->Radius);
  vtkNew<vtkIntArray> samples;
  samples->SetName(vtkDeepGICaptureNames::NumberOfSamples);
  samples->InsertNextValue(state->NumberOfSamples);
  output->GetFieldData()->AddArray(radius);
  output->GetFieldData()->AddArray(samples);
  vtkOpenGLCheckErrorMacro("failed after capturing the ambient visibility");
  return true;
}
