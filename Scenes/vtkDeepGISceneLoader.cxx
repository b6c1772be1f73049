#include "vtkDeepGISceneLoader.h"

#include "vtkAlgorithm.h"
#include "vtkCamera.h"
#include "vtkDeepGIOBJReader.h"
#include "vtkDeepGISceneFileChecks.h"
#include "vtkDeepGISceneLegacyVTK.h"
#include "vtkDeepGISceneLighting.h"
#include "vtkDeepGISceneMesh.h"
#include "vtkDeepGISceneMessages.h"
#include "vtkDeepGISceneVolumes.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cmath>
#include <functional>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkDeepGISceneLoader);

namespace
{
using vtkDeepGISceneFileChecks::IsRegularFile;
using vtkDeepGISceneMesh::Part;
using vtkDeepGISceneMessages::Collector;
using vtkDeepGISceneVolumes::Extension;
using vtkDeepGISceneVolumes::IsVolumeExtension;
} // anonymous namespace

class vtkDeepGISceneLoader::vtkInternals
{
public:
  std::vector<Part> Parts;
  vtkSmartPointer<vtkPolyData> Scene;
};

//------------------------------------------------------------------------------
vtkDeepGISceneLoader::vtkDeepGISceneLoader()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkDeepGISceneLoader::~vtkDeepGISceneLoader() = default;

//------------------------------------------------------------------------------
void vtkDeepGISceneLoader::Clear()
{
  this->Internals->Parts.clear();
  this->Internals->Scene = nullptr;
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkDeepGISceneLoader::IsVolumePath(const char* path)
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
bool vtkDeepGISceneLoader::Load(const char* path)
{
  return this->Guarded("Load", path, [&]() { return this->LoadUnguarded(path); });
}

//------------------------------------------------------------------------------
bool vtkDeepGISceneLoader::LoadUnguarded(const char* path)
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
bool vtkDeepGISceneLoader::LoadMesh(const char* fileName)
{
  return this->Guarded("LoadMesh", fileName, [&]() { return this->LoadMeshUnguarded(fileName); });
}

//------------------------------------------------------------------------------
bool vtkDeepGISceneLoader::LoadMeshUnguarded(const char* fileName)
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
  // Only regular files are read: a device (/dev/zero, /dev/urandom), FIFO
  // or directory would make a parser read forever or fail obscurely.
  if (!IsRegularFile(path))
  {
    vtkErrorMacro("Not a mesh file (a directory?): " << path);
    return false;
  }
  const std::string ext = Extension(path);
  if (ext == ".obj")
  {
    return this->LoadOBJ(path);
  }
  if (ext == ".vtk")
  {
    return this->LoadLegacyVTK(path);
  }
  if (ext == ".ply" || ext == ".stl" || ext == ".vtp")
  {
    return this->LoadWithVTKReader(path, ext);
  }
  if (IsVolumeExtension(ext))
  {
    vtkErrorMacro("" << path << " is a volume; load it with LoadVolume (or Load) and an iso-value");
    return false;
  }
  vtkErrorMacro("Unknown mesh file extension \"" << ext << "\" of " << path
                                                 << " (known: .ply .obj .vtp .vtk .stl)");
  return false;
}

//------------------------------------------------------------------------------
bool vtkDeepGISceneLoader::LoadLegacyVTK(const std::string& path)
{
  // The project's own parser, not vtkPolyDataReader (see vtkDeepGISceneLegacyVTK.h).
  vtkNew<vtkPolyData> legacy;
  const std::string why = vtkDeepGISceneLegacyVTK::Read(path, legacy);
  if (!why.empty())
  {
    vtkErrorMacro("Cannot read mesh " << path << ": " << why);
    return false;
  }
  vtkSmartPointer<vtkPolyData> mesh = this->PrepareMesh(legacy, path);
  if (mesh)
  {
    this->AddPart(mesh, vtksys::SystemTools::GetFilenameName(path), this->DefaultColor);
  }
  return mesh != nullptr;
}

