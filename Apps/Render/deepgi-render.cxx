// deepgi-render: the main job. Renders a scene twice at one still camera,
// as plain VTK and through vtkDeepGIPass (direct + AV * ambient + indirect
// light + reflections), converges the GI image until it stops changing,
// and writes the images and figures that show what global illumination
// changed. Run with --help for the options.

#include "DeepGIOutput.h"
#include "DeepGIRenderFigures.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkDeepAmbientObscurancePass.h"
#include "vtkDeepGBufferPass.h"
#include "vtkDeepGICameraText.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIDemoScene.h"
#include "vtkDeepGIPass.h"
#include "vtkDeepGIRenderWindowFactory.h"
#include "vtkDeepGISceneLoader.h"
#include "vtkDeepRadiosityPass.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <vtksys/SystemInformation.hxx>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
namespace Fig = DeepGIRenderFigures;

constexpr int ExitUsage = 2;
constexpr int ExitFailure = 1;

// The files this program writes; all are removed before a run, so that a
// failed or differently configured run never leaves old ones beside new.
const char* const OutputFiles[] = { "plain.png", "gi.png", "compare.png", "gbuffer.png" };

const char* Usage = R"(Usage: deepgi-render [options]

Renders a scene with global illumination (vtkDeepGIPass: deep G-buffer
ambient obscurance, screen-space radiosity and mirror reflections, Mara et
al. HPG 2016) beside plain VTK, at one still camera, and writes into the
output directory:
  plain.png     the scene as plain VTK renders it
  gi.png        the same view through vtkDeepGIPass, converged
  compare.png   plain | GI on top; what GI changed below: the ambient
                visibility (white: open, dark: occluded) and the indirect
                light it added (scaled to be visible; the factor is shown)
  gbuffer.png   the G-buffer's layers as one contact sheet (rows: layers;
                columns: direct radiance, depth, normal, albedo)
The GI image is converged: frames are rendered at the still camera until
one changes the image by at most --tolerance (mean over the pixels and
RGB channels) or --max-frames is reached. Progress is printed per frame.

Global illumination:
  --preset NAME       high_performance, balanced (default), high_quality,
                      or off (plain VTK and the G-buffer only)
  --effects LIST      the effects switched on: a comma-separated subset of
                      ao, radiosity, reflections, or all (default). Each
                      still runs only where the scene needs it.
  --radius F          gather radius of obscurance and radiosity as a
                      fraction of the scene's diagonal (default: the
                      passes' own, 0.05 for obscurance and 0.5 for
                      radiosity); larger gives broader shadows and light
  --exposure E        multiplies every light's intensity, in both images
                      (default 1): raise it for a dark result
  --tolerance T       convergence threshold: the largest mean change of the
                      last frame, in 8-bit levels (default 0.07; the demo
                      scene's change falls from 0.11 to a floor of about
                      0.06 over 10 frames, where the image is within 0.25
                      levels of 24 converged frames on average); 0 renders
                      all --max-frames frames
  --max-frames N      at most N GI frames, 1 to 10000 (default 16)
  --guard-band B      the G-buffer's guard band, a fraction of the image
                      height added on each side, 0 to 0.5 (default 0.1)

Scene (default: the built-in demo scene, a room with columns in front of
banners, mouldings, a decal and a thin panel):
  --mesh FILE         load a mesh: .ply .obj (with its .mtl colours) .vtp
                      .vtk .stl; may be given several times
  --volume PATH       load a volume and render its iso-surface: .vti .mhd
                      .mha .nhdr .nrrd, a directory holding one of them, or
                      a slice-series prefix such as .../headsq/quarter
  --iso VALUE         iso-value for --volume (default 500)
  --triangles N       demo scene: at least N triangles (default 10000)
  --scale S           demo scene: uniform scale factor (default 1)
  --view NAME         demo scene: the camera, one of default, overview,
                      columns, decal, panel (default: default)
  --camera PX,PY,PZ,FX,FY,FZ,UX,UY,UZ[,A]
                      the camera, for any scene: position, focal point,
                      view-up and view angle in degrees (default 30), the
                      values ParaView's Adjust Camera dialog shows. The
                      camera rendered is printed in this form.

