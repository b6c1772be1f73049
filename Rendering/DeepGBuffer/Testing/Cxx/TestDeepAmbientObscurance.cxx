// Exact and qualitative properties of vtkDeepAmbientObscurancePass on small
// scenes made of planes and boxes (radius set explicitly, 240 x 200 px):
// - an unoccluded plane (oblique perspective and parallel views) has AV = 1
//   within 1e-3 (raw and filtered; the bias beta = 0.01 r absorbs the
//   Oct16 normal quantisation, < 0.01 rad);
// - the raw AV equals an independent CPU evaluation of eq. 1-2 with the same
//   taps (and the same MIP level and rotated-grid texel per tap) on the
//   captured G-buffer (|difference| <= 2e-3 on >= 99 % of the
//   pixels: float vs double rounding may pick a neighbouring texel for a
//   tap that lands on a texel border);
// - the estimators on the corner's floor against the closed form of the
//   exact obscurance, bin means of AV: the default VISIBILITY_BITMASK within
//   0.04 beyond r / 8 of the wall and 0.08 nearer (measured +0.012 to
//   +0.031 and +0.047: a sector between two taps gets the farther tap's
//   falloff), SOLID_ANGLE within 0.03 and 0.15 (measured +0.080: the taps,
//   at least r_p / 2N pixels from X, miss the wall's nearest part, whose
//   solid angle is largest);
// - VISIBILITY_BITMASK and the layers' depth: a thin plate 1.5 r in front of
//   a wall leaves the wall around it unobscured (AV >= 0.97, two layers),
//   one layer (a height field) darkens it by at least 0.03, and a box that
//   reaches back to the wall darkens the wall around it by at least 0.1
//   more than the plate;
// - with EQUATION_1 (every check below):
// - a floor + wall corner: AV < 1 near the corner, 1 (1e-3) farther than r
//   from it, increasing with the distance (bins of r / 8, each mean at least
//   the previous one minus 0.02, the residual noise of 16 taps);
// - the bilateral filter does not bleed across a depth discontinuity: a quad
//   0.3 in front of a plane (r = 1, so the plane is obscured around the quad
//   while the quad is not) keeps AV = 1 (1e-3) on the quad after filtering,
//   and every filtered plane pixel next to the silhouette lies within the
//   range of the raw plane values of its (2 BlurRadius + 1)^2 window (1e-5,
//   float rounding): a filter that only averages same-surface values cannot
//   leave that range;
// - the filtered AV equals a CPU evaluation of the separable bilateral
//   filter (Gaussian, plane and normal weights) of the raw AV on a sphere
//   resting on a floor, for BlurNormalPower 8 (the default, compiled as
//   products), then 3, 2.5 (pow) and 0 (no normal weight) set on the same
//   pass between frames (each rebuilds the filter): mean |difference|
//   <= 1e-6 and at most 0.5 % of the pixels off by more than 1e-5 (float
//   against double; measured: 1e-8 and none); the filtered AV of power 8
//   and of the others differ by more than 0.01 somewhere, so the power is
//   seen;
// - UseSecondLayer: raw AV with every layer <= raw AV with layer 0 only
//   (eq. 1's max over more layers, 1e-5), and strictly lower (by > 0.02) on
//   floor pixels near a corner hidden behind a column;
// - the composite image is the plain G-buffer image times AV (8-bit
//   rounding: <= 2 levels) with the same depth buffer; background kept;
// - no NaN or Inf anywhere; N = 1 and N = 99 (clamped to 98) give finite
//   values; ReleaseGraphicsResources then Render gives the same AV (1e-6).

#include "DeepGBufferTestUtilities.h"

#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkDeepAmbientObscurancePass.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

using namespace DeepGBufferTest;
using namespace DeepGITest;

namespace
{
constexpr int Width = 240;
constexpr int Height = 200;
constexpr double Pi = 3.14159265358979323846;

using Scene = std::function<void(vtkRenderer*)>;

struct Result
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkNew<vtkImageData> AO;
  vtkNew<vtkImageData> Layers;
};

// Renders `scene` with `pass` (3 frames) and captures AV and the layers.
bool Render(const Scene& scene, vtkDeepAmbientObscurancePass* pass, Result& r)
{
  r.Window = MakeWindow(Width, Height);
  r.Renderer = vtkSmartPointer<vtkRenderer>::New();
  r.Window->AddRenderer(r.Renderer);
  scene(r.Renderer);
  r.Renderer->ResetCameraClippingRange();
  r.Renderer->SetPass(pass);
  for (int f = 0; f < 3; ++f)
  {
    r.Window->Render();
  }
  const bool ok = pass->CaptureAmbientVisibility(r.AO, r.Renderer) &&
    pass->GetGBufferPass()->CaptureLayers(r.Layers, r.Renderer);
  Check(ok, "capture");
  Check(AllFinite(r.AO), "AV finite");
  return ok;
}

