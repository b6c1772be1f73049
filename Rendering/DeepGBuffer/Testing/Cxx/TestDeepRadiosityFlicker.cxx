// Temporal stability of vtkDeepRadiosityPass along the demo scene's camera
// path (vtkDeepGIDemoScene::SetCameraToPathFrame, 240 frames per loop,
// 160 x 120 pixels, default parameters): for every pixel of layer 0 whose
// surface point is also seen in the previous frame (reprojected with the
// captures' matrices, the previous frame's layer-0 point within 1 % of the
// distance), the absolute change of the indirect radiance luminance between
// the two frames. The flicker is its mean over the pixels and over frames
// 8 to 19 (after the history has built up), divided by the mean indirect
// luminance of those pixels. With the temporal filter (alpha 0.85, the
// default) it must stay below FlickerBound; without it (alpha 0) it must be
// larger by at least MinimumGain. The guard band (section 3.5, the pass's
// default 0.1 of the height) must not make it worse: its relative flicker
// is at most GuardBandTolerance times that without a guard band. With the
// taps spread over two frames (TemporalInterleave 2) it must stay below
// InterleavedFlickerBound.
//
// Measured with the filter: relative flicker 0.0259 with the guard band,
// 0.0295 without it; the mean |change| is close (0.00463 and
// 0.00419): the ratio falls because the guard band brings more light to the
// frame's edges (mean 0.179 instead of 0.142). The surfaces that entered
// the frame one frame earlier (582 pixel pairs) change by 0.00212 with the
// guard band and 0.00222 without it: on this path the guard band does not
// make entering surfaces steadier; what it adds is the light from outside
// the view (see TestDeepGuardBand and Documentation/benchmark-radiosity.md,
// "Guard band").

#include "DeepGBufferTestUtilities.h"

#include "vtkCamera.h"
#include "vtkDeepGBufferPass.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIDemoScene.h"
#include "vtkDeepRadiosityPass.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkMatrix4x4.h"

#include <cstdio>

using namespace DeepGBufferTest;
using namespace DeepGITest;

