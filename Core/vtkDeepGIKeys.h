/**
 * @class   vtkDeepGIKeys
 * @brief   Information keys the DeepGI modules share, with no OpenGL.
 *
 * Keys set on props by scene content (DeepGI::Scenes) and read by the render
 * passes (DeepGI::RenderingDeepGBuffer), kept here so that scene content
 * does not depend on rendering.
 *
 * EMISSIVE (integer, on a prop's PropertyKeys, vtkProp::SetPropertyKeys):
 * 1 marks VTK's ambient term of the prop (Ambient x AmbientColor) as light
 * the surface emits, e.g. a lamp drawn with Ambient 1, AmbientColor the
 * lamp's colour and Diffuse 0. The deep G-buffer keeps such a prop's
 * ambient term in RADIANCE and out of AMBIENT, so radiosity gathers it as
 * emitted light and ambient obscurance does not darken it. Without the key
 * (or 0) the ambient term is the environment's light, as VTK's lighting
 * treats it. vtkDeepGBufferPass::EMISSIVE() is the same key.
 */

#ifndef vtkDeepGIKeys_h
#define vtkDeepGIKeys_h

#include "vtkDeepGICoreModule.h" // for export macro
#include "vtkObject.h"

class vtkInformationIntegerKey;

class VTKDEEPGICORE_EXPORT vtkDeepGIKeys : public vtkObject
{
public:
  static vtkDeepGIKeys* New();
  vtkTypeMacro(vtkDeepGIKeys, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// A prop's ambient term is emitted light (see the class description).
  static vtkInformationIntegerKey* EMISSIVE();

protected:
  vtkDeepGIKeys() = default;
  ~vtkDeepGIKeys() override = default;

private:
  vtkDeepGIKeys(const vtkDeepGIKeys&) = delete;
  void operator=(const vtkDeepGIKeys&) = delete;
};

#endif
