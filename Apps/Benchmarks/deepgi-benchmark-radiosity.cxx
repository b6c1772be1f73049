// deepgi-benchmark-radiosity: time and error of the deep screen-space
// radiosity (vtkDeepRadiosityPass) against the ray-traced one-bounce
// irradiance (vtkDeepGIReferenceIrradiance), side by side in one run.
//
// Methods: one-layer and two-layer G-buffer, each of Table 2's presets
// (HIGH_PERFORMANCE, BALANCED, HIGH_QUALITY), with and without eq. 5's n_Y
// test (12 settings by default). Every method computes the single bounce:
// Damping 0 (the bounce input is the direct light only) and TemporalAlpha 0
// (no history), so one still frame is the estimate the pass makes every
// frame, and the reference's one-bounce E is the exact quantity it
// estimates. (A converged temporal filter would average rotated spirals:
// a different, less noisy estimator that the single frame bounds; the
// single frame is what a moving camera sees.)
//
// - accuracy (at --accuracy-size, default 200x150): a still frame; the
//   G-buffer capture of that frame (two layers) goes to the reference
//   (VTK's lights of the scene, plus the emitting surfaces the scene
//   polydata marks with "Emission"), layer 0, with MaximumDistance = the pass's effective radius r
//   (the gather's own limit) and unlimited. The pass's "Irradiance_0" (E after the bilateral
//   filter; alpha 0) is compared with the reference's "IndirectIrradiance" on the luminance of E
//   (0.2126, 0.7152, 0.0722) over the valid pixels of layer 0 and over those where layer 1 exists:
//   RMSE, MAE, bias (mean signed error), relative error (sum |error| / sum E_ref). Also: the
//   estimator normalised by N instead of M (E M / N, from the same capture: "Irradiance_0" x
//   "Confidence_0" after the filter, and "RawIrradiance_0" x "RawConfidence_0" before it), and the
//   mean |error| in the lowest and highest quartiles of the confidence.
// - time (at --size, default 320x240): median over the frames of every
//   round after warm-up; each method's frames back to back, all methods
//   in each round; every frame timed from Render() to WaitForCompletion().
// - multiple bounces (--bounces N, default 4; 0 skips it): two layers,
//   SOLID_ANGLE, BALANCED, the default guard band, TemporalAlpha 0, still
//   camera: the pass with Damping 1 and 0.5 after BounceFrames frames (the
//   converged sum of the damped bounces, section 3.3) against the reference
//   with NumberOfBounces N and BounceDamping equal to the Damping, limited to
//   r on every segment and unlimited; the same method's first frame with
//   Damping 0 against the one-bounce reference for comparison.
//
// Outputs in --output DIR: benchmark-radiosity.md, benchmark-radiosity.csv,
// benchmark-radiosity-plot.png (RMSE against time, one curve per method
// family, mean over the scenes), benchmark-radiosity-plot-SCENE.png and
// errors/SCENE-METHOD.png (|E - E_ref| on the luminance).

#include "DeepGIBenchmarkCommon.h"
#include "DeepGIOutput.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkDeepGBufferPass.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIDemoScene.h"
#include "vtkDeepGIReferenceIrradiance.h"
#include "vtkDeepGISceneLoader.h"
#include "vtkDeepRadiosityPass.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkXMLPolyDataWriter.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

// The project's test data folder (Testing/Data), set by CMake.
#ifndef DEEPGI_DATA_DIR
#error "DEEPGI_DATA_DIR must name the project's Testing/Data folder"
#endif

