#include "vtkDeepGBufferPass.h"

#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIKeys.h"

#include "vtkActor.h"
#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkCamera.h"
#include "vtkDeepGBufferLayerExchange.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkIntArray.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLightsPass.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFXAAFilter.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkOverlayPass.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProp.h"
#include "vtkProp3D.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkShaderProperty.h"
#include "vtkShadowMapBakerPass.h"
#include "vtkShadowMapPass.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkTextureUnitManager.h"
#include "vtkTranslucentPass.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumetricPass.h"
#include "vtkWeakPointer.h"
#include "vtk_glew.h"

#include "vtkDeepGBufferCommon.h"
#include "vtkDeepGBufferGS.h"
#include "vtkDeepGBufferGuardBandDecGS.h"
#include "vtkDeepGBufferGuardBandGS.h"
#include "vtkDeepGBufferLayerDecFS.h"
#include "vtkDeepGBufferLayerDecVS.h"
#include "vtkDeepGBufferLayerImplVS.h"
#include "vtkDeepGBufferLayerTestFS.h"
#include "vtkDeepGBufferOutputsFS.h"
#include "vtkDeepGBufferResolveFS.h"
#include "vtkDeepGBufferShaderTokens.h"
#include "vtkDeepGBufferUnlitNormalFS.h"
#include "vtkDeepGIShaderConstantsGLSL.h"
#include "vtkDeepScreenSpaceHelpers.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkDeepGBufferPass);

namespace
{
// The G-buffer's layer drawing as a render pass: vtkShadowMapPass runs it as
// its opaque sequence, so that the shadow pass's shader hooks are on the
// props while the layers are drawn.
class vtkDeepGBufferDrawStep : public vtkRenderPass
{
public:
  static vtkDeepGBufferDrawStep* New();
  vtkTypeMacro(vtkDeepGBufferDrawStep, vtkRenderPass);
  void Render(const vtkRenderState* s) override
  {
    this->NumberOfRenderedProps = 0;
    if (this->Draw)
    {
      this->Draw(s);
    }
  }
  std::function<void(const vtkRenderState*)> Draw;
  // For a Draw that delegates to another pass, which counted its props.
  void AddRenderedProps(int count) { this->NumberOfRenderedProps += count; }
};
vtkStandardNewMacro(vtkDeepGBufferDrawStep);
}

namespace
{
using Matrix = std::array<double, 16>; // row-major, column vectors (VTK convention)

Matrix ToArray(vtkMatrix4x4* m)
{
  Matrix a;
  std::copy(&m->Element[0][0], &m->Element[0][0] + 16, a.begin());
  return a;
}

// VTK's mappers rasterise with the matrices vtkOpenGLCamera::GetKeyMatrices
// caches, recomputed only when the camera or the renderer was modified
// since; a camera changed without Modified() (VTK 9.1's vtkCamera::DeepCopy
// does not call it, and scripts restore saved views with it) would have its
// layers rasterised with the last frame's view while the effects
// reconstruct and reproject them with the camera's own (`view` and
// `projection`, row-major). Modified() when the cached ones differ makes
// them agree. The cached view is a copy of the camera's, so it is compared
// exactly; the projection within round-off of its aspect ratio.
void ModifyStaleCamera(vtkRenderer* renderer, const Matrix& view, const Matrix& projection)
{
  auto* camera = vtkOpenGLCamera::SafeDownCast(renderer->GetActiveCamera());
  if (!camera)
  {
    return;
  }
  vtkMatrix4x4* cachedView = nullptr; // transposed, as GLSL reads it
  vtkMatrix3x3* normals = nullptr;
  vtkMatrix4x4* cachedProjection = nullptr; // transposed
  vtkMatrix4x4* worldToClip = nullptr;
  camera->GetKeyMatrices(renderer, cachedView, normals, cachedProjection, worldToClip);
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      const double p = projection[r * 4 + c];
      if (cachedView->GetElement(c, r) != view[r * 4 + c] ||
        std::abs(cachedProjection->GetElement(c, r) - p) > 1e-9 * std::max(1.0, std::abs(p)))
      {
        camera->Modified();
        return;
      }
    }
  }
}

Matrix Multiply(const Matrix& a, const Matrix& b)
{
  Matrix c;
  vtkMatrix4x4::Multiply4x4(a.data(), b.data(), c.data());
  return c;
}

Matrix Invert(const Matrix& a)
{
  Matrix c;
  vtkMatrix4x4::Invert(a.data(), c.data());
  return c;
}

Matrix Identity()
{
  Matrix a{};
  a[0] = a[5] = a[10] = a[15] = 1.0;
  return a;
}

// Constant-velocity extrapolation of a rigid transform: T(t+1) = T(t) T(t-1)^-1 T(t).
Matrix Extrapolate(const Matrix& previous, const Matrix& current)
{
  return Multiply(Multiply(current, Invert(previous)), current);
}

// GLSL mat4 uniforms are column-major.
std::array<float, 16> ToColumnMajor(const Matrix& a)
{
  std::array<float, 16> f;
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      f[c * 4 + r] = static_cast<float>(a[r * 4 + c]);
    }
  }
  return f;
}

// The projection of the layers: the camera's projection P with clip x and y
// scaled by frame / (frame + 2 guard) per axis, i.e. the frustum widened so
// that the frame's pixels keep their size and position and the guard band
// surrounds them (both perspective and parallel projections; depth is
// unchanged).
Matrix WithGuardBand(const Matrix& projection, const std::array<float, 2>& scale)
{
  Matrix p = projection;
  for (int c = 0; c < 4; ++c)
  {
    p[c] *= scale[0];
    p[4 + c] *= scale[1];
  }
  return p;
}

// (P22, P23, P32, P33): what deepDistanceFromClip needs of a projection.
std::array<float, 4> ProjectionDepthRows(const Matrix& projection)
{
  return { static_cast<float>(projection[10]), static_cast<float>(projection[11]),
    static_cast<float>(projection[14]), static_cast<float>(projection[15]) };
}

// Which separation test the fragment shader applies to layers j > 0.
enum TestMode
{
  TEST_NONE = DEEP_TEST_NONE,              // layer 0, or the oracle layer
  TEST_SAME_PIXEL = DEEP_TEST_SAME_PIXEL,  // DEPTH_PEEL, PREVIOUS, PREDICT, DELAY
  TEST_REPROJECTED = DEEP_TEST_REPROJECTED // REPROJECT: tested in the previous frame
};

const char* const OracleNames[] = { "DEPTH_PEEL", "PREVIOUS", "REPROJECT", "PREDICT", "DELAY",
  "AUTOMATIC" };
const char* const QuantityNames[] = { "RADIANCE", "ALBEDO", "NORMAL", "DEPTH", "AMBIENT",
  "REFLECTIVITY" };

// Quantities every G-buffer has; REFLECTIVITY, the last one, is optional.
constexpr int BaseQuantities = vtkDeepGBufferPass::REFLECTIVITY;

// Internal formats of the quantities, in the order of the Quantity enum.
const GLenum QuantityInternalFormats[] = { GL_RGBA16F, GL_RGBA8, GL_RG8, GL_R32F, GL_R11F_G11F_B10F,
  GL_RGBA8 };
// Bytes per texel of those formats.
const int QuantityBytes[] = { 8, 4, 2, 4, 4, 4 };
const GLenum QuantityFormats[] = { GL_RGBA, GL_RGBA, GL_RG, GL_RED, GL_RGB, GL_RGBA };
const GLenum QuantityTypes[] = { GL_HALF_FLOAT, GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE, GL_FLOAT,
  GL_FLOAT, GL_UNSIGNED_BYTE };

// Upper bound of the number of floats a VTK polydata vertex shader passes on
// per vertex (position, normal, colour, texture coordinates, clip distances,
// picking); used to keep the geometry shader's output within the GPU limit.
constexpr int MaximumVaryingComponentsPerVertex = 48;
}

//------------------------------------------------------------------------------
// The G-buffer of one renderer: its textures, framebuffers and the history
// that the single-pass oracles read. Keyed by renderer so that several
// renderers (or viewports) never read each other's history.
struct vtkDeepGBufferRendererState
{
  vtkWeakPointer<vtkRenderer> Renderer;

  int Width = 0; // of the layers: the frame plus the guard band on both sides
  int Height = 0;
  int GuardBand = 0;     // pixels added on each side of the frame (last frame)
  int Slots = 0;         // array layers: k, plus one oracle layer for PREDICT/DELAY
  int HistoryLayers = 0; // max(1, k - 1)
  GLuint Textures[vtkDeepGBufferPass::NUMBER_OF_QUANTITIES] = { 0, 0, 0, 0, 0, 0 };
  GLuint DepthTexture = 0;
  GLuint HistoryTexture = 0; // R32F array: the oracle's distances of the previous frame
  GLuint LayeredFramebuffer = 0;
  std::vector<GLuint> LayerFramebuffers; // one per layer, for mappers without the routing GS
  // Whether the fragment shader's AMBIENT output is stored (see
  // UpdateAmbientWrites); new targets store it.
  bool WritesAmbient = true;

  // History for the oracles.
  unsigned long long FrameIndex = 0;
  bool HistoryValid = false;
  bool HistoryIsPredicted = false; // PREDICT/DELAY store their oracle layer
  int HistoryNumberOfLayers = 0;
  bool HasPreviousCamera = false;
  Matrix View = Identity(), Projection = Identity();
  Matrix PreviousView = Identity(), PreviousProjection = Identity();
  // The camera's own projections (the frame without the guard band).
  Matrix FrameProjection = Identity(), PreviousFrameProjection = Identity();
  // The camera the displayed layers were rasterised with: the current one,
  // or the previous one for DELAY. LayerProjection covers the layers (frame
  // and guard band); LayerFrameProjection is the camera's own, which covers
  // the frame.
  Matrix LayerView = Identity(), LayerProjection = Identity();
  Matrix LayerFrameProjection = Identity();

  struct PropHistory
  {
    Matrix Model = Identity();
    Matrix PreviousModel = Identity();
    unsigned long long Frame = 0;
    unsigned long long PreviousFrame = 0;
    Matrix OtherModel = Identity(); // M_o
  };
  std::map<vtkProp*, PropHistory> Props;
  std::map<vtkProp*, vtkWeakPointer<vtkProp>> PropLiveness;

  // What the last frame rendered, for capture and display, and what it was
  // rendered with, for ReuseLayers.
  int RenderedLayers = 0;
  vtkMTimeType LayersTime = 0; // GetLayersTime
  vtkMTimeType RenderedSettingsTime = 0;
  int RenderedWindowSize[2] = { 0, 0 };
  double ClippingRange[2] = { 0.0, 1.0 };
  double MinimumSeparation = 0.0;
  int Oracle = vtkDeepGBufferPass::DEPTH_PEEL;

  // The memory of the layers (each quantity, the depth buffer) and history.
  vtkTypeInt64 TextureBytes() const
  {
    const vtkTypeInt64 texels = static_cast<vtkTypeInt64>(this->Width) * this->Height;
    vtkTypeInt64 perSlot = this->DepthTexture ? 4 : 0;
    for (int q = 0; q < vtkDeepGBufferPass::NUMBER_OF_QUANTITIES; ++q)
    {
      perSlot += this->Textures[q] ? QuantityBytes[q] : 0;
    }
    return texels * (perSlot * this->Slots + (this->HistoryTexture ? 4 * this->HistoryLayers : 0));
  }

  void ReleaseTextures()
  {
    for (GLuint& t : this->Textures)
    {
      if (t)
      {
        glDeleteTextures(1, &t);
        t = 0;
      }
    }
    for (GLuint* t : { &this->DepthTexture, &this->HistoryTexture })
    {
      if (*t)
      {
        glDeleteTextures(1, t);
        *t = 0;
      }
    }
    if (this->LayeredFramebuffer)
    {
      glDeleteFramebuffers(1, &this->LayeredFramebuffer);
      this->LayeredFramebuffer = 0;
    }
    if (!this->LayerFramebuffers.empty())
    {
      glDeleteFramebuffers(
        static_cast<GLsizei>(this->LayerFramebuffers.size()), this->LayerFramebuffers.data());
      this->LayerFramebuffers.clear();
    }
    this->Width = this->Height = this->Slots = this->HistoryLayers = 0;
    this->HistoryValid = false;
    this->RenderedSettingsTime = 0;
    this->LayersTime = 0;
  }
};

//------------------------------------------------------------------------------
// The warnings given once per pass.
enum WarningSlot
{
  WARN_ORACLE_LAYERS,
  WARN_GEOMETRY_SHADER_LAYERS,
  WARN_SEPARATION_EXCEEDS_SCENE,
  WARN_FRAMEBUFFER_INCOMPLETE,
  WARN_GUARD_BAND_LIMITED,
  WARN_LAYER_EXCHANGE_FAILED,
  NUMBER_OF_WARNINGS
};

class vtkDeepGBufferPass::vtkInternals
{
public:
  std::map<vtkRenderer*, std::unique_ptr<vtkDeepGBufferRendererState>> States;
  vtkDeepGBufferRendererState* Current = nullptr; // state of the renderer being drawn
  vtkRenderer* FirstRenderer = nullptr;

