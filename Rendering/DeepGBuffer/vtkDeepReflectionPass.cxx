#include "vtkDeepReflectionPass.h"
#include "vtkDeepGICaptureNames.h"

#include "vtkActor.h"
#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkDataArray.h"
#include "vtkDeepGBufferPass.h"
#include "vtkDeepGIShaderConstantsGLSL.h"
#include "vtkDeepScreenSpaceHelpers.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLTexture.h"
#include "vtkPointData.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkTextureUnitManager.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWeakPointer.h"
#include "vtk_glew.h"

#include "vtkDeepReflectionCompositeFS.h"
#include "vtkDeepReflectionFS.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkDeepReflectionPass);

namespace
{
enum Target
{
  REFLECTED = 0, // RGBA16F: L_r, alpha 1 where traced
  HIT = 1,       // RG32F: hit layer (-1 environment), hit distance
  NUMBER_OF_TARGETS = 2
};

// Kinds of environment the trace shader is compiled for (DEEP_ENVIRONMENT).
enum Environment
{
  ENVIRONMENT_BACKGROUND = DEEP_ENVIRONMENT_BACKGROUND,
  ENVIRONMENT_EQUIRECTANGULAR = DEEP_ENVIRONMENT_EQUIRECTANGULAR,
  ENVIRONMENT_CUBE_MAP = DEEP_ENVIRONMENT_CUBE_MAP,
  NUMBER_OF_ENVIRONMENTS = 3
};

// Whether an actor's material can give a non-zero REFLECTIVITY (the mapping
// of vtkDeepGBufferPass::SetWriteReflectivity). Only opaque geometry is in
// the G-buffer.
bool ActorReflects(vtkActor* actor)
{
  if (!actor || !actor->GetVisibility() || !actor->GetMapper() || !actor->HasOpaqueGeometry())
  {
    return false;
  }
  vtkProperty* property = actor->GetProperty();
  if (property->GetInterpolation() == VTK_PBR)
  {
    // (1 - roughness)^2 vanishes only at roughness 1, unless a material
    // texture scales the roughness down per pixel.
    return property->GetRoughness() < 1.0 || property->GetTexture("materialTex") != nullptr;
  }
  const double* color = property->GetSpecularColor();
  return property->GetLighting() && property->GetSpecular() > 0.0 &&
    std::max({ color[0], color[1], color[2] }) > 0.0;
}

// Whether a prop (an actor, or the actors of an assembly) reflects.
bool PropReflects(vtkProp* prop)
{
  return vtkDeepScreenSpace::AnyActorOf(prop, ActorReflects);
}

// Whether any prop of the frame reflects.
bool SceneReflects(const vtkRenderState* s)
{
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    if (PropReflects(s->GetPropArray()[i]))
    {
      return true;
    }
  }
  return false;
}

bool ReadyQuad(vtkOpenGLQuadHelper*& quad, vtkOpenGLRenderWindow* window, const char* source,
  int environment = ENVIRONMENT_BACKGROUND)
{
  std::string fs = source;
  vtkShaderProgram::Substitute(fs, "//VTK::DeepReflection::Environment",
    std::string(vtkDeepGIShaderConstantsGLSL) + "#define DEEP_ENVIRONMENT " +
      std::to_string(environment));
  return vtkDeepScreenSpace::ReadyQuad(quad, window, fs.c_str());
}
}

//------------------------------------------------------------------------------
// The reflection targets of one renderer.
struct vtkDeepReflectionRendererState
{
  vtkWeakPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkTextureObject> Targets[NUMBER_OF_TARGETS];
  int Width = 0; // of the G-buffer's layers (frame and guard band)
  int Height = 0;
  int GuardBand = 0;
  bool HasFrame = false; // the targets hold this renderer's last frame
  bool Traced = false;
  double MaximumDistance = 0.0;
  double Thickness = 0.0;
  double View[16];
  double FrameProjection[16]; // the camera's: the frame without the guard band

  void Attach(vtkRenderer* renderer) { this->Renderer = renderer; }

  vtkTypeInt64 TextureBytes() const
  {
    vtkTypeInt64 bytes = 0;
    for (const auto& t : this->Targets)
    {
      bytes += vtkDeepScreenSpace::TextureBytes(t);
    }
    return bytes;
  }

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
    this->Traced = false;
  }
};

