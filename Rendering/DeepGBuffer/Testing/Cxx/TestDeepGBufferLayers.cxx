// Exact properties of the deep G-buffer at a still camera, on the demo
// scene and on the Cornell box whose coincident duplicate faces are the case
// minimum separation exists for (paper section 2):
// - layer 0 (image and depth) is what VTK draws without the pass;
// - no captured value is NaN or Inf;
// - every valid layer-1 pixel lies at least dz behind layer 0;
// - PREVIOUS, REPROJECT, PREDICT and DELAY give DEPTH_PEEL's layers 0 and 1
//   (same valid mask, depth within a relative 1e-5: the geometry shader path
//   interpolates gl_FragCoord.w in a different order);
// - with dz = 0 the Cornell box's duplicate faces come back in layer 1,
//   with dz > 0 they do not.

#include "DeepGBufferTestUtilities.h"
#include "DeepGITestData.h"

#include "vtkCamera.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIDemoScene.h"
#include "vtkDeepGISceneLoader.h"
#include "vtkFloatArray.h"
#include "vtkLight.h"

#include <functional>

using namespace DeepGBufferTest;
using namespace DeepGITest;

namespace
{
constexpr int Width = 320;
constexpr int Height = 240;
constexpr double EquivalenceTolerance = 1e-5;

using SceneBuilder = std::function<bool(vtkRenderWindow*, vtkRenderer*)>;

// Renders `frames` frames of a still camera and captures the layers.
// Returns the window so that callers can read its framebuffer.
vtkSmartPointer<vtkRenderWindow> RenderScene(
  const SceneBuilder& build, vtkDeepGBufferPass* pass, vtkImageData* capture, int frames = 3)
{
  auto window = MakeWindow(Width, Height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  if (!build(window, renderer))
  {
    return nullptr;
  }
  if (pass)
  {
    renderer->SetPass(pass);
  }
  for (int f = 0; f < frames; ++f)
  {
    window->Render();
  }
  if (pass && capture && !pass->CaptureLayers(capture, renderer))
  {
    return nullptr;
  }
  return window;
}

void CheckLayerZeroMatchesPlainVTK(const SceneBuilder& build, const char* name)
{
  vtkNew<vtkDeepGBufferPass> pass;
  auto withPass = RenderScene(build, pass, nullptr);
  auto plain = RenderScene(build, nullptr, nullptr);
  vtkNew<vtkImageData> rgbPass, rgbPlain, depthPass, depthPlain;
  ReadWindow(withPass, rgbPass, depthPass);
  ReadWindow(plain, rgbPlain, depthPlain);
  vtkDataArray* a = rgbPass->GetPointData()->GetScalars();
  vtkDataArray* b = rgbPlain->GetPointData()->GetScalars();
  vtkDataArray* za = depthPass->GetPointData()->GetScalars();
  vtkDataArray* zb = depthPlain->GetPointData()->GetScalars();
  double maxColor = 0.0, maxDepth = 0.0;
  long colorDiffs = 0;
  for (vtkIdType p = 0; p < a->GetNumberOfTuples(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      double d = std::abs(a->GetComponent(p, c) - b->GetComponent(p, c));
      maxColor = std::max(maxColor, d);
      colorDiffs += d > 0 ? 1 : 0;
    }
    maxDepth = std::max(maxDepth, std::abs(za->GetTuple1(p) - zb->GetTuple1(p)));
  }
  pass->ReleaseGraphicsResources(withPass);
  // Radiance is stored as RGBA16F (11-bit mantissa): at most one 8-bit
  // level. Depth goes through a 32-bit float texture into the window's
  // 24-bit depth buffer, and the geometry shader path interpolates it in a
  // different order: a few 24-bit levels (2^-24 = 6e-8 each).
  const double depthTolerance = 4.0 / (1 << 24);
  Check(maxColor <= 1.0,
    Format("%s: layer 0 colour is what VTK draws (max difference %g of 255, in %ld channels)", name,
      maxColor, colorDiffs));
  Check(maxDepth <= depthTolerance,
    Format("%s: layer 0 depth is what VTK draws (max difference %g <= %g)", name, maxDepth,
      depthTolerance));
}

// Every oracle builds the layers DEPTH_PEEL builds, in the number of
// geometry passes it promises.
void CheckOraclesMatchDepthPeeling(const SceneBuilder& build, const char* name, double dz)
{
  vtkNew<vtkImageData> reference;
  vtkNew<vtkDeepGBufferPass> peel;
  peel->SetOracleToDepthPeel();
  peel->SetMinimumSeparation(dz);
  auto peelWindow = RenderScene(build, peel, reference);
  if (!Check(peelWindow != nullptr, Format("%s: the scene is built and captured", name)))
  {
    return;
  }
  peel->ReleaseGraphicsResources(peelWindow);

  for (int oracle = vtkDeepGBufferPass::DEPTH_PEEL; oracle <= vtkDeepGBufferPass::DELAY; ++oracle)
  {
    vtkNew<vtkDeepGBufferPass> pass;
    pass->SetOracle(oracle);
    pass->SetMinimumSeparation(dz);
    vtkNew<vtkImageData> capture;
    auto window = RenderScene(build, pass, capture);
    const char* oracleName = vtkDeepGBufferPass::GetOracleAsString(oracle);
    if (!Check(window != nullptr, Format("%s/%s: captured", name, oracleName)))
    {
      continue;
    }
    const int geometryPasses = pass->GetLastGeometryPassCount();
    const int effectiveOracle = pass->GetEffectiveOracle();
    pass->ReleaseGraphicsResources(window);

    SeparationReport separation = CheckSeparation(capture, 1, dz, 1e-6);
    LayerDifference layer0 = CompareLayer(capture, reference, 0, EquivalenceTolerance);
    LayerDifference layer1 = CompareLayer(capture, reference, 1, EquivalenceTolerance, nullptr, dz);
    std::printf("%s/%s: %d geometry pass(es), layer 1: %ld px, separation violations %ld "
                "(worst excess over dz %g), vs DEPTH_PEEL: layer 0 %ld / layer 1 %ld of %ld px "
                "differ (mask %ld, depth %ld, rounding ties %ld)\n",
      name, oracleName, geometryPasses, separation.Pixels, separation.Violations,
      separation.WorstExcess, layer0.Different(), layer1.Different(), layer1.Compared,
      layer1.MaskMismatches, layer1.DepthMismatches, layer1.Ties);
    const bool singlePass = oracle != vtkDeepGBufferPass::DEPTH_PEEL;
    const std::string what = std::string(name) + "/" + oracleName;
    Check(AllFinite(capture), what + ": the layers are finite");
    Check(separation.Violations == 0, what + ": layer 1 at least dz behind layer 0");
    Check(separation.Pixels >= Width * Height / 20, what + ": layer 1 covers >= 5 % of the view");
    Check(layer0.Different() == 0 && layer1.Different() == 0,
      what + ": layers 0 and 1 equal DEPTH_PEEL's");
    Check(effectiveOracle == oracle, what + ": the oracle asked for is used");
    Check(geometryPasses == (singlePass ? 1 : 2),
      Format("%s: %d geometry pass(es)", what.c_str(), singlePass ? 1 : 2));
  }
}

// Pixels of layer 1 that repeat layer 0's surface (depth within 1e-4).
long DuplicatePixels(vtkImageData* capture)
{
  vtkDataArray* d0 = Layer(capture, vtkDeepGICaptureNames::Depth, 0);
  vtkDataArray* d1 = Layer(capture, vtkDeepGICaptureNames::Depth, 1);
  vtkDataArray* v1 = Layer(capture, vtkDeepGICaptureNames::Valid, 1);
  long count = 0;
  for (vtkIdType p = 0; p < d1->GetNumberOfTuples(); ++p)
  {
    if (v1->GetTuple1(p) &&
      std::abs(d1->GetTuple1(p) - d0->GetTuple1(p)) <= 1e-4 * d1->GetTuple1(p))
    {
      ++count;
    }
  }
  return count;
}

// Minimum separation is what keeps the duplicate faces out of layer 1.
void CheckSeparationRemovesDuplicateFaces(const SceneBuilder& cornell)
{
  for (double dz : { 0.0, 0.05 })
  {
    vtkNew<vtkDeepGBufferPass> pass;
    pass->SetOracleToDepthPeel();
    pass->SetMinimumSeparation(dz);
    vtkNew<vtkImageData> capture;
    auto window = RenderScene(cornell, pass, capture);
    if (!Check(window != nullptr, Format("cornell-original, dz = %g: captured", dz)))
    {
      return;
    }
    pass->ReleaseGraphicsResources(window);
    long duplicates = DuplicatePixels(capture);
    Check((dz == 0.0) == (duplicates > 0),
      Format("cornell-original, dz = %g: %ld layer-1 pixels repeat layer 0's surface "
             "(duplicates only without minimum separation)",
        dz, duplicates));
  }
}
}

int TestDeepGBufferLayers(int argc, char* argv[])
{
  const std::string data = DeepGITestData::Folder(argc, argv, "TestDeepGBufferLayers");
  if (!DeepGITestData::Require(data,
        { "scenes/cornell-original/CornellBox-Original.obj",
          "scenes/cornell-original/CornellBox-Original.mtl" },
        "TestDeepGBufferLayers"))
  {
    return EXIT_FAILURE;
  }

  SceneBuilder demo = [](vtkRenderWindow*, vtkRenderer* renderer)
  {
    AddDemoScene(renderer);
    return true;
  };
  SceneBuilder cornell = [data](vtkRenderWindow*, vtkRenderer* renderer)
  {
    vtkNew<vtkDeepGISceneLoader> loader;
    if (!loader->Load((data + "/scenes/cornell-original/CornellBox-Original.obj").c_str()) ||
      loader->Populate(renderer) == 0)
    {
      return false;
    }
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(0.0, 1.0, 3.9);
    camera->SetFocalPoint(0.0, 1.0, 0.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetViewAngle(40.0);
    renderer->ResetCameraClippingRange();
    return true;
  };

  CheckLayerZeroMatchesPlainVTK(demo, "demo");
  CheckOraclesMatchDepthPeeling(demo, "demo", 0.15);
  CheckLayerZeroMatchesPlainVTK(cornell, "cornell-original");
  CheckOraclesMatchDepthPeeling(cornell, "cornell-original", 0.05);
  CheckSeparationRemovesDuplicateFaces(cornell);
  return ExitStatus();
}
