#include "vtkDeepGIEGLRenderWindow.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLState.h"
#include "vtk_glew.h"

// EGL after GLEW (GLEW must come before any other GL header). EGL's
// platform header pulls in no X11 headers unless USE_X11 is defined.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#if DEEPGI_HEADLESS_HAVE_GLX
// Last: X11's macros (None, Bool, ...) must not reach the headers above.
#include <GL/glx.h>
#endif

#include <cstdlib>
#include <map>
#include <mutex>
#include <sstream>
#include <vector>

namespace
{
//------------------------------------------------------------------------------
// Human-readable names for EGL error codes, so that messages say what failed.
const char* EGLErrorName(EGLint code)
{
  switch (code)
  {
    case EGL_SUCCESS:
      return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
      return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE:
      return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP:
      return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW:
      return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE:
      return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST:
      return "EGL_CONTEXT_LOST";
    default:
      return "unknown EGL error";
  }
}

std::string EGLErrorString(EGLint code)
{
  std::ostringstream s;
  s << EGLErrorName(code) << " (0x" << std::hex << code << ")";
  return s.str();
}

std::string EGLErrorString()
{
  return EGLErrorString(eglGetError());
}

bool HasExtension(const char* list, const char* name)
{
  if (!list || !name)
  {
    return false;
  }
  // Extension strings are space separated; match whole words only.
  const std::string haystack = std::string(" ") + list + " ";
  return haystack.find(std::string(" ") + name + " ") != std::string::npos;
}

//------------------------------------------------------------------------------
// Client extensions (EGL_EXT_platform_base and friends), queried once.
struct EGLClientExtensions
{
  PFNEGLGETPLATFORMDISPLAYEXTPROC GetPlatformDisplay = nullptr;
  PFNEGLQUERYDEVICESEXTPROC QueryDevices = nullptr;
  PFNEGLQUERYDEVICESTRINGEXTPROC QueryDeviceString = nullptr;
  bool Surfaceless = false;
  bool Device = false;

  static const EGLClientExtensions& Get()
  {
    static const EGLClientExtensions instance;
    return instance;
  }

private:
  EGLClientExtensions()
  {
    const char* ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!ext)
    {
      // EGL < 1.5 without EGL_EXT_client_extensions: leaves EGL_BAD_DISPLAY.
      eglGetError();
      return;
    }
    if (HasExtension(ext, "EGL_EXT_platform_base"))
    {
      this->GetPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    }
    if (HasExtension(ext, "EGL_EXT_device_enumeration") || HasExtension(ext, "EGL_EXT_device_base"))
    {
      this->QueryDevices =
        reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    }
    if (HasExtension(ext, "EGL_EXT_device_query") || HasExtension(ext, "EGL_EXT_device_base"))
    {
      this->QueryDeviceString = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
        eglGetProcAddress("eglQueryDeviceStringEXT"));
    }
    this->Surfaceless =
      this->GetPlatformDisplay && HasExtension(ext, "EGL_MESA_platform_surfaceless");
    this->Device = this->GetPlatformDisplay && this->QueryDevices &&
      HasExtension(ext, "EGL_EXT_platform_device");
  }
};

std::vector<EGLDeviceEXT> QueryDevices()
{
  std::vector<EGLDeviceEXT> devices;
  const EGLClientExtensions& ext = EGLClientExtensions::Get();
  if (!ext.Device)
  {
    return devices;
  }
  EGLint count = 0;
  if (!ext.QueryDevices(0, nullptr, &count) || count <= 0)
  {
    eglGetError();
    return devices;
  }
  devices.resize(count);
  if (!ext.QueryDevices(count, devices.data(), &count))
  {
    eglGetError();
    devices.clear();
    return devices;
  }
  devices.resize(count);
  return devices;
}

std::string DeviceExtensions(EGLDeviceEXT device)
{
  const EGLClientExtensions& ext = EGLClientExtensions::Get();
  const char* s = ext.QueryDeviceString ? ext.QueryDeviceString(device, EGL_EXTENSIONS) : nullptr;
  return s ? s : "";
}

bool IsSoftwareDevice(EGLDeviceEXT device)
{
  return HasExtension(DeviceExtensions(device).c_str(), "EGL_MESA_device_software");
}

//------------------------------------------------------------------------------
// eglGetPlatformDisplay returns the same handle for the same device or
// platform, so several windows may share one EGLDisplay. eglInitialize on an
// initialised display is harmless, but eglTerminate would invalidate every
// context on it: count the users and terminate with the last one.
class DisplayRegistry
{
public:
  static bool Acquire(EGLDisplay dpy, EGLint* major, EGLint* minor)
  {
    std::lock_guard<std::mutex> lock(Mutex());
    if (!eglInitialize(dpy, major, minor))
    {
      return false;
    }
    ++Counts()[dpy];
    return true;
  }

