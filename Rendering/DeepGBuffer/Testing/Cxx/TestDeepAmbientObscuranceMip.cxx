// The camera-space distance MIP pyramid of vtkDeepAmbientObscurancePass
// (rotated-grid downsampling, SAO / Mara et al. 2016 section 3.4):
// - at an odd size (101 x 77, so the clamp at the right and top edges is
//   exercised) with two layers, every texel of every level m of every layer
//   equals exactly the level-0 texel that m steps of
//   (x, y) -> (2x + (y & 1), 2y + (x & 1)) (each clamped to the finer
//   level's size) select, level 0 equals the G-buffer's distance, and the
//   number of levels is min(MaximumMipLevel, floor(log2(max(w, h)))) + 1;
// - MaximumMipLevel = 0 builds level 0 only (only level 0 can be captured,
//   level 1 is refused) and the raw AV is finite;
// - on the floor/wall corner at 240 x 200 (r = 1, N = 16, q = 8, L = 5)
//   the filtered AV with the pyramid stays close to the AV read from level 0
//   only: mean |difference| <= 0.005 and 99th percentile <= 0.03 over the
//   valid pixels (taps move by up to 2^m - 1 < h_i / q pixels);
// - prints the frame-time ratio pyramid / level 0 on a larger radius (not
//   asserted: timings depend on the machine).

#include "DeepGBufferTestUtilities.h"

#include "vtkCamera.h"
#include "vtkDeepAmbientObscurancePass.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkFieldData.h"
#include "vtkPolyDataMapper.h"

#include <algorithm>
#include <chrono>
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

Frame Render(vtkDeepAmbientObscurancePass* pass, int width, int height, int frames = 3)
{
  Frame f;
  f.Window = MakeWindow(width, height);
  f.Renderer = vtkSmartPointer<vtkRenderer>::New();
  f.Window->AddRenderer(f.Renderer);
  AddCornerScene(f.Renderer, true);
  f.Renderer->ResetCameraClippingRange();
  f.Renderer->SetPass(pass);
  for (int i = 0; i < frames; ++i)
  {
    f.Window->Render();
  }
  return f;
}

void TestPyramidContents()
{
  const int w = 101, h = 77;
  vtkNew<vtkDeepAmbientObscurancePass> pass;
  pass->SetRadius(1.0);
  Frame f = Render(pass, w, h);
  vtkNew<vtkImageData> layers;
  Check(pass->GetGBufferPass()->CaptureLayers(layers, f.Renderer), "capture layers");
  const int layerCount = static_cast<int>(
    layers->GetFieldData()->GetArray(vtkDeepGICaptureNames::NumberOfLayers)->GetTuple1(0));
  vtkNew<vtkImageData> level0;
  if (!pass->CaptureDistancePyramid(0, level0, f.Renderer))
  {
    Check(false, "capture level 0");
    return;
  }
  const int levels = static_cast<int>(
    level0->GetFieldData()->GetArray(vtkDeepGICaptureNames::NumberOfMipLevels)->GetTuple1(0));
  std::printf("pyramid: %d x %d, %d layers, %d levels\n", w, h, layerCount, levels);
  Check(levels == 6, "levels = min(5, floor(log2(101))) + 1 = 6");
  Check(layerCount >= 2, "two layers");
  long compared = 0, mismatched = 0, nonEmpty = 0;
  for (int j = 0; j < layerCount; ++j)
  {
    vtkDataArray* reference = Layer(layers, vtkDeepGICaptureNames::Depth, j);
    for (int m = 0; m < levels; ++m)
    {
      vtkNew<vtkImageData> level;
      if (!pass->CaptureDistancePyramid(m, level, f.Renderer))
      {
        Check(false, "capture a level");
        continue;
      }
      int dims[3];
      level->GetDimensions(dims);
      Check(dims[0] == std::max(1, w >> m) && dims[1] == std::max(1, h >> m), "level size");
      vtkDataArray* values = Layer(level, vtkDeepGICaptureNames::Distance, j);
      if (!values)
      {
        Check(false, "level has the layer");
        continue;
      }
      for (int y = 0; y < dims[1]; ++y)
      {
        for (int x = 0; x < dims[0]; ++x)
        {
          int sx = x, sy = y;
          for (int k = m; k > 0; --k)
          {
            const int nx = std::min(2 * sx + (sy & 1), std::max(1, w >> (k - 1)) - 1);
            const int ny = std::min(2 * sy + (sx & 1), std::max(1, h >> (k - 1)) - 1);
            sx = nx;
            sy = ny;
          }
          const double expected = reference->GetTuple1(static_cast<vtkIdType>(sy) * w + sx);
          const double actual = values->GetTuple1(static_cast<vtkIdType>(y) * dims[0] + x);
          ++compared;
          nonEmpty += expected > 0.0 ? 1 : 0;
          mismatched += expected == actual ? 0 : 1;
        }
      }
    }
  }
  std::printf("pyramid: %ld texels compared (%ld non-empty), %ld differ from the rotated-grid "
              "level-0 texel\n",
    compared, nonEmpty, mismatched);
  Check(compared > 0 && nonEmpty > compared / 2 && mismatched == 0,
    "every level holds the rotated grid's level-0 texel");
  vtkNew<vtkImageData> beyond;
  pass->GlobalWarningDisplayOff();
  Check(!pass->CaptureDistancePyramid(levels, beyond, f.Renderer), "no level past the last");
  pass->GlobalWarningDisplayOn();
  pass->ReleaseGraphicsResources(f.Window);
}