Deep G-buffer:
  --layers K          layers with --preset off, 1 to 8 (default 2); the GI
                      pass chooses 1 or 2 itself
  --dz VALUE          minimum separation between layers in world units
                      (default: automatic, 1.5 % of the scene's diagonal)
  --oracle NAME       depth_peel, previous, reproject, predict, delay or
                      automatic (default: depth_peel on a CPU renderer,
                      reproject on a GPU)

Output:
  --size WxH          image size in pixels (default 640x480)
  --backend NAME      auto, x11 or egl (default auto: x11 when an X display
                      can be opened, else egl)
  --output DIR        output directory, created if needed (default output)
  --help              print this text and exit

Exit status: 0 on success, 1 when loading, rendering or writing fails,
2 for bad options.
)";

struct Options
{
  std::vector<std::string> Meshes;
  std::string Volume;
  double Iso = 500.0;
  bool IsoGiven = false;
  long long Triangles = 10000;
  double Scale = 1.0;
  std::string View = "default";
  bool ViewGiven = false;
  std::string Camera; // --camera's text, empty for the scene's own camera
  int Layers = 2;
  bool LayersGiven = false;
  double Dz = -1.0; // < 0: automatic
  int Oracle = vtkDeepGBufferPass::AUTOMATIC;
  int Width = 640;
  int Height = 480;
  std::string Backend = "auto";
  std::string Output = "output";
  int Preset = vtkDeepGIPass::BALANCED; // -1: off
  std::string Effects = "all";
  int EffectMask =
    vtkDeepGIPass::AMBIENT_OBSCURANCE | vtkDeepGIPass::RADIOSITY | vtkDeepGIPass::REFLECTIONS;
  double RadiusFraction = -1.0; // < 0: the passes' defaults
  double Exposure = 1.0;
  double Tolerance = 0.07; // 8-bit levels
  int MaximumFrames = 16;
  double GuardBand = vtkDeepRadiosityPass::DEFAULT_GUARD_BAND;
  bool GiOptionGiven = false;

  bool Loaded() const { return !this->Meshes.empty() || !this->Volume.empty(); }
};

bool ParseInteger(const std::string& text, long long minimum, long long maximum, long long& value)
{
  if (text.empty())
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(text.c_str(), &end, 10);
  if (errno != 0 || *end != '\0' || v < minimum || v > maximum)
  {
    return false;
  }
  value = v;
  return true;
}

bool ParseReal(const std::string& text, double& value)
{
  if (text.empty())
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if (errno != 0 || *end != '\0' || !std::isfinite(v))
  {
    return false;
  }
  value = v;
  return true;
}

bool ParseSize(const std::string& value, int& width, int& height)
{
  const size_t x = value.find_first_of("xX");
  long long w = 0, h = 0;
  if (x == std::string::npos || !ParseInteger(value.substr(0, x), 1, 16384, w) ||
    !ParseInteger(value.substr(x + 1), 1, 16384, h))
  {
    return false;
  }
  width = static_cast<int>(w);
  height = static_cast<int>(h);
  return true;
}

// One option's value into `o`: returns "" or what is wrong with the value.
using OptionHandler = std::string (*)(const std::string& value, Options& o);

struct OptionEntry
{
  const char* Name;
  OptionHandler Handle;
};