  // Returns true when no display is in use any more.
  static bool Release(EGLDisplay dpy)
  {
    std::lock_guard<std::mutex> lock(Mutex());
    auto& counts = Counts();
    auto it = counts.find(dpy);
    if (it != counts.end() && --it->second <= 0)
    {
      counts.erase(it);
      eglTerminate(dpy);
    }
    return counts.empty();
  }

private:
  static std::mutex& Mutex()
  {
    static std::mutex m;
    return m;
  }
  static std::map<EGLDisplay, int>& Counts()
  {
    static std::map<EGLDisplay, int> counts;
    return counts;
  }
};

// Open and initialise one candidate display; returns EGL_NO_DISPLAY (and
// appends the reason to `log`) on failure.
EGLDisplay OpenDisplay(
  EGLenum platform, void* native, const std::string& what, std::ostringstream& log)
{
  const EGLClientExtensions& ext = EGLClientExtensions::Get();
  EGLDisplay dpy = ext.GetPlatformDisplay(platform, native, nullptr);
  if (dpy == EGL_NO_DISPLAY)
  {
    log << "  " << what << ": eglGetPlatformDisplayEXT failed: " << EGLErrorString() << "\n";
    return EGL_NO_DISPLAY;
  }
  EGLint major = 0, minor = 0;
  if (!DisplayRegistry::Acquire(dpy, &major, &minor))
  {
    log << "  " << what << ": eglInitialize failed: " << EGLErrorString() << "\n";
    return EGL_NO_DISPLAY;
  }
  if (major < 1 || (major == 1 && minor < 4))
  {
    log << "  " << what << ": EGL " << major << "." << minor
        << " is too old (desktop OpenGL needs EGL 1.4)\n";
    DisplayRegistry::Release(dpy);
    return EGL_NO_DISPLAY;
  }
  return dpy;
}

// The devices of the EGL device platform; an empty list, with the reason in
// `log`, when that platform is missing or reports none.
std::vector<EGLDeviceEXT> ListDevices(std::ostringstream& log)
{
  const EGLClientExtensions& ext = EGLClientExtensions::Get();
  if (!ext.Device)
  {
    log << "  EGL device platform: EGL_EXT_platform_device / eglQueryDevicesEXT not available\n";
  }
  std::vector<EGLDeviceEXT> devices = QueryDevices();
  if (ext.Device && devices.empty())
  {
    log << "  EGL device platform: eglQueryDevicesEXT reports no device\n";
  }
  return devices;
}

// Opens device i; on success `description` names it with its extensions.
EGLDisplay OpenDevice(const std::vector<EGLDeviceEXT>& devices, int i, std::string& description,
  std::ostringstream& log)
{
  std::ostringstream what;
  what << "EGL device " << i;
  std::string devExt = DeviceExtensions(devices[i]);
  if (!devExt.empty())
  {
    what << " (" << devExt << ")";
  }
  EGLDisplay dpy = OpenDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], what.str(), log);
  if (dpy != EGL_NO_DISPLAY)
  {
    description = what.str();
  }
  return dpy;
}

// The first device, in enumeration order, that is (software = true) or is
// not (software = false) a software renderer and opens.
EGLDisplay OpenFirstDevice(const std::vector<EGLDeviceEXT>& devices, bool software,
  std::string& description, std::ostringstream& log)
{
  for (int i = 0; i < static_cast<int>(devices.size()); ++i)
  {
    if (IsSoftwareDevice(devices[i]) == software)
    {
      EGLDisplay dpy = OpenDevice(devices, i, description, log);
      if (dpy != EGL_NO_DISPLAY)
      {
        return dpy;
      }
    }
  }
  return EGL_NO_DISPLAY;
}

// Mesa's surfaceless platform (no device, no window system).
EGLDisplay OpenSurfaceless(std::string& description, std::ostringstream& log)
{
  if (!EGLClientExtensions::Get().Surfaceless)
  {
    log << "  Mesa surfaceless platform: EGL_MESA_platform_surfaceless not available\n";
    return EGL_NO_DISPLAY;
  }
  EGLDisplay dpy = OpenDisplay(
    EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, "Mesa surfaceless platform", log);
  if (dpy != EGL_NO_DISPLAY)
  {
    description = "Mesa surfaceless platform";
  }
  return dpy;
}

