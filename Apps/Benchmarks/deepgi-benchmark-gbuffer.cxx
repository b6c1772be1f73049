// deepgi-benchmark-gbuffer: the cost of the deep G-buffer's second layer,
// measured side by side in one run (paper Table 5).
//
// The demo scene (at least 1M triangles by default) is rendered at
// 1024x1024 along its camera path with:
//   - VTK without the pass (reference),
//   - the G-buffer with one layer (the first layer's cost),
//   - two layers with DEPTH_PEEL (two geometry submissions),
//   - two layers with each single-pass oracle (PREVIOUS, REPROJECT,
//     PREDICT, DELAY: one submission through the routing geometry shader),
//   - two layers with REPROJECT and the guard band of the radiosity and GI
//     passes (vtkDeepRadiosityPass::DEFAULT_GUARD_BAND), whose cost is
//     reported against REPROJECT without it.
// Each method renders the same camera sequence; every frame is timed from
// Render() to glFinish (vtkRenderWindow::WaitForCompletion). The methods run
// in rounds (all methods, then all again) so that slow drifts of the
// machine affect them alike, and the median frame time of each is reported
// with the second layer's cost, (T2 - T1), as a ratio of the first layer's T1.

#include "DeepGIBenchmarkCommon.h"

#include "vtkCamera.h"
#include "vtkDeepGBufferPass.h"
#include "vtkDeepGIDemoScene.h"
#include "vtkDeepGIRenderWindowFactory.h"
#include "vtkDeepRadiosityPass.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using namespace DeepGIBenchmark;
const char* const Program = "deepgi-benchmark-gbuffer";

/// Frames of the demo scene's camera path: the timed frames follow it.
constexpr int PathFrames = 120;

struct Options
{
  long long Triangles = 1200000;
  int Width = 1024;
  int Height = 1024;
  int Frames = 9;
  int Rounds = 2;
  int Warmup = 3;
  int Backend = vtkDeepGIRenderWindowFactory::BACKEND_AUTO;
  std::string Output = "output";
};

void Usage()
{
  std::printf("Usage: deepgi-benchmark-gbuffer [options]\n"
              "Times the deep G-buffer's first and second layers on the demo scene.\n"
              "  --triangles N   demo scene size (default 1200000)\n"
              "  --size WxH      render size in pixels (default 1024x1024)\n"
              "  --frames N      timed frames per method and round (default 9)\n"
              "  --rounds N      rounds over all methods (default 2)\n"
              "  --backend NAME  auto, x11 or egl (default auto)\n"
              "  --output DIR    writes DIR/benchmark-gbuffer.{md,csv} (default output)\n"
              "  --help          this text\n");
}

bool ParseOptions(int argc, char* argv[], Options& o)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto next = [&](const char* what) -> const char*
    {
      if (i + 1 >= argc)
      {
        std::fprintf(stderr, "%s: %s needs a value\n", Program, what);
        return nullptr;
      }
      return argv[++i];
    };
    const char* value = nullptr;
    if (arg == "--help" || arg == "-h")
    {
      Usage();
      std::exit(0);
    }
    else if (arg == "--triangles" && (value = next("--triangles")))
    {
      o.Triangles = std::atoll(value);
    }
    else if (arg == "--size" && (value = next("--size")))
    {
      if (std::sscanf(value, "%dx%d", &o.Width, &o.Height) != 2)
      {
        o.Width = 0;
      }
    }
    else if (arg == "--frames" && (value = next("--frames")))
    {
      o.Frames = std::atoi(value);
    }
    else if (arg == "--rounds" && (value = next("--rounds")))
    {
      o.Rounds = std::atoi(value);
    }
    else if (arg == "--backend" && (value = next("--backend")))
    {
      o.Backend = vtkDeepGIRenderWindowFactory::GetBackendFromString(value);
    }
    else if (arg == "--output" && (value = next("--output")))
    {
      o.Output = value;
    }
    else
    {
      if (!value)
      {
        std::fprintf(stderr, "%s: unknown or incomplete option %s\n", Program, arg.c_str());
      }
      return false;
    }
  }
  if (o.Triangles < 1 || o.Width < 1 || o.Height < 1 || o.Frames < 1 || o.Rounds < 1 ||
    o.Backend < 0)
  {
    return Report(Program, "invalid option value");
  }
  return true;
}

