// Single-bounce properties of vtkDeepRadiosityPass on small lit scenes
// (160 x 120 px, Damping 0 and TemporalAlpha 0 unless stated):
// - the raw gather (eq. 4-5 with Estimator ACCEPTED_TAPS, both layers,
//   confidence M / N) equals an
//   independent CPU evaluation with the documented taps, MIP texels and
//   layer choice on the captured G-buffer, for the BALANCED (n_Y test, MIP
//   level >= 2) and HIGH_PERFORMANCE (no n_Y test, level >= 3, the
//   receivers on a grid of half the resolution: compared there) presets,
//   and BALANCED with 4 taps of the outer ring (OuterSamples), also in the
//   first frame of the temporal filter with the taps spread over 2 and 3
//   frames (TemporalInterleave: every 2nd or 3rd tap):
//   |E difference| <= 1e-3 (1 + |E|) and the same M on >= 99 % of the
//   valid pixels of each layer (float vs double may move a tap across a
//   texel border);
// - a white floor beside a lit red wall receives red light: L_ind.r > 0.02
//   next to the wall, green and blue < 2 % of red, decreasing with the
//   distance from the wall, and the raw E exactly 0 beyond the gather's
//   reach (OUTER_RADIUS_SCALE r with the default outer ring);
// - a blue panel whose lit face looks away from the floor adds no blue to
//   the floor behind it: with eq. 4 (ACCEPTED_TAPS) with the n_Y test
//   (<= 1e-5) and some without it; with the default SOLID_ANGLE in both
//   cases (<= 1e-5);
// - the composite is RADIANCE + L_ind (8-bit rounding: <= 2 levels),
//   background kept;
// - eq. 7's boost: a (1, 0.5, 0.5) floor (stored as 8-bit 128 / 255) gets
//   boost(rho) = 0.498 times the light of boost 1 (1e-5), a white floor none;
// - the confidence fallback is c L + (1 - c) rho E_env / pi (1e-5), and the
//   automatic E_env is pi times the renderer's ambient colour;
// - UpdateRadiosity and ActivateTexture called from another pass's opaque
//   step give Render's radiosity (1e-6) and leave the framebuffer to it;
//   without layers UpdateRadiosity fails with one error;
// - presets set Table 2's values; PrintSelf prints every parameter.

#include "DeepRadiosityTest.h"

#include "vtkDeepAmbientObscurancePass.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkObjectFactory.h"
#include "vtkRenderState.h"

#include <algorithm>
#include <sstream>
#include <vector>

using namespace DeepRadiosityTest;
using namespace DeepGITest;

// A composite pass of its own, as vtkDeepGIPass will be: its opaque step
// builds the layers, calls UpdateRadiosity, binds INDIRECT_RADIANCE and
// draws only the plain G-buffer image.
class ExternalOpaqueStep : public vtkRenderPass
{
public:
  static ExternalOpaqueStep* New();
  vtkTypeMacro(ExternalOpaqueStep, vtkRenderPass);
  vtkDeepRadiosityPass* Radiosity = nullptr;
  int Units = 0;   // frames in which INDIRECT_RADIANCE could be bound
  int Updates = 0; // frames in which UpdateRadiosity succeeded
  void Render(const vtkRenderState* s) override
  {
    vtkDeepGBufferPass* gbuffer = this->Radiosity->GetGBufferPass();
    if (gbuffer->RenderLayers(s) && this->Radiosity->UpdateRadiosity(s))
    {
      ++this->Updates;
      const int unit = this->Radiosity->ActivateTexture(
        s->GetRenderer(), vtkDeepRadiosityPass::INDIRECT_RADIANCE, 0);
      this->Units += unit >= 0 ? 1 : 0;
      this->Radiosity->DeactivateTexture(
        s->GetRenderer(), vtkDeepRadiosityPass::INDIRECT_RADIANCE, 0);
      gbuffer->ResolveToFramebuffer(s);
    }
  }
};
vtkStandardNewMacro(ExternalOpaqueStep);

class ExternalComposite : public vtkRenderPass
{
public:
  static ExternalComposite* New();
  vtkTypeMacro(ExternalComposite, vtkRenderPass);
  vtkNew<ExternalOpaqueStep> Step;
  void Render(const vtkRenderState* s) override
  {
    this->Step->Radiosity->GetGBufferPass()->RenderFrame(s, this->Step);
  }
};
vtkStandardNewMacro(ExternalComposite);

