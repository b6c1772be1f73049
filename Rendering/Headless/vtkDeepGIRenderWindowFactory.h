/**
 * @class   vtkDeepGIRenderWindowFactory
 * @brief   Creates an offscreen render window for the X11 or the EGL backend.
 *
 * Scripts, tests and the command-line renderer ask this class for their
 * render window instead of calling vtkRenderWindow::New(), so that the same
 * program runs on a desktop, under Xvfb and on a headless server:
 *
 * - BACKEND_X11: vtkRenderWindow::New() (Debian's VTK: vtkXOpenGLRenderWindow)
 *   with offscreen rendering on. Needs a reachable X server (DISPLAY).
 * - BACKEND_EGL: a vtkDeepGIEGLRenderWindow: no X server, an EGL context on
 *   a GPU's EGL device or on Mesa's surfaceless platform.
 * - BACKEND_AUTO: X11 when DISPLAY is set and an X connection opens, else EGL.
 *
 * All methods are static; the class is a vtkObject only so that it is
 * wrapped for Python:
 * @code{.py}
 * from vtkdeepgi import vtkDeepGIRenderWindowFactory as F
 * rw = F.NewRenderWindow(F.GetBackendFromString("auto"))
 * @endcode
 */

#ifndef vtkDeepGIRenderWindowFactory_h
#define vtkDeepGIRenderWindowFactory_h

#include "vtkDeepGIHeadlessModule.h" // For export macro
#include "vtkObject.h"
#include "vtkWrappingHints.h" // For VTK_NEWINSTANCE

class vtkRenderWindow;

class VTKDEEPGIHEADLESS_EXPORT vtkDeepGIRenderWindowFactory : public vtkObject
{
public:
  static vtkDeepGIRenderWindowFactory* New();
  vtkTypeMacro(vtkDeepGIRenderWindowFactory, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Backend
  {
    BACKEND_AUTO = 0,
    BACKEND_X11 = 1,
    BACKEND_EGL = 2
  };

  /**
   * A new offscreen render window for `backend` (a Backend value); the caller
   * owns the reference (Delete() it, or hand it to a vtkSmartPointer with
   * TakeReference). The window has no renderer yet. Returns nullptr, after a
   * vtkErrorMacro saying why, when the backend cannot work here: an unknown
   * value, X11 without a reachable X server, or EGL missing from this build
   * or unable to create an OpenGL 3.2+ context. An EGL window comes back with
   * its context already created (which is how availability is tested) but
   * not current.
   */
  VTK_NEWINSTANCE
  static vtkRenderWindow* NewRenderWindow(int backend);

  /**
   * "auto", "x11" or "egl" (case-insensitive) to a Backend value; -1 for
   * anything else, nullptr included.
   */
  static int GetBackendFromString(const char* name);

  /**
   * A Backend value to "auto", "x11" or "egl"; nullptr for unknown values.
   */
  static const char* GetBackendAsString(int backend);

  /**
   * The backend BACKEND_AUTO resolves to right now: BACKEND_X11 when
   * IsX11Available(), else BACKEND_EGL. Other values are returned unchanged.
   */
  static int ResolveBackend(int backend);

  /**
   * True when DISPLAY is set and non-empty and an X connection to it opens.
   */
  static bool IsX11Available();

  /**
   * True when this build has EGL support and an EGL display can be
   * initialised (no context is created).
   */
  static bool IsEGLAvailable();

protected:
  vtkDeepGIRenderWindowFactory() = default;
  ~vtkDeepGIRenderWindowFactory() override = default;

private:
  vtkDeepGIRenderWindowFactory(const vtkDeepGIRenderWindowFactory&) = delete;
  void operator=(const vtkDeepGIRenderWindowFactory&) = delete;
};

#endif
