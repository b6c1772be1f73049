// Numerical stability of vtkDeepAmbientObscurancePass and of the deep
// G-buffer under it at extreme scales, clipping ranges, view angles, window
// sizes and sample counts (160 x 120 px unless stated). Each check is
// printed with its numbers and its tolerance; the reasons are next to them.
//
// Scene: floor + wall corner + a box (occludes the floor and the wall, so
// layer 1 has content), automatic radius and dz (5 % and 1.5 % of the
// bounds' diagonal: both follow the scene's scale).
// The 4096 x 4096 case dominates the run time: about 35-40 s on llvmpipe
// with 2 cores (the rest of the test takes about 5 s).

#include "DeepGBufferTestUtilities.h"

#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkDeepAmbientObscurancePass.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <vector>

using namespace DeepGBufferTest;
using namespace DeepGITest;

namespace
{
constexpr int Width = 160;
constexpr int Height = 120;

void AddQuad(
  vtkRenderer* renderer, double s, const double o[3], const double a[3], const double b[3])
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(s * o[0], s * o[1], s * o[2]);
  plane->SetPoint1(s * a[0], s * a[1], s * a[2]);
  plane->SetPoint2(s * b[0], s * b[1], s * b[2]);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
}

using Scene = std::function<void(vtkRenderer*)>;

// Floor y = 0, wall z = -2, a unit box on the floor; everything times s.
Scene CornerBox(double s)
{
  return [s](vtkRenderer* renderer)
  {
    const double f0[3] = { -4, 0, 4 }, f1[3] = { 4, 0, 4 }, f2[3] = { -4, 0, -2 };
    AddQuad(renderer, s, f0, f1, f2);
    const double w0[3] = { -4, 0, -2 }, w1[3] = { 4, 0, -2 }, w2[3] = { -4, 3, -2 };
    AddQuad(renderer, s, w0, w1, w2);
    vtkNew<vtkCubeSource> cube;
    cube->SetCenter(0.8 * s, 0.5 * s, -0.8 * s);
    cube->SetXLength(s);
    cube->SetYLength(s);
    cube->SetZLength(s);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(cube->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    renderer->AddActor(actor);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(0.0, 2.5 * s, 5.0 * s);
    camera->SetFocalPoint(0.0, 0.5 * s, -1.0 * s);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetViewAngle(40.0);
    renderer->ResetCameraClippingRange();
  };
}

struct Frame
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkNew<vtkImageData> AO;
  vtkNew<vtkImageData> Layers;
  bool Ok = false;
};

// Renders 3 frames of `scene` (then `after` may change the camera) with the
// AO pass and captures AV and the layers.
void RenderAO(const Scene& scene, vtkDeepAmbientObscurancePass* pass, Frame& f, int width = Width,
  int height = Height, const std::function<void(vtkRenderer*)>& after = nullptr,
  bool captureLayers = true, int frames = 3)
{
  f.Window = MakeWindow(width, height);
  f.Renderer = vtkSmartPointer<vtkRenderer>::New();
  f.Window->AddRenderer(f.Renderer);
  scene(f.Renderer);
  if (after)
  {
    after(f.Renderer);
  }
  f.Renderer->SetPass(pass);
  for (int k = 0; k < frames; ++k)
  {
    f.Window->Render();
  }
  f.Ok = pass->CaptureAmbientVisibility(f.AO, f.Renderer) &&
    (!captureLayers || pass->GetGBufferPass()->CaptureLayers(f.Layers, f.Renderer));
}

vtkDataArray* Array(vtkImageData* image, const char* name)
{
  return image->GetPointData()->GetArray(name);
}

// AV (both arrays) finite and in [0, 1]; no NaN/Inf in the layers either.
bool FiniteAndInRange(Frame& f, bool layers = true)
{
  if (!f.Ok || !AllFinite(f.AO) || (layers && !AllFinite(f.Layers)))
  {
    return false;
  }
  for (const char* name :
    { vtkDeepGICaptureNames::AmbientVisibility, vtkDeepGICaptureNames::RawAmbientVisibility })
  {
    vtkDataArray* a = Array(f.AO, name);
    for (vtkIdType p = 0; p < a->GetNumberOfTuples(); ++p)
    {
      const double v = a->GetTuple1(p);
      if (v < 0.0 || v > 1.0)
      {
        return false;
      }
    }
  }
  return true;
}

