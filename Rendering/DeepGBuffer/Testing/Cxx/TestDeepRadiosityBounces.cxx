// Progressive bounces, temporal filter and per-renderer history of
// vtkDeepRadiosityPass:
// - energy: an open grey box (albedo 0.8, boost 1, delta 0.5) at a fixed
//   camera, 64 x 64, 100 frames. With alpha = 0 the total indirect light
//   never decreases (relative 1e-5: each frame adds one bounce to a
//   positive linear map started from 0), frame 2 exceeds frame 1 by > 1 %
//   (a second bounce arrived), frame 100 exceeds frame 1 by > 3 % (measured
//   6.8 % with alpha 0, 4.8 % with 0.85), frames 90..100 differ by < 0.1 %
//   (converged), and every L_ind stays below the bound
//   2 rho D / (1 - 2 rho delta) = 8 D (D the largest direct radiance): E
//   is at most 2 pi max B with every estimator (the default SOLID_ANGLE
//   caps E there), so L <= 2 rho max B and
//   B <= D + delta L. With alpha = 0.85 (jittered taps) the same bound holds
//   and frames 90..100 differ by < 1 %. Layer-1 pixels gain light from the
//   bounces too (propagation across layers);
// - reprojection at a still camera with alpha = 1: a static pixel keeps
//   last frame's E exactly; a pixel whose surface moved (a box shifted by
//   0.6) gets this frame's filtered E; a pixel whose layer 0 is now last
//   frame's layer 1 (uncovered by the box) gets last frame's layer-1 E;
// - a camera orbiting 0.5 degree per frame over planar surfaces keeps the
//   history on > 95 % of the lit pixels (alpha = 1);
// - history per renderer: one pass on two renderers of one window (a red
//   and a green wall) gives, after 10 frames, the same E as each scene alone
//   (1e-4 relative); a resize and ReleaseGraphicsResources restart the
//   history (Frames = 1) and the same first frame (1e-6).

#include "DeepRadiosityTest.h"
#include "vtkDeepGICaptureNames.h"

#include <algorithm>
#include <vector>

using namespace DeepRadiosityTest;
using namespace DeepGITest;

