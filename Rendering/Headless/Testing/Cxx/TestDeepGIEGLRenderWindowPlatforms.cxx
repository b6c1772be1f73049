// Every EGL platform choice this machine offers, without an X display: Mesa's
// surfaceless platform, the device platform with automatic device choice, and
// each enumerated EGL device by index. Each renders the test scene and is
// checked numerically. Choices the machine lacks are reported and skipped;
// at least one must work.
#include "vtkDeepGIEGLRenderWindow.h"

#include "DeepGIHeadlessTestHelpers.h"

int TestDeepGIEGLRenderWindowPlatforms(int, char*[])
{
  using namespace deepgi_headless_test;
  using namespace DeepGITest;
  using W = vtkDeepGIEGLRenderWindow;
  if (!RequireNoDisplay("TestDeepGIEGLRenderWindowPlatforms"))
  {
    return EXIT_FAILURE;
  }
  ScopedMessageCounter messages;
  int rendered = 0;

  struct Choice
  {
    int Platform;
    int Device;
    std::string Label;
  };
  std::vector<Choice> choices = { { W::PLATFORM_AUTO, -1, "auto" },
    { W::PLATFORM_SURFACELESS, -1, "surfaceless" }, { W::PLATFORM_DEVICE, -1, "device auto" } };
  vtkNew<W> probe;
  const int devices = probe->GetNumberOfDevices();
  std::printf("%d EGL device(s)\n", devices);
  for (int i = 0; i < devices; ++i)
  {
    choices.push_back({ W::PLATFORM_DEVICE, i, "device " + std::to_string(i) });
  }

  for (const Choice& c : choices)
  {
    if (c.Device < 0 && !W::IsEGLAvailable(c.Platform))
    {
      std::printf("%s: not available here, skipped\n", c.Label.c_str());
      continue;
    }
    vtkNew<W> rw;
    rw->SetPlatform(c.Platform);
    rw->SetDeviceIndex(c.Device);
    SetUpWindow(rw);
    RenderAndCheck(rw, c.Label.c_str());
    std::printf("%s: %s, OpenGL %d.%d\n", c.Label.c_str(), rw->GetPlatformDescription(),
      rw->GetContextMajorVersion(), rw->GetContextMinorVersion());
    ++rendered;
  }
  Check(rendered > 0, Format("%d EGL platform(s) rendered (at least one)", rendered));
  messages.CheckNone();
  return ExitStatus();
}