namespace
{
using namespace DeepGIBenchmark;
const char* const Program = "deepgi-benchmark-radiosity";
const char* const SceneNames[] = { "demo", "cornell-lucy", "cornell-original", "dragon" };

// Still frames of the multi-bounce measurement: frame t adds bounce t, so
// after 20 frames the remaining terms are (delta rho K)^20, far below the
// reference's noise for any albedo below 1 (the change between the last two
// frames is printed).
constexpr int BounceFrames = 20;

// layers (1 or 2) : preset (hp, balanced, hq) [: nt (no n_Y test)] [: n | sa
// (estimator)] [: gb (guard band)]
const char* const DefaultMethods = "1:hp,1:hp:nt,1:balanced,1:balanced:nt,1:hq,1:hq:nt,"
                                   "2:hp,2:hp:nt,2:balanced,2:balanced:nt,2:hq,2:hq:nt,"
                                   "2:hp:n,2:balanced:n,2:hq:n,2:hp:sa,2:balanced:sa,2:hq:sa,"
                                   "2:hp:sa:gb,2:balanced:sa:gb,2:hq:sa:gb";

// Width of the frame's border, as a fraction of the height, on which the
// guard band's effect is measured separately.
constexpr double BorderFraction = 0.1;

void Usage()
{
  std::printf(
    "Usage: deepgi-benchmark-radiosity [options]\n"
    "Time and error of vtkDeepRadiosityPass (single bounce) against the ray-traced\n"
    "one-bounce irradiance of vtkDeepGIReferenceIrradiance, measured in one run.\n"
    "  --size WxH           timing size in pixels (default 320x240)\n"
    "  --accuracy-size WxH  size of the error measurement (default 200x150)\n"
    "  --frames N           timed frames per method and round (default 5)\n"
    "  --rounds N           rounds over all methods (default 2)\n"
    "  --samples N          reference rays per pixel (default 64)\n"
    "  --radius-fraction F  gather radius r = F x scene diagonal, every method\n"
    "                       (default: vtkDeepRadiosityPass's own)\n"
    "  --scenes LIST        comma list of demo, cornell-lucy, cornell-original,\n"
    "                       dragon (default all four)\n"
    "  --methods LIST       comma list of L:P[:nt][:E][:gb][:o][:m]: L layers (1 or 2), P the\n"
    "                       preset (hp, balanced, hq), nt: the n_Y test off (else on),\n"
    "                       E the estimator: n (ALL_TAPS) or sa (SOLID_ANGLE); without\n"
    "                       it ACCEPTED_TAPS (eq. 4); gb: a G-buffer guard band of\n"
    "                       vtkDeepRadiosityPass::DEFAULT_GUARD_BAND (else none);\n"
    "                       o: the pass's default OuterSamples (else 0, the paper's\n"
    "                       gather, which reaches r; with them it reaches\n"
    "                       OUTER_RADIUS_SCALE r, beyond the limited reference);\n"
    "                       m: the preset's MinimumMipLevel (else Table 2's, 3, 2\n"
    "                       and 0; BALANCED's own is 1).\n"
    "                       Default: %s\n"
    "  --data DIR           test data folder (default %s)\n"
    "  --bounces N          multi-bounce comparison against the reference with N\n"
    "                       bounces, 1..16 (default 4; 0 skips it)\n"
    "  --no-error-maps      do not write the error-map PNGs\n"
    "  --backend NAME       auto, x11 or egl (default auto)\n"
    "  --output DIR         output directory (default output)\n"
    "  --help               this text\n",
    DefaultMethods, DEEPGI_DATA_DIR);
}

struct Method
{
  std::string Name;
  std::string Family; // curve of the plot: layers and n_Y test
  int Layers = 2;
  int Preset = vtkDeepRadiosityPass::BALANCED;
  bool NormalTest = true;
  int Estimator = vtkDeepRadiosityPass::ACCEPTED_TAPS;
  bool GuardBand = false;
  bool OuterRing = false; // the pass's default OuterSamples, else 0
  bool PresetMip = false; // the preset's MinimumMipLevel, else Table 2's
};

// Table 2's minimum MIP level per preset; BALANCED's own is 1.
constexpr int Table2MinimumMipLevel[] = { 3, 2, 0 };

bool ParseMethod(const std::string& spec, Method& m)
{
  const std::vector<std::string> p = Split(spec, ':');
  if (p.size() < 2 || p.size() > 7 || (p[0] != "1" && p[0] != "2"))
  {
    return false;
  }
  m.NormalTest = true;
  m.Estimator = vtkDeepRadiosityPass::ACCEPTED_TAPS;
  m.GuardBand = false;
  m.OuterRing = false;
  m.PresetMip = false;
  for (size_t k = 2; k < p.size(); ++k)
  {
    if (p[k] == "gb")
    {
      m.GuardBand = true;
    }
    else if (p[k] == "o")
    {
      m.OuterRing = true;
    }
    else if (p[k] == "m")
    {
      m.PresetMip = true;
    }
    else if (p[k] == "nt")
    {
      m.NormalTest = false;
    }
    else if (p[k] == "n")
    {
      m.Estimator = vtkDeepRadiosityPass::ALL_TAPS;
    }
    else if (p[k] == "sa")
    {
      m.Estimator = vtkDeepRadiosityPass::SOLID_ANGLE;
    }
    else
    {
      return false;
    }
  }
  const char* const presets[] = { "hp", "balanced", "hq" };
  const auto it = std::find(std::begin(presets), std::end(presets), p[1]);
  if (it == std::end(presets))
  {
    return false;
  }
  m.Layers = p[0] == "1" ? 1 : 2;
  m.Preset = static_cast<int>(it - std::begin(presets));
  const char* const estimators[] = { "", ", /N", ", solid angle" };
  const std::string label = std::string(m.Layers == 1 ? "1 layer" : "2 layers") +
    (m.NormalTest ? "" : ", no n_Y test") + estimators[m.Estimator] +
    (m.GuardBand ? ", guard band" : "") + (m.OuterRing ? ", outer ring" : "") +
    (m.PresetMip ? ", preset's minimum MIP level" : "");
  m.Name = label + ", " + vtkDeepRadiosityPass::GetPresetAsString(m.Preset);
  m.Family = label;
  return true;
}

struct Options : AccuracyOptions
{
  // RadiusFraction: > 0: every pass's AutomaticRadiusFraction; 0 (the
  // default): the pass's own.
  Options()
    : AccuracyOptions({ 320, 240 }, { 200, 150 }, 5, 2, 64,
        std::vector<std::string>(std::begin(SceneNames), std::end(SceneNames)), DefaultMethods)
  {
    this->Data = DEEPGI_DATA_DIR;
  }
  int Bounces = 4;
  std::vector<Method> Methods;
};

bool ParseOptions(int argc, char* argv[], Options& o)
{
  const CommandLine commandLine{ Program, Usage,
    std::vector<std::string>(std::begin(SceneNames), std::end(SceneNames)), { "--bounces" },
    [&o](const std::string&, const std::string& value, std::string& error)
    {
      if (!ParseInt(value, o.Bounces) || o.Bounces < 0 || o.Bounces > 16)
      {
        error = "--bounces needs an integer 0..16, got '" + value + "'";
        return false;
      }
      return true;
    } };
  return ParseAccuracyOptions(argc, argv, commandLine, o) &&
    ParseMethodList(Program, o.MethodList, ParseMethod,
      "L:P[:nt][:n|sa][:gb], L 1 or 2, P hp, balanced or hq", o.Methods);
}

/// Luminance of the RGB array `name` of `image` per pixel (0 if absent).
std::vector<float> Luminance(vtkImageData* image, const char* name)
{
  const vtkIdType n = static_cast<vtkIdType>(image->GetDimensions()[0]) * image->GetDimensions()[1];
  std::vector<float> lum(n, 0.0f);
  vtkDataArray* a = image->GetPointData()->GetArray(name);
  for (vtkIdType i = 0; a && i < n; ++i)
  {
    lum[i] = static_cast<float>(0.2126 * a->GetComponent(i, 0) + 0.7152 * a->GetComponent(i, 1) +
      0.0722 * a->GetComponent(i, 2));
  }
  return lum;
}

std::vector<float> Scalar(vtkImageData* image, const char* name)
{
  const vtkIdType n = static_cast<vtkIdType>(image->GetDimensions()[0]) * image->GetDimensions()[1];
  std::vector<float> v(n, 0.0f);
  vtkDataArray* a = image->GetPointData()->GetArray(name);
  for (vtkIdType i = 0; a && i < n; ++i)
  {
    v[i] = static_cast<float>(a->GetComponent(i, 0));
  }
  return v;
}

struct Stats
{
  double Rmse = 0, Mae = 0, Bias = 0, Relative = 0;
  long Pixels = 0;
};

Stats Errors(const std::vector<float>& e, const std::vector<float>& ref,
  const std::vector<unsigned char>& mask)
{
  Stats s;
  double s2 = 0, sref = 0;
  for (size_t i = 0; i < e.size(); ++i)
  {
    if (!mask[i])
    {
      continue;
    }
    const double d = static_cast<double>(e[i]) - ref[i];
    s2 += d * d;
    s.Mae += std::fabs(d);
    s.Bias += d;
    sref += ref[i];
    ++s.Pixels;
  }
  if (s.Pixels)
  {
    s.Relative = sref > 0 ? s.Mae / sref : 0.0;
    s.Rmse = std::sqrt(s2 / s.Pixels);
    s.Mae /= s.Pixels;
    s.Bias /= s.Pixels;
  }
  return s;
}

/// Mean |e - ref| over the masked pixels whose confidence lies in the
/// lowest and in the highest quartile of the masked confidences.
std::pair<double, double> ErrorByConfidence(const std::vector<float>& e,
  const std::vector<float>& ref, const std::vector<float>& confidence,
  const std::vector<unsigned char>& mask)
{
  std::vector<float> c;
  for (size_t i = 0; i < e.size(); ++i)
  {
    if (mask[i])
    {
      c.push_back(confidence[i]);
    }
  }
  if (c.size() < 8)
  {
    return { 0.0, 0.0 };
  }
  std::sort(c.begin(), c.end());
  const float q1 = c[c.size() / 4], q3 = c[(3 * c.size()) / 4];
  double lo = 0, hi = 0;
  long nlo = 0, nhi = 0;
  for (size_t i = 0; i < e.size(); ++i)
  {
    if (!mask[i])
    {
      continue;
    }
    const double d = std::fabs(static_cast<double>(e[i]) - ref[i]);
    if (confidence[i] <= q1)
    {
      lo += d;
      ++nlo;
    }
    if (confidence[i] >= q3)
    {
      hi += d;
      ++nhi;
    }
  }
  return { nlo ? lo / nlo : 0.0, nhi ? hi / nhi : 0.0 };
}

/// Writes an axis-aligned rectangle (corner, two edges) as a .vtp file;
/// false with `error` set when it cannot.
bool WriteRectangle(const std::string& file, const double o[3], const double p1[3],
  const double p2[3], std::string& error)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(o[0], o[1], o[2]);
  plane->SetPoint1(p1[0], p1[1], p1[2]);
  plane->SetPoint2(p2[0], p2[1], p2[2]);
  plane->SetResolution(8, 8);
  return DeepGIOutput::WriteAtomically(
    file,
    [&plane](const std::string& temporary)
    {
      vtkNew<vtkXMLPolyDataWriter> writer;
      writer->SetInputConnection(plane->GetOutputPort());
      writer->SetFileName(temporary.c_str());
      return writer->Write() == 1 && writer->GetErrorCode() == 0;
    },
    error);
}