namespace
{
struct Gather
{
  double E[3] = { 0, 0, 0 };
  double Confidence = 0.0;
};

// The level-0 texel a tap at window point (tx, ty), h pixels from the
// receiver, reads: MIP level clamp(floor(log2(h / q)), lo, hi) and the
// rotated-grid texel stored there.
void SourceTexel(
  double tx, double ty, double h, double q, int minMip, int maxMip, int W, int H, int& cx, int& cy)
{
  int m = minMip;
  if (maxMip > 0 && h >= 2.0 * q)
  {
    m = std::max(m, static_cast<int>(std::floor(std::log2(h / q))));
  }
  m = std::min(m, maxMip);
  cx = std::min(static_cast<int>(tx) >> m, std::max(W >> m, 1) - 1);
  cy = std::min(static_cast<int>(ty) >> m, std::max(H >> m, 1) - 1);
  for (int k = m; k > 0; --k)
  {
    const int nx = std::min(2 * cx + (cy & 1), std::max(W >> (k - 1), 1) - 1);
    const int ny = std::min(2 * cy + (cx & 1), std::max(H >> (k - 1), 1) - 1);
    cx = nx;
    cy = ny;
  }
}

// Of the layers' surfaces at source texel (cx, cy), the one passing eq. 5
// for X (normal nX) with the larger contribution B (w.n_X), into `best`;
// false when none passes.
bool BestCandidate(vtkImageData* layers, int layerCount, const double X[3], const double nX[3],
  int cx, int cy, double radius, bool normalTest, double best[3])
{
  const double eps = vtkDeepRadiosityPass::COSINE_EPSILON;
  const vtkIdType source = static_cast<vtkIdType>(cy) * layers->GetDimensions()[0] + cx;
  double bestScore = 0.0;
  for (int k = 0; k < layerCount; ++k)
  {
    double Y[3];
    if (!CameraPosition(layers, k, cx, cy, Y))
    {
      continue;
    }
    const double v[3] = { Y[0] - X[0], Y[1] - X[1], Y[2] - X[2] };
    const double vv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    if (!(vv < radius * radius) || !(vv > 0.0))
    {
      continue;
    }
    const double len = std::sqrt(vv);
    const double w[3] = { v[0] / len, v[1] / len, v[2] / len };
    const double cosX = w[0] * nX[0] + w[1] * nX[1] + w[2] * nX[2];
    double nY[3];
    Layer(layers, vtkDeepGICaptureNames::Normal, k)->GetTuple(source, nY);
    if (!(cosX > eps) || (normalTest && !(w[0] * nY[0] + w[1] * nY[1] + w[2] * nY[2] < -eps)))
    {
      continue;
    }
    double c[3], score = 1.0;
    for (int a = 0; a < 3; ++a)
    {
      const double B =
        std::max(Layer(layers, vtkDeepGICaptureNames::Radiance, k)->GetComponent(source, a) -
            Layer(layers, vtkDeepGICaptureNames::Ambient, k)->GetComponent(source, a),
          0.0);
      c[a] = B * cosX;
      score += c[a] * c[a];
    }
    if (score > bestScore)
    {
      bestScore = score;
      std::copy(c, c + 3, best);
    }
  }
  return bestScore > 0.0;
}

// Eq. 4-5 on the CPU in double precision for the surface of layer `layer`
// at pixel (i, j), following the class documentation: taps of section 3.4
// with r_p from layer 0's depth, MIP level clamp(floor(log2(h / q)), lo,
// hi) and its rotated-grid level-0 texel, candidates of every layer, the
// cosine tests with COSINE_EPSILON, the larger contribution per tap.
// `divisor`: the gather's resolution divisor; (i, j) is then the receiver
// (i / divisor, j / divisor) of its grid, whose index sets the rotation and
// which leaves out the sources of its own cell. `Outer`: the taps of the
// outer ring (OuterSamples), after the spiral's. `Stride`, `Phase`: the
// frame's share of the taps (TemporalInterleave), those i = Phase + x + y
// mod Stride for receiver (x, y), each counting Stride times in the
// confidence; `Rotation`: the frame's rotation offset, 2 pi fract(k /
// golden ratio) in frame k while the temporal filter is on.
struct TapSettings
{
  int LayerCount = 2;
  int Samples = 14;
  int Outer = 0;
  double Radius = 1.0;
  double MipThreshold = 8.0;
  int MinMip = 0;
  int MaxMip = 0;
  bool NormalTest = true;
  int Divisor = 1;
  int Stride = 1;
  int Phase = 0;
  double Rotation = 0.0;
};

Gather ReferenceGather(vtkImageData* layers, int i, int j, int layer, const TapSettings& t)
{
  const int n = t.Samples, outer = t.Outer, divisor = t.Divisor;
  Gather g;
  const int* dims = layers->GetDimensions();
  const int W = dims[0], H = dims[1];
  double X[3], X0[3];
  if (!CameraPosition(layers, layer, i, j, X) || !CameraPosition(layers, 0, i, j, X0))
  {
    return g;
  }
  const double* P = vtkDoubleArray::SafeDownCast(
    layers->GetFieldData()->GetArray(vtkDeepGICaptureNames::ProjectionMatrix))
                      ->GetPointer(0);
  double nX[3];
  Layer(layers, vtkDeepGICaptureNames::Normal, layer)
    ->GetTuple(static_cast<vtkIdType>(j) * W + i, nX);
  const double rp = t.Radius * P[5] * 0.5 * H / (P[14] * X0[2] + P[15]);
  // The rotation in float, as the shader computes it: h phi moves a far
  // tap by a twentieth of a pixel between float and double.
  const float dotted =
    0.06711056f * static_cast<float>(i / divisor) + 0.00583715f * static_cast<float>(j / divisor);
  const double ign = 52.9829189f * (dotted - std::floor(dotted));
  const float phi =
    static_cast<float>(2.0 * Pi * (ign - std::floor(ign))) + static_cast<float>(t.Rotation);
  const int tau = vtkDeepAmbientObscurancePass::GetSpiralTurns(n);
  // Taps after the first at the offset fract(4 phi / (2 pi)) across their
  // rings where these are wider than a texel of the minimum MIP level, at
  // full resolution.
  const double offset = phi * (2.0f / static_cast<float>(Pi));
  const double radialOffset = offset - std::floor(offset);
  const double scale = vtkDeepRadiosityPass::OUTER_RADIUS_SCALE;
  const double reach = outer > 0 ? scale * t.Radius : t.Radius;
  const double outerWidth = outer > 0 ? rp * (scale - 1.0) / outer : 0.0;
  const int minMip = t.MinMip;
  int used = 0;
  const int phase = (t.Phase + i / divisor + j / divisor) % t.Stride;
  for (int s = phase; s < n + outer; s += t.Stride)
  {
    double h, theta;
    if (s < n)
    {
      const bool middle = s == 0 || rp / n <= (1 << minMip) || divisor > 1;
      const double kappa = (s + (middle ? 0.5 : radialOffset)) / n;
      theta = 2.0 * Pi * kappa * tau + phi;
      h = rp * kappa;
    }
    else
    {
      const bool middle = outerWidth <= (1 << minMip) || divisor > 1;
      h = rp + outerWidth * (s - n + (middle ? 0.5 : radialOffset));
      theta = 2.0 * Pi * (s - n + 0.5) / outer + phi;
    }
    const double tx = i + 0.5 + h * std::cos(theta), ty = j + 0.5 + h * std::sin(theta);
    if (tx < 0 || ty < 0 || tx >= W || ty >= H)
    {
      continue;
    }
    int cx, cy;
    SourceTexel(tx, ty, h, t.MipThreshold, minMip, t.MaxMip, W, H, cx, cy);
    // On a reduced grid the receiver leaves out the sources whose bounce
    // input reads it: those in its cell, floor(s / D + 1 / 2) = receiver.
    if (divisor > 1 && (2 * cx + divisor) / (2 * divisor) == i / divisor &&
      (2 * cy + divisor) / (2 * divisor) == j / divisor)
    {
      continue;
    }
    double best[3] = { 0.0, 0.0, 0.0 };
    if (BestCandidate(layers, t.LayerCount, X, nX, cx, cy, reach, t.NormalTest, best))
    {
      ++used;
      for (int a = 0; a < 3; ++a)
      {
        g.E[a] += best[a];
      }
    }
  }
  for (double& e : g.E)
  {
    e = used > 0 ? 2.0 * Pi / used * e : 0.0;
  }
  g.Confidence = std::min(static_cast<double>(used) * t.Stride / (n + outer), 1.0);
  return g;
}

vtkSmartPointer<vtkDeepRadiosityPass> SingleBouncePass(double radius)
{
  auto pass = vtkSmartPointer<vtkDeepRadiosityPass>::New();
  pass->SetRadius(radius);
  pass->SetDamping(0.0);
  pass->SetTemporalAlpha(0.0);
  return pass;
}

// The taps `pass` gathers with in the first frame of `f`: its settings, the
// MIP range the frame's size allows and, with `interleave` > 1, the
// temporal filter's share of the taps and rotation in that frame.
TapSettings TapSettingsOf(vtkDeepRadiosityPass* pass, const Frame& f, int layerCount, double radius,
  int outer, int interleave)
{
  int finest = 0;
  while ((std::max(f.Width, f.Height) >> (finest + 1)) > 0)
  {
    ++finest;
  }
  TapSettings taps;
  taps.MaxMip = std::min(std::max(pass->GetMaximumMipLevel(), pass->GetMinimumMipLevel()), finest);
  taps.MinMip = std::min(pass->GetMinimumMipLevel(), taps.MaxMip);
  taps.LayerCount = layerCount;
  taps.Samples = pass->GetNumberOfSamples();
  taps.Outer = outer;
  taps.Radius = radius;
  taps.MipThreshold = pass->GetMipThreshold();
  taps.NormalTest = pass->GetUseNormalTest();
  taps.Divisor = pass->GetResolutionDivisor();
  if (interleave > 1)
  {
    // The history's first frame, k = 1: phase k mod S, rotation
    // 2 pi fract(k / golden ratio).
    const double inverseGoldenRatio = 0.6180339887498949;
    taps.Stride = interleave;
    taps.Phase = 1 % interleave;
    taps.Rotation = 2.0 * Pi * inverseGoldenRatio;
  }
  return taps;
}

// `interleave` > 1: the first frame with the temporal filter on and the taps
// spread over that many frames (TemporalInterleave).
void TestReference(int preset, int outer = 0, int interleave = 1)
{
  const double radius = 1.5;
  auto pass = SingleBouncePass(radius);
  pass->SetPreset(preset);
  pass->SetOuterSamples(outer);
  if (interleave > 1)
  {
    pass->SetTemporalAlpha(0.5);
    pass->SetTemporalInterleave(interleave);
  }
  // The CPU evaluation reads a tap's B at its source texel, as the gather
  // does without AverageFarTaps (the outer ring's taps read coarse levels).
  pass->SetAverageFarTaps(false);
  // The CPU evaluation below is eq. 4 as printed (2 pi / M sum), not the
  // default SOLID_ANGLE estimator.
  pass->SetEstimator(vtkDeepRadiosityPass::ACCEPTED_TAPS);
  // The CPU evaluation reads the captured frame, so the layers must be the
  // frame alone (TestDeepGuardBand checks the guard band against a wider
  // frame).
  pass->GetGBufferPass()->SetGuardBand(0.0);
  Frame f;
  // A white box in front of the corner puts floor and wall into layer 1.
  auto scene = [](vtkRenderer* r)
  {
    RedWallScene(r);
    const double center[3] = { 1.6, 0.5, 0.6 }, size[3] = { 0.6, 1.0, 0.6 };
    Diffuse(AddBox(r, center, size), 1, 1, 1);
  };
  if (!RenderFrames(scene, pass, 1, f))
  {
    return;
  }
  Check(AllFinite(f.Radiosity), "radiosity finite");
  const int layerCount = static_cast<int>(
    f.Radiosity->GetFieldData()->GetArray(vtkDeepGICaptureNames::NumberOfLayers)->GetTuple1(0));
  Check(layerCount == 2, "two layers");
  // On a reduced grid (HIGH_PERFORMANCE: divisor 2) the gather runs for the
  // receivers, texels (divisor i, divisor j); the capture repeats each over
  // the texels it stands for.
  const int divisor = pass->GetResolutionDivisor();
  const TapSettings taps = TapSettingsOf(pass, f, layerCount, radius, outer, interleave);
  for (int layer = 0; layer < layerCount; ++layer)
  {
    const std::string suffix = "_" + std::to_string(layer);
    long compared = 0, mismatched = 0, withLight = 0;
    double worst = 0.0;
    for (int j = 0; j < f.Height; ++j)
    {
      for (int i = 0; i < f.Width; ++i)
      {
        if (At(f.Radiosity, vtkDeepGICaptureNames::Valid + suffix, i, j) == 0 || i % divisor != 0 ||
          j % divisor != 0)
        {
          continue;
        }
        ++compared;
        const Gather g = ReferenceGather(f.Layers, i, j, layer, taps);
        // The targets are RGBA16F: 11 significant bits, a relative
        // rounding of at most 2^-11 (4.9e-4).
        bool same = std::abs(At(f.Radiosity, vtkDeepGICaptureNames::RawConfidence + suffix, i, j) -
                      g.Confidence) < 1e-3;
        for (int c = 0; c < 3; ++c)
        {
          const double d = std::abs(
            At(f.Radiosity, vtkDeepGICaptureNames::RawIrradiance + suffix, i, j, c) - g.E[c]);
          same = same && d <= 1e-3 * (1.0 + std::abs(g.E[c]));
          worst = std::max(worst, d);
        }
        withLight += g.E[0] > 0.01 ? 1 : 0;
        mismatched += same ? 0 : 1;
      }
    }
    std::printf("%s, %d outer taps, taps over %d frames, layer %d: %ld pixels, %ld with "
                "E.r > 0.01, %ld differ from the CPU (largest |dE| %.3g)\n",
      vtkDeepRadiosityPass::GetPresetAsString(preset), outer, interleave, layer, compared,
      withLight, mismatched, worst);
    Check(compared > (layer == 0 ? f.Width * f.Height / (2 * divisor * divisor) : 50 / divisor),
      "layer has surface pixels");
    Check(withLight > compared / 20, "some pixels gather light");
    Check(mismatched <= compared / 100, "GPU gather equals the CPU eq. 4-5 on >= 99 % of pixels");
  }
  pass->ReleaseGraphicsResources(f.Window);
}

void TestBleeding()
{
  const double radius = 1.5;
  auto pass = SingleBouncePass(radius);
  // With the outer ring (OuterSamples, on by default) the gather reaches
  // OUTER_RADIUS_SCALE r.
  const double reach = radius * vtkDeepRadiosityPass::OUTER_RADIUS_SCALE;
  Frame f;
  if (!RenderFrames([](vtkRenderer* r) { RedWallScene(r); }, pass, 1, f))
  {
    return;
  }
  // Floor pixels of layer 0, binned by the distance x from the wall.
  const double edges[] = { 0.0, 0.3, 0.6, 0.9, 1.2, 1.5, 4.0 };
  constexpr int bins = 6;
  double sum[bins][3] = {}, beyond = 0.0;
  long count[bins] = {};
  for (int j = 0; j < f.Height; ++j)
  {
    for (int i = 0; i < f.Width; ++i)
    {
      double p[3];
      if (!WorldPosition(f.Layers, 0, i, j, p) || std::abs(p[1]) > 1e-3 || std::abs(p[2]) > 2.0)
      {
        continue;
      }
      for (int b = 0; b < bins; ++b)
      {
        if (p[0] >= edges[b] && p[0] < edges[b + 1])
        {
          ++count[b];
          for (int c = 0; c < 3; ++c)
          {
            sum[b][c] += At(f.Radiosity,
              vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0), i, j, c);
          }
        }
      }
      if (p[0] > reach + 0.05)
      {
        beyond = std::max(beyond,
          At(f.Radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::RawIrradiance, 0), i,
            j, 0));
      }
    }
  }
  double mean[bins][3];
  for (int b = 0; b < bins; ++b)
  {
    for (int c = 0; c < 3; ++c)
    {
      mean[b][c] = count[b] ? sum[b][c] / count[b] : 0.0;
    }
    std::printf("floor x in [%.1f, %.1f): %ld px, mean L_ind (%.4f, %.4f, %.4f)\n", edges[b],
      edges[b + 1], count[b], mean[b][0], mean[b][1], mean[b][2]);
    Check(count[b] > 20, "floor bin has pixels");
  }
  Check(mean[0][0] > 0.02, "red light next to the red wall");
  Check(mean[0][1] < 0.02 * mean[0][0] && mean[0][2] < 0.02 * mean[0][0],
    "green and blue < 2 % of red next to the wall");
  Check(mean[0][0] > mean[2][0] && mean[2][0] > mean[4][0], "red light falls off with distance");
  std::printf("largest raw E.r farther than 1.5 r + 0.05 from the wall: %.3g\n", beyond);
  Check(beyond == 0.0, "no indirect light beyond the gather's reach");
  pass->ReleaseGraphicsResources(f.Window);
}

