#include "vtkDeepGINrrdReader.h"

#include "vtkCommand.h"
#include "vtkDataObject.h"
#include "vtkDeepGISceneFileChecks.h"
#include "vtkDeepGISceneText.h"
#include "vtkErrorCode.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkImageReader2.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <vtksys/FStream.hxx>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <sstream>
#include <stdexcept>
#include <vector>

vtkStandardNewMacro(vtkDeepGINrrdReader);

namespace
{
// The largest volume read (bytes of voxel data): 4 GiB.
constexpr std::uint64_t MaximumBytes = std::uint64_t(4) << 30;

using vtkDeepGISceneText::Lower;
using vtkDeepGISceneText::ParseInteger;
using vtkDeepGISceneText::Trim;
using vtkDeepGISceneText::Words;

using vtkDeepGISceneFileChecks::RegularFileSize;

struct Header
{
  int Dimension = 0;
  int ScalarType = -1;
  int ScalarBytes = 0;
  std::vector<long long> Sizes;
  double Spacing[3] = { 1.0, 1.0, 1.0 };
  double Origin[3] = { 0.0, 0.0, 0.0 };
  bool HaveSpacings = false;
  bool LeftHanded = false;
  std::string Encoding = "raw";
  bool BigEndian = false;
  long long ByteSkip = 0;
  std::vector<std::string> DataFiles; // empty: attached data
  std::uint64_t DataOffset = 0;       // attached data: where the header ends
};

// At most 80 characters of `s` for a message, non-printable ones as '?'.
std::string Quote(const std::string& s)
{
  std::string q = s.substr(0, 80);
  for (char& c : q)
  {
    c = std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  }
  return "\"" + q + (s.size() > 80 ? "...\"" : "\"");
}

// Parses "(x,y,z)" into three finite numbers.
bool ParseVector(const std::string& text, double v[3])
{
  std::string s = text;
  for (char& c : s)
  {
    c = (c == '(' || c == ')' || c == ',') ? ' ' : c;
  }
  std::istringstream in(s);
  return static_cast<bool>(in >> v[0] >> v[1] >> v[2]) && std::isfinite(v[0]) &&
    std::isfinite(v[1]) && std::isfinite(v[2]);
}

int ScalarType(const std::string& type, int& bytes)
{
  struct Type
  {
    const char* Names;
    int VTKType;
    int Bytes;
  };
  static const Type types[] = { { "|short|short int|signed short|signed short int|int16|int16_t|",
                                  VTK_SHORT, 2 },
    { "|ushort|unsigned short|unsigned short int|uint16|uint16_t|", VTK_UNSIGNED_SHORT, 2 },
    { "|uchar|unsigned char|uint8|uint8_t|", VTK_UNSIGNED_CHAR, 1 },
    { "|signed char|int8|int8_t|", VTK_SIGNED_CHAR, 1 },
    { "|int|signed int|int32|int32_t|", VTK_INT, 4 },
    { "|uint|unsigned int|uint32|uint32_t|", VTK_UNSIGNED_INT, 4 }, { "|float|", VTK_FLOAT, 4 },
    { "|double|", VTK_DOUBLE, 8 } };
  const std::string key = "|" + Lower(type) + "|";
  for (const Type& t : types)
  {
    if (std::string(t.Names).find(key) != std::string::npos)
    {
      bytes = t.Bytes;
      return t.VTKType;
    }
  }
  return -1;
}

// Formats `number` into a NRRD file pattern holding exactly one %d / %i
// conversion with optional '0' flag and width ("quarter.%d", "slice%03d.raw").
// The pattern comes from a file, so it is never handed to printf.
bool FormatPattern(const std::string& pattern, long long number, std::string& result)
{
  result.clear();
  int conversions = 0;
  for (size_t i = 0; i < pattern.size(); ++i)
  {
    if (pattern[i] != '%' || (i + 1 < pattern.size() && pattern[i + 1] == '%'))
    {
      result += pattern[i];
      i += pattern[i] == '%' ? 1 : 0;
      continue;
    }
    size_t j = i + 1;
    const bool zero = j < pattern.size() && pattern[j] == '0';
    j += zero ? 1 : 0;
    size_t width = 0;
    while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j])))
    {
      width = std::min<size_t>(10 * width + (pattern[j++] - '0'), 64);
    }
    if (j >= pattern.size() || (pattern[j] != 'd' && pattern[j] != 'i') || ++conversions > 1)
    {
      return false;
    }
    // The magnitude in unsigned arithmetic: -LLONG_MIN does not fit a long long.
    const unsigned long long magnitude = number < 0 ? 0ULL - static_cast<unsigned long long>(number)
                                                    : static_cast<unsigned long long>(number);
    std::string digits = std::to_string(magnitude);
    const size_t sign = number < 0 ? 1 : 0;
    const size_t pad = digits.size() + sign < width ? width - digits.size() - sign : 0;
    result += zero ? "" : std::string(pad, ' ');
    result += (number < 0 ? "-" : "") + (zero ? std::string(pad, '0') : "") + digits;
    i = j;
  }
  return conversions == 1;
}