/// Populates `renderer` with `name` (the scenes' own colours, lights and
/// camera). Returns the scene's triangles for the reference.
vtkSmartPointer<vtkPolyData> LoadScene(const Options& o, const std::string& name,
  vtkRenderer* renderer, vtkSmartPointer<vtkObject>& keep)
{
  if (name == "demo")
  {
    auto demo = vtkSmartPointer<vtkDeepGIDemoScene>::New();
    demo->SetTargetNumberOfTriangles(100000);
    demo->Populate(renderer);
    demo->SetCameraToDefaultView(renderer->GetActiveCamera());
    keep = demo;
    renderer->ResetCameraClippingRange();
    return demo->GetScenePolyData();
  }
  auto loader = vtkSmartPointer<vtkDeepGISceneLoader>::New();
  bool ok = false;
  if (name == "cornell-lucy")
  {
    ok = loader->Load((o.Data + "/scenes/cornell-lucy/CornellBox-Lucy.obj").c_str());
  }
  else if (name == "cornell-original")
  {
    ok = loader->Load((o.Data + "/scenes/cornell-original/CornellBox-Original.obj").c_str());
  }
  else
  {
    // The dragon alone bounces little light onto itself: it stands on a
    // white floor in front of a red wall (both 8 x 8 quads) so that the
    // floor and the wall exchange light with it and with each other.
    ok = loader->Load((o.Data + "/meshes/dragon.ply").c_str());
    if (ok)
    {
      double b[6];
      loader->GetBounds(b);
      const double sx = b[1] - b[0], sz = b[5] - b[4];
      const double m = 0.6 * std::max(sx, sz);
      const double cx = 0.5 * (b[0] + b[1]), cz = 0.5 * (b[4] + b[5]);
      const double f0[3] = { cx - m, b[2], cz + m }, f1[3] = { cx + m, b[2], cz + m },
                   f2[3] = { cx - m, b[2], cz - m };
      const double wz = b[4] - 0.15 * sz;
      const double w0[3] = { cx - m, b[2], wz }, w1[3] = { cx + m, b[2], wz },
                   w2[3] = { cx - m, b[2] + 1.2 * (b[3] - b[2]), wz };
      const std::string floorFile = o.Output + "/dragon-floor.vtp";
      const std::string wallFile = o.Output + "/dragon-wall.vtp";
      std::string error;
      if (!WriteRectangle(floorFile, f0, f1, f2, error) ||
        !WriteRectangle(wallFile, w0, w1, w2, error))
      {
        std::fprintf(stderr, "%s: %s\n", Program, error.c_str());
        return nullptr;
      }
      loader->SetDefaultColor(0.9, 0.9, 0.9);
      ok = loader->LoadMesh(floorFile.c_str());
      loader->SetDefaultColor(0.9, 0.15, 0.1);
      ok = ok && loader->LoadMesh(wallFile.c_str());
      // Seen from the front and above, the wall behind.
      loader->SetViewDirection(0.3, -0.45, -1.0);
    }
  }
  if (!ok)
  {
    std::fprintf(
      stderr, "%s: cannot load scene %s from %s\n", Program, name.c_str(), o.Data.c_str());
    return nullptr;
  }
  loader->Populate(renderer);
  loader->ResetCamera(renderer);
  keep = loader;
  return loader->GetScenePolyData();
}

struct Result
{
  std::string Scene;
  Method M;
  double FrameMs = 0;
  double Radius = 0;
  Stats Limited, Unlimited, Layer1, RawM, RawN, FilteredN;
  double LowConfidenceError = 0, HighConfidenceError = 0;
  Stats Border, BorderUnlimited; // the pixels within BorderFraction of the frame's edge
};

