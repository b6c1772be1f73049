#include "vtkDeepGIEXRWriter.h"

#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStringArray.h"

#include <ImfChannelList.h>
#include <ImfCompression.h>
#include <ImfDoubleAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIntAttribute.h>
#include <ImfMatrixAttribute.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>
#include <ImfStringAttribute.h>
#include <half.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

vtkStandardNewMacro(vtkDeepGIEXRWriter);

namespace
{
const char* const FieldPrefix = "vtkFieldData.";

// Channel names of an array (see the class documentation).
std::vector<std::string> ChannelNames(const std::string& name, int components)
{
  std::vector<std::string> channels;
  const bool defaultLayer =
    (name == "RGB" && components == 3) || (name == "RGBA" && components == 4);
  const std::string prefix = defaultLayer ? "" : name + ".";
  for (int c = 0; c < components; ++c)
  {
    if (components == 1)
    {
      channels.push_back(prefix + "Y");
    }
    else if (components <= 4)
    {
      channels.push_back(prefix + "RGBA"[c]);
    }
    else
    {
      channels.push_back(prefix + std::to_string(c));
    }
  }
  return channels;
}

// Header attributes "vtkFieldData.<name>" for the field arrays of one tuple
// (see the class documentation); others are skipped with a warning.
void AddFieldData(vtkFieldData* fd, Imf::Header& header, vtkObject* self)
{
  for (int a = 0; fd && a < fd->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* abstract = fd->GetAbstractArray(a);
    if (!abstract || !abstract->GetName())
    {
      continue;
    }
    const std::string name = FieldPrefix + std::string(abstract->GetName());
    vtkDataArray* array = vtkDataArray::SafeDownCast(abstract);
    auto strings = vtkStringArray::SafeDownCast(abstract);
    if (strings && strings->GetNumberOfValues() == 1)
    {
      header.insert(name, Imf::StringAttribute(strings->GetValue(0)));
    }
    else if (array && array->GetNumberOfTuples() == 1 && array->GetNumberOfComponents() == 1)
    {
      if (array->GetDataType() == VTK_FLOAT || array->GetDataType() == VTK_DOUBLE)
      {
        header.insert(name, Imf::DoubleAttribute(array->GetComponent(0, 0)));
      }
      else
      {
        header.insert(name, Imf::IntAttribute(static_cast<int>(array->GetComponent(0, 0))));
      }
    }
    else if (array && array->GetNumberOfTuples() == 1 && array->GetNumberOfComponents() == 16)
    {
      Imath::M44d m;
      for (int k = 0; k < 16; ++k)
      {
        m[k / 4][k % 4] = array->GetComponent(0, k);
      }
      header.insert(name, Imf::M44dAttribute(m));
    }
    else
    {
      vtkWarningWithObjectMacro(self,
        "Field array \"" << abstract->GetName()
                         << "\" is not one number, one string or one 4x4 matrix; "
                            "not written.");
    }
  }
}

// The whole file in memory: OpenEXR writes its line offset table when the
// OutputFile is destroyed and cannot report a failure then, so the file's
// own writing (and its errors) is left to WriteAtomically.
bool Encode(const Imf::Header& header, const Imf::FrameBuffer& frameBuffer, int height,
  std::string& bytes, std::string& reason)
{
  try
  {
    Imf::StdOSStream stream;
    {
      Imf::OutputFile file(stream, header);
      file.setFrameBuffer(frameBuffer);
      file.writePixels(height);
    }
    bytes = stream.str();
    return true;
  }
  catch (const std::exception& e)
  {
    reason = e.what();
    return false;
  }
}

// Writes `bytes` under a temporary name next to `path` (a new file, created
// with O_EXCL, with the permissions the umask gives new files), every write
// and the close checked, and renames it onto `path` once complete. A failed
// write (a full disk) leaves no partial file and keeps an older file of that
// name; a symbolic link at `path` is replaced, its target left alone.
bool WriteAtomically(
  const std::string& path, const std::string& bytes, std::string& reason, int& errorNumber)
{
  std::vector<char> name(path.begin(), path.end());
  const char suffix[] = ".partial-XXXXXX";
  name.insert(name.end(), suffix, suffix + sizeof(suffix)); // with the terminating 0
  const int fd = mkstemp(name.data());
  if (fd < 0)
  {
    errorNumber = errno;
    reason = std::strerror(errorNumber);
    return false;
  }
  const mode_t mask = umask(0);
  umask(mask);
  fchmod(fd, 0666 & ~mask);
  std::FILE* file = fdopen(fd, "wb");
  if (!file)
  {
    errorNumber = errno;
    close(fd);
    std::remove(name.data());
    reason = std::strerror(errorNumber);
    return false;
  }
  bool ok = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
  ok = ok && std::fflush(file) == 0 && fsync(fileno(file)) == 0;
  errorNumber = ok ? 0 : errno;
  if (std::fclose(file) != 0 && ok)
  {
    ok = false;
    errorNumber = errno;
  }
  if (ok && std::rename(name.data(), path.c_str()) != 0)
  {
    ok = false;
    errorNumber = errno;
  }
  if (!ok)
  {
    std::remove(name.data());
    reason = std::strerror(errorNumber);
  }
  return ok;
}
}

//------------------------------------------------------------------------------
vtkDeepGIEXRWriter::vtkDeepGIEXRWriter() = default;
vtkDeepGIEXRWriter::~vtkDeepGIEXRWriter() = default;

int vtkDeepGIEXRWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}

