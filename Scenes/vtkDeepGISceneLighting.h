/**
 * @file   vtkDeepGISceneLighting.h
 * @brief  The material and lights vtkDeepGISceneLoader gives its parts
 *         (private to DeepGI::Scenes).
 */

#ifndef vtkDeepGISceneLighting_h
#define vtkDeepGISceneLighting_h

#include "vtkDeepGISceneMesh.h"
#include "vtkSmartPointer.h"

class vtkActor;
class vtkLight;
class vtkRenderer;

namespace vtkDeepGISceneLighting
{
/// VTK's Ambient and Diffuse coefficients of every part that does not emit.
constexpr double MaterialAmbient = 0.1;
constexpr double MaterialDiffuse = 0.9;

/**
 * The actor of a part: scalar colouring off, the part's colour, Ambient
 * 0.1, Diffuse 0.9, Specular 0; an emitter (Ke > 0) self-lit with Ambient 1
 * in Ke / max(Ke), Diffuse 0 and the EMISSIVE key.
 */
vtkSmartPointer<vtkActor> MakeActor(const vtkDeepGISceneMesh::Part& part);

/**
 * The light standing for an emitting part in a scene of diagonal
 * `diagonal` (see vtkDeepGISceneLoader::AddEmitterLight); nullptr for a
 * part that emits nothing or has no area.
 */
vtkSmartPointer<vtkLight> EmitterLight(const vtkDeepGISceneMesh::Part& part, double diagonal);

/**
 * Adds the default lights (see vtkDeepGISceneLoader::AddDefaultLight): the
 * camera light, and when `bounds` are initialized the lamp below their top
 * along `viewUp`.
 */
void AddDefaultLights(vtkRenderer* renderer, const double bounds[6], const double viewUp[3]);
}

#endif
// VTK-HeaderTest-Exclude: vtkDeepGISceneLighting.h