/// The multi-bounce measurement of one scene and damping.
struct BounceResult
{
  std::string Scene;
  double Damping = 0;
  double Change = 0;     // RMS change of E between the last two frames / mean E
  int UnchangedFrom = 0; // first frame equal to the one before (0: none)
  double MeanPass = 0, MeanReference = 0, MeanReferenceUnlimited = 0;
  Stats Limited, Unlimited, OneBounce;
  double ReferenceError = 0, ReferenceSeconds = 0;
};

struct SceneInfo
{
  std::string Name;
  vtkIdType Triangles;
  double Radius, MeanReference, MeanReferenceUnlimited, ReferenceError, ReferenceSeconds;
  double GBuffer1Ms, GBuffer2Ms;
  long Valid, Layer1;
};

/// Everything measured, in the order of the scenes.
struct Measurements
{
  std::vector<Result> Results;
  std::vector<BounceResult> Bounces;
  std::vector<SceneInfo> Scenes;
};

/// One G-buffer per layer count, shared by the methods that use it, and
/// a two-layer one with the default guard band for the "gb" methods.
struct GBuffers
{
  GBuffers()
  {
    this->OneLayer->SetNumberOfLayers(1);
    this->TwoLayers->SetNumberOfLayers(2);
    this->TwoLayersGuarded->SetNumberOfLayers(2);
    this->TwoLayersGuarded->SetGuardBand(vtkDeepRadiosityPass::DEFAULT_GUARD_BAND);
  }
  vtkNew<vtkDeepGBufferPass> OneLayer, TwoLayers, TwoLayersGuarded;
};

/// The still frame at the accuracy size that every method is measured on,
/// and the ray-traced one-bounce irradiance of its layer 0.
struct AccuracyFrame
{
  std::string Scene;
  int Width = 0, Height = 0;
  vtkSmartPointer<vtkImageData> Capture = vtkSmartPointer<vtkImageData>::New(); // two layers
  std::vector<unsigned char> Valid;                                             // layer 0 valid
  std::vector<unsigned char> Layer1; // valid, and layer 1 exists
  std::vector<unsigned char> Border; // valid, within BorderFraction of the frame's edge
  long ValidCount = 0, Layer1Count = 0;
  double Radius = 0.0;                              // the passes' effective gather radius r
  std::vector<float> Reference, ReferenceUnlimited; // luminance of E_ref,r and of E_ref
  double MeanReference = 0.0, MeanReferenceUnlimited = 0.0;
  double ReferenceError = 0.0, ReferenceSeconds = 0.0;
};

/// Mean of `values` over the pixels of `mask` (`count` of them).
double MaskedMean(
  const std::vector<float>& values, const std::vector<unsigned char>& mask, long count)
{
  double sum = 0;
  for (size_t i = 0; i < values.size(); ++i)
  {
    sum += mask[i] ? values[i] : 0.0;
  }
  return sum / std::max(1L, count);
}

/// Every method's pass, in the order of the methods.
std::vector<vtkSmartPointer<vtkDeepRadiosityPass>> MakePasses(const Options& o, GBuffers& gbuffers)
{
  std::vector<vtkSmartPointer<vtkDeepRadiosityPass>> passes;
  for (const Method& m : o.Methods)
  {
    auto pass = vtkSmartPointer<vtkDeepRadiosityPass>::New();
    pass->SetGBufferPass(m.Layers == 1 ? gbuffers.OneLayer.GetPointer()
        : m.GuardBand                  ? gbuffers.TwoLayersGuarded.GetPointer()
                                       : gbuffers.TwoLayers.GetPointer());
    pass->SetPreset(m.Preset);
    // Table 2's configurations as the paper runs them: every texel
    // gathers (HIGH_PERFORMANCE's reduced grid is measured by
    // deepgi_benchmark_frame.py and the image benchmark), at Table 2's
    // minimum MIP level unless `m` asks for the preset's.
    pass->SetResolutionDivisor(1);
    if (!m.PresetMip)
    {
      pass->SetMinimumMipLevel(Table2MinimumMipLevel[m.Preset]);
    }
    pass->SetUseNormalTest(m.NormalTest);
    if (!m.OuterRing)
    {
      pass->SetOuterSamples(0);
    }
    pass->SetEstimator(m.Estimator);
    pass->SetDamping(0.0);
    pass->SetTemporalAlpha(0.0);
    if (o.RadiusFraction > 0.0)
    {
      pass->SetAutomaticRadiusFraction(o.RadiusFraction);
    }
    passes.push_back(pass);
  }
  return passes;
}

/// The two-layer G-buffer's capture of a still frame and its pixel masks.
bool CaptureAccuracyFrame(const View& view, vtkDeepGBufferPass* gbuffer, AccuracyFrame& frame)
{
  view.Renderer->SetPass(gbuffer);
  view.Window->Render();
  if (!gbuffer->CaptureLayers(frame.Capture, view.Renderer))
  {
    return Report(Program, "the G-buffer capture failed on " + frame.Scene);
  }
  const int w = frame.Width, h = frame.Height;
  const size_t np = static_cast<size_t>(w) * h;
  const std::vector<float> valid0 =
    Scalar(frame.Capture, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 0).c_str());
  const std::vector<float> valid1 =
    Scalar(frame.Capture, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 1).c_str());
  frame.Valid.assign(np, 0);
  frame.Layer1.assign(np, 0);
  frame.Border.assign(np, 0);
  const int borderWidth = static_cast<int>(std::lround(BorderFraction * h));
  for (size_t i = 0; i < np; ++i)
  {
    const int x = static_cast<int>(i % w), y = static_cast<int>(i / w);
    frame.Valid[i] = valid0[i] > 0;
    frame.Layer1[i] = frame.Valid[i] && valid1[i] > 0;
    frame.Border[i] = frame.Valid[i] &&
      (x < borderWidth || y < borderWidth || x >= w - borderWidth || y >= h - borderWidth);
    frame.ValidCount += frame.Valid[i];
    frame.Layer1Count += frame.Layer1[i];
  }
  return true;
}