float Value(vtkImageData* image, const char* name, int i, int j)
{
  return static_cast<float>(
    image->GetPointData()->GetArray(name)->GetComponent(static_cast<vtkIdType>(j) * Width + i, 0));
}

// Eq. 1-2 on the CPU, in double precision, with the documented taps and hash
// and the distance pyramid's level choice: tap i at level
// m = clamp(floor(log2(h_i / q)), 0, levels - 1) uses the level-0 texel the
// rotated grid (2x + (y & 1), 2y + (x & 1)) selects for its coarse texel.
double ReferenceAV(vtkImageData* layers, int i, int j, int layerCount, int n, double radius,
  double bias, double epsilon, double q, int levels)
{
  double X[3];
  if (!CameraPosition(layers, 0, i, j, X))
  {
    return 1.0;
  }
  const double* P = vtkDoubleArray::SafeDownCast(
    layers->GetFieldData()->GetArray(vtkDeepGICaptureNames::ProjectionMatrix))
                      ->GetPointer(0);
  double nX[3];
  Layer(layers, vtkDeepGICaptureNames::Normal, 0)
    ->GetTuple(static_cast<vtkIdType>(j) * Width + i, nX);
  const double w = P[14] * X[2] + P[15];
  const double rp = radius * P[5] * 0.5 * Height / w;
  const double ign = 52.9829189 * std::fmod(0.06711056 * i + 0.00583715 * j, 1.0);
  const double phi = 2.0 * Pi * (ign - std::floor(ign));
  const int tau = vtkDeepAmbientObscurancePass::GetSpiralTurns(n);
  double sum = 0.0;
  for (int s = 0; s < n; ++s)
  {
    const double kappa = (s + 0.5) / n;
    const double theta = 2.0 * Pi * kappa * tau + phi;
    const double h = rp * kappa;
    double tx = i + 0.5 + h * std::cos(theta);
    double ty = j + 0.5 + h * std::sin(theta);
    if (tx < 0 || ty < 0 || tx >= Width || ty >= Height)
    {
      continue;
    }
    const int m = (levels > 1 && h >= 2.0 * q)
      ? std::min(static_cast<int>(std::floor(std::log2(h / q))), levels - 1)
      : 0;
    int cx = std::min(static_cast<int>(tx) >> m, std::max(Width >> m, 1) - 1);
    int cy = std::min(static_cast<int>(ty) >> m, std::max(Height >> m, 1) - 1);
    for (int k = m; k > 0; --k)
    {
      const int nx = std::min(2 * cx + (cy & 1), std::max(Width >> (k - 1), 1) - 1);
      const int ny = std::min(2 * cy + (cx & 1), std::max(Height >> (k - 1), 1) - 1);
      cx = nx;
      cy = ny;
    }
    tx = cx;
    ty = cy;
    double best = 0.0;
    for (int layer = 0; layer < layerCount; ++layer)
    {
      double Y[3];
      if (!CameraPosition(layers, layer, tx, ty, Y))
      {
        continue;
      }
      const double v[3] = { Y[0] - X[0], Y[1] - X[1], Y[2] - X[2] };
      const double vv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
      if (vv < radius * radius)
      {
        const double vn = v[0] * nX[0] + v[1] * nX[1] + v[2] * nX[2];
        best = std::max(best,
          (1.0 - vv / (radius * radius)) * std::max((vn - bias) / std::sqrt(vv + epsilon), 0.0));
      }
    }
    sum += best;
  }
  return std::max(0.0, 1.0 - std::sqrt(Pi / n * sum));
}

vtkSmartPointer<vtkDeepAmbientObscurancePass> MakePass(double radius)
{
  auto pass = vtkSmartPointer<vtkDeepAmbientObscurancePass>::New();
  pass->SetRadius(radius);
  // The properties below are those of eq. 1, which the CPU evaluation
  // reproduces; TestCornerClosedForm measures the other estimators.
  pass->SetEstimatorToEquation1();
  return pass;
}

// Floor y = 0 (z in [-2, 4]) meeting a wall z = -2.
void CornerScene(vtkRenderer* renderer)
{
  const double f0[3] = { -4, 0, 4 }, f1[3] = { 4, 0, 4 }, f2[3] = { -4, 0, -2 };
  AddQuad(renderer, f0, f1, f2);
  const double w0[3] = { -4, 0, -2 }, w1[3] = { 4, 0, -2 }, w2[3] = { -4, 4, -2 };
  AddQuad(renderer, w0, w1, w2);
  SetCamera(renderer, 0.0, 2.5, 4.0, 0.0, 0.3, -1.5);
}

