// Code shared by the deepgi-benchmark-* programs: the command line of the
// accuracy benchmarks and option parsing helpers, the render window, frame
// timing in rounds, medians of frame times, the output directory, tables,
// error maps and error-against-time plots made with VTK's charts offscreen.
#ifndef DeepGIBenchmarkCommon_h
#define DeepGIBenchmarkCommon_h

#include "vtkDeepGIRenderWindowFactory.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"

#include <chrono>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

class vtkRenderPass;
class vtkRenderer;

namespace DeepGIBenchmark
{
/// Prints "PROGRAM: what" on stderr; returns false (`return Report(...)`).
bool Report(const char* program, const std::string& what);

/// The options of the accuracy benchmarks (deepgi-benchmark-ao and
/// deepgi-benchmark-radiosity).
struct AccuracyOptions
{
  struct Size
  {
    int Width;
    int Height;
  };
  /// A benchmark's defaults: the timing and the accuracy sizes, the timed
  /// and the warm-up frames per method and round, the reference's rays per
  /// pixel, the scenes and the methods (a comma list).
  AccuracyOptions(Size timing, Size accuracy, int frames, int warmup, int samples,
    const std::vector<std::string>& scenes, const std::string& methods)
    : Width(timing.Width)
    , Height(timing.Height)
    , AccuracyWidth(accuracy.Width)
    , AccuracyHeight(accuracy.Height)
    , Frames(frames)
    , Warmup(warmup)
    , Samples(samples)
    , Scenes(scenes)
    , MethodList(methods)
  {
  }
  int Width, Height;                 // --size: the timing size
  int AccuracyWidth, AccuracyHeight; // --accuracy-size: the size of the error measurement
  int Frames;                        // --frames: timed frames per method and round
  int Rounds = 2;                    // --rounds: rounds over all methods
  int Warmup;                        // untimed frames before each method's timed ones
  int Samples;                       // --samples: reference rays per pixel
  double RadiusFraction = 0.0;       // --radius-fraction
  int Backend = vtkDeepGIRenderWindowFactory::BACKEND_AUTO;
  std::string Output = "output";
  std::string Data;
  std::vector<std::string> Scenes;
  bool ScenesGiven = false; // --scenes was on the command line
  std::string MethodList;   // --methods
  bool ErrorMaps = true;    // false with --no-error-maps
};

/// A benchmark's own option with a value: false with `error` set when
/// `value` is invalid.
using OptionParser =
  std::function<bool(const std::string& arg, const std::string& value, std::string& error)>;

/// What an accuracy benchmark's command line accepts beyond the shared options.
struct CommandLine
{
  const char* Program;
  void (*Usage)();
  std::vector<std::string> SceneNames; // what --scenes accepts
  std::vector<std::string> OwnOptions; // the benchmark's own options with a value
  OptionParser ParseOwn;               // reads each of OwnOptions
};

/// Reads the command line into `o`: --help / -h (prints the usage, exits 0),
/// --no-error-maps, --size, --accuracy-size, --frames, --rounds, --samples,
/// --radius-fraction, --scenes, --methods (into MethodList), --data,
/// --backend, --output, and the benchmark's own options. False, with the
/// reason on stderr, at the first unknown option or invalid value.
bool ParseAccuracyOptions(
  int argc, char* argv[], const CommandLine& commandLine, AccuracyOptions& o);

/// `list` cut at commas, each parsed by `parse` into `methods`: false, with
/// the reason on stderr, when it names no method or one that `parse`
/// rejects ("unknown method 'M' (SYNTAX)").
template <typename Method>
bool ParseMethodList(const char* program, const std::string& list,
  bool (*parse)(const std::string&, Method&), const std::string& syntax,
  std::vector<Method>& methods);

/// `s` cut at every `sep` (empty fields kept, a trailing separator dropped).
std::vector<std::string> Split(const std::string& s, char sep);

/// Whole string as a decimal integer in [-1e9, 1e9].
bool ParseInt(const std::string& s, int& v);

/// Whole string as a number in (0, 1] (a radius as a fraction of the
/// scene's diagonal).
bool ParseFraction(const std::string& s, double& v);

/// "WxH" with 16..8192 pixels per side.
bool ParseSize(const std::string& s, int& w, int& h);

/// Median (mean of the two middle values for an even count; 0 if empty).
double Median(std::vector<double> v);

/// printf-style formatting of one number.
std::string Fmt(const char* format, double v);

/// `name` with every character that is not a letter or digit replaced by '-'
/// (for file names).
std::string FileTag(const std::string& name);

/// Milliseconds of `frame()` (which must wait for the GPU), repeated
/// `warmup + frames` times; the warm-up frames are not returned.
/// `prepare(f)`, when given, runs untimed before frame f (0: the first
/// warm-up frame).
std::vector<double> TimeFrames(const std::function<void()>& frame, int warmup, int frames,
  const std::function<void(int)>& prepare = nullptr);

/// Seconds from `start` to now.
double SecondsSince(std::chrono::steady_clock::time_point start);

/// A benchmark's offscreen render window, without multisampling, and its
/// one renderer.
struct View
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
};

