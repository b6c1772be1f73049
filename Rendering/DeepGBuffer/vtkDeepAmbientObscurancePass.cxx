#include "vtkDeepAmbientObscurancePass.h"

#include "vtkDeepGBufferPass.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkRenderState.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWeakPointer.h"
#include "vtk_glew.h"

#include "vtkDeepAmbientObscuranceBlurFS.h"
#include "vtkDeepAmbientObscuranceCommon.h"
#include "vtkDeepAmbientObscuranceCompositeFS.h"
#include "vtkDeepAmbientObscuranceFS.h"
#include "vtkDeepGBufferCommon.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkDeepAmbientObscurancePass);

//------------------------------------------------------------------------------
// The opaque step handed to vtkDeepGBufferPass::RenderFrame: calls back into
// the AO pass, so that the camera, clear, lights and the translucent,
// volumetric and overlay steps stay the G-buffer pass's.
class vtkDeepAmbientObscuranceOpaqueStep : public vtkRenderPass
{
public:
  static vtkDeepAmbientObscuranceOpaqueStep* New();
  vtkTypeMacro(vtkDeepAmbientObscuranceOpaqueStep, vtkRenderPass);
  vtkDeepAmbientObscurancePass* Owner = nullptr;
  void Render(const vtkRenderState* s) override
  {
    this->NumberOfRenderedProps = 0;
    if (this->Owner)
    {
      this->Owner->RenderOpaque(s);
    }
  }

protected:
  vtkDeepAmbientObscuranceOpaqueStep() = default;
  ~vtkDeepAmbientObscuranceOpaqueStep() override = default;

private:
  vtkDeepAmbientObscuranceOpaqueStep(const vtkDeepAmbientObscuranceOpaqueStep&) = delete;
  void operator=(const vtkDeepAmbientObscuranceOpaqueStep&) = delete;
};
vtkStandardNewMacro(vtkDeepAmbientObscuranceOpaqueStep);

namespace
{
// Mara et al. 2016, Listing 3: tau[N - 1] is the discrepancy-minimising
// number of spiral turns for N samples, N = 1..98.
const int SpiralTurns[vtkDeepAmbientObscurancePass::MAXIMUM_NUMBER_OF_SAMPLES] = { 1, 1, 2, 3,
  2, 5, 2, 3, 2, 3, 3, 5, 5, 3, 4, 7, 5, 5, 7, 9, 8, 5, 5, 7, 7, 7, 8, 5, 8, 11, 12, 7, 10, 13, 8,
  11, 8, 7, 14, 11, 11, 13, 12, 13, 19, 17, 13, 11, 18, 19, 11, 11, 14, 17, 21, 15, 16, 17, 18, 13,
  17, 11, 17, 19, 18, 25, 18, 19, 19, 29, 21, 19, 27, 31, 29, 21, 18, 17, 29, 31, 31, 23, 18, 25,
  26, 25, 23, 19, 34, 19, 27, 21, 25, 39, 29, 17, 21, 27 };

enum Target
{
  RAW = 0,
  BLUR_TEMP = 1,
  FILTERED = 2,
  NUMBER_OF_TARGETS = 3
};
}

//------------------------------------------------------------------------------
// The AO targets of one renderer.
struct vtkDeepAmbientObscuranceRendererState
{
  vtkWeakPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkTextureObject> Targets[NUMBER_OF_TARGETS];
  int Width = 0;
  int Height = 0;
  bool HasFrame = false;
  double Radius = 0.0;
  int NumberOfSamples = 0;

  void Release(vtkWindow* w)
  {
    for (auto& t : this->Targets)
    {
      if (t)
      {
        t->ReleaseGraphicsResources(w);
        t = nullptr;
      }
    }
    this->Width = this->Height = 0;
    this->HasFrame = false;
  }
};

class vtkDeepAmbientObscurancePass::vtkInternals
{
public:
  vtkDeepAmbientObscuranceOpaqueStep* OpaqueStep = nullptr;
  std::map<vtkRenderer*, std::unique_ptr<vtkDeepAmbientObscuranceRendererState>> States;
  vtkRenderer* FirstRenderer = nullptr;
  vtkOpenGLFramebufferObject* Framebuffer = nullptr;
  vtkOpenGLQuadHelper* AOQuad = nullptr;
  vtkOpenGLQuadHelper* BlurQuad = nullptr;
  vtkOpenGLQuadHelper* CompositeQuad = nullptr;
  bool WarnedUnsupported = false;

