// The guard band is bounded by what the frame needs
// (vtkDeepGBufferPass::ComputeGuardBandPixels):
// 1. At most MAXIMUM_GUARD_BAND of the frame's smaller side: an 8 x 4000
//    frame with a band of 0.5 of its height gets 8 pixels per side (layers
//    of 24 x 4016), not 2000 (4008 x 8000, 10 GB of layers); frames at
//    least as wide as tall keep round(fraction x height).
// 2. At most MAXIMUM_GUARD_BAND_PIXELS (1024) whatever the frame's size.
// 3. Rendered: a 16 x 600 window with a band of 0.5 has layers of
//    32 x 616 (8 pixels per side), and the pass warns once, in the first
//    frame, not again in later frames; a frame the limits do not touch
//    gives no warning.

#include "DeepGBufferTestUtilities.h"

#include <string>

using namespace DeepGBufferTest;
using namespace DeepGITest;

namespace
{
struct WarningRecorder
{
  int Count = 0;
  std::string Last;
  void OnWarning(vtkObject*, unsigned long, void* callData)
  {
    ++this->Count;
    this->Last = callData ? static_cast<const char*>(callData) : "";
  }
};

void CheckPixels()
{
  bool limited = false;
  Check(vtkDeepGBufferPass::ComputeGuardBandPixels(0.5, 8, 4000, 16384, &limited) == 8 && limited,
    "8 x 4000 with 0.5: 8 pixels per side (0.5 x the width, aligned), limited");
  Check(vtkDeepGBufferPass::ComputeGuardBandPixels(0.5, 4000, 8, 16384, &limited) == 8 && !limited,
    "4000 x 8 with 0.5: 4 pixels rounded up to 8, not limited");
  Check(
    vtkDeepGBufferPass::ComputeGuardBandPixels(0.1, 480, 640, 16384, &limited) == 64 && !limited,
    "a portrait frame with the default band is not limited");
  Check(
    vtkDeepGBufferPass::ComputeGuardBandPixels(0.5, 300, 640, 16384, &limited) == 152 && limited,
    "a portrait frame with 0.5: 0.5 x 300 = 150, aligned to 152");
  Check(vtkDeepGBufferPass::ComputeGuardBandPixels(0.5, 8192, 8192, 65536, &limited) ==
        vtkDeepGBufferPass::MAXIMUM_GUARD_BAND_PIXELS &&
      limited,
    "8192 x 8192 with 0.5: the absolute limit of 1024 pixels");
  Check(
    vtkDeepGBufferPass::ComputeGuardBandPixels(0.1, 1920, 1080, 16384, &limited) == 112 && !limited,
    "1920 x 1080 with 0.1: 112 pixels as before");
}

// Renders a lit quad in a width x height window with a band of `fraction`
// for `frames` frames; returns the layer size, the band and the warnings.
void RenderFrames(int width, int height, double fraction, int frames, int layerSize[2], int& guard,
  WarningRecorder& warnings)
{
  auto window = MakeWindow(width, height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  const double o[3] = { -2, -2, 0 }, p1[3] = { 2, -2, 0 }, p2[3] = { -2, 2, 0 };
  AddQuad(renderer, o, p1, p2);
  SetCamera(renderer, 0.3, 0.2, 5.0, 0.0, 0.0, 0.0);
  renderer->ResetCameraClippingRange();
  vtkNew<vtkDeepGBufferPass> pass;
  pass->AddObserver(vtkCommand::WarningEvent, &warnings, &WarningRecorder::OnWarning);
  pass->SetGuardBand(fraction);
  renderer->SetPass(pass);
  for (int k = 0; k < frames; ++k)
  {
    window->Render();
  }
  guard = -1;
  layerSize[0] = layerSize[1] = 0;
  pass->GetLayerExtent(renderer, layerSize, guard);
  renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(window);
}

void CheckRendered()
{
  int size[2] = { 0, 0 };
  int guard = -1;
  WarningRecorder tall;
  RenderFrames(16, 600, 0.5, 3, size, guard, tall);
  std::printf("16 x 600, band 0.5: layers %d x %d, %d pixels per side, %d warning(s): %s\n",
    size[0], size[1], guard, tall.Count, tall.Last.c_str());
  Check(guard == 8 && size[0] == 32 && size[1] == 616,
    "a tall, narrow frame gets 8 pixels per side (32 x 616), not 304 (624 x 1208)");
  Check(tall.Count == 1 && tall.Last.find("limited to 8 pixels") != std::string::npos,
    "one warning in three frames, naming the limit");

  WarningRecorder wide;
  RenderFrames(64, 48, 0.5, 2, size, guard, wide);
  Check(guard == 24 && size[0] == 112 && size[1] == 96 && wide.Count == 0,
    "64 x 48 with 0.5: 24 pixels per side as asked, no warning");
}
}

int TestDeepGuardBandLimits(int, char*[])
{
  CheckPixels();
  CheckRendered();
  return ExitStatus();
}