// Choose and initialise a display following the platform policy documented
// in the header. `description` says what was chosen; `log` collects why the
// other candidates failed.
EGLDisplay ChooseDisplay(
  int platform, int deviceIndex, std::string& description, std::ostringstream& log)
{
  const bool wantDevice = platform == vtkDeepGIEGLRenderWindow::PLATFORM_DEVICE ||
    platform == vtkDeepGIEGLRenderWindow::PLATFORM_AUTO;
  const bool wantSurfaceless = platform == vtkDeepGIEGLRenderWindow::PLATFORM_SURFACELESS ||
    platform == vtkDeepGIEGLRenderWindow::PLATFORM_AUTO;
  const std::vector<EGLDeviceEXT> devices =
    wantDevice ? ListDevices(log) : std::vector<EGLDeviceEXT>();

  // An explicit device index wins for AUTO and DEVICE.
  if (wantDevice && deviceIndex >= 0)
  {
    if (deviceIndex < static_cast<int>(devices.size()))
    {
      return OpenDevice(devices, deviceIndex, description, log);
    }
    log << "  EGL device " << deviceIndex << ": only " << devices.size() << " device(s) found\n";
    return EGL_NO_DISPLAY;
  }
  EGLDisplay dpy = EGL_NO_DISPLAY;
  // Hardware devices first (a GPU server's NVIDIA device, a DRM render node).
  if (wantDevice)
  {
    dpy = OpenFirstDevice(devices, false, description, log);
  }
  if (dpy == EGL_NO_DISPLAY && wantSurfaceless)
  {
    dpy = OpenSurfaceless(description, log);
  }
  // Last resort: software devices (Mesa's llvmpipe device).
  if (dpy == EGL_NO_DISPLAY && wantDevice)
  {
    dpy = OpenFirstDevice(devices, true, description, log);
  }
  return dpy;
}

// libglvnd allows one window-system API's context to be current per thread:
// eglMakeCurrent fails with EGL_BAD_ACCESS while a GLX context (an X11 VTK
// window's) is current. Release that one so that both kinds of window can
// live in one process. Returns true when a GLX context was released.
bool ReleaseCurrentGLXContext()
{
#if DEEPGI_HEADLESS_HAVE_GLX
  if (glXGetCurrentContext())
  {
    Display* dpy = glXGetCurrentDisplay();
    return dpy && glXMakeCurrent(dpy, None, nullptr);
  }
#endif
  return false;
}

// eglMakeCurrent, retried once after releasing a current GLX context.
// Returns EGL_SUCCESS or the EGL error code.
EGLint MakeCurrentEGL(EGLDisplay dpy, EGLSurface surface, EGLContext ctx)
{
  if (eglMakeCurrent(dpy, surface, surface, ctx))
  {
    return EGL_SUCCESS;
  }
  EGLint error = eglGetError();
  if (error == EGL_BAD_ACCESS && ReleaseCurrentGLXContext())
  {
    error = eglMakeCurrent(dpy, surface, surface, ctx) ? EGL_SUCCESS : eglGetError();
  }
  return error;
}

const char* GLEWErrorName(GLenum code)
{
  switch (code)
  {
    case GLEW_ERROR_NO_GL_VERSION:
      return "GLEW_ERROR_NO_GL_VERSION (no OpenGL version: is a context current?)";
    case GLEW_ERROR_GL_VERSION_10_ONLY:
      return "GLEW_ERROR_GL_VERSION_10_ONLY (OpenGL 1.1 or later needed)";
    case GLEW_ERROR_GLX_VERSION_11_ONLY:
      return "GLEW_ERROR_GLX_VERSION_11_ONLY (GLX 1.2 or later needed)";
    case GLEW_ERROR_NO_GLX_DISPLAY:
      return "GLEW_ERROR_NO_GLX_DISPLAY (no GLX display)";
    default:
      return reinterpret_cast<const char*>(glewGetErrorString(code));
  }
}
// A pbuffer-capable RGBA8 config for desktop OpenGL (the pbuffer only backs
// the default framebuffer; VTK renders into its own FBOs), or, with
// EGL_KHR_surfaceless_context, any 8-bit RGB one without a pbuffer. False
// with `why` set when there is none.
bool ChooseConfig(EGLDisplay display, bool surfacelessContext, EGLConfig& config, bool& usePbuffer,
  std::string& why)
{
  EGLint numConfigs = 0;
  usePbuffer = true;
  const EGLint attribs[] = { EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8,
    EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE };
  if (eglChooseConfig(display, attribs, &config, 1, &numConfigs) && numConfigs >= 1)
  {
    return true;
  }
  eglGetError();
  usePbuffer = false;
  const EGLint anySurface[] = { EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8,
    EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE };
  if (surfacelessContext && eglChooseConfig(display, anySurface, &config, 1, &numConfigs) &&
    numConfigs >= 1)
  {
    return true;
  }
  why = "no EGL config supports desktop OpenGL with 8-bit RGBA" +
    std::string(surfacelessContext ? "" : " and a pbuffer");
  return false;
}