const OptionEntry OptionTable[] = {
  { "--preset",
    [](const std::string& v, Options& o) -> std::string
    {
      o.Preset = v == "off" ? -1 : vtkDeepGIPass::GetPresetFromString(v.c_str());
      return v == "off" || o.Preset >= 0 ? ""
                                         : "needs high_performance, balanced, high_quality or off";
    } },
  { "--effects",
    [](const std::string& v, Options& o) -> std::string
    {
      o.Effects = v;
      o.GiOptionGiven = true;
      return vtkDeepGIPass::ParseEffects(v.c_str(), o.EffectMask) && o.EffectMask != 0
        ? ""
        : "needs a comma-separated list of distinct ao, radiosity, reflections, or all";
    } },
  { "--radius",
    [](const std::string& v, Options& o) -> std::string
    {
      o.GiOptionGiven = true;
      return ParseReal(v, o.RadiusFraction) && o.RadiusFraction > 0.0 && o.RadiusFraction <= 1.0
        ? ""
        : "needs a fraction of the scene's diagonal in (0, 1]";
    } },
  { "--exposure",
    [](const std::string& v, Options& o) -> std::string
    {
      return ParseReal(v, o.Exposure) && o.Exposure > 0.0 && o.Exposure <= 1000.0
        ? ""
        : "needs a factor in (0, 1000]";
    } },
  { "--tolerance",
    [](const std::string& v, Options& o) -> std::string
    {
      o.GiOptionGiven = true;
      return ParseReal(v, o.Tolerance) && o.Tolerance >= 0.0 && o.Tolerance <= 255.0
        ? ""
        : "needs a number of 8-bit levels from 0 to 255";
    } },
  { "--max-frames",
    [](const std::string& v, Options& o) -> std::string
    {
      long long n = 0;
      o.GiOptionGiven = true;
      o.MaximumFrames = ParseInteger(v, 1, 10000, n) ? static_cast<int>(n) : 0;
      return o.MaximumFrames > 0 ? "" : "needs an integer from 1 to 10000";
    } },
  { "--guard-band",
    [](const std::string& v, Options& o) -> std::string
    {
      o.GiOptionGiven = true;
      return ParseReal(v, o.GuardBand) && o.GuardBand >= 0.0 &&
          o.GuardBand <= vtkDeepGBufferPass::MAXIMUM_GUARD_BAND
        ? ""
        : "needs a number from 0 to 0.5";
    } },
  { "--mesh",
    [](const std::string& v, Options& o) -> std::string
    {
      o.Meshes.push_back(v);
      return "";
    } },
  { "--volume",
    [](const std::string& v, Options& o) -> std::string
    {
      const bool first = o.Volume.empty();
      o.Volume = v;
      return first ? "" : "is given twice";
    } },
  { "--iso",
    [](const std::string& v, Options& o) -> std::string
    {
      o.IsoGiven = true;
      return ParseReal(v, o.Iso) ? "" : "needs a finite number";
    } },
  { "--triangles",
    [](const std::string& v, Options& o) -> std::string
    {
      return ParseInteger(v, 0, 500000000, o.Triangles) ? ""
                                                        : "needs an integer from 0 to 500000000";
    } },
  { "--scale",
    [](const std::string& v, Options& o) -> std::string
    { return ParseReal(v, o.Scale) && o.Scale > 0.0 ? "" : "needs a positive number"; } },
  { "--view",
    [](const std::string& v, Options& o) -> std::string
    {
      o.View = v;
      o.ViewGiven = true;
      for (int i = 0; i < vtkDeepGIDemoScene::GetNumberOfNamedViews(); ++i)
      {
        if (v == vtkDeepGIDemoScene::GetNamedViewName(i))
        {
          return "";
        }
      }
      return "needs one of default, overview, columns, decal, panel";
    } },
  { "--camera",
    [](const std::string& v, Options& o) -> std::string
    {
      vtkNew<vtkCamera> camera;
      const std::string problem = vtkDeepGICameraText::Apply(v.c_str(), camera);
      o.Camera = v;
      return problem.empty() ? "" : "is not a camera (" + problem + ")";
    } },
  { "--layers",
    [](const std::string& v, Options& o) -> std::string
    {
      long long n = 0;
      o.LayersGiven = true;
      o.Layers = ParseInteger(v, 1, vtkDeepGBufferPass::MAXIMUM_NUMBER_OF_LAYERS, n)
        ? static_cast<int>(n)
        : 0;
      return o.Layers > 0 ? "" : "needs an integer from 1 to 8";
    } },
  { "--dz",
    [](const std::string& v, Options& o) -> std::string
    { return ParseReal(v, o.Dz) && o.Dz >= 0.0 ? "" : "needs a number >= 0 (world units)"; } },
  { "--oracle",
    [](const std::string& v, Options& o) -> std::string
    {
      o.Oracle = vtkDeepGBufferPass::GetOracleFromString(v.c_str());
      return o.Oracle >= 0 ? ""
                           : "needs depth_peel, previous, reproject, predict, delay or automatic";
    } },
  { "--size",
    [](const std::string& v, Options& o) -> std::string
    { return ParseSize(v, o.Width, o.Height) ? "" : "needs WIDTHxHEIGHT, each 1 to 16384"; } },
  { "--backend",
    [](const std::string& v, Options& o) -> std::string
    {
      o.Backend = v;
      return vtkDeepGIRenderWindowFactory::GetBackendFromString(v.c_str()) >= 0
        ? ""
        : "needs auto, x11 or egl";
    } },
  { "--output",
    [](const std::string& v, Options& o) -> std::string
    {
      o.Output = v;
      return v.empty() ? "needs a directory name" : "";
    } },
};

