#include "DeepGIBenchmarkCommon.h"

#include "DeepGIOutput.h"

#include "vtkAxis.h"
#include "vtkChartXY.h"
#include "vtkContextScene.h"
#include "vtkContextView.h"
#include "vtkDeepGIRenderWindowFactory.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPlot.h"
#include "vtkRenderPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace DeepGIBenchmark
{
namespace
{
/// --data DIR, --backend NAME (auto, x11, egl), --output DIR (not empty).
/// Returns false with `error` set when `arg` is one of them and `value` is
/// invalid; other options are ignored.
bool ParseSharedOption(const std::string& arg, const std::string& value, std::string& data,
  int& backend, std::string& output, std::string& error)
{
  if (arg == "--data")
  {
    data = value;
  }
  else if (arg == "--backend")
  {
    backend = vtkDeepGIRenderWindowFactory::GetBackendFromString(value.c_str());
    if (backend < 0)
    {
      error = "unknown backend '" + value + "' (auto, x11, egl)";
      return false;
    }
  }
  else if (arg == "--output")
  {
    if (value.empty())
    {
      error = "--output needs a directory";
      return false;
    }
    output = value;
  }
  return true;
}

/// "a, b, c"
std::string JoinWithCommas(const std::vector<std::string>& items)
{
  std::string list;
  for (const std::string& item : items)
  {
    list += (list.empty() ? "" : ", ") + item;
  }
  return list;
}

/// "unknown scene 'S' (KNOWN)" for the first of `scenes` that is not one of
/// `known`; empty when all are.
std::string UnknownScene(
  const std::vector<std::string>& scenes, const std::vector<std::string>& known)
{
  for (const std::string& s : scenes)
  {
    if (std::find(known.begin(), known.end(), s) == known.end())
    {
      return "unknown scene '" + s + "' (" + JoinWithCommas(known) + ")";
    }
  }
  return std::string();
}

/// Reads one of the shared options with a value; false with `error` set
/// when `value` is invalid.
bool ParseAccuracyOption(const std::string& arg, const std::string& value,
  const CommandLine& commandLine, AccuracyOptions& o, std::string& error)
{
  if (arg == "--size" && !ParseSize(value, o.Width, o.Height))
  {
    error = "--size needs WxH with 16..8192 pixels per side, got '" + value + "'";
  }
  else if (arg == "--accuracy-size" && !ParseSize(value, o.AccuracyWidth, o.AccuracyHeight))
  {
    error = "--accuracy-size needs WxH with 16..8192 pixels per side, got '" + value + "'";
  }
  else if (arg == "--frames" && (!ParseInt(value, o.Frames) || o.Frames < 1 || o.Frames > 10000))
  {
    error = "--frames needs an integer 1..10000, got '" + value + "'";
  }
  else if (arg == "--rounds" && (!ParseInt(value, o.Rounds) || o.Rounds < 1 || o.Rounds > 100))
  {
    error = "--rounds needs an integer 1..100, got '" + value + "'";
  }
  else if (arg == "--samples" &&
    (!ParseInt(value, o.Samples) || o.Samples < 1 || o.Samples > 1048576))
  {
    error = "--samples needs an integer 1..1048576, got '" + value + "'";
  }
  else if (arg == "--radius-fraction" && !ParseFraction(value, o.RadiusFraction))
  {
    error = "--radius-fraction needs a number in (0, 1], got '" + value + "'";
  }
  else if (arg == "--scenes")
  {
    o.ScenesGiven = true;
    o.Scenes = Split(value, ',');
    error = o.Scenes.empty() ? "--scenes needs at least one scene"
                             : UnknownScene(o.Scenes, commandLine.SceneNames);
  }
  else if (arg == "--methods")
  {
    o.MethodList = value;
  }
  else if (std::find(commandLine.OwnOptions.begin(), commandLine.OwnOptions.end(), arg) !=
    commandLine.OwnOptions.end())
  {
    return commandLine.ParseOwn(arg, value, error);
  }
  else
  {
    return ParseSharedOption(arg, value, o.Data, o.Backend, o.Output, error);
  }
  return error.empty();
}
}

//------------------------------------------------------------------------------
bool Report(const char* program, const std::string& what)
{
  std::fprintf(stderr, "%s: %s\n", program, what.c_str());
  return false;
}

bool ParseAccuracyOptions(
  int argc, char* argv[], const CommandLine& commandLine, AccuracyOptions& o)
{
  static const char* const withValue[] = { "--size", "--accuracy-size", "--frames", "--rounds",
    "--samples", "--radius-fraction", "--scenes", "--methods", "--data", "--backend", "--output" };
  const std::vector<std::string>& own = commandLine.OwnOptions;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h")
    {
      commandLine.Usage();
      std::exit(0);
    }
    if (arg == "--no-error-maps")
    {
      o.ErrorMaps = false;
      continue;
    }
    if (std::find(std::begin(withValue), std::end(withValue), arg) == std::end(withValue) &&
      std::find(own.begin(), own.end(), arg) == own.end())
    {
      return Report(commandLine.Program, "unknown option " + arg);
    }
    if (i + 1 >= argc)
    {
      return Report(commandLine.Program, arg + " needs a value");
    }
    std::string error;
    if (!ParseAccuracyOption(arg, argv[++i], commandLine, o, error))
    {
      return Report(commandLine.Program, error);
    }
  }
  return true;
}

