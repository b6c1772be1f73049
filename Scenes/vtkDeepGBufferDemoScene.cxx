#include "vtkDeepGBufferDemoScene.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkDeepGBufferDemoScene);
