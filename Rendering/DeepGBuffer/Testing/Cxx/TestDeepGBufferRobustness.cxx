// Bad input and the situations a VTK scene puts a render pass in. Each case
// checks numbers, not only that nothing crashed:
// - NaN, negative and huge dz; layer counts 0, 1, 4 and 100; PREDICT with
//   more than two layers: a warning and a safe value; the default oracle
//   AUTOMATIC peels on a CPU renderer and reprojects on a GPU;
// - an empty renderer; props added and removed between frames; a window
//   resized between frames; ReleaseGraphicsResources and render again;
// - parallel projection; two renderers in one window (non-origin viewport),
//   sharing one pass, each with its own history and its own lights;
// - meshes without normals, lines and wireframe (the per-layer path) and a
//   translucent prop drawn by VTK after the G-buffer.

#include "DeepGBufferTestUtilities.h"

#include "vtkCamera.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkLight.h"
#include "vtkLineSource.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"

#include <functional>

using namespace DeepGBufferTest;
using namespace DeepGITest;

namespace
{
vtkSmartPointer<vtkActor> MakeActor(vtkAlgorithm* source, double r, double g, double b)
{
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  return actor;
}

// A sphere of radius 1 at the origin in front of a wall at z = -2.
void AddSphereAndWall(vtkRenderer* renderer, bool normals = true)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);
  sphere->SetGenerateNormals(normals);
  vtkNew<vtkPlaneSource> wall;
  wall->SetOrigin(-3, -3, -2);
  wall->SetPoint1(3, -3, -2);
  wall->SetPoint2(-3, 3, -2);
  renderer->AddActor(MakeActor(sphere, 0.9, 0.2, 0.2));
  renderer->AddActor(MakeActor(wall, 0.2, 0.8, 0.2));
  renderer->GetActiveCamera()->SetPosition(0, 0, 8);
  renderer->GetActiveCamera()->SetFocalPoint(0, 0, 0);
  renderer->ResetCameraClippingRange();
}

long ValidCount(vtkImageData* capture, int layer)
{
  vtkDataArray* valid = Layer(capture, vtkDeepGICaptureNames::Valid, layer);
  long n = 0;
  for (vtkIdType p = 0; valid && p < valid->GetNumberOfTuples(); ++p)
  {
    n += valid->GetTuple1(p) != 0;
  }
  return n;
}

bool Separated(vtkImageData* capture, int layers, double dz)
{
  for (int j = 1; j < layers; ++j)
  {
    SeparationReport r = CheckSeparation(capture, j, dz, 1e-5);
    if (r.Violations)
    {
      std::printf("  layer %d: %ld of %ld pixels closer than dz\n", j, r.Violations, r.Pixels);
      return false;
    }
  }
  return true;
}