std::vector<std::string> Split(const std::string& s, char sep)
{
  std::vector<std::string> parts;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, sep))
  {
    parts.push_back(item);
  }
  return parts;
}

bool ParseInt(const std::string& s, int& v)
{
  char* end = nullptr;
  const long x = std::strtol(s.c_str(), &end, 10);
  if (s.empty() || *end || x < -1000000000L || x > 1000000000L)
  {
    return false;
  }
  v = static_cast<int>(x);
  return true;
}

bool ParseFraction(const std::string& s, double& v)
{
  char* end = nullptr;
  const double x = std::strtod(s.c_str(), &end);
  if (s.empty() || *end || !(x > 0.0 && x <= 1.0))
  {
    return false;
  }
  v = x;
  return true;
}

bool ParseSize(const std::string& s, int& w, int& h)
{
  const std::vector<std::string> p = Split(s, 'x');
  return p.size() == 2 && ParseInt(p[0], w) && ParseInt(p[1], h) && w >= 16 && h >= 16 &&
    w <= 8192 && h <= 8192;
}

double Median(std::vector<double> v)
{
  if (v.empty())
  {
    return 0.0;
  }
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string Fmt(const char* format, double v)
{
  char b[64];
  std::snprintf(b, sizeof(b), format, v);
  return b;
}

std::string FileTag(const std::string& name)
{
  std::string tag = name;
  for (char& ch : tag)
  {
    if (!std::isalnum(static_cast<unsigned char>(ch)))
    {
      ch = '-';
    }
  }
  return tag;
}

std::vector<double> TimeFrames(const std::function<void()>& frame, int warmup, int frames,
  const std::function<void(int)>& prepare)
{
  std::vector<double> ms;
  for (int f = 0; f < warmup + frames; ++f)
  {
    if (prepare)
    {
      prepare(f);
    }
    const auto start = std::chrono::steady_clock::now();
    frame();
    const auto stop = std::chrono::steady_clock::now();
    if (f >= warmup)
    {
      ms.push_back(std::chrono::duration<double, std::milli>(stop - start).count());
    }
  }
  return ms;
}

double SecondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool OpenView(const char* program, int backend, int width, int height, View& view)
{
  view.Window =
    vtkSmartPointer<vtkRenderWindow>::Take(vtkDeepGIRenderWindowFactory::NewRenderWindow(backend));
  if (!view.Window)
  {
    return Report(program, "no render window for this backend");
  }
  view.Window->SetMultiSamples(0);
  view.Window->SetOffScreenRendering(1);
  view.Window->SetSize(width, height);
  view.Renderer = vtkSmartPointer<vtkRenderer>::New();
  view.Window->AddRenderer(view.Renderer);
  return true;
}

std::vector<std::vector<double>> TimePassesInRounds(const View& view,
  const std::vector<vtkRenderPass*>& passes, int rounds, int warmup, int frames,
  const std::function<void(int)>& prepare)
{
  std::vector<std::vector<double>> ms(passes.size());
  for (int round = 0; round < rounds; ++round)
  {
    for (size_t k = 0; k < passes.size(); ++k)
    {
      view.Renderer->SetPass(passes[k]);
      const std::vector<double> t = TimeFrames(
        [&view]()
        {
          view.Window->Render();
          view.Window->WaitForCompletion();
        },
        warmup, frames, prepare);
      ms[k].insert(ms[k].end(), t.begin(), t.end());
    }
  }
  return ms;
}

std::string OpenGLRendererName(vtkRenderWindow* window)
{
  std::string name = "unknown";
  if (auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window))
  {
    std::istringstream lines(gl->ReportCapabilities());
    std::string line;
    while (std::getline(lines, line))
    {
      if (line.find("OpenGL renderer string") != std::string::npos)
      {
        name = line.substr(line.find(':') + 1);
        name.erase(0, name.find_first_not_of(' '));
      }
    }
  }
  return name;
}

bool PrepareOutputs(const char* program, const std::string& output, bool errorMaps)
{
  std::string error;
  if (!DeepGIOutput::PrepareDirectory(output, error) ||
    (errorMaps && !DeepGIOutput::PrepareDirectory(output + "/errors", error)))
  {
    return Report(program, error);
  }
  return true;
}

bool WriteTables(const char* program, const std::string& output, const std::string& stem,
  const std::string& markdown, const std::string& csv)
{
  std::fputs(markdown.c_str(), stdout);
  std::string error;
  if (!DeepGIOutput::WriteText(output + "/" + stem + ".md", markdown, error) ||
    !DeepGIOutput::WriteText(output + "/" + stem + ".csv", csv, error))
  {
    return Report(program, error);
  }
  return true;
}

std::string ErrorMapFile(
  const std::string& output, const std::string& scene, const std::string& method)
{
  return output + "/errors/" + FileTag(scene) + "-" + FileTag(method) + ".png";
}

bool WriteErrorMap(const std::string& file, int w, int h, const std::vector<float>& error,
  const std::vector<unsigned char>& mask, double scale, std::string& message)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(w, h, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* p = static_cast<unsigned char*>(image->GetScalarPointer());
  for (size_t i = 0; i < error.size(); ++i)
  {
    unsigned char rgb[3] = { 20, 20, 60 }; // excluded / empty
    if (mask[i])
    {
      const double e = std::min(1.0, std::fabs(error[i]) / scale) * 3.0;
      rgb[0] = static_cast<unsigned char>(255 * std::min(1.0, e));
      rgb[1] = static_cast<unsigned char>(255 * std::min(1.0, std::max(0.0, e - 1.0)));
      rgb[2] = static_cast<unsigned char>(255 * std::min(1.0, std::max(0.0, e - 2.0)));
    }
    std::copy(rgb, rgb + 3, p + 3 * i);
  }
  return DeepGIOutput::WritePNG(image, file, message);
}

