// No rings in the indirect light around a bright object: the scene of
// Examples/Cxx/OneLineRecipe.cxx (a sphere resting on a plane, VTK's default
// actors and headlight, 400 x 300) converged with vtkDeepGIPass's defaults.
//
// The floor's indirect light (GI image minus plain VTK) is averaged over
// the floor pixels at each whole-pixel distance from the sphere's outline
// (below its centre), which averages the spiral's noise away but keeps
// anything that depends on that distance alone. From its peak outwards the
// profile falls smoothly; rings are steps on the way down, r_p / N pixels
// apart. A cubic fitted to the profile's logarithm leaves a residual of
// 0.18/255 RMS; with every pixel's taps at the middle of their rings (the
// paper's spiral) it is 0.86/255. Checks: the peak is at least 5/255 (the
// floor receives the sphere's light) and the residual at most 0.4/255.

#include "DeepGBufferTestUtilities.h"

#include "vtkCamera.h"
#include "vtkDeepGIPass.h"
#include "vtkMath.h"
#include "vtkPlaneSource.h"
#include "vtkSphereSource.h"

#include <cmath>
#include <cstdio>
#include <vector>

using namespace DeepGBufferTest;
using namespace DeepGITest;

namespace
{
constexpr int Width = 400;
constexpr int Height = 300;

struct Images
{
  vtkNew<vtkImageData> Plain, PlainDepth, Sphere, SphereDepth, GI;
};

void RenderImages(Images& images)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(32);
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-2, -0.5, 2);
  plane->SetPoint1(2, -0.5, 2);
  plane->SetPoint2(-2, -0.5, -2);
  auto window = MakeWindow(Width, Height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  AddSourceActor(renderer, sphere);
  vtkActor* floor = AddSourceActor(renderer, plane);
  renderer->GetActiveCamera()->SetFocalPoint(0, -0.5, 0);
  renderer->GetActiveCamera()->SetPosition(0, 1.2, 4.5);
  renderer->ResetCameraClippingRange();

  floor->VisibilityOff();
  window->Render();
  ReadWindow(window, images.Sphere, images.SphereDepth);
  floor->VisibilityOn();
  window->Render();
  ReadWindow(window, images.Plain, images.PlainDepth);

  vtkNew<vtkDeepGIPass> gi;
  renderer->SetPass(gi);
  gi->Converge(renderer, 16, 0.07 / 255);
  ReadWindow(window, images.GI, nullptr);
}

bool Covered(vtkImageData* depth, vtkIdType p)
{
  return depth->GetPointData()->GetScalars()->GetComponent(p, 0) < 1.0;
}

// Mean over RGB of GI - plain, in 8-bit levels, per whole-pixel distance
// 0, 1, ... from the sphere's outline (a circle of the sphere's area around
// its centroid), over the floor pixels below the sphere's centre.
std::vector<double> IndirectProfile(Images& images, int bins)
{
  double cx = 0.0, cy = 0.0, area = 0.0;
  for (int j = 0; j < Height; ++j)
  {
    for (int i = 0; i < Width; ++i)
    {
      if (Covered(images.SphereDepth, i + static_cast<vtkIdType>(j) * Width))
      {
        cx += i;
        cy += j;
        area += 1.0;
      }
    }
  }
  Check(area > 100.0, "the sphere covers pixels");
  cx /= std::max(area, 1.0);
  cy /= std::max(area, 1.0);
  const double radius = std::sqrt(area / vtkMath::Pi());

  std::vector<double> sum(bins, 0.0), count(bins, 0.0);
  vtkDataArray* gi = images.GI->GetPointData()->GetScalars();
  vtkDataArray* plain = images.Plain->GetPointData()->GetScalars();
  for (int j = 0; j < static_cast<int>(cy); ++j) // rows count from the bottom
  {
    for (int i = 0; i < Width; ++i)
    {
      const vtkIdType p = i + static_cast<vtkIdType>(j) * Width;
      const int bin = static_cast<int>(std::hypot(i - cx, j - cy) - radius);
      if (bin < 0 || bin >= bins || Covered(images.SphereDepth, p) ||
        !Covered(images.PlainDepth, p))
      {
        continue;
      }
      for (int c = 0; c < 3; ++c)
      {
        sum[bin] += (gi->GetComponent(p, c) - plain->GetComponent(p, c)) / 3.0;
      }
      count[bin] += 1.0;
    }
  }
  std::vector<double> profile(bins, 0.0);
  for (int b = 0; b < bins; ++b)
  {
    Check(count[b] >= 10.0, "floor pixels at distance " + std::to_string(b));
    profile[b] = sum[b] / std::max(count[b], 1.0);
  }
  return profile;
}

// RMS residual of the least-squares cubic in x = k / n through log(y_k).
double SmoothFitResidual(const std::vector<double>& y)
{
  const int n = static_cast<int>(y.size());
  double normal[4][4] = {}, rhs[4] = {};
  for (int k = 0; k < n; ++k)
  {
    const double x = static_cast<double>(k) / n;
    const double powers[4] = { 1.0, x, x * x, x * x * x };
    for (int r = 0; r < 4; ++r)
    {
      rhs[r] += powers[r] * std::log(y[k]);
      for (int c = 0; c < 4; ++c)
      {
        normal[r][c] += powers[r] * powers[c];
      }
    }
  }
  double* rows[4] = { normal[0], normal[1], normal[2], normal[3] };
  if (!vtkMath::SolveLinearSystem(rows, rhs, 4))
  {
    return VTK_DOUBLE_MAX;
  }
  double squared = 0.0;
  for (int k = 0; k < n; ++k)
  {
    const double x = static_cast<double>(k) / n;
    const double fit = std::exp(rhs[0] + x * (rhs[1] + x * (rhs[2] + x * rhs[3])));
    squared += (y[k] - fit) * (y[k] - fit);
  }
  return std::sqrt(squared / n);
}
}

int TestDeepRadiosityRings(int, char*[])
{
  Images images;
  RenderImages(images);
  const std::vector<double> profile = IndirectProfile(images, static_cast<int>(0.4 * Height));

  int peak = 0;
  for (int b = 1; b < static_cast<int>(profile.size()); ++b)
  {
    peak = profile[b] > profile[peak] ? b : peak;
  }
  std::printf("indirect light on the floor by distance from the sphere (8-bit levels):\n");
  for (int b = 0; b < static_cast<int>(profile.size()); ++b)
  {
    std::printf("%5.1f%s", profile[b], b % 16 == 15 ? "\n" : " ");
  }
  std::printf("\npeak %.1f at %d px\n", profile[peak], peak);
  Check(profile[peak] >= 5.0, "the floor receives the sphere's light");

  const std::vector<double> falling(profile.begin() + peak, profile.end());
  bool positive = true;
  for (double value : falling)
  {
    positive = positive && value > 0.0;
  }
  Check(positive, "indirect light on the floor out to 0.4 of the height");
  if (positive)
  {
    const double residual = SmoothFitResidual(falling);
    std::printf("residual of a smooth fit from the peak outwards: %.3f RMS\n", residual);
    Check(residual <= 0.4, "no rings: the falling profile is smooth");
  }
  return ExitStatus();
}
