// Tests vtkDeepGIEXRReader and vtkDeepGIEXRWriter (no rendering):
//  1. FLOAT round trip: every float value bit-identical (negative, tiny,
//     huge, infinite included), doubles rounded to float, unsigned char and
//     6-component arrays, origin and orientation; the written file checked
//     with OpenEXR directly (channel names, types, windows, top row);
//  2. HALF round trip: |a - b| <= 2^-11 |a| + 2^-24 for every value;
//  3. a file written with OpenEXR directly (tiled, half and uint channels,
//     unlayered R G B A, an offset data window) read into the documented
//     arrays, rows flipped, origin honoured;
//  4. a G-buffer capture round trip (the arrays and field data of
//     vtkDeepGBufferPass::CaptureLayers, two layers): identical arrays and
//     field data, and vtkDeepGIReferenceObscurance gives bit-identical
//     results on the original and the reloaded capture;
//  5. bad input: missing file, not an EXR file, unwritable path, empty and
//     3D images, no numeric arrays, no file name, no input: errors, no crash.

#include "DeepGIReferenceTestUtilities.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIEXRReader.h"
#include "vtkDeepGIEXRWriter.h"
#include "vtkDeepGIReferenceObscurance.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfTiledOutputFile.h>
#include <half.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

using namespace DeepGIReferenceTest;
using namespace DeepGITest;

namespace
{
// A deterministic value for (array, tuple, component), covering signs and
// magnitudes from 1e-30 to 1e30 (float) or a half-representable range.
double Value(int array, vtkIdType tuple, int component, bool halfRange)
{
  const double u = std::sin(12.9898 * (tuple + 1) + 78.233 * (component + 1) + 3.7 * array);
  const double exponent = halfRange ? std::fmod(std::fabs(u) * 1e3, 8.0) - 4.0
                                    : std::fmod(std::fabs(u) * 1e4, 60.0) - 30.0;
  return (u < 0 ? -1.0 : 1.0) * std::pow(10.0, exponent);
}

vtkSmartPointer<vtkImageData> MakeImage(int w, int h, bool halfRange)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  image->SetOrigin(3, 2, 0);
  const vtkIdType n = static_cast<vtkIdType>(w) * h;
  struct Spec
  {
    std::string Name;
    int Components;
    int Type;
  };
  const Spec specs[] = { { vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Radiance, 0), 4,
                           VTK_FLOAT },
    { vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Depth, 0), 1, VTK_FLOAT },
    { "RGB", 3, VTK_FLOAT }, { "Many", 6, VTK_FLOAT }, { "Pair", 2, VTK_FLOAT },
    { vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Normal, 0), 3, VTK_DOUBLE },
    { vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 0), 1, VTK_UNSIGNED_CHAR } };
  int index = 0;
  for (const Spec& spec : specs)
  {
    vtkSmartPointer<vtkDataArray> array =
      vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(spec.Type));
    array->SetName(spec.Name.c_str());
    array->SetNumberOfComponents(spec.Components);
    array->SetNumberOfTuples(n);
    for (vtkIdType t = 0; t < n; ++t)
    {
      for (int c = 0; c < spec.Components; ++c)
      {
        array->SetComponent(t, c,
          spec.Type == VTK_UNSIGNED_CHAR ? (t * 37 + c) % 256 : Value(index, t, c, halfRange));
      }
    }
    image->GetPointData()->AddArray(array);
    ++index;
  }
  if (!halfRange)
  {
    auto radiance = vtkFloatArray::SafeDownCast(image->GetPointData()->GetArray(
      vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Radiance, 0).c_str()));
    radiance->SetTypedComponent(0, 0, std::numeric_limits<float>::infinity());
    radiance->SetTypedComponent(1, 1, -0.0f);
    radiance->SetTypedComponent(2, 2, std::numeric_limits<float>::denorm_min());
  }
  return image;
}

// Compares every array of `expected` with the array of the same name in
// `actual`: float arrays bit for bit (or within half precision), others
// after rounding to float.
void CompareImages(vtkImageData* expected, vtkImageData* actual, bool half, const std::string& what)
{
  int dims[3], dimsActual[3];
  expected->GetDimensions(dims);
  actual->GetDimensions(dimsActual);
  Check(dims[0] == dimsActual[0] && dims[1] == dimsActual[1] && dimsActual[2] == 1,
    what + ": dimensions " + std::to_string(dimsActual[0]) + " x " + std::to_string(dimsActual[1]));
  double o[3], oa[3];
  expected->GetOrigin(o);
  actual->GetOrigin(oa);
  Check(o[0] == oa[0] && o[1] == oa[1] && oa[2] == 0, what + ": origin restored");
  int arrays = 0, bad = 0;
  double worst = 0;
  for (int a = 0; a < expected->GetPointData()->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* e = expected->GetPointData()->GetArray(a);
    auto r = vtkFloatArray::SafeDownCast(actual->GetPointData()->GetArray(e->GetName()));
    if (!r || r->GetNumberOfComponents() != e->GetNumberOfComponents() ||
      r->GetNumberOfTuples() != e->GetNumberOfTuples())
    {
      Check(false, what + ": float array " + e->GetName() + " with its shape");
      continue;
    }
    ++arrays;
    for (vtkIdType i = 0; i < e->GetNumberOfTuples(); ++i)
    {
      for (int c = 0; c < e->GetNumberOfComponents(); ++c)
      {
        const float x = static_cast<float>(e->GetComponent(i, c));
        const float y = r->GetTypedComponent(i, c);
        if (half)
        {
          const double err = std::fabs(static_cast<double>(x) - y);
          const double tolerance = std::ldexp(std::fabs(x), -11) + std::ldexp(1.0, -24);
          bad += !(err <= tolerance);
          worst = std::max(worst, err / tolerance);
        }
        else
        {
          bad += std::memcmp(&x, &y, sizeof(float)) != 0;
        }
      }
    }
  }
  if (half)
  {
    std::cout << what << ": largest error / (2^-11 |a| + 2^-24) = " << worst << "\n";
  }
  Check(arrays == expected->GetPointData()->GetNumberOfArrays(), what + ": all arrays read back");
  Check(bad == 0, what + ": " + std::to_string(bad) + " values differ");
}

vtkSmartPointer<vtkImageData> Read(const std::string& file)
{
  vtkNew<vtkDeepGIEXRReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(reader->GetOutput());
  return image;
}

bool Write(vtkImageData* image, const std::string& file, int pixelType)
{
  vtkNew<vtkDeepGIEXRWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(file.c_str());
  writer->SetPixelType(pixelType);
  return writer->Write() == 1;
}

