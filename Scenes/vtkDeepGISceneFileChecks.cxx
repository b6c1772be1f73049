#include "vtkDeepGISceneFileChecks.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkPLYReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSTLReader.h"
#include "vtkXMLPolyDataReader.h"

#include <vtksys/FStream.hxx>
#include <vtksys/SystemTools.hxx>

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <sstream>
#include <vector>

namespace vtkDeepGISceneFileChecks
{
namespace
{
// VTK 9.1's vtkPLY reads lines into a 4096-byte buffer (get_words): longer
// ones are split, and a split element line has fewer values than its
// properties need, which vtkPLY reads past. Such lines are refused.
constexpr std::size_t MaximumPLYLineBytes = 4000;

struct PLYProperty
{
  bool IsList = false;
  int CountBytes = 0; // list count type (integer types only)
  int ItemBytes = 0;  // scalar type, or the list's item type
  bool CountSigned = false;
  bool ItemInteger = false;
  bool ItemSigned = false;
  bool Indices = false; // a face's vertex_indices: each must name a vertex
  std::string Name;
};

struct PLYElement
{
  std::string Name;
  long long Count = 0;
  std::vector<PLYProperty> Properties;
};

// Bytes of a PLY scalar type, 0 if unknown; `isInteger`, `isSigned` set.
int PLYTypeBytes(const std::string& type, bool& isInteger, bool& isSigned)
{
  struct Type
  {
    const char* Name;
    int Bytes;
    bool Integer;
    bool Signed;
  };
  static const Type types[] = { { "char", 1, true, true }, { "int8", 1, true, true },
    { "uchar", 1, true, false }, { "uint8", 1, true, false }, { "short", 2, true, true },
    { "int16", 2, true, true }, { "ushort", 2, true, false }, { "uint16", 2, true, false },
    { "int", 4, true, true }, { "int32", 4, true, true }, { "uint", 4, true, false },
    { "uint32", 4, true, false }, { "float", 4, false, true }, { "float32", 4, false, true },
    { "double", 8, false, true }, { "float64", 8, false, true } };
  for (const Type& t : types)
  {
    if (type == t.Name)
    {
      isInteger = t.Integer;
      isSigned = t.Signed;
      return t.Bytes;
    }
  }
  return 0;
}

std::vector<std::string> Words(const std::string& line)
{
  std::vector<std::string> words;
  std::istringstream in(line);
  std::string w;
  while (in >> w)
  {
    words.push_back(w);
  }
  return words;
}

// One property line ("property TYPE NAME", "property list CTYPE ITYPE NAME").
std::string ParsePLYProperty(const std::vector<std::string>& words, PLYProperty& property)
{
  bool integer = false, isSigned = false;
  property.Name = words.back();
  if (words.size() == 5 && words[1] == "list")
  {
    property.IsList = true;
    property.CountBytes = PLYTypeBytes(words[2], integer, isSigned);
    property.CountSigned = isSigned;
    if (!property.CountBytes || !integer)
    {
      return "a list count type that is not an integer type";
    }
    property.ItemBytes = PLYTypeBytes(words[3], integer, isSigned);
    property.ItemInteger = integer;
    property.ItemSigned = isSigned;
    property.Indices = words[4] == "vertex_indices" || words[4] == "vertex_index";
    return property.ItemBytes ? "" : "an unknown list item type";
  }
  if (words.size() != 3)
  {
    return "a malformed property line";
  }
  property.ItemBytes = PLYTypeBytes(words[1], integer, isSigned);
  return property.ItemBytes ? "" : "an unknown property type";
}

// The header: format and elements. Leaves `in` at the first data byte.
std::string ParsePLYHeader(std::istream& in, std::string& format, std::vector<PLYElement>& elements)
{
  std::string line;
  bool tooLong = false;
  if (!ReadLine(in, line, MaximumPLYLineBytes, tooLong) ||
    Words(line) != std::vector<std::string>{ "ply" })
  {
    return "it does not start with the line \"ply\"";
  }
  while (ReadLine(in, line, MaximumPLYLineBytes, tooLong))
  {
    // vtkPLY reads the header as C strings: a NUL (or another control
    // character) would end or split a line differently from here.
    for (char c : line)
    {
      if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\r')
      {
        return "the header holds a control character";
      }
    }
    const std::vector<std::string> words = Words(line);
    if (words.empty() || words[0] == "comment" || words[0] == "obj_info")
    {
      continue;
    }
    if (words[0] == "end_header")
    {
      return format.empty() ? "the header has no format line" : "";
    }
    if (words[0] == "format" && words.size() == 3 && format.empty() &&
      (words[1] == "ascii" || words[1] == "binary_little_endian" ||
        words[1] == "binary_big_endian"))
    {
      format = words[1];
    }
    else if (words[0] == "element" && words.size() == 3)
    {
      PLYElement element;
      element.Name = words[1].substr(0, 40); // for messages
      for (char& c : element.Name)
      {
        c = std::isprint(static_cast<unsigned char>(c)) ? c : '?';
      }
      char* end = nullptr;
      element.Count = std::strtoll(words[2].c_str(), &end, 10);
      if (*end || element.Count < 0 || element.Count > INT_MAX)
      {
        return "an element count is not an integer from 0 to 2^31 - 1";
      }
      elements.push_back(element);
    }
    else if (words[0] == "property" && !elements.empty())
    {
      PLYProperty property;
      const std::string why = ParsePLYProperty(words, property);
      if (!why.empty())
      {
        return "the header has " + why;
      }
      property.Indices = property.Indices && elements.back().Name == "face";
      elements.back().Properties.push_back(property);
    }
    else
    {
      std::string shown = line.substr(0, 80);
      for (char& c : shown)
      {
        c = std::isprint(static_cast<unsigned char>(c)) ? c : '?';
      }
      return "the header line \"" + shown + "\" is not PLY";
    }
  }
  return tooLong ? "a header line is longer than " + std::to_string(MaximumPLYLineBytes) + " bytes"
                 : "the header has no end_header line";
}

// Reads one binary value of `bytes` bytes in the file's byte order.
bool ReadPLYValue(
  std::istream& in, int bytes, bool integer, bool isSigned, bool bigEndian, double& value)
{
  unsigned char b[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
  if (!in.read(reinterpret_cast<char*>(b), bytes))
  {
    return false;
  }
  std::uint64_t u = 0;
  for (int i = 0; i < bytes; ++i)
  {
    u = (u << 8) | b[bigEndian ? i : bytes - 1 - i];
  }
  if (!integer)
  {
    float f;
    double d;
    std::uint32_t u32 = static_cast<std::uint32_t>(u);
    std::memcpy(&f, &u32, 4);
    std::memcpy(&d, &u, 8);
    value = bytes == 4 ? f : d;
    return true;
  }
  const std::uint64_t sign = std::uint64_t(1) << (8 * bytes - 1);
  value =
    (isSigned && (u & sign)) ? -static_cast<double>((~u & (sign - 1)) + 1) : static_cast<double>(u);
  return true;
}

// A vertex index of a face names one of the `vertices` (vtkPLYReader reads
// the points of every face while it reads the faces).
bool IsVertexIndex(double value, long long vertices)
{
  return std::isfinite(value) && value >= 0.0 && value < static_cast<double>(vertices);
}

std::string CheckBinaryPLY(std::istream& in, std::uint64_t size, bool bigEndian,
  const std::vector<PLYElement>& elements, long long vertices)
{
  std::uint64_t position = static_cast<std::uint64_t>(in.tellg());
  for (const PLYElement& e : elements)
  {
    bool anyList = false;
    std::uint64_t fixed = 0;
    for (const PLYProperty& p : e.Properties)
    {
      anyList = anyList || p.IsList;
      fixed += p.IsList ? 0 : p.ItemBytes;
    }
    const std::string truncated = "it ends inside element " + e.Name + " (truncated)";
    if (!anyList)
    {
      if (fixed * static_cast<std::uint64_t>(e.Count) > size - position)
      {
        return truncated;
      }
      position += fixed * static_cast<std::uint64_t>(e.Count);
      continue;
    }
    for (long long i = 0; i < e.Count; ++i)
    {
      for (const PLYProperty& p : e.Properties)
      {
        std::uint64_t need = p.IsList ? p.CountBytes : p.ItemBytes;
        if (need > size - position)
        {
          return truncated;
        }
        if (p.IsList)
        {
          double count = 0;
          in.seekg(static_cast<std::streamoff>(position));
          if (!ReadPLYValue(in, p.CountBytes, true, p.CountSigned, bigEndian, count) || count < 0)
          {
            return "element " + e.Name + " has a negative or unreadable list count";
          }
          position += need;
          need = static_cast<std::uint64_t>(count) * p.ItemBytes;
          if (need > size - position)
          {
            return truncated;
          }
          for (double k = 0, index = 0; p.Indices && k < count; ++k)
          {
            if (!ReadPLYValue(in, p.ItemBytes, p.ItemInteger, p.ItemSigned, bigEndian, index) ||
              !IsVertexIndex(index, vertices))
            {
              return "face " + std::to_string(i) + " names a vertex outside the " +
                std::to_string(vertices) + " vertices";
            }
          }
        }
        position += need;
      }
    }
  }
  return "";
}

// Whether `word` is a number vtkPLY reads (atoi / atof on it is safe anyway;
// this refuses text where values belong, e.g. a truncated line).
bool IsNumber(const std::string& word)
{
  char* end = nullptr;
  std::strtod(word.c_str(), &end);
  return end != word.c_str() && *end == '\0';
}

std::string CheckAsciiPLY(
  std::istream& in, const std::vector<PLYElement>& elements, long long vertices)
{
  std::string line;
  bool tooLong = false;
  for (const PLYElement& e : elements)
  {
    for (long long i = 0; i < e.Count; ++i)
    {
      if (!ReadLine(in, line, MaximumPLYLineBytes, tooLong))
      {
        return tooLong ? "a line of element " + e.Name + " is longer than " +
            std::to_string(MaximumPLYLineBytes) + " bytes"
                       : "it ends after " + std::to_string(i) + " of the " +
            std::to_string(e.Count) + " lines of element " + e.Name + " (truncated)";
      }
      const std::vector<std::string> words = Words(line);
      size_t next = 0;
      for (const PLYProperty& p : e.Properties)
      {
        long long count = 1;
        if (p.IsList)
        {
          char* end = nullptr;
          count = next < words.size() ? std::strtoll(words[next].c_str(), &end, 10) : -1;
          if (count < 0 || *end)
          {
            return "line " + std::to_string(i + 1) + " of element " + e.Name +
              " has a missing or malformed list count";
          }
          ++next;
        }
        for (long long k = 0; k < count; ++k, ++next)
        {
          if (next >= words.size() || !IsNumber(words[next]))
          {
            return "line " + std::to_string(i + 1) + " of element " + e.Name +
              " has fewer values than its properties need";
          }
          if (p.Indices && !IsVertexIndex(std::atof(words[next].c_str()), vertices))
          {
            return "face " + std::to_string(i) + " names a vertex outside the " +
              std::to_string(vertices) + " vertices";
          }
        }
      }
    }
  }
  return "";
}
// The properties vtkPLYReader reads, as it reads them: it asks for x, y and
// z and goes on after "Cannot read geometry" with a closed file; it reads a
// face's vertex_indices without checking they are there (then frees an
// uninitialised pointer); it reads its known properties as lists or scalars
// whatever the file says.
std::string CheckPLYProperties(const std::vector<PLYElement>& elements)
{
  static const std::vector<std::string> vertexScalars = { "x", "y", "z", "u", "v", "texture_u",
    "texture_v", "nx", "ny", "nz", "red", "green", "blue", "alpha", "diffuse_red", "diffuse_green",
    "diffuse_blue" };
  static const std::vector<std::string> faceScalars = { "intensity", "red", "green", "blue",
    "alpha" };
  static const std::vector<std::string> faceLists = { "vertex_indices", "texcoord" };
  auto in = [](const std::vector<std::string>& names, const std::string& name)
  { return std::find(names.begin(), names.end(), name) != names.end(); };
  int xyz = 0;
  for (const PLYElement& e : elements)
  {
    bool indices = false;
    for (const PLYProperty& p : e.Properties)
    {
      const bool vertex = e.Name == "vertex", face = e.Name == "face";
      if ((vertex && in(vertexScalars, p.Name) && p.IsList) ||
        (face && in(faceScalars, p.Name) && p.IsList) ||
        (face && in(faceLists, p.Name) && !p.IsList))
      {
        return "the property " + p.Name + " of element " + e.Name + " is " +
          (p.IsList ? "a list" : "not a list");
      }
      xyz += vertex && (p.Name == "x" || p.Name == "y" || p.Name == "z") ? 1 : 0;
      indices = indices || (face && p.Name == "vertex_indices");
    }
    if (e.Name == "face" && !indices)
    {
      return "its face element has no vertex_indices list";
    }
  }
  return xyz >= 3 ? "" : "it has no vertex element with x, y and z";
}

} // anonymous namespace

//------------------------------------------------------------------------------
bool IsRegularFile(const std::string& path)
{
  std::uint64_t bytes = 0;
  return RegularFileSize(path, bytes);
}

//------------------------------------------------------------------------------
bool RegularFileSize(const std::string& path, std::uint64_t& bytes)
{
  struct stat s;
  if (path.empty() || stat(path.c_str(), &s) != 0 || !S_ISREG(s.st_mode))
  {
    return false;
  }
  bytes = static_cast<std::uint64_t>(s.st_size);
  return true;
}

//------------------------------------------------------------------------------
bool ReadLine(std::istream& in, std::string& line, std::size_t maxBytes, bool& tooLong)
{
  line.clear();
  tooLong = false;
  std::streambuf* buffer = in.rdbuf();
  if (!in.good() || !buffer)
  {
    return false;
  }
  for (;;)
  {
    const int c = buffer->sbumpc();
    if (c == std::char_traits<char>::eof())
    {
      in.setstate(std::ios::eofbit);
      return !line.empty();
    }
    if (c == '\n')
    {
      return true;
    }
    if (line.size() >= maxBytes)
    {
      tooLong = true;
      in.setstate(std::ios::failbit);
      return false;
    }
    line += static_cast<char>(c);
  }
}

//------------------------------------------------------------------------------
std::string CheckPLY(const std::string& path)
{
  // The file is validated here and then read by vtkPLYReader, rather than
  // read by a PLY parser of our own: the walk below is all that VTK's reader
  // lacks (it trusts the counts), and VTK keeps reading the properties (colours,
  // texture coordinates) the loader may want later.
  std::uint64_t size = 0;
  vtksys::ifstream in(path.c_str(), std::ios::in | std::ios::binary);
  if (!RegularFileSize(path, size) || !in)
  {
    return "it cannot be opened";
  }
  std::string format;
  std::vector<PLYElement> elements;
  std::string why = ParsePLYHeader(in, format, elements);
  if (!why.empty())
  {
    return why;
  }
  why = CheckPLYProperties(elements);
  if (!why.empty())
  {
    return why;
  }
  // vtkPLYReader reads the points of each face as it reads the faces: the
  // vertices must come first, once.
  long long vertices = -1;
  bool faces = false;
  for (const PLYElement& e : elements)
  {
    if (e.Properties.empty() && e.Count > 0)
    {
      return "element " + e.Name + " has no properties";
    }
    if ((e.Name == "vertex" && (vertices >= 0 || faces)) || (e.Name == "face" && faces))
    {
      return "it has a second vertex or face element, or faces before the vertices";
    }
    vertices = e.Name == "vertex" ? e.Count : vertices;
    faces = faces || e.Name == "face";
  }
  vertices = std::max(vertices, 0LL);
  if (format == "ascii")
  {
    return CheckAsciiPLY(in, elements, vertices);
  }
  return CheckBinaryPLY(in, size, format == "binary_big_endian", elements, vertices);
}

//------------------------------------------------------------------------------
std::string CheckSTL(const std::string& path)
{
  std::uint64_t size = 0;
  if (!RegularFileSize(path, size))
  {
    return "it cannot be opened";
  }
  if (vtksys::SystemTools::DetectFileType(path.c_str()) == vtksys::SystemTools::FileTypeText)
  {
    return ""; // vtkSTLReader's ASCII parser reports what it cannot read
  }
  vtksys::ifstream in(path.c_str(), std::ios::in | std::ios::binary);
  unsigned char header[84];
  if (size < 84 || !in.read(reinterpret_cast<char*>(header), 84))
  {
    return "a binary STL needs 84 bytes of header, this one has " + std::to_string(size) +
      " bytes (truncated)";
  }
  const std::uint64_t triangles = std::uint64_t(header[80]) | std::uint64_t(header[81]) << 8 |
    std::uint64_t(header[82]) << 16 | std::uint64_t(header[83]) << 24;
  const std::uint64_t needed = 84 + 50 * triangles;
  if (needed > size)
  {
    return "its header declares " + std::to_string(triangles) + " triangles (" +
      std::to_string(needed) + " bytes) but it has " + std::to_string(size) + " bytes (truncated)";
  }
  return "";
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkAlgorithm> MakeMeshReader(
  const std::string& path, const std::string& ext, std::string& invalid)
{
  if (ext == ".ply")
  {
    invalid = CheckPLY(path);
    auto r = vtkSmartPointer<vtkPLYReader>::New();
    r->SetFileName(path.c_str());
    return r;
  }
  if (ext == ".stl")
  {
    invalid = CheckSTL(path);
    auto r = vtkSmartPointer<vtkSTLReader>::New();
    r->SetFileName(path.c_str());
    return r;
  }
  if (ext == ".vtp")
  {
    auto r = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    r->SetFileName(path.c_str());
    return r;
  }
  return nullptr;
}
}
