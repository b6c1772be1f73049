#include "vtkDeepGBufferSceneLoader.h"

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkAppendPolyData.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCleanPolyData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDeepGIKeys.h"
#include "vtkDeepGISceneFileChecks.h"
#include "vtkDeepGISceneLegacyVTK.h"
#include "vtkDeepGISceneNrrd.h"
#include "vtkDeepGISceneOBJ.h"
#include "vtkDeepGISceneText.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkFlyingEdges3D.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkIntArray.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkMetaImageReader.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPLYReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSTLReader.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume16Reader.h"
#include "vtkXMLImageDataReader.h"
#include "vtkXMLPolyDataReader.h"

#include <vtksys/Directory.hxx>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

vtkStandardNewMacro(vtkDeepGBufferSceneLoader);

namespace
{
using vtkDeepGISceneText::Lower;

// The lighting coefficients of every actor made here (VTK's Ambient and
// Diffuse); the scene polydata carries the diffuse one as field data.
constexpr double MaterialAmbient = 0.1;
constexpr double MaterialDiffuse = 0.9;

struct Part
{
  std::string Name;
  double Color[3];
  double Emission[3] = { 0.0, 0.0, 0.0 }; // MTL Ke, radiance
  vtkSmartPointer<vtkPolyData> PolyData;
};

// Collects the error messages of a reader instead of printing them, so that
// the loader reports one clear error of its own.
class ErrorCollector : public vtkCommand
{
public:
  static ErrorCollector* New() { return new ErrorCollector; }
  void Execute(vtkObject*, unsigned long, void* callData) override
  {
    std::string message = callData ? static_cast<const char*>(callData) : "";
    // Keep the text after "ERROR: In FILE, line N\n".
    const size_t newline = message.find('\n');
    if ((message.compare(0, 6, "ERROR:") == 0 || message.compare(0, 8, "Warning:") == 0) &&
      newline != std::string::npos)
    {
      message = message.substr(newline + 1);
    }
    while (!message.empty() && std::isspace(static_cast<unsigned char>(message.back())))
    {
      message.pop_back();
    }
    if (!message.empty())
    {
      this->Messages += (this->Messages.empty() ? "" : "; ") + message;
    }
  }
  void Watch(vtkObject* object) { object->AddObserver(vtkCommand::ErrorEvent, this); }
  // Warnings too, for readers whose warnings mean lost data (vtkSTLReader
  // guessing the file type, vtkPLYReader failing to open the file).
  void WatchAll(vtkObject* object)
  {
    this->Watch(object);
    object->AddObserver(vtkCommand::WarningEvent, this);
  }
  std::string Messages;
};

// Records the messages VTK sends to its output window (generic warnings
// such as vtkDataReader's "Error reading binary data!" have no object to
// observe) while it is installed, then puts the previous window back.
class OutputTrap : public vtkOutputWindow
{
public:
  static OutputTrap* New() { return new OutputTrap; }
  void DisplayErrorText(const char* text) override { this->Add(text); }
  void DisplayWarningText(const char* text) override { this->Add(text); }
  void DisplayGenericWarningText(const char* text) override { this->Add(text); }
  void DisplayText(const char*) override {}
  void DisplayDebugText(const char*) override {}
  void Add(const char* text)
  {
    std::string message = text ? text : "";
    const size_t newline = message.find('\n');
    message = newline == std::string::npos ? message : message.substr(newline + 1);
    while (!message.empty() && std::isspace(static_cast<unsigned char>(message.back())))
    {
      message.pop_back();
    }
    if (!message.empty() && this->Messages.find(message) == std::string::npos)
    {
      this->Messages += (this->Messages.empty() ? "" : "; ") + message;
    }
  }
  std::string Messages;
};

class ScopedOutputTrap
{
public:
  ScopedOutputTrap()
    : Previous(vtkOutputWindow::GetInstance())
  {
    vtkOutputWindow::SetInstance(this->Trap);
  }
  ~ScopedOutputTrap() { vtkOutputWindow::SetInstance(this->Previous); }
  const std::string& Messages() const { return this->Trap->Messages; }

private:
  vtkSmartPointer<vtkOutputWindow> Previous;
  vtkNew<OutputTrap> Trap;
};

std::string Extension(const std::string& path)
{
  return Lower(vtksys::SystemTools::GetFilenameLastExtension(path));
}

bool IsVolumeExtension(const std::string& ext)
{
  return ext == ".vti" || ext == ".mhd" || ext == ".mha" || ext == ".nhdr" || ext == ".nrrd";
}

// Only regular files are read: a device (/dev/zero, /dev/urandom), FIFO or
// directory would make a parser read forever or fail obscurely.
bool IsRegularFile(const std::string& path)
{
  return vtkDeepGISceneFileChecks::IsRegularFile(path);
}

// Marks the points with a NaN or infinite coordinate; returns how many.
vtkIdType MarkNonFinitePoints(vtkPoints* points, std::vector<char>& nonFinite)
{
  const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  nonFinite.assign(static_cast<size_t>(n), 0);
  vtkIdType count = 0;
  double p[3];
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      nonFinite[static_cast<size_t>(i)] = 1;
      ++count;
    }
  }
  return count;
}

bool AllFinite(vtkDataArray* array)
{
  const vtkIdType n = array->GetNumberOfValues();
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (!std::isfinite(array->GetVariantValue(i).ToDouble()))
    {
      return false;
    }
  }
  return true;
}

// Whether a cell array's offsets start at 0, never decrease and end at the
// connectivity's size: a corrupt file can make a reader (vtkPolyDataReader)
// produce offsets past the connectivity, which any walk over the cells
// would read beyond.
bool IsConsistent(vtkCellArray* cells)
{
  if (!cells)
  {
    return true;
  }
  vtkDataArray* offsets = cells->GetOffsetsArray();
  vtkDataArray* connectivity = cells->GetConnectivityArray();
  const vtkIdType n = offsets ? offsets->GetNumberOfValues() : 0;
  if (n == 0 || !connectivity)
  {
    return connectivity == nullptr || connectivity->GetNumberOfValues() == 0;
  }
  double previous = 0.0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double o = offsets->GetComponent(i, 0);
    if ((i == 0 && o != 0.0) || o < previous)
    {
      return false;
    }
    previous = o;
  }
  return previous == static_cast<double>(connectivity->GetNumberOfValues());
}