struct Difference
{
  double Max = 0.0, Mean = 0.0;
  long Pixels = 0, Above = 0; // pixels valid in both; of those, |d| > `limit`
  long MaskMismatches = 0;
};

// Pixelwise |a - b| of an AV array where both frames have a surface.
Difference CompareAV(vtkImageData* a, vtkImageData* b, const char* name, double limit)
{
  Difference d;
  vtkDataArray* x = Array(a, name);
  vtkDataArray* y = Array(b, name);
  vtkDataArray* vx = Array(a, vtkDeepGICaptureNames::Valid);
  vtkDataArray* vy = Array(b, vtkDeepGICaptureNames::Valid);
  for (vtkIdType p = 0; p < x->GetNumberOfTuples(); ++p)
  {
    if ((vx->GetTuple1(p) != 0) != (vy->GetTuple1(p) != 0))
    {
      ++d.MaskMismatches;
      continue;
    }
    if (vx->GetTuple1(p) == 0)
    {
      continue;
    }
    const double e = std::abs(x->GetTuple1(p) - y->GetTuple1(p));
    ++d.Pixels;
    d.Above += e > limit ? 1 : 0;
    d.Mean += e;
    d.Max = std::max(d.Max, e);
  }
  d.Mean /= std::max(d.Pixels, 1L);
  return d;
}

void PrintDifference(const char* what, const char* name, const Difference& d, double limit)
{
  std::printf("  %s %s: %ld px, max |dAV| %.2e, mean %.2e, %ld px above %.0e, %ld mask "
              "mismatches\n",
    what, name, d.Pixels, d.Max, d.Mean, d.Above, limit, d.MaskMismatches);
}

// Layers of `b` (scale s) against `a` (scale 1): depth / s within a relative
// `tolerance`, same masks; layer 1 at least dz behind layer 0 in both.
void CompareScaledLayers(Frame& a, Frame& b, double s, const char* what, long allowedBeyond = 0)
{
  long mismatch = 0, compared = 0, beyond = 0;
  double worst = 0.0;
  for (int layer = 0; layer < 2; ++layer)
  {
    vtkDataArray* da = Layer(a.Layers, vtkDeepGICaptureNames::Depth, layer);
    vtkDataArray* db = Layer(b.Layers, vtkDeepGICaptureNames::Depth, layer);
    vtkDataArray* va = Layer(a.Layers, vtkDeepGICaptureNames::Valid, layer);
    vtkDataArray* vb = Layer(b.Layers, vtkDeepGICaptureNames::Valid, layer);
    for (vtkIdType p = 0; p < da->GetNumberOfTuples(); ++p)
    {
      if ((va->GetTuple1(p) != 0) != (vb->GetTuple1(p) != 0))
      {
        ++mismatch;
        continue;
      }
      if (va->GetTuple1(p) != 0)
      {
        ++compared;
        const double e = std::abs(db->GetTuple1(p) / s - da->GetTuple1(p)) / da->GetTuple1(p);
        worst = std::max(worst, e);
        beyond += e > 1e-5 ? 1 : 0;
      }
    }
  }
  const double dz = b.Renderer && vtkDeepAmbientObscurancePass::SafeDownCast(b.Renderer->GetPass())
    ? vtkDeepAmbientObscurancePass::SafeDownCast(b.Renderer->GetPass())
        ->GetGBufferPass()
        ->GetEffectiveMinimumSeparation()
    : 0.0;
  SeparationReport sep = CheckSeparation(b.Layers, 1, dz, 1e-5);
  std::printf("  %s layers vs scale 1: %ld px compared, worst relative depth difference %.2e "
              "(%ld px above 1e-5), %ld mask mismatches; layer 1: %ld px, %ld closer than dz = "
              "%.3g\n",
    what, compared, worst, beyond, mismatch, sep.Pixels, sep.Violations, dz);
  // Depths are float camera distances (24-bit mantissa) rasterised from
  // scaled float vertices: 1e-5 relative is ~100 ulps. Edges may move by a
  // pixel under rounding of the scaled coordinates: <= 0.5 % of the pixels.
  Check(beyond <= allowedBeyond, "scaled layer depth = scale x depth (relative 1e-5)");
  Check(mismatch <= compared / 200, "layer masks equal at scale (<= 0.5 % edge pixels)");
  // Separation with 1e-5 of the depth: the test's own float rounding.
  Check(sep.Violations == 0 && sep.Pixels > Width * Height / 50, "layer 1 >= dz behind layer 0");
}

