#include "vtkDeepGBufferLayerExchange.h"

//------------------------------------------------------------------------------
void vtkDeepGBufferLayerExchange::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BytesSent: " << this->BytesSent << "\n";
}