// The arrays and field data that vtkDeepGBufferPass::CaptureLayers makes: a
// camera looking down at a floor with a box, two layers.
vtkSmartPointer<vtkImageData> MakeCapture(int w, int h)
{
  vtkNew<vtkCamera> camera;
  camera->SetPosition(0.3, 0.2, 3);
  camera->SetFocalPoint(0.3, 0.2, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetClippingRange(0.3, 6);
  vtkMatrix4x4* view = camera->GetModelViewTransformMatrix();
  vtkMatrix4x4* projection = camera->GetProjectionTransformMatrix(double(w) / h, -1, 1);
  auto capture = vtkSmartPointer<vtkImageData>::New();
  capture->SetDimensions(w, h, 1);
  const vtkIdType n = static_cast<vtkIdType>(w) * h;
  double up[4] = { 0, 0, 1, 0 }, nc[4];
  view->MultiplyPoint(up, nc);
  for (int layer = 0; layer < 2; ++layer)
  {
    const std::string s = "_" + std::to_string(layer);
    vtkNew<vtkFloatArray> radiance, albedo, normal, depth, ambient;
    vtkNew<vtkUnsignedCharArray> valid;
    radiance->SetName((vtkDeepGICaptureNames::Radiance + s).c_str());
    radiance->SetNumberOfComponents(4);
    albedo->SetName((vtkDeepGICaptureNames::Albedo + s).c_str());
    albedo->SetNumberOfComponents(3);
    normal->SetName((vtkDeepGICaptureNames::Normal + s).c_str());
    normal->SetNumberOfComponents(3);
    ambient->SetName((vtkDeepGICaptureNames::Ambient + s).c_str());
    ambient->SetNumberOfComponents(3);
    depth->SetName((vtkDeepGICaptureNames::Depth + s).c_str());
    valid->SetName((vtkDeepGICaptureNames::Valid + s).c_str());
    for (vtkFloatArray* a :
      { radiance.Get(), albedo.Get(), normal.Get(), depth.Get(), ambient.Get() })
    {
      a->SetNumberOfTuples(n);
    }
    valid->SetNumberOfTuples(n);
    for (vtkIdType p = 0; p < n; ++p)
    {
      // Layer 0 everywhere at depth 3 (the floor), layer 1 on half the pixels.
      const bool on = layer == 0 || (p % 3) != 0;
      valid->SetValue(p, on ? 1 : 0);
      depth->SetValue(p, on ? 3.0f + 0.5f * layer : 0.0f);
      for (int c = 0; c < 3; ++c)
      {
        normal->SetTypedComponent(p, c, on ? static_cast<float>(nc[c]) : 0.0f);
        albedo->SetTypedComponent(p, c, on ? ((p + c) % 256) / 255.0f : 0.0f);
        ambient->SetTypedComponent(p, c, on ? 0.1f * albedo->GetTypedComponent(p, c) : 0.0f);
        radiance->SetTypedComponent(p, c, on ? static_cast<float>(Value(layer, p, c, true)) : 0);
      }
      radiance->SetTypedComponent(p, 3, on ? 1.0f : 0.0f);
    }
    for (vtkFloatArray* a :
      { radiance.Get(), albedo.Get(), normal.Get(), depth.Get(), ambient.Get() })
    {
      capture->GetPointData()->AddArray(a);
    }
    capture->GetPointData()->AddArray(valid);
  }
  vtkNew<vtkDoubleArray> separation;
  separation->SetName(vtkDeepGICaptureNames::MinimumSeparation);
  separation->InsertNextValue(0.123456789012345);
  vtkNew<vtkIntArray> layers;
  layers->SetName(vtkDeepGICaptureNames::NumberOfLayers);
  layers->InsertNextValue(2);
  vtkNew<vtkStringArray> oracle;
  oracle->SetName(vtkDeepGICaptureNames::Oracle);
  oracle->InsertNextValue("REPROJECT");
  capture->GetFieldData()->AddArray(separation);
  capture->GetFieldData()->AddArray(layers);
  capture->GetFieldData()->AddArray(oracle);
  AddCameraMatrices(capture, view, projection);
  return capture;
}

// The written file, checked with OpenEXR directly: names, types, windows,
// and the file's top row is VTK's last row.
void CheckFloatFileLayout(const std::string& floatFile, vtkImageData* image, int w, int h)
{
  Imf::InputFile file(floatFile.c_str());
  const Imf::ChannelList& channels = file.header().channels();
  int count = 0;
  bool allFloat = true;
  for (auto it = channels.begin(); it != channels.end(); ++it)
  {
    ++count;
    allFloat = allFloat && it.channel().type == Imf::FLOAT;
  }
  Check(count == 4 + 1 + 3 + 6 + 2 + 3 + 1, "FLOAT: 20 channels (" + std::to_string(count) + ")");
  Check(allFloat, "FLOAT: every channel is FLOAT");
  for (const char* name : { "Radiance_0.R", "Radiance_0.A", "Depth_0.Y", "R", "G", "B", "Many.5",
         "Pair.G", "Normal_0.B", "Valid_0.Y" })
  {
    Check(channels.findChannel(name) != nullptr, std::string("channel ") + name);
  }
  const Imath::Box2i window = file.header().dataWindow();
  Check(window.min.x == 3 && window.min.y == 2 && window.max.x == 3 + w - 1 &&
      window.max.y == 2 + h - 1 && file.header().displayWindow() == window,
    "data and display windows from the origin");
  Check(file.header().compression() == Imf::ZIP_COMPRESSION, "ZIP compression");
  std::vector<float> depth(static_cast<size_t>(w) * h);
  Imf::FrameBuffer frameBuffer;
  frameBuffer.insert("Depth_0.Y", Imf::Slice::Make(Imf::FLOAT, depth.data(), window));
  file.setFrameBuffer(frameBuffer);
  file.readPixels(window.min.y, window.max.y);
  auto d = vtkFloatArray::SafeDownCast(image->GetPointData()->GetArray(
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Depth, 0).c_str()));
  bool flipped = true;
  for (int x = 0; x < w; ++x)
  {
    flipped = flipped && depth[x] == d->GetValue(static_cast<vtkIdType>(h - 1) * w + x) &&
      depth[static_cast<size_t>(h - 1) * w + x] == d->GetValue(x);
  }
  Check(flipped, "the file's top row is VTK's last row");
}

// 1. FLOAT round trip: every float value bit-identical; returns the image
// written to `floatFile`.
vtkSmartPointer<vtkImageData> CheckFloatRoundTrip(const std::string& floatFile, int w, int h)
{
  auto image = MakeImage(w, h, false);
  Check(Write(image, floatFile, vtkDeepGIEXRWriter::FLOAT), "FLOAT: written");
  Check(vtkDeepGIEXRReader::CanReadFile(floatFile.c_str()), "CanReadFile on the written file");
  CompareImages(image, Read(floatFile), false, "FLOAT round trip");
  CheckFloatFileLayout(floatFile, image, w, h);
  return image;
}

// 2. HALF round trip: |a - b| <= 2^-11 |a| + 2^-24 for every value.
void CheckHalfRoundTrip(const std::string& directory, int w, int h)
{
  const std::string halfFile = directory + "/TestDeepGIEXR-half.exr";
  auto halfImage = MakeImage(w, h, true);
  Check(Write(halfImage, halfFile, vtkDeepGIEXRWriter::HALF), "HALF: written");
  {
    Imf::InputFile file(halfFile.c_str());
    Check(file.header().channels().findChannel("Radiance_0.R")->type == Imf::HALF,
      "HALF: channels are HALF");
  }
  CompareImages(halfImage, Read(halfFile), true, "HALF round trip");
}