// Keeps the cells whose point ids exist and whose points are finite,
// counting the others.
struct CellFilter
{
  vtkIdType NumberOfPoints = 0;
  std::vector<char> NonFinite; // per point
  vtkIdType OutOfRange = 0;
  vtkIdType WithNonFinite = 0;

  // 0: usable, 1: an id outside the points, 2: a non-finite point.
  int Check(vtkIdType n, const vtkIdType* ids) const
  {
    int why = 0;
    for (vtkIdType i = 0; i < n && why != 1; ++i)
    {
      why = (ids[i] < 0 || ids[i] >= this->NumberOfPoints) ? 1
        : this->NonFinite[static_cast<size_t>(ids[i])]     ? 2
                                                           : why;
    }
    return why;
  }

  vtkSmartPointer<vtkCellArray> Apply(vtkCellArray* cells)
  {
    if (!cells || cells->GetNumberOfCells() == 0)
    {
      return nullptr;
    }
    vtkIdType n;
    const vtkIdType* ids;
    auto kept = vtkSmartPointer<vtkCellArray>::New();
    vtkIdType bad = 0;
    auto it = vtk::TakeSmartPointer(cells->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      it->GetCurrentCell(n, ids);
      const int why = this->Check(n, ids);
      this->OutOfRange += why == 1 ? 1 : 0;
      this->WithNonFinite += why == 2 ? 1 : 0;
      bad += why ? 1 : 0;
      if (!why)
      {
        kept->InsertNextCell(n, ids);
      }
    }
    if (bad == 0)
    {
      return cells;
    }
    return kept->GetNumberOfCells() ? kept : nullptr;
  }
};

// The point ids of a triangle, sorted: equal for coincident triangles.
struct TriangleKey
{
  vtkIdType Ids[3];
  bool operator==(const TriangleKey& o) const
  {
    return Ids[0] == o.Ids[0] && Ids[1] == o.Ids[1] && Ids[2] == o.Ids[2];
  }
};

struct TriangleKeyHash
{
  size_t operator()(const TriangleKey& k) const
  {
    std::hash<vtkIdType> h;
    return h(k.Ids[0]) ^ (h(k.Ids[1]) * 0x9e3779b97f4a7c15ULL) ^
      (h(k.Ids[2]) * 0xc2b2ae3d27d4eb4fULL);
  }
};

// Point normals of a triangle mesh (vtkPolyDataNormals, split at
// `featureAngle`, consistent winding). Its consistency walk costs cubic time
// in the number of exactly coincident triangles sharing edges (2,000 copies
// of one face: 43 s), so the normals are computed with each such set once,
// and every copy then takes the triangle (winding and points, hence
// normals) of its first instance: the output has every triangle of the
// input, in the input's order.
vtkSmartPointer<vtkPolyData> ComputePointNormals(vtkPolyData* mesh, double featureAngle)
{
  std::unordered_map<TriangleKey, vtkIdType, TriangleKeyHash> firstOf;
  std::vector<vtkIdType> uniqueOf; // per input triangle: its cell in `unique`
  vtkNew<vtkCellArray> unique;
  vtkIdType n;
  const vtkIdType* ids;
  auto it = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    it->GetCurrentCell(n, ids);
    TriangleKey key = { { ids[0], n > 1 ? ids[1] : ids[0], n > 2 ? ids[2] : ids[0] } };
    std::sort(key.Ids, key.Ids + 3);
    auto inserted = firstOf.emplace(key, unique->GetNumberOfCells());
    if (inserted.second || n != 3)
    {
      uniqueOf.push_back(unique->InsertNextCell(n, ids));
      continue;
    }
    uniqueOf.push_back(inserted.first->second);
  }
  vtkNew<vtkPolyData> once;
  once->SetPoints(mesh->GetPoints());
  once->SetPolys(unique);
  vtkNew<vtkPolyDataNormals> computer;
  computer->SetInputData(once);
  computer->SetFeatureAngle(featureAngle);
  computer->SplittingOn();
  computer->ConsistencyOn();
  computer->AutoOrientNormalsOff();
  computer->ComputePointNormalsOn();
  computer->ComputeCellNormalsOff();
  computer->Update();
  auto withNormals = vtkSmartPointer<vtkPolyData>::New();
  withNormals->ShallowCopy(computer->GetOutput());
  vtkCellArray* computed = withNormals->GetPolys();
  if (static_cast<vtkIdType>(uniqueOf.size()) == unique->GetNumberOfCells() ||
    computed->GetNumberOfCells() != unique->GetNumberOfCells())
  {
    return withNormals; // no coincident triangles
  }
  vtkNew<vtkCellArray> all;
  vtkNew<vtkIdList> cell;
  for (vtkIdType c : uniqueOf)
  {
    computed->GetCellAtId(c, cell);
    all->InsertNextCell(cell);
  }
  withNormals->SetPolys(all);
  return withNormals;
}
} // anonymous namespace

class vtkDeepGBufferSceneLoader::vtkInternals
{
public:
  std::vector<Part> Parts;
  vtkSmartPointer<vtkPolyData> Scene;
};

//------------------------------------------------------------------------------
vtkDeepGBufferSceneLoader::vtkDeepGBufferSceneLoader()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkDeepGBufferSceneLoader::~vtkDeepGBufferSceneLoader() = default;

