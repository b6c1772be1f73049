// vtkDeepGIPass::Converge extrapolates the bounces still to come
// (ConvergeExtrapolatesBounces, vtkDeepRadiosityPass::ExtrapolateBounces)
// on the demo room at 160 x 120, BALANCED. The fixed point is the image
// after 40 frames without extrapolation.
// 1. The factor rho / (1 - rho): 0 in frames 1-3 (the series starts at
//    E = 0, and rho is measured over two frames and must agree with the
//    same measure one frame earlier), then within (0, 4] (rho, the decay
//    of the mean increment per frame, is about 0.4 in a room).
// 2. After 4 frames the image is at least 3 times closer to the fixed point
//    (mean absolute RGB difference) with extrapolation than without.
// 3. The fixed point is unchanged: after 40 frames with extrapolation the
//    image is within 1/255 of it everywhere.
// 4. Converge(16, 0.07/255) meets the tolerance in fewer frames with it.
// 5. Afterwards ExtrapolateBounces is off again. A Render() at the same
//    camera holds the converged image, extrapolating as Converge's frames
//    do; once the camera has moved a Render() (the temporal filter on)
//    extrapolates nothing.

#include "DeepRadiosityTest.h"

#include "vtkCamera.h"
#include "vtkDeepGIPass.h"

#include <vector>

using namespace DeepRadiosityTest;
using namespace DeepGITest;

namespace
{
constexpr int W = 160, H = 120;
constexpr int FixedPointFrames = 40;

struct Room
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkDeepGIPass> Pass;
  std::vector<double> Factors; // LastBounceExtrapolation after each frame
  vtkNew<vtkCallbackCommand> Progress;

  explicit Room(bool extrapolate)
  {
    this->Window = MakeWindow(W, H);
    this->Window->AddRenderer(this->Renderer);
    AddDemoScene(this->Renderer);
    this->Pass->SetConvergeExtrapolatesBounces(extrapolate);
    this->Renderer->SetPass(this->Pass);
    this->Progress->SetClientData(this);
    this->Progress->SetCallback(
      [](vtkObject*, unsigned long, void* data, void*)
      {
        auto* room = static_cast<Room*>(data);
        room->Factors.push_back(room->Pass->GetRadiosityPass()->GetLastBounceExtrapolation());
      });
    this->Pass->AddObserver(vtkCommand::ProgressEvent, this->Progress);
  }
  ~Room()
  {
    this->Renderer->SetPass(nullptr);
    this->Pass->ReleaseGraphicsResources(this->Window);
  }

  std::vector<double> Pixels()
  {
    vtkNew<vtkUnsignedCharArray> rgb;
    this->Window->GetPixelData(0, 0, W - 1, H - 1, /*front=*/0, rgb);
    return std::vector<double>(rgb->GetPointer(0), rgb->GetPointer(0) + rgb->GetNumberOfValues());
  }
};

struct Difference
{
  double Mean = 0.0;
  double Maximum = 0.0;
};

Difference Compare(const std::vector<double>& a, const std::vector<double>& b)
{
  Difference d;
  if (a.size() != b.size() || a.empty())
  {
    d.Mean = d.Maximum = 255.0;
    return d;
  }
  for (size_t i = 0; i < a.size(); ++i)
  {
    const double e = std::abs(a[i] - b[i]);
    d.Mean += e;
    d.Maximum = std::max(d.Maximum, e);
  }
  d.Mean /= static_cast<double>(a.size());
  return d;
}

std::vector<double> FixedPoint()
{
  Room room(false);
  room.Pass->Converge(room.Renderer, FixedPointFrames);
  return room.Pixels();
}

void CheckFactorsAndEarlyImage(const std::vector<double>& fixedPoint)
{
  Room plain(false);
  plain.Pass->Converge(plain.Renderer, 4);
  const Difference without = Compare(plain.Pixels(), fixedPoint);
  Room room(true);
  room.Pass->Converge(room.Renderer, 4);
  const Difference with = Compare(room.Pixels(), fixedPoint);
  std::string factors;
  for (double f : room.Factors)
  {
    factors += Format(" %.3f", f);
  }
  std::printf("factors per frame:%s\n", factors.c_str());
  std::printf("after 4 frames, from the fixed point: %.4f/255 mean (max %.0f) without, %.4f/255 "
              "(max %.0f) with extrapolation\n",
    without.Mean, without.Maximum, with.Mean, with.Maximum);
  bool inRange = room.Factors.size() == 4 && room.Factors[0] == 0.0 && room.Factors[1] == 0.0 &&
    room.Factors[2] == 0.0;
  for (size_t k = 3; inRange && k < room.Factors.size(); ++k)
  {
    inRange = room.Factors[k] > 0.0 && room.Factors[k] <= 4.0;
  }
  Check(inRange, "the factor is 0 in frames 1-3, then within (0, 4]");
  for (double f : plain.Factors)
  {
    inRange = inRange && f == 0.0;
  }
  Check(inRange, "off: no frame extrapolates");
  Check(with.Mean > 0.0 && 3.0 * with.Mean <= without.Mean,
    "after 4 frames the image is at least 3 times closer to the fixed point");

  Check(!room.Pass->GetRadiosityPass()->GetExtrapolateBounces(),
    "after Converge ExtrapolateBounces is off again");
  room.Window->Render();
  Check(room.Pass->GetRadiosityPass()->GetLastBounceExtrapolation() > 0.0,
    "a frame at Converge's camera holds its image, extrapolated");
  room.Renderer->GetActiveCamera()->Azimuth(1.0);
  room.Window->Render();
  Check(room.Pass->GetRadiosityPass()->GetLastBounceExtrapolation() == 0.0,
    "after the camera moved the radiosity extrapolates nothing");
}

void CheckFixedPoint(const std::vector<double>& fixedPoint)
{
  Room room(true);
  room.Pass->Converge(room.Renderer, FixedPointFrames);
  const Difference d = Compare(room.Pixels(), fixedPoint);
  std::printf("after %d frames with extrapolation, from the fixed point: %.4f/255 mean, max %.0f\n",
    FixedPointFrames, d.Mean, d.Maximum);
  Check(d.Maximum <= 1.0, "the fixed point is unchanged (within 1/255)");
}

void CheckTolerance()
{
  int frames[2] = { 0, 0 };
  for (int extrapolate = 0; extrapolate < 2; ++extrapolate)
  {
    Room room(extrapolate != 0);
    frames[extrapolate] = room.Pass->Converge(room.Renderer, 16, 0.07 / 255.0);
    Check(room.Pass->GetLastConvergenceReached(),
      Text(extrapolate ? "with" : "without", " extrapolation the tolerance is met"));
  }
  std::printf(
    "Converge(16, 0.07/255): %d frames without, %d with extrapolation\n", frames[0], frames[1]);
  Check(frames[1] < frames[0], "with extrapolation the tolerance is met in fewer frames");
}
}

int TestDeepGIConvergeExtrapolation(int, char*[])
{
  const std::vector<double> fixedPoint = FixedPoint();
  CheckFactorsAndEarlyImage(fixedPoint);
  CheckFixedPoint(fixedPoint);
  CheckTolerance();
  return ExitStatus();
}