// Obscurance of a floor point at distance s r from an infinitely tall and
// wide wall (eq. 2 with beta = epsilon = 0, integrated over the hemisphere;
// the closed form of TestDeepGIReferenceObscurance).
double FloorBesideWallObscurance(double s)
{
  s = std::min(s, 1.0);
  const double pi = vtkMath::Pi();
  return (2.0 / pi) *
    (pi / 4.0 - 1.5 * s * std::sqrt(1.0 - s * s) - (0.5 + s * s) * std::asin(s) + 0.5 * pi * s * s);
}

// An estimator on the corner's floor against the closed form, in bins of
// r / 8 from the wall (see the top of the file): the largest bin error
// beyond r / 8 at most `far`, the nearest bin's at most `near`.
void TestCornerClosedForm(int estimator, double far, double near)
{
  const double radius = 1.0;
  auto pass = vtkSmartPointer<vtkDeepAmbientObscurancePass>::New();
  pass->SetRadius(radius);
  pass->SetEstimator(estimator);
  const char* name = vtkDeepAmbientObscurancePass::GetEstimatorAsString(estimator);
  Result r;
  if (!Render(CornerScene, pass, r))
  {
    return;
  }
  const int bins = 8;
  std::vector<double> sum(bins, 0.0), exact(bins, 0.0);
  std::vector<long> count(bins, 0);
  for (int j = 0; j < Height; ++j)
  {
    for (int i = 0; i < Width; ++i)
    {
      double p[3];
      if (!WorldPosition(r.Layers, 0, i, j, p) || std::abs(p[1]) > 1e-3 || std::abs(p[0]) > 2.0)
      {
        continue;
      }
      const double t = p[2] + 2.0;
      if (t < radius)
      {
        const int b = std::min(bins - 1, static_cast<int>(t / radius * bins));
        sum[b] += Value(r.AO, vtkDeepGICaptureNames::AmbientVisibility, i, j);
        exact[b] += 1.0 - FloorBesideWallObscurance(t / radius);
        ++count[b];
      }
    }
  }
  std::printf("corner, %s: mean AV / exact AV by distance from the wall (bins of r/8):", name);
  double worst = 0.0;
  for (int b = 0; b < bins; ++b)
  {
    const double n = std::max(count[b], 1L);
    std::printf(" %.3f/%.3f", sum[b] / n, exact[b] / n);
    worst = b > 0 ? std::max(worst, std::abs(sum[b] - exact[b]) / n) : worst;
    Check(count[b] > 0, "every distance bin has pixels");
  }
  const double nearest = (sum[0] - exact[0]) / std::max(count[0], 1L);
  std::printf(
    "\ncorner, %s: nearest bin %+.3f, largest error beyond it %.3f\n", name, nearest, worst);
  Check(worst <= far, "AV near the closed form beyond r / 8");
  Check(std::abs(nearest) <= near, "AV near the closed form within r / 8");
  pass->ReleaseGraphicsResources(r.Window);
}

// A wall z = 0 with, 1.5 r in front of it, a thin plate (one quad) on the
// left and, on the right, a closed box whose back face is 0.05 r from the
// wall; camera facing the wall.
void PlateAndBoxScene(vtkRenderer* renderer)
{
  const double w0[3] = { -4, -3, 0 }, w1[3] = { 4, -3, 0 }, w2[3] = { -4, 3, 0 };
  AddQuad(renderer, w0, w1, w2);
  const double p0[3] = { -2.5, -0.5, 1.5 }, p1[3] = { -1.5, -0.5, 1.5 }, p2[3] = { -2.5, 0.5, 1.5 };
  AddQuad(renderer, p0, p1, p2);
  const double c[3] = { 2.0, 0.0, 0.775 }, s[3] = { 1.0, 1.0, 1.45 };
  AddBox(renderer, c, s);
  SetCamera(renderer, 0.0, 0.0, 9.0, 0.0, 0.0, 0.0);
}

// Mean filtered AV of the wall pixels whose point lies 0.15 to 0.4 (world
// units, per axis) outside the unit square around (cx, 0).
double WallBandVisibility(const Result& r, double cx)
{
  double sum = 0.0;
  long count = 0;
  for (int j = 0; j < Height; ++j)
  {
    for (int i = 0; i < Width; ++i)
    {
      double p[3];
      if (!WorldPosition(r.Layers, 0, i, j, p) || std::abs(p[2]) > 1e-3)
      {
        continue;
      }
      const double outside = std::max(std::abs(p[0] - cx), std::abs(p[1])) - 0.5;
      if (outside > 0.15 && outside < 0.4)
      {
        sum += Value(r.AO, vtkDeepGICaptureNames::AmbientVisibility, i, j);
        ++count;
      }
    }
  }
  Check(count > 100, "the wall band has pixels");
  return sum / std::max(count, 1L);
}