// The composite of the red-wall scene: RADIANCE + L_ind of layer 0,
// background kept.
void TestComposite()
{
  auto composite = SingleBouncePass(1.5);
  Frame g;
  if (!RenderFrames([](vtkRenderer* r) { RedWallScene(r); }, composite, 1, g))
  {
    return;
  }
  vtkNew<vtkImageData> rgb;
  ReadWindow(g.Window, rgb, nullptr);
  vtkDataArray* pixels = rgb->GetPointData()->GetScalars();
  double worst = 0.0;
  long background = 0, wrongBackground = 0;
  for (int j = 0; j < g.Height; ++j)
  {
    for (int i = 0; i < g.Width; ++i)
    {
      const vtkIdType p = static_cast<vtkIdType>(j) * g.Width + i;
      if (At(g.Radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 0), i, j) == 0)
      {
        ++background;
        wrongBackground +=
          pixels->GetComponent(p, 0) + pixels->GetComponent(p, 1) + pixels->GetComponent(p, 2) > 0
          ? 1
          : 0;
        continue;
      }
      for (int c = 0; c < 3; ++c)
      {
        const double expected = 255.0 *
          std::min(1.0,
            Layer(g.Layers, vtkDeepGICaptureNames::Radiance, 0)->GetComponent(p, c) +
              At(g.Radiosity,
                vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0), i, j, c));
        worst = std::max(worst, std::abs(pixels->GetComponent(p, c) - expected));
      }
    }
  }
  std::printf("composite: largest difference from RADIANCE + L_ind %.2f levels; %ld background "
              "pixels, %ld not black\n",
    worst, background, wrongBackground);
  Check(worst <= 2.0, "composite = RADIANCE + L_ind");
  Check(background > 0 && wrongBackground == 0, "background kept");
  composite->ReleaseGraphicsResources(g.Window);
}

