/**
 * The names of the arrays in the passes' captures, in one place.
 *
 * The passes copy what they rendered into a vtkImageData (a "capture"):
 * vtkDeepGBufferPass::CaptureLayers, vtkDeepAmbientObscurancePass::
 * CaptureAmbientVisibility and CaptureDistancePyramid,
 * vtkDeepRadiosityPass::CaptureIrradiance and
 * vtkDeepReflectionPass::CaptureReflections. The references, the OpenEXR
 * IO, the examples and the tests read those arrays by these names. No other
 * C++ file spells them as string literals (test deepgi-capture-names,
 * Testing/Architecture/CheckCaptureNames.cmake, reads the list below).
 *
 * Per-layer point-data arrays are named `<quantity>_<layer>` (Layer()):
 * "Depth_0", "Valid_1". Point data has one tuple per pixel of the frame
 * (the guard band cropped), except CaptureDistancePyramid's. Distances and
 * lengths are in world units.
 *
 * Keep one `constexpr const char* Name = "Name";` per line: the check reads
 * the names from these lines.
 */

#ifndef vtkDeepGICaptureNames_h
#define vtkDeepGICaptureNames_h

#include <string> // for Layer

namespace vtkDeepGICaptureNames
{
// -- Per-layer point data of CaptureLayers (name_j for layer j) --------------
/// RGBA float: the shaded colour of layer j (alpha 1 on a surface).
constexpr const char* Radiance = "Radiance";
/// RGB float in [0, 1]: the diffuse colour (albedo) of layer j.
constexpr const char* Albedo = "Albedo";
/// 3 floats: the decoded camera-space unit normal of layer j (0 where empty).
constexpr const char* Normal = "Normal";
/// RGB float: the part of Radiance_j from VTK's ambient term, so that
/// Radiance_j - Ambient_j is the direct radiance from the lights.
constexpr const char* Ambient = "Ambient";
/// float: camera-space distance of layer j's surface, world units; 0 where empty.
constexpr const char* Depth = "Depth";
/// RGB float in [0, 1]: the mirror reflectivity (CaptureLayers: layer j,
/// only while WriteReflectivity is on; CaptureReflections: unsuffixed,
/// layer 0's).
constexpr const char* Reflectivity = "Reflectivity";
/// unsigned char, 1 where the pixel has a surface (Valid_j: in layer j;
/// CaptureAmbientVisibility: unsuffixed, layer 0) or, in CaptureReflections
/// (unsuffixed), where a ray was traced.
constexpr const char* Valid = "Valid";

// -- Per-layer point data of CaptureIrradiance (j = 0, 1) --------------------
/// RGB float: irradiance E_t after the bilateral and temporal filters.
constexpr const char* Irradiance = "Irradiance";
/// RGB float: the indirect radiance L_ind (with the confidence fallback
/// when it is on).
constexpr const char* IndirectRadiance = "IndirectRadiance";
/// float in [0, 1]: filtered confidence M / N of the gather.
constexpr const char* Confidence = "Confidence";
/// RGB float: this frame's irradiance after the bilateral filter, before
/// the temporal one.
constexpr const char* FilteredIrradiance = "FilteredIrradiance";
/// RGB float: this frame's gathered irradiance (eq. 4) before any filter.
constexpr const char* RawIrradiance = "RawIrradiance";
/// float in [0, 1]: this frame's confidence M / N before any filter.
constexpr const char* RawConfidence = "RawConfidence";

// -- Per-layer point data of CaptureDistancePyramid -------------------------
/// float: camera-space distance of layer j at one pyramid level, world
/// units; 0 where empty. One tuple per texel of that level (guard band
/// included).
constexpr const char* Distance = "Distance";

// -- Point data of CaptureAmbientVisibility ---------------------------------
/// float in [0, 1]: ambient visibility after the bilateral filter (and the
/// temporal accumulation): what the image was composited with; 1 where empty.
constexpr const char* AmbientVisibility = "AmbientVisibility";
/// float in [0, 1]: ambient visibility of eq. 1 before any filter; 1 where empty.
constexpr const char* RawAmbientVisibility = "RawAmbientVisibility";

// -- Point data of CaptureReflections ---------------------------------------
/// RGB float: the reflected radiance L_r; 0 where no ray was traced.
constexpr const char* ReflectedRadiance = "ReflectedRadiance";
/// float: the layer a ray hit; -1 for the environment or no ray.
constexpr const char* HitLayer = "HitLayer";
/// float: the ray parameter t of the hit, world units; 0 where none.
constexpr const char* HitDistance = "HitDistance";

// -- Field data ----------------------------------------------------------------
/// 16 doubles, row-major: the frame's world-to-camera matrix (every capture
/// but CaptureDistancePyramid's).
constexpr const char* ViewMatrix = "ViewMatrix";
/// 16 doubles, row-major: the frame's camera-to-clip matrix (z in [-1, 1]).
constexpr const char* ProjectionMatrix = "ProjectionMatrix";
/// double: CaptureLayers' minimum separation dz between layers, world units.
constexpr const char* MinimumSeparation = "MinimumSeparation";
/// int: the number of layers rendered (CaptureLayers, CaptureIrradiance).
constexpr const char* NumberOfLayers = "NumberOfLayers";
/// string: CaptureLayers' oracle (vtkDeepGBufferPass::GetOracleAsString).
constexpr const char* Oracle = "Oracle";
/// double: the effective sampling radius r, world units
/// (CaptureAmbientVisibility, CaptureIrradiance).
constexpr const char* Radius = "Radius";
/// int: taps per pixel (CaptureAmbientVisibility, CaptureIrradiance).
constexpr const char* NumberOfSamples = "NumberOfSamples";
/// double: CaptureIrradiance's reprojection tolerance, world units.
constexpr const char* ReprojectionTolerance = "ReprojectionTolerance";
/// 3 doubles: CaptureIrradiance's environment irradiance (RGB).
constexpr const char* EnvironmentIrradiance = "EnvironmentIrradiance";
/// int: CaptureIrradiance's frames since the history was reset (1 for a
/// single bounce).
constexpr const char* Frames = "Frames";
/// double: CaptureReflections' maximum ray distance t_max, world units.
constexpr const char* MaximumDistance = "MaximumDistance";
/// double: CaptureReflections' surface thickness dz, world units.
constexpr const char* Thickness = "Thickness";
/// int: CaptureReflections' 1 when the frame traced rays, else 0.
constexpr const char* Traced = "Traced";
/// int: CaptureDistancePyramid's number of levels built (L + 1).
constexpr const char* NumberOfMipLevels = "NumberOfMipLevels";

/// The name of a per-layer array: `quantity` + "_" + `layer` ("Depth_0").
inline std::string Layer(const char* quantity, int layer)
{
  return std::string(quantity) + "_" + std::to_string(layer);
}
}

#endif