// A desktop OpenGL core-profile context: 4.5 first, then older versions
// down to the 3.2 that VTK requires. The attribute names are EGL 1.5's;
// they have the same values as EGL_KHR_create_context's. Without either,
// the default context. `log` lists what failed.
EGLContext CreateCoreContext(
  EGLDisplay display, EGLConfig config, const char* displayExtensions, std::ostringstream& log)
{
  EGLint eglMajor = 0, eglMinor = 0;
  eglInitialize(display, &eglMajor, &eglMinor); // already initialised: returns version
  const bool canRequestVersion = (eglMajor > 1 || (eglMajor == 1 && eglMinor >= 5)) ||
    HasExtension(displayExtensions, "EGL_KHR_create_context");
  if (!canRequestVersion)
  {
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, nullptr);
    if (context == EGL_NO_CONTEXT)
    {
      log << " default context: " << EGLErrorString() << ";";
    }
    return context;
  }
  const int versions[][2] = { { 4, 5 }, { 4, 3 }, { 4, 1 }, { 3, 3 }, { 3, 2 } };
  for (const auto& v : versions)
  {
    const EGLint attributes[] = { EGL_CONTEXT_MAJOR_VERSION, v[0], EGL_CONTEXT_MINOR_VERSION, v[1],
      EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE };
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, attributes);
    if (context != EGL_NO_CONTEXT)
    {
      return context;
    }
    log << " " << v[0] << "." << v[1] << " core: " << EGLErrorString() << ";";
  }
  return EGL_NO_CONTEXT;
}

// A GL function as GLEW loaded it (nullptr when it did not).
struct GLEntryPoint
{
  const char* Name;
  void* Pointer;
};

// The entry points VTK's OpenGL2 backend and this project's passes call
// through GLEW. GLEW's pointers are only set by glewInit(), so the table is
// read when called, not at load time.
std::vector<GLEntryPoint> GLEntryPoints()
{
#define DEEPGI_ENTRY(fn)                                                                           \
  {                                                                                                \
#fn, reinterpret_cast < void*>(fn)                                                             \
  }
  return {
    DEEPGI_ENTRY(glGetStringi),
    DEEPGI_ENTRY(glGenFramebuffers),
    DEEPGI_ENTRY(glBindFramebuffer),
    DEEPGI_ENTRY(glFramebufferTexture2D),
    DEEPGI_ENTRY(glFramebufferTexture),
    DEEPGI_ENTRY(glFramebufferRenderbuffer),
    DEEPGI_ENTRY(glCheckFramebufferStatus),
    DEEPGI_ENTRY(glBlitFramebuffer),
    DEEPGI_ENTRY(glDeleteFramebuffers),
    DEEPGI_ENTRY(glGenRenderbuffers),
    DEEPGI_ENTRY(glRenderbufferStorageMultisample),
    DEEPGI_ENTRY(glDrawBuffers),
    DEEPGI_ENTRY(glGenVertexArrays),
    DEEPGI_ENTRY(glBindVertexArray),
    DEEPGI_ENTRY(glGenBuffers),
    DEEPGI_ENTRY(glBindBuffer),
    DEEPGI_ENTRY(glBufferData),
    DEEPGI_ENTRY(glMapBufferRange),
    DEEPGI_ENTRY(glVertexAttribPointer),
    DEEPGI_ENTRY(glEnableVertexAttribArray),
    DEEPGI_ENTRY(glCreateShader),
    DEEPGI_ENTRY(glShaderSource),
    DEEPGI_ENTRY(glCompileShader),
    DEEPGI_ENTRY(glCreateProgram),
    DEEPGI_ENTRY(glLinkProgram),
    DEEPGI_ENTRY(glUseProgram),
    DEEPGI_ENTRY(glGetUniformLocation),
    DEEPGI_ENTRY(glUniformMatrix4fv),
    DEEPGI_ENTRY(glActiveTexture),
    DEEPGI_ENTRY(glTexImage3D),
    DEEPGI_ENTRY(glTexImage2DMultisample),
    DEEPGI_ENTRY(glGenerateMipmap),
    DEEPGI_ENTRY(glBlendFuncSeparate),
    DEEPGI_ENTRY(glGenQueries),
  };
#undef DEEPGI_ENTRY
}
} // namespace

