// vtkDeepGIPass::Converge can be interrupted and works through wrapping
// passes.
// 1. An observer of ProgressEvent that sets the window's AbortRender flag
//    after the 3rd frame stops Converge(renderer, 1e9) after 3 frames (the
//    1e9 frames clamped to MAXIMUM_CONVERGE_FRAMES with one warning);
//    GetLastConvergenceAborted() is true.
// 2. An AbortCheckEvent observer of the window that sets the flag once 2
//    frames are complete stops it after the frame in which it did (VTK
//    fires AbortCheckEvent at most 5 times a second, after a frame through
//    Converge's CheckAbortStatus or during one through the mappers').
// 3. SIGINT raised during frame 2's progress stops it after 2 frames; the
//    program's own SIGINT handler is restored and then receives that
//    SIGINT once.
// 4. An exception thrown by an observer leaves Converge; the SIGINT handler
//    is restored and a later Converge renders all its frames.
// 5. Wrapped by vtkOpenGLFXAAPass, vtkSSAAPass, vtkToneMappingPass or a
//    render pass of the test's own that only calls it (as ParaView's
//    compositing passes do), the pass converges: no warning that the renderer does not use it, the
//    change is measured and the tolerance met before the frame cap, and
//    the GI effects ran. A renderer without the pass still gets that
//    warning.
// 6. After Converge, a frame at the same camera holds the converged image:
//    reading the window through vtkWindowToImageFilter, which renders it
//    again (and sets and restores the renderer's viewport), gives the
//    converged frame (at most 1/255 apart in any channel; measured 0) and
//    its ambient visibility (within 1e-3; measured below 1e-4). Once the
//    camera has moved, frames render with the interactive settings again:
//    back at the converged camera, the obscurance's narrower blur moves
//    the ambient visibility by more than 0.01 somewhere (measured 0.10).
//    After an aborted Converge nothing is held (the same difference). Two
//    renderers sharing the pass, each converged in turn, both hold their
//    images when the window is rendered again.

#include "DeepRadiosityTest.h"

#include "vtkCamera.h"
#include "vtkDeepAmbientObscurancePass.h"
#include "vtkDeepGIPass.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFXAAPass.h"
#include "vtkSSAAPass.h"
#include "vtkToneMappingPass.h"
#include "vtkWindowToImageFilter.h"

#include <csignal>
#include <cstring>
#include <functional>
#include <stdexcept>

#include <signal.h>

using namespace DeepRadiosityTest;
using namespace DeepGITest;

namespace
{
constexpr int W = 96, H = 72;

// The red-wall scene with an ambient term on every actor (obscurance and
// radiosity both run).
struct Scene
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkDeepGIPass> Pass;

  Scene()
  {
    this->Window = MakeWindow(W, H);
    this->Window->AddRenderer(this->Renderer);
    RedWallSceneWithAmbient(this->Renderer);
  }
  ~Scene()
  {
    this->Renderer->SetPass(nullptr);
    this->Pass->ReleaseGraphicsResources(this->Window);
  }
};

// Calls `action(k)` at the k-th event of `object`.
struct Observer
{
  int Count = 0;
  std::function<void(int)> Action;
  vtkNew<vtkCallbackCommand> Callback;
  vtkObject* Object = nullptr;
  unsigned long Tag = 0;
  Observer(vtkObject* object, unsigned long event, std::function<void(int)> action)
    : Action(std::move(action))
    , Object(object)
  {
    this->Callback->SetClientData(this);
    this->Callback->SetCallback(
      [](vtkObject*, unsigned long, void* self, void*)
      {
        auto* o = static_cast<Observer*>(self);
        o->Action(++o->Count);
      });
    this->Tag = object->AddObserver(event, this->Callback);
  }
  ~Observer() { this->Object->RemoveObserver(this->Tag); }
};

volatile std::sig_atomic_t TestInterrupts = 0;
extern "C" void CountInterrupt(int)
{
  ++TestInterrupts;
}

void (*CurrentInterruptHandler())(int)
{
  struct sigaction current;
  sigaction(SIGINT, nullptr, &current);
  return current.sa_handler;
}

