#include "vtkDeepGIOBJReader.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDeepGISceneFileChecks.h"
#include "vtkDeepGISceneText.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#include <vtksys/FStream.hxx>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <new>
#include <set>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

vtkStandardNewMacro(vtkDeepGIOBJReader);

namespace
{
using vtkDeepGISceneText::ParseInteger;
using vtkDeepGISceneText::Trim;
using vtkDeepGISceneText::Words;

using vtkDeepGISceneFileChecks::IsRegularFile;

// Reads the logical lines of an OBJ or MTL file: comments ('#' to the end of
// the line) and surrounding white space removed, backslash continuations
// joined (a lone "\\" joins nothing). `lineNumber` is the number of the
// line's first physical line. Lines (joined or not) longer than
// MaximumLineBytes end the file with TooLong set.
class LogicalLineReader
{
public:
  explicit LogicalLineReader(std::istream& in)
    : In(in)
  {
  }
  bool Next(std::string& line, int& lineNumber)
  {
    line.clear();
    std::string physical;
    bool any = false;
    const size_t limit = vtkDeepGISceneFileChecks::MaximumLineBytes;
    while (vtkDeepGISceneFileChecks::ReadLine(this->In, physical, limit, this->TooLong))
    {
      ++this->Physical;
      if (!any)
      {
        lineNumber = this->Physical;
      }
      any = true;
      const size_t hash = physical.find('#');
      if (hash != std::string::npos)
      {
        physical.erase(hash);
      }
      physical = Trim(physical);
      const bool continued = !physical.empty() && physical.back() == '\\';
      if (continued)
      {
        physical.pop_back();
      }
      line += (line.empty() || physical.empty() ? "" : " ") + physical;
      if (line.size() > limit)
      {
        this->TooLong = true;
        return false;
      }
      if (!continued)
      {
        line = Trim(line);
        return true;
      }
    }
    line = Trim(line);
    return any && !this->TooLong;
  }
  bool TooLong = false;

private:
  std::istream& In;
  int Physical = 0;
};

// The rest of a logical line after its first word ("usemtl red" -> "red").
std::string Rest(const std::string& line)
{
  const size_t end = line.find_first_of(" \t");
  return end == std::string::npos ? std::string() : Trim(line.substr(end));
}

// Parses a whole word as a number.
bool ParseDouble(const std::string& word, double& value)
{
  if (word.empty())
  {
    return false;
  }
  char* end = nullptr;
  value = std::strtod(word.c_str(), &end);
  return end == word.c_str() + word.size();
}

// Resolves a 1-based OBJ index (negative: relative to the `count` elements
// defined so far, -1 the last one) to a 0-based index. Returns -1 for 0,
// malformed indices and relative ones before the first element. Positive
// indices are not checked against `count` here (OBJ allows references to
// elements defined further down), only against the final count.
long long ResolveIndex(const std::string& word, long long count)
{
  long long i = 0;
  if (!ParseInteger(word, i) || i == 0)
  {
    return -1;
  }
  if (i > 0)
  {
    return i - 1;
  }
  return count + i >= 0 ? count + i : -1;
}

// The faces of one material of an OBJ file, as 0-based indices into the
// file's vertices and normals (-1: no normal).
struct FaceList
{
  std::string Material;
  std::vector<size_t> FaceStarts{ 0 }; // face f is corners FaceStarts[f] to FaceStarts[f + 1]
  std::vector<int> FaceLines;
  std::vector<long long> Vertices;
  std::vector<long long> Normals;
};

// How many faces were skipped for one reason, and the line of the first.
struct SkippedFaces
{
  long long Count = 0;
  int FirstLine = 0;
  void Add(int line) { this->FirstLine = this->Count++ ? this->FirstLine : line; }
};

// The geometry of an OBJ file: vertices, normals and each material's faces,
// in the order the materials are first used (faces before any usemtl:
// material "").
struct Geometry
{
  std::vector<float> Vertices; // x, y, z
  std::vector<float> Normals;  // x, y, z
  std::vector<FaceList> Lists;
  std::map<std::string, size_t> ListOfMaterial;
  size_t Current = 0; // the list of the last usemtl
  std::vector<std::string> Libraries;
  SkippedFaces Malformed;

