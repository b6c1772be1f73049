// Temporal stability of vtkDeepRadiosityPass along the demo scene's camera
// path (vtkDeepGBufferDemoScene::SetCameraToPathFrame, 240 frames per loop,
// 160 x 120 pixels, default parameters): for every pixel of layer 0 whose
// surface point is also seen in the previous frame (reprojected with the
// captures' matrices, the previous frame's layer-0 point within 1 % of the
// distance), the absolute change of the indirect radiance luminance between
// the two frames. The flicker is its mean over the pixels and over frames
// 8 to 19 (after the history has built up), divided by the mean indirect
// luminance of those pixels. With the temporal filter (alpha 0.85, the
// default) it must stay below FlickerBound; without it (alpha 0) it must be
// larger by at least MinimumGain.

#include "DeepGBufferTestUtilities.h"

#include "vtkCamera.h"
#include "vtkDeepGBufferDemoScene.h"
#include "vtkDeepGBufferPass.h"
#include "vtkDeepRadiosityPass.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkMatrix4x4.h"

#include <cstdio>

using namespace DeepGBufferTest;

namespace
{
constexpr int PathFrames = 240;
constexpr int FirstMeasuredFrame = 8;
constexpr int LastFrame = 19;
// Measured (llvmpipe, 224188 pixel pairs) with the default estimator
// SOLID_ANGLE: 0.059 with the filter, 0.148 without it (2.50 x); mean
// |change| 0.00138 over a mean indirect luminance of 0.0233. With eq. 4
// (ACCEPTED_TAPS, the default before) it was 0.033 and 0.088 under a bound
// of 0.05: SOLID_ANGLE's E is about 5x darker on this scene (the radiosity
// demo image: mean L_ind 0.108 -> 0.021), so the relative measure divides
// by a much smaller mean, and the absolute change fell by less than that
// (about 3x, inferred from the two ratios). The bound is raised to 0.075
// for that reason (27 % above the measurement); the filter's gain, the
// test's main claim, keeps its bound.
constexpr double FlickerBound = 0.075;
constexpr double MinimumGain = 2.0;

double Luminance(vtkDataArray* a, vtkIdType i)
{
  return 0.2126 * a->GetComponent(i, 0) + 0.7152 * a->GetComponent(i, 1) +
    0.0722 * a->GetComponent(i, 2);
}

// Pixel of `world` in the frame of `layers` (false when outside it).
bool Project(vtkImageData* layers, const double world[3], int& i, int& j)
{
  vtkNew<vtkMatrix4x4> view, projection, m;
  view->DeepCopy(
    vtkDoubleArray::SafeDownCast(layers->GetFieldData()->GetArray("ViewMatrix"))->GetPointer(0));
  projection->DeepCopy(
    vtkDoubleArray::SafeDownCast(layers->GetFieldData()->GetArray("ProjectionMatrix"))
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
// surfaces seen in consecutive frames.
double Flicker(double alpha)
{
  auto window = MakeWindow(160, 120);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0, 0, 0);
  window->AddRenderer(renderer);
  vtkNew<vtkDeepGBufferDemoScene> scene;
  scene->SetTargetNumberOfTriangles(20000);
  scene->Populate(renderer);
  vtkNew<vtkDeepRadiosityPass> pass;
  pass->SetTemporalAlpha(alpha);
  renderer->SetPass(pass);
  vtkSmartPointer<vtkImageData> previousLayers, previousRadiosity;
  double change = 0.0, level = 0.0;
  long pixels = 0;
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
      return 0.0;
    }
    if (frame >= FirstMeasuredFrame && previousLayers)
    {
      const int* dims = layers->GetDimensions();
      vtkDataArray* now = radiosity->GetPointData()->GetArray("IndirectRadiance_0");
      vtkDataArray* before = previousRadiosity->GetPointData()->GetArray("IndirectRadiance_0");
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
        }
      }
    }
    previousLayers = layers;
    previousRadiosity = radiosity;
  }
  const double flicker = level > 0.0 ? change / level : 0.0;
  std::printf("alpha %.2f: %ld reprojected pixels, mean |change| %.5f, mean indirect luminance "
              "%.5f, relative flicker %.4f\n",
    alpha, pixels, pixels ? change / pixels : 0.0, pixels ? level / pixels : 0.0, flicker);
  Check(pixels > 10000, "enough pixels are seen in consecutive frames");
  return flicker;
}
}

int TestDeepRadiosityFlicker(int, char*[])
{
  const double filtered = Flicker(0.85);
  const double unfiltered = Flicker(0.0);
  Check(filtered < FlickerBound,
    "flicker with the temporal filter below " + std::to_string(FlickerBound));
  Check(unfiltered > MinimumGain * filtered,
    "flicker without the temporal filter > " + std::to_string(MinimumGain) + " x with it");
  return CheckFailures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
