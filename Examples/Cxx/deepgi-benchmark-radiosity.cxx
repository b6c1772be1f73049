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
#include "vtkDeepGBufferDemoScene.h"
#include "vtkDeepGBufferPass.h"
#include "vtkDeepGBufferSceneLoader.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIReferenceIrradiance.h"
#include "vtkDeepGIRenderWindowFactory.h"
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

struct Options
{
  int Width = 320;
  int Height = 240;
  int AccuracyWidth = 200;
  int AccuracyHeight = 150;
  int Frames = 5;
  int Rounds = 2;
  int Warmup = 2;
  int Samples = 64;
  int Backend = vtkDeepGIRenderWindowFactory::BACKEND_AUTO;
  std::string Output = "output";
  std::string Data = DEEPGI_DATA_DIR;
  std::vector<std::string> Scenes = { "demo", "cornell-lucy", "cornell-original", "dragon" };
  std::vector<std::string> Methods;
  bool ErrorMaps = true;
  int Bounces = 4;
  double RadiusFraction = 0.0; // > 0: every pass's AutomaticRadiusFraction; 0: the pass's default
};

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
  std::printf("Usage: deepgi-benchmark-radiosity [options]\n"
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
              "  --methods LIST       comma list of L:P[:nt][:E][:gb]: L layers (1 or 2), P the\n"
              "                       preset (hp, balanced, hq), nt: the n_Y test off (else on),\n"
              "                       E the estimator: n (ALL_TAPS) or sa (SOLID_ANGLE); without\n"
              "                       it ACCEPTED_TAPS (eq. 4); gb: a G-buffer guard band of\n"
              "                       vtkDeepRadiosityPass::DEFAULT_GUARD_BAND (else none).\n"
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
};

