// vtkDeepGIPass::Converge keeps the G-buffer's layers and the ambient
// visibility while nothing they depend on changes (ConvergeReusesLayers),
// and the images are those of rendering everything every frame.
// 1. Nothing changes: every Converge frame keeps the layers of the frame
//    before (the first, those of the frames rendered before Converge), and
//    the image after 5 frames equals, bit for bit, the one with
//    ConvergeReusesLayers off, which keeps nothing.
// 2. A ProgressEvent observer changes one input after frame 2: an actor's
//    colour, the light's intensity, the camera, the renderer's ambient
//    light, the window size, or the obscurance's radius. After a change of
//    the camera or a prop, frames 3 and 4 render the layers again with
//    REPROJECT (the oracle builds frame 3's layer 1 from frame 2's camera),
//    frame 5 keeps them; with DEPTH_PEEL (exact in every frame) and after a
//    change of the lighting or the window size (peeled without history)
//    only frame 3 renders them; the radius keeps the layers and recomputes
//    the obscurance. The image after frame 5 equals the one with
//    ConvergeReusesLayers off, bit for bit.
//    The radiosity builds its geometry keys (the stage timer's "radiosity:
//    geometry key") in exactly the frames that render the layers; with
//    HIGH_PERFORMANCE's reduced grid it also keeps its copy of the layers.
//    The obscurance builds its key pyramid in those frames too, and after
//    a change of its radius; it gathers in them and in frame 1, where
//    Converge's wider blur reads more of the guard band than the frames
//    before shaded: its gather is kept and extended by that ring.
// 3. Two renderers share the pass (side by side) and one of them's camera
//    moves after frame 2. Each renderer decides for itself: the second
//    (whose flags are the window's last) renders its layers again when its
//    own camera moved, and keeps them when the first one's did; the window
//    equals the one with ConvergeReusesLayers off. (VTK 9.1 alone draws the
//    unchanged renderer with the other one's lights here, 5/255 off: its
//    shader programs are shared and take a renderer's lights only when they
//    are newer than the last upload; vtkDeepGBufferPass uploads them for
//    every draw.)
// The layer count is fixed (AdaptiveLayers off): the coverage query's result
// arrives after a number of frames that depends on the machine.

#include "DeepRadiosityTest.h"

#include "vtkDeepAmbientObscurancePass.h"
#include "vtkDeepGBufferPass.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIPass.h"
#include "vtkDeepGIStageTimer.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLightCollection.h"
#include "vtkPointData.h"

#include <functional>
#include <vector>

using namespace DeepRadiosityTest;
using namespace DeepGITest;

namespace
{
constexpr int W = 96, H = 72;
constexpr int Frames = 5;
constexpr int ChangeAfterFrame = 2;

// The red-wall scene with an ambient term on every actor, so that the
// obscurance and the radiosity both run.
struct GIScene
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkSmartPointer<vtkRenderer> Second; // sharing the pass, when asked for
  vtkNew<vtkDeepGIPass> Pass;

  GIScene(bool twoRenderers, int oracle, int preset)
  {
    this->Window = MakeWindow(W, H);
    this->Window->AddRenderer(this->Renderer);
    RedWallSceneWithAmbient(this->Renderer);
    this->Pass->SetPreset(preset);
    this->Pass->AdaptiveLayersOff();
    // A guard band wide enough (24 pixels) that the obscurance shades as
    // much of it as its blur reads, 4 pixels more in Converge than before.
    this->Pass->GetGBufferPass()->SetGuardBand(0.25);
    this->Pass->GetGBufferPass()->SetOracle(oracle);
    this->Renderer->SetPass(this->Pass);
    if (twoRenderers)
    {
      this->Renderer->SetViewport(0.0, 0.0, 0.5, 1.0);
      this->Second = vtkSmartPointer<vtkRenderer>::New();
      this->Second->SetViewport(0.5, 0.0, 1.0, 1.0);
      this->Window->AddRenderer(this->Second);
      RedWallSceneWithAmbient(this->Second);
      this->Second->SetPass(this->Pass);
    }
  }
  ~GIScene()
  {
    this->Renderer->SetPass(nullptr);
    if (this->Second)
    {
      this->Second->SetPass(nullptr);
    }
    this->Pass->ReleaseGraphicsResources(this->Window);
  }
};

using Change = std::function<void(GIScene&)>;

struct Run
{
  std::vector<unsigned char> Pixels;
  std::vector<float> Visibility;       // the first renderer's AV after Converge
  std::vector<int> Reused;             // LastFrameReusedLayers after each Converge frame
  std::vector<int> Keyed;              // whether each frame built the radiosity's geometry keys
  std::vector<int> ObscuranceKeyed;    // the obscurance's key pyramid
  std::vector<int> ObscuranceGathered; // ran the obscurance's gather
  int Effects = 0;
};

