// The guard band of the deep G-buffer (vtkDeepGBufferPass::SetGuardBand,
// paper section 3.5, Table 2's last column).
//
// 1. Exactness: the frame of a W x H render with a guard band of g pixels
//    is the centre of a (W + 2g) x (H + 2g) render without a guard band
//    whose camera has the same, widened frustum (view angle theta' with
//    tan(theta' / 2) = tan(theta / 2) (H + 2g) / H): the layers, the
//    ambient visibility and the irradiance (raw gather and filtered) agree
//    on at least 99.5 % of the frame's pixels, the ambient visibility to
//    1e-4 on all (its blur reads the band's AV, which is shaded BlurRadius
//    pixels deep). The guard band is thus exactly "what lies just outside
//    the view", gathered as input.
// 2. It matters: without a guard band the frame's border pixels miss the
//    occluders and the light outside the view; their error against the
//    wide render is many times the guard band's.
// 3. GuardBandShadedFraction 0 shades only the frame, yet its raw gather
//    still reads the whole guard band (equal to the wide render).
// 4. The resolved image and depth are VTK's own, with and without a guard
//    band, also for props drawn without the routing geometry shader: wide
//    lines (VTK's geometry shader widens clip-space lines) and point
//    Gaussian splats (their geometry shader projects view-space quads).
// 5. Bad values of the guard band are clamped or ignored with a warning;
//    the pixel count is aligned to 8 and limited by the largest texture
//    (the other limits: TestDeepGuardBandLimits).

#include "DeepRadiosityTest.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDeepAmbientObscurancePass.h"
#include "vtkDeepGBufferPass.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepRadiosityPass.h"
#include "vtkMath.h"
#include "vtkPointGaussianMapper.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>

using namespace DeepRadiosityTest;
using namespace DeepGITest;

namespace
{
constexpr int Width = 96;
constexpr int Height = 72;
constexpr double GuardFraction = 0.125; // 9 pixels at 72, rounded up to 16
constexpr int Guard = 16;

// A room corner with a box, lit by the sun: occluders and lit walls reach
// beyond every edge of the frame.
void Room(vtkRenderer* renderer)
{
  const double f[3][3] = { { -3, 0, 3 }, { 3, 0, 3 }, { -3, 0, -3 } };
  Diffuse(AddQuad(renderer, f[0], f[1], f[2]), 0.9, 0.9, 0.9);
  const double b[3][3] = { { -3, 0, -3 }, { 3, 0, -3 }, { -3, 3, -3 } };
  Diffuse(AddQuad(renderer, b[0], b[1], b[2]), 0.2, 0.8, 0.2);
  const double l[3][3] = { { -3, 0, 3 }, { -3, 0, -3 }, { -3, 3, 3 } };
  Diffuse(AddQuad(renderer, l[0], l[1], l[2]), 0.9, 0.1, 0.1);
  const double center[3] = { 0.8, 0.7, -0.5 }, size[3] = { 1.2, 1.4, 1.2 };
  // The box has an ambient term, which the obscurance darkens.
  Diffuse(AddBox(renderer, center, size), 0.9, 0.9, 0.9)->GetProperty()->SetAmbient(0.2);
  AddSun(renderer, 2, 5, 3);
  SetCamera(renderer, 1.0, 1.6, 4.0, -0.5, 0.8, -1.0);
}

// Widens the camera's vertical view angle by (H + 2g) / H in tangent.
void Widen(vtkRenderer* renderer, int guard)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  const double half = vtkMath::RadiansFromDegrees(camera->GetViewAngle()) / 2.0;
  const double wide = std::atan(std::tan(half) * (Height + 2.0 * guard) / Height);
  camera->SetViewAngle(vtkMath::DegreesFromRadians(2.0 * wide));
}

struct Result
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkNew<vtkImageData> Layers;
  vtkNew<vtkImageData> Visibility;
  vtkNew<vtkImageData> Radiosity;
};

// Renders the room with the ambient obscurance pass (one frame) and then
// the radiosity pass sharing one G-buffer (`frames` frames with damping
// `damping`, no temporal filter): `guardFraction` of the height as guard
// band, `widen` pixels of widened view (the no-guard-band reference),
// `shaded` of the guard band shaded.
void Render(
  Result& r, double guardFraction, int widen, double shaded, double damping = 0.0, int frames = 1)
{
  r.Window = MakeWindow(Width + 2 * widen, Height + 2 * widen);
  r.Renderer = vtkSmartPointer<vtkRenderer>::New();
  r.Renderer->SetBackground(0, 0, 0);
  r.Window->AddRenderer(r.Renderer);
  Room(r.Renderer);
  Widen(r.Renderer, widen);
  r.Renderer->ResetCameraClippingRange(-3, 3, 0, 3, -3, 3);

  vtkNew<vtkDeepGBufferPass> gbuffer;
  gbuffer->SetGuardBand(guardFraction);
  vtkNew<vtkDeepAmbientObscurancePass> ao;
  ao->SetGBufferPass(gbuffer);
  ao->SetGuardBandShadedFraction(shaded);
  r.Renderer->SetPass(ao);
  r.Window->Render();
  ao->CaptureAmbientVisibility(r.Visibility, r.Renderer);

  vtkNew<vtkDeepRadiosityPass> radiosity;
  radiosity->SetGBufferPass(gbuffer);
  radiosity->SetDamping(damping);
  radiosity->SetTemporalAlpha(0.0);
  radiosity->SetGuardBandShadedFraction(shaded);
  r.Renderer->SetPass(radiosity);
  for (int k = 0; k < frames; ++k)
  {
    r.Window->Render();
  }
  radiosity->CaptureIrradiance(r.Radiosity, r.Renderer);
  gbuffer->CaptureLayers(r.Layers, r.Renderer);
  r.Renderer->SetPass(nullptr);
  for (vtkRenderPass* pass : std::initializer_list<vtkRenderPass*>{ ao, radiosity, gbuffer })
  {
    pass->ReleaseGraphicsResources(r.Window);
  }
}

struct Comparison
{
  int Pixels = 0;
  int Agreeing = 0;
  double Largest = 0.0;
  double BorderMean = 0.0; // mean |a - b| over the pixels within `Border` of the frame's edge
};
constexpr int Border = 12;

// Compares array `name` of `frame` (W x H) with the centre of `wide`
// ((W + 2 offset) x (H + 2 offset)) on the pixels both have a surface.
Comparison Compare(vtkImageData* frame, vtkImageData* wide, const char* name, int offset,
  vtkImageData* frameLayers, vtkImageData* wideLayers, double tolerance)
{
  Comparison c;
  vtkDataArray* a = frame->GetPointData()->GetArray(name);
  vtkDataArray* b = wide->GetPointData()->GetArray(name);
  vtkDataArray* va = frameLayers->GetPointData()->GetArray(
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 0).c_str());
  vtkDataArray* vb = wideLayers->GetPointData()->GetArray(
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 0).c_str());
  if (!a || !b || !va || !vb)
  {
    return c;
  }
  const int wideWidth = Width + 2 * offset;
  double borderSum = 0.0;
  int borderPixels = 0;
  for (int j = 0; j < Height; ++j)
  {
    for (int i = 0; i < Width; ++i)
    {
      const vtkIdType p = static_cast<vtkIdType>(j) * Width + i;
      const vtkIdType q = static_cast<vtkIdType>(j + offset) * wideWidth + i + offset;
      if (va->GetComponent(p, 0) == 0 || vb->GetComponent(q, 0) == 0)
      {
        continue;
      }
      double difference = 0.0;
      for (int k = 0; k < std::min(3, a->GetNumberOfComponents()); ++k)
      {
        difference = std::max(difference, std::abs(a->GetComponent(p, k) - b->GetComponent(q, k)));
      }
      ++c.Pixels;
      c.Agreeing += difference <= tolerance ? 1 : 0;
      c.Largest = std::max(c.Largest, difference);
      if (i < Border || j < Border || i >= Width - Border || j >= Height - Border)
      {
        borderSum += difference;
        ++borderPixels;
      }
    }
  }
  c.BorderMean = borderPixels ? borderSum / borderPixels : 0.0;
  return c;
}

bool MostlyEqual(const Comparison& c)
{
  return c.Pixels > Width * Height / 2 && c.Agreeing >= 0.995 * c.Pixels;
}

void Report(const char* what, const Comparison& c)
{
  std::printf("%s: %d px, %.2f %% agree, largest |difference| %.3g, border mean %.3g\n", what,
    c.Pixels, 100.0 * c.Agreeing / std::max(1, c.Pixels), c.Largest, c.BorderMean);
}

