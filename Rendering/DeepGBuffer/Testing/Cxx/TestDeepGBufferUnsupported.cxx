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

// 0: passed, 1: failed, 125: the OpenGL has what the pass needs.
// `captureSource` is the object whose capture is tried (the pass by default).
int CheckPass(vtkRenderPass* pass, const std::function<bool(vtkImageData*, vtkRenderer*)>& capture,
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
    return 125;
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
  std::printf("%s: warnings %d, capture %s with %d error(s), max difference to plain VTK %g\n",
    pass->GetClassName(), warned, ok ? "succeeded" : "failed", errors.Count, maximum);
  return (warned == 1 && !ok && errors.Count == 1 && maximum == 0.0) ? 0 : 1;
}
}

int TestDeepGBufferUnsupported(int, char*[])
{
  vtkNew<vtkDeepGBufferPass> gbuffer;
  const int gbufferResult = CheckPass(gbuffer,
    [&](vtkImageData* out, vtkRenderer* renderer)
    { return gbuffer->CaptureLayers(out, renderer); });
  if (gbufferResult == 125)
  {
    return 125;
  }
  vtkNew<vtkDeepAmbientObscurancePass> ao;
  const int aoResult = CheckPass(ao,
    [&](vtkImageData* out, vtkRenderer* renderer)
    { return ao->CaptureAmbientVisibility(out, renderer); });
  vtkNew<vtkDeepRadiosityPass> radiosity;
  const int radiosityResult = CheckPass(radiosity,
    [&](vtkImageData* out, vtkRenderer* renderer)
    { return radiosity->CaptureIrradiance(out, renderer); });
  vtkNew<vtkDeepGIPass> gi;
  const int giResult = CheckPass(
    gi,
    [&](vtkImageData* out, vtkRenderer* renderer)
    { return gi->GetGBufferPass()->CaptureLayers(out, renderer); },
    gi->GetGBufferPass());
  return (gbufferResult == 0 && aoResult == 0 && radiosityResult == 0 && giResult == 0) ? 0 : 1;
}
