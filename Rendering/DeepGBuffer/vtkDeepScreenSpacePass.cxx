#include "vtkDeepScreenSpacePass.h"

#include "vtkDeepGBufferPass.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <cmath>

//------------------------------------------------------------------------------
// The opaque step handed to vtkDeepGBufferPass::RenderFrame: calls back into
// the owner, so that the camera, clear, lights and the translucent,
// volumetric and overlay steps stay the G-buffer pass's.
class vtkDeepScreenSpacePass::vtkOpaqueStep : public vtkRenderPass
{
public:
  static vtkOpaqueStep* New();
  vtkTypeMacro(vtkOpaqueStep, vtkRenderPass);
  vtkDeepScreenSpacePass* Owner = nullptr;
  void Render(const vtkRenderState* s) override
  {
    this->NumberOfRenderedProps = 0;
    if (this->Owner)
    {
      this->Owner->RenderOpaque(s);
    }
  }

protected:
  vtkOpaqueStep() = default;
  ~vtkOpaqueStep() override = default;

private:
  vtkOpaqueStep(const vtkOpaqueStep&) = delete;
  void operator=(const vtkOpaqueStep&) = delete;
};
vtkStandardNewMacro(vtkDeepScreenSpacePass::vtkOpaqueStep);

//------------------------------------------------------------------------------
vtkDeepScreenSpacePass::vtkDeepScreenSpacePass()
{
  this->GBufferPass = vtkDeepGBufferPass::New();
  this->OpaqueStep = vtkOpaqueStep::New();
  this->OpaqueStep->Owner = this;
}

//------------------------------------------------------------------------------
vtkDeepScreenSpacePass::~vtkDeepScreenSpacePass()
{
  this->OpaqueStep->Owner = nullptr;
  this->OpaqueStep->Delete();
  this->GBufferPass->Delete();
}

//------------------------------------------------------------------------------
void vtkDeepScreenSpacePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GBufferPass: " << this->GBufferPass << "\n";
}

//------------------------------------------------------------------------------
void vtkDeepScreenSpacePass::SetGBufferPass(vtkDeepGBufferPass* pass)
{
  if (!pass)
  {
    vtkWarningMacro("SetGBufferPass(nullptr) ignored: the pass needs a G-buffer.");
    return;
  }
  if (pass == this->GBufferPass)
  {
    return;
  }
  pass->Register(this);
  this->GBufferPass->UnRegister(this);
  this->GBufferPass = pass;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkDeepScreenSpacePass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  this->GBufferPass->RenderFrame(s, this->OpaqueStep);
  this->NumberOfRenderedProps = this->GBufferPass->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
bool vtkDeepScreenSpacePass::GetLayerFrame(
  vtkRenderer* renderer, const char* caller, LayerFrame& frame)
{
  frame.Layers = this->GBufferPass->GetLayerCamera(renderer, frame.View, frame.Projection);
  if (frame.Layers <= 0 ||
    !this->GBufferPass->GetLayerExtent(renderer, frame.Size, frame.GuardBand))
  {
    vtkErrorMacro(<< caller
                  << ": the G-buffer pass has no layers for this renderer; call "
                     "GetGBufferPass()->RenderLayers first.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkDeepScreenSpacePass::SetFraction(const char* name, double fraction, double& value)
{
  if (std::isnan(fraction))
  {
    vtkWarningMacro(<< name << " must be a number (got NaN); keeping " << value << ".");
    return;
  }
  if (fraction < 0.0 || fraction > 1.0)
  {
    const double clamped = std::min(std::max(fraction, 0.0), 1.0);
    vtkWarningMacro(<< name << " must be within [0, 1] (got " << fraction << "); using "
                    << clamped << ".");
    fraction = clamped;
  }
  if (fraction != value)
  {
    value = fraction;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkDeepScreenSpacePass::SetManualLength(const char* name, double length, double& value,
  bool& automatic, bool allowInfinity, const char* atZero)
{
  if (std::isnan(length) || (!allowInfinity && std::isinf(length)))
  {
    vtkWarningMacro(<< name << " " << length << " is not "
                    << (allowInfinity ? "a number" : "finite") << "; keeping " << value << ".");
    return;
  }
  if (length < 0.0)
  {
    vtkWarningMacro(<< name << " " << length << " is negative; using 0" << atZero << ".");
    length = 0.0;
  }
  if (length != value || automatic)
  {
    value = length;
    automatic = false;
    this->Modified();
  }
}
