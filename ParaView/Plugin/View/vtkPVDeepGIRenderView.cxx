#include "vtkPVDeepGIRenderView.h"

#include "vtkDeepAmbientObscurancePass.h"
#include "vtkDeepGBufferPass.h"
#include "vtkDeepGIKeys.h"
#include "vtkDeepGIPass.h"
#include "vtkDeepRadiosityPass.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPVDeepGILayerExchange.h"
#include "vtkPVSynchronizedRenderer.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

vtkStandardNewMacro(vtkPVDeepGIRenderView);

//------------------------------------------------------------------------------
vtkPVDeepGIRenderView::vtkPVDeepGIRenderView() = default;

//------------------------------------------------------------------------------
// ParaView does not release the render pass it was given: the pass's OpenGL
// objects are released here, while the view's window still exists.
vtkPVDeepGIRenderView::~vtkPVDeepGIRenderView()
{
  this->GIPass->ReleaseGraphicsResources(this->GetRenderWindow());
  if (this->PassInstalled)
  {
    this->SynchronizedRenderers->SetRenderPass(nullptr);
  }
}

//------------------------------------------------------------------------------
void vtkPVDeepGIRenderView::SetPreset(int preset)
{
  this->GIPass->SetPreset(preset);
}

//------------------------------------------------------------------------------
int vtkPVDeepGIRenderView::GetPreset()
{
  return this->GIPass->GetPreset();
}

//------------------------------------------------------------------------------
void vtkPVDeepGIRenderView::SetAmbientObscurance(bool on)
{
  this->GIPass->SetAmbientObscurance(on);
}

//------------------------------------------------------------------------------
void vtkPVDeepGIRenderView::SetRadiosity(bool on)
{
  this->GIPass->SetRadiosity(on);
}

//------------------------------------------------------------------------------
void vtkPVDeepGIRenderView::SetReflections(bool on)
{
  this->GIPass->SetReflections(on);
}

//------------------------------------------------------------------------------
void vtkPVDeepGIRenderView::SetObscuranceRadius(double fraction)
{
  this->GIPass->GetAmbientObscurancePass()->SetAutomaticRadiusFraction(fraction);
}

//------------------------------------------------------------------------------
void vtkPVDeepGIRenderView::SetRadiosityRadius(double fraction)
{
  this->GIPass->GetRadiosityPass()->SetAutomaticRadiusFraction(fraction);
}

//------------------------------------------------------------------------------
vtkDeepGIPass* vtkPVDeepGIRenderView::GetDeepGIPass()
{
  return this->GIPass;
}

//------------------------------------------------------------------------------
const char* vtkPVDeepGIRenderView::GetLastFrameEffectsAsString()
{
  this->LastFrameEffects = this->UseDeepGI
    ? vtkDeepGIPass::GetEffectsAsString(this->GIPass->GetLastFrameEffects())
    : std::string("NONE");
  return this->LastFrameEffects.c_str();
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkPVDeepGIRenderView::GetLayerExchangeBytes()
{
  return this->LayerExchange->GetBytesSent();
}

//------------------------------------------------------------------------------
void vtkPVDeepGIRenderView::AboutToRenderOnLocalProcess(bool interactive)
{
  this->Superclass::AboutToRenderOnLocalProcess(interactive);
  this->InstallPass();
  this->LayerExchange->ResetBytesSent();
  const bool distributed = this->ConfigureDistribution();
  if (!interactive && this->UseDeepGI && this->ConvergeStills && !this->Converging)
  {
    this->ConvergeStill(distributed);
  }
}

//------------------------------------------------------------------------------
// The pass takes the place of vtkPVDefaultPass under ParaView's camera pass
// (vtkPVSynchronizedRenderer::SetupPasses), as vtkOSPRayPass does.
// vtkPVRenderView::Render has already configured ParaView's SSAO for this
// frame; it is switched off here because the deep G-buffer's obscurance
// replaces it.
void vtkPVDeepGIRenderView::InstallPass()
{
  if (this->UseDeepGI != this->PassInstalled)
  {
    this->SynchronizedRenderers->SetRenderPass(this->UseDeepGI ? this->GIPass.Get() : nullptr);
    this->PassInstalled = this->UseDeepGI;
  }
  if (this->UseDeepGI)
  {
    this->GetRenderer()->SetUseSSAO(false);
  }
}

//------------------------------------------------------------------------------
// What a distributed render needs (see the class description); returns
// whether this render is one. The scene's size comes from ParaView's
// geometry bounds on one process too, so that one process and several
// use the same lengths.
bool vtkPVDeepGIRenderView::ConfigureDistribution()
{
  vtkInformation* information = this->GetRenderer()->GetInformation();
  if (this->GeometryBounds.IsValid())
  {
    double bounds[6];
    this->GeometryBounds.GetBounds(bounds);
    information->Set(vtkDeepGIKeys::SCENE_BOUNDS(), bounds, 6);
  }
  else
  {
    information->Remove(vtkDeepGIKeys::SCENE_BOUNDS());
  }
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const bool distributed = this->UseDeepGI && controller &&
    controller->GetNumberOfProcesses() > 1 && this->SynchronizedRenderers->GetEnabled();
  this->GIPass->GetGBufferPass()->SetLayerExchange(
    distributed ? this->LayerExchange.Get() : nullptr);
  this->GIPass->SetAdaptiveLayers(!distributed);
  if (distributed)
  {
    this->SynchronizedRenderers->SetRenderEmptyImages(true);
  }
  return distributed;
}

//------------------------------------------------------------------------------
// Converge renders the window itself, before vtkPVRenderView::Render draws
// the final frame. Distributed, the frame count must be the same on every
// process: the tolerance is not tested (tolerance 0).
void vtkPVDeepGIRenderView::ConvergeStill(bool distributed)
{
  this->Converging = true;
  this->GIPass->Converge(
    this->GetRenderer(), this->ConvergeMaximumFrames, distributed ? 0.0 : this->ConvergeTolerance);
  this->Converging = false;
}

//------------------------------------------------------------------------------
void vtkPVDeepGIRenderView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "UseDeepGI: " << this->UseDeepGI << "\n";
  os << indent << "ConvergeStills: " << this->ConvergeStills << "\n";
  os << indent << "ConvergeMaximumFrames: " << this->ConvergeMaximumFrames << "\n";
  os << indent << "ConvergeTolerance: " << this->ConvergeTolerance << "\n";
  os << indent << "DeepGIPass:\n";
  this->GIPass->PrintSelf(os, indent.GetNextIndent());
}
