// Tests the emitted radiance of vtkDeepGIReferenceIrradiance (the scene's
// cell array "Emission") on synthetic captures (no rendering): a camera at
// height 3 looks straight down at the plane z = 0; every pixel gets the
// plane's exact depth and the normal +z.
//
//  1. closed form: an emitting square (half side 0.5, uniform L_e, facing
//     down) at height 1, no lights: for a point X under or beside it
//     E(X) = pi L_e F(X), F the view factor from X to the parallel square
//     (four corner rectangles). Per pixel and channel |E - exact| < 4 SE +
//     1e-6, and the mean difference within 4 standard errors of the mean;
//  2. emission adds to the lit diffuse radiance: the same square with a
//     directional light from below gives pi (L_e + rho I) F;
//  3. back faces: the square wound the other way gives the same E with
//     TwoSidedLighting on (VTK draws the ambient term, the emission, on both
//     sides) and exactly 0 with it off;
//  4. without the array, or with EmissionArrayName empty: E exactly 0 and no
//     warning (a light above the square lights only its back, which the
//     points below do not see);
//  5. bad arrays: NaN, infinite and negative components are set to 0 with
//     one warning (the remaining channel still matches its closed form); a
//     2-component array and one with the wrong number of tuples are ignored
//     with a warning (E = 0);
//  6. DIRECT_RADIANCE: an emitting floor seen from the front reports L_e
//     exactly (plus rho I cos under a light); from behind L_e with
//     TwoSidedLighting on and 0 with it off;
//  7. an unsigned char array is a colour: divided by 255.

#include "DeepGIReferenceTestUtilities.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDeepGIReferenceIrradiance.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
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
const int Width = 12, Height = 12;
const double CameraHeight = 3.0, CameraX = 0.3, CameraY = -0.2;

// A Width x Height capture of the plane z = 0 seen from above (perspective,
// 40 degrees); positions receives each pixel's point.
vtkSmartPointer<vtkImageData> MakeCapture(std::vector<std::array<double, 3>>& positions)
{
  vtkNew<vtkCamera> camera;
  camera->SetPosition(CameraX, CameraY, CameraHeight);
  camera->SetFocalPoint(CameraX, CameraY, 0.0);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(40.0);
  camera->SetClippingRange(0.1, 2.0 * CameraHeight);
  Layer0Capture capture(Width, Height, camera);
  vtkMatrix4x4* view = capture.View;
  vtkMatrix4x4* inverseView = capture.InverseView;
  vtkMatrix4x4* inverseProjection = capture.InverseProjection;
  vtkFloatArray* depth = capture.Depth;
  vtkFloatArray* normal = capture.Normal;
  vtkFloatArray* albedo = capture.Albedo;
  vtkUnsignedCharArray* valid = capture.Valid;
  const vtkIdType n = Width * Height;
  positions.assign(n, { 0, 0, 0 });
  double up[4] = { 0, 0, 1, 0 }, upCamera[4];
  view->MultiplyPoint(up, upCamera);
  for (int j = 0; j < Height; ++j)
  {
    for (int i = 0; i < Width; ++i)
    {
      const vtkIdType p = j * Width + i;
      // The pixel centre's viewing ray in camera space, scaled to reach the
      // plane (camera-space depth CameraHeight).
      double ray[4] = { (i + 0.5) / Width * 2 - 1, (j + 0.5) / Height * 2 - 1, 1, 1 };
      inverseProjection->MultiplyPoint(ray, ray);
      const double t = CameraHeight / -(ray[2] / ray[3]);
      double pc[4] = { t * ray[0] / ray[3], t * ray[1] / ray[3], -CameraHeight, 1 }, pw[4];
      inverseView->MultiplyPoint(pc, pw);
      depth->SetValue(p, static_cast<float>(CameraHeight));
      valid->SetValue(p, 1);
      for (int c = 0; c < 3; ++c)
      {
        normal->SetComponent(p, c, upCamera[c]);
        albedo->SetComponent(p, c, 0.5);
        positions[p][c] = pw[c] / pw[3];
      }
    }
  }
  return capture.Image;
}