/// A `width` x `height` view of `backend`; false, with "PROGRAM: no render
/// window for this backend" on stderr, when the backend has none.
bool OpenView(const char* program, int backend, int width, int height, View& view);

/// Frame times of `passes` (nullptr: VTK's own rendering) in `view`:
/// `rounds` rounds over all passes in their order, each pass's frames back
/// to back (`warmup` untimed, then `frames` timed from Render() to
/// WaitForCompletion()), so that slow drifts of the machine affect all
/// passes alike. `prepare` as for TimeFrames. Returns each pass's
/// milliseconds, all rounds together.
std::vector<std::vector<double>> TimePassesInRounds(const View& view,
  const std::vector<vtkRenderPass*>& passes, int rounds, int warmup, int frames,
  const std::function<void(int)>& prepare = nullptr);

/// The frame times of an accuracy benchmark at its timing size (--size):
/// `baselines` (nullptr: VTK without a pass), then every method's pass,
/// timed in rounds (TimePassesInRounds with --rounds, --frames and the
/// warm-up). Each method's median into its result's FrameMs (`results` in
/// the order of `passes`); returns the baselines' medians.
template <typename Pass, typename Result>
std::vector<double> TimeMethods(const View& view, const AccuracyOptions& o,
  std::vector<vtkRenderPass*> baselines, const std::vector<vtkSmartPointer<Pass>>& passes,
  std::vector<Result>& results);

/// The "OpenGL renderer string" of `window`'s capabilities ("unknown" when
/// it reports none).
std::string OpenGLRendererName(vtkRenderWindow* window);

/// Makes the output directory (and its "errors" folder with `errorMaps`),
/// checked before the measuring; false, with "PROGRAM: reason" on stderr,
/// when it cannot.
bool PrepareOutputs(const char* program, const std::string& output, bool errorMaps);

/// Prints `markdown` on stdout and writes OUTPUT/STEM.md and OUTPUT/STEM.csv
/// with DeepGIOutput; false, with "PROGRAM: reason" on stderr, when it cannot.
bool WriteTables(const char* program, const std::string& output, const std::string& stem,
  const std::string& markdown, const std::string& csv);

/// OUTPUT/errors/SCENE-METHOD.png, both names through FileTag.
std::string ErrorMapFile(
  const std::string& output, const std::string& scene, const std::string& method);

/// Writes a w x h PNG of `error` (bottom row first) with the colour map
/// black -> red -> yellow -> white for error = 0 .. `scale`; pixels where
/// mask is 0 are dark blue. Written with DeepGIOutput::WritePNG; false with
/// `message` set when it fails.
bool WriteErrorMap(const std::string& file, int w, int h, const std::vector<float>& error,
  const std::vector<unsigned char>& mask, double scale, std::string& message);

/// One curve per family (in `families`' order, skipping missing ones) of
/// (x, y) points sorted by x, drawn with vtkChartXY in an offscreen
/// 900 x 600 window of `backend` and written as a PNG with
/// DeepGIOutput::WritePNG; false with `message` set when it fails.
using Curves = std::map<std::string, std::vector<std::pair<double, double>>>;
bool WritePlot(const std::string& file, const std::string& title, const std::string& xTitle,
  const std::string& yTitle, const std::vector<std::string>& families, const Curves& curves,
  int backend, std::string& message);

/// One method's frame time and error on one scene: a point of the
/// error-against-time plots.
struct PlotPoint
{
  std::string Scene;
  std::string Method;
  std::string Family; // the curve
  double FrameMs;
  double Error;
};

/// The error-against-time plots of a benchmark.
struct ErrorTimePlots
{
  std::string Title; // "TITLE (mean over scenes)", "TITLE, SCENE"
  std::string XTitle;
  std::string YTitle;
  /// (method, family) in the benchmark's order: the order of the curves,
  /// and of the points of the plot of the means (one per entry).
  std::vector<std::pair<std::string, std::string>> Methods;
  std::vector<std::string> Scenes; // one plot each
  std::vector<PlotPoint> Points;
};

/// The error-against-time plots `title` of an accuracy benchmark's
/// `results` (each with its Scene, its method M and FrameMs) of `methods`
/// (each with its Name) on `scenes` (each with its Name): `familyOf(method)`
/// names the method's curve, `errorOf(result)` is the error on the y axis.
template <typename Method, typename Scene, typename Result, typename FamilyOf, typename ErrorOf>
ErrorTimePlots MakeErrorTimePlots(const std::string& title, const std::string& yTitle,
  const std::vector<Method>& methods, const std::vector<Scene>& scenes,
  const std::vector<Result>& results, FamilyOf familyOf, ErrorOf errorOf);

/// Writes OUTPUT/STEM-plot.png (every method's frame time and error,
/// averaged over the scenes) and OUTPUT/STEM-plot-SCENE.png for each scene
/// (its name through FileTag) with WritePlot; false, with "PROGRAM: reason"
/// on stderr, when it cannot.
bool WriteErrorTimePlots(const char* program, const std::string& output, const std::string& stem,
  int backend, const ErrorTimePlots& plots);