// Options that only make sense together.
std::string CheckCombinations(const Options& o)
{
  if (o.Preset < 0 && o.GiOptionGiven)
  {
    return "--effects, --radius, --tolerance, --max-frames and --guard-band need a preset "
           "(not --preset off)";
  }
  if (o.Preset >= 0 && o.LayersGiven)
  {
    return "--layers is for --preset off; the GI pass chooses 1 or 2 layers itself";
  }
  if (o.IsoGiven && o.Volume.empty())
  {
    return "--iso is only used with --volume";
  }
  if (o.Loaded() && o.ViewGiven)
  {
    return "--view is for the demo scene; loaded data gets a still camera framing it";
  }
  if (o.ViewGiven && !o.Camera.empty())
  {
    return "--view and --camera both choose the camera; give one";
  }
  return "";
}

// Returns 0 to go on, or an exit status (help printed: 0 through `exitNow`).
int ParseOptions(int argc, char* argv[], Options& o, bool& exitNow)
{
  exitNow = false;
  auto bad = [](const std::string& message)
  {
    std::cerr << "deepgi-render: " << message << "\nRun 'deepgi-render --help' for the options.\n";
    return ExitUsage;
  };
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h")
    {
      std::cout << Usage;
      exitNow = true;
      return 0;
    }
    const OptionEntry* entry = nullptr;
    for (const OptionEntry& e : OptionTable)
    {
      entry = arg == e.Name ? &e : entry;
    }
    if (!entry)
    {
      return bad("unknown option '" + arg + "'");
    }
    if (i + 1 >= argc)
    {
      return bad("option " + arg + " needs a value");
    }
    const std::string value = argv[++i];
    const std::string problem = entry->Handle(value, o);
    if (!problem.empty())
    {
      return bad(arg + " " + problem + ", got '" + value + "'");
    }
  }
  const std::string conflict = CheckCombinations(o);
  return conflict.empty() ? 0 : bad(conflict);
}

// The scene on the renderer, with its camera; keeps the object that owns it.
struct Scene
{
  vtkNew<vtkDeepGIDemoScene> Demo;
  vtkNew<vtkDeepGISceneLoader> Loader;
  vtkIdType Triangles = 0;
  std::string Description;
};

// Whether the demo scene of `triangles` triangles fits in the memory the
// host has free: measured about 100 bytes per triangle (the polydata, its
// normals and the OpenGL copies; 4 million triangles: 520 MB in all), so
// 120 bytes and a 200 MB base are asked for. Without the check a large
// --triangles ends in an uncaught std::bad_alloc or the kernel's OOM killer.
bool DemoSceneFits(long long triangles)
{
  // DEEPGI_HOST_MEMORY_KIB, when set, limits the host's memory (KiB).
  vtksys::SystemInformation host;
  const long long totalKiB = host.GetHostMemoryAvailable("DEEPGI_HOST_MEMORY_KIB");
  const long long freeKiB = std::max(0LL, totalKiB - host.GetHostMemoryUsed());
  const double neededGiB = (200.0e6 + 120.0 * static_cast<double>(triangles)) / (1 << 30);
  const double freeGiB = static_cast<double>(freeKiB) / (1 << 20);
  if (totalKiB > 0 && neededGiB > freeGiB)
  {
    std::cerr << "deepgi-render: --triangles " << triangles << " needs about " << std::fixed
              << std::setprecision(1) << neededGiB << " GiB of memory; " << freeGiB
              << " GiB are free\n";
    return false;
  }
  return true;
}