// One quad (corners in order) with Colors `rgb`; `emission` (may be null)
// becomes the cell array "Emission".
vtkSmartPointer<vtkPolyData> QuadScene(
  const std::array<std::array<double, 3>, 4>& corners, vtkDataArray* emission)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  vtkIdType ids[4];
  for (int k = 0; k < 4; ++k)
  {
    ids[k] = points->InsertNextPoint(corners[k].data());
  }
  polys->InsertNextCell(4, ids);
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("Colors");
  colors->SetNumberOfComponents(3);
  const unsigned char grey[3] = { 128, 128, 128 };
  colors->InsertNextTypedTuple(grey);
  auto scene = vtkSmartPointer<vtkPolyData>::New();
  scene->SetPoints(points);
  scene->SetPolys(polys);
  scene->GetCellData()->AddArray(colors);
  if (emission)
  {
    scene->GetCellData()->AddArray(emission);
  }
  return scene;
}

const double Half = 0.5, Lift = 1.0;
const double Emitted[3] = { 0.8, 0.5, 0.2 };

// The square [-Half, Half]^2 at height Lift, facing down (front towards the
// plane) or up.
vtkSmartPointer<vtkPolyData> SquareScene(bool facingDown, vtkDataArray* emission)
{
  const double s = Half, h = Lift;
  if (facingDown)
  {
    return QuadScene({ { { -s, -s, h }, { -s, s, h }, { s, s, h }, { s, -s, h } } }, emission);
  }
  return QuadScene({ { { -s, -s, h }, { s, -s, h }, { s, s, h }, { -s, s, h } } }, emission);
}

vtkSmartPointer<vtkFloatArray> EmissionArray(
  const double rgb[3], int components = 3, vtkIdType tuples = 1, const char* name = "Emission")
{
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  for (vtkIdType t = 0; t < tuples; ++t)
  {
    for (int c = 0; c < components; ++c)
    {
      array->SetComponent(t, c, rgb[c % 3]);
    }
  }
  return array;
}

// A directional scene light shining from `from` towards the origin.
vtkSmartPointer<vtkLight> Directional(const double from[3], double intensity)
{
  auto light = vtkSmartPointer<vtkLight>::New();
  light->SetLightTypeToSceneLight();
  light->SetPosition(from[0], from[1], from[2]);
  light->SetFocalPoint(0, 0, 0);
  light->SetPositional(false);
  light->SetIntensity(intensity);
  return light;
}

vtkFloatArray* Array(vtkDeepGIReferenceIrradiance* reference, const char* name)
{
  return vtkFloatArray::SafeDownCast(reference->GetOutput()->GetPointData()->GetArray(name));
}

// Compares E per pixel and channel with exact(p, c) (channels with a
// negative exact value are skipped).
void CompareExact(vtkDeepGIReferenceIrradiance* reference,
  const std::function<double(vtkIdType, int)>& exact, const std::string& what)
{
  vtkFloatArray* e = Array(reference, "IndirectIrradiance");
  vtkFloatArray* se = Array(reference, "IndirectIrradianceStandardError");
  if (!e || !se)
  {
    Check(false, what + ": output arrays missing");
    return;
  }
  int n = 0, bad = 0;
  double sumDiff = 0, sumVar = 0, maxRatio = 0, maxExact = 0;
  for (vtkIdType p = 0; p < e->GetNumberOfTuples(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double x = exact(p, c);
      if (!(x >= 0))
      {
        continue;
      }
      const double diff = e->GetComponent(p, c) - x;
      const double tolerance = 4.0 * se->GetComponent(p, c) + 1e-6;
      bad += std::fabs(diff) > tolerance;
      maxRatio = std::max(maxRatio, std::fabs(diff) / tolerance);
      maxExact = std::max(maxExact, x);
      sumDiff += diff;
      sumVar += se->GetComponent(p, c) * se->GetComponent(p, c);
      ++n;
    }
  }
  const double meanDiff = n ? sumDiff / n : 0, meanSE = n ? std::sqrt(sumVar) / n : 0;
  std::cout << what << ": " << n << " values (exact up to " << maxExact << "), mean E - exact "
            << meanDiff << " (its standard error " << meanSE << "), max |diff| / tolerance "
            << maxRatio << "\n";
  Check(n > 0 && maxExact > 0.1, what + ": values compared");
  Check(bad == 0, what + ": " + std::to_string(bad) + " values beyond 4 standard errors");
  Check(std::fabs(meanDiff) < 4 * meanSE + 1e-6, what + ": mean difference within 4 SE");
}

