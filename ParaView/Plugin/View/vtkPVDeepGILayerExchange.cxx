#include "vtkPVDeepGILayerExchange.h"

#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"

#include <cstdint>
#include <cstring>

vtkStandardNewMacro(vtkPVDeepGILayerExchange);
vtkCxxSetObjectMacro(vtkPVDeepGILayerExchange, Controller, vtkMultiProcessController);

//------------------------------------------------------------------------------
vtkPVDeepGILayerExchange::~vtkPVDeepGILayerExchange()
{
  this->SetController(nullptr);
}

//------------------------------------------------------------------------------
bool vtkPVDeepGILayerExchange::CompositeLayer(vtkIdType pixels, std::vector<float>& depth,
  std::vector<unsigned char>& attributes, int bytesPerPixel)
{
  vtkMultiProcessController* controller =
    this->Controller ? this->Controller : vtkMultiProcessController::GetGlobalController();
  if (!controller || controller->GetNumberOfProcesses() < 2)
  {
    return true;
  }
  const vtkTypeUInt64 process = static_cast<vtkTypeUInt64>(controller->GetLocalProcessId());

  // 1. The nearest process per pixel.
  std::vector<unsigned long long> keys(pixels);
  std::vector<unsigned long long> nearest(pixels);
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &depth[p], sizeof(bits));
    keys[p] = (static_cast<unsigned long long>(bits) << 32) | process;
  }
  if (!controller->AllReduce(keys.data(), nearest.data(), pixels, vtkCommunicator::MIN_OP))
  {
    return false;
  }

  // 2. The nearest process's depth and record.
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    const std::uint32_t bits = static_cast<std::uint32_t>(nearest[p] >> 32);
    std::memcpy(&depth[p], &bits, sizeof(bits));
    if ((nearest[p] & 0xffffffffULL) != process)
    {
      std::memset(attributes.data() + p * bytesPerPixel, 0, bytesPerPixel);
    }
  }
  std::vector<unsigned char> owned(attributes.size());
  if (!controller->AllReduce(attributes.data(), owned.data(),
        static_cast<vtkIdType>(attributes.size()), vtkCommunicator::MAX_OP))
  {
    return false;
  }
  attributes.swap(owned);
  this->BytesSent += static_cast<vtkTypeInt64>(pixels) * (8 + bytesPerPixel);
  return true;
}

//------------------------------------------------------------------------------
void vtkPVDeepGILayerExchange::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller << "\n";
}
