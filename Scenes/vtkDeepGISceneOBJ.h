/**
 * @file   vtkDeepGISceneOBJ.h
 * @brief  The OBJ/MTL reader of vtkDeepGBufferSceneLoader (private to DeepGI::Scenes).
 *
 * OBJ files are read by this parser rather than by vtkOBJImporter, whose
 * VTK 9.1 parser resolves relative (negative) vertex indices against a
 * function-static vertex count that is never reset: from the second OBJ
 * file a process imports on, "f -4 -3 -2 -1" points past the vertices
 * (out-of-bounds reads, garbage or empty parts). Neither the importer nor
 * vtkOBJReader checks indices against the vertex count at all.
 *
 * Read: `v`, `vn`, `f` (corners v, v/t, v/t/n or v//n), `usemtl` and
 * `mtllib`; the materials' Kd and Ke from the MTL file (the OBJ's `mtllib`,
 * else NAME.obj.mtl or NAME.mtl next to it). Faces indexing vertices the
 * file does not define are skipped with a warning (an error if none is
 * left). Lines longer than 1 MiB are refused; an MTL file is read only if
 * it is a regular file of at most 64 MiB.
 *
 * This is not a VTK algorithm: the loader reports every message of a load
 * as its own (observers of the loader see them, in the order they arise),
 * so the reader hands its messages back instead of raising them.
 */

#ifndef vtkDeepGISceneOBJ_h
#define vtkDeepGISceneOBJ_h

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkPolyData;

namespace vtkDeepGISceneOBJ
{
/// The faces of one material, with what the MTL file says about it.
struct Group
{
  /// "": the faces before any `usemtl`, or all faces when there is no MTL file.
  std::string Material;
  /**
   * The material's own points (vertex and normal pairs, never merged) and
   * polygons; point normals, normalized, when every corner has a usable one.
   */
  vtkSmartPointer<vtkPolyData> PolyData;
  /// Whether the MTL file gives the material a Kd (then Color holds it).
  bool HasColor = false;
  double Color[3] = { 0.0, 0.0, 0.0 };
  /// The material's Ke, negative components clamped to 0 (negative radiance is meaningless).
  double Emission[3] = { 0.0, 0.0, 0.0 };
  /// A material that the MTL file read does not define.
  bool Unknown = false;
};

/// What Read makes of an OBJ file.
struct Scene
{
  /// One group per material with faces, in the order of first use.
  std::vector<Group> Groups;
  /// The MTL file read; empty when there is none, or it could not be read.
  std::string MaterialFile;
  /// Warnings, in the order they arose (skipped faces, unusable MTL files).
  std::vector<std::string> Warnings;
};

/**
 * Reads the OBJ file `path` (and its MTL file) into `scene`. Returns an
 * empty string on success, else one sentence saying why it cannot be read.
 */
std::string Read(const std::string& path, Scene& scene);
}

#endif
// VTK-HeaderTest-Exclude: vtkDeepGISceneOBJ.h
