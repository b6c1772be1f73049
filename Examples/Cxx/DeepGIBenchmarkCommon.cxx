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
#include "vtkPlot.h"
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
//------------------------------------------------------------------------------
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

std::vector<double> TimeFrames(const std::function<void()>& frame, int warmup, int frames)
{
  std::vector<double> ms;
  for (int f = 0; f < warmup + frames; ++f)
  {
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
}
