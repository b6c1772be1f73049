#include "vtkDeepScreenSpaceHelpers.h"
#include "vtkDeepGICaptureNames.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDeepGIKeys.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtk_glew.h"

#include "vtkDeepGBufferCommon.h"
#include "vtkDeepGIShaderConstantsGLSL.h"
#include "vtkDeepScreenSpaceCommon.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <locale>
#include <sstream>
#include <string>
#include <vector>

namespace
{
// Mara et al. 2016, Listing 3: tau[N - 1] is the discrepancy-minimising
// number of spiral turns for N samples, N = 1..98.
const int SpiralTurnsTable[98] = { 1, 1, 2, 3, 2, 5, 2, 3, 2, 3, 3, 5, 5, 3, 4, 7, 5, 5, 7, 9, 8, 5,
  5, 7, 7, 7, 8, 5, 8, 11, 12, 7, 10, 13, 8, 11, 8, 7, 14, 11, 11, 13, 12, 13, 19, 17, 13, 11, 18,
  19, 11, 11, 14, 17, 21, 15, 16, 17, 18, 13, 17, 11, 17, 19, 18, 25, 18, 19, 19, 29, 21, 19, 27,
  31, 29, 21, 18, 17, 29, 31, 31, 23, 18, 25, 26, 25, 23, 19, 34, 19, 27, 21, 25, 39, 29, 17, 21,
  27 };
}

namespace vtkDeepScreenSpace
{
//------------------------------------------------------------------------------
int SpiralTurns(int numberOfSamples)
{
  if (numberOfSamples < 1 || numberOfSamples > 98)
  {
    return 0;
  }
  return SpiralTurnsTable[numberOfSamples - 1];
}

//------------------------------------------------------------------------------
bool ReadyQuad(vtkOpenGLQuadHelper*& quad, vtkOpenGLRenderWindow* window, const char* source)
{
  if (!quad)
  {
    std::string fs = source;
    vtkShaderProgram::Substitute(fs, "//VTK::DeepGBuffer::Common",
      std::string(vtkDeepGIShaderConstantsGLSL) + vtkDeepGBufferCommon);
    vtkShaderProgram::Substitute(fs, "//VTK::DeepScreenSpace::Common", vtkDeepScreenSpaceCommon);
    quad = new vtkOpenGLQuadHelper(
      window, vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), fs.c_str(), "");
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(quad->Program);
  }
  return quad->Program && quad->Program->GetCompiled();
}

//------------------------------------------------------------------------------
std::string NormalWeightSource(double power)
{
  std::ostringstream glsl;
  glsl.imbue(std::locale::classic()); // GLSL's decimal point, whatever the user's locale
  glsl << "float deepNormalWeight(float facing)\n{\n";
  const int whole = static_cast<int>(power);
  if (power == whole)
  {
    // facing^whole by squaring: f holds facing^(2^i) for bit i of whole.
    glsl << "  float weight = 1.0;\n  float f = facing;\n";
    for (int rest = whole; rest > 0; rest >>= 1)
    {
      if (rest & 1)
      {
        glsl << "  weight *= f;\n";
      }
      if (rest > 1)
      {
        glsl << "  f *= f;\n";
      }
    }
    glsl << "  return weight;\n";
  }
  else
  {
    glsl << std::setprecision(9) << std::showpoint << "  return pow(max(facing, 1e-30), " << power
         << ");\n";
  }
  glsl << "}\n";
  return glsl.str();
}

//------------------------------------------------------------------------------
bool ReadyBilateralQuad(vtkOpenGLQuadHelper*& quad, double& compiledPower,
  vtkOpenGLRenderWindow* window, const char* source, double power)
{
  if (quad && compiledPower != power)
  {
    ReleaseQuad(quad, window);
  }
  // ReadyQuad reads the source only to compile: compose it only then.
  std::string fs;
  if (!quad)
  {
    fs = source;
    vtkShaderProgram::Substitute(
      fs, "//VTK::DeepScreenSpace::NormalWeight", NormalWeightSource(power));
    compiledPower = power;
  }
  return ReadyQuad(quad, window, fs.c_str());
}