void TestScale(Frame& reference)
{
  std::printf("scale:\n");
  vtkNew<vtkDeepAmbientObscurancePass> pass1;
  RenderAO(CornerBox(1.0), pass1, reference);
  Check(FiniteAndInRange(reference), "scale 1: AV and layers finite, AV in [0, 1]");
  const double r1 = pass1->GetEffectiveRadius();
  for (double s : { 1e-4, 1e4 })
  {
    vtkNew<vtkDeepAmbientObscurancePass> pass;
    Frame f;
    RenderAO(CornerBox(s), pass, f);
    char what[64];
    std::snprintf(what, sizeof(what), "scale %.0e", s);
    std::printf(" %s: radius %.6g (scale 1: %.6g), dz %.6g\n", what, pass->GetEffectiveRadius(), r1,
      pass->GetGBufferPass()->GetEffectiveMinimumSeparation());
    Check(FiniteAndInRange(f), "AV and layers finite, AV in [0, 1]");
    // The automatic radius is a fraction of the bounds' diagonal: it must
    // scale exactly up to the float rounding of the points the bounds come
    // from (6e-8 relative): 1e-6.
    Check(
      std::abs(pass->GetEffectiveRadius() / s - r1) <= 1e-6 * r1, "radius scales with the scene");
    // Everything in eq. 1-2 is scale-free (beta = Bias r, eps = Epsilon r^2,
    // r_p in pixels), so AV must be the same up to float rounding: taps that
    // land on a texel border may pick the neighbour, and silhouette pixels
    // may flip. Bounds: mean 2e-3, 99 % of pixels within 0.02, max 0.3.
    for (const char* name :
      { vtkDeepGICaptureNames::RawAmbientVisibility, vtkDeepGICaptureNames::AmbientVisibility })
    {
      Difference d = CompareAV(f.AO, reference.AO, name, 0.02);
      PrintDifference(what, name, d, 0.02);
      Check(d.Mean <= 2e-3 && d.Above <= d.Pixels / 100 && d.Max <= 0.3 &&
          d.MaskMismatches <= d.Pixels / 200,
        "AV equals scale 1's (mean 2e-3, 99 % within 0.02)");
    }
    CompareScaledLayers(reference, f, s, what);

    // G-buffer alone at this scale: REPROJECT = DEPTH_PEEL at a still camera.
    vtkNew<vtkImageData> peel, reproject;
    for (int oracle : { vtkDeepGBufferPass::DEPTH_PEEL, vtkDeepGBufferPass::REPROJECT })
    {
      auto window = MakeWindow(Width, Height);
      vtkNew<vtkRenderer> renderer;
      window->AddRenderer(renderer);
      CornerBox(s)(renderer);
      vtkNew<vtkDeepGBufferPass> g;
      g->SetOracle(oracle);
      renderer->SetPass(g);
      for (int k = 0; k < 3; ++k)
      {
        window->Render();
      }
      g->CaptureLayers(oracle == vtkDeepGBufferPass::DEPTH_PEEL ? peel : reproject, renderer);
      if (oracle == vtkDeepGBufferPass::REPROJECT)
      {
        Check(g->GetEffectiveOracle() == vtkDeepGBufferPass::REPROJECT, "REPROJECT used");
        const double dz = g->GetEffectiveMinimumSeparation();
        LayerDifference l0 = CompareLayer(reproject, peel, 0, 1e-5);
        LayerDifference l1 = CompareLayer(reproject, peel, 1, 1e-5, nullptr, dz);
        SeparationReport sep = CheckSeparation(reproject, 1, dz, 1e-5);
        std::printf("  %s REPROJECT vs DEPTH_PEEL: layer 0 %ld / layer 1 %ld of %ld px differ "
                    "(ties %ld), separation violations %ld\n",
          what, l0.Different(), l1.Different(), l1.Compared, l1.Ties, sep.Violations);
        // Same tolerance as TestDeepGBufferLayers (relative 1e-5: the
        // geometry shader interpolates in a different order).
        Check(
          AllFinite(reproject) && l0.Different() == 0 && l1.Different() == 0 && sep.Violations == 0,
          "REPROJECT equals DEPTH_PEEL");
      }
      g->ReleaseGraphicsResources(window);
    }
    pass->ReleaseGraphicsResources(f.Window);
  }
  pass1->ReleaseGraphicsResources(reference.Window);
}

void TestClippingRange(Frame& reference)
{
  std::printf("near/far ratio:\n");
  // The geometry lies between about 2.5 and 11 units from the camera.
  struct Range
  {
    double Near, Far;
  };
  for (Range range : { Range{ 1.5, 15.0 }, Range{ 1e-5, 100.0 } })
  {
    vtkNew<vtkDeepAmbientObscurancePass> pass;
    Frame f;
    RenderAO(CornerBox(1.0), pass, f, Width, Height,
      [range](vtkRenderer* renderer)
      { renderer->GetActiveCamera()->SetClippingRange(range.Near, range.Far); });
    char what[64];
    std::snprintf(what, sizeof(what), "near/far %.0e", range.Near / range.Far);
    std::printf(" %s (near %g, far %g):\n", what, range.Near, range.Far);
    Check(FiniteAndInRange(f), "AV and layers finite, AV in [0, 1]");
    // AV uses camera distances reconstructed from gl_FragCoord.w (exact in
    // float whatever the range), so it does not lose precision with the
    // ratio. What does change is which surface wins the depth test: with
    // 1e-7, a 32-bit float depth resolves about d^2 / near * 6e-8 = 0.4
    // units at d = 8, so where wall and floor meet (and at the box's foot)
    // a few pixels may show the other surface, and the default estimator
    // gives a whole sector to each surface such a pixel's taps find (with
    // 1e-7 measured: mean 4.3e-3, 1.0 % of the raw and 2.5 % of the
    // filtered pixels off by more than 0.02). Bounds: mean 6e-3, 96 % of
    // pixels within 0.02 of the reference range's AV.
    for (const char* name :
      { vtkDeepGICaptureNames::RawAmbientVisibility, vtkDeepGICaptureNames::AmbientVisibility })
    {
      Difference d = CompareAV(f.AO, reference.AO, name, 0.02);
      PrintDifference(what, name, d, 0.02);
      Check(d.Mean <= 6e-3 && d.Above <= d.Pixels / 25 && d.MaskMismatches <= d.Pixels / 200,
        "AV equals the automatic range's (mean 6e-3, 96 % within 0.02)");
    }
    CompareScaledLayers(reference, f, 1.0, what, 100000);
    pass->ReleaseGraphicsResources(f.Window);

    // The G-buffer alone with this range: REPROJECT = DEPTH_PEEL.
    vtkNew<vtkImageData> peel, reproject;
    for (int oracle : { vtkDeepGBufferPass::DEPTH_PEEL, vtkDeepGBufferPass::REPROJECT })
    {
      auto window = MakeWindow(Width, Height);
      vtkNew<vtkRenderer> renderer;
      window->AddRenderer(renderer);
      CornerBox(1.0)(renderer);
      renderer->GetActiveCamera()->SetClippingRange(range.Near, range.Far);
      vtkNew<vtkDeepGBufferPass> g;
      g->SetOracle(oracle);
      renderer->SetPass(g);
      for (int k = 0; k < 3; ++k)
      {
        window->Render();
      }
      g->CaptureLayers(oracle == vtkDeepGBufferPass::DEPTH_PEEL ? peel : reproject, renderer);
      if (oracle == vtkDeepGBufferPass::REPROJECT)
      {
        const double dz = g->GetEffectiveMinimumSeparation();
        LayerDifference l0 = CompareLayer(reproject, peel, 0, 1e-5);
        LayerDifference l1 = CompareLayer(reproject, peel, 1, 1e-5, nullptr, dz);
        std::printf("  %s REPROJECT vs DEPTH_PEEL: layer 0 %ld / layer 1 %ld of %ld px differ "
                    "(ties %ld)\n",
          what, l0.Different(), l1.Different(), l1.Compared, l1.Ties);
        Check(g->GetEffectiveOracle() == vtkDeepGBufferPass::REPROJECT && AllFinite(reproject) &&
            l0.Different() == 0 && l1.Different() == 0,
          "REPROJECT equals DEPTH_PEEL");
      }
      g->ReleaseGraphicsResources(window);
    }
  }
}

// A 400 x 400 plane y = 0 (no other geometry), seen from height h.
Scene Plane(double size = 200.0)
{
  return [size](vtkRenderer* renderer)
  {
    const double o[3] = { -size, 0, -size }, a[3] = { size, 0, -size }, b[3] = { -size, 0, size };
    AddQuad(renderer, 1.0, o, a, b);
  };
}

// Largest 1 - AV (raw and filtered) over valid pixels; counts valid pixels.
double WorstUnoccluded(Frame& f, long& valid)
{
  double worst = 0.0;
  valid = 0;
  vtkDataArray* v = Array(f.AO, vtkDeepGICaptureNames::Valid);
  for (const char* name :
    { vtkDeepGICaptureNames::RawAmbientVisibility, vtkDeepGICaptureNames::AmbientVisibility })
  {
    vtkDataArray* a = Array(f.AO, name);
    for (vtkIdType p = 0; p < a->GetNumberOfTuples(); ++p)
    {
      if (v->GetTuple1(p) != 0)
      {
        worst = std::max(worst, 1.0 - a->GetTuple1(p));
        valid += name[0] == 'A' ? 1 : 0;
      }
    }
  }
  return worst;
}

void TestGrazing()
{
  std::printf("grazing views of an unoccluded plane (radius 1):\n");
  for (double degrees : { 2.0, 1.0 })
  {
    for (double bias : { 0.01, 0.0 })
    {
      vtkNew<vtkDeepAmbientObscurancePass> pass;
      pass->SetRadius(1.0);
      pass->SetBias(bias);
      Frame f;
      RenderAO(Plane(), pass, f, Width, Height,
        [degrees](vtkRenderer* renderer)
        {
          // Camera 0.5 above the plane looking down by `degrees`.
          vtkCamera* camera = renderer->GetActiveCamera();
          const double t = std::tan(degrees * 3.14159265358979 / 180.0);
          camera->SetPosition(0.0, 0.5, 150.0);
          camera->SetFocalPoint(0.0, 0.5 - 10.0 * t, 140.0);
          camera->SetViewUp(0.0, 1.0, 0.0);
          camera->SetViewAngle(30.0);
          renderer->ResetCameraClippingRange();
        });
      long valid = 0;
      const double worst = WorstUnoccluded(f, valid);
      std::printf(
        " %.0f degrees, bias %.2f r: %ld valid px, max 1 - AV %.2e\n", degrees, bias, valid, worst);
      Check(FiniteAndInRange(f), "AV and layers finite, AV in [0, 1]");
      if (bias > 0.0)
      {
        // As TestDeepAmbientObscurance's oblique plane: 1e-3. The plane's
        // normal is exact, v lies in the plane up to float rounding of the
        // reconstructed positions, far below beta = 0.01 r.
        Check(valid > Width * Height / 4 && worst <= 1e-3, "AV = 1 within 1e-3 (default bias)");
      }
      else
      {
        // Informational: how much the bias matters at grazing angles.
        Check(valid > Width * Height / 4 && worst <= 1.0, "bias 0: finite (value reported above)");
      }
      pass->ReleaseGraphicsResources(f.Window);
    }
  }
}