namespace
{
constexpr int PathFrames = 240;
constexpr int FirstMeasuredFrame = 8;
constexpr int LastFrame = 19;
// Measured (llvmpipe, 224188 pixel pairs, the pass's defaults): 0.0259
// with the filter, 0.0501 without it (1.93 x). The bound is 20 % above the
// measurement; the filter's gain, the test's main claim, must be at least
// 1.5.
constexpr double FlickerBound = 0.03;
// With the taps spread over 2 frames (TemporalInterleave 2), each frame's
// gather has half the taps: measured 0.0348, a third above the default's.
// The bound is 20 % above the measurement, below the 0.05 without filter.
constexpr double InterleavedFlickerBound = 0.042;
constexpr double MinimumGain = 1.5;
constexpr double GuardBandTolerance = 1.1;

struct Measure
{
  double All = 0.0;      // relative flicker of all the pixels seen in consecutive frames
  double Entering = 0.0; // mean |change| of those that entered the frame one frame before
};

double Luminance(vtkDataArray* a, vtkIdType i)
{
  return 0.2126 * a->GetComponent(i, 0) + 0.7152 * a->GetComponent(i, 1) +
    0.0722 * a->GetComponent(i, 2);
}

// Pixel of `world` in the frame of `layers` (false when outside it).
bool Project(vtkImageData* layers, const double world[3], int& i, int& j)
{
  vtkNew<vtkMatrix4x4> view, projection, m;
  view->DeepCopy(vtkDoubleArray::SafeDownCast(
    layers->GetFieldData()->GetArray(vtkDeepGICaptureNames::ViewMatrix))
                   ->GetPointer(0));
  projection->DeepCopy(vtkDoubleArray::SafeDownCast(
    layers->GetFieldData()->GetArray(vtkDeepGICaptureNames::ProjectionMatrix))
                         ->GetPointer(0));
  vtkMatrix4x4::Multiply4x4(projection, view, m);
  const double p[4] = { world[0], world[1], world[2], 1.0 };
  double clip[4];
  m->MultiplyPoint(p, clip);
  if (!(clip[3] > 0.0))
  {
    return false;
  }
  const int* dims = layers->GetDimensions();
  const double x = (clip[0] / clip[3] * 0.5 + 0.5) * dims[0];
  const double y = (clip[1] / clip[3] * 0.5 + 0.5) * dims[1];
  i = static_cast<int>(std::floor(x));
  j = static_cast<int>(std::floor(y));
  return i >= 0 && j >= 0 && i < dims[0] && j < dims[1];
}

// Mean relative frame-to-frame change of the indirect luminance of the
// surfaces seen in consecutive frames, over the frame and over its border.
Measure Flicker(double alpha, double guardBand, int interleave = 1)
{
  auto window = MakeWindow(160, 120);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0, 0, 0);
  window->AddRenderer(renderer);
  vtkNew<vtkDeepGIDemoScene> scene;
  scene->SetTargetNumberOfTriangles(20000);
  scene->Populate(renderer);
  vtkNew<vtkDeepRadiosityPass> pass;
  pass->SetTemporalAlpha(alpha);
  pass->SetTemporalInterleave(interleave);
  pass->GetGBufferPass()->SetGuardBand(guardBand);
  renderer->SetPass(pass);
  vtkSmartPointer<vtkImageData> previousLayers, previousRadiosity, earlierLayers;
  double change = 0.0, level = 0.0, enteringChange = 0.0;
  long pixels = 0, entering = 0;
  for (int frame = 0; frame <= LastFrame; ++frame)
  {
    scene->SetCameraToPathFrame(renderer->GetActiveCamera(), frame, PathFrames);
    window->Render();
    auto layers = vtkSmartPointer<vtkImageData>::New();
    auto radiosity = vtkSmartPointer<vtkImageData>::New();
    if (!pass->CaptureIrradiance(radiosity, renderer) ||
      !pass->GetGBufferPass()->CaptureLayers(layers, renderer))
    {
      Check(false, "capture");
      return {};
    }
    if (frame >= FirstMeasuredFrame && previousLayers)
    {
      const int* dims = layers->GetDimensions();
      vtkDataArray* now = radiosity->GetPointData()->GetArray(
        vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0).c_str());
      vtkDataArray* before = previousRadiosity->GetPointData()->GetArray(
        vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0).c_str());
      for (int j = 0; j < dims[1]; ++j)
      {
        for (int i = 0; i < dims[0]; ++i)
        {
          double X[3], Xp[3], c[3];
          int pi = 0, pj = 0;
          if (!WorldPosition(layers, 0, i, j, X) || !Project(previousLayers, X, pi, pj) ||
            !WorldPosition(previousLayers, 0, pi, pj, Xp) || !CameraPosition(layers, 0, i, j, c))
          {
            continue;
          }
          const double distance = std::sqrt(vtkMath::Distance2BetweenPoints(X, Xp));
          if (distance > 0.01 * std::sqrt(vtkMath::Dot(c, c)))
          {
            continue;
          }
          const double a = Luminance(now, static_cast<vtkIdType>(j) * dims[0] + i);
          const double b = Luminance(before, static_cast<vtkIdType>(pj) * dims[0] + pi);
          change += std::fabs(a - b);
          level += 0.5 * (a + b);
          ++pixels;
          int ei = 0, ej = 0;
          if (earlierLayers && !Project(earlierLayers, X, ei, ej))
          {
            enteringChange += std::fabs(a - b);
            ++entering;
          }
        }
      }
    }
    earlierLayers = previousLayers;
    previousLayers = layers;
    previousRadiosity = radiosity;
  }
  Measure m;
  m.All = level > 0.0 ? change / level : 0.0;
  m.Entering = entering ? enteringChange / entering : 0.0;
  std::printf("alpha %.2f, taps over %d frames, guard band %.2f: %ld reprojected pixels, mean "
              "|change| %.5f, mean indirect luminance %.5f, relative flicker %.4f; %ld entering "
              "pixels, mean |change| %.5f\n",
    alpha, interleave, guardBand, pixels, pixels ? change / pixels : 0.0,
    pixels ? level / pixels : 0.0, m.All, entering, m.Entering);
  Check(pixels > 10000, "enough pixels are seen in consecutive frames");
  Check(entering > 100, "surfaces enter the frame along the path");
  renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(window);
  return m;
}
}

int TestDeepRadiosityFlicker(int, char*[])
{
  const double guardBand = vtkDeepRadiosityPass::DEFAULT_GUARD_BAND;
  const Measure filtered = Flicker(0.85, guardBand);
  const Measure unfiltered = Flicker(0.0, guardBand);
  const Measure noGuardBand = Flicker(0.85, 0.0);
  const Measure interleaved = Flicker(0.85, guardBand, 2);
  Check(filtered.All < FlickerBound,
    "flicker with the temporal filter below " + std::to_string(FlickerBound));
  Check(unfiltered.All > MinimumGain * filtered.All,
    "flicker without the temporal filter > " + std::to_string(MinimumGain) + " x with it");
  Check(filtered.All <= GuardBandTolerance * noGuardBand.All,
    "the guard band does not increase the flicker");
  Check(interleaved.All < InterleavedFlickerBound,
    "flicker with the taps spread over 2 frames below " + std::to_string(InterleavedFlickerBound));
  return ExitStatus();
}
