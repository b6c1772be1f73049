// The hooks of distributed rendering, on one process (the exchanges here are
// the test's own; the MPI one is tested by the ParaView plugin's 1, 2 and 4
// rank tests):
// 1. vtkDeepGIPass with an exchange that returns the layers unchanged: it
//    is called once per layer and frame with the layers' pixels (frame plus
//    guard band) and 30 bytes per pixel (the quantities as read back:
//    RADIANCE 8, ALBEDO 4, NORMAL 2, DEPTH 4, AMBIENT 12), with depths in
//    [0, 1]; the G-buffer's oracle is DEPTH_PEEL; the captured layers and
//    the image equal exactly those of the same pass without an exchange
//    and with the DEPTH_PEEL oracle (reading back and uploading are
//    lossless).
// 2. A renderer without props still calls it once per layer (the processes
//    call it together).
// 3. An exchange that empties layer 0 (as if another process's nearest
//    surface were beyond the far plane everywhere) leaves no valid texel in
//    the captured layer 0: the layers hold what the exchange returns.
// 4. vtkDeepGIKeys::SCENE_BOUNDS on the renderer: bounds with three times
//    the visible props' diagonal triple the obscurance and radiosity radii
//    and the G-buffer's minimum separation; without the key they are back.

#include "DeepRadiosityTest.h"

#include "vtkDeepAmbientObscurancePass.h"
#include "vtkDeepGBufferLayerExchange.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIKeys.h"
#include "vtkDeepGIPass.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace DeepRadiosityTest;
using namespace DeepGITest;

