// The VTK shader text vtkDeepGBufferPass substitutes exists in this VTK:
// every hook of vtkDeepGBufferShaderTokens.h appears in the shader templates
// compiled into VTK's OpenGL2 library (vtkPolyDataVS, vtkPolyDataFS), and
// the geometry-shader tokens in vtkPointGaussianMapper's template, which
// projects view-space positions itself. A VTK that renames one of them
// fails here instead of drawing layers without their G-buffer values. The
// probes of the final fragment shader are exercised by the rendering tests
// named in the header.

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
int Failures = 0;

void Expect(const char* shader, const char* shaderName, const char* token)
{
  const bool found = std::strstr(shader, token) != nullptr;
  std::printf("%s: %s has \"%s\"\n", found ? "ok" : "FAILED", shaderName, token);
  Failures += found ? 0 : 1;
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
  const bool detects = std::strstr(vtkPolyDataFS, "//VTK::NoSuchHook::Impl") == nullptr;
  std::printf("%s: a token that VTK lacks is not found\n", detects ? "ok" : "FAILED");
  Failures += detects ? 0 : 1;
  std::printf("%d failure(s)\n", Failures);
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
