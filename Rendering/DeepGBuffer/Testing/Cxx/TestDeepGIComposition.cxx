// vtkDeepGIPass composes with the rest of VTK. One 240 x 160 window, two
// renderers side by side (viewports (0, 0.5) and (0.5, 1)), each with its own
// vtkDeepGIPass:
// - left: the headsq skin (vtkFlyingEdges3D at 500, opaque, ambient 0.2)
//   with the same volume drawn by vtkSmartVolumeMapper (bone, translucent)
//   beside it,
//   a translucent sphere (opacity 0.4), a 2D text actor, FXAA on;
// - right: a lit box on a specular floor (every effect).
// Checked: no error event from the window, the renderers or any pass in
// the first frames, after a resize to 200 x 140, and after
// ReleaseGraphicsResources + render; the volume, the translucent sphere
// and the text each change the left image (the same frame without each
// differs in more than 50 pixels by more than 8/255); the right renderer
// runs every effect; the left runs AO and radiosity; the images after the
// resize have the new size and are not blank.

#include "DeepGITestData.h"
#include "DeepGITestHeadsq.h"
#include "DeepRadiosityTest.h"

#include "vtkColorTransferFunction.h"
#include "vtkDeepAmbientObscurancePass.h"
#include "vtkDeepGIPass.h"
#include "vtkDeepReflectionPass.h"
#include "vtkFlyingEdges3D.h"
#include "vtkImageData.h"
#include "vtkPiecewiseFunction.h"
#include "vtkSmartVolumeMapper.h"
#include "vtkSphereSource.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkVolume.h"
#include "vtkVolume16Reader.h"
#include "vtkVolumeProperty.h"

#include <memory>
#include <vector>

using namespace DeepRadiosityTest;
using namespace DeepGITest;

namespace
{
struct Composed
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Left;
  vtkNew<vtkRenderer> Right;
  vtkNew<vtkDeepGIPass> LeftPass;
  vtkNew<vtkDeepGIPass> RightPass;
  vtkNew<vtkVolume> Volume;
  vtkSmartPointer<vtkActor> Sphere;
  vtkNew<vtkTextActor> Text;
};

int CountDifferent(vtkImageData* a, vtkImageData* b, double threshold)
{
  vtkDataArray* x = a->GetPointData()->GetScalars();
  vtkDataArray* y = b->GetPointData()->GetScalars();
  int count = 0;
  for (vtkIdType p = 0; p < x->GetNumberOfTuples(); ++p)
  {
    double d = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      d = std::max(d, std::abs(x->GetComponent(p, c) - y->GetComponent(p, c)));
    }
    count += d > threshold ? 1 : 0;
  }
  return count;
}

double Brightest(vtkImageData* image)
{
  vtkDataArray* x = image->GetPointData()->GetScalars();
  double m = 0.0;
  for (vtkIdType p = 0; p < x->GetNumberOfTuples(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      m = std::max(m, x->GetComponent(p, c));
    }
  }
  return m;
}

// Left: the headsq skin (opaque, ambient 0.2), the same volume drawn by
// vtkSmartVolumeMapper beside it, a translucent sphere and a 2D text, FXAA on.
void AddHeadScene(Composed& s, vtkAlgorithm* reader)
{
  vtkNew<vtkFlyingEdges3D> skin;
  skin->SetInputConnection(reader->GetOutputPort());
  skin->SetValue(0, 500.0);
  vtkActor* skinActor = AddSourceActor(s.Left, skin);
  skinActor->GetProperty()->SetColor(0.9, 0.75, 0.65);
  skinActor->GetProperty()->SetAmbient(0.2);
  const double boneColor[3] = { 1.0, 1.0, 0.9 };
  ShowBone(s.Volume, reader, boneColor, 0.3);
  // Beside the skin (the bone inside it is hidden by the opaque skin, as
  // it should be: the volume composes against layer 0's depth).
  s.Volume->SetPosition(210.0, 0.0, 0.0);
  s.Left->AddVolume(s.Volume);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(100.0, -20.0, 70.0);
  sphere->SetRadius(30.0);
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(16);
  s.Sphere = AddSourceActor(s.Left, sphere);
  s.Sphere->GetProperty()->SetColor(0.2, 0.5, 1.0);
  s.Sphere->GetProperty()->SetOpacity(0.4);
  s.Text->SetInput("GI");
  s.Text->GetTextProperty()->SetFontSize(28);
  s.Text->GetTextProperty()->SetColor(1.0, 1.0, 0.0);
  s.Text->SetDisplayPosition(4, 4);
  s.Left->AddActor2D(s.Text);
  s.Left->GetActiveCamera()->SetPosition(100.0, -400.0, 70.0);
  s.Left->GetActiveCamera()->SetFocalPoint(100.0, 100.0, 70.0);
  s.Left->GetActiveCamera()->SetViewUp(0.0, 0.0, -1.0);
  s.Left->ResetCamera();
  s.Left->UseFXAAOn();
  s.Left->SetPass(s.LeftPass);
}

