// The deep G-buffer through the project's EGL render window, with no X
// server (the test runs with DISPLAY removed): layers are built, separated
// by dz, finite, and layer 0 matches an unpassed render in the same window.

#include "DeepGBufferTestUtilities.h"

#include "vtkCamera.h"
#include "vtkDeepGIDemoScene.h"
#include "vtkDeepGIRenderWindowFactory.h"

int TestDeepGBufferEGL(int, char*[])
{
  vtkSmartPointer<vtkRenderWindow> window = vtkSmartPointer<vtkRenderWindow>::Take(
    vtkDeepGIRenderWindowFactory::NewRenderWindow(vtkDeepGIRenderWindowFactory::BACKEND_EGL));
  if (!DeepGITest::Check(window != nullptr, "an EGL render window is created"))
  {
    return EXIT_FAILURE;
  }
  window->SetMultiSamples(0);
  window->SetSize(256, 192);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  DeepGBufferTest::AddDemoScene(renderer, 10000);
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
  pass->ReleaseGraphicsResources(window);
  DeepGITest::Check(captured, "the layers are captured");
  DeepGITest::Check(DeepGBufferTest::AllFinite(capture), "the captured layers are finite");
  DeepGITest::Check(separation.Violations == 0,
    DeepGITest::Format("layer 1: %ld pixels closer than dz %g", separation.Violations, dz));
  DeepGITest::Check(separation.Pixels > 1000,
    DeepGITest::Format("layer 1: %ld pixels (> 1000)", separation.Pixels));
  DeepGITest::Check(maximum <= 1.0,
    DeepGITest::Format("layer 0 matches plain VTK (max difference %g <= 1)", maximum));
  return DeepGITest::ExitStatus();
}
