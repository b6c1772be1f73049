// Tests vtkDeepGIReferenceIrradiance, the Embree ground truth of one-bounce
// diffuse indirect irradiance, on synthetic captures (no rendering): every
// pixel of a camera looking straight down at the plane z = 0 gets the plane's
// exact depth and the normal +z; the plane itself is not part of the scene
// unless a test adds it.
//
//  1. analytic: a horizontal square (half side s) at height h facing down,
//     lit from below by a directional light with n.l = 1, so L = rho I; for a
//     point under it E = pi L F with F the view factor of the parallel
//     rectangles (closed form, four corner rectangles). Per pixel and channel
//     |E - exact| < 4.5 SE + 1e-6, mean difference within 4 SE of the mean.
//     The same square wound the other way (seen from behind) gives the same E
//     with TwoSidedLighting on and E = 0 with it off; point normals that
//     point up (away from the light) give E = 0 (the shading normal is used).
//     MaximumDistance r: E = 0 for r < h, and E = pi L R^2 / (R^2 + h^2),
//     R^2 = r^2 - h^2 (a coaxial disc) where that disc lies inside the square;
//  2. a white floor beside a red wall: E red (r > g, b), larger near the wall;
//  3. a roof shading the wall: with Shadows on the wall is dark and E = 0,
//     with Shadows off E is the lit wall's;
//  4. two seeds agree within 4.5 combined standard errors;
//  5. scenes, cameras and lights scaled by 1e-4 and 1e4 (and moved away from
//     the origin): the same E within noise;
//  6. lights from a vtkRenderer (headlight, camera light, scene light, a
//     switched-off light, automatic headlight); bad input: no lights (warning,
//     E = 0), no scene, NaN and negative MaximumDistance (errors).

#include "DeepGIReferenceTestUtilities.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIReferenceIrradiance.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

using namespace DeepGIReferenceTest;
using namespace DeepGITest;

