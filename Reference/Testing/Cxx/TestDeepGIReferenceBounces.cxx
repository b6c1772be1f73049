// Tests the multiple bounces of vtkDeepGIReferenceIrradiance
// (NumberOfBounces, BounceDamping) on a synthetic capture (no rendering) of
// the inside of a closed sphere: a camera at the centre looks at the wall;
// every pixel gets the exact point and (inward) normal of the facet its
// ray meets.
//
// Inside a sphere of radius R the view factor from a wall point to a wall
// patch dA is dA / (4 pi R^2) whatever the two points (cos_X = cos_Y =
// d / 2R), so the irradiance of a wall point is pi times the area-weighted
// mean radiance of the wall, the same everywhere. With uniform albedo rho,
// damping delta, emitted radiance L_e(Y) and no lights, by induction
// (L_k = L_e + delta rho E_{k-1} / pi is uniform beyond L_e):
//
//   E_k = pi <L_e> (1 + delta rho + ... + (delta rho)^(k-1)).
//
// With MaximumDistance m < 2R only the wall within m counts: d = 2R cos, so
// a cosine-weighted direction reaches it with probability q = (m / 2R)^2,
// and with a uniform L_e every segment limited to m gives
//
//   E_k = pi q L_e (1 + delta rho q + ... + (delta rho q)^(k-1))
//
// (limiting the first segment only would give pi q L_e (1 + delta rho +
// ...)). Checks:
//  1. half the sphere emits (variance in every sample): E_k of every pixel
//     and channel within 4 standard errors (+1e-6) of the closed form, and
//     the mean over the pixels within 4 standard errors of the mean, for
//     k = 1, 2, 4 with delta 1 and k = 6 with delta 0.5;
//  2. MaximumDistance limits every segment: uniform emission, m = R;
//  3. NumberOfBounces 1 is the one-bounce result bit for bit (a reference
//     never given the new settings, and one set to 16 bounces and damping
//     0.3 then back to 1 bounce); BounceDamping has no effect with 1 bounce;
//  4. determinism: 3 bounces bit-identical with 1 and 2 threads;
//  5. bad values: NumberOfBounces 0, -3, 17 and BounceDamping -0.5, 2, NaN
//     are clamped (NaN ignored) with one warning each; valid values give
//     none.
// The sphere's facets (and no point normals) make the closed form exact
// only up to the faceting, about 1e-4 relative here, far below the noise.

#include "DeepGIReferenceTestUtilities.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIReferenceIrradiance.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

using namespace DeepGIReferenceTest;
using namespace DeepGITest;

