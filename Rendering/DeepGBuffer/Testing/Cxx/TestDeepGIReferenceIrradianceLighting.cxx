// vtkDeepGIReferenceIrradiance's light model against VTK's own rendering:
// the demo scene with its two scene lights (a point light and a directional
// light) plus a headlight, a camera light and an attenuated spot light is
// rendered into a deep G-buffer; on every valid pixel of layers 0 and 1 the
// reference's DIRECT_RADIANCE (L_direct evaluated at the pixel's surface
// point from the scene's "Colors", the actors' Diffuse 0.9, the shading
// normal and the lights taken from the renderer) must equal the captured
// Radiance_j - Ambient_j (VTK's diffuse term; the scene has no specular).
// Tolerance per channel 3 % + 0.004: the scene's "Colors" are 8-bit
// roundings of the actors' double colours (up to 2 % on dark channels) and
// the radiance layer is RGBA16F; at least 99.5 % of the pixels must pass
// (measured: 99.98 % of layer 0, 99.97 % of layer 1; the few others lie on
// silhouettes, where the reconstructed point can land on another triangle).
// With only the scene lights (headlight and camera light left out) the match
// must break: the camera-attached lights are placed as VTK places them.

#include "DeepGBufferTestUtilities.h"

#include "vtkCamera.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIDemoScene.h"
#include "vtkDeepGIReferenceIrradiance.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"

#include <algorithm>
#include <vector>

using namespace DeepGBufferTest;
using namespace DeepGITest;

int TestDeepGIReferenceIrradianceLighting(int, char*[])
{
  auto window = MakeWindow(160, 120);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkDeepGIDemoScene> scene;
  scene->SetTargetNumberOfTriangles(20000);
  scene->Populate(renderer);
  scene->SetCameraToDefaultView(renderer->GetActiveCamera());

  vtkNew<vtkLight> headlight, cameraLight, spot;
  headlight->SetLightTypeToHeadlight();
  headlight->SetIntensity(0.25);
  cameraLight->SetLightTypeToCameraLight();
  cameraLight->SetPosition(1, 1, 1);
  cameraLight->SetFocalPoint(0, 0, 0);
  cameraLight->SetColor(0.6, 0.7, 1.0);
  cameraLight->SetIntensity(0.3);
  spot->SetLightTypeToSceneLight();
  spot->SetPositional(true);
  spot->SetPosition(-1.0, 2.5, 1.5);
  spot->SetFocalPoint(-0.5, 0.0, 0.0);
  spot->SetConeAngle(35);
  spot->SetExponent(2);
  spot->SetAttenuationValues(1.0, 0.1, 0.05);
  spot->SetColor(1.0, 0.5, 0.3);
  spot->SetIntensity(0.8);
  renderer->AddLight(headlight);
  renderer->AddLight(cameraLight);
  renderer->AddLight(spot);
  renderer->ResetCameraClippingRange();

  vtkNew<vtkDeepGBufferPass> pass;
  renderer->SetPass(pass);
  window->Render();
  vtkNew<vtkImageData> capture;
  Check(pass->CaptureLayers(capture, renderer), "capture");

  vtkNew<vtkDeepGIReferenceIrradiance> reference;
  reference->SetInputData(capture);
  reference->SetSceneData(scene->GetScenePolyData());
  Check(reference->GetDiffuseCoefficient() == 1.0, "the scene's own Diffuse is used");
  reference->SetLightsFromRenderer(renderer);
  reference->SetQuantityToDirectRadiance();
  Check(reference->GetNumberOfLights() == 5, "five lights from the renderer");

  for (int layer = 0; layer < 2; ++layer)
  {
    reference->SetLayer(layer);
    const std::string what = "layer " + std::to_string(layer);
    reference->Update();
    if (reference->GetOutput()->GetNumberOfPoints() == 0)
    {
      Check(false, what + ": update");
      continue;
    }
    vtkDataArray* direct = reference->GetOutput()->GetPointData()->GetArray("DirectRadiance");
    vtkDataArray* radiance = Layer(capture, vtkDeepGICaptureNames::Radiance, layer);
    vtkDataArray* ambient = Layer(capture, vtkDeepGICaptureNames::Ambient, layer);
    vtkDataArray* valid = Layer(capture, vtkDeepGICaptureNames::Valid, layer);
    long pixels = 0, passed = 0;
    std::vector<double> errors;
    double sumVTK = 0.0;
    for (vtkIdType p = 0; p < valid->GetNumberOfTuples(); ++p)
    {
      if (!valid->GetTuple1(p))
      {
        continue;
      }
      ++pixels;
      bool ok = true;
      double worst = 0.0;
      for (int c = 0; c < 3; ++c)
      {
        const double vtk = radiance->GetComponent(p, c) - ambient->GetComponent(p, c);
        const double ref = direct->GetComponent(p, c);
        const double difference = std::fabs(ref - vtk);
        ok = ok && difference <= 0.03 * std::fabs(vtk) + 0.004;
        worst = std::max(worst, difference);
        sumVTK += vtk;
      }
      passed += ok;
      errors.push_back(worst);
    }
    std::sort(errors.begin(), errors.end());
    const double median = errors.empty() ? 0.0 : errors[errors.size() / 2];
    const double p99 = errors.empty() ? 0.0 : errors[errors.size() * 99 / 100];
    std::printf("%s: %ld pixels, %ld within tolerance (%.2f %%), |L_ref - L_vtk| median %.5f, "
                "99th percentile %.5f, mean VTK direct radiance %.4f\n",
      what.c_str(), pixels, passed, pixels ? 100.0 * passed / pixels : 0.0, median, p99,
      pixels ? sumVTK / (3.0 * pixels) : 0.0);
    Check(pixels > 1000, what + ": enough valid pixels");
    Check(passed >= 0.995 * pixels, what + ": 99.5 % of the pixels match VTK's diffuse term");
    Check(sumVTK > 0.05 * 3 * pixels, what + ": the scene is lit");
  }
  // Light placement matters: without the lights that follow the camera the
  // match must break on many pixels.
  reference->RemoveAllLights();
  vtkCollectionSimpleIterator it;
  vtkLight* light;
  vtkLightCollection* lights = renderer->GetLights();
  for (lights->InitTraversal(it); (light = lights->GetNextLight(it));)
  {
    if (light->LightTypeIsSceneLight())
    {
      reference->AddLight(light);
    }
  }
  reference->SetLayer(0);
  reference->Update();
  {
    vtkDataArray* direct = reference->GetOutput()->GetPointData()->GetArray("DirectRadiance");
    vtkDataArray* radiance = Layer(capture, vtkDeepGICaptureNames::Radiance, 0);
    vtkDataArray* ambient = Layer(capture, vtkDeepGICaptureNames::Ambient, 0);
    vtkDataArray* valid = Layer(capture, vtkDeepGICaptureNames::Valid, 0);
    long pixels = 0, passed = 0;
    for (vtkIdType p = 0; p < valid->GetNumberOfTuples(); ++p)
    {
      if (!valid->GetTuple1(p))
      {
        continue;
      }
      ++pixels;
      bool ok = true;
      for (int c = 0; c < 3; ++c)
      {
        const double vtk = radiance->GetComponent(p, c) - ambient->GetComponent(p, c);
        ok = ok && std::fabs(direct->GetComponent(p, c) - vtk) <= 0.03 * std::fabs(vtk) + 0.004;
      }
      passed += ok;
    }
    std::printf("scene lights only: %ld of %ld pixels within tolerance\n", passed, pixels);
    Check(passed < 0.5 * pixels, "the camera-attached lights are needed for the match");
  }
  return ExitStatus();
}