/// Every method's still frame (the radius is the same automatic r).
bool CaptureStillFrames(const View& view,
  const std::vector<vtkSmartPointer<vtkDeepRadiosityPass>>& passes, const std::string& scene,
  std::vector<vtkSmartPointer<vtkImageData>>& captures)
{
  for (const auto& pass : passes)
  {
    view.Renderer->SetPass(pass);
    view.Window->Render();
    auto c = vtkSmartPointer<vtkImageData>::New();
    if (!pass->CaptureIrradiance(c, view.Renderer))
    {
      return Report(Program, "the radiosity capture failed on " + scene);
    }
    captures.push_back(c);
  }
  return true;
}

/// The luminance of the reference's indirect irradiance with
/// MaximumDistance r (`limited`, its mean standard error in
/// `limitedError`) and unlimited, on the frame's capture.
bool ComputeLimitedAndUnlimited(vtkDeepGIReferenceIrradiance* reference, const AccuracyFrame& frame,
  std::vector<float>& limited, std::vector<float>& unlimited, double& limitedError)
{
  reference->SetInputData(frame.Capture);
  reference->SetMaximumDistance(frame.Radius);
  reference->Update();
  if (reference->GetOutput()->GetNumberOfPoints() == 0)
  {
    return Report(Program, "the reference failed on " + frame.Scene);
  }
  limited = Luminance(reference->GetOutput(), "IndirectIrradiance");
  limitedError = reference->GetMeanStandardError();
  reference->SetMaximumDistance(VTK_DOUBLE_MAX);
  reference->Update();
  if (reference->GetOutput()->GetNumberOfPoints() == 0)
  {
    return Report(Program, "the reference failed on " + frame.Scene);
  }
  unlimited = Luminance(reference->GetOutput(), "IndirectIrradiance");
  return true;
}

/// The one-bounce reference of the frame, limited to r and unlimited.
bool ComputeReference(const Options& o, vtkPolyData* geometry, vtkRenderer* renderer,
  vtkDeepGIReferenceIrradiance* reference, AccuracyFrame& frame)
{
  // The loaders' scene polydata carry the cell arrays the reference reads:
  // "Colors" and "Diffuse", and for emitters (cornell-original's lamp)
  // "Emission", the colour the lamp is drawn with, so the reference sees
  // the same sources as the pass's B(Y) = Radiance - Ambient.
  reference->SetSceneData(geometry);
  reference->SetEmissionArrayName("Emission");
  reference->SetLightsFromRenderer(renderer);
  reference->SetSamplesPerPixel(o.Samples);
  reference->SetLayer(0);
  const auto start = std::chrono::steady_clock::now();
  if (!ComputeLimitedAndUnlimited(
        reference, frame, frame.Reference, frame.ReferenceUnlimited, frame.ReferenceError))
  {
    return false;
  }
  frame.ReferenceSeconds = SecondsSince(start);
  frame.MeanReference = MaskedMean(frame.Reference, frame.Valid, frame.ValidCount);
  frame.MeanReferenceUnlimited =
    MaskedMean(frame.ReferenceUnlimited, frame.Valid, frame.ValidCount);
  return true;
}

/// Method `m`'s errors from its still frame's capture `c`: E (layer 0,
/// after the filter) against both references, on all valid pixels, on
/// layer 1's and on the border's; eq. 4 against dividing by N; error by
/// confidence. The error map of E - E_ref,r into `error`.
Result MeasureMethod(
  const Method& m, vtkImageData* c, const AccuracyFrame& frame, std::vector<float>& error)
{
  const std::vector<float>& ref = frame.Reference;
  const std::vector<float> e =
    Luminance(c, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Irradiance, 0).c_str());
  const std::vector<float> conf =
    Scalar(c, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Confidence, 0).c_str());
  const std::vector<float> raw =
    Luminance(c, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::RawIrradiance, 0).c_str());
  const std::vector<float> rawConf =
    Scalar(c, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::RawConfidence, 0).c_str());
  const size_t np = e.size();
  std::vector<float> eN(np), rawN(np);
  error.resize(np);
  for (size_t i = 0; i < np; ++i)
  {
    eN[i] = e[i] * conf[i];
    rawN[i] = raw[i] * rawConf[i];
    error[i] = e[i] - ref[i];
  }
  Result res;
  res.Scene = frame.Scene;
  res.M = m;
  res.Radius = frame.Radius;
  res.Limited = Errors(e, ref, frame.Valid);
  res.Unlimited = Errors(e, frame.ReferenceUnlimited, frame.Valid);
  res.Layer1 = Errors(e, ref, frame.Layer1);
  res.Border = Errors(e, ref, frame.Border);
  res.BorderUnlimited = Errors(e, frame.ReferenceUnlimited, frame.Border);
  res.RawM = Errors(raw, ref, frame.Valid);
  res.RawN = Errors(rawN, ref, frame.Valid);
  res.FilteredN = Errors(eN, ref, frame.Valid);
  const auto byConfidence = ErrorByConfidence(e, ref, conf, frame.Valid);
  res.LowConfidenceError = byConfidence.first;
  res.HighConfidenceError = byConfidence.second;
  return res;
}

/// Every method's accuracy (into `results`), with its error map.
bool MeasureAccuracy(const Options& o, const std::vector<vtkSmartPointer<vtkImageData>>& captures,
  const AccuracyFrame& frame, std::vector<Result>& results)
{
  for (size_t k = 0; k < o.Methods.size(); ++k)
  {
    std::vector<float> error;
    results.push_back(MeasureMethod(o.Methods[k], captures[k], frame, error));
    std::string message;
    if (o.ErrorMaps &&
      !WriteErrorMap(ErrorMapFile(o.Output, frame.Scene, o.Methods[k].Name), frame.Width,
        frame.Height, error, frame.Valid, 2.0 * std::max(1e-6, frame.MeanReference), message))
    {
      return Report(Program, message);
    }
  }
  return true;
}

/// The last of a series of still frames of one pass.
struct StillSeries
{
  std::vector<float> Last; // luminance of E in the last frame
  double Change = 0;       // RMS change of E from the frame before, over the mean E
  int UnchangedFrom = 0;   // the first frame that did not change E at all (0: none)
};

