#include "vtkDeepGBufferSceneLoader.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkDeepGBufferSceneLoader);
