// Helpers of the vtkDeepRadiosityPass tests that compare with the ray-traced
// one-bounce irradiance (vtkDeepGIReferenceIrradiance): the demo scene and
// the Cornell box as renderers with their scene polydata, luminance arrays
// and the reference of a capture.
#ifndef DeepRadiosityReferenceTest_h
#define DeepRadiosityReferenceTest_h

#include "DeepGBufferTestUtilities.h"

#include "vtkDeepGBufferPass.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIDemoScene.h"
#include "vtkDeepGIReferenceIrradiance.h"
#include "vtkDeepGISceneLoader.h"
#include "vtkDeepRadiosityPass.h"

#include <limits>
#include <string>
#include <vector>

namespace DeepRadiosityReferenceTest
{
using namespace DeepGBufferTest;

// Populates `renderer` with the demo scene (default view) or the Cornell box
// (cornell-original under `data`); returns the scene's triangles with their
// "Colors" and "Diffuse" for the reference, null on failure. `keep` owns the
// scene object.
inline vtkSmartPointer<vtkPolyData> PopulateScene(const std::string& name, const std::string& data,
  vtkRenderer* renderer, vtkSmartPointer<vtkObject>& keep)
{
  if (name == "demo")
  {
    auto demo = vtkSmartPointer<vtkDeepGIDemoScene>::New();
    demo->SetTargetNumberOfTriangles(20000);
    demo->Populate(renderer);
    demo->SetCameraToDefaultView(renderer->GetActiveCamera());
    renderer->ResetCameraClippingRange();
    keep = demo;
    return demo->GetScenePolyData();
  }
  auto loader = vtkSmartPointer<vtkDeepGISceneLoader>::New();
  if (!loader->Load((data + "/scenes/cornell-original/CornellBox-Original.obj").c_str()))
  {
    return nullptr;
  }
  loader->Populate(renderer);
  loader->ResetCamera(renderer);
  keep = loader;
  return loader->GetScenePolyData();
}

// Luminance (0.2126, 0.7152, 0.0722) of the RGB array `name` per pixel.
inline std::vector<double> Luminance(vtkImageData* image, const std::string& name)
{
  vtkDataArray* a = image->GetPointData()->GetArray(name.c_str());
  std::vector<double> lum(a->GetNumberOfTuples());
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    lum[i] = 0.2126 * a->GetComponent(i, 0) + 0.7152 * a->GetComponent(i, 1) +
      0.0722 * a->GetComponent(i, 2);
  }
  return lum;
}

// Layer 0's one-bounce irradiance luminance of `layers` (a CaptureLayers
// image) from the lights of `renderer`, gathering only within `maximumDistance`.
inline std::vector<double> ReferenceIrradiance(vtkPolyData* scene, vtkRenderer* renderer,
  vtkImageData* layers, double maximumDistance, int samples, double& standardError)
{
  vtkNew<vtkDeepGIReferenceIrradiance> reference;
  reference->SetInputData(layers);
  reference->SetSceneData(scene);
  reference->SetLightsFromRenderer(renderer);
  reference->SetSamplesPerPixel(samples);
  reference->SetMaximumDistance(maximumDistance);
  reference->SetLayer(0);
  reference->Update();
  if (reference->GetOutput()->GetNumberOfPoints() == 0)
  {
    DeepGITest::Check(false, "reference computed");
    return {};
  }
  standardError = reference->GetMeanStandardError();
  return Luminance(reference->GetOutput(), "IndirectIrradiance");
}

// One single-bounce frame of a vtkDeepRadiosityPass against the ray-traced
// one-bounce irradiance of the whole scene (no distance limit, 32 rays per
// pixel), layer 0: the luminance of E after the filter and of E_ref per
// pixel, and which pixels are valid.
struct SingleBounceCapture
{
  vtkNew<vtkImageData> Radiosity; // CaptureIrradiance
  vtkNew<vtkImageData> Layers;    // the G-buffer's CaptureLayers
  std::vector<double> Irradiance, Reference;
  vtkDataArray* Valid = nullptr;
  double StandardError = 0.0;
};

// Renders scene `name` (see PopulateScene) at width x height through `pass`,
// which keeps its settings but Damping 0 and TemporalAlpha 0, and fills `c`;
// false (with a failed check) when the scene does not load or a capture
// fails.
inline bool CaptureSingleBounce(const std::string& name, const std::string& data,
  vtkDeepRadiosityPass* pass, int width, int height, SingleBounceCapture& c)
{
  auto window = MakeWindow(width, height);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0, 0, 0);
  window->AddRenderer(renderer);
  vtkSmartPointer<vtkObject> keep;
  vtkSmartPointer<vtkPolyData> scene = PopulateScene(name, data, renderer, keep);
  if (!scene)
  {
    DeepGITest::Check(false, name + " loaded");
    return false;
  }
  pass->SetDamping(0.0);
  pass->SetTemporalAlpha(0.0);
  renderer->SetPass(pass);
  window->Render();
  if (!pass->CaptureIrradiance(c.Radiosity, renderer) ||
    !pass->GetGBufferPass()->CaptureLayers(c.Layers, renderer))
  {
    DeepGITest::Check(false, name + " captured");
    return false;
  }
  c.Reference = ReferenceIrradiance(
    scene, renderer, c.Layers, std::numeric_limits<double>::infinity(), 32, c.StandardError);
  c.Irradiance =
    Luminance(c.Radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Irradiance, 0));
  c.Valid = c.Layers->GetPointData()->GetArray(
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 0).c_str());
  const bool ok = c.Valid && c.Reference.size() == c.Irradiance.size();
  pass->ReleaseGraphicsResources(window);
  return ok;
}
}

#endif
