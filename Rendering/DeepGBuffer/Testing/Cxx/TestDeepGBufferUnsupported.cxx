// An OpenGL that lacks what the G-buffer needs. CTest runs this test with
// Mesa told to expose OpenGL 4.1 without ARB_copy_image (no
// glCopyImageSubData). Each pass (vtkDeepGBufferPass,
// vtkDeepAmbientObscurancePass, vtkDeepRadiosityPass and vtkDeepGIPass) must say so once with a
// warning over three frames and render VTK's plain image exactly; a capture
// fails with one error (for vtkDeepGIPass: its G-buffer's capture), not a crash; rendering after
// ReleaseGraphicsResources still works (the check, and its warning, are made again for the released
// context). On a driver that ignores Mesa's overrides the test is skipped.

#include "DeepGBufferTestUtilities.h"

#include "vtkDeepAmbientObscurancePass.h"
#include "vtkDeepGIPass.h"
#include "vtkDeepRadiosityPass.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPolyDataMapper.h"
#include "vtkSphereSource.h"
#include "vtk_glew.h"

#include <functional>

using namespace DeepGBufferTest;
using namespace DeepGITest;

namespace
{
vtkSmartPointer<vtkRenderWindow> RenderSphere(vtkRenderPass* pass, vtkRenderer* renderer)
{
  auto window = MakeWindow(160, 120);
  window->AddRenderer(renderer);
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  if (pass)
  {
    renderer->SetPass(pass);
  }
  for (int frame = 0; frame < 3; ++frame)
  {
    window->Render();
  }
  return window;
}

// Checks that the pass warns once, refuses the capture with one error and
// draws what plain VTK draws. Returns false, having checked nothing, when
// the OpenGL has what the pass needs (the test is then skipped).
// `captureSource` is the object whose capture is tried (the pass by default).
bool CheckPass(vtkRenderPass* pass, const std::function<bool(vtkImageData*, vtkRenderer*)>& capture,
  vtkObject* captureSource = nullptr)
{
  EventCounter warnings(pass, vtkCommand::WarningEvent);
  EventCounter errors(captureSource ? captureSource : pass, vtkCommand::ErrorEvent);
  vtkNew<vtkRenderer> renderer, plainRenderer;
  auto window = RenderSphere(pass, renderer);
  vtkOpenGLRenderWindow::SafeDownCast(window)->MakeCurrent();
  if (GLEW_VERSION_4_3 || GLEW_ARB_copy_image)
  {
    std::printf("this OpenGL has glCopyImageSubData (Mesa overrides ignored): skipped\n");
    pass->ReleaseGraphicsResources(window);
    return false;
  }
  vtkNew<vtkImageData> captured, image, plainImage;
  const bool ok = capture(captured, renderer);
  ReadWindow(window, image, nullptr);
  auto plainWindow = RenderSphere(nullptr, plainRenderer);
  ReadWindow(plainWindow, plainImage, nullptr);
  const double maximum = MaximumColorDifference(image, plainImage);
  const int warned = warnings.Count;
  pass->ReleaseGraphicsResources(window);
  window->Render();
  pass->ReleaseGraphicsResources(window);
  const char* name = pass->GetClassName();
  Check(warned == 1, Format("%s: one warning (got %d)", name, warned));
  Check(!ok, Format("%s: the capture is refused", name));
  Check(errors.Count == 1, Format("%s: one error from the capture (got %d)", name, errors.Count));
  Check(
    maximum == 0.0, Format("%s: the image equals plain VTK's (max difference %g)", name, maximum));
  return true;
}
}

int TestDeepGBufferUnsupported(int, char*[])
{
  vtkNew<vtkDeepGBufferPass> gbuffer;
  const bool checked = CheckPass(gbuffer,
    [&](vtkImageData* out, vtkRenderer* renderer)
    { return gbuffer->CaptureLayers(out, renderer); });
  if (!checked)
  {
    return 125;
  }
  vtkNew<vtkDeepAmbientObscurancePass> ao;
  CheckPass(ao,
    [&](vtkImageData* out, vtkRenderer* renderer)
    { return ao->CaptureAmbientVisibility(out, renderer); });
  vtkNew<vtkDeepRadiosityPass> radiosity;
  CheckPass(radiosity,
    [&](vtkImageData* out, vtkRenderer* renderer)
    { return radiosity->CaptureIrradiance(out, renderer); });
  vtkNew<vtkDeepGIPass> gi;
  CheckPass(
    gi,
    [&](vtkImageData* out, vtkRenderer* renderer)
    { return gi->GetGBufferPass()->CaptureLayers(out, renderer); },
    gi->GetGBufferPass());
  return ExitStatus();
}
