#include "DeepGIRenderFigures.h"

#include "DeepGIOutput.h"

#include "vtkDataArray.h"
#include "vtkImageAppend.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkTextProperty.h"
#include "vtkTextRenderer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace DeepGIRenderFigures
{
namespace
{
vtkSmartPointer<vtkImageData> NewRGB(int width, int height)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  return image;
}

unsigned char ToByte(double v)
{
  return static_cast<unsigned char>(std::lround(255.0 * std::min(1.0, std::max(0.0, v))));
}

// Value of component c of tuple i, mapped to [0, 1] (before clamping).
double Mapped(
  vtkDataArray* a, vtkIdType i, int c, Mapping mapping, double lo, double hi, double scale)
{
  const int components = a->GetNumberOfComponents();
  switch (mapping)
  {
    case Mapping::Grey:
      return a->GetComponent(i, 0);
    case Mapping::Depth:
      return hi > lo ? 1.0 - 0.8 * (a->GetComponent(i, 0) - lo) / (hi - lo) : 1.0;
    case Mapping::Normal:
      return a->GetComponent(i, std::min(c, components - 1)) * 0.5 + 0.5;
    case Mapping::Exposure:
      return scale * a->GetComponent(i, std::min(c, components - 1));
    case Mapping::Colour:
    default:
      return a->GetComponent(i, std::min(c, components - 1));
  }
}

// The 99th percentile of the largest RGB component over the valid pixels.
double Percentile99(vtkDataArray* a, vtkUnsignedCharArray* valid)
{
  std::vector<double> values;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    if (!valid || valid->GetValue(i))
    {
      double m = 0.0;
      for (int c = 0; c < std::min(3, a->GetNumberOfComponents()); ++c)
      {
        m = std::max(m, a->GetComponent(i, c));
      }
      values.push_back(m);
    }
  }
  if (values.empty())
  {
    return 0.0;
  }
  const size_t k = static_cast<size_t>(0.99 * static_cast<double>(values.size() - 1));
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[k];
}

