// vtkDeepGIRenderWindowFactory with an X server (scripts/test.sh runs ctest
// under Xvfb): auto resolves to x11, the x11 window renders the test scene,
// and an EGL window works in the same process, also while an X11 window is
// alive (following the contract in vtkDeepGIEGLRenderWindow.h: the EGL window
// takes over from a current GLX context by itself, and is released with
// ReleaseCurrent() before the X11 window renders or is destroyed). Skipped
// (125) when no X server answers.
#include "vtkDeepGIRenderWindowFactory.h"

#include "DeepGIHeadlessTestHelpers.h"

int TestDeepGIRenderWindowFactoryX11(int, char*[])
{
  using namespace deepgi_headless_test;
  using namespace DeepGITest;
  using F = vtkDeepGIRenderWindowFactory;
  if (!F::IsX11Available())
  {
    std::printf("no X server (DISPLAY unset or not answering): skipped\n");
    return 125; // VTK_SKIP_RETURN_CODE
  }
  ScopedMessageCounter messages;

  Check(F::ResolveBackend(F::BACKEND_AUTO) == F::BACKEND_X11,
    "auto resolves to x11 when X is available");
  for (int backend : { F::BACKEND_X11, F::BACKEND_AUTO, F::BACKEND_EGL })
  {
    vtkSmartPointer<vtkRenderWindow> rw;
    rw.TakeReference(F::NewRenderWindow(backend));
    std::string label = std::string("factory window, backend ") + F::GetBackendAsString(backend);
    if (!Check(rw != nullptr, label + ": a window"))
    {
      continue;
    }
    const bool isEGL = rw->IsA("vtkDeepGIEGLRenderWindow") != 0;
    Check(isEGL == (backend == F::BACKEND_EGL),
      Format("%s: the backend's class (%s)", label.c_str(), rw->GetClassName()));
    Check(!rw->GetShowWindow(), label + ": factory windows are offscreen");
    SetUpWindow(rw);
    RenderAndCheck(rw, label.c_str());
  }
  // Both kinds alive in one thread.
  {
    vtkSmartPointer<vtkRenderWindow> x11, egl;
    x11.TakeReference(F::NewRenderWindow(F::BACKEND_X11));
    egl.TakeReference(F::NewRenderWindow(F::BACKEND_EGL));
    if (!Check(x11 && egl, "mixed: both windows created"))
    {
      return EXIT_FAILURE;
    }
    SetUpWindow(x11);
    SetUpWindow(egl);
    RenderAndCheck(x11, "mixed: x11");
    RenderAndCheck(egl, "mixed: egl while the GLX context was current");
    egl->ReleaseCurrent();
    RenderAndCheck(x11, "mixed: x11 after egl released its context");
    RenderAndCheck(egl, "mixed: egl again");
    egl->ReleaseCurrent();
    x11 = nullptr;
    RenderAndCheck(egl, "mixed: egl after the x11 window is gone");
  }

  messages.CheckNone();
  return ExitStatus();
}
