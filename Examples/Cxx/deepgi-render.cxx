// deepgi-render: renders a scene with vtkDeepGBufferPass and writes the lit
// image and every layer's G-buffer quantities as PNG files.
//
// With no arguments it renders the built-in demo scene (vtkDeepGBufferDemoScene)
// at 1024x768 along the first frames of its camera path and writes
// output/lit.png and output/layerJ_{radiance,depth,normal,albedo}.png.
// With --gi PRESET it also renders the scene with vtkDeepGIPass (ambient
// obscurance, radiosity and reflections composited) and writes gi.png.
// Run with --help for the options.

#include "vtkCamera.h"
#include "vtkDeepGBufferDemoScene.h"
#include "vtkDeepGBufferPass.h"
#include "vtkDeepGBufferSceneLoader.h"
#include "vtkDeepGIPass.h"
#include "vtkDeepGIRenderWindowFactory.h"
#include "vtkDeepRadiosityPass.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkWindowToImageFilter.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
// Frames in one loop of the demo scene's camera path: --frames N renders
// frames 0 .. N-1 of this loop.
constexpr int PathFrames = 120;

constexpr int ExitUsage = 2;
constexpr int ExitFailure = 1;

const char* Usage = R"(Usage: deepgi-render [options]

Renders a scene with the deep G-buffer pass (vtkDeepGBufferPass, Mara et al.
HPG 2016) offscreen and writes PNG images into the output directory:
  lit.png                   the image as the pass shows it (layer 0 radiance)
  layerJ_radiance.png       direct radiance of layer J (J = 0 .. K-1)
  layerJ_depth.png          camera-space depth of layer J, normalised
  layerJ_normal.png         camera-space normal of layer J, n * 0.5 + 0.5
  layerJ_albedo.png         diffuse albedo of layer J
  gi.png                    with --gi: the global illumination composite
lit.png is the last of the --frames frames. Each layer image is one more
frame at the same camera, with the pass's debug display switched to that
layer and quantity (the oracles then see a still camera). gi.png is
rendered after them, at the same camera, with vtkDeepGIPass (direct +
AV * ambient + radiosity + reflections, Documentation/gi.md) converged over
--converge frames.

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
  --view NAME         demo scene: a still camera at a named view instead of
                      the camera path: default, overview, columns, decal,
                      panel

Deep G-buffer:
  --layers K          number of layers, 1 to 8 (default 2)
  --dz VALUE          minimum separation between layers in world units
                      (default: automatic, 1.5 % of the scene's diagonal)
  --oracle NAME       depth_peel, previous, reproject, predict or delay
                      (default reproject)

Rendering:
  --size WxH          image size in pixels (default 1024x768)
  --frames N          frames rendered before the images are written
                      (default 3, so the oracles have history). The demo
                      scene's camera moves along its path (frames 0 .. N-1 of
                      a 120-frame loop); loaded data and --view stay still.
  --backend NAME      auto, x11 or egl (default auto: x11 when an X display
                      can be opened, else egl)
  --output DIR        output directory, created if needed (default output)
  --gi PRESET         off (default), high_performance, balanced or
                      high_quality: also render gi.png with vtkDeepGIPass
                      and that preset
  --effects LIST      with --gi: the effects switched on, a comma-separated
                      subset of ao, radiosity, reflections (default all
                      three; each still runs only where the scene needs it)
  --converge N        with --gi: frames rendered at the still camera before
                      gi.png is written, 1 to 10000 (default 20)
  --guard-band B      with --gi: the G-buffer's guard band, a fraction of
                      the image height added on each side, 0 to 0.5
                      (default 0.1); the effects gather from it
  --help              print this text and exit

Exit status: 0 on success, 1 when loading or rendering fails, 2 for bad
options.
)";

struct Options
{
  std::vector<std::string> Meshes;
  std::string Volume;
  double Iso = 500.0;
  bool IsoGiven = false;
  long long Triangles = 10000;
  double Scale = 1.0;
  std::string View;
  int Layers = 2;
  double Dz = -1.0; // < 0: automatic
  int Oracle = vtkDeepGBufferPass::REPROJECT;
  std::string OracleName = "reproject";
  int Width = 1024;
  int Height = 768;
  int Frames = 3;
  std::string Backend = "auto";
  std::string Output = "output";
  int GI = -1; // a vtkDeepGIPass preset; -1: off
  bool AmbientObscurance = true;
  bool Radiosity = true;
  bool Reflections = true;
  bool EffectsGiven = false;
  int Converge = 20;
  bool ConvergeGiven = false;
  double GuardBand = vtkDeepRadiosityPass::DEFAULT_GUARD_BAND;
  bool GuardBandGiven = false;
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

// Returns 0 to go on, or an exit status (help printed: 0 through `exitNow`).
int ParseOptions(int argc, char* argv[], Options& o, bool& exitNow)
{
  exitNow = false;
  auto bad = [](const std::string& message) {
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
    static const char* const withValue[] = { "--mesh", "--volume", "--iso", "--triangles",
      "--scale", "--view", "--layers", "--dz", "--oracle", "--size", "--frames", "--backend",
      "--output", "--gi", "--effects", "--converge", "--guard-band" };
    bool known = false;
    for (const char* name : withValue)
    {
      known = known || arg == name;
    }
    if (!known)
    {
      return bad("unknown option '" + arg + "'");
    }
    if (i + 1 >= argc)
    {
      return bad("option " + arg + " needs a value");
    }
    const std::string value = argv[++i];
    long long n = 0;
    if (arg == "--mesh")
    {
      o.Meshes.push_back(value);
    }
    else if (arg == "--volume")
    {
      if (!o.Volume.empty())
      {
        return bad("--volume given twice");
      }
      o.Volume = value;
    }
    else if (arg == "--iso")
    {
      if (!ParseReal(value, o.Iso))
      {
        return bad("--iso needs a finite number, got '" + value + "'");
      }
      o.IsoGiven = true;
    }
    else if (arg == "--triangles")
    {
      if (!ParseInteger(value, 0, 500000000, n))
      {
        return bad("--triangles needs an integer from 0 to 500000000, got '" + value + "'");
      }
      o.Triangles = n;
    }
    else if (arg == "--scale")
    {
      if (!ParseReal(value, o.Scale) || o.Scale <= 0.0)
      {
        return bad("--scale needs a positive number, got '" + value + "'");
      }
    }
    else if (arg == "--view")
    {
      bool found = false;
      for (int v = 0; v < vtkDeepGBufferDemoScene::GetNumberOfNamedViews(); ++v)
      {
        found = found || value == vtkDeepGBufferDemoScene::GetNamedViewName(v);
      }
      if (!found)
      {
        return bad("--view needs one of default, overview, columns, decal, panel; got '" +
          value + "'");
      }
      o.View = value;
    }
    else if (arg == "--layers")
    {
      if (!ParseInteger(value, 1, vtkDeepGBufferPass::MAXIMUM_NUMBER_OF_LAYERS, n))
      {
        return bad("--layers needs an integer from 1 to " +
          std::to_string(vtkDeepGBufferPass::MAXIMUM_NUMBER_OF_LAYERS) + ", got '" + value +
          "'");
      }
      o.Layers = static_cast<int>(n);
    }
    else if (arg == "--dz")
    {
      if (!ParseReal(value, o.Dz) || o.Dz < 0.0)
      {
        return bad("--dz needs a number >= 0 (world units), got '" + value + "'");
      }
    }
    else if (arg == "--oracle")
    {
      const int oracle = vtkDeepGBufferPass::GetOracleFromString(value.c_str());
      if (oracle < 0)
      {
        return bad("--oracle needs depth_peel, previous, reproject, predict or delay, got '" +
          value + "'");
      }
      o.Oracle = oracle;
      o.OracleName = value;
    }
    else if (arg == "--size")
    {
      const size_t x = value.find_first_of("xX");
      long long w = 0, h = 0;
      if (x == std::string::npos || !ParseInteger(value.substr(0, x), 1, 16384, w) ||
        !ParseInteger(value.substr(x + 1), 1, 16384, h))
      {
        return bad("--size needs WIDTHxHEIGHT, each 1 to 16384, got '" + value + "'");
      }
      o.Width = static_cast<int>(w);
      o.Height = static_cast<int>(h);
    }
    else if (arg == "--frames")
    {
      if (!ParseInteger(value, 1, 100000, n))
      {
        return bad("--frames needs an integer from 1 to 100000, got '" + value + "'");
      }
      o.Frames = static_cast<int>(n);
    }
    else if (arg == "--backend")
    {
      if (vtkDeepGIRenderWindowFactory::GetBackendFromString(value.c_str()) < 0)
      {
        return bad("--backend needs auto, x11 or egl, got '" + value + "'");
      }
      o.Backend = value;
    }
    else if (arg == "--output")
    {
      if (value.empty())
      {
        return bad("--output needs a directory name");
      }
      o.Output = value;
    }
    else if (arg == "--gi")
    {
      if (value == "off")
      {
        o.GI = -1;
      }
      else
      {
        o.GI = vtkDeepGIPass::GetPresetFromString(value.c_str());
        if (o.GI < 0)
        {
          return bad(
            "--gi needs off, high_performance, balanced or high_quality, got '" + value + "'");
        }
      }
    }
    else if (arg == "--effects")
    {
      o.EffectsGiven = true;
      o.AmbientObscurance = o.Radiosity = o.Reflections = false;
      std::stringstream list(value);
      std::string item;
      int count = 0;
      while (std::getline(list, item, ','))
      {
        bool* flag = item == "ao" ? &o.AmbientObscurance
          : item == "radiosity"   ? &o.Radiosity
          : item == "reflections" ? &o.Reflections
                                  : nullptr;
        if (!flag || *flag)
        {
          return bad("--effects needs a comma-separated list of distinct ao, radiosity, "
                     "reflections; got '" +
            value + "'");
        }
        *flag = true;
        ++count;
      }
      if (count == 0 || value.back() == ',')
      {
        return bad("--effects needs a comma-separated list of distinct ao, radiosity, "
                   "reflections; got '" +
          value + "'");
      }
    }
    else if (arg == "--converge")
    {
      long long n = 0;
      if (!ParseInteger(value, 1, 10000, n))
      {
        return bad("--converge needs an integer from 1 to 10000, got '" + value + "'");
      }
      o.Converge = static_cast<int>(n);
      o.ConvergeGiven = true;
    }
    else if (arg == "--guard-band")
    {
      if (!ParseReal(value, o.GuardBand) || o.GuardBand < 0.0 ||
        o.GuardBand > vtkDeepGBufferPass::MAXIMUM_GUARD_BAND)
      {
        return bad("--guard-band needs a number from 0 to 0.5, got '" + value + "'");
      }
      o.GuardBandGiven = true;
    }
  }
  if (o.GI < 0 && (o.EffectsGiven || o.ConvergeGiven || o.GuardBandGiven))
  {
    return bad("--effects, --converge and --guard-band need --gi with a preset");
  }
  const bool loaded = !o.Meshes.empty() || !o.Volume.empty();
  if (o.IsoGiven && o.Volume.empty())
  {
    return bad("--iso is only used with --volume");
  }
  if (loaded && !o.View.empty())
  {
    return bad("--view is for the demo scene; loaded data gets a still camera framing it");
  }
  return 0;
}

bool WritePNG(vtkRenderWindow* window, const std::string& fileName)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff(); // offscreen: the image is in the back buffer
  grab->ShouldRerenderOff();  // the caller rendered the frame to keep
  grab->SetInputBufferTypeToRGB();
  grab->Update();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(fileName.c_str());
  writer->Write();
  if (writer->GetErrorCode() != 0 || !vtksys::SystemTools::FileExists(fileName, true))
  {
    std::cerr << "deepgi-render: cannot write " << fileName << "\n";
    return false;
  }
  std::cout << "  wrote " << fileName << "\n";
  return true;
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
  vtkCamera* camera = renderer->GetActiveCamera();