// Right: a lit box on a specular floor (every effect).
void AddBoxScene(Composed& s)
{
  const double f0[3] = { -2, 0, 2 }, f1[3] = { 2, 0, 2 }, f2[3] = { -2, 0, -2 };
  vtkActor* floor = Diffuse(AddQuad(s.Right, f0, f1, f2), 0.9, 0.9, 0.9);
  floor->GetProperty()->SetSpecular(0.5);
  floor->GetProperty()->SetAmbient(0.2);
  const double center[3] = { 0, 0.5, 0 }, size[3] = { 1, 1, 1 };
  Diffuse(AddBox(s.Right, center, size), 1.0, 0.3, 0.2)->GetProperty()->SetAmbient(0.2);
  AddSun(s.Right, 2, 4, 3);
  SetCamera(s.Right, 3, 2.5, 4, 0, 0.3, 0);
  s.Right->ResetCameraClippingRange();
  s.Right->SetPass(s.RightPass);
}

// Counts the error events of the window, the renderers, every pass and the
// volume mapper.
struct ErrorWatch
{
  explicit ErrorWatch(Composed& s)
  {
    const std::vector<vtkObject*> watched = { s.Window.Get(), s.Left.Get(), s.Right.Get(),
      s.LeftPass.Get(), s.RightPass.Get(), s.LeftPass->GetGBufferPass(),
      s.LeftPass->GetAmbientObscurancePass(), s.LeftPass->GetRadiosityPass(),
      s.LeftPass->GetReflectionPass(), s.RightPass->GetGBufferPass(),
      s.RightPass->GetAmbientObscurancePass(), s.RightPass->GetRadiosityPass(),
      s.RightPass->GetReflectionPass(), s.Volume->GetMapper() };
    for (vtkObject* o : watched)
    {
      this->Counters.emplace_back(new EventCounter(o, vtkCommand::ErrorEvent));
    }
  }
  int Count() const
  {
    int n = 0;
    for (auto& e : this->Counters)
    {
      n += e->Count;
    }
    return n;
  }
  std::vector<std::unique_ptr<EventCounter>> Counters;
};

// Each of the volume, the translucent sphere and the text changes the image.
void CheckEveryPropIsDrawn(Composed& s, vtkImageData* full)
{
  auto without = [&](vtkProp* prop, const char* what)
  {
    prop->VisibilityOff();
    s.Window->Render();
    vtkNew<vtkImageData> image;
    ReadWindow(s.Window, image, nullptr);
    prop->VisibilityOn();
    s.Window->Render();
    const int different = CountDifferent(full, image, 8.0);
    std::printf("without the %s: %d pixels differ by more than 8/255\n", what, different);
    Check(different > 50, std::string("the ") + what + " is drawn");
  };
  without(s.Volume, "volume");
  without(s.Sphere, "translucent sphere");
  without(s.Text, "text");
}