// VISIBILITY_BITMASK reads how deep the layers' surfaces are (r = 1): the
// plate, 1.5 r from the wall and one layer thick, does not darken the wall
// around it, which a height field (one layer: everything behind a surface
// solid) does; the box, which layers 0 and 1 show entering and leaving,
// darkens the wall around it (its sides are within 0.4 r).
void TestSolidsAndThinSurfaces()
{
  auto twoLayers = vtkSmartPointer<vtkDeepAmbientObscurancePass>::New();
  twoLayers->SetRadius(1.0);
  auto heightField = vtkSmartPointer<vtkDeepAmbientObscurancePass>::New();
  heightField->SetRadius(1.0);
  heightField->UseSecondLayerOff();
  Result a, b;
  if (!Render(PlateAndBoxScene, twoLayers, a) || !Render(PlateAndBoxScene, heightField, b))
  {
    return;
  }
  const double plate = WallBandVisibility(a, -2.0), box = WallBandVisibility(a, 2.0);
  const double plateOneLayer = WallBandVisibility(b, -2.0);
  std::printf("wall around the plate: AV %.3f (one layer %.3f); around the box: AV %.3f\n", plate,
    plateOneLayer, box);
  Check(plate >= 0.97, "a thin plate 1.5 r away leaves the wall unobscured");
  Check(plateOneLayer <= plate - 0.03, "a height field darkens the wall behind the plate");
  Check(box <= plate - 0.1, "the box, a solid up to the wall, obscures the wall around it");
  twoLayers->ReleaseGraphicsResources(a.Window);
  heightField->ReleaseGraphicsResources(b.Window);
}

void TestPlane(bool parallel)
{
  auto pass = MakePass(1.0);
  Result r;
  if (!Render(
        [&](vtkRenderer* ren)
        {
          const double o[3] = { -20, 0, -20 }, p1[3] = { 20, 0, -20 }, p2[3] = { -20, 0, 20 };
          AddQuad(ren, o, p1, p2);
          SetCamera(ren, 0.0, 3.0, 4.0, 0.0, 0.0, -2.0, parallel);
        },
        pass, r))
  {
    return;
  }
  long valid = 0;
  double worst = 0.0;
  for (int j = 0; j < Height; ++j)
  {
    for (int i = 0; i < Width; ++i)
    {
      if (Value(r.AO, vtkDeepGICaptureNames::Valid, i, j) == 0)
      {
        continue;
      }
      ++valid;
      worst = std::max(worst, 1.0 - Value(r.AO, vtkDeepGICaptureNames::RawAmbientVisibility, i, j));
      worst = std::max(worst, 1.0 - Value(r.AO, vtkDeepGICaptureNames::AmbientVisibility, i, j));
    }
  }
  std::printf("plane (%s): %ld valid pixels, max 1 - AV = %.2e\n",
    parallel ? "parallel" : "perspective", valid, worst);
  Check(valid > Width * Height / 2, "plane covers the image");
  Check(worst <= 1e-3, "unoccluded plane has AV = 1");
  pass->ReleaseGraphicsResources(r.Window);
}

