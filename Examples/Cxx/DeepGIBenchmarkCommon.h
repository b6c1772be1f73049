// Code shared by the deepgi-benchmark-* programs: option parsing helpers,
// medians of frame times, error maps and error-against-time plots made with
// VTK's charts offscreen.
#ifndef DeepGIBenchmarkCommon_h
#define DeepGIBenchmarkCommon_h

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace DeepGIBenchmark
{
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
std::vector<double> TimeFrames(const std::function<void()>& frame, int warmup, int frames);

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
}

#endif