// The demo scene or the user's data, with the scene's own camera.
bool PopulateScene(const Options& o, vtkRenderer* renderer, Scene& scene)
{
  if (!o.Loaded())
  {
    if (!DemoSceneFits(o.Triangles))
    {
      return false;
    }
    scene.Demo->SetTargetNumberOfTriangles(o.Triangles);
    scene.Demo->SetScaleFactor(o.Scale);
    scene.Demo->Populate(renderer);
    scene.Demo->SetCameraToNamedView(renderer->GetActiveCamera(), o.View.c_str());
    scene.Triangles = scene.Demo->GetNumberOfTriangles();
    scene.Description = "demo scene, view " + o.View;
    return true;
  }
  for (const std::string& mesh : o.Meshes)
  {
    if (!scene.Loader->LoadMesh(mesh.c_str()))
    {
      std::cerr << "deepgi-render: cannot load the mesh " << mesh << "\n";
      return false;
    }
  }
  if (!o.Volume.empty())
  {
    if (!scene.Loader->LoadVolume(o.Volume.c_str(), o.Iso))
    {
      std::cerr << "deepgi-render: cannot load the volume " << o.Volume << "\n";
      return false;
    }
    if (o.Meshes.empty())
    {
      // CT data such as headsq: look at the face (from +y), head up (-z).
      scene.Loader->SetViewDirection(0.0, -1.0, 0.0);
      scene.Loader->SetViewUp(0.0, 0.0, -1.0);
    }
  }
  scene.Loader->Populate(renderer);
  scene.Loader->ResetCamera(renderer);
  scene.Triangles = scene.Loader->GetNumberOfTriangles();
  scene.Description = "loaded data";
  return true;
}

// The scene, with its own camera or the user's (--camera, checked with the
// options).
bool LoadScene(const Options& o, vtkRenderer* renderer, Scene& scene)
{
  if (!PopulateScene(o, renderer, scene))
  {
    return false;
  }
  if (!o.Camera.empty())
  {
    vtkDeepGICameraText::Apply(o.Camera.c_str(), renderer->GetActiveCamera());
    renderer->ResetCameraClippingRange();
  }
  return true;
}

// Scales every light of the renderer (VTK's automatic headlight included,
// created here) so that plain VTK and GI see the same exposure.
void ApplyExposure(vtkRenderer* renderer, double exposure)
{
  if (renderer->GetLights()->GetNumberOfItems() == 0)
  {
    renderer->CreateLight();
  }
  vtkLightCollection* lights = renderer->GetLights();
  lights->InitTraversal();
  while (vtkLight* light = lights->GetNextItem())
  {
    light->SetIntensity(light->GetIntensity() * exposure);
  }
}

// Removes this program's outputs from an earlier run.
bool PrepareOutput(const std::string& dir)
{
  std::string error;
  if (!DeepGIOutput::PrepareDirectory(dir, error))
  {
    std::cerr << "deepgi-render: " << error << "\n";
    return false;
  }
  for (const char* name : OutputFiles)
  {
    const std::string path = dir + "/" + name;
    if (vtksys::SystemTools::FileExists(path) && !vtksys::SystemTools::RemoveFile(path))
    {
      std::cerr << "deepgi-render: cannot remove the old " << path << "\n";
      return false;
    }
  }
  return true;
}

double Milliseconds(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since)
    .count();
}

// Plain VTK: the renderer's own passes, one frame (the second, so that the
// first-frame set-up is not timed).
vtkSmartPointer<vtkImageData> RenderPlain(vtkRenderWindow* window, double& milliseconds)
{
  window->Render();
  const auto start = std::chrono::steady_clock::now();
  window->Render();
  milliseconds = Milliseconds(start);
  std::cout << "  plain VTK: " << std::fixed << std::setprecision(1) << milliseconds
            << " ms per frame\n";
  return Fig::GrabWindow(window);
}

// Prints "frame k of N" with the frame's time and change while converging.
struct ProgressPrinter
{
  vtkDeepGIPass* Pass = nullptr;
  int MaximumFrames = 0;
  int Frame = 0;
  std::chrono::steady_clock::time_point Last;

  static void Print(vtkObject*, unsigned long, void* clientData, void*)
  {
    auto* self = static_cast<ProgressPrinter*>(clientData);
    ++self->Frame;
    std::cout << "  GI frame " << self->Frame << " of at most " << self->MaximumFrames << ": "
              << std::fixed << std::setprecision(1) << Milliseconds(self->Last) << " ms";
    const double change = self->Pass->GetLastConvergenceChange();
    if (change >= 0.0)
    {
      std::cout << ", change " << std::setprecision(3) << 255.0 * change << "/255";
    }
    std::cout << (self->Frame == 1 ? " (includes shader compilation)" : "") << std::endl;
    self->Last = std::chrono::steady_clock::now();
  }
};

