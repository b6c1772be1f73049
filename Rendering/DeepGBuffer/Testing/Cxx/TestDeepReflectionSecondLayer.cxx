// Paper Figure 13: the second layer lets a mirror reflect what the camera
// cannot see. A mirror floor, a red box hidden from the camera behind a
// grey panel that leaves a gap above the floor, so the box is visible in
// the mirror through the gap. With two layers the reflection rays that
// reach the box hit layer 1 (the box behind the panel) and return its
// colour; with one layer the same rays find nothing and fall back to the
// background. 200 x 150 px.

#include "DeepReflectionTestUtilities.h"

#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepReflectionPass.h"

using namespace DeepGBufferTest;
using namespace DeepReflectionTest;
using namespace DeepGITest;

namespace
{
bool IsRed(vtkDataArray* rgb, vtkIdType p, double tolerance)
{
  return std::abs(rgb->GetComponent(p, 0) - 1.0) < tolerance &&
    std::abs(rgb->GetComponent(p, 1)) < tolerance && std::abs(rgb->GetComponent(p, 2)) < tolerance;
}
}

int TestDeepReflectionSecondLayer(int, char*[])
{
  auto window = MakeWindow(200, 150);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.0, 0.0, 1.0);
  window->AddRenderer(renderer);

  MakeMirror(AddQuad(renderer, { -10, 0, 10 }, { 10, 0, 10 }, { -10, 0, -10 }));
  // The panel: x in [-2, 2], y in [0.5, 3] at z = 0, facing the camera.
  MakeConstant(AddQuad(renderer, { -2, 0.5, 0 }, { 2, 0.5, 0 }, { -2, 3, 0 }), 0.5, 0.5, 0.5);
  vtkNew<vtkCubeSource> box;
  box->SetCenter(0.0, 1.0, -2.0);
  MakeConstant(AddSourceActor(renderer, box), 1.0, 0.0, 0.0);

  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 3.0, 8.0);
  camera->SetFocalPoint(0.0, 0.5, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(40.0);
  renderer->ResetCameraClippingRange();

  vtkNew<vtkDeepReflectionPass> pass;
  pass->GetGBufferPass()->SetOracleToDepthPeel(); // exact layers on the first frame
  renderer->SetPass(pass);
  window->Render();

  // The scene does what it should: the box is hidden in layer 0, present in layer 1.
  vtkNew<vtkImageData> layers;
  pass->GetGBufferPass()->CaptureLayers(layers, renderer);
  long redLayer0 = 0, redLayer1 = 0;
  for (vtkIdType p = 0; p < layers->GetNumberOfPoints(); ++p)
  {
    redLayer0 += IsRed(Layer(layers, vtkDeepGICaptureNames::Radiance, 0), p, 0.02) ? 1 : 0;
    redLayer1 += IsRed(Layer(layers, vtkDeepGICaptureNames::Radiance, 1), p, 0.02) &&
        Layer(layers, vtkDeepGICaptureNames::Valid, 1)->GetTuple1(p)
      ? 1
      : 0;
  }
  std::printf("red pixels: layer 0 %ld, layer 1 %ld\n", redLayer0, redLayer1);
  Check(redLayer0 == 0 && redLayer1 > 100, "the box is hidden in layer 0 and seen in layer 1");

  vtkNew<vtkImageData> two;
  pass->CaptureReflections(two, renderer);
  Check(AllFinite(two), "reflection capture is finite");
  vtkDataArray* hitLayer = two->GetPointData()->GetArray(vtkDeepGICaptureNames::HitLayer);
  vtkDataArray* radiance = two->GetPointData()->GetArray(vtkDeepGICaptureNames::ReflectedRadiance);
  std::vector<vtkIdType> boxPixels;
  long redOtherLayer = 0;
  for (vtkIdType p = 0; p < two->GetNumberOfPoints(); ++p)
  {
    if (IsRed(radiance, p, 0.02))
    {
      if (hitLayer->GetTuple1(p) == 1.0)
      {
        boxPixels.push_back(p);
      }
      else
      {
        ++redOtherLayer;
      }
    }
  }
  std::printf("two layers: %zu mirror pixels reflect the box from layer 1, %ld red elsewhere\n",
    boxPixels.size(), redOtherLayer);
  Check(boxPixels.size() >= 50, "the hidden box is reflected, found in layer 1 (>= 50 pixels)");
  Check(redOtherLayer == 0, "no red reflection comes from another layer or the environment");

  // One layer: the same rays pass behind the panel and miss.
  pass->GetGBufferPass()->SetNumberOfLayers(1);
  window->Render();
  vtkNew<vtkImageData> one;
  pass->CaptureReflections(one, renderer);
  hitLayer = one->GetPointData()->GetArray(vtkDeepGICaptureNames::HitLayer);
  radiance = one->GetPointData()->GetArray(vtkDeepGICaptureNames::ReflectedRadiance);
  long stillRed = 0, background = 0;
  for (vtkIdType p : boxPixels)
  {
    stillRed += IsRed(radiance, p, 0.1) ? 1 : 0;
    background += hitLayer->GetTuple1(p) == -1.0 &&
        std::abs(radiance->GetComponent(p, 2) - 1.0) < 1e-3 && radiance->GetComponent(p, 0) < 1e-3
      ? 1
      : 0;
  }
  std::printf(
    "one layer: of those pixels %ld red, %ld show the background\n", stillRed, background);
  Check(stillRed == 0, "without layer 1 the box is not reflected");
  Check(background == static_cast<long>(boxPixels.size()),
    "without layer 1 those rays fall back to the background colour");

  pass->ReleaseGraphicsResources(window);
  return ExitStatus();
}
