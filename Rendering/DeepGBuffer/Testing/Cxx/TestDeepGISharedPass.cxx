// One vtkDeepGIPass set on the renderers of two render windows: the pass
// renders into one window at a time (its sub-passes' OpenGL objects belong
// to one context) and refuses the other clearly.
// 1. Rendering A, B, A, B, A, B: A gets GI, and its image is the one a pass
//    of its own gives after 3 frames (B's frames do not disturb it); B is
//    drawn the plain VTK way (its image equals VTK's without a pass, no GI
//    effect reported) with ONE error naming the cause; no OpenGL error in
//    either context.
// 2. ReleaseGraphicsResources(B) frees nothing of A's; after
//    ReleaseGraphicsResources(A) the pass renders GI into B, and A is the
//    refused one.
// 3. Nothing else is reported, also when the windows are destroyed (VTK's
//    "texture units have not been released" and leaked-object warnings
//    included).

#include "DeepRadiosityTest.h"

#include "vtkDeepGIPass.h"
#include "vtkOutputWindow.h"
#include "vtk_glew.h"

#include <string>

using namespace DeepRadiosityTest;
using namespace DeepGITest;

namespace
{
constexpr int W = 96, H = 72;

// Messages that reach VTK's output window (not handled by an observer).
struct OutputMessages
{
  int Count = 0;
  unsigned long Tags[2] = { 0, 0 };
  void OnMessage(vtkObject*, unsigned long, void* text)
  {
    ++this->Count;
    std::printf("output window: %s\n", text ? static_cast<const char*>(text) : "");
  }
  OutputMessages()
  {
    vtkOutputWindow* window = vtkOutputWindow::GetInstance();
    this->Tags[0] = window->AddObserver(vtkCommand::ErrorEvent, this, &OutputMessages::OnMessage);
    this->Tags[1] = window->AddObserver(vtkCommand::WarningEvent, this, &OutputMessages::OnMessage);
  }
  ~OutputMessages()
  {
    for (unsigned long tag : this->Tags)
    {
      vtkOutputWindow::GetInstance()->RemoveObserver(tag);
    }
  }
};

struct ErrorRecorder
{
  int Count = 0;
  std::string Last;
  void OnError(vtkObject*, unsigned long, void* text)
  {
    ++this->Count;
    this->Last = text ? static_cast<const char*>(text) : "";
  }
};

// The red-wall scene with an ambient term, in its own window.
struct View
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkImageData> Image;
  int GLErrors = 0;

  explicit View(double wallScale)
  {
    this->Window = MakeWindow(W, H);
    this->Window->AddRenderer(this->Renderer);
    RedWallScene(this->Renderer, wallScale);
    vtkActorCollection* actors = this->Renderer->GetActors();
    vtkCollectionSimpleIterator it;
    actors->InitTraversal(it);
    while (vtkActor* actor = actors->GetNextActor(it))
    {
      actor->GetProperty()->SetAmbient(0.3);
    }
    this->Renderer->ResetCameraClippingRange();
  }
  void Render()
  {
    this->Window->Render();
    ReadWindow(this->Window, this->Image, nullptr);
    this->Window->MakeCurrent();
    while (glGetError() != GL_NO_ERROR)
    {
      ++this->GLErrors;
    }
  }
};

void CheckSharedPass()
{
  OutputMessages output;
  {
    // References: A with a pass of its own (3 frames), B without a pass.
    View referenceA(1.0), plainB(0.8);
    // Two layers always: the adaptive count follows occlusion queries read
    // when ready, which would make the two runs depend on timing.
    vtkNew<vtkDeepGIPass> own;
    own->AdaptiveLayersOff();
    referenceA.Renderer->SetPass(own);
    for (int k = 0; k < 3; ++k)
    {
      referenceA.Render();
    }
    plainB.Render();

    View a(1.0), b(0.8);
    vtkNew<vtkDeepGIPass> gi;
    gi->AdaptiveLayersOff();
    ErrorRecorder errors;
    gi->AddObserver(vtkCommand::ErrorEvent, &errors, &ErrorRecorder::OnError);
    a.Renderer->SetPass(gi);
    b.Renderer->SetPass(gi);
    int effectsA = ~0, effectsB = ~0;
    for (int k = 0; k < 3; ++k)
    {
      a.Render();
      effectsA &= gi->GetLastFrameEffects();
      b.Render();
      effectsB &= gi->GetLastFrameEffects();
    }
    const double differenceA = MaximumColorDifference(a.Image, referenceA.Image);
    const double differenceB = MaximumColorDifference(b.Image, plainB.Image);
    std::printf("A, B alternately: A's effects %s, B's %s; A vs its own pass %.0f, B vs plain VTK "
                "%.0f (0..255); %d error(s) of the pass, %d OpenGL error(s); the error: %s\n",
      vtkDeepGIPass::GetEffectsAsString(effectsA).c_str(),
      vtkDeepGIPass::GetEffectsAsString(effectsB).c_str(), differenceA, differenceB, errors.Count,
      a.GLErrors + b.GLErrors, errors.Last.substr(errors.Last.find("vtkDeepGIPass (")).c_str());
    Check((effectsA & vtkDeepGIPass::RADIOSITY) && (effectsA & vtkDeepGIPass::AMBIENT_OBSCURANCE),
      "the first window gets GI in every frame");
    Check(differenceA <= 1.0, "its image is the one of a pass of its own: B does not disturb it");
    Check(effectsB == 0 && differenceB <= 1.0, "the second window is drawn the plain VTK way");
    Check(errors.Count == 1 && errors.Last.find("cannot render into another") != std::string::npos,
      "one error, naming the cause");
    Check(a.GLErrors == 0 && b.GLErrors == 0 && referenceA.GLErrors == 0,
      "no OpenGL error in either context");

    gi->ReleaseGraphicsResources(b.Window);
    a.Render();
    Check((gi->GetLastFrameEffects() & vtkDeepGIPass::RADIOSITY) && a.GLErrors == 0,
      "releasing the refused window frees nothing of the first window's");
    gi->ReleaseGraphicsResources(a.Window);
    b.Render();
    const int effectsAfter = gi->GetLastFrameEffects();
    a.Render();
    Check((effectsAfter & vtkDeepGIPass::RADIOSITY) && gi->GetLastFrameEffects() == 0 &&
        errors.Count == 2 && b.GLErrors == 0 && a.GLErrors == 0,
      "after ReleaseGraphicsResources(A) the pass renders GI into B and refuses A");
    gi->ReleaseGraphicsResources(b.Window);
    own->ReleaseGraphicsResources(referenceA.Window);
    for (View* view : { &referenceA, &plainB, &a, &b })
    {
      view->Renderer->SetPass(nullptr);
    }
  } // the windows are destroyed here
  Check(output.Count == 0, "nothing else reported, also when the windows are destroyed");
}
}

int TestDeepGISharedPass(int, char*[])
{
  CheckSharedPass();
  return ExitStatus();
}
