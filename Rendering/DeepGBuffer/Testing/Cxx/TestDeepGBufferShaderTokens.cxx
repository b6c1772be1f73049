// The VTK shader text vtkDeepGBufferPass substitutes exists in this VTK:
// every hook of vtkDeepGBufferShaderTokens.h appears in the shader templates
// compiled into VTK's OpenGL2 library (vtkPolyDataVS, vtkPolyDataFS), and
// the geometry-shader tokens in vtkPointGaussianMapper's template, which
// projects view-space positions itself. A VTK that renames one of them
// fails here instead of drawing layers without their G-buffer values. The
// probes of the final fragment shader are exercised by the rendering tests
// named in the header.

#include "DeepGITestChecks.h"

#include "vtkDeepGBufferShaderTokens.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <initializer_list>

// VTK's templates (vtkRenderingOpenGL2 exports them; their headers are
// generated at VTK's build and not installed).
extern const char* vtkPolyDataVS;
extern const char* vtkPolyDataFS;
extern const char* vtkPointGaussianGS;

namespace
{
void Expect(const char* shader, const char* shaderName, const char* token)
{
  DeepGITest::Check(
    std::strstr(shader, token) != nullptr, DeepGITest::Format("%s has \"%s\"", shaderName, token));
}
}

int TestDeepGBufferShaderTokens(int, char*[])
{
  namespace Tokens = vtkDeepGBufferShaderTokens;
  for (const char* hook : Tokens::VertexHooks)
  {
    Expect(vtkPolyDataVS, "vtkPolyDataVS", hook);
  }
  for (const char* hook : Tokens::FragmentHooks)
  {
    Expect(vtkPolyDataFS, "vtkPolyDataFS", hook);
  }
  for (const char* token :
    { Tokens::GeometryProjects, Tokens::GeometryMain, Tokens::GeometryEmitVertex })
  {
    Expect(vtkPointGaussianGS, "vtkPointGaussianGS", token);
  }
  // The check itself can fail: a token VTK does not have is reported missing.
  DeepGITest::Check(std::strstr(vtkPolyDataFS, "//VTK::NoSuchHook::Impl") == nullptr,
    "a token that VTK lacks is not found");
  return DeepGITest::ExitStatus();
}
