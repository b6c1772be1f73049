// Extreme scenes and bad parameters for vtkDeepRadiosityPass (small
// windows, a few frames each); every capture is checked for NaN, Inf and
// negative light:
// - scale: the red-wall scene at 1e-4 and 1e4 times its size gives the
//   same L_ind as at size 1 (automatic radius, tolerance and separation):
//   mean |difference| < 1e-3 and >= 99 % of the pixels within 0.01;
// - near/far 1e-1 and 1e-7 (near 1e-6 and 1e-1 before a far plane at
//   10): L_ind finite and non-negative, and its mean |difference| from the
//   clipping range fitted to the scene below 0.01 (the G-buffer stores
//   camera-space distance in float, not the depth buffer's value);
// - alpha 0, 0.99 and 1, delta 0 and 1, N 1, 98 and 99 (clamped to 98);
// - no lights: L_ind exactly 0 and one warning; a black scene: L_ind
//   exactly 0; an explicit radius 0: L_ind exactly 0; an empty scene: one
//   warning, nothing to gather;
// - an all-white closed box (rho = 1) viewed from inside, 100 frames: with
//   delta = 0.45 every L_ind stays below 2 rho D / (1 - 2 rho delta) = 20 D;
//   with delta = 1 (a divergent configuration: the true radiosity of a
//   closed white room is infinite) every value stays finite;
// - a shared one-layer G-buffer: layer 0 lit, layer 1 empty and 0;
// - bad parameters (NaN, infinite, negative, out of range) warn once each
//   and keep or clamp the value.

#include "DeepRadiosityTest.h"
#include "vtkDeepGICaptureNames.h"

#include <cmath>
#include <limits>

using namespace DeepRadiosityTest;
using namespace DeepGITest;

namespace
{
using Configure = std::function<void(vtkDeepRadiosityPass*)>;

bool Healthy(Frame& f, const std::string& what)
{
  const bool finite = AllFinite(f.Radiosity);
  const bool positive =
    Minimum(f.Radiosity,
      vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0)) >= 0.0 &&
    Minimum(f.Radiosity,
      vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 1)) >= 0.0 &&
    Minimum(f.Radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Irradiance, 0)) >=
      0.0 &&
    Minimum(f.Radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Irradiance, 1)) >= 0.0;
  Check(finite && positive, what + ": finite and non-negative");
  return finite && positive;
}

void TestScale()
{
  Frame frames[3];
  const double scales[3] = { 1.0, 1e-4, 1e4 };
  for (int k = 0; k < 3; ++k)
  {
    vtkNew<vtkDeepRadiosityPass> pass;
    pass->SetTemporalAlpha(0.0);
    const double s = scales[k];
    if (!RenderFrames([s](vtkRenderer* r) { RedWallScene(r, s); }, pass, 3, frames[k]))
    {
      return;
    }
    Healthy(frames[k], "scale " + std::to_string(s));
    pass->ReleaseGraphicsResources(frames[k].Window);
  }
  const double radius =
    frames[0].Radiosity->GetFieldData()->GetArray(vtkDeepGICaptureNames::Radius)->GetTuple1(0);
  for (int k = 1; k < 3; ++k)
  {
    long compared = 0, far = 0;
    double mean = 0.0;
    for (int j = 0; j < frames[0].Height; ++j)
    {
      for (int i = 0; i < frames[0].Width; ++i)
      {
        if (At(frames[0].Radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 0),
              i, j) == 0 &&
          At(frames[k].Radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 0), i,
            j) == 0)
        {
          continue;
        }
        ++compared;
        double worst = 0.0;
        for (int c = 0; c < 3; ++c)
        {
          const double d = std::abs(
            At(frames[0].Radiosity,
              vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0), i, j, c) -
            At(frames[k].Radiosity,
              vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0), i, j, c));
          mean += d / 3.0;
          worst = std::max(worst, d);
        }
        far += worst > 0.01 ? 1 : 0;
      }
    }
    mean /= std::max(compared, 1L);
    const double r =
      frames[k].Radiosity->GetFieldData()->GetArray(vtkDeepGICaptureNames::Radius)->GetTuple1(0);
    std::printf("scale %g: radius %g (scale 1: %g), mean |L_ind - L_ind(scale 1)| %.2e, %ld of "
                "%ld pixels differ by > 0.01\n",
      scales[k], r, radius, mean, far, compared);
    Check(std::abs(r / scales[k] - radius) < 1e-6 * radius, "radius follows the scale");
    Check(mean < 1e-3 && far <= compared / 100, "same indirect light at any scale");
  }
}

