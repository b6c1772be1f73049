#include "vtkDeepGIRenderWindowFactory.h"

#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderWindow.h"

#if DEEPGI_HEADLESS_HAVE_EGL
#include "vtkDeepGIEGLRenderWindow.h"
#endif

#if DEEPGI_HEADLESS_HAVE_X11
#include <X11/Xlib.h>

#include <chrono>
#include <thread>
#endif

// vtkRenderWindow::New() must find VTK's OpenGL2 implementation even when the
// application itself never mentions RenderingOpenGL2.
#include "vtkAutoInit.h"
VTK_MODULE_INIT(vtkRenderingOpenGL2);

#include <cctype>
#include <cstdlib>
#include <sstream>
#include <string>

vtkStandardNewMacro(vtkDeepGIRenderWindowFactory);

namespace
{
#if DEEPGI_HEADLESS_HAVE_X11
// One X connection for every window this factory makes, opened with a few
// retries: a busy Xvfb occasionally drops a connection during its handshake
// (seen as a few percent of XOpenDisplay calls failing under load), and
// vtkXOpenGLRenderWindow aborts the process when its own XOpenDisplay fails.
// Windows given a display do not close it; it lives as long as the process.
Display* SharedDisplay()
{
  static Display* display = nullptr;
  if (!display)
  {
    for (int attempt = 0; attempt < 20 && !display; ++attempt)
    {
      display = XOpenDisplay(nullptr);
      if (!display)
      {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
      }
    }
  }
  return display;
}
#endif

// The static methods have no `this`: report through a temporary instance so
// the message names the class like any vtkErrorMacro.
void ReportError(const std::string& message)
{
  vtkNew<vtkDeepGIRenderWindowFactory> reporter;
  vtkErrorWithObjectMacro(reporter.Get(), << message);
}
}

//------------------------------------------------------------------------------
int vtkDeepGIRenderWindowFactory::GetBackendFromString(const char* name)
{
  if (!name)
  {
    return -1;
  }
  std::string s(name);
  for (char& c : s)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  if (s == "auto")
  {
    return BACKEND_AUTO;
  }
  if (s == "x11")
  {
    return BACKEND_X11;
  }
  if (s == "egl")
  {
    return BACKEND_EGL;
  }
  return -1;
}

//------------------------------------------------------------------------------
const char* vtkDeepGIRenderWindowFactory::GetBackendAsString(int backend)
{
  switch (backend)
  {
    case BACKEND_AUTO:
      return "auto";
    case BACKEND_X11:
      return "x11";
    case BACKEND_EGL:
      return "egl";
    default:
      return nullptr;
  }
}

//------------------------------------------------------------------------------
bool vtkDeepGIRenderWindowFactory::IsX11Available()
{
#if DEEPGI_HEADLESS_HAVE_X11
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
  {
    return false;
  }
  return SharedDisplay() != nullptr;
#else
  return false;
#endif
}

//------------------------------------------------------------------------------
bool vtkDeepGIRenderWindowFactory::IsEGLAvailable()
{
#if DEEPGI_HEADLESS_HAVE_EGL
  return vtkDeepGIEGLRenderWindow::IsEGLAvailable();
#else
  return false;
#endif
}

//------------------------------------------------------------------------------
int vtkDeepGIRenderWindowFactory::ResolveBackend(int backend)
{
  if (backend == BACKEND_AUTO)
  {
    return IsX11Available() ? BACKEND_X11 : BACKEND_EGL;
  }
  return backend;
}

//------------------------------------------------------------------------------
vtkRenderWindow* vtkDeepGIRenderWindowFactory::NewRenderWindow(int backend)
{
  const char* requested = GetBackendAsString(backend);
  if (!requested)
  {
    std::ostringstream msg;
    msg << "unknown backend " << backend << " (use BACKEND_AUTO, BACKEND_X11 or BACKEND_EGL)";
    ReportError(msg.str());
    return nullptr;
  }
  const int resolved = ResolveBackend(backend);

  if (resolved == BACKEND_X11)
  {
    if (!IsX11Available())
    {
      const char* display = std::getenv("DISPLAY");
      ReportError(std::string("the x11 backend needs an X server, but ") +
        ((display && *display) ? ("none answers on DISPLAY=" + std::string(display))
                               : std::string("DISPLAY is not set")) +
        ". Use the egl backend, or run under scripts/with-display.sh (Xvfb).");
      return nullptr;
    }
    vtkRenderWindow* rw = vtkRenderWindow::New();
    if (!rw || !rw->IsA("vtkOpenGLRenderWindow"))
    {
      ReportError(std::string("vtkRenderWindow::New() gave ") +
        (rw ? rw->GetClassName() : "nothing") +
        ", not an OpenGL render window; is VTK::RenderingOpenGL2 available?");
      if (rw)
      {
        rw->Delete();
      }
      return nullptr;
    }
#if DEEPGI_HEADLESS_HAVE_X11
    rw->SetDisplayId(SharedDisplay());
#endif
    rw->SetOffScreenRendering(1);
    return rw;
  }

#if DEEPGI_HEADLESS_HAVE_EGL
  vtkDeepGIEGLRenderWindow* rw = vtkDeepGIEGLRenderWindow::New();
  if (!rw->InitializeEGL())
  {
    // InitializeEGL() has reported the details.
    ReportError(std::string("the egl backend") +
      (backend == BACKEND_AUTO ? " (chosen by auto: no X server)" : "") +
      " is not available: no OpenGL 3.2+ context could be created through EGL.");
    rw->Delete();
    return nullptr;
  }
  // Hand the window back with no context current, as vtkRenderWindow::New()
  // does: the next Render() makes it current.
  rw->ReleaseCurrent();
  return rw;
#else
  ReportError(std::string("the egl backend") +
    (backend == BACKEND_AUTO ? " (chosen by auto: no X server)" : "") +
    " is not available: this build of vtkDeepGIHeadless has no EGL support (libEGL and its "
    "headers were not found at configure time; install libegl-dev and reconfigure).");
  return nullptr;
#endif
}

//------------------------------------------------------------------------------
void vtkDeepGIRenderWindowFactory::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "X11 support: " << (DEEPGI_HEADLESS_HAVE_X11 ? "yes" : "no") << "\n";
  os << indent << "EGL support: " << (DEEPGI_HEADLESS_HAVE_EGL ? "yes" : "no") << "\n";
}