void ConfigureGI(const Options& o, vtkDeepGIPass* gi)
{
  gi->SetPreset(o.Preset);
  gi->SetAmbientObscurance((o.EffectMask & vtkDeepGIPass::AMBIENT_OBSCURANCE) != 0);
  gi->SetRadiosity((o.EffectMask & vtkDeepGIPass::RADIOSITY) != 0);
  gi->SetReflections((o.EffectMask & vtkDeepGIPass::REFLECTIONS) != 0);
  gi->GetGBufferPass()->SetOracle(o.Oracle);
  gi->GetGBufferPass()->SetGuardBand(o.GuardBand);
  if (o.Dz >= 0.0)
  {
    gi->GetGBufferPass()->SetMinimumSeparation(o.Dz);
  }
  if (o.RadiusFraction > 0.0)
  {
    gi->GetAmbientObscurancePass()->SetAutomaticRadiusFraction(o.RadiusFraction);
    gi->GetRadiosityPass()->SetAutomaticRadiusFraction(o.RadiusFraction);
  }
}

// The GI image, converged at the still camera; returns the frames rendered.
int ConvergeGI(const Options& o, vtkRenderer* renderer, vtkDeepGIPass* gi)
{
  ProgressPrinter printer;
  printer.Pass = gi;
  printer.MaximumFrames = o.MaximumFrames;
  printer.Last = std::chrono::steady_clock::now();
  vtkNew<vtkCallbackCommand> progress;
  progress->SetCallback(&ProgressPrinter::Print);
  progress->SetClientData(&printer);
  const unsigned long tag = gi->AddObserver(vtkCommand::ProgressEvent, progress);
  renderer->SetPass(gi);
  const int frames = gi->Converge(renderer, o.MaximumFrames, o.Tolerance / 255.0);
  gi->RemoveObserver(tag);
  return frames;
}

// compare.png: plain | GI over ambient visibility | indirect light.
vtkSmartPointer<vtkImageData> CompareFigure(
  vtkImageData* plain, vtkImageData* gi, vtkDeepGIPass* pass, vtkRenderer* renderer)
{
  int dims[3];
  plain->GetDimensions(dims);
  const int ran = pass->GetLastFrameEffects();
  vtkSmartPointer<vtkImageData> visibility, indirect;
  double scale = 1.0;
  vtkNew<vtkImageData> capture;
  if ((ran & vtkDeepGIPass::AMBIENT_OBSCURANCE) &&
    pass->GetAmbientObscurancePass()->CaptureAmbientVisibility(capture, renderer))
  {
    visibility = Fig::Panel(capture, vtkDeepGICaptureNames::AmbientVisibility,
      vtkDeepGICaptureNames::Valid, Fig::Mapping::Grey);
  }
  if ((ran & vtkDeepGIPass::RADIOSITY) &&
    pass->GetRadiosityPass()->CaptureIrradiance(capture, renderer))
  {
    indirect = Fig::Panel(capture,
      vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0).c_str(),
      vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 0).c_str(), Fig::Mapping::Exposure,
      &scale);
  }
  auto plainPanel = vtkSmartPointer<vtkImageData>::New();
  plainPanel->DeepCopy(plain);
  auto giPanel = vtkSmartPointer<vtkImageData>::New();
  giPanel->DeepCopy(gi);
  Fig::Label(plainPanel, "plain VTK");
  Fig::Label(
    giPanel, std::string("vtkDeepGIPass ") + vtkDeepGIPass::GetPresetAsString(pass->GetPreset()));
  if (!visibility)
  {
    visibility = Fig::BlankPanel(dims[0], dims[1]);
  }
  Fig::Label(visibility,
    (ran & vtkDeepGIPass::AMBIENT_OBSCURANCE) ? "ambient visibility (dark: occluded)"
                                              : "ambient obscurance did not run");
  std::ostringstream label;
  label << std::setprecision(3) << "indirect light added (x" << scale << ")";
  if (!indirect)
  {
    indirect = Fig::BlankPanel(dims[0], dims[1]);
  }
  Fig::Label(indirect, (ran & vtkDeepGIPass::RADIOSITY) ? label.str() : "radiosity did not run");
  return Fig::Tile({ plainPanel, giPanel, visibility, indirect }, 2);
}