//------------------------------------------------------------------------------
void ReleaseQuad(vtkOpenGLQuadHelper*& quad, vtkWindow* window)
{
  if (quad)
  {
    quad->ReleaseGraphicsResources(window);
    delete quad;
    quad = nullptr;
  }
}

//------------------------------------------------------------------------------
vtkTypeInt64 TextureBytes(const vtkSmartPointer<vtkTextureObject>& texture)
{
  if (!texture || !texture->GetHandle())
  {
    return 0;
  }
  // Every level up to MaxLevel when the texture is mipmapped.
  const bool mipmapped = texture->GetMinificationFilter() >= vtkTextureObject::NearestMipmapNearest;
  const int levels = mipmapped ? texture->GetMaxLevel() + 1 : 1;
  vtkTypeInt64 texels = 0;
  for (int level = 0; level < levels; ++level)
  {
    texels += static_cast<vtkTypeInt64>(std::max(1u, texture->GetWidth() >> level)) *
      std::max(1u, texture->GetHeight() >> level);
  }
  const unsigned int internalFormat =
    texture->GetInternalFormat(texture->GetVTKDataType(), texture->GetComponents(), false);
  const bool halfFloat = internalFormat == GL_R16F || internalFormat == GL_RG16F ||
    internalFormat == GL_RGB16F || internalFormat == GL_RGBA16F;
  const int componentBytes =
    halfFloat ? 2 : vtkAbstractArray::GetDataTypeSize(texture->GetVTKDataType());
  return texels * std::max(1, static_cast<int>(texture->GetDepth())) * texture->GetComponents() *
    componentBytes;
}

//------------------------------------------------------------------------------
bool AllocateTarget(vtkSmartPointer<vtkTextureObject>& texture, vtkOpenGLRenderWindow* window,
  int width, int height, int components, bool halfFloat)
{
  if (texture && texture->GetWidth() == static_cast<unsigned int>(width) &&
    texture->GetHeight() == static_cast<unsigned int>(height))
  {
    return true;
  }
  if (!texture)
  {
    static const int internalFormats[4] = { GL_R32F, GL_RG32F, GL_RGB32F, GL_RGBA32F };
    static const int halfFormats[4] = { GL_R16F, GL_RG16F, GL_RGB16F, GL_RGBA16F };
    static const int formats[4] = { GL_RED, GL_RG, GL_RGB, GL_RGBA };
    texture = vtkSmartPointer<vtkTextureObject>::New();
    texture->SetContext(window);
    texture->SetInternalFormat((halfFloat ? halfFormats : internalFormats)[components - 1]);
    texture->SetFormat(formats[components - 1]);
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

//------------------------------------------------------------------------------
void ReleaseTarget(vtkSmartPointer<vtkTextureObject>& texture, vtkWindow* window)
{
  if (texture)
  {
    texture->ReleaseGraphicsResources(window);
    texture = nullptr;
  }
}

//------------------------------------------------------------------------------
ScopedStageState::ScopedStageState(vtkOpenGLState* state)
  : State(state)
  , Viewport(state)
  , ScissorTest(state, GL_SCISSOR_TEST)
  , Scissor(state)
  , Blend(state, GL_BLEND)
  , DepthTest(state, GL_DEPTH_TEST)
{
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->PushFramebufferBindings();
}

ScopedStageState::~ScopedStageState()
{
  this->State->PopFramebufferBindings();
}

//------------------------------------------------------------------------------
void ReadyCoverage(vtkSmartPointer<vtkTextureObject>& coverage, vtkOpenGLRenderWindow* window,
  int width, int height, bool wanted)
{
  if (!wanted)
  {
    ReleaseTarget(coverage, window);
    return;
  }
  if (coverage)
  {
    if (coverage->GetWidth() != static_cast<unsigned int>(width) ||
      coverage->GetHeight() != static_cast<unsigned int>(height))
    {
      coverage->Resize(width, height);
    }
    return;
  }
  coverage = vtkSmartPointer<vtkTextureObject>::New();
  coverage->SetContext(window);
  coverage->SetMinificationFilter(vtkTextureObject::Nearest);
  coverage->SetMagnificationFilter(vtkTextureObject::Nearest);
  if (!coverage->AllocateDepth(width, height, vtkTextureObject::Float32))
  {
    vtkGenericWarningMacro("Could not allocate the surface coverage; every texel is shaded.");
    ReleaseTarget(coverage, window);
  }
}

//------------------------------------------------------------------------------
ScopedCoverageAttachment::ScopedCoverageAttachment(
  vtkOpenGLState* state, unsigned int framebuffer, vtkTextureObject* coverage)
  : State(state)
  , Framebuffer(framebuffer)
  , Attached(coverage && coverage->GetHandle() && framebuffer)
  , DepthTest(state, GL_DEPTH_TEST)
  , DepthFunc(state)
  , DepthMask(state)
{
  if (this->Attached)
  {
    glFramebufferTexture2D(
      GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, coverage->GetHandle(), 0);
    state->vtkglEnable(GL_DEPTH_TEST);
  }
}

ScopedCoverageAttachment::~ScopedCoverageAttachment()
{
  if (this->Attached)
  {
    this->State->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, this->Framebuffer);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, 0, 0);
  }
}

