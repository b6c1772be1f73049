// Temporal accumulation with reprojection of vtkDeepAmbientObscurancePass
// (TemporalAlpha):
// (1) TemporalAlpha 0 (also after accumulating for a few frames) gives
//     exactly the AV arrays and the image of a pass at default settings;
// (2) still camera, N = 4, BlurRadius 0, alpha 0.9 on the floor/wall corner:
//     after 20 frames the mean |AV - AV(N = 98)| over the valid pixels is at
//     least 30 % below that of a single N = 4 frame (the per-frame rotation
//     offset makes the frames sample other directions);
// (3) a small orbit around the box: AV finite and in [0, 1]; the pixels the
//     test's own CPU reprojection clearly rejects (outside the previous
//     image, previous texel empty, or previous distance off by > 5 %, with
//     a one-texel margin) hold exactly AV_now (the raw AV, BlurRadius 0),
//     the clearly accepted ones mix(AV_now, AV_prev, alpha) (1e-4), and
//     both kinds occur;
// (4) the history is reset (first frame = AV_now) after
//     ReleaseGraphicsResources, after a render of the renderer without the
//     pass, and after a resize.

#include "DeepGBufferTestUtilities.h"

#include "vtkCamera.h"
#include "vtkDeepAmbientObscurancePass.h"
#include "vtkDeepGBufferPass.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkFieldData.h"
#include "vtkMatrix4x4.h"
#include "vtkPolyDataMapper.h"

#include <algorithm>
#include <cmath>
#include <vector>

using namespace DeepGBufferTest;
using namespace DeepGITest;

namespace
{
struct Frame
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
};

Frame Setup(vtkDeepAmbientObscurancePass* pass, int width, int height, bool box)
{
  Frame f;
  f.Window = MakeWindow(width, height);
  f.Renderer = vtkSmartPointer<vtkRenderer>::New();
  f.Window->AddRenderer(f.Renderer);
  AddCornerScene(f.Renderer, box);
  f.Renderer->ResetCameraClippingRange();
  f.Renderer->SetPass(pass);
  return f;
}

void Finish(vtkDeepAmbientObscurancePass* pass, Frame& f)
{
  f.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(f.Window);
}

vtkDataArray* Array(vtkImageData* image, const char* name)
{
  return image->GetPointData()->GetArray(name);
}

bool Capture(vtkDeepAmbientObscurancePass* pass, Frame& f, vtkImageData* av)
{
  const bool ok = pass->CaptureAmbientVisibility(av, f.Renderer);
  Check(ok, "capture AV");
  return ok;
}

// True if AV equals the raw AV exactly at every pixel (BlurRadius 0: the
// first frame after a reset).
bool EqualsRaw(vtkImageData* av)
{
  vtkDataArray* a = Array(av, vtkDeepGICaptureNames::AmbientVisibility);
  vtkDataArray* r = Array(av, vtkDeepGICaptureNames::RawAmbientVisibility);
  for (vtkIdType p = 0; p < a->GetNumberOfTuples(); ++p)
  {
    if (a->GetTuple1(p) != r->GetTuple1(p))
    {
      return false;
    }
  }
  return true;
}

double MeanAbsoluteError(vtkImageData* a, vtkImageData* reference)
{
  vtkDataArray* x = Array(a, vtkDeepGICaptureNames::AmbientVisibility);
  vtkDataArray* y = Array(reference, vtkDeepGICaptureNames::AmbientVisibility);
  vtkDataArray* valid = Array(reference, vtkDeepGICaptureNames::Valid);
  double sum = 0.0;
  long n = 0;
  for (vtkIdType p = 0; p < x->GetNumberOfTuples(); ++p)
  {
    if (valid->GetTuple1(p) > 0)
    {
      sum += std::abs(x->GetTuple1(p) - y->GetTuple1(p));
      ++n;
    }
  }
  return n ? sum / n : 0.0;
}

