/**
 * @file   vtkDeepGISceneVolumes.h
 * @brief  The volume files vtkDeepGISceneLoader iso-surfaces, and how each
 *         is read (private to DeepGI::Scenes).
 *
 * A volume path is a .vti (vtkXMLImageDataReader), .mhd or .mha
 * (vtkMetaImageReader), .nhdr or .nrrd (vtkDeepGINrrdReader) file, a
 * directory holding exactly one of them, or a slice-series prefix
 * (PREFIX.nhdr if it exists, else the raw 16-bit slices PREFIX.1,
 * PREFIX.2, ... read by vtkVolume16Reader).
 */

#ifndef vtkDeepGISceneVolumes_h
#define vtkDeepGISceneVolumes_h

#include "vtkSmartPointer.h"

#include <string>

class vtkImageData;
class vtkPolyData;

namespace vtkDeepGISceneVolumes
{
/// The extension of `path`, lower case, with its dot ("" if none).
std::string Extension(const std::string& path);

/// Whether `extension` (as Extension gives it) is that of a volume file.
bool IsVolumeExtension(const std::string& extension);

/// How raw slices without a header are read.
struct RawSlices
{
  double Spacing[3] = { 1.0, 1.0, 1.0 };
  bool LittleEndian = true;
};

/**
 * Reads the volume `path` into `output`. Returns "" on success, else one
 * sentence saying why it cannot be read.
 */
std::string Read(const std::string& path, const RawSlices& raw, vtkImageData* output);

/**
 * The iso-surface of `image` at `isoValue` (vtkFlyingEdges3D; normals from
 * the gradient when `computeNormals`) into `mesh`: its points, triangles
 * and normals. Returns "" on success, else why the surface is empty (no
 * scalars, not 3D, an iso-value outside the data). `path` names the volume
 * in the message.
 */
std::string IsoSurface(vtkImageData* image, double isoValue, bool computeNormals,
  const std::string& path, vtkSmartPointer<vtkPolyData>& mesh);
}

#endif
// VTK-HeaderTest-Exclude: vtkDeepGISceneVolumes.h
