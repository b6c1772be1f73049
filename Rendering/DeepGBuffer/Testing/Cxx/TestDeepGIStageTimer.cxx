// The profiling aids of the passes: vtkDeepGIStageTimer and GetTextureBytes.
// 1. The timer alone: nested stages are exclusive (a stage's time excludes
//    the stages it contains), counts and the order of first runs are kept,
//    StopStage without a stage does nothing, Reset forgets.
// 2. Attached to vtkDeepGIPass's G-buffer, three frames with obscurance and
//    radiosity time every stage three times (the layers, the obscurance
//    gather, blur and composite, the radiosity bounce input, gather, blur and
//    temporal filter), and the stages' total lies within the frames' time.
// 3. Detached, no stage is timed.
// 4. GetTextureBytes: the G-buffer's layers are 26 bytes per texel per layer
//    (Table 1's quantities, the depth buffer) plus the oracle's 4-byte
//    history; the GI pass holds the sum of its passes; 0 after
//    ReleaseGraphicsResources, and the same rule after a new frame (whose
//    layer count the adaptive layers may have changed).

#include "DeepRadiosityTest.h"

#include "vtkDeepAmbientObscurancePass.h"
#include "vtkDeepGIPass.h"
#include "vtkDeepGIStageTimer.h"
#include "vtkDeepReflectionPass.h"

#include <chrono>
#include <cstring>
#include <thread>

using namespace DeepRadiosityTest;
using namespace DeepGITest;

namespace
{
constexpr int W = 96, H = 72;

int StageIndex(vtkDeepGIStageTimer* timer, const char* name)
{
  for (int i = 0; i < timer->GetNumberOfStages(); ++i)
  {
    if (std::strcmp(timer->GetStageName(i), name) == 0)
    {
      return i;
    }
  }
  return -1;
}

void Sleep(int milliseconds)
{
  std::this_thread::sleep_for(std::chrono::milliseconds(milliseconds));
}

void CheckTimerAlone()
{
  vtkNew<vtkDeepGIStageTimer> timer;
  timer->StopStage(); // nothing runs: no effect
  const auto start = std::chrono::steady_clock::now();
  timer->StartStage("outer");
  Sleep(30);
  timer->StartStage("inner");
  Sleep(60);
  timer->StopStage();
  Sleep(30);
  timer->StopStage();
  timer->StartStage("inner");
  timer->StopStage();
  const double elapsed =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const double outer = timer->GetStageMilliseconds(0), inner = timer->GetStageMilliseconds(1);
  std::printf("timer alone: outer %.1f ms (60 slept), inner %.1f ms (60 slept), %.1f ms in all\n",
    outer, inner, elapsed);
  Check(timer->GetNumberOfStages() == 2 && std::strcmp(timer->GetStageName(0), "outer") == 0 &&
      std::strcmp(timer->GetStageName(1), "inner") == 0 && timer->GetStageCount(0) == 1 &&
      timer->GetStageCount(1) == 2,
    "timer alone: stages, their order and counts");
  // Sleeping lasts at least as long as asked, and exclusive times add up to
  // at most the time of the whole sequence (the inner stage counted in the
  // outer one too would exceed it by 60 ms); no upper bound on a sleep.
  Check(outer >= 59.0 && inner >= 59.0 && outer + inner <= elapsed,
    "timer alone: nested times are exclusive");
  Check(timer->GetStageName(2) == nullptr && timer->GetStageMilliseconds(-1) == 0.0 &&
      std::abs(timer->GetTotalMilliseconds() - outer - inner) <= 1e-9,
    "timer alone: out-of-range stages are empty, the total is the sum");
  timer->Reset();
  Check(timer->GetNumberOfStages() == 0, "timer alone: Reset removes the stages");
}

void CheckPassStages(vtkRenderWindow* window, vtkDeepGIPass* gi)
{
  vtkNew<vtkDeepGIStageTimer> timer;
  gi->GetGBufferPass()->SetStageTimer(timer);
  const int frames = 3;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < frames; ++i)
  {
    window->Render();
  }
  window->WaitForCompletion();
  const double elapsed =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  gi->GetGBufferPass()->SetStageTimer(nullptr);
  for (int i = 0; i < timer->GetNumberOfStages(); ++i)
  {
    std::printf("  %-28s %8.2f ms in %d runs\n", timer->GetStageName(i),
      timer->GetStageMilliseconds(i), timer->GetStageCount(i));
  }
  const char* expected[] = { "G-buffer: layers", "G-buffer: resolve", "obscurance: gather",
    "obscurance: blur", "radiosity: bounce input", "radiosity: gather", "radiosity: blur",
    "radiosity: temporal", "GI: composite" };
  for (const char* name : expected)
  {
    const int i = StageIndex(timer, name);
    Check(i >= 0 && timer->GetStageCount(i) == frames && timer->GetStageMilliseconds(i) > 0.0,
      Format("stage '%s' timed in each of %d frames", name, frames));
  }
  Check(timer->GetTotalMilliseconds() <= elapsed,
    Format("stages total %.1f ms <= frames %.1f ms", timer->GetTotalMilliseconds(), elapsed));
  timer->Reset();
  window->Render();
  Check(timer->GetNumberOfStages() == 0, "a detached timer times no stage");
}

