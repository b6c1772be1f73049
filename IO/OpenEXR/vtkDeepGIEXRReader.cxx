#include "vtkDeepGIEXRReader.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <ImfChannelList.h>
#include <ImfDoubleAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfIntAttribute.h>
#include <ImfMatrixAttribute.h>
#include <ImfStdIO.h>
#include <ImfStringAttribute.h>
#include <ImfTestFile.h>

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkDeepGIEXRReader);

namespace
{
const char* const FieldPrefix = "vtkFieldData.";

// One output array: its name and the file's channels, in component order.
struct Group
{
  std::string Name;
  std::vector<std::string> Channels;
};

// Sort key of a channel's last name part inside its layer: R, G, B, A first,
// digit-only names numerically, the rest alphabetically.
std::pair<int, std::string> ComponentKey(const std::string& part)
{
  static const std::string rgba = "RGBA";
  if (part.size() == 1 && rgba.find(part[0]) != std::string::npos)
  {
    return { static_cast<int>(rgba.find(part[0])), std::string() };
  }
  if (!part.empty() &&
    std::all_of(part.begin(), part.end(),
      [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }))
  {
    // Left-pad so that the string comparison is numeric.
    return { 4, std::string(32 - std::min<size_t>(part.size(), 32), '0') + part };
  }
  return { 5, part };
}

// Groups the channels into output arrays (see the class documentation).
std::vector<Group> GroupChannels(const std::vector<std::string>& channels)
{
  std::map<std::string, std::vector<std::string>> layers; // layer -> channels
  std::vector<std::string> layerOrder;
  std::vector<Group> singles;
  std::vector<std::string> rgba;
  for (const std::string& name : channels)
  {
    const size_t dot = name.rfind('.');
    if (dot == std::string::npos)
    {
      if (name == "R" || name == "G" || name == "B" || name == "A")
      {
        rgba.push_back(name);
      }
      else
      {
        singles.push_back({ name, { name } });
      }
      continue;
    }
    const std::string layer = name.substr(0, dot);
    if (!layers.count(layer))
    {
      layerOrder.push_back(layer);
    }
    layers[layer].push_back(name);
  }
  auto byComponent = [](const std::string& a, const std::string& b)
  {
    const size_t da = a.rfind('.'), db = b.rfind('.');
    return ComponentKey(da == std::string::npos ? a : a.substr(da + 1)) <
      ComponentKey(db == std::string::npos ? b : b.substr(db + 1));
  };
  std::vector<Group> groups;
  if (!rgba.empty())
  {
    std::sort(rgba.begin(), rgba.end(), byComponent);
    std::string name;
    for (const std::string& c : rgba)
    {
      name += c;
    }
    groups.push_back({ name, rgba });
  }
  for (const std::string& layer : layerOrder)
  {
    std::vector<std::string>& members = layers[layer];
    std::sort(members.begin(), members.end(), byComponent);
    groups.push_back({ layer, members });
  }
  groups.insert(groups.end(), singles.begin(), singles.end());
  return groups;
}

// The most float bytes an image may need (1 GiB: 8192 x 8192 RGBA), and
// the most one line buffer of OpenEXR may take (up to 256 scan lines or one
// tile of the file's own pixels).
constexpr double MaximumBytes = 1024.0 * 1024 * 1024;
// The most a compressed image can shrink: zlib's limit is about 1032:1 (ZIP,
// ZIPS, PXR24 and the DC part of DWAA / DWAB), RLE's 64:1, B44's 32:3.
constexpr double MaximumCompressionRatio = 1100.0;

// A corrupt or hostile header can claim a data window of billions of pixels
// in a file of a few kilobytes; the pixels would be allocated (and zeroed)
// before OpenEXR notices the data is missing. The claim is checked against a
// limit and against what the file can hold. "" or why the image is refused.
std::string CheckClaimedSize(const Imf::Header& header, const std::string& fileName)
{
  const Imath::Box2i data = header.dataWindow();
  const double width = static_cast<double>(data.max.x) - data.min.x + 1.0;
  const double height = static_cast<double>(data.max.y) - data.min.y + 1.0;
  if (width < 1.0 || height < 1.0 || width > 2147483647.0 || height > 2147483647.0)
  {
    return "\"" + fileName + "\" has an invalid data window.";
  }
  double stored = 0.0; // bytes of one pixel in the file, uncompressed
  double channels = 0.0;
  for (auto it = header.channels().begin(); it != header.channels().end(); ++it)
  {
    stored += it.channel().type == Imf::HALF ? 2.0 : 4.0;
    channels += 1.0;
  }
  const double floatBytes = width * height * channels * 4.0;
  struct stat file;
  const double fileBytes =
    stat(fileName.c_str(), &file) == 0 ? static_cast<double>(file.st_size) : 0.0;
  const double ratio = header.compression() == Imf::NO_COMPRESSION ? 1.0 : MaximumCompressionRatio;
  const double buffer = header.hasTileDescription()
    ? static_cast<double>(header.tileDescription().xSize) * header.tileDescription().ySize * stored
    : width * stored * 256.0;
  if (buffer > MaximumBytes)
  {
    return "\"" + fileName + "\" has lines or tiles too large to buffer (corrupt?).";
  }
  if (floatBytes > MaximumBytes || width * height * stored > fileBytes * ratio)
  {
    char claim[160];
    std::snprintf(claim, sizeof(claim), "%.0f x %.0f pixels of %.0f channel(s) (%.3g bytes)", width,
      height, channels, floatBytes);
    return "\"" + fileName + "\" claims " + claim +
      (floatBytes > MaximumBytes
          ? ", more than the limit of 1 GiB."
          : ", more than its " + std::to_string(static_cast<long long>(fileBytes)) +
            " bytes can hold (corrupt or truncated).");
  }
  return "";
}

// The attributes of a single-part header: each one's size must lie inside
// the file (OpenEXR allocates what a size claims before reading it).
std::string CheckHeaderBytes(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  size_t at = 8; // magic number and version
  while (at < bytes.size() && bytes[at] != '\0')
  {
    for (int strings = 0; strings < 2; ++strings) // name, type
    {
      const size_t end = bytes.find('\0', at);
      if (end == std::string::npos || end - at > 255)
      {
        return "\"" + fileName + "\" has a malformed header.";
      }
      at = end + 1;
    }
    if (bytes.size() - at < 4)
    {
      return "\"" + fileName + "\" has a truncated header.";
    }
    const std::uint32_t size = std::uint32_t(static_cast<unsigned char>(bytes[at])) |
      std::uint32_t(static_cast<unsigned char>(bytes[at + 1])) << 8 |
      std::uint32_t(static_cast<unsigned char>(bytes[at + 2])) << 16 |
      std::uint32_t(static_cast<unsigned char>(bytes[at + 3])) << 24;
    at += 4;
    if (size > bytes.size() - at)
    {
      return "\"" + fileName + "\" has a header attribute larger than the file.";
    }
    at += size;
  }
  return at < bytes.size() ? "" : "\"" + fileName + "\" has a truncated header.";
}

// The header alone (OpenEXR's InputFile allocates its line buffers from
// the header while opening), checked before the file is opened for pixels.
std::string CheckHeader(const std::string& fileName)
{
  std::string error = CheckHeaderBytes(fileName);
  if (!error.empty())
  {
    return error;
  }
  Imf::StdIFStream stream(fileName.c_str());
  char start[8];
  stream.read(start, 8);
  int version = static_cast<unsigned char>(start[4]) | static_cast<unsigned char>(start[5]) << 8 |
    static_cast<unsigned char>(start[6]) << 16 | static_cast<unsigned char>(start[7]) << 24;
  Imf::Header header;
  header.readFrom(stream, version);
  return CheckClaimedSize(header, fileName);
}

// Opens the file after the checks that give clear messages; nullptr and
// `error` set on failure.
std::unique_ptr<Imf::InputFile> Open(const std::string& fileName, std::string& error)
{
  if (fileName.empty())
  {
    error = "No file name.";
    return nullptr;
  }
  bool tiled = false, deep = false, multiPart = false;
  FILE* file = std::fopen(fileName.c_str(), "rb");
  if (!file)
  {
    error = "Cannot open \"" + fileName + "\".";
    return nullptr;
  }
  std::fclose(file);
  if (!Imf::isOpenExrFile(fileName.c_str(), tiled, deep, multiPart))
  {
    error = "\"" + fileName + "\" is not an OpenEXR file.";
    return nullptr;
  }
  if (deep || multiPart)
  {
    error = "\"" + fileName + "\" holds " + (deep ? "deep data" : "several parts") +
      ", which this reader does not read.";
    return nullptr;
  }
  try
  {
    error = CheckHeader(fileName);
    if (!error.empty())
    {
      return nullptr;
    }
    std::unique_ptr<Imf::InputFile> input(new Imf::InputFile(fileName.c_str()));
    error = CheckClaimedSize(input->header(), fileName);
    return error.empty() ? std::move(input) : nullptr;
  }
  catch (const std::exception& e)
  {
    error = "Cannot read \"" + fileName + "\": " + e.what();
    return nullptr;
  }
}
}

