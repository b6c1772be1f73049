#include "vtkDeepGIKeys.h"

#include "vtkInformationDoubleVectorKey.h"
#include "vtkInformationIntegerKey.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkDeepGIKeys);
vtkInformationKeyMacro(vtkDeepGIKeys, EMISSIVE, Integer);
vtkInformationKeyRestrictedMacro(vtkDeepGIKeys, SCENE_BOUNDS, DoubleVector, 6);

//------------------------------------------------------------------------------
void vtkDeepGIKeys::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