void TestWindowSizes()
{
  std::printf("window sizes (unoccluded plane, radius 1):\n");
  for (int size : { 1, 4096 })
  {
    vtkNew<vtkDeepAmbientObscurancePass> pass;
    pass->SetRadius(1.0);
    if (size > 1)
    {
      // 16.7 M pixels on llvmpipe: one frame, 4 taps and a 1-tap filter keep
      // this case to a few tens of seconds; the check is about the size.
      pass->SetNumberOfSamples(4);
      pass->SetBlurRadius(1);
    }
    Frame f;
    const auto start = std::chrono::steady_clock::now();
    RenderAO(
      Plane(50.0), pass, f, size, size,
      [](vtkRenderer* renderer)
      {
        vtkCamera* camera = renderer->GetActiveCamera();
        camera->SetPosition(0.0, 3.0, 4.0);
        camera->SetFocalPoint(0.0, 0.0, -2.0);
        camera->SetViewUp(0.0, 1.0, 0.0);
        renderer->ResetCameraClippingRange();
      },
      size == 1, size == 1 ? 3 : 1);
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    long valid = 0;
    const double worst = f.Ok ? WorstUnoccluded(f, valid) : 1.0;
    const int* captured = f.AO->GetDimensions();
    std::printf(" %d x %d: capture %d x %d, %ld valid px, max 1 - AV %.2e, %.2f s\n", size, size,
      captured[0], captured[1], valid, worst, seconds);
    Check(f.Ok && captured[0] == size && captured[1] == size, "capture has the window's size");
    Check(FiniteAndInRange(f, size == 1),
      size == 1 ? "AV and layers finite, AV in [0, 1]"
                : "AV finite, in [0, 1] (layers not captured)");
    // The plane fills the view; 1e-3 as for every unoccluded plane.
    Check(valid == static_cast<long>(size) * size && worst <= 1e-3, "AV = 1 within 1e-3");
    pass->ReleaseGraphicsResources(f.Window);
  }
}

void TestSampleCounts(Frame& reference)
{
  std::printf("sample counts (corner + box, scale 1):\n");
  const double mean16 = [&]
  {
    double sum = 0.0;
    long n = 0;
    vtkDataArray* a = Array(reference.AO, vtkDeepGICaptureNames::RawAmbientVisibility);
    vtkDataArray* v = Array(reference.AO, vtkDeepGICaptureNames::Valid);
    for (vtkIdType p = 0; p < a->GetNumberOfTuples(); ++p)
    {
      if (v->GetTuple1(p) != 0)
      {
        sum += a->GetTuple1(p);
        ++n;
      }
    }
    return sum / std::max(n, 1L);
  }();
  for (int n : { 1, 98, 99 })
  {
    vtkNew<vtkDeepAmbientObscurancePass> pass;
    EventCounter warnings(pass, vtkCommand::WarningEvent);
    pass->SetNumberOfSamples(n);
    Frame f;
    RenderAO(CornerBox(1.0), pass, f);
    double sum = 0.0;
    long count = 0;
    vtkDataArray* a = Array(f.AO, vtkDeepGICaptureNames::RawAmbientVisibility);
    vtkDataArray* v = Array(f.AO, vtkDeepGICaptureNames::Valid);
    for (vtkIdType p = 0; p < a->GetNumberOfTuples(); ++p)
    {
      if (v->GetTuple1(p) != 0)
      {
        sum += a->GetTuple1(p);
        ++count;
      }
    }
    const double mean = sum / std::max(count, 1L);
    const double fieldN = f.AO->GetFieldData()->GetArray(vtkDeepGICaptureNames::NumberOfSamples)
      ? f.AO->GetFieldData()->GetArray(vtkDeepGICaptureNames::NumberOfSamples)->GetTuple1(0)
      : -1;
    std::printf(" N = %d: used %d (capture says %g), %d warning(s), mean raw AV %.4f (N = 16: "
                "%.4f)\n",
      n, pass->GetNumberOfSamples(), fieldN, warnings.Count, mean, mean16);
    Check(FiniteAndInRange(f), "AV and layers finite, AV in [0, 1]");
    const int expected = std::min(n, 98);
    Check(pass->GetNumberOfSamples() == expected && fieldN == expected &&
        warnings.Count == (n == 99 ? 1 : 0),
      "N used as given, 99 clamped to 98 with one warning");
    if (n != 1)
    {
      // N = 16 and N = 98 estimate the same integral: their image means
      // differ by the sampling noise of 16 taps averaged over ~10^4 pixels,
      // far below 0.02.
      Check(std::abs(mean - mean16) <= 0.02, "mean AV of N = 98 within 0.02 of N = 16's");
    }
    pass->ReleaseGraphicsResources(f.Window);
  }
}
}

int TestDeepAmbientObscuranceExtremes(int, char*[])
{
  Frame reference;
  TestScale(reference);
  {
    vtkNew<vtkDeepAmbientObscurancePass> pass;
    RenderAO(CornerBox(1.0), pass, reference);
    TestClippingRange(reference);
    TestSampleCounts(reference);
    pass->ReleaseGraphicsResources(reference.Window);
  }
  TestGrazing();
  TestWindowSizes();
  return ExitStatus();
}
