// Regression images of vtkDeepAmbientObscurancePass: one 800 x 300 window,
// two 400 x 300 viewports. Left: the AO-composited image (the pass on the
// renderer, composition set explicitly to COMPOSITE_MULTIPLY so that a
// change of the default does not change the baseline). Right: the filtered
// ambient visibility itself, captured from the left renderer and shown as a
// grey image (AV x 255, nearest-neighbour) by a vtkImageActor, so the AV is
// part of the baseline independently of the lit colours.
//
// Before the image comparison the captured AV is checked numerically (VTK
// 9.1's image threshold is a sum of large per-pixel excesses, see
// VTK91-NOTES.md): finite, in [0, 1], 1 exactly on empty pixels, a mean over
// the surface pixels inside a stated range, a stated fraction of surface
// pixels unoccluded (AV > 0.999) and darkened (AV < 0.8), and the AV shown
// on the right equals the AV of the final frame (1e-6: still camera).
#ifndef DeepAmbientObscuranceImageTest_h
#define DeepAmbientObscuranceImageTest_h

#include "DeepGBufferTestUtilities.h"

#include "vtkCamera.h"
#include "vtkDeepAmbientObscurancePass.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkImageActor.h"
#include "vtkImageProperty.h"
#include "vtkRegressionTestImage.h"

#include <algorithm>
#include <functional>

namespace DeepGBufferTest
{
struct AVExpectations
{
  double MeanMin, MeanMax; // mean filtered AV over surface pixels
  double UnoccludedMin;    // fraction of surface pixels with AV > 0.999
  double DarkMin;          // fraction of surface pixels with AV < 0.8
};

// `build` fills the renderer and sets its camera; `configure` sets the pass.
inline int RunAOImageTest(int argc, char* argv[], const std::function<bool(vtkRenderer*)>& build,
  const std::function<void(vtkDeepAmbientObscurancePass*)>& configure, const AVExpectations& e,
  double threshold)
{
  constexpr int W = 400, H = 300;
  auto window = MakeWindow(2 * W, H);
  vtkNew<vtkRenderer> lit, avView;
  lit->SetViewport(0.0, 0.0, 0.5, 1.0);
  avView->SetViewport(0.5, 0.0, 1.0, 1.0);
  lit->SetBackground(0.1, 0.1, 0.15);
  avView->SetBackground(0.1, 0.1, 0.15);
  window->AddRenderer(lit);
  window->AddRenderer(avView);
  if (!build(lit))
  {
    return EXIT_FAILURE;
  }
  vtkNew<vtkDeepAmbientObscurancePass> pass;
  pass->SetComposition(vtkDeepAmbientObscurancePass::COMPOSITE_MULTIPLY);
  configure(pass);
  lit->SetPass(pass);

  // The AV viewport: image pixel (i, j) at viewport pixel (i, j), black
  // until the first AV is captured.
  vtkSmartPointer<vtkImageData> grey = ShowImagePixelForPixel(avView, W, H, 1);

  for (int frame = 0; frame < 3; ++frame)
  {
    window->Render();
  }
  vtkNew<vtkImageData> shown, av;
  bool ok = pass->CaptureAmbientVisibility(shown, lit);
  if (ok)
  {
    ShowValues(
      shown->GetPointData()->GetArray(vtkDeepGICaptureNames::AmbientVisibility), 1.0, grey);
    window->Render();
    ok = pass->CaptureAmbientVisibility(av, lit);
  }
  if (!DeepGITest::Check(ok, "ambient visibility captured"))
  {
    return EXIT_FAILURE;
  }

  vtkDataArray* a = av->GetPointData()->GetArray(vtkDeepGICaptureNames::AmbientVisibility);
  vtkDataArray* raw = av->GetPointData()->GetArray(vtkDeepGICaptureNames::RawAmbientVisibility);
  vtkDataArray* valid = av->GetPointData()->GetArray(vtkDeepGICaptureNames::Valid);
  vtkDataArray* before = shown->GetPointData()->GetArray(vtkDeepGICaptureNames::AmbientVisibility);
  long surface = 0, unoccluded = 0, dark = 0, outOfRange = 0, emptyNotOne = 0;
  double sum = 0.0, changed = 0.0;
  for (vtkIdType p = 0; p < a->GetNumberOfTuples(); ++p)
  {
    const double v = a->GetTuple1(p), r = raw->GetTuple1(p);
    outOfRange += (v < 0.0 || v > 1.0 || r < 0.0 || r > 1.0) ? 1 : 0;
    changed = std::max(changed, std::abs(v - before->GetTuple1(p)));
    if (valid->GetTuple1(p) == 0)
    {
      emptyNotOne += (v != 1.0 || r != 1.0) ? 1 : 0;
      continue;
    }
    ++surface;
    sum += v;
    unoccluded += v > 0.999 ? 1 : 0;
    dark += v < 0.8 ? 1 : 0;
  }
  const double mean = sum / std::max(surface, 1L);
  const double fu = static_cast<double>(unoccluded) / std::max(surface, 1L);
  const double fd = static_cast<double>(dark) / std::max(surface, 1L);
  std::printf("AV: radius %.4g, N %d\n", pass->GetEffectiveRadius(), pass->GetNumberOfSamples());
  DeepGITest::Check(AllFinite(av), "the captured AV is finite");
  DeepGITest::Check(outOfRange == 0,
    DeepGITest::Format("filtered and raw AV in [0, 1] (%ld values outside)", outOfRange));
  DeepGITest::Check(
    emptyNotOne == 0, DeepGITest::Format("AV is 1 on empty pixels (%ld are not)", emptyNotOne));
  DeepGITest::Check(surface > W * H / 10, DeepGITest::Format("%ld surface pixels", surface));
  DeepGITest::Check(mean >= e.MeanMin && mean <= e.MeanMax,
    DeepGITest::Format("mean AV over the surface %.4f in %.3f..%.3f", mean, e.MeanMin, e.MeanMax));
  DeepGITest::Check(fu >= e.UnoccludedMin,
    DeepGITest::Format("fraction unoccluded (AV > 0.999) %.3f >= %.3f", fu, e.UnoccludedMin));
  DeepGITest::Check(
    fd >= e.DarkMin, DeepGITest::Format("fraction dark (AV < 0.8) %.3f >= %.3f", fd, e.DarkMin));
  DeepGITest::Check(changed <= 1e-6,
    DeepGITest::Format("the AV shown equals the final frame's (change %.2e <= 1e-6)", changed));
  CheckRegressionImage(argc, argv, window, threshold);
  pass->ReleaseGraphicsResources(window);
  return DeepGITest::ExitStatus();
}
}

#endif
