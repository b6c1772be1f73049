#include "vtkDeepGISceneLegacyVTK.h"

#include "vtkCellArray.h"
#include "vtkDeepGISceneFileChecks.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <vtksys/FStream.hxx>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <sstream>
#include <vector>

namespace vtkDeepGISceneLegacyVTK
{
namespace
{
// The largest legacy file read (it is read into memory): 1 GiB.
constexpr std::uint64_t MaximumBytes = std::uint64_t(1) << 30;

// Bytes of a legacy data type, 0 for the types that cannot be read or
// skipped by size (bit, string, unknown); `isFloat` set for float, double.
int TypeBytes(const std::string& type, bool& isFloat, bool& isSigned)
{
  static const char* const one[] = { "unsigned_char", "char", "signed_char" };
  static const char* const two[] = { "unsigned_short", "short" };
  static const char* const four[] = { "unsigned_int", "int", "vtktypeint32", "vtktypeuint32" };
  static const char* const eight[] = { "unsigned_long", "long", "vtktypeint64", "vtktypeuint64",
    "vtkIdType", "unsigned_long_long", "long_long" };
  isFloat = type == "float" || type == "double";
  isSigned = type.compare(0, 8, "unsigned") != 0 && type.find("uint") == std::string::npos;
  if (isFloat)
  {
    return type == "float" ? 4 : 8;
  }
  for (const char* t : one)
  {
    if (type == t)
    {
      return 1;
    }
  }
  for (const char* t : two)
  {
    if (type == t)
    {
      return 2;
    }
  }
  for (const char* t : four)
  {
    if (type == t)
    {
      return 4;
    }
  }
  for (const char* t : eight)
  {
    if (type == t)
    {
      return 8;
    }
  }
  return 0;
}

// Reads the file's keywords, numbers and binary blocks, checking every count
// against the bytes left.
class Parser
{
public:
  Parser(const std::string& text, bool binary)
    : Text(text)
    , Binary(binary)
  {
  }

  // The next white-space separated word; false at the end.
  bool Token(std::string& token)
  {
    while (this->Pos < this->Text.size() &&
      std::isspace(static_cast<unsigned char>(this->Text[this->Pos])))
    {
      ++this->Pos;
    }
    const size_t start = this->Pos;
    while (this->Pos < this->Text.size() &&
      !std::isspace(static_cast<unsigned char>(this->Text[this->Pos])))
    {
      ++this->Pos;
    }
    token = this->Text.substr(start, std::min<size_t>(this->Pos - start, 256));
    return this->Pos > start;
  }

  // The rest of the current line (its newline consumed).
  std::string Line()
  {
    const size_t end = this->Text.find('\n', this->Pos);
    const size_t stop = end == std::string::npos ? this->Text.size() : end;
    std::string line = this->Text.substr(this->Pos, std::min<size_t>(stop - this->Pos, 4096));
    this->Pos = end == std::string::npos ? this->Text.size() : end + 1;
    return line;
  }

  bool Count(std::uint64_t& value, const char* what)
  {
    std::string token;
    char* end = nullptr;
    if (!this->Token(token) || token.empty() || token[0] == '-' ||
      (value = std::strtoull(token.c_str(), &end, 10), *end) || value > (1ULL << 40))
    {
      this->Error = std::string("a malformed ") + what;
      return false;
    }
    return true;
  }

  // Reads (or, with `values` null, skips) `count` values of `type`.
  bool Values(const std::string& type, std::uint64_t count, std::vector<double>* values,
    const std::string& what)
  {
    bool isFloat = false, isSigned = false;
    const int bytes = TypeBytes(type, isFloat, isSigned);
    if (!bytes)
    {
      this->Error = what + " has the unsupported type \"" + type + "\"";
      return false;
    }
    if (this->Binary && this->Pos > 0 && this->Text[this->Pos - 1] != '\n')
    {
      this->Line(); // binary data starts on the line after its keyword
    }
    const std::uint64_t left = this->Text.size() - this->Pos;
    if (count > left / (this->Binary ? bytes : 1))
    {
      this->Error = what + " needs " + std::to_string(count) + " values, more than the " +
        std::to_string(left) + " bytes left (truncated)";
      return false;
    }
    if (values)
    {
      values->resize(static_cast<size_t>(count));
    }
    return this->Binary ? this->BinaryValues(bytes, isFloat, isSigned, count, values)
                        : this->TextValues(count, values, what);
  }

