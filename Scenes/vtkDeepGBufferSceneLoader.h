/**
 * @class   vtkDeepGBufferSceneLoader
 * @brief   The scene loader under its former name.
 *
 * @deprecated Use vtkDeepGISceneLoader; this name stays for one release
 * (removed in the next release). It is a subclass that adds nothing, so C++
 * and Python code written for it (`vtkDeepGBufferSceneLoader()`) keeps
 * working.
 */

#ifndef vtkDeepGBufferSceneLoader_h
#define vtkDeepGBufferSceneLoader_h

#include "vtkDeepGISceneLoader.h"
#include "vtkDeepGIScenesModule.h" // for export macro

class VTKDEEPGISCENES_EXPORT vtkDeepGBufferSceneLoader : public vtkDeepGISceneLoader
{
public:
  static vtkDeepGBufferSceneLoader* New();
  vtkTypeMacro(vtkDeepGBufferSceneLoader, vtkDeepGISceneLoader);

protected:
  vtkDeepGBufferSceneLoader() = default;
  ~vtkDeepGBufferSceneLoader() override = default;

private:
  vtkDeepGBufferSceneLoader(const vtkDeepGBufferSceneLoader&) = delete;
  void operator=(const vtkDeepGBufferSceneLoader&) = delete;
};

#endif