//------------------------------------------------------------------------------
ScopedCoverageWrite::ScopedCoverageWrite(
  vtkOpenGLState* state, unsigned int framebuffer, vtkTextureObject* coverage)
  : ScopedCoverageAttachment(state, framebuffer, coverage)
{
  if (this->Attached)
  {
    state->vtkglDepthFunc(GL_ALWAYS);
    state->vtkglDepthMask(GL_TRUE);
  }
}

//------------------------------------------------------------------------------
ScopedBackgroundSkip::ScopedBackgroundSkip(
  vtkOpenGLState* state, unsigned int framebuffer, vtkTextureObject* coverage)
  : ScopedCoverageAttachment(state, framebuffer, coverage)
  , ClearColor(state)
{
  if (this->Attached)
  {
    // Every quad at depth 1: GL_GREATER passes where the coverage is 0.
    // vtkOpenGLState does not track the depth range: saved and restored here.
    glGetDoublev(GL_DEPTH_RANGE, this->DepthRange);
    glDepthRange(1.0, 1.0);
    state->vtkglDepthFunc(GL_GREATER);
    state->vtkglDepthMask(GL_FALSE);
  }
}

ScopedBackgroundSkip::~ScopedBackgroundSkip()
{
  if (this->Attached)
  {
    glDepthRange(this->DepthRange[0], this->DepthRange[1]);
  }
}

void ScopedBackgroundSkip::Draw(vtkOpenGLQuadHelper* quad, const float background[4])
{
  if (this->Attached)
  {
    this->State->vtkglClearColor(background[0], background[1], background[2], background[3]);
    this->State->vtkglClear(GL_COLOR_BUFFER_BIT);
  }
  quad->Render();
}

//------------------------------------------------------------------------------
ScopedCompositeState::ScopedCompositeState(
  vtkOpenGLState* state, unsigned int sourceFactor, unsigned int destinationFactor)
  : Blend(state, GL_BLEND)
  , DepthTest(state, GL_DEPTH_TEST)
  , DepthMask(state)
  , BlendFunc(state)
{
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(sourceFactor, destinationFactor, GL_ZERO, GL_ONE);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_FALSE);
}

//------------------------------------------------------------------------------
void AddCameraFieldData(vtkFieldData* fd, const double view[16], const double projection[16])
{
  for (auto matrix : { std::make_pair(vtkDeepGICaptureNames::ViewMatrix, view),
         std::make_pair(vtkDeepGICaptureNames::ProjectionMatrix, projection) })
  {
    vtkNew<vtkDoubleArray> values;
    values->SetName(matrix.first);
    values->SetNumberOfComponents(16);
    values->InsertNextTuple(matrix.second);
    fd->AddArray(values);
  }
}

//------------------------------------------------------------------------------
const char* PresetName(int preset)
{
  static const char* const names[] = { "HIGH_PERFORMANCE", "BALANCED", "HIGH_QUALITY" };
  return preset >= 0 && preset < 3 ? names[preset] : "UNKNOWN";
}

//------------------------------------------------------------------------------
double SceneDiagonal(vtkRenderer* renderer)
{
  double bounds[6];
  vtkInformation* information = renderer->GetInformation();
  if (information && information->Has(vtkDeepGIKeys::SCENE_BOUNDS()))
  {
    information->Get(vtkDeepGIKeys::SCENE_BOUNDS(), bounds);
  }
  else
  {
    renderer->ComputeVisiblePropBounds(bounds);
  }
  if (!vtkMath::AreBoundsInitialized(bounds))
  {
    return 0.0;
  }
  const double extent[3] = { bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] };
  const double diagonal = vtkMath::Norm(extent);
  return std::isfinite(diagonal) ? diagonal : 0.0;
}

//------------------------------------------------------------------------------
void ProjectionUniforms(const double projection[16], float projXY[4], float projT[4])
{
  projXY[0] = static_cast<float>(projection[0]);
  projXY[1] = static_cast<float>(projection[5]);
  projXY[2] = static_cast<float>(projection[2]);
  projXY[3] = static_cast<float>(projection[6]);
  projT[0] = static_cast<float>(projection[3]);
  projT[1] = static_cast<float>(projection[7]);
  projT[2] = static_cast<float>(projection[14]);
  projT[3] = static_cast<float>(projection[15]);
}

//------------------------------------------------------------------------------
void ReprojectionUniforms(const double view[16], const double projection[16], bool hasHistory,
  const double previousView[16], const double previousProjection[16], float toPrevious[16],
  float previousProjectionGL[16])
{
  vtkNew<vtkMatrix4x4> toPreviousMatrix, inverseView;
  if (hasHistory)
  {
    inverseView->DeepCopy(view);
    inverseView->Invert();
    vtkMatrix4x4::Multiply4x4(
      previousView, &inverseView->Element[0][0], &toPreviousMatrix->Element[0][0]);
  }
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      toPrevious[c * 4 + r] = static_cast<float>(toPreviousMatrix->GetElement(r, c));
      previousProjectionGL[c * 4 + r] =
        static_cast<float>(hasHistory ? previousProjection[r * 4 + c] : projection[r * 4 + c]);
    }
  }
}

//------------------------------------------------------------------------------
RenderCounter::~RenderCounter()
{
  if (this->Observer && this->Renderer)
  {
    this->Renderer->RemoveObserver(this->Tag);
  }
}

void RenderCounter::Count(vtkObject*, unsigned long, void* clientData, void*)
{
  ++static_cast<RenderCounter*>(clientData)->Renders;
}

void RenderCounter::Observe(vtkRenderer* renderer)
{
  this->Renderer = renderer;
  this->Observer = vtkSmartPointer<vtkCallbackCommand>::New();
  this->Observer->SetClientData(this);
  this->Observer->SetCallback(&RenderCounter::Count);
  this->Tag = renderer->AddObserver(vtkCommand::StartEvent, this->Observer);
}

bool RenderCounter::Consecutive()
{
  const bool consecutive = this->Renders == this->LastRenders + 1;
  this->LastRenders = this->Renders;
  return consecutive;
}
//------------------------------------------------------------------------------
void CropGuardBand(vtkImageData* image, int guardBand)
{
  int dims[3];
  image->GetDimensions(dims);
  if (guardBand <= 0 || dims[0] <= 2 * guardBand || dims[1] <= 2 * guardBand)
  {
    return;
  }
  const int w = dims[0] - 2 * guardBand, h = dims[1] - 2 * guardBand;
  vtkPointData* pd = image->GetPointData();
  std::vector<vtkSmartPointer<vtkDataArray>> cropped;
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* full = pd->GetArray(a);
    if (!full)
    {
      continue;
    }
    vtkSmartPointer<vtkDataArray> frame = vtk::TakeSmartPointer(full->NewInstance());
    frame->SetName(full->GetName());
    frame->SetNumberOfComponents(full->GetNumberOfComponents());
    frame->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
    for (int y = 0; y < h; ++y)
    {
      for (int x = 0; x < w; ++x)
      {
        frame->SetTuple(static_cast<vtkIdType>(y) * w + x,
          static_cast<vtkIdType>(y + guardBand) * dims[0] + x + guardBand, full);
      }
    }
    cropped.push_back(frame);
  }
  pd->Initialize();
  image->SetDimensions(w, h, 1);
  for (auto& array : cropped)
  {
    pd->AddArray(array);
  }
}