void TestCorner()
{
  const double radius = 1.0;
  auto pass = MakePass(radius);
  Result r;
  if (!Render(CornerScene, pass, r))
  {
    return;
  }
  // CPU reference of the raw AV.
  long compared = 0, mismatched = 0;
  double meanDifference = 0.0, maxDifference = 0.0;
  const int layerCount =
    r.Layers->GetFieldData()->GetArray(vtkDeepGICaptureNames::NumberOfLayers)->GetTuple1(0);
  vtkNew<vtkImageData> pyramid;
  Check(pass->CaptureDistancePyramid(0, pyramid, r.Renderer), "capture the distance pyramid");
  const int levels = static_cast<int>(
    pyramid->GetFieldData()->GetArray(vtkDeepGICaptureNames::NumberOfMipLevels)->GetTuple1(0));
  std::printf("corner: %d pyramid levels\n", levels);
  for (int j = 0; j < Height; ++j)
  {
    for (int i = 0; i < Width; ++i)
    {
      if (Value(r.AO, vtkDeepGICaptureNames::Valid, i, j) == 0)
      {
        continue;
      }
      const double reference = ReferenceAV(r.Layers, i, j, layerCount, pass->GetNumberOfSamples(),
        radius, pass->GetBias() * radius, pass->GetEpsilon() * radius * radius,
        pass->GetMipThreshold(), levels);
      const double d =
        std::abs(reference - Value(r.AO, vtkDeepGICaptureNames::RawAmbientVisibility, i, j));
      ++compared;
      mismatched += d > 2e-3 ? 1 : 0;
      meanDifference += d;
      maxDifference = std::max(maxDifference, d);
    }
  }
  meanDifference /= std::max(compared, 1L);
  std::printf("corner: CPU reference vs GPU raw AV over %ld pixels: mean %.2e, max %.2e, "
              "%ld above 2e-3\n",
    compared, meanDifference, maxDifference, mismatched);
  Check(compared > 0 && mismatched <= compared / 100, "raw AV matches the CPU reference");

  // AV against the distance t from the wall, floor pixels only.
  const int bins = 8;
  std::vector<double> sum(bins, 0.0);
  std::vector<long> count(bins, 0);
  double farWorstRaw = 0.0, farWorstFiltered = 0.0;
  long far = 0;
  for (int j = 0; j < Height; ++j)
  {
    for (int i = 0; i < Width; ++i)
    {
      double p[3];
      if (!WorldPosition(r.Layers, 0, i, j, p) || std::abs(p[1]) > 1e-3 || std::abs(p[0]) > 3.0)
      {
        continue;
      }
      const double t = p[2] + 2.0;
      if (t < radius)
      {
        const int b = std::min(bins - 1, static_cast<int>(t / radius * bins));
        sum[b] += Value(r.AO, vtkDeepGICaptureNames::AmbientVisibility, i, j);
        ++count[b];
      }
      if (t > 1.02 * radius)
      {
        farWorstRaw = std::max(
          farWorstRaw, 1.0 - Value(r.AO, vtkDeepGICaptureNames::RawAmbientVisibility, i, j));
      }
      if (t > 1.5 * radius)
      {
        ++far;
        farWorstFiltered = std::max(
          farWorstFiltered, 1.0 - Value(r.AO, vtkDeepGICaptureNames::AmbientVisibility, i, j));
      }
    }
  }
  std::printf("corner: mean AV by distance from the wall (bins of r/8):");
  double previous = -1.0;
  bool monotonic = true;
  for (int b = 0; b < bins; ++b)
  {
    const double mean = count[b] ? sum[b] / count[b] : -1.0;
    std::printf(" %.3f", mean);
    Check(count[b] > 0, "every distance bin has pixels");
    monotonic = monotonic && mean >= previous - 0.02;
    previous = mean;
  }
  std::printf("\ncorner: far floor (%ld px): max 1 - AV raw %.2e (t > 1.02 r), filtered %.2e "
              "(t > 1.5 r)\n",
    far, farWorstRaw, farWorstFiltered);
  Check(count[0] > 0 && sum[0] / count[0] < 0.8, "AV well below 1 at the corner");
  Check(monotonic, "AV increases with the distance from the corner");
  Check(far > 100 && farWorstRaw <= 1e-3 && farWorstFiltered <= 1e-3, "AV = 1 far from the corner");

  // Composite: the AO image is the plain G-buffer image times AV.
  vtkNew<vtkImageData> rgbAO, depthAO, rgbPlain, depthPlain;
  ReadWindow(r.Window, rgbAO, depthAO);
  pass->ReleaseGraphicsResources(r.Window);
  {
    auto window = MakeWindow(Width, Height);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    CornerScene(renderer);
    renderer->ResetCameraClippingRange();
    vtkNew<vtkDeepGBufferPass> plain;
    renderer->SetPass(plain);
    for (int f = 0; f < 3; ++f)
    {
      window->Render();
    }
    ReadWindow(window, rgbPlain, depthPlain);
    plain->ReleaseGraphicsResources(window);
  }
  double worstColor = 0.0, worstDepth = 0.0;
  vtkDataArray* a = rgbAO->GetPointData()->GetScalars();
  vtkDataArray* b = rgbPlain->GetPointData()->GetScalars();
  for (vtkIdType p = 0; p < a->GetNumberOfTuples(); ++p)
  {
    const double av =
      r.AO->GetPointData()->GetArray(vtkDeepGICaptureNames::AmbientVisibility)->GetTuple1(p);
    for (int c = 0; c < 3; ++c)
    {
      worstColor =
        std::max(worstColor, std::abs(a->GetComponent(p, c) - b->GetComponent(p, c) * av));
    }
    worstDepth = std::max(worstDepth,
      std::abs(depthAO->GetPointData()->GetScalars()->GetTuple1(p) -
        depthPlain->GetPointData()->GetScalars()->GetTuple1(p)));
  }
  std::printf("composite: max |AO image - plain image x AV| = %.2f levels, max depth difference "
              "%.2e\n",
    worstColor, worstDepth);
  Check(worstColor <= 2.0, "composite = plain image x AV");
  Check(worstDepth <= 1e-6, "composite writes layer-0 depth");
}