//------------------------------------------------------------------------------
vtkDeepGIEXRReader::vtkDeepGIEXRReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkDeepGIEXRReader::~vtkDeepGIEXRReader() = default;

int vtkDeepGIEXRReader::FillInputPortInformation(int, vtkInformation*)
{
  return 1;
}

bool vtkDeepGIEXRReader::CanReadFile(const char* fileName)
{
  if (!fileName)
  {
    return false;
  }
  FILE* file = std::fopen(fileName, "rb");
  if (!file)
  {
    return false;
  }
  std::fclose(file);
  try
  {
    return Imf::isOpenExrFile(fileName);
  }
  catch (const std::exception&)
  {
    return false;
  }
}

//------------------------------------------------------------------------------
int vtkDeepGIEXRReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  std::string error;
  auto file = Open(this->FileName, error);
  if (!file)
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  const Imath::Box2i data = file->header().dataWindow();
  const Imath::Box2i display = file->header().displayWindow();
  const int width = data.max.x - data.min.x + 1;
  const int height = data.max.y - data.min.y + 1;
  vtkInformation* info = outputVector->GetInformationObject(0);
  const int extent[6] = { 0, width - 1, 0, height - 1, 0, 0 };
  // File pixel (x, y) -> VTK point (x, dy0 + dy1 - y): the first VTK row is
  // the file's last one.
  const double origin[3] = { static_cast<double>(data.min.x),
    static_cast<double>(display.min.y) + display.max.y - data.max.y, 0.0 };
  const double spacing[3] = { 1.0, 1.0, 1.0 };
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  info->Set(vtkDataObject::ORIGIN(), origin, 3);
  info->Set(vtkDataObject::SPACING(), spacing, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(info, VTK_FLOAT, 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkDeepGIEXRReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector);
  output->Initialize();
  std::string error;
  auto file = Open(this->FileName, error);
  if (!file)
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  const Imf::Header& header = file->header();
  const Imath::Box2i data = header.dataWindow();
  const Imath::Box2i display = header.displayWindow();
  const int width = data.max.x - data.min.x + 1;
  const int height = data.max.y - data.min.y + 1;
  const size_t pixels = static_cast<size_t>(width) * height;

  std::vector<std::string> names;
  for (auto it = header.channels().begin(); it != header.channels().end(); ++it)
  {
    if (it.channel().xSampling != 1 || it.channel().ySampling != 1)
    {
      vtkWarningMacro(
        "Channel " << it.name() << " of \"" << this->FileName << "\" is subsampled; skipped.");
      continue;
    }
    names.emplace_back(it.name());
  }

  // Each channel is read as float into its own plane, in the file's row
  // order; OpenEXR converts half and uint. A corrupt header can claim a
  // data window too large to allocate: std::bad_alloc is caught below.
  std::map<std::string, std::vector<float>> planes;
  try
  {
    Imf::FrameBuffer frameBuffer;
    for (const std::string& name : names)
    {
      std::vector<float>& plane = planes[name];
      plane.assign(pixels, 0.0f);
      frameBuffer.insert(name, Imf::Slice::Make(Imf::FLOAT, plane.data(), data));
    }
    file->setFrameBuffer(frameBuffer);
    file->readPixels(data.min.y, data.max.y);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Cannot read the pixels of \"" << this->FileName << "\": " << e.what());
    return 0;
  }

  output->SetExtent(0, width - 1, 0, height - 1, 0, 0);
  output->SetOrigin(
    data.min.x, static_cast<double>(display.min.y) + display.max.y - data.max.y, 0.0);
  output->SetSpacing(1.0, 1.0, 1.0);
  bool first = true;
  for (const Group& group : GroupChannels(names))
  {
    vtkNew<vtkFloatArray> array;
    array->SetName(group.Name.c_str());
    const int components = static_cast<int>(group.Channels.size());
    array->SetNumberOfComponents(components);
    array->SetNumberOfTuples(static_cast<vtkIdType>(pixels));
    float* out = array->GetPointer(0);
    for (int c = 0; c < components; ++c)
    {
      const std::vector<float>& plane = planes[group.Channels[c]];
      for (int row = 0; row < height; ++row)
      {
        // VTK row `row` (bottom-up) is the file's row height - 1 - row.
        const float* in = plane.data() + static_cast<size_t>(height - 1 - row) * width;
        float* o = out + static_cast<size_t>(row) * width * components + c;
        for (int x = 0; x < width; ++x)
        {
          o[static_cast<size_t>(x) * components] = in[x];
        }
      }
    }
    if (first)
    {
      output->GetPointData()->SetScalars(array);
      first = false;
    }
    else
    {
      output->GetPointData()->AddArray(array);
    }
  }

  // Field data written by vtkDeepGIEXRWriter.
  const std::string prefix = FieldPrefix;
  for (auto it = header.begin(); it != header.end(); ++it)
  {
    const std::string name = it.name();
    if (name.compare(0, prefix.size(), prefix) != 0)
    {
      continue;
    }
    const std::string arrayName = name.substr(prefix.size());
    const Imf::Attribute& attribute = it.attribute();
    if (auto d = dynamic_cast<const Imf::DoubleAttribute*>(&attribute))
    {
      vtkNew<vtkDoubleArray> array;
      array->SetName(arrayName.c_str());
      array->InsertNextValue(d->value());
      output->GetFieldData()->AddArray(array);
    }
    else if (auto i = dynamic_cast<const Imf::IntAttribute*>(&attribute))
    {
      vtkNew<vtkIntArray> array;
      array->SetName(arrayName.c_str());
      array->InsertNextValue(i->value());
      output->GetFieldData()->AddArray(array);
    }
    else if (auto s = dynamic_cast<const Imf::StringAttribute*>(&attribute))
    {
      vtkNew<vtkStringArray> array;
      array->SetName(arrayName.c_str());
      array->InsertNextValue(s->value());
      output->GetFieldData()->AddArray(array);
    }
    else if (auto m = dynamic_cast<const Imf::M44dAttribute*>(&attribute))
    {
      vtkNew<vtkDoubleArray> array;
      array->SetName(arrayName.c_str());
      array->SetNumberOfComponents(16);
      array->SetNumberOfTuples(1);
      for (int k = 0; k < 16; ++k)
      {
        array->SetComponent(0, k, m->value()[k / 4][k % 4]);
      }
      output->GetFieldData()->AddArray(array);
    }
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkDeepGIEXRReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
}
