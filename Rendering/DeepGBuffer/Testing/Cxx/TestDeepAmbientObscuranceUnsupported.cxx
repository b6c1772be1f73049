// vtkDeepAmbientObscurancePass on an OpenGL that lacks what the G-buffer
// needs (CTest runs it with Mesa told to expose OpenGL 4.1 without
// ARB_copy_image, like TestDeepGBufferUnsupported): the AO pass warns once
// over three frames, the image is VTK's plain image (exactly), and a capture
// fails with one error instead of crashing. Skipped (125) where the driver
// ignores Mesa's overrides.

#include "DeepGBufferTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDeepAmbientObscurancePass.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPolyDataMapper.h"
#include "vtkSphereSource.h"
#include "vtk_glew.h"

namespace
{
struct EventCounter
{
  int Count = 0;
  vtkNew<vtkCallbackCommand> Callback;
  EventCounter(vtkObject* object, unsigned long event)
  {
    this->Callback->SetClientData(this);
    this->Callback->SetCallback(
      [](vtkObject*, unsigned long, void* self, void*) { ++static_cast<EventCounter*>(self)->Count; });
    object->AddObserver(event, this->Callback);
  }
};

vtkSmartPointer<vtkRenderWindow> RenderSphere(vtkRenderPass* pass, vtkRenderer* renderer)
{
  auto window = DeepGBufferTest::MakeWindow(160, 120);
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
}

int TestDeepAmbientObscuranceUnsupported(int, char*[])
{
  vtkNew<vtkDeepAmbientObscurancePass> pass;
  EventCounter warnings(pass, vtkCommand::WarningEvent);
  EventCounter errors(pass, vtkCommand::ErrorEvent);
  vtkNew<vtkRenderer> renderer, plainRenderer;
  auto window = RenderSphere(pass, renderer);
  vtkOpenGLRenderWindow::SafeDownCast(window)->MakeCurrent();
  if (GLEW_VERSION_4_3 || GLEW_ARB_copy_image)
  {
    std::printf("this OpenGL has glCopyImageSubData (Mesa overrides ignored): skipped\n");
    pass->ReleaseGraphicsResources(window);
    return 125;
  }
  vtkNew<vtkImageData> capture, image, plainImage;
  const bool captured = pass->CaptureAmbientVisibility(capture, renderer);
  DeepGBufferTest::ReadWindow(window, image, nullptr);
  auto plainWindow = RenderSphere(nullptr, plainRenderer);
  DeepGBufferTest::ReadWindow(plainWindow, plainImage, nullptr);

  double maximum = 0.0;
  vtkDataArray* a = image->GetPointData()->GetScalars();
  vtkDataArray* b = plainImage->GetPointData()->GetScalars();
  for (vtkIdType p = 0; p < a->GetNumberOfTuples(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      maximum = std::max(maximum, std::abs(a->GetComponent(p, c) - b->GetComponent(p, c)));
    }
  }
  std::printf("warnings %d, capture %s with %d error(s), max difference to plain VTK %g\n",
    warnings.Count, captured ? "succeeded" : "failed", errors.Count, maximum);
  pass->ReleaseGraphicsResources(window);
  // Rendering again after the release still works (and warns no more).
  window->Render();
  pass->ReleaseGraphicsResources(window);
  return (warnings.Count == 1 && !captured && errors.Count == 1 && maximum == 0.0) ? 0 : 1;
}
