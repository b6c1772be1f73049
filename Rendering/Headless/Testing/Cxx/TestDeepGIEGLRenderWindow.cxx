// Renders an unlit sphere through vtkDeepGIEGLRenderWindow with no X display
// (ctest runs it with DISPLAY empty) and checks the image numerically, the GL
// error state and that VTK printed no error or warning (GLEW's GLX complaint
// included). Then releases the graphics resources and renders twice more.
#include "vtkDeepGIEGLRenderWindow.h"

#include "DeepGIHeadlessTestHelpers.h"

#include <cstring>
#include <sstream>

int TestDeepGIEGLRenderWindow(int, char*[])
{
  using namespace deepgi_headless_test;
  if (!RequireNoDisplay("TestDeepGIEGLRenderWindow"))
  {
    return EXIT_FAILURE;
  }
  ScopedMessageCounter messages;
  int failures = 0;

  vtkNew<vtkDeepGIEGLRenderWindow> rw;
  if (rw->HasContext() || std::strlen(rw->GetPlatformDescription()) != 0)
  {
    std::fprintf(stderr, "a new window must not have a context yet\n");
    ++failures;
  }
  SetUpWindow(rw);
  if (rw->GetShowWindow() || !rw->GetUseOffScreenBuffers())
  {
    std::fprintf(stderr, "the EGL window must be offscreen\n");
    ++failures;
  }

  failures += RenderAndCheck(rw, "first render");
  if (!rw->HasContext() || !rw->IsCurrent())
  {
    std::fprintf(stderr, "after Render the EGL context must exist and be current\n");
    return EXIT_FAILURE;
  }
  std::printf("platform: %s, OpenGL %d.%d, renderer: %s\n", rw->GetPlatformDescription(),
    rw->GetContextMajorVersion(), rw->GetContextMinorVersion(),
    reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  const int major = rw->GetContextMajorVersion();
  const int minor = rw->GetContextMinorVersion();
  if (major < 3 || (major == 3 && minor < 2))
  {
    std::fprintf(stderr, "expected an OpenGL 3.2+ context, got %d.%d\n", major, minor);
    ++failures;
  }
  GLint profile = 0;
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  if (!(profile & GL_CONTEXT_CORE_PROFILE_BIT))
  {
    std::fprintf(stderr, "expected a core profile context (mask 0x%x)\n", profile);
    ++failures;
  }
  if (!rw->SupportsOpenGL() || !rw->IsDirect())
  {
    std::fprintf(stderr, "SupportsOpenGL/IsDirect must be true with a context\n");
    ++failures;
  }

  // Release everything VTK allocated on the context, then render again twice:
  // VTK must rebuild its framebuffers, shaders and buffers on the same context.
  rw->ReleaseGraphicsResources(rw);
  failures += CountGLErrors(rw, "after ReleaseGraphicsResources");
  failures += RenderAndCheck(rw, "render after release");
  failures += RenderAndCheck(rw, "second render after release");

  // A resize must resize VTK's framebuffers (not the pbuffer).
  rw->SetSize(2 * Size, Size);
  rw->Render();
  failures += CountGLErrors(rw, "after resize");
  int* size = rw->GetSize();
  if (size[0] != 2 * Size || size[1] != Size)
  {
    std::fprintf(stderr, "size after resize is %dx%d\n", size[0], size[1]);
    ++failures;
  }
  rw->SetSize(Size, Size);
  failures += RenderAndCheck(rw, "render after resize back");

  // Finalize destroys the context; the next render creates a new one.
  rw->Finalize();
  if (rw->HasContext())
  {
    std::fprintf(stderr, "Finalize must destroy the EGL context\n");
    ++failures;
  }
  failures += RenderAndCheck(rw, "render on a new context after Finalize");

  // PrintSelf reports the EGL state.
  std::ostringstream printed;
  rw->Print(printed);
  if (printed.str().find("PlatformDescription: ") == std::string::npos ||
    printed.str().find("ContextVersion: ") == std::string::npos)
  {
    std::fprintf(stderr, "PrintSelf lacks the EGL state\n");
    ++failures;
  }

  if (messages.Errors() || messages.Warnings())
  {
    std::fprintf(stderr, "VTK reported %d error(s) and %d warning(s)\n", messages.Errors(),
      messages.Warnings());
    ++failures;
  }
  std::printf("%d failure(s)\n", failures);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