//------------------------------------------------------------------------------
void vtkDeepGBufferSceneLoader::Clear()
{
  this->Internals->Parts.clear();
  this->Internals->Scene = nullptr;
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkDeepGBufferSceneLoader::IsVolumePath(const char* path)
{
  if (!path || !*path)
  {
    return false;
  }
  const std::string p = path;
  if (IsVolumeExtension(Extension(p)) || vtksys::SystemTools::FileIsDirectory(p))
  {
    return true;
  }
  // A slice-series prefix.
  return !vtksys::SystemTools::FileExists(p) &&
    (IsRegularFile(p + ".nhdr") || IsRegularFile(p + ".1"));
}

//------------------------------------------------------------------------------
bool vtkDeepGBufferSceneLoader::Load(const char* path)
{
  return this->Guarded("Load", path, [&]() { return this->LoadUnguarded(path); });
}

//------------------------------------------------------------------------------
bool vtkDeepGBufferSceneLoader::LoadUnguarded(const char* path)
{
  if (!path || !*path)
  {
    vtkErrorMacro("Load: no file name given");
    return false;
  }
  if (IsVolumePath(path))
  {
    return this->LoadVolumeUnguarded(path, this->IsoValue);
  }
  return this->LoadMeshUnguarded(path);
}

//------------------------------------------------------------------------------
bool vtkDeepGBufferSceneLoader::LoadMesh(const char* fileName)
{
  return this->Guarded("LoadMesh", fileName, [&]() { return this->LoadMeshUnguarded(fileName); });
}

//------------------------------------------------------------------------------
bool vtkDeepGBufferSceneLoader::LoadMeshUnguarded(const char* fileName)
{
  if (!fileName || !*fileName)
  {
    vtkErrorMacro("LoadMesh: no file name given");
    return false;
  }
  const std::string path = fileName;
  if (!vtksys::SystemTools::FileExists(path))
  {
    vtkErrorMacro("Mesh file not found: " << path);
    return false;
  }
  if (!IsRegularFile(path))
  {
    vtkErrorMacro("Not a mesh file (a directory?): " << path);
    return false;
  }
  const std::string ext = Extension(path);
  if (ext == ".obj")
  {
    return this->LoadOBJ(fileName);
  }
  if (ext == ".vtk")
  {
    // The project's own parser, not vtkPolyDataReader (see vtkDeepGISceneLegacyVTK.h).
    vtkNew<vtkPolyData> legacy;
    const std::string why = vtkDeepGISceneLegacyVTK::Read(path, legacy);
    if (!why.empty())
    {
      vtkErrorMacro("Cannot read mesh " << path << ": " << why);
      return false;
    }
    vtkSmartPointer<vtkPolyData> mesh = this->PrepareMesh(legacy, fileName);
    return mesh &&
      this->AddPart(mesh, vtksys::SystemTools::GetFilenameName(path).c_str(), this->DefaultColor);
  }

  vtkSmartPointer<vtkAlgorithm> reader;
  std::string invalid; // why a file is refused before VTK's reader sees it
  if (ext == ".ply")
  {
    invalid = vtkDeepGISceneFileChecks::CheckPLY(path);
    auto r = vtkSmartPointer<vtkPLYReader>::New();
    r->SetFileName(fileName);
    reader = r;
  }
  else if (ext == ".stl")
  {
    invalid = vtkDeepGISceneFileChecks::CheckSTL(path);
    auto r = vtkSmartPointer<vtkSTLReader>::New();
    r->SetFileName(fileName);
    reader = r;
  }
  else if (ext == ".vtp")
  {
    auto r = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    r->SetFileName(fileName);
    reader = r;
  }
  else if (IsVolumeExtension(ext))
  {
    vtkErrorMacro("" << path << " is a volume; load it with LoadVolume (or Load) and an iso-value");
    return false;
  }
  else
  {
    vtkErrorMacro("Unknown mesh file extension \"" << ext << "\" of " << path
                                                   << " (known: .ply .obj .vtp .vtk .stl)");
    return false;
  }

  if (!invalid.empty())
  {
    vtkErrorMacro("Cannot read mesh " << path << ": " << invalid);
    return false;
  }

  // Warnings of these readers mean lost data (vtkSTLReader guessing a binary
  // file, vtkPLYReader missing properties); the XML reader's do not.
  vtkNew<ErrorCollector> errors;
  if (ext == ".vtp")
  {
    errors->Watch(reader);
  }
  else
  {
    errors->WatchAll(reader);
  }
  errors->Watch(reader->GetExecutive());
  {
    ScopedOutputTrap trap;
    reader->Update();
    errors->Messages = errors->Messages.empty() ? trap.Messages() : errors->Messages;
    if (!errors->Messages.empty() && ext != ".vtp")
    {
      errors->Messages += " (the file is truncated or corrupt)";
    }
  }
  vtkPolyData* output = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!errors->Messages.empty() || !output)
  {
    vtkErrorMacro("Cannot read mesh "
      << path << ": " << (errors->Messages.empty() ? std::string("no output") : errors->Messages));
    return false;
  }
  vtkSmartPointer<vtkPolyData> mesh = this->PrepareMesh(output, fileName);
  if (!mesh)
  {
    return false;
  }
  return this->AddPart(
    mesh, vtksys::SystemTools::GetFilenameName(path).c_str(), this->DefaultColor);
}