void CheckAbort()
{
  Scene scene;
  scene.Renderer->SetPass(scene.Pass);
  EventCounter warnings(scene.Pass, vtkCommand::WarningEvent);
  EventCounter frames(scene.Window, vtkCommand::EndEvent);
  int progressEvents = 0;
  {
    Observer abort(scene.Pass, vtkCommand::ProgressEvent,
      [&](int k)
      {
        progressEvents = k;
        if (k == 3)
        {
          scene.Window->SetAbortRender(1);
        }
      });
    const int rendered = scene.Pass->Converge(scene.Renderer, 1000000000);
    std::printf("Converge(1e9) with an abort after frame 3: %d frames, %d renders, %d progress "
                "events, %d warning(s)\n",
      rendered, frames.Count, progressEvents, warnings.Count);
    Check(rendered == 3 && frames.Count == 3 && progressEvents == 3,
      "an observer that aborts after 3 frames stops Converge after 3 frames");
    Check(scene.Pass->GetLastConvergenceAborted() && !scene.Pass->GetLastConvergenceReached(),
      "GetLastConvergenceAborted() tells it was aborted");
    Check(warnings.Count == 1, "1e9 frames are clamped with one warning");
  }
  {
    frames.Count = 0;
    int completeAtAbort = -1;
    Observer check(scene.Window, vtkCommand::AbortCheckEvent,
      [&](int)
      {
        if (frames.Count >= 2 && completeAtAbort < 0)
        {
          completeAtAbort = frames.Count;
          scene.Window->SetAbortRender(1);
        }
      });
    const int rendered = scene.Pass->Converge(scene.Renderer, 50);
    std::printf("AbortCheckEvent observer: %d frames, %d renders, %d abort checks, aborted with %d "
                "frames complete\n",
      rendered, frames.Count, check.Count, completeAtAbort);
    Check(scene.Pass->GetLastConvergenceAborted() && rendered == frames.Count &&
        completeAtAbort >= 2 && (rendered == completeAtAbort || rendered == completeAtAbort + 1) &&
        rendered < 50,
      "an AbortCheckEvent observer of the window stops it after the frame in which it aborts");
  }
  Check(scene.Pass->Converge(scene.Renderer, 2) == 2 && !scene.Pass->GetLastConvergenceAborted(),
    "without an abort every frame is rendered");
  Check(scene.Pass->GetLastFrameEffects() & vtkDeepGIPass::RADIOSITY, "the GI effects ran");
}

void CheckInterrupt()
{
  Scene scene;
  scene.Renderer->SetPass(scene.Pass);
  TestInterrupts = 0;
  void (*previous)(int) = std::signal(SIGINT, CountInterrupt);
  int interruptsDuringConverge = -1;
  int rendered = 0;
  {
    Observer interrupt(scene.Pass, vtkCommand::ProgressEvent,
      [&](int k)
      {
        if (k == 2)
        {
          std::raise(SIGINT);
          interruptsDuringConverge = TestInterrupts;
        }
      });
    rendered = scene.Pass->Converge(scene.Renderer, 50);
  }
  std::printf("SIGINT at frame 2: %d frames; the program's handler saw %d SIGINT during Converge, "
              "%d after\n",
    rendered, interruptsDuringConverge, static_cast<int>(TestInterrupts));
  Check(rendered == 2 && scene.Pass->GetLastConvergenceAborted(),
    "SIGINT stops Converge after the frame in progress");
  Check(interruptsDuringConverge == 0 && TestInterrupts == 1,
    "the program's SIGINT handler gets the SIGINT once, after Converge");
  Check(CurrentInterruptHandler() == CountInterrupt, "the program's SIGINT handler is restored");

  int thrownAt = 0;
  {
    Observer thrower(scene.Pass, vtkCommand::ProgressEvent,
      [](int k)
      {
        if (k == 2)
        {
          throw std::runtime_error("stop");
        }
      });
    try
    {
      scene.Pass->Converge(scene.Renderer, 50);
    }
    catch (const std::runtime_error&)
    {
      thrownAt = 2;
      // VTK's InvokeEvent holds a reference to the command while it runs;
      // the exception skipped its release (LeakSanitizer finds it).
      thrower.Callback->UnRegister(nullptr);
    }
  }
  Check(thrownAt == 2, "an observer's exception leaves Converge");
  Check(CurrentInterruptHandler() == CountInterrupt && TestInterrupts == 1,
    "after the exception the SIGINT handler is restored, no SIGINT raised");
  Check(scene.Pass->Converge(scene.Renderer, 3) == 3, "Converge works after the exception");
  std::signal(SIGINT, previous);
}