// Mean over the pixels valid in both of |L_ind(a) - L_ind(b)| (RGB mean).
double MeanDifference(Frame& a, Frame& b)
{
  long compared = 0;
  double sum = 0.0;
  for (int j = 0; j < a.Height; ++j)
  {
    for (int i = 0; i < a.Width; ++i)
    {
      if (At(a.Radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 0), i, j) ==
          0 ||
        At(b.Radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 0), i, j) == 0)
      {
        continue;
      }
      ++compared;
      for (int c = 0; c < 3; ++c)
      {
        sum +=
          std::abs(
            At(a.Radiosity,
              vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0), i, j, c) -
            At(b.Radiosity,
              vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0), i, j, c)) /
          3.0;
      }
    }
  }
  return compared ? sum / compared : VTK_DOUBLE_MAX;
}

void TestClippingRange()
{
  Frame fitted;
  vtkNew<vtkDeepRadiosityPass> reference;
  reference->SetTemporalAlpha(0.0);
  if (!RenderFrames([](vtkRenderer* r) { RedWallScene(r); }, reference, 3, fitted))
  {
    return;
  }
  const double ranges[2][2] = { { 1.0, 10.0 }, { 1e-6, 10.0 } };
  for (const auto& range : ranges)
  {
    Frame f;
    vtkNew<vtkDeepRadiosityPass> pass;
    pass->SetTemporalAlpha(0.0);
    if (!RenderFrames([](vtkRenderer* r) { RedWallScene(r); }, pass, 3, f, 160, 120, range))
    {
      continue;
    }
    char what[64];
    std::snprintf(what, sizeof(what), "near/far %.0e", range[0] / range[1]);
    const double* used = f.Renderer->GetActiveCamera()->GetClippingRange();
    const double mean = MeanDifference(f, fitted);
    std::printf("%s (rendered with near %g, far %g): mean |L_ind - L_ind(fitted range)| %.2e\n",
      what, used[0], used[1], mean);
    Check(used[0] == range[0] && used[1] == range[1], std::string(what) + ": range kept");
    Healthy(f, what);
    Check(mean < 0.01, std::string(what) + ": same indirect light as with a fitted clipping range");
    pass->ReleaseGraphicsResources(f.Window);
  }
  reference->ReleaseGraphicsResources(fitted.Window);
}

void TestParameters()
{
  struct Case
  {
    const char* Name;
    Configure Setup;
  };
  const Case cases[] = {
    { "alpha 0", [](vtkDeepRadiosityPass* p) { p->SetTemporalAlpha(0.0); } },
    { "alpha 0.99", [](vtkDeepRadiosityPass* p) { p->SetTemporalAlpha(0.99); } },
    { "alpha 1", [](vtkDeepRadiosityPass* p) { p->SetTemporalAlpha(1.0); } },
    { "delta 0", [](vtkDeepRadiosityPass* p) { p->SetDamping(0.0); } },
    { "delta 1", [](vtkDeepRadiosityPass* p) { p->SetDamping(1.0); } },
    { "N 1", [](vtkDeepRadiosityPass* p) { p->SetNumberOfSamples(1); } },
    { "N 98", [](vtkDeepRadiosityPass* p) { p->SetNumberOfSamples(98); } },
    { "HIGH_QUALITY", [](vtkDeepRadiosityPass* p) { p->SetPresetToHighQuality(); } },
    { "HIGH_PERFORMANCE", [](vtkDeepRadiosityPass* p) { p->SetPresetToHighPerformance(); } },
    { "no filter, MIP 0..0",
      [](vtkDeepRadiosityPass* p)
      {
        p->SetBlurRadius(0);
        p->SetMinimumMipLevel(0);
        p->SetMaximumMipLevel(0);
      } },
  };
  for (const Case& c : cases)
  {
    vtkNew<vtkDeepRadiosityPass> pass;
    c.Setup(pass);
    Frame f;
    if (RenderFrames([](vtkRenderer* r) { RedWallScene(r); }, pass, 5, f, 96, 72))
    {
      Healthy(f, c.Name);
      std::printf("%s: largest L_ind %.3f\n", c.Name,
        Maximum(
          f.Radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0)));
      Check(Maximum(f.Radiosity,
              vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0)) > 0.05,
        std::string(c.Name) + ": light");
    }
    pass->ReleaseGraphicsResources(f.Window);
  }
  vtkNew<vtkDeepRadiosityPass> pass;
  EventCounter warnings(pass, vtkCommand::WarningEvent);
  pass->SetNumberOfSamples(99);
  Check(warnings.Count == 1 && pass->GetNumberOfSamples() == 98, "N 99 becomes 98 with a warning");
  Frame f;
  if (RenderFrames([](vtkRenderer* r) { RedWallScene(r); }, pass, 2, f, 96, 72))
  {
    Healthy(f, "N 99");
  }
  pass->ReleaseGraphicsResources(f.Window);
}