  vtkDeepAmbientObscuranceRendererState* Find(vtkRenderer* renderer)
  {
    auto it = this->States.find(renderer ? renderer : this->FirstRenderer);
    return (it == this->States.end() || !it->second->HasFrame) ? nullptr : it->second.get();
  }
};

//------------------------------------------------------------------------------
vtkDeepAmbientObscurancePass::vtkDeepAmbientObscurancePass()
  : Internals(new vtkInternals)
{
  this->GBufferPass = vtkDeepGBufferPass::New();
  this->Internals->OpaqueStep = vtkDeepAmbientObscuranceOpaqueStep::New();
  this->Internals->OpaqueStep->Owner = this;
}

//------------------------------------------------------------------------------
vtkDeepAmbientObscurancePass::~vtkDeepAmbientObscurancePass()
{
  vtkInternals& in = *this->Internals;
  if (in.AOQuad || in.Framebuffer || !in.States.empty())
  {
    vtkWarningMacro("Destroyed without ReleaseGraphicsResources(); OpenGL objects are leaked "
                    "unless the context was destroyed first.");
  }
  delete in.AOQuad;
  delete in.BlurQuad;
  delete in.CompositeQuad;
  if (in.Framebuffer)
  {
    in.Framebuffer->Delete();
  }
  in.OpaqueStep->Owner = nullptr;
  in.OpaqueStep->Delete();
  this->GBufferPass->Delete();
}

//------------------------------------------------------------------------------
void vtkDeepAmbientObscurancePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GBufferPass: " << this->GBufferPass << "\n";
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "AutomaticRadius: " << (this->AutomaticRadius ? "On" : "Off") << "\n";
  os << indent << "AutomaticRadiusFraction: " << this->AutomaticRadiusFraction << "\n";
  os << indent << "EffectiveRadius: " << this->EffectiveRadius << "\n";
  os << indent << "Bias: " << this->Bias << "\n";
  os << indent << "Epsilon: " << this->Epsilon << "\n";
  os << indent << "Intensity: " << this->Intensity << "\n";
  os << indent << "NumberOfSamples: " << this->NumberOfSamples
     << " (spiral turns " << GetSpiralTurns(this->NumberOfSamples) << ")\n";
  os << indent << "UseSecondLayer: " << (this->UseSecondLayer ? "On" : "Off") << "\n";
  os << indent << "BlurRadius: " << this->BlurRadius << "\n";
  os << indent << "BlurPlaneTolerance: " << this->BlurPlaneTolerance << "\n";
  os << indent << "BlurNormalPower: " << this->BlurNormalPower << "\n";
  os << indent << "Composition: "
     << (this->Composition == COMPOSITE_MULTIPLY ? "COMPOSITE_MULTIPLY" : "?") << "\n";
}

//------------------------------------------------------------------------------
int vtkDeepAmbientObscurancePass::GetSpiralTurns(int numberOfSamples)
{
  if (numberOfSamples < 1 || numberOfSamples > MAXIMUM_NUMBER_OF_SAMPLES)
  {
    return 0;
  }
  return SpiralTurns[numberOfSamples - 1];
}