void TestExactness()
{
  Result guarded, wide, plain, unshaded;
  Render(guarded, GuardFraction, 0, 1.0);
  Render(wide, 0.0, Guard, 1.0);
  Render(plain, 0.0, 0, 1.0);
  Render(unshaded, GuardFraction, 0, 0.0);
  int dims[3];
  guarded.Layers->GetDimensions(dims);
  Check(dims[0] == Width && dims[1] == Height, "captures are the frame's size");
  Check(AllFinite(guarded.Radiosity) && AllFinite(guarded.Visibility), "finite results");

  const Comparison depth = Compare(guarded.Layers, wide.Layers,
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Depth, 0).c_str(), Guard, guarded.Layers,
    wide.Layers, 1e-4);
  const Comparison radiance = Compare(guarded.Layers, wide.Layers,
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Radiance, 0).c_str(), Guard, guarded.Layers,
    wide.Layers, 2e-3);
  const Comparison av = Compare(guarded.Visibility, wide.Visibility,
    vtkDeepGICaptureNames::AmbientVisibility, Guard, guarded.Layers, wide.Layers, 2e-3);
  const Comparison raw = Compare(guarded.Radiosity, wide.Radiosity,
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::RawIrradiance, 0).c_str(), Guard,
    guarded.Layers, wide.Layers, 2e-3);
  const Comparison filtered = Compare(guarded.Radiosity, wide.Radiosity,
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Irradiance, 0).c_str(), Guard,
    guarded.Layers, wide.Layers, 2e-3);
  Report("guard band vs wide: layer 0 distance", depth);
  Report("guard band vs wide: layer 0 radiance", radiance);
  Report("guard band vs wide: AV", av);
  Report("guard band vs wide: raw E", raw);
  Report("guard band vs wide: E", filtered);
  Check(MostlyEqual(depth), "layer 0 = the wide render's centre");
  Check(MostlyEqual(radiance), "radiance = the wide render's centre");
  Check(MostlyEqual(av), "AV = the wide render's centre");
  // The blur at the frame's edges reads the band's AV: shaded for it also
  // without the temporal filter, which shades no more of the band than that.
  Check(av.Largest <= 1e-4, "AV = the wide render's centre at every pixel, the edges included");
  Check(MostlyEqual(raw), "raw irradiance = the wide render's centre");
  Check(MostlyEqual(filtered), "filtered irradiance = the wide render's centre");

  const Comparison plainAV = Compare(plain.Visibility, wide.Visibility,
    vtkDeepGICaptureNames::AmbientVisibility, Guard, plain.Layers, wide.Layers, 2e-3);
  const Comparison plainE = Compare(plain.Radiosity, wide.Radiosity,
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Irradiance, 0).c_str(), Guard, plain.Layers,
    wide.Layers, 2e-3);
  Report("no guard band vs wide: AV", plainAV);
  Report("no guard band vs wide: E", plainE);
  Check(plainAV.BorderMean > 10.0 * av.BorderMean && plainAV.BorderMean > 1e-3,
    "without a guard band the border's AV misses what is outside the view");
  Check(plainE.BorderMean > 10.0 * filtered.BorderMean && plainE.BorderMean > 1e-3,
    "without a guard band the border's irradiance misses the light outside the view");

  const Comparison unshadedRaw = Compare(unshaded.Radiosity, wide.Radiosity,
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::RawIrradiance, 0).c_str(), Guard,
    unshaded.Layers, wide.Layers, 2e-3);
  Report("shaded fraction 0 vs wide: raw E", unshadedRaw);
  Check(MostlyEqual(unshadedRaw), "shaded fraction 0 still gathers from the whole guard band");

  // Progressive bounces (section 3.3) reproject last frame's irradiance:
  // with the whole guard band shaded, five frames of bounces also equal the
  // wide render's.
  Result guardedBounces, wideBounces;
  Render(guardedBounces, GuardFraction, 0, 1.0, 0.5, 5);
  Render(wideBounces, 0.0, Guard, 1.0, 0.5, 5);
  const Comparison bounces = Compare(guardedBounces.Radiosity, wideBounces.Radiosity,
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0).c_str(), Guard,
    guardedBounces.Layers, wideBounces.Layers, 2e-3);
  const Comparison bouncesLayer1 = Compare(guardedBounces.Radiosity, wideBounces.Radiosity,
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 1).c_str(), Guard,
    guardedBounces.Layers, wideBounces.Layers, 2e-3);
  Report("guard band vs wide after 5 bounces: L_ind", bounces);
  Report("guard band vs wide after 5 bounces: layer 1 L_ind", bouncesLayer1);
  Check(MostlyEqual(bounces), "bounces = the wide render's centre");
}

