// vtkDeepGIOBJReader and vtkDeepGINrrdReader as VTK algorithms: each in a
// pipeline with Update(), the numbers of its output (point and cell counts,
// material values, extent, spacing, origin, voxel values), and bad input (a
// missing or malformed file) giving one error of the reader and an empty
// output.
//   TestDeepGISceneReaders --data DIR -T TEMPDIR (-T: where its files are written)

#include "DeepGITestChecks.h"
#include "DeepGITestData.h"

#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDeepGINrrdReader.h"
#include "vtkDeepGIOBJReader.h"
#include "vtkErrorCode.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFlyingEdges3D.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkTriangleFilter.h"

#include <cmath>
#include <fstream>
#include <string>

namespace
{
using DeepGITest::Check;
using DeepGITest::Text;

// Counts the error events of an object instead of printing them.
class ErrorCounter : public vtkCommand
{
public:
  static ErrorCounter* New() { return new ErrorCounter; }
  void Execute(vtkObject*, unsigned long, void*) override { ++this->Count; }
  int Count = 0;
};

std::string Write(const std::string& path, const std::string& content)
{
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

bool Near(const double* a, double x, double y, double z)
{
  return std::abs(a[0] - x) < 1e-12 && std::abs(a[1] - y) < 1e-12 && std::abs(a[2] - z) < 1e-12;
}

// Three materials: "red" (a quad), "lamp" (two triangles, Ke with a
// negative component) and "ghost", which the MTL file does not define.
void TestOBJMaterials(const std::string& temp)
{
  Write(
    temp + "/readers.mtl", "newmtl red\nKd 0.5 0.1 0.2\nnewmtl lamp\nKd 0.8 0.8 0.8\nKe 4 2 -1\n");
  const std::string obj = Write(temp + "/readers.obj",
    "mtllib readers.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\n"
    "usemtl red\nf 1 2 3 4\nusemtl lamp\nf 1 2 5\nf 2 3 5\nusemtl ghost\nf 3 4 5\n");
  vtkNew<vtkDeepGIOBJReader> reader;
  reader->SetFileName(obj.c_str());
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(reader->GetOutputPort());
  triangles->Update();
  vtkPolyData* mesh = reader->GetOutput();
  Check(mesh->GetNumberOfCells() == 4 && mesh->GetNumberOfPoints() == 11,
    Text("OBJ: 4 faces and 11 points (4 + 4 + 3, each material its own), got ",
      mesh->GetNumberOfCells(), " and ", mesh->GetNumberOfPoints()));
  Check(triangles->GetOutput()->GetNumberOfCells() == 5,
    Text("OBJ through vtkTriangleFilter: 5 triangles, got ",
      triangles->GetOutput()->GetNumberOfCells()));
  vtkDataArray* ids = mesh->GetCellData()->GetArray("MaterialId");
  Check(ids && ids->GetTuple1(0) == 0 && ids->GetTuple1(1) == 1 && ids->GetTuple1(2) == 1 &&
      ids->GetTuple1(3) == 2,
    "OBJ: MaterialId 0, 1, 1, 2");
  vtkFieldData* fd = mesh->GetFieldData();
  auto* names = vtkStringArray::SafeDownCast(fd->GetAbstractArray("MaterialName"));
  Check(names && names->GetNumberOfValues() == 3 && names->GetValue(0) == "red" &&
      names->GetValue(1) == "lamp" && names->GetValue(2) == "ghost",
    "OBJ: materials red, lamp, ghost in the order of first use");
  vtkDataArray* kd = fd->GetArray("MaterialKd");
  vtkDataArray* ke = fd->GetArray("MaterialKe");
  vtkDataArray* hasKd = fd->GetArray("MaterialHasKd");
  vtkDataArray* defined = fd->GetArray("MaterialDefined");
  Check(kd && Near(kd->GetTuple3(0), 0.5, 0.1, 0.2), "OBJ: red's Kd is (0.5, 0.1, 0.2)");
  Check(ke && Near(ke->GetTuple3(1), 4, 2, 0) && Near(ke->GetTuple3(0), 0, 0, 0),
    "OBJ: lamp's Ke is (4, 2, 0) (negative clamped), red's 0");
  Check(hasKd && defined && hasKd->GetTuple1(1) == 1 && hasKd->GetTuple1(2) == 0 &&
      defined->GetTuple1(0) == 1 && defined->GetTuple1(2) == 0,
    "OBJ: ghost has no Kd and is not defined; the others are");
  Check(!mesh->GetPointData()->GetNormals(), "OBJ without vn: no normals");
  Check(reader->GetErrorCode() == vtkErrorCode::NoError, "OBJ: no error code");
}

// The Cornell box of Testing/Data: 8 materials, the light's Ke (17, 12, 4).
void TestOBJCornellBox(const std::string& data)
{
  vtkNew<vtkDeepGIOBJReader> reader;
  const std::string obj = data + "/scenes/cornell-original/CornellBox-Original.obj";
  reader->SetFileName(obj.c_str());
  reader->Update();
  vtkPolyData* mesh = reader->GetOutput();
  vtkFieldData* fd = mesh->GetFieldData();
  auto* names = vtkStringArray::SafeDownCast(fd->GetAbstractArray("MaterialName"));
  const vtkIdType materials = names ? names->GetNumberOfValues() : 0;
  Check(mesh->GetNumberOfCells() == 18 && materials == 8,
    Text("Cornell box: 18 faces, 8 materials, got ", mesh->GetNumberOfCells(), ", ", materials));
  const bool lampLast = materials == 8 && names->GetValue(7) == "light";
  Check(lampLast && Near(fd->GetArray("MaterialKe")->GetTuple3(7), 17, 12, 4),
    "Cornell box: the light's Ke is (17, 12, 4)");
}

// A 3 x 2 x 2 volume of unsigned chars 0..11 with spacing and origin.
void TestNrrd(const std::string& temp)
{
  std::string voxels;
  for (char v = 0; v < 12; ++v)
  {
    voxels += v;
  }
  const std::string nrrd = Write(temp + "/readers.nrrd",
    "NRRD0004\ndimension: 3\ntype: unsigned char\nsizes: 3 2 2\nspacings: 0.5 2 1.5\n"
    "space origin: (1,2,3)\nencoding: raw\nendian: little\n\n" +
      voxels);
  vtkNew<vtkDeepGINrrdReader> reader;
  reader->SetFileName(nrrd.c_str());
  reader->UpdateInformation();
  vtkInformation* info = reader->GetOutputInformation(0);
  int extent[6];
  info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  Check(extent[0] == 0 && extent[1] == 2 && extent[3] == 1 && extent[5] == 1,
    Text("NRRD information: whole extent 0..2, 0..1, 0..1, got ..", extent[1], ", ..", extent[3],
      ", ..", extent[5]));
  Check(Near(info->Get(vtkDataObject::SPACING()), 0.5, 2, 1.5) &&
      Near(info->Get(vtkDataObject::ORIGIN()), 1, 2, 3),
    "NRRD information: spacing (0.5, 2, 1.5), origin (1, 2, 3)");
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  Check(image->GetNumberOfPoints() == 12 && image->GetScalarComponentAsDouble(2, 1, 1, 0) == 11.0 &&
      image->GetScalarComponentAsDouble(1, 0, 1, 0) == 7.0,
    Text("NRRD data: 12 voxels, voxel (2, 1, 1) = 11 and (1, 0, 1) = 7, got ",
      image->GetNumberOfPoints(), " voxels"));
}

// headsq through the reader and vtkFlyingEdges3D.
void TestNrrdHeadsq(const std::string& data)
{
  vtkNew<vtkDeepGINrrdReader> reader;
  const std::string nhdr = data + "/volumes/headsq/quarter.nhdr";
  reader->SetFileName(nhdr.c_str());
  vtkNew<vtkFlyingEdges3D> iso;
  iso->SetInputConnection(reader->GetOutputPort());
  iso->SetValue(0, 500.0);
  iso->Update();
  int dims[3];
  reader->GetOutput()->GetDimensions(dims);
  Check(dims[0] == 64 && dims[1] == 64 && dims[2] == 93 &&
      Near(reader->GetOutput()->GetSpacing(), 3.2, 3.2, 1.5),
    Text("headsq: 64 x 64 x 93 voxels of 3.2 x 3.2 x 1.5, got ", dims[0], " x ", dims[1], " x ",
      dims[2]));
  Check(iso->GetOutput()->GetNumberOfCells() > 10000,
    Text("headsq: the skin at 500 has over 10,000 triangles, got ",
      iso->GetOutput()->GetNumberOfCells()));
}

// `reader` on `path` gives one error of its own (none of its executive),
// an error code and an empty output.
template <typename Reader>
void Refused(const std::string& path, const std::string& what)
{
  vtkNew<Reader> reader;
  reader->SetFileName(path.c_str());
  vtkNew<ErrorCounter> errors, executiveErrors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executiveErrors);
  reader->Update();
  Check(errors->Count == 1 && executiveErrors->Count == 0,
    Text(what, ": one error of the reader, none of the pipeline, got ", errors->Count, " and ",
      executiveErrors->Count));
  Check(reader->GetErrorCode() != vtkErrorCode::NoError, what + ": an error code");
  Check(reader->GetOutput()->GetNumberOfPoints() == 0, what + ": an empty output");
}

void TestBadInput(const std::string& temp)
{
  Refused<vtkDeepGIOBJReader>(temp + "/missing.obj", "missing OBJ");
  Refused<vtkDeepGIOBJReader>(
    Write(temp + "/malformed.obj", "v 0 0 0\nv 1 x 0\nf 1 2 3\n"), "malformed OBJ");
  Refused<vtkDeepGINrrdReader>(temp + "/missing.nhdr", "missing NRRD");
  Refused<vtkDeepGINrrdReader>(
    Write(temp + "/malformed.nhdr", "NRRD0004\ndimension: 2\nsizes: 2 2\n"), "malformed NRRD");
  Refused<vtkDeepGINrrdReader>(Write(temp + "/truncated.nrrd",
                                 "NRRD0004\ndimension: 3\ntype: short\nsizes: 4 4 4\n"
                                 "encoding: raw\n\nshort"),
    "truncated NRRD");
}
}

int TestDeepGISceneReaders(int argc, char* argv[])
{
  const std::string data = DeepGITestData::Folder(argc, argv, "TestDeepGISceneReaders");
  const std::string temp = DeepGITest::Argument(argc, argv, "-T", ".");
  if (!DeepGITestData::Require(data,
        { "scenes/cornell-original/CornellBox-Original.obj", "volumes/headsq/quarter.nhdr" },
        "TestDeepGISceneReaders"))
  {
    return EXIT_FAILURE;
  }
  TestOBJMaterials(temp);
  TestOBJCornellBox(data);
  TestNrrd(temp);
  TestNrrdHeadsq(data);
  TestBadInput(temp);
  return DeepGITest::ExitStatus();
}