// gbuffer.png: one row per layer, the quantities at half resolution.
vtkSmartPointer<vtkImageData> GBufferSheet(vtkDeepGBufferPass* pass, vtkRenderer* renderer)
{
  vtkNew<vtkImageData> layers;
  if (!pass->CaptureLayers(layers, renderer))
  {
    return nullptr;
  }
  const struct
  {
    const char* Array;
    const char* Label;
    Fig::Mapping Mapping;
  } quantities[] = { { vtkDeepGICaptureNames::Radiance, "radiance", Fig::Mapping::Colour },
    { vtkDeepGICaptureNames::Depth, "depth", Fig::Mapping::Depth },
    { vtkDeepGICaptureNames::Normal, "normal", Fig::Mapping::Normal },
    { vtkDeepGICaptureNames::Albedo, "albedo", Fig::Mapping::Colour } };
  std::vector<vtkSmartPointer<vtkImageData>> panels;
  for (int j = 0; j < pass->GetEffectiveNumberOfLayers(); ++j)
  {
    const std::string valid = vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, j);
    for (const auto& q : quantities)
    {
      const std::string name = vtkDeepGICaptureNames::Layer(q.Array, j);
      auto panel = Fig::Panel(layers, name.c_str(), valid.c_str(), q.Mapping);
      if (!panel)
      {
        return nullptr;
      }
      panel = Fig::Half(panel);
      Fig::Label(panel, "layer " + std::to_string(j) + " " + q.Label);
      panels.push_back(panel);
    }
  }
  return panels.empty() ? nullptr : Fig::Tile(panels, 4);
}

bool Write(vtkImageData* image, const std::string& dir, const char* name, const char* what,
  std::vector<std::string>& written)
{
  if (!image || !Fig::WritePNG(image, dir + "/" + name))
  {
    std::cerr << "deepgi-render: no " << what << " to write (" << name << ")\n";
    return false;
  }
  written.push_back(std::string(name) + "  " + what);
  return true;
}

std::string Levels(double levels)
{
  std::ostringstream text;
  text << levels << "/255";
  return text.str();
}

void PrintSummary(
  const Options& o, vtkDeepGIPass* gi, int frames, const std::vector<std::string>& written)
{
  std::cout << std::defaultfloat << std::setprecision(4) << "deepgi-render: done\n";
  if (gi)
  {
    std::cout << "  GI: preset " << vtkDeepGIPass::GetPresetAsString(gi->GetPreset())
              << ", effects on: " << o.Effects << "; the last frame ran "
              << vtkDeepGIPass::GetEffectsAsString(gi->GetLastFrameEffects()) << " with "
              << gi->GetLastFrameNumberOfLayers() << " layer(s)\n"
              << "  radius: obscurance " << gi->GetAmbientObscurancePass()->GetEffectiveRadius()
              << ", radiosity " << gi->GetRadiosityPass()->GetEffectiveRadius()
              << " (world units); exposure " << o.Exposure << "\n"
              << "  converged: " << frames << " frame(s), ";
    if (gi->GetLastConvergenceChange() >= 0.0)
    {
      std::cout << "last change " << 255.0 * gi->GetLastConvergenceChange() << "/255, ";
    }
    std::cout << (gi->GetLastConvergenceReached()
                     ? "at most the tolerance " + Levels(o.Tolerance)
                     : "stopped at --max-frames " + std::to_string(o.MaximumFrames))
              << "\n";
  }
  std::cout << "  files in " << o.Output << "/:\n";
  for (const std::string& w : written)
  {
    std::cout << "    " << w << "\n";
  }
}

// --preset off: the G-buffer alone, for its contact sheet.
bool RunGBufferOnly(const Options& o, vtkRenderWindow* window, vtkRenderer* renderer,
  std::vector<std::string>& written)
{
  vtkNew<vtkDeepGBufferPass> pass;
  pass->SetNumberOfLayers(o.Layers);
  pass->SetOracle(o.Oracle);
  if (o.Dz >= 0.0)
  {
    pass->SetMinimumSeparation(o.Dz);
  }
  renderer->SetPass(pass);
  window->Render();
  window->Render(); // the oracles have a previous frame
  std::cout << "  G-buffer: " << pass->GetEffectiveNumberOfLayers() << " layer(s), dz "
            << pass->GetEffectiveMinimumSeparation() << ", oracle "
            << vtkDeepGBufferPass::GetOracleAsString(pass->GetEffectiveOracle()) << "\n";
  const bool ok = Write(GBufferSheet(pass, renderer), o.Output, "gbuffer.png",
    "the G-buffer's layers (rows) and quantities (columns)", written);
  renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(window);
  return ok;
}

