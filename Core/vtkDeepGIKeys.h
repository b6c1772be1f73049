/**
 * @class   vtkDeepGIKeys
 * @brief   Information keys the DeepGI modules share, with no OpenGL.
 *
 * Keys set on props and renderers by scene content (DeepGI::Scenes) and
 * applications, and read by the render passes
 * (DeepGI::RenderingDeepGBuffer), kept here so that scene content does not
 * depend on rendering.
 *
 * EMISSIVE (integer, on a prop's PropertyKeys, vtkProp::SetPropertyKeys):
 * 1 marks VTK's ambient term of the prop (Ambient x AmbientColor) as light
 * the surface emits, e.g. a lamp drawn with Ambient 1, AmbientColor the
 * lamp's colour and Diffuse 0. The deep G-buffer keeps such a prop's
 * ambient term in RADIANCE and out of AMBIENT, so radiosity gathers it as
 * emitted light and ambient obscurance does not darken it. Without the key
 * (or 0) the ambient term is the environment's light, as VTK's lighting
 * treats it. vtkDeepGBufferPass::EMISSIVE() is the same key.
 *
 * SCENE_BOUNDS (6 doubles, on a renderer's vtkViewport::GetInformation):
 * the bounds of the whole scene, for a renderer that draws only part of it,
 * such as one process of a distributed render (ParaView's pvbatch under MPI
 * sets the global bounds on every process). Every automatic length of the
 * passes (radii, minimum separation, reflection distance) is a fraction of
 * the scene's bounding-box diagonal: with the key it is the diagonal of
 * these bounds, so that every process uses the same lengths; without it,
 * that of the renderer's visible props.
 */

#ifndef vtkDeepGIKeys_h
#define vtkDeepGIKeys_h

#include "vtkDeepGICoreModule.h" // for export macro
#include "vtkObject.h"

class vtkInformationDoubleVectorKey;
class vtkInformationIntegerKey;

class VTKDEEPGICORE_EXPORT vtkDeepGIKeys : public vtkObject
{
public:
  static vtkDeepGIKeys* New();
  vtkTypeMacro(vtkDeepGIKeys, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// A prop's ambient term is emitted light (see the class description).
  static vtkInformationIntegerKey* EMISSIVE();

  /// The whole scene's bounds, on a renderer (see the class description).
  static vtkInformationDoubleVectorKey* SCENE_BOUNDS();

protected:
  vtkDeepGIKeys() = default;
  ~vtkDeepGIKeys() override = default;

private:
  vtkDeepGIKeys(const vtkDeepGIKeys&) = delete;
  void operator=(const vtkDeepGIKeys&) = delete;
};

#endif