class vtkDeepReflectionPass::vtkInternals
{
public:
  vtkDeepScreenSpace::RendererStates<vtkDeepReflectionRendererState> States;
  vtkOpenGLFramebufferObject* Framebuffer = nullptr;
  vtkOpenGLQuadHelper* TraceQuads[NUMBER_OF_ENVIRONMENTS] = { nullptr, nullptr, nullptr };
  vtkOpenGLQuadHelper* CompositeQuad = nullptr;
  bool WarnedMappedEnvironment = false;
  // Whether the last frame of each renderer drawn by this pass had a
  // reflective prop. The G-buffer writes reflectivity while any has, so that
  // renderers sharing the pass do not rebuild every shader on each frame.
  std::map<vtkRenderer*, std::pair<vtkWeakPointer<vtkRenderer>, bool>> Reflects;

  bool AnyReflects()
  {
    bool any = false;
    for (auto it = this->Reflects.begin(); it != this->Reflects.end();)
    {
      if (!it->second.first)
      {
        it = this->Reflects.erase(it);
        continue;
      }
      any = any || it->second.second;
      ++it;
    }
    return any;
  }
};

//------------------------------------------------------------------------------
vtkDeepReflectionPass::vtkDeepReflectionPass()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkDeepReflectionPass::~vtkDeepReflectionPass()
{
  vtkInternals& in = *this->Internals;
  if (in.CompositeQuad || in.Framebuffer || !in.States.Empty())
  {
    vtkWarningMacro("Destroyed without ReleaseGraphicsResources(); OpenGL objects are leaked "
                    "unless the context was destroyed first.");
  }
  for (vtkOpenGLQuadHelper* quad : in.TraceQuads)
  {
    delete quad;
  }
  delete in.CompositeQuad;
  if (in.Framebuffer)
  {
    in.Framebuffer->Delete();
  }
}

//------------------------------------------------------------------------------
void vtkDeepReflectionPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaximumDistance: " << this->MaximumDistance << "\n";
  os << indent << "AutomaticMaximumDistance: " << (this->AutomaticMaximumDistance ? "On" : "Off")
     << "\n";
  os << indent << "AutomaticDistanceFraction: " << this->AutomaticDistanceFraction << "\n";
  os << indent << "Thickness: " << this->Thickness << "\n";
  os << indent << "AutomaticThickness: " << (this->AutomaticThickness ? "On" : "Off") << "\n";
  os << indent << "NumberOfSteps: " << this->NumberOfSteps << "\n";
  os << indent << "PixelStride: " << this->PixelStride << "\n";
  os << indent << "RefinementSteps: " << this->RefinementSteps << "\n";
  os << indent << "EffectiveMaximumDistance: " << this->EffectiveMaximumDistance << "\n";
  os << indent << "EffectiveThickness: " << this->EffectiveThickness << "\n";
  os << indent << "LastFrameTraced: " << this->LastFrameTraced << "\n";
}

//------------------------------------------------------------------------------
void vtkDeepReflectionPass::SetMaximumDistance(double distance)
{
  // +inf is allowed: the ray is still cut where it leaves the view frustum.
  vtkDeepSetManualLengthMacro(
    MaximumDistance, distance, true, " (reflections show the environment only)");
}

void vtkDeepReflectionPass::SetThickness(double thickness)
{
  vtkDeepSetManualLengthMacro(Thickness, thickness, false, "");
}

void vtkDeepReflectionPass::SetNumberOfSteps(int steps)
{
  const int clamped = std::min(std::max(steps, 1), static_cast<int>(MAXIMUM_NUMBER_OF_STEPS));
  if (clamped != steps)
  {
    vtkWarningMacro("NumberOfSteps " << steps << " is outside [1, " << MAXIMUM_NUMBER_OF_STEPS
                                     << "]; using " << clamped << ".");
  }
  if (clamped != this->NumberOfSteps)
  {
    this->NumberOfSteps = clamped;
    this->Modified();
  }
}

