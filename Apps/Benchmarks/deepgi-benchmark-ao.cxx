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
#include "vtkDeepGBufferPass.h"
#include "vtkDeepGICameraText.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIDemoScene.h"
#include "vtkDeepGIReferenceObscurance.h"
#include "vtkDeepGISceneLoader.h"
#include "vtkDeepRadiosityPass.h"
#include "vtkImageData.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
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

const char* const SceneNames[] = { "demo", "demo-columns", "cornell-lucy", "dragon", "headsq" };

// Default methods: families (SSAO kernel sizes, ours 1 layer / 2 layers at
// several N with BlurRadius 4) and named settings of ours.
const char* const DefaultMethods = "ssao:8,ssao:16,ssao:32,ssao:64,"
                                   "ours1:4,ours1:8,ours1:16,ours1:32,"
                                   "ours2:4,ours2:8,ours2:16,ours2:32,ours2cull:16,ours2:16:4:sa,"
                                   "low,medium,high";

void Usage()
{
  std::printf("Usage: deepgi-benchmark-ao [options]\n"
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
              "                       ours1:N[:B][:E] / ours2:N[:B][:E] (one / two layers, N\n"
              "                       samples, BlurRadius B, default 4, estimator E: vb, the\n"
              "                       default VISIBILITY_BITMASK, sa SOLID_ANGLE or eq1\n"
              "                       EQUATION_1), ours2cull:N[:B][:E] (two layers, layer 1 with\n"
              "                       back-face culling), ours2gb:N[:B][:E] (two layers, a\n"
              "                       G-buffer guard band of 0.1), low, medium, high (two\n"
              "                       layers with a quality preset). Default:\n"
              "                       %s\n"
              "  --mesh FILE          one more scene: a mesh or OBJ scene the scene loader reads\n"
              "                       (.ply, .stl, .vtk, .vtp, .obj; repeatable); --scene FILE is\n"
              "                       the same. With any of them, only the files are measured\n"
              "                       unless --scenes names built-in scenes too.\n"
              "  --volume FILE --iso V  one more scene: the iso-surface V of a volume\n"
              "  --camera PX,PY,PZ,FX,FY,FZ,UX,UY,UZ[,A]\n"
              "                       the camera of the --mesh, --scene or --volume (with its\n"
              "                       --iso) given just before: position, focal point, view-up,\n"
              "                       view angle in degrees (default 30), as ParaView's Adjust\n"
              "                       Camera shows them. Without it the scene is framed along\n"
              "                       -z. The scene table shows every scene's camera so.\n"
              "  --data DIR           test data folder (default %s)\n"
              "  --no-error-maps      do not write the error-map PNGs\n"
              "  --backend NAME       auto, x11 or egl (default auto)\n"
              "  --output DIR         output directory (default output)\n"
              "  --help               this text\n",
    DefaultMethods, DEEPGI_DATA_DIR);
}

struct Method
{
  std::string Name;                 // as in the table
  std::string Family;               // curve of the plot
  int Kind = 0;                     // 0 SSAO, 1 ours
  int Parameter = 16;               // SSAO kernel size or N
  int Layers = 2;                   // ours
  int Blur = 4;                     // ours
  int Preset = -1;                  // ours: a vtkDeepAmbientObscurancePass quality preset, or -1
  bool CullLayer1BackFaces = false; // ours: layer 1 culled, as vtkDeepGIPass's G-buffer
  double GuardBand = 0.0;           // ours: the G-buffer's guard band
  int Estimator = -1; // ours: vtkDeepAmbientObscurancePass::EstimatorType, or -1 (default)
};

/// The plots' curve of `m`: its family, or its own for a named setting.
std::string CurveOf(const Method& m)
{
  return m.Family.empty() ? m.Name : m.Family;
}

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
  if (p.size() >= 3 && (p.back() == "sa" || p.back() == "eq1" || p.back() == "vb"))
  {
    estimator = p.back();
    p.pop_back();
    m.Estimator = estimator == "sa" ? vtkDeepAmbientObscurancePass::SOLID_ANGLE
      : estimator == "vb"           ? vtkDeepAmbientObscurancePass::VISIBILITY_BITMASK
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
    (p[0] == "ours1" || p[0] == "ours2" || p[0] == "ours2cull" || p[0] == "ours2gb"))
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
    m.CullLayer1BackFaces = p[0] == "ours2cull";
    m.GuardBand = p[0] == "ours2gb" ? vtkDeepRadiosityPass::DEFAULT_GUARD_BAND : 0.0;
    const std::string label = layers == 1 ? "1 layer"
      : m.CullLayer1BackFaces             ? "2 layers, layer 1 culled"
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

