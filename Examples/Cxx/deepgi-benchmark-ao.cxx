// deepgi-benchmark-ao: time and error of ambient obscurance methods, side by
// side in one run.
//
// For each scene (the demo scene from its default view and from its
// "columns" view, cornell-lucy, dragon.ply and an iso-surface of headsq) and
// each method (VTK's vtkSSAOPass at several
// kernel sizes, vtkDeepAmbientObscurancePass with one and with two layers
// at several N, and named settings (N, BlurRadius)):
//
// - accuracy (at --accuracy-size, default 320x240): the same still camera
//   is rendered with the method and without it (plain VTK for vtkSSAOPass,
//   the G-buffer pass alone for ours). Every surface is white and
//   ambient-only (Ambient 1, Diffuse 0, Specular 0), so the plain image is
//   white and the luminance ratio (method / plain, clamped to [0, 1]) is the
//   method's ambient visibility AV on that pixel. The ground truth is
//   vtkDeepGIReferenceObscurance (Embree) on the G-buffer capture of the
//   same frame (layer 0), same r, beta = eps = 0 (the obscurance itself,
//   not the screen-space estimators' regularised form). Errors: RMSE and mean absolute error over
//   valid pixels (layer 0 valid, both plain luminances > 0.05), RMSE on the
//   pixels where layer 1 exists (Valid_1), raw and after fitting one
//   exponent gamma per method and scene (AV^gamma vs reference).
// - time (at --size, default 640x480): median over the frames of every
//   round after warm-up; each method's frames back to back, all methods
//   in each round; every frame timed from Render() to WaitForCompletion().
//
// Outputs in --output DIR: benchmark-ao.md, benchmark-ao.csv,
// benchmark-ao-plot.png (RMSE against time, one curve per method family,
// averaged over the scenes), benchmark-ao-plot-SCENE.png and
// errors/SCENE-METHOD.png (|AV - AV_ref|, colour map 0..0.5).

#include "DeepGIBenchmarkCommon.h"
#include "DeepGIOutput.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkDeepAmbientObscurancePass.h"
#include "vtkDeepGBufferDemoScene.h"
#include "vtkDeepGBufferPass.h"
#include "vtkDeepGBufferSceneLoader.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIReferenceObscurance.h"
#include "vtkDeepGIRenderWindowFactory.h"
#include "vtkDeepRadiosityPass.h"
#include "vtkImageData.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSSAOPass.h"
#include "vtkSmartPointer.h"
#include "vtkWindowToImageFilter.h"
#include <vtksys/SystemTools.hxx>

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
const char* const Program = "deepgi-benchmark-ao";

struct Options
{
  int Width = 640;
  int Height = 480;
  int AccuracyWidth = 320;
  int AccuracyHeight = 240;
  int Frames = 7;
  int Rounds = 2;
  int Warmup = 3;
  int Samples = 256;
  double RadiusFraction = 0.05;
  int Backend = vtkDeepGIRenderWindowFactory::BACKEND_AUTO;
  std::string Output = "output";
  std::string Data = DEEPGI_DATA_DIR;
  // The user's own scenes ("mesh:PATH" or "volume:ISO:PATH"), measured after
  // the built-in ones named with --scenes (none unless --scenes is given).
  std::vector<std::string> Files;
  bool ScenesGiven = false;
  std::string PendingVolume; // a --volume waiting for its --iso
  std::vector<std::string> Scenes = { "demo", "demo-columns", "cornell-lucy", "dragon", "headsq" };
  std::vector<std::string> Methods;
  bool ErrorMaps = true;
};

// Default methods: families (SSAO kernel sizes, ours 1 layer / 2 layers at
// several N with BlurRadius 4) and named settings of ours.
const char* const DefaultMethods = "ssao:8,ssao:16,ssao:32,ssao:64,"
                                   "ours1:4,ours1:8,ours1:16,ours1:32,"
                                   "ours2:4,ours2:8,ours2:16,ours2:32,ours2nc:16,"
                                   "low,medium,high";

void Usage()
{
  std::printf(
    "Usage: deepgi-benchmark-ao [options]\n"
    "Time and error against a ray-traced reference of vtkSSAOPass and of the deep\n"
    "ambient obscurance (1 and 2 layers) on several scenes, measured in one run.\n"
    "  --size WxH           timing size in pixels (default 640x480)\n"
    "  --accuracy-size WxH  size of the error measurement (default 320x240)\n"
    "  --frames N           timed frames per method and round (default 7)\n"
    "  --rounds N           rounds over all methods (default 2)\n"
    "  --samples N          reference rays per pixel (default 256)\n"
    "  --radius-fraction F  r = F x scene diagonal, every method (default 0.05)\n"
    "  --scenes LIST        comma list of demo, demo-columns (the demo scene's\n"
    "                       columns view), cornell-lucy, dragon, headsq\n"
    "                       (default all five)\n"
    "  --methods LIST       comma list of ssao:K (vtkSSAOPass, kernel size K, blur on),\n"
    "                       ours1:N[:B] / ours2:N[:B] (one / two layers, N samples,\n"
    "                       BlurRadius B, default 4), ours2nc:N[:B] (two layers,\n"
    "                       layer 1 without back-face culling), ours2gb:N[:B] (two\n"
    "                       layers, a G-buffer guard band of 0.1), low, medium, high (two\n"
    "                       layers with a quality preset). Default:\n"
    "                       %s\n"
    "  --mesh FILE          one more scene: a mesh or OBJ scene the scene loader reads\n"
    "                       (.ply, .stl, .vtk, .vtp, .obj; repeatable); --scene FILE is\n"
    "                       the same. With any of them, only the files are measured\n"
    "                       unless --scenes names built-in scenes too.\n"
    "  --volume FILE --iso V  one more scene: the iso-surface V of a volume\n"
    "  --data DIR           test data folder (default %s)\n"
    "  --no-error-maps      do not write the error-map PNGs\n"
    "  --backend NAME       auto, x11 or egl (default auto)\n"
    "  --output DIR         output directory (default output)\n"
    "  --help               this text\n",
    DefaultMethods, DEEPGI_DATA_DIR);
}