void TestNoBleed()
{
  const double radius = 1.0;
  auto pass = MakePass(radius);
  const int R = pass->GetBlurRadius();
  Result r;
  if (!Render(
        [](vtkRenderer* ren)
        {
          const double o[3] = { -20, -20, 0 }, p1[3] = { 20, -20, 0 }, p2[3] = { -20, 20, 0 };
          AddQuad(ren, o, p1, p2);
          const double q0[3] = { -1, -1, 0.3 }, q1[3] = { 1, -1, 0.3 }, q2[3] = { -1, 1, 0.3 };
          AddQuad(ren, q0, q1, q2);
          SetCamera(ren, 0.0, 0.0, 10.0, 0.0, 0.0, 0.0);
        },
        pass, r))
  {
    return;
  }
  auto depth = [&](int i, int j)
  {
    return Layer(r.Layers, vtkDeepGICaptureNames::Depth, 0)
      ->GetTuple1(static_cast<vtkIdType>(j) * Width + i);
  };
  auto onQuad = [&](int i, int j) { return depth(i, j) < 9.85; };
  double quadWorst = 0.0, worstEscape = 0.0, nearPlaneMax = 0.0;
  long planeChecked = 0, quadPixels = 0;
  for (int j = R; j < Height - R; ++j)
  {
    for (int i = R; i < Width - R; ++i)
    {
      if (onQuad(i, j))
      {
        ++quadPixels;
        quadWorst =
          std::max(quadWorst, 1.0 - Value(r.AO, vtkDeepGICaptureNames::AmbientVisibility, i, j));
        quadWorst =
          std::max(quadWorst, 1.0 - Value(r.AO, vtkDeepGICaptureNames::RawAmbientVisibility, i, j));
        continue;
      }
      // Plane pixels within 2 px of the silhouette.
      bool adjacent = false;
      for (int dj = -2; dj <= 2 && !adjacent; ++dj)
      {
        for (int di = -2; di <= 2 && !adjacent; ++di)
        {
          adjacent = onQuad(i + di, j + dj);
        }
      }
      if (!adjacent)
      {
        continue;
      }
      double lo = 1e30, hi = -1e30;
      for (int dj = -R; dj <= R; ++dj)
      {
        for (int di = -R; di <= R; ++di)
        {
          if (!onQuad(i + di, j + dj))
          {
            const double v =
              Value(r.AO, vtkDeepGICaptureNames::RawAmbientVisibility, i + di, j + dj);
            lo = std::min(lo, v);
            hi = std::max(hi, v);
          }
        }
      }
      const double f = Value(r.AO, vtkDeepGICaptureNames::AmbientVisibility, i, j);
      worstEscape = std::max(worstEscape, std::max(lo - f, f - hi));
      nearPlaneMax = std::max(nearPlaneMax, hi);
      ++planeChecked;
    }
  }
  std::printf("no bleed: quad %ld px, max 1 - AV %.2e; %ld plane px at the silhouette, largest "
              "raw AV in their windows %.3f, worst escape from the window's range %.2e\n",
    quadPixels, quadWorst, planeChecked, nearPlaneMax, worstEscape);
  Check(quadPixels > 100 && quadWorst <= 1e-3, "quad keeps AV = 1 after filtering");
  Check(planeChecked > 100 && nearPlaneMax < 0.95, "plane is obscured at the silhouette");
  Check(worstEscape <= 1e-5, "filtered plane values stay within their surface's range");
  pass->ReleaseGraphicsResources(r.Window);
}

