// Tests vtkDeepGIReferenceObscurance, the Embree ground truth of ambient
// visibility, on synthetic captures (no rendering, no display): each pixel of
// a camera looking down at a floor gets the floor's exact depth and normal,
// and the scene is made of large quads.
//
//  1. unoccluded plane: AV = 1 and standard error 0 exactly;
//  2. floor beside a tall wall (distance d per pixel) against the closed form
//       A(s) = (2/pi) [pi/4 - 3/2 s sqrt(1-s^2) - (1/2 + s^2) asin(s) + pi/2 s^2],
//     s = min(d/r, 1), and the inside of a three-plane corner (floor + two
//     walls) against a numerical integral of the projected-disc form
//       A = (1/pi) int_{unit disc} (1 - t_min(u, w)^2 / r^2)_+ du dw;
//     tolerance: |AV - AV_exact| < 4.5 standard errors + 1e-4 per pixel,
//     and the mean difference within 4 standard errors of the mean;
//  3. two seeds agree within 4.5 combined standard errors per pixel;
//  4. same seed: bit-identical twice, and with 1 and 2 threads; the
//     deprecated SetScene and Compute give the pipeline's result;
//  5. scene, camera and radius scaled by 1e-4 and 1e4 (and the scene moved
//     1e4 * size away from the origin): same AV within noise;
//  6. bad input: errors, no crash.

