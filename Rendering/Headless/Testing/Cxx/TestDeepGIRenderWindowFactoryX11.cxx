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
  using F = vtkDeepGIRenderWindowFactory;
  if (!F::IsX11Available())
  {
    std::printf("no X server (DISPLAY unset or not answering): skipped\n");
    return 125; // VTK_SKIP_RETURN_CODE
  }
  ScopedMessageCounter messages;
  int failures = 0;

  if (F::ResolveBackend(F::BACKEND_AUTO) != F::BACKEND_X11)
  {
    std::fprintf(stderr, "auto must resolve to x11 when X is available\n");
    ++failures;
  }
  for (int backend : { F::BACKEND_X11, F::BACKEND_AUTO, F::BACKEND_EGL })
  {
    vtkSmartPointer<vtkRenderWindow> rw;
    rw.TakeReference(F::NewRenderWindow(backend));
    std::string label = std::string("factory window, backend ") + F::GetBackendAsString(backend);
    if (!rw)
    {
      std::fprintf(stderr, "%s: no window\n", label.c_str());
      ++failures;
      continue;
    }
    const bool isEGL = rw->IsA("vtkDeepGIEGLRenderWindow") != 0;
    if (isEGL != (backend == F::BACKEND_EGL))
    {
      std::fprintf(stderr, "%s: unexpected class %s\n", label.c_str(), rw->GetClassName());
      ++failures;
    }
    if (rw->GetShowWindow())
    {
      std::fprintf(stderr, "%s: factory windows must be offscreen\n", label.c_str());
      ++failures;
    }
    SetUpWindow(rw);
    failures += RenderAndCheck(rw, label.c_str());
  }
  // Both kinds alive in one thread.
  {
    vtkSmartPointer<vtkRenderWindow> x11, egl;
    x11.TakeReference(F::NewRenderWindow(F::BACKEND_X11));
    egl.TakeReference(F::NewRenderWindow(F::BACKEND_EGL));
    if (!x11 || !egl)
    {
      std::fprintf(stderr, "mixed: could not create both windows\n");
      return EXIT_FAILURE;
    }
    SetUpWindow(x11);
    SetUpWindow(egl);
    failures += RenderAndCheck(x11, "mixed: x11");
    failures += RenderAndCheck(egl, "mixed: egl while the GLX context was current");
    egl->ReleaseCurrent();
    failures += RenderAndCheck(x11, "mixed: x11 after egl released its context");
    failures += RenderAndCheck(egl, "mixed: egl again");
    egl->ReleaseCurrent();
    x11 = nullptr;
    failures += RenderAndCheck(egl, "mixed: egl after the x11 window is gone");
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
