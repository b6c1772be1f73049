// Regression tests of vtkDeepGISceneLoader on files that crashed, hung,
// lost data silently or allocated without bound (Testing/Data/robustness,
// see MANIFEST.md). Each finding is one CTest test:
//   TestDeepGISceneLoaderRobustness --data DIR -T TEMPDIR --finding NAME
// NAME: ply-truncated, nrrd-rejected, nrrd-pattern-overflow, device-files,
// duplicate-faces, truncated-data, non-finite-points, huge-volume,
// obj-continuation, fuzz-findings. Every refused file must give exactly one error and
// leave the loader empty; nothing is rendered.

#include "DeepGITestChecks.h"
#include "DeepGITestData.h"

#include "vtkCommand.h"
#include "vtkDeepGISceneLoader.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <vtksys/SystemTools.hxx>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

namespace
{
using DeepGITest::Check;
using DeepGITest::Text;

// Counts the errors and warnings of the loader instead of printing them.
class Messages : public vtkCommand
{
public:
  static Messages* New() { return new Messages; }
  void Execute(vtkObject*, unsigned long event, void* callData) override
  {
    // Without VTK's "ERROR: In FILE, line N" first line.
    std::string text = callData ? static_cast<const char*>(callData) : "";
    text = text.substr(text.find('\n') == std::string::npos ? 0 : text.find('\n') + 1);
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings).push_back(text);
  }
  void Clear()
  {
    this->Errors.clear();
    this->Warnings.clear();
  }
  std::vector<std::string> Errors, Warnings;
};

struct Fixture
{
  std::string Data, Temp;
  vtkNew<vtkDeepGISceneLoader> Loader;
  vtkNew<Messages> Log;

  Fixture()
  {
    this->Loader->AddObserver(vtkCommand::ErrorEvent, this->Log);
    this->Loader->AddObserver(vtkCommand::WarningEvent, this->Log);
  }

  std::string Path(const std::string& name) const { return this->Data + "/robustness/" + name; }

  // `path` is refused with exactly one error holding `expected`.
  void Refused(const std::string& path, const std::string& expected)
  {
    this->Log->Clear();
    this->Loader->Clear();
    const bool loaded = this->Loader->Load(path.c_str());
    Check(!loaded, Text(path, " is refused"));
    Check(this->Log->Errors.size() == 1,
      Text(path, " gives one error (got ", this->Log->Errors.size(), ")"));
    // The message without the file's path (which may hold the word expected).
    std::string error = this->Log->Errors.empty() ? "" : this->Log->Errors.back();
    for (size_t at; !path.empty() && (at = error.find(path)) != std::string::npos;)
    {
      error.erase(at, path.size());
    }
    Check(error.find(expected) != std::string::npos,
      Text(path, ": the error says \"", expected, "\": ", error));
    Check(this->Loader->GetNumberOfParts() == 0, Text(path, " adds no part"));
  }

  // `path` loads without errors; returns the warnings.
  std::vector<std::string> Loads(const std::string& path)
  {
    this->Log->Clear();
    this->Loader->Clear();
    Check(this->Loader->Load(path.c_str()), Text(path, " loads"));
    Check(this->Log->Errors.empty(), Text(path, " loads without errors"));
    return this->Log->Warnings;
  }

  // The first `bytes` bytes of `name`, written to the temporary directory.
  std::string Truncated(const std::string& name, size_t bytes)
  {
    std::ifstream in(this->Path(name), std::ios::binary);
    std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string out = this->Temp + "/trunc_" + std::to_string(bytes) + "_" + name;
    std::ofstream(out, std::ios::binary) << content.substr(0, bytes);
    return out;
  }

  std::string Write(const std::string& name, const std::string& content)
  {
    const std::string out = this->Temp + "/" + name;
    std::ofstream(out, std::ios::binary) << content;
    return out;
  }
};

size_t FileSize(const std::string& path)
{
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  return static_cast<size_t>(in.tellg());
}