struct Method
{
  Method(const std::string& name, int layers, int oracle = vtkDeepGBufferPass::DEPTH_PEEL,
    double guardBand = 0.0)
    : Name(name)
    , Layers(layers)
    , Oracle(oracle)
    , GuardBand(guardBand)
  {
  }
  std::string Name;
  int Layers = 0; // 0: VTK without the pass
  int Oracle = vtkDeepGBufferPass::DEPTH_PEEL;
  double GuardBand = 0.0;
  vtkSmartPointer<vtkDeepGBufferPass> Pass;
  std::vector<double> Milliseconds;
  int GeometryPasses = 0;
};

/// VTK without the pass, one layer, two layers with each oracle, and two
/// layers with REPROJECT and a guard band; each G-buffer pass made.
std::vector<Method> MakeMethods()
{
  std::vector<Method> methods;
  methods.emplace_back("VTK without the pass", 0);
  methods.emplace_back("G-buffer, 1 layer", 1);
  for (int oracle = vtkDeepGBufferPass::DEPTH_PEEL; oracle <= vtkDeepGBufferPass::DELAY; ++oracle)
  {
    methods.emplace_back(
      std::string("2 layers, ") + vtkDeepGBufferPass::GetOracleAsString(oracle), 2, oracle);
  }
  // The default oracle with the guard band of the radiosity and GI passes.
  const double guardBand = vtkDeepRadiosityPass::DEFAULT_GUARD_BAND;
  char guardName[64];
  std::snprintf(guardName, sizeof(guardName), "2 layers, REPROJECT, guard band %g", guardBand);
  methods.emplace_back(guardName, 2, vtkDeepGBufferPass::REPROJECT, guardBand);
  for (Method& m : methods)
  {
    if (m.Layers > 0)
    {
      m.Pass = vtkSmartPointer<vtkDeepGBufferPass>::New();
      m.Pass->SetNumberOfLayers(m.Layers);
      m.Pass->SetOracle(m.Oracle);
      m.Pass->SetGuardBand(m.GuardBand);
    }
  }
  return methods;
}

/// Every method's frame times along the scene's camera path, all methods in
/// each round, and its geometry submissions per frame.
void TimeAlongCameraPath(
  const Options& o, const View& view, vtkDeepGIDemoScene* scene, std::vector<Method>& methods)
{
  std::vector<vtkRenderPass*> passes;
  for (const Method& m : methods)
  {
    passes.push_back(m.Pass);
  }
  // Warm-up frames compile the shaders and fill the oracle's history.
  const std::vector<std::vector<double>> ms =
    TimePassesInRounds(view, passes, o.Rounds, o.Warmup, o.Frames,
      [&view, scene](int f)
      {
        scene->SetCameraToPathFrame(view.Renderer->GetActiveCamera(), f, PathFrames);
        view.Renderer->ResetCameraClippingRange();
      });
  for (size_t k = 0; k < methods.size(); ++k)
  {
    methods[k].Milliseconds = ms[k];
    if (methods[k].Pass)
    {
      methods[k].GeometryPasses = methods[k].Pass->GetLastGeometryPassCount();
    }
  }
}