//------------------------------------------------------------------------------
bool vtkDeepGBufferSceneLoader::LoadOBJ(const char* fileName)
{
  // The project's own parser, not vtkOBJImporter or vtkOBJReader (see
  // vtkDeepGISceneOBJ.h). It hands its messages back, so that they are this
  // loader's like those of every other format.
  const std::string path = fileName;
  vtkDeepGISceneOBJ::Scene obj;
  const std::string error = vtkDeepGISceneOBJ::Read(path, obj);
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
    return false;
  }
  for (const std::string& warning : obj.Warnings)
  {
    vtkWarningMacro(<< warning);
  }

  // One part per material group that PrepareMesh keeps.
  const std::string base = vtksys::SystemTools::GetFilenameName(path);
  std::vector<Part> parts;
  std::string unknownMaterials;
  for (const vtkDeepGISceneOBJ::Group& group : obj.Groups)
  {
    Part part;
    part.Name = group.Material.empty() ? base : base + ":" + group.Material;
    const double* color = group.HasColor ? group.Color : this->DefaultColor;
    std::copy(color, color + 3, part.Color);
    std::copy(group.Emission, group.Emission + 3, part.Emission);
    if (group.Unknown)
    {
      unknownMaterials += (unknownMaterials.empty() ? "" : ", ") + group.Material;
    }
    part.PolyData = this->PrepareMesh(group.PolyData, (path + " " + part.Name).c_str());
    if (part.PolyData)
    {
      parts.push_back(part);
    }
  }
  if (parts.empty())
  {
    return false; // PrepareMesh reported why
  }
  if (!unknownMaterials.empty())
  {
    vtkWarningMacro("OBJ " << path << " uses materials missing from " << obj.MaterialFile << " ("
                           << unknownMaterials << "); they get the default colour");
  }
  for (const Part& part : parts)
  {
    this->AddPart(part.PolyData, part.Name.c_str(), part.Color);
    std::copy(part.Emission, part.Emission + 3, this->Internals->Parts.back().Emission);
  }
  return true;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkDeepGBufferSceneLoader::PrepareMesh(
  vtkPolyData* input, const char* what)
{
  if (!input || input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    vtkErrorMacro("" << what << " has no polygons (empty mesh, or points/lines only)");
    return nullptr;
  }
  // Only what is used below (points, polygons, strips, point normals), and
  // only cells whose point ids exist and whose points are finite: not every
  // reader checks ids (the filters below would read out of bounds), and one
  // NaN or infinite point makes the bounds, the camera and the image wrong.
  if (!IsConsistent(input->GetPolys()) || !IsConsistent(input->GetStrips()))
  {
    vtkErrorMacro("" << what << " has corrupt polygons (cell offsets beyond its point ids)");
    return nullptr;
  }
  vtkPoints* inputPoints = input->GetPoints();
  const vtkIdType numberOfPoints = inputPoints ? inputPoints->GetNumberOfPoints() : 0;
  CellFilter filter;
  filter.NumberOfPoints = numberOfPoints;
  const vtkIdType nonFinite = MarkNonFinitePoints(inputPoints, filter.NonFinite);
  vtkSmartPointer<vtkCellArray> polys = filter.Apply(input->GetPolys());
  vtkSmartPointer<vtkCellArray> strips = filter.Apply(input->GetStrips());
  if (!polys && !strips)
  {
    vtkErrorMacro("" << what << " has no polygons whose point ids are within its " << numberOfPoints
                     << " points and whose points are finite");
    return nullptr;
  }
  if (filter.OutOfRange)
  {
    vtkWarningMacro("" << what << ": skipped " << filter.OutOfRange
                       << " polygon(s) with point ids outside its " << numberOfPoints << " points");
  }
  if (nonFinite)
  {
    vtkWarningMacro("" << what << ": dropped " << nonFinite
                       << " point(s) with non-finite (NaN or infinite) coordinates and the "
                       << filter.WithNonFinite << " polygon(s) using them");
  }
  vtkNew<vtkPolyData> checked;
  checked->SetPoints(inputPoints);
  checked->SetPolys(polys);
  checked->SetStrips(strips);
  vtkDataArray* inputNormals = input->GetPointData()->GetNormals();
  if (inputNormals && inputNormals->GetNumberOfComponents() == 3 &&
    inputNormals->GetNumberOfTuples() == numberOfPoints && AllFinite(inputNormals))
  {
    checked->GetPointData()->SetNormals(inputNormals);
  }

  // Drop unused points without merging any (coincident duplicates stay, as
  // in the data), then triangles only.
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputData(checked);
  clean->PointMergingOff();
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(clean->GetOutputPort());
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  triangles->Update();
  vtkPolyData* tri = triangles->GetOutput();
  if (tri->GetNumberOfPolys() == 0)
  {
    vtkErrorMacro("" << what << " has no non-degenerate triangles");
    return nullptr;
  }

  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(tri->GetPoints());
  mesh->SetPolys(tri->GetPolys());
  vtkDataArray* normals = tri->GetPointData()->GetNormals();
  if (normals && normals->GetNumberOfComponents() == 3)
  {
    mesh->GetPointData()->SetNormals(normals);
  }
  else if (this->ComputeNormals)
  {
    return ComputePointNormals(mesh, this->FeatureAngle);
  }
  return mesh;
}

