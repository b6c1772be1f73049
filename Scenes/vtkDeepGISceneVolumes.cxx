#include "vtkDeepGISceneVolumes.h"

#include "vtkAlgorithm.h"
#include "vtkDataArray.h"
#include "vtkDeepGINrrdReader.h"
#include "vtkDeepGISceneFileChecks.h"
#include "vtkDeepGISceneMessages.h"
#include "vtkDeepGISceneText.h"
#include "vtkExecutive.h"
#include "vtkFlyingEdges3D.h"
#include "vtkImageData.h"
#include "vtkMetaImageReader.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkVolume16Reader.h"
#include "vtkXMLImageDataReader.h"

#include <vtksys/Directory.hxx>
#include <vtksys/SystemTools.hxx>

#include <cmath>
#include <sstream>
#include <vector>

namespace vtkDeepGISceneVolumes
{
namespace
{
using vtkDeepGISceneFileChecks::IsRegularFile;
using vtkDeepGISceneMessages::Collector;

// The one volume file in the directory `path` (into `file`), or why not.
std::string FileInDirectory(const std::string& path, std::string& file)
{
  vtksys::Directory dir;
  if (!dir.Load(path))
  {
    return "Cannot list the directory " + path;
  }
  std::vector<std::string> headers;
  for (unsigned long i = 0; i < dir.GetNumberOfFiles(); ++i)
  {
    const std::string name = dir.GetFile(i);
    if (IsVolumeExtension(Extension(name)) && IsRegularFile(path + "/" + name))
    {
      headers.push_back(name);
    }
  }
  if (headers.size() != 1)
  {
    return "The directory " + path + " holds " + std::to_string(headers.size()) +
      " volume files (.nhdr .nrrd .mhd .mha .vti); give exactly one file instead";
  }
  file = path + "/" + headers[0];
  return "";
}

// The raw 16-bit slices PREFIX.1, PREFIX.2, ...: square, their side from
// the size of the first.
std::string ReadRawSlices(const std::string& prefix, const RawSlices& raw, vtkImageData* output)
{
  int slices = 1;
  while (slices < 100000 && IsRegularFile(prefix + "." + std::to_string(slices + 1)))
  {
    ++slices;
  }
  const unsigned long bytes = vtksys::SystemTools::FileLength(prefix + ".1");
  const int side = static_cast<int>(std::lround(std::sqrt(bytes / 2.0)));
  if (side < 2 || static_cast<unsigned long>(2 * side * side) != bytes)
  {
    return "Slice " + prefix + ".1 has " + std::to_string(bytes) +
      " bytes, not a square 16-bit image; give a .nhdr header";
  }
  vtkNew<vtkVolume16Reader> reader;
  reader->SetFilePrefix(prefix.c_str());
  reader->SetDataDimensions(side, side);
  reader->SetImageRange(1, slices);
  reader->SetDataSpacing(const_cast<double*>(raw.Spacing));
  if (raw.LittleEndian)
  {
    reader->SetDataByteOrderToLittleEndian();
  }
  else
  {
    reader->SetDataByteOrderToBigEndian();
  }
  vtkNew<Collector> errors;
  errors->Watch(reader);
  errors->Watch(reader->GetExecutive());
  reader->Update();
  if (!errors->Messages.empty() || reader->GetOutput()->GetNumberOfPoints() == 0)
  {
    return "Cannot read the slice series " + prefix + ": " + errors->Messages;
  }
  output->ShallowCopy(reader->GetOutput());
  return "";
}

// vtkDeepGINrrdReader, whose one error already names the file.
std::string ReadNrrd(const std::string& path, vtkImageData* output)
{
  vtkNew<vtkDeepGINrrdReader> reader;
  reader->SetFileName(path.c_str());
  vtkNew<Collector> errors;
  errors->Watch(reader);
  errors->Watch(reader->GetExecutive());
  reader->Update();
  if (!errors->Errors.empty())
  {
    return errors->Errors.front();
  }
  output->ShallowCopy(reader->GetOutput());
  return "";
}

// A .vti, .mhd or .mha file, through VTK's reader.
std::string ReadWithVTK(const std::string& path, const std::string& ext, vtkImageData* output)
{
  vtkSmartPointer<vtkAlgorithm> reader;
  if (ext == ".vti")
  {
    auto r = vtkSmartPointer<vtkXMLImageDataReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else
  {
    auto r = vtkSmartPointer<vtkMetaImageReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  vtkNew<Collector> errors;
  errors->Watch(reader);
  errors->Watch(reader->GetExecutive());
  reader->Update();
  vtkImageData* image = vtkImageData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!errors->Messages.empty() || !image || image->GetNumberOfPoints() == 0)
  {
    return "Cannot read volume " + path + ": " +
      (errors->Messages.empty() ? std::string("no data") : errors->Messages);
  }
  output->ShallowCopy(image);
  return "";
}

// A volume file (not a directory or prefix).
std::string ReadFile(const std::string& path, vtkImageData* output)
{
  if (!IsRegularFile(path))
  {
    return "Not a volume file: " + path;
  }
  const std::string ext = Extension(path);
  if (ext == ".nhdr" || ext == ".nrrd")
  {
    return ReadNrrd(path, output);
  }
  if (ext == ".vti" || ext == ".mhd" || ext == ".mha")
  {
    return ReadWithVTK(path, ext, output);
  }
  return "Unknown volume file extension \"" + ext + "\" of " + path +
    " (known: .vti .mhd .mha .nhdr .nrrd, a directory or a slice-series prefix)";
}
} // anonymous namespace

//------------------------------------------------------------------------------
std::string Extension(const std::string& path)
{
  return vtkDeepGISceneText::Lower(vtksys::SystemTools::GetFilenameLastExtension(path));
}

//------------------------------------------------------------------------------
bool IsVolumeExtension(const std::string& ext)
{
  return ext == ".vti" || ext == ".mhd" || ext == ".mha" || ext == ".nhdr" || ext == ".nrrd";
}

//------------------------------------------------------------------------------
std::string Read(const std::string& path, const RawSlices& raw, vtkImageData* output)
{
  if (vtksys::SystemTools::FileIsDirectory(path))
  {
    std::string file;
    const std::string why = FileInDirectory(path, file);
    return why.empty() ? Read(file, raw, output) : why;
  }
  if (vtksys::SystemTools::FileExists(path))
  {
    return ReadFile(path, output);
  }
  // A slice-series prefix: PREFIX.nhdr if there is one, else raw slices.
  if (IsRegularFile(path + ".nhdr"))
  {
    return ReadFile(path + ".nhdr", output);
  }
  if (!IsRegularFile(path + ".1"))
  {
    return "Volume not found: " + path + " (no such file, directory, or slice series " + path +
      ".1, " + path + ".2, ...)";
  }
  return ReadRawSlices(path, raw, output);
}

//------------------------------------------------------------------------------
std::string IsoSurface(vtkImageData* image, double isoValue, bool computeNormals,
  const std::string& path, vtkSmartPointer<vtkPolyData>& mesh)
{
  std::ostringstream why;
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  int dims[3];
  image->GetDimensions(dims);
  if (!scalars || dims[0] < 2 || dims[1] < 2 || dims[2] < 2)
  {
    why << "Volume " << path << " has no scalars or is not 3D (dimensions " << dims[0] << " x "
        << dims[1] << " x " << dims[2] << ")";
    return why.str();
  }
  double range[2];
  scalars->GetRange(range, 0);
  if (!(isoValue > range[0] && isoValue < range[1]))
  {
    why << "Iso-value " << isoValue << " is outside the data range of " << path << " [" << range[0]
        << ", " << range[1] << "]: the surface is empty";
    return why.str();
  }
  vtkNew<vtkFlyingEdges3D> iso;
  iso->SetInputData(image);
  iso->SetValue(0, isoValue);
  iso->SetComputeNormals(computeNormals);
  iso->ComputeGradientsOff();
  iso->ComputeScalarsOff();
  iso->Update();
  vtkPolyData* surface = iso->GetOutput();
  if (surface->GetNumberOfPolys() == 0)
  {
    why << "The iso-surface of " << path << " at " << isoValue << " is empty";
    return why.str();
  }
  mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(surface->GetPoints());
  mesh->SetPolys(surface->GetPolys());
  if (computeNormals && surface->GetPointData()->GetNormals())
  {
    mesh->GetPointData()->SetNormals(surface->GetPointData()->GetNormals());
  }
  return "";
}
}