  // The scene.
  const bool loaded = !o.Meshes.empty() || !o.Volume.empty();
  vtkNew<vtkDeepGBufferDemoScene> demo;
  vtkNew<vtkDeepGBufferSceneLoader> loader;
  vtkIdType triangles = 0;
  if (loaded)
  {
    for (const std::string& mesh : o.Meshes)
    {
      if (!loader->LoadMesh(mesh.c_str()))
      {
        std::cerr << "deepgi-render: cannot load the mesh " << mesh << "\n";
        return ExitFailure;
      }
    }
    if (!o.Volume.empty())
    {
      if (!loader->LoadVolume(o.Volume.c_str(), o.Iso))
      {
        std::cerr << "deepgi-render: cannot load the volume " << o.Volume << "\n";
        return ExitFailure;
      }
      if (o.Meshes.empty())
      {
        // CT data such as headsq: look at the face (from +y), head up (-z).
        loader->SetViewDirection(0.0, -1.0, 0.0);
        loader->SetViewUp(0.0, 0.0, -1.0);
      }
    }
    loader->Populate(renderer);
    loader->ResetCamera(renderer);
    triangles = loader->GetNumberOfTriangles();
  }
  else
  {
    demo->SetTargetNumberOfTriangles(o.Triangles);
    demo->SetScaleFactor(o.Scale);
    demo->Populate(renderer);
    if (!o.View.empty())
    {
      demo->SetCameraToNamedView(camera, o.View.c_str());
    }
    else
    {
      demo->SetCameraToPathFrame(camera, 0, PathFrames);
    }
    triangles = demo->GetNumberOfTriangles();
  }