void vtkDeepReflectionPass::SetPixelStride(double pixels)
{
  if (!std::isfinite(pixels) || pixels <= 0.0)
  {
    vtkWarningMacro("PixelStride must be a positive number of pixels (got "
      << pixels << "); keeping " << this->PixelStride << ".");
    return;
  }
  if (pixels < 0.01)
  {
    vtkWarningMacro("PixelStride " << pixels << " is below 0.01 pixel; using 0.01.");
    pixels = 0.01;
  }
  if (pixels != this->PixelStride)
  {
    this->PixelStride = pixels;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkDeepReflectionPass::RendererReflects(vtkRenderer* renderer)
{
  return vtkDeepScreenSpace::AnyActor(renderer, ActorReflects);
}

//------------------------------------------------------------------------------
void vtkDeepReflectionPass::Render(const vtkRenderState* s)
{
  // Compute only what the scene requires: the G-buffer stores reflectivity
  // (and rays are traced) only while some visible prop can reflect.
  this->LastFrameTraced = SceneReflects(s);
  vtkRenderer* renderer = s->GetRenderer();
  this->Internals->Reflects[renderer] = { renderer, this->LastFrameTraced };
  this->GBufferPass->SetWriteReflectivity(this->Internals->AnyReflects());
  this->Superclass::Render(s);
}

//------------------------------------------------------------------------------
namespace
{
bool AllocateTarget(vtkSmartPointer<vtkTextureObject>& texture, vtkOpenGLRenderWindow* window,
  int width, int height, int target)
{
  if (texture && texture->GetWidth() == static_cast<unsigned int>(width) &&
    texture->GetHeight() == static_cast<unsigned int>(height))
  {
    return true;
  }
  if (!texture)
  {
    const int components = target == REFLECTED ? 4 : 2;
    texture = vtkSmartPointer<vtkTextureObject>::New();
    texture->SetContext(window);
    texture->SetInternalFormat(target == REFLECTED ? GL_RGBA16F : GL_RG32F);
    texture->SetFormat(target == REFLECTED ? GL_RGBA : GL_RG);
    texture->SetDataType(GL_FLOAT);
    texture->SetMinificationFilter(vtkTextureObject::Nearest);
    texture->SetMagnificationFilter(vtkTextureObject::Nearest);
    texture->SetWrapS(vtkTextureObject::ClampToEdge);
    texture->SetWrapT(vtkTextureObject::ClampToEdge);
    return texture->Allocate2D(width, height, components, VTK_FLOAT);
  }
  texture->Resize(width, height);
  return true;
}

// GLSL mat3 uniform (column-major) of a row-major 3x3.
void ToColumnMajor3(const double m[3][3], float out[9])
{
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      out[c * 3 + r] = static_cast<float>(m[r][c]);
    }
  }
}

// Camera space -> the renderer's environment frame (GLSL mat3): rows right,
// up, front of the environment frame times the inverse view rotation.
void ViewToEnvironment(vtkRenderer* renderer, const double view[16], float out[9])
{
  vtkNew<vtkMatrix4x4> inverseView;
  inverseView->DeepCopy(view);
  inverseView->Invert();
  double up[3], right[3], front[3];
  renderer->GetEnvironmentUp(up);
  renderer->GetEnvironmentRight(right);
  vtkMath::Normalize(up);
  vtkMath::Normalize(right);
  vtkMath::Cross(right, up, front);
  const double* environmentFrame[3] = { right, up, front };
  double toEnvironment[3][3];
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      toEnvironment[r][c] = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        toEnvironment[r][c] += environmentFrame[r][k] * inverseView->GetElement(k, c);
      }
    }
  }
  ToColumnMajor3(toEnvironment, out);
}
}

//------------------------------------------------------------------------------
void vtkDeepReflectionPass::RenderOpaque(const vtkRenderState* s)
{
  vtkInternals& in = *this->Internals;
  vtkOpenGLRenderer* renderer = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  vtkDeepGBufferPass* gbuffer = this->GBufferPass;
  if (vtkDeepReflectionRendererState* existing = in.States.Existing(renderer))
  {
    existing->HasFrame = false;
  }
  if (!this->RenderLayersOrWarn(s, "reflections"))
  {
    this->LastFrameTraced = false;
    return;
  }
  if (!this->UpdateReflections(s))
  {
    gbuffer->ResolveToFramebuffer(s);
    this->LastFrameTraced = false;
    return;
  }
  gbuffer->ResolveToFramebuffer(s);
  vtkDeepReflectionRendererState& state = *in.States.Existing(renderer);
  this->LastFrameTraced = state.Traced;
  if (!state.Traced)
  {
    // Nothing reflects: exactly the G-buffer's image.
    return;
  }
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  vtkOpenGLState* ostate = window->GetState();
  const int radianceUnit = gbuffer->ActivateTexture(renderer, vtkDeepGBufferPass::RADIANCE);
  const int reflectivityUnit = gbuffer->ActivateTexture(renderer, vtkDeepGBufferPass::REFLECTIVITY);
  auto deactivate = [&]()
  {
    gbuffer->DeactivateTexture(renderer, vtkDeepGBufferPass::REFLECTIVITY);
    gbuffer->DeactivateTexture(renderer, vtkDeepGBufferPass::RADIANCE);
  };
  // Composite: layer-0 image and depth, then RADIANCE + REFLECTIVITY x L_r
  // where traced (alpha kept).
  if (gbuffer->GetDisplayQuantity() == vtkDeepGBufferPass::RADIANCE && radianceUnit >= 0 &&
    reflectivityUnit >= 0)
  {
    vtkDeepScreenSpace::ScopedStageTime time(this->GetStageTimer(), "reflections: composite");
    vtkDeepScreenSpace::ScopedCompositeState compositeState(ostate, GL_ONE, GL_ZERO);
    vtkShaderProgram* program = in.CompositeQuad->Program;
    window->GetShaderCache()->ReadyShaderProgram(program);
    state.Targets[REFLECTED]->Activate();
    program->SetUniformi("deepReflected", state.Targets[REFLECTED]->GetTextureUnit());
    program->SetUniformi("deepRadiance", radianceUnit);
    program->SetUniformi("deepReflectivity", reflectivityUnit);
    program->SetUniformi("deepGuardBand", state.GuardBand);
    in.CompositeQuad->Render();
    state.Targets[REFLECTED]->Deactivate();
  }
  deactivate();
  vtkOpenGLCheckErrorMacro("failed after vtkDeepReflectionPass");
}

