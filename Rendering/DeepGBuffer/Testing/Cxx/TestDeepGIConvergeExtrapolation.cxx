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
// 5. After interactive frames at the camera (the temporal filter on), as
//    when Converge starts where a user's camera stopped, the radiosity is
//    nearly converged: no frame starts extrapolating once the image's
//    change c_k times the larger of c_k / c_k-1 and c_k-1 / c_k-2 is
//    within the tolerance (the next frame is expected to meet it), and the
//    tolerance is met in no more frames than without extrapolation.
// 6. Afterwards ExtrapolateBounces is off again. A Render() at the same
//    camera holds the converged image, extrapolating as Converge's frames
//    do; once the camera has moved a Render() (the temporal filter on)
//    extrapolates nothing.

#include "DeepRadiosityTest.h"

#include "vtkCamera.h"
#include "vtkDeepGIPass.h"

#include <memory>
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
  std::vector<double> Changes; // LastConvergenceChange after each frame
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
        room->Changes.push_back(room->Pass->GetLastConvergenceChange());
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

// Converge(16, 0.07/255) after `interactiveFrames` Render() at the camera.
Room* ConvergeAfterInteraction(bool extrapolate, int interactiveFrames, int& frames)
{
  auto* room = new Room(extrapolate);
  for (int k = 0; k < interactiveFrames; ++k)
  {
    room->Window->Render();
  }
  room->Factors.clear();
  room->Changes.clear();
  frames = room->Pass->Converge(room->Renderer, 16, 0.07 / 255.0);
  return room;
}

void CheckAfterInteraction()
{
  // 24-28 frames: the radiosity would start extrapolating in frame 5,
  // which then needs frame 6, where frame 5 meets the tolerance without.
  constexpr int InteractiveFrames = 26;
  constexpr double Tolerance = 0.07 / 255.0;
  int frames[2] = { 0, 0 };
  std::unique_ptr<Room> without(ConvergeAfterInteraction(false, InteractiveFrames, frames[0]));
  std::unique_ptr<Room> with(ConvergeAfterInteraction(true, InteractiveFrames, frames[1]));
  std::string sequence;
  bool held = true;
  int holds = 0;
  const std::vector<double>& c = with->Changes;
  for (size_t k = 0; k < c.size(); ++k)
  {
    sequence += Format(" %.3f (%.2f)", 255.0 * c[k], with->Factors[k]);
    if (k >= 2 && k + 1 < c.size() && c[k - 2] > 0.0 && c[k - 1] > 0.0 && with->Factors[k] == 0.0 &&
      c[k] * std::max(c[k] / c[k - 1], c[k - 1] / c[k - 2]) <= Tolerance)
    {
      ++holds;
      held = held && with->Factors[k + 1] == 0.0;
    }
  }
  std::printf("after %d interactive frames, changes/255 (factors):%s; %d frames without, %d with "
              "extrapolation\n",
    InteractiveFrames, sequence.c_str(), frames[0], frames[1]);
  Check(holds > 0 && held,
    "no frame starts extrapolating once the next frame is expected to meet the tolerance");
  Check(with->Pass->GetLastConvergenceReached() && frames[1] <= frames[0],
    "after interaction the tolerance is met in no more frames with extrapolation");
}
}

int TestDeepGIConvergeExtrapolation(int, char*[])
{
  const std::vector<double> fixedPoint = FixedPoint();
  CheckFactorsAndEarlyImage(fixedPoint);
  CheckFixedPoint(fixedPoint);
  CheckTolerance();
  CheckAfterInteraction();
  return ExitStatus();
}