#include "DeepGIReferenceTestUtilities.h"
#include "DeepGITestChecks.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIReferenceObscurance.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <functional>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace
{
using DeepGIReferenceTest::Estimate;
using DeepGIReferenceTest::WallObscurance;
using DeepGITest::Check;
using DeepGITest::Format;

// Geometry of a test: floor z = 0 (x >= WallX), optional walls x = WallX and
// y = WallY (floor side y >= WallY), everything extending Extent from the
// corner; all lengths multiplied by Scale and shifted by Shift.
struct Setup
{
  bool WallXOn = false;
  bool WallYOn = false;
  double WallX = 0.0;
  double WallY = -1e9;
  double Extent = 20.0;
  double Scale = 1.0;
  double Shift[3] = { 0, 0, 0 };
};

void AddQuad(vtkPoints* points, vtkCellArray* polys, const double p[4][3], const Setup& s)
{
  vtkIdType ids[4];
  for (int k = 0; k < 4; ++k)
  {
    ids[k] = points->InsertNextPoint(p[k][0] * s.Scale + s.Shift[0], p[k][1] * s.Scale + s.Shift[1],
      p[k][2] * s.Scale + s.Shift[2]);
  }
  polys->InsertNextCell(4, ids);
}

vtkSmartPointer<vtkPolyData> MakeScene(const Setup& s)
{
  auto scene = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  const double e = s.Extent;
  const double y0 = s.WallYOn ? s.WallY : -e;
  const double floorQuad[4][3] = { { s.WallX, y0, 0 }, { s.WallX + e, y0, 0 },
    { s.WallX + e, y0 + 2 * e, 0 }, { s.WallX, y0 + 2 * e, 0 } };
  AddQuad(points, polys, floorQuad, s);
  if (s.WallXOn)
  {
    const double wall[4][3] = { { s.WallX, y0 - e, 0 }, { s.WallX, y0 + 2 * e, 0 },
      { s.WallX, y0 + 2 * e, e }, { s.WallX, y0 - e, e } };
    AddQuad(points, polys, wall, s);
  }
  if (s.WallYOn)
  {
    const double wall[4][3] = { { s.WallX - e, y0, 0 }, { s.WallX + e, y0, 0 },
      { s.WallX + e, y0, e }, { s.WallX - e, y0, e } };
    AddQuad(points, polys, wall, s);
  }
  scene->SetPoints(points);
  scene->SetPolys(polys);
  return scene;
}

// A w x h capture of the floor seen from (cx, cy, height) looking straight
// down (perspective, 40 degrees), with its exact depth and normal; pixels
// whose floor point is not on the floor's side of the walls are invalid.
// positions receives the unscaled floor point of each pixel.
vtkSmartPointer<vtkImageData> MakeCapture(const Setup& s, int w, int h, double cx, double cy,
  double height, std::vector<std::array<double, 3>>* positions = nullptr)
{
  vtkNew<vtkCamera> camera;
  camera->SetPosition(
    cx * s.Scale + s.Shift[0], cy * s.Scale + s.Shift[1], height * s.Scale + s.Shift[2]);
  camera->SetFocalPoint(cx * s.Scale + s.Shift[0], cy * s.Scale + s.Shift[1], s.Shift[2]);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(40.0);
  camera->SetClippingRange(0.1 * height * s.Scale, 2.0 * height * s.Scale);
  vtkMatrix4x4* view = camera->GetModelViewTransformMatrix();
  vtkMatrix4x4* projection =
    camera->GetProjectionTransformMatrix(static_cast<double>(w) / h, -1, 1);
  vtkNew<vtkMatrix4x4> inverseView, inverseProjection;
  vtkMatrix4x4::Invert(view, inverseView);
  vtkMatrix4x4::Invert(projection, inverseProjection);

  auto capture = vtkSmartPointer<vtkImageData>::New();
  capture->SetDimensions(w, h, 1);
  vtkNew<vtkFloatArray> depth, normal;
  vtkNew<vtkUnsignedCharArray> valid;
  depth->SetName(vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Depth, 0).c_str());
  depth->SetNumberOfTuples(w * h);
  normal->SetName(vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Normal, 0).c_str());
  normal->SetNumberOfComponents(3);
  normal->SetNumberOfTuples(w * h);
  valid->SetName(vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 0).c_str());
  valid->SetNumberOfTuples(w * h);
  if (positions)
  {
    positions->assign(w * h, { 0, 0, 0 });
  }
  // The floor's normal (0, 0, 1) in camera space.
  double up[4] = { 0, 0, 1, 0 }, nc[4];
  view->MultiplyPoint(up, nc);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      const vtkIdType p = j * w + i;
      double ndc[2] = { (i + 0.5) / w * 2 - 1, (j + 0.5) / h * 2 - 1 };
      double a[4] = { ndc[0], ndc[1], -1, 1 }, b[4] = { ndc[0], ndc[1], 1, 1 };
      inverseProjection->MultiplyPoint(a, a);
      inverseProjection->MultiplyPoint(b, b);
      double wa[4], wb[4];
      for (int c = 0; c < 4; ++c)
      {
        a[c] /= (c < 3 ? a[3] : 1.0);
        b[c] /= (c < 3 ? b[3] : 1.0);
      }
      a[3] = b[3] = 1.0;
      inverseView->MultiplyPoint(a, wa);
      inverseView->MultiplyPoint(b, wb);
      // Intersect the world segment with z = Shift[2].
      const double f = (s.Shift[2] - wa[2]) / (wb[2] - wa[2]);
      double x[3], xc[4];
      for (int c = 0; c < 3; ++c)
      {
        x[c] = wa[c] + f * (wb[c] - wa[c]);
      }
      double xw[4] = { x[0], x[1], x[2], 1.0 };
      view->MultiplyPoint(xw, xc);
      const double ux = (x[0] - s.Shift[0]) / s.Scale, uy = (x[1] - s.Shift[1]) / s.Scale;
      const bool ok = ux > s.WallX && (!s.WallYOn || uy > s.WallY);
      depth->SetValue(p, ok ? static_cast<float>(-xc[2]) : 0.0f);
      valid->SetValue(p, ok ? 1 : 0);
      for (int c = 0; c < 3; ++c)
      {
        normal->SetComponent(p, c, ok ? nc[c] : 0.0);
      }
      if (positions)
      {
        (*positions)[p] = { ux, uy, 0.0 };
      }
    }
  }
  capture->GetPointData()->AddArray(depth);
  capture->GetPointData()->AddArray(normal);
  capture->GetPointData()->AddArray(valid);
  DeepGIReferenceTest::AddCameraMatrices(capture, view, projection);
  return capture;
}

// Numerical integral of A over the projected unit disc for a floor point at
// distances a (from x = WallX) and b (from y = WallY) of two infinite walls.
double CornerObscurance(double a, double b, double r)
{
  const int nr = 200, nphi = 800;
  double sum = 0.0;
  for (int i = 0; i < nr; ++i)
  {
    const double rho = (i + 0.5) / nr;
    for (int k = 0; k < nphi; ++k)
    {
      const double phi = (k + 0.5) / nphi * 2 * vtkMath::Pi();
      const double u = rho * std::cos(phi), w = rho * std::sin(phi);
      double t = std::numeric_limits<double>::infinity();
      if (u < 0)
      {
        t = std::min(t, a / -u);
      }
      if (w < 0)
      {
        t = std::min(t, b / -w);
      }
      sum += std::max(0.0, 1.0 - t * t / (r * r)) * rho;
    }
  }
  return sum * (1.0 / nr) * (2 * vtkMath::Pi() / nphi) / vtkMath::Pi();
}