// (1)
void TestOffIsIdentical()
{
  const int w = 160, h = 120;
  vtkNew<vtkDeepAmbientObscurancePass> a, b;
  Check(a->GetTemporalAlpha() == 0.0, "default TemporalAlpha 0");
  a->SetTemporalAlpha(2.0);
  Check(a->GetTemporalAlpha() == 0.99, "TemporalAlpha clamped to 0.99");
  a->SetTemporalAlpha(0.5);
  Frame fa = Setup(a, w, h, true);
  Frame fb = Setup(b, w, h, true);
  for (int i = 0; i < 3; ++i)
  {
    fa.Window->Render();
  }
  a->SetTemporalAlpha(0.0);
  for (int i = 0; i < 2; ++i)
  {
    fa.Window->Render();
    fb.Window->Render();
  }
  vtkNew<vtkImageData> avA, avB, rgbA, rgbB;
  if (Capture(a, fa, avA) && Capture(b, fb, avB))
  {
    bool same = true;
    for (const char* name :
      { vtkDeepGICaptureNames::AmbientVisibility, vtkDeepGICaptureNames::RawAmbientVisibility })
    {
      vtkDataArray* x = Array(avA, name);
      vtkDataArray* y = Array(avB, name);
      for (vtkIdType p = 0; p < x->GetNumberOfTuples(); ++p)
      {
        same = same && x->GetTuple1(p) == y->GetTuple1(p);
      }
    }
    Check(same, "alpha 0: AV arrays bit-identical to a default pass");
  }
  ReadWindow(fa.Window, rgbA, nullptr);
  ReadWindow(fb.Window, rgbB, nullptr);
  const double diff = MaximumColorDifference(rgbA, rgbB);
  std::printf("(1) alpha 0 vs default: max colour difference %g\n", diff);
  Check(diff == 0.0, "alpha 0: image identical to a default pass");
  Finish(a, fa);
  Finish(b, fb);
}

// (2)
void TestConvergence()
{
  const int w = 200, h = 160;
  auto configure = [](vtkDeepAmbientObscurancePass* pass, int n, double alpha)
  {
    pass->SetRadius(1.0);
    pass->SetNumberOfSamples(n);
    pass->SetBlurRadius(0);
    pass->SetTemporalAlpha(alpha);
  };
  vtkNew<vtkDeepAmbientObscurancePass> reference, single, accumulated;
  configure(reference, 98, 0.0);
  configure(single, 4, 0.0);
  configure(accumulated, 4, 0.9);
  Frame fr = Setup(reference, w, h, false);
  Frame fs = Setup(single, w, h, false);
  Frame fa = Setup(accumulated, w, h, false);
  fr.Window->Render();
  fs.Window->Render();
  vtkNew<vtkImageData> avR, avS, avA, avFirst;
  for (int i = 0; i < 20; ++i)
  {
    fa.Window->Render();
    if (i == 0)
    {
      Capture(accumulated, fa, avFirst);
    }
  }
  if (Capture(reference, fr, avR) && Capture(single, fs, avS) && Capture(accumulated, fa, avA))
  {
    Check(EqualsRaw(avFirst), "first accumulated frame is AV_now");
    Check(AllFinite(avA), "accumulated AV finite");
    const double single1 = MeanAbsoluteError(avS, avR);
    const double first = MeanAbsoluteError(avFirst, avR);
    const double accumulated20 = MeanAbsoluteError(avA, avR);
    std::printf("(2) mean |AV - AV(N=98)|: single N=4 frame %.5f, first temporal frame %.5f, "
                "20 frames alpha 0.9 %.5f (reduction %.1f %%)\n",
      single1, first, accumulated20, 100.0 * (1.0 - accumulated20 / single1));
    Check(accumulated20 <= 0.7 * single1, "accumulation reduces the error by >= 30 %");
  }
  Finish(reference, fr);
  Finish(single, fs);
  Finish(accumulated, fa);
}

struct Camera
{
  double View[16];
  double Projection[16];
};