struct Method
{
  std::string Name;   // as in the table
  std::string Family; // curve of the plot
  int Kind = 0;       // 0 SSAO, 1 ours
  int Parameter = 16; // SSAO kernel size or N
  int Layers = 2;     // ours
  int Blur = 4;       // ours
  int Preset = -1;    // ours: a vtkDeepAmbientObscurancePass quality preset, or -1
  bool DeepLayerBackfaceCulling = true; // ours: the G-buffer's culling in layer 1
  double GuardBand = 0.0;               // ours: the G-buffer's guard band
  int Estimator = -1; // ours: vtkDeepAmbientObscurancePass::EstimatorType, or -1 (default)
};

/// Width of the frame's border, as a fraction of the height, on which the
/// guard band's effect is measured separately.
constexpr double BorderFraction = 0.1;

bool ParseMethod(const std::string& spec, Method& m)
{
  const char* const presetNames[] = { "low", "medium", "high" };
  for (int preset = vtkDeepAmbientObscurancePass::HIGH_PERFORMANCE;
       preset <= vtkDeepAmbientObscurancePass::HIGH_QUALITY; ++preset)
  {
    if (spec == presetNames[preset])
    {
      vtkNew<vtkDeepAmbientObscurancePass> settings;
      settings->SetPreset(preset);
      m = { std::string("ours 2 layers, preset ") + presetNames[preset], "", 1,
        settings->GetNumberOfSamples(), 2, settings->GetBlurRadius(), preset };
      return true;
    }
  }
  std::vector<std::string> p = Split(spec, ':');
  std::string estimator;
  if (p.size() >= 3 && (p.back() == "sa" || p.back() == "eq1"))
  {
    estimator = p.back();
    p.pop_back();
    m.Estimator = estimator == "sa" ? vtkDeepAmbientObscurancePass::SOLID_ANGLE
                                    : vtkDeepAmbientObscurancePass::EQUATION_1;
  }
  if (p.size() == 2 && p[0] == "ssao" && estimator.empty())
  {
    int k = 0;
    if (!ParseInt(p[1], k) || k < 1 || k > 1000)
    {
      return false;
    }
    m = { "vtkSSAOPass K=" + p[1], "vtkSSAOPass (kernel size)", 0, k, 0, 0 };
    return true;
  }
  if ((p.size() == 2 || p.size() == 3) &&
    (p[0] == "ours1" || p[0] == "ours2" || p[0] == "ours2nc" || p[0] == "ours2gb"))
  {
    int n = 0, b = 4;
    if (!ParseInt(p[1], n) || n < 1 || n > 98 ||
      (p.size() == 3 && (!ParseInt(p[2], b) || b < 0 || b > 16)))
    {
      return false;
    }
    const int layers = p[0] == "ours1" ? 1 : 2;
    m.Kind = 1;
    m.Parameter = n;
    m.Layers = layers;
    m.Blur = b;
    m.DeepLayerBackfaceCulling = p[0] != "ours2nc";
    m.GuardBand = p[0] == "ours2gb" ? vtkDeepRadiosityPass::DEFAULT_GUARD_BAND : 0.0;
    const std::string label = layers == 1 ? "1 layer"
      : !m.DeepLayerBackfaceCulling       ? "2 layers, no layer-1 culling"
      : m.GuardBand > 0.0                 ? "2 layers, guard band"
                                          : "2 layers";
    const std::string by = estimator == "sa" ? ", solid angle"
      : estimator == "eq1"                   ? ", eq. 1"
                                             : "";
    m.Name = "ours " + label + by + " N=" + p[1] + (b != 4 ? " B=" + std::to_string(b) : "");
    m.Family = b == 4 ? "ours, " + label + by + " (N)" : "";
    return true;
  }
  return false;
}