// "data file: PATTERN MIN MAX STEP [SUBDIM]": the file names, at most
// `slices` of them (the count comes from overflow-safe unsigned arithmetic,
// never from looping until the counter passes MAX).
std::string ExpandPattern(
  const std::vector<std::string>& words, long long slices, std::vector<std::string>& names)
{
  long long first = 0, last = 0, step = 0, subdim = 2;
  if (!ParseInteger(words[1], first) || !ParseInteger(words[2], last) ||
    !ParseInteger(words[3], step) || step == 0 ||
    (words.size() == 5 && (!ParseInteger(words[4], subdim) || subdim != 2)))
  {
    return "its data file pattern needs integers MIN MAX STEP (STEP not 0) and, if given, "
           "the sub-dimension 2";
  }
  if ((step > 0 && last < first) || (step < 0 && last > first))
  {
    return "its data file range " + words[1] + ".." + words[2] + " does not go in steps of " +
      words[3];
  }
  const unsigned long long span = step > 0
    ? static_cast<unsigned long long>(last) - static_cast<unsigned long long>(first)
    : static_cast<unsigned long long>(first) - static_cast<unsigned long long>(last);
  const unsigned long long stride =
    step > 0 ? static_cast<unsigned long long>(step) : 0ULL - static_cast<unsigned long long>(step);
  const unsigned long long count = span / stride; // files - 1
  if (count != 0 && count + 1 != static_cast<unsigned long long>(slices))
  {
    return "its data file pattern names " +
      (count == ULLONG_MAX ? std::string("2^64") : std::to_string(count + 1)) +
      " files, not one per slice (" + std::to_string(slices) + ")";
  }
  for (unsigned long long k = 0; k <= count; ++k)
  {
    // first + k * step, between first and last: k * stride <= span fits.
    const unsigned long long u = step > 0 ? static_cast<unsigned long long>(first) + k * stride
                                          : static_cast<unsigned long long>(first) - k * stride;
    const long long number = static_cast<long long>(u);
    std::string name;
    if (!FormatPattern(words[0], number, name))
    {
      return "its data file pattern " + Quote(words[0]) + " needs exactly one %d";
    }
    names.push_back(name);
  }
  return "";
}

std::string ParseSizes(const std::string& value, Header& h)
{
  for (const std::string& w : Words(value))
  {
    long long s = 0;
    if (!ParseInteger(w, s) || s < 1 || s > INT_MAX)
    {
      return "its sizes " + Quote(value) + " are not positive integers";
    }
    h.Sizes.push_back(s);
  }
  return "";
}

void ParseSpacings(const std::string& value, Header& h)
{
  const std::vector<std::string> words = Words(value);
  for (size_t i = 0; i < 3; ++i)
  {
    // "nan" (no spacing), negative or malformed spacings: 1.
    const double d = i < words.size() ? std::atof(words[i].c_str()) : 1.0;
    h.Spacing[i] = (std::isfinite(d) && d > 0.0) ? d : 1.0;
  }
  h.HaveSpacings = true;
}

void ParseDirections(const std::string& value, Header& h)
{
  // "(a,0,0) (0,b,0) (0,0,c)": the spacing is each vector's length.
  const std::vector<std::string> vectors = Words(value);
  for (size_t i = 0; i < 3 && i < vectors.size() && !h.HaveSpacings; ++i)
  {
    double d[3];
    if (ParseVector(vectors[i], d) && vtkMath::Norm(d) > 0.0 && std::isfinite(vtkMath::Norm(d)))
    {
      h.Spacing[i] = vtkMath::Norm(d);
    }
  }
}