// (3)
void TestMovingCamera()
{
  const int w = 200, h = 160;
  const double alpha = 0.9;
  vtkNew<vtkDeepAmbientObscurancePass> pass;
  pass->SetRadius(1.0);
  pass->SetNumberOfSamples(8);
  pass->SetBlurRadius(0);
  pass->SetTemporalAlpha(alpha);
  Frame f = Setup(pass, w, h, true);
  for (int i = 0; i < 3; ++i)
  {
    f.Window->Render();
  }
  vtkNew<vtkImageData> previousAV, previousDistance;
  Camera previous;
  Capture(pass, f, previousAV);
  pass->CaptureDistancePyramid(0, previousDistance, f.Renderer);
  pass->GetGBufferPass()->GetLayerCamera(f.Renderer, previous.View, previous.Projection);
  long rejected = 0, accepted = 0, rejectedWrong = 0, acceptedWrong = 0;
  bool inRange = true;
  for (int frame = 0; frame < 5; ++frame)
  {
    f.Renderer->GetActiveCamera()->Azimuth(3.0);
    f.Renderer->ResetCameraClippingRange();
    f.Window->Render();
    vtkNew<vtkImageData> av, distance;
    Camera now;
    if (!Capture(pass, f, av) || !pass->CaptureDistancePyramid(0, distance, f.Renderer))
    {
      return;
    }
    pass->GetGBufferPass()->GetLayerCamera(f.Renderer, now.View, now.Projection);
    vtkDataArray* a = Array(av, vtkDeepGICaptureNames::AmbientVisibility);
    vtkDataArray* raw = Array(av, vtkDeepGICaptureNames::RawAmbientVisibility);
    vtkDataArray* d =
      Array(distance, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Distance, 0).c_str());
    vtkDataArray* pa = Array(previousAV, vtkDeepGICaptureNames::AmbientVisibility);
    vtkDataArray* pd = Array(
      previousDistance, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Distance, 0).c_str());
    // Current camera -> previous camera.
    vtkNew<vtkMatrix4x4> inverse, toPrevious;
    inverse->DeepCopy(now.View);
    inverse->Invert();
    vtkMatrix4x4::Multiply4x4(previous.View, &inverse->Element[0][0], &toPrevious->Element[0][0]);
    const double* P = now.Projection;
    const double* Q = previous.Projection;
    for (int y = 0; y < h; ++y)
    {
      for (int x = 0; x < w; ++x)
      {
        const vtkIdType p = y * w + x;
        const double value = a->GetTuple1(p);
        inRange = inRange && std::isfinite(value) && value >= 0.0 && value <= 1.0;
        const double dist = d->GetTuple1(p);
        if (!(dist > 0.0))
        {
          continue;
        }
        // Camera-space point (as deepPositionFromDistance).
        const double nx = (x + 0.5) / w * 2.0 - 1.0, ny = (y + 0.5) / h * 2.0 - 1.0;
        const double z = -dist, cw = -P[14] * dist + P[15];
        const double X[4] = { (nx * cw - P[2] * z - P[3]) / P[0],
          (ny * cw - P[6] * z - P[7]) / P[5], z, 1.0 };
        double Y[4], C[4];
        toPrevious->MultiplyPoint(X, Y);
        const double dr = -Y[2];
        for (int r = 0; r < 4; ++r)
        {
          C[r] = Q[r * 4] * Y[0] + Q[r * 4 + 1] * Y[1] + Q[r * 4 + 2] * Y[2] + Q[r * 4 + 3] * Y[3];
        }
        const double px = (C[0] / C[3] * 0.5 + 0.5) * w, py = (C[1] / C[3] * 0.5 + 0.5) * h;
        // Classify over the 3x3 texels around the nearest one, so that float
        // rounding on the GPU cannot change the outcome.
        const int tx = static_cast<int>(std::floor(px)), ty = static_cast<int>(std::floor(py));
        bool outside =
          C[3] <= 0.0 || dr <= 0.0 || px < -1.0 || py < -1.0 || px >= w + 1.0 || py >= h + 1.0;
        bool allBad = true, allGood = true, nearEdge = false;
        std::vector<double> candidates;
        if (!outside)
        {
          for (int oy = -1; oy <= 1; ++oy)
          {
            for (int ox = -1; ox <= 1; ++ox)
            {
              const int sx = tx + ox, sy = ty + oy;
              if (sx < 0 || sy < 0 || sx >= w || sy >= h)
              {
                nearEdge = true;
                continue;
              }
              const double prevDist = pd->GetTuple1(sy * w + sx);
              const double mismatch = std::abs(prevDist - dr) / dr;
              const bool bad = !(prevDist > 0.0) || mismatch > 0.05;
              const bool good = prevDist > 0.0 && mismatch < 0.005;
              allBad = allBad && bad;
              allGood = allGood && good;
              candidates.push_back(
                (1.0 - alpha) * raw->GetTuple1(p) + alpha * pa->GetTuple1(sy * w + sx));
            }
          }
        }
        if (outside || (allBad && !candidates.empty()))
        {
          ++rejected;
          rejectedWrong += value != raw->GetTuple1(p) ? 1 : 0;
        }
        else if (allGood && !nearEdge)
        {
          ++accepted;
          double best = 1.0;
          for (double c : candidates)
          {
            best = std::min(best, std::abs(c - value));
          }
          acceptedWrong += best > 1e-4 ? 1 : 0;
        }
      }
    }
    previousAV->DeepCopy(av);
    previousDistance->DeepCopy(distance);
    previous = now;
  }
  std::printf("(3) orbit, 5 frames: %ld clearly rejected pixels (%ld not AV_now), %ld clearly "
              "accepted (%ld not the mix)\n",
    rejected, rejectedWrong, accepted, acceptedWrong);
  Check(inRange, "AV finite and in [0, 1] while moving");
  Check(rejected > 0 && rejectedWrong == 0, "rejected pixels hold AV_now");
  Check(accepted > 0 && acceptedWrong == 0, "accepted pixels hold the mix");
  Finish(pass, f);
}