namespace
{
// Lengths of a test are multiplied by Scale and shifted by Shift.
struct Frame
{
  double Scale = 1.0;
  double Shift[3] = { 0, 0, 0 };
  void Apply(const double in[3], double out[3]) const
  {
    for (int c = 0; c < 3; ++c)
    {
      out[c] = in[c] * this->Scale + this->Shift[c];
    }
  }
};

// A scene of quads, each with an RGB colour (cell data "Colors").
class SceneBuilder
{
public:
  explicit SceneBuilder(const Frame& f)
    : F(f)
  {
    this->Colors->SetName("Colors");
    this->Colors->SetNumberOfComponents(3);
  }
  void Quad(const std::array<std::array<double, 3>, 4>& corners, const unsigned char rgb[3])
  {
    vtkIdType ids[4];
    for (int k = 0; k < 4; ++k)
    {
      double p[3];
      this->F.Apply(corners[k].data(), p);
      ids[k] = this->Points->InsertNextPoint(p);
    }
    this->Polys->InsertNextCell(4, ids);
    this->Colors->InsertNextTypedTuple(rgb);
  }
  vtkSmartPointer<vtkPolyData> Build()
  {
    auto scene = vtkSmartPointer<vtkPolyData>::New();
    scene->SetPoints(this->Points);
    scene->SetPolys(this->Polys);
    scene->GetCellData()->AddArray(this->Colors);
    return scene;
  }

private:
  Frame F;
  vtkNew<vtkPoints> Points;
  vtkNew<vtkCellArray> Polys;
  vtkNew<vtkUnsignedCharArray> Colors;
};

// A w x h capture of the plane z = 0 seen from (cx, cy, height) looking down
// (perspective, 40 degrees) with exact depth, normal +z and Albedo_0;
// positions receives each pixel's unscaled point.
vtkSmartPointer<vtkImageData> MakeCapture(const Frame& f, int w, int h, double cx, double cy,
  double height, const double albedo[3], std::vector<std::array<double, 3>>& positions)
{
  vtkNew<vtkCamera> camera;
  const double eye[3] = { cx, cy, height }, target[3] = { cx, cy, 0 };
  double e[3], t[3];
  f.Apply(eye, e);
  f.Apply(target, t);
  camera->SetPosition(e);
  camera->SetFocalPoint(t);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(40.0);
  camera->SetClippingRange(0.1 * height * f.Scale, 2.0 * height * f.Scale);
  Layer0Capture capture(w, h, camera);
  vtkMatrix4x4* view = capture.View;
  vtkMatrix4x4* inverseView = capture.InverseView;
  vtkMatrix4x4* inverseProjection = capture.InverseProjection;
  vtkFloatArray* depth = capture.Depth;
  vtkFloatArray* normal = capture.Normal;
  vtkFloatArray* alb = capture.Albedo;
  vtkUnsignedCharArray* valid = capture.Valid;
  positions.assign(w * h, { 0, 0, 0 });
  double up[4] = { 0, 0, 1, 0 }, nc[4];
  view->MultiplyPoint(up, nc);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      const vtkIdType p = j * w + i;
      double a[4] = { (i + 0.5) / w * 2 - 1, (j + 0.5) / h * 2 - 1, -1, 1 };
      double b[4] = { a[0], a[1], 1, 1 };
      inverseProjection->MultiplyPoint(a, a);
      inverseProjection->MultiplyPoint(b, b);
      for (int c = 0; c < 3; ++c)
      {
        a[c] /= a[3];
        b[c] /= b[3];
      }
      a[3] = b[3] = 1.0;
      double wa[4], wb[4];
      inverseView->MultiplyPoint(a, wa);
      inverseView->MultiplyPoint(b, wb);
      const double s = (f.Shift[2] - wa[2]) / (wb[2] - wa[2]);
      double x[4] = { 0, 0, 0, 1 }, xc[4];
      for (int c = 0; c < 3; ++c)
      {
        x[c] = wa[c] + s * (wb[c] - wa[c]);
      }
      view->MultiplyPoint(x, xc);
      depth->SetValue(p, static_cast<float>(-xc[2]));
      valid->SetValue(p, 1);
      for (int c = 0; c < 3; ++c)
      {
        normal->SetComponent(p, c, nc[c]);
        alb->SetComponent(p, c, albedo[c]);
        positions[p][c] = (x[c] - f.Shift[c]) / f.Scale;
      }
    }
  }
  return capture.Image;
}

vtkFloatArray* Array(vtkDeepGIReferenceIrradiance* reference, const char* name)
{
  return vtkFloatArray::SafeDownCast(reference->GetOutput()->GetPointData()->GetArray(name));
}

// Compares E per pixel and channel with exact(p, c); returns the number of
// compared values.
int CompareExact(vtkDeepGIReferenceIrradiance* reference,
  const std::function<double(vtkIdType, int)>& exact, const std::string& what)
{
  vtkFloatArray* e = Array(reference, "IndirectIrradiance");
  vtkFloatArray* se = Array(reference, "IndirectIrradianceStandardError");
  if (!e || !se)
  {
    Check(false, what + ": output arrays missing");
    return 0;
  }
  int n = 0, bad = 0;
  double sumDiff = 0, sumVar = 0, maxRatio = 0;
  for (vtkIdType p = 0; p < e->GetNumberOfTuples(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double x = exact(p, c);
      if (!(x >= 0))
      {
        continue; // not comparable here
      }
      const double diff = e->GetComponent(p, c) - x;
      const double tolerance = 4.5 * se->GetComponent(p, c) + 1e-6;
      bad += std::fabs(diff) > tolerance;
      maxRatio = std::max(maxRatio, std::fabs(diff) / tolerance);
      sumDiff += diff;
      sumVar += se->GetComponent(p, c) * se->GetComponent(p, c);
      ++n;
    }
  }
  const double meanDiff = n ? sumDiff / n : 0, meanSE = n ? std::sqrt(sumVar) / n : 0;
  std::cout << what << ": " << n << " values, mean E - exact " << meanDiff
            << " (its standard error " << meanSE << "), max |diff| / tolerance " << maxRatio
            << ", mean SE " << reference->GetMeanStandardError() << ", "
            << reference->GetComputeTime() << " s\n";
  Check(n > 0, what + ": values compared");
  Check(bad == 0, what + ": " + std::to_string(bad) + " values beyond 4.5 standard errors");
  Check(std::fabs(meanDiff) < 4 * meanSE + 1e-6, what + ": mean difference within 4 SE");
  return n;
}

