#include "vtkDeepGISceneMesh.h"

#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCleanPolyData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkStringArray.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <unordered_map>

namespace vtkDeepGISceneMesh
{
namespace
{
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
// `input`'s points, finite normals and the cells `filter` keeps; nullptr
// (and `prepared.Error`) when no cell is left.
vtkSmartPointer<vtkPolyData> CheckedCells(
  vtkPolyData* input, const std::string& what, Prepared& prepared)
{
  vtkPoints* inputPoints = input->GetPoints();
  const vtkIdType numberOfPoints = inputPoints ? inputPoints->GetNumberOfPoints() : 0;
  CellFilter filter;
  filter.NumberOfPoints = numberOfPoints;
  const vtkIdType nonFinite = MarkNonFinitePoints(inputPoints, filter.NonFinite);
  vtkSmartPointer<vtkCellArray> polys = filter.Apply(input->GetPolys());
  vtkSmartPointer<vtkCellArray> strips = filter.Apply(input->GetStrips());
  std::ostringstream message;
  if (!polys && !strips)
  {
    message << what << " has no polygons whose point ids are within its " << numberOfPoints
            << " points and whose points are finite";
    prepared.Error = message.str();
    return nullptr;
  }
  if (filter.OutOfRange)
  {
    message << what << ": skipped " << filter.OutOfRange
            << " polygon(s) with point ids outside its " << numberOfPoints << " points";
    prepared.Warnings.push_back(message.str());
    message.str("");
  }
  if (nonFinite)
  {
    message << what << ": dropped " << nonFinite
            << " point(s) with non-finite (NaN or infinite) coordinates and the "
            << filter.WithNonFinite << " polygon(s) using them";
    prepared.Warnings.push_back(message.str());
  }
  auto checked = vtkSmartPointer<vtkPolyData>::New();
  checked->SetPoints(inputPoints);
  checked->SetPolys(polys);
  checked->SetStrips(strips);
  vtkDataArray* inputNormals = input->GetPointData()->GetNormals();
  if (inputNormals && inputNormals->GetNumberOfComponents() == 3 &&
    inputNormals->GetNumberOfTuples() == numberOfPoints && AllFinite(inputNormals))
  {
    checked->GetPointData()->SetNormals(inputNormals);
  }
  return checked;
}

// The triangles of `checked`, without unused points and without merging
// any (coincident duplicates stay, as in the data).
vtkSmartPointer<vtkPolyData> Triangles(vtkPolyData* checked)
{
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputData(checked);
  clean->PointMergingOff();
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(clean->GetOutputPort());
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  triangles->Update();
  vtkPolyData* tri = triangles->GetOutput();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(tri->GetPoints());
  mesh->SetPolys(tri->GetPolys());
  vtkDataArray* normals = tri->GetPointData()->GetNormals();
  if (normals && normals->GetNumberOfComponents() == 3)
  {
    mesh->GetPointData()->SetNormals(normals);
  }
  return mesh;
}

// A part's cell arrays: its albedo "Colors" and its "PartId".
void AddPartArrays(vtkPolyData* copy, const Part& part, int id)
{
  const vtkIdType n = copy->GetNumberOfCells();
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("Colors");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(n);
  unsigned char rgb[3];
  for (int c = 0; c < 3; ++c)
  {
    rgb[c] =
      static_cast<unsigned char>(std::lround(255.0 * vtkMath::ClampValue(part.Color[c], 0.0, 1.0)));
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
}

// What Populate draws, for references that light the scene
// (vtkDeepGIReferenceIrradiance): an emitter's colour Ke / max(Ke)
// (Ambient 1, EMISSIVE) and its Diffuse 0, the other parts' emission 0 and
// Diffuse `diffuse`.
void AddEmissionArrays(vtkPolyData* copy, const Part& part, double diffuse)
{
  const vtkIdType n = copy->GetNumberOfCells();
  const double brightest = Brightest(part);
  float emitted[3] = { 0.0f, 0.0f, 0.0f };
  for (int c = 0; c < 3 && brightest > 0.0; ++c)
  {
    emitted[c] = static_cast<float>(part.Emission[c] / brightest);
  }
  vtkNew<vtkFloatArray> emission;
  emission->SetName("Emission");
  emission->SetNumberOfComponents(3);
  emission->SetNumberOfTuples(n);
  vtkNew<vtkFloatArray> diffuseArray;
  diffuseArray->SetName("Diffuse");
  diffuseArray->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    emission->SetTypedTuple(i, emitted);
    diffuseArray->SetValue(i, brightest > 0.0 ? 0.0f : static_cast<float>(diffuse));
  }
  copy->GetCellData()->AddArray(emission);
  copy->GetCellData()->AddArray(diffuseArray);
}
// The material `m` of vtkDeepGIOBJReader's output: the RGB tuple of the
// field array `name`.
void MaterialColor(vtkFieldData* materials, const char* name, vtkIdType m, double rgb[3])
{
  vtkDataArray* array = materials->GetArray(name);
  for (int c = 0; c < 3; ++c)
  {
    rgb[c] = array ? array->GetComponent(m, c) : 0.0;
  }
}

bool MaterialFlag(vtkFieldData* materials, const char* name, vtkIdType m)
{
  vtkDataArray* array = materials->GetArray(name);
  return array && array->GetComponent(m, 0) != 0.0;
}

std::string StringValue(vtkFieldData* fieldData, const char* name, vtkIdType i)
{
  auto* array = vtkStringArray::SafeDownCast(fieldData->GetAbstractArray(name));
  return array && i < array->GetNumberOfValues() ? array->GetValue(i) : std::string();
}
} // anonymous namespace

//------------------------------------------------------------------------------
double Brightest(const Part& part)
{
  return std::max({ part.Emission[0], part.Emission[1], part.Emission[2] });
}

//------------------------------------------------------------------------------
Prepared Prepare(
  vtkPolyData* input, const std::string& what, bool computeNormals, double featureAngle)
{
  Prepared prepared;
  if (!input || input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    prepared.Error = what + " has no polygons (empty mesh, or points/lines only)";
    return prepared;
  }
  // Only what is used below (points, polygons, strips, point normals), and
  // only cells whose point ids exist and whose points are finite: not every
  // reader checks ids (the filters below would read out of bounds), and one
  // NaN or infinite point makes the bounds, the camera and the image wrong.
  if (!IsConsistent(input->GetPolys()) || !IsConsistent(input->GetStrips()))
  {
    prepared.Error = what + " has corrupt polygons (cell offsets beyond its point ids)";
    return prepared;
  }
  vtkSmartPointer<vtkPolyData> checked = CheckedCells(input, what, prepared);
  if (!checked)
  {
    return prepared;
  }
  vtkSmartPointer<vtkPolyData> mesh = Triangles(checked);
  if (mesh->GetNumberOfPolys() == 0)
  {
    prepared.Error = what + " has no non-degenerate triangles";
    return prepared;
  }
  const bool compute = computeNormals && !mesh->GetPointData()->GetNormals();
  prepared.Mesh = compute ? ComputePointNormals(mesh, featureAngle) : mesh;
  return prepared;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> ExtractMaterial(vtkPolyData* mesh, int material)
{
  vtkDataArray* ids = mesh->GetCellData()->GetArray("MaterialId");
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  std::unordered_map<vtkIdType, vtkIdType> pointOf;
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> pointNormals;
  pointNormals->SetName("Normals");
  pointNormals->SetNumberOfComponents(3);
  vtkNew<vtkCellArray> polys;
  std::vector<vtkIdType> corners;
  vtkIdType cell = 0, n;
  const vtkIdType* cellIds;
  auto it = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cell)
  {
    if (!ids || static_cast<int>(ids->GetComponent(cell, 0)) != material)
    {
      continue;
    }
    it->GetCurrentCell(n, cellIds);
    corners.clear();
    for (vtkIdType c = 0; c < n; ++c)
    {
      auto inserted = pointOf.emplace(cellIds[c], points->GetNumberOfPoints());
      if (inserted.second)
      {
        points->InsertNextPoint(mesh->GetPoint(cellIds[c]));
        if (normals)
        {
          pointNormals->InsertNextTuple(normals->GetTuple(cellIds[c]));
        }
      }
      corners.push_back(inserted.first->second);
    }
    polys->InsertNextCell(n, corners.data());
  }
  auto part = vtkSmartPointer<vtkPolyData>::New();
  part->SetPoints(points);
  part->SetPolys(polys);
  if (normals)
  {
    part->GetPointData()->SetNormals(pointNormals);
  }
  return part;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> Append(const std::vector<Part>& parts, double diffuse)
{
  bool emitters = false;
  for (const Part& part : parts)
  {
    emitters = emitters || Brightest(part) > 0.0;
  }
  vtkNew<vtkAppendPolyData> append;
  int id = 0;
  for (const Part& part : parts)
  {
    auto copy = vtkSmartPointer<vtkPolyData>::New();
    copy->ShallowCopy(part.PolyData);
    AddPartArrays(copy, part, id++);
    if (emitters)
    {
      AddEmissionArrays(copy, part, diffuse);
    }
    append->AddInputData(copy);
  }
  append->Update();
  auto scene = vtkSmartPointer<vtkPolyData>::New();
  scene->ShallowCopy(append->GetOutput());
  // The actors' diffuse coefficient, for references that light the scene.
  vtkNew<vtkDoubleArray> diffuseArray;
  diffuseArray->SetName("Diffuse");
  diffuseArray->InsertNextValue(diffuse);
  scene->GetFieldData()->AddArray(diffuseArray);
  return scene;
}

//------------------------------------------------------------------------------
std::vector<Part> MaterialParts(vtkPolyData* mesh, const std::string& base,
  const double defaultColor[3], std::string& unknown, std::string& materialFile)
{
  vtkFieldData* materials = mesh->GetFieldData();
  vtkAbstractArray* names = materials->GetAbstractArray("MaterialName");
  const vtkIdType count = names ? names->GetNumberOfValues() : 0;
  std::vector<Part> parts;
  for (vtkIdType m = 0; m < count; ++m)
  {
    const std::string material = StringValue(materials, "MaterialName", m);
    Part part;
    part.Name = material.empty() ? base : base + ":" + material;
    MaterialColor(materials, "MaterialKd", m, part.Color);
    if (!MaterialFlag(materials, "MaterialHasKd", m))
    {
      std::copy(defaultColor, defaultColor + 3, part.Color);
    }
    MaterialColor(materials, "MaterialKe", m, part.Emission);
    if (!MaterialFlag(materials, "MaterialDefined", m))
    {
      unknown += (unknown.empty() ? "" : ", ") + material;
    }
    part.PolyData = ExtractMaterial(mesh, static_cast<int>(m));
    parts.push_back(part);
  }
  materialFile = StringValue(materials, "MaterialFile", 0);
  return parts;
}
}