/// --mesh FILE, --scene FILE (any file vtkDeepGBufferSceneLoader reads),
/// --volume FILE --iso V: one scene each, checked for a readable file here.
template <typename Bad>
bool ParseSceneFileOption(const std::string& arg, const std::string& value, Options& o, Bad bad)
{
  if (arg != "--mesh" && arg != "--scene" && arg != "--volume" && arg != "--iso")
  {
    return true;
  }
  if (arg != "--iso" && !vtksys::SystemTools::FileExists(value, true))
  {
    return bad(arg + ": no such file '" + value + "'");
  }
  if (arg == "--iso")
  {
    char* end = nullptr;
    const double iso = std::strtod(value.c_str(), &end);
    if (o.PendingVolume.empty())
    {
      return bad("--iso needs a --volume before it");
    }
    if (value.empty() || *end || !std::isfinite(iso))
    {
      return bad("--iso needs a finite number, got '" + value + "'");
    }
    o.Files.push_back("volume:" + value + ":" + o.PendingVolume);
    o.PendingVolume.clear();
  }
  else if (arg == "--volume")
  {
    if (!o.PendingVolume.empty())
    {
      return bad("--volume " + o.PendingVolume + " needs --iso V after it");
    }
    o.PendingVolume = value;
  }
  else
  {
    o.Files.push_back("mesh:" + value);
  }
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
      "--samples", "--radius-fraction", "--scenes", "--methods", "--data", "--backend", "--output",
      "--mesh", "--scene", "--volume", "--iso" };
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
    if (arg == "--scenes")
    {
      o.ScenesGiven = true;
      o.Scenes = Split(value, ',');
      if (o.Scenes.empty())
      {
        return bad("--scenes needs at least one scene");
      }
      for (const std::string& s : o.Scenes)
      {
        if (s != "demo" && s != "demo-columns" && s != "cornell-lucy" && s != "dragon" &&
          s != "headsq")
        {
          return bad(
            "unknown scene '" + s + "' (demo, demo-columns, cornell-lucy, dragon, headsq)");
        }
      }
    }
    if (arg == "--methods")
    {
      methods = value;
    }
    if (!ParseSceneFileOption(arg, value, o, bad))
    {
      return false;
    }
    std::string error;
    if (!ParseSharedOption(arg, value, o.Data, o.Backend, o.Output, error))
    {
      return bad(error);
    }
  }
  if (!o.PendingVolume.empty())
  {
    return bad("--volume " + o.PendingVolume + " needs --iso V after it");
  }
  if (!o.Files.empty())
  {
    o.Scenes = o.ScenesGiven ? o.Scenes : std::vector<std::string>();
    o.Scenes.insert(o.Scenes.end(), o.Files.begin(), o.Files.end());
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
      return bad("unknown method '" + m +
        "' (ssao:K, ours1:N[:B][:E], ours2:N[:B][:E], ours2nc:N[:B][:E], ours2gb:N[:B][:E], low, "
        "medium, high; E: sa or eq1)");
    }
  }
  return true;
}

/// Luminance (0..1) of the window's last frame, bottom row first.
std::vector<float> GrabLuminance(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->SetInputBufferTypeToRGB();
  grab->Update();
  vtkImageData* image = grab->GetOutput();
  vtkDataArray* rgb = image->GetPointData()->GetScalars();
  std::vector<float> lum(rgb->GetNumberOfTuples());
  for (vtkIdType i = 0; i < rgb->GetNumberOfTuples(); ++i)
  {
    lum[i] =
      static_cast<float>((0.2126 * rgb->GetComponent(i, 0) + 0.7152 * rgb->GetComponent(i, 1) +
                           0.0722 * rgb->GetComponent(i, 2)) /
        255.0);
  }
  return lum;
}

struct Accuracy
{
  double Rmse = 0, Mae = 0, RmseLayer1 = 0;               // raw
  double Gamma = 1, CRmse = 0, CMae = 0, CRmseLayer1 = 0; // calibrated
  double CaptureDifference = -1;                          // ours: mean |ratio - captured AV|
  double MeanAV = 0;
  double CRmseBorder = 0; // calibrated, on the valid pixels within BorderFraction of the edge
  long BorderPixels = 0;
};

struct Result
{
  std::string Scene;
  Method M;
  double FrameMs = 0;
  Accuracy A;
};

/// Where a two-layer setting's AV differs from the one-layer setting with
/// the same N and BlurRadius, and which of the two is nearer the reference.
struct SecondLayerEffect
{
  std::string Scene, TwoLayers, OneLayer;
  long Changed = 0, Valid = 0;         // pixels with |AV_2 - AV_1| > SecondLayerChange
  double RmseOne = 0.0, RmseTwo = 0.0; // calibrated, on the changed pixels
};

/// AV difference above which a pixel counts as changed by the second layer.
constexpr double SecondLayerChange = 0.02;

const char* const TimeAxis = "frame time [ms] (median)";
const char* const ErrorAxis = "RMSE of AV vs ray-traced reference (gamma-calibrated)";

struct ErrorStats
{
  double Rmse, Mae, RmseLayer1;
};

ErrorStats Errors(const std::vector<float>& av, const std::vector<float>& ref,
  const std::vector<unsigned char>& mask, const std::vector<unsigned char>& layer1, double gamma)
{
  double s2 = 0, s1 = 0, l2 = 0;
  long n = 0, nl = 0;
  for (size_t i = 0; i < av.size(); ++i)
  {
    if (!mask[i])
    {
      continue;
    }
    const double a = gamma == 1.0 ? av[i] : std::pow(std::max(0.0f, av[i]), gamma);
    const double d = a - ref[i];
    s2 += d * d;
    s1 += std::fabs(d);
    ++n;
    if (layer1[i])
    {
      l2 += d * d;
      ++nl;
    }
  }
  return { n ? std::sqrt(s2 / n) : 0.0, n ? s1 / n : 0.0, nl ? std::sqrt(l2 / nl) : 0.0 };
}