// Renders `scene` (5 frames) and checks that L_ind is exactly 0.
void ExpectDark(const char* what, const Scene& scene, const Configure& setup, int expectedWarnings)
{
  vtkNew<vtkDeepRadiosityPass> pass;
  setup(pass);
  EventCounter warnings(pass, vtkCommand::WarningEvent);
  Frame f;
  if (!RenderFrames(scene, pass, 5, f, 96, 72))
  {
    return;
  }
  Healthy(f, what);
  const double largest = std::max(
    Maximum(f.Radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0)),
    Maximum(f.Radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 1)));
  std::printf("%s: largest L_ind %g, %d warning(s)\n", what, largest, warnings.Count);
  Check(largest == 0.0, std::string(what) + ": no indirect light");
  Check(warnings.Count == expectedWarnings, std::string(what) + ": warnings");
  pass->ReleaseGraphicsResources(f.Window);
}

void TestDark()
{
  ExpectDark(
    "no lights",
    [](vtkRenderer* r)
    {
      RedWallScene(r);
      r->RemoveAllLights();
      r->AutomaticLightCreationOff();
    },
    [](vtkDeepRadiosityPass*) {}, 1);
  ExpectDark(
    "black scene",
    [](vtkRenderer* r)
    {
      RedWallScene(r);
      for (int a = 0; a < r->GetActors()->GetNumberOfItems(); ++a)
      {
        Diffuse(vtkActor::SafeDownCast(r->GetActors()->GetItemAsObject(a)), 0, 0, 0);
      }
    },
    [](vtkDeepRadiosityPass*) {}, 0);
  ExpectDark(
    "radius 0", [](vtkRenderer* r) { RedWallScene(r); },
    [](vtkDeepRadiosityPass* p) { p->SetRadius(0.0); }, 0);
  ExpectDark(
    "empty scene", [](vtkRenderer* r) { AddSun(r, 1, 1, 1); }, [](vtkDeepRadiosityPass*) {}, 1);
}

// Six white quads facing inwards (4 x 3 x 4), lit by a sun (VTK's lights
// cast no shadows, so the walls facing it are lit), camera inside.
void ClosedWhiteBox(vtkRenderer* renderer)
{
  const double q[6][3][3] = {
    { { -2, 0, 2 }, { 2, 0, 2 }, { -2, 0, -2 } },   // floor, normal +y
    { { -2, 3, -2 }, { 2, 3, -2 }, { -2, 3, 2 } },  // ceiling, normal -y
    { { -2, 0, -2 }, { 2, 0, -2 }, { -2, 3, -2 } }, // back, normal +z
    { { 2, 0, 2 }, { -2, 0, 2 }, { 2, 3, 2 } },     // front, normal -z
    { { -2, 0, 2 }, { -2, 0, -2 }, { -2, 3, 2 } },  // left, normal +x
    { { 2, 0, -2 }, { 2, 0, 2 }, { 2, 3, -2 } },    // right, normal -x
  };
  for (const auto& quad : q)
  {
    Diffuse(AddQuad(renderer, quad[0], quad[1], quad[2]), 1, 1, 1);
  }
  AddSun(renderer, -1, 3, 2);
  SetCamera(renderer, 0.5, 1.6, 1.8, -0.3, 1.0, -2.0);
  renderer->GetActiveCamera()->SetViewAngle(90.0);
}

void TestClosedBox()
{
  for (double delta : { 0.45, 1.0 })
  {
    vtkNew<vtkDeepRadiosityPass> pass;
    pass->SetDamping(delta);
    Frame f;
    if (!RenderFrames(ClosedWhiteBox, pass, 100, f, 48, 48))
    {
      continue;
    }
    const bool healthy = Healthy(f, "closed white box");
    double direct = 0.0;
    vtkDataArray* radiance = Layer(f.Layers, vtkDeepGICaptureNames::Radiance, 0);
    for (vtkIdType p = 0; p < radiance->GetNumberOfTuples(); ++p)
    {
      direct = std::max(direct, radiance->GetComponent(p, 0));
    }
    const double largest = Maximum(
      f.Radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0));
    std::printf("closed white box, delta %.2f, 100 frames: largest L_ind %.3f, largest direct "
                "%.3f\n",
      delta, largest, direct);
    if (delta < 0.5)
    {
      Check(healthy && largest <= 2.0 * direct / (1.0 - 2.0 * delta),
        "closed white box: below 2 rho D / (1 - 2 rho delta)");
    }
    Check(
      Total(f.Radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 0)) == 48 * 48,
      "the box fills the view");
    pass->ReleaseGraphicsResources(f.Window);
  }
}