/// The run's settings and a row per method; the CSV file's rows into `csv`.
std::string MethodTable(const Options& o, vtkDeepGIDemoScene* scene, const std::string& device,
  const std::vector<Method>& methods, std::string& csvText)
{
  const double firstLayer = Median(methods[1].Milliseconds);
  std::ostringstream md, csv;
  md << "Demo scene, " << scene->GetNumberOfTriangles() << " triangles, " << o.Width << "x"
     << o.Height << ", camera moving along the scene's path; median of " << o.Frames * o.Rounds
     << " frames per method (" << o.Rounds << " rounds); OpenGL renderer: " << device << ".\n\n";
  md << "| method | geometry submissions | frame [ms] | second layer [ms] | second layer / first "
        "layer |\n";
  md << "|---|---|---|---|---|\n";
  csv << "method,geometry_submissions,frame_ms,second_layer_ms,second_over_first\n";
  char buffer[512];
  for (const Method& m : methods)
  {
    const double t = Median(m.Milliseconds);
    if (m.Layers < 2 || m.GuardBand > 0.0)
    {
      std::snprintf(buffer, sizeof(buffer), "| %s | %d | %.1f | | |\n", m.Name.c_str(),
        m.Layers == 0 ? 1 : m.GeometryPasses, t);
      md << buffer;
      std::snprintf(buffer, sizeof(buffer), "%s,%d,%.3f,,\n", m.Name.c_str(),
        m.Layers == 0 ? 1 : m.GeometryPasses, t);
      csv << buffer;
      continue;
    }
    const double second = t - firstLayer;
    std::snprintf(buffer, sizeof(buffer), "| %s | %d | %.1f | %.1f | %.2f |\n", m.Name.c_str(),
      m.GeometryPasses, t, second, second / firstLayer);
    md << buffer;
    std::snprintf(buffer, sizeof(buffer), "%s,%d,%.3f,%.3f,%.4f\n", m.Name.c_str(),
      m.GeometryPasses, t, second, second / firstLayer);
    csv << buffer;
  }
  csvText = csv.str();
  return md.str();
}

/// The first layer's cost against VTK without the pass (with the paper's
/// figures), and the guard band's cost against REPROJECT without it.
std::string Summary(const Options& o, const std::vector<Method>& methods)
{
  const double vtkOnly = Median(methods[0].Milliseconds);
  const double firstLayer = Median(methods[1].Milliseconds);
  char buffer[512];
  std::snprintf(buffer, sizeof(buffer),
    "\nFirst layer (1-layer G-buffer) %.1f ms = %.2f x VTK without the pass (%.1f ms).\n"
    "Paper (Table 5, GTX 980, 1080p): REPROJECT adds about 0.4-0.6 of the first layer's cost "
    "and is about twice as fast as depth peeling.\n",
    firstLayer, firstLayer / vtkOnly, vtkOnly);
  std::string text = buffer;
  double reproject = 0.0, guarded = 0.0;
  int guardPixels = 0;
  for (const Method& m : methods)
  {
    if (m.Layers == 2 && m.Oracle == vtkDeepGBufferPass::REPROJECT)
    {
      (m.GuardBand > 0.0 ? guarded : reproject) = Median(m.Milliseconds);
      if (m.GuardBand > 0.0)
      {
        guardPixels = m.Pass->GetEffectiveGuardBand();
      }
    }
  }
  std::snprintf(buffer, sizeof(buffer),
    "Guard band %g (%d pixels per side: %.2f x the pixels): 2 layers, REPROJECT %.1f ms = %.2f x "
    "without it (%.1f ms).\n",
    vtkDeepRadiosityPass::DEFAULT_GUARD_BAND, guardPixels,
    static_cast<double>(o.Width + 2 * guardPixels) * (o.Height + 2 * guardPixels) /
      (static_cast<double>(o.Width) * o.Height),
    guarded, reproject > 0.0 ? guarded / reproject : 0.0, reproject);
  return text + buffer;
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
  // The outputs are checked before the measuring.
  View view;
  if (!PrepareOutputs(Program, options.Output, false) ||
    !OpenView(Program, options.Backend, options.Width, options.Height, view))
  {
    return 1;
  }
  vtkNew<vtkDeepGIDemoScene> scene;
  scene->SetTargetNumberOfTriangles(options.Triangles);
  scene->Populate(view.Renderer);
  std::vector<Method> methods = MakeMethods();
  TimeAlongCameraPath(options, view, scene, methods);
  const std::string device = OpenGLRendererName(view.Window);
  std::string csv;
  const std::string markdown =
    MethodTable(options, scene, device, methods, csv) + Summary(options, methods);
  for (Method& m : methods)
  {
    if (m.Pass)
    {
      m.Pass->ReleaseGraphicsResources(view.Window);
    }
  }
  return WriteTables(Program, options.Output, "benchmark-gbuffer", markdown, csv) ? 0 : 1;
}