// Whether the stages timed since the last Reset include `name`.
bool Ran(vtkDeepGIStageTimer* timer, const char* name)
{
  for (int stage = 0; stage < timer->GetNumberOfStages(); ++stage)
  {
    if (std::string(timer->GetStageName(stage)) == name)
    {
      return timer->GetStageCount(stage) > 0;
    }
  }
  return false;
}

// One frame before Converge, then Converge(Frames) with `change` applied
// after frame ChangeAfterFrame; the final image and what each frame kept.
Run Converge(bool reuse, const Change& change, bool twoRenderers, int oracle, int preset)
{
  GIScene scene(twoRenderers, oracle, preset);
  vtkNew<vtkDeepGIStageTimer> timer;
  scene.Pass->GetGBufferPass()->SetStageTimer(timer);
  scene.Pass->SetConvergeReusesLayers(reuse);
  // VTK adds the headlight during the first frame: the inputs are still
  // from the third frame on.
  for (int k = 0; k < 3; ++k)
  {
    scene.Window->Render();
  }
  Run run;
  timer->Reset();
  struct Observed
  {
    GIScene* Scene;
    Run* Result;
    const Change* Apply;
    vtkDeepGIStageTimer* Timer;
  } observed{ &scene, &run, &change, timer };
  vtkNew<vtkCallbackCommand> progress;
  progress->SetCallback(
    [](vtkObject*, unsigned long, void* data, void*)
    {
      auto* o = static_cast<Observed*>(data);
      o->Result->Reused.push_back(o->Scene->Pass->GetLastFrameReusedLayers() ? 1 : 0);
      o->Result->Keyed.push_back(Ran(o->Timer, "radiosity: geometry key") ? 1 : 0);
      o->Result->ObscuranceKeyed.push_back(Ran(o->Timer, "obscurance: key pyramid") ? 1 : 0);
      o->Result->ObscuranceGathered.push_back(Ran(o->Timer, "obscurance: gather") ? 1 : 0);
      o->Timer->Reset();
      if (o->Result->Reused.size() == ChangeAfterFrame && *o->Apply)
      {
        (*o->Apply)(*o->Scene);
      }
    });
  progress->SetClientData(&observed);
  scene.Pass->AddObserver(vtkCommand::ProgressEvent, progress);
  scene.Pass->Converge(scene.Renderer, Frames);
  scene.Pass->RemoveObserver(progress);
  run.Effects = scene.Pass->GetLastFrameEffects();
  const int* size = scene.Window->GetSize();
  vtkNew<vtkUnsignedCharArray> rgb;
  scene.Window->GetPixelData(0, 0, size[0] - 1, size[1] - 1, /*front=*/0, rgb);
  run.Pixels.assign(rgb->GetPointer(0), rgb->GetPointer(0) + rgb->GetNumberOfValues());
  vtkNew<vtkImageData> visibility;
  scene.Pass->GetAmbientObscurancePass()->CaptureAmbientVisibility(visibility, scene.Renderer);
  if (vtkFloatArray* av = vtkFloatArray::SafeDownCast(
        visibility->GetPointData()->GetArray(vtkDeepGICaptureNames::AmbientVisibility)))
  {
    run.Visibility.assign(av->GetPointer(0), av->GetPointer(0) + av->GetNumberOfValues());
  }
  return run;
}

std::string Flags(const std::vector<int>& flags)
{
  std::string text;
  for (int f : flags)
  {
    text += f ? '1' : '0';
  }
  return text;
}

int MaximumDifference(const Run& a, const Run& b)
{
  if (a.Pixels.size() != b.Pixels.size() || a.Pixels.empty())
  {
    return 256;
  }
  int maximum = 0;
  for (size_t i = 0; i < a.Pixels.size(); ++i)
  {
    maximum = std::max(maximum, std::abs(a.Pixels[i] - b.Pixels[i]));
  }
  return maximum;
}