// One "field: value" line of the header; "" or why it is refused.
std::string ParseField(const std::string& field, const std::string& value, Header& h)
{
  long long integer = 0;
  if (field == "dimension")
  {
    if (!ParseInteger(value, integer) || integer != 3)
    {
      return "its dimension is " + Quote(value) + " (only 3D volumes are read)";
    }
    h.Dimension = 3;
  }
  else if (field == "type")
  {
    h.ScalarType = ScalarType(value, h.ScalarBytes);
    if (h.ScalarType < 0)
    {
      return "its type " + Quote(value) + " is not supported";
    }
  }
  else if (field == "sizes")
  {
    return ParseSizes(value, h);
  }
  else if (field == "spacings")
  {
    ParseSpacings(value, h);
  }
  else if (field == "space directions")
  {
    ParseDirections(value, h);
  }
  else if (field == "space origin")
  {
    double o[3];
    if (ParseVector(value, o))
    {
      std::copy(o, o + 3, h.Origin);
    }
  }
  else if (field == "space")
  {
    h.LeftHanded = value == "3D-left-handed" || value == "left-anterior-superior" || value == "LAS";
  }
  else if (field == "encoding")
  {
    h.Encoding = Lower(value);
    if (h.Encoding != "raw")
    {
      return "its encoding " + Quote(value) + " is not supported (only raw)";
    }
  }
  else if (field == "endian")
  {
    if (Lower(value) != "little" && Lower(value) != "big")
    {
      return "its endian " + Quote(value) + " is neither little nor big";
    }
    h.BigEndian = Lower(value) == "big";
  }
  else if (field == "byte skip" || field == "byteskip")
  {
    if (!ParseInteger(value, h.ByteSkip) || h.ByteSkip < -1)
    {
      return "its byte skip " + Quote(value) + " is not an integer >= -1";
    }
  }
  else if (field == "line skip" || field == "lineskip")
  {
    if (!ParseInteger(value, integer) || integer != 0)
    {
      return "it has a line skip, which is not supported";
    }
  }
  return "";
}

// The "data file" field: one name, a pattern, or "LIST" (names follow).
std::string ParseDataFile(const std::string& value, bool& list, std::vector<std::string>& names,
  std::vector<std::string>& pattern)
{
  const std::vector<std::string> words = Words(value);
  if (words.empty())
  {
    return "its data file field is empty";
  }
  if (words[0] == "LIST")
  {
    list = true;
  }
  else if (words.size() == 4 || words.size() == 5)
  {
    pattern = words; // expanded once the sizes are known
  }
  else
  {
    names.push_back(value);
  }
  return "";
}

// Reads the header lines; leaves `in` at the first byte after the header.
std::string ParseHeader(
  std::istream& in, Header& h, std::vector<std::string>& names, std::vector<std::string>& pattern)
{
  std::string line;
  bool tooLong = false, list = false;
  const std::size_t maxLine = vtkDeepGISceneFileChecks::MaximumLineBytes;
  if (!vtkDeepGISceneFileChecks::ReadLine(in, line, maxLine, tooLong) || line.size() < 8 ||
    line.compare(0, 7, "NRRD000") != 0 || line[7] < '1' || line[7] > '5')
  {
    return "it does not start with NRRD0001 to NRRD0005";
  }
  std::uint64_t headerBytes = line.size() + 1;
  for (int number = 2; vtkDeepGISceneFileChecks::ReadLine(in, line, maxLine, tooLong); ++number)
  {
    headerBytes += line.size() + 1;
    if (headerBytes > vtkDeepGISceneFileChecks::MaximumTextFileBytes)
    {
      return "its header is longer than 64 MiB";
    }
    const std::string t = Trim(line);
    if (list)
    {
      if (!t.empty())
      {
        names.push_back(t);
      }
      continue;
    }
    if (t.empty())
    {
      break; // end of header (attached data follows)
    }
    const size_t colon = t.find(": ");
    if (t[0] == '#' || t.find(":=") != std::string::npos)
    {
      continue; // comments and key/value pairs
    }
    if (colon == std::string::npos)
    {
      return "its line " + std::to_string(number) + " is not a \"field: value\" line";
    }
    const std::string field = Lower(Trim(t.substr(0, colon)));
    const std::string value = Trim(t.substr(colon + 2));
    const std::string why = (field == "data file" || field == "datafile")
      ? ParseDataFile(value, list, names, pattern)
      : ParseField(field, value, h);
    if (!why.empty())
    {
      return why;
    }
  }
  if (tooLong)
  {
    return "a header line is longer than 1 MiB";
  }
  h.DataOffset = headerBytes;
  return "";
}