  long long VertexCount() const { return static_cast<long long>(this->Vertices.size() / 3); }
  long long NormalCount() const { return static_cast<long long>(this->Normals.size() / 3); }
  void UseMaterial(const std::string& material)
  {
    auto it = this->ListOfMaterial.find(material);
    if (it == this->ListOfMaterial.end())
    {
      it = this->ListOfMaterial.emplace(material, this->Lists.size()).first;
      this->Lists.emplace_back();
      this->Lists.back().Material = material;
    }
    this->Current = it->second;
  }
};

// "v x y z [w | r g b]", "vn x y z": appends x, y, z to `target`.
bool ParseVector(const std::vector<std::string>& words, std::vector<float>& target)
{
  double xyz[3];
  if (words.size() < 4 || !ParseDouble(words[1], xyz[0]) || !ParseDouble(words[2], xyz[1]) ||
    !ParseDouble(words[3], xyz[2]))
  {
    return false;
  }
  target.insert(target.end(),
    { static_cast<float>(xyz[0]), static_cast<float>(xyz[1]), static_cast<float>(xyz[2]) });
  return true;
}

// "f v v v ...", each corner v, v/t, v/t/n or v//n: appended to the current
// material's faces, or counted as malformed.
void ParseFace(const std::vector<std::string>& words, int lineNumber, Geometry& geometry)
{
  FaceList& list = geometry.Lists[geometry.Current];
  const long long vertexCount = geometry.VertexCount();
  const long long normalCount = geometry.NormalCount();
  std::vector<std::string> parts;
  bool ok = words.size() >= 4;
  for (size_t w = 1; ok && w < words.size(); ++w)
  {
    parts.clear();
    size_t start = 0;
    for (size_t slash; (slash = words[w].find('/', start)) != std::string::npos; start = slash + 1)
    {
      parts.push_back(words[w].substr(start, slash - start));
    }
    parts.push_back(words[w].substr(start));
    const long long v = ResolveIndex(parts[0], vertexCount);
    long long n = -1;
    if (parts.size() > 3 || v < 0)
    {
      ok = false;
    }
    else if (parts.size() == 3 && !parts[2].empty())
    {
      // An unusable normal index costs the normal, not the face.
      n = ResolveIndex(parts[2], normalCount);
    }
    list.Vertices.push_back(v);
    list.Normals.push_back(n);
  }
  if (ok)
  {
    list.FaceStarts.push_back(list.Vertices.size());
    list.FaceLines.push_back(lineNumber);
  }
  else
  {
    list.Vertices.resize(list.FaceStarts.back());
    list.Normals.resize(list.FaceStarts.back());
    geometry.Malformed.Add(lineNumber);
  }
}

// Reads the vertices, normals, faces, materials used and material libraries
// of the OBJ file `path`. Returns why the file cannot be read, or "".
std::string ReadGeometry(const std::string& path, Geometry& geometry)
{
  vtksys::ifstream in(path.c_str());
  if (!in)
  {
    return "Cannot open OBJ " + path;
  }
  geometry.UseMaterial("");
  LogicalLineReader reader(in);
  std::string line;
  int lineNumber = 0;
  while (reader.Next(line, lineNumber))
  {
    const std::vector<std::string> words = Words(line);
    if (words.empty())
    {
      continue;
    }
    const std::string& command = words[0];
    if (command == "v" || command == "vn")
    {
      if (!ParseVector(words, command == "v" ? geometry.Vertices : geometry.Normals))
      {
        std::ostringstream message;
        message << "Cannot read OBJ " << path << ": malformed '" << command << "' at line "
                << lineNumber;
        return message.str();
      }
    }
    else if (command == "f")
    {
      ParseFace(words, lineNumber, geometry);
    }
    else if (command == "usemtl")
    {
      geometry.UseMaterial(Rest(line));
    }
    else if (command == "mtllib")
    {
      geometry.Libraries.push_back(Rest(line));
    }
    // vt, p, l, g, o, s and the rest play no part in the surfaces.
  }
  if (reader.TooLong)
  {
    std::ostringstream message;
    message << "Cannot read OBJ " << path << ": line " << lineNumber << " is longer than "
            << vtkDeepGISceneFileChecks::MaximumLineBytes << " bytes";
    return message.str();
  }
  return std::string();
}

// `list` without the faces that index vertices beyond `vertexCount` (counted
// in `skipped`), and without normal indices beyond `normalCount`.
FaceList KeepFacesInRange(
  const FaceList& list, long long vertexCount, long long normalCount, SkippedFaces& skipped)
{
  FaceList kept;
  kept.Material = list.Material;
  for (size_t f = 0; f < list.FaceLines.size(); ++f)
  {
    const size_t b = list.FaceStarts[f], e = list.FaceStarts[f + 1];
    bool ok = true;
    for (size_t c = b; c < e; ++c)
    {
      ok = ok && list.Vertices[c] < vertexCount;
    }
    if (!ok)
    {
      skipped.Add(list.FaceLines[f]);
      continue;
    }
    for (size_t c = b; c < e; ++c)
    {
      kept.Vertices.push_back(list.Vertices[c]);
      kept.Normals.push_back(list.Normals[c] < normalCount ? list.Normals[c] : -1);
    }
    kept.FaceStarts.push_back(kept.Vertices.size());
    kept.FaceLines.push_back(list.FaceLines[f]);
  }
  return kept;
}

// Skips the faces whose corners index vertices that the file does not
// define (positive indices may point forward, so this waits for the end of
// the file). Skipped faces are a warning while faces are left, else the
// error returned.
std::string SkipOutOfRangeFaces(
  const std::string& path, Geometry& geometry, std::vector<std::string>& warnings)
{
  SkippedFaces outOfRange;
  long long faceCount = 0;
  for (FaceList& list : geometry.Lists)
  {
    list = KeepFacesInRange(list, geometry.VertexCount(), geometry.NormalCount(), outOfRange);
    faceCount += static_cast<long long>(list.FaceLines.size());
  }
  const SkippedFaces& malformed = geometry.Malformed;
  if (malformed.Count || outOfRange.Count)
  {
    std::ostringstream message;
    message << "OBJ " << path << ": skipped";
    if (outOfRange.Count)
    {
      message << " " << outOfRange.Count << " face(s) with vertex indices outside the "
              << geometry.VertexCount() << " vertices (first at line " << outOfRange.FirstLine
              << ")";
    }
    if (malformed.Count)
    {
      message << (outOfRange.Count ? " and" : "") << " " << malformed.Count
              << " malformed face(s) (fewer than 3 corners, index 0, a relative index before "
                 "the first vertex or not a number; first at line "
              << malformed.FirstLine << ")";
    }
    if (faceCount == 0)
    {
      return message.str() + ", leaving no faces";
    }
    warnings.push_back(message.str());
  }
  if (faceCount == 0)
  {
    return path + " has no polygons (empty mesh, or points/lines only)";
  }
  return std::string();
}

// The MTL file of the OBJ file `path`: the first `mtllib` that is a regular
// file (a library naming several files tries the whole name, then each),
// else NAME.obj.mtl or NAME.mtl next to it; "" if none is. Libraries that
// exist but are no regular file (devices, directories) are a warning.
std::string FindMaterialFile(const std::string& path, const std::vector<std::string>& libraries,
  std::vector<std::string>& warnings)
{
  const std::string dir = vtksys::SystemTools::GetFilenamePath(path);
  auto inDir = [&](const std::string& name)
  { return (dir.empty() || vtksys::SystemTools::FileIsFullPath(name)) ? name : dir + "/" + name; };
  std::string mtl;
  for (const std::string& library : libraries)
  {
    std::vector<std::string> candidates = { library };
    const std::vector<std::string> names = Words(library); // "mtllib a.mtl b.mtl"
    if (names.size() > 1)
    {
      candidates.insert(candidates.end(), names.begin(), names.end());
    }
    for (const std::string& candidate : candidates)
    {
      if (mtl.empty() && IsRegularFile(inDir(candidate)))
      {
        mtl = inDir(candidate);
      }
      else if (vtksys::SystemTools::FileExists(inDir(candidate)) &&
        !IsRegularFile(inDir(candidate)))
      {
        warnings.push_back("OBJ " + path + ": mtllib " + candidate +
          " is not a regular file (a device or directory?); ignored");
      }
    }
  }
  if (!mtl.empty())
  {
    return mtl;
  }
  const std::string base = vtksys::SystemTools::GetFilenameName(path);
  for (const std::string& candidate :
    { path + ".mtl", inDir(vtksys::SystemTools::GetFilenameWithoutLastExtension(base) + ".mtl") })
  {
    if (IsRegularFile(candidate))
    {
      return candidate;
    }
  }
  return std::string();
}

// The materials of an MTL file: every name, and the diffuse colours (Kd)
// and emitted radiances (Ke) of those that have a usable one.
struct Materials
{
  std::map<std::string, std::array<double, 3>> Kd, Ke;
  std::set<std::string> Names;
};

// "Kd r g b", or "Kd r" for a grey (Ke alike); not "Kd spectral ..." or
// "Kd xyz ...". False for anything else and for non-finite components.
bool ParseColor(const std::vector<std::string>& words, std::array<double, 3>& rgb)
{
  bool ok = false;
  if (words.size() == 4)
  {
    ok = ParseDouble(words[1], rgb[0]) && ParseDouble(words[2], rgb[1]) &&
      ParseDouble(words[3], rgb[2]);
  }
  else if (words.size() == 2 && ParseDouble(words[1], rgb[0]))
  {
    rgb[1] = rgb[2] = rgb[0];
    ok = true;
  }
  return ok && std::isfinite(rgb[0]) && std::isfinite(rgb[1]) && std::isfinite(rgb[2]);
}

// Reads the MTL file `path`; false when it is larger than
// MaximumTextFileBytes, cannot be opened or has a line that is too long.
bool ReadMaterials(const std::string& path, Materials& materials)
{
  std::uint64_t bytes = 0;
  vtksys::ifstream in(path.c_str());
  if (!vtkDeepGISceneFileChecks::RegularFileSize(path, bytes) ||
    bytes > vtkDeepGISceneFileChecks::MaximumTextFileBytes || !in)
  {
    return false;
  }
  LogicalLineReader reader(in);
  std::string line, current;
  int lineNumber = 0;
  while (reader.Next(line, lineNumber))
  {
    const std::vector<std::string> words = Words(line);
    if (words.empty())
    {
      continue;
    }
    if (words[0] == "newmtl")
    {
      current = Rest(line);
      materials.Names.insert(current);
    }
    else if ((words[0] == "Kd" || words[0] == "Ke") && !current.empty())
    {
      std::array<double, 3> rgb = { 0.0, 0.0, 0.0 };
      if (ParseColor(words, rgb))
      {
        (words[0] == "Kd" ? materials.Kd : materials.Ke)[current] = rgb;
      }
    }
  }
  return !reader.TooLong;
}

// Without materials the file is one part: every list's faces appended to
// the first list's (material "").
void MergeFaceLists(std::vector<FaceList>& lists)
{
  FaceList& all = lists[0];
  for (size_t l = 1; l < lists.size(); ++l)
  {
    const size_t offset = all.Vertices.size();
    for (size_t f = 1; f < lists[l].FaceStarts.size(); ++f)
    {
      all.FaceStarts.push_back(offset + lists[l].FaceStarts[f]);
    }
    all.FaceLines.insert(all.FaceLines.end(), lists[l].FaceLines.begin(), lists[l].FaceLines.end());
    all.Vertices.insert(all.Vertices.end(), lists[l].Vertices.begin(), lists[l].Vertices.end());
    all.Normals.insert(all.Normals.end(), lists[l].Normals.begin(), lists[l].Normals.end());
  }
  lists.resize(1);
}

// Whether every corner of `list` has a finite, non-zero normal.
bool HasUsableNormals(const FaceList& list, const std::vector<float>& normals)
{
  for (long long n : list.Normals)
  {
    const float* normal = n >= 0 ? &normals[3 * n] : nullptr;
    if (!normal || !std::isfinite(normal[0]) || !std::isfinite(normal[1]) ||
      !std::isfinite(normal[2]) || (normal[0] == 0.0f && normal[1] == 0.0f && normal[2] == 0.0f))
    {
      return false;
    }
  }
  return true;
}

// The output being built: every material's points, normals and faces.
struct Surface
{
  vtkNew<vtkPoints> Points;
  vtkNew<vtkFloatArray> Normals;
  vtkNew<vtkCellArray> Polys;
  vtkNew<vtkIntArray> MaterialIds;
};

// Appends the faces of one material, with points of their own (vertex and
// normal pairs where `withNormals`), never merged with other points:
// coincident vertices and faces stay as they are in the file.
void AppendFaces(
  const FaceList& list, const Geometry& geometry, bool withNormals, int material, Surface& surface)
{
  std::unordered_map<unsigned long long, vtkIdType> pointOf;
  std::vector<vtkIdType> ids;
  for (size_t f = 0; f + 1 < list.FaceStarts.size(); ++f)
  {
    ids.clear();
    for (size_t c = list.FaceStarts[f]; c < list.FaceStarts[f + 1]; ++c)
    {
      const long long v = list.Vertices[c];
      const long long n = withNormals ? list.Normals[c] : -1;
      const unsigned long long key =
        (static_cast<unsigned long long>(v) << 32) ^ static_cast<unsigned long long>(n + 1);
      auto inserted = pointOf.emplace(key, surface.Points->GetNumberOfPoints());
      if (inserted.second)
      {
        surface.Points->InsertNextPoint(&geometry.Vertices[3 * v]);
        if (withNormals)
        {
          const float* stored = &geometry.Normals[3 * n];
          double normal[3] = { stored[0], stored[1], stored[2] };
          vtkMath::Normalize(normal);
          surface.Normals->InsertNextTuple(normal);
        }
      }
      ids.push_back(inserted.first->second);
    }
    surface.Polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    surface.MaterialIds->InsertNextValue(material);
  }
}

// The output's field data: one tuple per material.
class MaterialTable
{
public:
  MaterialTable()
  {
    this->Name->SetName("MaterialName");
    this->Kd->SetName("MaterialKd");
    this->Kd->SetNumberOfComponents(3);
    this->HasKd->SetName("MaterialHasKd");
    this->Ke->SetName("MaterialKe");
    this->Ke->SetNumberOfComponents(3);
    this->Defined->SetName("MaterialDefined");
  }