// One direction of the bilateral filter of vtkDeepAmbientObscuranceBlurFS
// in double precision: input (Width x Height) -> output along `axis`.
void FilterOneAxis(vtkImageData* layers, const std::vector<double>& input, int axis, int radius,
  double tolerance, double power, std::vector<double>& output)
{
  vtkDataArray* normals = Layer(layers, vtkDeepGICaptureNames::Normal, 0);
  const double sigma = std::max(0.5 * radius, 0.5);
  output = input;
  for (int j = 0; j < Height; ++j)
  {
    for (int i = 0; i < Width; ++i)
    {
      double X[3], n[3];
      if (!CameraPosition(layers, 0, i, j, X))
      {
        continue;
      }
      normals->GetTuple(static_cast<vtkIdType>(j) * Width + i, n);
      double sum = input[j * Width + i], weights = 1.0;
      for (int k = -radius; k <= radius; ++k)
      {
        const int ti = axis == 0 ? i + k : i, tj = axis == 0 ? j : j + k;
        double Y[3], nY[3];
        if (k == 0 || ti < 0 || tj < 0 || ti >= Width || tj >= Height ||
          !CameraPosition(layers, 0, ti, tj, Y))
        {
          continue;
        }
        normals->GetTuple(static_cast<vtkIdType>(tj) * Width + ti, nY);
        const double YX[3] = { Y[0] - X[0], Y[1] - X[1], Y[2] - X[2] };
        const double plane =
          std::max(0.0, 1.0 - std::abs(vtkMath::Dot(YX, n)) / (tolerance * -X[2]));
        const double facing = std::max(0.0, vtkMath::Dot(n, nY));
        const double w = std::exp(-k * k / (2.0 * sigma * sigma)) * plane *
          (power > 0.0 ? std::pow(facing, power) : 1.0);
        sum += w * input[tj * Width + ti];
        weights += w;
      }
      output[j * Width + i] = sum / weights;
    }
  }
}

void SphereOnFloorScene(vtkRenderer* renderer)
{
  const double f0[3] = { -4, 0, 4 }, f1[3] = { 4, 0, 4 }, f2[3] = { -4, 0, -4 };
  AddQuad(renderer, f0, f1, f2);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0.0, 1.0, 0.0);
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(96);
  sphere->SetPhiResolution(48);
  AddSourceActor(renderer, sphere);
  SetCamera(renderer, 0.0, 2.5, 5.0, 0.0, 0.6, 0.0);
}

// Compares the captured filtered AV with the CPU filter of the captured raw
// AV for `power`; returns the filtered AV.
std::vector<double> CheckFilter(const Result& r, vtkDeepAmbientObscurancePass* pass, double power)
{
  std::vector<double> raw(Width * Height), horizontal, filtered, gpu(Width * Height);
  for (int j = 0; j < Height; ++j)
  {
    for (int i = 0; i < Width; ++i)
    {
      raw[j * Width + i] = Value(r.AO, vtkDeepGICaptureNames::RawAmbientVisibility, i, j);
      gpu[j * Width + i] = Value(r.AO, vtkDeepGICaptureNames::AmbientVisibility, i, j);
    }
  }
  const int R = pass->GetBlurRadius();
  const double tolerance = pass->GetBlurPlaneTolerance();
  FilterOneAxis(r.Layers, raw, 0, R, tolerance, power, horizontal);
  FilterOneAxis(r.Layers, horizontal, 1, R, tolerance, power, filtered);
  double sum = 0.0;
  long off = 0;
  for (size_t k = 0; k < gpu.size(); ++k)
  {
    const double difference = std::abs(gpu[k] - filtered[k]);
    sum += difference;
    off += difference > 1e-5 ? 1 : 0;
  }
  const double mean = sum / (Width * Height);
  const double darkest = *std::min_element(gpu.begin(), gpu.end());
  std::printf("filter, BlurNormalPower %g: mean |GPU - CPU| %.2e, %ld px off by > 1e-5, "
              "darkest AV %.3f\n",
    power, mean, off, darkest);
  Check(darkest < 0.8, "the sphere obscures the floor");
  Check(mean <= 1e-6 && off <= Width * Height / 200, "filtered AV matches the CPU filter");
  return gpu;
}

// One pass and one window, the exponent changed between frames: each new
// value rebuilds the filter's shader.
void TestFilterAgainstCPU()
{
  auto pass = MakePass(0.8);
  Result r;
  if (!Render(SphereOnFloorScene, pass, r))
  {
    return;
  }
  std::vector<double> powerEight;
  double powerSeen = 0.0;
  for (const double power : { 8.0, 3.0, 2.5, 0.0 })
  {
    pass->SetBlurNormalPower(power);
    r.Window->Render();
    Check(pass->CaptureAmbientVisibility(r.AO, r.Renderer), "capture");
    const std::vector<double> gpu = CheckFilter(r, pass, power);
    if (power == 8.0)
    {
      powerEight = gpu;
    }
    for (size_t k = 0; k < gpu.size(); ++k)
    {
      powerSeen = std::max(powerSeen, std::abs(gpu[k] - powerEight[k]));
    }
  }
  std::printf("filter: largest |AV(power 8) - AV(other powers)| %.3f\n", powerSeen);
  Check(powerSeen > 0.01, "the normal weight's power changes the filtered AV");
  pass->ReleaseGraphicsResources(r.Window);
}

