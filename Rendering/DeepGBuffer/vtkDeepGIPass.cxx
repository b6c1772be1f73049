#include "vtkDeepGIPass.h"

#include "vtkActor.h"
#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkDataSet.h"
#include "vtkDeepAmbientObscurancePass.h"
#include "vtkDeepGBufferPass.h"
#include "vtkDeepRadiosityPass.h"
#include "vtkDeepReflectionPass.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMapper.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWeakPointer.h"
#include "vtk_glew.h"

#include "vtkDeepGICompositeFS.h"
#include "vtkDeepGICoverageFS.h"
#include "vtkDeepScreenSpaceHelpers.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <csignal>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include <signal.h>

vtkStandardNewMacro(vtkDeepGIPass);

//------------------------------------------------------------------------------
// The opaque step handed to vtkDeepGBufferPass::RenderFrame: calls back into
// the GI pass, so that the camera, clear, lights and the translucent,
// volumetric and overlay steps stay the G-buffer pass's.
class vtkDeepGIOpaqueStep : public vtkRenderPass
{
public:
  static vtkDeepGIOpaqueStep* New();
  vtkTypeMacro(vtkDeepGIOpaqueStep, vtkRenderPass);
  vtkDeepGIPass* Owner = nullptr;
  void Render(const vtkRenderState* s) override
  {
    this->NumberOfRenderedProps = 0;
    if (this->Owner)
    {
      this->Owner->RenderOpaque(s);
    }
  }

protected:
  vtkDeepGIOpaqueStep() = default;
  ~vtkDeepGIOpaqueStep() override = default;

private:
  vtkDeepGIOpaqueStep(const vtkDeepGIOpaqueStep&) = delete;
  void operator=(const vtkDeepGIOpaqueStep&) = delete;
};
vtkStandardNewMacro(vtkDeepGIOpaqueStep);

namespace
{
constexpr int EffectMask =
  vtkDeepGIPass::AMBIENT_OBSCURANCE | vtkDeepGIPass::RADIOSITY | vtkDeepGIPass::REFLECTIONS;

// Calls `visit` on every visible actor with opaque geometry of the
// renderer (also inside assemblies) until it returns true.
template <typename Visitor>
bool AnyOpaqueActor(vtkRenderer* renderer, Visitor visit)
{
  return vtkDeepScreenSpace::AnyActor(renderer,
    [&visit](vtkActor* actor)
    { return actor->GetMapper() && actor->HasOpaqueGeometry() && visit(actor); });
}

// Whether some visible opaque actor has a non-black diffuse albedo
// (Diffuse x DiffuseColor), i.e. whether eq. 6's rho can be non-zero.
// Colours from scalars or textures are not known here and count as
// non-black.
bool HasDiffuseAlbedo(vtkRenderer* renderer)
{
  return AnyOpaqueActor(renderer,
    [](vtkActor* actor)
    {
      vtkProperty* property = actor->GetProperty();
      if (!(property->GetDiffuse() > 0.0))
      {
        return false;
      }
      if (actor->GetTexture() || property->GetTexture("albedoTex"))
      {
        return true;
      }
      vtkMapper* mapper = actor->GetMapper();
      if (mapper->GetScalarVisibility())
      {
        // Colours from scalars when the input has the array the mapper
        // would colour by (unknown inputs, e.g. composite data, count too).
        vtkDataSet* input = mapper->GetInputAsDataSet();
        int cellFlag = 0;
        if (!input ||
          vtkAbstractMapper::GetScalars(input, mapper->GetScalarMode(),
            mapper->GetArrayAccessMode(), mapper->GetArrayId(), mapper->GetArrayName(), cellFlag))
        {
          return true;
        }
      }
      const double* color = property->GetDiffuseColor();
      return std::max({ color[0], color[1], color[2] }) > 0.0;
    });
}

// The latest modification of the renderer's prop collection and props.
vtkMTimeType PropsTime(vtkRenderer* renderer)
{
  vtkMTimeType time = renderer->GetViewProps()->GetMTime();
  vtkCollectionSimpleIterator it;
  vtkPropCollection* props = renderer->GetViewProps();
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    time = std::max(time, prop->GetRedrawMTime());
  }
  return time;
}

// What the layer-1 coverage depends on: the camera's view (position, focal
// point, up, angle, parallel scale and projection; not its modification
// time, which VTK moves every frame when it resets the clipping range) and
// the latest modification of the prop collection and of any prop.
using SceneKey = std::array<double, 13>;
SceneKey SceneSignature(vtkRenderer* renderer)
{
  SceneKey key{};
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->GetPosition(key.data());
  camera->GetFocalPoint(key.data() + 3);
  camera->GetViewUp(key.data() + 6);
  key[9] = camera->GetViewAngle();
  key[10] = camera->GetParallelScale();
  key[11] = camera->GetParallelProjection();
  key[12] = static_cast<double>(PropsTime(renderer));
  return key;
}

// The same props, and the same camera up to a relative 1e-5: VTK's own
// round trips move it by more than float round-off (vtkWindowToImageFilter
// renders with a view angle recomputed from the viewport, 3e-8 off).
bool SameScene(const SceneKey& a, const SceneKey& b)
{
  for (size_t i = 0; i + 1 < a.size(); ++i)
  {
    if (std::abs(a[i] - b[i]) > 1e-5 * std::max({ 1.0, std::abs(a[i]), std::abs(b[i]) }))
    {
      return false;
    }
  }
  return a.back() == b.back();
}

// The latest modification of the renderer's lights and of their collection.
vtkMTimeType LightsTime(vtkRenderer* renderer)
{
  vtkLightCollection* lights = renderer->GetLights();
  vtkMTimeType time = lights->GetMTime();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    time = std::max(time, light->GetMTime());
  }
  return time;
}

// What the layers and the obscurance of a still frame depend on besides
// the scene signature and the passes' own settings (which vtkDeepGBufferPass
// and vtkDeepAmbientObscurancePass check): the renderer (ambient,
// background, two-sided lighting, ...) and its lights.
vtkMTimeType LightingTime(vtkRenderer* renderer)
{
  return std::max(renderer->GetMTime(), LightsTime(renderer));
}

// What ends the hold of a converged still image besides the scene and the
// passes' settings: the lights, and the renderer's ambient colour,
// background and two-sided lighting, compared by value, because
// vtkWindowToImageFilter sets and restores the renderer's viewport, which
// moves the renderer's modification time (the layers are then drawn
// again, LightingTime, but the still image is held).
using HoldKey = std::array<double, 8>;
HoldKey HoldSignature(vtkRenderer* renderer)
{
  HoldKey key{};
  key[0] = static_cast<double>(LightsTime(renderer));
  renderer->GetAmbient(key.data() + 1);
  renderer->GetBackground(key.data() + 4);
  key[7] = renderer->GetTwoSidedLighting();
  return key;
}
}