  // The Kd and Ke of `material` in `materials` (none: no MTL file).
  void Add(const std::string& material, const Materials* materials)
  {
    std::array<double, 3> kd = { 0.0, 0.0, 0.0 }, ke = { 0.0, 0.0, 0.0 };
    const bool hasKd = materials && materials->Kd.count(material);
    if (hasKd)
    {
      kd = materials->Kd.at(material);
    }
    if (materials && materials->Ke.count(material))
    {
      // Negative radiance is meaningless; such a Ke emits nothing.
      for (int c = 0; c < 3; ++c)
      {
        ke[c] = std::max(0.0, materials->Ke.at(material)[c]);
      }
    }
    // Faces without a material, and every face when there is no MTL file,
    // have nothing to look up: only a named material can be missing.
    const bool defined = !materials || material.empty() || materials->Names.count(material);
    this->Name->InsertNextValue(material);
    this->Kd->InsertNextTuple(kd.data());
    this->HasKd->InsertNextValue(hasKd ? 1 : 0);
    this->Ke->InsertNextTuple(ke.data());
    this->Defined->InsertNextValue(defined ? 1 : 0);
  }

  void AddTo(vtkFieldData* fieldData, const std::string& materialFile)
  {
    vtkNew<vtkStringArray> file;
    file->SetName("MaterialFile");
    file->InsertNextValue(materialFile);
    for (vtkAbstractArray* array : { static_cast<vtkAbstractArray*>(this->Name), //
           static_cast<vtkAbstractArray*>(this->Kd), static_cast<vtkAbstractArray*>(this->HasKd),
           static_cast<vtkAbstractArray*>(this->Ke), static_cast<vtkAbstractArray*>(this->Defined),
           static_cast<vtkAbstractArray*>(file) })
    {
      fieldData->AddArray(array);
    }
  }

private:
  vtkNew<vtkStringArray> Name;
  vtkNew<vtkDoubleArray> Kd, Ke;
  vtkNew<vtkUnsignedCharArray> HasKd, Defined;
};

// The MTL file of the OBJ file `path`, read into `materials`; "" when there
// is none or it cannot be read (a warning), and then the faces of all
// materials are one list.
std::string ReadMaterialFile(const std::string& path, Geometry& geometry, Materials& materials,
  std::vector<std::string>& warnings)
{
  std::string file = FindMaterialFile(path, geometry.Libraries, warnings);
  if (!file.empty() && !ReadMaterials(file, materials))
  {
    warnings.push_back("Cannot read the materials " + file + " of " + path +
      " (larger than 64 MiB or a line longer than 1 MiB); the parts get the default colour");
    file.clear();
  }
  if (file.empty())
  {
    MergeFaceLists(geometry.Lists);
  }
  return file;
}

// The output: one material per list with faces.
void MakeOutput(const Geometry& geometry, const Materials* materials,
  const std::string& materialFile, vtkPolyData* output)
{
  bool withNormals = true;
  for (const FaceList& list : geometry.Lists)
  {
    withNormals = withNormals && HasUsableNormals(list, geometry.Normals);
  }
  Surface surface;
  surface.Normals->SetName("Normals");
  surface.Normals->SetNumberOfComponents(3);
  surface.MaterialIds->SetName("MaterialId");
  MaterialTable table;
  int material = 0;
  for (const FaceList& list : geometry.Lists)
  {
    if (!list.FaceLines.empty())
    {
      AppendFaces(list, geometry, withNormals, material++, surface);
      table.Add(list.Material, materials);
    }
  }
  output->SetPoints(surface.Points);
  output->SetPolys(surface.Polys);
  output->GetCellData()->AddArray(surface.MaterialIds);
  if (withNormals)
  {
    output->GetPointData()->SetNormals(surface.Normals);
  }
  table.AddTo(output->GetFieldData(), materialFile);
}

// Reads the OBJ file `path` (and its MTL file) into `output`. Returns "" on
// success, else one sentence saying why it cannot be read.
std::string Read(const std::string& path, vtkPolyData* output, std::vector<std::string>& warnings)
{
  if (!IsRegularFile(path))
  {
    return "Cannot open OBJ " + path + " (missing, or not a regular file)";
  }
  Geometry geometry;
  std::string error = ReadGeometry(path, geometry);
  if (error.empty())
  {
    error = SkipOutOfRangeFaces(path, geometry, warnings);
  }
  if (!error.empty())
  {
    return error;
  }
  Materials materials;
  const std::string materialFile = ReadMaterialFile(path, geometry, materials, warnings);
  MakeOutput(geometry, materialFile.empty() ? nullptr : &materials, materialFile, output);
  return std::string();
}
} // anonymous namespace

//------------------------------------------------------------------------------
vtkDeepGIOBJReader::vtkDeepGIOBJReader()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkDeepGIOBJReader::~vtkDeepGIOBJReader()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
int vtkDeepGIOBJReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  const std::string path = this->FileName ? this->FileName : "";
  std::vector<std::string> warnings;
  std::string error = path.empty() ? "No OBJ file name given" : "";
  // A file may declare more than memory holds: an error of this read, not
  // the end of the process.
  try
  {
    error = error.empty() ? Read(path, output, warnings) : error;
  }
  catch (const std::bad_alloc&)
  {
    error = "Out of memory reading OBJ " + path;
  }
  catch (const std::length_error&)
  {
    error = "OBJ " + path + " declares more data than fits";
  }
  this->SetErrorCode(error.empty() ? vtkErrorCode::NoError : vtkErrorCode::FileFormatError);
  if (!error.empty())
  {
    output->Initialize();
    vtkErrorMacro(<< error);
    return 1;
  }
  for (const std::string& warning : warnings)
  {
    vtkWarningMacro(<< warning);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkDeepGIOBJReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
