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
  using namespace DeepGITest;
  if (!RequireNoDisplay("TestDeepGIEGLRenderWindow"))
  {
    return EXIT_FAILURE;
  }
  ScopedMessageCounter messages;

  vtkNew<vtkDeepGIEGLRenderWindow> rw;
  Check(!rw->HasContext() && std::strlen(rw->GetPlatformDescription()) == 0,
    "a new window has no context yet");
  SetUpWindow(rw);
  Check(!rw->GetShowWindow() && rw->GetUseOffScreenBuffers(), "the EGL window is offscreen");

  RenderAndCheck(rw, "first render");
  if (!Check(
        rw->HasContext() && rw->IsCurrent(), "after Render the EGL context exists and is current"))
  {
    return EXIT_FAILURE;
  }
  std::printf("platform: %s, OpenGL %d.%d, renderer: %s\n", rw->GetPlatformDescription(),
    rw->GetContextMajorVersion(), rw->GetContextMinorVersion(),
    reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  const int major = rw->GetContextMajorVersion();
  const int minor = rw->GetContextMinorVersion();
  Check(!(major < 3 || (major == 3 && minor < 2)),
    Format("an OpenGL 3.2+ context (got %d.%d)", major, minor));
  GLint profile = 0;
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  Check((profile & GL_CONTEXT_CORE_PROFILE_BIT) != 0,
    Format("a core profile context (mask 0x%x)", static_cast<unsigned>(profile)));
  Check(rw->SupportsOpenGL() && rw->IsDirect(), "SupportsOpenGL and IsDirect with a context");

  // Release everything VTK allocated on the context, then render again twice:
  // VTK must rebuild its framebuffers, shaders and buffers on the same context.
  rw->ReleaseGraphicsResources(rw);
  CheckNoGLErrors(rw, "after ReleaseGraphicsResources");
  RenderAndCheck(rw, "render after release");
  RenderAndCheck(rw, "second render after release");

  // A resize must resize VTK's framebuffers (not the pbuffer).
  rw->SetSize(2 * Size, Size);
  rw->Render();
  CheckNoGLErrors(rw, "after resize");
  int* size = rw->GetSize();
  Check(size[0] == 2 * Size && size[1] == Size,
    Format("size after resize %dx%d (%dx%d)", size[0], size[1], 2 * Size, Size));
  rw->SetSize(Size, Size);
  RenderAndCheck(rw, "render after resize back");

  // Finalize destroys the context; the next render creates a new one.
  rw->Finalize();
  Check(!rw->HasContext(), "Finalize destroys the EGL context");
  RenderAndCheck(rw, "render on a new context after Finalize");

  // PrintSelf reports the EGL state.
  std::ostringstream printed;
  rw->Print(printed);
  Check(printed.str().find("PlatformDescription: ") != std::string::npos &&
      printed.str().find("ContextVersion: ") != std::string::npos,
    "PrintSelf reports the EGL state");

  messages.CheckNone();
  return ExitStatus();
}