/// `frames` still frames of a fresh two-layer SOLID_ANGLE BALANCED pass on
/// `gbuffer` (the one with the guard band) with Damping `delta`.
bool RenderStillSeries(const Options& o, const View& view, vtkDeepGBufferPass* gbuffer,
  const AccuracyFrame& frame, double delta, int frames, StillSeries& series)
{
  vtkNew<vtkDeepRadiosityPass> pass;
  pass->SetGBufferPass(gbuffer);
  pass->SetPreset(vtkDeepRadiosityPass::BALANCED);
  pass->SetEstimator(vtkDeepRadiosityPass::SOLID_ANGLE);
  pass->SetUseNormalTest(true);
  pass->SetDamping(delta);
  pass->SetTemporalAlpha(0.0);
  if (o.RadiusFraction > 0.0)
  {
    pass->SetAutomaticRadiusFraction(o.RadiusFraction);
  }
  view.Renderer->SetPass(pass);
  bool ok = true;
  std::vector<float> before;
  const long valid = std::max(1L, frame.ValidCount);
  for (int f = 1; f <= frames && ok; ++f)
  {
    view.Window->Render();
    vtkNew<vtkImageData> c;
    ok = pass->CaptureIrradiance(c, view.Renderer);
    before.swap(series.Last);
    series.Last =
      Luminance(c, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Irradiance, 0).c_str());
    if (f > 1)
    {
      double d2 = 0, sum = 0;
      for (size_t i = 0; i < series.Last.size(); ++i)
      {
        const float d = series.Last[i] - before[i];
        d2 += frame.Valid[i] ? d * d : 0.0;
        sum += frame.Valid[i] ? series.Last[i] : 0.0;
      }
      series.Change = std::sqrt(d2 / valid) / std::max(1e-12, sum / valid);
      series.UnchangedFrom = d2 == 0.0 && series.UnchangedFrom == 0 ? f : series.UnchangedFrom;
    }
  }
  view.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(view.Window);
  return ok || Report(Program, "the radiosity capture failed on " + frame.Scene);
}

/// The converged damped bounces (Damping 1 and 0.5) against the reference
/// with NumberOfBounces = --bounces, and the first frame with Damping 0
/// against the one-bounce reference.
bool MeasureBounces(const Options& o, const View& view, vtkDeepGBufferPass* gbuffer,
  vtkDeepGIReferenceIrradiance* reference, const AccuracyFrame& frame,
  std::vector<BounceResult>& bounces)
{
  StillSeries single;
  if (!RenderStillSeries(o, view, gbuffer, frame, 0.0, 1, single))
  {
    return false;
  }
  const Stats oneBounce = Errors(single.Last, frame.Reference, frame.Valid);
  for (double delta : { 1.0, 0.5 })
  {
    BounceResult b;
    b.Scene = frame.Scene;
    b.Damping = delta;
    b.OneBounce = oneBounce;
    StillSeries series;
    if (!RenderStillSeries(o, view, gbuffer, frame, delta, BounceFrames, series))
    {
      return false;
    }
    b.Change = series.Change;
    b.UnchangedFrom = series.UnchangedFrom;
    b.MeanPass = MaskedMean(series.Last, frame.Valid, frame.ValidCount);
    const auto start = std::chrono::steady_clock::now();
    reference->SetNumberOfBounces(o.Bounces);
    reference->SetBounceDamping(delta);
    std::vector<float> refN, refNAll;
    if (!ComputeLimitedAndUnlimited(reference, frame, refN, refNAll, b.ReferenceError))
    {
      return false;
    }
    b.ReferenceSeconds = SecondsSince(start);
    b.MeanReference = MaskedMean(refN, frame.Valid, frame.ValidCount);
    b.MeanReferenceUnlimited = MaskedMean(refNAll, frame.Valid, frame.ValidCount);
    b.Limited = Errors(series.Last, refN, frame.Valid);
    b.Unlimited = Errors(series.Last, refNAll, frame.Valid);
    bounces.push_back(b);
  }
  reference->SetNumberOfBounces(1);
  reference->SetBounceDamping(1.0);
  return true;
}

/// Accuracy, multiple bounces, then time of every method on `sceneName`.
bool MeasureScene(const Options& o, const std::string& sceneName, Measurements& measured)
{
  View view;
  if (!OpenView(Program, o.Backend, o.AccuracyWidth, o.AccuracyHeight, view))
  {
    return false;
  }
  view.Renderer->SetBackground(0.0, 0.0, 0.0);
  vtkSmartPointer<vtkObject> keep;
  vtkSmartPointer<vtkPolyData> geometry = LoadScene(o, sceneName, view.Renderer, keep);
  if (!geometry)
  {
    return false;
  }
  GBuffers gbuffers;
  const std::vector<vtkSmartPointer<vtkDeepRadiosityPass>> passes = MakePasses(o, gbuffers);
  AccuracyFrame frame;
  frame.Scene = sceneName;
  frame.Width = o.AccuracyWidth;
  frame.Height = o.AccuracyHeight;
  std::vector<vtkSmartPointer<vtkImageData>> captures;
  if (!CaptureAccuracyFrame(view, gbuffers.TwoLayers, frame) ||
    !CaptureStillFrames(view, passes, sceneName, captures))
  {
    return false;
  }
  frame.Radius = passes.front()->GetEffectiveRadius();
  vtkNew<vtkDeepGIReferenceIrradiance> reference;
  std::vector<Result> results;
  if (!ComputeReference(o, geometry, view.Renderer, reference, frame) ||
    !MeasureAccuracy(o, captures, frame, results) ||
    (o.Bounces > 0 &&
      !MeasureBounces(o, view, gbuffers.TwoLayersGuarded, reference, frame, measured.Bounces)))
  {
    return false;
  }
  const std::vector<double> gbufferMs =
    TimeMethods(view, o, { gbuffers.OneLayer, gbuffers.TwoLayers }, passes, results);
  measured.Results.insert(measured.Results.end(), results.begin(), results.end());
  measured.Scenes.push_back({ sceneName, geometry->GetNumberOfPolys(), frame.Radius,
    frame.MeanReference, frame.MeanReferenceUnlimited, frame.ReferenceError, frame.ReferenceSeconds,
    gbufferMs[0], gbufferMs[1], frame.ValidCount, frame.Layer1Count });

  view.Renderer->SetPass(nullptr);
  for (const auto& pass : passes)
  {
    pass->ReleaseGraphicsResources(view.Window);
  }
  gbuffers.OneLayer->ReleaseGraphicsResources(view.Window);
  gbuffers.TwoLayers->ReleaseGraphicsResources(view.Window);
  gbuffers.TwoLayersGuarded->ReleaseGraphicsResources(view.Window);
  std::fprintf(stderr, "%s: scene %s done\n", Program, sceneName.c_str());
  return true;
}