struct Options : AccuracyOptions
{
  Options()
    : AccuracyOptions({ 640, 480 }, { 320, 240 }, 7, 3, 256,
        std::vector<std::string>(std::begin(SceneNames), std::end(SceneNames)), DefaultMethods)
  {
    this->RadiusFraction = 0.05;
    this->Data = DEEPGI_DATA_DIR;
  }
  // The user's own scenes ("mesh:CAMERA:PATH" or "volume:ISO:CAMERA:PATH",
  // CAMERA empty for the loader's camera; a camera's text has no colon),
  // measured after the built-in ones named with --scenes (none unless
  // --scenes is given).
  std::vector<std::string> Files;
  std::string PendingVolume; // a --volume waiting for its --iso
  std::vector<Method> Methods;
};

/// --camera TEXT: the camera of the user's scene given last, checked here.
bool ParseCameraOption(const std::string& value, Options& o, std::string& error)
{
  if (!o.PendingVolume.empty())
  {
    error = "--volume " + o.PendingVolume + " needs --iso V before --camera";
    return false;
  }
  if (o.Files.empty())
  {
    error = "--camera needs a --mesh, --scene or --volume before it";
    return false;
  }
  vtkNew<vtkCamera> camera;
  const std::string reason = vtkDeepGICameraText::Apply(value.c_str(), camera);
  if (!reason.empty())
  {
    error = "--camera '" + value + "': " + reason;
    return false;
  }
  // The camera field follows the kind ("mesh") and, for a volume, the iso-value.
  std::string& spec = o.Files.back();
  const size_t field = spec.rfind("volume:", 0) == 0 ? spec.find(':', 7) + 1 : 5;
  if (spec[field] != ':')
  {
    error = "a second --camera for the same scene";
    return false;
  }
  spec.insert(field, vtkDeepGICameraText::Write(camera));
  return true;
}

/// --mesh FILE, --scene FILE (any file vtkDeepGISceneLoader reads),
/// --volume FILE --iso V: one scene each, checked for a readable file here;
/// --camera TEXT after one gives it a camera.
bool ParseSceneFileOption(
  const std::string& arg, const std::string& value, Options& o, std::string& error)
{
  if (arg == "--camera")
  {
    return ParseCameraOption(value, o, error);
  }
  if (arg != "--iso" && !vtksys::SystemTools::FileExists(value, true))
  {
    error = arg + ": no such file '" + value + "'";
    return false;
  }
  if (arg == "--iso")
  {
    char* end = nullptr;
    const double iso = std::strtod(value.c_str(), &end);
    if (o.PendingVolume.empty())
    {
      error = "--iso needs a --volume before it";
      return false;
    }
    if (value.empty() || *end || !std::isfinite(iso))
    {
      error = "--iso needs a finite number, got '" + value + "'";
      return false;
    }
    o.Files.push_back("volume:" + value + "::" + o.PendingVolume);
    o.PendingVolume.clear();
  }
  else if (arg == "--volume")
  {
    if (!o.PendingVolume.empty())
    {
      error = "--volume " + o.PendingVolume + " needs --iso V after it";
      return false;
    }
    o.PendingVolume = value;
  }
  else
  {
    o.Files.push_back("mesh::" + value);
  }
  return true;
}

bool ParseOptions(int argc, char* argv[], Options& o)
{
  const CommandLine commandLine{ Program, Usage,
    std::vector<std::string>(std::begin(SceneNames), std::end(SceneNames)),
    { "--mesh", "--scene", "--volume", "--iso", "--camera" },
    [&o](const std::string& arg, const std::string& value, std::string& error)
    { return ParseSceneFileOption(arg, value, o, error); } };
  if (!ParseAccuracyOptions(argc, argv, commandLine, o))
  {
    return false;
  }
  if (!o.PendingVolume.empty())
  {
    return Report(Program, "--volume " + o.PendingVolume + " needs --iso V after it");
  }
  if (!o.Files.empty())
  {
    o.Scenes = o.ScenesGiven ? o.Scenes : std::vector<std::string>();
    o.Scenes.insert(o.Scenes.end(), o.Files.begin(), o.Files.end());
  }
  return ParseMethodList(Program, o.MethodList, ParseMethod,
    "ssao:K, ours1:N[:B][:E], ours2:N[:B][:E], ours2cull:N[:B][:E], ours2gb:N[:B][:E], low, "
    "medium, high; E: vb, sa or eq1",
    o.Methods);
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
  double Rmse = 0, Mae = 0, RmseLayer1 = 0, Bias = 0;     // raw
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
  double RmseOne = 0.0, RmseTwo = 0.0; // raw, on the changed pixels
  double CalibratedRmseOne = 0.0, CalibratedRmseTwo = 0.0;
};

/// AV difference above which a pixel counts as changed by the second layer.
constexpr double SecondLayerChange = 0.02;

struct ErrorStats
{
  double Rmse, Mae, RmseLayer1;
  double Bias; // mean AV - AV_ref: > 0 lighter than the truth, < 0 darker
};

