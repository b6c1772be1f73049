// Regression image of the demo scene: the lit image and layer 1, where the
// banners appear behind the columns and the wall behind the thin panel.
// Threshold 0.5: the images must match the baseline almost exactly (VTK's
// metric sums per-pixel excesses over 105 of 255; 0.5 allows a handful of
// pixels on edges to differ after llvmpipe or driver updates).

#include "DeepGBufferImageTest.h"

int TestDeepGBufferDemoImage(int argc, char* argv[])
{
  return DeepGBufferTest::RunLayerImageTest(
    argc, argv, [](vtkRenderer* renderer) { return DeepGBufferTest::AddDemoScene(renderer); }, 0.15,
    10000, 0.5);
}