// A shared G-buffer pass with one layer: layer 0 gathers, layer 1 is empty.
void TestOneLayer()
{
  vtkNew<vtkDeepGBufferPass> gbuffer;
  gbuffer->SetNumberOfLayers(1);
  vtkNew<vtkDeepRadiosityPass> pass;
  pass->SetGBufferPass(gbuffer);
  Frame f;
  if (!RenderFrames([](vtkRenderer* r) { RedWallScene(r); }, pass, 3, f, 96, 72))
  {
    return;
  }
  Healthy(f, "one layer");
  const double layers =
    f.Radiosity->GetFieldData()->GetArray(vtkDeepGICaptureNames::NumberOfLayers)->GetTuple1(0);
  std::printf(
    "one G-buffer layer: %g radiosity layer(s), %g valid layer-1 px, largest L_ind %.3f\n", layers,
    Total(f.Radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 1)),
    Maximum(f.Radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0)));
  Check(pass->GetGBufferPass() == gbuffer.GetPointer(), "shared G-buffer pass");
  Check(layers == 1 &&
      Total(f.Radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 1)) == 0 &&
      Maximum(f.Radiosity,
        vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 1)) == 0 &&
      Maximum(f.Radiosity,
        vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0)) > 0.05,
    "one layer: layer 0 lit, layer 1 empty");
  pass->ReleaseGraphicsResources(f.Window);
}

void TestBadParameters()
{
  vtkNew<vtkDeepRadiosityPass> pass;
  EventCounter warnings(pass, vtkCommand::WarningEvent);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  int expected = 0;
  auto expect = [&](bool ok, const std::string& what)
  {
    ++expected;
    Check(ok && warnings.Count == expected, what);
  };
  pass->SetRadius(2.0);
  pass->SetRadius(nan);
  expect(pass->GetRadius() == 2.0, "radius NaN keeps the value");
  pass->SetRadius(-1.0);
  expect(pass->GetRadius() == 0.0 && !pass->GetAutomaticRadius(), "negative radius becomes 0");
  pass->SetNumberOfSamples(0);
  expect(pass->GetNumberOfSamples() == 1, "N 0 becomes 1");
  pass->SetTemporalAlpha(1.5);
  expect(pass->GetTemporalAlpha() == 1.0, "alpha 1.5 becomes 1");
  pass->SetTemporalAlpha(-0.5);
  expect(pass->GetTemporalAlpha() == 0.0, "alpha -0.5 becomes 0");
  pass->SetTemporalAlpha(nan);
  expect(pass->GetTemporalAlpha() == 0.0, "alpha NaN keeps the value");
  pass->SetDamping(2.0);
  expect(pass->GetDamping() == 1.0, "delta 2 becomes 1");
  pass->SetDamping(nan);
  expect(pass->GetDamping() == 1.0, "delta NaN keeps the value");
  pass->SetReprojectionTolerance(-1.0);
  expect(pass->GetReprojectionTolerance() == 0.0 && !pass->GetAutomaticReprojectionTolerance(),
    "negative tolerance becomes 0");
  pass->SetReprojectionTolerance(inf);
  expect(pass->GetReprojectionTolerance() == 0.0, "infinite tolerance keeps the value");
  pass->SetEnvironmentIrradiance(nan, 1.0, 1.0);
  expect(pass->GetAutomaticEnvironmentIrradiance(), "NaN environment keeps the automatic one");
  pass->SetEnvironmentIrradiance(-1.0, 0.5, 0.25);
  expect(pass->GetEnvironmentIrradiance()[0] == 0.0 && pass->GetEnvironmentIrradiance()[1] == 0.5 &&
      !pass->GetAutomaticEnvironmentIrradiance(),
    "negative environment component becomes 0");
  pass->SetGBufferPass(nullptr);
  expect(pass->GetGBufferPass() != nullptr, "null G-buffer pass refused");
}
}

int TestDeepRadiosityExtremes(int, char*[])
{
  TestScale();
  TestClippingRange();
  TestParameters();
  TestDark();
  TestClosedBox();
  TestOneLayer();
  TestBadParameters();
  return ExitStatus();
}