/// The stages of an accuracy benchmark, which RunAccuracyBenchmark runs in
/// this order.
template <typename Options, typename Measurements>
struct AccuracyBenchmark
{
  const char* Program;
  const char* Stem; // of the output files: STEM.md, STEM.csv, STEM-plot.png, ...
  /// Reads the command line; false, with the reason on stderr, when it is
  /// not valid (then the usage is printed).
  bool (*ParseOptions)(int argc, char* argv[], Options& o);
  void (*Usage)();
  /// Measures one of Options::Scenes (accuracy, then time); false, with the
  /// reason on stderr, when it cannot.
  bool (*MeasureScene)(const Options& o, const std::string& scene, Measurements& measured);
  std::string (*Markdown)(const Options& o, const Measurements& measured);
  std::string (*Csv)(const Measurements& measured);
  ErrorTimePlots (*Plots)(const Options& o, const Measurements& measured);
};

/// Runs `benchmark`'s stages: parses the command line, checks the outputs
/// (before the hours of measuring), measures every scene in turn, then
/// writes the tables and plots (WriteResults). Returns main's exit status:
/// 2 for an invalid command line, 1 when a measurement or an output fails.
template <typename Options, typename Measurements>
int RunAccuracyBenchmark(
  const AccuracyBenchmark<Options, Measurements>& benchmark, int argc, char* argv[]);

/// An accuracy benchmark's outputs: WriteTables, then WriteErrorTimePlots,
/// then where they are on stdout; false, with "PROGRAM: reason" on stderr,
/// when they cannot be written.
bool WriteResults(const char* program, const AccuracyOptions& o, const std::string& stem,
  const std::string& markdown, const std::string& csv, const ErrorTimePlots& plots);

//------------------------------------------------------------------------------
template <typename Method>
bool ParseMethodList(const char* program, const std::string& list,
  bool (*parse)(const std::string&, Method&), const std::string& syntax,
  std::vector<Method>& methods)
{
  const std::vector<std::string> specs = Split(list, ',');
  if (specs.empty())
  {
    return Report(program, "--methods needs at least one method");
  }
  for (const std::string& spec : specs)
  {
    Method m;
    if (!parse(spec, m))
    {
      return Report(program, "unknown method '" + spec + "' (" + syntax + ")");
    }
    methods.push_back(m);
  }
  return true;
}

template <typename Method, typename Scene, typename Result, typename FamilyOf, typename ErrorOf>
ErrorTimePlots MakeErrorTimePlots(const std::string& title, const std::string& yTitle,
  const std::vector<Method>& methods, const std::vector<Scene>& scenes,
  const std::vector<Result>& results, FamilyOf familyOf, ErrorOf errorOf)
{
  ErrorTimePlots plots;
  plots.Title = title;
  plots.XTitle = "frame time [ms] (median)";
  plots.YTitle = yTitle;
  for (const Method& m : methods)
  {
    plots.Methods.emplace_back(m.Name, familyOf(m));
  }
  for (const Scene& s : scenes)
  {
    plots.Scenes.push_back(s.Name);
  }
  for (const Result& r : results)
  {
    plots.Points.push_back({ r.Scene, r.M.Name, familyOf(r.M), r.FrameMs, errorOf(r) });
  }
  return plots;
}

template <typename Pass, typename Result>
std::vector<double> TimeMethods(const View& view, const AccuracyOptions& o,
  std::vector<vtkRenderPass*> baselines, const std::vector<vtkSmartPointer<Pass>>& passes,
  std::vector<Result>& results)
{
  view.Window->SetSize(o.Width, o.Height);
  const size_t baselineCount = baselines.size();
  for (const auto& pass : passes)
  {
    baselines.push_back(pass);
  }
  const std::vector<std::vector<double>> ms =
    TimePassesInRounds(view, baselines, o.Rounds, o.Warmup, o.Frames);
  for (size_t k = 0; k < results.size(); ++k)
  {
    results[k].FrameMs = Median(ms[baselineCount + k]);
  }
  std::vector<double> medians;
  for (size_t k = 0; k < baselineCount; ++k)
  {
    medians.push_back(Median(ms[k]));
  }
  return medians;
}

template <typename Options, typename Measurements>
int RunAccuracyBenchmark(
  const AccuracyBenchmark<Options, Measurements>& benchmark, int argc, char* argv[])
{
  Options options;
  if (!benchmark.ParseOptions(argc, argv, options))
  {
    benchmark.Usage();
    return 2;
  }
  // The outputs are checked before the hours of measuring.
  if (!PrepareOutputs(benchmark.Program, options.Output, options.ErrorMaps))
  {
    return 1;
  }
  Measurements measured;
  for (const std::string& scene : options.Scenes)
  {
    if (!benchmark.MeasureScene(options, scene, measured))
    {
      return 1;
    }
  }
  const std::string markdown = benchmark.Markdown(options, measured);
  const std::string csv = benchmark.Csv(measured);
  return WriteResults(benchmark.Program, options, benchmark.Stem, markdown, csv,
           benchmark.Plots(options, measured))
    ? 0
    : 1;
}
}

#endif