//------------------------------------------------------------------------------
struct vtkDeepGIEGLRenderWindow::vtkInternals
{
  EGLDisplay Display = EGL_NO_DISPLAY;
  EGLContext Context = EGL_NO_CONTEXT;
  EGLSurface Surface = EGL_NO_SURFACE;
  bool InitFailed = false;
};

vtkStandardNewMacro(vtkDeepGIEGLRenderWindow);

//------------------------------------------------------------------------------
vtkDeepGIEGLRenderWindow::vtkDeepGIEGLRenderWindow()
  : Platform(PLATFORM_AUTO)
  , ContextMajorVersion(0)
  , ContextMinorVersion(0)
  , Internals(new vtkInternals)
{
  // Headless by construction: never shown, always VTK's offscreen buffers.
  this->ShowWindow = false;
  this->UseOffScreenBuffers = true;
  this->Mapped = 0;
  this->OwnContext = 1;
  this->ScreenSize[0] = 1920;
  this->ScreenSize[1] = 1080;
  this->DeviceIndex = -1; // vtkRenderWindow's default is 0; -1 means automatic here
  if (const char* env = std::getenv("VTK_DEFAULT_EGL_DEVICE_INDEX"))
  {
    char* end = nullptr;
    long v = std::strtol(env, &end, 10);
    if (end != env && v >= -1 && v < VTK_INT_MAX)
    {
      this->DeviceIndex = static_cast<int>(v);
    }
  }
}

//------------------------------------------------------------------------------
vtkDeepGIEGLRenderWindow::~vtkDeepGIEGLRenderWindow()
{
  // Must run here: the base destructor's Finalize() cannot reach our EGL
  // state any more (virtual calls in a destructor stop at that class).
  this->Finalize();
  delete this->Internals;
  this->Internals = nullptr;
}

//------------------------------------------------------------------------------
int vtkDeepGIEGLRenderWindow::GetNumberOfDevices()
{
  return static_cast<int>(QueryDevices().size());
}

//------------------------------------------------------------------------------
bool vtkDeepGIEGLRenderWindow::IsEGLAvailable(int platform)
{
  const EGLClientExtensions& ext = EGLClientExtensions::Get();
  if (!ext.GetPlatformDisplay)
  {
    return false;
  }
  std::string description;
  std::ostringstream log;
  EGLDisplay dpy = ChooseDisplay(platform, -1, description, log);
  if (dpy == EGL_NO_DISPLAY)
  {
    return false;
  }
  DisplayRegistry::Release(dpy);
  return true;
}

//------------------------------------------------------------------------------
bool vtkDeepGIEGLRenderWindow::HasContext() const
{
  return this->Internals && this->Internals->Context != EGL_NO_CONTEXT;
}

//------------------------------------------------------------------------------
bool vtkDeepGIEGLRenderWindow::InitializeEGL()
{
  vtkInternals* impl = this->Internals;
  if (impl->Context != EGL_NO_CONTEXT)
  {
    this->MakeCurrent();
    if (!this->Initialized)
    {
      this->OpenGLInit();
    }
    return this->Initialized && this->GlewInitValid;
  }
  if (impl->InitFailed)
  {
    // Already reported in detail; do not retry on every render.
    return false;
  }
  std::string description;
  if (!this->OpenDisplay(description))
  {
    return false;
  }
  if (!eglBindAPI(EGL_OPENGL_API))
  {
    return this->FailContext(description, "eglBindAPI(EGL_OPENGL_API) failed: " + EGLErrorString());
  }
  const char* displayExtensions = eglQueryString(impl->Display, EGL_EXTENSIONS);
  const bool surfacelessContext = HasExtension(displayExtensions, "EGL_KHR_surfaceless_context");
  EGLConfig config = nullptr;
  bool usePbuffer = true;
  std::string why;
  if (!ChooseConfig(impl->Display, surfacelessContext, config, usePbuffer, why))
  {
    return this->FailContext(description, why);
  }
  std::ostringstream contextLog;
  impl->Context = CreateCoreContext(impl->Display, config, displayExtensions, contextLog);
  if (impl->Context == EGL_NO_CONTEXT)
  {
    return this->FailContext(
      description, "eglCreateContext failed for every OpenGL version tried:" + contextLog.str());
  }
  if (usePbuffer)
  {
    const EGLint pbAttribs[] = { EGL_WIDTH, 16, EGL_HEIGHT, 16, EGL_NONE };
    impl->Surface = eglCreatePbufferSurface(impl->Display, config, pbAttribs);
    if (impl->Surface == EGL_NO_SURFACE)
    {
      why = EGLErrorString();
      if (!surfacelessContext)
      {
        return this->FailContext(description, "eglCreatePbufferSurface failed: " + why);
      }
      vtkDebugMacro("eglCreatePbufferSurface failed (" << why << "); using a surfaceless context");
    }
  }
  const EGLint madeCurrent = MakeCurrentEGL(impl->Display, impl->Surface, impl->Context);
  if (madeCurrent != EGL_SUCCESS)
  {
    return this->FailContext(description, "eglMakeCurrent failed: " + EGLErrorString(madeCurrent));
  }
  return this->InitializeContext(description);
}