//------------------------------------------------------------------------------
// Per-renderer state: the adaptive layer count and its occlusion query, and
// whether the renderer's last frame reflected.
struct vtkDeepGIRendererState
{
  vtkWeakPointer<vtkRenderer> Renderer;
  GLuint Query = 0;
  bool QueryPending = false;
  bool QueryStale = false; // issued before the scene last changed
  int Layers = 2;
  int FramesAtOneLayer = 0;
  SceneKey Scene{};
  // The first frame after a change is not measured: the single-pass
  // oracles place newly visible geometry in layer 1 one frame late.
  bool Settling = true;
  bool Reflects = false;
  // The inputs of the last frame, for Converge's reuse of the layers: how
  // many frames in a row had its camera and props, whether it has layers
  // and whether they were peeled (exact without history), and whether this
  // frame may keep them (ReuseLayers).
  SceneKey StillScene{};
  vtkMTimeType StillLighting = 0;
  int StillFrames = 0;
  bool StillValid = false;
  bool StillPeeled = false;
  bool ReuseLayers = false;
  bool ObscuranceOfLayers = false; // the obscurance is of the current layers
  // After a Converge that was not aborted: the settings' time then (or
  // after the last frame that held its image), while frames hold the
  // converged image (HoldsStillImage).
  bool HoldStill = false;
  vtkMTimeType HoldSettingsTime = 0;
  HoldKey HoldLighting{};
  HoldKey FrameLighting{}; // HoldSignature during the last frame

  void Release()
  {
    if (this->Query)
    {
      glDeleteQueries(1, &this->Query);
      this->Query = 0;
    }
    this->QueryPending = false;
    this->QueryStale = false;
    this->Layers = 2;
    this->FramesAtOneLayer = 0;
    this->Scene = SceneKey{};
    this->Settling = true;
    this->StillValid = false;
    this->StillFrames = 0;
    this->HoldStill = false;
  }
};

class vtkDeepGIPass::vtkInternals
{
public:
  vtkDeepGIOpaqueStep* OpaqueStep = nullptr;
  // The render window whose context holds this pass's OpenGL objects
  // (null: none yet), the windows refused since (one error each), and
  // the plain VTK steps that draw their renderers.
  vtkWeakPointer<vtkRenderWindow> Window;
  std::vector<vtkWeakPointer<vtkRenderWindow>> Refused;
  vtkNew<vtkRenderStepsPass> PlainSteps;
  std::map<vtkRenderer*, std::unique_ptr<vtkDeepGIRendererState>> States;
  // One composite program per combination of effects (bits 0-2) and AV
  // composition (bit 3: MultiplyVisibility).
  static constexpr int MultiplyVariant = EffectMask + 1;
  vtkOpenGLQuadHelper* CompositeQuads[2 * MultiplyVariant] = {};
  vtkOpenGLQuadHelper* CoverageQuad = nullptr;
  bool Converging = false;
  unsigned long long RenderedFrames = 0; // calls of Render, for Converge
  bool WarnedUnsupported = false;
  // The effects wanted in the frame being rendered (set by Render).
  int Wanted = 0;
  // AV scales the whole direct radiance (COMPOSITE_MULTIPLY) instead of the
  // ambient term only, in the frame being rendered (set by Render).
  bool MultiplyVisibility = false;
  vtkDeepGIRendererState* Current = nullptr;

  bool AnyReflects()
  {
    bool any = false;
    for (auto it = this->States.begin(); it != this->States.end();)
    {
      if (!it->second->Renderer)
      {
        // The renderer is gone; its query went with its context.
        it = this->States.erase(it);
        continue;
      }
      any = any || it->second->Reflects;
      ++it;
    }
    return any;
  }
};

//------------------------------------------------------------------------------
vtkDeepGIPass::vtkDeepGIPass()
  : Internals(new vtkInternals)
{
  this->GBufferPass = vtkDeepGBufferPass::New();
  this->GBufferPass->SetGuardBand(vtkDeepRadiosityPass::DEFAULT_GUARD_BAND);
  this->AmbientObscurancePass = vtkDeepAmbientObscurancePass::New();
  this->RadiosityPass = vtkDeepRadiosityPass::New();
  this->ReflectionPass = vtkDeepReflectionPass::New();
  this->AmbientObscurancePass->SetGBufferPass(this->GBufferPass);
  this->RadiosityPass->SetGBufferPass(this->GBufferPass);
  this->ReflectionPass->SetGBufferPass(this->GBufferPass);
  this->Internals->OpaqueStep = vtkDeepGIOpaqueStep::New();
  this->Internals->OpaqueStep->Owner = this;
  this->SetPreset(BALANCED);
}

//------------------------------------------------------------------------------
vtkDeepGIPass::~vtkDeepGIPass()
{
  vtkInternals& in = *this->Internals;
  for (vtkOpenGLQuadHelper* quad : in.CompositeQuads)
  {
    delete quad;
  }
  delete in.CoverageQuad;
  in.OpaqueStep->Owner = nullptr;
  in.OpaqueStep->Delete();
  this->ReflectionPass->Delete();
  this->RadiosityPass->Delete();
  this->AmbientObscurancePass->Delete();
  this->GBufferPass->Delete();
}

//------------------------------------------------------------------------------
void vtkDeepGIPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "AmbientObscurance: " << (this->AmbientObscurance ? "On" : "Off") << "\n";
  os << indent << "Radiosity: " << (this->Radiosity ? "On" : "Off") << "\n";
  os << indent << "Reflections: " << (this->Reflections ? "On" : "Off") << "\n";
  os << indent << "Preset: " << GetPresetAsString(this->Preset) << "\n";
  os << indent << "AdaptiveLayers: " << (this->AdaptiveLayers ? "On" : "Off") << "\n";
  os << indent << "UseSecondLayer: " << (this->UseSecondLayer ? "On" : "Off") << "\n";
  os << indent << "LayerProbeInterval: " << this->LayerProbeInterval << "\n";
  os << indent << "LastFrameEffects: " << GetEffectsAsString(this->LastFrameEffects) << "\n";
  os << indent << "LastFrameNumberOfLayers: " << this->LastFrameNumberOfLayers << "\n";
  os << indent << "ConvergeReusesLayers: " << this->ConvergeReusesLayers << "\n";
  os << indent << "ConvergeExtrapolatesBounces: " << this->ConvergeExtrapolatesBounces << "\n";
  os << indent << "LastFrameReusedLayers: " << this->LastFrameReusedLayers << "\n";
  os << indent << "LastLayerCoverage: " << this->LastLayerCoverage << "\n";
  os << indent << "LastConvergenceChange: " << this->LastConvergenceChange << "\n";
  os << indent << "LastConvergenceReached: " << this->LastConvergenceReached << "\n";
  os << indent << "LastConvergenceAborted: " << this->LastConvergenceAborted << "\n";
  os << indent << "GBufferPass:\n";
  this->GBufferPass->PrintSelf(os, indent.GetNextIndent());
  os << indent << "AmbientObscurancePass:\n";
  this->AmbientObscurancePass->PrintSelf(os, indent.GetNextIndent());
  os << indent << "RadiosityPass:\n";
  this->RadiosityPass->PrintSelf(os, indent.GetNextIndent());
  os << indent << "ReflectionPass:\n";
  this->ReflectionPass->PrintSelf(os, indent.GetNextIndent());
}