namespace
{
// An open box of albedo 0.8 (floor, back, left and right walls, 4 x 3 x 4)
// with a white box inside, lit from the open front and above.
void GreyRoom(vtkRenderer* renderer)
{
  const double grey = 0.8;
  const double f[3][3] = { { -2, 0, 2 }, { 2, 0, 2 }, { -2, 0, -2 } };
  Diffuse(AddQuad(renderer, f[0], f[1], f[2]), grey, grey, grey);
  const double b[3][3] = { { -2, 0, -2 }, { 2, 0, -2 }, { -2, 3, -2 } };
  Diffuse(AddQuad(renderer, b[0], b[1], b[2]), grey, grey, grey);
  const double l[3][3] = { { -2, 0, 2 }, { -2, 0, -2 }, { -2, 3, 2 } };
  Diffuse(AddQuad(renderer, l[0], l[1], l[2]), grey, grey, grey);
  const double r[3][3] = { { 2, 0, -2 }, { 2, 0, 2 }, { 2, 3, -2 } };
  Diffuse(AddQuad(renderer, r[0], r[1], r[2]), grey, grey, grey);
  const double center[3] = { 0.3, 0.6, 0.0 }, size[3] = { 1.0, 1.2, 1.0 };
  Diffuse(AddBox(renderer, center, size), grey, grey, grey);
  AddSun(renderer, 1.5, 4, 3);
  SetCamera(renderer, 0.5, 2.2, 6.5, 0.0, 1.0, -1.0);
}

double LargestDirect(vtkImageData* layers)
{
  double largest = 0.0;
  for (int j = 0; j < 2; ++j)
  {
    vtkDataArray* radiance = Layer(layers, vtkDeepGICaptureNames::Radiance, j);
    vtkDataArray* ambient = Layer(layers, vtkDeepGICaptureNames::Ambient, j);
    for (vtkIdType p = 0; p < radiance->GetNumberOfTuples(); ++p)
    {
      for (int c = 0; c < 3; ++c)
      {
        largest = std::max(largest, radiance->GetComponent(p, c) - ambient->GetComponent(p, c));
      }
    }
  }
  return largest;
}

void TestEnergy(double alpha)
{
  constexpr int frames = 100;
  const double rho = 0.8, delta = 0.5;
  vtkNew<vtkDeepRadiosityPass> pass;
  pass->SetDamping(delta);
  pass->SetTemporalAlpha(alpha);
  auto window = MakeWindow(64, 64);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  GreyRoom(renderer);
  renderer->ResetCameraClippingRange();
  renderer->SetPass(pass);
  std::vector<double> total(frames), layer1(frames);
  double largest = 0.0;
  bool finite = true, monotone = true;
  vtkNew<vtkImageData> radiosity;
  for (int k = 0; k < frames; ++k)
  {
    window->Render();
    pass->CaptureIrradiance(radiosity, renderer);
    total[k] =
      Total(radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0)) +
      Total(radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 1));
    layer1[k] =
      Total(radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 1));
    largest = std::max({ largest,
      Maximum(radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0)),
      Maximum(
        radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 1)) });
    finite = finite && AllFinite(radiosity) &&
      Minimum(
        radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0)) >= 0.0;
    if (k > 0 && total[k] < total[k - 1] * (1.0 - 1e-5))
    {
      monotone = false;
    }
  }
  vtkNew<vtkImageData> layers;
  pass->GetGBufferPass()->CaptureLayers(layers, renderer);
  const double direct = LargestDirect(layers);
  const double bound = 2.0 * rho * direct / (1.0 - 2.0 * rho * delta);
  const double frames90 = std::abs(total[99] - total[89]) / total[99];
  // With the temporal filter every frame rotates the spiral, so the total
  // fluctuates from frame to frame (about 1 % here); convergence is the
  // absence of drift between the means of frames 81-90 and 91-100.
  double earlier = 0.0, later = 0.0;
  for (int k = 80; k < 90; ++k)
  {
    earlier += total[k] / 10.0;
    later += total[k + 10] / 10.0;
  }
  const double drift = std::abs(later - earlier) / later;
  std::printf("alpha %.2f: total L_ind frame 1 %.2f, 2 %.2f, 10 %.2f, 50 %.2f, 100 %.2f; change "
              "90..100 %.2e, drift of the 10-frame mean %.2e; largest L_ind %.3f, bound %.3f (D = "
              "%.3f); layer 1 total frame 1 %.3f, 100 %.3f\n",
    alpha, total[0], total[1], total[9], total[49], total[99], frames90, drift, largest, bound,
    direct, layer1[0], layer1[99]);
  Check(finite, "finite and non-negative every frame");
  Check(largest <= bound, "L_ind below the derived bound");
  // The default SOLID_ANGLE gathers only the solid angle the taps see
  // within r, so each bounce adds less than eq. 4's division by M did (its
  // bound was x 1.2): measured x 1.078 (alpha 0) and x 1.112 (alpha 0.85)
  // with the default guard band (x 1.074 and x 1.048 without one).
  Check(total[99] > total[0] * 1.03, "bounces add light");
  // Layer 1 (the floor and walls behind the box, Figure 5) gains x 1.083
  // (alpha 0) and x 1.181 (alpha 0.85) with the default guard band, x 1.069
  // and x 1.099 without one; no propagation into layer 1 would give x 1.
  Check(layer1[99] > layer1[0] * 1.05, "layer-1 pixels gain light from the bounces");
  if (alpha == 0.0)
  {
    Check(monotone, "total never decreases (alpha 0)");
    Check(total[1] > total[0] * 1.01, "frame 2 adds the second bounce");
    Check(frames90 < 1e-3, "converged by frame 90 (alpha 0)");
  }
  else
  {
    Check(drift < 5e-3, "converged by frame 90 (alpha 0.85)");
  }
  pass->ReleaseGraphicsResources(window);
}

