/**
 * @class   vtkDeepGIEGLRenderWindow
 * @brief   OpenGL render window that owns an EGL context and needs no X server.
 *
 * Debian's VTK 9.1 is built for X11 only: its vtkRenderWindow needs an X
 * display, and VTK's own vtkEGLRenderWindow is not compiled in. This window
 * fills the gap. It is a vtkGenericOpenGLRenderWindow that creates, makes
 * current and destroys its own EGL context, so no observers are needed:
 *
 * - Display: on a machine with a GPU, an EGL device (EGL_EXT_platform_device,
 *   enumerated with eglQueryDevicesEXT; NVIDIA's headless path); otherwise
 *   Mesa's surfaceless platform (EGL_MESA_platform_surfaceless, llvmpipe when
 *   there is no GPU). See SetPlatform() and SetDeviceIndex().
 * - Context: desktop OpenGL, core profile. 4.5 is requested first, then 4.3,
 *   4.1, 3.3 and 3.2; VTK needs at least 3.2.
 * - Drawable: a 16x16 pbuffer only gives the context a default framebuffer;
 *   VTK draws into its own offscreen framebuffers (RenderFramebuffer,
 *   DisplayFramebuffer), which follow SetSize(). The window is always
 *   offscreen: ShowWindow stays false and UseOffScreenBuffers stays true.
 *
 * GLEW: Debian's libGLEW 2.2 is the GLX build. Its glewInit() loads the GL
 * entry points (through glXGetProcAddressARB, which under libglvnd returns
 * the same dispatch stubs as eglGetProcAddress and needs no X connection),
 * then asks GLX for its extensions and returns GLEW_ERROR_NO_GLX_DISPLAY
 * because no GLX context is current. VTK treats that as fatal. This window
 * overrides OpenGLInitContext(): it accepts exactly that one code, and only
 * when its own EGL context is current, checks GL 3.2 and that the GL entry
 * points VTK and this project need resolved (each compared with
 * eglGetProcAddress), and reports any other failure as an error.
 *
 * Several windows may exist at once and in sequence; EGL displays are
 * reference counted so that eglTerminate() runs only when the last window
 * using a display lets it go. Finalize() (also run by the destructor)
 * releases VTK's graphics resources while the context is current, destroys
 * the context and restores whatever EGL context was current before.
 *
 * Mixing with X11 windows in one thread: libglvnd lets only one window-system
 * API (GLX or EGL) have a current context per thread. This window releases a
 * current GLX context itself when it needs its own, but an X11 window does
 * not do the reverse (X error BadAccess in glXMakeCurrent, fatal by default):
 * call ReleaseCurrent() on this window before rendering or destroying an
 * X11 window in the same thread.
 *
 * Environment: VTK_DEFAULT_EGL_DEVICE_INDEX (as in VTK's own EGL window) sets
 * the default device index.
 *
 * @sa vtkDeepGIRenderWindowFactory
 */

#ifndef vtkDeepGIEGLRenderWindow_h
#define vtkDeepGIEGLRenderWindow_h

#include "vtkDeepGIHeadlessModule.h" // For export macro
#include "vtkGenericOpenGLRenderWindow.h"

#include <string> // For std::string