// (4)
void TestResets()
{
  const int w = 120, h = 100;
  vtkNew<vtkDeepAmbientObscurancePass> pass;
  pass->SetRadius(1.0);
  pass->SetNumberOfSamples(4);
  pass->SetBlurRadius(0);
  pass->SetTemporalAlpha(0.9);
  Frame f = Setup(pass, w, h, true);
  f.Window->Render();
  f.Window->Render();
  vtkNew<vtkImageData> av;
  Capture(pass, f, av);
  Check(!EqualsRaw(av), "second frame accumulates");

  pass->ReleaseGraphicsResources(f.Window);
  f.Window->Render();
  if (Capture(pass, f, av))
  {
    Check(AllFinite(av), "after ReleaseGraphicsResources: finite");
    Check(EqualsRaw(av), "after ReleaseGraphicsResources: history reset");
  }
  f.Window->Render();
  Capture(pass, f, av);
  Check(!EqualsRaw(av), "accumulates again");

  f.Renderer->SetPass(nullptr);
  f.Window->Render();
  f.Renderer->SetPass(pass);
  f.Window->Render();
  Capture(pass, f, av);
  Check(EqualsRaw(av), "after a render without the pass: history reset");

  f.Window->SetSize(w + 10, h);
  f.Window->Render();
  Capture(pass, f, av);
  Check(EqualsRaw(av), "after a resize: history reset");
  f.Window->Render();
  Capture(pass, f, av);
  Check(!EqualsRaw(av) && AllFinite(av), "accumulates after the resize");
  Finish(pass, f);
}
}

int TestDeepAmbientObscuranceTemporal(int, char*[])
{
  TestOffIsIdentical();
  TestConvergence();
  TestMovingCamera();
  TestResets();
  return ExitStatus();
}