// 3. A tiled file with half and uint channels and an offset data window,
// written with OpenEXR directly, is read into the documented arrays.
void CheckTiledFileRead(const std::string& directory)
{
  const std::string tiledFile = directory + "/TestDeepGIEXR-tiled.exr";
  const int tw = 6, th = 4;
  Imath::Box2i display(Imath::V2i(0, 0), Imath::V2i(19, 9));
  Imath::Box2i data(Imath::V2i(5, 3), Imath::V2i(5 + tw - 1, 3 + th - 1));
  Imf::Header header(display, data);
  for (const char* c : { "R", "G", "B", "A" })
  {
    header.channels().insert(c, Imf::Channel(Imf::HALF));
  }
  header.channels().insert("id.Y", Imf::Channel(Imf::UINT));
  header.channels().insert("Z", Imf::Channel(Imf::FLOAT));
  header.setTileDescription(Imf::TileDescription(4, 4));
  std::vector<half> rgba(static_cast<size_t>(tw) * th * 4);
  std::vector<uint32_t> id(static_cast<size_t>(tw) * th);
  std::vector<float> z(static_cast<size_t>(tw) * th);
  for (int y = 0; y < th; ++y)
  {
    for (int x = 0; x < tw; ++x)
    {
      const size_t p = static_cast<size_t>(y) * tw + x;
      for (int c = 0; c < 4; ++c)
      {
        rgba[4 * p + c] = half(0.25f * c + 0.125f * x + 0.0625f * y); // exact in half
      }
      id[p] = 16777216u - static_cast<uint32_t>(p); // exact in float up to 2^24
      z[p] = 100.0f * y + x;
    }
  }
  Imf::FrameBuffer frameBuffer;
  const char* names[4] = { "R", "G", "B", "A" };
  for (int c = 0; c < 4; ++c)
  {
    frameBuffer.insert(names[c],
      Imf::Slice::Make(Imf::HALF, rgba.data() + c, data, 4 * sizeof(half), 4 * sizeof(half) * tw));
  }
  frameBuffer.insert("id.Y", Imf::Slice::Make(Imf::UINT, id.data(), data));
  frameBuffer.insert("Z", Imf::Slice::Make(Imf::FLOAT, z.data(), data));
  {
    Imf::TiledOutputFile file(tiledFile.c_str(), header);
    file.setFrameBuffer(frameBuffer);
    file.writeTiles(0, file.numXTiles() - 1, 0, file.numYTiles() - 1);
  }
  auto read = Read(tiledFile);
  int dims[3];
  read->GetDimensions(dims);
  double origin[3];
  read->GetOrigin(origin);
  auto rgbaArray = vtkFloatArray::SafeDownCast(read->GetPointData()->GetArray("RGBA"));
  auto idArray = vtkFloatArray::SafeDownCast(read->GetPointData()->GetArray("id"));
  auto zArray = vtkFloatArray::SafeDownCast(read->GetPointData()->GetArray("Z"));
  Check(dims[0] == tw && dims[1] == th, "tiled: dimensions of the data window");
  // File (x, y) -> VTK (x, 0 + 9 - y): the data window's last row y = 6 is
  // VTK y = 3.
  Check(origin[0] == 5 && origin[1] == 3, "tiled: origin (5, 3) from the data window");
  Check(rgbaArray && rgbaArray->GetNumberOfComponents() == 4 &&
      read->GetPointData()->GetScalars() == rgbaArray,
    "tiled: R G B A -> active scalars \"RGBA\"");
  Check(idArray && idArray->GetNumberOfComponents() == 1 && zArray, "tiled: \"id\" and \"Z\"");
  int bad = 0;
  for (int y = 0; rgbaArray && idArray && zArray && y < th; ++y)
  {
    for (int x = 0; x < tw; ++x)
    {
      const size_t p = static_cast<size_t>(y) * tw + x;
      const vtkIdType v = static_cast<vtkIdType>(th - 1 - y) * tw + x; // flipped
      for (int c = 0; c < 4; ++c)
      {
        bad += rgbaArray->GetTypedComponent(v, c) != static_cast<float>(rgba[4 * p + c]);
      }
      bad += idArray->GetValue(v) != static_cast<float>(id[p]);
      bad += zArray->GetValue(v) != z[p];
    }
  }
  Check(bad == 0,
    "tiled: half, uint and float values exact, rows flipped (" + std::to_string(bad) + " differ)");
}

// A box (five faces) on the floor the capture of MakeCapture looks at.
vtkSmartPointer<vtkPolyData> BoxScene()
{
  auto scene = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  const double box[8][3] = { { 0, 0, 0 }, { 0.5, 0, 0 }, { 0.5, 0.5, 0 }, { 0, 0.5, 0 },
    { 0, 0, 0.5 }, { 0.5, 0, 0.5 }, { 0.5, 0.5, 0.5 }, { 0, 0.5, 0.5 } };
  for (const auto& p : box)
  {
    points->InsertNextPoint(p);
  }
  const vtkIdType faces[5][4] = { { 4, 5, 6, 7 }, { 0, 1, 5, 4 }, { 1, 2, 6, 5 }, { 2, 3, 7, 6 },
    { 3, 0, 4, 7 } };
  for (const auto& f : faces)
  {
    polys->InsertNextCell(4, f);
  }
  scene->SetPoints(points);
  scene->SetPolys(polys);
  return scene;
}