/// The settings of the run and the table of the scenes.
std::string SceneTable(const Options& o, const Measurements& measured)
{
  std::ostringstream md;
  md << "Accuracy at " << o.AccuracyWidth << "x" << o.AccuracyHeight << ", time at " << o.Width
     << "x" << o.Height << " (median of " << o.Frames * o.Rounds << " frames per method, "
     << o.Rounds << " rounds, after " << o.Warmup
     << " warm-up frames per round). Single bounce: Damping 0, TemporalAlpha 0. Errors on the "
        "luminance of the irradiance E (layer 0, after the bilateral filter) against "
        "vtkDeepGIReferenceIrradiance ("
     << o.Samples
     << " rays per pixel) with MaximumDistance = r (E_ref,r) and unlimited (E_ref).\n\n";
  md << "| scene | triangles | r | valid px | layer-1 px | mean E_ref,r | mean E_ref | reference "
        "std. error | reference [s] | G-buffer 1 layer [ms] | G-buffer 2 layers [ms] |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const SceneInfo& s : measured.Scenes)
  {
    char b[512];
    std::snprintf(b, sizeof(b),
      "| %s | %lld | %.4g | %ld | %ld | %.4f | %.4f | %.4f | %.1f | %.2f | %.2f |\n",
      s.Name.c_str(), static_cast<long long>(s.Triangles), s.Radius, s.Valid, s.Layer1,
      s.MeanReference, s.MeanReferenceUnlimited, s.ReferenceError, s.ReferenceSeconds, s.GBuffer1Ms,
      s.GBuffer2Ms);
    md << b;
  }
  return md.str();
}

/// The table of every scene and method.
std::string ResultTable(const Measurements& measured)
{
  std::ostringstream md;
  md << "\n| scene | method | frame [ms] | RMSE vs E_ref,r | MAE | bias | rel. error | RMSE "
        "layer-1 px | RMSE vs E_ref | bias vs E_ref | rel. error vs E_ref |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Result& r : measured.Results)
  {
    char b[1024];
    std::snprintf(b, sizeof(b),
      "| %s | %s | %.2f | %.4f | %.4f | %+.4f | %.3f | %.4f | %.4f | %+.4f | %.3f |\n",
      r.Scene.c_str(), r.M.Name.c_str(), r.FrameMs, r.Limited.Rmse, r.Limited.Mae, r.Limited.Bias,
      r.Limited.Relative, r.Layer1.Rmse, r.Unlimited.Rmse, r.Unlimited.Bias, r.Unlimited.Relative);
    md << b;
  }
  return md.str();
}

/// The CSV file: a row per scene and method.
std::string Csv(const Measurements& measured)
{
  std::ostringstream csv;
  csv << "scene,method,family,layers,preset,normal_test,estimator,frame_ms,radius,rmse,mae,bias,"
         "relative,"
         "rmse_layer1,rmse_unlimited,mae_unlimited,bias_unlimited,relative_unlimited,"
         "rmse_raw_m,bias_raw_m,rmse_raw_n,bias_raw_n,rmse_filtered_n,bias_filtered_n,"
         "mae_low_confidence,mae_high_confidence,guard_band,rmse_border,bias_border,"
         "rmse_border_unlimited\n";
  for (const Result& r : measured.Results)
  {
    char b[1024];
    std::snprintf(b, sizeof(b),
      "\"%s\",\"%s\",\"%s\",%d,%d,%d,%d,%.4f,%.5g,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,"
      "%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%d,%.5f,%.5f,%.5f\n",
      r.Scene.c_str(), r.M.Name.c_str(), r.M.Family.c_str(), r.M.Layers, r.M.Preset,
      r.M.NormalTest ? 1 : 0, r.M.Estimator, r.FrameMs, r.Radius, r.Limited.Rmse, r.Limited.Mae,
      r.Limited.Bias, r.Limited.Relative, r.Layer1.Rmse, r.Unlimited.Rmse, r.Unlimited.Mae,
      r.Unlimited.Bias, r.Unlimited.Relative, r.RawM.Rmse, r.RawM.Bias, r.RawN.Rmse, r.RawN.Bias,
      r.FilteredN.Rmse, r.FilteredN.Bias, r.LowConfidenceError, r.HighConfidenceError,
      r.M.GuardBand ? 1 : 0, r.Border.Rmse, r.Border.Bias, r.BorderUnlimited.Rmse);
    csv << b;
  }
  return csv.str();
}

std::string EstimatorSection(const Measurements& measured)
{
  std::ostringstream md;
  md << "\n### Estimator: eq. 4 (divide by M) against dividing by N\n\n"
     << "Same frames; E_N = E_M x M / N (raw: this frame's gather before any filter; filtered: "
        "\"Irradiance_0\" x \"Confidence_0\"). Errors against E_ref,r.\n\n"
     << "| scene | method | RMSE raw /M | bias raw /M | RMSE raw /N | bias raw /N | RMSE "
        "filtered /M | RMSE filtered /N | bias filtered /N "
        "|\n|---|---|---|---|---|---|---|---|---|\n";
  for (const Result& r : measured.Results)
  {
    if (r.M.Estimator != vtkDeepRadiosityPass::ACCEPTED_TAPS)
    {
      continue; // E M / N is the ALL_TAPS estimate only when E is eq. 4's
    }
    char b[512];
    std::snprintf(b, sizeof(b), "| %s | %s | %.4f | %+.4f | %.4f | %+.4f | %.4f | %.4f | %+.4f |\n",
      r.Scene.c_str(), r.M.Name.c_str(), r.RawM.Rmse, r.RawM.Bias, r.RawN.Rmse, r.RawN.Bias,
      r.Limited.Rmse, r.FilteredN.Rmse, r.FilteredN.Bias);
    md << b;
  }
  return md.str();
}