//------------------------------------------------------------------------------
void vtkDeepAmbientObscurancePass::SetGBufferPass(vtkDeepGBufferPass* pass)
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
void vtkDeepAmbientObscurancePass::SetRadius(double radius)
{
  if (!std::isfinite(radius))
  {
    vtkWarningMacro("Radius " << radius << " is not finite; keeping " << this->Radius << ".");
    return;
  }
  if (radius < 0.0)
  {
    vtkWarningMacro("Radius " << radius << " is negative; using 0.");
    radius = 0.0;
  }
  if (radius != this->Radius || this->AutomaticRadius)
  {
    this->Radius = radius;
    this->AutomaticRadius = false;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkDeepAmbientObscurancePass::SetIntensity(double intensity)
{
  if (!std::isfinite(intensity))
  {
    vtkWarningMacro("Intensity " << intensity << " is not finite; keeping " << this->Intensity
                                 << ".");
    return;
  }
  if (intensity < 0.0)
  {
    vtkWarningMacro("Intensity " << intensity << " is negative; using 0 (no obscurance).");
    intensity = 0.0;
  }
  if (intensity != this->Intensity)
  {
    this->Intensity = intensity;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkDeepAmbientObscurancePass::SetNumberOfSamples(int samples)
{
  if (samples < 1 || samples > MAXIMUM_NUMBER_OF_SAMPLES)
  {
    const int clamped = std::min(std::max(samples, 1), static_cast<int>(MAXIMUM_NUMBER_OF_SAMPLES));
    vtkWarningMacro("NumberOfSamples "
      << samples << " is outside 1.." << MAXIMUM_NUMBER_OF_SAMPLES
      << " (the paper's Listing 3 gives spiral turns for N = 1..98); using " << clamped << ".");
    samples = clamped;
  }
  if (samples != this->NumberOfSamples)
  {
    this->NumberOfSamples = samples;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkDeepAmbientObscurancePass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  this->GBufferPass->RenderFrame(s, this->Internals->OpaqueStep);
  this->NumberOfRenderedProps = this->GBufferPass->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
namespace
{
bool ReadyQuad(vtkOpenGLQuadHelper*& quad, vtkOpenGLRenderWindow* window, const char* source)
{
  if (!quad)
  {
    std::string fs = source;
    vtkShaderProgram::Substitute(fs, "//VTK::DeepGBuffer::Common", vtkDeepGBufferCommon);
    vtkShaderProgram::Substitute(fs, "//VTK::DeepAO::Common", vtkDeepAmbientObscuranceCommon);
    quad = new vtkOpenGLQuadHelper(
      window, vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), fs.c_str(), "");
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(quad->Program);
  }
  return quad->Program && quad->Program->GetCompiled();
}

bool AllocateTarget(vtkSmartPointer<vtkTextureObject>& texture, vtkOpenGLRenderWindow* window,
  int width, int height)
{
  if (texture && texture->GetWidth() == static_cast<unsigned int>(width) &&
    texture->GetHeight() == static_cast<unsigned int>(height))
  {
    return true;
  }
  if (!texture)
  {
    texture = vtkSmartPointer<vtkTextureObject>::New();
    texture->SetContext(window);
    texture->SetInternalFormat(GL_R32F);
    texture->SetFormat(GL_RED);
    texture->SetDataType(GL_FLOAT);
    texture->SetMinificationFilter(vtkTextureObject::Nearest);
    texture->SetMagnificationFilter(vtkTextureObject::Nearest);
    texture->SetWrapS(vtkTextureObject::ClampToEdge);
    texture->SetWrapT(vtkTextureObject::ClampToEdge);
    return texture->Allocate2D(width, height, 1, VTK_FLOAT);
  }
  texture->Resize(width, height);
  return true;
}
}

//------------------------------------------------------------------------------
void vtkDeepAmbientObscurancePass::RenderOpaque(const vtkRenderState* s)
{
  vtkInternals& in = *this->Internals;
  vtkOpenGLRenderer* renderer = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  vtkDeepGBufferPass* gbuffer = this->GBufferPass;
  if (!gbuffer->RenderLayers(s))
  {
    // The opaque props have been drawn the plain way.
    if (!renderer->GetSelector() && !in.WarnedUnsupported)
    {
      in.WarnedUnsupported = true;
      vtkWarningMacro("The deep G-buffer is unavailable; rendering without ambient obscurance.");
    }
    auto it = in.States.find(renderer);
    if (it != in.States.end())
    {
      it->second->HasFrame = false;
    }
    return;
  }

  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  vtkOpenGLState* ostate = window->GetState();
  vtkOpenGLClearErrorMacro();

  double view[16], projection[16];
  const int layers = gbuffer->GetLayerCamera(renderer, view, projection);
  int size[2] = { 0, 0 };
  s->GetWindowSize(size);
  const int width = size[0], height = size[1];

  // Effective radius.
  double radius = this->Radius;
  if (this->AutomaticRadius)
  {
    double bounds[6];
    renderer->ComputeVisiblePropBounds(bounds);
    double diagonal = 0.0;
    if (vtkMath::AreBoundsInitialized(bounds))
    {
      const double extent[3] = { bounds[1] - bounds[0], bounds[3] - bounds[2],
        bounds[5] - bounds[4] };
      diagonal = vtkMath::Norm(extent);
    }
    radius = this->AutomaticRadiusFraction * diagonal;
  }
  this->EffectiveRadius = radius;

  auto& slot = in.States[renderer];
  if (!slot)
  {
    slot.reset(new vtkDeepAmbientObscuranceRendererState);
    slot->Renderer = renderer;
  }
  if (!in.FirstRenderer || !in.States.count(in.FirstRenderer))
  {
    in.FirstRenderer = renderer;
  }
  vtkDeepAmbientObscuranceRendererState& state = *slot;
  state.HasFrame = false;
  for (auto& t : state.Targets)
  {
    if (!AllocateTarget(t, window, width, height))
    {
      vtkErrorMacro("Could not allocate the ambient obscurance targets.");
      gbuffer->ResolveToFramebuffer(s);
      return;
    }
  }
  state.Width = width;
  state.Height = height;
  if (!in.Framebuffer)
  {
    in.Framebuffer = vtkOpenGLFramebufferObject::New();
    in.Framebuffer->SetContext(window);
  }

  const bool aoReady = ReadyQuad(in.AOQuad, window, vtkDeepAmbientObscuranceFS);
  const bool blurReady = ReadyQuad(in.BlurQuad, window, vtkDeepAmbientObscuranceBlurFS);
  const bool compositeReady = ReadyQuad(in.CompositeQuad, window, vtkDeepAmbientObscuranceCompositeFS);
  if (!aoReady || !blurReady || !compositeReady)
  {
    vtkErrorMacro("The ambient obscurance shaders failed to compile.");
    gbuffer->ResolveToFramebuffer(s);
    return;
  }

  // Projection terms of deepPositionFromDistance (row-major P).
  const float projXY[4] = { static_cast<float>(projection[0]), static_cast<float>(projection[5]),
    static_cast<float>(projection[2]), static_cast<float>(projection[6]) };
  const float projT[4] = { static_cast<float>(projection[3]), static_cast<float>(projection[7]),
    static_cast<float>(projection[14]), static_cast<float>(projection[15]) };

  const int distanceUnit = gbuffer->ActivateTexture(renderer, vtkDeepGBufferPass::DEPTH);
  const int normalUnit = gbuffer->ActivateTexture(renderer, vtkDeepGBufferPass::NORMAL);

  {
    vtkOpenGLState::ScopedglViewport savedViewport(ostate);
    vtkOpenGLState::ScopedglEnableDisable savedScissor(ostate, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglEnableDisable savedBlend(ostate, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable savedDepthTest(ostate, GL_DEPTH_TEST);
    ostate->vtkglDisable(GL_SCISSOR_TEST);
    ostate->vtkglDisable(GL_BLEND);
    ostate->vtkglDisable(GL_DEPTH_TEST);
    ostate->PushFramebufferBindings();
    in.Framebuffer->Bind();
    ostate->vtkglViewport(0, 0, width, height);

    // Equations 1-2 into RAW.
    in.Framebuffer->AddColorAttachment(0, state.Targets[RAW]);
    in.Framebuffer->ActivateDrawBuffers(1);
    vtkShaderProgram* program = in.AOQuad->Program;
    window->GetShaderCache()->ReadyShaderProgram(program);
    program->SetUniformi("deepDistance", distanceUnit);
    program->SetUniformi("deepNormal", normalUnit);
    program->SetUniform4f("deepProjXY", projXY);
    program->SetUniform4f("deepProjT", projT);
    program->SetUniformi("deepLayers", this->UseSecondLayer ? std::max(1, layers) : 1);
    program->SetUniformi("deepSamples", this->NumberOfSamples);
    program->SetUniformf("deepTurns", static_cast<float>(GetSpiralTurns(this->NumberOfSamples)));
    program->SetUniformf("deepRadius", static_cast<float>(radius));
    program->SetUniformf("deepBias", static_cast<float>(this->Bias * radius));
    program->SetUniformf("deepEpsilon",
      static_cast<float>(std::max(this->Epsilon * radius * radius, 1e-30)));
    program->SetUniformf("deepIntensity", static_cast<float>(this->Intensity));
    in.AOQuad->Render();

    // Separable bilateral reconstruction: RAW -> BLUR_TEMP -> FILTERED.
    const int passes[2][3] = { { RAW, BLUR_TEMP, 0 }, { BLUR_TEMP, FILTERED, 1 } };
    program = in.BlurQuad->Program;
    for (const auto& pass : passes)
    {
      in.Framebuffer->AddColorAttachment(0, state.Targets[pass[1]]);
      in.Framebuffer->ActivateDrawBuffers(1);
      window->GetShaderCache()->ReadyShaderProgram(program);
      vtkTextureObject* input = state.Targets[pass[0]];
      input->Activate();
      program->SetUniformi("deepInput", input->GetTextureUnit());
      program->SetUniformi("deepDistance", distanceUnit);
      program->SetUniformi("deepNormal", normalUnit);
      program->SetUniform4f("deepProjXY", projXY);
      program->SetUniform4f("deepProjT", projT);
      const int axis[2] = { pass[2] == 0 ? 1 : 0, pass[2] == 0 ? 0 : 1 };
      program->SetUniform2i("deepAxis", axis);
      program->SetUniformi("deepBlurRadius", this->BlurRadius);
      program->SetUniformf("deepPlaneTolerance", static_cast<float>(this->BlurPlaneTolerance));
      program->SetUniformf("deepNormalPower", static_cast<float>(this->BlurNormalPower));
      in.BlurQuad->Render();
      input->Deactivate();
    }
    in.Framebuffer->RemoveColorAttachment(0);
    ostate->PopFramebufferBindings();
  }

  // Composite: layer-0 image and depth, then colour *= AV.
  gbuffer->ResolveToFramebuffer(s);
  {
    vtkOpenGLState::ScopedglEnableDisable savedBlend(ostate, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable savedDepthTest(ostate, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglDepthMask savedDepthMask(ostate);
    vtkOpenGLState::ScopedglBlendFuncSeparate savedBlendFunc(ostate);
    ostate->vtkglEnable(GL_BLEND);
    ostate->vtkglBlendFuncSeparate(GL_ZERO, GL_SRC_COLOR, GL_ZERO, GL_ONE);
    ostate->vtkglDisable(GL_DEPTH_TEST);
    ostate->vtkglDepthMask(GL_FALSE);
    vtkShaderProgram* program = in.CompositeQuad->Program;
    window->GetShaderCache()->ReadyShaderProgram(program);
    vtkTextureObject* visibility = state.Targets[FILTERED];
    visibility->Activate();
    program->SetUniformi("deepVisibility", visibility->GetTextureUnit());
    program->SetUniformi("deepDistance", distanceUnit);
    in.CompositeQuad->Render();
    visibility->Deactivate();
  }

  gbuffer->DeactivateTexture(renderer, vtkDeepGBufferPass::NORMAL);
  gbuffer->DeactivateTexture(renderer, vtkDeepGBufferPass::DEPTH);
  state.HasFrame = true;
  state.Radius = radius;
  state.NumberOfSamples = this->NumberOfSamples;
  vtkOpenGLCheckErrorMacro("failed after vtkDeepAmbientObscurancePass");
}

//------------------------------------------------------------------------------
void vtkDeepAmbientObscurancePass::ReleaseGraphicsResources(vtkWindow* w)
{
  vtkInternals& in = *this->Internals;
  for (auto& entry : in.States)
  {
    entry.second->Release(w);
  }
  in.States.clear();
  in.FirstRenderer = nullptr;
  for (vtkOpenGLQuadHelper** quad : { &in.AOQuad, &in.BlurQuad, &in.CompositeQuad })
  {
    if (*quad)
    {
      (*quad)->ReleaseGraphicsResources(w);
      delete *quad;
      *quad = nullptr;
    }
  }
  if (in.Framebuffer)
  {
    in.Framebuffer->ReleaseGraphicsResources(w);
    in.Framebuffer->Delete();
    in.Framebuffer = nullptr;
  }
  this->GBufferPass->ReleaseGraphicsResources(w);
  this->Superclass::ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
bool vtkDeepAmbientObscurancePass::CaptureAmbientVisibility(
  vtkImageData* output, vtkRenderer* renderer)
{
  vtkDeepAmbientObscuranceRendererState* state = this->Internals->Find(renderer);
  if (!output || !state || !state->Renderer)
  {
    vtkErrorMacro("CaptureAmbientVisibility: no ambient obscurance has been rendered for this "
                  "renderer.");
    return false;
  }
  vtkRenderer* ren = state->Renderer;
  const GLuint distanceHandle = this->GBufferPass->GetTextureHandle(ren, vtkDeepGBufferPass::DEPTH);
  if (!distanceHandle)
  {
    vtkErrorMacro("CaptureAmbientVisibility: the G-buffer of this renderer is gone.");
    return false;
  }
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  window->MakeCurrent();
  vtkOpenGLState* ostate = window->GetState();
  vtkOpenGLClearErrorMacro();

  const int w = state->Width, h = state->Height;
  const size_t pixels = static_cast<size_t>(w) * h;
  std::vector<float> raw(pixels), filtered(pixels);
  ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);
  vtkOpenGLState::ScopedglActiveTexture savedUnit(ostate);
  GLint previous2D = 0, previousArray = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous2D);
  glGetIntegerv(GL_TEXTURE_BINDING_2D_ARRAY, &previousArray);
  glBindTexture(GL_TEXTURE_2D, state->Targets[RAW]->GetHandle());
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RED, GL_FLOAT, raw.data());
  glBindTexture(GL_TEXTURE_2D, state->Targets[FILTERED]->GetHandle());
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RED, GL_FLOAT, filtered.data());
  glBindTexture(GL_TEXTURE_2D, previous2D);
  // The distance array holds every layer (and possibly an oracle layer):
  // ask for its depth first.
  glBindTexture(GL_TEXTURE_2D_ARRAY, distanceHandle);
  GLint arrayDepth = 1;
  glGetTexLevelParameteriv(GL_TEXTURE_2D_ARRAY, 0, GL_TEXTURE_DEPTH, &arrayDepth);
  std::vector<float> distance(pixels * std::max(1, arrayDepth));
  glGetTexImage(GL_TEXTURE_2D_ARRAY, 0, GL_RED, GL_FLOAT, distance.data());
  glBindTexture(GL_TEXTURE_2D_ARRAY, previousArray);
  ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, 4);

  output->Initialize();
  output->SetDimensions(w, h, 1);
  output->SetSpacing(1.0, 1.0, 1.0);
  output->SetOrigin(0.0, 0.0, 0.0);
  vtkNew<vtkFloatArray> av, rawAV;
  vtkNew<vtkUnsignedCharArray> valid;
  av->SetName("AmbientVisibility");
  av->SetNumberOfTuples(pixels);
  rawAV->SetName("RawAmbientVisibility");
  rawAV->SetNumberOfTuples(pixels);
  valid->SetName("Valid");
  valid->SetNumberOfTuples(pixels);
  for (size_t p = 0; p < pixels; ++p)
  {
    const bool isValid = distance[p] > 0.0f;
    valid->SetValue(p, isValid ? 1 : 0);
    av->SetValue(p, isValid ? filtered[p] : 1.0f);
    rawAV->SetValue(p, isValid ? raw[p] : 1.0f);
  }
  output->GetPointData()->AddArray(av);
  output->GetPointData()->AddArray(rawAV);
  output->GetPointData()->AddArray(valid);
  vtkNew<vtkDoubleArray> radius;
  radius->SetName("Radius");
  radius->InsertNextValue(state->Radius);
  vtkNew<vtkIntArray> samples;
  samples->SetName("NumberOfSamples");
  samples->InsertNextValue(state->NumberOfSamples);
  output->GetFieldData()->AddArray(radius);
  output->GetFieldData()->AddArray(samples);
  vtkOpenGLCheckErrorMacro("failed after capturing the ambient visibility");
  return true;
}