//------------------------------------------------------------------------------
void vtkDeepGIPass::SetPreset(int preset)
{
  // AO quality with its spiral taps and blur radius, radiosity Table 2
  // preset, reflection steps and refinements.
  struct Settings
  {
    int AOQuality;
    int AOSamples;
    int AOBlurRadius;
    int RadiosityPreset;
    int ReflectionSteps;
    int Refinements;
  };
  static const Settings presets[] = { { vtkDeepAmbientObscurancePass::HIGH_PERFORMANCE, 8, 2,
                                        vtkDeepRadiosityPass::HIGH_PERFORMANCE, 32, 2 },
    { vtkDeepAmbientObscurancePass::BALANCED, 16, 4, vtkDeepRadiosityPass::BALANCED, 64, 4 },
    { vtkDeepAmbientObscurancePass::HIGH_QUALITY, 32, 6, vtkDeepRadiosityPass::HIGH_QUALITY, 128,
      6 } };
  if (preset < HIGH_PERFORMANCE || preset > HIGH_QUALITY)
  {
    vtkWarningMacro("Unknown preset " << preset << "; the settings are unchanged.");
    return;
  }
  const Settings& p = presets[preset];
  // The shared G-buffer culls back faces in layer 1 (the radiosity's
  // choice), so no layer pair shows where a solid ends: the spiral
  // SOLID_ANGLE estimator, whose final images are 1-6 % closer to the
  // reference there than VISIBILITY_BITMASK's (Documentation/gi.md).
  this->AmbientObscurancePass->SetPreset(p.AOQuality);
  this->AmbientObscurancePass->SetEstimatorToSolidAngle();
  this->AmbientObscurancePass->SetNumberOfSamples(p.AOSamples);
  this->AmbientObscurancePass->SetBlurRadius(p.AOBlurRadius);
  this->RadiosityPass->SetPreset(p.RadiosityPreset);
  this->ReflectionPass->SetNumberOfSteps(p.ReflectionSteps);
  this->ReflectionPass->SetRefinementSteps(p.Refinements);
  this->Preset = preset;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkDeepGIPass::SetPreset(const char* name)
{
  const int preset = GetPresetFromString(name);
  if (preset < 0)
  {
    vtkWarningMacro("Unknown preset '" << (name ? name : "(null)")
                                       << "' (high_performance, balanced or high_quality); "
                                          "the settings are unchanged.");
    return;
  }
  this->SetPreset(preset);
}

//------------------------------------------------------------------------------
bool vtkDeepGIPass::SetEffects(const char* names)
{
  int effects = 0;
  if (!ParseEffects(names, effects))
  {
    vtkWarningMacro("SetEffects: '" << (names ? names : "(null)")
                                    << "' is not a list of distinct ao, radiosity, reflections "
                                       "(or all, none); the effects are unchanged.");
    return false;
  }
  this->SetAmbientObscurance((effects & AMBIENT_OBSCURANCE) != 0);
  this->SetRadiosity((effects & RADIOSITY) != 0);
  this->SetReflections((effects & REFLECTIONS) != 0);
  return true;
}

//------------------------------------------------------------------------------
bool vtkDeepGIPass::ParseEffects(const char* names, int& effects)
{
  std::string list;
  for (const char* c = names ? names : ""; *c; ++c)
  {
    if (!std::isspace(static_cast<unsigned char>(*c)))
    {
      list += static_cast<char>(std::tolower(static_cast<unsigned char>(*c)));
    }
  }
  if (list == "all" || list == "none")
  {
    effects = list == "all" ? EffectMask : 0;
    return true;
  }
  int parsed = 0;
  size_t start = 0;
  while (!list.empty() && start <= list.size())
  {
    const size_t end = std::min(list.find(',', start), list.size());
    const std::string item = list.substr(start, end - start);
    const int bit = item == "ao" ? AMBIENT_OBSCURANCE
      : item == "radiosity"      ? RADIOSITY
      : item == "reflections"    ? REFLECTIONS
                                 : 0;
    if (!bit || (parsed & bit))
    {
      return false;
    }
    parsed |= bit;
    start = end + 1;
  }
  if (!parsed)
  {
    return false;
  }
  effects = parsed;
  return true;
}

//------------------------------------------------------------------------------
const char* vtkDeepGIPass::GetPresetAsString(int preset)
{
  static_assert(HIGH_PERFORMANCE == 0 && BALANCED == 1 && HIGH_QUALITY == 2,
    "the presets of the deep passes share their values");
  return vtkDeepScreenSpace::PresetName(preset);
}

//------------------------------------------------------------------------------
int vtkDeepGIPass::GetPresetFromString(const char* name)
{
  if (!name)
  {
    return -1;
  }
  std::string key;
  for (const char* c = name; *c; ++c)
  {
    key += *c == '-' ? '_' : static_cast<char>(std::toupper(static_cast<unsigned char>(*c)));
  }
  for (int p = HIGH_PERFORMANCE; p <= HIGH_QUALITY; ++p)
  {
    if (key == GetPresetAsString(p))
    {
      return p;
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
void vtkDeepGIPass::SetLayerProbeInterval(int frames)
{
  if (frames < 1)
  {
    vtkWarningMacro("LayerProbeInterval " << frames << " is below 1 frame; using 1.");
    frames = 1;
  }
  if (frames != this->LayerProbeInterval)
  {
    this->LayerProbeInterval = frames;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
std::string vtkDeepGIPass::GetEffectsAsString(int effects)
{
  std::string names;
  const std::pair<int, const char*> bits[] = { { AMBIENT_OBSCURANCE, "AMBIENT_OBSCURANCE" },
    { RADIOSITY, "RADIOSITY" }, { REFLECTIONS, "REFLECTIONS" }, { SECOND_LAYER, "SECOND_LAYER" } };
  for (const auto& bit : bits)
  {
    if (effects & bit.first)
    {
      names += (names.empty() ? "" : "|") + std::string(bit.second);
    }
  }
  return names.empty() ? "NONE" : names;
}

//------------------------------------------------------------------------------
int vtkDeepGIPass::Converge(vtkRenderer* renderer, int frames)
{
  return this->Converge(renderer, frames, 0.0);
}

//------------------------------------------------------------------------------
namespace
{
// The renderer's viewport colour as the window holds it after Render()
// (RGB, 8 bits per channel, read from the back buffer as
// vtkWindowToImageFilter does with ReadFrontBufferOff).
bool ReadViewportColour(vtkRenderer* renderer, vtkUnsignedCharArray* rgb)
{
  const int* size = renderer->GetSize();
  const int* origin = renderer->GetOrigin();
  if (size[0] < 1 || size[1] < 1)
  {
    return false;
  }
  return renderer->GetRenderWindow()->GetPixelData(origin[0], origin[1], origin[0] + size[0] - 1,
           origin[1] + size[1] - 1, /*front=*/0, rgb) == 1 &&
    rgb->GetNumberOfValues() == 3LL * size[0] * size[1];
}

// Mean absolute difference of two colour readbacks, in units of the full
// scale (1/255 per level).
double MeanAbsoluteChange(vtkUnsignedCharArray* a, vtkUnsignedCharArray* b)
{
  const vtkIdType n = a->GetNumberOfValues();
  const unsigned char* pa = a->GetPointer(0);
  const unsigned char* pb = b->GetPointer(0);
  double sum = 0.0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    sum += std::abs(static_cast<int>(pa[i]) - static_cast<int>(pb[i]));
  }
  return n > 0 ? sum / (255.0 * static_cast<double>(n)) : 0.0;
}
} // anonymous namespace

//------------------------------------------------------------------------------
namespace
{
// SIGINT while converging: caught into a flag; when the scope ends the
// previous action is restored and, if SIGINT arrived, raised again for it
// (Python's handler then raises KeyboardInterrupt). A SIGINT that is
// ignored stays ignored.
volatile std::sig_atomic_t InterruptReceived = 0;

extern "C" void CatchInterrupt(int)
{
  InterruptReceived = 1;
}

class ScopedInterruptCatcher
{
public:
  ScopedInterruptCatcher()
  {
    InterruptReceived = 0;
    struct sigaction current;
    if (sigaction(SIGINT, nullptr, &current) != 0 || current.sa_handler == SIG_IGN)
    {
      return;
    }
    struct sigaction catcher;
    std::memset(&catcher, 0, sizeof(catcher));
    catcher.sa_handler = CatchInterrupt;
    sigemptyset(&catcher.sa_mask);
    this->Installed = sigaction(SIGINT, &catcher, &this->Previous) == 0;
  }
  ~ScopedInterruptCatcher()
  {
    if (this->Installed)
    {
      sigaction(SIGINT, &this->Previous, nullptr);
      if (InterruptReceived)
      {
        std::raise(SIGINT);
      }
    }
  }
  bool Received() const { return InterruptReceived != 0; }
  ScopedInterruptCatcher(const ScopedInterruptCatcher&) = delete;
  void operator=(const ScopedInterruptCatcher&) = delete;

private:
  bool Installed = false;
  struct sigaction Previous;
};

// Sets a flag for a scope, also when an exception leaves it.
class ScopedFlag
{
public:
  explicit ScopedFlag(bool& flag)
    : Flag(flag)
  {
    this->Flag = true;
  }
  ~ScopedFlag() { this->Flag = false; }
  ScopedFlag(const ScopedFlag&) = delete;
  void operator=(const ScopedFlag&) = delete;

private:
  bool& Flag;
};

// A blur radius `scale` times `radius`, rounded, within the passes' 16.
int StillBlurRadius(int radius, double scale)
{
  return std::min(16, static_cast<int>(std::lround(scale * radius)));
}

// Converge's settings for a scope, restored after (also when an observer
// throws): the radiosity's temporal filter off and both blurs widened.
class ScopedStillEffects
{
public:
  ScopedStillEffects(
    vtkDeepRadiosityPass* radiosity, vtkDeepAmbientObscurancePass* obscurance, bool extrapolate)
    : Radiosity(radiosity)
    , Obscurance(obscurance)
    , Alpha(radiosity->GetTemporalAlpha())
    , RadiosityBlur(radiosity->GetBlurRadius())
    , ObscuranceBlur(obscurance->GetBlurRadius())
    , Extrapolate(radiosity->GetExtrapolateBounces())
  {
    this->Radiosity->SetTemporalAlpha(0.0);
    this->Radiosity->SetExtrapolateBounces(extrapolate);
    this->Radiosity->SetBlurRadius(
      StillBlurRadius(this->RadiosityBlur, vtkDeepGIPass::STILL_BLUR_SCALE));
    this->Obscurance->SetBlurRadius(
      StillBlurRadius(this->ObscuranceBlur, vtkDeepGIPass::STILL_OBSCURANCE_BLUR_SCALE));
  }
  ~ScopedStillEffects()
  {
    this->Radiosity->SetTemporalAlpha(this->Alpha);
    this->Radiosity->SetBlurRadius(this->RadiosityBlur);
    this->Radiosity->SetExtrapolateBounces(this->Extrapolate);
    this->Obscurance->SetBlurRadius(this->ObscuranceBlur);
  }
  ScopedStillEffects(const ScopedStillEffects&) = delete;
  void operator=(const ScopedStillEffects&) = delete;

private:
  vtkDeepRadiosityPass* Radiosity;
  vtkDeepAmbientObscurancePass* Obscurance;
  double Alpha;
  int RadiosityBlur;
  int ObscuranceBlur;
  bool Extrapolate;
};
} // anonymous namespace

//------------------------------------------------------------------------------
bool vtkDeepGIPass::CheckConvergeArguments(
  vtkRenderer* renderer, int& maximumFrames, double& tolerance)
{
  if (!renderer || !renderer->GetRenderWindow())
  {
    vtkWarningMacro("Converge: a renderer in a render window is needed; nothing rendered.");
    return false;
  }
  if (maximumFrames < 1)
  {
    vtkWarningMacro("Converge: " << maximumFrames << " frames requested; nothing rendered.");
    return false;
  }
  if (maximumFrames > MAXIMUM_CONVERGE_FRAMES)
  {
    vtkWarningMacro("Converge: " << maximumFrames << " frames requested; rendering at most "
                                 << MAXIMUM_CONVERGE_FRAMES << " (MAXIMUM_CONVERGE_FRAMES).");
    maximumFrames = MAXIMUM_CONVERGE_FRAMES;
  }
  if (!(tolerance >= 0.0))
  {
    vtkWarningMacro("Converge: tolerance " << tolerance << " is not >= 0; using 0 (all "
                                           << maximumFrames << " frames).");
    tolerance = 0.0;
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkDeepGIPass::Converge(vtkRenderer* renderer, int maximumFrames, double tolerance)
{
  this->LastConvergenceChange = -1.0;
  this->LastConvergenceReached = false;
  this->LastConvergenceAborted = false;
  if (!this->CheckConvergeArguments(renderer, maximumFrames, tolerance))
  {
    return 0;
  }
  const vtkMTimeType before = this->GetSettingsTime();
  const int frames = this->RenderStillFrames(renderer, maximumFrames, tolerance);
  this->KeepHolds(before);
  // The settings are restored now: their time marks the still image.
  auto found = this->Internals->States.find(renderer);
  if (found != this->Internals->States.end() && found->second && !this->LastConvergenceAborted)
  {
    found->second->HoldStill = true;
    found->second->HoldSettingsTime = this->GetSettingsTime();
    found->second->HoldLighting = found->second->FrameLighting;
  }
  return frames;
}

//------------------------------------------------------------------------------
// Converge's frames, with its still settings in place for their duration.
int vtkDeepGIPass::RenderStillFrames(vtkRenderer* renderer, int maximumFrames, double tolerance)
{
  vtkRenderWindow* window = renderer->GetRenderWindow();
  const bool measure = tolerance > 0.0;
  vtkNew<vtkUnsignedCharArray> previous;
  vtkNew<vtkUnsignedCharArray> current;
  bool havePrevious = false;
  double changes[3] = { -1.0, -1.0, -1.0 }; // the image's last three changes, oldest first
  // All restored also when an observer throws.
  ScopedFlag converging(this->Internals->Converging);
  ScopedInterruptCatcher interrupt;
  // At a still camera the temporal filter has nothing to follow: without it
  // (and with it the spiral's rotation fixed) each frame is the previous
  // bounce plus one, exactly, and the image converges geometrically instead
  // of at the filter's pace (Documentation/performance.md).
  ScopedStillEffects still(
    this->RadiosityPass, this->AmbientObscurancePass, this->ConvergeExtrapolatesBounces);
  int k = 0;
  while (k < maximumFrames)
  {
    const unsigned long long renderedBefore = this->Internals->RenderedFrames;
    window->Render();
    ++k;
    // Whether the renderer uses this pass is seen, not searched for: the
    // wrappers around it (FXAA, SSAA, tone mapping, ParaView's camera and
    // IceT passes, ...) need not be known.
    if (k == 1 && this->Internals->RenderedFrames == renderedBefore)
    {
      vtkWarningMacro("Converge: the renderer's frame did not use this pass (call SetPass "
                      "first); the frames are rendered without converging anything.");
    }
    bool done = false;
    if (measure && ReadViewportColour(renderer, current))
    {
      if (havePrevious && current->GetNumberOfValues() == previous->GetNumberOfValues())
      {
        this->LastConvergenceChange = MeanAbsoluteChange(current, previous);
        done = this->LastConvergenceChange <= tolerance;
        std::copy(changes + 1, changes + 3, changes);
        changes[2] = this->LastConvergenceChange;
        this->HoldOffExtrapolation(changes, tolerance);
      }
      previous->DeepCopy(current);
      havePrevious = true;
    }
    double progress = done ? 1.0 : static_cast<double>(k) / maximumFrames;
    this->InvokeEvent(vtkCommand::ProgressEvent, &progress);
    if (done)
    {
      this->LastConvergenceReached = true;
      break;
    }
    // VTK's abort convention: the window's AbortRender flag, set by an
    // observer (of ProgressEvent, or of the window's AbortCheckEvent that
    // CheckAbortStatus fires); Render() clears it before the next frame.
    if (window->CheckAbortStatus() || interrupt.Received())
    {
      this->LastConvergenceAborted = true;
      break;
    }
  }
  return k;
}

//------------------------------------------------------------------------------
// Extrapolated bounces (ConvergeExtrapolatesBounces) move the image towards
// the fixed point in one step when they start, a change of about
// 1 / (1 - rho) times the frame's own, after which a frame more is needed:
// two frames at best. They do not start while the image's next change is
// expected within the tolerance without them: its last change times the
// larger of the ratios of its last three (the first changes fall faster
// than the later ones; a single ratio underestimated the next change of a
// room by half). Once started, this does not stop them.
void vtkDeepGIPass::HoldOffExtrapolation(const double changes[3], double tolerance)
{
  const bool extrapolating = this->RadiosityPass->GetLastBounceExtrapolation() > 0.0;
  const bool measured = changes[0] > 0.0 && changes[1] > 0.0;
  const double rho = measured ? std::max(changes[1] / changes[0], changes[2] / changes[1]) : 1.0;
  const bool nearlyConverged = measured && changes[2] * rho <= tolerance;
  this->RadiosityPass->SetExtrapolateBounces(
    this->ConvergeExtrapolatesBounces && (extrapolating || !nearlyConverged));
}

//------------------------------------------------------------------------------
bool vtkDeepGIPass::AcceptWindow(vtkRenderer* renderer)
{
  vtkInternals& in = *this->Internals;
  vtkRenderWindow* window = renderer->GetRenderWindow();
  if (!in.Window || in.Window == window)
  {
    in.Window = window;
    return true;
  }
  for (const auto& refused : in.Refused)
  {
    if (refused == window)
    {
      return false;
    }
  }
  in.Refused.emplace_back(window);
  vtkErrorMacro("This vtkDeepGIPass renders into render window "
    << static_cast<void*>(in.Window.GetPointer())
    << " and cannot render into another one: its OpenGL objects belong to that window's "
       "context. Render window "
    << static_cast<void*>(window)
    << " is drawn without global illumination. Give each render window its own vtkDeepGIPass, "
       "or call ReleaseGraphicsResources(first window) before moving the pass.");
  return false;
}

//------------------------------------------------------------------------------
void vtkDeepGIPass::Render(const vtkRenderState* s)
{
  vtkInternals& in = *this->Internals;
  ++in.RenderedFrames;
  this->NumberOfRenderedProps = 0;
  vtkRenderer* renderer = s->GetRenderer();
  if (!this->AcceptWindow(renderer))
  {
    // Another window's renderer: VTK's plain image, no OpenGL object of
    // this pass touched.
    this->LastFrameEffects = 0;
    this->LastFrameNumberOfLayers = 0;
    this->LastFrameReusedLayers = false;
    in.PlainSteps->Render(s);
    this->NumberOfRenderedProps = in.PlainSteps->GetNumberOfRenderedProps();
    return;
  }
  auto& slot = in.States[renderer];
  if (!slot || !slot->Renderer)
  {
    // New, or a new renderer at the address of a deleted one (whose query
    // went with its context).
    slot.reset(new vtkDeepGIRendererState);
    slot->Renderer = renderer;
  }
  vtkDeepGIRendererState& state = *slot;
  const int wanted = this->WantedEffects(renderer);
  state.Reflects = (wanted & REFLECTIONS) != 0;
  if (this->HoldsStillImage(renderer, state))
  {
    const vtkMTimeType before = this->GetSettingsTime();
    {
      ScopedFlag converging(in.Converging);
      ScopedStillEffects still(
        this->RadiosityPass, this->AmbientObscurancePass, this->ConvergeExtrapolatesBounces);
      this->RenderFrame(s, state, wanted);
    }
    this->KeepHolds(before);
  }
  else
  {
    this->RenderFrame(s, state, wanted);
  }
}

//------------------------------------------------------------------------------
// A frame at the camera, props, lights and settings of the converged still
// image that ended the last Converge renders as Converge's frames do, so
// that it shows that image: re-rendering the window (vtkWindowToImageFilter
// by default, VTK's regression tests, an expose event) would otherwise
// draw it with the interactive settings. Any change ends the hold.
bool vtkDeepGIPass::HoldsStillImage(vtkRenderer* renderer, vtkDeepGIRendererState& state)
{
  if (this->Internals->Converging)
  {
    return false; // the still settings are in place already
  }
  state.HoldStill = state.HoldStill && SameScene(SceneSignature(renderer), state.StillScene) &&
    HoldSignature(renderer) == state.HoldLighting &&
    this->GetSettingsTime() == state.HoldSettingsTime;
  return state.HoldStill;
}

//------------------------------------------------------------------------------
// Setting and restoring the still settings modifies the passes without
// changing their settings: renderers that held a still image at the
// settings' time `before` (the other renderers sharing this pass too)
// keep holding it.
void vtkDeepGIPass::KeepHolds(vtkMTimeType before)
{
  const vtkMTimeType after = this->GetSettingsTime();
  for (auto& entry : this->Internals->States)
  {
    if (entry.second && entry.second->HoldSettingsTime == before)
    {
      entry.second->HoldSettingsTime = after;
    }
  }
}

//------------------------------------------------------------------------------
vtkMTimeType vtkDeepGIPass::GetSettingsTime()
{
  return std::max(
    { this->GetMTime(), this->GBufferPass->GetMTime(), this->AmbientObscurancePass->GetMTime(),
      this->RadiosityPass->GetMTime(), this->ReflectionPass->GetMTime() });
}

//------------------------------------------------------------------------------
void vtkDeepGIPass::RenderFrame(const vtkRenderState* s, vtkDeepGIRendererState& state, int wanted)
{
  vtkInternals& in = *this->Internals;
  vtkRenderer* renderer = s->GetRenderer();
  this->UpdateLayerCount(renderer, state);
  // Only layer 0 is read unless an effect looks behind it.
  const bool deepEffect = this->UseSecondLayer &&
    ((wanted & (RADIOSITY | REFLECTIONS)) ||
      ((wanted & AMBIENT_OBSCURANCE) && this->AmbientObscurancePass->GetUseSecondLayer()));
  const int layers = !deepEffect ? 1 : (this->AdaptiveLayers ? state.Layers : 2);
  this->GBufferPass->SetNumberOfLayers(layers);
  this->GBufferPass->SetWriteReflectivity(in.AnyReflects());
  this->DecideLayerReuse(renderer, state); // after UpdateLayerCount and the layer count
  // Compared with the next frame's by HoldsStillImage, both taken while
  // the passes around this one (ParaView's IceT compositing) have set the
  // renderer up for the frame.
  state.FrameLighting = HoldSignature(renderer);

  in.Wanted = wanted;
  in.MultiplyVisibility = (wanted & AMBIENT_OBSCURANCE) &&
    this->AmbientObscurancePass->ResolveComposition(renderer) ==
      vtkDeepAmbientObscurancePass::COMPOSITE_MULTIPLY;
  in.Current = &state;
  this->GBufferPass->RenderFrame(s, in.OpaqueStep);
  in.Current = nullptr;
  this->NumberOfRenderedProps = this->GBufferPass->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
// Converge's frames keep the last frame's layers and obscurance when
// nothing they depend on changed (camera, props, renderer, lights; the
// sub-passes check their own settings and the window size): at a still
// camera only the radiosity's bounce changes from frame to frame. After a
// change of camera or props the single-pass oracles build layer 1 from the
// frame before, so the first frame's layers are provisional unless they
// were peeled; a change of lighting alone is redrawn once. Each renderer
// sharing the pass decides for itself.
void vtkDeepGIPass::DecideLayerReuse(vtkRenderer* renderer, vtkDeepGIRendererState& state)
{
  // state.Scene: this frame's signature, as UpdateLayerCount kept it (it
  // changes only when the scene did).
  const SceneKey& scene = state.Scene;
  const vtkMTimeType lighting = LightingTime(renderer);
  state.StillFrames = scene == state.StillScene ? state.StillFrames + 1 : 0;
  const bool settled = state.StillFrames >= 2 || (state.StillFrames == 1 && state.StillPeeled);
  state.ReuseLayers = this->Internals->Converging && this->ConvergeReusesLayers &&
    state.StillValid && settled && lighting == state.StillLighting;
  state.StillScene = scene;
  state.StillLighting = lighting;
  state.StillValid = false; // until this frame has layers
}

//------------------------------------------------------------------------------
// What the scene requires (see the class description).
int vtkDeepGIPass::WantedEffects(vtkRenderer* renderer) const
{
  int wanted = 0;
  // With the ambient composition AV scales only the ambient term, which
  // must then exist; the multiplying one darkens whatever VTK shaded.
  const vtkDeepAmbientObscurancePass* obscurance = this->AmbientObscurancePass;
  if (this->AmbientObscurance &&
    (obscurance->ResolveComposition(renderer) == vtkDeepAmbientObscurancePass::COMPOSITE_MULTIPLY ||
      vtkDeepAmbientObscurancePass::RendererHasAmbientTerm(renderer)))
  {
    wanted |= AMBIENT_OBSCURANCE;
  }
  if (this->Radiosity && vtkDeepRadiosityPass::RendererHasLightOn(renderer) &&
    HasDiffuseAlbedo(renderer))
  {
    wanted |= RADIOSITY;
  }
  if (this->Reflections && vtkDeepReflectionPass::RendererReflects(renderer))
  {
    wanted |= REFLECTIONS;
  }
  return wanted;
}

//------------------------------------------------------------------------------
// The adaptive layer count: the newest layer-1 coverage collected without
// waiting, two layers at once when the camera or props changed, and a probe
// with two layers after LayerProbeInterval frames at one.
void vtkDeepGIPass::UpdateLayerCount(vtkRenderer* renderer, vtkDeepGIRendererState& state)
{
  if (state.QueryPending)
  {
    GLuint available = 0;
    glGetQueryObjectuiv(state.Query, GL_QUERY_RESULT_AVAILABLE, &available);
    if (available)
    {
      GLuint64 covered = 0;
      glGetQueryObjectui64v(state.Query, GL_QUERY_RESULT, &covered);
      state.QueryPending = false;
      if (!state.QueryStale)
      {
        this->LastLayerCoverage = static_cast<long long>(covered);
        state.Layers = covered > 0 ? 2 : 1;
        state.FramesAtOneLayer = 0;
      }
    }
  }
  const SceneKey scene = SceneSignature(renderer);
  if (!SameScene(scene, state.Scene))
  {
    state.Scene = scene;
    state.Layers = 2;
    state.FramesAtOneLayer = 0;
    state.QueryStale = state.QueryPending;
    state.Settling = true;
  }
  else if (state.Layers == 1 && !this->Internals->Converging &&
    ++state.FramesAtOneLayer >= this->LayerProbeInterval)
  {
    state.Layers = 2;
    state.FramesAtOneLayer = 0;
  }
}

//------------------------------------------------------------------------------
void vtkDeepGIPass::RenderOpaque(const vtkRenderState* s)
{
  vtkInternals& in = *this->Internals;
  vtkOpenGLRenderer* renderer = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  vtkDeepGBufferPass* gbuffer = this->GBufferPass;
  this->LastFrameEffects = 0;
  this->LastFrameNumberOfLayers = 0;
  vtkDeepGIRendererState* state = in.Current;
  const bool reused = state && state->ReuseLayers && gbuffer->ReuseLayers(s);
  this->LastFrameReusedLayers = reused;
  if (!reused && !gbuffer->RenderLayers(s))
  {
    // The opaque props have been drawn the plain way.
    if (!renderer->GetSelector() && !in.WarnedUnsupported)
    {
      in.WarnedUnsupported = true;
      vtkWarningMacro("The deep G-buffer is unavailable; rendering without global illumination.");
    }
    return;
  }
  if (state)
  {
    state->StillValid = true;
    state->StillPeeled = gbuffer->GetEffectiveOracle() == vtkDeepGBufferPass::DEPTH_PEEL;
  }
  const int layers = gbuffer->GetEffectiveNumberOfLayers();
  const int secondLayer = layers >= 2 ? SECOND_LAYER : 0;
  this->LastFrameNumberOfLayers = layers;
  vtkOpenGLClearErrorMacro();
  const int effects = this->UpdateEffects(s, reused);
  gbuffer->ResolveToFramebuffer(s);
  if (!reused)
  {
    // Kept layers cover what they covered when they were rendered.
    this->QueryLayerCoverage(renderer, layers);
  }
  this->LastFrameEffects = effects | secondLayer;
  if (effects && gbuffer->GetDisplayQuantity() == vtkDeepGBufferPass::RADIANCE)
  {
    // Otherwise nothing to add: exactly the G-buffer's (VTK's) image, or
    // its debug display.
    this->LastFrameEffects = this->Composite(renderer, effects) | secondLayer;
  }
  vtkOpenGLCheckErrorMacro("failed after vtkDeepGIPass");
}

//------------------------------------------------------------------------------
// Runs the wanted effects over the layers; returns those that produced a
// result. On kept layers the obscurance is kept too where it can be.
int vtkDeepGIPass::UpdateEffects(const vtkRenderState* s, bool layersReused)
{
  const int wanted = this->Internals->Wanted;
  int effects = 0;
  vtkDeepAmbientObscurancePass* obscurance = this->AmbientObscurancePass;
  vtkDeepGIRendererState* state = this->Internals->Current;
  const bool keep = layersReused && state && state->ObscuranceOfLayers &&
    obscurance->CanReuseAmbientVisibility(s->GetRenderer());
  if ((wanted & AMBIENT_OBSCURANCE) && (keep || obscurance->UpdateAmbientVisibility(s)))
  {
    effects |= AMBIENT_OBSCURANCE;
  }
  if (state)
  {
    state->ObscuranceOfLayers = (effects & AMBIENT_OBSCURANCE) != 0;
  }
  if ((wanted & RADIOSITY) && this->RadiosityPass->UpdateRadiosity(s))
  {
    effects |= RADIOSITY;
  }
  if ((wanted & REFLECTIONS) && this->ReflectionPass->UpdateReflections(s) &&
    this->ReflectionPass->GetReflectionTextureHandle(s->GetRenderer()) != 0)
  {
    effects |= REFLECTIONS;
  }
  return effects;
}

//------------------------------------------------------------------------------
// Counts the layer-1 pixels with an occlusion query (a full-screen quad that
// discards where layer 1 is empty), read by a later frame's Render. The
// first frame after a change is not measured (see Settling).
void vtkDeepGIPass::QueryLayerCoverage(vtkOpenGLRenderer* renderer, int layers)
{
  vtkInternals& in = *this->Internals;
  vtkDeepGIRendererState* state = in.Current;
  if (!state)
  {
    return;
  }
  const bool settling = state->Settling;
  state->Settling = false;
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (settling || layers < 2 || !this->AdaptiveLayers || state->QueryPending ||
    !vtkDeepScreenSpace::ReadyQuad(in.CoverageQuad, window, vtkDeepGICoverageFS))
  {
    return;
  }
  vtkDeepScreenSpace::ScopedStageTime time(
    this->GBufferPass->GetStageTimer(), "GI: layer-1 coverage query");
  if (!state->Query)
  {
    glGenQueries(1, &state->Query);
  }
  vtkOpenGLState* ostate = window->GetState();
  vtkOpenGLState::ScopedglEnableDisable savedDepthTest(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable savedBlend(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglDepthMask savedDepthMask(ostate);
  vtkOpenGLState::ScopedglColorMask savedColorMask(ostate);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglDepthMask(GL_FALSE);
  ostate->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  int layerSize[2] = { 0, 0 };
  int guardBand = 0;
  this->GBufferPass->GetLayerExtent(renderer, layerSize, guardBand);
  const int distanceUnit = this->GBufferPass->ActivateTexture(renderer, vtkDeepGBufferPass::DEPTH);
  in.CoverageQuad->Program->SetUniformi("deepDistance", distanceUnit);
  in.CoverageQuad->Program->SetUniformi("deepGuardBand", guardBand);
  glBeginQuery(GL_SAMPLES_PASSED, state->Query);
  in.CoverageQuad->Render();
  glEndQuery(GL_SAMPLES_PASSED);
  this->GBufferPass->DeactivateTexture(renderer, vtkDeepGBufferPass::DEPTH);
  state->QueryPending = true;
  state->QueryStale = false;
}

//------------------------------------------------------------------------------
// The texture units of the composite's inputs (-1: not bound).
struct vtkDeepGIPass::vtkCompositeInputs
{
  int Distance = -1;
  int Radiance = -1;
  int Ambient = -1;
  int Visibility = -1;
  int Indirect = -1;
  int Reflected = -1;
  int Reflectivity = -1;
};

//------------------------------------------------------------------------------
// Composes layer 0 (class description): binds the inputs of `effects`,
// leaves out an effect whose texture cannot be bound, draws, and returns
// the effects composited.
int vtkDeepGIPass::Composite(vtkOpenGLRenderer* renderer, int effects)
{
  vtkDeepScreenSpace::ScopedStageTime time(this->GBufferPass->GetStageTimer(), "GI: composite");
  vtkCompositeInputs inputs;
  int composited = this->ActivateCompositeInputs(renderer, effects, inputs);
  if (!this->DrawComposite(renderer, composited, inputs))
  {
    vtkErrorMacro("The GI composite is unavailable; showing the direct image.");
    composited = 0;
  }
  this->DeactivateCompositeInputs(renderer, inputs);
  return composited;
}

//------------------------------------------------------------------------------
int vtkDeepGIPass::ActivateCompositeInputs(
  vtkOpenGLRenderer* renderer, int effects, vtkCompositeInputs& inputs)
{
  vtkDeepGBufferPass* gbuffer = this->GBufferPass;
  inputs.Distance = gbuffer->ActivateTexture(renderer, vtkDeepGBufferPass::DEPTH);
  inputs.Radiance = gbuffer->ActivateTexture(renderer, vtkDeepGBufferPass::RADIANCE);
  int composited = effects;
  if (effects & AMBIENT_OBSCURANCE)
  {
    if (!this->Internals->MultiplyVisibility)
    {
      inputs.Ambient = gbuffer->ActivateTexture(renderer, vtkDeepGBufferPass::AMBIENT);
    }
    inputs.Visibility = this->AmbientObscurancePass->ActivateVisibilityTexture(renderer);
    const bool ambientMissing = !this->Internals->MultiplyVisibility && inputs.Ambient < 0;
    composited &= (ambientMissing || inputs.Visibility < 0) ? ~AMBIENT_OBSCURANCE : ~0;
  }
  if (effects & RADIOSITY)
  {
    inputs.Indirect =
      this->RadiosityPass->ActivateTexture(renderer, vtkDeepRadiosityPass::INDIRECT_RADIANCE, 0);
    composited &= inputs.Indirect < 0 ? ~RADIOSITY : ~0;
  }
  if (effects & REFLECTIONS)
  {
    inputs.Reflected = this->ReflectionPass->ActivateReflectionTexture(renderer);
    inputs.Reflectivity = gbuffer->ActivateTexture(renderer, vtkDeepGBufferPass::REFLECTIVITY);
    composited &= (inputs.Reflected < 0 || inputs.Reflectivity < 0) ? ~REFLECTIONS : ~0;
  }
  return composited;
}

//------------------------------------------------------------------------------
// One program per combination of effects (the composite shader's
// DEEP_GI_* switches); false when it is unavailable.
bool vtkDeepGIPass::DrawComposite(
  vtkOpenGLRenderer* renderer, int composited, const vtkCompositeInputs& inputs)
{
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  const bool multiply = (composited & AMBIENT_OBSCURANCE) && this->Internals->MultiplyVisibility;
  vtkOpenGLQuadHelper*& quad =
    this->Internals->CompositeQuads[composited + (multiply ? vtkInternals::MultiplyVariant : 0)];
  std::string fs = vtkDeepGICompositeFS;
  vtkShaderProgram::Substitute(fs, "//VTK::DeepGI::Effects",
    std::string("#define DEEP_GI_AO ") + ((composited & AMBIENT_OBSCURANCE) ? "1" : "0") +
      "\n#define DEEP_GI_AO_MULTIPLY " + (multiply ? "1" : "0") + "\n#define DEEP_GI_RADIOSITY " +
      ((composited & RADIOSITY) ? "1" : "0") + "\n#define DEEP_GI_REFLECTIONS " +
      ((composited & REFLECTIONS) ? "1" : "0") + "\n");
  if (inputs.Distance < 0 || inputs.Radiance < 0 ||
    !vtkDeepScreenSpace::ReadyQuad(quad, window, fs.c_str()))
  {
    return false;
  }
  vtkOpenGLState* ostate = window->GetState();
  // The colour is replaced, the framebuffer's alpha kept.
  vtkDeepScreenSpace::ScopedCompositeState compositeState(ostate, GL_ONE, GL_ZERO);
  int layerSize[2] = { 0, 0 };
  int guardBand = 0;
  this->GBufferPass->GetLayerExtent(renderer, layerSize, guardBand);
  vtkShaderProgram* program = quad->Program;
  program->SetUniformi("deepDistance", inputs.Distance);
  program->SetUniformi("deepRadiance", inputs.Radiance);
  program->SetUniformi("deepGuardBand", guardBand);
  if (composited & AMBIENT_OBSCURANCE)
  {
    if (!multiply)
    {
      program->SetUniformi("deepAmbient", inputs.Ambient);
    }
    program->SetUniformi("deepVisibility", inputs.Visibility);
  }
  if (composited & RADIOSITY)
  {
    program->SetUniformi("deepIndirect", inputs.Indirect);
  }
  if (composited & REFLECTIONS)
  {
    program->SetUniformi("deepReflected", inputs.Reflected);
    program->SetUniformi("deepReflectivity", inputs.Reflectivity);
  }
  quad->Render();
  return true;
}

//------------------------------------------------------------------------------
void vtkDeepGIPass::DeactivateCompositeInputs(
  vtkOpenGLRenderer* renderer, const vtkCompositeInputs& inputs)
{
  vtkDeepGBufferPass* gbuffer = this->GBufferPass;
  if (inputs.Reflectivity >= 0)
  {
    gbuffer->DeactivateTexture(renderer, vtkDeepGBufferPass::REFLECTIVITY);
  }
  if (inputs.Reflected >= 0)
  {
    this->ReflectionPass->DeactivateReflectionTexture(renderer);
  }
  if (inputs.Indirect >= 0)
  {
    this->RadiosityPass->DeactivateTexture(renderer, vtkDeepRadiosityPass::INDIRECT_RADIANCE, 0);
  }
  if (inputs.Visibility >= 0)
  {
    this->AmbientObscurancePass->DeactivateVisibilityTexture(renderer);
  }
  if (inputs.Ambient >= 0)
  {
    gbuffer->DeactivateTexture(renderer, vtkDeepGBufferPass::AMBIENT);
  }
  gbuffer->DeactivateTexture(renderer, vtkDeepGBufferPass::RADIANCE);
  gbuffer->DeactivateTexture(renderer, vtkDeepGBufferPass::DEPTH);
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkDeepGIPass::GetTextureBytes()
{
  // The effect passes share the G-buffer (counted once).
  return this->GBufferPass->GetTextureBytes() + this->AmbientObscurancePass->GetTextureBytes() +
    this->RadiosityPass->GetTextureBytes() + this->ReflectionPass->GetTextureBytes();
}

//------------------------------------------------------------------------------
void vtkDeepGIPass::ReleaseGraphicsResources(vtkWindow* w)
{
  vtkInternals& in = *this->Internals;
  in.PlainSteps->ReleaseGraphicsResources(w);
  if (in.Window && w != in.Window)
  {
    // A refused window: none of this pass's objects are in its context.
    return;
  }
  in.Window = nullptr;
  in.Refused.clear();
  for (auto& entry : in.States)
  {
    entry.second->Release();
  }
  in.States.clear();
  for (vtkOpenGLQuadHelper*& quad : in.CompositeQuads)
  {
    vtkDeepScreenSpace::ReleaseQuad(quad, w);
  }
  vtkDeepScreenSpace::ReleaseQuad(in.CoverageQuad, w);
  this->AmbientObscurancePass->ReleaseGraphicsResources(w);
  this->RadiosityPass->ReleaseGraphicsResources(w);
  this->ReflectionPass->ReleaseGraphicsResources(w);
  this->GBufferPass->ReleaseGraphicsResources(w);
  this->Superclass::ReleaseGraphicsResources(w);
}