double MaxIrradiance(vtkDeepGIReferenceIrradiance* reference)
{
  vtkFloatArray* e = Array(reference, "IndirectIrradiance");
  double m = 0;
  for (vtkIdType i = 0; e && i < e->GetNumberOfValues(); ++i)
  {
    m = std::max(m, static_cast<double>(std::fabs(e->GetValue(i))));
  }
  return e ? m : -1;
}

// Scene of test 1: the square [-s, s]^2 at height h, facing down (or up).
const double SquareHalf = 2.0, SquareHeight = 1.0;
const unsigned char SquareColor[3] = { 200, 100, 50 };
const double LightColor[3] = { 1.0, 0.9, 0.7 }, LightIntensity = 0.8;

vtkSmartPointer<vtkPolyData> SquareScene(const Frame& f, bool facingDown)
{
  SceneBuilder b(f);
  const double s = SquareHalf, h = SquareHeight;
  if (facingDown)
  {
    b.Quad({ { { -s, -s, h }, { -s, s, h }, { s, s, h }, { s, -s, h } } }, SquareColor);
  }
  else
  {
    b.Quad({ { { -s, -s, h }, { s, -s, h }, { s, s, h }, { -s, s, h } } }, SquareColor);
  }
  return b.Build();
}

// A scene light; directional lights shine from `from` towards `to`.
vtkSmartPointer<vtkLight> SceneLight(const Frame& f, const double from[3], const double to[3],
  bool positional, double intensity, const double color[3])
{
  auto light = vtkSmartPointer<vtkLight>::New();
  light->SetLightTypeToSceneLight();
  double p[3], q[3];
  f.Apply(from, p);
  f.Apply(to, q);
  light->SetPosition(p);
  light->SetFocalPoint(q);
  light->SetPositional(positional);
  light->SetConeAngle(180);
  light->SetIntensity(intensity);
  light->SetDiffuseColor(color[0], color[1], color[2]);
  return light;
}

// Wall scene of tests 2-5: white floor z = 0 for x > 0 (not seen from floor
// points, it is their own plane), red wall x = 0 (height 2, facing +x),
// optionally a roof at z = 5 over x in [-1, 6] facing up.
const unsigned char White[3] = { 255, 255, 255 };
const unsigned char Red[3] = { 160, 17, 13 }; // Cornell box red .63/.065/.05

vtkSmartPointer<vtkPolyData> WallScene(const Frame& f, bool roof)
{
  SceneBuilder b(f);
  const double e = 20;
  b.Quad({ { { 0, -e, 0 }, { e, -e, 0 }, { e, e, 0 }, { 0, e, 0 } } }, White);
  b.Quad({ { { 0, -e, 0 }, { 0, e, 0 }, { 0, e, 2 }, { 0, -e, 2 } } }, Red);
  if (roof)
  {
    b.Quad({ { { -1, -e, 5 }, { 6, -e, 5 }, { 6, e, 5 }, { -1, e, 5 } } }, White);
  }
  return b.Build();
}

const double White3[3] = { 1, 1, 1 };
const double AlbedoX[3] = { 0.5, 0.6, 0.7 };
const double Below[3] = { 0, 0, -1 }, Origin[3] = { 0, 0, 0 };
const double SunFrom[3] = { 1, 0, 1 };

// Test 1's directional light below the square, n.l = 1.
vtkSmartPointer<vtkLight> SquareLight(const Frame& f)
{
  return SceneLight(f, Below, Origin, false, LightIntensity, LightColor);
}