// A render pass that only calls another one, unknown to vtkDeepGIPass.
class DelegatingPass : public vtkRenderPass
{
public:
  static DelegatingPass* New();
  vtkTypeMacro(DelegatingPass, vtkRenderPass);
  void Render(const vtkRenderState* s) override
  {
    this->Delegate->Render(s);
    this->NumberOfRenderedProps = this->Delegate->GetNumberOfRenderedProps();
  }
  void ReleaseGraphicsResources(vtkWindow* w) override
  {
    this->Delegate->ReleaseGraphicsResources(w);
  }
  vtkSmartPointer<vtkRenderPass> Delegate;
};
vtkStandardNewMacro(DelegatingPass);

// Converge through a wrapping pass made by `wrap` around the GI pass.
using Wrap = std::function<vtkSmartPointer<vtkRenderPass>(vtkDeepGIPass*)>;
void CheckWrapped(const char* name, const Wrap& wrap)
{
  Scene scene;
  vtkSmartPointer<vtkRenderPass> wrapper = wrap(scene.Pass);
  scene.Renderer->SetPass(wrapper);
  EventCounter warnings(scene.Pass, vtkCommand::WarningEvent);
  const double tolerance = 0.5 / 255.0;
  const int rendered = scene.Pass->Converge(scene.Renderer, 30, tolerance);
  std::printf("%s: %d frames, last change %.4f/255, effects %s, %d warning(s)\n", name, rendered,
    255.0 * scene.Pass->GetLastConvergenceChange(),
    vtkDeepGIPass::GetEffectsAsString(scene.Pass->GetLastFrameEffects()).c_str(), warnings.Count);
  Check(warnings.Count == 0, std::string(name) + ": no warning that the pass is not used");
  Check(scene.Pass->GetLastConvergenceReached() && rendered >= 2 && rendered < 30 &&
      scene.Pass->GetLastConvergenceChange() >= 0.0 &&
      scene.Pass->GetLastConvergenceChange() <= tolerance,
    std::string(name) + ": the change is measured and the tolerance met before the cap");
  Check((scene.Pass->GetLastFrameEffects() & vtkDeepGIPass::RADIOSITY) != 0,
    std::string(name) + ": the GI effects ran");
  scene.Renderer->SetPass(nullptr);
  wrapper->ReleaseGraphicsResources(scene.Window);
}

void CheckWrappers()
{
  CheckWrapped("vtkOpenGLFXAAPass",
    [](vtkDeepGIPass* gi)
    {
      auto fxaa = vtkSmartPointer<vtkOpenGLFXAAPass>::New();
      fxaa->SetDelegatePass(gi);
      return fxaa;
    });
  CheckWrapped("vtkSSAAPass",
    [](vtkDeepGIPass* gi)
    {
      auto ssaa = vtkSmartPointer<vtkSSAAPass>::New();
      ssaa->SetDelegatePass(gi);
      return ssaa;
    });
  CheckWrapped("vtkToneMappingPass",
    [](vtkDeepGIPass* gi)
    {
      auto toneMapping = vtkSmartPointer<vtkToneMappingPass>::New();
      toneMapping->SetToneMappingType(vtkToneMappingPass::GenericFilmic);
      toneMapping->SetDelegatePass(gi);
      return toneMapping;
    });
  // A wrapper the pass knows nothing about (as ParaView's IceT compositing
  // pass is): seen to render the pass, no warning.
  CheckWrapped("a delegating vtkRenderPass subclass",
    [](vtkDeepGIPass* gi)
    {
      auto delegating = vtkSmartPointer<DelegatingPass>::New();
      delegating->Delegate = gi;
      return delegating;
    });
  // A renderer that does not use the pass still gets the warning.
  Scene scene;
  EventCounter warnings(scene.Pass, vtkCommand::WarningEvent);
  Check(scene.Pass->Converge(scene.Renderer, 2) == 2 && warnings.Count == 1,
    "a renderer without the pass: the frames and one warning");
}

// The window's colour, rendered again first or not.
void ReadColour(vtkRenderWindow* window, bool render, vtkImageData* colour)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetShouldRerender(render);
  grab->ReadFrontBufferOff();
  grab->SetInputBufferTypeToRGB();
  grab->Update();
  colour->DeepCopy(grab->GetOutput());
}