double MaxAbs(vtkDeepGIReferenceIrradiance* reference, const char* name)
{
  vtkFloatArray* a = Array(reference, name);
  double m = 0;
  for (vtkIdType i = 0; a && i < a->GetNumberOfValues(); ++i)
  {
    m = std::max(m, static_cast<double>(std::fabs(a->GetValue(i))));
  }
  return a ? m : -1;
}

const double Below[3] = { 0, 0, -1 }, Above[3] = { 0, 0, 1 };

// The capture of the plane z = 0 and the closed forms there: F, the view
// factor to the square, and E = pi L_e F of the emitting square alone.
struct Plane
{
  Plane() { this->Capture = MakeCapture(this->Positions); }
  double ViewFactor(vtkIdType p) const
  {
    return SquareViewFactor(this->Positions[p][0], this->Positions[p][1], Half, Lift);
  }
  double EmittedExact(vtkIdType p, int c) const
  {
    return vtkMath::Pi() * Emitted[c] * this->ViewFactor(p);
  }
  std::function<double(vtkIdType, int)> EmittedExactFunction() const
  {
    return [this](vtkIdType p, int c) { return this->EmittedExact(p, c); };
  }
  std::vector<std::array<double, 3>> Positions;
  vtkSmartPointer<vtkImageData> Capture;
};

// 1. Closed form, no lights: no warning either.
void CheckEmittingSquareMatchesClosedForm(const Plane& plane)
{
  vtkNew<vtkDeepGIReferenceIrradiance> reference;
  vtkNew<EventCounter> events;
  reference->AddObserver(vtkCommand::WarningEvent, events);
  reference->SetSceneData(SquareScene(true, EmissionArray(Emitted)));
  reference->SetSamplesPerPixel(1024);
  Check(Estimate(reference, plane.Capture), "emitting square: update");
  CompareExact(reference, plane.EmittedExactFunction(), "emitting square, no lights (closed form)");
  Check(events->Warnings == 0, "an emitting scene without lights: no warning");
}

// 2. Emission adds to the diffuse radiance from a light below (n.l = 1).
void CheckEmissionAddsToLitRadiance(const Plane& plane)
{
  const double intensity = 0.6, rho = 128.0 / 255.0;
  vtkNew<vtkDeepGIReferenceIrradiance> reference;
  reference->SetSceneData(SquareScene(true, EmissionArray(Emitted)));
  reference->AddLight(Directional(Below, intensity));
  reference->SetSamplesPerPixel(1024);
  Check(Estimate(reference, plane.Capture), "emitting and lit square: update");
  CompareExact(
    reference,
    [&](vtkIdType p, int c)
    { return vtkMath::Pi() * (Emitted[c] + rho * intensity) * plane.ViewFactor(p); },
    "emitting square lit from below: pi (L_e + rho I) F");
}

// 3. Back faces: emitted on both sides with two-sided lighting, as VTK draws
// the ambient term; nothing with it off.
void CheckBackFacesEmitWithTwoSidedLighting(const Plane& plane)
{
  vtkNew<vtkDeepGIReferenceIrradiance> reference;
  reference->SetSceneData(SquareScene(false, EmissionArray(Emitted)));
  reference->SetSamplesPerPixel(1024);
  Check(Estimate(reference, plane.Capture), "emitting square seen from behind: update");
  CompareExact(reference, plane.EmittedExactFunction(),
    "emitting square seen from behind, two-sided (closed form)");
  reference->TwoSidedLightingOff();
  Check(Estimate(reference, plane.Capture) && MaxAbs(reference, "IndirectIrradiance") == 0.0,
    "emitting square seen from behind, one-sided: E = 0");
}