// Floor pixels (both layers) behind the blue panel, within r of it: their
// largest and mean blue excess b - (r + g) / 2 of the raw E (the bilateral
// filter rightly blends in the light of the floor in front of the panel,
// which is the same plane).
void BlueExcess(Frame& f, double& largest, double& mean, long& pixels)
{
  largest = mean = 0.0;
  pixels = 0;
  for (int layer = 0; layer < 2; ++layer)
  {
    const std::string name =
      vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::RawIrradiance, layer);
    for (int j = 0; j < f.Height; ++j)
    {
      for (int i = 0; i < f.Width; ++i)
      {
        double p[3];
        if (!WorldPosition(f.Layers, layer, i, j, p) || std::abs(p[1]) > 1e-3 || p[0] < 1.2 ||
          p[0] > 2.45 || std::abs(p[2]) > 1.0)
        {
          continue;
        }
        const double excess = At(f.Radiosity, name, i, j, 2) -
          0.5 * (At(f.Radiosity, name, i, j, 0) + At(f.Radiosity, name, i, j, 1));
        largest = std::max(largest, excess);
        mean += excess;
        ++pixels;
      }
    }
  }
  mean = pixels ? mean / pixels : 0.0;
}

void TestNormalTest()
{
  // [estimator][n_Y test]: eq. 4 needs the n_Y test to reject the face
  // looking away; the default SOLID_ANGLE weights each tap by max(-w.n_Y, 0)
  // and rejects it with or without the test.
  const int estimators[2] = { vtkDeepRadiosityPass::ACCEPTED_TAPS,
    vtkDeepRadiosityPass::SOLID_ANGLE };
  double largest[2][2], mean[2][2];
  long pixels[2][2];
  for (int e = 0; e < 2; ++e)
  {
    for (int on = 0; on < 2; ++on)
    {
      auto pass = SingleBouncePass(1.5);
      if (e == 0)
      {
        pass->SetEstimator(estimators[e]);
      }
      pass->SetUseNormalTest(on != 0);
      Frame f;
      if (!RenderFrames([](vtkRenderer* r) { BlueBackScene(r); }, pass, 1, f))
      {
        return;
      }
      BlueExcess(f, largest[e][on], mean[e][on], pixels[e][on]);
      std::printf("%s, n_Y test %s: %ld floor pixels behind the panel, blue excess mean %.4g, "
                  "largest %.4g\n",
        vtkDeepRadiosityPass::GetEstimatorAsString(estimators[e]), on ? "on" : "off", pixels[e][on],
        mean[e][on], largest[e][on]);
      pass->ReleaseGraphicsResources(f.Window);
    }
  }
  Check(pixels[0][1] > 50 && pixels[1][1] > 50, "floor pixels behind the panel");
  Check(largest[0][1] <= 1e-5, "eq. 4 with the n_Y test: a face looking away sends no light");
  Check(mean[0][0] > 0.005, "eq. 4 without the n_Y test: the face looking away sends light");
  Check(largest[1][0] <= 1e-5 && largest[1][1] <= 1e-5,
    "SOLID_ANGLE (default): a face looking away sends no light, n_Y test or not");
}