//------------------------------------------------------------------------------
// What one UpdateReflections call decides and carries from stage to stage.
struct vtkDeepReflectionPass::vtkTraceFrame : vtkDeepScreenSpacePass::EffectFrame
{
  double MaximumDistance = 0.0;
  double Thickness = 0.0;
  // VTK's environment texture, bound while the rays are traced, or none
  // (the background is the environment).
  vtkOpenGLTexture* Environment = nullptr;
  vtkTextureObject* EnvironmentObject = nullptr;
  int EnvironmentKind = ENVIRONMENT_BACKGROUND;
  int DistanceUnit = -1;
  int NormalUnit = -1;
  int RadianceUnit = -1;
  int ReflectivityUnit = -1;
};

//------------------------------------------------------------------------------
bool vtkDeepReflectionPass::UpdateReflections(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  // Rays are traced for the frame's pixels (no guard band shaded); they
  // march through the whole layers, so leaving the guard band ends them
  // (section 3.6).
  vtkTraceFrame frame;
  if (!this->BeginEffectFrame(s, "UpdateReflections", 0.0, frame))
  {
    return false;
  }
  this->ComputeRayLimits(frame);
  vtkDeepReflectionRendererState& state = this->Internals->States.Get(frame.Renderer);
  state.HasFrame = false;
  state.Traced = false;
  std::copy(frame.View, frame.View + 16, state.View);
  vtkDeepScreenSpace::FrameProjection(
    frame.Projection, frame.Size, frame.GuardBand, state.FrameProjection);
  state.MaximumDistance = frame.MaximumDistance;
  state.Thickness = frame.Thickness;

  // Compute only what the scene requires: rays only where the G-buffer
  // holds reflectivity for this frame and some visible prop can reflect.
  if (!this->GBufferPass->GetWriteReflectivity() || !SceneReflects(s))
  {
    state.Release(frame.Window); // nothing reflects: no targets kept
    state.HasFrame = true;
    return true;
  }
  this->BindEnvironment(frame);
  bool traced = false;
  if (!this->PrepareTargets(frame, state))
  {
    vtkErrorMacro("The reflection targets or shaders are unavailable; rendering without "
                  "reflections.");
  }
  else if (!this->ActivateLayers(frame))
  {
    vtkErrorMacro("No free texture units for the reflections; rendering without them.");
    this->DeactivateLayers(frame);
    state.HasFrame = true;
  }
  else
  {
    this->TraceRays(frame, state);
    this->DeactivateLayers(frame);
    state.HasFrame = true;
    state.Traced = traced = true;
  }
  if (frame.Environment)
  {
    frame.Environment->PostRender(frame.Renderer);
  }
  vtkOpenGLCheckErrorMacro("failed after the reflection rays");
  return traced;
}

