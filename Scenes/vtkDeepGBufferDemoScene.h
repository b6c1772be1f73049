/**
 * @class   vtkDeepGBufferDemoScene
 * @brief   The procedural demo room under its former name.
 *
 * @deprecated Use vtkDeepGIDemoScene; this name stays for one release
 * (removed in the next release). It is a subclass that adds nothing, so C++
 * and Python code written for it (`vtkDeepGBufferDemoScene()`) keeps
 * working.
 */

#ifndef vtkDeepGBufferDemoScene_h
#define vtkDeepGBufferDemoScene_h

#include "vtkDeepGIDemoScene.h"
#include "vtkDeepGIScenesModule.h" // for export macro

class VTKDEEPGISCENES_EXPORT vtkDeepGBufferDemoScene : public vtkDeepGIDemoScene
{
public:
  static vtkDeepGBufferDemoScene* New();
  vtkTypeMacro(vtkDeepGBufferDemoScene, vtkDeepGIDemoScene);

protected:
  vtkDeepGBufferDemoScene() = default;
  ~vtkDeepGBufferDemoScene() override = default;

private:
  vtkDeepGBufferDemoScene(const vtkDeepGBufferDemoScene&) = delete;
  void operator=(const vtkDeepGBufferDemoScene&) = delete;
};

#endif
