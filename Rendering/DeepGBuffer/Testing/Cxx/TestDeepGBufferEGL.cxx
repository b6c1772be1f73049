// The deep G-buffer through the project's EGL render window, with no X
// server (the test runs with DISPLAY removed): layers are built, separated
// by dz, finite, and layer 0 matches an unpassed render in the same window.

#include "DeepGBufferTestUtilities.h"

#include "vtkCamera.h"
#include "vtkDeepGBufferDemoScene.h"
#include "vtkDeepGIRenderWindowFactory.h"

int TestDeepGBufferEGL(int, char*[])
{
  vtkSmartPointer<vtkRenderWindow> window = vtkSmartPointer<vtkRenderWindow>::Take(
    vtkDeepGIRenderWindowFactory::NewRenderWindow(vtkDeepGIRenderWindowFactory::BACKEND_EGL));
  if (!window)
  {
    std::printf("FAILED: no EGL render window\n");
    return 1;
  }
  window->SetMultiSamples(0);
  window->SetSize(256, 192);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkDeepGBufferDemoScene> scene;
  scene->SetTargetNumberOfTriangles(10000);
  scene->Populate(renderer);
  scene->SetCameraToDefaultView(renderer->GetActiveCamera());
  renderer->ResetCameraClippingRange();
  window->Render();
  vtkNew<vtkImageData> plain;
  DeepGBufferTest::ReadWindow(window, plain, nullptr);

  vtkNew<vtkDeepGBufferPass> pass;
  renderer->SetPass(pass);
  window->Render();
  window->Render();
  vtkNew<vtkImageData> capture, image;
  const bool captured = pass->CaptureLayers(capture, renderer);
  DeepGBufferTest::ReadWindow(window, image, nullptr);
  const double dz = pass->GetEffectiveMinimumSeparation();
  DeepGBufferTest::SeparationReport separation =
    DeepGBufferTest::CheckSeparation(capture, 1, dz, 1e-6);
  const double maximum = DeepGBufferTest::MaximumColorDifference(image, plain);
  std::printf("EGL: layer 1 %ld px, %ld closer than dz %g; max difference to plain VTK %g\n",
    separation.Pixels, separation.Violations, dz, maximum);
  pass->ReleaseGraphicsResources(window);
  const bool ok = captured && DeepGBufferTest::AllFinite(capture) && separation.Violations == 0 &&
    separation.Pixels > 1000 && maximum <= 1.0;
  return ok ? 0 : 1;
}