//------------------------------------------------------------------------------
bool vtkDeepGISceneLoader::LoadWithVTKReader(const std::string& path, const std::string& ext)
{
  std::string invalid;
  vtkSmartPointer<vtkAlgorithm> reader =
    vtkDeepGISceneFileChecks::MakeMeshReader(path, ext, invalid);
  if (!invalid.empty())
  {
    vtkErrorMacro("Cannot read mesh " << path << ": " << invalid);
    return false;
  }
  // Warnings of the PLY and STL readers mean lost data (vtkSTLReader
  // guessing a binary file, vtkPLYReader missing properties); the XML
  // reader's do not.
  vtkNew<Collector> errors;
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
    vtkDeepGISceneMessages::ScopedOutputTrap trap;
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
  vtkSmartPointer<vtkPolyData> mesh = this->PrepareMesh(output, path);
  if (mesh)
  {
    this->AddPart(mesh, vtksys::SystemTools::GetFilenameName(path), this->DefaultColor);
  }
  return mesh != nullptr;
}

//------------------------------------------------------------------------------
bool vtkDeepGISceneLoader::LoadOBJ(const std::string& path)
{
  vtkNew<vtkDeepGIOBJReader> reader;
  reader->SetFileName(path.c_str());
  vtkNew<Collector> messages;
  messages->WatchAll(reader);
  reader->Update();
  if (!messages->Errors.empty())
  {
    vtkErrorMacro(<< messages->Errors.front());
    return false;
  }
  for (const std::string& warning : messages->Warnings)
  {
    vtkWarningMacro(<< warning);
  }
  // One part per material that PrepareMesh keeps.
  std::string unknownMaterials, materialFile;
  std::vector<Part> parts;
  for (Part& part : vtkDeepGISceneMesh::MaterialParts(reader->GetOutput(),
         vtksys::SystemTools::GetFilenameName(path), this->DefaultColor, unknownMaterials,
         materialFile))
  {
    part.PolyData = this->PrepareMesh(part.PolyData, path + " " + part.Name);
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
    vtkWarningMacro("OBJ " << path << " uses materials missing from " << materialFile << " ("
                           << unknownMaterials << "); they get the default colour");
  }
  for (const Part& part : parts)
  {
    this->AddPart(part.PolyData, part.Name, part.Color, part.Emission);
  }
  return true;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkDeepGISceneLoader::PrepareMesh(
  vtkPolyData* input, const std::string& what)
{
  const vtkDeepGISceneMesh::Prepared prepared =
    vtkDeepGISceneMesh::Prepare(input, what, this->ComputeNormals, this->FeatureAngle);
  for (const std::string& warning : prepared.Warnings)
  {
    vtkWarningMacro(<< warning);
  }
  if (!prepared.Mesh)
  {
    vtkErrorMacro(<< prepared.Error);
  }
  return prepared.Mesh;
}

//------------------------------------------------------------------------------
void vtkDeepGISceneLoader::AddPart(
  vtkPolyData* mesh, const std::string& name, const double color[3], const double emission[3])
{
  Part part;
  part.Name = name;
  std::copy(color, color + 3, part.Color);
  if (emission)
  {
    std::copy(emission, emission + 3, part.Emission);
  }
  part.PolyData = mesh;
  this->Internals->Parts.push_back(part);
  this->Internals->Scene = nullptr;
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkDeepGISceneLoader::LoadVolume(const char* path, double isoValue)
{
  return this->Guarded(
    "LoadVolume", path, [&]() { return this->LoadVolumeUnguarded(path, isoValue); });
}

//------------------------------------------------------------------------------
bool vtkDeepGISceneLoader::Guarded(
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
bool vtkDeepGISceneLoader::LoadVolumeUnguarded(const char* path, double isoValue)
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
  vtkDeepGISceneVolumes::RawSlices raw;
  std::copy(this->RawSliceSpacing, this->RawSliceSpacing + 3, raw.Spacing);
  raw.LittleEndian = this->RawSliceLittleEndian;
  const std::string why = vtkDeepGISceneVolumes::Read(path, raw, image);
  if (!why.empty())
  {
    vtkErrorMacro(<< why);
    return false;
  }
  vtkSmartPointer<vtkPolyData> mesh;
  const std::string empty =
    vtkDeepGISceneVolumes::IsoSurface(image, isoValue, this->ComputeNormals, path, mesh);
  if (!empty.empty())
  {
    vtkErrorMacro(<< empty);
    return false;
  }
  std::ostringstream name;
  name << vtksys::SystemTools::GetFilenameName(path) << "@" << isoValue;
  this->AddPart(mesh, name.str(), this->DefaultColor);
  return true;
}

//------------------------------------------------------------------------------
int vtkDeepGISceneLoader::GetNumberOfParts()
{
  return static_cast<int>(this->Internals->Parts.size());
}

//------------------------------------------------------------------------------
const char* vtkDeepGISceneLoader::GetPartName(int part)
{
  if (part < 0 || part >= this->GetNumberOfParts())
  {
    return nullptr;
  }
  return this->Internals->Parts[part].Name.c_str();
}

//------------------------------------------------------------------------------
void vtkDeepGISceneLoader::GetPartColor(int part, double rgb[3])
{
  const bool valid = part >= 0 && part < this->GetNumberOfParts();
  for (int i = 0; i < 3; ++i)
  {
    rgb[i] = valid ? this->Internals->Parts[part].Color[i] : 0.0;
  }
}

//------------------------------------------------------------------------------
void vtkDeepGISceneLoader::GetPartEmission(int part, double rgb[3])
{
  const bool valid = part >= 0 && part < this->GetNumberOfParts();
  for (int i = 0; i < 3; ++i)
  {
    rgb[i] = valid ? this->Internals->Parts[part].Emission[i] : 0.0;
  }
}

//------------------------------------------------------------------------------
vtkPolyData* vtkDeepGISceneLoader::GetPartPolyData(int part)
{
  if (part < 0 || part >= this->GetNumberOfParts())
  {
    return nullptr;
  }
  return this->Internals->Parts[part].PolyData;
}

//------------------------------------------------------------------------------
vtkIdType vtkDeepGISceneLoader::GetNumberOfTriangles()
{
  vtkIdType n = 0;
  for (const Part& part : this->Internals->Parts)
  {
    n += part.PolyData->GetNumberOfPolys();
  }
  return n;
}

//------------------------------------------------------------------------------
void vtkDeepGISceneLoader::GetBounds(double bounds[6])
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
vtkPolyData* vtkDeepGISceneLoader::GetScenePolyData()
{
  if (this->Internals->Parts.empty())
  {
    return nullptr;
  }
  if (!this->Internals->Scene)
  {
    this->Internals->Scene =
      vtkDeepGISceneMesh::Append(this->Internals->Parts, vtkDeepGISceneLighting::MaterialDiffuse);
  }
  return this->Internals->Scene;
}

//------------------------------------------------------------------------------
int vtkDeepGISceneLoader::Populate(vtkRenderer* renderer)
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
    renderer->AddActor(vtkDeepGISceneLighting::MakeActor(part));
    if (vtkDeepGISceneMesh::Brightest(part) > 0.0)
    {
      emitters = this->AddEmitterLight(renderer, index) || emitters;
    }
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
bool vtkDeepGISceneLoader::AddEmitterLight(vtkRenderer* renderer, int index)
{
  if (!renderer || index < 0 || index >= this->GetNumberOfParts())
  {
    vtkErrorMacro("AddEmitterLight: no renderer or no part " << index);
    return false;
  }
  double bounds[6];
  this->GetBounds(bounds);
  double diagonal = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    diagonal += (bounds[2 * c + 1] - bounds[2 * c]) * (bounds[2 * c + 1] - bounds[2 * c]);
  }
  vtkSmartPointer<vtkLight> light =
    vtkDeepGISceneLighting::EmitterLight(this->Internals->Parts[index], std::sqrt(diagonal));
  if (light)
  {
    renderer->AddLight(light);
  }
  return light != nullptr;
}

//------------------------------------------------------------------------------
void vtkDeepGISceneLoader::AddDefaultLight(vtkRenderer* renderer)
{
  if (!renderer)
  {
    vtkErrorMacro("AddDefaultLight: no renderer");
    return;
  }
  double bounds[6];
  this->GetBounds(bounds);
  vtkDeepGISceneLighting::AddDefaultLights(renderer, bounds, this->ViewUp);
}

//------------------------------------------------------------------------------
void vtkDeepGISceneLoader::ResetCamera(vtkRenderer* renderer)
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
void vtkDeepGISceneLoader::PrintSelf(ostream& os, vtkIndent indent)
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