bool WritePlot(const std::string& file, const std::string& title, const std::string& xTitle,
  const std::string& yTitle, const std::vector<std::string>& families, const Curves& curves,
  int backend, std::string& message)
{
  vtkSmartPointer<vtkRenderWindow> window =
    vtkSmartPointer<vtkRenderWindow>::Take(vtkDeepGIRenderWindowFactory::NewRenderWindow(backend));
  if (!window)
  {
    message = "cannot write " + file + ": no render window for the plot";
    return false;
  }
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  vtkNew<vtkContextView> view;
  view->SetRenderWindow(window);
  view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
  window->SetSize(900, 600);
  vtkNew<vtkChartXY> chart;
  view->GetScene()->AddItem(chart);
  chart->SetTitle(title);
  chart->SetShowLegend(true);
  chart->GetAxis(vtkAxis::BOTTOM)->SetTitle(xTitle);
  chart->GetAxis(vtkAxis::LEFT)->SetTitle(yTitle);
  const unsigned char colors[][3] = { { 200, 40, 40 }, { 40, 90, 200 }, { 30, 150, 60 },
    { 150, 60, 170 }, { 230, 140, 20 }, { 20, 160, 170 }, { 60, 60, 60 }, { 140, 90, 40 } };
  const int colorCount = static_cast<int>(sizeof(colors) / sizeof(colors[0]));
  int c = 0;
  // The tables must live until the chart is rendered.
  std::vector<vtkSmartPointer<vtkTable>> tables;
  for (const std::string& family : families)
  {
    auto it = curves.find(family);
    if (it == curves.end() || it->second.empty())
    {
      continue;
    }
    std::vector<std::pair<double, double>> pts = it->second;
    std::sort(pts.begin(), pts.end());
    auto table = vtkSmartPointer<vtkTable>::New();
    vtkNew<vtkFloatArray> x, y;
    x->SetName("x");
    y->SetName(family.c_str());
    for (const auto& pt : pts)
    {
      x->InsertNextValue(static_cast<float>(pt.first));
      y->InsertNextValue(static_cast<float>(pt.second));
    }
    table->AddColumn(x);
    table->AddColumn(y);
    tables.push_back(table);
    vtkPlot* line = chart->AddPlot(pts.size() > 1 ? vtkChart::LINE : vtkChart::POINTS);
    line->SetInputData(table, 0, 1);
    const unsigned char* col = colors[c++ % colorCount];
    line->SetColor(col[0], col[1], col[2], 255);
    line->SetWidth(2.5);
  }
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->Update();
  return DeepGIOutput::WritePNG(grab->GetOutput(), file, message);
}

bool WriteErrorTimePlots(const char* program, const std::string& output, const std::string& stem,
  int backend, const ErrorTimePlots& plots)
{
  std::vector<std::string> families;
  for (const auto& method : plots.Methods)
  {
    if (std::find(families.begin(), families.end(), method.second) == families.end())
    {
      families.push_back(method.second);
    }
  }
  Curves mean;
  for (const auto& method : plots.Methods)
  {
    double t = 0, e = 0;
    int n = 0;
    for (const PlotPoint& p : plots.Points)
    {
      if (p.Method == method.first)
      {
        t += p.FrameMs;
        e += p.Error;
        ++n;
      }
    }
    if (n)
    {
      mean[method.second].push_back({ t / n, e / n });
    }
  }
  std::string error;
  if (!WritePlot(output + "/" + stem + "-plot.png", plots.Title + " (mean over scenes)",
        plots.XTitle, plots.YTitle, families, mean, backend, error))
  {
    return Report(program, error);
  }
  for (const std::string& scene : plots.Scenes)
  {
    Curves curves;
    for (const PlotPoint& p : plots.Points)
    {
      if (p.Scene == scene)
      {
        curves[p.Family].push_back({ p.FrameMs, p.Error });
      }
    }
    if (!WritePlot(output + "/" + stem + "-plot-" + FileTag(scene) + ".png",
          plots.Title + ", " + scene, plots.XTitle, plots.YTitle, families, curves, backend, error))
    {
      return Report(program, error);
    }
  }
  return true;
}

bool WriteResults(const char* program, const AccuracyOptions& o, const std::string& stem,
  const std::string& markdown, const std::string& csv, const ErrorTimePlots& plots)
{
  if (!WriteTables(program, o.Output, stem, markdown, csv) ||
    !WriteErrorTimePlots(program, o.Output, stem, o.Backend, plots))
  {
    return false;
  }
  std::printf("\nwrote %s/%s.{md,csv}, %s/%s-plot.png\n", o.Output.c_str(), stem.c_str(),
    o.Output.c_str(), stem.c_str());
  return true;
}
}