ErrorStats Errors(const std::vector<float>& av, const std::vector<float>& ref,
  const std::vector<unsigned char>& mask, const std::vector<unsigned char>& layer1, double gamma)
{
  double s2 = 0, s1 = 0, l2 = 0, signedSum = 0;
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
    signedSum += d;
    ++n;
    if (layer1[i])
    {
      l2 += d * d;
      ++nl;
    }
  }
  return { n ? std::sqrt(s2 / n) : 0.0, n ? s1 / n : 0.0, nl ? std::sqrt(l2 / nl) : 0.0,
    n ? signedSum / n : 0.0 };
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

/// The position, PX,PY,PZ, of a camera's text: what names a scene seen
/// through --camera.
std::string PositionOf(const std::string& camera)
{
  std::istringstream fields(camera);
  std::string x, y, z;
  std::getline(fields, x, ',');
  std::getline(fields, y, ',');
  std::getline(fields, z, ',');
  return x + "," + y + "," + z;
}

/// A scene of the user's ("mesh:CAMERA:PATH" or "volume:ISO:CAMERA:PATH")
/// into `loader`; its name (the file's, with the iso-value) and camera text.
bool LoadUserFile(
  const std::string& spec, vtkDeepGISceneLoader* loader, std::string& name, std::string& camera)
{
  if (spec.rfind("mesh:", 0) == 0)
  {
    const size_t colon = spec.find(':', 5);
    const std::string path = spec.substr(colon + 1);
    camera = spec.substr(5, colon - 5);
    name = vtksys::SystemTools::GetFilenameName(path);
    return loader->Load(path.c_str());
  }
  const size_t colon = spec.find(':', 7), cameraEnd = spec.find(':', colon + 1);
  const std::string iso = spec.substr(7, colon - 7), path = spec.substr(cameraEnd + 1);
  camera = spec.substr(colon + 1, cameraEnd - colon - 1);
  name = vtksys::SystemTools::GetFilenameName(path) + " iso " + iso;
  return loader->LoadVolume(path.c_str(), std::strtod(iso.c_str(), nullptr));
}