void TestReprojection()
{
  vtkNew<vtkDeepRadiosityPass> pass;
  pass->SetDamping(0.0);
  pass->SetTemporalAlpha(1.0);
  constexpr int W = 160, H = 120;
  auto window = MakeWindow(W, H);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  RedWallScene(renderer);
  const double center[3] = { 1.6, 0.4, 0.6 }, size[3] = { 0.5, 0.8, 0.5 };
  vtkActor* box = Diffuse(AddBox(renderer, center, size), 1, 1, 1);
  renderer->ResetCameraClippingRange();
  renderer->SetPass(pass);
  vtkNew<vtkImageData> before, beforeLayers, after, afterLayers;
  window->Render();
  pass->CaptureIrradiance(before, renderer);
  pass->GetGBufferPass()->CaptureLayers(beforeLayers, renderer);
  box->SetPosition(0.6, 0.0, 0.0);
  window->Render();
  pass->CaptureIrradiance(after, renderer);
  pass->GetGBufferPass()->CaptureLayers(afterLayers, renderer);
  const double tolerance =
    after->GetFieldData()->GetArray(vtkDeepGICaptureNames::ReprojectionTolerance)->GetTuple1(0);
  long kept = 0, fresh = 0, fromLayer1 = 0, wrong = 0;
  for (int j = 0; j < H; ++j)
  {
    for (int i = 0; i < W; ++i)
    {
      if (At(after, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 0), i, j) == 0)
      {
        continue;
      }
      const vtkIdType p = static_cast<vtkIdType>(j) * W + i;
      const double d = Layer(afterLayers, vtkDeepGICaptureNames::Depth, 0)->GetTuple1(p);
      const double d0 = Layer(beforeLayers, vtkDeepGICaptureNames::Depth, 0)->GetTuple1(p);
      const double d1 = Layer(beforeLayers, vtkDeepGICaptureNames::Depth, 1)->GetTuple1(p);
      const double e0 = d0 > 0 ? std::abs(d0 - d) : 1e30, e1 = d1 > 0 ? std::abs(d1 - d) : 1e30;
      std::string expected;
      std::string source;
      if (std::min(e0, e1) > tolerance)
      {
        expected = vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::FilteredIrradiance, 0);
        ++fresh;
      }
      else
      {
        expected = e0 <= e1 ? vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Irradiance, 0)
                            : vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Irradiance, 1);
        (e0 <= e1 ? kept : fromLayer1)++;
      }
      vtkImageData* from =
        expected == vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::FilteredIrradiance, 0)
        ? after.GetPointer()
        : before.GetPointer();
      for (int c = 0; c < 3; ++c)
      {
        if (std::abs(At(after, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Irradiance, 0),
                       i, j, c) -
              At(from, expected, i, j, c)) > 1e-6 * (1.0 + std::abs(At(from, expected, i, j, c))))
        {
          ++wrong;
          break;
        }
      }
    }
  }
  std::printf("reprojection (alpha 1, box moved): %ld pixels keep layer-0 history, %ld take "
              "layer-1 history, %ld rejected; %ld differ from the expected source\n",
    kept, fromLayer1, fresh, wrong);
  Check(kept > 1000 && fromLayer1 > 20 && fresh > 20, "every case occurs");
  Check(wrong <= (kept + fromLayer1 + fresh) / 500, "history from the right layer or rejected");
  pass->ReleaseGraphicsResources(window);
}

// RedWallScene with a green wall. The two renderers of TestRenderers
// differ in colours only: VTK 9.1 updates a shader program's light
// uniforms only when the renderer's lights or camera changed after the
// program's last update (vtkOpenGLRenderer::UpdateLightingUniforms), so
// renderers with different lights or cameras sharing a program light each
// other's props from the second frame on, with or without these passes.
void GreenWallScene(vtkRenderer* renderer)
{
  RedWallScene(renderer);
  Diffuse(vtkActor::SafeDownCast(renderer->GetActors()->GetItemAsObject(1)), 0, 1, 0);
}

// Camera orbiting 0.5 degree per frame around planar surfaces, alpha = 1:
// the fraction of surface pixels whose history is rejected (E equals this
// frame's filtered E) stays small because the reprojected surface is
// compared at the previous texel's centre through its plane.
void TestMotion()
{
  vtkNew<vtkDeepRadiosityPass> pass;
  pass->SetDamping(0.0);
  pass->SetTemporalAlpha(1.0);
  constexpr int W = 160, H = 120;
  auto window = MakeWindow(W, H);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  RedWallScene(renderer);
  renderer->ResetCameraClippingRange();
  renderer->SetPass(pass);
  window->Render();
  vtkNew<vtkImageData> radiosity;
  double worst = 0.0;
  for (int k = 0; k < 4; ++k)
  {
    renderer->GetActiveCamera()->Azimuth(0.5);
    renderer->ResetCameraClippingRange();
    window->Render();
    pass->CaptureIrradiance(radiosity, renderer);
    long surface = 0, rejected = 0;
    for (int j = 0; j < H; ++j)
    {
      for (int i = 0; i < W; ++i)
      {
        if (At(radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 0), i, j) == 0)
        {
          continue;
        }
        ++surface;
        bool fresh = true;
        for (int c = 0; c < 3; ++c)
        {
          fresh = fresh &&
            At(radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Irradiance, 0), i, j,
              c) ==
              At(radiosity,
                vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::FilteredIrradiance, 0), i, j,
                c);
        }
        // Pixels without light (E = 0 both ways) say nothing.
        fresh = fresh &&
          At(radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::FilteredIrradiance, 0),
            i, j, 0) > 0.0;
        rejected += fresh ? 1 : 0;
      }
    }
    worst = std::max(worst, static_cast<double>(rejected) / std::max(surface, 1L));
  }
  std::printf("orbit 0.5 degree per frame: at most %.3f of the surface pixels lose their "
              "history\n",
    worst);
  Check(worst < 0.05, "history survives a slow camera motion over planar surfaces");
  pass->ReleaseGraphicsResources(window);
}