bool RunGI(const Options& o, vtkRenderWindow* window, vtkRenderer* renderer, vtkImageData* plain,
  std::vector<std::string>& written)
{
  vtkNew<vtkDeepGIPass> gi;
  ConfigureGI(o, gi);
  const int frames = ConvergeGI(o, renderer, gi);
  if (gi->GetGBufferPass()->GetEffectiveNumberOfLayers() < 1)
  {
    std::cerr << "deepgi-render: the deep G-buffer is not supported by this OpenGL (see the "
                 "warning above); no GI image was made\n";
    return false;
  }
  auto giImage = Fig::GrabWindow(window);
  const bool ok = Write(giImage, o.Output, "gi.png", "the GI image (vtkDeepGIPass)", written) &&
    Write(CompareFigure(plain, giImage, gi, renderer), o.Output, "compare.png",
      "plain | GI, and below: ambient visibility | indirect light", written) &&
    Write(GBufferSheet(gi->GetGBufferPass(), renderer), o.Output, "gbuffer.png",
      "the G-buffer's layers (rows) and quantities (columns)", written);
  PrintSummary(o, gi, frames, written);
  renderer->SetPass(nullptr);
  gi->ReleaseGraphicsResources(window);
  return ok;
}

vtkSmartPointer<vtkRenderWindow> MakeWindow(const Options& o, vtkRenderer* renderer)
{
  const int backend = vtkDeepGIRenderWindowFactory::GetBackendFromString(o.Backend.c_str());
  vtkSmartPointer<vtkRenderWindow> window =
    vtkSmartPointer<vtkRenderWindow>::Take(vtkDeepGIRenderWindowFactory::NewRenderWindow(backend));
  if (!window)
  {
    std::cerr << "deepgi-render: no render window for the '" << o.Backend
              << "' backend (see the error above)\n";
    return nullptr;
  }
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(o.Width, o.Height);
  window->AddRenderer(renderer);
  return window;
}
} // anonymous namespace

int main(int argc, char* argv[])
{
  Options o;
  bool exitNow = false;
  const int status = ParseOptions(argc, argv, o, exitNow);
  if (status != 0 || exitNow)
  {
    return status;
  }

  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.0, 0.0, 0.0);
  Scene scene;
  if (!LoadScene(o, renderer, scene) || !PrepareOutput(o.Output))
  {
    return ExitFailure;
  }
  ApplyExposure(renderer, o.Exposure);
  // Made after loading, so that bad data fails without needing a display.
  vtkSmartPointer<vtkRenderWindow> window = MakeWindow(o, renderer);
  if (!window)
  {
    return ExitFailure;
  }
  std::cout << "deepgi-render: " << scene.Description << ", " << scene.Triangles << " triangles, "
            << o.Width << "x" << o.Height << ", backend " << o.Backend << ", preset "
            << (o.Preset < 0 ? "off" : vtkDeepGIPass::GetPresetAsString(o.Preset)) << std::endl;
  std::cout << "  camera (--camera): " << vtkDeepGICameraText::Write(renderer->GetActiveCamera())
            << std::endl;

  std::vector<std::string> written;
  double plainMilliseconds = 0.0;
  vtkSmartPointer<vtkImageData> plain = RenderPlain(window, plainMilliseconds);
  if (!Write(plain, o.Output, "plain.png", "plain VTK", written))
  {
    return ExitFailure;
  }
  const bool ok = o.Preset < 0 ? RunGBufferOnly(o, window, renderer, written)
                               : RunGI(o, window, renderer, plain, written);
  if (o.Preset < 0)
  {
    PrintSummary(o, nullptr, 0, written);
  }
  // The window releases the renderer's OpenGL resources when it goes away,
  // while its context still exists.
  return ok ? 0 : ExitFailure;
}