/// Populates `renderer` with `name`; white ambient-only materials, still camera.
bool LoadScene(const Options& o, const std::string& name, vtkRenderer* renderer, SceneSetup& s,
  vtkSmartPointer<vtkObject>& keep)
{
  s.Name = name;
  if (name == "demo" || name == "demo-columns")
  {
    auto demo = vtkSmartPointer<vtkDeepGIDemoScene>::New();
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
    auto loader = vtkSmartPointer<vtkDeepGISceneLoader>::New();
    bool ok = false;
    std::string camera; // the user's --camera, or empty
    if (name.rfind("mesh:", 0) == 0 || name.rfind("volume:", 0) == 0)
    {
      ok = LoadUserFile(name, loader, s.Name, camera);
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
    if (!camera.empty())
    {
      // Checked when the options were read; named by where it stands.
      vtkDeepGICameraText::Apply(camera.c_str(), renderer->GetActiveCamera());
      s.Name += " from " + PositionOf(camera);
    }
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

/// One scene's row of the first table.
struct SceneInfo
{
  std::string Name;
  vtkIdType Triangles;
  double Radius, RefError, PlainMs, GBufferMs;
  long Valid, Excluded, Layer1;
  double ReferenceSeconds;
  std::string Camera; // as --camera takes it
};

/// Everything measured, in the order of the scenes.
struct Measurements
{
  std::vector<Result> Results;
  std::vector<SecondLayerEffect> Effects;
  std::vector<SceneInfo> Scenes;
  std::string Device = "unknown";
};

/// The pixels of the accuracy frame the errors are measured on.
struct PixelMasks
{
  std::vector<unsigned char> Valid;  // layer 0 valid, both plain luminances > 0.05
  std::vector<unsigned char> Layer1; // valid, and layer 1 exists
  std::vector<unsigned char> Border; // valid, within BorderFraction of the frame's edge
  long ValidCount = 0, Excluded = 0, Layer1Count = 0, BorderCount = 0;
};

/// The still frame at the accuracy size that every method is measured on.
struct AccuracyFrame
{
  std::string Scene;
  int Width = 0, Height = 0;
  std::vector<float> PlainVTK;     // luminance without any pass (for vtkSSAOPass)
  std::vector<float> PlainGBuffer; // luminance of the G-buffer pass alone (for ours)
  vtkSmartPointer<vtkImageData> Capture = vtkSmartPointer<vtkImageData>::New(); // its layers
  PixelMasks Pixels;
  std::vector<float> Reference; // ray-traced AV of layer 0
  double ReferenceSeconds = 0.0;
  double ReferenceError = 0.0; // the reference's mean standard error
};

/// `frames` still frames through `pass` (nullptr: VTK's own rendering),
/// finished on the GPU.
void RenderStill(const View& view, vtkRenderPass* pass, int frames)
{
  view.Renderer->SetPass(pass);
  for (int f = 0; f < frames; ++f)
  {
    view.Window->Render();
  }
  view.Window->WaitForCompletion();
}

/// The diagonal of `geometry`'s bounds, the unit of --radius-fraction.
double Diagonal(vtkPolyData* geometry)
{
  double bounds[6];
  geometry->GetBounds(bounds);
  return std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
}

/// Every method's pass, in the order of `methods`, with radius `r`.
std::vector<vtkSmartPointer<vtkRenderPass>> MakePasses(const std::vector<Method>& methods, double r)
{
  std::vector<vtkSmartPointer<vtkRenderPass>> passes;
  for (const Method& m : methods)
  {
    if (m.Kind == 0)
    {
      auto ssao = vtkSmartPointer<vtkSSAOPass>::New();
      ssao->SetDelegatePass(vtkSmartPointer<vtkRenderStepsPass>::New());
      ssao->SetRadius(r);
      ssao->SetBias(0.02 * r); // VTK's default ratio Bias / Radius = 0.01 / 0.5
      ssao->SetKernelSize(static_cast<unsigned int>(m.Parameter));
      ssao->SetBlur(true);
      passes.push_back(ssao);
      continue;
    }
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
    if (m.CullLayer1BackFaces)
    {
      ao->GetGBufferPass()->SetDeepLayerBackfaceCulling(true);
    }
    ao->GetGBufferPass()->SetGuardBand(m.GuardBand);
    passes.push_back(ao);
  }
  return passes;
}

/// The pixels of `frame` whose errors count, from its capture and plain
/// luminances.
PixelMasks ClassifyPixels(const AccuracyFrame& frame)
{
  const int w = frame.Width, h = frame.Height;
  const size_t np = static_cast<size_t>(w) * h;
  PixelMasks px;
  px.Valid.assign(np, 0);
  px.Layer1.assign(np, 0);
  px.Border.assign(np, 0);
  const int borderWidth = static_cast<int>(std::lround(BorderFraction * h));
  vtkDataArray* valid0 = frame.Capture->GetPointData()->GetArray(
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 0).c_str());
  vtkDataArray* valid1 = frame.Capture->GetPointData()->GetArray(
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 1).c_str());
  for (size_t i = 0; i < np; ++i)
  {
    if (!valid0 || !(valid0->GetComponent(i, 0) > 0))
    {
      continue;
    }
    if (!(frame.PlainVTK[i] > 0.05f && frame.PlainGBuffer[i] > 0.05f))
    {
      ++px.Excluded;
      continue;
    }
    px.Valid[i] = 1;
    ++px.ValidCount;
    const int x = static_cast<int>(i % w), y = static_cast<int>(i / w);
    if (x < borderWidth || y < borderWidth || x >= w - borderWidth || y >= h - borderWidth)
    {
      px.Border[i] = 1;
      ++px.BorderCount;
    }
    if (valid1 && valid1->GetComponent(i, 0) > 0)
    {
      px.Layer1[i] = 1;
      ++px.Layer1Count;
    }
  }
  return px;
}

/// The plain frames (VTK's, then the G-buffer pass's), the G-buffer capture
/// and its pixel masks; the OpenGL renderer's name into `device` once known.
bool CaptureAccuracyFrame(
  const View& view, vtkDeepGBufferPass* gbuffer, AccuracyFrame& frame, std::string& device)
{
  RenderStill(view, nullptr, 2);
  if (device == "unknown")
  {
    device = OpenGLRendererName(view.Window);
  }
  frame.PlainVTK = GrabLuminance(view.Window);
  RenderStill(view, gbuffer, 3); // the oracle gets a history at the still camera
  frame.PlainGBuffer = GrabLuminance(view.Window);
  if (!gbuffer->CaptureLayers(frame.Capture, view.Renderer))
  {
    return Report(Program, "the G-buffer capture failed on " + frame.Scene);
  }
  frame.Pixels = ClassifyPixels(frame);
  return true;
}

/// vtkDeepGIReferenceObscurance on the frame's capture (layer 0).
bool ComputeReference(const Options& o, vtkPolyData* geometry, double r, AccuracyFrame& frame)
{
  vtkNew<vtkDeepGIReferenceObscurance> reference;
  reference->SetInputData(frame.Capture);
  reference->SetSceneData(geometry);
  reference->SetRadius(r);
  // The quantity itself (eq. 2 with beta = epsilon = 0), not the
  // regularised form the screen-space estimators use.
  reference->SetBias(0.0);
  reference->SetEpsilon(0.0);
  reference->SetSamplesPerPixel(o.Samples);
  const auto start = std::chrono::steady_clock::now();
  reference->Update();
  if (reference->GetOutput()->GetNumberOfPoints() == 0)
  {
    return Report(Program, "the reference failed on " + frame.Scene);
  }
  frame.ReferenceSeconds = SecondsSince(start);
  frame.ReferenceError = reference->GetMeanStandardError();
  vtkDataArray* av =
    reference->GetOutput()->GetPointData()->GetArray(vtkDeepGICaptureNames::AmbientVisibility);
  frame.Reference.assign(frame.PlainVTK.size(), 1.0f);
  for (size_t i = 0; i < frame.Reference.size(); ++i)
  {
    frame.Reference[i] = static_cast<float>(av->GetComponent(i, 0));
  }
  return true;
}

/// Mean |AV - the pass's own captured AV| over the valid pixels (-1 when
/// the pass cannot capture it).
double CaptureDifference(vtkDeepAmbientObscurancePass* ao, vtkRenderer* renderer,
  const std::vector<float>& av, const PixelMasks& px)
{
  vtkNew<vtkImageData> captured;
  if (!ao->CaptureAmbientVisibility(captured, renderer))
  {
    return -1;
  }
  vtkDataArray* cav = captured->GetPointData()->GetArray(vtkDeepGICaptureNames::AmbientVisibility);
  double diff = 0;
  for (size_t i = 0; i < av.size(); ++i)
  {
    if (px.Valid[i])
    {
      diff += std::fabs(av[i] - cav->GetComponent(i, 0));
    }
  }
  return px.ValidCount ? diff / px.ValidCount : 0.0;
}

/// Method `m`'s still frame through `pass`: its AV (into `av`) and errors
/// against the reference, raw and calibrated.
Result MeasureMethod(const View& view, const Method& m, vtkRenderPass* pass,
  const AccuracyFrame& frame, std::vector<float>& av)
{
  const PixelMasks& px = frame.Pixels;
  const std::vector<float>& ref = frame.Reference;
  RenderStill(view, pass, 3);
  const std::vector<float> lum = GrabLuminance(view.Window);
  const std::vector<float>& plain = m.Kind == 0 ? frame.PlainVTK : frame.PlainGBuffer;
  av.assign(lum.size(), 1.0f);
  double sumAV = 0;
  for (size_t i = 0; i < av.size(); ++i)
  {
    if (px.Valid[i])
    {
      av[i] = std::min(1.0f, std::max(0.0f, lum[i] / plain[i]));
      sumAV += av[i];
    }
  }
  Result res;
  res.Scene = frame.Scene;
  res.M = m;
  res.A.MeanAV = px.ValidCount ? sumAV / px.ValidCount : 0.0;
  if (m.Kind == 1)
  {
    res.A.CaptureDifference =
      CaptureDifference(vtkDeepAmbientObscurancePass::SafeDownCast(pass), view.Renderer, av, px);
  }
  const ErrorStats raw = Errors(av, ref, px.Valid, px.Layer1, 1.0);
  res.A.Rmse = raw.Rmse;
  res.A.Mae = raw.Mae;
  res.A.RmseLayer1 = raw.RmseLayer1;
  res.A.Bias = raw.Bias;
  res.A.Gamma = FitGamma(av, ref, px.Valid, px.Layer1);
  const ErrorStats cal = Errors(av, ref, px.Valid, px.Layer1, res.A.Gamma);
  res.A.CRmse = cal.Rmse;
  res.A.CMae = cal.Mae;
  res.A.CRmseLayer1 = cal.RmseLayer1;
  res.A.CRmseBorder = Errors(av, ref, px.Border, px.Border, res.A.Gamma).Rmse;
  res.A.BorderPixels = px.BorderCount;
  return res;
}

/// The error map of AV - AV_ref (colour map 0..0.5).
bool WriteAVErrorMap(
  const Options& o, const Method& m, const AccuracyFrame& frame, const std::vector<float>& av)
{
  std::vector<float> error(av.size());
  for (size_t i = 0; i < av.size(); ++i)
  {
    error[i] = av[i] - frame.Reference[i];
  }
  std::string message;
  if (!WriteErrorMap(ErrorMapFile(o.Output, frame.Scene, m.Name), frame.Width, frame.Height, error,
        frame.Pixels.Valid, 0.5, message))
  {
    return Report(Program, message);
  }
  return true;
}

/// For every two-layer setting and every one-layer setting with the same N
/// and BlurRadius: the pixels where the second layer changes AV.
void CompareLayers(const std::vector<Method>& methods, const AccuracyFrame& frame,
  const std::vector<Result>& results, const std::vector<std::vector<float>>& av,
  std::vector<SecondLayerEffect>& effects)
{
  const PixelMasks& px = frame.Pixels;
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
      std::vector<unsigned char> changed(px.Valid.size(), 0);
      SecondLayerEffect e{ frame.Scene, m2.Name, m1.Name, 0, px.ValidCount };
      for (size_t i = 0; i < changed.size(); ++i)
      {
        if (px.Valid[i] && std::fabs(av[two][i] - av[one][i]) > SecondLayerChange)
        {
          changed[i] = 1;
          ++e.Changed;
        }
      }
      e.RmseOne = Errors(av[one], frame.Reference, changed, changed, 1.0).Rmse;
      e.RmseTwo = Errors(av[two], frame.Reference, changed, changed, 1.0).Rmse;
      e.CalibratedRmseOne =
        Errors(av[one], frame.Reference, changed, changed, results[one].A.Gamma).Rmse;
      e.CalibratedRmseTwo =
        Errors(av[two], frame.Reference, changed, changed, results[two].A.Gamma).Rmse;
      effects.push_back(e);
    }
  }
}

