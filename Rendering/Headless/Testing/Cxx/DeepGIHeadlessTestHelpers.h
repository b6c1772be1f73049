// Shared helpers of the headless-window tests: a scene whose image is known
// exactly, numeric checks of that image, GL error checks and a counter of
// VTK errors and warnings, all reported through DeepGITestChecks.h.
#ifndef DeepGIHeadlessTestHelpers_h
#define DeepGIHeadlessTestHelpers_h

#include "DeepGITestChecks.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOutputWindow.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"
#include "vtk_glew.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace deepgi_headless_test
{
// Colours chosen so that c * 255 is an integer: the 8-bit framebuffer holds
// them exactly (background 0.2/0.4/0.6 -> 51/102/153, sphere 1.0/0.6/0.2 ->
// 255/153/51).
constexpr double Background[3] = { 0.2, 0.4, 0.6 };
constexpr double SphereColor[3] = { 1.0, 0.6, 0.2 };
constexpr int Size = 200;
// Parallel projection with ParallelScale 1: the window spans 2 world units,
// so the sphere (radius 0.5) covers a disc of 50 px radius at the centre.
constexpr double DiscRadiusPx = 0.25 * Size;

// Counts VTK errors and warnings while installed, and still prints them.
class CountingOutputWindow : public vtkOutputWindow
{
public:
  static CountingOutputWindow* New()
  {
    auto* instance = new CountingOutputWindow;
    instance->InitializeObjectBase();
    return instance;
  }
  vtkTypeMacro(CountingOutputWindow, vtkOutputWindow);
  void DisplayErrorText(const char* t) override
  {
    ++this->Errors;
    if (this->Quiet)
    {
      // An error the test provokes on purpose: echo it without the words
      // that ctest's failure regex looks for.
      std::string text(t);
      for (std::string::size_type p = text.find("ERROR"); p != std::string::npos;
           p = text.find("ERROR", p))
      {
        text.replace(p, 5, "expected error");
      }
      std::printf("%s", text.c_str());
      return;
    }
    this->Superclass::DisplayErrorText(t);
  }
  void DisplayWarningText(const char* t) override
  {
    ++this->Warnings;
    this->Superclass::DisplayWarningText(t);
  }
  void DisplayGenericWarningText(const char* t) override
  {
    ++this->Warnings;
    this->Superclass::DisplayGenericWarningText(t);
  }
  int Errors = 0;
  int Warnings = 0;
  bool Quiet = false;
};

// Installs a CountingOutputWindow for the scope of the object.
// With expectErrors, errors are counted and echoed but not logged as
// errors (vtkLogger's stderr output is turned off meanwhile).
class ScopedMessageCounter
{
public:
  explicit ScopedMessageCounter(bool expectErrors = false)
  {
    this->Previous = vtkOutputWindow::GetInstance();
    this->Previous->Register(nullptr);
    vtkOutputWindow::SetInstance(this->Counter);
    this->Counter->Quiet = expectErrors;
    if (expectErrors)
    {
      // 9.1 has no getter for the stderr level alone; with no log file the
      // cutoff is that level.
      this->PreviousStderr = vtkLogger::GetCurrentVerbosityCutoff();
      vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
    }
    this->Quiet = expectErrors;
  }
  ~ScopedMessageCounter()
  {
    if (this->Quiet)
    {
      vtkLogger::SetStderrVerbosity(static_cast<vtkLogger::Verbosity>(this->PreviousStderr));
    }
    vtkOutputWindow::SetInstance(this->Previous);
    this->Previous->UnRegister(nullptr);
  }
  int Errors() const { return this->Counter->Errors; }
  // Checks that VTK printed no error and no warning while installed.
  void CheckNone() const
  {
    DeepGITest::Check(this->Errors() == 0 && this->Warnings() == 0,
      DeepGITest::Format(
        "VTK reported %d error(s) and %d warning(s)", this->Errors(), this->Warnings()));
  }
  int Warnings() const { return this->Counter->Warnings; }
  void Reset()
  {
    this->Counter->Errors = 0;
    this->Counter->Warnings = 0;
  }

private:
  vtkNew<CountingOutputWindow> Counter;
  vtkOutputWindow* Previous;
  int PreviousStderr = 0;
  bool Quiet = false;
};

// A renderer with the test scene: an unlit sphere of flat colour.
inline vtkSmartPointer<vtkRenderer> MakeSphereRenderer()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(0.5);
  sphere->SetThetaResolution(96);
  sphere->SetPhiResolution(48);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(SphereColor[0], SphereColor[1], SphereColor[2]);
  actor->GetProperty()->LightingOff();

  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->AddActor(actor);
  renderer->SetBackground(Background[0], Background[1], Background[2]);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetPosition(0, 0, 5);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetParallelScale(1.0);
  camera->SetClippingRange(1.0, 10.0);
  return renderer;
}

