// The first image a user renders, Examples/Cxx/OneLineRecipe.cxx's scene
// (a sphere resting on a plane, VTK's default actors and headlight,
// 400 x 300) converged with vtkDeepGIPass's defaults and read back with
// vtkWindowToImageFilter, which renders the window again: that frame holds
// the converged image. Two artifacts are checked for.
//
// Rings in the indirect light. The floor's indirect light (GI image minus
// plain VTK) is averaged over the floor pixels at each whole-pixel
// distance from the sphere's outline (below its centre), which averages
// the spiral's noise away but keeps anything that depends on that distance
// alone. From its peak outwards the profile falls smoothly; rings are
// steps on the way down, r_p / N pixels apart. A cubic fitted to the
// profile's logarithm leaves a residual of 0.18/255 RMS; with every
// pixel's taps at the middle of their rings (the paper's spiral) it is
// 0.86/255. Checks: the peak is at least 5/255 (the floor receives the
// sphere's light) and the residual at most 0.4/255.
//
// Grain in the contact shadow. Over the floor pixels 1 to 12 pixels below
// the sphere's outline whose 5 x 5 neighbourhood is floor, the RMS of the
// ambient visibility minus its neighbourhood's mean: the pattern the
// obscurance's taps leave. GRAIN_MEASURED. The check requires at most
// GRAIN_LIMIT, and a shadow (mean AV at most 0.95) so that a blank band
// cannot pass.

#include "DeepGBufferTestUtilities.h"

#include "vtkCamera.h"
#include "vtkDeepAmbientObscurancePass.h"
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
  vtkNew<vtkImageData> Plain, PlainDepth, Sphere, SphereDepth, GI, Visibility;
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
  Check(gi->GetAmbientObscurancePass()->CaptureAmbientVisibility(images.Visibility, renderer),
    "the ambient visibility is captured");
}

bool Covered(vtkImageData* depth, vtkIdType p)
{
  return depth->GetPointData()->GetScalars()->GetComponent(p, 0) < 1.0;
}

// The sphere's outline: a circle of the sphere's area around its centroid.
struct Outline
{
  double X = 0.0, Y = 0.0, Radius = 0.0;

  explicit Outline(vtkImageData* sphereDepth)
  {
    double area = 0.0;
    for (int j = 0; j < Height; ++j)
    {
      for (int i = 0; i < Width; ++i)
      {
        if (Covered(sphereDepth, i + static_cast<vtkIdType>(j) * Width))
        {
          this->X += i;
          this->Y += j;
          area += 1.0;
        }
      }
    }
    Check(area > 100.0, "the sphere covers pixels");
    this->X /= std::max(area, 1.0);
    this->Y /= std::max(area, 1.0);
    this->Radius = std::sqrt(area / vtkMath::Pi());
  }

  // The whole-pixel distance of pixel (i, j) from the outline.
  int Distance(int i, int j) const
  {
    return static_cast<int>(std::hypot(i - this->X, j - this->Y) - this->Radius);
  }
};

// Whether pixel p shows the floor and not the sphere.
bool Floor(const Images& images, vtkIdType p)
{
  return !Covered(images.SphereDepth, p) && Covered(images.PlainDepth, p);
}

// Mean over RGB of GI - plain, in 8-bit levels, per whole-pixel distance
// 0, 1, ... from the sphere's outline, over the floor pixels below the
// sphere's centre.
std::vector<double> IndirectProfile(Images& images, int bins)
{
  const Outline outline(images.SphereDepth);
  std::vector<double> sum(bins, 0.0), count(bins, 0.0);
  vtkDataArray* gi = images.GI->GetPointData()->GetScalars();
  vtkDataArray* plain = images.Plain->GetPointData()->GetScalars();
  for (int j = 0; j < static_cast<int>(outline.Y); ++j) // rows count from the bottom
  {
    for (int i = 0; i < Width; ++i)
    {
      const vtkIdType p = i + static_cast<vtkIdType>(j) * Width;
      const int bin = outline.Distance(i, j);
      if (bin < 0 || bin >= bins || !Floor(images, p))
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

// The mean of AV over the 5 x 5 neighbourhood of pixel (i, j); false
// where it holds a pixel that is not floor (next to the sphere AV rightly
// changes fastest).
bool FloorNeighbourhoodMean(const Images& images, vtkDataArray* av, int i, int j, double& mean)
{
  double sum = 0.0;
  for (int dj = -2; dj <= 2; ++dj)
  {
    for (int di = -2; di <= 2; ++di)
    {
      const vtkIdType q = (i + di) + static_cast<vtkIdType>(j + dj) * Width;
      if (!Floor(images, q))
      {
        return false;
      }
      sum += av->GetComponent(q, 0);
    }
  }
  mean = sum / 25.0;
  return true;
}

// Over the floor pixels 1 to 12 pixels below the sphere's outline: the
// RMS of AV minus its neighbourhood's mean, and the mean AV.
void ContactGrain(const Images& images, double& grain, double& meanVisibility)
{
  const Outline outline(images.SphereDepth);
  vtkDataArray* av =
    images.Visibility->GetPointData()->GetArray(vtkDeepGICaptureNames::AmbientVisibility);
  Check(av && av->GetNumberOfTuples() == Width * Height, "ambient visibility of every pixel");
  double squared = 0.0, sum = 0.0, count = 0.0;
  for (int j = 2; av && j < static_cast<int>(outline.Y); ++j)
  {
    for (int i = 2; i < Width - 2; ++i)
    {
      const int distance = outline.Distance(i, j);
      double mean = 0.0;
      if (distance < 1 || distance > 12 || !FloorNeighbourhoodMean(images, av, i, j, mean))
      {
        continue;
      }
      const double value = av->GetComponent(i + static_cast<vtkIdType>(j) * Width, 0);
      squared += (value - mean) * (value - mean);
      sum += value;
      count += 1.0;
    }
  }
  Check(count >= 500.0, "floor pixels in the contact shadow");
  grain = std::sqrt(squared / std::max(count, 1.0));
  meanVisibility = sum / std::max(count, 1.0);
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

int TestDeepGIOneLineRecipe(int, char*[])
{
  Images images;
  RenderImages(images);

  double grain = 0.0, meanVisibility = 0.0;
  ContactGrain(images, grain, meanVisibility);
  std::printf("contact shadow: mean AV %.3f, grain %.4f RMS\n", meanVisibility, grain);
  Check(meanVisibility <= 0.95, "a contact shadow under the sphere");
  Check(grain <= 0.005, "no grain in the contact shadow");

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