//------------------------------------------------------------------------------
// The EGL display of the chosen platform and device; false, with the log of
// what was tried, when none opens.
bool vtkDeepGIEGLRenderWindow::OpenDisplay(std::string& description)
{
  vtkInternals* impl = this->Internals;
  const EGLClientExtensions& ext = EGLClientExtensions::Get();
  std::ostringstream log;
  if (!ext.GetPlatformDisplay)
  {
    log << "  EGL_EXT_platform_base is not available in this libEGL\n";
  }
  else
  {
    impl->Display = ChooseDisplay(this->Platform, this->DeviceIndex, description, log);
  }
  if (impl->Display == EGL_NO_DISPLAY)
  {
    impl->InitFailed = true;
    vtkErrorMacro("No EGL display could be opened (platform "
      << this->Platform << ", device index " << this->DeviceIndex << "):\n"
      << log.str()
      << "Install Mesa's EGL (libegl-mesa0, libgl1-mesa-dri) or a GPU driver with EGL.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
// VTK's OpenGL state on the new, current context.
bool vtkDeepGIEGLRenderWindow::InitializeContext(const std::string& description)
{
  GLint glMajor = 0, glMinor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &glMajor);
  glGetIntegerv(GL_MINOR_VERSION, &glMinor);
  this->ContextMajorVersion = glMajor;
  this->ContextMinorVersion = glMinor;
  this->PlatformDescription = description;
  this->Mapped = 0;
  // A fresh context: VTK's cached GL state must be re-read from it.
  this->Initialized = false;
  this->OpenGLInit();
  if (!this->Initialized || !this->GlewInitValid)
  {
    // OpenGLInitContext() has reported the reason.
    this->PlatformDescription.clear();
    this->ContextMajorVersion = this->ContextMinorVersion = 0;
    return this->FailContext(
      description, "VTK could not initialise OpenGL on the new context (see the error above)");
  }
  vtkDebugMacro("EGL context " << glMajor << "." << glMinor << " on " << description << ": "
                               << reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  return true;
}

//------------------------------------------------------------------------------
// Reports why the context could not be made, releases what was made, and
// stops later renders from retrying. Returns false.
bool vtkDeepGIEGLRenderWindow::FailContext(const std::string& description, const std::string& what)
{
  vtkInternals* impl = this->Internals;
  vtkErrorMacro("EGL context creation failed on " << description << ": " << what);
  if (impl->Surface != EGL_NO_SURFACE)
  {
    eglDestroySurface(impl->Display, impl->Surface);
    impl->Surface = EGL_NO_SURFACE;
  }
  if (impl->Context != EGL_NO_CONTEXT)
  {
    eglMakeCurrent(impl->Display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(impl->Display, impl->Context);
    impl->Context = EGL_NO_CONTEXT;
  }
  DisplayRegistry::Release(impl->Display);
  impl->Display = EGL_NO_DISPLAY;
  impl->InitFailed = true;
  return false;
}

//------------------------------------------------------------------------------
void vtkDeepGIEGLRenderWindow::OpenGLInitContext()
{
  if (!this->Initialized)
  {
    this->GlewInitValid = false;
    if (!this->MakeContextCurrentForInit() || !this->LoadOpenGL() || !this->CheckEntryPoints())
    {
      return;
    }
    this->GlewInitValid = true;
    this->Initialized = true;
    this->QueryLineWidthRange();
  }
  // With Initialized set this only stamps the context creation time.
  this->Superclass::OpenGLInitContext();
}

//------------------------------------------------------------------------------
bool vtkDeepGIEGLRenderWindow::MakeContextCurrentForInit()
{
  if (!this->HasContext())
  {
    vtkErrorMacro("OpenGLInitContext: this window has no EGL context yet");
    return false;
  }
  this->MakeCurrent();
  if (!this->IsCurrent())
  {
    vtkErrorMacro("OpenGLInitContext: the EGL context could not be made current");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
// GLEW's entry points for the current EGL context, and OpenGL 3.2 at least.
bool vtkDeepGIEGLRenderWindow::LoadOpenGL()
{
  // Debian's libGLEW is the GLX build: glewInit() first loads the core and
  // extension GL entry points for the current context (through
  // glXGetProcAddressARB, which libglvnd answers without an X connection
  // with the same dispatch stubs as eglGetProcAddress), and only then asks
  // GLX for its own extensions. With an EGL context no GLX display is
  // current, so that last step returns GLEW_ERROR_NO_GLX_DISPLAY after the
  // GL part succeeded. That code, and only that code, is expected here;
  // CheckEntryPoints() verifies that the GL part really is usable.
  const GLenum result = glewInit();
  if (result == GLEW_ERROR_NO_GLX_DISPLAY)
  {
    vtkDebugMacro("glewInit: GLX extensions skipped (EGL context, no GLX display)");
  }
  else if (result != GLEW_OK)
  {
    vtkErrorMacro("GLEW could not load OpenGL for the EGL context: " << GLEWErrorName(result));
    return false;
  }
  if (!GLEW_VERSION_3_2)
  {
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    vtkErrorMacro("OpenGL 3.2 or later is required; the EGL context provides "
      << (version ? version : "no version string"));
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
// Every entry point of GLEntryPoints() must be loaded by GLEW and known to
// EGL; a missing one is an error, differing addresses are only noted.
bool vtkDeepGIEGLRenderWindow::CheckEntryPoints()
{
  std::ostringstream missing;
  int differing = 0;
  for (const GLEntryPoint& e : GLEntryPoints())
  {
    void* fromEGL = reinterpret_cast<void*>(eglGetProcAddress(e.Name));
    if (!e.Pointer || !fromEGL)
    {
      missing << " " << e.Name << (e.Pointer ? "" : "[GLEW]") << (fromEGL ? "" : "[EGL]");
    }
    else if (e.Pointer != fromEGL)
    {
      ++differing;
    }
  }
  if (!missing.str().empty())
  {
    vtkErrorMacro("OpenGL entry points did not resolve for the EGL context:" << missing.str());
    return false;
  }
  if (differing)
  {
    // Not an error: without libglvnd the loaders may hand out different
    // (equally valid) addresses.
    vtkDebugMacro(<< differing << " GL entry points differ between GLEW and eglGetProcAddress");
  }
  return true;
}

//------------------------------------------------------------------------------
// What vtkOpenGLRenderWindow::OpenGLInitContext does after glewInit.
void vtkDeepGIEGLRenderWindow::QueryLineWidthRange()
{
  GLfloat lineWidthRange[2] = { 1.0f, 1.0f };
  this->MaximumHardwareLineWidth = 1.0f;
  glGetFloatv(
    this->LineSmoothing ? GL_SMOOTH_LINE_WIDTH_RANGE : GL_ALIASED_LINE_WIDTH_RANGE, lineWidthRange);
  if (glGetError() == GL_NO_ERROR)
  {
    this->MaximumHardwareLineWidth = lineWidthRange[1];
  }
}

//------------------------------------------------------------------------------
void vtkDeepGIEGLRenderWindow::Initialize()
{
  this->InitializeEGL();
}

//------------------------------------------------------------------------------
void vtkDeepGIEGLRenderWindow::CreateAWindow()
{
  this->InitializeEGL();
}

//------------------------------------------------------------------------------
void vtkDeepGIEGLRenderWindow::Render()
{
  if (!this->InitializeEGL())
  {
    vtkErrorMacro("Render skipped: this window has no usable EGL OpenGL context");
    return;
  }
  this->Superclass::Render();
}

//------------------------------------------------------------------------------
void vtkDeepGIEGLRenderWindow::Finalize()
{
  this->DestroyWindow();
}

//------------------------------------------------------------------------------
void vtkDeepGIEGLRenderWindow::DestroyWindow()
{
  vtkInternals* impl = this->Internals;
  if (!impl)
  {
    return;
  }
  impl->InitFailed = false;
  if (impl->Context == EGL_NO_CONTEXT)
  {
    return;
  }

  // Another window's context may be current; put it back afterwards.
  EGLDisplay prevDisplay = eglGetCurrentDisplay();
  EGLContext prevContext = eglGetCurrentContext();
  EGLSurface prevDraw = eglGetCurrentSurface(EGL_DRAW);
  EGLSurface prevRead = eglGetCurrentSurface(EGL_READ);

  // VTK's textures, buffers, shaders and framebuffers belong to this context:
  // free them while it is current.
  this->MakeCurrent();
  this->ReleaseGraphicsResources(this);

  const EGLContext ownContext = impl->Context;
  eglMakeCurrent(impl->Display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (impl->Surface != EGL_NO_SURFACE)
  {
    eglDestroySurface(impl->Display, impl->Surface);
    impl->Surface = EGL_NO_SURFACE;
  }
  eglDestroyContext(impl->Display, impl->Context);
  impl->Context = EGL_NO_CONTEXT;
  const bool noDisplayLeft = DisplayRegistry::Release(impl->Display);
  impl->Display = EGL_NO_DISPLAY;

  if (prevContext != EGL_NO_CONTEXT && prevContext != ownContext)
  {
    eglMakeCurrent(prevDisplay, prevDraw, prevRead, prevContext);
  }
  if (noDisplayLeft && eglGetCurrentContext() == EGL_NO_CONTEXT)
  {
    // Free EGL's per-thread state once nothing of ours is left.
    eglReleaseThread();
  }

  this->Mapped = 0;
  this->Initialized = false;
  this->GlewInitValid = false;
  this->PlatformDescription.clear();
  this->ContextMajorVersion = this->ContextMinorVersion = 0;
}

//------------------------------------------------------------------------------
void vtkDeepGIEGLRenderWindow::MakeCurrent()
{
  vtkInternals* impl = this->Internals;
  if (!impl || impl->Context == EGL_NO_CONTEXT)
  {
    return;
  }
  if (eglGetCurrentContext() == impl->Context)
  {
    return;
  }
  const EGLint result = MakeCurrentEGL(impl->Display, impl->Surface, impl->Context);
  if (result != EGL_SUCCESS)
  {
    vtkErrorMacro("eglMakeCurrent failed: " << EGLErrorString(result));
  }
}

//------------------------------------------------------------------------------
void vtkDeepGIEGLRenderWindow::ReleaseCurrent()
{
  vtkInternals* impl = this->Internals;
  if (impl && impl->Context != EGL_NO_CONTEXT && eglGetCurrentContext() == impl->Context)
  {
    eglMakeCurrent(impl->Display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
}

//------------------------------------------------------------------------------
bool vtkDeepGIEGLRenderWindow::IsCurrent()
{
  vtkInternals* impl = this->Internals;
  this->CurrentStatus =
    impl && impl->Context != EGL_NO_CONTEXT && eglGetCurrentContext() == impl->Context;
  return this->CurrentStatus;
}

//------------------------------------------------------------------------------
int vtkDeepGIEGLRenderWindow::SupportsOpenGL()
{
  this->SupportsOpenGLStatus = (this->InitializeEGL() && GLEW_VERSION_3_2) ? 1 : 0;
  return this->SupportsOpenGLStatus;
}

//------------------------------------------------------------------------------
vtkTypeBool vtkDeepGIEGLRenderWindow::IsDirect()
{
  this->DirectStatus = this->HasContext() ? 1 : 0;
  return this->DirectStatus;
}

//------------------------------------------------------------------------------
void* vtkDeepGIEGLRenderWindow::GetGenericContext()
{
  return this->Internals ? this->Internals->Context : nullptr;
}

//------------------------------------------------------------------------------
void* vtkDeepGIEGLRenderWindow::GetGenericDisplayId()
{
  return this->Internals ? this->Internals->Display : nullptr;
}

//------------------------------------------------------------------------------
void* vtkDeepGIEGLRenderWindow::GetGenericDrawable()
{
  return this->Internals ? this->Internals->Surface : nullptr;
}

//------------------------------------------------------------------------------
void vtkDeepGIEGLRenderWindow::SetShowWindow(bool val)
{
  if (val)
  {
    vtkWarningMacro("vtkDeepGIEGLRenderWindow renders offscreen only; ShowWindow stays off");
  }
}

//------------------------------------------------------------------------------
void vtkDeepGIEGLRenderWindow::SetUseOffScreenBuffers(bool val)
{
  if (!val)
  {
    vtkWarningMacro("vtkDeepGIEGLRenderWindow always renders into offscreen buffers; "
                    "UseOffScreenBuffers stays on");
  }
}

//------------------------------------------------------------------------------
void vtkDeepGIEGLRenderWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Platform: "
     << (this->Platform == PLATFORM_DEVICE
            ? "DEVICE"
            : (this->Platform == PLATFORM_SURFACELESS ? "SURFACELESS" : "AUTO"))
     << "\n";
  os << indent << "DeviceIndex: " << this->DeviceIndex << "\n";
  os << indent << "HasContext: " << (this->HasContext() ? "yes" : "no") << "\n";
  os << indent << "PlatformDescription: " << this->PlatformDescription << "\n";
  os << indent << "ContextVersion: " << this->ContextMajorVersion << "."
     << this->ContextMinorVersion << "\n";
}
