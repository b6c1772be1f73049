// Regression image of vtkDeepReflectionPass in the demo room: the floor is
// a 40 % Phong mirror (Specular 0.4, white SpecularColor) and the sphere a
// smooth PBR metal (metallic 1, roughness 0.1, its albedo as base colour),
// so both material mappings show. Before the image comparison the capture
// is checked numerically (VTK 9.1's image metric is a sum that lets many
// slightly wrong pixels pass): rays on at least 20 % of the pixels, at
// least half of them hitting the room, all values finite.
// Threshold 0.5: the image must match the baseline almost exactly (VTK's
// metric sums per-pixel excesses over 105 of 255; 0.5 allows a handful of
// edge pixels to differ after llvmpipe or driver updates). 300 x 225 px.

#include "DeepGBufferTestUtilities.h"

#include "vtkActorCollection.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIDemoScene.h"
#include "vtkDeepReflectionPass.h"
#include "vtkRegressionTestImage.h"

using namespace DeepGBufferTest;
using namespace DeepGITest;

int TestDeepReflectionDemoImage(int argc, char* argv[])
{
  auto window = MakeWindow(300, 225);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.1, 0.15);
  window->AddRenderer(renderer);
  vtkNew<vtkDeepGIDemoScene> scene;
  scene->SetTargetNumberOfTriangles(20000);
  scene->Populate(renderer);
  scene->SetCameraToDefaultView(renderer->GetActiveCamera());
  renderer->ResetCameraClippingRange();

  // Actors are added per material in material order; find them by colour.
  double floorColor[3], sphereColor[3];
  for (int m = 0; m < scene->GetNumberOfMaterials(); ++m)
  {
    const std::string name = scene->GetMaterialName(m);
    if (name == "floor")
    {
      scene->GetMaterialColor(m, floorColor);
    }
    else if (name == "sphere")
    {
      scene->GetMaterialColor(m, sphereColor);
    }
  }
  auto same = [](const double* a, const double* b)
  { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; };
  int changed = 0;
  vtkActorCollection* actors = renderer->GetActors();
  actors->InitTraversal();
  while (vtkActor* actor = actors->GetNextActor())
  {
    vtkProperty* p = actor->GetProperty();
    if (same(p->GetDiffuseColor(), floorColor))
    {
      p->SetSpecular(0.4);
      p->SetSpecularColor(1.0, 1.0, 1.0);
      ++changed;
    }
    else if (same(p->GetDiffuseColor(), sphereColor))
    {
      p->SetInterpolationToPBR();
      p->SetMetallic(1.0);
      p->SetRoughness(0.1);
      ++changed;
    }
  }
  Check(changed == 2, "floor and sphere found");

  vtkNew<vtkDeepReflectionPass> pass;
  renderer->SetPass(pass);
  for (int frame = 0; frame < 3; ++frame)
  {
    window->Render();
  }
  vtkNew<vtkImageData> capture;
  pass->CaptureReflections(capture, renderer);
  long traced = 0, hits = 0;
  vtkDataArray* valid = capture->GetPointData()->GetArray(vtkDeepGICaptureNames::Valid);
  vtkDataArray* layer = capture->GetPointData()->GetArray(vtkDeepGICaptureNames::HitLayer);
  for (vtkIdType p = 0; p < valid->GetNumberOfTuples(); ++p)
  {
    traced += valid->GetTuple1(p) ? 1 : 0;
    hits += valid->GetTuple1(p) && layer->GetTuple1(p) >= 0.0 ? 1 : 0;
  }
  std::printf("%ld traced pixels, %ld hits\n", traced, hits);
  Check(AllFinite(capture), "reflection capture is finite");
  Check(
    traced >= 0.2 * 300 * 225 && hits >= traced / 2, "the floor and the sphere reflect the room");

  CheckRegressionImage(argc, argv, window, 0.5);
  pass->ReleaseGraphicsResources(window);
  return ExitStatus();
}
