#include "vtkDeepScreenSpacePass.h"

#include "vtkDeepGBufferPass.h"
#include "vtkDeepScreenSpaceHelpers.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"

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
vtkDeepGIStageTimer* vtkDeepScreenSpacePass::GetStageTimer() const
{
  return this->GBufferPass->GetStageTimer();
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
bool vtkDeepScreenSpacePass::BeginEffectFrame(
  const vtkRenderState* s, const char* caller, double shadedFraction, EffectFrame& frame)
{
  frame.State = s;
  frame.Renderer = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  frame.Window = vtkOpenGLRenderWindow::SafeDownCast(
    frame.Renderer ? frame.Renderer->GetRenderWindow() : nullptr);
  if (!frame.Window)
  {
    vtkErrorMacro(<< caller << ": an OpenGL renderer and render window are needed.");
    return false;
  }
  frame.GL = frame.Window->GetState();
  if (!this->GetLayerFrame(frame.Renderer, caller, frame))
  {
    return false;
  }
  vtkDeepScreenSpace::ShadedRegion(frame.Size, frame.GuardBand, shadedFraction, frame.Region);
  vtkDeepScreenSpace::ProjectionUniforms(frame.Projection, frame.ProjXY, frame.ProjT);
  return true;
}

//------------------------------------------------------------------------------
double vtkDeepScreenSpacePass::RotationOffset(unsigned long long frameIndex)
{
  const double goldenRatioConjugate = 0.6180339887498949;
  const double f = goldenRatioConjugate * static_cast<double>(frameIndex % 1000003u);
  return 2.0 * vtkMath::Pi() * (f - std::floor(f));
}

//------------------------------------------------------------------------------
void vtkDeepScreenSpacePass::SetLayerUniforms(
  vtkShaderProgram* program, const EffectFrame& frame, int distanceUnit, int normalUnit)
{
  program->SetUniformi("deepDistance", distanceUnit);
  if (normalUnit >= 0)
  {
    program->SetUniformi("deepNormal", normalUnit);
  }
  program->SetUniform4f("deepProjXY", frame.ProjXY);
  program->SetUniform4f("deepProjT", frame.ProjT);
}

//------------------------------------------------------------------------------
void vtkDeepScreenSpacePass::SetKeyUniforms(
  vtkShaderProgram* program, int keyUnit, const float projXY[4], const float projT[4])
{
  program->SetUniformi("deepKey", keyUnit);
  program->SetUniform4f("deepProjXY", projXY);
  program->SetUniform4f("deepProjT", projT);
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
    vtkWarningMacro(<< name << " must be within [0, 1] (got " << fraction << "); using " << clamped
                    << ".");
    fraction = clamped;
  }
  if (fraction != value)
  {
    value = fraction;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkDeepScreenSpacePass::RenderLayersOrWarn(const vtkRenderState* s, const char* effect)
{
  if (this->GBufferPass->RenderLayers(s))
  {
    return true;
  }
  if (!s->GetRenderer()->GetSelector() && !this->WarnedLayersUnavailable)
  {
    this->WarnedLayersUnavailable = true;
    vtkWarningMacro("The deep G-buffer is unavailable; rendering without " << effect << ".");
  }
  return false;
}

//------------------------------------------------------------------------------
vtkOpenGLState* vtkDeepScreenSpacePass::BeginCapture(
  vtkRenderer* renderer, const char* caller, unsigned int& distanceHandle)
{
  distanceHandle = this->GBufferPass->GetTextureHandle(renderer, vtkDeepGBufferPass::DEPTH);
  if (!distanceHandle)
  {
    vtkErrorMacro(<< caller << ": the G-buffer of this renderer is gone.");
    return nullptr;
  }
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  window->MakeCurrent();
  vtkOpenGLClearErrorMacro();
  return window->GetState();
}

//------------------------------------------------------------------------------
void vtkDeepScreenSpacePass::SetSampleCount(int samples, int& value)
{
  const int maximum = MAXIMUM_NUMBER_OF_SAMPLES;
  if (samples < 1 || samples > maximum)
  {
    const int clamped = std::min(std::max(samples, 1), maximum);
    vtkWarningMacro("NumberOfSamples "
      << samples << " is outside 1.." << maximum
      << " (the paper's Listing 3 gives spiral turns for N = 1..98); using " << clamped << ".");
    samples = clamped;
  }
  if (samples != value)
  {
    value = samples;
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