  // Per-frame drawing parameters read by SetShaderParameters.
  int EmitMask = 1;
  int OtherClipLayerMask = 0;
  int TargetLayer = 0;
  int TestMode = TEST_NONE;
  int OracleLayerIndex = -1;
  int HistoryUnit = -1;
  // Set while a deeper layer is peeled with back faces culled: the state
  // through which SetShaderParameters culls them.
  vtkOpenGLState* CullingState = nullptr;
  float MinimumSeparation = 0.0f;
  std::array<float, 4> ProjectionZ{}, OtherProjectionZ{};
  std::array<float, 16> InverseProjection{};
  std::array<float, 2> ViewportSize{};
  std::array<float, 2> GuardBandScale{ { 1.0f, 1.0f } };
  Matrix OtherView = Identity(), OtherProjection = Identity();
  Matrix OtherWorldToClip = Identity(); // P_o V_o
  bool OtherUsesPreviousFrame = false;
  bool OtherIsPrediction = false;

  // Which props the geometry shader routes; a change rebuilds the shaders.
  std::map<vtkProp*, bool> RoutedProps;
  bool IsRouted(vtkProp* prop) const
  {
    auto it = this->RoutedProps.find(prop);
    return it != this->RoutedProps.end() && it->second;
  }
  int GeometryShaderSlots = 0;
  int GeometryShaderLayers = 0;
  vtkTimeStamp ShaderStageTime;

  // Capabilities of the current context.
  vtkOpenGLRenderWindow* CheckedWindow = nullptr;
  bool Supported = false;
  int MaximumSlots = 1;
  bool CPURenderer = false;   // Mesa llvmpipe or softpipe: AUTOMATIC peels
  int MaximumTextureSize = 0; // GL_MAX_TEXTURE_SIZE, which limits the guard band
  bool Warned[NUMBER_OF_WARNINGS] = {};

  vtkOpenGLQuadHelper* ResolveQuad = nullptr;

  vtkLightsPass* LightsPass = nullptr;
  vtkNew<vtkRenderStepsPass> Steps;
  vtkNew<vtkDeepGBufferDrawStep> OpaqueStep;
  vtkNew<vtkDeepGBufferDrawStep> DrawStep;
  // FXAA, then the overlay pass (RenderFrame, when the frame is anti-aliased).
  vtkNew<vtkDeepGBufferDrawStep> AntiAliasedOverlayStep;
  vtkNew<vtkOpenGLFXAAFilter> FXAAFilter;
  // A single-sampled copy of a multisampled window's colour, which FXAA
  // reads (it cannot read a multisampled framebuffer).
  vtkSmartPointer<vtkOpenGLFramebufferObject> ResolvedColor;

  // The prop's model matrix in the other frame (SetShaderParameters).
  Matrix OtherModelMatrix(vtkProp* prop);

  void WarnOnce(vtkDeepGBufferPass* self, WarningSlot which, const std::string& message)
  {
    if (!this->Warned[which])
    {
      this->Warned[which] = true;
      vtkWarningWithObjectMacro(self, << message);
    }
  }
};

//------------------------------------------------------------------------------
vtkDeepGBufferPass::vtkDeepGBufferPass()
  : Internals(new vtkInternals)
{
  this->Internals->LightsPass = vtkLightsPass::New();
  this->TranslucentPass = vtkTranslucentPass::New();
  this->VolumetricPass = vtkVolumetricPass::New();
  this->OverlayPass = vtkOverlayPass::New();
  this->Internals->ShaderStageTime.Modified();
}

//------------------------------------------------------------------------------
vtkDeepGBufferPass::~vtkDeepGBufferPass()
{
  if (this->Internals->ResolveQuad || !this->Internals->States.empty())
  {
    vtkWarningMacro("Destroyed without ReleaseGraphicsResources(); OpenGL objects are leaked "
                    "unless the context was destroyed first.");
  }
  delete this->Internals->ResolveQuad;
  this->Internals->LightsPass->Delete();
  this->SetTranslucentPass(nullptr);
  this->SetStageTimer(nullptr);
  this->SetVolumetricPass(nullptr);
  this->SetOverlayPass(nullptr);
  this->SetShadowMapPass(nullptr);
  this->SetLayerExchange(nullptr);
}

vtkCxxSetObjectMacro(vtkDeepGBufferPass, TranslucentPass, vtkRenderPass);
vtkCxxSetObjectMacro(vtkDeepGBufferPass, LayerExchange, vtkDeepGBufferLayerExchange);
vtkCxxSetObjectMacro(vtkDeepGBufferPass, VolumetricPass, vtkRenderPass);
vtkCxxSetObjectMacro(vtkDeepGBufferPass, OverlayPass, vtkRenderPass);
vtkCxxSetObjectMacro(vtkDeepGBufferPass, ShadowMapPass, vtkShadowMapPass);
vtkCxxSetObjectMacro(vtkDeepGBufferPass, StageTimer, vtkDeepGIStageTimer);
//------------------------------------------------------------------------------
vtkInformationIntegerKey* vtkDeepGBufferPass::EMISSIVE()
{
  return vtkDeepGIKeys::EMISSIVE();
}

//------------------------------------------------------------------------------
void vtkDeepGBufferPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Oracle: " << GetOracleAsString(this->Oracle) << "\n";
  os << indent << "NumberOfLayers: " << this->NumberOfLayers << "\n";
  os << indent << "MinimumSeparation: " << this->MinimumSeparation << "\n";
  os << indent << "AutomaticMinimumSeparation: " << this->AutomaticMinimumSeparation << "\n";
  os << indent << "AutomaticSeparationFraction: " << this->AutomaticSeparationFraction << "\n";
  os << indent << "DeepLayerBackfaceCulling: " << this->DeepLayerBackfaceCulling << "\n";
  os << indent << "SkipBackgroundTexels: " << this->SkipBackgroundTexels << "\n";
  os << indent << "WriteReflectivity: " << this->WriteReflectivity << "\n";
  os << indent << "GuardBand: " << this->GuardBand << "\n";
  os << indent << "EffectiveGuardBand: " << this->EffectiveGuardBand << " pixels\n";
  os << indent << "EffectiveMinimumSeparation: " << this->EffectiveMinimumSeparation << "\n";
  os << indent << "EffectiveNumberOfLayers: " << this->EffectiveNumberOfLayers << "\n";
  os << indent << "EffectiveOracle: " << GetOracleAsString(this->EffectiveOracle) << "\n";
  os << indent << "LastGeometryPassCount: " << this->LastGeometryPassCount << "\n";
  os << indent << "DisplayQuantity: " << GetQuantityAsString(this->DisplayQuantity) << "\n";
  os << indent << "DisplayLayer: " << this->DisplayLayer << "\n";
  os << indent << "TranslucentPass: " << this->TranslucentPass << "\n";
  os << indent << "VolumetricPass: " << this->VolumetricPass << "\n";
  os << indent << "OverlayPass: " << this->OverlayPass << "\n";
  os << indent << "ShadowMapPass: " << this->ShadowMapPass << "\n";
}

//------------------------------------------------------------------------------
const char* vtkDeepGBufferPass::GetOracleAsString(int oracle)
{
  return (oracle >= DEPTH_PEEL && oracle <= AUTOMATIC) ? OracleNames[oracle] : "UNKNOWN";
}

int vtkDeepGBufferPass::GetOracleFromString(const char* name)
{
  if (!name)
  {
    return -1;
  }
  std::string upper(name);
  std::transform(upper.begin(), upper.end(), upper.begin(),
    [](unsigned char c) { return c == '-' ? '_' : static_cast<char>(std::toupper(c)); });
  for (int i = DEPTH_PEEL; i <= AUTOMATIC; ++i)
  {
    if (upper == OracleNames[i])
    {
      return i;
    }
  }
  return -1;
}

const char* vtkDeepGBufferPass::GetQuantityAsString(int quantity)
{
  return (quantity >= RADIANCE && quantity < NUMBER_OF_QUANTITIES) ? QuantityNames[quantity]
                                                                   : "UNKNOWN";
}

//------------------------------------------------------------------------------
void vtkDeepGBufferPass::SetNumberOfLayers(int layers)
{
  int clamped = std::min(std::max(layers, 1), static_cast<int>(MAXIMUM_NUMBER_OF_LAYERS));
  if (clamped != layers)
  {
    vtkWarningMacro("NumberOfLayers " << layers << " is outside [1, " << MAXIMUM_NUMBER_OF_LAYERS
                                      << "]; using " << clamped << ".");
  }
  if (clamped != this->NumberOfLayers)
  {
    this->NumberOfLayers = clamped;
    this->Modified();
  }
}

void vtkDeepGBufferPass::SetMinimumSeparation(double dz)
{
  if (!std::isfinite(dz))
  {
    vtkWarningMacro("MinimumSeparation must be finite (got "
      << dz << "); keeping "
      << (this->AutomaticMinimumSeparation ? "the automatic value" : "the previous value") << ".");
    return;
  }
  if (dz < 0.0)
  {
    vtkWarningMacro("MinimumSeparation must not be negative (got " << dz << "); using 0.");
    dz = 0.0;
  }
  if (dz != this->MinimumSeparation || this->AutomaticMinimumSeparation)
  {
    this->MinimumSeparation = dz;
    this->AutomaticMinimumSeparation = false;
    this->Modified();
  }
}

void vtkDeepGBufferPass::SetGuardBand(double fraction)
{
  if (std::isnan(fraction))
  {
    vtkWarningMacro("GuardBand must be a number (got NaN); keeping " << this->GuardBand << ".");
    return;
  }
  if (fraction < 0.0 || fraction > MAXIMUM_GUARD_BAND)
  {
    const double clamped = std::min(std::max(fraction, 0.0), MAXIMUM_GUARD_BAND);
    vtkWarningMacro("GuardBand must be within [0, " << MAXIMUM_GUARD_BAND << "] (got " << fraction
                                                    << "); using " << clamped << ".");
    fraction = clamped;
  }
  if (fraction != this->GuardBand)
  {
    this->GuardBand = fraction;
    this->Modified();
  }
}

void vtkDeepGBufferPass::SetWriteReflectivity(bool write)
{
  if (write != this->WriteReflectivity)
  {
    this->WriteReflectivity = write;
    // The fragment shaders gain or lose their REFLECTIVITY output.
    this->Internals->ShaderStageTime.Modified();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkDeepGBufferPass::EncodeOct16(const double normal[3], unsigned char encoded[2])
{
  double l1 = std::abs(normal[0]) + std::abs(normal[1]) + std::abs(normal[2]);
  if (!(l1 > 0.0))
  {
    encoded[0] = encoded[1] = 127;
    return;
  }
  double p[2] = { normal[0] / l1, normal[1] / l1 };
  if (normal[2] < 0.0)
  {
    double q[2] = { (1.0 - std::abs(p[1])) * (p[0] >= 0.0 ? 1.0 : -1.0),
      (1.0 - std::abs(p[0])) * (p[1] >= 0.0 ? 1.0 : -1.0) };
    p[0] = q[0];
    p[1] = q[1];
  }
  for (int i = 0; i < 2; ++i)
  {
    double c = std::min(std::max(p[i], -1.0), 1.0);
    encoded[i] = static_cast<unsigned char>(std::floor(c * 127.0 + 0.5) + 127.0);
  }
}

void vtkDeepGBufferPass::DecodeOct16(const unsigned char encoded[2], double normal[3])
{
  double p[2] = { (encoded[0] - 127.0) / 127.0, (encoded[1] - 127.0) / 127.0 };
  normal[0] = p[0];
  normal[1] = p[1];
  normal[2] = 1.0 - std::abs(p[0]) - std::abs(p[1]);
  if (normal[2] < 0.0)
  {
    normal[0] = (1.0 - std::abs(p[1])) * (p[0] >= 0.0 ? 1.0 : -1.0);
    normal[1] = (1.0 - std::abs(p[0])) * (p[1] >= 0.0 ? 1.0 : -1.0);
  }
  vtkMath::Normalize(normal);
}

//------------------------------------------------------------------------------
namespace
{
// Whether a triangle geometry shader can route every primitive this prop's
// mapper draws. Decided from the prop alone, so that the decision made
// before drawing and the one made while the mapper builds its shaders agree.
bool IsRoutable(vtkProp* prop)
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  if (!actor || !actor->GetMapper() ||
    std::string(actor->GetMapper()->GetClassName()) != "vtkOpenGLPolyDataMapper")
  {
    return false;
  }
  vtkProperty* property = actor->GetProperty();
  if (property->GetRepresentation() != VTK_SURFACE || property->GetEdgeVisibility() ||
    property->GetVertexVisibility())
  {
    return false;
  }
  if (actor->GetShaderProperty() && actor->GetShaderProperty()->HasGeometryShaderCode())
  {
    return false;
  }
  vtkPolyData* input = vtkPolyDataMapper::SafeDownCast(actor->GetMapper())->GetInput();
  return input && input->GetNumberOfVerts() == 0 && input->GetNumberOfLines() == 0;
}
}

//------------------------------------------------------------------------------
namespace
{
namespace Tokens = vtkDeepGBufferShaderTokens;

bool Contains(const std::string& shader, const char* token)
{
  return shader.find(token) != std::string::npos;
}

// The DEEP_GBUFFER_* expressions of vtkDeepGBufferOutputsFS for this
// mapper's final fragment shader (what VTK's shading declared).
std::string OutputExpressions(const std::string& fs, bool writeReflectivity)
{
  const bool pbr = Contains(fs, Tokens::PBRAlbedoDeclaration);
  const bool textured = Contains(fs, Tokens::TextureColorDeclaration) && !pbr;
  // VTK's colour is ambientColor + diffuse + specular (times the texture):
  // its ambient part is what ambient obscurance darkens. PBR lighting has no
  // separate ambient term here (its image-based light is left whole).
  std::string defines = std::string("#define DEEP_GBUFFER_ALBEDO ") +
    (pbr           ? "albedo"
        : textured ? "(diffuseColor * tcolor.rgb)"
                   : "diffuseColor") +
    "\n#define DEEP_GBUFFER_AMBIENT " +
    (pbr           ? "vec3(0.0)"
        : textured ? "(ambientColor * tcolor.rgb)"
                   : "ambientColor") +
    "\n#define DEEP_GBUFFER_NORMAL " +
    (Contains(fs, Tokens::ShadingNormalDeclaration) ? "normalize(normalVCVSOutput)"
                                                    : "deepGeometricNormal") +
    "\n";
  if (writeReflectivity)
  {
    // Mirror reflectance from VTK's material (see SetWriteReflectivity). PBR:
    // Fresnel at normal incidence, F0 as VTK's PBR lighting computes it
    // (its F0 where lit; the base-layer default 0.04 where unlit), fading
    // to 0 as the surface gets rough. Phong/Gouraud: VTK's specularColor,
    // i.e. Specular x SpecularColor; props without lighting have none.
    const std::string f0 =
      Contains(fs, Tokens::PBRFresnelDeclaration) ? "F0" : "mix(vec3(0.04), albedo, metallic)";
    defines += std::string("#define DEEP_GBUFFER_REFLECTIVITY ") +
      (pbr ? "(" + f0 + " * ((1.0 - roughness) * (1.0 - roughness)))"
          : Contains(fs, Tokens::SpecularColorDeclaration) ? std::string("specularColor")
                                                           : std::string("vec3(0.0)")) +
      "\n";
  }
  return defines;
}
}

//------------------------------------------------------------------------------
// Vertex stage: the other frame's clip position and the guard band (paper
// sections 3.2 and 3.5); geometry stage: the layer routing of Listing 2
// when one pass fills every layer; fragment stage: the minimum-separation
// test before VTK's colouring and lighting.
bool vtkDeepGBufferPass::PreReplaceShaderValues(std::string& vertexShader,
  std::string& geometryShader, std::string& fragmentShader, vtkAbstractMapper* mapper,
  vtkProp* prop)
{
  if (!vtkOpenGLPolyDataMapper::SafeDownCast(mapper))
  {
    return true;
  }
  vtkInternals& in = *this->Internals;
  const bool routed = in.GeometryShaderSlots > 1 && geometryShader.empty() && in.IsRouted(prop);
  // Mappers whose geometry shader projects view-space positions itself get
  // the guard band's scale at each vertex it emits, not in the vertex shader.
  const bool geometryShaderProjects = Contains(geometryShader, Tokens::GeometryProjects);
  vtkShaderProgram::Substitute(vertexShader, Tokens::CameraDeclarations,
    std::string(Tokens::CameraDeclarations) + "\n" + vtkDeepGBufferLayerDecVS, false);
  vtkShaderProgram::Substitute(vertexShader, Tokens::PositionImplementation,
    std::string(Tokens::PositionImplementation) + "\n" +
      (geometryShaderProjects ? "#define DEEP_GBUFFER_GS_PROJECTS\n" : "") +
      vtkDeepGBufferLayerImplVS,
    false);
  if (geometryShaderProjects)
  {
    vtkShaderProgram::Substitute(geometryShader, Tokens::GeometryMain,
      std::string(vtkDeepGBufferGuardBandDecGS) + Tokens::GeometryMain, false);
    vtkShaderProgram::Substitute(geometryShader, Tokens::GeometryEmitVertex,
      std::string(vtkDeepGBufferGuardBandGS) + Tokens::GeometryEmitVertex, true);
  }
  if (routed)
  {
    std::string gs = vtkDeepGBufferGS;
    vtkShaderProgram::Substitute(
      gs, "DEEP_GBUFFER_MAX_VERTICES", std::to_string(3 * in.GeometryShaderSlots));
    vtkShaderProgram::Substitute(
      gs, "DEEP_GBUFFER_LAYER_SLOTS", std::to_string(in.GeometryShaderSlots));
    vtkShaderProgram::Substitute(
      gs, "DEEP_GBUFFER_DISPLAYED_LAYERS", std::to_string(in.GeometryShaderLayers));
    geometryShader = gs;
  }
  vtkShaderProgram::Substitute(fragmentShader, Tokens::DepthPeelingDeclarations,
    std::string(Tokens::DepthPeelingDeclarations) + "\n" + vtkDeepGIShaderConstantsGLSL +
      (routed ? "#define DEEP_GBUFFER_ROUTED\n" : "") +
      (in.GeometryShaderLayers == 1 ? "#define DEEP_GBUFFER_SINGLE_LAYER\n" : "") +
      "//VTK::DeepGBuffer::OutputExpressions\n" + vtkDeepGBufferLayerDecFS + vtkDeepGBufferCommon,
    false);
  vtkShaderProgram::Substitute(fragmentShader, Tokens::DepthPeelingPreColor,
    std::string(Tokens::DepthPeelingPreColor) + "\n" + vtkDeepGBufferLayerTestFS, false);
  // The outputs go after texturing, where VTK's albedo is final (Post).
  vtkShaderProgram::Substitute(fragmentShader, Tokens::TextureCoordinates,
    std::string(Tokens::TextureCoordinates) + "\n  //VTK::DeepGBuffer::Impl\n", false);
  return true;
}

//------------------------------------------------------------------------------
// The G-buffer outputs, once VTK's shading has declared what they read.
bool vtkDeepGBufferPass::PostReplaceShaderValues(std::string& vtkNotUsed(vertexShader),
  std::string& vtkNotUsed(geometryShader), std::string& fragmentShader, vtkAbstractMapper* mapper,
  vtkProp* vtkNotUsed(prop))
{
  if (!vtkOpenGLPolyDataMapper::SafeDownCast(mapper))
  {
    return true;
  }
  if (!Contains(fragmentShader, Tokens::ShadingNormalDeclaration))
  {
    vtkShaderProgram::Substitute(fragmentShader, Tokens::UniformFlow,
      std::string(Tokens::UniformFlow) + "\n" + vtkDeepGBufferUnlitNormalFS, false);
  }
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::DeepGBuffer::OutputExpressions",
    OutputExpressions(fragmentShader, this->WriteReflectivity), false);
  vtkShaderProgram::Substitute(
    fragmentShader, "//VTK::DeepGBuffer::Impl", vtkDeepGBufferOutputsFS, false);
  return true;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkDeepGBufferPass::GetShaderStageMTime()
{
  return this->Internals->ShaderStageTime.GetMTime();
}

//------------------------------------------------------------------------------
namespace
{
// Adds the back faces to the faces the rasteriser culls for the draw that
// follows, on top of what the prop's property culls (vtkOpenGLProperty sets
// the culling per actor just before its mapper draws, which is when the
// render pass's SetShaderParameters runs).
void CullBackFaces(vtkOpenGLState* state)
{
  GLint mode = GL_BACK;
  if (state->GetEnumState(GL_CULL_FACE))
  {
    glGetIntegerv(GL_CULL_FACE_MODE, &mode);
  }
  state->vtkglCullFace(mode == GL_BACK ? GL_BACK : GL_FRONT_AND_BACK);
  state->vtkglEnable(GL_CULL_FACE);
}

// The face culling of the renderer's state, restored when the scope ends.
class ScopedFaceCulling
{
public:
  explicit ScopedFaceCulling(vtkOpenGLState* state)
    : State(state)
    , Enabled(state->GetEnumState(GL_CULL_FACE))
  {
    glGetIntegerv(GL_CULL_FACE_MODE, &this->Mode);
  }
  ~ScopedFaceCulling()
  {
    this->State->vtkglCullFace(static_cast<unsigned int>(this->Mode));
    this->State->SetEnumState(GL_CULL_FACE, this->Enabled);
  }
  ScopedFaceCulling(const ScopedFaceCulling&) = delete;
  ScopedFaceCulling& operator=(const ScopedFaceCulling&) = delete;

private:
  vtkOpenGLState* State;
  bool Enabled;
  GLint Mode = GL_BACK;
};

// The model-to-stored-coordinates matrix of a mapper's vertex buffer: the
// same association as vtkOpenGLPolyDataMapper, (P V) (M S^-1), where stored
// coordinates are (x - shift) * scale.
Matrix ModelToStored(const Matrix& model, vtkAbstractMapper* mapper)
{
  vtkOpenGLVertexBufferObject* positions =
    static_cast<vtkOpenGLPolyDataMapper*>(mapper)->GetVBOs()->GetVBO("vertexMC");
  if (!positions || !positions->GetCoordShiftAndScaleEnabled())
  {
    return model;
  }
  const std::vector<double>& shift = positions->GetShift();
  const std::vector<double>& scale = positions->GetScale();
  Matrix unshift = Identity();
  for (int i = 0; i < 3 && i < static_cast<int>(shift.size()); ++i)
  {
    unshift[i * 4 + i] = 1.0 / scale[i];
    unshift[i * 4 + 3] = shift[i];
  }
  return Multiply(model, unshift);
}

// Uniform setters that skip what the compiler removed (e.g. the routing
// uniforms without a geometry shader).
void SetIfUsed(vtkShaderProgram* program, const char* name, int value)
{
  if (program->IsUniformUsed(name))
  {
    program->SetUniformi(name, value);
  }
}

void SetIfUsed(vtkShaderProgram* program, const char* name, float value)
{
  if (program->IsUniformUsed(name))
  {
    program->SetUniformf(name, value);
  }
}

template <size_t N>
void SetIfUsed(vtkShaderProgram* program, const char* name, const std::array<float, N>& value)
{
  static_assert(N == 2 || N == 4 || N == 16, "vec2, vec4 or mat4");
  if (!program->IsUniformUsed(name))
  {
    return;
  }
  std::array<float, N> copy = value; // VTK's setters take non-const pointers
  if (N == 2)
  {
    program->SetUniform2f(name, copy.data());
  }
  else if (N == 4)
  {
    program->SetUniform4f(name, copy.data());
  }
  else
  {
    program->SetUniformMatrix4x4(name, copy.data());
  }
}
}

//------------------------------------------------------------------------------
// Per draw: the prop's position in the other frame (vertex stage), and the
// layer test's and outputs' uniforms. Every program gets the uniforms it
// uses, also those whose vertex shader has no position hook (and so no
// deepOtherMCDC), such as point Gaussian splats: their fragment shaders
// still write the layers.
bool vtkDeepGBufferPass::SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper,
  vtkProp* prop, vtkOpenGLVertexArrayObject* vtkNotUsed(VAO))
{
  vtkInternals& in = *this->Internals;
  if (!vtkOpenGLPolyDataMapper::SafeDownCast(mapper) || !in.Current)
  {
    return true;
  }
  // VTK uploads a renderer's lights to a program only when they or its
  // camera are newer than the program's last upload
  // (vtkOpenGLRenderer::UpdateLightingUniforms). The programs are shared
  // by the window's renderers, so a renderer whose camera and lights are
  // older than another's would draw with that one's view-space lights.
  // Forgetting the upload time makes the mapper's lighting step, which
  // follows this call, upload this renderer's (a few uniforms per draw).
  program->SetUniformGroupUpdateTime(vtkShaderProgram::LightingGroup, 0);
  SetIfUsed(program, "deepGuardBandScale", in.GuardBandScale);
  if (program->IsUniformUsed("deepOtherMCDC"))
  {
    // Computed like VTK's own MCDCMatrix, so that DELAY rasterises exactly
    // what the previous frame did.
    const Matrix otherModel = in.OtherModelMatrix(prop);
    std::array<float, 16> otherMCDC =
      ToColumnMajor(Multiply(in.OtherWorldToClip, ModelToStored(otherModel, mapper)));
    program->SetUniformMatrix4x4("deepOtherMCDC", otherMCDC.data());
  }
  // Shaders with the routing geometry shader choose positions per layer
  // there; the others swap in the vertex shader for the layer they draw.
  const bool routedProgram = program->IsUniformUsed("deepEmitMask");
  SetIfUsed(program, "deepVertexUsesOtherClip",
    routedProgram ? 0 : (in.OtherClipLayerMask >> in.TargetLayer) & 1);
  SetIfUsed(program, "deepEmitMask", in.EmitMask);
  SetIfUsed(program, "deepOtherClipLayerMask", in.OtherClipLayerMask);
  SetIfUsed(program, "deepTestMode", in.TestMode);
  SetIfUsed(program, "deepTargetLayer", in.TargetLayer);
  SetIfUsed(program, "deepOracleLayerIndex", in.OracleLayerIndex);
  SetIfUsed(program, "deepCullBackFaces", this->DeepLayerBackfaceCulling ? 1 : 0);
  SetIfUsed(program, "deepMinimumSeparation", in.MinimumSeparation);
  SetIfUsed(program, "deepProjectionZ", in.ProjectionZ);
  SetIfUsed(program, "deepOtherProjectionZ", in.OtherProjectionZ);
  SetIfUsed(program, "deepInverseProjection", in.InverseProjection);
  SetIfUsed(program, "deepViewportSize", in.ViewportSize);
  SetIfUsed(program, "deepHistoryDistance", in.HistoryUnit);
  // An emissive prop's ambient term is its emission, not the environment's
  // light: it stays in RADIANCE and out of AMBIENT (see EMISSIVE()).
  vtkInformation* keys = prop ? prop->GetPropertyKeys() : nullptr;
  SetIfUsed(
    program, "deepEmissive", keys && keys->Has(EMISSIVE()) && keys->Get(EMISSIVE()) != 0 ? 1 : 0);
  if (in.CullingState && !routedProgram)
  {
    CullBackFaces(in.CullingState);
  }
  return true;
}

//------------------------------------------------------------------------------
// The prop's model matrix in the other frame the oracle needs: its previous
// one (REPROJECT, DELAY) or the one extrapolated from its last two
// (PREDICT), when the prop was drawn in the previous frame; otherwise this
// frame's. The history is updated once per frame.
Matrix vtkDeepGBufferPass::vtkInternals::OtherModelMatrix(vtkProp* prop)
{
  vtkDeepGBufferRendererState& state = *this->Current;
  auto& history = state.Props[prop];
  if (history.Frame == state.FrameIndex)
  {
    return history.OtherModel;
  }
  vtkProp3D* prop3D = vtkProp3D::SafeDownCast(prop);
  const Matrix model = prop3D ? ToArray(prop3D->GetMatrix()) : Identity();
  history.PreviousModel = history.Model;
  history.PreviousFrame = history.Frame;
  history.Model = model;
  history.Frame = state.FrameIndex;
  state.PropLiveness[prop] = prop;
  Matrix otherModel = model;
  if (history.PreviousFrame + 1 == state.FrameIndex && history.PreviousFrame != 0)
  {
    if (this->OtherUsesPreviousFrame)
    {
      otherModel = history.PreviousModel;
    }
    else if (this->OtherIsPrediction)
    {
      otherModel = Extrapolate(history.PreviousModel, model);
    }
  }
  history.OtherModel = otherModel;
  return otherModel;
}

//------------------------------------------------------------------------------
namespace
{
GLuint NewArrayTexture(GLenum internalFormat, GLenum format, GLenum type, int w, int h, int layers)
{
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D_ARRAY, texture);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, internalFormat, w, h, layers, 0, format, type, nullptr);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  return texture;
}
}

//------------------------------------------------------------------------------
// The draw buffers of a renderer's G-buffer framebuffers: every quantity
// allocated, except AMBIENT while it is not written (GL_NONE). Returns the
// count.
static GLsizei DrawBufferList(const vtkDeepGBufferRendererState& state,
  GLenum buffers[vtkDeepGBufferPass::NUMBER_OF_QUANTITIES])
{
  for (int q = 0; q < vtkDeepGBufferPass::NUMBER_OF_QUANTITIES; ++q)
  {
    buffers[q] = GL_COLOR_ATTACHMENT0 + q;
  }
  if (!state.WritesAmbient)
  {
    buffers[vtkDeepGBufferPass::AMBIENT] = GL_NONE;
  }
  return state.Textures[vtkDeepGBufferPass::REFLECTIVITY] ? vtkDeepGBufferPass::NUMBER_OF_QUANTITIES
                                                          : BaseQuantities;
}

//------------------------------------------------------------------------------
// Allocates (or keeps) the textures and framebuffers of a renderer's
// G-buffer. Returns false if the framebuffer is incomplete.
static bool AllocateTargets(vtkDeepGBufferRendererState& state, vtkOpenGLState* ostate, int width,
  int height, int slots, int historyLayers)
{
  if (state.Width == width && state.Height == height && state.Slots == slots &&
    state.HistoryLayers == historyLayers && state.LayeredFramebuffer)
  {
    return true;
  }
  state.ReleaseTextures();
  state.Width = width;
  state.Height = height;
  state.Slots = slots;
  state.HistoryLayers = historyLayers;
  state.WritesAmbient = true;
  for (int q = 0; q < BaseQuantities; ++q)
  {
    state.Textures[q] = NewArrayTexture(
      QuantityInternalFormats[q], QuantityFormats[q], QuantityTypes[q], width, height, slots);
  }
  state.DepthTexture =
    NewArrayTexture(GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, width, height, slots);
  state.HistoryTexture = NewArrayTexture(GL_R32F, GL_RED, GL_FLOAT, width, height, historyLayers);

  ostate->PushFramebufferBindings();
  bool complete = true;
  // The draw buffers are framebuffer state, set once here with raw GL:
  // vtkOpenGLState caches them across framebuffers, so setting them through
  // it after a bind may be skipped.
  GLenum drawBuffers[vtkDeepGBufferPass::NUMBER_OF_QUANTITIES];
  const GLsizei drawBufferCount = DrawBufferList(state, drawBuffers);
  auto attach = [&](GLuint framebuffer, int layer)
  {
    ostate->vtkglBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glDrawBuffers(drawBufferCount, drawBuffers);
    for (int q = 0; q < BaseQuantities; ++q)
    {
      if (layer < 0)
      {
        glFramebufferTexture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + q, state.Textures[q], 0);
      }
      else
      {
        glFramebufferTextureLayer(
          GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + q, state.Textures[q], 0, layer);
      }
    }
    if (layer < 0)
    {
      glFramebufferTexture(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, state.DepthTexture, 0);
    }
    else
    {
      glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, state.DepthTexture, 0, layer);
    }
    complete = complete && glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  };
  glGenFramebuffers(1, &state.LayeredFramebuffer);
  attach(state.LayeredFramebuffer, -1);
  state.LayerFramebuffers.resize(slots);
  glGenFramebuffers(slots, state.LayerFramebuffers.data());
  for (int j = 0; j < slots; ++j)
  {
    attach(state.LayerFramebuffers[j], j);
  }
  ostate->PopFramebufferBindings();
  state.HistoryValid = false;
  return complete;
}

//------------------------------------------------------------------------------
// Adds or removes the optional REFLECTIVITY target of a renderer's G-buffer
// (attachment BaseQuantities of every framebuffer) without touching the
// other targets, so the oracles' history survives the change.
static bool UpdateReflectivityTarget(
  vtkDeepGBufferRendererState& state, vtkOpenGLState* ostate, bool write)
{
  GLuint& texture = state.Textures[vtkDeepGBufferPass::REFLECTIVITY];
  if (write == (texture != 0))
  {
    return true;
  }
  if (write)
  {
    texture = NewArrayTexture(QuantityInternalFormats[vtkDeepGBufferPass::REFLECTIVITY],
      QuantityFormats[vtkDeepGBufferPass::REFLECTIVITY],
      QuantityTypes[vtkDeepGBufferPass::REFLECTIVITY], state.Width, state.Height, state.Slots);
  }
  const GLuint removed = write ? 0 : texture;
  texture = write ? texture : 0; // attaching 0 detaches
  GLenum drawBuffers[vtkDeepGBufferPass::NUMBER_OF_QUANTITIES];
  const GLsizei count = DrawBufferList(state, drawBuffers);
  ostate->PushFramebufferBindings();
  bool complete = true;
  auto attach = [&](GLuint framebuffer, int layer)
  {
    ostate->vtkglBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    if (layer < 0)
    {
      glFramebufferTexture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + BaseQuantities, texture, 0);
    }
    else
    {
      glFramebufferTextureLayer(
        GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + BaseQuantities, texture, 0, layer);
    }
    glDrawBuffers(count, drawBuffers);
    complete = complete && glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  };
  attach(state.LayeredFramebuffer, -1);
  for (int j = 0; j < static_cast<int>(state.LayerFramebuffers.size()); ++j)
  {
    attach(state.LayerFramebuffers[j], j);
  }
  ostate->PopFramebufferBindings();
  if (removed)
  {
    glDeleteTextures(1, &removed);
  }
  return complete;
}

//------------------------------------------------------------------------------
// Stores the fragment shader's AMBIENT output only while some prop can have
// an ambient term. Otherwise the target holds zeros, cleared once, and its
// draw buffer is GL_NONE, so the shader's ambient output and its store are
// dropped: on llvmpipe that is 7 % of the instructions of building two
// layers with VTK's default properties (Ambient 0; performance.md). The
// consumers read the same zeros either way.
static void UpdateAmbientWrites(
  vtkDeepGBufferRendererState& state, vtkOpenGLState* ostate, bool write)
{
  if (state.WritesAmbient == write)
  {
    return;
  }
  ostate->PushFramebufferBindings();
  if (!write)
  {
    // The zeros, once, while AMBIENT is still a draw buffer (the per-frame
    // clear skips it afterwards).
    ostate->vtkglBindFramebuffer(GL_FRAMEBUFFER, state.LayeredFramebuffer);
    const float zero[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
    glClearBufferfv(GL_COLOR, vtkDeepGBufferPass::AMBIENT, zero);
  }
  state.WritesAmbient = write;
  GLenum drawBuffers[vtkDeepGBufferPass::NUMBER_OF_QUANTITIES];
  const GLsizei count = DrawBufferList(state, drawBuffers);
  ostate->vtkglBindFramebuffer(GL_FRAMEBUFFER, state.LayeredFramebuffer);
  glDrawBuffers(count, drawBuffers);
  for (GLuint framebuffer : state.LayerFramebuffers)
  {
    ostate->vtkglBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glDrawBuffers(count, drawBuffers);
  }
  ostate->PopFramebufferBindings();
}

//------------------------------------------------------------------------------
namespace
{
// Copies layer `from` of the distance texture into layer `to` of the history.
void CopyDistanceLayer(vtkDeepGBufferRendererState& state, int from, int to)
{
  glCopyImageSubData(state.Textures[vtkDeepGBufferPass::DEPTH], GL_TEXTURE_2D_ARRAY, 0, 0, 0, from,
    state.HistoryTexture, GL_TEXTURE_2D_ARRAY, 0, 0, 0, to, state.Width, state.Height, 1);
}

// Bytes per pixel of quantity q as it is read back and uploaded (its format
// and type, e.g. 12 for AMBIENT's R11F_G11F_B10F read as three floats).
int QuantityTransferBytes(int q)
{
  const int components = QuantityFormats[q] == GL_RGBA ? 4
    : QuantityFormats[q] == GL_RGB                     ? 3
    : QuantityFormats[q] == GL_RG                      ? 2
                                                       : 1;
  const int componentBytes = QuantityTypes[q] == GL_UNSIGNED_BYTE ? 1
    : QuantityTypes[q] == GL_HALF_FLOAT                           ? 2
                                                                  : 4;
  return components * componentBytes;
}

// Copies one quantity's plane (`bytes` per pixel) into the interleaved
// per-pixel records at `offset` (toInterleaved), or back out of them.
void InterleavePlane(std::vector<unsigned char>& plane, int bytes,
  std::vector<unsigned char>& interleaved, int offset, int stride, bool toInterleaved)
{
  const size_t pixels = plane.size() / bytes;
  for (size_t p = 0; p < pixels; ++p)
  {
    unsigned char* record = interleaved.data() + p * stride + offset;
    unsigned char* texel = plane.data() + p * bytes;
    if (toInterleaved)
    {
      std::copy(texel, texel + bytes, record);
    }
    else
    {
      std::copy(record, record + bytes, texel);
    }
  }
}

// Writes layer `layer` of an array texture. The active unit's binding is
// restored: while layers are drawn it holds the oracle's history.
void UploadLayer(
  GLuint texture, int layer, int width, int height, GLenum format, GLenum type, const void* data)
{
  GLint bound = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D_ARRAY, &bound);
  glBindTexture(GL_TEXTURE_2D_ARRAY, texture);
  glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, layer, width, height, 1, format, type, data);
  glBindTexture(GL_TEXTURE_2D_ARRAY, static_cast<GLuint>(bound));
}

// Clears every layer of every quantity (distance 0 marks an empty pixel)
// and the depth.
void ClearLayers(vtkDeepGBufferRendererState& state, vtkOpenGLState* ostate)
{
  ostate->vtkglBindFramebuffer(GL_FRAMEBUFFER, state.LayeredFramebuffer);
  const float zero[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
  for (int q = 0; q < vtkDeepGBufferPass::NUMBER_OF_QUANTITIES; ++q)
  {
    if (state.Textures[q])
    {
      glClearBufferfv(GL_COLOR, q, zero);
    }
  }
  const float farDepth = 1.0f;
  glClearBufferfv(GL_DEPTH, 0, &farDepth);
}

void DrawOpaque(const std::vector<vtkProp*>& props, vtkRenderer* renderer)
{
  for (vtkProp* prop : props)
  {
    prop->RenderOpaqueGeometry(renderer);
  }
}

// The history the next frame's separation tests read (Listing 2 reads
// Z_{t-1}): the oracle's own layer, or the displayed layers but the last.
// Peeling copied each layer before drawing the next; a single pass did not.
void StoreHistory(vtkDeepGBufferRendererState& state, int layers, int oracleSlots, bool peeled)
{
  if (oracleSlots)
  {
    CopyDistanceLayer(state, layers, 0);
  }
  else if (!peeled)
  {
    for (int j = 0; j + 1 < layers; ++j)
    {
      CopyDistanceLayer(state, j, j);
    }
  }
  state.HistoryValid = true;
  state.HistoryIsPredicted = oracleSlots == 1;
  state.HistoryNumberOfLayers = layers;
}

// Forgets the motion history of props that no longer exist.
void ForgetDeletedProps(vtkDeepGBufferRendererState& state)
{
  for (auto it = state.PropLiveness.begin(); it != state.PropLiveness.end();)
  {
    if (!it->second)
    {
      state.Props.erase(it->first);
      it = state.PropLiveness.erase(it);
    }
    else
    {
      ++it;
    }
  }
}
}