void TestRenderers()
{
  constexpr int W = 120, H = 90, frames = 10;
  vtkNew<vtkDeepRadiosityPass> shared;
  auto window = MakeWindow(2 * W, H);
  vtkNew<vtkRenderer> left, right;
  left->SetViewport(0.0, 0.0, 0.5, 1.0);
  right->SetViewport(0.5, 0.0, 1.0, 1.0);
  window->AddRenderer(left);
  window->AddRenderer(right);
  GreenWallScene(left);
  RedWallScene(right);
  for (vtkRenderer* r : { left.GetPointer(), right.GetPointer() })
  {
    r->SetBackground(0.0, 0.0, 0.0);
    r->ResetCameraClippingRange();
    r->SetPass(shared);
  }
  for (int k = 0; k < frames; ++k)
  {
    window->Render();
  }
  vtkNew<vtkImageData> a, b;
  shared->CaptureIrradiance(a, left);
  shared->CaptureIrradiance(b, right);
  const Scene scenes[2] = { GreenWallScene, [](vtkRenderer* r) { RedWallScene(r); } };
  vtkImageData* together[2] = { a, b };
  for (int s = 0; s < 2; ++s)
  {
    vtkNew<vtkDeepRadiosityPass> alone;
    Frame f;
    if (!RenderFrames(scenes[s], alone, frames, f, W, H))
    {
      continue;
    }
    double worst = 0.0, largest = 0.0;
    for (int j = 0; j < H; ++j)
    {
      for (int i = 0; i < W; ++i)
      {
        for (int c = 0; c < 3; ++c)
        {
          const double x = At(f.Radiosity,
            vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Irradiance, 0), i, j, c);
          worst = std::max(worst,
            std::abs(
              At(together[s], vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Irradiance, 0), i,
                j, c) -
              x));
          largest = std::max(largest, x);
        }
      }
    }
    std::printf("renderer %d of 2: frames %g, largest |E - E alone| %.3g (largest E %.3f)\n", s,
      together[s]->GetFieldData()->GetArray(vtkDeepGICaptureNames::Frames)->GetTuple1(0), worst,
      largest);
    Check(
      together[s]->GetFieldData()->GetArray(vtkDeepGICaptureNames::Frames)->GetTuple1(0) == frames,
      "each renderer counts its own frames");
    Check(largest > 0.1 && worst <= 1e-4 * largest, "two renderers = each alone");
    alone->ReleaseGraphicsResources(f.Window);
  }
  shared->ReleaseGraphicsResources(window);
}

void TestRestart()
{
  vtkNew<vtkDeepRadiosityPass> pass;
  auto window = MakeWindow(120, 90);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  RedWallScene(renderer);
  renderer->ResetCameraClippingRange();
  renderer->SetPass(pass);
  vtkNew<vtkImageData> first, again, resized;
  window->Render();
  pass->CaptureIrradiance(first, renderer);
  for (int k = 0; k < 4; ++k)
  {
    window->Render();
  }
  pass->ReleaseGraphicsResources(window);
  window->Render();
  pass->CaptureIrradiance(again, renderer);
  double worst = 0.0;
  vtkDataArray* x = first->GetPointData()->GetArray(
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Irradiance, 0).c_str());
  vtkDataArray* y = again->GetPointData()->GetArray(
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Irradiance, 0).c_str());
  for (vtkIdType p = 0; p < x->GetNumberOfTuples(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      worst = std::max(worst, std::abs(x->GetComponent(p, c) - y->GetComponent(p, c)));
    }
  }
  std::printf("after ReleaseGraphicsResources: frames %g, largest |E - first frame E| %.3g\n",
    again->GetFieldData()->GetArray(vtkDeepGICaptureNames::Frames)->GetTuple1(0), worst);
  Check(again->GetFieldData()->GetArray(vtkDeepGICaptureNames::Frames)->GetTuple1(0) == 1,
    "history restarted");
  Check(worst <= 1e-6, "same first frame after ReleaseGraphicsResources");
  window->Render();
  window->SetSize(100, 80);
  window->Render();
  pass->CaptureIrradiance(resized, renderer);
  Check(resized->GetFieldData()->GetArray(vtkDeepGICaptureNames::Frames)->GetTuple1(0) == 1 &&
      resized->GetDimensions()[0] == 100 && AllFinite(resized),
    "a resize restarts the history");
  pass->ReleaseGraphicsResources(window);
}
}

int TestDeepRadiosityBounces(int, char*[])
{
  TestEnergy(0.0);
  TestEnergy(0.85);
  TestReprojection();
  TestMotion();
  TestRenderers();
  TestRestart();
  return ExitStatus();
}