//------------------------------------------------------------------------------
// How far rays march and how thick a layer's surface is taken to be.
void vtkDeepReflectionPass::ComputeRayLimits(vtkTraceFrame& frame)
{
  const double diagonal = vtkDeepScreenSpace::SceneDiagonal(frame.Renderer);
  frame.MaximumDistance = this->AutomaticMaximumDistance
    ? this->AutomaticDistanceFraction * diagonal
    : this->MaximumDistance;
  frame.Thickness = this->Thickness;
  if (this->AutomaticThickness)
  {
    // The minimum separation is the thickness the layers guarantee; without
    // one, a small fraction of the scene.
    frame.Thickness = this->GBufferPass->GetEffectiveMinimumSeparation();
    if (!(frame.Thickness > 0.0))
    {
      frame.Thickness = 0.005 * diagonal;
    }
  }
  this->EffectiveMaximumDistance = frame.MaximumDistance;
  this->EffectiveThickness = frame.Thickness;
}

//------------------------------------------------------------------------------
// The environment: VTK's environment texture if any, else the background.
void vtkDeepReflectionPass::BindEnvironment(vtkTraceFrame& frame)
{
  vtkOpenGLTexture* environment =
    vtkOpenGLTexture::SafeDownCast(frame.Renderer->GetEnvironmentTexture());
  if (!environment)
  {
    return;
  }
  // VTK uploads float or 16-bit texels as they are only in direct-scalars
  // mode; otherwise an HDR environment is mapped to 8-bit colours.
  vtkImageData* input = environment->GetInput();
  vtkDataArray* texels = input ? input->GetPointData()->GetScalars() : nullptr;
  if (texels && texels->GetDataType() != VTK_UNSIGNED_CHAR &&
    environment->GetColorMode() != VTK_COLOR_MODE_DIRECT_SCALARS &&
    !this->Internals->WarnedMappedEnvironment)
  {
    this->Internals->WarnedMappedEnvironment = true;
    vtkWarningMacro("The environment texture's texels are not 8-bit and its ColorMode is not "
                    "direct scalars: VTK maps them through a lookup table. Call "
                    "SetColorModeToDirectScalars() on it to reflect the HDR values.");
  }
  environment->Render(frame.Renderer); // loads (if needed) and binds it
  vtkTextureObject* object = environment->GetTextureObject();
  if (!object || !object->GetHandle())
  {
    environment->PostRender(frame.Renderer);
    return;
  }
  frame.Environment = environment;
  frame.EnvironmentObject = object;
  frame.EnvironmentKind =
    object->GetTarget() == GL_TEXTURE_CUBE_MAP ? ENVIRONMENT_CUBE_MAP : ENVIRONMENT_EQUIRECTANGULAR;
}

//------------------------------------------------------------------------------
bool vtkDeepReflectionPass::PrepareTargets(
  const vtkTraceFrame& frame, vtkDeepReflectionRendererState& state)
{
  vtkInternals& in = *this->Internals;
  vtkOpenGLRenderWindow* window = frame.Window;
  bool allocated = true;
  for (int t = 0; t < NUMBER_OF_TARGETS; ++t)
  {
    allocated =
      allocated && AllocateTarget(state.Targets[t], window, frame.Size[0], frame.Size[1], t);
  }
  if (!in.Framebuffer)
  {
    in.Framebuffer = vtkOpenGLFramebufferObject::New();
    in.Framebuffer->SetContext(window);
  }
  const bool traceReady = ReadyQuad(
    in.TraceQuads[frame.EnvironmentKind], window, vtkDeepReflectionFS, frame.EnvironmentKind);
  const bool compositeReady = ReadyQuad(in.CompositeQuad, window, vtkDeepReflectionCompositeFS);
  if (!allocated || !traceReady || !compositeReady)
  {
    return false;
  }
  state.Width = frame.Size[0];
  state.Height = frame.Size[1];
  state.GuardBand = frame.GuardBand;
  return true;
}

//------------------------------------------------------------------------------
// The G-buffer textures the rays read; false when a texture unit is missing.
bool vtkDeepReflectionPass::ActivateLayers(vtkTraceFrame& frame)
{
  vtkDeepGBufferPass* gbuffer = this->GBufferPass;
  frame.DistanceUnit = gbuffer->ActivateTexture(frame.Renderer, vtkDeepGBufferPass::DEPTH);
  frame.NormalUnit = gbuffer->ActivateTexture(frame.Renderer, vtkDeepGBufferPass::NORMAL);
  frame.RadianceUnit = gbuffer->ActivateTexture(frame.Renderer, vtkDeepGBufferPass::RADIANCE);
  frame.ReflectivityUnit =
    gbuffer->ActivateTexture(frame.Renderer, vtkDeepGBufferPass::REFLECTIVITY);
  return frame.DistanceUnit >= 0 && frame.NormalUnit >= 0 && frame.RadianceUnit >= 0 &&
    frame.ReflectivityUnit >= 0;
}

