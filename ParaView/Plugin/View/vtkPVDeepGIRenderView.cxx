#include "vtkPVDeepGIRenderView.h"

#include "vtkDeepAmbientObscurancePass.h"
#include "vtkDeepGIPass.h"
#include "vtkDeepRadiosityPass.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
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
void vtkPVDeepGIRenderView::AboutToRenderOnLocalProcess(bool interactive)
{
  this->Superclass::AboutToRenderOnLocalProcess(interactive);
  this->InstallPass();
  if (!interactive && this->UseDeepGI && this->ConvergeStills && !this->Converging)
  {
    this->ConvergeStill();
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
// Converge renders the window itself, before vtkPVRenderView::Render draws
// the final frame. The tolerance test reads back this process's image, so
// with several processes the ranks could stop after different numbers of
// frames and leave IceT's compositing waiting: there the still is rendered
// as one frame, with one warning per view.
void vtkPVDeepGIRenderView::ConvergeStill()
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    if (!this->WarnedConvergeWithProcesses)
    {
      vtkWarningMacro("ConvergeStills is not available with "
        << controller->GetNumberOfProcesses() << " processes yet; stills show single frames.");
      this->WarnedConvergeWithProcesses = true;
    }
    return;
  }
  this->Converging = true;
  this->GIPass->Converge(this->GetRenderer(), this->ConvergeMaximumFrames, this->ConvergeTolerance);
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