/// Every method's accuracy on `frame` (into `results`, with its error map),
/// then the second layer's effects.
bool MeasureAccuracy(const Options& o, const View& view,
  const std::vector<vtkSmartPointer<vtkRenderPass>>& passes, const AccuracyFrame& frame,
  std::vector<Result>& results, std::vector<SecondLayerEffect>& effects)
{
  std::vector<std::vector<float>> av(o.Methods.size());
  for (size_t k = 0; k < o.Methods.size(); ++k)
  {
    results.push_back(MeasureMethod(view, o.Methods[k], passes[k], frame, av[k]));
    if (o.ErrorMaps && !WriteAVErrorMap(o, o.Methods[k], frame, av[k]))
    {
      return false;
    }
  }
  CompareLayers(o.Methods, frame, results, av, effects);
  return true;
}

/// Accuracy, then time, of every method on the scene `sceneSpec`.
bool MeasureScene(const Options& o, const std::string& sceneSpec, Measurements& measured)
{
  View view;
  SceneSetup scene;
  vtkSmartPointer<vtkObject> keep;
  if (!OpenView(Program, o.Backend, o.AccuracyWidth, o.AccuracyHeight, view) ||
    !LoadScene(o, sceneSpec, view.Renderer, scene, keep))
  {
    return false;
  }
  const double r = o.RadiusFraction * Diagonal(scene.Geometry);
  const std::vector<vtkSmartPointer<vtkRenderPass>> passes = MakePasses(o.Methods, r);
  vtkNew<vtkDeepGBufferPass> gbuffer;
  gbuffer->SetNumberOfLayers(2);

  AccuracyFrame frame;
  // The built-in scene's name, or the user's file name (its iso-value).
  frame.Scene = scene.Name;
  frame.Width = o.AccuracyWidth;
  frame.Height = o.AccuracyHeight;
  std::vector<Result> results;
  if (!CaptureAccuracyFrame(view, gbuffer, frame, measured.Device) ||
    !ComputeReference(o, scene.Geometry, r, frame) ||
    !MeasureAccuracy(o, view, passes, frame, results, measured.Effects))
  {
    return false;
  }
  const std::vector<double> plainMs = TimeMethods(view, o, { nullptr, gbuffer }, passes, results);
  measured.Results.insert(measured.Results.end(), results.begin(), results.end());
  const PixelMasks& px = frame.Pixels;
  measured.Scenes.push_back({ frame.Scene, scene.Geometry->GetNumberOfPolys(), r,
    frame.ReferenceError, plainMs[0], plainMs[1], px.ValidCount, px.Excluded, px.Layer1Count,
    frame.ReferenceSeconds, vtkDeepGICameraText::Write(view.Renderer->GetActiveCamera()) });

  view.Renderer->SetPass(nullptr);
  for (const auto& pass : passes)
  {
    pass->ReleaseGraphicsResources(view.Window);
  }
  gbuffer->ReleaseGraphicsResources(view.Window);
  std::fprintf(stderr, "%s: scene %s done\n", Program, frame.Scene.c_str());
  return true;
}