void TestBoost()
{
  auto floorScene = [](double r, double g, double b)
  {
    return [=](vtkRenderer* renderer)
    {
      RedWallScene(renderer);
      vtkActor* floor = vtkActor::SafeDownCast(renderer->GetActors()->GetItemAsObject(0));
      Diffuse(floor, r, g, b);
    };
  };
  double ratio = 0.0, worst = 0.0, whiteFloor = 0.0;
  long compared = 0;
  Frame plain, boosted, white;
  auto p1 = SingleBouncePass(1.5);
  auto p2 = SingleBouncePass(1.5);
  p2->UseColorBoostOn();
  auto p3 = SingleBouncePass(1.5);
  p3->UseColorBoostOn();
  if (!RenderFrames(floorScene(1, 0.5, 0.5), p1, 1, plain) ||
    !RenderFrames(floorScene(1, 0.5, 0.5), p2, 1, boosted) ||
    !RenderFrames(floorScene(1, 1, 1), p3, 1, white))
  {
    return;
  }
  for (int j = 0; j < plain.Height; ++j)
  {
    for (int i = 0; i < plain.Width; ++i)
    {
      double p[3];
      const vtkIdType pixel = static_cast<vtkIdType>(j) * plain.Width + i;
      if (!WorldPosition(plain.Layers, 0, i, j, p) || std::abs(p[1]) > 1e-3 || p[0] < 0.01)
      {
        continue; // not the floor
      }
      whiteFloor = std::max(whiteFloor,
        At(white.Radiosity,
          vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0), i, j, 0));
      const double a = At(plain.Radiosity,
        vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0), i, j, 0);
      if (a > 1e-3)
      {
        ++compared;
        // Eq. 7 of the stored (8-bit) albedo: (max - min) / max.
        double rho[3];
        Layer(boosted.Layers, vtkDeepGICaptureNames::Albedo, 0)->GetTuple(pixel, rho);
        const double boost =
          (std::max({ rho[0], rho[1], rho[2] }) - std::min({ rho[0], rho[1], rho[2] })) /
          std::max({ rho[0], rho[1], rho[2] });
        ratio =
          At(boosted.Radiosity,
            vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0), i, j, 0) /
          a;
        worst = std::max(worst, std::abs(ratio - boost));
      }
    }
  }
  std::printf("boost: %ld floor pixels, largest |L_boost / L - boost(rho)| %.3g; white floor "
              "largest "
              "L_ind %.3g\n",
    compared, worst, whiteFloor);
  // Both radiances come from RGBA16F targets, each rounded by at most 2^-11
  // (4.9e-4) relative; boost(rho) is at most 1.
  Check(compared > 50 && worst <= 1e-3, "L_boost = boost(rho) L for a (1, 0.5, 0.5) floor");
  Check(whiteFloor == 0.0, "boost of a white floor is 0");
  p1->ReleaseGraphicsResources(plain.Window);
  p2->ReleaseGraphicsResources(boosted.Window);
  p3->ReleaseGraphicsResources(white.Window);
}