//------------------------------------------------------------------------------
bool vtkDeepGBufferSceneLoader::AddPart(vtkPolyData* mesh, const char* name, const double color[3])
{
  Part part;
  part.Name = name ? name : "";
  for (int i = 0; i < 3; ++i)
  {
    part.Color[i] = color[i];
  }
  part.PolyData = mesh;
  this->Internals->Parts.push_back(part);
  this->Internals->Scene = nullptr;
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkDeepGBufferSceneLoader::LoadVolume(const char* path, double isoValue)
{
  return this->Guarded(
    "LoadVolume", path, [&]() { return this->LoadVolumeUnguarded(path, isoValue); });
}

//------------------------------------------------------------------------------
bool vtkDeepGBufferSceneLoader::Guarded(
  const char* what, const char* path, const std::function<bool()>& load)
{
  // A file may declare more than memory holds, and not every reader checks:
  // running out of memory is an error of this load, not the end of the process.
  try
  {
    return load();
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro(<< what << ": out of memory reading " << (path ? path : "(null)"));
  }
  catch (const std::length_error&)
  {
    vtkErrorMacro(<< what << ": " << (path ? path : "(null)") << " declares more data than fits");
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkDeepGBufferSceneLoader::LoadVolumeUnguarded(const char* path, double isoValue)
{
  if (!path || !*path)
  {
    vtkErrorMacro("LoadVolume: no path given");
    return false;
  }
  if (!std::isfinite(isoValue))
  {
    vtkErrorMacro("LoadVolume: the iso-value must be finite, got " << isoValue);
    return false;
  }
  vtkNew<vtkImageData> image;
  if (!this->ReadVolume(path, image))
  {
    return false;
  }
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  int dims[3];
  image->GetDimensions(dims);
  if (!scalars || dims[0] < 2 || dims[1] < 2 || dims[2] < 2)
  {
    vtkErrorMacro("Volume " << path << " has no scalars or is not 3D (dimensions " << dims[0]
                            << " x " << dims[1] << " x " << dims[2] << ")");
    return false;
  }
  double range[2];
  scalars->GetRange(range, 0);
  if (!(isoValue > range[0] && isoValue < range[1]))
  {
    vtkErrorMacro("Iso-value " << isoValue << " is outside the data range of " << path << " ["
                               << range[0] << ", " << range[1] << "]: the surface is empty");
    return false;
  }

  vtkNew<vtkFlyingEdges3D> iso;
  iso->SetInputData(image);
  iso->SetValue(0, isoValue);
  iso->SetComputeNormals(this->ComputeNormals);
  iso->ComputeGradientsOff();
  iso->ComputeScalarsOff();
  iso->Update();
  vtkPolyData* surface = iso->GetOutput();
  if (surface->GetNumberOfPolys() == 0)
  {
    vtkErrorMacro("The iso-surface of " << path << " at " << isoValue << " is empty");
    return false;
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(surface->GetPoints());
  mesh->SetPolys(surface->GetPolys());
  if (this->ComputeNormals && surface->GetPointData()->GetNormals())
  {
    mesh->GetPointData()->SetNormals(surface->GetPointData()->GetNormals());
  }
  std::ostringstream name;
  name << vtksys::SystemTools::GetFilenameName(path) << "@" << isoValue;
  return this->AddPart(mesh, name.str().c_str(), this->DefaultColor);
}

//------------------------------------------------------------------------------
bool vtkDeepGBufferSceneLoader::ReadVolume(const char* path, vtkImageData* output)
{
  const std::string p = path;
  if (vtksys::SystemTools::FileIsDirectory(p))
  {
    vtksys::Directory dir;
    if (!dir.Load(p))
    {
      vtkErrorMacro("Cannot list the directory " << p);
      return false;
    }
    std::vector<std::string> headers;
    for (unsigned long i = 0; i < dir.GetNumberOfFiles(); ++i)
    {
      const std::string name = dir.GetFile(i);
      if (IsVolumeExtension(Extension(name)) && IsRegularFile(p + "/" + name))
      {
        headers.push_back(name);
      }
    }
    if (headers.size() != 1)
    {
      vtkErrorMacro("The directory " << p << " holds " << headers.size()
                                     << " volume files (.nhdr .nrrd .mhd .mha .vti); give "
                                        "exactly one file instead");
      return false;
    }
    return this->ReadVolume((p + "/" + headers[0]).c_str(), output);
  }

  if (!vtksys::SystemTools::FileExists(p))
  {
    // A slice-series prefix: PREFIX.nhdr if there is one, else raw slices.
    if (IsRegularFile(p + ".nhdr"))
    {
      return this->ReadVolume((p + ".nhdr").c_str(), output);
    }
    if (!IsRegularFile(p + ".1"))
    {
      vtkErrorMacro("Volume not found: " << p << " (no such file, directory, or slice series " << p
                                         << ".1, " << p << ".2, ...)");
      return false;
    }
    int slices = 1;
    while (slices < 100000 && IsRegularFile(p + "." + std::to_string(slices + 1)))
    {
      ++slices;
    }
    const unsigned long bytes = vtksys::SystemTools::FileLength(p + ".1");
    const int side = static_cast<int>(std::lround(std::sqrt(bytes / 2.0)));
    if (side < 2 || static_cast<unsigned long>(2 * side * side) != bytes)
    {
      vtkErrorMacro("Slice " << p << ".1 has " << bytes
                             << " bytes, not a square 16-bit image; give a .nhdr header");
      return false;
    }
    vtkNew<vtkVolume16Reader> reader;
    reader->SetFilePrefix(path);
    reader->SetDataDimensions(side, side);
    reader->SetImageRange(1, slices);
    reader->SetDataSpacing(this->RawSliceSpacing);
    if (this->RawSliceLittleEndian)
    {
      reader->SetDataByteOrderToLittleEndian();
    }
    else
    {
      reader->SetDataByteOrderToBigEndian();
    }
    vtkNew<ErrorCollector> errors;
    errors->Watch(reader);
    errors->Watch(reader->GetExecutive());
    reader->Update();
    if (!errors->Messages.empty() || reader->GetOutput()->GetNumberOfPoints() == 0)
    {
      vtkErrorMacro("Cannot read the slice series " << p << ": " << errors->Messages);
      return false;
    }
    output->ShallowCopy(reader->GetOutput());
    return true;
  }

  if (!IsRegularFile(p))
  {
    vtkErrorMacro("Not a volume file: " << p);
    return false;
  }
  const std::string ext = Extension(p);
  vtkSmartPointer<vtkAlgorithm> reader;
  if (ext == ".nhdr" || ext == ".nrrd")
  {
    // Never vtkNrrdReader: see vtkDeepGISceneNrrd.h.
    const std::string why = vtkDeepGISceneNrrd::Read(p, output);
    if (!why.empty())
    {
      vtkErrorMacro("Cannot read NRRD " << p << ": " << why);
      return false;
    }
    return true;
  }
  else if (ext == ".vti")
  {
    auto r = vtkSmartPointer<vtkXMLImageDataReader>::New();
    r->SetFileName(path);
    reader = r;
  }
  else if (ext == ".mhd" || ext == ".mha")
  {
    auto r = vtkSmartPointer<vtkMetaImageReader>::New();
    r->SetFileName(path);
    reader = r;
  }
  else
  {
    vtkErrorMacro("Unknown volume file extension \""
      << ext << "\" of " << p << " (known: .vti .mhd .mha .nhdr .nrrd, a directory or a "
      << "slice-series prefix)");
    return false;
  }
  vtkNew<ErrorCollector> errors;
  errors->Watch(reader);
  errors->Watch(reader->GetExecutive());
  reader->Update();
  vtkImageData* image = vtkImageData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!errors->Messages.empty() || !image || image->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro("Cannot read volume "
      << p << ": " << (errors->Messages.empty() ? std::string("no data") : errors->Messages));
    return false;
  }
  output->ShallowCopy(image);
  return true;
}

//------------------------------------------------------------------------------
int vtkDeepGBufferSceneLoader::GetNumberOfParts()
{
  return static_cast<int>(this->Internals->Parts.size());
}

//------------------------------------------------------------------------------
const char* vtkDeepGBufferSceneLoader::GetPartName(int part)
{
  if (part < 0 || part >= this->GetNumberOfParts())
  {
    return nullptr;
  }
  return this->Internals->Parts[part].Name.c_str();
}

//------------------------------------------------------------------------------
void vtkDeepGBufferSceneLoader::GetPartColor(int part, double rgb[3])
{
  const bool valid = part >= 0 && part < this->GetNumberOfParts();
  for (int i = 0; i < 3; ++i)
  {
    rgb[i] = valid ? this->Internals->Parts[part].Color[i] : 0.0;
  }
}

//------------------------------------------------------------------------------
void vtkDeepGBufferSceneLoader::GetPartEmission(int part, double rgb[3])
{
  const bool valid = part >= 0 && part < this->GetNumberOfParts();
  for (int i = 0; i < 3; ++i)
  {
    rgb[i] = valid ? this->Internals->Parts[part].Emission[i] : 0.0;
  }
}

//------------------------------------------------------------------------------
vtkPolyData* vtkDeepGBufferSceneLoader::GetPartPolyData(int part)
{
  if (part < 0 || part >= this->GetNumberOfParts())
  {
    return nullptr;
  }
  return this->Internals->Parts[part].PolyData;
}

//------------------------------------------------------------------------------
vtkIdType vtkDeepGBufferSceneLoader::GetNumberOfTriangles()
{
  vtkIdType n = 0;
  for (const Part& part : this->Internals->Parts)
  {
    n += part.PolyData->GetNumberOfPolys();
  }
  return n;
}

//------------------------------------------------------------------------------
void vtkDeepGBufferSceneLoader::GetBounds(double bounds[6])
{
  vtkMath::UninitializeBounds(bounds);
  bool first = true;
  for (const Part& part : this->Internals->Parts)
  {
    double b[6];
    part.PolyData->GetBounds(b);
    for (int i = 0; i < 3; ++i)
    {
      bounds[2 * i] = first ? b[2 * i] : std::min(bounds[2 * i], b[2 * i]);
      bounds[2 * i + 1] = first ? b[2 * i + 1] : std::max(bounds[2 * i + 1], b[2 * i + 1]);
    }
    first = false;
  }
}

//------------------------------------------------------------------------------
vtkPolyData* vtkDeepGBufferSceneLoader::GetScenePolyData()
{
  if (this->Internals->Parts.empty())
  {
    return nullptr;
  }
  if (!this->Internals->Scene)
  {
    vtkNew<vtkAppendPolyData> append;
    int id = 0;
    bool emitters = false;
    for (const Part& part : this->Internals->Parts)
    {
      emitters = emitters || std::max({ part.Emission[0], part.Emission[1], part.Emission[2] }) > 0;
    }
    for (const Part& part : this->Internals->Parts)
    {
      auto copy = vtkSmartPointer<vtkPolyData>::New();
      copy->ShallowCopy(part.PolyData);
      const vtkIdType n = copy->GetNumberOfCells();
      vtkNew<vtkUnsignedCharArray> colors;
      colors->SetName("Colors");
      colors->SetNumberOfComponents(3);
      colors->SetNumberOfTuples(n);
      unsigned char rgb[3];
      for (int c = 0; c < 3; ++c)
      {
        rgb[c] = static_cast<unsigned char>(
          std::lround(255.0 * vtkMath::ClampValue(part.Color[c], 0.0, 1.0)));
      }
      vtkNew<vtkIntArray> ids;
      ids->SetName("PartId");
      ids->SetNumberOfTuples(n);
      for (vtkIdType i = 0; i < n; ++i)
      {
        colors->SetTypedTuple(i, rgb);
        ids->SetValue(i, id);
      }
      copy->GetCellData()->AddArray(colors);
      copy->GetCellData()->AddArray(ids);
      if (emitters)
      {
        // What Populate draws, for references that light the scene
        // (vtkDeepGIReferenceIrradiance): an emitter's colour Ke / max(Ke)
        // (Ambient 1, EMISSIVE) and its Diffuse 0, the other parts'
        // emission 0 and Diffuse MaterialDiffuse.
        const double brightest = std::max({ part.Emission[0], part.Emission[1], part.Emission[2] });
        float emitted[3] = { 0.0f, 0.0f, 0.0f };
        for (int c = 0; c < 3 && brightest > 0.0; ++c)
        {
          emitted[c] = static_cast<float>(part.Emission[c] / brightest);
        }
        vtkNew<vtkFloatArray> emission;
        emission->SetName("Emission");
        emission->SetNumberOfComponents(3);
        emission->SetNumberOfTuples(n);
        vtkNew<vtkFloatArray> diffuse;
        diffuse->SetName("Diffuse");
        diffuse->SetNumberOfTuples(n);
        for (vtkIdType i = 0; i < n; ++i)
        {
          emission->SetTypedTuple(i, emitted);
          diffuse->SetValue(i, brightest > 0.0 ? 0.0f : static_cast<float>(MaterialDiffuse));
        }
        copy->GetCellData()->AddArray(emission);
        copy->GetCellData()->AddArray(diffuse);
      }
      append->AddInputData(copy);
      ++id;
    }
    append->Update();
    this->Internals->Scene = vtkSmartPointer<vtkPolyData>::New();
    this->Internals->Scene->ShallowCopy(append->GetOutput());
    // The actors' diffuse coefficient, for references that light the scene.
    vtkNew<vtkDoubleArray> diffuse;
    diffuse->SetName("Diffuse");
    diffuse->InsertNextValue(MaterialDiffuse);
    this->Internals->Scene->GetFieldData()->AddArray(diffuse);
  }
  return this->Internals->Scene;
}

//------------------------------------------------------------------------------
int vtkDeepGBufferSceneLoader::Populate(vtkRenderer* renderer)
{
  if (!renderer)
  {
    vtkErrorMacro("Populate: no renderer");
    return 0;
  }
  int added = 0;
  bool emitters = false;
  for (int index = 0; index < this->GetNumberOfParts(); ++index)
  {
    const Part& part = this->Internals->Parts[index];
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(part.PolyData);
    mapper->ScalarVisibilityOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    vtkProperty* property = actor->GetProperty();
    property->SetDiffuseColor(part.Color[0], part.Color[1], part.Color[2]);
    property->SetAmbientColor(part.Color[0], part.Color[1], part.Color[2]);
    property->SetAmbient(MaterialAmbient);
    property->SetDiffuse(MaterialDiffuse);
    property->SetSpecular(0.0);
    property->SetInterpolationToPhong();
    const double brightest = std::max({ part.Emission[0], part.Emission[1], part.Emission[2] });
    if (brightest > 0.0)
    {
      // An emitter (MTL Ke): drawn self-lit, with its colour Ke / max(Ke) as
      // VTK's ambient term (its displayable radiance; Ke itself is usually
      // far above 1), no diffuse or specular term, and marked EMISSIVE so
      // the deep G-buffer keeps that term in the direct radiance B(Y) that
      // vtkDeepRadiosityPass gathers. Its light reaches the scene through
      // the spot light AddEmitterLight puts on it.
      property->SetAmbientColor(
        part.Emission[0] / brightest, part.Emission[1] / brightest, part.Emission[2] / brightest);
      property->SetAmbient(1.0);
      property->SetDiffuse(0.0);
      vtkNew<vtkInformation> keys;
      keys->Set(vtkDeepGIKeys::EMISSIVE(), 1);
      actor->SetPropertyKeys(keys);
      emitters = this->AddEmitterLight(renderer, index) || emitters;
    }
    renderer->AddActor(actor);
    ++added;
  }
  // A scene with its own lamps is lit by them alone.
  if (this->DefaultLight && !emitters)
  {
    this->AddDefaultLight(renderer);
  }
  return added;
}

//------------------------------------------------------------------------------
bool vtkDeepGBufferSceneLoader::AddEmitterLight(vtkRenderer* renderer, int index)
{
  if (!renderer || index < 0 || index >= this->GetNumberOfParts())
  {
    vtkErrorMacro("AddEmitterLight: no renderer or no part " << index);
    return false;
  }
  const Part& part = this->Internals->Parts[index];
  const double brightest = std::max({ part.Emission[0], part.Emission[1], part.Emission[2] });
  vtkPolyData* mesh = part.PolyData;
  vtkPoints* points = mesh ? mesh->GetPoints() : nullptr;
  if (!(brightest > 0.0) || !points || mesh->GetNumberOfPolys() == 0)
  {
    return false;
  }
  // Area, area-weighted centroid and area-weighted normal (from the
  // triangles' winding) of the emitting surface.
  double area = 0.0, centroid[3] = { 0, 0, 0 }, normal[3] = { 0, 0, 0 };
  auto cells = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    cells->GetCurrentCell(n, ids);
    if (n != 3)
    {
      continue; // the parts are triangulated
    }
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      points->GetPoint(ids[k], p[k]);
    }
    double e1[3], e2[3], cross[3];
    vtkMath::Subtract(p[1], p[0], e1);
    vtkMath::Subtract(p[2], p[0], e2);
    vtkMath::Cross(e1, e2, cross);
    const double a = 0.5 * vtkMath::Norm(cross);
    area += a;
    for (int c = 0; c < 3; ++c)
    {
      centroid[c] += a * (p[0][c] + p[1][c] + p[2][c]) / 3.0;
      normal[c] += 0.5 * cross[c];
    }
  }
  if (!(area > 0.0))
  {
    return false;
  }
  for (int c = 0; c < 3; ++c)
  {
    centroid[c] /= area;
  }
  // |sum of a_i n_i| = area for a flat emitter, less for a curved one.
  const double flatness = vtkMath::Normalize(normal) / area;
  double bounds[6];
  this->GetBounds(bounds);
  double diagonal = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    diagonal += (bounds[2 * c + 1] - bounds[2 * c]) * (bounds[2 * c + 1] - bounds[2 * c]);
  }
  diagonal = std::sqrt(diagonal);

  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPositional(true);
  light->SetColor(
    part.Emission[0] / brightest, part.Emission[1] / brightest, part.Emission[2] / brightest);
  // 1 / d^2 falloff, as light from a small area emitter falls off.
  light->SetAttenuationValues(0.0, 0.0, 1.0);
  if (flatness > 0.9)
  {
    // A flat Lambertian emitter of radiance Ke and area A sends the radiant
    // intensity Ke A cos(theta) into its front half-space. VTK's diffuse
    // term has no 1 / pi (radiance = Kd E / pi is written Kd x intensity x
    // cos / d^2), so the intensity is max(Ke) A / pi, and a spot light
    // (exponent 1: the cos(theta) falloff) with a cone just under 90
    // degrees lights that half-space. It sits a hair in front of the
    // emitter, so the surface the emitter lies on is not lit at grazing.
    light->SetIntensity(brightest * area / vtkMath::Pi());
    light->SetConeAngle(89.0);
    light->SetExponent(1.0);
    const double offset = 1e-4 * std::max(diagonal, 1e-12);
    double position[3];
    for (int c = 0; c < 3; ++c)
    {
      position[c] = centroid[c] + offset * normal[c];
    }
    light->SetPosition(position);
    light->SetFocalPoint(position[0] + normal[0], position[1] + normal[1], position[2] + normal[2]);
  }
  else
  {
    // A curved emitter: a point light of the same power (Ke pi A in all
    // directions, i.e. intensity Ke A / 4, / pi in VTK's units).
    light->SetIntensity(brightest * area / (4.0 * vtkMath::Pi()));
    light->SetConeAngle(180.0);
    light->SetPosition(centroid);
    light->SetFocalPoint(centroid[0], centroid[1] - 1.0, centroid[2]);
  }
  renderer->AddLight(light);
  return true;
}