/// The settings of the run and the table of the scenes.
std::string SceneTable(const Options& o, const Measurements& measured)
{
  std::ostringstream md;
  md
    << "Accuracy at " << o.AccuracyWidth << "x" << o.AccuracyHeight << ", time at " << o.Width
    << "x" << o.Height << " (median of " << o.Frames * o.Rounds << " frames per method, "
    << o.Rounds << " rounds, after " << o.Warmup
    << " warm-up frames per round); OpenGL renderer: " << measured.Device << ".\n"
    << "r = " << o.RadiusFraction
    << " x scene diagonal for every method; vtkSSAOPass: Radius r, Bias 0.02 r, Blur on; "
       "ours: Radius r and the pass's defaults (Bias 0.01 r, Epsilon 1e-4 r^2, estimator "
       "VISIBILITY_BITMASK unless the method says otherwise); reference: Embree, "
    << o.Samples
    << " rays per pixel, beta = eps = 0 (the obscurance itself), on the G-buffer capture of the "
       "same frame (layer 0).\nAV of a method = luminance(method) / luminance(plain) on white "
       "ambient-only surfaces (plain = VTK for vtkSSAOPass, the G-buffer pass alone for ours).\n\n";
  md << "| scene | triangles | r | valid px | excluded px | layer-1 px | reference std. error | "
        "reference [s] | VTK frame [ms] | G-buffer (2 layers) frame [ms] | camera (--camera) "
        "|\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const SceneInfo& s : measured.Scenes)
  {
    // The name and the camera are of any length: streamed, not formatted.
    char b[256];
    std::snprintf(b, sizeof(b), " | %lld | %.4g | %ld | %ld | %ld | %.4f | %.1f | %.2f | %.2f | ",
      static_cast<long long>(s.Triangles), s.Radius, s.Valid, s.Excluded, s.Layer1, s.RefError,
      s.ReferenceSeconds, s.PlainMs, s.GBufferMs);
    md << "| " << s.Name << b << s.Camera << " |\n";
  }
  return md.str();
}