// Test 1's capture of the plane under the square and the closed form of E
// there: E = pi L F, L = rho I, F the view factor of the parallel square.
struct SquareCase
{
  explicit SquareCase(const Frame& f)
  {
    this->Capture = MakeCapture(f, 16, 16, 0.3, -0.2, 3.0, AlbedoX, this->Positions);
    for (int c = 0; c < 3; ++c)
    {
      this->L[c] = SquareColor[c] / 255.0 * LightIntensity * LightColor[c];
    }
  }
  double Exact(vtkIdType p, int c) const
  {
    return vtkMath::Pi() * this->L[c] *
      SquareViewFactor(this->Positions[p][0], this->Positions[p][1], SquareHalf, SquareHeight);
  }
  std::function<double(vtkIdType, int)> ExactFunction() const
  {
    return [this](vtkIdType p, int c) { return this->Exact(p, c); };
  }
  std::vector<std::array<double, 3>> Positions;
  vtkSmartPointer<vtkImageData> Capture;
  double L[3];
};

vtkSmartPointer<vtkDeepGIReferenceIrradiance> MakeReference(
  vtkPolyData* scene, vtkLight* light, int samplesPerPixel)
{
  auto reference = vtkSmartPointer<vtkDeepGIReferenceIrradiance>::New();
  reference->SetSceneData(scene);
  reference->AddLight(light);
  reference->SetSamplesPerPixel(samplesPerPixel);
  return reference;
}

// 1. Analytic: parallel square lit from below; IndirectRadiance = rho_X E / pi.
void CheckSquareMatchesClosedForm(vtkDeepGIReferenceIrradiance* reference, const SquareCase& square)
{
  Check(Estimate(reference, square.Capture), "square: update");
  CompareExact(reference, square.ExactFunction(), "square facing down (closed form)");
  vtkFloatArray* e = Array(reference, "IndirectIrradiance");
  vtkFloatArray* l = Array(reference, vtkDeepGICaptureNames::IndirectRadiance);
  double maxError = l ? 0 : 1;
  for (vtkIdType p = 0; l && p < e->GetNumberOfTuples(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      maxError = std::max(maxError,
        std::fabs(l->GetComponent(p, c) - AlbedoX[c] * e->GetComponent(p, c) / vtkMath::Pi()));
    }
  }
  Check(maxError < 1e-6,
    "IndirectRadiance = rho_X E / pi (max error " + std::to_string(maxError) + ")");
}

// Seen from behind: two-sided lighting flips the normal (same E), one-sided
// lighting makes it black.
void CheckBackFacesFollowTwoSidedLighting(const SquareCase& square)
{
  const Frame unit;
  auto back = MakeReference(SquareScene(unit, false), SquareLight(unit), 1024);
  Check(Estimate(back, square.Capture), "square from behind: update");
  CompareExact(back, square.ExactFunction(), "square facing up, two-sided lighting (closed form)");
  back->TwoSidedLightingOff();
  Estimate(back, square.Capture);
  Check(MaxIrradiance(back) == 0.0, "square facing up, one-sided lighting: E = 0");
}

// Point normals are the shading normals: pointing up (away from the light
// below) they leave the front face unlit.
void CheckPointNormalsShade(const SquareCase& square)
{
  const Frame unit;
  auto scene = SquareScene(unit, true);
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  for (int k = 0; k < 4; ++k)
  {
    normals->InsertNextTuple3(0, 0, 1);
  }
  scene->GetPointData()->SetNormals(normals);
  auto shaded = MakeReference(scene, SquareLight(unit), 64);
  Estimate(shaded, square.Capture);
  Check(MaxIrradiance(shaded) == 0.0, "point normals facing away from the light: E = 0");
  for (int k = 0; k < 4; ++k)
  {
    normals->SetTuple3(k, 0, 0, -1);
  }
  normals->Modified();
  shaded->SetSamplesPerPixel(1024);
  Estimate(shaded, square.Capture);
  CompareExact(shaded, square.ExactFunction(), "point normals facing the light (closed form)");
}