//------------------------------------------------------------------------------
// Checks once per context what the G-buffer needs: geometry shaders and
// array textures (OpenGL 3.2), glCopyImageSubData (4.3 or ARB_copy_image),
// four draw buffers, and how many layers a geometry shader can emit.
static bool CheckSupport(vtkOpenGLRenderWindow* window, int& maximumSlots, std::string& why)
{
  int major = 0, minor = 0;
  window->GetOpenGLVersion(major, minor);
  if (major * 10 + minor < 32)
  {
    why = "OpenGL " + std::to_string(major) + "." + std::to_string(minor) +
      " has no geometry shaders or array textures (3.2 is required)";
    return false;
  }
  if (!(GLEW_VERSION_4_3 || GLEW_ARB_copy_image))
  {
    why = "glCopyImageSubData (OpenGL 4.3 or ARB_copy_image) is not available";
    return false;
  }
  GLint drawBuffers = 0, attachments = 0, arrayLayers = 0, gsVertices = 0, gsComponents = 0;
  glGetIntegerv(GL_MAX_DRAW_BUFFERS, &drawBuffers);
  glGetIntegerv(GL_MAX_COLOR_ATTACHMENTS, &attachments);
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &arrayLayers);
  glGetIntegerv(GL_MAX_GEOMETRY_OUTPUT_VERTICES, &gsVertices);
  glGetIntegerv(GL_MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS, &gsComponents);
  if (drawBuffers < vtkDeepGBufferPass::NUMBER_OF_QUANTITIES ||
    attachments < vtkDeepGBufferPass::NUMBER_OF_QUANTITIES)
  {
    why =
      "fewer than " + std::to_string(vtkDeepGBufferPass::NUMBER_OF_QUANTITIES) + " draw buffers";
    return false;
  }
  maximumSlots = std::min({ static_cast<int>(arrayLayers), static_cast<int>(gsVertices) / 3,
    static_cast<int>(gsComponents) / (3 * MaximumVaryingComponentsPerVertex),
    vtkDeepGBufferPass::MAXIMUM_NUMBER_OF_LAYERS + 1 });
  return true;
}

//------------------------------------------------------------------------------
// Whether the current context renders on the CPU (Mesa llvmpipe or
// softpipe), where AUTOMATIC peels: there a geometry shader's single pass
// costs more than the second pass it saves (see the class description).
static bool IsCPURenderer()
{
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return renderer &&
    (std::strstr(renderer, "llvmpipe") != nullptr || std::strstr(renderer, "softpipe") != nullptr);
}

//------------------------------------------------------------------------------
// What one RenderLayers call decides and carries from stage to stage.
struct vtkDeepGBufferPass::vtkLayerFrame
{
  const vtkRenderState* State = nullptr;
  vtkOpenGLRenderer* Renderer = nullptr;
  vtkOpenGLRenderWindow* Window = nullptr;
  vtkOpenGLState* GL = nullptr;
  vtkDeepGBufferRendererState* RendererState = nullptr;
  // The layers: the frame and the guard band around it (section 3.5).
  int Guard = 0;
  int Width = 0;
  int Height = 0;
  // Layout: the oracle, the layers shown, the extra oracle layer of
  // PREDICT and DELAY, and whether one geometry pass fills every layer.
  int Oracle = REPROJECT;
  int Layers = 2;
  int OracleSlots = 0;
  int Slots = 2;
  bool SinglePass = false;
  double MinimumSeparation = 0.0;
  bool HistoryUsable = false;
  std::vector<vtkProp*> RoutedProps;
  std::vector<vtkProp*> OtherProps;
  // What the draw did.
  int GeometryPasses = 0;
  bool RoutedDone = false;
};

namespace
{
// The opaque props drawn the way VTK draws them, without layers.
void RenderPlain(const vtkRenderState* s)
{
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    s->GetPropArray()[i]->RenderOpaqueGeometry(s->GetRenderer());
  }
}
}

//------------------------------------------------------------------------------
bool vtkDeepGBufferPass::RenderLayers(const vtkRenderState* s)
{
  vtkLayerFrame frame;
  if (!this->BeginLayerFrame(s, frame))
  {
    return false;
  }
  this->BakeShadowMaps(frame);
  this->ChooseLayout(frame);
  if (!this->PrepareRendererState(frame))
  {
    RenderPlain(s);
    return false;
  }
  this->UpdateCameras(frame);
  this->ClassifyProps(frame);
  vtkDeepScreenSpace::ScopedStageTime time(this->StageTimer, "G-buffer: layers");
  if (!this->DrawFrame(frame))
  {
    RenderPlain(s);
    return false;
  }
  ForgetDeletedProps(*frame.RendererState);
  this->RecordFrame(frame);
  vtkOpenGLCheckErrorMacro("failed after building the deep G-buffer");
  return true;
}

//------------------------------------------------------------------------------
bool vtkDeepGBufferPass::ReuseLayers(const vtkRenderState* s)
{
  vtkInternals& in = *this->Internals;
  vtkRenderer* renderer = s->GetRenderer();
  auto it = in.States.find(renderer);
  if (it == in.States.end() || !in.Supported || this->LayerExchange || renderer->GetSelector())
  {
    return false;
  }
  const vtkDeepGBufferRendererState& state = *it->second;
  int size[2] = { 0, 0 };
  s->GetWindowSize(size);
  if (!state.LayeredFramebuffer || state.RenderedSettingsTime != this->GetMTime() ||
    size[0] != state.RenderedWindowSize[0] || size[1] != state.RenderedWindowSize[1])
  {
    return false;
  }
  // Another renderer may have been drawn since.
  this->ReportLayers(state);
  this->LastGeometryPassCount = 0;
  return true;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkDeepGBufferPass::GetLayersTime(vtkRenderer* renderer) const
{
  const auto it = this->Internals->States.find(renderer);
  return it == this->Internals->States.end() ? 0 : it->second->LayersTime;
}

//------------------------------------------------------------------------------
// The Effective* values of the layers the frame uses.
void vtkDeepGBufferPass::ReportLayers(const vtkDeepGBufferRendererState& state)
{
  this->EffectiveGuardBand = state.GuardBand;
  this->EffectiveMinimumSeparation = state.MinimumSeparation;
  this->EffectiveNumberOfLayers = state.RenderedLayers;
  this->EffectiveOracle = state.Oracle;
}

//------------------------------------------------------------------------------
bool vtkDeepGBufferPass::BeginLayerFrame(const vtkRenderState* s, vtkLayerFrame& frame)
{
  vtkInternals& in = *this->Internals;
  frame.State = s;
  frame.Renderer = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  frame.Window = vtkOpenGLRenderWindow::SafeDownCast(
    frame.Renderer ? frame.Renderer->GetRenderWindow() : nullptr);
  if (!frame.Window)
  {
    vtkErrorMacro("vtkDeepGBufferPass needs an OpenGL renderer and render window.");
    return false;
  }
  frame.GL = frame.Window->GetState();
  this->CheckContext(frame.Window);
  // Hardware picking draws ids into VTK's own buffers: leave it alone.
  if (!in.Supported || frame.Renderer->GetSelector())
  {
    RenderPlain(s);
    return false;
  }
  int size[2] = { 0, 0 };
  s->GetWindowSize(size);
  if (size[0] < 1 || size[1] < 1)
  {
    return false;
  }
  bool limited = false;
  frame.Guard =
    ComputeGuardBandPixels(this->GuardBand, size[0], size[1], in.MaximumTextureSize, &limited);
  if (limited)
  {
    std::ostringstream message;
    message << "The guard band of " << this->GuardBand << " of the height of a " << size[0] << " x "
            << size[1] << " frame is limited to " << frame.Guard << " pixels per side (at most "
            << MAXIMUM_GUARD_BAND << " of the smaller side, " << MAXIMUM_GUARD_BAND_PIXELS
            << " pixels, and layers within this GPU's texture size " << in.MaximumTextureSize
            << "); warned once.";
    in.WarnOnce(this, WARN_GUARD_BAND_LIMITED, message.str());
  }
  frame.Width = size[0] + 2 * frame.Guard;
  frame.Height = size[1] + 2 * frame.Guard;
  in.GuardBandScale = { static_cast<float>(static_cast<double>(size[0]) / frame.Width),
    static_cast<float>(static_cast<double>(size[1]) / frame.Height) };
  return true;
}

//------------------------------------------------------------------------------
void vtkDeepGBufferPass::CheckContext(vtkOpenGLRenderWindow* window)
{
  vtkInternals& in = *this->Internals;
  if (in.CheckedWindow == window)
  {
    return;
  }
  std::string why;
  in.CheckedWindow = window;
  GLint maximumTextureSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maximumTextureSize);
  in.MaximumTextureSize = static_cast<int>(maximumTextureSize);
  in.Supported = CheckSupport(window, in.MaximumSlots, why);
  in.CPURenderer = IsCPURenderer();
  if (!in.Supported)
  {
    vtkWarningMacro(
      "The deep G-buffer is not supported by this OpenGL (" << why << "); rendering without it.");
  }
}

//------------------------------------------------------------------------------
// VTK's shadow maps for this frame's lights and props, baked before the
// layers read them. The baker renders from the light cameras into its own
// framebuffer and viewport; the renderer's are restored for the layers.
void vtkDeepGBufferPass::BakeShadowMaps(vtkLayerFrame& frame)
{
  if (!this->ShadowMapPass || !this->ShadowMapPass->GetShadowMapBakerPass())
  {
    return;
  }
  vtkDeepScreenSpace::ScopedStageTime time(this->StageTimer, "G-buffer: shadow maps");
  // VTK 9.1's baker re-bakes only when lights or props changed, even after
  // ReleaseGraphicsResources freed its maps, and the shadow pass then reads
  // the missing maps: mark the lights changed while a shadowing light has
  // no map.
  vtkShadowMapBakerPass* baker = this->ShadowMapPass->GetShadowMapBakerPass();
  if (!baker->GetShadowMaps())
  {
    vtkLightCollection* lights = frame.Renderer->GetLights();
    vtkCollectionSimpleIterator it;
    lights->InitTraversal(it);
    while (vtkLight* light = lights->GetNextLight(it))
    {
      if (light->GetSwitch() && baker->LightCreatesShadow(light))
      {
        lights->Modified();
        break;
      }
    }
  }
  vtkOpenGLState::ScopedglViewport bakerViewport(frame.GL);
  vtkOpenGLState::ScopedglScissor bakerScissor(frame.GL);
  vtkOpenGLState::ScopedglClearColor bakerClearColor(frame.GL);
  baker->Render(frame.State);
}

//------------------------------------------------------------------------------
// The effective oracle, layer count and minimum separation of this frame.
void vtkDeepGBufferPass::ChooseLayout(vtkLayerFrame& frame)
{
  vtkInternals& in = *this->Internals;
  // Composited layers are peeled one submission each: layer k + 1 is
  // tested against the composited layer k, which no single-pass oracle
  // (built from this process's history) knows.
  frame.Oracle = this->LayerExchange ? DEPTH_PEEL : this->Oracle;
  if (frame.Oracle == AUTOMATIC)
  {
    frame.Oracle = in.CPURenderer ? DEPTH_PEEL : REPROJECT;
  }
  frame.Layers = this->NumberOfLayers;
  if ((frame.Oracle == PREDICT || frame.Oracle == DELAY) && frame.Layers > 2)
  {
    in.WarnOnce(this, WARN_ORACLE_LAYERS,
      std::string(GetOracleAsString(frame.Oracle)) +
        " predicts one layer; with more than 2 layers REPROJECT is used.");
    frame.Oracle = REPROJECT;
  }
  frame.OracleSlots = (frame.Oracle == PREDICT || frame.Oracle == DELAY) ? 1 : 0;
  if (frame.Layers + frame.OracleSlots > in.MaximumSlots)
  {
    in.WarnOnce(this, WARN_GEOMETRY_SHADER_LAYERS,
      "This GPU's geometry shaders allow " + std::to_string(in.MaximumSlots - frame.OracleSlots) +
        " layers; NumberOfLayers is limited to that.");
    frame.Layers = std::max(1, in.MaximumSlots - frame.OracleSlots);
  }
  frame.Slots = frame.Layers + frame.OracleSlots;
  frame.SinglePass = frame.Layers > 1 && frame.Oracle != DEPTH_PEEL;

  const double diagonal = vtkDeepScreenSpace::SceneDiagonal(frame.Renderer);
  frame.MinimumSeparation = this->AutomaticMinimumSeparation
    ? this->AutomaticSeparationFraction * diagonal
    : this->MinimumSeparation;
  if (frame.Layers > 1 && diagonal > 0.0 && frame.MinimumSeparation > diagonal)
  {
    in.WarnOnce(this, WARN_SEPARATION_EXCEEDS_SCENE,
      "MinimumSeparation " + std::to_string(frame.MinimumSeparation) +
        " exceeds the scene's size " + std::to_string(diagonal) +
        ": layers beyond the first will be empty.");
  }
}