vtkFloatArray* Array(vtkDeepGIReferenceObscurance* reference, const char* name)
{
  return vtkFloatArray::SafeDownCast(reference->GetOutput()->GetPointData()->GetArray(name));
}

// Compares AV per pixel against exact(p) (AV, not A); returns the largest
// ratio of |difference| to the tolerance 4.5 SE + 1e-4 (below 1 passes).
double CompareExact(vtkDeepGIReferenceObscurance* reference,
  const std::function<double(vtkIdType)>& exact, const char* what)
{
  vtkFloatArray* av = Array(reference, vtkDeepGICaptureNames::AmbientVisibility);
  vtkFloatArray* se = Array(reference, "StandardError");
  auto valid = vtkUnsignedCharArray::SafeDownCast(
    reference->GetOutput()->GetPointData()->GetArray(vtkDeepGICaptureNames::Valid));
  double sumDiff = 0.0, sumVar = 0.0, maxZ = 0.0, maxDiff = 0.0;
  int n = 0, bad = 0;
  for (vtkIdType p = 0; p < av->GetNumberOfTuples(); ++p)
  {
    if (!valid->GetValue(p))
    {
      continue;
    }
    const double diff = av->GetValue(p) - exact(p);
    const double e = se->GetValue(p);
    if (std::fabs(diff) > 4.5 * e + 1e-4)
    {
      ++bad;
    }
    maxZ = std::max(maxZ, std::fabs(diff) / (4.5 * e + 1e-4));
    maxDiff = std::max(maxDiff, std::fabs(diff));
    sumDiff += diff;
    sumVar += e * e;
    ++n;
  }
  const double meanDiff = sumDiff / n, meanSE = std::sqrt(sumVar) / n;
  std::cout << what << ": " << n << " pixels, mean AV - exact " << meanDiff
            << " (its standard error " << meanSE << "), max |diff| " << maxDiff
            << ", max |diff| / tolerance " << maxZ << ", mean SE "
            << reference->GetMeanStandardError() << ", max SE "
            << reference->GetMaximumStandardError() << ", " << reference->GetComputeTime()
            << " s\n";
  Check(n > 0, Format("%s: %d valid pixels", what, n));
  Check(bad == 0, Format("%s: %d pixels beyond 4.5 standard errors + 1e-4", what, bad));
  Check(std::fabs(meanDiff) < 4.0 * meanSE + 1e-4,
    Format("%s: mean difference %g within 4 standard errors of the mean (%g) + 1e-4", what,
      meanDiff, meanSE));
  return maxZ;
}

bool SameArrays(vtkDeepGIReferenceObscurance* a, vtkImageData* b)
{
  for (const char* name : { vtkDeepGICaptureNames::AmbientVisibility, "StandardError" })
  {
    vtkFloatArray* x = Array(a, name);
    auto y = vtkFloatArray::SafeDownCast(b->GetPointData()->GetArray(name));
    if (!x || !y || x->GetNumberOfValues() != y->GetNumberOfValues() ||
      std::memcmp(x->GetPointer(0), y->GetPointer(0), sizeof(float) * x->GetNumberOfValues()))
    {
      return false;
    }
  }
  return true;
}
// A reference on `s`'s scene with the test's radius and sample count.
vtkSmartPointer<vtkDeepGIReferenceObscurance> MakeReference(
  vtkPolyData* scene, double radius, int seed = -1)
{
  auto reference = vtkSmartPointer<vtkDeepGIReferenceObscurance>::New();
  reference->SetSceneData(scene);
  reference->SetRadius(radius);
  reference->SetSamplesPerPixel(1024);
  if (seed >= 0)
  {
    reference->SetSeed(seed);
  }
  return reference;
}