// MaximumDistance: a coaxial disc of radius R = sqrt(r^2 - h^2).
void CheckMaximumDistanceLimitsToADisc(
  vtkDeepGIReferenceIrradiance* reference, const SquareCase& square)
{
  reference->SetMaximumDistance(0.9 * SquareHeight);
  Estimate(reference, square.Capture);
  Check(MaxIrradiance(reference) == 0.0, "MaximumDistance < h: E = 0");
  const double r = 1.6 * SquareHeight;
  const double r2 = r * r - SquareHeight * SquareHeight;
  reference->SetMaximumDistance(r);
  Estimate(reference, square.Capture);
  CompareExact(
    reference,
    [&](vtkIdType p, int c)
    {
      const double R = std::sqrt(r2);
      if (std::fabs(square.Positions[p][0]) + R >= SquareHalf ||
        std::fabs(square.Positions[p][1]) + R >= SquareHalf)
      {
        return -1.0; // the disc leaves the square
      }
      return vtkMath::Pi() * square.L[c] * r2 / (r2 + SquareHeight * SquareHeight);
    },
    "MaximumDistance 1.6 h (coaxial disc)");
  reference->SetMaximumDistance(std::numeric_limits<double>::infinity());
}

// A "Diffuse" field array scales rho_Y.
void CheckDiffuseFieldScalesReflectance(const SquareCase& square)
{
  const Frame unit;
  auto scene = SquareScene(unit, true);
  vtkNew<vtkDoubleArray> diffuse;
  diffuse->SetName("Diffuse");
  diffuse->InsertNextValue(0.5);
  scene->GetFieldData()->AddArray(diffuse);
  auto half = MakeReference(scene, SquareLight(unit), 1024);
  Estimate(half, square.Capture);
  CompareExact(
    half, [&](vtkIdType p, int c) { return 0.5 * square.Exact(p, c); },
    "field data Diffuse 0.5 (closed form)");
}

// Tests 2-5's capture of the white floor beside the red wall, in the sun
// from above +x, and its result with seed 1.
struct WallCase
{
  WallCase()
  {
    const Frame unit;
    this->Capture = MakeCapture(unit, 24, 8, 3.4, 0.0, 3.0, White3, this->Positions);
    this->Scene = WallScene(unit, false);
    this->Reference =
      MakeReference(this->Scene, SceneLight(unit, SunFrom, Origin, false, 1.0, White3), 1024);
    this->Reference->SetSeed(1);
    Check(Estimate(this->Reference, this->Capture), "wall: update");
    this->Result->DeepCopy(this->Reference->GetOutput());
  }
  std::vector<std::array<double, 3>> Positions;
  vtkSmartPointer<vtkImageData> Capture;
  vtkSmartPointer<vtkPolyData> Scene;
  vtkSmartPointer<vtkDeepGIReferenceIrradiance> Reference;
  vtkNew<vtkImageData> Result;
};

// 2. The red wall bleeds red onto the white floor, more near the wall.
void CheckRedWallBleedsRed(const WallCase& wall)
{
  vtkFloatArray* e = Array(wall.Reference, "IndirectIrradiance");
  vtkFloatArray* se = Array(wall.Reference, "IndirectIrradianceStandardError");
  int notRed = 0;
  double nearSum = 0, farSum = 0, nearVar = 0, farVar = 0;
  int nearN = 0, farN = 0;
  for (vtkIdType p = 0; p < e->GetNumberOfTuples(); ++p)
  {
    const double r = e->GetComponent(p, 0);
    notRed += !(r > e->GetComponent(p, 1) && r > e->GetComponent(p, 2));
    const double d = wall.Positions[p][0];
    const double s = se->GetComponent(p, 0);
    if (d > 0 && d < 0.8)
    {
      nearSum += r;
      nearVar += s * s;
      ++nearN;
    }
    else if (d > 2.4)
    {
      farSum += r;
      farVar += s * s;
      ++farN;
    }
  }
  const double nearMean = nearSum / nearN, farMean = farSum / farN;
  const double sigma = std::sqrt(nearVar / (nearN * nearN) + farVar / (farN * farN));
  std::cout << "red wall: mean E_r at d < 0.8: " << nearMean << ", at d > 2.4: " << farMean
            << " (difference standard error " << sigma << ")\n";
  Check(
    notRed == 0, "red wall: E_r > E_g, E_b on every pixel (" + std::to_string(notRed) + " not)");
  Check(nearMean - farMean > 10 * sigma, "red wall: more irradiance near the wall");
}