bool Contains(const std::vector<std::string>& messages, const std::string& text)
{
  for (const std::string& m : messages)
  {
    if (m.find(text) != std::string::npos)
    {
      return true;
    }
  }
  return false;
}

// Truncations of `name` at `count` lengths spread over the file (and just
// short of its end: 2 bytes, since the last byte of m_bin.vtk is the
// newline after its data) are refused with "truncated"; the whole file loads.
void TruncationsRefused(Fixture& f, const std::string& name, size_t first, int count)
{
  const size_t size = FileSize(f.Path(name));
  std::vector<size_t> lengths = { size - 2, size - 3, size - 50 };
  for (int i = 0; i < count; ++i)
  {
    lengths.push_back(first + (size - first) * i / count);
  }
  for (size_t n : lengths)
  {
    f.Refused(f.Truncated(name, n), "truncated");
  }
  f.Loads(f.Path(name));
}

// Finding 1: every truncated PLY crashed VTK 9.1's vtkPLYReader.
void PlyTruncated(Fixture& f)
{
  f.Refused(f.Path("min_trunc_face.ply"), "truncated");
  TruncationsRefused(f, "m_bin.ply", 300, 40);
  f.Refused(f.Truncated("m_bin.ply", 100), "end_header"); // inside the header
  // ASCII: a face line with fewer indices than its count.
  f.Refused(f.Write("short_face.ply",
              "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
              "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
              "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n"),
    "fewer values");
}

// Finding 2: headers our parser refused reached vtkNrrdReader (memory
// errors, endless loops). Now every NRRD is refused by our parser alone.
void NrrdRejected(Fixture& f)
{
  for (const char* name : { "nrrd_overflow.nhdr", "nrrd_segv_read.nhdr", "nrrd_heap_overflow2.nhdr",
         "nrrd_hang.nhdr", "nrrd_hang2.nhdr" })
  {
    f.Refused(f.Path(name), "Cannot read NRRD");
  }
}

// Finding 3: `data file: PATTERN first last step` near LONG_MAX / LONG_MIN.
void NrrdPatternOverflow(Fixture& f)
{
  f.Refused(f.Path("wrap.nhdr"), "missing or not a regular file");
  const std::string head = "NRRD0004\ntype: unsigned short\ndimension: 3\nencoding: raw\n";
  f.Refused(
    f.Write("min.nhdr",
      head + "sizes: 64 64 2\ndata file: s.%d -9223372036854775808 -9223372036854775807 1\n"),
    "missing or not a regular file");
  f.Refused(
    f.Write("span.nhdr",
      head + "sizes: 64 64 2\ndata file: s.%d -9223372036854775808 9223372036854775807 1\n"),
    "not one per slice");
  // From LLONG_MAX down to LLONG_MIN in steps of -LLONG_MAX: 3 files.
  f.Refused(f.Write("down.nhdr",
              head +
                "sizes: 64 64 3\ndata file: s.%d 9223372036854775807 "
                "-9223372036854775808 -9223372036854775807\n"),
    "missing or not a regular file");
  f.Refused(
    f.Write("toolong.nhdr", head + "sizes: 64 64 2\ndata file: s.%d 1 99999999999999999999 1\n"),
    "integers");
}

// Finding 4: device files named by mtllib or as data files.
void DeviceFiles(Fixture& f)
{
  for (const char* name : { "devurandom.obj", "devzero.obj" })
  {
    const std::vector<std::string> warnings = f.Loads(f.Path(name));
    Check(Contains(warnings, "not a regular file"), Text(name, " warns about its mtllib"));
  }
  f.Refused("/dev/zero", "Not a mesh file");
  const std::string head = "NRRD0004\ntype: uchar\ndimension: 3\nencoding: raw\nsizes: 4 4 4\n";
  f.Refused(f.Write("zero.nhdr", head + "data file: /dev/zero\n"), "not a regular file");
  // A line without an end (here: 2 MiB) is refused, not read forever.
  f.Refused(f.Write("longline.obj",
              "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 " + std::string(size_t(2) << 20, '1')),
    "longer than");
}

