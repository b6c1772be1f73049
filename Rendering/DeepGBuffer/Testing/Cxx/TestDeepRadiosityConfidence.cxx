// The confidence M / N of vtkDeepRadiosityPass (section 3.2) tells where
// the screen-space gather lacks information: against the ray-traced
// one-bounce irradiance of the whole scene (vtkDeepGIReferenceIrradiance,
// MaximumDistance unlimited), the relative error sum |E - E_ref| / sum E_ref
// of layer 0's pixels in the lowest quarter of the (filtered) confidence
// exceeds that of the highest quarter by at least MinimumRatio, on the demo
// scene and on the Cornell box (single bounce: Damping 0, TemporalAlpha 0,
// BALANCED; 160 x 120; reference with 32 rays per pixel, mean standard
// error 0.11 (demo) and 0.05 (Cornell) in irradiance units, which averages
// out over a quarter of the pixels).
//
// Measured with the default estimator SOLID_ANGLE and the pass's default
// guard band (relative error lowest / highest quarter): demo 0.958 / 0.574
// (1.67 x), Cornell box lit by its lamp (its spot light, and its emitting
// quad through the scene's "Emission" cell array) 0.976 / 0.755 (1.29 x).
// MinimumRatio 1.25 lies below the smaller. With eq. 4
// (ACCEPTED_TAPS) it is 0.94 / 0.42 (2.25 x) and 1.00 / 0.69 (1.45 x):
// SOLID_ANGLE is darker, so its high-confidence pixels are further below
// the full truth. Against the reference limited to the gather radius r,
// eq. 4 reverses the relation (the error grows with the confidence: 2.7 /
// 2.0 and 1.0 / 1.4), because it divides by M and so overestimates most
// where a few taps find a bright surface; see
// Documentation/benchmark-radiosity.md.
//
// The gather radius is 0.1 of the scene's diagonal (the paper's scale),
// where taps are rejected for their distance and the
// confidence says where light is missing. At the default 0.5 the demo
// keeps the relation (0.288 / 0.200, 1.44 x) but the Cornell box, whole
// within the radius, does not (0.456 / 0.517, 0.88 x).

#include "DeepGITestData.h"
#include "DeepRadiosityReferenceTest.h"

#include "vtkDeepGBufferPass.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepRadiosityPass.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <utility>

using namespace DeepRadiosityReferenceTest;
using namespace DeepGITest;

namespace
{
constexpr double MinimumRatio = 1.25;

// Relative error of the lowest and of the highest confidence quarter.
std::pair<double, double> Measure(const std::string& sceneName, const std::string& data)
{
  vtkNew<vtkDeepRadiosityPass> pass;
  pass->SetAutomaticRadiusFraction(0.1);
  SingleBounceCapture c;
  if (!CaptureSingleBounce(sceneName, data, pass, 160, 120, c))
  {
    return { 0.0, 0.0 };
  }
  const std::vector<double>& e = c.Irradiance;
  const std::vector<double>& ref = c.Reference;
  vtkDataArray* confidence = c.Radiosity->GetPointData()->GetArray(
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Confidence, 0).c_str());
  vtkDataArray* valid = c.Valid;
  // Valid pixels sorted by confidence, split into quarters of equal count.
  std::vector<std::pair<double, size_t>> sorted;
  for (size_t i = 0; i < e.size(); ++i)
  {
    if (valid->GetComponent(i, 0) > 0)
    {
      sorted.push_back({ confidence->GetComponent(i, 0), i });
    }
  }
  std::sort(sorted.begin(), sorted.end());
  const size_t quarter = sorted.size() / 4;
  auto relativeError = [&](size_t begin, size_t end)
  {
    double error = 0, total = 0;
    for (size_t k = begin; k < end; ++k)
    {
      const size_t i = sorted[k].second;
      error += std::fabs(e[i] - ref[i]);
      total += ref[i];
    }
    return total > 0 ? error / total : 0.0;
  };
  const double low = relativeError(0, quarter);
  const double high = relativeError(sorted.size() - quarter, sorted.size());
  std::printf("%s: %zu valid px, r %.4g; confidence of the lowest quarter %.3f..%.3f, of the "
              "highest %.3f..%.3f; relative error %.3f / %.3f (%.2f x); reference std. error "
              "%.4f\n",
    sceneName.c_str(), sorted.size(), pass->GetEffectiveRadius(), sorted.front().first,
    sorted[quarter - 1].first, sorted[sorted.size() - quarter].first, sorted.back().first, low,
    high, low / std::max(1e-12, high), c.StandardError);
  Check(sorted.size() > 5000, sceneName + ": enough valid pixels");
  return { low, high };
}
}

int TestDeepRadiosityConfidence(int argc, char* argv[])
{
  const std::string data = DeepGITestData::Folder(argc, argv, "TestDeepRadiosityConfidence");
  if (!DeepGITestData::Require(data,
        { "scenes/cornell-original/CornellBox-Original.obj",
          "scenes/cornell-original/CornellBox-Original.mtl" },
        "TestDeepRadiosityConfidence"))
  {
    return EXIT_FAILURE;
  }
  for (const char* scene : { "demo", "cornell-original" })
  {
    const std::pair<double, double> q = Measure(scene, data);
    Check(q.second > 0 && q.first > MinimumRatio * q.second,
      std::string(scene) + ": relative error of the lowest confidence quarter > " +
        std::to_string(MinimumRatio) + " x that of the highest");
  }
  return ExitStatus();
}