// Resolved colour and depth with a guard band = without one = VTK's own
// image, with a wide-line wireframe prop (VTK's geometry shader widens
// clip-space lines) and point Gaussian splats (their geometry shader
// projects view-space quads; their vertex shader has no position hook).
void TestResolve()
{
  // 0: VTK without a pass; 1: G-buffer without a guard band; 2: with 0.25;
  // 3: with 0.25 and without the splats.
  vtkNew<vtkImageData> rgb[4], depth[4];
  for (int k = 0; k < 4; ++k)
  {
    auto window = MakeWindow(Width, Height);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    Room(renderer);
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(-1.5, 1.0, 0.5);
    sphere->SetRadius(0.6);
    vtkActor* wire = AddSourceActor(renderer, sphere);
    wire->GetProperty()->SetRepresentationToWireframe();
    wire->GetProperty()->SetLineWidth(3.0);
    wire->GetProperty()->SetColor(1.0, 1.0, 0.2);
    vtkNew<vtkPoints> centers;
    centers->InsertNextPoint(1.8, 0.4, 1.2);
    centers->InsertNextPoint(-0.5, 2.0, -1.0);
    vtkNew<vtkPolyData> points;
    points->SetPoints(centers);
    vtkNew<vtkPointGaussianMapper> splats;
    splats->SetInputData(points);
    splats->SetScaleFactor(0.35);
    splats->EmissiveOff();
    vtkNew<vtkActor> splatActor;
    splatActor->SetMapper(splats);
    splatActor->GetProperty()->SetColor(0.3, 0.5, 1.0);
    splatActor->SetVisibility(k != 3);
    renderer->AddActor(splatActor);
    renderer->ResetCameraClippingRange();
    vtkNew<vtkDeepGBufferPass> pass;
    pass->SetGuardBand(k >= 2 ? 0.25 : 0.0);
    if (k > 0)
    {
      renderer->SetPass(pass);
    }
    window->Render();
    // 0.25 x 72 = 18 pixels, rounded up to a multiple of 8.
    Check(pass->GetEffectiveGuardBand() == (k >= 2 ? 24 : 0), "effective guard band in pixels");
    ReadWindow(window, rgb[k], depth[k]);
    renderer->SetPass(nullptr);
    pass->ReleaseGraphicsResources(window);
  }
  auto depthDifference = [&](int a, int b, double& largest)
  {
    vtkDataArray* da = depth[a]->GetPointData()->GetScalars();
    vtkDataArray* db = depth[b]->GetPointData()->GetScalars();
    int differing = 0;
    largest = 0.0;
    for (vtkIdType p = 0; p < da->GetNumberOfTuples(); ++p)
    {
      const double d = std::abs(da->GetComponent(p, 0) - db->GetComponent(p, 0));
      largest = std::max(largest, d);
      differing += d > 1e-5 ? 1 : 0;
    }
    return differing;
  };
  auto colourDiffering = [&](int a, int b)
  {
    vtkDataArray* x = rgb[a]->GetPointData()->GetScalars();
    vtkDataArray* y = rgb[b]->GetPointData()->GetScalars();
    int differing = 0;
    for (vtkIdType p = 0; p < x->GetNumberOfTuples(); ++p)
    {
      double d = 0.0;
      for (int c = 0; c < 3; ++c)
      {
        d = std::max(d, std::abs(x->GetComponent(p, c) - y->GetComponent(p, c)));
      }
      differing += d > 8.0 ? 1 : 0;
    }
    return differing;
  };
  double largestGuard = 0.0, largestVTK = 0.0;
  const int depthGuard = depthDifference(2, 1, largestGuard);
  const int depthVTK = depthDifference(1, 0, largestVTK);
  const double colourGuard = MaximumColorDifference(rgb[2], rgb[1]);
  const int colourVTK = colourDiffering(1, 0);
  const int splatPixels = colourDiffering(2, 3);
  std::printf("resolve with guard band 0.25 vs none: largest colour difference %.3g, %d depth "
              "pixels differ by > 1e-5 (largest %.3g); G-buffer vs VTK: %d pixels differ by "
              "> 8/255, %d depth pixels by > 1e-5 (largest %.3g); the splats cover %d pixels\n",
    colourGuard, depthGuard, largestGuard, colourVTK, depthVTK, largestVTK, splatPixels);
  Check(depthGuard <= Width * Height / 200, "resolved depth with a guard band is the frame's");
  Check(colourGuard <= 3.0, "resolved colour with a guard band is the frame's");
  Check(colourVTK <= Width * Height / 200 && depthVTK <= Width * Height / 200,
    "the resolved G-buffer is VTK's image");
  Check(splatPixels > 200, "the point Gaussian splats are drawn in the layers");
}