/// Frame time of VTK without a pass on `scene`.
double PlainMs(const Measurements& measured, const std::string& scene)
{
  double plainMs = 0;
  for (const SceneInfo& s : measured.Scenes)
  {
    if (s.Name == scene)
    {
      plainMs = s.PlainMs;
    }
  }
  return plainMs;
}

/// The table of every scene and method.
std::string ResultTable(const Measurements& measured)
{
  std::ostringstream md;
  md << "\n| scene | method | frame [ms] | AO cost [ms] | RMSE | MAE | bias | RMSE layer-1 px | "
        "gamma | RMSE cal. | MAE cal. | RMSE cal. layer-1 px | mean AV | ratio vs captured AV |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Result& r : measured.Results)
  {
    char b[1024];
    std::snprintf(b, sizeof(b),
      "| %s | %s | %.2f | %.2f | %.4f | %.4f | %+.4f | %.4f | %.2f | %.4f | %.4f | %.4f | %.3f | "
      "%s |\n",
      r.Scene.c_str(), r.M.Name.c_str(), r.FrameMs, r.FrameMs - PlainMs(measured, r.Scene),
      r.A.Rmse, r.A.Mae, r.A.Bias, r.A.RmseLayer1, r.A.Gamma, r.A.CRmse, r.A.CMae, r.A.CRmseLayer1,
      r.A.MeanAV, r.A.CaptureDifference < 0 ? "" : Fmt("%.4f", r.A.CaptureDifference).c_str());
    md << b;
  }
  return md.str();
}

/// The CSV file: a row per scene and method.
std::string Csv(const Measurements& measured)
{
  std::ostringstream csv;
  csv << "scene,method,family,kind,samples,layers,blur,frame_ms,ao_cost_ms,rmse,mae,bias,"
         "rmse_layer1,gamma,rmse_cal,mae_cal,rmse_cal_layer1,mean_av,capture_difference\n";
  for (const Result& r : measured.Results)
  {
    const double plainMs = PlainMs(measured, r.Scene);
    char b[1024];
    std::snprintf(b, sizeof(b),
      // Text fields are quoted: method names may contain commas.
      "\"%s\",\"%s\",\"%s\",%s,%d,%d,%d,%.4f,%.4f,%.5f,%.5f,%.5f,%.5f,%.4f,%.5f,%.5f,%.5f,%.4f,"
      "%s\n",
      r.Scene.c_str(), r.M.Name.c_str(), r.M.Family.c_str(), r.M.Kind == 0 ? "ssao" : "ours",
      r.M.Parameter, r.M.Kind == 0 ? 0 : r.M.Layers, r.M.Blur, r.FrameMs, r.FrameMs - plainMs,
      r.A.Rmse, r.A.Mae, r.A.Bias, r.A.RmseLayer1, r.A.Gamma, r.A.CRmse, r.A.CMae, r.A.CRmseLayer1,
      r.A.MeanAV, r.A.CaptureDifference < 0 ? "" : Fmt("%.5f", r.A.CaptureDifference).c_str());
    csv << b;
  }
  return csv.str();
}

