// Regression images of the deep G-buffer: one window, two viewports sharing
// the scene's actors. Left: layer 0 radiance (the lit image, what VTK
// draws). Right: layer 1 radiance through the pass's debug display. Before
// the image comparison the captured layers are checked numerically, since
// VTK 9.1's image threshold is a sum that lets many slightly wrong pixels
// pass.
#ifndef DeepGBufferImageTest_h
#define DeepGBufferImageTest_h

#include "DeepGBufferTestUtilities.h"

#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkRegressionTestImage.h"

#include <functional>

namespace DeepGBufferTest
{
// `build` fills the left renderer and sets its camera; dz < 0 keeps the
// automatic minimum separation. The image threshold
// is VTK 9.1's summed metric (see VTK91-NOTES.md); `threshold` is chosen per
// test and explained there.
inline int RunLayerImageTest(int argc, char* argv[], const std::function<bool(vtkRenderer*)>& build,
  double dz, long minimumLayer1Pixels, double threshold)
{
  auto window = MakeWindow(600, 300);
  vtkNew<vtkRenderer> lit, deep;
  lit->SetViewport(0.0, 0.0, 0.5, 1.0);
  deep->SetViewport(0.5, 0.0, 1.0, 1.0);
  lit->SetBackground(0.1, 0.1, 0.15);
  deep->SetBackground(0.1, 0.1, 0.15);
  window->AddRenderer(lit);
  window->AddRenderer(deep);
  if (!build(lit))
  {
    return EXIT_FAILURE;
  }
  vtkActorCollection* actors = lit->GetActors();
  actors->InitTraversal();
  while (vtkActor* actor = actors->GetNextActor())
  {
    deep->AddActor(actor);
  }
  deep->SetActiveCamera(lit->GetActiveCamera());
  deep->SetLightCollection(lit->GetLights());
  deep->AutomaticLightCreationOff();

  vtkNew<vtkDeepGBufferPass> layer0, layer1;
  for (vtkDeepGBufferPass* pass : { layer0.Get(), layer1.Get() })
  {
    if (dz >= 0.0)
    {
      pass->SetMinimumSeparation(dz);
    }
  }
  layer1->SetDisplayLayer(1);
  lit->SetPass(layer0);
  deep->SetPass(layer1);
  for (int frame = 0; frame < 3; ++frame)
  {
    window->Render();
  }

  vtkNew<vtkImageData> capture;
  layer1->CaptureLayers(capture, deep);
  dz = layer1->GetEffectiveMinimumSeparation();
  SeparationReport separation = CheckSeparation(capture, 1, dz, 1e-6);
  DeepGITest::Check(AllFinite(capture), "the captured layers are finite");
  DeepGITest::Check(separation.Violations == 0,
    DeepGITest::Format(
      "layer 1: %ld pixels closer than dz = %g behind layer 0", separation.Violations, dz));
  DeepGITest::Check(separation.Pixels >= minimumLayer1Pixels,
    DeepGITest::Format("layer 1: %ld pixels (>= %ld)", separation.Pixels, minimumLayer1Pixels));
  CheckRegressionImage(argc, argv, window, threshold);
  layer0->ReleaseGraphicsResources(window);
  layer1->ReleaseGraphicsResources(window);
  return DeepGITest::ExitStatus();
}
}

#endif
