// EGL window lifetimes without an X display: two windows created, rendered
// and destroyed in sequence; then two windows alive at once (they share the
// EGL display), rendered in turn, the first destroyed while the second's
// context is current, and the second still rendering correctly afterwards.
#include "vtkDeepGIEGLRenderWindow.h"

#include "DeepGIHeadlessTestHelpers.h"

#include <EGL/egl.h>

int TestDeepGIEGLRenderWindowLifetime(int, char*[])
{
  using namespace deepgi_headless_test;
  if (!RequireNoDisplay("TestDeepGIEGLRenderWindowLifetime"))
  {
    return EXIT_FAILURE;
  }
  ScopedMessageCounter messages;
  int failures = 0;

  // In sequence: each window creates and destroys its own context.
  for (int i = 0; i < 2; ++i)
  {
    auto rw = vtkSmartPointer<vtkDeepGIEGLRenderWindow>::New();
    SetUpWindow(rw);
    std::string label = "sequential window " + std::to_string(i);
    failures += RenderAndCheck(rw, label.c_str());
    rw = nullptr; // destroyed here
    if (eglGetCurrentContext() != EGL_NO_CONTEXT)
    {
      std::fprintf(stderr, "%s: a context is still current after destruction\n", label.c_str());
      ++failures;
    }
  }

  // Side by side.
  auto a = vtkSmartPointer<vtkDeepGIEGLRenderWindow>::New();
  auto b = vtkSmartPointer<vtkDeepGIEGLRenderWindow>::New();
  SetUpWindow(a);
  SetUpWindow(b);
  failures += RenderAndCheck(a, "window A");
  failures += RenderAndCheck(b, "window B");
  failures += RenderAndCheck(a, "window A again");
  if (a->GetGenericContext() == b->GetGenericContext())
  {
    std::fprintf(stderr, "two windows must have two contexts\n");
    ++failures;
  }
  b->MakeCurrent();
  void* bContext = b->GetGenericContext();
  a = nullptr; // destroying A must leave B's context current and usable
  if (eglGetCurrentContext() != bContext)
  {
    std::fprintf(stderr, "destroying A did not restore B's current context\n");
    ++failures;
  }
  failures += RenderAndCheck(b, "window B after A was destroyed");
  b = nullptr;
  if (eglGetCurrentContext() != EGL_NO_CONTEXT)
  {
    std::fprintf(stderr, "a context is still current after both windows are gone\n");
    ++failures;
  }

  // And a fresh window after everything was torn down (display terminated).
  {
    vtkNew<vtkDeepGIEGLRenderWindow> c;
    SetUpWindow(c);
    failures += RenderAndCheck(c, "window C after teardown");
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
