// Regression image of vtkDeepAmbientObscurancePass on the demo scene
// (20k triangles, default view, automatic radius, N = 16): left the
// AO-composited image, right the ambient visibility (see
// DeepAmbientObscuranceImageTest.h).
// Threshold 0.5, as for TestDeepGBufferDemoImage: VTK's metric sums
// per-pixel excesses over 105 of 255, so 0.5 allows a handful of edge pixels
// to differ after an llvmpipe or driver update while any visible change of
// the AO (a brighter or darker region) fails. The numeric checks on the
// captured AV carry the exact expectations: the ranges below are the values
// measured when the baseline was made (default estimator SOLID_ANGLE: mean
// 0.917, unoccluded fraction 0.401, dark fraction 0.168) with margins of about 0.03 for the mean
// and a third of the fractions, wide enough for another rasteriser and narrow enough to catch an AV
// that is all 1 or all dark.

#include "DeepAmbientObscuranceImageTest.h"

int TestDeepAmbientObscuranceDemoImage(int argc, char* argv[])
{
  return DeepGBufferTest::RunAOImageTest(
    argc, argv, [](vtkRenderer* renderer) { return DeepGBufferTest::AddDemoScene(renderer); },
    [](vtkDeepAmbientObscurancePass*) {}, { 0.887, 0.947, 0.27, 0.11 }, 0.5);
}
