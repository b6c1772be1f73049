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
  using namespace DeepGITest;
  if (!RequireNoDisplay("TestDeepGIEGLRenderWindowLifetime"))
  {
    return EXIT_FAILURE;
  }
  ScopedMessageCounter messages;

  // In sequence: each window creates and destroys its own context.
  for (int i = 0; i < 2; ++i)
  {
    auto rw = vtkSmartPointer<vtkDeepGIEGLRenderWindow>::New();
    SetUpWindow(rw);
    std::string label = "sequential window " + std::to_string(i);
    RenderAndCheck(rw, label.c_str());
    rw = nullptr; // destroyed here
    Check(eglGetCurrentContext() == EGL_NO_CONTEXT,
      label + ": no context is current after destruction");
  }

  // Side by side.
  auto a = vtkSmartPointer<vtkDeepGIEGLRenderWindow>::New();
  auto b = vtkSmartPointer<vtkDeepGIEGLRenderWindow>::New();
  SetUpWindow(a);
  SetUpWindow(b);
  RenderAndCheck(a, "window A");
  RenderAndCheck(b, "window B");
  RenderAndCheck(a, "window A again");
  Check(a->GetGenericContext() != b->GetGenericContext(), "two windows have two contexts");
  b->MakeCurrent();
  void* bContext = b->GetGenericContext();
  a = nullptr; // destroying A must leave B's context current and usable
  Check(eglGetCurrentContext() == bContext, "destroying A leaves B's context current");
  RenderAndCheck(b, "window B after A was destroyed");
  b = nullptr;
  Check(
    eglGetCurrentContext() == EGL_NO_CONTEXT, "no context is current after both windows are gone");

  // And a fresh window after everything was torn down (display terminated).
  {
    vtkNew<vtkDeepGIEGLRenderWindow> c;
    SetUpWindow(c);
    RenderAndCheck(c, "window C after teardown");
  }

  messages.CheckNone();
  return ExitStatus();
}