// 3. Shadows: a roof shades the wall from the sun.
void CheckRoofShadowsTheWall(const WallCase& wall)
{
  const Frame unit;
  auto roof = MakeReference(
    WallScene(unit, true), SceneLight(unit, SunFrom, Origin, false, 1.0, White3), 256);
  Check(Estimate(roof, wall.Capture), "roof, shadows off: update");
  const double lit = MaxIrradiance(roof);
  const double litMean = roof->GetMeanStandardError();
  roof->ShadowsOn();
  Check(Estimate(roof, wall.Capture), "roof, shadows on: update");
  const double shadowed = MaxIrradiance(roof);
  std::cout << "roof: max E shadows off " << lit << " (mean SE " << litMean << "), on " << shadowed
            << "\n";
  Check(lit > 0.1, "roof, shadows off: the wall lights the floor");
  Check(shadowed == 0.0, "roof, shadows on: wall and roof underside dark, E = 0");
  // Without the roof, shadow rays must not darken anything.
  wall.Reference->ShadowsOn();
  Estimate(wall.Reference, wall.Capture);
  vtkFloatArray* a = Array(wall.Reference, "IndirectIrradiance");
  auto b = vtkFloatArray::SafeDownCast(wall.Result->GetPointData()->GetArray("IndirectIrradiance"));
  double maxDiff = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
  {
    maxDiff = std::max(maxDiff, static_cast<double>(std::fabs(a->GetValue(i) - b->GetValue(i))));
  }
  Check(maxDiff == 0.0,
    "no roof: shadows on and off identical (max diff " + std::to_string(maxDiff) + ")");
  wall.Reference->ShadowsOff();
}

// Checks that two results agree within k combined standard errors; returns
// whether fewer than a quarter of the values are identical (independent
// samples).
bool CompareResults(vtkImageData* a, vtkImageData* b, double k, const std::string& what)
{
  auto ea = vtkFloatArray::SafeDownCast(a->GetPointData()->GetArray("IndirectIrradiance"));
  auto sa =
    vtkFloatArray::SafeDownCast(a->GetPointData()->GetArray("IndirectIrradianceStandardError"));
  auto eb = vtkFloatArray::SafeDownCast(b->GetPointData()->GetArray("IndirectIrradiance"));
  auto sb =
    vtkFloatArray::SafeDownCast(b->GetPointData()->GetArray("IndirectIrradianceStandardError"));
  int bad = 0, identical = 0, n = 0;
  double maxZ = 0;
  for (vtkIdType i = 0; i < ea->GetNumberOfValues(); ++i)
  {
    const double sigma = std::hypot(sa->GetValue(i), sb->GetValue(i));
    const double diff = std::fabs(ea->GetValue(i) - eb->GetValue(i));
    bad += diff > k * sigma + 1e-6 * std::fabs(eb->GetValue(i)) + 1e-7;
    identical += diff == 0 && sigma > 0;
    maxZ = std::max(maxZ, diff / std::max(sigma, 1e-12));
    ++n;
  }
  std::cout << what << ": max |diff| / combined SE " << maxZ << "\n";
  Check(bad == 0, what + ": " + std::to_string(bad) + " values differ beyond the noise");
  return identical < n / 4;
}

// 4. Two seeds agree within noise.
void CheckSeedsAgreeWithinNoise(const WallCase& wall)
{
  const Frame unit;
  auto other =
    MakeReference(wall.Scene, SceneLight(unit, SunFrom, Origin, false, 1.0, White3), 1024);
  other->SetSeed(2);
  Estimate(other, wall.Capture);
  Check(CompareResults(other->GetOutput(), wall.Result, 4.5, "seeds 1 vs 2"),
    "seeds 1 vs 2: the seed changes the samples");
}