void vtkDeepReflectionPass::DeactivateLayers(const vtkTraceFrame& frame)
{
  for (int quantity : { vtkDeepGBufferPass::REFLECTIVITY, vtkDeepGBufferPass::RADIANCE,
         vtkDeepGBufferPass::NORMAL, vtkDeepGBufferPass::DEPTH })
  {
    this->GBufferPass->DeactivateTexture(frame.Renderer, quantity);
  }
}

//------------------------------------------------------------------------------
// Marches a ray per frame pixel through the layers (section 3.6) into
// REFLECTED (radiance) and HIT (layer, distance); untraced pixels keep no
// radiance and hit layer -1.
void vtkDeepReflectionPass::TraceRays(
  const vtkTraceFrame& frame, vtkDeepReflectionRendererState& state)
{
  vtkInternals& in = *this->Internals;
  vtkDeepScreenSpace::ScopedStageTime time(this->GetStageTimer(), "reflections: trace");
  vtkOpenGLState* ostate = frame.GL;
  vtkDeepScreenSpace::ScopedStageState stageState(ostate);
  in.Framebuffer->Bind();
  in.Framebuffer->AddColorAttachment(REFLECTED, state.Targets[REFLECTED]);
  in.Framebuffer->AddColorAttachment(HIT, state.Targets[HIT]);
  in.Framebuffer->ActivateDrawBuffers(NUMBER_OF_TARGETS);
  ostate->vtkglViewport(0, 0, frame.Size[0], frame.Size[1]);
  const float clearReflected[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
  const float clearHit[4] = { -1.0f, 0.0f, 0.0f, 0.0f };
  glClearBufferfv(GL_COLOR, REFLECTED, clearReflected);
  glClearBufferfv(GL_COLOR, HIT, clearHit);
  ostate->vtkglEnable(GL_SCISSOR_TEST);
  const int* region = frame.Region;
  ostate->vtkglScissor(region[0], region[1], region[2] - region[0], region[3] - region[1]);

  vtkShaderProgram* program = in.TraceQuads[frame.EnvironmentKind]->Program;
  frame.Window->GetShaderCache()->ReadyShaderProgram(program);
  this->SetTraceUniforms(program, frame);
  in.TraceQuads[frame.EnvironmentKind]->Render();
  in.Framebuffer->RemoveColorAttachment(HIT);
  in.Framebuffer->RemoveColorAttachment(REFLECTED);
}

//------------------------------------------------------------------------------
void vtkDeepReflectionPass::SetTraceUniforms(vtkShaderProgram* program, const vtkTraceFrame& frame)
{
  SetLayerUniforms(program, frame, frame.DistanceUnit, frame.NormalUnit);
  program->SetUniformi("deepRadiance", frame.RadianceUnit);
  program->SetUniformi("deepReflectivity", frame.ReflectivityUnit);
  program->SetUniformi("deepLayers", std::max(1, frame.Layers));
  // The full projection for projecting ray points (column-major for GLSL).
  float projectionGL[16];
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      projectionGL[c * 4 + r] = static_cast<float>(frame.Projection[r * 4 + c]);
    }
  }
  program->SetUniformMatrix4x4("deepProjection", projectionGL);
  // +infinity is a valid t_max (cut at the view frustum in the shader).
  program->SetUniformf("deepMaxDistance",
    static_cast<float>(
      std::min(frame.MaximumDistance, static_cast<double>(std::numeric_limits<float>::max()))));
  program->SetUniformf("deepThickness", static_cast<float>(frame.Thickness));
  program->SetUniformi("deepMaxSteps", this->NumberOfSteps);
  program->SetUniformf("deepPixelStride", static_cast<float>(this->PixelStride));
  program->SetUniformi("deepRefinements", this->RefinementSteps);
  float toEnvironmentGL[9];
  ViewToEnvironment(frame.Renderer, frame.View, toEnvironmentGL);
  program->SetUniformMatrix3x3("deepViewToEnvironment", toEnvironmentGL);
  double background[3], background2[3];
  frame.Renderer->GetBackground(background);
  frame.Renderer->GetBackground2(background2);
  const float backgroundGL[3] = { static_cast<float>(background[0]),
    static_cast<float>(background[1]), static_cast<float>(background[2]) };
  const float background2GL[3] = { static_cast<float>(background2[0]),
    static_cast<float>(background2[1]), static_cast<float>(background2[2]) };
  program->SetUniform3f("deepBackground", backgroundGL);
  program->SetUniform3f("deepBackground2", background2GL);
  program->SetUniformi("deepGradient", frame.Renderer->GetGradientBackground() ? 1 : 0);
  if (frame.EnvironmentObject)
  {
    program->SetUniformi("deepEnvironment", frame.EnvironmentObject->GetTextureUnit());
  }
}