// Puts the scene in `rw` at the test size, without MSAA.
inline void SetUpWindow(vtkRenderWindow* rw)
{
  rw->SetSize(Size, Size);
  rw->SetMultiSamples(0);
  rw->AddRenderer(MakeSphereRenderer());
}

// Drains and reports pending GL errors of the window's context.
inline int CountGLErrors(vtkRenderWindow* rw, const char* when)
{
  rw->MakeCurrent();
  int count = 0;
  for (GLenum e = glGetError(); e != GL_NO_ERROR && count < 32; e = glGetError())
  {
    std::fprintf(stderr, "GL error 0x%04x %s\n", static_cast<unsigned>(e), when);
    ++count;
  }
  return count;
}

// Checks that the window's context has no pending GL error.
inline void CheckNoGLErrors(vtkRenderWindow* rw, const char* when)
{
  const int errors = CountGLErrors(rw, when);
  DeepGITest::Check(errors == 0, DeepGITest::Format("%s: no GL error (%d)", when, errors));
}

inline bool Near(const unsigned char* p, const double c[3], int tol)
{
  for (int i = 0; i < 3; ++i)
  {
    int expected = static_cast<int>(std::lround(c[i] * 255.0));
    if (std::abs(static_cast<int>(p[i]) - expected) > tol)
    {
      return false;
    }
  }
  return true;
}

// Checks the rendered image pixel by pixel: sphere colour well inside the
// disc, background well outside, and a disc area within 2% of pi r^2 (the
// tessellated sphere's silhouette is a 96-gon, slightly smaller). The first
// few wrong pixels are printed.
inline void CheckSphereImage(vtkRenderWindow* rw, const char* label)
{
  using DeepGITest::Check;
  using DeepGITest::Format;
  vtkNew<vtkUnsignedCharArray> pixels;
  if (!Check(rw->GetPixelData(0, 0, Size - 1, Size - 1, 1, pixels) == 1 ||
          pixels->GetNumberOfValues() != 0,
        Format("%s: GetPixelData", label)))
  {
    return;
  }
  if (!Check(pixels->GetNumberOfValues() == 3 * Size * Size,
        Format("%s: %lld pixel bytes (%d)", label,
          static_cast<long long>(pixels->GetNumberOfValues()), 3 * Size * Size)))
  {
    return;
  }
  const unsigned char* data = pixels->GetPointer(0);
  int wrongPixels = 0;
  int sphereCount = 0;
  const double centre = 0.5 * (Size - 1);
  for (int y = 0; y < Size; ++y)
  {
    for (int x = 0; x < Size; ++x)
    {
      const unsigned char* p = data + 3 * (y * Size + x);
      const double r = std::hypot(x - centre, y - centre);
      const bool isSphere = Near(p, SphereColor, 2);
      const bool isBackground = Near(p, Background, 2);
      sphereCount += isSphere ? 1 : 0;
      const char* problem = nullptr;
      if (r < DiscRadiusPx - 3 && !isSphere)
      {
        problem = "expected sphere colour";
      }
      else if (r > DiscRadiusPx + 2 && !isBackground)
      {
        problem = "expected background";
      }
      else if (!isSphere && !isBackground)
      {
        problem = "neither sphere nor background (no MSAA, so no blending)";
      }
      if (problem)
      {
        if (wrongPixels < 5)
        {
          std::fprintf(
            stderr, "%s: pixel (%d,%d) = (%d,%d,%d): %s\n", label, x, y, p[0], p[1], p[2], problem);
        }
        ++wrongPixels;
      }
    }
  }
  Check(wrongPixels == 0,
    Format("%s: sphere colour inside the disc, background outside, nothing else "
           "(%d pixels wrong)",
      label, wrongPixels));
  const double expectedArea = M_PI * DiscRadiusPx * DiscRadiusPx;
  Check(std::fabs(sphereCount - expectedArea) <= 0.02 * expectedArea,
    Format(
      "%s: the sphere covers %d pixels, pi r^2 = %.0f +- 2%%", label, sphereCount, expectedArea));
}

// Renders and checks the image and the GL error state.
inline void RenderAndCheck(vtkRenderWindow* rw, const char* label)
{
  rw->Render();
  CheckNoGLErrors(rw, label);
  CheckSphereImage(rw, label);
}

// Fails when DISPLAY is set: these tests must prove that EGL needs no X.
inline bool RequireNoDisplay(const char* test)
{
  const char* display = std::getenv("DISPLAY");
  if (display && *display)
  {
    std::fprintf(stderr,
      "%s must run without an X display, but DISPLAY=%s (ctest sets DISPLAY= for it)\n", test,
      display);
    return false;
  }
  return true;
}
} // namespace deepgi_headless_test

#endif