// 4. No array, or no array name: E = 0 and no warning.
void CheckMissingEmissionArrayEmitsNothing(const Plane& plane)
{
  vtkNew<vtkDeepGIReferenceIrradiance> reference;
  vtkNew<EventCounter> events;
  reference->AddObserver(vtkCommand::WarningEvent, events);
  reference->AddLight(Directional(Above, 1.0));
  reference->SetSamplesPerPixel(64);
  reference->SetSceneData(SquareScene(true, nullptr));
  Check(Estimate(reference, plane.Capture) && MaxAbs(reference, "IndirectIrradiance") == 0.0 &&
      events->Warnings == 0,
    "no Emission array: E = 0, no warning");
  reference->SetSceneData(SquareScene(true, EmissionArray(Emitted, 3, 1, "Glow")));
  Check(Estimate(reference, plane.Capture) && MaxAbs(reference, "IndirectIrradiance") == 0.0 &&
      events->Warnings == 0,
    "an array of another name: E = 0, no warning");
  reference->SetEmissionArrayName("Glow");
  reference->SetSamplesPerPixel(1024);
  Check(Estimate(reference, plane.Capture), "EmissionArrayName Glow: update");
  CompareExact(reference, plane.EmittedExactFunction(), "EmissionArrayName Glow (closed form)");
  reference->SetEmissionArrayName(nullptr);
  Check(Estimate(reference, plane.Capture) && MaxAbs(reference, "IndirectIrradiance") == 0.0 &&
      events->Warnings == 0,
    "EmissionArrayName null: no emission, no warning");
  reference->SetEmissionArrayName("");
  Check(Estimate(reference, plane.Capture) && MaxAbs(reference, "IndirectIrradiance") == 0.0 &&
      events->Warnings == 0,
    "EmissionArrayName empty: no emission, no warning");
}

// 5. Bad arrays.
void CheckBadEmissionArraysAreRepaired(const Plane& plane)
{
  vtkNew<vtkDeepGIReferenceIrradiance> reference;
  vtkNew<EventCounter> events;
  reference->AddObserver(vtkCommand::WarningEvent, events);
  reference->AddObserver(vtkCommand::ErrorEvent, events);
  // A light that reaches only the square's back, so that an ignored
  // array does not also bring the warning about a scene without light.
  reference->AddLight(Directional(Above, 1.0));
  reference->SetSamplesPerPixel(1024);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double bad[3] = { nan, -1.0, Emitted[2] };
  reference->SetSceneData(SquareScene(true, EmissionArray(bad)));
  Check(Estimate(reference, plane.Capture) && events->Warnings == 1 && events->Errors == 0,
    "NaN and negative emission: one warning");
  Check(MaxAbs(reference, "IndirectIrradiance") < 10.0, "NaN and negative emission: E finite");
  CompareExact(
    reference, [&](vtkIdType p, int c) { return c == 2 ? plane.EmittedExact(p, c) : 0.0; },
    "NaN and negative emission clamped to 0, blue unchanged");
  const double infinite[3] = { std::numeric_limits<double>::infinity(), 0.0, 0.0 };
  reference->SetSceneData(SquareScene(true, EmissionArray(infinite)));
  Check(Estimate(reference, plane.Capture) && events->Warnings == 2 &&
      MaxAbs(reference, "IndirectIrradiance") == 0.0,
    "infinite emission: a warning, set to 0");
  reference->SetSceneData(SquareScene(true, EmissionArray(Emitted, 2)));
  Check(Estimate(reference, plane.Capture) && events->Warnings == 3 &&
      MaxAbs(reference, "IndirectIrradiance") == 0.0,
    "a 2-component Emission array: a warning, ignored");
  reference->SetSceneData(SquareScene(true, EmissionArray(Emitted, 3, 2)));
  Check(Estimate(reference, plane.Capture) && events->Warnings == 4 &&
      MaxAbs(reference, "IndirectIrradiance") == 0.0,
    "an Emission array with more tuples than cells: a warning, ignored");
  // One component is grey.
  const double grey[3] = { 0.4, 0.4, 0.4 };
  reference->SetSceneData(SquareScene(true, EmissionArray(grey, 1)));
  Check(Estimate(reference, plane.Capture) && events->Warnings == 4, "grey emission: update");
  CompareExact(
    reference, [&](vtkIdType p, int) { return vtkMath::Pi() * 0.4 * plane.ViewFactor(p); },
    "a 1-component Emission array is grey (closed form)");
}