namespace
{
const double Radius = 1.0;
const int Rings = 48, Sectors = 96;
const double Albedo[3] = { 0.9, 0.6, 0.3 };
const double Emitted[3] = { 0.5, 0.8, 1.0 };

using Triangle = std::array<std::array<double, 3>, 3>;

// A closed latitude-longitude sphere around the origin (outward winding, no
// normals), its triangles, and per cell whether its centre has z > 0.
struct Sphere
{
  vtkSmartPointer<vtkPolyData> PolyData;
  std::vector<Triangle> Triangles;
  std::vector<bool> Upper;
};

Sphere MakeSphere()
{
  Sphere sphere;
  std::vector<std::array<double, 3>> p;
  auto point = [&](int ring, int sector)
  {
    const double theta = vtkMath::Pi() * ring / Rings;
    const double phi = 2 * vtkMath::Pi() * (sector % Sectors) / Sectors;
    return std::array<double, 3>{ Radius * std::sin(theta) * std::cos(phi),
      Radius * std::sin(theta) * std::sin(phi), Radius * std::cos(theta) };
  };
  for (int ring = 0; ring < Rings; ++ring)
  {
    for (int sector = 0; sector < Sectors; ++sector)
    {
      const auto a = point(ring, sector), b = point(ring + 1, sector),
                 c = point(ring + 1, sector + 1), d = point(ring, sector + 1);
      // (a, b, c) and (a, c, d) wind outward; the pole rings lose their
      // degenerate half.
      if (ring + 1 < Rings)
      {
        sphere.Triangles.push_back({ a, b, c });
      }
      if (ring > 0)
      {
        sphere.Triangles.push_back({ a, c, d });
      }
    }
  }
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  for (const Triangle& t : sphere.Triangles)
  {
    vtkIdType ids[3];
    for (int k = 0; k < 3; ++k)
    {
      ids[k] = points->InsertNextPoint(t[k].data());
    }
    polys->InsertNextCell(3, ids);
    sphere.Upper.push_back(t[0][2] + t[1][2] + t[2][2] > 0.0);
  }
  vtkNew<vtkFloatArray> colors;
  colors->SetName("Colors");
  colors->SetNumberOfComponents(3);
  for (size_t i = 0; i < sphere.Triangles.size(); ++i)
  {
    colors->InsertNextTuple(Albedo);
  }
  sphere.PolyData = vtkSmartPointer<vtkPolyData>::New();
  sphere.PolyData->SetPoints(points);
  sphere.PolyData->SetPolys(polys);
  sphere.PolyData->GetCellData()->AddArray(colors);
  return sphere;
}

double Area(const Triangle& t)
{
  double u[3], v[3], n[3];
  vtkMath::Subtract(t[1].data(), t[0].data(), u);
  vtkMath::Subtract(t[2].data(), t[0].data(), v);
  vtkMath::Cross(u, v, n);
  return 0.5 * vtkMath::Norm(n);
}

// Sets the "Emission" cell array: L_e on the upper cells only, or on all;
// returns the area-weighted mean factor <L_e> / L_e.
double SetEmission(Sphere& sphere, bool upperOnly)
{
  vtkNew<vtkFloatArray> emission;
  emission->SetName("Emission");
  emission->SetNumberOfComponents(3);
  const double zero[3] = { 0, 0, 0 };
  double emitting = 0, total = 0;
  for (size_t i = 0; i < sphere.Triangles.size(); ++i)
  {
    const bool emits = !upperOnly || sphere.Upper[i];
    emission->InsertNextTuple(emits ? Emitted : zero);
    const double a = Area(sphere.Triangles[i]);
    total += a;
    emitting += emits ? a : 0.0;
  }
  sphere.PolyData->GetCellData()->AddArray(emission);
  sphere.PolyData->Modified();
  return emitting / total;
}

// Moeller-Trumbore: distance along the unit ray to the triangle, or -1.
double Intersect(const double o[3], const double d[3], const Triangle& t)
{
  double e1[3], e2[3], p[3], s[3], q[3];
  vtkMath::Subtract(t[1].data(), t[0].data(), e1);
  vtkMath::Subtract(t[2].data(), t[0].data(), e2);
  vtkMath::Cross(d, e2, p);
  const double det = vtkMath::Dot(e1, p);
  if (std::fabs(det) < 1e-14)
  {
    return -1;
  }
  vtkMath::Subtract(o, t[0].data(), s);
  const double u = vtkMath::Dot(s, p) / det;
  vtkMath::Cross(s, e1, q);
  const double v = vtkMath::Dot(d, q) / det;
  const double distance = vtkMath::Dot(e2, q) / det;
  return u < 0 || v < 0 || u + v > 1 || distance <= 0 ? -1 : distance;
}

const int Width = 12, Height = 12;

// A Width x Height capture from the sphere's centre looking down -z (a 70
// degree perspective): each pixel's facet point and its inward normal.
vtkSmartPointer<vtkImageData> MakeCapture(const Sphere& sphere)
{
  vtkNew<vtkCamera> camera;
  camera->SetPosition(0, 0, 0);
  camera->SetFocalPoint(0.1, 0.05, -1);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(70.0);
  camera->SetClippingRange(0.01, 3.0 * Radius);
  Layer0Capture capture(Width, Height, camera);
  vtkMatrix4x4* view = capture.View;
  vtkMatrix4x4* inverseView = capture.InverseView;
  vtkMatrix4x4* inverseProjection = capture.InverseProjection;
  vtkFloatArray* depth = capture.Depth;
  vtkFloatArray* normal = capture.Normal;
  vtkFloatArray* albedo = capture.Albedo;
  vtkUnsignedCharArray* valid = capture.Valid;
  const double eye[3] = { 0, 0, 0 };
  for (int j = 0; j < Height; ++j)
  {
    for (int i = 0; i < Width; ++i)
    {
      const vtkIdType p = j * Width + i;
      double ray[4] = { (i + 0.5) / Width * 2 - 1, (j + 0.5) / Height * 2 - 1, 1, 1 };
      inverseProjection->MultiplyPoint(ray, ray);
      double rc[4] = { ray[0] / ray[3], ray[1] / ray[3], ray[2] / ray[3], 0 }, rw[4];
      inverseView->MultiplyPoint(rc, rw);
      vtkMath::Normalize(rw);
      double nearest = std::numeric_limits<double>::infinity();
      const Triangle* hit = nullptr;
      for (const Triangle& t : sphere.Triangles)
      {
        const double distance = Intersect(eye, rw, t);
        if (distance > 0 && distance < nearest)
        {
          nearest = distance;
          hit = &t;
        }
      }
      double x[4] = { nearest * rw[0], nearest * rw[1], nearest * rw[2], 1 }, xc[4];
      view->MultiplyPoint(x, xc);
      // Inward: minus the outward winding normal.
      double e1[3], e2[3], inward[4] = { 0, 0, 0, 0 }, nc[4];
      vtkMath::Subtract((*hit)[1].data(), (*hit)[0].data(), e1);
      vtkMath::Subtract((*hit)[2].data(), (*hit)[0].data(), e2);
      vtkMath::Cross(e2, e1, inward);
      vtkMath::Normalize(inward);
      view->MultiplyPoint(inward, nc);
      depth->SetValue(p, static_cast<float>(-xc[2]));
      valid->SetValue(p, 1);
      for (int c = 0; c < 3; ++c)
      {
        normal->SetComponent(p, c, nc[c]);
        albedo->SetComponent(p, c, Albedo[c]);
      }
    }
  }
  return capture.Image;
}

vtkFloatArray* Array(vtkDeepGIReferenceIrradiance* reference, const char* name)
{
  return vtkFloatArray::SafeDownCast(reference->GetOutput()->GetPointData()->GetArray(name));
}

// Compares E per pixel and channel with the uniform exact[c].
void CompareExact(
  vtkDeepGIReferenceIrradiance* reference, const double exact[3], const std::string& what)
{
  vtkFloatArray* e = Array(reference, "IndirectIrradiance");
  vtkFloatArray* se = Array(reference, "IndirectIrradianceStandardError");
  if (!e || !se)
  {
    Check(false, what + ": output arrays missing");
    return;
  }
  int n = 0, bad = 0;
  double sumDiff = 0, sumVar = 0, maxRatio = 0, sumE = 0;
  for (vtkIdType p = 0; p < e->GetNumberOfTuples(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double diff = e->GetComponent(p, c) - exact[c];
      const double tolerance = 4.0 * se->GetComponent(p, c) + 1e-6;
      bad += std::fabs(diff) > tolerance;
      maxRatio = std::max(maxRatio, std::fabs(diff) / tolerance);
      // Relative to each channel's exact value, so the channels weigh alike.
      sumDiff += diff / exact[c];
      sumVar += se->GetComponent(p, c) * se->GetComponent(p, c) / (exact[c] * exact[c]);
      sumE += e->GetComponent(p, c) / exact[c];
      ++n;
    }
  }
  const double meanDiff = n ? sumDiff / n : 0, meanSE = n ? std::sqrt(sumVar) / n : 0;
  std::cout << what << ": exact (" << exact[0] << ", " << exact[1] << ", " << exact[2]
            << "), mean E / exact " << (n ? sumE / n : 0) << ", mean relative difference "
            << meanDiff << " (its standard error " << meanSE << "), max |diff| / tolerance "
            << maxRatio << "\n";
  Check(n == 3 * Width * Height, what + ": all values compared");
  Check(bad == 0, what + ": " + std::to_string(bad) + " values beyond 4 standard errors");
  Check(std::fabs(meanDiff) < 4 * meanSE + 1e-6, what + ": mean difference within 4 SE");
}

bool SameOutput(vtkImageData* a, vtkImageData* b)
{
  for (const char* name : { "IndirectIrradiance", "IndirectIrradianceStandardError",
         vtkDeepGICaptureNames::IndirectRadiance, "IndirectRadianceStandardError",
         vtkDeepGICaptureNames::Valid })
  {
    vtkDataArray* x = a->GetPointData()->GetArray(name);
    vtkDataArray* y = b->GetPointData()->GetArray(name);
    if (!x || !y || x->GetNumberOfValues() != y->GetNumberOfValues())
    {
      return false;
    }
    for (vtkIdType i = 0; i < x->GetNumberOfValues(); ++i)
    {
      if (x->GetVariantValue(i) != y->GetVariantValue(i))
      {
        return false;
      }
    }
  }
  return true;
}

// pi * mean * (1 + g + ... + g^(k-1)) per channel with g = delta rho q.
void Series(double mean, double q, double delta, int k, double exact[3])
{
  for (int c = 0; c < 3; ++c)
  {
    const double g = delta * Albedo[c] * q;
    double sum = 0, term = 1;
    for (int j = 0; j < k; ++j)
    {
      sum += term;
      term *= g;
    }
    exact[c] = vtkMath::Pi() * q * mean * Emitted[c] * sum;
  }
}
}