//------------------------------------------------------------------------------
void vtkDeepGBufferSceneLoader::AddDefaultLight(vtkRenderer* renderer)
{
  if (!renderer)
  {
    vtkErrorMacro("AddDefaultLight: no renderer");
    return;
  }
  // Key light in camera coordinates (the camera at (0, 0, 1) looking at the
  // origin): from above left of the viewer, so any model is lit on the side
  // it is seen from.
  vtkNew<vtkLight> key;
  key->SetLightTypeToCameraLight();
  key->SetPositional(false);
  key->SetPosition(-0.4, 0.6, 1.0);
  key->SetFocalPoint(0.0, 0.0, 0.0);
  key->SetColor(1.0, 1.0, 1.0);
  key->SetIntensity(0.6);
  renderer->AddLight(key);

  // Point light just below the top of the loaded geometry (along ViewUp):
  // inside a room or a Cornell box it lights the floor and the walls the
  // way a ceiling lamp does; above an object it lights it from above.
  double bounds[6];
  this->GetBounds(bounds);
  if (!vtkMath::AreBoundsInitialized(bounds))
  {
    return;
  }
  double up[3] = { this->ViewUp[0], this->ViewUp[1], this->ViewUp[2] };
  if (vtkMath::Normalize(up) == 0.0)
  {
    up[1] = 1.0;
  }
  double position[3];
  for (int i = 0; i < 3; ++i)
  {
    const double center = 0.5 * (bounds[2 * i] + bounds[2 * i + 1]);
    const double extent = bounds[2 * i + 1] - bounds[2 * i];
    position[i] = center + 0.45 * extent * up[i];
  }
  vtkNew<vtkLight> lamp;
  lamp->SetLightTypeToSceneLight();
  lamp->SetPositional(true);
  lamp->SetConeAngle(180.0); // >= 90: a point light, not a spot light
  lamp->SetAttenuationValues(1.0, 0.0, 0.0);
  lamp->SetPosition(position);
  lamp->SetFocalPoint(position[0] - up[0], position[1] - up[1], position[2] - up[2]);
  lamp->SetColor(1.0, 0.96, 0.9);
  lamp->SetIntensity(0.7);
  renderer->AddLight(lamp);
}

