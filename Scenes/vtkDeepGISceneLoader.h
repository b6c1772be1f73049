/**
 * @class   vtkDeepGISceneLoader
 * @brief   Loads a user's meshes and iso-surfaces of volumes into a renderer.
 *
 * Each successful Load adds one or more parts (a triangle vtkPolyData with a
 * name and a diffuse colour); Populate() puts one actor per part on a
 * renderer, with the lighting the deep G-buffer expects (Ambient 0.1,
 * Diffuse 0.9, Specular 0).
 *
 * Meshes (by extension, case-insensitive):
 * - .ply (vtkPLYReader), .stl (vtkSTLReader), .vtp (vtkXMLPolyDataReader),
 *   .vtk (legacy polydata, read by the project's own parser,
 *   vtkDeepGISceneLegacyVTK.h: VTK 9.1's vtkPolyDataReader reads out of
 *   bounds on malformed cell lists). VTK 9.1's readers trust the counts a
 *   file declares, so the loader checks first (vtkDeepGISceneFileChecks.h):
 *   a PLY's header and every element, list counts and face indices
 *   included, must be in the file (a truncated PLY crashes vtkPLYReader); a
 *   binary STL must hold the triangles its header declares. Warnings of
 *   these readers count as errors (they mean lost data);
 * - .obj: read by vtkDeepGIOBJReader (the project's own parser: VTK 9.1's
 *   vtkOBJImporter resolves relative indices such as "f -4 -3 -2 -1" against
 *   a vertex count left over from the previous OBJ file of the process, and
 *   neither it nor vtkOBJReader checks indices). With an MTL file (the
 *   file's `mtllib`, else NAME.obj.mtl or NAME.mtl next to it): one part per
 *   material, in the order of first `usemtl`, coloured with the material's
 *   Kd (DefaultColor for faces without a material, materials without Kd or
 *   missing from the MTL file, with a warning for the latter) and emitting
 *   the material's Ke (emitters: see Populate); without one, a single part
 *   in DefaultColor. The reader's warnings (skipped faces, unusable MTL
 *   files) are the loader's; normals (`vn`) are kept when every corner of
 *   the file has one. Coincident vertices and faces stay as they are in the
 *   file.
 * Polygons and strips become triangles (vtkTriangleFilter); vertices, lines
 * and unused points are dropped; points are not merged. Polygons and strips
 * with point ids outside the mesh's points are dropped with a warning, and
 * so are points with a NaN or infinite coordinate, with the polygons using
 * them (one such point would make the bounds, the camera and the image
 * wrong). Meshes without point normals get them from vtkPolyDataNormals
 * (splitting at FeatureAngle) when ComputeNormals is on, computed once for
 * each set of coincident triangles (same points; its consistency walk is
 * cubic in their number), which all keep their place in the mesh; finite
 * normals stored in the file are kept.
 *
 * Volumes are iso-surfaced with vtkFlyingEdges3D at the iso-value given
 * (normals from the volume's gradient when ComputeNormals is on):
 * - .vti (vtkXMLImageDataReader), .mhd/.mha (vtkMetaImageReader);
 * - .nhdr/.nrrd: 3D volumes with raw encoding, attached or detached (a
 *   single data file, a `data file: PATTERN MIN MAX STEP` slice series or a
 *   LIST), read by vtkDeepGINrrdReader only (VTK 9.1's vtkNrrdReader
 *   overflows the heap or hangs on malformed headers). Data files must be regular files holding
 * what the sizes need; volumes over 4 GiB and other encodings (gzip, ascii, ...) are refused;
 * - a slice-series prefix such as .../headsq/quarter (files quarter.1,
 *   quarter.2, ...): PREFIX.nhdr is used if it exists, else the slices are
 *   read as square 16-bit images (size from the file size) with
 *   RawSliceSpacing and RawSliceLittleEndian (vtkVolume16Reader);
 * - a directory holding exactly one .nhdr, .nrrd, .mhd, .mha or .vti file.
 *
 * Only regular files are read (never devices, FIFOs or directories).
 * Errors (missing files, unknown extensions, unreadable, truncated or empty
 * data, an iso-value outside the data, running out of memory) are reported
 * with one vtkErrorMacro and the Load returns false, leaving the parts
 * loaded so far unchanged.
 */

#ifndef vtkDeepGISceneLoader_h
#define vtkDeepGISceneLoader_h

#include "vtkDeepGIScenesModule.h" // for export macro
#include "vtkDeepGISetGet.h"       // for vtkDeepGISetClampMacro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for the protected helpers

#include <functional> // for std::function
#include <memory>     // for std::unique_ptr
#include <string>     // for the protected helpers

class vtkImageData;
class vtkPolyData;
class vtkRenderer;