// 1. An unoccluded plane: AV = 1 and standard error 0 exactly.
void CheckUnoccludedPlaneIsFullyVisible(double r)
{
  Setup s;
  s.WallX = -10;
  vtkNew<vtkDeepGIReferenceObscurance> reference;
  reference->SetSceneData(MakeScene(s));
  reference->SetRadius(r);
  reference->SetSamplesPerPixel(256);
  auto capture = MakeCapture(s, 16, 16, 0, 0, 3);
  Check(Estimate(reference, capture), "plane: update succeeds");
  vtkFloatArray* av = Array(reference, vtkDeepGICaptureNames::AmbientVisibility);
  int notOne = 0;
  for (vtkIdType p = 0; p < av->GetNumberOfTuples(); ++p)
  {
    notOne += av->GetValue(p) != 1.0f;
  }
  Check(notOne == 0, Format("plane: %d pixels with AV != 1", notOne));
  Check(reference->GetMaximumStandardError() == 0.0, "plane: standard error 0");
  Check(reference->GetNumberOfValidPixels() == 256,
    Format("plane: %lld valid pixels (256)",
      static_cast<long long>(reference->GetNumberOfValidPixels())));
  std::cout << "plane: AV = 1 on " << reference->GetNumberOfValidPixels() << " pixels, "
            << reference->GetComputeTime() << " s\n";
}

// 2b. Three-plane corner (floor and two walls) against the numerical
// integral.
void CheckCornerMatchesIntegral(double r)
{
  Setup corner;
  corner.WallXOn = corner.WallYOn = true;
  corner.WallY = 0.0;
  std::vector<std::array<double, 3>> cornerPositions;
  auto cornerCapture = MakeCapture(corner, 24, 24, 0.6, 0.6, 3.6, &cornerPositions);
  auto cornerReference = MakeReference(MakeScene(corner), r);
  Check(Estimate(cornerReference, cornerCapture), "corner: update succeeds");
  // Both walls within r: numerical integral; otherwise only the nearer
  // wall can be hit within r and the closed form applies.
  std::vector<double> cornerExact(cornerPositions.size(), 1.0);
  for (size_t p = 0; p < cornerPositions.size(); ++p)
  {
    const double a = cornerPositions[p][0] - corner.WallX, b = cornerPositions[p][1] - corner.WallY;
    if (a > 0 && b > 0)
    {
      cornerExact[p] =
        1.0 - (a < r && b < r ? CornerObscurance(a, b, r) : WallObscurance(std::min(a, b), r));
    }
  }
  CompareExact(
    cornerReference, [&](vtkIdType p) { return cornerExact[p]; }, "corner (numerical integral)");
  Check(cornerReference->GetMeanStandardError() > 0.0, "corner: noise reported");
}

// 3. Two seeds agree within noise.
void CheckSeedsAgreeWithinNoise(
  vtkPolyData* scene, double r, vtkImageData* wallCapture, vtkImageData* wallResult)
{
  auto other = MakeReference(scene, r, 2);
  Check(Estimate(other, wallCapture), "seed 2: update succeeds");
  vtkFloatArray* a = Array(other, vtkDeepGICaptureNames::AmbientVisibility);
  vtkFloatArray* ae = Array(other, "StandardError");
  auto b = vtkFloatArray::SafeDownCast(
    wallResult->GetPointData()->GetArray(vtkDeepGICaptureNames::AmbientVisibility));
  auto be = vtkFloatArray::SafeDownCast(wallResult->GetPointData()->GetArray("StandardError"));
  int bad = 0, n = 0, identical = 0;
  double sumDiff = 0, sumVar = 0, maxZ = 0;
  for (vtkIdType p = 0; p < a->GetNumberOfTuples(); ++p)
  {
    if (a->GetValue(p) < 0)
    {
      continue;
    }
    const double diff = a->GetValue(p) - b->GetValue(p);
    const double sigma =
      std::sqrt(ae->GetValue(p) * ae->GetValue(p) + be->GetValue(p) * be->GetValue(p));
    bad += std::fabs(diff) > 4.5 * sigma + 1e-6;
    identical += diff == 0.0 && sigma > 0;
    maxZ = std::max(maxZ, std::fabs(diff) / std::max(sigma, 1e-9));
    sumDiff += diff;
    sumVar += sigma * sigma;
    ++n;
  }
  std::cout << "seeds 1 vs 2: mean difference " << sumDiff / n << " (standard error "
            << std::sqrt(sumVar) / n << "), max |diff|/sigma " << maxZ << "\n";
  Check(bad == 0, Format("seeds: %d pixels differ by more than 4.5 sigma", bad));
  Check(std::fabs(sumDiff / n) < 4 * std::sqrt(sumVar) / n,
    Format("seeds: mean difference %g within 4 standard errors", sumDiff / n));
  Check(identical < n / 4,
    Format("seeds: the seed changes the samples (%d of %d pixels identical)", identical, n));
}