void ColumnScene(vtkRenderer* renderer)
{
  const double f0[3] = { -4, 0, 4 }, f1[3] = { 4, 0, 4 }, f2[3] = { -4, 0, -2 };
  AddQuad(renderer, f0, f1, f2);
  const double w0[3] = { -4, 0, -2 }, w1[3] = { 4, 0, -2 }, w2[3] = { -4, 3, -2 };
  AddQuad(renderer, w0, w1, w2);
  const double c[3] = { 0.0, 1.5, 0.0 }, s[3] = { 0.8, 3.0, 0.8 };
  AddBox(renderer, c, s);
  SetCamera(renderer, 0.0, 1.5, 6.0, 0.0, 0.7, -1.0);
}

void TestSecondLayer()
{
  auto on = MakePass(2.5);
  auto off = MakePass(2.5);
  off->UseSecondLayerOff();
  Result a, b;
  if (!Render(ColumnScene, on, a) || !Render(ColumnScene, off, b))
  {
    return;
  }
  long lower = 0, higher = 0;
  double worstHigher = 0.0, largestGain = 0.0;
  for (int j = 0; j < Height; ++j)
  {
    for (int i = 0; i < Width; ++i)
    {
      if (Value(a.AO, vtkDeepGICaptureNames::Valid, i, j) == 0)
      {
        continue;
      }
      const double d = Value(a.AO, vtkDeepGICaptureNames::RawAmbientVisibility, i, j) -
        Value(b.AO, vtkDeepGICaptureNames::RawAmbientVisibility, i, j);
      higher += d > 1e-5 ? 1 : 0;
      worstHigher = std::max(worstHigher, d);
      lower += d < -0.02 ? 1 : 0;
      largestGain = std::max(largestGain, -d);
    }
  }
  std::printf("second layer: %ld px darker by > 0.02 (largest %.3f), %ld px brighter (worst "
              "%.2e)\n",
    lower, largestGain, higher, worstHigher);
  Check(higher == 0, "more layers never raise the raw AV");
  Check(lower > 50, "the second layer adds occlusion behind the column");
  on->ReleaseGraphicsResources(a.Window);
  off->ReleaseGraphicsResources(b.Window);
}

void TestSampleCountsAndRelease()
{
  for (int n : { 1, 99 })
  {
    auto pass = MakePass(1.0);
    pass->SetNumberOfSamples(n);
    Result r;
    if (Render(CornerScene, pass, r))
    {
      std::printf("N = %d (used %d): finite\n", n, pass->GetNumberOfSamples());
    }
    pass->ReleaseGraphicsResources(r.Window);
  }

  auto pass = MakePass(1.0);
  Result r;
  if (!Render(CornerScene, pass, r))
  {
    return;
  }
  pass->ReleaseGraphicsResources(r.Window);
  vtkNew<vtkImageData> failed;
  // Nothing to capture after the release (an error is expected, not a crash).
  pass->GlobalWarningDisplayOff();
  Check(!pass->CaptureAmbientVisibility(failed, r.Renderer), "no capture after release");
  pass->GlobalWarningDisplayOn();
  r.Window->Render();
  vtkNew<vtkImageData> again;
  Check(pass->CaptureAmbientVisibility(again, r.Renderer), "capture after release and render");
  double worst = 0.0;
  vtkDataArray* x = r.AO->GetPointData()->GetArray(vtkDeepGICaptureNames::AmbientVisibility);
  vtkDataArray* y = again->GetPointData()->GetArray(vtkDeepGICaptureNames::AmbientVisibility);
  for (vtkIdType p = 0; y && p < x->GetNumberOfTuples(); ++p)
  {
    worst = std::max(worst, std::abs(x->GetTuple1(p) - y->GetTuple1(p)));
  }
  std::printf("release and render again: max AV difference %.2e\n", worst);
  Check(y && worst <= 1e-6, "same AV after ReleaseGraphicsResources");
  pass->ReleaseGraphicsResources(r.Window);
}
}

int TestDeepAmbientObscurance(int, char*[])
{
  TestPlane(false);
  TestPlane(true);
  TestCorner();
  TestCornerClosedForm(vtkDeepAmbientObscurancePass::VISIBILITY_BITMASK, 0.04, 0.08);
  TestCornerClosedForm(vtkDeepAmbientObscurancePass::SOLID_ANGLE, 0.03, 0.15);
  TestSolidsAndThinSurfaces();
  TestNoBleed();
  TestFilterAgainstCPU();
  TestSecondLayer();
  TestSampleCountsAndRelease();
  return ExitStatus();
}