//------------------------------------------------------------------------------
void vtkDeepGBufferSceneLoader::ResetCamera(vtkRenderer* renderer)
{
  if (!renderer)
  {
    vtkErrorMacro("ResetCamera: no renderer");
    return;
  }
  double bounds[6];
  if (this->Internals->Parts.empty())
  {
    renderer->ComputeVisiblePropBounds(bounds);
  }
  else
  {
    this->GetBounds(bounds);
  }
  if (!vtkMath::AreBoundsInitialized(bounds))
  {
    renderer->ResetCamera();
    return;
  }
  double direction[3] = { this->ViewDirection[0], this->ViewDirection[1], this->ViewDirection[2] };
  if (vtkMath::Normalize(direction) == 0.0)
  {
    direction[2] = -1.0;
  }
  const double center[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(center);
  camera->SetPosition(center[0] - direction[0], center[1] - direction[1], center[2] - direction[2]);
  camera->SetViewUp(this->ViewUp);
  camera->OrthogonalizeViewUp();
  renderer->ResetCamera(bounds);
  renderer->ResetCameraClippingRange(bounds);
}

//------------------------------------------------------------------------------
void vtkDeepGBufferSceneLoader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "IsoValue: " << this->IsoValue << "\n";
  os << indent << "ComputeNormals: " << (this->ComputeNormals ? "On" : "Off") << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "DefaultColor: (" << this->DefaultColor[0] << ", " << this->DefaultColor[1]
     << ", " << this->DefaultColor[2] << ")\n";
  os << indent << "RawSliceSpacing: (" << this->RawSliceSpacing[0] << ", "
     << this->RawSliceSpacing[1] << ", " << this->RawSliceSpacing[2] << ")\n";
  os << indent << "RawSliceLittleEndian: " << (this->RawSliceLittleEndian ? "On" : "Off") << "\n";
  os << indent << "DefaultLight: " << (this->DefaultLight ? "On" : "Off") << "\n";
  os << indent << "ViewDirection: (" << this->ViewDirection[0] << ", " << this->ViewDirection[1]
     << ", " << this->ViewDirection[2] << ")\n";
  os << indent << "ViewUp: (" << this->ViewUp[0] << ", " << this->ViewUp[1] << ", "
     << this->ViewUp[2] << ")\n";
  os << indent << "NumberOfParts: " << this->Internals->Parts.size() << "\n";
  for (const Part& part : this->Internals->Parts)
  {
    os << indent.GetNextIndent() << part.Name << ": " << part.PolyData->GetNumberOfPolys()
       << " triangles, colour (" << part.Color[0] << ", " << part.Color[1] << ", " << part.Color[2]
       << "), emission (" << part.Emission[0] << ", " << part.Emission[1] << ", "
       << part.Emission[2] << ")\n";
  }
}
