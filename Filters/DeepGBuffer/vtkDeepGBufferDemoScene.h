#ifndef vtkDeepGBufferDemoScene_h
#define vtkDeepGBufferDemoScene_h
#include "vtkDeepGIFiltersModule.h"
#include "vtkObject.h"
class VTKDEEPGIFILTERS_EXPORT vtkDeepGBufferDemoScene : public vtkObject
{
public:
  static vtkDeepGBufferDemoScene* New();
  vtkTypeMacro(vtkDeepGBufferDemoScene, vtkObject);
protected:
  vtkDeepGBufferDemoScene() = default;
  ~vtkDeepGBufferDemoScene() override = default;
private:
  vtkDeepGBufferDemoScene(const vtkDeepGBufferDemoScene&) = delete;
  void operator=(const vtkDeepGBufferDemoScene&) = delete;
};
#endif