// Range of component 0 over the valid pixels.
void ValidRange(vtkDataArray* a, vtkUnsignedCharArray* valid, double& lo, double& hi)
{
  lo = VTK_DOUBLE_MAX;
  hi = -VTK_DOUBLE_MAX;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    if (!valid || valid->GetValue(i))
    {
      lo = std::min(lo, a->GetComponent(i, 0));
      hi = std::max(hi, a->GetComponent(i, 0));
    }
  }
}
} // anonymous namespace

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> GrabWindow(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff(); // offscreen: the image is in the back buffer
  grab->ShouldRerenderOff();  // the caller rendered the frame to keep
  grab->SetInputBufferTypeToRGB();
  grab->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(grab->GetOutput());
  return image;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> Panel(vtkImageData* capture, const char* arrayName,
  const char* validName, Mapping mapping, double* scale)
{
  vtkDataArray* a = capture ? capture->GetPointData()->GetArray(arrayName) : nullptr;
  if (!a)
  {
    return nullptr;
  }
  auto* valid = vtkUnsignedCharArray::SafeDownCast(capture->GetPointData()->GetArray(validName));
  double lo = 0.0, hi = 0.0, factor = 1.0;
  if (mapping == Mapping::Depth)
  {
    ValidRange(a, valid, lo, hi);
  }
  if (mapping == Mapping::Exposure)
  {
    const double p99 = Percentile99(a, valid);
    factor = p99 > 0.0 ? 1.0 / p99 : 1.0;
    if (scale)
    {
      *scale = factor;
    }
  }
  int dims[3];
  capture->GetDimensions(dims);
  auto panel = NewRGB(dims[0], dims[1]);
  auto* out = static_cast<unsigned char*>(panel->GetScalarPointer());
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    const bool inside = !valid || valid->GetValue(i);
    for (int c = 0; c < 3; ++c)
    {
      out[3 * i + c] = inside ? ToByte(Mapped(a, i, c, mapping, lo, hi, factor)) : 0;
    }
  }
  return panel;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> BlankPanel(int width, int height)
{
  auto panel = NewRGB(width, height);
  std::fill_n(static_cast<unsigned char*>(panel->GetScalarPointer()), 3LL * width * height, 64);
  return panel;
}

//------------------------------------------------------------------------------
void Label(vtkImageData* panel, const std::string& text)
{
  vtkTextRenderer* renderer = vtkTextRenderer::GetInstance();
  if (!renderer || text.empty())
  {
    return; // no FreeType renderer: the panel stays unlabelled
  }
  vtkNew<vtkTextProperty> property;
  property->SetFontSize(15);
  property->SetColor(1.0, 1.0, 1.0);
  property->SetBackgroundColor(0.0, 0.0, 0.0);
  property->SetBackgroundOpacity(0.6);
  vtkNew<vtkImageData> textImage;
  int textSize[2] = { 0, 0 };
  if (!renderer->RenderString(property, text, textImage, textSize, 96))
  {
    return;
  }
  int dims[3];
  panel->GetDimensions(dims);
  const int* extent = textImage->GetExtent();
  const int margin = 4;
  for (int ty = 0; ty < textSize[1]; ++ty)
  {
    const int y = dims[1] - margin - textSize[1] + ty;
    for (int tx = 0; tx < textSize[0]; ++tx)
    {
      const int x = margin + tx;
      if (x >= dims[0] || y < 0 || y >= dims[1])
      {
        continue;
      }
      const auto* rgba = static_cast<unsigned char*>(
        textImage->GetScalarPointer(extent[0] + tx, extent[2] + ty, extent[4]));
      auto* rgb = static_cast<unsigned char*>(panel->GetScalarPointer(x, y, 0));
      const double alpha = rgba[3] / 255.0;
      for (int c = 0; c < 3; ++c)
      {
        rgb[c] = ToByte((alpha * rgba[c] + (1.0 - alpha) * rgb[c]) / 255.0);
      }
    }
  }
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> Half(vtkImageData* panel)
{
  int dims[3];
  panel->GetDimensions(dims);
  const int w = std::max(1, dims[0] / 2), h = std::max(1, dims[1] / 2);
  auto half = NewRGB(w, h);
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      auto* out = static_cast<unsigned char*>(half->GetScalarPointer(x, y, 0));
      for (int c = 0; c < 3; ++c)
      {
        int sum = 0, count = 0;
        for (int dy = 0; dy < 2; ++dy)
        {
          for (int dx = 0; dx < 2; ++dx)
          {
            const int sx = std::min(2 * x + dx, dims[0] - 1),
                      sy = std::min(2 * y + dy, dims[1] - 1);
            sum += static_cast<unsigned char*>(panel->GetScalarPointer(sx, sy, 0))[c];
            ++count;
          }
        }
        out[c] = static_cast<unsigned char>((sum + count / 2) / count);
      }
    }
  }
  return half;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> Tile(
  const std::vector<vtkSmartPointer<vtkImageData>>& panels, int columns)
{
  // VTK images grow upwards: the rows are appended bottom row first.
  vtkNew<vtkImageAppend> rows;
  rows->SetAppendAxis(1);
  const int count = static_cast<int>(panels.size());
  const int numberOfRows = (count + columns - 1) / columns;
  for (int r = numberOfRows - 1; r >= 0; --r)
  {
    vtkNew<vtkImageAppend> row;
    row->SetAppendAxis(0);
    for (int c = 0; c < columns; ++c)
    {
      const int k = r * columns + c;
      if (k < count)
      {
        row->AddInputData(panels[k]);
      }
      else
      {
        int dims[3];
        panels[0]->GetDimensions(dims);
        row->AddInputData(BlankPanel(dims[0], dims[1]));
      }
    }
    row->Update();
    auto copy = vtkSmartPointer<vtkImageData>::New();
    copy->DeepCopy(row->GetOutput());
    rows->AddInputData(copy);
  }
  rows->Update();
  auto tiled = vtkSmartPointer<vtkImageData>::New();
  tiled->DeepCopy(rows->GetOutput());
  return tiled;
}

//------------------------------------------------------------------------------
bool WritePNG(vtkImageData* image, const std::string& fileName)
{
  std::string error;
  if (!DeepGIOutput::WritePNG(image, fileName, error))
  {
    std::cerr << "deepgi-render: " << error << "\n";
    return false;
  }
  return true;
}
} // namespace DeepGIRenderFigures