/// gamma in [0.05, 20] minimising the RMSE of AV^gamma (golden section on log gamma).
double FitGamma(const std::vector<float>& av, const std::vector<float>& ref,
  const std::vector<unsigned char>& mask, const std::vector<unsigned char>& layer1)
{
  double a = std::log(0.05), b = std::log(20.0);
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - g * (b - a), d = a + g * (b - a);
  auto f = [&](double x) { return Errors(av, ref, mask, layer1, std::exp(x)).Rmse; };
  double fc = f(c), fd = f(d);
  for (int it = 0; it < 40; ++it)
  {
    if (fc < fd)
    {
      b = d;
      d = c;
      fd = fc;
      c = b - g * (b - a);
      fc = f(c);
    }
    else
    {
      a = c;
      c = d;
      fc = fd;
      d = a + g * (b - a);
      fd = f(d);
    }
  }
  return std::exp(0.5 * (a + b));
}

struct SceneSetup
{
  std::string Name;
  vtkSmartPointer<vtkPolyData> Geometry;
};

/// Populates `renderer` with `name`; white ambient-only materials, still camera.
bool LoadScene(const Options& o, const std::string& name, vtkRenderer* renderer, SceneSetup& s,
  vtkSmartPointer<vtkObject>& keep)
{
  s.Name = name;
  if (name == "demo" || name == "demo-columns")
  {
    auto demo = vtkSmartPointer<vtkDeepGBufferDemoScene>::New();
    demo->SetTargetNumberOfTriangles(200000);
    demo->Populate(renderer);
    if (name == "demo")
    {
      demo->SetCameraToDefaultView(renderer->GetActiveCamera());
    }
    else
    {
      demo->SetCameraToNamedView(renderer->GetActiveCamera(), "columns");
    }
    s.Geometry = demo->GetScenePolyData();
    keep = demo;
  }
  else
  {
    auto loader = vtkSmartPointer<vtkDeepGBufferSceneLoader>::New();
    bool ok = false;
    if (name.rfind("mesh:", 0) == 0)
    {
      s.Name = vtksys::SystemTools::GetFilenameName(name.substr(5));
      ok = loader->Load(name.substr(5).c_str());
    }
    else if (name.rfind("volume:", 0) == 0)
    {
      const size_t colon = name.find(':', 7);
      const std::string path = name.substr(colon + 1);
      s.Name = vtksys::SystemTools::GetFilenameName(path) + " iso " + name.substr(7, colon - 7);
      ok =
        loader->LoadVolume(path.c_str(), std::strtod(name.substr(7, colon - 7).c_str(), nullptr));
    }
    else if (name == "cornell-lucy")
    {
      ok = loader->Load((o.Data + "/scenes/cornell-lucy/CornellBox-Lucy.obj").c_str());
    }
    else if (name == "dragon")
    {
      ok = loader->Load((o.Data + "/meshes/dragon.ply").c_str());
    }
    else
    {
      ok = loader->LoadVolume((o.Data + "/volumes/headsq/quarter").c_str(), 500.0);
      loader->SetViewDirection(0.0, -1.0, 0.0);
      loader->SetViewUp(0.0, 0.0, -1.0);
    }
    if (!ok)
    {
      std::fprintf(
        stderr, "%s: cannot load scene %s from %s\n", Program, name.c_str(), o.Data.c_str());
      return false;
    }
    loader->Populate(renderer);
    loader->ResetCamera(renderer);
    s.Geometry = loader->GetScenePolyData();
    keep = loader;
  }
  vtkActorCollection* actors = renderer->GetActors();
  actors->InitTraversal();
  while (vtkActor* actor = actors->GetNextActor())
  {
    vtkProperty* p = actor->GetProperty();
    p->SetColor(1.0, 1.0, 1.0);
    p->SetAmbient(1.0);
    p->SetDiffuse(0.0);
    p->SetSpecular(0.0);
  }
  renderer->SetBackground(0.0, 0.0, 0.0);
  renderer->ResetCameraClippingRange();
  return true;
}

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
  std::vector<SecondLayerEffect> effects;
  struct SceneInfo
  {
    std::string Name;
    vtkIdType Triangles;
    double Radius, RefError, PlainMs, GBufferMs;
    long Valid, Excluded, Layer1;
    double ReferenceSeconds;
  };
  std::vector<SceneInfo> infos;
  std::string device = "unknown";

  for (const std::string& sceneSpec : options.Scenes)
  {
    vtkSmartPointer<vtkRenderWindow> window = vtkSmartPointer<vtkRenderWindow>::Take(
      vtkDeepGIRenderWindowFactory::NewRenderWindow(options.Backend));
    if (!window)
    {
      std::fprintf(stderr, "%s: no render window for this backend\n", Program);
      return 1;
    }
    window->SetMultiSamples(0);
    window->SetSize(options.AccuracyWidth, options.AccuracyHeight);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    SceneSetup scene;
    vtkSmartPointer<vtkObject> keep;
    if (!LoadScene(options, sceneSpec, renderer, scene, keep))
    {
      return 1;
    }
    // The built-in scene's name, or the user's file name (its iso-value).
    const std::string sceneName = scene.Name;
    double bounds[6];
    scene.Geometry->GetBounds(bounds);
    const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
      (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
      (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
    const double r = options.RadiusFraction * diagonal;

    // The passes of every method.
    std::vector<vtkSmartPointer<vtkRenderPass>> passes;
    std::vector<vtkSmartPointer<vtkRenderStepsPass>> steps;
    for (const Method& m : methods)
    {
      if (m.Kind == 0)
      {
        auto basic = vtkSmartPointer<vtkRenderStepsPass>::New();
        auto ssao = vtkSmartPointer<vtkSSAOPass>::New();
        ssao->SetDelegatePass(basic);
        ssao->SetRadius(r);
        ssao->SetBias(0.02 * r); // VTK's default ratio Bias / Radius = 0.01 / 0.5
        ssao->SetKernelSize(static_cast<unsigned int>(m.Parameter));
        ssao->SetBlur(true);
        steps.push_back(basic);
        passes.push_back(ssao);
      }
      else
      {
        auto ao = vtkSmartPointer<vtkDeepAmbientObscurancePass>::New();
        ao->SetRadius(r);
        if (m.Preset >= 0)
        {
          ao->SetPreset(m.Preset);
        }
        else
        {
          ao->SetNumberOfSamples(m.Parameter);
          ao->SetBlurRadius(m.Blur);
        }
        if (m.Estimator >= 0)
        {
          ao->SetEstimator(m.Estimator);
        }
        ao->SetUseSecondLayer(m.Layers == 2);
        ao->GetGBufferPass()->SetNumberOfLayers(m.Layers);
        ao->GetGBufferPass()->SetDeepLayerBackfaceCulling(m.DeepLayerBackfaceCulling);
        ao->GetGBufferPass()->SetGuardBand(m.GuardBand);
        passes.push_back(ao);
      }
    }
    auto gbuffer = vtkSmartPointer<vtkDeepGBufferPass>::New();
    gbuffer->SetNumberOfLayers(2);

    auto renderStill = [&](vtkRenderPass* pass, int frames)
    {
      renderer->SetPass(pass);
      for (int f = 0; f < frames; ++f)
      {
        window->Render();
      }
      window->WaitForCompletion();
    };

    // ---- accuracy ----
    const int w = options.AccuracyWidth, h = options.AccuracyHeight;
    renderStill(nullptr, 2);
    if (device == "unknown")
    {
      if (auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window))
      {
        std::istringstream lines(gl->ReportCapabilities());
        std::string line;
        while (std::getline(lines, line))
        {
          if (line.find("OpenGL renderer string") != std::string::npos)
          {
            device = line.substr(line.find(':') + 1);
            device.erase(0, device.find_first_not_of(' '));
          }
        }
      }
    }
    const std::vector<float> plainVTK = GrabLuminance(window);
    renderStill(gbuffer, 3); // the oracle gets a history at the still camera
    const std::vector<float> plainGB = GrabLuminance(window);
    vtkNew<vtkImageData> capture;
    if (!gbuffer->CaptureLayers(capture, renderer))
    {
      std::fprintf(stderr, "%s: the G-buffer capture failed on %s\n", Program, sceneName.c_str());
      return 1;
    }
    const size_t np = static_cast<size_t>(w) * h;
    std::vector<unsigned char> mask(np, 0), layer1(np, 0), border(np, 0);
    const int borderWidth = static_cast<int>(std::lround(BorderFraction * h));
    long nBorder = 0;
    vtkDataArray* valid0 = capture->GetPointData()->GetArray(
      vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 0).c_str());
    vtkDataArray* valid1 = capture->GetPointData()->GetArray(
      vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 1).c_str());
    long nValid = 0, nExcluded = 0, nLayer1 = 0;
    for (size_t i = 0; i < np; ++i)
    {
      if (valid0 && valid0->GetComponent(i, 0) > 0)
      {
        if (plainVTK[i] > 0.05f && plainGB[i] > 0.05f)
        {
          mask[i] = 1;
          ++nValid;
          const int x = static_cast<int>(i % w), y = static_cast<int>(i / w);
          if (x < borderWidth || y < borderWidth || x >= w - borderWidth || y >= h - borderWidth)
          {
            border[i] = 1;
            ++nBorder;
          }
          if (valid1 && valid1->GetComponent(i, 0) > 0)
          {
            layer1[i] = 1;
            ++nLayer1;
          }
        }
        else
        {
          ++nExcluded;
        }
      }
    }

    vtkNew<vtkDeepGIReferenceObscurance> reference;
    reference->SetScene(scene.Geometry);
    reference->SetRadius(r);
    // The quantity itself (eq. 2 with beta = epsilon = 0), not the
    // regularised form the screen-space estimators use.
    reference->SetBias(0.0);
    reference->SetEpsilon(0.0);
    reference->SetSamplesPerPixel(options.Samples);
    const auto refStart = std::chrono::steady_clock::now();
    if (!reference->Compute(capture))
    {
      std::fprintf(stderr, "%s: the reference failed on %s\n", Program, sceneName.c_str());
      return 1;
    }
    const double refSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - refStart).count();
    std::vector<float> ref(np, 1.0f);
    vtkDataArray* refAV =
      reference->GetOutput()->GetPointData()->GetArray(vtkDeepGICaptureNames::AmbientVisibility);
    for (size_t i = 0; i < np; ++i)
    {
      ref[i] = static_cast<float>(refAV->GetComponent(i, 0));
    }

    std::vector<Result> sceneResults;
    std::vector<std::vector<float>> sceneAV(methods.size());
    for (size_t k = 0; k < methods.size(); ++k)
    {
      const Method& m = methods[k];
      renderStill(passes[k], 3);
      const std::vector<float> lum = GrabLuminance(window);
      const std::vector<float>& plain = m.Kind == 0 ? plainVTK : plainGB;
      std::vector<float> av(np, 1.0f);
      double sumAV = 0;
      for (size_t i = 0; i < np; ++i)
      {
        if (mask[i])
        {
          av[i] = std::min(1.0f, std::max(0.0f, lum[i] / plain[i]));
          sumAV += av[i];
        }
      }
      Result res;
      res.Scene = sceneName;
      res.M = m;
      res.A.MeanAV = nValid ? sumAV / nValid : 0.0;
      if (m.Kind == 1)
      {
        vtkNew<vtkImageData> captured;
        auto* ao = vtkDeepAmbientObscurancePass::SafeDownCast(passes[k]);
        if (ao->CaptureAmbientVisibility(captured, renderer))
        {
          vtkDataArray* cav =
            captured->GetPointData()->GetArray(vtkDeepGICaptureNames::AmbientVisibility);
          double diff = 0;
          for (size_t i = 0; i < np; ++i)
          {
            if (mask[i])
            {
              diff += std::fabs(av[i] - cav->GetComponent(i, 0));
            }
          }
          res.A.CaptureDifference = nValid ? diff / nValid : 0.0;
        }
      }
      const ErrorStats raw = Errors(av, ref, mask, layer1, 1.0);
      res.A.Rmse = raw.Rmse;
      res.A.Mae = raw.Mae;
      res.A.RmseLayer1 = raw.RmseLayer1;
      res.A.Gamma = FitGamma(av, ref, mask, layer1);
      const ErrorStats cal = Errors(av, ref, mask, layer1, res.A.Gamma);
      res.A.CRmse = cal.Rmse;
      res.A.CMae = cal.Mae;
      res.A.CRmseLayer1 = cal.RmseLayer1;
      res.A.CRmseBorder = Errors(av, ref, border, border, res.A.Gamma).Rmse;
      res.A.BorderPixels = nBorder;
      if (options.ErrorMaps)
      {
        std::vector<float> error(np);
        for (size_t i = 0; i < np; ++i)
        {
          error[i] = av[i] - ref[i];
        }
        if (!WriteErrorMap(
              options.Output + "/errors/" + FileTag(sceneName) + "-" + FileTag(m.Name) + ".png", w,
              h, error, mask, 0.5, outputError))
        {
          std::fprintf(stderr, "%s: %s\n", Program, outputError.c_str());
          return 1;
        }
      }
      sceneResults.push_back(res);
      sceneAV[k] = av;
    }

    for (size_t two = 0; two < methods.size(); ++two)
    {
      const Method& m2 = methods[two];
      for (size_t one = 0; one < methods.size() && m2.Kind == 1 && m2.Layers == 2; ++one)
      {
        const Method& m1 = methods[one];
        if (m1.Kind != 1 || m1.Layers != 1 || m1.Parameter != m2.Parameter || m1.Blur != m2.Blur)
        {
          continue;
        }
        std::vector<unsigned char> changed(np, 0);
        SecondLayerEffect e{ sceneName, m2.Name, m1.Name, 0, nValid };
        for (size_t i = 0; i < np; ++i)
        {
          if (mask[i] && std::fabs(sceneAV[two][i] - sceneAV[one][i]) > SecondLayerChange)
          {
            changed[i] = 1;
            ++e.Changed;
          }
        }
        e.RmseOne = Errors(sceneAV[one], ref, changed, changed, sceneResults[one].A.Gamma).Rmse;
        e.RmseTwo = Errors(sceneAV[two], ref, changed, changed, sceneResults[two].A.Gamma).Rmse;
        effects.push_back(e);
      }
    }

    // ---- time ----
    window->SetSize(options.Width, options.Height);
    std::vector<std::vector<double>> ms(methods.size() + 2);
    for (int round = 0; round < options.Rounds; ++round)
    {
      for (size_t k = 0; k < methods.size() + 2; ++k)
      {
        vtkRenderPass* pass =
          k == 0 ? nullptr : (k == 1 ? gbuffer.GetPointer() : passes[k - 2].GetPointer());
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
    infos.push_back(
      { sceneName, scene.Geometry->GetNumberOfPolys(), r, reference->GetMeanStandardError(),
        Median(ms[0]), Median(ms[1]), nValid, nExcluded, nLayer1, refSeconds });
    renderer->SetPass(nullptr);
    for (auto& p : passes)
    {
      p->ReleaseGraphicsResources(window);
    }
    gbuffer->ReleaseGraphicsResources(window);
    std::fprintf(stderr, "%s: scene %s done\n", Program, sceneName.c_str());
  }

  // ---- tables ----
  std::ostringstream md, csv;
  md
    << "Accuracy at " << options.AccuracyWidth << "x" << options.AccuracyHeight << ", time at "
    << options.Width << "x" << options.Height << " (median of " << options.Frames * options.Rounds
    << " frames per method, " << options.Rounds << " rounds, after " << options.Warmup
    << " warm-up frames per round); OpenGL renderer: " << device << ".\n"
    << "r = " << options.RadiusFraction
    << " x scene diagonal for every method; vtkSSAOPass: Radius r, Bias 0.02 r, Blur on; "
       "ours: Radius r and the pass's defaults (Bias 0.01 r, Epsilon 1e-4 r^2, estimator "
       "SOLID_ANGLE unless the method says otherwise); reference: Embree, "
    << options.Samples
    << " rays per pixel, beta = eps = 0 (the obscurance itself), on the G-buffer capture of the "
       "same frame (layer 0).\nAV of a method = luminance(method) / luminance(plain) on white "
       "ambient-only surfaces (plain = VTK for vtkSSAOPass, the G-buffer pass alone for ours).\n\n";
  md << "| scene | triangles | r | valid px | excluded px | layer-1 px | reference std. error | "
        "reference [s] | VTK frame [ms] | G-buffer (2 layers) frame [ms] "
        "|\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (const SceneInfo& s : infos)
  {
    char b[512];
    std::snprintf(b, sizeof(b),
      "| %s | %lld | %.4g | %ld | %ld | %ld | %.4f | %.1f | %.2f | %.2f |\n", s.Name.c_str(),
      static_cast<long long>(s.Triangles), s.Radius, s.Valid, s.Excluded, s.Layer1, s.RefError,
      s.ReferenceSeconds, s.PlainMs, s.GBufferMs);
    md << b;
  }
  md << "\n| scene | method | frame [ms] | AO cost [ms] | RMSE | MAE | RMSE layer-1 px | gamma | "
        "RMSE cal. | MAE cal. | RMSE cal. layer-1 px | mean AV | ratio vs captured AV |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  csv << "scene,method,family,kind,samples,layers,blur,frame_ms,ao_cost_ms,rmse,mae,rmse_layer1,"
         "gamma,rmse_cal,mae_cal,rmse_cal_layer1,mean_av,capture_difference\n";
  for (const Result& r : results)
  {
    double plainMs = 0;
    for (const SceneInfo& s : infos)
    {
      if (s.Name == r.Scene)
      {
        plainMs = s.PlainMs;
      }
    }
    char b[1024];
    std::snprintf(b, sizeof(b),
      "| %s | %s | %.2f | %.2f | %.4f | %.4f | %.4f | %.2f | %.4f | %.4f | %.4f | %.3f | %s |\n",
      r.Scene.c_str(), r.M.Name.c_str(), r.FrameMs, r.FrameMs - plainMs, r.A.Rmse, r.A.Mae,
      r.A.RmseLayer1, r.A.Gamma, r.A.CRmse, r.A.CMae, r.A.CRmseLayer1, r.A.MeanAV,
      r.A.CaptureDifference < 0 ? "" : Fmt("%.4f", r.A.CaptureDifference).c_str());
    md << b;
    std::snprintf(b, sizeof(b),
      // Text fields are quoted: method names may contain commas.
      "\"%s\",\"%s\",\"%s\",%s,%d,%d,%d,%.4f,%.4f,%.5f,%.5f,%.5f,%.4f,%.5f,%.5f,%.5f,%.4f,%s\n",
      r.Scene.c_str(), r.M.Name.c_str(), r.M.Family.c_str(), r.M.Kind == 0 ? "ssao" : "ours",
      r.M.Parameter, r.M.Kind == 0 ? 0 : r.M.Layers, r.M.Blur, r.FrameMs, r.FrameMs - plainMs,
      r.A.Rmse, r.A.Mae, r.A.RmseLayer1, r.A.Gamma, r.A.CRmse, r.A.CMae, r.A.CRmseLayer1,
      r.A.MeanAV, r.A.CaptureDifference < 0 ? "" : Fmt("%.5f", r.A.CaptureDifference).c_str());
    csv << b;
  }

  // ---- goals ----
  md << "\n### Goals\n\n";
  // Raw errors are what a user sees; the calibrated ones fit an exponent per
  // method and scene against the reference, which no user can do.
  for (int calibrated = 0; calibrated <= 1; ++calibrated)
  {
    auto rmse = [&](const Result& r) { return calibrated ? r.A.CRmse : r.A.Rmse; };
    auto rmse1 = [&](const Result& r) { return calibrated ? r.A.CRmseLayer1 : r.A.RmseLayer1; };
    md << (calibrated ? "\nCalibrated errors (secondary: one exponent per method and scene "
                        "fitted to the reference):\n\n"
                      : "Raw errors (headline):\n\n");
    md << "| scene | goal 1: worst over SSAO settings of (best 2-layer RMSE at <= its time) / "
          "SSAO RMSE (goal <= 0.6) | goal 2: per N, layer-1 RMSE 2 layers / 1 layer (goal <= 0.8) "
          "and time ratio (goal <= 1.3) |\n|---|---|---|\n";
    for (const SceneInfo& s : infos)
    {
      std::ostringstream g1, g2;
      double worst = -1;
      bool missing = false;
      for (const Result& a : results)
      {
        if (a.Scene != s.Name || a.M.Kind != 0)
        {
          continue;
        }
        double best = -1;
        for (const Result& b : results)
        {
          if (b.Scene == s.Name && b.M.Kind == 1 && b.M.Layers == 2 && b.FrameMs <= a.FrameMs &&
            (best < 0 || rmse(b) < best))
          {
            best = rmse(b);
          }
        }
        double bestAny = -1; // best 2-layer RMSE at any time
        for (const Result& b : results)
        {
          if (b.Scene == s.Name && b.M.Kind == 1 && b.M.Layers == 2 &&
            (bestAny < 0 || rmse(b) < bestAny))
          {
            bestAny = rmse(b);
          }
        }
        if (best < 0)
        {
          missing = true;
          g1 << a.M.Name << ": no 2-layer setting as fast";
          if (bestAny >= 0)
          {
            g1 << " (at any time: " << Fmt("%.2f", bestAny / std::max(1e-9, rmse(a))) << ")";
          }
          g1 << "; ";
          continue;
        }
        const double ratio = best / std::max(1e-9, rmse(a));
        g1 << a.M.Name << ": " << Fmt("%.2f", ratio) << "; ";
        worst = std::max(worst, ratio);
      }
      std::string g1s = (worst < 0 ? std::string("n/a") : Fmt("%.2f", worst)) +
        (worst >= 0 && worst <= 0.6 && !missing ? " (met)" : " (missed)") + " [" + g1.str() + "]";
      for (const Result& two : results)
      {
        if (two.Scene != s.Name || two.M.Kind != 1 || two.M.Layers != 2)
        {
          continue;
        }
        for (const Result& one : results)
        {
          if (one.Scene == s.Name && one.M.Kind == 1 && one.M.Layers == 1 &&
            one.M.Parameter == two.M.Parameter && one.M.Blur == two.M.Blur)
          {
            const double er = rmse1(two) / std::max(1e-9, rmse1(one));
            const double tr = two.FrameMs / std::max(1e-9, one.FrameMs);
            g2 << two.M.Name << ": " << Fmt("%.2f", er) << " / " << Fmt("%.2f", tr)
               << (er <= 0.8 && tr <= 1.3 ? " met" : " missed") << "; ";
          }
        }
      }
      md << "| " << s.Name << " | " << g1s << " | " << g2.str() << " |\n";
    }
  }

  md << "\n### The frame's border\n\n"
     << "Calibrated RMSE on all valid pixels and on those within " << BorderFraction
     << " of the height of the frame's edge, where the screen-space methods lack the "
        "occluders outside the view unless the G-buffer has a guard band.\n\n"
     << "| scene | method | frame [ms] | RMSE cal. | RMSE cal. border | border px |\n"
        "|---|---|---|---|---|---|\n";
  for (const Result& r : results)
  {
    md << "| " << r.Scene << " | " << r.M.Name << " | " << Fmt("%.2f", r.FrameMs) << " | "
       << Fmt("%.4f", r.A.CRmse) << " | " << Fmt("%.4f", r.A.CRmseBorder) << " | "
       << r.A.BorderPixels << " |\n";
  }

  md << "\n### Where the second layer changes AV\n\n"
     << "Pixels where a two-layer setting's AV differs by more than " << SecondLayerChange
     << " from the one-layer setting with the same N and BlurRadius, and the calibrated RMSE "
        "of both on those pixels only.\n\n"
     << "| scene | two layers | one layer | changed px | of valid px | RMSE cal. 1 layer | "
        "RMSE cal. 2 layers |\n|---|---|---|---|---|---|---|\n";
  for (const SecondLayerEffect& e : effects)
  {
    md << "| " << e.Scene << " | " << e.TwoLayers << " | " << e.OneLayer << " | " << e.Changed
       << " | " << e.Valid << " | " << Fmt("%.4f", e.RmseOne) << " | " << Fmt("%.4f", e.RmseTwo)
       << " |\n";
  }

  std::fputs(md.str().c_str(), stdout);
  if (!DeepGIOutput::WriteText(options.Output + "/benchmark-ao.md", md.str(), outputError) ||
    !DeepGIOutput::WriteText(options.Output + "/benchmark-ao.csv", csv.str(), outputError))
  {
    std::fprintf(stderr, "%s: %s\n", Program, outputError.c_str());
    return 1;
  }

  // ---- plots ----
  std::vector<std::string> families;
  for (const Method& m : methods)
  {
    const std::string f = m.Family.empty() ? m.Name : m.Family;
    if (std::find(families.begin(), families.end(), f) == families.end())
    {
      families.push_back(f);
    }
  }
  Curves mean;
  for (size_t k = 0; k < methods.size(); ++k)
  {
    double t = 0, e = 0;
    int n = 0;
    for (const Result& r : results)
    {
      if (r.M.Name == methods[k].Name)
      {
        t += r.FrameMs;
        e += r.A.CRmse;
        ++n;
      }
    }
    const std::string f = methods[k].Family.empty() ? methods[k].Name : methods[k].Family;
    if (n)
    {
      mean[f].push_back({ t / n, e / n });
    }
  }
  if (!WritePlot(options.Output + "/benchmark-ao-plot.png",
        "Ambient obscurance: error vs time (mean over scenes)", TimeAxis, ErrorAxis, families, mean,
        options.Backend, outputError))
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
        curves[r.M.Family.empty() ? r.M.Name : r.M.Family].push_back({ r.FrameMs, r.A.CRmse });
      }
    }
    if (!WritePlot(options.Output + "/benchmark-ao-plot-" + FileTag(s.Name) + ".png",
          "Ambient obscurance: error vs time, " + s.Name, TimeAxis, ErrorAxis, families, curves,
          options.Backend, outputError))
    {
      std::fprintf(stderr, "%s: %s\n", Program, outputError.c_str());
      return 1;
    }
  }
  std::printf("\nwrote %s/benchmark-ao.{md,csv}, %s/benchmark-ao-plot.png\n",
    options.Output.c_str(), options.Output.c_str());
  return 0;
}
