// Oct16 normal encoding (paper Table 1): the angular error of an
// encode/decode round trip is bounded over the whole sphere, for the C++
// codec and for the GLSL encoder that the G-buffer shaders use.
//
// The bound: 255 symmetric levels per octahedron coordinate (step 1/127)
// give a worst case of 0.954 degrees (measured over 2M directions); the test
// requires max < 1.0 degree and mean < 0.35 degree over 1M directions for
// the C++ codec and a 512 x 512 latitude-longitude grid for the GLSL encoder.
// The geometry key's packing of the two levels into one float is exact.

#include "DeepGBufferTestUtilities.h"
#include "vtkDeepGBufferPass.h"

#include "vtkDeepGBufferCommon.h" // the GLSL under test

#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

namespace
{
constexpr double MaximumErrorDegrees = 1.0;
constexpr double MeanErrorDegrees = 0.35;

// Direction of texel (x, y) of a size x size latitude-longitude grid, the
// same arithmetic as the GLSL below (which runs in single precision).
void GridDirection(int x, int y, int size, double d[3])
{
  const double theta = vtkMath::Pi() * (y + 0.5) / size;
  const double phi = 2.0 * vtkMath::Pi() * (x + 0.5) / size;
  d[0] = std::sin(theta) * std::cos(phi);
  d[1] = std::sin(theta) * std::sin(phi);
  d[2] = std::cos(theta);
}

// Direction i of n on a Fibonacci sphere: near-uniform coverage, both poles.
void FibonacciDirection(int i, int n, double d[3])
{
  const double z = 1.0 - 2.0 * (i + 0.5) / n;
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double phi = (i + 0.5) * vtkMath::Pi() * (3.0 - std::sqrt(5.0));
  d[0] = r * std::cos(phi);
  d[1] = r * std::sin(phi);
  d[2] = z;
}

double AngleDegrees(const double a[3], const double b[3])
{
  return vtkMath::DegreesFromRadians(vtkMath::AngleBetweenVectors(a, b));
}

void CheckStatistics(const char* what, double maximum, double sum, int count)
{
  const double mean = sum / count;
  DeepGITest::Check(maximum < MaximumErrorDegrees,
    DeepGITest::Format(
      "%s: %d directions, max error %.4f deg < %.2f", what, count, maximum, MaximumErrorDegrees));
  DeepGITest::Check(mean < MeanErrorDegrees,
    DeepGITest::Format("%s: mean error %.4f deg < %.2f", what, mean, MeanErrorDegrees));
}

void CheckCppCodecAccuracy()
{
  const int n = 1000000;
  double maximum = 0.0, sum = 0.0;
  for (int i = 0; i < n; ++i)
  {
    double d[3], r[3];
    unsigned char e[2];
    FibonacciDirection(i, n, d);
    vtkDeepGBufferPass::EncodeOct16(d, e);
    vtkDeepGBufferPass::DecodeOct16(e, r);
    const double err = AngleDegrees(d, r);
    maximum = std::max(maximum, err);
    sum += err;
  }
  // The axes are exact by construction.
  const double axes[6][3] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 },
    { 0, 0, -1 } };
  for (const auto& axis : axes)
  {
    unsigned char e[2];
    double r[3];
    vtkDeepGBufferPass::EncodeOct16(axis, e);
    vtkDeepGBufferPass::DecodeOct16(e, r);
    if (!DeepGITest::Check(AngleDegrees(axis, r) <= 1e-9,
          DeepGITest::Format("axis (%g %g %g) is exact", axis[0], axis[1], axis[2])))
    {
      return;
    }
  }
  CheckStatistics("C++ codec", maximum, sum, n);
}

// Runs `body` (GLSL statements writing gl_FragData[0] from `texel`, the
// integer texel, with vtkDeepGBufferCommon included) over a size x size
// target of the given format, then `read` while the target is bound.
bool DrawFullScreen(const std::string& body, int size, int internalFormat, int format, int dataType,
  int components, const std::function<void()>& read)
{
  vtkNew<vtkRenderer> renderer;
  vtkSmartPointer<vtkRenderWindow> window = DeepGBufferTest::MakeWindow(16, 16);
  window->AddRenderer(renderer);
  window->Render();
  vtkOpenGLRenderWindow* glWindow = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!DeepGITest::Check(glWindow != nullptr, "an OpenGL render window"))
  {
    return false;
  }
  glWindow->MakeCurrent();

  vtkNew<vtkTextureObject> target;
  target->SetContext(glWindow);
  target->SetInternalFormat(internalFormat);
  target->SetFormat(format);
  target->SetDataType(dataType);
  target->Allocate2D(size, size, components, dataType == GL_FLOAT ? VTK_FLOAT : VTK_UNSIGNED_CHAR);

  vtkNew<vtkOpenGLFramebufferObject> fbo;
  fbo->SetContext(glWindow);
  vtkOpenGLState* ostate = glWindow->GetState();
  ostate->PushFramebufferBindings();
  fbo->Bind();
  fbo->AddColorAttachment(0, target);
  fbo->ActivateDrawBuffers(1);
  vtkOpenGLState::ScopedglViewport savedViewport(ostate);
  vtkOpenGLState::ScopedglScissor savedScissor(ostate);
  ostate->vtkglViewport(0, 0, size, size);
  ostate->vtkglScissor(0, 0, size, size);

  std::string fs = "//VTK::System::Dec\n"
                   "in vec2 texCoord;\n"
                   "uniform int width;\n";
  fs += vtkDeepGBufferCommon;
  fs += "//VTK::Output::Dec\n"
        "void main()\n"
        "{\n"
        "  ivec2 texel = ivec2(floor(texCoord * float(width)));\n" +
    body + "}\n";
  bool ok = false;
  {
    vtkOpenGLQuadHelper quad(
      glWindow, vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), fs.c_str(), "");
    ok = DeepGITest::Check(quad.Program && quad.Program->GetCompiled(), "the shader compiles");
    if (ok)
    {
      glWindow->GetShaderCache()->ReadyShaderProgram(quad.Program);
      quad.Program->SetUniformi("width", size);
      ostate->vtkglDisable(GL_BLEND);
      ostate->vtkglDisable(GL_DEPTH_TEST);
      quad.Render();
    }
    quad.ReleaseGraphicsResources(glWindow);
  }
  if (ok)
  {
    ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);
    target->Bind();
    read();
    ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, 4);
  }
  fbo->UnBind();
  ostate->PopFramebufferBindings();
  target->ReleaseGraphicsResources(glWindow);
  fbo->ReleaseGraphicsResources(glWindow);
  return ok;
}