void TestFallback()
{
  const double environment[3] = { 0.3 * Pi, 0.2 * Pi, 0.1 * Pi };
  auto off = SingleBouncePass(1.0);
  auto on = SingleBouncePass(1.0);
  on->ConfidenceFallbackOn();
  on->SetEnvironmentIrradiance(environment);
  Frame a, b;
  if (!RenderFrames([](vtkRenderer* r) { RedWallScene(r); }, off, 1, a) ||
    !RenderFrames([](vtkRenderer* r) { RedWallScene(r); }, on, 1, b))
  {
    return;
  }
  double worst = 0.0, lowest = 1.0;
  for (int j = 0; j < a.Height; ++j)
  {
    for (int i = 0; i < a.Width; ++i)
    {
      if (At(a.Radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 0), i, j) == 0)
      {
        continue;
      }
      const double c =
        At(b.Radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Confidence, 0), i, j);
      lowest = std::min(lowest, c);
      for (int k = 0; k < 3; ++k)
      {
        const double rho = Layer(b.Layers, vtkDeepGICaptureNames::Albedo, 0)
                             ->GetComponent(static_cast<vtkIdType>(j) * a.Width + i, k);
        const double expected = c *
            At(a.Radiosity,
              vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0), i, j, k) +
          (1.0 - c) * rho * environment[k] / Pi;
        worst = std::max(worst,
          std::abs(
            At(b.Radiosity,
              vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0), i, j, k) -
            expected));
      }
    }
  }
  std::printf("fallback: lowest confidence %.3f, largest difference from c L + (1 - c) rho E/pi "
              "%.3g\n",
    lowest, worst);
  Check(lowest < 0.5, "some pixels have a low confidence");
  // L and c come from RGBA16F targets (rounded by at most 2^-11, 4.9e-4,
  // relative), and L is below 1 here.
  Check(worst <= 1e-3, "fallback = c L + (1 - c) rho E_env / pi");

  // Automatic environment: pi times the renderer's ambient colour.
  auto automatic = SingleBouncePass(1.0);
  Frame c;
  RenderFrames(
    [](vtkRenderer* r)
    {
      RedWallScene(r);
      r->SetAmbient(0.2, 0.3, 0.4);
    },
    automatic, 1, c);
  const double* e = automatic->GetEffectiveEnvironmentIrradiance();
  Check(std::abs(e[0] - 0.2 * Pi) < 1e-12 && std::abs(e[1] - 0.3 * Pi) < 1e-12 &&
      std::abs(e[2] - 0.4 * Pi) < 1e-12,
    "automatic environment irradiance = pi x ambient colour");
  off->ReleaseGraphicsResources(a.Window);
  on->ReleaseGraphicsResources(b.Window);
  automatic->ReleaseGraphicsResources(c.Window);
}