// The last frame's ambient visibility (filtered) of the scene's renderer.
vtkSmartPointer<vtkDataArray> ReadVisibility(Scene& scene, vtkRenderer* renderer = nullptr)
{
  vtkNew<vtkImageData> capture;
  Check(scene.Pass->GetAmbientObscurancePass()->CaptureAmbientVisibility(
          capture, renderer ? renderer : scene.Renderer.GetPointer()),
    "the ambient visibility is captured");
  return capture->GetPointData()->GetArray(vtkDeepGICaptureNames::AmbientVisibility);
}

// The largest difference between two arrays of ambient visibility.
double MaximumDifference(vtkDataArray* a, vtkDataArray* b)
{
  double maximum = 0.0;
  for (vtkIdType v = 0; v < a->GetNumberOfValues(); ++v)
  {
    maximum = std::max(maximum, std::abs(a->GetComponent(v, 0) - b->GetComponent(v, 0)));
  }
  return maximum;
}

void CheckHold()
{
  Scene scene;
  scene.Renderer->SetPass(scene.Pass);
  scene.Pass->Converge(scene.Renderer, 16, 0.07 / 255.0);
  vtkNew<vtkImageData> converged, held;
  ReadColour(scene.Window, false, converged);
  const auto convergedVisibility = ReadVisibility(scene);
  ReadColour(scene.Window, true, held);
  const double colour = MaximumColorDifference(converged, held);
  const double visibility = MaximumDifference(convergedVisibility, ReadVisibility(scene));
  std::printf("rendered again after Converge: %.0f/255 and AV %.4f from the converged frame\n",
    colour, visibility);
  Check(colour <= 1.0, "the frame after Converge shows the converged image");
  Check(visibility <= 1e-3, "the frame after Converge keeps the still image's obscurance");

  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->Azimuth(5.0);
  scene.Window->Render();
  camera->Azimuth(-5.0);
  scene.Window->Render();
  const double moved = MaximumDifference(convergedVisibility, ReadVisibility(scene));
  std::printf("after the camera moved and came back: AV %.4f from the converged frame\n", moved);
  Check(moved > 0.01, "after the camera moved, frames use the interactive settings");

  Observer abort(
    scene.Pass, vtkCommand::ProgressEvent, [&scene](int) { scene.Window->SetAbortRender(1); });
  scene.Pass->Converge(scene.Renderer, 16, 0.07 / 255.0);
  Check(scene.Pass->GetLastConvergenceAborted(), "Converge aborted");
  const auto aborted = ReadVisibility(scene);
  scene.Window->Render();
  const double afterAbort = MaximumDifference(aborted, ReadVisibility(scene));
  std::printf("rendered again after an aborted Converge: AV %.4f from its frame\n", afterAbort);
  Check(afterAbort > 0.01, "after an aborted Converge, frames use the interactive settings");
}

// Two renderers sharing the pass, each converged: rendering the window
// again holds both still images.
void CheckSharedHold()
{
  Scene scene;
  vtkNew<vtkRenderer> right;
  scene.Renderer->SetViewport(0.0, 0.0, 0.5, 1.0);
  right->SetViewport(0.5, 0.0, 1.0, 1.0);
  RedWallSceneWithAmbient(right);
  scene.Window->AddRenderer(right);
  scene.Renderer->SetPass(scene.Pass);
  right->SetPass(scene.Pass);
  scene.Pass->Converge(scene.Renderer, 16, 0.07 / 255.0);
  scene.Pass->Converge(right, 16, 0.07 / 255.0);
  const auto left = ReadVisibility(scene);
  const auto rightVisibility = ReadVisibility(scene, right);
  vtkNew<vtkImageData> colour;
  ReadColour(scene.Window, true, colour);
  const double leftDifference = MaximumDifference(left, ReadVisibility(scene));
  const double rightDifference = MaximumDifference(rightVisibility, ReadVisibility(scene, right));
  std::printf("shared pass, rendered again: AV %.4f (left), %.4f (right) from the converged "
              "frames\n",
    leftDifference, rightDifference);
  Check(leftDifference <= 1e-3 && rightDifference <= 1e-3,
    "renderers sharing the pass both hold their still images");
  right->SetPass(nullptr);
}
}

int TestDeepGIConverge(int, char*[])
{
  CheckHold();
  CheckSharedHold();
  CheckAbort();
  CheckInterrupt();
  CheckWrappers();
  return ExitStatus();
}