namespace
{
constexpr int W = 80, H = 60;

// Records the calls; optionally empties layer 0.
class RecordingExchange : public vtkDeepGBufferLayerExchange
{
public:
  static RecordingExchange* New();
  vtkTypeMacro(RecordingExchange, vtkDeepGBufferLayerExchange);
  bool CompositeLayer(vtkIdType pixels, std::vector<float>& depth,
    std::vector<unsigned char>& attributes, int bytesPerPixel) override
  {
    const bool sizes = static_cast<vtkIdType>(depth.size()) == pixels &&
      static_cast<vtkIdType>(attributes.size()) == pixels * bytesPerPixel;
    this->SizesConsistent = this->SizesConsistent && sizes;
    this->DepthsInRange = this->DepthsInRange &&
      std::all_of(depth.begin(), depth.end(), [](float d) { return d >= 0.0f && d <= 1.0f; });
    this->Pixels = pixels;
    this->BytesPerPixel = bytesPerPixel;
    if (this->EmptyLayerZero && this->Calls % 2 == 0)
    {
      std::fill(depth.begin(), depth.end(), 1.0f);
      std::fill(attributes.begin(), attributes.end(), 0);
    }
    ++this->Calls;
    return true;
  }
  int Calls = 0;
  vtkIdType Pixels = 0;
  int BytesPerPixel = 0;
  bool SizesConsistent = true;
  bool DepthsInRange = true;
  bool EmptyLayerZero = false;
};
vtkStandardNewMacro(RecordingExchange);

struct Frame
{
  vtkNew<vtkImageData> Layers;
  vtkNew<vtkImageData> Colour;
  vtkNew<vtkImageData> Depth;
};

// One frame of `gi` on the red-wall scene in `window`, captured.
void RenderOnce(vtkRenderWindow* window, vtkRenderer* renderer, vtkDeepGIPass* gi, Frame& frame)
{
  gi->SetAdaptiveLayers(false);
  renderer->SetPass(gi);
  window->Render();
  gi->GetGBufferPass()->CaptureLayers(frame.Layers, renderer);
  ReadWindow(window, frame.Colour, frame.Depth);
  renderer->SetPass(nullptr);
  gi->ReleaseGraphicsResources(window);
}

void CheckIdentityExchange(vtkRenderWindow* window, vtkRenderer* renderer)
{
  Frame plain, exchanged;
  vtkNew<vtkDeepGIPass> reference;
  reference->GetGBufferPass()->SetOracle(vtkDeepGBufferPass::DEPTH_PEEL);
  RenderOnce(window, renderer, reference, plain);

  vtkNew<vtkDeepGIPass> gi;
  vtkNew<RecordingExchange> exchange;
  gi->GetGBufferPass()->SetLayerExchange(exchange);
  RenderOnce(window, renderer, gi, exchanged);
  // One more frame, counted alone (capturing the window above rendered too).
  renderer->SetPass(gi);
  exchange->Calls = 0;
  window->Render();
  const int guard = gi->GetGBufferPass()->GetEffectiveGuardBand();
  const vtkIdType pixels = static_cast<vtkIdType>(W + 2 * guard) * (H + 2 * guard);
  std::printf("identity exchange: %d calls in a frame, %lld pixels (%lld expected), %d bytes per "
              "pixel\n",
    exchange->Calls, static_cast<long long>(exchange->Pixels), static_cast<long long>(pixels),
    exchange->BytesPerPixel);
  Check(exchange->Calls == 2 && exchange->Pixels == pixels && exchange->BytesPerPixel == 30 &&
      exchange->SizesConsistent && exchange->DepthsInRange,
    "an exchange is called once per layer and frame with the layers' pixels and 30 bytes per "
    "pixel");
  Check(gi->GetGBufferPass()->GetEffectiveOracle() == vtkDeepGBufferPass::DEPTH_PEEL,
    "with an exchange the oracle is DEPTH_PEEL");
  Check(SameArrays(plain.Layers, exchanged.Layers),
    "an exchange that changes nothing: the captured layers are exactly those without it");
  Check(SameArrays(plain.Colour, exchanged.Colour),
    "an exchange that changes nothing: the image is exactly the one without it");
  renderer->SetPass(nullptr);
  gi->ReleaseGraphicsResources(window);
}

void CheckEmptyRenderer(vtkRenderWindow* window)
{
  vtkNew<vtkRenderer> empty;
  window->AddRenderer(empty);
  // The scene's renderer draws without the pass meanwhile.
  vtkNew<vtkDeepGIPass> gi;
  vtkNew<RecordingExchange> exchange;
  gi->GetGBufferPass()->SetLayerExchange(exchange);
  gi->SetAdaptiveLayers(false);
  empty->SetPass(gi);
  window->Render();
  std::printf("no props: %d calls\n", exchange->Calls);
  Check(exchange->Calls == 2, "a renderer without props still exchanges both layers");
  empty->SetPass(nullptr);
  gi->ReleaseGraphicsResources(window);
  window->RemoveRenderer(empty);
}

void CheckEmptiedLayer(vtkRenderWindow* window, vtkRenderer* renderer)
{
  Frame frame;
  vtkNew<vtkDeepGIPass> gi;
  vtkNew<RecordingExchange> exchange;
  exchange->EmptyLayerZero = true;
  gi->GetGBufferPass()->SetLayerExchange(exchange);
  RenderOnce(window, renderer, gi, frame);
  vtkDataArray* valid = Layer(frame.Layers, vtkDeepGICaptureNames::Valid, 0);
  double validTexels = 0.0;
  for (vtkIdType p = 0; valid && p < valid->GetNumberOfTuples(); ++p)
  {
    validTexels += valid->GetTuple1(p);
  }
  std::printf("layer 0 emptied by the exchange: %g valid texels\n", validTexels);
  Check(valid && validTexels == 0.0, "the layers hold what the exchange returns");
}

void CheckSceneBounds(vtkRenderWindow* window, vtkRenderer* renderer)
{
  vtkNew<vtkDeepGIPass> gi;
  gi->SetAdaptiveLayers(false);
  renderer->SetPass(gi);
  auto lengths = [&](double out[3])
  {
    window->Render();
    out[0] = gi->GetAmbientObscurancePass()->GetEffectiveRadius();
    out[1] = gi->GetRadiosityPass()->GetEffectiveRadius();
    out[2] = gi->GetGBufferPass()->GetEffectiveMinimumSeparation();
  };
  double own[3], scaled[3], again[3];
  lengths(own);
  double bounds[6];
  renderer->ComputeVisiblePropBounds(bounds);
  for (int a = 0; a < 3; ++a)
  {
    const double centre = 0.5 * (bounds[2 * a] + bounds[2 * a + 1]);
    const double half = 0.5 * (bounds[2 * a + 1] - bounds[2 * a]);
    bounds[2 * a] = centre - 3.0 * half;
    bounds[2 * a + 1] = centre + 3.0 * half;
  }
  renderer->GetInformation()->Set(vtkDeepGIKeys::SCENE_BOUNDS(), bounds, 6);
  lengths(scaled);
  renderer->GetInformation()->Remove(vtkDeepGIKeys::SCENE_BOUNDS());
  lengths(again);
  bool tripled = true, restored = true;
  for (int i = 0; i < 3; ++i)
  {
    std::printf(
      "length %d: %g, with SCENE_BOUNDS %g, without again %g\n", i, own[i], scaled[i], again[i]);
    tripled = tripled && own[i] > 0.0 && std::abs(scaled[i] - 3.0 * own[i]) <= 1e-9 * own[i];
    restored = restored && again[i] == own[i];
  }
  Check(tripled, "SCENE_BOUNDS of three times the diagonal triple every automatic length");
  Check(restored, "without SCENE_BOUNDS the visible props set the lengths again");
  renderer->SetPass(nullptr);
  gi->ReleaseGraphicsResources(window);
}
}

int TestDeepGBufferLayerExchange(int, char*[])
{
  vtkSmartPointer<vtkRenderWindow> window = MakeWindow(W, H);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  RedWallScene(renderer);
  CheckIdentityExchange(window, renderer);
  CheckEmptyRenderer(window);
  CheckEmptiedLayer(window, renderer);
  CheckSceneBounds(window, renderer);
  return ExitStatus();
}