// 5. Scale invariance, with a positional light (no attenuation) too.
void CheckScaleInvariance(const WallCase& wall)
{
  const double lamp[3] = { 3, 1, 4 };
  auto makeLitWall = [&](const Frame& f)
  {
    auto reference =
      MakeReference(WallScene(f, false), SceneLight(f, SunFrom, Origin, false, 0.5, White3), 1024);
    reference->AddLight(SceneLight(f, lamp, Origin, true, 0.7, LightColor));
    reference->SetSeed(3);
    reference->ShadowsOn();
    return reference;
  };
  auto base = makeLitWall(Frame());
  Estimate(base, wall.Capture);
  vtkNew<vtkImageData> baseResult;
  baseResult->DeepCopy(base->GetOutput());
  for (double scale : { 1e-4, 1e4 })
  {
    Frame f;
    f.Scale = scale;
    f.Shift[0] = 3e4 * scale;
    f.Shift[1] = -2e4 * scale;
    f.Shift[2] = 1e4 * scale;
    std::vector<std::array<double, 3>> positions;
    auto capture = MakeCapture(f, 24, 8, 3.4, 0.0, 3.0, White3, positions);
    auto scaled = makeLitWall(f);
    Check(Estimate(scaled, capture), "scale " + std::to_string(scale) + ": update");
    CompareResults(scaled->GetOutput(), baseResult, 4.5, "scale " + std::to_string(scale));
  }
  // The square at other scales against the closed form.
  for (double scale : { 1e-4, 1e4 })
  {
    Frame f;
    f.Scale = scale;
    f.Shift[0] = -1e4 * scale;
    f.Shift[2] = 2e4 * scale;
    const SquareCase square(f);
    auto scaled = MakeReference(SquareScene(f, true), SquareLight(f), 1024);
    Estimate(scaled, square.Capture);
    CompareExact(scaled, square.ExactFunction(),
      "square at scale " + std::to_string(scale) + " (closed form)");
  }
}

// 6a. Lights from a renderer.
void CheckLightsFromRenderer()
{
  const Frame unit;
  vtkNew<vtkRenderer> renderer;
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(1, 2, 10);
  camera->SetFocalPoint(1, 2, 0);
  camera->SetViewUp(0, 1, 0);
  vtkNew<vtkLight> headlight, cameraLight, off;
  headlight->SetLightTypeToHeadlight();
  cameraLight->SetLightTypeToCameraLight(); // at (0, 0, 1) towards (0, 0, 0)
  cameraLight->SetIntensity(0.5);
  off->SwitchOff();
  renderer->AddLight(headlight);
  renderer->AddLight(cameraLight);
  renderer->AddLight(off);
  renderer->AddLight(SceneLight(unit, SunFrom, Origin, false, 1.0, White3));
  vtkNew<vtkDeepGIReferenceIrradiance> fromRenderer;
  fromRenderer->SetLightsFromRenderer(renderer);
  Check(fromRenderer->GetNumberOfLights() == 3, "renderer: 3 switched-on lights");
  double p[3], d[3], c[3];
  bool positional;
  fromRenderer->GetLight(0, p, d, c, positional);
  Check(std::fabs(p[0] - 1) + std::fabs(p[1] - 2) + std::fabs(p[2] - 10) < 1e-9 &&
      std::fabs(d[2] + 1) < 1e-9,
    "headlight at the camera, looking along its view direction");
  fromRenderer->GetLight(1, p, d, c, positional);
  Check(std::fabs(p[0] - 1) + std::fabs(p[1] - 2) + std::fabs(p[2] - 10) < 1e-9 &&
      std::fabs(d[2] + 1) < 1e-9 && std::fabs(c[0] - 0.5) < 1e-12,
    "camera light (0,0,1)->(0,0,0) at the camera, intensity 0.5");
  fromRenderer->GetLight(2, p, d, c, positional);
  Check(std::fabs(d[0] + std::sqrt(0.5)) < 1e-9 && std::fabs(d[2] + std::sqrt(0.5)) < 1e-9,
    "scene light direction in world space");
  vtkNew<vtkRenderer> empty;
  empty->GetActiveCamera()->SetPosition(0, 0, 5);
  fromRenderer->SetLightsFromRenderer(empty);
  Check(fromRenderer->GetNumberOfLights() == 1, "no lights on: VTK's automatic headlight");
  empty->AutomaticLightCreationOff();
  fromRenderer->SetLightsFromRenderer(empty);
  Check(fromRenderer->GetNumberOfLights() == 0, "no automatic light creation: no light");
  vtkNew<vtkLight> cameraOnly;
  cameraOnly->SetLightTypeToHeadlight();
  vtkNew<EventCounter> events;
  fromRenderer->AddObserver(vtkCommand::WarningEvent, events);
  Check(!fromRenderer->AddLight(cameraOnly) && events->Warnings == 1,
    "headlight without a camera: skipped with a warning");
  fromRenderer->Print(std::cout);
}