std::string ConfidenceSection(const Measurements& measured)
{
  std::ostringstream md;
  md << "\n### Error against confidence\n\n"
     << "Mean |E - E_ref,r| over the valid pixels in the lowest and in the highest quartile of "
        "the filtered confidence M / N.\n\n"
     << "| scene | method | lowest quartile | highest quartile | ratio |\n|---|---|---|---|---|\n";
  for (const Result& r : measured.Results)
  {
    char b[512];
    std::snprintf(b, sizeof(b), "| %s | %s | %.4f | %.4f | %.2f |\n", r.Scene.c_str(),
      r.M.Name.c_str(), r.LowConfidenceError, r.HighConfidenceError,
      r.LowConfidenceError / std::max(1e-9, r.HighConfidenceError));
    md << b;
  }
  return md.str();
}

std::string GuardBandSection(const Measurements& measured)
{
  std::ostringstream md;
  md << "\n### Guard band\n\n"
     << "Two layers, SOLID_ANGLE, each preset, without and with a guard band of "
     << vtkDeepRadiosityPass::DEFAULT_GUARD_BAND
     << " of the height per side (shaded fraction from the preset). Border: the valid pixels "
        "within "
     << BorderFraction << " of the height of the frame's edge.\n\n"
     << "| scene | method | frame [ms] | RMSE vs E_ref,r | RMSE border | bias border | RMSE "
        "border vs E_ref | border px |\n|---|---|---|---|---|---|---|---|\n";
  for (const Result& r : measured.Results)
  {
    if (r.M.Layers != 2 || !r.M.NormalTest || r.M.Estimator != vtkDeepRadiosityPass::SOLID_ANGLE)
    {
      continue;
    }
    char b[512];
    std::snprintf(b, sizeof(b), "| %s | %s | %.2f | %.4f | %.4f | %+.4f | %.4f | %ld |\n",
      r.Scene.c_str(), r.M.Name.c_str(), r.FrameMs, r.Limited.Rmse, r.Border.Rmse, r.Border.Bias,
      r.BorderUnlimited.Rmse, r.Border.Pixels);
    md << b;
  }
  return md.str();
}

std::string BouncesSection(const Options& o, const Measurements& measured)
{
  if (measured.Bounces.empty())
  {
    return std::string();
  }
  std::ostringstream md;
  md << "\n### Multiple bounces\n\n"
     << "Two layers, SOLID_ANGLE, BALANCED, guard band " << vtkDeepRadiosityPass::DEFAULT_GUARD_BAND
     << ", TemporalAlpha 0, still camera: E of "
     << "the pass with Damping delta after " << BounceFrames
     << " frames against vtkDeepGIReferenceIrradiance with NumberOfBounces " << o.Bounces
     << " and BounceDamping delta (" << o.Samples
     << " paths per pixel), MaximumDistance r on every segment (E_ref,r) and unlimited "
        "(E_ref). change: RMS of the change of E between the last two frames over the mean "
        "E; fixed from: the first frame whose E equals the frame before's exactly. 1 bounce: "
        "the same method's first frame with Damping 0 against the one-bounce E_ref,r.\n\n"
     << "| scene | delta | change | fixed from | mean E | mean E_ref,r | mean E_ref | RMSE vs "
        "E_ref,r | bias | rel. error | RMSE vs E_ref | bias vs E_ref | rel. error vs E_ref | "
        "1 bounce: RMSE | bias | rel. error | reference std. error | reference [s] |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const BounceResult& b : measured.Bounces)
  {
    const std::string fixed = b.UnchangedFrom ? std::to_string(b.UnchangedFrom) : "-";
    char line[1024];
    std::snprintf(line, sizeof(line),
      "| %s | %.2g | %.1e | %s | %.4f | %.4f | %.4f | %.4f | %+.4f | %.3f | %.4f | %+.4f | "
      "%.3f | %.4f | %+.4f | %.3f | %.4f | %.1f |\n",
      b.Scene.c_str(), b.Damping, b.Change, fixed.c_str(), b.MeanPass, b.MeanReference,
      b.MeanReferenceUnlimited, b.Limited.Rmse, b.Limited.Bias, b.Limited.Relative,
      b.Unlimited.Rmse, b.Unlimited.Bias, b.Unlimited.Relative, b.OneBounce.Rmse, b.OneBounce.Bias,
      b.OneBounce.Relative, b.ReferenceError, b.ReferenceSeconds);
    md << line;
  }
  return md.str();
}

std::string TimeRatiosSection(const Measurements& measured)
{
  std::ostringstream md;
  md << "\n### Time ratios (same run)\n\n"
     << "| scene | method | frame / frame of 2 layers, BALANCED (eq. 4) |\n|---|---|---|\n";
  for (const Result& r : measured.Results)
  {
    double base = 0;
    for (const Result& b : measured.Results)
    {
      if (b.Scene == r.Scene && b.M.Layers == 2 && b.M.NormalTest &&
        b.M.Preset == vtkDeepRadiosityPass::BALANCED &&
        b.M.Estimator == vtkDeepRadiosityPass::ACCEPTED_TAPS)
      {
        base = b.FrameMs;
      }
    }
    md << "| " << r.Scene << " | " << r.M.Name << " | "
       << (base > 0 ? Fmt("%.2f", r.FrameMs / base) : std::string("n/a")) << " |\n";
  }
  return md.str();
}

/// The markdown file (also printed on stdout).
std::string Markdown(const Options& o, const Measurements& measured)
{
  return SceneTable(o, measured) + ResultTable(measured) + EstimatorSection(measured) +
    ConfidenceSection(measured) + GuardBandSection(measured) + BouncesSection(o, measured) +
    TimeRatiosSection(measured);
}

/// RMSE of E against E_ref,r against the frame time, one curve per method family.
ErrorTimePlots Plots(const Options& o, const Measurements& measured)
{
  return MakeErrorTimePlots(
    "Radiosity (single bounce): error vs time",
    "RMSE of E vs ray-traced reference (max. distance r)", o.Methods, measured.Scenes,
    measured.Results, [](const Method& m) { return m.Family; },
    [](const Result& r) { return r.Limited.Rmse; });
}
}

int main(int argc, char* argv[])
{
  const AccuracyBenchmark<Options, Measurements> stages{ Program, "benchmark-radiosity",
    ParseOptions, Usage, MeasureScene, Markdown, Csv, Plots };
  return RunAccuracyBenchmark(stages, argc, argv);
}