// The G-buffer's bytes for its last frame's layers, and whether the GI
// pass reports the sum of its passes.
void CheckBytesOfFrame(vtkDeepGIPass* gi, const char* when)
{
  vtkDeepGBufferPass* gbuffer = gi->GetGBufferPass();
  const vtkTypeInt64 layers = gbuffer->GetEffectiveNumberOfLayers();
  const vtkTypeInt64 side = 2 * gbuffer->GetEffectiveGuardBand();
  const vtkTypeInt64 texels = (W + side) * (H + side);
  const vtkTypeInt64 expected = texels * (26 * layers + 4 * std::max<vtkTypeInt64>(1, layers - 1));
  const vtkTypeInt64 sum = gbuffer->GetTextureBytes() +
    gi->GetAmbientObscurancePass()->GetTextureBytes() + gi->GetRadiosityPass()->GetTextureBytes() +
    gi->GetReflectionPass()->GetTextureBytes();
  std::printf("%s: %lld layers, G-buffer %lld bytes (%lld expected), GI %lld bytes\n", when,
    static_cast<long long>(layers), static_cast<long long>(gbuffer->GetTextureBytes()),
    static_cast<long long>(expected), static_cast<long long>(gi->GetTextureBytes()));
  Check(gbuffer->GetTextureBytes() == expected && gi->GetTextureBytes() == sum &&
      gi->GetRadiosityPass()->GetTextureBytes() > 0 &&
      gi->GetAmbientObscurancePass()->GetTextureBytes() > 0,
    Format("texture bytes %s: the G-buffer's as expected, GI's the sum of its passes", when));
}

void CheckTextureBytes(vtkRenderWindow* window, vtkDeepGIPass* gi)
{
  CheckBytesOfFrame(gi, "rendered");
  gi->ReleaseGraphicsResources(window);
  Check(gi->GetTextureBytes() == 0,
    Format("%lld bytes after ReleaseGraphicsResources (0)",
      static_cast<long long>(gi->GetTextureBytes())));
  window->Render();
  CheckBytesOfFrame(gi, "released and rendered again");
}
}

int TestDeepGIStageTimer(int, char*[])
{
  CheckTimerAlone();
  vtkSmartPointer<vtkRenderWindow> window = MakeWindow(W, H);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  RedWallScene(renderer);
  vtkNew<vtkDeepGIPass> gi;
  gi->GetAmbientObscurancePass()->SetComposition(vtkDeepAmbientObscurancePass::COMPOSITE_MULTIPLY);
  renderer->SetPass(gi);
  window->Render();
  CheckPassStages(window, gi);
  CheckTextureBytes(window, gi);
  gi->ReleaseGraphicsResources(window);
  return ExitStatus();
}