// Sizes, voxel count and the data files against each other and the limit.
std::string CheckSizes(const Header& h, std::uint64_t& bytes)
{
  if (h.Dimension != 3 || h.ScalarType < 0 || h.Sizes.size() != 3)
  {
    return h.Dimension != 3 ? "it has no dimension field"
      : h.ScalarType < 0    ? "it has no type field"
                            : "it needs 3 sizes (it has " + std::to_string(h.Sizes.size()) + ")";
  }
  // Each size is at most 2^31, so the product of the first two fits 64 bits.
  const std::uint64_t slice = std::uint64_t(h.Sizes[0]) * std::uint64_t(h.Sizes[1]) * h.ScalarBytes;
  const std::uint64_t limit = MaximumBytes;
  if (slice > limit || std::uint64_t(h.Sizes[2]) > limit / slice)
  {
    std::ostringstream why;
    why << "its sizes " << h.Sizes[0] << " x " << h.Sizes[1] << " x " << h.Sizes[2] << " need "
        << (double(slice) * double(h.Sizes[2])) << " bytes, more than the limit of "
        << (limit >> 30) << " GiB";
    return why.str();
  }
  bytes = slice * std::uint64_t(h.Sizes[2]);
  return "";
}

// Each data file exists, is regular and holds what the sizes need.
std::string CheckData(const std::string& path, Header& h, std::uint64_t bytes)
{
  const bool attached = h.DataFiles.empty();
  const std::vector<std::string> files = attached ? std::vector<std::string>{ path } : h.DataFiles;
  const std::uint64_t perFile = bytes / files.size();
  const std::uint64_t offset = attached ? h.DataOffset : 0;
  for (const std::string& f : files)
  {
    std::uint64_t size = 0;
    if (!RegularFileSize(f, size))
    {
      return "its data file " + f + " is missing or not a regular file";
    }
    if (h.ByteSkip == -1)
    {
      h.ByteSkip = size >= perFile + offset ? static_cast<long long>(size - perFile - offset) : 0;
    }
    const std::uint64_t skip = offset + static_cast<std::uint64_t>(h.ByteSkip);
    if (size < skip || size - skip < perFile)
    {
      return "its data file " + f + " has " + std::to_string(size) + " bytes, fewer than the " +
        std::to_string(skip + perFile) + " its sizes need (truncated)";
    }
  }
  return "";
}

// Collects the error messages of the image reader.
class Messages : public vtkCommand
{
public:
  static Messages* New() { return new Messages; }
  void Execute(vtkObject*, unsigned long, void* callData) override
  {
    std::string m = callData ? static_cast<const char*>(callData) : "";
    this->Text += (this->Text.empty() ? "" : "; ") + Trim(m.substr(m.find('\n') + 1));
  }
  std::string Text;
};

std::string ReadData(const std::string& path, const Header& h, vtkImageData* output)
{
  vtkNew<vtkImageReader2> reader;
  // NRRD data is in index order; a left-handed space is made right-handed
  // by flipping the rows, as vtkNrrdReader does (and as vtkVolume16Reader
  // reads the headsq slices).
  reader->SetFileLowerLeft(h.LeftHanded ? 0 : 1);
  reader->SetDataScalarType(h.ScalarType);
  reader->SetNumberOfScalarComponents(1);
  reader->SetDataExtent(0, static_cast<int>(h.Sizes[0] - 1), 0, static_cast<int>(h.Sizes[1] - 1), 0,
    static_cast<int>(h.Sizes[2] - 1));
  reader->SetDataSpacing(const_cast<double*>(h.Spacing));
  reader->SetDataOrigin(const_cast<double*>(h.Origin));
  if (h.BigEndian)
  {
    reader->SetDataByteOrderToBigEndian();
  }
  else
  {
    reader->SetDataByteOrderToLittleEndian();
  }
  const bool attached = h.DataFiles.empty();
  reader->SetHeaderSize(static_cast<unsigned long>((attached ? h.DataOffset : 0) + h.ByteSkip));
  if (h.DataFiles.size() > 1)
  {
    vtkNew<vtkStringArray> names;
    for (const std::string& f : h.DataFiles)
    {
      names->InsertNextValue(f);
    }
    reader->SetFileNames(names);
    reader->SetFileDimensionality(2);
  }
  else
  {
    reader->SetFileName(attached ? path.c_str() : h.DataFiles[0].c_str());
    reader->SetFileDimensionality(3);
  }
  vtkNew<Messages> messages;
  reader->AddObserver(vtkCommand::ErrorEvent, messages);
  reader->AddObserver(vtkCommand::WarningEvent, messages);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, messages);
  reader->Update();
  if (!messages->Text.empty() || reader->GetOutput()->GetNumberOfPoints() == 0)
  {
    return "its data cannot be read: " + messages->Text;
  }
  output->ShallowCopy(reader->GetOutput());
  return "";
}