// Finding 5: 2,000 coincident copies of one face took 43 s in
// vtkPolyDataNormals; the test's TIMEOUT (60 s) is the only time bound.
void DuplicateFaces(Fixture& f)
{
  f.Loads(f.Path("dupface_2000.obj"));
  Check(f.Loader->GetNumberOfTriangles() == 2000,
    Text("dupface_2000.obj keeps its 2000 triangles (has ", f.Loader->GetNumberOfTriangles(), ")"));
  vtkPolyData* pd = f.Loader->GetPartPolyData(0);
  Check(pd && pd->GetPointData()->GetNormals(), "dupface_2000.obj gets normals");
}

// Finding 6: truncated STL and legacy .vtk, short NRRD data, gzip claimed
// on raw data: all loaded "successfully".
void TruncatedData(Fixture& f)
{
  TruncationsRefused(f, "m_bin.stl", 84, 30);
  TruncationsRefused(f, "m_bin.vtk", 40000, 30);
  f.Refused(f.Truncated("m_bin.stl", 60), "truncated");
  f.Refused(f.Path("short.nhdr"), "truncated");
  f.Refused(f.Path("ov_gzip.nhdr"), "encoding \"gzip\" is not supported");
}

// Finding 7: one non-finite vertex made the image black.
void NonFinitePoints(Fixture& f)
{
  for (const char* name : { "fandisk_inf.obj", "fandisk_nan.obj" })
  {
    const std::vector<std::string> warnings = f.Loads(f.Path(name));
    Check(Contains(warnings, "dropped 1 point(s) with non-finite"),
      Text(name, " warns about its non-finite point"));
    double b[6];
    f.Loader->GetBounds(b);
    bool finite = true;
    for (double v : b)
    {
      finite = finite && std::isfinite(v) && std::abs(v) < 1e6;
    }
    Check(finite, Text(name, " has finite bounds"));
    vtkPoints* points = f.Loader->GetPartPolyData(0)->GetPoints();
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
    {
      double p[3];
      points->GetPoint(i, p);
      finite = finite && std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
    }
    Check(finite, Text(name, " keeps finite points only"));
  }
}

// Finding 13: sizes 100000^3 ended in an uncaught std::bad_alloc.
void HugeVolume(Fixture& f)
{
  f.Refused(f.Path("huge.nhdr"), "more than the limit");
}

// A lone "\" before "usemtl red" made the material "l red".
void ObjContinuation(Fixture& f)
{
  f.Loads(f.Path("cont_usemtl.obj"));
  Check(f.Loader->GetNumberOfParts() == 1 &&
      std::string(f.Loader->GetPartName(0)) == "cont_usemtl.obj:red",
    Text("the part is cont_usemtl.obj:red (got ",
      (f.Loader->GetNumberOfParts() ? f.Loader->GetPartName(0) : "none"), ")"));
  double rgb[3];
  f.Loader->GetPartColor(0, rgb);
  Check(rgb[0] == 1.0 && rgb[1] == 0.0 && rgb[2] == 0.0, "red has Kd 1 0 0");
  // A continued line joins its parts with one space.
  f.Loads(f.Write("continued.obj", "v 0 \\\n 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 \\\n3\n"));
  Check(f.Loader->GetNumberOfTriangles() == 1, "continued lines make one triangle");
}