class VTKDEEPGISCENES_EXPORT vtkDeepGISceneLoader : public vtkObject
{
public:
  static vtkDeepGISceneLoader* New();
  vtkTypeMacro(vtkDeepGISceneLoader, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Loads `path` as a mesh or, for volume paths (see the class
   * description), as the iso-surface at IsoValue. Returns false on error.
   */
  bool Load(const char* path);

  /// Loads a mesh file (.ply, .obj, .vtp, .vtk, .stl). Returns false on error.
  bool LoadMesh(const char* fileName);

  /// Loads a volume and adds its iso-surface at `isoValue`. Returns false on error.
  bool LoadVolume(const char* path, double isoValue);

  /// Whether Load() would treat `path` as a volume (by extension or form).
  static bool IsVolumePath(const char* path);

  /// Forgets all parts.
  void Clear();

  ///@{
  /**
   * Iso-value used by Load() for volumes, in the volume's scalar units.
   * Default 500 (skin of the headsq CT data).
   *
   * @unit the volume's scalar units
   * @range any
   * @default 500
   */
  vtkSetMacro(IsoValue, double);
  vtkGetMacro(IsoValue, double);
  ///@}

  ///@{
  /**
   * Compute point normals for meshes that have none, and gradient normals
   * for iso-surfaces. Off leaves them without normals. Default on.
   * Normals stored in a file are kept.
   *
   * @range on/off
   * @default on
   */
  vtkSetMacro(ComputeNormals, bool);
  vtkGetMacro(ComputeNormals, bool);
  vtkBooleanMacro(ComputeNormals, bool);
  ///@}

  ///@{
  /**
   * Feature angle (degrees) where computed mesh normals are split, so hard
   * edges stay hard. Range 0 to 180. Default 30.
   *
   * @unit degrees
   * @range 0 to 180, clamped
   * @default 30
   */
  vtkDeepGISetClampMacro(FeatureAngle, double, 0.0, 180.0);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /**
   * Diffuse colour (RGB, 0-1) of parts without a material. Default
   * (0.8, 0.8, 0.8).
   *
   * @unit RGB 0-1
   * @default (0.8, 0.8, 0.8)
   */
  vtkSetVector3Macro(DefaultColor, double);
  vtkGetVector3Macro(DefaultColor, double);
  ///@}

  ///@{
  /**
   * For slice-series prefixes without a .nhdr: voxel spacing of the 16-bit
   * slices (default 1, 1, 1).
   *
   * @unit volume units
   * @default (1, 1, 1)
   */
  vtkSetVector3Macro(RawSliceSpacing, double);
  vtkGetVector3Macro(RawSliceSpacing, double);
  ///@}

  ///@{
  /**
   * For slice-series prefixes without a .nhdr: byte order of the 16-bit
   * slices (default little endian).
   *
   * @range on/off
   * @default on
   */
  vtkSetMacro(RawSliceLittleEndian, bool);
  vtkGetMacro(RawSliceLittleEndian, bool);
  vtkBooleanMacro(RawSliceLittleEndian, bool);
  ///@}

  ///@{
  /**
   * Whether Populate() also adds the default light (see AddDefaultLight).
   * Default on.
   *
   * @range on/off
   * @default on
   */
  vtkSetMacro(DefaultLight, bool);
  vtkGetMacro(DefaultLight, bool);
  vtkBooleanMacro(DefaultLight, bool);
  ///@}

  ///@{
  /**
   * Direction the camera looks along for ResetCamera(). Default (0, 0, -1):
   * looking down -z (with ViewUp's +y up), the usual frame of OBJ scenes
   * (Cornell boxes open towards +z). The headsq CT volume faces the camera
   * with (0, -1, 0) and view-up (0, 0, -1).
   *
   * @default (0, 0, -1)
   */
  vtkSetVector3Macro(ViewDirection, double);
  vtkGetVector3Macro(ViewDirection, double);
  ///@}

  ///@{
  /**
   * View-up of the camera for ResetCamera(). Default (0, 1, 0); the headsq
   * CT volume faces the camera with direction (0, -1, 0) and up (0, 0, -1).
   *
   * @default (0, 1, 0)
   */
  vtkSetVector3Macro(ViewUp, double);
  vtkGetVector3Macro(ViewUp, double);
  ///@}

  ///@{
  /**
   * The loaded parts: names ("bunny.ply", "CornellBox-Original.obj:leftWall",
   * "quarter.nhdr@500"), diffuse colours and triangle meshes (owned by the
   * loader). Out-of-range indices give nullptr and black.
   */
  int GetNumberOfParts();
  const char* GetPartName(int part);
  void GetPartColor(int part, double rgb[3]);
  /// Emitted radiance (MTL Ke, RGB, >= 0) of a part; 0 for non-emitters.
  void GetPartEmission(int part, double rgb[3]);
  vtkPolyData* GetPartPolyData(int part);
  ///@}

  /// Total number of triangles of all parts.
  vtkIdType GetNumberOfTriangles();

  /// Bounds of all parts (uninitialised bounds when nothing is loaded).
  void GetBounds(double bounds[6]);

  /**
   * All parts appended into one polydata with cell data "Colors" (unsigned
   * char RGB, the part's diffuse albedo) and "PartId" (int), field data
   * "Diffuse" (the actors' diffuse coefficient, 0.9), and point
   * "Normals" if every part has them. When a part emits (see Populate), the
   * cells also carry what Populate draws: "Emission" (float RGB, Ke / max(Ke)
   * on emitters, 0 elsewhere: the emitted radiance the deep G-buffer stores
   * for them, read by vtkDeepGIReferenceIrradiance) and "Diffuse" (float, 0
   * on emitters, 0.9 elsewhere). Owned by the loader; nullptr when nothing is
   * loaded.
   */
  vtkPolyData* GetScenePolyData();

  /**
   * Adds one actor per part (scalar colouring off, the part's colour,
   * Ambient 0.1, Diffuse 0.9, Specular 0) and, if DefaultLight is on, the
   * default light. Returns the number of actors added.
   *
   * Emitters (parts whose MTL material has a Ke > 0, e.g. the lamp of the
   * Cornell box) are drawn self-lit: Ambient 1 with AmbientColor
   * Ke / max(Ke), Diffuse 0, Specular 0, and the actor's PropertyKeys carry
   * vtkDeepGIKeys::EMISSIVE() = 1 (the key vtkDeepGBufferPass::EMISSIVE() reads), so their colour
   * enters the deep G-buffer's direct radiance (RADIANCE - AMBIENT) and with it the radiosity's
   * B(Y). Each emitter also gets a light (AddEmitterLight); a scene with emitters is lit by them
   * only (no default lights).
   */
  int Populate(vtkRenderer* renderer);

  /**
   * Adds the default lights: a white directional camera light (intensity
   * 0.6) from above left of the viewer, so that any model is lit on the side
   * it is seen from, and, when parts are loaded, a warm point light
   * (intensity 0.7, no attenuation) at the centre of their bounds moved 45 %
   * of the bounds' size along ViewUp, i.e. just below the top: a ceiling lamp
   * for rooms and Cornell boxes, a light from above for objects.
   */
  void AddDefaultLight(vtkRenderer* renderer);

  /**
   * Adds the VTK light that stands for the emitting part `part` (see
   * Populate): for a flat emitter of radiance Ke and area A, a positional
   * spot light 1e-4 of the scene's diagonal in front of its area-weighted
   * centroid, pointing along its normal (the triangles' winding), cone
   * angle 89 degrees, exponent 1 (the cos falloff of a Lambertian emitter),
   * attenuation 1 / d^2, colour Ke / max(Ke) and intensity max(Ke) A / pi
   * (VTK's diffuse term has no 1 / pi); for a curved one, a point light of
   * the same power (intensity max(Ke) A / (4 pi)). Returns false (and adds
   * nothing) for a part that emits nothing or has no area.
   */
  bool AddEmitterLight(vtkRenderer* renderer, int part);

  /**
   * Points the renderer's active camera along ViewDirection with ViewUp at
   * the loaded parts' bounds (all visible props when nothing is loaded),
   * fits them in view and resets the clipping range.
   */
  void ResetCamera(vtkRenderer* renderer);

protected:
  vtkDeepGISceneLoader();
  ~vtkDeepGISceneLoader() override;

  double IsoValue = 500.0;
  bool ComputeNormals = true;
  double FeatureAngle = 30.0;
  double DefaultColor[3] = { 0.8, 0.8, 0.8 };
  double RawSliceSpacing[3] = { 1.0, 1.0, 1.0 };
  bool RawSliceLittleEndian = true;
  bool DefaultLight = true;
  double ViewDirection[3] = { 0.0, 0.0, -1.0 };
  double ViewUp[3] = { 0.0, 1.0, 0.0 };

  bool LoadUnguarded(const char* path);
  bool LoadMeshUnguarded(const char* fileName);
  bool LoadVolumeUnguarded(const char* path, double isoValue);
  /// Runs `load`, turning std::bad_alloc and std::length_error into an error.
  bool Guarded(const char* what, const char* path, const std::function<bool()>& load);
  /// .obj through vtkDeepGIOBJReader: one part per material.
  bool LoadOBJ(const std::string& path);
  /// .vtk through the project's own legacy parser.
  bool LoadLegacyVTK(const std::string& path);
  /// .ply, .stl and .vtp through VTK's readers, after the file checks.
  bool LoadWithVTKReader(const std::string& path, const std::string& extension);
  /// A reader's mesh as a part holds it, its warnings and error reported; nullptr on error.
  vtkSmartPointer<vtkPolyData> PrepareMesh(vtkPolyData* input, const std::string& what);
  void AddPart(vtkPolyData* mesh, const std::string& name, const double color[3],
    const double emission[3] = nullptr);

private:
  vtkDeepGISceneLoader(const vtkDeepGISceneLoader&) = delete;
  void operator=(const vtkDeepGISceneLoader&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