// 4. Determinism: same seed twice, 1 and 2 threads.
void CheckSameSeedIsDeterministic(
  vtkDeepGIReferenceObscurance* reference, vtkImageData* wallCapture, vtkImageData* wallResult)
{
  // The thread count is no input of the pipeline: Modified() makes each
  // update run again.
  vtkSMPTools::Initialize(1);
  reference->Modified();
  Check(Estimate(reference, wallCapture), "1 thread: update succeeds");
  Check(SameArrays(reference, wallResult), "1 thread: identical to the default");
  vtkSMPTools::Initialize(2);
  reference->Modified();
  Check(Estimate(reference, wallCapture), "2 threads: update succeeds");
  Check(SameArrays(reference, wallResult), "2 threads: identical to the default");
  reference->Modified();
  Check(Estimate(reference, wallCapture), "again: update succeeds");
  Check(SameArrays(reference, wallResult), "same seed twice: identical");
  std::cout << "determinism: 2 threads " << reference->GetComputeTime() << " s for "
            << reference->GetNumberOfRays() << " rays\n";
  vtkSMPTools::Initialize();
}

// 4b. The deprecated SetScene, GetScene and Compute wrap the pipeline.
void CheckDeprecatedMethodsWrapThePipeline(
  vtkPolyData* scene, double r, vtkImageData* wallCapture, vtkImageData* wallResult)
{
  auto reference = vtkSmartPointer<vtkDeepGIReferenceObscurance>::New();
  reference->SetScene(scene);
  reference->SetRadius(r);
  reference->SetSamplesPerPixel(1024);
  reference->SetSeed(1);
  Check(reference->GetScene() == scene && reference->Compute(wallCapture) &&
      SameArrays(reference, wallResult),
    "deprecated SetScene and Compute: the pipeline's result");
}

// 5. Scale invariance (and a position far from the origin).
void CheckScaleInvariance(const Setup& wall,
  const std::vector<std::array<double, 3>>& wallPositions, double r, vtkImageData* wallResult,
  double wallMaximumStandardError)
{
  for (double scale : { 1e-4, 1e4 })
  {
    Setup scaled = wall;
    scaled.Scale = scale;
    scaled.Shift[0] = 3e4 * scale;
    scaled.Shift[1] = -2e4 * scale;
    scaled.Shift[2] = 1e4 * scale;
    auto capture = MakeCapture(scaled, 24, 24, 0.6, 0.0, 3.6);
    auto s = MakeReference(MakeScene(scaled), r * scale, 1);
    Check(Estimate(s, capture), Format("scale %g: update succeeds", scale));
    std::string what = "wall at scale " + std::to_string(scale) + " (closed form)";
    CompareExact(
      s, [&](vtkIdType p) { return 1.0 - WallObscurance(wallPositions[p][0] - wall.WallX, r); },
      what.c_str());
    vtkFloatArray* a = Array(s, vtkDeepGICaptureNames::AmbientVisibility);
    auto b = vtkFloatArray::SafeDownCast(
      wallResult->GetPointData()->GetArray(vtkDeepGICaptureNames::AmbientVisibility));
    double maxDiff = 0;
    for (vtkIdType p = 0; p < a->GetNumberOfTuples(); ++p)
    {
      maxDiff = std::max(maxDiff, std::fabs(static_cast<double>(a->GetValue(p)) - b->GetValue(p)));
    }
    Check(maxDiff < 4.5 * std::sqrt(2.0) * wallMaximumStandardError,
      Format("scale %g: max |AV - AV(scale 1)| = %g within 4.5 sqrt(2) max SE", scale, maxDiff));
  }
}

