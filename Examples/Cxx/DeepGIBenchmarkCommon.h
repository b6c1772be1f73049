// Code shared by the deepgi-benchmark-* programs: the command line of the
// accuracy benchmarks and option parsing helpers, the render window, frame
// timing in rounds, medians of frame times, the output directory, tables,
// error maps and error-against-time plots made with VTK's charts offscreen.
#ifndef DeepGIBenchmarkCommon_h
#define DeepGIBenchmarkCommon_h

#include "vtkDeepGIRenderWindowFactory.h"
#include "vtkSmartPointer.h"

#include <chrono>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

class vtkRenderPass;
class vtkRenderWindow;
class vtkRenderer;

namespace DeepGIBenchmark
{
/// Prints "PROGRAM: what" on stderr; returns false (`return Report(...)`).
bool Report(const char* program, const std::string& what);

/// The options of the accuracy benchmarks (deepgi-benchmark-ao and
/// deepgi-benchmark-radiosity), whose values each benchmark's defaults set.
struct AccuracyOptions
{
  int Width = 0;          // --size: the timing size
  int Height = 0;         //
  int AccuracyWidth = 0;  // --accuracy-size: the size of the error measurement
  int AccuracyHeight = 0; //
  int Frames = 0;         // --frames: timed frames per method and round
  int Rounds = 0;         // --rounds: rounds over all methods
  int Warmup = 0;         // untimed frames before each method's timed ones
  int Samples = 0;        // --samples: reference rays per pixel
  double RadiusFraction = 0.0;
  int Backend = vtkDeepGIRenderWindowFactory::BACKEND_AUTO;
  std::string Output = "output";
  std::string Data;
  std::vector<std::string> Scenes;
  bool ScenesGiven = false; // --scenes was on the command line
  std::string MethodList;   // --methods, the benchmark's default list unless given
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

/// The options every benchmark shares: --data DIR, --backend NAME (auto,
/// x11, egl), --output DIR (not empty). Returns false with `error` set when
/// `arg` is one of them and `value` is invalid; other options are ignored.
bool ParseSharedOption(const std::string& arg, const std::string& value, std::string& data,
  int& backend, std::string& output, std::string& error);

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

/// Writes OUTPUT/STEM-plot.png (every method's frame time and error,
/// averaged over the scenes) and OUTPUT/STEM-plot-SCENE.png for each scene
/// (its name through FileTag) with WritePlot; false, with "PROGRAM: reason"
/// on stderr, when it cannot.
bool WriteErrorTimePlots(const char* program, const std::string& output, const std::string& stem,
  int backend, const ErrorTimePlots& plots);

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
}

#endif
