// Regression image of vtkDeepRadiosityPass on the demo scene (20k
// triangles, default view, automatic radius, BALANCED, Damping 0.5,
// TemporalAlpha 0 so that the progressive bounces converge to a fixed
// image): one 640 x 240 window, left the composite RADIANCE + L_ind, right
// L_ind itself (layer 0, x 8, clamped, nearest-neighbour) so the indirect
// light is part of the baseline independently of the direct light.
// Threshold 0.5, as for the other demo-scene images: VTK's metric sums
// per-pixel excesses over 105 of 255.
// Numeric checks on the captured radiosity carry the expectations (ranges
// around the values measured when the baseline was made, margins about
// 20 %; default estimator SOLID_ANGLE, guard band, gather radius 0.5 of
// the diagonal and AverageFarTaps): mean L_ind over the surface pixels
// (0.130; 0.0227 with the radius 0.1 of the diagonal, which missed the
// light of the far walls), the mean confidence (0.328) and the fraction of
// surface pixels above 0.25 (0.685), the growth of the total indirect light
// from frame 1 (single bounce) to frame 20 (x 1.223), finite
// and non-negative values, and the L_ind shown equals the final frame's
// (converged: 1e-5).

#include "DeepRadiosityTest.h"

#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIDemoScene.h"
#include "vtkImageActor.h"
#include "vtkImageProperty.h"
#include "vtkRegressionTestImage.h"

#include <algorithm>

using namespace DeepRadiosityTest;
using namespace DeepGITest;

// Scale of the L_ind view: the mean L_ind (0.130) times 2 is about 66/255,
// so the indirect light is visible in the baseline without clipping most
// of it.
constexpr double ShownScale = 2.0;

int TestDeepRadiosityDemoImage(int argc, char* argv[])
{
  constexpr int W = 320, H = 240, frames = 20;
  auto window = MakeWindow(2 * W, H);
  vtkNew<vtkRenderer> lit, view;
  lit->SetViewport(0.0, 0.0, 0.5, 1.0);
  view->SetViewport(0.5, 0.0, 1.0, 1.0);
  lit->SetBackground(0.1, 0.1, 0.15);
  view->SetBackground(0.1, 0.1, 0.15);
  window->AddRenderer(lit);
  window->AddRenderer(view);
  AddDemoScene(lit);
  vtkNew<vtkDeepRadiosityPass> pass;
  pass->SetTemporalAlpha(0.0);
  pass->SetDamping(0.5);
  lit->SetPass(pass);

  // The L_ind viewport: image pixel (i, j) at viewport pixel (i, j).
  vtkSmartPointer<vtkImageData> rgb = ShowImagePixelForPixel(view, W, H, 3);

  vtkNew<vtkImageData> first, shown, last;
  window->Render();
  bool ok = pass->CaptureIrradiance(first, lit);
  for (int k = 1; k < frames && ok; ++k)
  {
    window->Render();
  }
  ok = ok && pass->CaptureIrradiance(shown, lit);
  if (ok)
  {
    vtkDataArray* l = shown->GetPointData()->GetArray(
      vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0).c_str());
    ShowValues(l, ShownScale, rgb);
    window->Render();
    ok = pass->CaptureIrradiance(last, lit);
  }
  if (!Check(ok, "the irradiance of the first, shown and last frames is captured"))
  {
    return EXIT_FAILURE;
  }

  vtkDataArray* l = last->GetPointData()->GetArray(
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0).c_str());
  vtkDataArray* before = shown->GetPointData()->GetArray(
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0).c_str());
  vtkDataArray* confidence = last->GetPointData()->GetArray(
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Confidence, 0).c_str());
  vtkDataArray* valid = last->GetPointData()->GetArray(
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 0).c_str());
  long surface = 0, confident = 0;
  double sum = 0.0, changed = 0.0, largest = 0.0, confidenceSum = 0.0;
  for (vtkIdType p = 0; p < l->GetNumberOfTuples(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      changed = std::max(changed, std::abs(l->GetComponent(p, c) - before->GetComponent(p, c)));
      largest = std::max(largest, l->GetComponent(p, c));
    }
    if (valid->GetTuple1(p) == 0)
    {
      continue;
    }
    ++surface;
    sum += (l->GetComponent(p, 0) + l->GetComponent(p, 1) + l->GetComponent(p, 2)) / 3.0;
    confident += confidence->GetTuple1(p) > 0.25 ? 1 : 0;
    confidenceSum += confidence->GetTuple1(p);
  }
  const double mean = sum / std::max(surface, 1L);
  const double fraction = static_cast<double>(confident) / std::max(surface, 1L);
  const double meanConfidence = confidenceSum / std::max(surface, 1L);
  const double growth =
    Total(last, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0)) /
    Total(first, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0));
  std::printf(
    "demo scene: %ld surface px (radius %.4g, N %d), mean L_ind %.4f, largest %.4f, "
    "mean confidence %.3f, > 0.25 on %.3f, total frame %d / frame 1 = %.4f, change since the "
    "displayed frame %.2e\n",
    surface, pass->GetEffectiveRadius(), pass->GetNumberOfSamples(), mean, largest, meanConfidence,
    fraction, frames, growth, changed);
  Check(AllFinite(last) &&
      Minimum(last, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0)) >=
        0.0,
    "finite, non-negative");
  Check(surface > W * H / 2, "the scene fills the view");
  Check(mean >= 0.104 && mean <= 0.156, "mean L_ind in the measured range (0.130)");
  Check(meanConfidence >= 0.26 && meanConfidence <= 0.39,
    "mean confidence in the measured range (0.328)");
  Check(fraction >= 0.55 && fraction <= 0.82, "fraction with confidence > 0.25 (0.685)");
  Check(growth >= 1.12 && growth <= 1.33, "bounces add light (x 1.223)");
  Check(changed <= 1e-5 * std::max(largest, 1.0), "converged: the image shows the final L_ind");
  CheckRegressionImage(argc, argv, window, 0.5);
  pass->ReleaseGraphicsResources(window);
  return ExitStatus();
}