// 4. A G-buffer capture round trip: identical arrays and field data, and
// vtkDeepGIReferenceObscurance gives bit-identical results on the original
// and the reloaded capture.
void CheckCaptureRoundTrip(const std::string& directory)
{
  const std::string captureFile = directory + "/TestDeepGIEXR-capture.exr";
  auto capture = MakeCapture(24, 16);
  Check(Write(capture, captureFile, vtkDeepGIEXRWriter::FLOAT), "capture: written");
  auto read = Read(captureFile);
  CompareImages(capture, read, false, "capture round trip");
  vtkFieldData* fd = read->GetFieldData();
  auto separation =
    vtkDoubleArray::SafeDownCast(fd->GetArray(vtkDeepGICaptureNames::MinimumSeparation));
  auto layers = vtkIntArray::SafeDownCast(fd->GetArray(vtkDeepGICaptureNames::NumberOfLayers));
  auto oracle = vtkStringArray::SafeDownCast(fd->GetAbstractArray(vtkDeepGICaptureNames::Oracle));
  Check(separation && separation->GetValue(0) == 0.123456789012345,
    "capture: MinimumSeparation (double) exact");
  Check(layers && layers->GetValue(0) == 2, "capture: NumberOfLayers (int)");
  Check(oracle && oracle->GetValue(0) == "REPROJECT", "capture: Oracle (string)");
  for (const char* name :
    { vtkDeepGICaptureNames::ViewMatrix, vtkDeepGICaptureNames::ProjectionMatrix })
  {
    vtkDataArray* a = capture->GetFieldData()->GetArray(name);
    vtkDataArray* b = fd->GetArray(name);
    bool same = b && b->GetNumberOfComponents() == 16;
    for (int k = 0; same && k < 16; ++k)
    {
      same = a->GetComponent(0, k) == b->GetComponent(0, k);
    }
    Check(same, std::string("capture: ") + name + " exact");
  }
  // The reloaded capture drives the reference exactly like the original.
  vtkSmartPointer<vtkPolyData> scene = BoxScene();
  vtkNew<vtkDeepGIReferenceObscurance> a, b;
  for (vtkDeepGIReferenceObscurance* r : { a.Get(), b.Get() })
  {
    r->SetSceneData(scene);
    r->SetSamplesPerPixel(16);
  }
  Estimate(a, capture);
  Estimate(b, read);
  auto av = vtkFloatArray::SafeDownCast(a->GetOutput()->GetPointData()->GetArray("Obscurance"));
  auto bv = vtkFloatArray::SafeDownCast(b->GetOutput()->GetPointData()->GetArray("Obscurance"));
  Check(av && bv && av->GetNumberOfValues() == bv->GetNumberOfValues() &&
      std::memcmp(av->GetPointer(0), bv->GetPointer(0), sizeof(float) * av->GetNumberOfValues()) ==
        0 &&
      a->GetMeanStandardError() > 0,
    "capture: the reference gives identical obscurance on the reloaded capture");
}