//------------------------------------------------------------------------------
unsigned int vtkDeepReflectionPass::GetReflectionTextureHandle(vtkRenderer* renderer)
{
  vtkDeepReflectionRendererState* state = this->Internals->States.Find(renderer);
  return state && state->Traced ? state->Targets[REFLECTED]->GetHandle() : 0;
}

int vtkDeepReflectionPass::ActivateReflectionTexture(vtkRenderer* renderer)
{
  vtkDeepReflectionRendererState* state = this->Internals->States.Find(renderer);
  if (!state || !state->Traced)
  {
    return -1;
  }
  state->Targets[REFLECTED]->Activate();
  return state->Targets[REFLECTED]->GetTextureUnit();
}

void vtkDeepReflectionPass::DeactivateReflectionTexture(vtkRenderer* renderer)
{
  vtkDeepReflectionRendererState* state = this->Internals->States.Find(renderer);
  if (state && state->Traced)
  {
    state->Targets[REFLECTED]->Deactivate();
  }
}

//------------------------------------------------------------------------------
namespace
{
// What CaptureReflections reads back: the traced radiance and hits, and
// layer 0 of the G-buffer's reflectivity; zeros where nothing was traced.
struct ReflectionDownload
{
  std::vector<float> Reflected, Hit;
  std::vector<unsigned char> Reflectivity;
};

void DownloadReflections(vtkDeepReflectionRendererState& state, GLuint reflectivityHandle,
  vtkOpenGLState* ostate, size_t pixels, ReflectionDownload& d)
{
  d.Reflected.assign(pixels * 4, 0.0f);
  d.Hit.assign(pixels * 2, 0.0f);
  d.Reflectivity.assign(pixels * 4, 0);
  if (!state.Traced)
  {
    return;
  }
  ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);
  vtkOpenGLState::ScopedglActiveTexture savedUnit(ostate);
  GLint previous2D = 0, previousArray = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous2D);
  glGetIntegerv(GL_TEXTURE_BINDING_2D_ARRAY, &previousArray);
  glBindTexture(GL_TEXTURE_2D, state.Targets[REFLECTED]->GetHandle());
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, d.Reflected.data());
  glBindTexture(GL_TEXTURE_2D, state.Targets[HIT]->GetHandle());
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RG, GL_FLOAT, d.Hit.data());
  glBindTexture(GL_TEXTURE_2D, previous2D);
  // Layer 0 of the G-buffer's reflectivity array is its first w x h texels.
  if (reflectivityHandle)
  {
    GLint depth = 0;
    glBindTexture(GL_TEXTURE_2D_ARRAY, reflectivityHandle);
    glGetTexLevelParameteriv(GL_TEXTURE_2D_ARRAY, 0, GL_TEXTURE_DEPTH, &depth);
    std::vector<unsigned char> all(pixels * 4 * std::max(1, static_cast<int>(depth)));
    glGetTexImage(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA, GL_UNSIGNED_BYTE, all.data());
    std::copy(all.begin(), all.begin() + pixels * 4, d.Reflectivity.begin());
  }
  glBindTexture(GL_TEXTURE_2D_ARRAY, previousArray);
  ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, 4);
}