  if (!vtksys::SystemTools::MakeDirectory(o.Output))
  {
    std::cerr << "deepgi-render: cannot create the output directory " << o.Output << "\n";
    return ExitFailure;
  }

  // Render window for the backend (X11 offscreen or EGL), from the
  // RenderingHeadless module; made after loading, so that bad data fails
  // without needing a display.
  const int backend = vtkDeepGIRenderWindowFactory::GetBackendFromString(o.Backend.c_str());
  vtkSmartPointer<vtkRenderWindow> window =
    vtkSmartPointer<vtkRenderWindow>::Take(vtkDeepGIRenderWindowFactory::NewRenderWindow(backend));
  if (!window)
  {
    std::cerr << "deepgi-render: no render window for the '" << o.Backend
              << "' backend (see the error above)\n";
    return ExitFailure;
  }
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(o.Width, o.Height);

  window->AddRenderer(renderer);

  // The pass.
  vtkNew<vtkDeepGBufferPass> pass;
  pass->SetNumberOfLayers(o.Layers);
  pass->SetOracle(o.Oracle);
  if (o.Dz >= 0.0)
  {
    pass->SetMinimumSeparation(o.Dz);
  }
  renderer->SetPass(pass);

  std::cout << "deepgi-render: "
            << (loaded ? "loaded data" : "demo scene") << ", " << triangles << " triangles, "
            << o.Width << "x" << o.Height << ", backend " << o.Backend << ", " << o.Layers
            << " layers, oracle " << vtkDeepGBufferPass::GetOracleAsString(o.Oracle) << ", dz "
            << (o.Dz >= 0.0 ? std::to_string(o.Dz) : std::string("automatic")) << "\n";