// 6b. Bad input: warnings or errors, no crash. A missing input is the
// executive's error; what the estimator refuses is its own.
void CheckBadInputIsRefused(vtkImageData* squareCapture)
{
  const Frame unit;
  vtkNew<EventCounter> events, executiveEvents;
  vtkNew<vtkDeepGIReferenceIrradiance> bad;
  bad->AddObserver(vtkCommand::ErrorEvent, events);
  bad->AddObserver(vtkCommand::WarningEvent, events);
  bad->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executiveEvents);
  Check(!Estimate(bad, squareCapture) && events->Errors == 0 && executiveEvents->Errors == 1,
    "no scene: the executive's error");
  vtkSmartPointer<vtkPolyData> scene = SquareScene(unit, true);
  bad->SetSceneData(scene);
  Check(Estimate(bad, squareCapture) && events->Warnings == 1 && MaxIrradiance(bad) == 0.0,
    "no lights: a warning and E = 0");
  bad->AddLight(SquareLight(unit));
  bad->SetMaximumDistance(std::numeric_limits<double>::quiet_NaN());
  Check(!Estimate(bad, squareCapture) && events->Errors == 1, "NaN MaximumDistance: error");
  bad->SetMaximumDistance(-1);
  Check(!Estimate(bad, squareCapture) && events->Errors == 2, "negative MaximumDistance: error");
  bad->SetMaximumDistance(std::numeric_limits<double>::infinity());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double nanPoint[3] = { nan, 0, 0 };
  Check(
    !bad->AddLight(SceneLight(unit, nanPoint, Origin, false, 1, White3)) && events->Warnings == 2,
    "light with a NaN position: skipped with a warning");
  Check(!bad->AddLight(SceneLight(unit, Origin, Origin, false, 1, White3)) && events->Warnings == 3,
    "light without a direction: skipped with a warning");
  scene->GetCellData()->RemoveArray("Colors");
  Check(Estimate(bad, squareCapture) && events->Warnings == 4, "no Colors: a warning");
  bad->SetDiffuseCoefficient(7);
  Check(bad->GetDiffuseCoefficient() == 1.0, "DiffuseCoefficient clamped");
  vtkNew<vtkImageData> noAlbedo;
  noAlbedo->DeepCopy(squareCapture);
  noAlbedo->GetPointData()->RemoveArray(
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Albedo, 0).c_str());
  Check(Estimate(bad, noAlbedo) && events->Warnings == 6 &&
      !bad->GetOutput()->GetPointData()->GetArray(vtkDeepGICaptureNames::IndirectRadiance),
    "no Albedo_0: warnings, no IndirectRadiance");
  const int executiveErrors = executiveEvents->Errors;

  Check(!Estimate(bad, nullptr) && events->Errors == 2 &&
      executiveEvents->Errors == executiveErrors + 1,
    "no capture: the executive's error");
}
}

int TestDeepGIReferenceIrradiance(int, char*[])
{
  const Frame unit;
  const SquareCase square(unit);
  auto reference = MakeReference(SquareScene(unit, true), SquareLight(unit), 1024);
  CheckSquareMatchesClosedForm(reference, square);
  CheckBackFacesFollowTwoSidedLighting(square);
  CheckPointNormalsShade(square);
  CheckMaximumDistanceLimitsToADisc(reference, square);
  CheckDiffuseFieldScalesReflectance(square);

  const WallCase wall;
  CheckRedWallBleedsRed(wall);
  CheckRoofShadowsTheWall(wall);
  CheckSeedsAgreeWithinNoise(wall);
  CheckScaleInvariance(wall);

  CheckLightsFromRenderer();
  CheckBadInputIsRefused(square.Capture);
  return ExitStatus();
}