vtkImageData* vtkDeepGIEXRWriter::GetInput()
{
  return vtkImageData::SafeDownCast(this->Superclass::GetInput());
}

//------------------------------------------------------------------------------
void vtkDeepGIEXRWriter::WriteData()
{
  vtkImageData* image = this->GetInput();
  if (this->FileName.empty())
  {
    vtkErrorMacro("No file name.");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return;
  }
  int extent[6];
  image->GetExtent(extent);
  const int width = extent[1] - extent[0] + 1;
  const int height = extent[3] - extent[2] + 1;
  if (image->GetNumberOfPoints() <= 0 || width <= 0 || height <= 0)
  {
    vtkErrorMacro("The image is empty: nothing to write to \"" << this->FileName << "\".");
    this->SetErrorCode(vtkErrorCode::UnknownError);
    return;
  }
  if (extent[5] != extent[4])
  {
    vtkErrorMacro("Only 2D images can be written to OpenEXR; the extent has "
      << extent[5] - extent[4] + 1 << " slices.");
    this->SetErrorCode(vtkErrorCode::UnknownError);
    return;
  }

  // Data window from the first point's index-space position.
  double origin[3], spacing[3];
  image->GetOrigin(origin);
  image->GetSpacing(spacing);
  auto index = [](double o, double s, int e)
  {
    const double v = (s != 0.0 ? o / s : 0.0) + e;
    return std::isfinite(v) && std::fabs(v) < 1e9 ? static_cast<int>(std::lround(v)) : 0;
  };
  Imath::Box2i window;
  window.min.x = index(origin[0], spacing[0], extent[0]);
  window.min.y = index(origin[1], spacing[1], extent[2]);
  window.max.x = window.min.x + width - 1;
  window.max.y = window.min.y + height - 1;
  Imf::Header header(window, window);
  header.compression() = Imf::ZIP_COMPRESSION;
  const Imf::PixelType type = this->PixelType == HALF ? Imf::HALF : Imf::FLOAT;

  // One interleaved float buffer per array, rows in the file's top-down
  // order (file row r is VTK row height - 1 - r); for HALF a rounded copy,
  // since OpenEXR only writes slices of the channel's own type.
  const size_t pixels = static_cast<size_t>(width) * height;
  std::vector<std::vector<float>> buffers;
  std::vector<std::vector<half>> halfBuffers;
  Imf::FrameBuffer frameBuffer;
  vtkPointData* pd = image->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* abstract = pd->GetAbstractArray(a);
    vtkDataArray* array = vtkDataArray::SafeDownCast(abstract);
    const std::string name = abstract && abstract->GetName() ? abstract->GetName() : "";
    if (!array || name.empty() || array->GetNumberOfTuples() != static_cast<vtkIdType>(pixels))
    {
      vtkWarningMacro("Point array " << a << " (\"" << name
                                     << "\") is not a named numeric array with one tuple per "
                                        "pixel; not written.");
      continue;
    }
    const int components = array->GetNumberOfComponents();
    const std::vector<std::string> channels = ChannelNames(name, components);
    bool clash = false;
    for (const std::string& channel : channels)
    {
      clash = clash || header.channels().findChannel(channel) != nullptr;
    }
    if (clash)
    {
      vtkWarningMacro("Point array \"" << name << "\" would reuse channel names; not written.");
      continue;
    }
    buffers.emplace_back(pixels * components);
    std::vector<float>& buffer = buffers.back();
    for (int row = 0; row < height; ++row)
    {
      const vtkIdType source = static_cast<vtkIdType>(height - 1 - row) * width;
      float* out = buffer.data() + static_cast<size_t>(row) * width * components;
      for (int x = 0; x < width; ++x)
      {
        for (int c = 0; c < components; ++c)
        {
          out[static_cast<size_t>(x) * components + c] =
            static_cast<float>(array->GetComponent(source + x, c));
        }
      }
    }
    const char* base = reinterpret_cast<const char*>(buffer.data());
    size_t xStride = sizeof(float) * components;
    if (type == Imf::HALF)
    {
      halfBuffers.emplace_back(buffer.begin(), buffer.end());
      base = reinterpret_cast<const char*>(halfBuffers.back().data());
      xStride = sizeof(half) * components;
    }
    const size_t componentSize = type == Imf::HALF ? sizeof(half) : sizeof(float);
    for (int c = 0; c < components; ++c)
    {
      header.channels().insert(channels[c], Imf::Channel(type));
      frameBuffer.insert(channels[c],
        Imf::Slice::Make(
          type, base + c * componentSize, window, xStride, xStride * static_cast<size_t>(width)));
    }
  }
  if (buffers.empty())
  {
    vtkErrorMacro("The image has no numeric point array to write to \"" << this->FileName << "\".");
    this->SetErrorCode(vtkErrorCode::UnknownError);
    return;
  }

  AddFieldData(image->GetFieldData(), header, this);

  std::string bytes, reason;
  int errorNumber = 0;
  if (!Encode(header, frameBuffer, height, bytes, reason) ||
    !WriteAtomically(this->FileName, bytes, reason, errorNumber))
  {
    vtkErrorMacro("Cannot write \"" << this->FileName << "\": " << reason);
    this->SetErrorCode(errorNumber == ENOSPC || errorNumber == EDQUOT || errorNumber == EFBIG
        ? vtkErrorCode::OutOfDiskSpaceError
        : vtkErrorCode::CannotOpenFileError);
  }
}

//------------------------------------------------------------------------------
void vtkDeepGIEXRWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "PixelType: " << (this->PixelType == HALF ? "HALF" : "FLOAT") << "\n";
}