// Filtered AV of the corner scene with the given MaximumMipLevel.
std::vector<float> CornerAV(int maximumMipLevel, std::vector<unsigned char>& valid)
{
  vtkNew<vtkDeepAmbientObscurancePass> pass;
  pass->SetRadius(1.0);
  pass->SetMaximumMipLevel(maximumMipLevel);
  Frame f = Render(pass, 240, 200);
  vtkNew<vtkImageData> ao;
  std::vector<float> out;
  if (!pass->CaptureAmbientVisibility(ao, f.Renderer))
  {
    Check(false, "capture AV");
    return out;
  }
  Check(AllFinite(ao), "AV finite");
  vtkDataArray* av = ao->GetPointData()->GetArray(vtkDeepGICaptureNames::AmbientVisibility);
  vtkDataArray* v = ao->GetPointData()->GetArray(vtkDeepGICaptureNames::Valid);
  valid.resize(av->GetNumberOfTuples());
  for (vtkIdType p = 0; p < av->GetNumberOfTuples(); ++p)
  {
    out.push_back(static_cast<float>(av->GetTuple1(p)));
    valid[p] = static_cast<unsigned char>(v->GetTuple1(p));
  }
  if (maximumMipLevel == 0)
  {
    vtkNew<vtkImageData> level;
    Check(pass->CaptureDistancePyramid(0, level, f.Renderer), "level 0 without a pyramid");
    pass->GlobalWarningDisplayOff();
    Check(!pass->CaptureDistancePyramid(1, level, f.Renderer), "no level 1 without a pyramid");
    pass->GlobalWarningDisplayOn();
  }
  pass->ReleaseGraphicsResources(f.Window);
  return out;
}

void TestCloseToLevelZero()
{
  std::vector<unsigned char> valid, valid0;
  const std::vector<float> mip = CornerAV(5, valid);
  const std::vector<float> flat = CornerAV(0, valid0);
  if (mip.empty() || mip.size() != flat.size())
  {
    Check(false, "two AV images");
    return;
  }
  std::vector<double> differences;
  double sum = 0.0;
  for (size_t p = 0; p < mip.size(); ++p)
  {
    if (valid[p])
    {
      const double d = std::abs(mip[p] - flat[p]);
      differences.push_back(d);
      sum += d;
    }
  }
  std::sort(differences.begin(), differences.end());
  const double mean = sum / std::max<size_t>(1, differences.size());
  const double p99 = differences.empty() ? 1.0 : differences[differences.size() * 99 / 100];
  std::printf("pyramid vs level 0 (corner, filtered AV, %zu px): mean %.4f, 99th percentile "
              "%.4f, max %.4f\n",
    differences.size(), mean, p99, differences.empty() ? 0.0 : differences.back());
  Check(mean <= 0.005, "mean |AV(pyramid) - AV(level 0)| <= 0.005");
  Check(p99 <= 0.03, "99th percentile <= 0.03");
}

void Time()
{
  double seconds[2] = { 0.0, 0.0 };
  const int levels[2] = { 0, 5 };
  for (int k = 0; k < 2; ++k)
  {
    vtkNew<vtkDeepAmbientObscurancePass> pass;
    pass->SetRadius(2.0);
    pass->SetNumberOfSamples(32);
    pass->SetMaximumMipLevel(levels[k]);
    Frame f = Render(pass, 512, 512, 1);
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < 3; ++i)
    {
      f.Window->Render();
    }
    seconds[k] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / 3;
    pass->ReleaseGraphicsResources(f.Window);
  }
  std::printf("timing (512 x 512, r = 2, N = 32, not asserted): level 0 only %.1f ms, pyramid "
              "%.1f ms per frame, ratio %.2f\n",
    1e3 * seconds[0], 1e3 * seconds[1], seconds[1] / std::max(seconds[0], 1e-9));
}
}

int TestDeepAmbientObscuranceMip(int, char*[])
{
  TestPyramidContents();
  TestCloseToLevelZero();
  Time();
  return ExitStatus();
}