// Renders a small scene with `pass`, `frames` times, and captures it.
vtkSmartPointer<vtkImageData> RenderAndCapture(vtkDeepGBufferPass* pass,
  const std::function<void(vtkRenderer*)>& build, int frames = 2, int width = 200, int height = 150)
{
  auto window = MakeWindow(width, height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  build(renderer);
  renderer->SetPass(pass);
  for (int f = 0; f < frames; ++f)
  {
    window->Render();
  }
  auto capture = vtkSmartPointer<vtkImageData>::New();
  if (!pass->CaptureLayers(capture, renderer))
  {
    capture = nullptr;
  }
  pass->ReleaseGraphicsResources(window);
  return capture;
}

void TestParameters()
{
  vtkNew<vtkDeepGBufferPass> pass;
  EventCounter warnings(pass, vtkCommand::WarningEvent);
  pass->SetMinimumSeparation(std::nan(""));
  Check(warnings.Count == 1 && pass->GetAutomaticMinimumSeparation(),
    "NaN dz warns and keeps the automatic separation");
  pass->SetMinimumSeparation(-1.0);
  Check(warnings.Count == 2 && pass->GetMinimumSeparation() == 0.0,
    "negative dz warns and is clamped to 0");
  pass->SetNumberOfLayers(0);
  Check(warnings.Count == 3 && pass->GetNumberOfLayers() == 1, "0 layers warns, clamped to 1");
  pass->SetNumberOfLayers(100);
  Check(warnings.Count == 4 &&
      pass->GetNumberOfLayers() == vtkDeepGBufferPass::MAXIMUM_NUMBER_OF_LAYERS,
    "100 layers warns, clamped to the maximum");
  Check(vtkDeepGBufferPass::GetOracleFromString("reproject") == vtkDeepGBufferPass::REPROJECT &&
      vtkDeepGBufferPass::GetOracleFromString("depth-peel") == vtkDeepGBufferPass::DEPTH_PEEL &&
      vtkDeepGBufferPass::GetOracleFromString("automatic") == vtkDeepGBufferPass::AUTOMATIC &&
      vtkDeepGBufferPass::GetOracleFromString("nonsense") == -1 &&
      vtkDeepGBufferPass::GetOracleFromString(nullptr) == -1,
    "oracle names parse, unknown ones give -1");

  // A dz larger than the scene: warned once at render time, layer 1 empty.
  vtkNew<vtkDeepGBufferPass> huge;
  EventCounter hugeWarnings(huge, vtkCommand::WarningEvent);
  huge->SetMinimumSeparation(1e30);
  auto capture = RenderAndCapture(huge, [](vtkRenderer* r) { AddSphereAndWall(r); });
  Check(capture && hugeWarnings.Count == 1 && ValidCount(capture, 0) > 0 &&
      ValidCount(capture, 1) == 0 && AllFinite(capture),
    "huge dz warns once and leaves layer 1 empty");
}

void TestLayerCounts()
{
  for (int oracle : { vtkDeepGBufferPass::DEPTH_PEEL, vtkDeepGBufferPass::REPROJECT })
  {
    for (int layers : { 1, 4 })
    {
      vtkNew<vtkDeepGBufferPass> pass;
      pass->SetOracle(oracle);
      pass->SetNumberOfLayers(layers);
      pass->SetMinimumSeparation(0.25);
      pass->DeepLayerBackfaceCullingOff(); // the sphere's far side makes layer 2
      auto capture = RenderAndCapture(
        pass, [](vtkRenderer* r) { AddSphereAndWall(r); }, 3);
      const bool shape = capture && Layer(capture, vtkDeepGICaptureNames::Depth, layers - 1) &&
        !Layer(capture, vtkDeepGICaptureNames::Depth, layers) &&
        pass->GetEffectiveNumberOfLayers() == layers;
      std::string what = std::to_string(layers) + " layer(s) with " +
        vtkDeepGBufferPass::GetOracleAsString(oracle) + ": capture shape, separation";
      Check(shape && Separated(capture, layers, 0.25) && AllFinite(capture) &&
          (layers == 1 || ValidCount(capture, 2) > 0),
        what.c_str());
    }
  }
  vtkNew<vtkDeepGBufferPass> predict;
  EventCounter warnings(predict, vtkCommand::WarningEvent);
  predict->SetOracleToPredict();
  predict->SetNumberOfLayers(3);
  auto capture = RenderAndCapture(
    predict, [](vtkRenderer* r) { AddSphereAndWall(r); }, 3);
  Check(capture && warnings.Count == 1 &&
      predict->GetEffectiveOracle() == vtkDeepGBufferPass::REPROJECT,
    "PREDICT with 3 layers warns and uses REPROJECT");
}

// AUTOMATIC, the default oracle, peels on a CPU renderer (two geometry
// passes) and reprojects on a GPU (one).
void TestAutomaticOracle()
{
  auto window = MakeWindow(200, 150);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  AddSphereAndWall(renderer);
  vtkNew<vtkDeepGBufferPass> automatic;
  renderer->SetPass(automatic);
  for (int frame = 0; frame < 3; ++frame)
  {
    window->Render();
  }
  const std::string capabilities = window->ReportCapabilities();
  const bool cpu = capabilities.find("llvmpipe") != std::string::npos ||
    capabilities.find("softpipe") != std::string::npos;
  const int expected = cpu ? vtkDeepGBufferPass::DEPTH_PEEL : vtkDeepGBufferPass::REPROJECT;
  std::printf("  AUTOMATIC on %s renderer: %s, %d geometry pass(es)\n", cpu ? "a CPU" : "a GPU",
    vtkDeepGBufferPass::GetOracleAsString(automatic->GetEffectiveOracle()),
    automatic->GetLastGeometryPassCount());
  Check(automatic->GetOracle() == vtkDeepGBufferPass::AUTOMATIC &&
      automatic->GetEffectiveOracle() == expected &&
      automatic->GetLastGeometryPassCount() == (cpu ? 2 : 1),
    "AUTOMATIC is the default: DEPTH_PEEL on a CPU renderer, REPROJECT on a GPU");
  renderer->SetPass(nullptr);
  automatic->ReleaseGraphicsResources(window);
}

void TestEmptyAndChangingScenes()
{
  vtkNew<vtkDeepGBufferPass> pass;
  auto empty = RenderAndCapture(pass, [](vtkRenderer*) {});
  Check(empty && ValidCount(empty, 0) == 0 && ValidCount(empty, 1) == 0 && AllFinite(empty),
    "an empty renderer gives empty, finite layers");

  // Props added and removed, window resized, resources released in between.
  auto window = MakeWindow(200, 150);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  AddSphereAndWall(renderer);
  vtkNew<vtkDeepGBufferPass> reproject;
  reproject->SetOracleToReproject();
  renderer->SetPass(reproject);
  window->Render();
  window->Render();
  vtkNew<vtkSphereSource> extraSource;
  extraSource->SetCenter(1.5, 1.0, 1.0);
  extraSource->SetRadius(0.4);
  auto extra = MakeActor(extraSource, 0.2, 0.2, 0.9);
  renderer->AddActor(extra);
  window->Render();
  vtkNew<vtkImageData> withExtra;
  reproject->CaptureLayers(withExtra, renderer);
  renderer->RemoveActor(extra);
  window->SetSize(260, 180);
  window->Render();
  vtkNew<vtkImageData> resized;
  reproject->CaptureLayers(resized, renderer);
  int dims[3];
  resized->GetDimensions(dims);
  Check(ValidCount(withExtra, 0) > 0 && dims[0] == 260 && dims[1] == 180 &&
      reproject->GetEffectiveOracle() == vtkDeepGBufferPass::DEPTH_PEEL &&
      Separated(resized, 2, reproject->GetEffectiveMinimumSeparation()),
    "props added/removed and a resize: new size, history reset to DEPTH_PEEL, separation");
  window->Render();
  Check(reproject->GetEffectiveOracle() == vtkDeepGBufferPass::REPROJECT,
    "the frame after a resize uses REPROJECT again");
  reproject->ReleaseGraphicsResources(window);
  window->Render();
  vtkNew<vtkImageData> again;
  Check(reproject->CaptureLayers(again, renderer) && ValidCount(again, 0) > 0,
    "ReleaseGraphicsResources then Render works");
  reproject->ReleaseGraphicsResources(window);
}

void TestViewportsAndProjection()
{
  // Two renderers side by side share one pass; the right one is parallel.
  auto build = [](vtkRenderWindow* window, vtkRenderer* left, vtkRenderer* right)
  {
    left->SetViewport(0.0, 0.0, 0.5, 1.0);
    right->SetViewport(0.5, 0.0, 1.0, 1.0);
    window->AddRenderer(left);
    window->AddRenderer(right);
    AddSphereAndWall(left);
    AddSphereAndWall(right);
    right->GetActiveCamera()->ParallelProjectionOn();
    right->GetActiveCamera()->SetParallelScale(3.0);
    right->ResetCameraClippingRange();
  };
  auto plainWindow = MakeWindow(400, 160);
  vtkNew<vtkRenderer> plainLeft, plainRight;
  build(plainWindow, plainLeft, plainRight);
  plainWindow->Render();

  auto window = MakeWindow(400, 160);
  vtkNew<vtkRenderer> left, right;
  build(window, left, right);
  vtkNew<vtkDeepGBufferPass> pass;
  pass->SetMinimumSeparation(0.25);
  left->SetPass(pass);
  right->SetPass(pass);
  window->Render();
  window->Render();
  vtkNew<vtkImageData> a, b, rgbPass, rgbPlain;
  pass->CaptureLayers(a, left);
  pass->CaptureLayers(b, right);
  ReadWindow(window, rgbPass, nullptr);
  ReadWindow(plainWindow, rgbPlain, nullptr);
  const double maximum = MaximumColorDifference(rgbPass, rgbPlain);
  int dims[3];
  b->GetDimensions(dims);
  Check(maximum <= 1.0, "two viewports, perspective and parallel: image equals plain VTK's");
  Check(dims[0] == 200 && dims[1] == 160 && ValidCount(a, 1) > 0 && ValidCount(b, 1) > 0 &&
      Separated(a, 2, 0.25) && Separated(b, 2, 0.25),
    "each renderer has its own layers and separation");
  pass->ReleaseGraphicsResources(window);
}

// Two renderers with scene lights share the pass; the left one's camera
// turns. The right one's image must not change: VTK 9.1's shader programs
// are shared by the renderers and take a renderer's lights only when they
// are newer than their last upload, so plain VTK draws the right renderer
// with the left one's view-space lights here.
void TestRenderersKeepTheirLights()
{
  auto frame = [](bool usePass, bool turnLeft)
  {
    auto window = MakeWindow(200, 100);
    vtkNew<vtkRenderer> left, right;
    left->SetViewport(0.0, 0.0, 0.5, 1.0);
    right->SetViewport(0.5, 0.0, 1.0, 1.0);
    for (vtkRenderer* renderer : { left.Get(), right.Get() })
    {
      window->AddRenderer(renderer);
      AddSphereAndWall(renderer);
      vtkNew<vtkLight> light;
      light->SetLightTypeToSceneLight();
      light->PositionalOff();
      light->SetPosition(1.0, 2.0, 1.5);
      light->SetFocalPoint(0.0, 0.0, 0.0);
      renderer->AddLight(light);
    }
    vtkNew<vtkDeepGBufferPass> pass;
    if (usePass)
    {
      left->SetPass(pass);
      right->SetPass(pass);
    }
    for (int k = 0; k < 4; ++k)
    {
      if (k == 2 && turnLeft)
      {
        left->GetActiveCamera()->Azimuth(30.0);
        left->ResetCameraClippingRange();
      }
      window->Render();
    }
    vtkNew<vtkUnsignedCharArray> rgb;
    window->GetPixelData(100, 0, 199, 99, /*front=*/0, rgb);
    std::vector<int> pixels(rgb->GetPointer(0), rgb->GetPointer(0) + rgb->GetNumberOfValues());
    left->SetPass(nullptr);
    right->SetPass(nullptr);
    pass->ReleaseGraphicsResources(window);
    return pixels;
  };
  auto difference = [](const std::vector<int>& a, const std::vector<int>& b)
  {
    int maximum = a.size() == b.size() && !a.empty() ? 0 : 256;
    for (size_t i = 0; maximum < 256 && i < a.size(); ++i)
    {
      maximum = std::max(maximum, std::abs(a[i] - b[i]));
    }
    return maximum;
  };
  const int plain = difference(frame(false, false), frame(false, true));
  const int deep = difference(frame(true, false), frame(true, true));
  std::printf("right renderer after the left one's camera turned: %d/255 with the pass "
              "(plain VTK: %d/255)\n",
    deep, plain);
  Check(deep == 0, "a renderer sharing the pass is drawn with its own lights");
}

void TestMappersAndTranslucency()
{
  // No normals: the shader's geometric normal faces the camera.
  vtkNew<vtkDeepGBufferPass> pass;
  auto capture = RenderAndCapture(pass, [](vtkRenderer* r) { AddSphereAndWall(r, false); });
  vtkDataArray* normals = Layer(capture, vtkDeepGICaptureNames::Normal, 0);
  vtkDataArray* valid = Layer(capture, vtkDeepGICaptureNames::Valid, 0);
  long facing = 0, total = 0;
  for (vtkIdType p = 0; p < normals->GetNumberOfTuples(); ++p)
  {
    if (valid->GetTuple1(p))
    {
      ++total;
      facing += normals->GetComponent(p, 2) > 0.0;
    }
  }
  Check(total > 0 && facing == total, "meshes without normals get camera-facing normals");

  // Lines, wireframe and a translucent sphere.
  auto window = MakeWindow(200, 150);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  AddSphereAndWall(renderer);
  vtkNew<vtkLineSource> line;
  line->SetPoint1(-2.5, -1.5, 1.5);
  line->SetPoint2(2.5, -1.5, 1.5);
  auto lineActor = MakeActor(line, 1, 1, 1);
  lineActor->GetProperty()->SetLineWidth(1.0);
  renderer->AddActor(lineActor);
  vtkNew<vtkSphereSource> wireSource;
  wireSource->SetCenter(-1.8, 1.2, 0.5);
  wireSource->SetRadius(0.5);
  auto wire = MakeActor(wireSource, 1, 1, 0);
  wire->GetProperty()->SetRepresentationToWireframe();
  renderer->AddActor(wire);
  vtkNew<vtkSphereSource> glassSource;
  glassSource->SetCenter(1.5, 1.2, 1.5);
  glassSource->SetRadius(0.5);
  auto glass = MakeActor(glassSource, 0.2, 0.4, 1.0);
  glass->GetProperty()->SetOpacity(0.4);
  renderer->AddActor(glass);
  vtkNew<vtkDeepGBufferPass> mixed;
  mixed->SetOracleToReproject();
  mixed->SetMinimumSeparation(0.25);
  renderer->SetPass(mixed);
  window->Render();
  window->Render();
  vtkNew<vtkImageData> layers, rgb;
  mixed->CaptureLayers(layers, renderer);
  ReadWindow(window, rgb, nullptr);

  // The glass sphere's centre pixel: drawn (bluish) but absent from the
  // G-buffer, whose layer 0 there is the wall.
  double world[4] = { 1.5, 1.2, 2.0, 1.0 }, display[3];
  renderer->SetWorldPoint(world);
  renderer->WorldToDisplay();
  renderer->GetDisplayPoint(display);
  const vtkIdType pixel =
    static_cast<vtkIdType>(display[1]) * 200 + static_cast<vtkIdType>(display[0]);
  vtkDataArray* colour = rgb->GetPointData()->GetScalars();
  vtkDataArray* albedo = Layer(layers, vtkDeepGICaptureNames::Albedo, 0);
  vtkDataArray* radiance = Layer(layers, vtkDeepGICaptureNames::Radiance, 0);
  std::printf("  glass pixel: final blue %g, layer-0 blue %g, layer-0 albedo (%g %g %g)\n",
    colour->GetComponent(pixel, 2), 255.0 * radiance->GetComponent(pixel, 2),
    albedo->GetComponent(pixel, 0), albedo->GetComponent(pixel, 1), albedo->GetComponent(pixel, 2));
  Check(colour->GetComponent(pixel, 2) > 255.0 * radiance->GetComponent(pixel, 2) + 20.0 &&
      albedo->GetComponent(pixel, 1) > 0.7 && albedo->GetComponent(pixel, 2) < 0.3,
    "a translucent prop is drawn after the G-buffer and kept out of it");
  // One routed submission for the triangle meshes, one per layer for the rest.
  Check(mixed->GetLastGeometryPassCount() == 3 && Separated(layers, 2, 0.25) && AllFinite(layers),
    "lines and wireframe take the per-layer path; separation holds");
  mixed->ReleaseGraphicsResources(window);
}
}

int TestDeepGBufferRobustness(int, char*[])
{
  TestParameters();
  TestLayerCounts();
  TestAutomaticOracle();
  TestEmptyAndChangingScenes();
  TestViewportsAndProjection();
  TestRenderersKeepTheirLights();
  TestMappersAndTranslucency();
  return ExitStatus();
}