// What fuzzing (scripts/fuzz.sh) found after the fixes above, as small
// hand-made files: each crashed VTK 9.1's vtkPLYReader or vtkPolyDataReader.
void FuzzFindings(Fixture& f)
{
  const std::string ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                          "property float y\nproperty float z\n";
  const std::string face = "element face 1\nproperty list uchar int vertex_indices\n";
  const std::string data = "0 0 0\n1 0 0\n0 1 0\n";
  // vtkPolygon::Initialize read the point of a face index past the points.
  f.Refused(f.Write("far_index.ply", ply + face + "end_header\n" + data + "3 0 1 7\n"),
    "names a vertex outside");
  // A NUL ended vtkPLY's header line early: a NULL element list.
  f.Refused(
    f.Write("nul.ply", ply + std::string("element face\0\0ace 1\n", 20) + "end_header\n" + data),
    "control character");
  // "Cannot read geometry", then vtkPLYReader went on with a closed file.
  f.Refused(f.Write("no_xyz.ply",
              "ply\nformat ascii 1.0\nelement vertex 1\nproperty float w\nend_header\n0\n"),
    "x, y and z");
  // A face element without vertex_indices: an uninitialised pointer freed.
  f.Refused(
    f.Write("no_indices.ply",
      ply + "element face 1\nproperty list uchar int corners\nend_header\n" + data + "3 0 1 2\n"),
    "no vertex_indices");
  f.Refused(f.Write("faces_first.ply",
              "ply\nformat ascii 1.0\n" + face +
                "element vertex 3\nproperty float x\n"
                "property float y\nproperty float z\nend_header\n3 0 1 2\n" +
                data),
    "faces before the vertices");
  // vtkCellArray::AppendLegacyFormat read past a cell list whose counts run
  // past its size.
  const std::string vtk = "# vtk DataFile Version 4.2\nx\nASCII\nDATASET POLYDATA\n"
                          "POINTS 3 float\n0 0 0 1 0 0 0 1 0\n";
  f.Refused(f.Write("run_past.vtk", vtk + "POLYGONS 1 4\n9 0 1 2\n"), "runs past");
  f.Refused(f.Write("offsets.vtk",
              "# vtk DataFile Version 5.1\nx\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n"
              "0 0 0 1 0 0 0 1 0\nPOLYGONS 2 3\nOFFSETS vtktypeint64\n0 9\n"
              "CONNECTIVITY vtktypeint64\n0 1 2\n"),
    "offsets end at");
  f.Loads(f.Write("good.vtk", vtk + "POLYGONS 1 4\n3 0 1 2\n"));
  Check(f.Loader->GetNumberOfTriangles() == 1, "good.vtk has one triangle");
}
} // anonymous namespace

int TestDeepGISceneLoaderRobustness(int argc, char* argv[])
{
  Fixture f;
  std::string finding;
  for (int i = 1; i + 1 < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--data")
    {
      f.Data = argv[++i];
    }
    else if (a == "-T")
    {
      f.Temp = argv[++i];
    }
    else if (a == "--finding")
    {
      finding = argv[++i];
    }
  }
  const std::map<std::string, std::function<void(Fixture&)>> findings = {
    { "ply-truncated", PlyTruncated }, { "nrrd-rejected", NrrdRejected },
    { "nrrd-pattern-overflow", NrrdPatternOverflow }, { "device-files", DeviceFiles },
    { "duplicate-faces", DuplicateFaces }, { "truncated-data", TruncatedData },
    { "non-finite-points", NonFinitePoints }, { "huge-volume", HugeVolume },
    { "obj-continuation", ObjContinuation }, { "fuzz-findings", FuzzFindings }
  };
  if (f.Data.empty() || f.Temp.empty() || !findings.count(finding))
  {
    std::cerr << "Usage: TestDeepGISceneLoaderRobustness --data DIR -T TEMPDIR --finding NAME\n";
    return EXIT_FAILURE;
  }
  if (!DeepGITestData::Require(
        f.Data, { "MANIFEST.md", "robustness/m_bin.ply" }, "TestDeepGISceneLoaderRobustness"))
  {
    return EXIT_FAILURE;
  }
  f.Temp += "/TestDeepGISceneLoaderRobustness-" + finding;
  vtksys::SystemTools::MakeDirectory(f.Temp);
  findings.at(finding)(f);
  return DeepGITest::ExitStatus();
}