// After a resize the images have the new size and are not blank.
void CheckResizeRenders(Composed& s, const ErrorWatch& errors)
{
  s.Window->SetSize(200, 140);
  s.Window->Render();
  s.Window->Render();
  vtkNew<vtkImageData> resized;
  ReadWindow(s.Window, resized, nullptr);
  const int* dims = resized->GetDimensions();
  std::printf("resized: %d x %d, brightest %.0f, errors %d\n", dims[0], dims[1], Brightest(resized),
    errors.Count());
  Check(dims[0] == 200 && dims[1] == 140 && Brightest(resized) > 100, "resize renders");
  Check(errors.Count() == 0, "no error events after the resize");
}

// ReleaseGraphicsResources, then rendering again works.
void CheckRenderAfterRelease(Composed& s, const ErrorWatch& errors)
{
  s.LeftPass->ReleaseGraphicsResources(s.Window);
  s.RightPass->ReleaseGraphicsResources(s.Window);
  s.Window->Render();
  s.Window->Render();
  vtkNew<vtkImageData> again;
  ReadWindow(s.Window, again, nullptr);
  std::printf("after ReleaseGraphicsResources: brightest %.0f, errors %d, effects %s / %s\n",
    Brightest(again), errors.Count(),
    vtkDeepGIPass::GetEffectsAsString(s.LeftPass->GetLastFrameEffects()).c_str(),
    vtkDeepGIPass::GetEffectsAsString(s.RightPass->GetLastFrameEffects()).c_str());
  Check(
    errors.Count() == 0 && Brightest(again) > 100 && (s.RightPass->GetLastFrameEffects() & 7) == 7,
    "ReleaseGraphicsResources then render works");
}
}

int TestDeepGIComposition(int argc, char* argv[])
{
  const std::string data = DeepGITestData::Folder(argc, argv, "TestDeepGIComposition");
  if (!DeepGITestData::Require(data,
        { "volumes/headsq/quarter.nhdr", "volumes/headsq/quarter.1", "volumes/headsq/quarter.93" },
        "TestDeepGIComposition"))
  {
    return EXIT_FAILURE;
  }
  vtkSmartPointer<vtkVolume16Reader> reader = DeepGITestData::ReadHeadsq(data);
  if (!reader)
  {
    return EXIT_FAILURE;
  }

  Composed s;
  s.Window = MakeWindow(240, 160);
  s.Left->SetViewport(0.0, 0.0, 0.5, 1.0);
  s.Right->SetViewport(0.5, 0.0, 1.0, 1.0);
  s.Left->SetBackground(0.1, 0.1, 0.15);
  s.Right->SetBackground(0.15, 0.1, 0.1);
  s.Window->AddRenderer(s.Left);
  s.Window->AddRenderer(s.Right);

  AddHeadScene(s, reader);
  AddBoxScene(s);
  const ErrorWatch errors(s);

  for (int k = 0; k < 3; ++k)
  {
    s.Window->Render();
  }
  vtkNew<vtkImageData> full;
  ReadWindow(s.Window, full, nullptr);
  const int leftEffects = s.LeftPass->GetLastFrameEffects();
  const int rightEffects = s.RightPass->GetLastFrameEffects();
  std::printf("left: %s, right: %s, errors %d\n",
    vtkDeepGIPass::GetEffectsAsString(leftEffects).c_str(),
    vtkDeepGIPass::GetEffectsAsString(rightEffects).c_str(), errors.Count());
  Check(errors.Count() == 0, "no error events");
  Check((leftEffects & (vtkDeepGIPass::AMBIENT_OBSCURANCE | vtkDeepGIPass::RADIOSITY)) ==
      (vtkDeepGIPass::AMBIENT_OBSCURANCE | vtkDeepGIPass::RADIOSITY),
    "left: AO and radiosity run under the volume and the translucent sphere");
  Check((rightEffects & 7) == 7, "right: every effect runs");
  CheckEveryPropIsDrawn(s, full);
  CheckResizeRenders(s, errors);
  CheckRenderAfterRelease(s, errors);
  s.LeftPass->ReleaseGraphicsResources(s.Window);
  s.RightPass->ReleaseGraphicsResources(s.Window);
  return ExitStatus();
}