//------------------------------------------------------------------------------
namespace
{
// Whether a visible prop can give the AMBIENT quantity a non-zero value:
// an actor with opaque geometry whose property or back-face property has
// Ambient > 0 (VTK's ambient colour is Ambient times AmbientColor, or times
// the scalar colour), or any other opaque 3D prop but a volume (volumes
// are drawn after the layers), whose mapper's ambient term is not known
// here.
bool CanHaveAmbientTerm(vtkRenderer* renderer)
{
  vtkCollectionSimpleIterator it;
  vtkPropCollection* props = renderer->GetViewProps();
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (!prop->GetVisibility() || !vtkProp3D::SafeDownCast(prop) || !prop->HasOpaqueGeometry())
    {
      continue;
    }
    prop->InitPathTraversal();
    while (vtkAssemblyPath* path = prop->GetNextPath())
    {
      vtkProp* part = path->GetLastNode()->GetViewProp();
      vtkActor* actor = vtkActor::SafeDownCast(part);
      if (!actor)
      {
        if (!vtkVolume::SafeDownCast(part) && part->GetVisibility() && part->HasOpaqueGeometry())
        {
          return true;
        }
        continue;
      }
      vtkProperty* back = actor->GetBackfaceProperty();
      if (actor->GetVisibility() && actor->HasOpaqueGeometry() &&
        (actor->GetProperty()->GetAmbient() > 0.0 || (back && back->GetAmbient() > 0.0)))
      {
        return true;
      }
    }
  }
  return false;
}
}

//------------------------------------------------------------------------------
// The renderer's state and its targets at this frame's size and layout.
bool vtkDeepGBufferPass::PrepareRendererState(vtkLayerFrame& frame)
{
  vtkInternals& in = *this->Internals;
  auto& slot = in.States[frame.Renderer];
  if (!slot)
  {
    slot.reset(new vtkDeepGBufferRendererState);
    slot->Renderer = frame.Renderer;
  }
  if (!in.FirstRenderer || !in.States.count(in.FirstRenderer))
  {
    in.FirstRenderer = frame.Renderer;
  }
  vtkDeepGBufferRendererState& state = *slot;
  frame.RendererState = &state;
  vtkOpenGLClearErrorMacro();
  if (!AllocateTargets(
        state, frame.GL, frame.Width, frame.Height, frame.Slots, std::max(1, frame.Layers - 1)) ||
    !UpdateReflectivityTarget(state, frame.GL, this->WriteReflectivity))
  {
    in.WarnOnce(this, WARN_FRAMEBUFFER_INCOMPLETE,
      "The deep G-buffer's framebuffer is incomplete; rendering without it.");
    state.ReleaseTextures();
    return false;
  }
  UpdateAmbientWrites(state, frame.GL, CanHaveAmbientTerm(frame.Renderer));
  state.FrameIndex++;
  return true;
}

//------------------------------------------------------------------------------
// Cameras of this frame and of the other frame the oracle needs (paper
// section 3.4: REPROJECT and DELAY read the previous frame, PREDICT
// extrapolates the next one).
void vtkDeepGBufferPass::UpdateCameras(vtkLayerFrame& frame)
{
  vtkInternals& in = *this->Internals;
  vtkDeepGBufferRendererState& state = *frame.RendererState;
  vtkCamera* camera = frame.Renderer->GetActiveCamera();
  // The aspect VTK's camera matrices use, so that DELAY's previous-frame
  // matrices match what VTK computed for that frame bit for bit.
  const double aspect = frame.Renderer->GetTiledAspectRatio();
  state.PreviousView = state.View;
  state.PreviousProjection = state.Projection;
  state.PreviousFrameProjection = state.FrameProjection;
  state.View = ToArray(camera->GetModelViewTransformMatrix());
  state.FrameProjection = ToArray(camera->GetProjectionTransformMatrix(aspect, -1, 1));
  ModifyStaleCamera(frame.Renderer, state.View, state.FrameProjection);
  // VTK's vertex shaders see the camera's projection; the layers' vertex
  // stage scales clip x and y by the same GuardBandScale (deepGuardBandScale).
  state.Projection = WithGuardBand(state.FrameProjection, in.GuardBandScale);
  const bool hadPreviousCamera = state.HasPreviousCamera;
  state.HasPreviousCamera = true;
  camera->GetClippingRange(state.ClippingRange);

  in.OtherUsesPreviousFrame =
    (frame.Oracle == REPROJECT || frame.Oracle == DELAY) && hadPreviousCamera;
  in.OtherIsPrediction = frame.Oracle == PREDICT && hadPreviousCamera;
  in.OtherView = state.View;
  in.OtherProjection = state.Projection;
  if (in.OtherUsesPreviousFrame)
  {
    in.OtherView = state.PreviousView;
    in.OtherProjection = state.PreviousProjection;
  }
  else if (in.OtherIsPrediction)
  {
    in.OtherView = Extrapolate(state.PreviousView, state.View);
  }
  in.OtherWorldToClip = Multiply(in.OtherProjection, in.OtherView);
  in.ProjectionZ = ProjectionDepthRows(state.Projection);
  in.OtherProjectionZ = ProjectionDepthRows(in.OtherProjection);
  in.InverseProjection = ToColumnMajor(Invert(state.Projection));
  in.ViewportSize = { static_cast<float>(frame.Width), static_cast<float>(frame.Height) };
  in.MinimumSeparation = static_cast<float>(frame.MinimumSeparation);

  // The history is usable if it was written by the previous frame with the
  // same layout and the meaning this oracle expects.
  frame.HistoryUsable = state.HistoryValid && hadPreviousCamera &&
    state.HistoryNumberOfLayers == frame.Layers &&
    state.HistoryIsPredicted == (frame.OracleSlots == 1);
}

//------------------------------------------------------------------------------
// Which props the geometry shader routes to every layer; a change of routing
// or layout rebuilds the shaders.
void vtkDeepGBufferPass::ClassifyProps(vtkLayerFrame& frame)
{
  vtkInternals& in = *this->Internals;
  // Props seen for the first time get fresh shaders anyway; only a prop
  // whose routing changed needs the rebuild (renderers sharing this pass
  // each classify their own props without invalidating the others').
  bool rebuild = false;
  for (int i = 0; i < frame.State->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = frame.State->GetPropArray()[i];
    const bool routed = frame.SinglePass && IsRoutable(prop);
    auto inserted = in.RoutedProps.insert({ prop, routed });
    if (!inserted.second && inserted.first->second != routed)
    {
      inserted.first->second = routed;
      rebuild = true;
    }
    (routed ? frame.RoutedProps : frame.OtherProps).push_back(prop);
  }
  const int geometryShaderSlots = frame.SinglePass ? frame.Slots : 0;
  if (rebuild || geometryShaderSlots != in.GeometryShaderSlots ||
    frame.Layers != in.GeometryShaderLayers)
  {
    in.GeometryShaderSlots = geometryShaderSlots;
    in.GeometryShaderLayers = frame.Layers;
    in.ShaderStageTime.Modified();
  }
}