void AddReflectionArrays(vtkPointData* pd, const ReflectionDownload& d, size_t pixels)
{
  vtkNew<vtkFloatArray> radiance, layer, distance, reflectance;
  vtkNew<vtkUnsignedCharArray> valid;
  radiance->SetName(vtkDeepGICaptureNames::ReflectedRadiance);
  radiance->SetNumberOfComponents(3);
  radiance->SetNumberOfTuples(pixels);
  layer->SetName(vtkDeepGICaptureNames::HitLayer);
  layer->SetNumberOfTuples(pixels);
  distance->SetName(vtkDeepGICaptureNames::HitDistance);
  distance->SetNumberOfTuples(pixels);
  reflectance->SetName(vtkDeepGICaptureNames::Reflectivity);
  reflectance->SetNumberOfComponents(3);
  reflectance->SetNumberOfTuples(pixels);
  valid->SetName(vtkDeepGICaptureNames::Valid);
  valid->SetNumberOfTuples(pixels);
  for (size_t p = 0; p < pixels; ++p)
  {
    const bool traced = d.Reflected[4 * p + 3] > 0.0f;
    valid->SetValue(p, traced ? 1 : 0);
    layer->SetValue(p, traced ? d.Hit[2 * p] : -1.0f);
    distance->SetValue(p, traced && d.Hit[2 * p] >= 0.0f ? d.Hit[2 * p + 1] : 0.0f);
    for (int c = 0; c < 3; ++c)
    {
      radiance->SetTypedComponent(p, c, traced ? d.Reflected[4 * p + c] : 0.0f);
      reflectance->SetTypedComponent(p, c, d.Reflectivity[4 * p + c] / 255.0f);
    }
  }
  pd->AddArray(radiance);
  pd->AddArray(layer);
  pd->AddArray(distance);
  pd->AddArray(reflectance);
  pd->AddArray(valid);
}

void AddReflectionFieldData(vtkFieldData* fd, const vtkDeepReflectionRendererState& state)
{
  for (auto value : { std::make_pair(vtkDeepGICaptureNames::MaximumDistance, state.MaximumDistance),
         std::make_pair(vtkDeepGICaptureNames::Thickness, state.Thickness) })
  {
    vtkNew<vtkDoubleArray> array;
    array->SetName(value.first);
    array->InsertNextValue(value.second);
    fd->AddArray(array);
  }
  vtkNew<vtkIntArray> traced;
  traced->SetName(vtkDeepGICaptureNames::Traced);
  traced->InsertNextValue(state.Traced ? 1 : 0);
  fd->AddArray(traced);
  vtkDeepScreenSpace::AddCameraFieldData(fd, state.View, state.FrameProjection);
}
}

//------------------------------------------------------------------------------
bool vtkDeepReflectionPass::CaptureReflections(vtkImageData* output, vtkRenderer* renderer)
{
  vtkDeepReflectionRendererState* state = this->Internals->States.Find(renderer);
  if (!output || !state || !state->Renderer)
  {
    vtkErrorMacro("CaptureReflections: no reflections have been rendered for this renderer.");
    return false;
  }
  vtkRenderer* ren = state->Renderer;
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  window->MakeCurrent();
  vtkOpenGLClearErrorMacro();
  int w = state->Width, h = state->Height;
  if (!state->Traced)
  {
    // Nothing traced: the image of the G-buffer's size, all invalid.
    double view[16], projection[16];
    if (!this->GBufferPass->GetLayerCamera(ren, view, projection))
    {
      vtkErrorMacro("CaptureReflections: no G-buffer for this renderer.");
      return false;
    }
    const int* size = ren->GetSize();
    w = size[0];
    h = size[1];
  }
  const size_t pixels = static_cast<size_t>(w) * h;
  ReflectionDownload download;
  DownloadReflections(*state,
    this->GBufferPass->GetTextureHandle(ren, vtkDeepGBufferPass::REFLECTIVITY), window->GetState(),
    pixels, download);
  output->Initialize();
  output->SetDimensions(w, h, 1);
  output->SetSpacing(1.0, 1.0, 1.0);
  output->SetOrigin(0.0, 0.0, 0.0);
  AddReflectionArrays(output->GetPointData(), download, pixels);
  if (state->Traced)
  {
    vtkDeepScreenSpace::CropGuardBand(output, state->GuardBand);
  }
  AddReflectionFieldData(output->GetFieldData(), *state);
  vtkOpenGLCheckErrorMacro("failed after capturing the reflections");
  return true;
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkDeepReflectionPass::GetTextureBytes()
{
  return this->Internals->States.TextureBytes();
}

//------------------------------------------------------------------------------
void vtkDeepReflectionPass::ReleaseGraphicsResources(vtkWindow* w)
{
  vtkInternals& in = *this->Internals;
  in.States.Release(w);
  in.Reflects.clear();
  for (vtkOpenGLQuadHelper*& quad : in.TraceQuads)
  {
    if (quad)
    {
      quad->ReleaseGraphicsResources(w);
      delete quad;
      quad = nullptr;
    }
  }
  if (in.CompositeQuad)
  {
    in.CompositeQuad->ReleaseGraphicsResources(w);
    delete in.CompositeQuad;
    in.CompositeQuad = nullptr;
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
