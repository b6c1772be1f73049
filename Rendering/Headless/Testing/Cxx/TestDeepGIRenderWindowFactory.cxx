// vtkDeepGIRenderWindowFactory without an X display (ctest sets DISPLAY=):
// backend names, auto resolving to EGL, the x11 backend refusing with an
// error instead of crashing, unknown backends, and an EGL window from the
// factory rendering the test scene correctly.
#include "vtkDeepGIRenderWindowFactory.h"

#include "DeepGIHeadlessTestHelpers.h"

#include <cstring>
#include <sstream>

int TestDeepGIRenderWindowFactory(int, char*[])
{
  using namespace deepgi_headless_test;
  using F = vtkDeepGIRenderWindowFactory;
  if (!RequireNoDisplay("TestDeepGIRenderWindowFactory"))
  {
    return EXIT_FAILURE;
  }
  int failures = 0;
  auto expect = [&](bool ok, const char* what)
  {
    if (!ok)
    {
      std::fprintf(stderr, "FAILED: %s\n", what);
      ++failures;
    }
  };

  vtkNew<F> factory;
  std::ostringstream printed;
  factory->Print(printed);
  expect(printed.str().find("EGL support: yes") != std::string::npos, "PrintSelf: EGL support");

  // Names.
  expect(F::GetBackendFromString("auto") == F::BACKEND_AUTO, "\"auto\"");
  expect(F::GetBackendFromString("x11") == F::BACKEND_X11, "\"x11\"");
  expect(F::GetBackendFromString("egl") == F::BACKEND_EGL, "\"egl\"");
  expect(F::GetBackendFromString("EGL") == F::BACKEND_EGL, "\"EGL\" (case-insensitive)");
  expect(F::GetBackendFromString("osmesa") == -1, "unknown name gives -1");
  expect(F::GetBackendFromString("") == -1, "empty name gives -1");
  expect(F::GetBackendFromString(nullptr) == -1, "nullptr gives -1");
  for (int b : { F::BACKEND_AUTO, F::BACKEND_X11, F::BACKEND_EGL })
  {
    expect(F::GetBackendFromString(F::GetBackendAsString(b)) == b, "name round trip");
  }
  expect(F::GetBackendAsString(7) == nullptr, "unknown value gives nullptr");

  // No X here: auto is EGL, x11 refuses.
  expect(!F::IsX11Available(), "no X11 without DISPLAY");
  expect(F::IsEGLAvailable(), "EGL available");
  expect(F::ResolveBackend(F::BACKEND_AUTO) == F::BACKEND_EGL, "auto resolves to egl");
  expect(F::ResolveBackend(F::BACKEND_X11) == F::BACKEND_X11, "x11 resolves to itself");
  {
    ScopedMessageCounter messages(/*expectErrors=*/true);
    vtkRenderWindow* rw = F::NewRenderWindow(F::BACKEND_X11);
    expect(rw == nullptr, "x11 backend without X gives nullptr");
    expect(messages.Errors() == 1, "x11 backend without X reports one error");
    if (rw)
    {
      rw->Delete();
    }
    messages.Reset();
    rw = F::NewRenderWindow(42);
    expect(rw == nullptr, "unknown backend gives nullptr");
    expect(messages.Errors() == 1, "unknown backend reports one error");
    if (rw)
    {
      rw->Delete();
    }
  }

  // Windows from the factory render the scene.
  ScopedMessageCounter messages;
  for (int backend : { F::BACKEND_EGL, F::BACKEND_AUTO })
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
    expect(rw->IsA("vtkDeepGIEGLRenderWindow") != 0, "egl/auto give a vtkDeepGIEGLRenderWindow");
    expect(rw->GetReferenceCount() == 1, "the caller holds the only reference");
    expect(!rw->GetShowWindow(), "factory windows are offscreen");
    SetUpWindow(rw);
    failures += RenderAndCheck(rw, label.c_str());
  }
  expect(messages.Errors() == 0 && messages.Warnings() == 0, "no VTK errors or warnings");

  std::printf("%d failure(s)\n", failures);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