bool ParseMethod(const std::string& spec, Method& m)
{
  const std::vector<std::string> p = Split(spec, ':');
  if (p.size() < 2 || p.size() > 5 || (p[0] != "1" && p[0] != "2"))
  {
    return false;
  }
  m.NormalTest = true;
  m.Estimator = vtkDeepRadiosityPass::ACCEPTED_TAPS;
  m.GuardBand = false;
  for (size_t k = 2; k < p.size(); ++k)
  {
    if (p[k] == "gb")
    {
      m.GuardBand = true;
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
    (m.GuardBand ? ", guard band" : "");
  m.Name = label + ", " + vtkDeepRadiosityPass::GetPresetAsString(m.Preset);
  m.Family = label;
  return true;
}

bool ParseOptions(int argc, char* argv[], Options& o)
{
  std::string methods = DefaultMethods;
  auto bad = [](const std::string& what)
  {
    std::fprintf(stderr, "%s: %s\n", Program, what.c_str());
    return false;
  };
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h")
    {
      Usage();
      std::exit(0);
    }
    if (arg == "--no-error-maps")
    {
      o.ErrorMaps = false;
      continue;
    }
    static const char* const withValue[] = { "--size", "--accuracy-size", "--frames", "--rounds",
      "--samples", "--radius-fraction", "--scenes", "--methods", "--bounces", "--data", "--backend",
      "--output" };
    if (std::find_if(std::begin(withValue), std::end(withValue),
          [&](const char* s) { return arg == s; }) == std::end(withValue))
    {
      return bad("unknown option " + arg);
    }
    if (i + 1 >= argc)
    {
      return bad(arg + " needs a value");
    }
    const std::string value = argv[++i];
    if (arg == "--size" && !ParseSize(value, o.Width, o.Height))
    {
      return bad("--size needs WxH with 16..8192 pixels per side, got '" + value + "'");
    }
    if (arg == "--accuracy-size" && !ParseSize(value, o.AccuracyWidth, o.AccuracyHeight))
    {
      return bad("--accuracy-size needs WxH with 16..8192 pixels per side, got '" + value + "'");
    }
    if (arg == "--frames" && (!ParseInt(value, o.Frames) || o.Frames < 1 || o.Frames > 10000))
    {
      return bad("--frames needs an integer 1..10000, got '" + value + "'");
    }
    if (arg == "--rounds" && (!ParseInt(value, o.Rounds) || o.Rounds < 1 || o.Rounds > 100))
    {
      return bad("--rounds needs an integer 1..100, got '" + value + "'");
    }
    if (arg == "--samples" && (!ParseInt(value, o.Samples) || o.Samples < 1 || o.Samples > 1048576))
    {
      return bad("--samples needs an integer 1..1048576, got '" + value + "'");
    }
    if (arg == "--radius-fraction" && !ParseFraction(value, o.RadiusFraction))
    {
      return bad("--radius-fraction needs a number in (0, 1], got '" + value + "'");
    }
    if (arg == "--bounces" && (!ParseInt(value, o.Bounces) || o.Bounces < 0 || o.Bounces > 16))
    {
      return bad("--bounces needs an integer 0..16, got '" + value + "'");
    }
    if (arg == "--scenes")
    {
      o.Scenes = Split(value, ',');
      if (o.Scenes.empty())
      {
        return bad("--scenes needs at least one scene");
      }
      for (const std::string& s : o.Scenes)
      {
        if (std::find(std::begin(SceneNames), std::end(SceneNames), s) == std::end(SceneNames))
        {
          return bad("unknown scene '" + s + "' (demo, cornell-lucy, cornell-original, dragon)");
        }
      }
    }
    if (arg == "--methods")
    {
      methods = value;
    }
    std::string error;
    if (!ParseSharedOption(arg, value, o.Data, o.Backend, o.Output, error))
    {
      return bad(error);
    }
  }
  o.Methods = Split(methods, ',');
  if (o.Methods.empty())
  {
    return bad("--methods needs at least one method");
  }
  for (const std::string& m : o.Methods)
  {
    Method parsed;
    if (!ParseMethod(m, parsed))
    {
      return bad(
        "unknown method '" + m + "' (L:P[:nt][:n|sa][:gb], L 1 or 2, P hp, balanced or hq)");
    }
  }
  return true;
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
    auto demo = vtkSmartPointer<vtkDeepGBufferDemoScene>::New();
    demo->SetTargetNumberOfTriangles(100000);
    demo->Populate(renderer);
    demo->SetCameraToDefaultView(renderer->GetActiveCamera());
    keep = demo;
    renderer->ResetCameraClippingRange();
    return demo->GetScenePolyData();
  }
  auto loader = vtkSmartPointer<vtkDeepGBufferSceneLoader>::New();
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
}