// 6. DIRECT_RADIANCE: the emitting floor itself (larger than the view).
void CheckDirectRadianceOfEmitter(const Plane& plane)
{
  const double e = 4.0;
  const std::array<std::array<double, 3>, 4> up = { { { -e, -e, 0 }, { e, -e, 0 }, { e, e, 0 },
    { -e, e, 0 } } };
  const std::array<std::array<double, 3>, 4> down = { { { -e, -e, 0 }, { -e, e, 0 }, { e, e, 0 },
    { e, -e, 0 } } };
  vtkNew<vtkDeepGIReferenceIrradiance> reference;
  reference->SetQuantityToDirectRadiance();
  auto maxError = [&](const double expected[3])
  {
    vtkFloatArray* l = Array(reference, "DirectRadiance");
    double m = l ? 0.0 : 1.0;
    for (vtkIdType p = 0; l && p < l->GetNumberOfTuples(); ++p)
    {
      for (int c = 0; c < 3; ++c)
      {
        m = std::max(m, std::fabs(l->GetComponent(p, c) - expected[c]));
      }
    }
    return m;
  };
  const double zero[3] = { 0, 0, 0 };
  reference->SetSceneData(QuadScene(up, EmissionArray(Emitted)));
  Check(Estimate(reference, plane.Capture) && maxError(Emitted) < 1e-6,
    "DIRECT_RADIANCE of an emitting floor: L_e");
  reference->AddLight(Directional(Above, 0.6));
  double lit[3];
  for (int c = 0; c < 3; ++c)
  {
    lit[c] = Emitted[c] + 128.0 / 255.0 * 0.6;
  }
  Check(Estimate(reference, plane.Capture) && maxError(lit) < 1e-6,
    "DIRECT_RADIANCE of an emitting floor under a light: L_e + rho I");
  reference->RemoveAllLights();
  reference->SetSceneData(QuadScene(down, EmissionArray(Emitted)));
  Check(Estimate(reference, plane.Capture) && maxError(Emitted) < 1e-6,
    "DIRECT_RADIANCE of an emitting floor seen from behind, two-sided: L_e");
  reference->TwoSidedLightingOff();
  Check(Estimate(reference, plane.Capture) && maxError(zero) == 0.0,
    "DIRECT_RADIANCE of an emitting floor seen from behind, one-sided: 0");
}

// 7. An unsigned char array is a colour (/ 255), like "Colors".
void CheckUnsignedCharEmissionIsAColour(const Plane& plane)
{
  vtkNew<vtkUnsignedCharArray> bytes;
  bytes->SetName("Emission");
  bytes->SetNumberOfComponents(3);
  const unsigned char rgb[3] = { 255, 51, 0 };
  bytes->InsertNextTypedTuple(rgb);
  vtkNew<vtkDeepGIReferenceIrradiance> reference;
  reference->SetSceneData(SquareScene(true, bytes));
  reference->SetSamplesPerPixel(1024);
  Check(Estimate(reference, plane.Capture), "unsigned char emission: update");
  CompareExact(
    reference,
    [&](vtkIdType p, int c) { return vtkMath::Pi() * rgb[c] / 255.0 * plane.ViewFactor(p); },
    "unsigned char emission / 255 (closed form)");
}
}

int TestDeepGIReferenceEmission(int, char*[])
{
  const Plane plane;
  CheckEmittingSquareMatchesClosedForm(plane);
  CheckEmissionAddsToLitRadiance(plane);
  CheckBackFacesEmitWithTwoSidedLighting(plane);
  CheckMissingEmissionArrayEmitsNothing(plane);
  CheckBadEmissionArraysAreRepaired(plane);
  CheckDirectRadianceOfEmitter(plane);
  CheckUnsignedCharEmissionIsAColour(plane);
  return ExitStatus();
}
