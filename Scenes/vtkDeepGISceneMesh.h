/**
 * @file   vtkDeepGISceneMesh.h
 * @brief  The parts of vtkDeepGISceneLoader and how a reader's mesh becomes
 *         one (private to DeepGI::Scenes).
 */

#ifndef vtkDeepGISceneMesh_h
#define vtkDeepGISceneMesh_h

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkPolyData;

namespace vtkDeepGISceneMesh
{
/// One part of a loaded scene: a named triangle mesh with its material.
struct Part
{
  std::string Name;
  double Color[3] = { 0.0, 0.0, 0.0 };    // diffuse albedo, RGB 0-1
  double Emission[3] = { 0.0, 0.0, 0.0 }; // MTL Ke, radiance
  vtkSmartPointer<vtkPolyData> PolyData;
};

/// The brightest component of a part's emission (0 for non-emitters).
double Brightest(const Part& part);

/// What Prepare makes of a reader's mesh.
struct Prepared
{
  /// The triangles; nullptr when nothing usable is left (then Error says why).
  vtkSmartPointer<vtkPolyData> Mesh;
  std::string Error;
  /// What was dropped, in the order it was found.
  std::vector<std::string> Warnings;
};

/**
 * The triangles of `input` as a part holds them: only points, polygons,
 * strips and finite point normals are kept; cells with point ids outside
 * the points, or using points with a NaN or infinite coordinate, are
 * dropped (a warning); polygons and strips become triangles, unused points
 * are dropped and none is merged. Without point normals, they are computed
 * when `computeNormals` (split at `featureAngle` degrees). `what` names the
 * mesh in the messages.
 */
Prepared Prepare(
  vtkPolyData* input, const std::string& what, bool computeNormals, double featureAngle);

/**
 * The faces of vtkDeepGIOBJReader's output whose "MaterialId" is `material`,
 * with the points they use (in the order of first use) and their normals.
 */
vtkSmartPointer<vtkPolyData> ExtractMaterial(vtkPolyData* mesh, int material);

/**
 * One part per material of vtkDeepGIOBJReader's output `mesh`, named
 * BASE:MATERIAL (BASE for the material ""), coloured with its Kd or
 * `defaultColor`, emitting its Ke, its polydata from ExtractMaterial (not
 * yet prepared). `unknown` lists the materials the MTL file `materialFile`
 * does not define.
 */
std::vector<Part> MaterialParts(vtkPolyData* mesh, const std::string& base,
  const double defaultColor[3], std::string& unknown, std::string& materialFile);

/**
 * All parts appended into one polydata, the arrays of
 * vtkDeepGISceneLoader::GetScenePolyData: cell data "Colors" and "PartId",
 * "Emission" and "Diffuse" when a part emits, and field data "Diffuse"
 * (`diffuse`, the actors' diffuse coefficient).
 */
vtkSmartPointer<vtkPolyData> Append(const std::vector<Part>& parts, double diffuse);
}

#endif
// VTK-HeaderTest-Exclude: vtkDeepGISceneMesh.h