int TestDeepGIReferenceBounces(int, char*[])
{
  Sphere sphere = MakeSphere();
  auto capture = MakeCapture(sphere);

  // 1. Half the sphere emits.
  const double mean = SetEmission(sphere, true);
  std::cout << "sphere: " << sphere.Triangles.size() << " triangles, emitting area fraction "
            << mean << "\n";
  {
    vtkNew<vtkDeepGIReferenceIrradiance> reference;
    vtkNew<EventCounter> events;
    reference->AddObserver(vtkCommand::WarningEvent, events);
    reference->AddObserver(vtkCommand::ErrorEvent, events);
    reference->SetSceneData(sphere.PolyData);
    reference->SetSamplesPerPixel(1024);
    for (auto setting : { std::make_pair(1, 1.0), std::make_pair(2, 1.0), std::make_pair(4, 1.0),
           std::make_pair(6, 0.5) })
    {
      reference->SetNumberOfBounces(setting.first);
      reference->SetBounceDamping(setting.second);
      const std::string what = "half-emitting sphere, " + std::to_string(setting.first) +
        " bounces, damping " + std::to_string(setting.second);
      Check(Estimate(reference, capture), what + ": update");
      double exact[3];
      Series(mean, 1.0, setting.second, setting.first, exact);
      CompareExact(reference, exact, what);
    }
    Check(events->Warnings == 0 && events->Errors == 0, "valid settings: no warning");
  }

  // 2. MaximumDistance limits every segment (uniform emission).
  SetEmission(sphere, false);
  {
    vtkNew<vtkDeepGIReferenceIrradiance> reference;
    reference->SetSceneData(sphere.PolyData);
    reference->SetSamplesPerPixel(1024);
    reference->SetMaximumDistance(Radius);
    const double q = 0.25; // (m / 2R)^2
    for (int k : { 1, 3 })
    {
      reference->SetNumberOfBounces(k);
      const std::string what =
        "uniformly emitting sphere, MaximumDistance R, " + std::to_string(k) + " bounces";
      Check(Estimate(reference, capture), what + ": update");
      double exact[3];
      Series(1.0, q, 1.0, k, exact);
      CompareExact(reference, exact, what);
    }
  }

  // 3. One bounce is the one-bounce result, whatever was set before.
  SetEmission(sphere, true);
  {
    vtkNew<vtkDeepGIReferenceIrradiance> plain, changed;
    for (vtkDeepGIReferenceIrradiance* r : { plain.Get(), changed.Get() })
    {
      r->SetSceneData(sphere.PolyData);
      r->SetSamplesPerPixel(64);
    }
    changed->SetNumberOfBounces(16);
    changed->SetBounceDamping(0.3);
    changed->SetNumberOfBounces(1);
    Check(Estimate(plain, capture) && Estimate(changed, capture), "1 bounce: update");
    Check(SameOutput(plain->GetOutput(), changed->GetOutput()),
      "NumberOfBounces 1 with BounceDamping 0.3 is bit-identical to the default");
    changed->SetNumberOfBounces(2);
    Check(Estimate(changed, capture) && !SameOutput(plain->GetOutput(), changed->GetOutput()),
      "NumberOfBounces 2 differs");
  }

  // 4. Determinism with 1 and 2 threads.
  {
    vtkNew<vtkDeepGIReferenceIrradiance> reference;
    reference->SetSceneData(sphere.PolyData);
    reference->SetSamplesPerPixel(64);
    reference->SetNumberOfBounces(3);
    reference->SetBounceDamping(0.7);
    Check(Estimate(reference, capture), "3 bounces: update");
    vtkNew<vtkImageData> first;
    first->DeepCopy(reference->GetOutput());
    // The thread count is no input of the pipeline: Modified() makes each
    // update run again.
    vtkSMPTools::Initialize(1);
    reference->Modified();
    Check(Estimate(reference, capture) && SameOutput(first, reference->GetOutput()),
      "3 bounces: 1 thread is bit-identical to the default");
    vtkSMPTools::Initialize(2);
    reference->Modified();
    Check(Estimate(reference, capture) && SameOutput(first, reference->GetOutput()),
      "3 bounces: 2 threads are bit-identical to the default");
    vtkSMPTools::Initialize();
  }

  // 5. Bad values: clamped or ignored, one warning each.
  {
    vtkNew<vtkDeepGIReferenceIrradiance> reference;
    vtkNew<EventCounter> events;
    reference->AddObserver(vtkCommand::WarningEvent, events);
    reference->SetNumberOfBounces(0);
    Check(reference->GetNumberOfBounces() == 1 && events->Warnings == 1,
      "NumberOfBounces 0: 1, a warning");
    reference->SetNumberOfBounces(-3);
    Check(reference->GetNumberOfBounces() == 1 && events->Warnings == 2,
      "NumberOfBounces -3: 1, a warning");
    reference->SetNumberOfBounces(17);
    Check(reference->GetNumberOfBounces() == 16 && events->Warnings == 3,
      "NumberOfBounces 17: 16, a warning");
    reference->SetNumberOfBounces(16);
    Check(reference->GetNumberOfBounces() == 16 && events->Warnings == 3,
      "NumberOfBounces 16: no warning");
    reference->SetBounceDamping(-0.5);
    Check(reference->GetBounceDamping() == 0.0 && events->Warnings == 4,
      "BounceDamping -0.5: 0, a warning");
    reference->SetBounceDamping(2.0);
    Check(reference->GetBounceDamping() == 1.0 && events->Warnings == 5,
      "BounceDamping 2: 1, a warning");
    reference->SetBounceDamping(0.25);
    reference->SetBounceDamping(std::numeric_limits<double>::quiet_NaN());
    Check(reference->GetBounceDamping() == 0.25 && events->Warnings == 6,
      "BounceDamping NaN: ignored, a warning");
    reference->SetBounceDamping(0.0);
    Check(
      reference->GetBounceDamping() == 0.0 && events->Warnings == 6, "BounceDamping 0: no warning");
  }

  return ExitStatus();
}