//------------------------------------------------------------------------------
// Binds the history the separation tests read, clears the layers and draws
// them, directly or through VTK's shadow pass; restores the OpenGL state.
bool vtkDeepGBufferPass::DrawFrame(vtkLayerFrame& frame)
{
  vtkInternals& in = *this->Internals;
  vtkDeepGBufferRendererState& state = *frame.RendererState;
  vtkOpenGLState* ostate = frame.GL;
  vtkTextureUnitManager* units = frame.Window->GetTextureUnitManager();
  in.HistoryUnit = units->Allocate();
  if (in.HistoryUnit < 0)
  {
    vtkErrorMacro("No free texture unit for the deep G-buffer.");
    return false;
  }
  ostate->vtkglActiveTexture(GL_TEXTURE0 + in.HistoryUnit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, state.HistoryTexture);
  ostate->PushFramebufferBindings();
  {
    vtkOpenGLState::ScopedglViewport savedViewport(ostate);
    vtkOpenGLState::ScopedglScissor savedScissor(ostate);
    vtkOpenGLState::ScopedglClearColor savedClearColor(ostate);
    vtkOpenGLState::ScopedglDepthMask savedDepthMask(ostate);
    ostate->vtkglViewport(0, 0, frame.Width, frame.Height);
    ostate->vtkglScissor(0, 0, frame.Width, frame.Height);
    ostate->vtkglDepthMask(GL_TRUE);
    ClearLayers(state, ostate);
    this->DrawLayersWithShadows(frame);
  }
  ostate->PopFramebufferBindings();
  ostate->vtkglActiveTexture(GL_TEXTURE0 + in.HistoryUnit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  units->Free(in.HistoryUnit);
  in.HistoryUnit = -1;
  return true;
}

//------------------------------------------------------------------------------
// Everything from here to PostRender draws the layers; with shadow maps it
// runs inside vtkShadowMapPass::Render (see SetShadowMapPass), whose opaque
// sequence is the user's again afterwards.
void vtkDeepGBufferPass::DrawLayersWithShadows(vtkLayerFrame& frame)
{
  vtkInternals& in = *this->Internals;
  vtkShadowMapPass* shadows = this->ShadowMapPass && this->ShadowMapPass->GetShadowMapBakerPass()
    ? this->ShadowMapPass
    : nullptr;
  if (!shadows)
  {
    this->DrawLayers(frame);
    return;
  }
  vtkSmartPointer<vtkRenderPass> shadowSequence = shadows->GetOpaqueSequence();
  in.DrawStep->Draw = [this, &frame](const vtkRenderState*) { this->DrawLayers(frame); };
  shadows->SetOpaqueSequence(in.DrawStep);
  shadows->Render(frame.State);
  shadows->SetOpaqueSequence(shadowSequence);
  in.DrawStep->Draw = nullptr;
}

//------------------------------------------------------------------------------
// One submission fills every layer when the history allows it (paper
// Listing 2); the layers the single pass did not draw are peeled one
// submission per layer (Listing 1). Then the history of the next frame.
void vtkDeepGBufferPass::DrawLayers(vtkLayerFrame& frame)
{
  vtkInternals& in = *this->Internals;
  // ALBEDO's alpha is the surface's facing, not an opacity: its draw buffer
  // (1) does not blend. The others keep VTK's opaque-pass blending (point
  // splats blend their shape into RADIANCE).
  const GLboolean albedoBlended = glIsEnabledi(GL_BLEND, 1);
  glDisablei(GL_BLEND, 1);
  this->PreRender(frame.State);
  in.Current = frame.RendererState;
  in.OracleLayerIndex = frame.OracleSlots ? frame.Layers : -1;
  // DELAY rasterises the displayed layers at the previous frame's
  // positions; its oracle layer at the current ones (Listing 2, lines 3-6).
  const int allOracleMask = frame.OracleSlots ? (1 << frame.Layers) : 0;
  const int delayedLayersMask = (frame.Oracle == DELAY) ? ((1 << frame.Layers) - 1) : 0;
  const int predictedLayerMask = (frame.Oracle == PREDICT) ? allOracleMask : 0;
  in.OtherClipLayerMask = delayedLayersMask | predictedLayerMask;

  if (!frame.RoutedProps.empty() && frame.HistoryUsable)
  {
    frame.GL->vtkglBindFramebuffer(GL_FRAMEBUFFER, frame.RendererState->LayeredFramebuffer);
    in.EmitMask = (1 << frame.Slots) - 1;
    in.TargetLayer = 0;
    in.TestMode = frame.Oracle == REPROJECT ? TEST_REPROJECTED : TEST_SAME_PIXEL;
    DrawOpaque(frame.RoutedProps, frame.Renderer);
    frame.RoutedDone = true;
    frame.GeometryPasses = 1;
  }
  const bool peeled = this->PeelLayers(frame, allOracleMask);
  StoreHistory(*frame.RendererState, frame.Layers, frame.OracleSlots, peeled);
  in.Current = nullptr;
  this->PostRender(frame.State);
  if (albedoBlended)
  {
    glEnablei(GL_BLEND, 1);
  }
}

//------------------------------------------------------------------------------
// Paper Listing 1: one submission per layer, each tested against the layer
// before it in this frame, for whatever the single pass did not draw.
// Returns whether anything was peeled.
bool vtkDeepGBufferPass::PeelLayers(vtkLayerFrame& frame, int allOracleMask)
{
  vtkInternals& in = *this->Internals;
  vtkDeepGBufferRendererState& state = *frame.RendererState;
  const bool peelRouted = !frame.RoutedDone && !frame.RoutedProps.empty();
  if (!peelRouted && frame.OtherProps.empty() && !this->LayerExchange)
  {
    return false;
  }
  for (int j = 0; j < frame.Layers; ++j)
  {
    if (j > 0)
    {
      CopyDistanceLayer(state, j - 1, j - 1);
    }
    in.TestMode = j > 0 ? TEST_SAME_PIXEL : TEST_NONE;
    if (peelRouted)
    {
      frame.GL->vtkglBindFramebuffer(GL_FRAMEBUFFER, state.LayeredFramebuffer);
      in.EmitMask = (1 << j) | (j == 0 ? allOracleMask : 0);
      in.TargetLayer = 0;
      DrawOpaque(frame.RoutedProps, frame.Renderer);
    }
    if (!frame.OtherProps.empty())
    {
      frame.GL->vtkglBindFramebuffer(GL_FRAMEBUFFER, state.LayerFramebuffers[j]);
      in.EmitMask = 1 << j;
      in.TargetLayer = j;
      // Deeper layers keep front faces only (the fragment shader's rule):
      // culled by the rasteriser, a back face costs no shading, which a
      // CPU renderer (Mesa llvmpipe) runs in full before a discard.
      ScopedFaceCulling culling(frame.GL);
      in.CullingState = j > 0 && this->DeepLayerBackfaceCulling ? frame.GL : nullptr;
      DrawOpaque(frame.OtherProps, frame.Renderer);
      in.CullingState = nullptr;
    }
    ++frame.GeometryPasses;
    if (this->LayerExchange)
    {
      this->ExchangeLayer(frame, j);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
// Distributed rendering: replaces layer j of every quantity and of the depth
// by its composite across the processes (see vtkDeepGBufferLayerExchange).
// The layer is read back through its framebuffer, interleaved per pixel for
// the exchange, and written back into the array textures.
void vtkDeepGBufferPass::ExchangeLayer(vtkLayerFrame& frame, int j)
{
  vtkDeepGBufferRendererState& state = *frame.RendererState;
  const vtkIdType pixels = static_cast<vtkIdType>(state.Width) * state.Height;
  std::vector<int> quantities;
  int bytesPerPixel = 0;
  for (int q = 0; q < NUMBER_OF_QUANTITIES; ++q)
  {
    if (state.Textures[q])
    {
      quantities.push_back(q);
      bytesPerPixel += QuantityTransferBytes(q);
    }
  }
  std::vector<float> depth(pixels);
  std::vector<unsigned char> attributes(pixels * bytesPerPixel);
  std::vector<unsigned char> plane;
  // Through VTK's state, which caches the pixel store (rows of RG8 are not
  // 4-byte aligned).
  frame.GL->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);
  frame.GL->vtkglPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  frame.GL->vtkglBindFramebuffer(GL_FRAMEBUFFER, state.LayerFramebuffers[j]);
  glReadPixels(0, 0, state.Width, state.Height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  int offset = 0;
  for (int q : quantities)
  {
    const int bytes = QuantityTransferBytes(q);
    plane.resize(pixels * bytes);
    glReadBuffer(GL_COLOR_ATTACHMENT0 + q);
    glReadPixels(
      0, 0, state.Width, state.Height, QuantityFormats[q], QuantityTypes[q], plane.data());
    InterleavePlane(plane, bytes, attributes, offset, bytesPerPixel, true);
    offset += bytes;
  }
  if (!this->LayerExchange->CompositeLayer(pixels, depth, attributes, bytesPerPixel))
  {
    this->Internals->WarnOnce(this, WARN_LAYER_EXCHANGE_FAILED,
      "The layer exchange failed; this process keeps its own layers.");
  }
  else
  {
    UploadLayer(
      state.DepthTexture, j, state.Width, state.Height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    offset = 0;
    for (int q : quantities)
    {
      const int bytes = QuantityTransferBytes(q);
      plane.resize(pixels * bytes);
      InterleavePlane(plane, bytes, attributes, offset, bytesPerPixel, false);
      UploadLayer(state.Textures[q], j, state.Width, state.Height, QuantityFormats[q],
        QuantityTypes[q], plane.data());
      offset += bytes;
    }
  }
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  frame.GL->vtkglPixelStorei(GL_PACK_ALIGNMENT, 4);
  frame.GL->vtkglPixelStorei(GL_UNPACK_ALIGNMENT, 4);
}

//------------------------------------------------------------------------------
// What later passes and captures read about this frame's layers.
void vtkDeepGBufferPass::RecordFrame(const vtkLayerFrame& frame)
{
  const vtkInternals& in = *this->Internals;
  vtkDeepGBufferRendererState& state = *frame.RendererState;
  const bool delayed = frame.Oracle == DELAY;
  state.RenderedLayers = frame.Layers;
  state.LayerView = delayed ? in.OtherView : state.View;
  state.LayerProjection = delayed ? in.OtherProjection : state.Projection;
  state.LayerFrameProjection =
    delayed && in.OtherUsesPreviousFrame ? state.PreviousFrameProjection : state.FrameProjection;
  state.GuardBand = frame.Guard;
  state.MinimumSeparation = frame.MinimumSeparation;
  state.Oracle = frame.RoutedDone ? frame.Oracle : DEPTH_PEEL;
  state.RenderedSettingsTime = this->GetMTime();
  vtkTimeStamp rendered;
  rendered.Modified();
  state.LayersTime = rendered.GetMTime();
  state.RenderedWindowSize[0] = frame.Width - 2 * frame.Guard;
  state.RenderedWindowSize[1] = frame.Height - 2 * frame.Guard;
  this->ReportLayers(state);
  this->LastGeometryPassCount = frame.GeometryPasses;
}

//------------------------------------------------------------------------------
void vtkDeepGBufferPass::ResolveToFramebuffer(const vtkRenderState* s)
{
  vtkInternals& in = *this->Internals;
  vtkRenderer* renderer = s->GetRenderer();
  auto it = in.States.find(renderer);
  if (it == in.States.end() || !it->second->LayeredFramebuffer)
  {
    return;
  }
  vtkDeepScreenSpace::ScopedStageTime time(this->StageTimer, "G-buffer: resolve");
  vtkDeepGBufferRendererState& state = *it->second;
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  vtkOpenGLState* ostate = window->GetState();

  if (!in.ResolveQuad)
  {
    std::string fs = vtkDeepGBufferResolveFS;
    vtkShaderProgram::Substitute(fs, "//VTK::DeepGBuffer::Common",
      std::string(vtkDeepGIShaderConstantsGLSL) + vtkDeepGBufferCommon);
    in.ResolveQuad = new vtkOpenGLQuadHelper(
      window, vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), fs.c_str(), "");
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(in.ResolveQuad->Program);
  }
  vtkShaderProgram* program = in.ResolveQuad->Program;
  if (!program || !program->GetCompiled())
  {
    vtkErrorMacro("The deep G-buffer resolve shader failed to compile.");
    return;
  }

  vtkTextureUnitManager* units = window->GetTextureUnitManager();
  // The optional REFLECTIVITY may not exist in this frame: show RADIANCE.
  const int quantity = state.Textures[this->DisplayQuantity] ? this->DisplayQuantity : RADIANCE;
  const GLuint textures[3] = { state.Textures[quantity], state.Textures[DEPTH],
    state.DepthTexture };
  const char* names[3] = { "deepQuantityTexture", "deepDistance", "deepHardwareDepth" };
  int boundUnits[3];
  for (int i = 0; i < 3; ++i)
  {
    boundUnits[i] = units->Allocate();
    ostate->vtkglActiveTexture(GL_TEXTURE0 + boundUnits[i]);
    glBindTexture(GL_TEXTURE_2D_ARRAY, textures[i]);
    program->SetUniformi(names[i], boundUnits[i]);
  }
  const int layer = std::min(this->DisplayLayer, state.RenderedLayers - 1);
  program->SetUniformi("deepLayer", layer);
  program->SetUniformi("deepQuantity", quantity);
  float range[2] = { static_cast<float>(state.ClippingRange[0]),
    static_cast<float>(state.ClippingRange[1]) };
  program->SetUniform2f("deepDistanceRange", range);
  program->SetUniformi("deepGuardBand", state.GuardBand);

  vtkOpenGLState::ScopedglEnableDisable blend(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthTest(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglDepthFunc depthFunc(ostate);
  vtkOpenGLState::ScopedglDepthMask depthMask(ostate);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  ostate->vtkglDepthMask(GL_TRUE);
  in.ResolveQuad->Render();

  for (int i = 0; i < 3; ++i)
  {
    ostate->vtkglActiveTexture(GL_TEXTURE0 + boundUnits[i]);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    units->Free(boundUnits[i]);
  }
  vtkOpenGLCheckErrorMacro("failed after resolving the deep G-buffer");
}

//------------------------------------------------------------------------------
void vtkDeepGBufferPass::Render(const vtkRenderState* s)
{
  this->RenderFrame(s, nullptr);
}

//------------------------------------------------------------------------------
void vtkDeepGBufferPass::RenderFrame(const vtkRenderState* s, vtkRenderPass* opaqueStep)
{
  vtkOpenGLClearErrorMacro();
  vtkInternals& in = *this->Internals;
  this->NumberOfRenderedProps = 0;
  if (!vtkOpenGLRenderer::SafeDownCast(s->GetRenderer()))
  {
    vtkErrorMacro("vtkDeepGBufferPass needs a vtkOpenGLRenderer.");
    return;
  }
  // VTK's own frame (vtkRenderStepsPass: camera and clear, lights, opaque,
  // translucent, volumetric, overlay) with the opaque step replaced by the
  // layers and what consumes them.
  in.OpaqueStep->Draw = [this, opaqueStep](const vtkRenderState* state)
  {
    if (opaqueStep)
    {
      opaqueStep->Render(state);
    }
    else if (this->RenderLayers(state))
    {
      this->ResolveToFramebuffer(state);
    }
  };
  vtkOpenGLRenderer* renderer = static_cast<vtkOpenGLRenderer*>(s->GetRenderer());
  vtkRenderWindow* window = renderer->GetRenderWindow();
  this->LastFrameAntiAliased = renderer->GetUseFXAA() || (window && window->GetMultiSamples() > 1);
  in.AntiAliasedOverlayStep->Draw = [this, renderer](const vtkRenderState* state)
  {
    vtkInternals& internals = *this->Internals;
    this->ApplyFXAA(renderer);
    if (this->OverlayPass)
    {
      this->OverlayPass->Render(state);
      internals.AntiAliasedOverlayStep->AddRenderedProps(
        this->OverlayPass->GetNumberOfRenderedProps());
    }
  };
  in.Steps->SetLightsPass(in.LightsPass);
  in.Steps->SetOpaquePass(in.OpaqueStep);
  in.Steps->SetTranslucentPass(this->TranslucentPass);
  in.Steps->SetVolumetricPass(this->VolumetricPass);
  in.Steps->SetOverlayPass(
    this->LastFrameAntiAliased ? in.AntiAliasedOverlayStep.GetPointer() : this->OverlayPass);
  in.Steps->SetPostProcessPass(nullptr);
  in.Steps->Render(s);
  in.OpaqueStep->Draw = nullptr;
  in.AntiAliasedOverlayStep->Draw = nullptr;
  this->NumberOfRenderedProps = in.Steps->GetNumberOfRenderedProps();
  vtkOpenGLCheckErrorMacro("failed after vtkDeepGBufferPass::Render");
}

//------------------------------------------------------------------------------
// VTK's FXAA on the renderer's viewport. VTK 9.1's filter copies the colour
// from the bound read framebuffer, which fails on a multisampled window
// (the image turns black, with or without this pass): there the colour is
// first resolved into a single-sampled framebuffer of the window's size,
// which FXAA reads while it draws into the window's.
void vtkDeepGBufferPass::ApplyFXAA(vtkOpenGLRenderer* renderer)
{
  vtkInternals& in = *this->Internals;
  vtkDeepScreenSpace::ScopedStageTime time(this->StageTimer, "FXAA");
  in.FXAAFilter->UpdateConfiguration(renderer->GetFXAAOptions());
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!window || window->GetMultiSamples() <= 1)
  {
    in.FXAAFilter->Execute(renderer);
    return;
  }
  const int* size = window->GetSize();
  if (!in.ResolvedColor)
  {
    in.ResolvedColor = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    in.ResolvedColor->SetContext(window);
  }
  vtkOpenGLState* ostate = window->GetState();
  ostate->PushFramebufferBindings();
  in.ResolvedColor->Bind();
  if (in.ResolvedColor->GetNumberOfColorAttachments() == 0)
  {
    in.ResolvedColor->PopulateFramebuffer(size[0], size[1]);
  }
  in.ResolvedColor->Resize(size[0], size[1]);
  ostate->PopFramebufferBindings();
  // Read: the window's multisampled colour; draw: the resolved copy.
  ostate->PushFramebufferBindings();
  in.ResolvedColor->Bind(GL_DRAW_FRAMEBUFFER);
  const int extent[4] = { 0, size[0] - 1, 0, size[1] - 1 };
  vtkOpenGLFramebufferObject::Blit(extent, extent, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  ostate->PopFramebufferBindings();
  ostate->PushReadFramebufferBinding();
  in.ResolvedColor->Bind(GL_READ_FRAMEBUFFER);
  in.FXAAFilter->Execute(renderer);
  ostate->PopReadFramebufferBinding();
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkDeepGBufferPass::GetTextureBytes()
{
  vtkTypeInt64 bytes = 0;
  for (const auto& entry : this->Internals->States)
  {
    bytes += entry.second->TextureBytes();
  }
  return bytes;
}

//------------------------------------------------------------------------------
void vtkDeepGBufferPass::ReleaseGraphicsResources(vtkWindow* w)
{
  vtkInternals& in = *this->Internals;
  for (auto& entry : in.States)
  {
    entry.second->ReleaseTextures();
  }
  in.States.clear();
  in.FirstRenderer = nullptr;
  if (in.ResolveQuad)
  {
    in.ResolveQuad->ReleaseGraphicsResources(w);
    delete in.ResolveQuad;
    in.ResolveQuad = nullptr;
  }
  in.CheckedWindow = nullptr;
  in.FXAAFilter->ReleaseGraphicsResources();
  if (in.ResolvedColor)
  {
    in.ResolvedColor->ReleaseGraphicsResources(w);
    in.ResolvedColor = nullptr;
  }
  in.LightsPass->ReleaseGraphicsResources(w);
  in.Steps->ReleaseGraphicsResources(w);
  for (vtkRenderPass* step : { this->TranslucentPass, this->VolumetricPass, this->OverlayPass,
         static_cast<vtkRenderPass*>(this->ShadowMapPass) })
  {
    if (step)
    {
      step->ReleaseGraphicsResources(w);
    }
  }
  this->Superclass::ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
namespace
{
vtkDeepGBufferRendererState* FindState(
  std::map<vtkRenderer*, std::unique_ptr<vtkDeepGBufferRendererState>>& states,
  vtkRenderer* renderer, vtkRenderer* first)
{
  auto it = states.find(renderer ? renderer : first);
  return (it == states.end() || !it->second->LayeredFramebuffer) ? nullptr : it->second.get();
}
}

int vtkDeepGBufferPass::ComputeGuardBandPixels(
  double fraction, int width, int height, int maximumTextureSize, bool* limited)
{
  // Rounded up to a multiple of GUARD_BAND_ALIGNMENT so that the frame keeps
  // its place in the blocks of the consumers' MIP levels.
  const int alignment = GUARD_BAND_ALIGNMENT;
  const double clamped =
    std::isfinite(fraction) ? std::min(std::max(fraction, 0.0), MAXIMUM_GUARD_BAND) : 0.0;
  auto alignUp = [alignment](double pixels)
  { return (static_cast<int>(std::lround(pixels)) + alignment - 1) / alignment * alignment; };
  const int guard = alignUp(clamped * std::max(height, 0));
  // What the frame needs: the band of a tall frame is bounded by its width
  // (at most MAXIMUM_GUARD_BAND of the smaller side, so the layers hold at
  // most about 4 x the frame's pixels), and no band exceeds
  // MAXIMUM_GUARD_BAND_PIXELS; the layers fit the largest texture.
  const int smallerSide = std::max(0, std::min(width, height));
  const int textureLimit =
    std::max(0, (maximumTextureSize - std::max(width, height)) / 2 / alignment * alignment);
  const int limit = std::min(
    { alignUp(MAXIMUM_GUARD_BAND * smallerSide), MAXIMUM_GUARD_BAND_PIXELS, textureLimit });
  if (limited)
  {
    *limited = guard > limit;
  }
  return std::min(guard, limit);
}

bool vtkDeepGBufferPass::GetLayerExtent(vtkRenderer* renderer, int size[2], int& guardBand)
{
  vtkDeepGBufferRendererState* state =
    FindState(this->Internals->States, renderer, this->Internals->FirstRenderer);
  if (!state)
  {
    return false;
  }
  size[0] = state->Width;
  size[1] = state->Height;
  guardBand = state->GuardBand;
  return true;
}

int vtkDeepGBufferPass::GetLayerCamera(
  vtkRenderer* renderer, double view[16], double projection[16])
{
  vtkDeepGBufferRendererState* state =
    FindState(this->Internals->States, renderer, this->Internals->FirstRenderer);
  if (!state)
  {
    return 0;
  }
  std::copy(state->LayerView.begin(), state->LayerView.end(), view);
  std::copy(state->LayerProjection.begin(), state->LayerProjection.end(), projection);
  return state->RenderedLayers;
}

unsigned int vtkDeepGBufferPass::GetTextureHandle(vtkRenderer* renderer, int quantity)
{
  vtkDeepGBufferRendererState* state =
    FindState(this->Internals->States, renderer, this->Internals->FirstRenderer);
  if (!state || quantity < 0 || quantity >= NUMBER_OF_QUANTITIES)
  {
    return 0;
  }
  return state->Textures[quantity];
}

int vtkDeepGBufferPass::ActivateTexture(vtkRenderer* renderer, int quantity)
{
  GLuint handle = this->GetTextureHandle(renderer, quantity);
  vtkOpenGLRenderWindow* window =
    vtkOpenGLRenderWindow::SafeDownCast(renderer ? renderer->GetRenderWindow() : nullptr);
  if (!handle || !window)
  {
    return -1;
  }
  int unit = window->GetTextureUnitManager()->Allocate();
  if (unit >= 0)
  {
    window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D_ARRAY, handle);
  }
  return unit;
}

void vtkDeepGBufferPass::DeactivateTexture(vtkRenderer* renderer, int quantity)
{
  GLuint handle = this->GetTextureHandle(renderer, quantity);
  vtkOpenGLRenderWindow* window =
    vtkOpenGLRenderWindow::SafeDownCast(renderer ? renderer->GetRenderWindow() : nullptr);
  if (!handle || !window)
  {
    return;
  }
  vtkTextureUnitManager* units = window->GetTextureUnitManager();
  for (int unit = 0; unit < units->GetNumberOfTextureUnits(); ++unit)
  {
    if (!units->IsAllocated(unit))
    {
      continue;
    }
    window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + unit);
    GLint bound = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D_ARRAY, &bound);
    if (static_cast<GLuint>(bound) == handle)
    {
      glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
      units->Free(unit);
      return;
    }
  }
}

//------------------------------------------------------------------------------
namespace
{
// The G-buffer's textures read back whole (every slot) in their stored
// formats.
struct LayerDownload
{
  std::vector<float> Radiance, Distance, Ambient;
  std::vector<unsigned char> Albedo, Normal, Reflectivity;
};

void DownloadLayers(
  const vtkDeepGBufferRendererState& state, vtkOpenGLState* ostate, LayerDownload& d)
{
  const size_t slotPixels = static_cast<size_t>(state.Width) * state.Height * state.Slots;
  d.Radiance.resize(slotPixels * 4);
  d.Distance.resize(slotPixels);
  d.Ambient.resize(slotPixels * 3);
  d.Albedo.resize(slotPixels * 4);
  d.Normal.resize(slotPixels * 2);
  ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);
  vtkOpenGLState::ScopedglActiveTexture savedUnit(ostate);
  GLint previous = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D_ARRAY, &previous);
  auto download = [&](int quantity, GLenum format, GLenum type, void* data)
  {
    glBindTexture(GL_TEXTURE_2D_ARRAY, state.Textures[quantity]);
    glGetTexImage(GL_TEXTURE_2D_ARRAY, 0, format, type, data);
  };
  download(vtkDeepGBufferPass::RADIANCE, GL_RGBA, GL_FLOAT, d.Radiance.data());
  download(vtkDeepGBufferPass::ALBEDO, GL_RGBA, GL_UNSIGNED_BYTE, d.Albedo.data());
  download(vtkDeepGBufferPass::NORMAL, GL_RG, GL_UNSIGNED_BYTE, d.Normal.data());
  download(vtkDeepGBufferPass::DEPTH, GL_RED, GL_FLOAT, d.Distance.data());
  download(vtkDeepGBufferPass::AMBIENT, GL_RGB, GL_FLOAT, d.Ambient.data());
  if (state.Textures[vtkDeepGBufferPass::REFLECTIVITY])
  {
    d.Reflectivity.resize(slotPixels * 4);
    download(vtkDeepGBufferPass::REFLECTIVITY, GL_RGBA, GL_UNSIGNED_BYTE, d.Reflectivity.data());
  }
  glBindTexture(GL_TEXTURE_2D_ARRAY, previous);
  ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, 4);
}

vtkSmartPointer<vtkFloatArray> NewLayerArray(
  const char* quantity, int layer, int components, size_t pixels)
{
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  array->SetName((quantity + std::string("_") + std::to_string(layer)).c_str());
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(static_cast<vtkIdType>(pixels));
  return array;
}

// The point-data arrays of layer j (CaptureLayers); 0 where it is empty.
void AddLayerArrays(vtkPointData* pd, const LayerDownload& d, int j, size_t pixels)
{
  auto radiance = NewLayerArray(vtkDeepGICaptureNames::Radiance, j, 4, pixels);
  auto albedo = NewLayerArray(vtkDeepGICaptureNames::Albedo, j, 3, pixels);
  auto normal = NewLayerArray(vtkDeepGICaptureNames::Normal, j, 3, pixels);
  auto ambient = NewLayerArray(vtkDeepGICaptureNames::Ambient, j, 3, pixels);
  auto depth = NewLayerArray(vtkDeepGICaptureNames::Depth, j, 1, pixels);
  auto reflectivity = d.Reflectivity.empty()
    ? nullptr
    : NewLayerArray(vtkDeepGICaptureNames::Reflectivity, j, 3, pixels);
  vtkNew<vtkUnsignedCharArray> valid;
  valid->SetName((vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, j)).c_str());
  valid->SetNumberOfTuples(static_cast<vtkIdType>(pixels));
  for (size_t p = 0; p < pixels; ++p)
  {
    const size_t q = pixels * j + p;
    const bool isValid = d.Distance[q] > 0.0f;
    valid->SetValue(p, isValid ? 1 : 0);
    depth->SetValue(p, isValid ? d.Distance[q] : 0.0f);
    for (int c = 0; c < 4; ++c)
    {
      radiance->SetTypedComponent(p, c, isValid ? d.Radiance[4 * q + c] : 0.0f);
    }
    double n[3] = { 0.0, 0.0, 0.0 };
    if (isValid)
    {
      vtkDeepGBufferPass::DecodeOct16(&d.Normal[2 * q], n);
    }
    for (int c = 0; c < 3; ++c)
    {
      albedo->SetTypedComponent(p, c, isValid ? d.Albedo[4 * q + c] / 255.0f : 0.0f);
      ambient->SetTypedComponent(p, c, isValid ? d.Ambient[3 * q + c] : 0.0f);
      normal->SetTypedComponent(p, c, static_cast<float>(n[c]));
      if (reflectivity)
      {
        reflectivity->SetTypedComponent(p, c, isValid ? d.Reflectivity[4 * q + c] / 255.0f : 0.0f);
      }
    }
  }
  for (vtkDataArray* array :
    { static_cast<vtkDataArray*>(radiance), static_cast<vtkDataArray*>(albedo),
      static_cast<vtkDataArray*>(normal), static_cast<vtkDataArray*>(depth),
      static_cast<vtkDataArray*>(ambient), static_cast<vtkDataArray*>(valid) })
  {
    pd->AddArray(array);
  }
  if (reflectivity)
  {
    pd->AddArray(reflectivity);
  }
}

// The frame's description in the capture's field data.
void AddFrameFieldData(vtkImageData* output, const vtkDeepGBufferRendererState& state)
{
  vtkNew<vtkDoubleArray> separation;
  separation->SetName(vtkDeepGICaptureNames::MinimumSeparation);
  separation->InsertNextValue(state.MinimumSeparation);
  vtkNew<vtkIntArray> layerCount;
  layerCount->SetName(vtkDeepGICaptureNames::NumberOfLayers);
  layerCount->InsertNextValue(state.RenderedLayers);
  vtkNew<vtkStringArray> oracleName;
  oracleName->SetName(vtkDeepGICaptureNames::Oracle);
  oracleName->InsertNextValue(vtkDeepGBufferPass::GetOracleAsString(state.Oracle));
  output->GetFieldData()->AddArray(separation);
  output->GetFieldData()->AddArray(layerCount);
  output->GetFieldData()->AddArray(oracleName);
  // The camera of the frame, so that positions can be reconstructed in world
  // space: pixel (i, j) of the frame has its centre at NDC
  // ((i + 0.5) / width * 2 - 1, (j + 0.5) / height * 2 - 1) of the frame's
  // own projection.
  vtkDeepScreenSpace::AddCameraFieldData(
    output->GetFieldData(), state.LayerView.data(), state.LayerFrameProjection.data());
}
}

//------------------------------------------------------------------------------
bool vtkDeepGBufferPass::CaptureLayers(vtkImageData* output, vtkRenderer* renderer)
{
  vtkDeepGBufferRendererState* state =
    FindState(this->Internals->States, renderer, this->Internals->FirstRenderer);
  if (!output || !state || !state->Renderer)
  {
    vtkErrorMacro("CaptureLayers: no deep G-buffer has been rendered for this renderer.");
    return false;
  }
  vtkOpenGLRenderWindow* window =
    vtkOpenGLRenderWindow::SafeDownCast(state->Renderer->GetRenderWindow());
  window->MakeCurrent();
  vtkOpenGLClearErrorMacro();
  LayerDownload download;
  DownloadLayers(*state, window->GetState(), download);
  output->Initialize();
  output->SetDimensions(state->Width, state->Height, 1);
  output->SetSpacing(1.0, 1.0, 1.0);
  output->SetOrigin(0.0, 0.0, 0.0);
  const size_t pixels = static_cast<size_t>(state->Width) * state->Height;
  for (int j = 0; j < state->RenderedLayers; ++j)
  {
    AddLayerArrays(output->GetPointData(), download, j, pixels);
  }
  vtkDeepScreenSpace::CropGuardBand(output, state->GuardBand);
  AddFrameFieldData(output, *state);
  vtkOpenGLCheckErrorMacro("failed after capturing the deep G-buffer");
  return true;
}