// 5a. Bad input to the reader: a missing file, not an EXR file, a truncated
// one, no file name: errors, no crash.
void CheckReaderRefusesBadFiles(const std::string& directory, const std::string& floatFile)
{
  vtkNew<EventCounter> events;
  vtkNew<vtkDeepGIEXRReader> reader;
  reader->AddObserver(vtkCommand::ErrorEvent, events);
  // The executive adds its own "returned failure" error to each reader error.
  vtkNew<EventCounter> executiveEvents;
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executiveEvents);
  reader->SetFileName((directory + "/no-such-file.exr").c_str());
  reader->Update();
  Check(events->Errors >= 1 && reader->GetOutput()->GetNumberOfPoints() == 0,
    "missing file: error, empty output");
  const std::string text = directory + "/TestDeepGIEXR-not-exr.exr";
  std::ofstream(text) << "this is not an OpenEXR file\n";
  const int before = events->Errors;
  reader->SetFileName(text.c_str());
  reader->Update();
  Check(events->Errors > before && reader->GetOutput()->GetNumberOfPoints() == 0 &&
      !vtkDeepGIEXRReader::CanReadFile(text.c_str()),
    "not an EXR file: error, empty output");
  // A truncated EXR file: the header is fine, the pixels are not.
  const std::string truncated = directory + "/TestDeepGIEXR-truncated.exr";
  {
    std::ifstream in(floatFile, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(truncated, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  }
  const int beforeTruncated = events->Errors;
  reader->SetFileName(truncated.c_str());
  reader->Update();
  Check(events->Errors > beforeTruncated, "truncated EXR file: error");
  reader->SetFileName(nullptr);
  const int beforeEmpty = events->Errors;
  reader->Update();
  Check(events->Errors > beforeEmpty, "no file name: error");
  reader->Print(std::cout);
}

// 5b. Bad input to the writer: no input, an unwritable path, empty and 3D
// images, no numeric arrays, no file name: errors, no crash.
void CheckWriterRefusesBadInput(const std::string& directory, vtkImageData* image)
{
  vtkNew<EventCounter> writerEvents;
  vtkNew<vtkDeepGIEXRWriter> writer;
  writer->AddObserver(vtkCommand::ErrorEvent, writerEvents);
  writer->AddObserver(vtkCommand::WarningEvent, writerEvents);
  writer->SetFileName((directory + "/no-such-directory/x.exr").c_str());
  Check(writer->Write() == 0 && writerEvents->Errors == 1, "no input: error");
  writer->SetInputData(image);
  Check(writer->Write() == 0 && writerEvents->Errors == 2, "unwritable path: error");
  writer->SetFileName((directory + "/TestDeepGIEXR-bad.exr").c_str());
  vtkNew<vtkImageData> empty;
  writer->SetInputData(empty);
  Check(writer->Write() == 0 && writerEvents->Errors == 3, "empty image: error");
  vtkNew<vtkImageData> volume;
  volume->SetDimensions(2, 2, 2);
  vtkNew<vtkFloatArray> values;
  values->SetName("v");
  values->SetNumberOfTuples(8);
  values->FillValue(1.0f);
  volume->GetPointData()->AddArray(values);
  writer->SetInputData(volume);
  Check(writer->Write() == 0 && writerEvents->Errors == 4, "3D image: error");
  vtkNew<vtkImageData> strings;
  strings->SetDimensions(2, 2, 1);
  vtkNew<vtkStringArray> names;
  names->SetName("names");
  names->SetNumberOfValues(4);
  strings->GetPointData()->AddArray(names);
  writer->SetInputData(strings);
  Check(writer->Write() == 0 && writerEvents->Errors == 5 && writerEvents->Warnings == 1,
    "only a string array: a warning and an error");
  writer->SetInputData(image);
  writer->SetFileName(nullptr);
  Check(writer->Write() == 0 && writerEvents->Errors == 6, "no file name: error");
  writer->SetPixelType(7);
  Check(writer->GetPixelType() == vtkDeepGIEXRWriter::FLOAT, "PixelType clamped");
  writer->Print(std::cout);
}
}

int TestDeepGIEXR(int argc, char* argv[])
{
  const std::string directory = Argument(argc, argv, "-T", ".");
  const int w = 7, h = 5;
  const std::string floatFile = directory + "/TestDeepGIEXR-float.exr";
  vtkSmartPointer<vtkImageData> image = CheckFloatRoundTrip(floatFile, w, h);
  CheckHalfRoundTrip(directory, w, h);
  CheckTiledFileRead(directory);
  CheckCaptureRoundTrip(directory);
  CheckReaderRefusesBadFiles(directory, floatFile);
  CheckWriterRefusesBadInput(directory, image);
  return ExitStatus();
}