  // Frames: the demo camera moves along its path so the oracles have motion
  // and history; loaded data and named views keep a still camera.
  double totalSeconds = 0.0;
  for (int f = 0; f < o.Frames; ++f)
  {
    if (!loaded && o.View.empty())
    {
      demo->SetCameraToPathFrame(camera, f, PathFrames);
    }
    const auto start = std::chrono::steady_clock::now();
    window->Render();
    totalSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  std::cout << std::fixed << std::setprecision(2) << "  " << o.Frames << " frame(s), "
            << 1000.0 * totalSeconds / o.Frames << " ms per frame (includes first-frame setup)"
            << std::defaultfloat << std::setprecision(6) << "\n";
  std::cout << "  effective: " << pass->GetEffectiveNumberOfLayers() << " layers, dz "
            << pass->GetEffectiveMinimumSeparation() << ", oracle "
            << vtkDeepGBufferPass::GetOracleAsString(pass->GetEffectiveOracle()) << ", "
            << pass->GetLastGeometryPassCount() << " geometry pass(es) in the last frame\n";

  const std::string dir = o.Output + "/";
  if (!WritePNG(window, dir + "lit.png"))
  {
    return ExitFailure;
  }

  // Each layer's quantities through the pass's debug display.
  const int layers = pass->GetEffectiveNumberOfLayers() > 0
    ? std::min(pass->GetEffectiveNumberOfLayers(), o.Layers)
    : o.Layers;
  const struct
  {
    int Quantity;
    const char* Name;
  } quantities[] = { { vtkDeepGBufferPass::RADIANCE, "radiance" },
    { vtkDeepGBufferPass::DEPTH, "depth" }, { vtkDeepGBufferPass::NORMAL, "normal" },
    { vtkDeepGBufferPass::ALBEDO, "albedo" } };
  for (int layer = 0; layer < layers; ++layer)
  {
    for (const auto& q : quantities)
    {
      pass->SetDisplayLayer(layer);
      pass->SetDisplayQuantity(q.Quantity);
      window->Render();
      if (!WritePNG(window, dir + "layer" + std::to_string(layer) + "_" + q.Name + ".png"))
      {
        return ExitFailure;
      }
    }
  }
  pass->SetDisplayLayer(0);
  pass->SetDisplayQuantity(vtkDeepGBufferPass::RADIANCE);

  // The global illumination composite at the same, still camera.
  if (o.GI >= 0)
  {
    pass->ReleaseGraphicsResources(window);
    vtkNew<vtkDeepGIPass> gi;
    gi->SetPreset(o.GI);
    gi->SetAmbientObscurance(o.AmbientObscurance);
    gi->SetRadiosity(o.Radiosity);
    gi->SetReflections(o.Reflections);
    gi->GetGBufferPass()->SetOracle(o.Oracle);
    gi->GetGBufferPass()->SetGuardBand(o.GuardBand);
    if (o.Dz >= 0.0)
    {
      gi->GetGBufferPass()->SetMinimumSeparation(o.Dz);
    }
    renderer->SetPass(gi);
    const auto start = std::chrono::steady_clock::now();
    gi->Converge(renderer, o.Converge);
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << std::fixed << std::setprecision(2) << "  gi " << vtkDeepGIPass::GetPresetAsString(o.GI)
              << ": " << o.Converge << " frame(s), " << 1000.0 * seconds / o.Converge
              << " ms per frame (includes first-frame setup)" << std::defaultfloat
              << std::setprecision(6) << "; last frame ran "
              << vtkDeepGIPass::GetEffectsAsString(gi->GetLastFrameEffects()) << " with "
              << gi->GetLastFrameNumberOfLayers() << " layer(s)\n";
    if (!WritePNG(window, dir + "gi.png"))
    {
      return ExitFailure;
    }
  }

  // The window releases the renderer's and the pass's OpenGL resources
  // when it goes away, while its context still exists.
  return 0;
}