class VTKDEEPGIHEADLESS_EXPORT vtkDeepGIEGLRenderWindow : public vtkGenericOpenGLRenderWindow
{
public:
  static vtkDeepGIEGLRenderWindow* New();
  vtkTypeMacro(vtkDeepGIEGLRenderWindow, vtkGenericOpenGLRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Which EGL platform provides the display.
   * PLATFORM_AUTO: a hardware EGL device if there is one, else Mesa's
   * surfaceless platform, else the first (software) EGL device.
   * PLATFORM_DEVICE: EGL device number DeviceIndex (or the first hardware
   * device, then device 0, when DeviceIndex is -1).
   * PLATFORM_SURFACELESS: Mesa's surfaceless platform.
   */
  enum Platform
  {
    PLATFORM_AUTO = 0,
    PLATFORM_DEVICE = 1,
    PLATFORM_SURFACELESS = 2
  };

  ///@{
  /**
   * The EGL platform to use (see Platform). Only read when the context is
   * created. Default PLATFORM_AUTO.
   * PLATFORM_AUTO: a hardware EGL device if there is one, else Mesa's surfaceless platform, else
   * the first (software) EGL device. PLATFORM_DEVICE: the EGL device DeviceIndex.
   * PLATFORM_SURFACELESS: Mesa's surfaceless platform.
   *
   * @type int (Platform)
   * @range PLATFORM_AUTO 0, PLATFORM_DEVICE 1, PLATFORM_SURFACELESS 2; clamped
   * @default PLATFORM_AUTO
   */
  vtkSetClampMacro(Platform, int, PLATFORM_AUTO, PLATFORM_SURFACELESS);
  vtkGetMacro(Platform, int);
  ///@}

  // DeviceIndex (vtkRenderWindow::SetDeviceIndex/GetDeviceIndex): the EGL
  // device, as enumerated by eglQueryDevicesEXT, that the device platform
  // uses; -1 (this class's default, unless VTK_DEFAULT_EGL_DEVICE_INDEX is
  // set) picks the first hardware device. Only read when the context is
  // created.

  /**
   * Number of EGL devices eglQueryDevicesEXT reports (0 when the device
   * extensions are missing).
   */
  int GetNumberOfDevices() override;

  /**
   * Whether an EGL display can be initialised on this machine with the
   * given platform choice. Cheap: creates no context.
   */
  static bool IsEGLAvailable(int platform = PLATFORM_AUTO);

  /**
   * Create the EGL display, context and pbuffer if they do not exist yet,
   * make the context current and initialise VTK's OpenGL state. Returns
   * false, after a vtkErrorMacro saying why, when that fails; later calls
   * then fail quietly until Finalize() allows a new attempt (e.g. after
   * SetPlatform()). Render() and Initialize() call it; call it directly to
   * test for a working context.
   */
  bool InitializeEGL();

  /**
   * True once an EGL context exists (it may not be current).
   */
  bool HasContext() const;

  /**
   * How the display was obtained, e.g. "EGL device 0 (EGL_NV_device_cuda
   * ...)" or "Mesa surfaceless platform"; empty before the context exists.
   */
  const char* GetPlatformDescription() const { return this->PlatformDescription.c_str(); }

  /**
   * The context's OpenGL version (e.g. 4.5), 0.0 before creation.
   */
  vtkGetMacro(ContextMajorVersion, int);
  vtkGetMacro(ContextMinorVersion, int);

  ///@{
  /**
   * vtkWindow / vtkRenderWindow API, implemented with EGL.
   */
  void Initialize() override;
  void Finalize() override;
  void Render() override;
  void MakeCurrent() override;
  void ReleaseCurrent() override;
  bool IsCurrent() override;
  int SupportsOpenGL() override;
  vtkTypeBool IsDirect() override;
  void* GetGenericContext() override;
  void* GetGenericDisplayId() override;
  void* GetGenericDrawable() override;
  void OpenGLInitContext() override;
  ///@}

  /**
   * The window is never shown: setting ShowWindow to true warns and is
   * ignored.
   *
   * @default off
   */
  void SetShowWindow(bool val) override;

  /**
   * Rendering always goes to VTK's offscreen framebuffers: setting this to
   * false warns and is ignored.
   *
   * @default on
   */
  void SetUseOffScreenBuffers(bool val) override;

protected:
  vtkDeepGIEGLRenderWindow();
  ~vtkDeepGIEGLRenderWindow() override;

  void CreateAWindow() override;
  void DestroyWindow() override;

  int Platform;
  int ContextMajorVersion;
  int ContextMinorVersion;
  std::string PlatformDescription;

private:
  vtkDeepGIEGLRenderWindow(const vtkDeepGIEGLRenderWindow&) = delete;
  void operator=(const vtkDeepGIEGLRenderWindow&) = delete;

  struct vtkInternals;
  vtkInternals* Internals;

  // The stages of InitializeEGL.
  bool OpenDisplay(std::string& description);
  bool InitializeContext(const std::string& description);
  bool FailContext(const std::string& description, const std::string& what);

  // The stages of OpenGLInitContext.
  bool MakeContextCurrentForInit();
  bool LoadOpenGL();
  bool CheckEntryPoints();
  void QueryLineWidthRange();
};

#endif