int main(int argc, char* argv[])
{
  Options options;
  if (!ParseOptions(argc, argv, options))
  {
    Usage();
    return 2;
  }
  std::vector<Method> methods;
  for (const std::string& spec : options.Methods)
  {
    Method m;
    ParseMethod(spec, m);
    methods.push_back(m);
  }
  // The outputs are checked before the hours of measuring.
  std::string outputError;
  if (!DeepGIOutput::PrepareDirectory(options.Output, outputError) ||
    (options.ErrorMaps && !DeepGIOutput::PrepareDirectory(options.Output + "/errors", outputError)))
  {
    std::fprintf(stderr, "%s: %s\n", Program, outputError.c_str());
    return 1;
  }

  std::vector<Result> results;
  std::vector<SceneInfo> infos;
  std::vector<BounceResult> bounceResults;
  for (const std::string& sceneName : options.Scenes)
  {
    vtkSmartPointer<vtkRenderWindow> window = vtkSmartPointer<vtkRenderWindow>::Take(
      vtkDeepGIRenderWindowFactory::NewRenderWindow(options.Backend));
    if (!window)
    {
      std::fprintf(stderr, "%s: no render window for this backend\n", Program);
      return 1;
    }
    window->SetMultiSamples(0);
    window->SetOffScreenRendering(1);
    window->SetSize(options.AccuracyWidth, options.AccuracyHeight);
    vtkNew<vtkRenderer> renderer;
    renderer->SetBackground(0.0, 0.0, 0.0);
    window->AddRenderer(renderer);
    vtkSmartPointer<vtkObject> keep;
    vtkSmartPointer<vtkPolyData> geometry = LoadScene(options, sceneName, renderer, keep);
    if (!geometry)
    {
      return 1;
    }

    // One G-buffer per layer count, shared by the methods that use it, and
    // a two-layer one with the default guard band for the "gb" methods.
    vtkNew<vtkDeepGBufferPass> gbuffer1, gbuffer2, gbuffer2Guard;
    gbuffer1->SetNumberOfLayers(1);
    gbuffer2->SetNumberOfLayers(2);
    gbuffer2Guard->SetNumberOfLayers(2);
    gbuffer2Guard->SetGuardBand(vtkDeepRadiosityPass::DEFAULT_GUARD_BAND);
    std::vector<vtkSmartPointer<vtkDeepRadiosityPass>> passes;
    for (const Method& m : methods)
    {
      auto pass = vtkSmartPointer<vtkDeepRadiosityPass>::New();
      pass->SetGBufferPass(m.Layers == 1 ? gbuffer1.GetPointer()
          : m.GuardBand                  ? gbuffer2Guard.GetPointer()
                                         : gbuffer2.GetPointer());
      pass->SetPreset(m.Preset);
      // Table 2's configurations as the paper runs them: every texel
      // gathers (HIGH_PERFORMANCE's reduced grid is measured by
      // deepgi_benchmark_frame.py and the image benchmark).
      pass->SetResolutionDivisor(1);
      pass->SetUseNormalTest(m.NormalTest);
      pass->SetEstimator(m.Estimator);
      pass->SetDamping(0.0);
      pass->SetTemporalAlpha(0.0);
      if (options.RadiusFraction > 0.0)
      {
        pass->SetAutomaticRadiusFraction(options.RadiusFraction);
      }
      passes.push_back(pass);
    }

    // ---- accuracy ----
    renderer->SetPass(gbuffer2);
    window->Render();
    vtkNew<vtkImageData> capture;
    if (!gbuffer2->CaptureLayers(capture, renderer))
    {
      std::fprintf(stderr, "%s: the G-buffer capture failed on %s\n", Program, sceneName.c_str());
      return 1;
    }
    const int w = options.AccuracyWidth, h = options.AccuracyHeight;
    const size_t np = static_cast<size_t>(w) * h;
    const std::vector<float> valid0 =
      Scalar(capture, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 0).c_str());
    const std::vector<float> valid1 =
      Scalar(capture, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 1).c_str());
    std::vector<unsigned char> mask(np, 0), layer1(np, 0), border(np, 0);
    long nValid = 0, nLayer1 = 0;
    const int borderWidth = static_cast<int>(std::lround(BorderFraction * h));
    for (size_t i = 0; i < np; ++i)
    {
      const int x = static_cast<int>(i % w), y = static_cast<int>(i / w);
      mask[i] = valid0[i] > 0;
      layer1[i] = mask[i] && valid1[i] > 0;
      border[i] = mask[i] &&
        (x < borderWidth || y < borderWidth || x >= w - borderWidth || y >= h - borderWidth);
      nValid += mask[i];
      nLayer1 += layer1[i];
    }

    // Every method's still frame (the radius is the same automatic r).
    std::vector<vtkSmartPointer<vtkImageData>> captures;
    for (auto& pass : passes)
    {
      renderer->SetPass(pass);
      window->Render();
      auto c = vtkSmartPointer<vtkImageData>::New();
      if (!pass->CaptureIrradiance(c, renderer))
      {
        std::fprintf(
          stderr, "%s: the radiosity capture failed on %s\n", Program, sceneName.c_str());
        return 1;
      }
      captures.push_back(c);
    }
    const double r = passes.front()->GetEffectiveRadius();

    vtkNew<vtkDeepGIReferenceIrradiance> reference;
    // The loaders' scene polydata carry the cell arrays the reference reads:
    // "Colors" and "Diffuse", and for emitters (cornell-original's lamp)
    // "Emission", the colour the lamp is drawn with, so the reference sees
    // the same sources as the pass's B(Y) = Radiance - Ambient.
    reference->SetScene(geometry);
    reference->SetEmissionArrayName("Emission");
    reference->SetLightsFromRenderer(renderer);
    reference->SetSamplesPerPixel(options.Samples);
    reference->SetLayer(0);
    const auto refStart = std::chrono::steady_clock::now();
    reference->SetMaximumDistance(r);
    if (!reference->Compute(capture))
    {
      std::fprintf(stderr, "%s: the reference failed on %s\n", Program, sceneName.c_str());
      return 1;
    }
    const std::vector<float> ref = Luminance(reference->GetOutput(), "IndirectIrradiance");
    const double refError = reference->GetMeanStandardError();
    reference->SetMaximumDistance(VTK_DOUBLE_MAX);
    if (!reference->Compute(capture))
    {
      std::fprintf(stderr, "%s: the reference failed on %s\n", Program, sceneName.c_str());
      return 1;
    }
    const std::vector<float> refAll = Luminance(reference->GetOutput(), "IndirectIrradiance");
    const double refSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - refStart).count();
    double meanRef = 0, meanRefAll = 0;
    for (size_t i = 0; i < np; ++i)
    {
      meanRef += mask[i] ? ref[i] : 0.0;
      meanRefAll += mask[i] ? refAll[i] : 0.0;
    }
    meanRef /= std::max(1L, nValid);
    meanRefAll /= std::max(1L, nValid);

    std::vector<Result> sceneResults;
    for (size_t k = 0; k < methods.size(); ++k)
    {
      vtkImageData* c = captures[k];
      const std::vector<float> e =
        Luminance(c, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Irradiance, 0).c_str());
      const std::vector<float> conf =
        Scalar(c, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Confidence, 0).c_str());
      const std::vector<float> raw =
        Luminance(c, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::RawIrradiance, 0).c_str());
      const std::vector<float> rawConf =
        Scalar(c, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::RawConfidence, 0).c_str());
      std::vector<float> eN(np), rawN(np), error(np);
      for (size_t i = 0; i < np; ++i)
      {
        eN[i] = e[i] * conf[i];
        rawN[i] = raw[i] * rawConf[i];
        error[i] = e[i] - ref[i];
      }
      Result res;
      res.Scene = sceneName;
      res.M = methods[k];
      res.Radius = r;
      res.Limited = Errors(e, ref, mask);
      res.Unlimited = Errors(e, refAll, mask);
      res.Layer1 = Errors(e, ref, layer1);
      res.Border = Errors(e, ref, border);
      res.BorderUnlimited = Errors(e, refAll, border);
      res.RawM = Errors(raw, ref, mask);
      res.RawN = Errors(rawN, ref, mask);
      res.FilteredN = Errors(eN, ref, mask);
      const auto byConfidence = ErrorByConfidence(e, ref, conf, mask);
      res.LowConfidenceError = byConfidence.first;
      res.HighConfidenceError = byConfidence.second;
      if (options.ErrorMaps)
      {
        if (!WriteErrorMap(
              options.Output + "/errors/" + sceneName + "-" + FileTag(methods[k].Name) + ".png", w,
              h, error, mask, 2.0 * std::max(1e-6, meanRef), outputError))
        {
          std::fprintf(stderr, "%s: %s\n", Program, outputError.c_str());
          return 1;
        }
      }
      sceneResults.push_back(res);
    }

    // ---- multiple bounces ----
    if (options.Bounces > 0)
    {
      // `frames` still frames of a fresh two-layer SOLID_ANGLE BALANCED pass
      // with the guard band and Damping `delta`: the luminance of E in the
      // last frame, the RMS change of E from the frame before over the mean
      // E, and the first frame that did not change E at all (0: none).
      auto still = [&](double delta, int frames, std::vector<float>& last, double& change,
                     int& unchangedFrom) -> bool
      {
        vtkNew<vtkDeepRadiosityPass> pass;
        pass->SetGBufferPass(gbuffer2Guard);
        pass->SetPreset(vtkDeepRadiosityPass::BALANCED);
        pass->SetEstimator(vtkDeepRadiosityPass::SOLID_ANGLE);
        pass->SetUseNormalTest(true);
        pass->SetDamping(delta);
        pass->SetTemporalAlpha(0.0);
        if (options.RadiusFraction > 0.0)
        {
          pass->SetAutomaticRadiusFraction(options.RadiusFraction);
        }
        renderer->SetPass(pass);
        bool ok = true;
        change = 0;
        unchangedFrom = 0;
        std::vector<float> before;
        for (int f = 1; f <= frames && ok; ++f)
        {
          window->Render();
          vtkNew<vtkImageData> c;
          ok = pass->CaptureIrradiance(c, renderer);
          before.swap(last);
          last = Luminance(
            c, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Irradiance, 0).c_str());
          if (f > 1)
          {
            double d2 = 0, sum = 0;
            for (size_t i = 0; i < np; ++i)
            {
              d2 += mask[i] ? (last[i] - before[i]) * (last[i] - before[i]) : 0.0;
              sum += mask[i] ? last[i] : 0.0;
            }
            change =
              std::sqrt(d2 / std::max(1L, nValid)) / std::max(1e-12, sum / std::max(1L, nValid));
            unchangedFrom = d2 == 0.0 && unchangedFrom == 0 ? f : unchangedFrom;
          }
        }
        renderer->SetPass(nullptr);
        pass->ReleaseGraphicsResources(window);
        if (!ok)
        {
          std::fprintf(
            stderr, "%s: the radiosity capture failed on %s\n", Program, sceneName.c_str());
        }
        return ok;
      };
      std::vector<float> single;
      double unusedChange;
      int unusedFrame;
      if (!still(0.0, 1, single, unusedChange, unusedFrame))
      {
        return 1;
      }
      const Stats oneBounce = Errors(single, ref, mask);
      for (double delta : { 1.0, 0.5 })
      {
        BounceResult b;
        b.Scene = sceneName;
        b.Damping = delta;
        b.OneBounce = oneBounce;
        std::vector<float> e;
        if (!still(delta, BounceFrames, e, b.Change, b.UnchangedFrom))
        {
          return 1;
        }
        for (size_t i = 0; i < np; ++i)
        {
          b.MeanPass += mask[i] ? e[i] : 0.0;
        }
        b.MeanPass /= std::max(1L, nValid);
        const auto start = std::chrono::steady_clock::now();
        reference->SetNumberOfBounces(options.Bounces);
        reference->SetBounceDamping(delta);
        reference->SetMaximumDistance(r);
        if (!reference->Compute(capture))
        {
          std::fprintf(stderr, "%s: the reference failed on %s\n", Program, sceneName.c_str());
          return 1;
        }
        const std::vector<float> refN = Luminance(reference->GetOutput(), "IndirectIrradiance");
        b.ReferenceError = reference->GetMeanStandardError();
        reference->SetMaximumDistance(VTK_DOUBLE_MAX);
        if (!reference->Compute(capture))
        {
          std::fprintf(stderr, "%s: the reference failed on %s\n", Program, sceneName.c_str());
          return 1;
        }
        const std::vector<float> refNAll = Luminance(reference->GetOutput(), "IndirectIrradiance");
        b.ReferenceSeconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        for (size_t i = 0; i < np; ++i)
        {
          b.MeanReference += mask[i] ? refN[i] : 0.0;
          b.MeanReferenceUnlimited += mask[i] ? refNAll[i] : 0.0;
        }
        b.MeanReference /= std::max(1L, nValid);
        b.MeanReferenceUnlimited /= std::max(1L, nValid);
        b.Limited = Errors(e, refN, mask);
        b.Unlimited = Errors(e, refNAll, mask);
        bounceResults.push_back(b);
      }
      reference->SetNumberOfBounces(1);
      reference->SetBounceDamping(1.0);
    }

    // ---- time ----
    window->SetSize(options.Width, options.Height);
    std::vector<std::vector<double>> ms(methods.size() + 2);
    for (int round = 0; round < options.Rounds; ++round)
    {
      for (size_t k = 0; k < methods.size() + 2; ++k)
      {
        vtkRenderPass* pass = nullptr;
        if (k < 2)
        {
          pass = k == 0 ? gbuffer1.GetPointer() : gbuffer2.GetPointer();
        }
        else
        {
          pass = passes[k - 2];
        }
        renderer->SetPass(pass);
        const std::vector<double> t = TimeFrames(
          [&]()
          {
            window->Render();
            window->WaitForCompletion();
          },
          options.Warmup, options.Frames);
        ms[k].insert(ms[k].end(), t.begin(), t.end());
      }
    }
    for (size_t k = 0; k < methods.size(); ++k)
    {
      sceneResults[k].FrameMs = Median(ms[k + 2]);
      results.push_back(sceneResults[k]);
    }
    infos.push_back({ sceneName, geometry->GetNumberOfPolys(), r, meanRef, meanRefAll, refError,
      refSeconds, Median(ms[0]), Median(ms[1]), nValid, nLayer1 });
    renderer->SetPass(nullptr);
    for (auto& p : passes)
    {
      p->ReleaseGraphicsResources(window);
    }
    gbuffer1->ReleaseGraphicsResources(window);
    gbuffer2->ReleaseGraphicsResources(window);
    gbuffer2Guard->ReleaseGraphicsResources(window);
    std::fprintf(stderr, "%s: scene %s done\n", Program, sceneName.c_str());
  }

  // ---- tables ----
  std::ostringstream md, csv;
  md << "Accuracy at " << options.AccuracyWidth << "x" << options.AccuracyHeight << ", time at "
     << options.Width << "x" << options.Height << " (median of " << options.Frames * options.Rounds
     << " frames per method, " << options.Rounds << " rounds, after " << options.Warmup
     << " warm-up frames per round). Single bounce: Damping 0, TemporalAlpha 0. Errors on the "
        "luminance of the irradiance E (layer 0, after the bilateral filter) against "
        "vtkDeepGIReferenceIrradiance ("
     << options.Samples
     << " rays per pixel) with MaximumDistance = r (E_ref,r) and unlimited (E_ref).\n\n";
  md << "| scene | triangles | r | valid px | layer-1 px | mean E_ref,r | mean E_ref | reference "
        "std. error | reference [s] | G-buffer 1 layer [ms] | G-buffer 2 layers [ms] |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const SceneInfo& s : infos)
  {
    char b[512];
    std::snprintf(b, sizeof(b),
      "| %s | %lld | %.4g | %ld | %ld | %.4f | %.4f | %.4f | %.1f | %.2f | %.2f |\n",
      s.Name.c_str(), static_cast<long long>(s.Triangles), s.Radius, s.Valid, s.Layer1,
      s.MeanReference, s.MeanReferenceUnlimited, s.ReferenceError, s.ReferenceSeconds, s.GBuffer1Ms,
      s.GBuffer2Ms);
    md << b;
  }
  md << "\n| scene | method | frame [ms] | RMSE vs E_ref,r | MAE | bias | rel. error | RMSE "
        "layer-1 px | RMSE vs E_ref | bias vs E_ref | rel. error vs E_ref |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|\n";
  csv << "scene,method,family,layers,preset,normal_test,estimator,frame_ms,radius,rmse,mae,bias,"
         "relative,"
         "rmse_layer1,rmse_unlimited,mae_unlimited,bias_unlimited,relative_unlimited,"
         "rmse_raw_m,bias_raw_m,rmse_raw_n,bias_raw_n,rmse_filtered_n,bias_filtered_n,"
         "mae_low_confidence,mae_high_confidence,guard_band,rmse_border,bias_border,"
         "rmse_border_unlimited\n";
  for (const Result& r : results)
  {
    char b[1024];
    std::snprintf(b, sizeof(b),
      "| %s | %s | %.2f | %.4f | %.4f | %+.4f | %.3f | %.4f | %.4f | %+.4f | %.3f |\n",
      r.Scene.c_str(), r.M.Name.c_str(), r.FrameMs, r.Limited.Rmse, r.Limited.Mae, r.Limited.Bias,
      r.Limited.Relative, r.Layer1.Rmse, r.Unlimited.Rmse, r.Unlimited.Bias, r.Unlimited.Relative);
    md << b;
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

  md << "\n### Estimator: eq. 4 (divide by M) against dividing by N\n\n"
     << "Same frames; E_N = E_M x M / N (raw: this frame's gather before any filter; filtered: "
        "\"Irradiance_0\" x \"Confidence_0\"). Errors against E_ref,r.\n\n"
     << "| scene | method | RMSE raw /M | bias raw /M | RMSE raw /N | bias raw /N | RMSE "
        "filtered /M | RMSE filtered /N | bias filtered /N "
        "|\n|---|---|---|---|---|---|---|---|---|\n";
  for (const Result& r : results)
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

  md << "\n### Error against confidence\n\n"
     << "Mean |E - E_ref,r| over the valid pixels in the lowest and in the highest quartile of "
        "the filtered confidence M / N.\n\n"
     << "| scene | method | lowest quartile | highest quartile | ratio |\n|---|---|---|---|---|\n";
  for (const Result& r : results)
  {
    char b[512];
    std::snprintf(b, sizeof(b), "| %s | %s | %.4f | %.4f | %.2f |\n", r.Scene.c_str(),
      r.M.Name.c_str(), r.LowConfidenceError, r.HighConfidenceError,
      r.LowConfidenceError / std::max(1e-9, r.HighConfidenceError));
    md << b;
  }

  md << "\n### Guard band\n\n"
     << "Two layers, SOLID_ANGLE, each preset, without and with a guard band of "
     << vtkDeepRadiosityPass::DEFAULT_GUARD_BAND
     << " of the height per side (shaded fraction from the preset). Border: the valid pixels "
        "within "
     << BorderFraction << " of the height of the frame's edge.\n\n"
     << "| scene | method | frame [ms] | RMSE vs E_ref,r | RMSE border | bias border | RMSE "
        "border vs E_ref | border px |\n|---|---|---|---|---|---|---|---|\n";
  for (const Result& r : results)
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

  if (!bounceResults.empty())
  {
    md << "\n### Multiple bounces\n\n"
       << "Two layers, SOLID_ANGLE, BALANCED, guard band "
       << vtkDeepRadiosityPass::DEFAULT_GUARD_BAND << ", TemporalAlpha 0, still camera: E of "
       << "the pass with Damping delta after " << BounceFrames
       << " frames against vtkDeepGIReferenceIrradiance with NumberOfBounces " << options.Bounces
       << " and BounceDamping delta (" << options.Samples
       << " paths per pixel), MaximumDistance r on every segment (E_ref,r) and unlimited "
          "(E_ref). change: RMS of the change of E between the last two frames over the mean "
          "E; fixed from: the first frame whose E equals the frame before's exactly. 1 bounce: "
          "the same method's first frame with Damping 0 against the one-bounce E_ref,r.\n\n"
       << "| scene | delta | change | fixed from | mean E | mean E_ref,r | mean E_ref | RMSE vs "
          "E_ref,r | bias | rel. error | RMSE vs E_ref | bias vs E_ref | rel. error vs E_ref | "
          "1 bounce: RMSE | bias | rel. error | reference std. error | reference [s] |\n"
          "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const BounceResult& b : bounceResults)
    {
      const std::string fixed = b.UnchangedFrom ? std::to_string(b.UnchangedFrom) : "-";
      char line[1024];
      std::snprintf(line, sizeof(line),
        "| %s | %.2g | %.1e | %s | %.4f | %.4f | %.4f | %.4f | %+.4f | %.3f | %.4f | %+.4f | "
        "%.3f | %.4f | %+.4f | %.3f | %.4f | %.1f |\n",
        b.Scene.c_str(), b.Damping, b.Change, fixed.c_str(), b.MeanPass, b.MeanReference,
        b.MeanReferenceUnlimited, b.Limited.Rmse, b.Limited.Bias, b.Limited.Relative,
        b.Unlimited.Rmse, b.Unlimited.Bias, b.Unlimited.Relative, b.OneBounce.Rmse,
        b.OneBounce.Bias, b.OneBounce.Relative, b.ReferenceError, b.ReferenceSeconds);
      md << line;
    }
  }

  md << "\n### Time ratios (same run)\n\n"
     << "| scene | method | frame / frame of 2 layers, BALANCED (eq. 4) |\n|---|---|---|\n";
  for (const Result& r : results)
  {
    double base = 0;
    for (const Result& b : results)
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

  std::fputs(md.str().c_str(), stdout);
  if (!DeepGIOutput::WriteText(options.Output + "/benchmark-radiosity.md", md.str(), outputError) ||
    !DeepGIOutput::WriteText(options.Output + "/benchmark-radiosity.csv", csv.str(), outputError))
  {
    std::fprintf(stderr, "%s: %s\n", Program, outputError.c_str());
    return 1;
  }

  // ---- plots ----
  std::vector<std::string> families;
  for (const Method& m : methods)
  {
    if (std::find(families.begin(), families.end(), m.Family) == families.end())
    {
      families.push_back(m.Family);
    }
  }
  const std::string xTitle = "frame time [ms] (median)";
  const std::string yTitle = "RMSE of E vs ray-traced reference (max. distance r)";
  Curves mean;
  for (const Method& m : methods)
  {
    double t = 0, e = 0;
    int n = 0;
    for (const Result& r : results)
    {
      if (r.M.Name == m.Name)
      {
        t += r.FrameMs;
        e += r.Limited.Rmse;
        ++n;
      }
    }
    if (n)
    {
      mean[m.Family].push_back({ t / n, e / n });
    }
  }
  if (!WritePlot(options.Output + "/benchmark-radiosity-plot.png",
        "Radiosity (single bounce): error vs time (mean over scenes)", xTitle, yTitle, families,
        mean, options.Backend, outputError))
  {
    std::fprintf(stderr, "%s: %s\n", Program, outputError.c_str());
    return 1;
  }
  for (const SceneInfo& s : infos)
  {
    Curves curves;
    for (const Result& r : results)
    {
      if (r.Scene == s.Name)
      {
        curves[r.M.Family].push_back({ r.FrameMs, r.Limited.Rmse });
      }
    }
    if (!WritePlot(options.Output + "/benchmark-radiosity-plot-" + s.Name + ".png",
          "Radiosity (single bounce): error vs time, " + s.Name, xTitle, yTitle, families, curves,
          options.Backend, outputError))
    {
      std::fprintf(stderr, "%s: %s\n", Program, outputError.c_str());
      return 1;
    }
  }
  std::printf("\nwrote %s/benchmark-radiosity.{md,csv}, %s/benchmark-radiosity-plot.png\n",
    options.Output.c_str(), options.Output.c_str());
  return 0;
}