  const std::string& Text;
  bool Binary;
  size_t Pos = 0;
  std::string Error;

private:
  bool BinaryValues(
    int bytes, bool isFloat, bool isSigned, std::uint64_t count, std::vector<double>* values)
  {
    const unsigned char* data =
      reinterpret_cast<const unsigned char*>(this->Text.data()) + this->Pos;
    this->Pos += static_cast<size_t>(count * bytes);
    for (std::uint64_t i = 0; values && i < count; ++i, data += bytes)
    {
      std::uint64_t u = 0;
      for (int b = 0; b < bytes; ++b)
      {
        u = (u << 8) | data[b]; // big endian
      }
      double v;
      if (isFloat)
      {
        float f;
        const std::uint32_t u32 = static_cast<std::uint32_t>(u);
        std::memcpy(&f, &u32, 4);
        std::memcpy(&v, &u, 8);
        v = bytes == 4 ? f : v;
      }
      else
      {
        const std::uint64_t sign = std::uint64_t(1) << (8 * bytes - 1);
        v = (isSigned && (u & sign)) ? -static_cast<double>((~u & (sign - 1)) + 1)
                                     : static_cast<double>(u);
      }
      (*values)[static_cast<size_t>(i)] = v;
    }
    return true;
  }

  bool TextValues(std::uint64_t count, std::vector<double>* values, const std::string& what)
  {
    std::string token;
    for (std::uint64_t i = 0; i < count; ++i)
    {
      char* end = nullptr;
      double v = 0.0;
      if (!this->Token(token) || (v = std::strtod(token.c_str(), &end), *end))
      {
        this->Error = what + " ends after " + std::to_string(i) + " of its " +
          std::to_string(count) + " values (truncated or malformed)";
        return false;
      }
      if (values)
      {
        (*values)[static_cast<size_t>(i)] = v;
      }
    }
    return true;
  }
};

// "METADATA": lines up to an empty one.
void SkipMetadata(Parser& p)
{
  p.Line();
  while (p.Pos < p.Text.size())
  {
    const std::string line = p.Line();
    if (line.find_first_not_of(" \t\r") == std::string::npos)
    {
      return;
    }
  }
}

// A cell section ("POLYGONS a b"): legacy lists before version 5, OFFSETS
// and CONNECTIVITY from version 5 on. `cells` null: checked, not kept.
bool ReadCells(Parser& p, int version, const std::string& keyword, vtkCellArray* cells)
{
  std::uint64_t a = 0, b = 0;
  if (!p.Count(a, keyword.c_str()) || !p.Count(b, keyword.c_str()))
  {
    return false;
  }
  std::vector<double> first, second;
  std::string token, type;
  if (version < 5)
  {
    if (!p.Values("int", b, &first, keyword))
    {
      return false;
    }
    size_t at = 0;
    for (std::uint64_t c = 0; c < a; ++c)
    {
      const double n = at < first.size() ? first[at] : -1.0;
      if (!(n >= 0.0) || n > static_cast<double>(first.size() - at - 1))
      {
        p.Error = keyword + " cell " + std::to_string(c) + " runs past its list";
        return false;
      }
      std::vector<vtkIdType> ids(first.begin() + at + 1, first.begin() + at + 1 + size_t(n));
      if (cells)
      {
        cells->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
      }
      at += 1 + static_cast<size_t>(n);
    }
    if (at != first.size())
    {
      p.Error = keyword + " lists " + std::to_string(first.size()) + " values for " +
        std::to_string(a) + " cells";
      return false;
    }
    return true;
  }
  // Version 5: OFFSETS TYPE (a values), CONNECTIVITY TYPE (b values).
  if (!p.Token(token) || token != "OFFSETS" || !p.Token(type) ||
    !p.Values(type, a, &first, keyword + " offsets") || !p.Token(token) ||
    token != "CONNECTIVITY" || !p.Token(type) ||
    !p.Values(type, b, &second, keyword + " connectivity"))
  {
    p.Error = p.Error.empty() ? keyword + " lacks its OFFSETS or CONNECTIVITY" : p.Error;
    return false;
  }
  for (size_t i = 0; i < first.size(); ++i)
  {
    if ((i == 0 && first[i] != 0.0) || (i > 0 && !(first[i] >= first[i - 1])))
    {
      p.Error = keyword + " offsets do not start at 0 and grow";
      return false;
    }
  }
  if (!first.empty() && first.back() != static_cast<double>(second.size()))
  {
    p.Error = keyword + " offsets end at " + std::to_string(first.back()) + ", not at " +
      std::to_string(second.size());
    return false;
  }
  for (size_t c = 0; cells && c + 1 < first.size(); ++c)
  {
    std::vector<vtkIdType> ids(
      second.begin() + size_t(first[c]), second.begin() + size_t(first[c + 1]));
    cells->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  return true;
}

// "FIELD NAME K": K arrays "NAME COMPONENTS TUPLES TYPE" and their values.
bool SkipField(Parser& p)
{
  std::string name;
  std::uint64_t arrays = 0;
  if (!p.Token(name) || !p.Count(arrays, "FIELD"))
  {
    return false;
  }
  for (std::uint64_t i = 0; i < arrays; ++i)
  {
    std::string array, type;
    std::uint64_t components = 0, tuples = 0;
    if (!p.Token(array))
    {
      return false;
    }
    if (array == "METADATA")
    {
      SkipMetadata(p);
      --i;
      continue;
    }
    if (array == "NULL_ARRAY")
    {
      continue;
    }
    if (!p.Count(components, "FIELD array") || !p.Count(tuples, "FIELD array") || !p.Token(type) ||
      components > (1u << 20) || !p.Values(type, components * tuples, nullptr, "FIELD array"))
    {
      return false;
    }
  }
  return true;
}

struct Geometry
{
  int Version = 0;
  std::vector<double> Points;
  bool DoublePoints = false;
  std::vector<double> Normals;
  vtkNew<vtkCellArray> Polys, Strips;
  std::uint64_t Attributes = 0; // tuples of the current POINT_DATA / CELL_DATA
  bool PointAttributes = false;
};

// One attribute of POINT_DATA / CELL_DATA (its keyword read): false when it
// cannot be skipped (then reading stops, keeping the geometry).
bool ReadAttribute(Parser& p, const std::string& keyword, Geometry& g)
{
  std::vector<std::string> words; // the rest of the keyword's line
  {
    std::istringstream in(p.Line());
    for (std::string w; in >> w;)
    {
      words.push_back(w);
    }
  }
  auto number = [&](size_t i, std::uint64_t fallback) -> std::uint64_t
  {
    char* end = nullptr;
    const std::uint64_t v = i < words.size() ? std::strtoull(words[i].c_str(), &end, 10) : fallback;
    return (i < words.size() && *end) ? 0 : v;
  };
  const std::uint64_t n = g.Attributes;
  std::string type = words.size() > 1 ? words[1] : "";
  std::uint64_t values = 0;
  std::vector<double>* keep = nullptr;
  if (keyword == "SCALARS")
  {
    std::string lookup, table;
    if (!p.Token(lookup) || lookup != "LOOKUP_TABLE" || !p.Token(table))
    {
      return false;
    }
    values = n * std::min<std::uint64_t>(number(2, 1), 16);
  }
  else if (keyword == "VECTORS" || keyword == "NORMALS")
  {
    values = 3 * n;
    keep = (keyword == "NORMALS" && g.PointAttributes && g.Normals.empty()) ? &g.Normals : nullptr;
  }
  else if (keyword == "TEXTURE_COORDINATES")
  {
    type = words.size() > 2 ? words[2] : "";
    values = n * std::min<std::uint64_t>(number(1, 0), 3);
  }
  else if (keyword == "TENSORS" || keyword == "TENSORS6")
  {
    values = (keyword == "TENSORS" ? 9 : 6) * n;
  }
  else if (keyword == "GLOBAL_IDS" || keyword == "PEDIGREE_IDS")
  {
    values = n;
  }
  else if (keyword == "COLOR_SCALARS" || keyword == "LOOKUP_TABLE")
  {
    const std::uint64_t k = std::min<std::uint64_t>(number(1, 0), 1ULL << 32);
    values = keyword == "LOOKUP_TABLE" ? 4 * k : n * std::min<std::uint64_t>(k, 16);
    type = p.Binary ? "unsigned_char" : "float";
  }
  else
  {
    return false;
  }
  return p.Values(type, values, keep, keyword);
}

// The sections after the header; "" or why the file is refused.
std::string ReadSections(Parser& p, Geometry& g)
{
  std::string keyword;
  bool attributes = false;
  while (p.Token(keyword))
  {
    std::uint64_t count = 0;
    bool ok = true;
    if (keyword == "POINTS" && g.Points.empty())
    {
      std::string type;
      ok = p.Count(count, "POINTS") && p.Token(type) && count <= (1ULL << 31) &&
        p.Values(type, 3 * count, &g.Points, "POINTS");
      g.DoublePoints = type == "double";
    }
    else if (keyword == "POLYGONS" || keyword == "TRIANGLE_STRIPS" || keyword == "VERTICES" ||
      keyword == "LINES")
    {
      vtkCellArray* cells = keyword == "POLYGONS" ? g.Polys.Get()
        : keyword == "TRIANGLE_STRIPS"            ? g.Strips.Get()
                                                  : nullptr;
      ok = ReadCells(p, g.Version, keyword, cells);
    }
    else if (keyword == "METADATA")
    {
      SkipMetadata(p);
    }
    else if (keyword == "FIELD")
    {
      ok = SkipField(p);
    }
    else if (keyword == "POINT_DATA" || keyword == "CELL_DATA")
    {
      ok = p.Count(g.Attributes, keyword.c_str());
      g.PointAttributes = keyword == "POINT_DATA";
      attributes = true;
    }
    else if (!attributes || !ReadAttribute(p, keyword, g))
    {
      // Unknown, or an attribute that cannot be skipped: the geometry is
      // complete if the points came first.
      return g.Points.empty() ? "it has the unexpected keyword \"" + keyword.substr(0, 40) + "\""
                              : "";
    }
    if (!ok)
    {
      if (attributes && !g.Points.empty() && p.Error.find("unsupported type") != std::string::npos)
      {
        return ""; // a string or bit array: the rest is not needed
      }
      return p.Error.empty() ? "its " + keyword.substr(0, 40) + " section is malformed" : p.Error;
    }
  }
  return "";
}

// Header: "# vtk DataFile Version X.Y", a title, ASCII or BINARY, DATASET POLYDATA.
std::string ReadHeader(const std::string& text, int& version, bool& binary, size_t& end)
{
  Parser p(text, false);
  const std::string first = p.Line();
  const std::string magic = "# vtk DataFile Version ";
  if (first.compare(0, magic.size(), magic) != 0)
  {
    return "it does not start with \"" + magic + "\"";
  }
  version = std::atoi(first.c_str() + magic.size());
  p.Line(); // title
  std::string format, dataset, type;
  if (!p.Token(format) || (format != "ASCII" && format != "BINARY"))
  {
    return "its third line is neither ASCII nor BINARY";
  }
  if (!p.Token(dataset) || dataset != "DATASET" || !p.Token(type) || type != "POLYDATA")
  {
    return "it does not hold polydata (DATASET POLYDATA)";
  }
  binary = format == "BINARY";
  end = p.Pos;
  return "";
}
} // anonymous namespace

//------------------------------------------------------------------------------
std::string Read(const std::string& path, vtkPolyData* output)
{
  std::uint64_t size = 0;
  if (!vtkDeepGISceneFileChecks::RegularFileSize(path, size) || size > MaximumBytes)
  {
    return size > MaximumBytes ? "it is larger than 1 GiB" : "it cannot be opened";
  }
  vtksys::ifstream in(path.c_str(), std::ios::in | std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  Geometry g;
  bool binary = false;
  size_t start = 0;
  std::string why = ReadHeader(text, g.Version, binary, start);
  Parser p(text, binary);
  p.Pos = start;
  why = why.empty() ? ReadSections(p, g) : why;
  if (!why.empty())
  {
    return why;
  }
  vtkNew<vtkPoints> points;
  points->SetDataType(g.DoublePoints ? VTK_DOUBLE : VTK_FLOAT);
  points->SetNumberOfPoints(static_cast<vtkIdType>(g.Points.size() / 3));
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    points->SetPoint(i, &g.Points[3 * static_cast<size_t>(i)]);
  }
  output->Initialize();
  output->SetPoints(points);
  output->SetPolys(g.Polys);
  output->SetStrips(g.Strips);
  if (!g.Normals.empty() && g.Normals.size() == g.Points.size())
  {
    vtkNew<vtkFloatArray> normals;
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(points->GetNumberOfPoints());
    for (size_t i = 0; i < g.Normals.size(); ++i)
    {
      normals->SetValue(static_cast<vtkIdType>(i), static_cast<float>(g.Normals[i]));
    }
    output->GetPointData()->SetNormals(normals);
  }
  return "";
}
}