// 6. Bad input: errors, an empty output, no crash. A missing input is the
// executive's error; what the estimator refuses is its own.
void CheckBadInputIsRefused(vtkPolyData* scene, vtkImageData* wallCapture)
{
  vtkNew<DeepGIReferenceTest::EventCounter> errors, executiveErrors;
  vtkNew<vtkDeepGIReferenceObscurance> bad;
  bad->AddObserver(vtkCommand::ErrorEvent, errors);
  bad->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executiveErrors);
  Check(!Estimate(bad, wallCapture) && errors->Errors == 0 && executiveErrors->Errors == 1,
    "no scene: the executive's error");
  bad->SetSceneData(scene);
  Check(!Estimate(bad, nullptr) && errors->Errors == 0 && executiveErrors->Errors == 2,
    "no capture: the executive's error");
  vtkNew<vtkImageData> empty;
  Check(!Estimate(bad, empty) && errors->Errors == 1, "empty capture: error");
  vtkNew<vtkImageData> noMatrices;
  noMatrices->DeepCopy(wallCapture);
  noMatrices->GetFieldData()->RemoveArray(vtkDeepGICaptureNames::ViewMatrix);
  Check(!Estimate(bad, noMatrices) && errors->Errors == 2, "capture without matrices: error");
  bad->SetRadius(std::numeric_limits<double>::quiet_NaN());
  Check(!Estimate(bad, wallCapture) && errors->Errors == 3, "NaN radius: error");
  bad->SetRadius(-1.0);
  Check(!Estimate(bad, wallCapture) && errors->Errors == 4, "negative radius: error");
  bad->SetRadius(std::numeric_limits<double>::infinity());
  Check(!Estimate(bad, wallCapture) && errors->Errors == 5, "infinite radius: error");
  Check(bad->GetNumberOfValidPixels() == 0 && bad->GetMeanStandardError() == 0.0,
    "failed update: statistics reset");
  bad->SetRadius(1.0);
  bad->SetLayer(1);
  Check(!Estimate(bad, wallCapture) && errors->Errors == 6, "missing layer: error");
  bad->SetLayer(0);
  vtkNew<vtkPolyData> noPolygons;
  bad->SetSceneData(noPolygons);
  Check(!Estimate(bad, wallCapture) && errors->Errors == 7, "scene without polygons: error");
  bad->SetSceneData(scene);
  bad->SetSamplesPerPixel(0);
  Check(bad->GetSamplesPerPixel() == 1, "SamplesPerPixel clamped to 1");
  bad->SetBias(-1);
  bad->SetEpsilon(-1);
  Check(bad->GetBias() == 0 && bad->GetEpsilon() == 0, "Bias and Epsilon clamped to 0");
  Check(Estimate(bad, wallCapture) && errors->Errors == 7, "one sample per pixel computes");
  Check(bad->GetMaximumStandardError() == 0.0, "one sample: standard error 0");
  bad->Print(std::cout);
}
}

int TestDeepGIReferenceObscurance(int, char*[])
{
  const double r = 1.0;
  CheckUnoccludedPlaneIsFullyVisible(r);

  // 2a. Floor beside a tall wall: d from 0 to about 1.3 r, against the
  // closed form. Its result is the one the later checks compare with.
  Setup wall;
  wall.WallXOn = true;
  std::vector<std::array<double, 3>> wallPositions;
  auto wallCapture = MakeCapture(wall, 24, 24, 0.6, 0.0, 3.6, &wallPositions);
  vtkSmartPointer<vtkPolyData> wallScene = MakeScene(wall);
  auto reference = MakeReference(wallScene, r, 1);
  Check(Estimate(reference, wallCapture), "wall: update succeeds");
  CompareExact(
    reference,
    [&](vtkIdType p) { return 1.0 - WallObscurance(wallPositions[p][0] - wall.WallX, r); },
    "wall (closed form)");
  vtkNew<vtkImageData> wallResult;
  wallResult->DeepCopy(reference->GetOutput());

  CheckCornerMatchesIntegral(r);
  CheckSeedsAgreeWithinNoise(wallScene, r, wallCapture, wallResult);
  CheckSameSeedIsDeterministic(reference, wallCapture, wallResult);
  CheckDeprecatedMethodsWrapThePipeline(wallScene, r, wallCapture, wallResult);
  CheckScaleInvariance(wall, wallPositions, r, wallResult, reference->GetMaximumStandardError());
  CheckBadInputIsRefused(wallScene, wallCapture);
  return DeepGITest::ExitStatus();
}