// UpdateRadiosity from another pass gives the same radiosity as Render and
// leaves the framebuffer to that pass (here: the plain G-buffer image).
void TestExternalComposite()
{
  auto own = SingleBouncePass(1.5);
  auto used = SingleBouncePass(1.5);
  Frame a, b;
  vtkNew<ExternalComposite> composite;
  composite->Step->Radiosity = used;
  if (!RenderFrames([](vtkRenderer* r) { RedWallScene(r); }, own, 2, a))
  {
    return;
  }
  b.Width = a.Width;
  b.Height = a.Height;
  b.Window = MakeWindow(b.Width, b.Height);
  b.Renderer = vtkSmartPointer<vtkRenderer>::New();
  b.Window->AddRenderer(b.Renderer);
  RedWallScene(b.Renderer);
  b.Renderer->ResetCameraClippingRange();
  b.Renderer->SetPass(composite);
  b.Window->Render();
  b.Window->Render();
  const bool ok = used->CaptureIrradiance(b.Radiosity, b.Renderer) &&
    used->GetGBufferPass()->CaptureLayers(b.Layers, b.Renderer);
  Check(ok && composite->Step->Updates == 2 && composite->Step->Units == 2,
    "UpdateRadiosity and ActivateTexture from another pass");
  if (!ok)
  {
    return;
  }
  vtkDataArray* x = a.Radiosity->GetPointData()->GetArray(
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0).c_str());
  vtkDataArray* y = b.Radiosity->GetPointData()->GetArray(
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0).c_str());
  double worst = 0.0, image = 0.0;
  vtkNew<vtkImageData> rgb;
  ReadWindow(b.Window, rgb, nullptr);
  for (vtkIdType p = 0; p < x->GetNumberOfTuples(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      worst = std::max(worst, std::abs(x->GetComponent(p, c) - y->GetComponent(p, c)));
      if (Layer(b.Layers, vtkDeepGICaptureNames::Valid, 0)->GetTuple1(p) != 0)
      {
        image = std::max(image,
          std::abs(rgb->GetPointData()->GetScalars()->GetComponent(p, c) -
            255.0 *
              std::min(
                1.0, Layer(b.Layers, vtkDeepGICaptureNames::Radiance, 0)->GetComponent(p, c))));
      }
    }
  }
  std::printf("external composite: largest |L_ind - L_ind of Render| %.3g, largest |image - "
              "RADIANCE| %.2f levels\n",
    worst, image);
  Check(worst <= 1e-6, "UpdateRadiosity = Render's radiosity");
  Check(image <= 1.0, "the framebuffer is the other pass's (plain RADIANCE)");
  // A renderer the G-buffer never saw: an error, no crash.
  vtkNew<vtkRenderer> other;
  b.Window->AddRenderer(other);
  b.Window->MakeCurrent();
  EventCounter errors(used, vtkCommand::ErrorEvent);
  vtkRenderState otherState(other);
  Check(!used->UpdateRadiosity(&otherState) && errors.Count == 1,
    "UpdateRadiosity without layers: false and one error");
  own->ReleaseGraphicsResources(a.Window);
  used->ReleaseGraphicsResources(b.Window);
}

