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
  using namespace DeepGITest;
  using F = vtkDeepGIRenderWindowFactory;
  if (!RequireNoDisplay("TestDeepGIRenderWindowFactory"))
  {
    return EXIT_FAILURE;
  }

  vtkNew<F> factory;
  std::ostringstream printed;
  factory->Print(printed);
  Check(printed.str().find("EGL support: yes") != std::string::npos, "PrintSelf: EGL support");

  // Names.
  Check(F::GetBackendFromString("auto") == F::BACKEND_AUTO, "\"auto\"");
  Check(F::GetBackendFromString("x11") == F::BACKEND_X11, "\"x11\"");
  Check(F::GetBackendFromString("egl") == F::BACKEND_EGL, "\"egl\"");
  Check(F::GetBackendFromString("EGL") == F::BACKEND_EGL, "\"EGL\" (case-insensitive)");
  Check(F::GetBackendFromString("osmesa") == -1, "unknown name gives -1");
  Check(F::GetBackendFromString("") == -1, "empty name gives -1");
  Check(F::GetBackendFromString(nullptr) == -1, "nullptr gives -1");
  for (int b : { F::BACKEND_AUTO, F::BACKEND_X11, F::BACKEND_EGL })
  {
    Check(F::GetBackendFromString(F::GetBackendAsString(b)) == b, "name round trip");
  }
  Check(F::GetBackendAsString(7) == nullptr, "unknown value gives nullptr");

  // No X here: auto is EGL, x11 refuses.
  Check(!F::IsX11Available(), "no X11 without DISPLAY");
  Check(F::IsEGLAvailable(), "EGL available");
  Check(F::ResolveBackend(F::BACKEND_AUTO) == F::BACKEND_EGL, "auto resolves to egl");
  Check(F::ResolveBackend(F::BACKEND_X11) == F::BACKEND_X11, "x11 resolves to itself");
  {
    ScopedMessageCounter messages(/*expectErrors=*/true);
    vtkRenderWindow* rw = F::NewRenderWindow(F::BACKEND_X11);
    Check(rw == nullptr, "x11 backend without X gives nullptr");
    Check(messages.Errors() == 1, "x11 backend without X reports one error");
    if (rw)
    {
      rw->Delete();
    }
    messages.Reset();
    rw = F::NewRenderWindow(42);
    Check(rw == nullptr, "unknown backend gives nullptr");
    Check(messages.Errors() == 1, "unknown backend reports one error");
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
    if (!Check(rw != nullptr, label + ": a window"))
    {
      continue;
    }
    Check(rw->IsA("vtkDeepGIEGLRenderWindow") != 0, "egl/auto give a vtkDeepGIEGLRenderWindow");
    Check(rw->GetReferenceCount() == 1, "the caller holds the only reference");
    Check(!rw->GetShowWindow(), "factory windows are offscreen");
    SetUpWindow(rw);
    RenderAndCheck(rw, label.c_str());
  }
  messages.CheckNone();
  return ExitStatus();
}