// Converge with and without reuse under `change`; `expected` is the
// reuse flags of the frames with reuse on; `obscuranceKeyed` the frames
// building the obscurance's key pyramid, when not those rendering the
// layers.
void CheckCase(const char* name, const Change& change, const std::string& expected,
  bool twoRenderers = false, int oracle = vtkDeepGBufferPass::REPROJECT,
  int preset = vtkDeepGIPass::BALANCED, std::string obscuranceKeyed = "")
{
  const Run kept = Converge(true, change, twoRenderers, oracle, preset);
  const Run full = Converge(false, change, twoRenderers, oracle, preset);
  const int difference = MaximumDifference(kept, full);
  std::printf("%s: frames keeping the layers %s (off: %s), effects %s, largest difference %d/255\n",
    name, Flags(kept.Reused).c_str(), Flags(full.Reused).c_str(),
    vtkDeepGIPass::GetEffectsAsString(kept.Effects).c_str(), difference);
  Check(Flags(kept.Reused) == expected, Text(name, ": the frames keep the layers as ", expected));
  Check(Flags(full.Reused) == std::string(Frames, '0'),
    Text(name, ": with ConvergeReusesLayers off no frame keeps them"));
  Check(
    (kept.Effects & vtkDeepGIPass::AMBIENT_OBSCURANCE) && (kept.Effects & vtkDeepGIPass::RADIOSITY),
    Text(name, ": the obscurance and the radiosity ran"));
  Check(difference == 0, Text(name, ": the image equals the one rendering everything"));
  Check(!kept.Visibility.empty() && kept.Visibility == full.Visibility,
    Text(name, ": the ambient visibility equals the one computing everything"));
  // With two renderers the flags are the second's, the keys both's.
  std::string rendered = expected;
  for (char& c : rendered)
  {
    c = c == '1' ? '0' : '1';
  }
  Check(twoRenderers || Flags(kept.Keyed) == rendered,
    Text(name, ": the radiosity's geometry keys are built as ", rendered, ", not as ",
      Flags(kept.Keyed)));
  Check(Flags(full.Keyed) == std::string(Frames, '1'),
    Text(name, ": with ConvergeReusesLayers off every frame builds the keys"));
  if (obscuranceKeyed.empty())
  {
    obscuranceKeyed = rendered;
  }
  std::string gathered = obscuranceKeyed;
  gathered[0] = '1';
  Check(twoRenderers || Flags(kept.ObscuranceKeyed) == obscuranceKeyed,
    Text(name, ": the obscurance's key pyramid is built as ", obscuranceKeyed, ", not as ",
      Flags(kept.ObscuranceKeyed)));
  Check(twoRenderers || Flags(kept.ObscuranceGathered) == gathered,
    Text(
      name, ": the obscurance gathers as ", gathered, ", not as ", Flags(kept.ObscuranceGathered)));
  Check(Flags(full.ObscuranceKeyed) == std::string(Frames, '1') &&
      Flags(full.ObscuranceGathered) == std::string(Frames, '1'),
    Text(
      name, ": with ConvergeReusesLayers off every frame builds the obscurance's key and gathers"));
}
}

int TestDeepGIConvergeReuse(int, char*[])
{
  CheckCase("nothing changes", nullptr, "11111");
  CheckCase("nothing changes, HIGH_PERFORMANCE", nullptr, "11111", false,
    vtkDeepGBufferPass::REPROJECT, vtkDeepGIPass::HIGH_PERFORMANCE);
  CheckCase(
    "the camera, HIGH_PERFORMANCE", [](GIScene& s) { s.Renderer->GetActiveCamera()->Azimuth(5.0); },
    "11001", false, vtkDeepGBufferPass::REPROJECT, vtkDeepGIPass::HIGH_PERFORMANCE);
  CheckCase(
    "an actor's colour",
    [](GIScene& s) { s.Renderer->GetActors()->GetLastActor()->GetProperty()->SetColor(0, 1, 0); },
    "11001");
  CheckCase(
    "the light's intensity",
    [](GIScene& s)
    { vtkLight::SafeDownCast(s.Renderer->GetLights()->GetItemAsObject(0))->SetIntensity(0.5); },
    "11011");
  CheckCase(
    "the camera", [](GIScene& s) { s.Renderer->GetActiveCamera()->Azimuth(5.0); }, "11001");
  CheckCase(
    "the camera, peeled", [](GIScene& s) { s.Renderer->GetActiveCamera()->Azimuth(5.0); }, "11011",
    false, vtkDeepGBufferPass::DEPTH_PEEL);
  CheckCase(
    "the renderer's ambient light", [](GIScene& s) { s.Renderer->SetAmbient(0.5, 0.5, 0.5); },
    "11011");
  CheckCase(
    "the window size", [](GIScene& s) { s.Window->SetSize(W - 16, H - 8); }, "11011");
  // The obscurance's own setting: the layers are kept, the obscurance is
  // computed again (the image would differ otherwise).
  CheckCase(
    "the obscurance's radius",
    [](GIScene& s) { s.Pass->GetAmbientObscurancePass()->SetRadius(0.3); }, "11111", false,
    vtkDeepGBufferPass::REPROJECT, vtkDeepGIPass::BALANCED, "00100");
  CheckCase(
    "two renderers, the second's camera",
    [](GIScene& s) { s.Second->GetActiveCamera()->Azimuth(5.0); }, "11001", true);
  CheckCase(
    "two renderers, the first's camera",
    [](GIScene& s) { s.Renderer->GetActiveCamera()->Azimuth(5.0); }, "11111", true);
  return ExitStatus();
}