//------------------------------------------------------------------------------
namespace
{
// The texels of layers of `size` at least `margin` from every edge.
void RegionInside(const int size[2], int margin, int region[4])
{
  region[0] = margin;
  region[1] = margin;
  region[2] = std::max(margin, size[0] - margin);
  region[3] = std::max(margin, size[1] - margin);
}
}

//------------------------------------------------------------------------------
void ShadedRegion(const int size[2], int guardBand, double shadedFraction, int region[4])
{
  const double fraction = std::min(std::max(shadedFraction, 0.0), 1.0);
  RegionInside(size, guardBand - static_cast<int>(std::lround(fraction * guardBand)), region);
}

//------------------------------------------------------------------------------
void LimitShadedRegion(const int size[2], int guardBand, int reach, int region[4])
{
  RegionInside(size, std::max(region[0], guardBand - std::max(reach, 0)), region);
}

//------------------------------------------------------------------------------
bool RegionContains(const int outer[4], const int inner[4])
{
  return outer[0] <= inner[0] && outer[1] <= inner[1] && inner[2] <= outer[2] &&
    inner[3] <= outer[3];
}

//------------------------------------------------------------------------------
int RegionRing(const int outer[4], const int inner[4], int rings[4][4])
{
  const int candidates[4][4] = { { outer[0], outer[1], outer[2], inner[1] },
    { outer[0], inner[3], outer[2], outer[3] }, { outer[0], inner[1], inner[0], inner[3] },
    { inner[2], inner[1], outer[2], inner[3] } };
  int count = 0;
  for (const auto& candidate : candidates)
  {
    if (candidate[0] < candidate[2] && candidate[1] < candidate[3])
    {
      std::copy(candidate, candidate + 4, rings[count++]);
    }
  }
  return count;
}

//------------------------------------------------------------------------------
void FrameProjection(
  const double layerProjection[16], const int size[2], int guardBand, double frame[16])
{
  std::copy(layerProjection, layerProjection + 16, frame);
  for (int axis = 0; axis < 2; ++axis)
  {
    const int frameSize = size[axis] - 2 * guardBand;
    const double scale = frameSize > 0 ? static_cast<double>(size[axis]) / frameSize : 1.0;
    for (int c = 0; c < 4; ++c)
    {
      frame[4 * axis + c] *= scale;
    }
  }
}

//------------------------------------------------------------------------------
void ReducedProjection(const double projection[16], const int size[2], const int reducedSize[2],
  int divisor, double reduced[16])
{
  std::copy(projection, projection + 16, reduced);
  for (int axis = 0; axis < 2; ++axis)
  {
    const double n = size[axis];
    const double k = divisor * static_cast<double>(reducedSize[axis]) / n;
    const double c = k + (1.0 - divisor) / n - 1.0;
    for (int col = 0; col < 4; ++col)
    {
      reduced[4 * axis + col] = (projection[4 * axis + col] - c * projection[12 + col]) / k;
    }
  }
}

//------------------------------------------------------------------------------
void SetShadedRegionUniforms(vtkShaderProgram* program, const int region[4])
{
  if (program->IsUniformUsed("deepShadedMin"))
  {
    program->SetUniform2i("deepShadedMin", region);
  }
  if (program->IsUniformUsed("deepShadedMax"))
  {
    program->SetUniform2i("deepShadedMax", region + 2);
  }
}
}