// Reads the header of the NRRD file `path` into `h` and checks its data
// files. Returns "" on success, else one sentence saying why the file cannot
// be read.
std::string ReadHeader(const std::string& path, Header& h)
{
  vtksys::ifstream in(path.c_str(), std::ios::in | std::ios::binary);
  if (!vtkDeepGISceneFileChecks::IsRegularFile(path) || !in)
  {
    return "it cannot be opened";
  }
  std::vector<std::string> names, pattern;
  std::string why = ParseHeader(in, h, names, pattern);
  std::uint64_t bytes = 0;
  why = why.empty() ? CheckSizes(h, bytes) : why;
  if (why.empty() && !pattern.empty())
  {
    why = ExpandPattern(pattern, h.Sizes[2], names);
  }
  if (!why.empty())
  {
    return why;
  }
  if (!names.empty() && names.size() != 1 && names.size() != static_cast<size_t>(h.Sizes[2]))
  {
    return "it names " + std::to_string(names.size()) + " data files for " +
      std::to_string(h.Sizes[2]) + " slices";
  }
  const std::string dir = vtksys::SystemTools::GetFilenamePath(path);
  for (const std::string& name : names)
  {
    h.DataFiles.push_back(
      (dir.empty() || vtksys::SystemTools::FileIsFullPath(name)) ? name : dir + "/" + name);
  }
  return CheckData(path, h, bytes);
}

// Runs `read`, turning running out of memory into the reason returned.
template <typename Read>
std::string Guarded(const Read& read)
{
  // A file may declare more than memory holds: an error of this read, not
  // the end of the process.
  try
  {
    return read();
  }
  catch (const std::bad_alloc&)
  {
    return "out of memory";
  }
  catch (const std::length_error&)
  {
    return "it declares more data than fits";
  }
}
} // anonymous namespace

class vtkDeepGINrrdReader::vtkInternals
{
public:
  Header Parsed;
  /// Why the file named by the header read last cannot be read ("": it can).
  std::string Error;
};

//------------------------------------------------------------------------------
vtkDeepGINrrdReader::vtkDeepGINrrdReader()
  : Internals(new vtkInternals)
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkDeepGINrrdReader::~vtkDeepGINrrdReader()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
int vtkDeepGINrrdReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInternals& internals = *this->Internals;
  internals.Parsed = Header();
  const std::string path = this->FileName ? this->FileName : "";
  internals.Error = path.empty() ? "no file name given"
                                 : Guarded([&]() { return ReadHeader(path, internals.Parsed); });
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  // A file that cannot be read has an empty extent, and RequestData leaves
  // the output empty; the request itself succeeds, so that the one error is
  // this reader's (a failed request adds the executive's).
  int extent[6] = { 0, -1, 0, -1, 0, -1 };
  this->SetErrorCode(
    internals.Error.empty() ? vtkErrorCode::NoError : vtkErrorCode::FileFormatError);
  if (!internals.Error.empty())
  {
    vtkErrorMacro("Cannot read NRRD " << path << ": " << internals.Error);
    outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
    return 1;
  }
  const Header& h = internals.Parsed;
  for (int axis = 0; axis < 3; ++axis)
  {
    extent[2 * axis + 1] = static_cast<int>(h.Sizes[axis] - 1);
  }
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  outInfo->Set(vtkDataObject::SPACING(), h.Spacing, 3);
  outInfo->Set(vtkDataObject::ORIGIN(), h.Origin, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, h.ScalarType, 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkDeepGINrrdReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector);
  output->Initialize();
  if (!this->Internals->Error.empty())
  {
    return 1; // RequestInformation reported why
  }
  const std::string path = this->FileName;
  const std::string why =
    Guarded([&]() { return ReadData(path, this->Internals->Parsed, output); });
  if (!why.empty())
  {
    output->Initialize();
    this->SetErrorCode(vtkErrorCode::FileFormatError);
    vtkErrorMacro("Cannot read NRRD " << path << ": " << why);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkDeepGINrrdReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