// Encodes a latitude-longitude grid of directions with the shaders' GLSL into an RG8 target,
// reads the bytes back and decodes them with the C++ codec.
void CheckGlslEncoderAccuracy()
{
  const int size = 512;
  const int n = size * size;
  std::vector<unsigned char> bytes(2 * n);
  const std::string body =
    "  vec2 angles = vec2(texel) + 0.5;\n"
    "  float theta = 3.14159265358979 * angles.y / float(width);\n"
    "  float phi = 6.28318530717959 * angles.x / float(width);\n"
    "  vec3 d = vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));\n"
    "  gl_FragData[0] = vec4(deepEncodeOct16(d), 0.0, 1.0);\n";
  if (!DrawFullScreen(body, size, GL_RG8, GL_RG, GL_UNSIGNED_BYTE, 2,
        [&] { glGetTexImage(GL_TEXTURE_2D, 0, GL_RG, GL_UNSIGNED_BYTE, bytes.data()); }))
  {
    return;
  }

  // The GPU evaluates the direction in single precision; compare the decoded
  // normal against the double-precision direction, and the bytes against
  // the C++ encoder (ties may round differently: at most one level apart).
  double maximum = 0.0, sum = 0.0;
  int byteMismatches = 0;
  for (int i = 0; i < n; ++i)
  {
    double d[3], r[3];
    GridDirection(i % size, i / size, size, d);
    vtkDeepGBufferPass::DecodeOct16(&bytes[2 * i], r);
    const double err = AngleDegrees(d, r);
    maximum = std::max(maximum, err);
    sum += err;
    unsigned char e[2];
    vtkDeepGBufferPass::EncodeOct16(d, e);
    for (int c = 0; c < 2; ++c)
    {
      if (std::abs(int(e[c]) - int(bytes[2 * i + c])) > 1)
      {
        ++byteMismatches;
      }
    }
  }
  if (!DeepGITest::Check(byteMismatches == 0,
        DeepGITest::Format(
          "GLSL and C++ encoders within one level (%d values differ more)", byteMismatches)))
  {
    return;
  }
  CheckStatistics("GLSL encoder", maximum, sum, n);
}

// The geometry key (vtkDeepGeometryKeyFS) stores an Oct16 normal's two
// 8-bit levels as one float, k.x + 256 k.y: for every pair of bytes, the
// packed value is that integer and unpacking it gives exactly the normal
// deepDecodeOct16 gives (so the effects reading the key compute bit for bit
// what they computed from the normal texture).
void CheckGlslKeyPacking()
{
  const int size = 256;
  std::vector<float> values(4 * size * size);
  const std::string body =
    "  vec2 encoded = vec2(texel) / 255.0;\n"
    "  float levels = deepPackOct16(encoded);\n"
    "  vec3 difference = deepUnpackOct16(levels) - deepDecodeOct16(encoded);\n"
    "  gl_FragData[0] = vec4(levels, abs(difference));\n";
  if (!DrawFullScreen(body, size, GL_RGBA32F, GL_RGBA, GL_FLOAT, 4,
        [&] { glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, values.data()); }))
  {
    return;
  }
  int wrongLevels = 0, inexact = 0;
  for (int i = 0; i < size * size; ++i)
  {
    const float expected = static_cast<float>(i % size + 256 * (i / size));
    wrongLevels += values[4 * i] != expected;
    inexact += values[4 * i + 1] != 0.0f || values[4 * i + 2] != 0.0f || values[4 * i + 3] != 0.0f;
  }
  DeepGITest::Check(wrongLevels == 0,
    DeepGITest::Format(
      "the key's packed levels are k.x + 256 k.y (%d of 65536 differ)", wrongLevels));
  DeepGITest::Check(inexact == 0,
    DeepGITest::Format(
      "unpacking the key gives deepDecodeOct16's normal exactly (%d of 65536 differ)", inexact));
}
}

int TestDeepGBufferOct16(int, char*[])
{
  CheckCppCodecAccuracy();
  CheckGlslEncoderAccuracy();
  CheckGlslKeyPacking();
  return DeepGITest::ExitStatus();
}