void TestBadValues()
{
  vtkNew<vtkDeepGBufferPass> pass;
  vtkNew<vtkCallbackCommand> counter;
  int warnings = 0;
  counter->SetClientData(&warnings);
  counter->SetCallback(
    [](vtkObject*, unsigned long, void* data, void*) { ++*static_cast<int*>(data); });
  pass->AddObserver(vtkCommand::WarningEvent, counter);
  pass->SetGuardBand(0.2);
  pass->SetGuardBand(std::nan(""));
  Check(pass->GetGuardBand() == 0.2 && warnings == 1, "NaN guard band ignored with a warning");
  pass->SetGuardBand(-1.0);
  Check(pass->GetGuardBand() == 0.0 && warnings == 2, "negative guard band clamped to 0");
  pass->SetGuardBand(7.0);
  Check(pass->GetGuardBand() == vtkDeepGBufferPass::MAXIMUM_GUARD_BAND && warnings == 3,
    "huge guard band clamped to the maximum");
  // The pixel count: rounded up to 8, limited by the largest texture.
  bool limited = true;
  Check(
    vtkDeepGBufferPass::ComputeGuardBandPixels(0.1, 1920, 1080, 16384, &limited) == 112 && !limited,
    "0.1 of 1080 is 108 pixels, rounded up to 112");
  Check(vtkDeepGBufferPass::ComputeGuardBandPixels(0.0, 640, 480, 16384) == 0 &&
      vtkDeepGBufferPass::ComputeGuardBandPixels(0.001, 640, 480, 16384) == 0 &&
      vtkDeepGBufferPass::ComputeGuardBandPixels(0.002, 640, 480, 16384) == 8,
    "small bands round to 0 or up to 8");
  Check(
    vtkDeepGBufferPass::ComputeGuardBandPixels(0.5, 12000, 6000, 13000, &limited) == 496 && limited,
    "a band that would exceed the largest texture is limited to fit (12000 + 2 x 496 <= 13000)");
  Check(
    vtkDeepGBufferPass::ComputeGuardBandPixels(0.1, 20000, 100, 16384, &limited) == 0 && limited,
    "a frame wider than the largest texture gets no band");
  Check(vtkDeepGBufferPass::ComputeGuardBandPixels(std::nan(""), 640, 480, 16384) == 0 &&
      vtkDeepGBufferPass::ComputeGuardBandPixels(9.0, 640, 480, 16384) == 240,
    "NaN gives no band, a huge fraction the maximum");

  vtkNew<vtkDeepRadiosityPass> radiosity;
  radiosity->AddObserver(vtkCommand::WarningEvent, counter);
  Check(radiosity->GetGBufferPass()->GetGuardBand() == vtkDeepRadiosityPass::DEFAULT_GUARD_BAND,
    "the radiosity pass's G-buffer has the default guard band");
  radiosity->SetGuardBandShadedFraction(std::nan(""));
  radiosity->SetGuardBandShadedFraction(3.0);
  Check(radiosity->GetGuardBandShadedFraction() == 1.0 && warnings == 5,
    "shaded fraction: NaN ignored, 3 clamped to 1, with warnings");
  radiosity->SetPreset(vtkDeepRadiosityPass::HIGH_PERFORMANCE);
  Check(radiosity->GetGuardBandShadedFraction() == 0.1, "HIGH_PERFORMANCE shades 10 %");
  radiosity->SetPreset(vtkDeepRadiosityPass::HIGH_QUALITY);
  Check(radiosity->GetGuardBandShadedFraction() == 0.8, "HIGH_QUALITY shades 80 %");
}
}

int TestDeepGuardBand(int, char*[])
{
  TestExactness();
  TestResolve();
  TestBadValues();
  return ExitStatus();
}