void TestPresets()
{
  vtkNew<vtkDeepRadiosityPass> pass;
  struct Expected
  {
    int Preset, Samples, BlurRadius;
    bool Test;
    int Mip, Divisor;
  };
  const Expected table[] = { { vtkDeepRadiosityPass::HIGH_PERFORMANCE, 13, 4, false, 3, 2 },
    { vtkDeepRadiosityPass::BALANCED, 14, 5, true, 1, 1 },
    { vtkDeepRadiosityPass::HIGH_QUALITY, 30, 6, true, 0, 1 } };
  Check(pass->GetNumberOfSamples() == 14 && pass->GetBlurRadius() == 5 &&
      pass->GetUseNormalTest() && pass->GetMinimumMipLevel() == 1 &&
      pass->GetResolutionDivisor() == 1,
    "defaults are BALANCED");
  for (const Expected& e : table)
  {
    pass->SetPreset(e.Preset);
    Check(pass->GetNumberOfSamples() == e.Samples && pass->GetBlurRadius() == e.BlurRadius &&
        pass->GetUseNormalTest() == e.Test && pass->GetMinimumMipLevel() == e.Mip &&
        pass->GetResolutionDivisor() == e.Divisor,
      std::string("preset ") + vtkDeepRadiosityPass::GetPresetAsString(e.Preset));
  }
  // The deprecated FilterTaps: taps per direction, 2 BlurRadius + 1.
  pass->SetFilterTaps(9);
  Check(pass->GetBlurRadius() == 4 && pass->GetFilterTaps() == 9,
    "FilterTaps 9 (deprecated) is BlurRadius 4");
  pass->SetFilterTaps(100);
  Check(pass->GetBlurRadius() == 16, "FilterTaps is clamped to 33 taps");
  EventCounter warnings(pass, vtkCommand::WarningEvent);
  pass->SetPreset(7);
  Check(warnings.Count == 1 && pass->GetNumberOfSamples() == 30, "unknown preset ignored");
  std::ostringstream os;
  pass->Print(os);
  for (const char* name :
    { vtkDeepGICaptureNames::Radius, "AutomaticRadius", "AutomaticRadiusFraction",
      "EffectiveRadius", vtkDeepGICaptureNames::NumberOfSamples, "UseNormalTest", "UseColorBoost",
      "BlurRadius", "BlurPlaneTolerance", "BlurNormalPower", "MipThreshold", "MinimumMipLevel",
      "MaximumMipLevel", "ResolutionDivisor", "Damping", "TemporalAlpha", "TemporalInterleave",
      vtkDeepGICaptureNames::ReprojectionTolerance, "AutomaticReprojectionTolerance",
      "AutomaticReprojectionFraction", "EffectiveReprojectionTolerance", "ConfidenceFallback",
      vtkDeepGICaptureNames::EnvironmentIrradiance, "AutomaticEnvironmentIrradiance",
      "EffectiveEnvironmentIrradiance", "GBufferPass" })
  {
    Check(os.str().find(std::string(name) + ":") != std::string::npos,
      std::string("PrintSelf prints ") + name);
  }
}
}

int TestDeepRadiosity(int, char*[])
{
  TestReference(vtkDeepRadiosityPass::BALANCED);
  TestReference(vtkDeepRadiosityPass::HIGH_PERFORMANCE);
  TestReference(vtkDeepRadiosityPass::BALANCED, 4);
  TestReference(vtkDeepRadiosityPass::BALANCED, 4, 2);
  TestReference(vtkDeepRadiosityPass::BALANCED, 4, 3);
  TestBleeding();
  TestComposite();
  TestNormalTest();
  TestBoost();
  TestFallback();
  TestExternalComposite();
  TestPresets();
  return ExitStatus();
}