/// Goal 1 on `scene`: for every SSAO setting, the best two-layer RMSE at
/// no more than its time over its RMSE; the worst of them against 0.6.
std::string GoalOne(const std::vector<Result>& results, const std::string& scene,
  const std::function<double(const Result&)>& rmse)
{
  std::ostringstream g1;
  double worst = -1;
  bool missing = false;
  for (const Result& a : results)
  {
    if (a.Scene != scene || a.M.Kind != 0)
    {
      continue;
    }
    double best = -1;    // best 2-layer RMSE at <= a's time
    double bestAny = -1; // best 2-layer RMSE at any time
    for (const Result& b : results)
    {
      if (b.Scene == scene && b.M.Kind == 1 && b.M.Layers == 2)
      {
        best = b.FrameMs <= a.FrameMs && (best < 0 || rmse(b) < best) ? rmse(b) : best;
        bestAny = bestAny < 0 || rmse(b) < bestAny ? rmse(b) : bestAny;
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
  return (worst < 0 ? std::string("n/a") : Fmt("%.2f", worst)) +
    (worst >= 0 && worst <= 0.6 && !missing ? " (met)" : " (missed)") + " [" + g1.str() + "]";
}

/// Goal 2 on `scene`: per N, the layer-1 RMSE of two layers over one layer
/// (<= 0.8) and the time ratio (<= 1.3).
std::string GoalTwo(const std::vector<Result>& results, const std::string& scene,
  const std::function<double(const Result&)>& rmse1)
{
  std::ostringstream g2;
  for (const Result& two : results)
  {
    if (two.Scene != scene || two.M.Kind != 1 || two.M.Layers != 2)
    {
      continue;
    }
    for (const Result& one : results)
    {
      if (one.Scene == scene && one.M.Kind == 1 && one.M.Layers == 1 &&
        one.M.Parameter == two.M.Parameter && one.M.Blur == two.M.Blur)
      {
        const double er = rmse1(two) / std::max(1e-9, rmse1(one));
        const double tr = two.FrameMs / std::max(1e-9, one.FrameMs);
        g2 << two.M.Name << ": " << Fmt("%.2f", er) << " / " << Fmt("%.2f", tr)
           << (er <= 0.8 && tr <= 1.3 ? " met" : " missed") << "; ";
      }
    }
  }
  return g2.str();
}

std::string GoalsSection(const Measurements& measured)
{
  std::ostringstream md;
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
    for (const SceneInfo& s : measured.Scenes)
    {
      md << "| " << s.Name << " | " << GoalOne(measured.Results, s.Name, rmse) << " | "
         << GoalTwo(measured.Results, s.Name, rmse1) << " |\n";
    }
  }
  return md.str();
}

std::string BorderSection(const Measurements& measured)
{
  std::ostringstream md;
  md << "\n### The frame's border\n\n"
     << "Calibrated RMSE on all valid pixels and on those within " << BorderFraction
     << " of the height of the frame's edge, where the screen-space methods lack the "
        "occluders outside the view unless the G-buffer has a guard band.\n\n"
     << "| scene | method | frame [ms] | RMSE cal. | RMSE cal. border | border px |\n"
        "|---|---|---|---|---|---|\n";
  for (const Result& r : measured.Results)
  {
    md << "| " << r.Scene << " | " << r.M.Name << " | " << Fmt("%.2f", r.FrameMs) << " | "
       << Fmt("%.4f", r.A.CRmse) << " | " << Fmt("%.4f", r.A.CRmseBorder) << " | "
       << r.A.BorderPixels << " |\n";
  }
  return md.str();
}

std::string SecondLayerSection(const Measurements& measured)
{
  std::ostringstream md;
  md << "\n### Where the second layer changes AV\n\n"
     << "Pixels where a two-layer setting's AV differs by more than " << SecondLayerChange
     << " from the one-layer setting with the same N and BlurRadius, and the raw and the "
        "calibrated RMSE of both on those pixels only.\n\n"
     << "| scene | two layers | one layer | changed px | of valid px | RMSE 1 layer | "
        "RMSE 2 layers | 2 layers / 1 layer | RMSE cal. 1 layer | RMSE cal. 2 layers "
        "|\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (const SecondLayerEffect& e : measured.Effects)
  {
    md << "| " << e.Scene << " | " << e.TwoLayers << " | " << e.OneLayer << " | " << e.Changed
       << " | " << e.Valid << " | " << Fmt("%.4f", e.RmseOne) << " | " << Fmt("%.4f", e.RmseTwo)
       << " | " << Fmt("%.2f", e.RmseTwo / e.RmseOne) << " | " << Fmt("%.4f", e.CalibratedRmseOne)
       << " | " << Fmt("%.4f", e.CalibratedRmseTwo) << " |\n";
  }
  return md.str();
}

/// The markdown file (also printed on stdout).
std::string Markdown(const Options& o, const Measurements& measured)
{
  return SceneTable(o, measured) + ResultTable(measured) + GoalsSection(measured) +
    BorderSection(measured) + SecondLayerSection(measured);
}

/// RMSE of AV (gamma-calibrated) against the frame time, one curve per method family.
ErrorTimePlots Plots(const Options& o, const Measurements& measured)
{
  return MakeErrorTimePlots("Ambient obscurance: error vs time",
    "RMSE of AV vs ray-traced reference (gamma-calibrated)", o.Methods, measured.Scenes,
    measured.Results, CurveOf, [](const Result& r) { return r.A.CRmse; });
}
}

int main(int argc, char* argv[])
{
  const AccuracyBenchmark<Options, Measurements> stages{ Program, "benchmark-ao", ParseOptions,
    Usage, MeasureScene, Markdown, Csv, Plots };
  return RunAccuracyBenchmark(stages, argc, argv);
}
