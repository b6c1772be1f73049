#include "vtkDeepGIKeys.h"

#include "vtkInformationIntegerKey.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkDeepGIKeys);
vtkInformationKeyMacro(vtkDeepGIKeys, EMISSIVE, Integer);

//------------------------------------------------------------------------------
void vtkDeepGIKeys::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
