// Regression image of vtkDeepRadiosityPass on the original Cornell box
// (Testing/Data/scenes/cornell-original) as vtkDeepGISceneLoader
// populates it: the lamp quad (MTL Ke 17 12 4) drawn EMISSIVE with colour
// Ke / max(Ke), and lit by the spot light AddEmitterLight puts on it.
// BALANCED preset, TemporalAlpha 0 so the progressive bounces converge in
// 20 frames, radius 0.3 of the scene diagonal, the lamp's light at an
// exposure of 4. One 512 x 256 window: left the composite RADIANCE + L_ind,
// right L_ind of layer 0 (x 4, clamped, nearest-neighbour) so the indirect
// light is part of the baseline independently of the direct light.
// Threshold 0.5, as for the other radiosity image: VTK's metric sums
// per-pixel excesses over 105 of 255.
// Numeric checks (measured values in brackets, with the default estimator
// SOLID_ANGLE; see radiosity.md):
// - every captured value finite, L_ind >= 0;
// - the lamp's direct radiance RADIANCE - AMBIENT is Ke / max(Ke)
//   = (1, 0.706, 0.235) (EMISSIVE: its ambient term is emission);
// - the ceiling beside the lamp (1 cm above it, so behind the spot light)
//   gets no direct light but L_ind > 0;
// - colour bleeding: over both layers, the box faces that look at the red
//   wall (camera-space normal x < -0.7; the camera looks down -z, so that is
//   the world normal) have a red / green ratio of L_ind above 4 (6.84), the
//   faces that look at the green wall below 1 (0.757);
// - regression ranges (+-20 % of the measured means): L_ind on the ceiling
//   (0.0796, 0.0421, 0.0083), over every surface pixel of both layers
//   (0.1080, 0.0582, 0.0125): 1.6-1.7 times what the gather gets without
//   its outer ring (OuterSamples 0), light the ray-traced reference has
//   (Documentation/radiosity.md).

#include "DeepGITestData.h"
#include "DeepRadiosityTest.h"

#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGISceneLoader.h"
#include "vtkImageActor.h"
#include "vtkImageProperty.h"
#include "vtkLightCollection.h"
#include "vtkRegressionTestImage.h"

#include <algorithm>

using namespace DeepRadiosityTest;
using namespace DeepGITest;

namespace
{
struct Region
{
  long Pixels = 0;
  double Sum[3] = { 0, 0, 0 };
  double Largest = 0.0;
  void Add(const double v[3], double largest = 0.0)
  {
    ++this->Pixels;
    for (int c = 0; c < 3; ++c)
    {
      this->Sum[c] += v[c];
    }
    this->Largest = std::max(this->Largest, largest);
  }
  double Mean(int c) const { return this->Sum[c] / std::max(1L, this->Pixels); }
};

// Loads the Cornell box into `lit` with its lamp's light at `exposure`
// times its physical intensity; false (with a message) when that fails.
bool PopulateCornellBox(const std::string& data, vtkRenderer* lit, double exposure)
{
  vtkNew<vtkDeepGISceneLoader> loader;
  if (!loader->Load((data + "/scenes/cornell-original/CornellBox-Original.obj").c_str()))
  {
    std::printf("could not load the Cornell box from %s\n", data.c_str());
    return false;
  }
  loader->Populate(lit);
  loader->ResetCamera(lit);
  // The lamp's light at its physical intensity (Ke A / pi) leaves the floor
  // at radiance ~0.18, dark on an 8-bit display without tone mapping: an
  // exposure of 4 (two stops), as a camera would use, shows the bleeding.
  vtkLight* lampLight = vtkLight::SafeDownCast(lit->GetLights()->GetItemAsObject(0));
  if (!lampLight || lit->GetLights()->GetNumberOfItems() != 1)
  {
    std::printf("Populate did not add the lamp's light\n");
    return false;
  }
  lampLight->SetIntensity(exposure * lampLight->GetIntensity());
  return true;
}

// The regions the checks measure, over both layers.
struct CornellRegions
{
  Region Lamp, Ceiling, TowardsRed, TowardsGreen, All;
};

CornellRegions MeasureRegions(vtkImageData* layers, vtkImageData* radiosity, int W, int H)
{
  CornellRegions regions;
  Region& lamp = regions.Lamp;
  Region& ceiling = regions.Ceiling;
  Region& towardsRed = regions.TowardsRed;
  Region& towardsGreen = regions.TowardsGreen;
  Region& all = regions.All;
  for (int layer = 0; layer < 2; ++layer)
  {
    const std::string j = "_" + std::to_string(layer);
    for (int y = 0; y < H; ++y)
    {
      for (int x = 0; x < W; ++x)
      {
        double p[3];
        if (!WorldPosition(layers, layer, x, y, p))
        {
          continue;
        }
        double direct[3], indirect[3], normal[3];
        for (int c = 0; c < 3; ++c)
        {
          direct[c] = At(layers, vtkDeepGICaptureNames::Radiance + j, x, y, c) -
            At(layers, vtkDeepGICaptureNames::Ambient + j, x, y, c);
          indirect[c] = At(radiosity, vtkDeepGICaptureNames::IndirectRadiance + j, x, y, c);
          normal[c] = At(layers, vtkDeepGICaptureNames::Normal + j, x, y, c);
        }
        all.Add(indirect);
        const bool underLamp = std::abs(p[0]) < 0.3 && p[2] > -0.3 && p[2] < 0.22;
        if (p[1] > 1.97 && underLamp && layer == 0 && std::abs(p[0]) < 0.2 && p[2] > -0.18 &&
          p[2] < 0.12)
        {
          lamp.Add(direct);
        }
        else if (p[1] > 1.985 && !underLamp && layer == 0)
        {
          ceiling.Add(indirect, std::max({ direct[0], direct[1], direct[2] }));
        }
        const bool box =
          std::abs(p[0]) < 0.9 && p[1] > 0.03 && p[1] < 1.9 && p[2] > -0.95 && p[2] < 0.9;
        if (box && normal[0] < -0.7)
        {
          towardsRed.Add(indirect);
        }
        else if (box && normal[0] > 0.7)
        {
          towardsGreen.Add(indirect);
        }
      }
    }
  }
  std::printf("lamp: %ld px, direct (%.4f, %.4f, %.4f)\n", lamp.Pixels, lamp.Mean(0), lamp.Mean(1),
    lamp.Mean(2));
  std::printf("ceiling: %ld px, largest direct %.2e, mean L_ind (%.4f, %.4f, %.4f)\n",
    ceiling.Pixels, ceiling.Largest, ceiling.Mean(0), ceiling.Mean(1), ceiling.Mean(2));
  std::printf("box faces towards the red wall: %ld px, L_ind (%.4f, %.4f, %.4f), r/g %.3f\n",
    towardsRed.Pixels, towardsRed.Mean(0), towardsRed.Mean(1), towardsRed.Mean(2),
    towardsRed.Mean(0) / towardsRed.Mean(1));
  std::printf("box faces towards the green wall: %ld px, L_ind (%.4f, %.4f, %.4f), r/g %.3f\n",
    towardsGreen.Pixels, towardsGreen.Mean(0), towardsGreen.Mean(1), towardsGreen.Mean(2),
    towardsGreen.Mean(0) / towardsGreen.Mean(1));
  std::printf("all surfaces: %ld px, mean L_ind (%.4f, %.4f, %.4f)\n", all.Pixels, all.Mean(0),
    all.Mean(1), all.Mean(2));

  return regions;
}

// The lamp's direct radiance RADIANCE - AMBIENT is Ke / max(Ke).
void CheckLampIsEmissive(const Region& lamp)
{
  Check(lamp.Pixels > 50 && std::abs(lamp.Mean(0) - 1.0) < 2e-3 &&
      std::abs(lamp.Mean(1) - 12.0 / 17.0) < 2e-3 && std::abs(lamp.Mean(2) - 4.0 / 17.0) < 2e-3,
    "the lamp's direct radiance is Ke / max(Ke)");
}

// The ceiling beside the lamp gets no direct light but L_ind > 0, in the
// measured range, as is the mean over every surface.
void CheckCeilingLitIndirectly(const CornellRegions& r)
{
  // RADIANCE - AMBIENT of an unlit surface is the rounding of AMBIENT's
  // R11G11B10F (5-6 mantissa bits: 2.3e-3 at 0.0725) against RGBA16F.
  Check(r.Ceiling.Pixels > 500 && r.Ceiling.Largest < 3e-3, "no direct light on the ceiling");
  Check(r.Ceiling.Mean(0) > 0.01 && r.Ceiling.Mean(1) > 0.005 && r.Ceiling.Mean(2) > 0.001,
    "L_ind > 0 on the ceiling");
  auto near = [](double value, double measured)
  { return std::abs(value - measured) <= 0.2 * measured; };
  Check(near(r.Ceiling.Mean(0), 0.0796) && near(r.Ceiling.Mean(1), 0.0421) &&
      near(r.Ceiling.Mean(2), 0.0083),
    "ceiling L_ind in the measured range");
  Check(near(r.All.Mean(0), 0.1080) && near(r.All.Mean(1), 0.0582) && near(r.All.Mean(2), 0.0125),
    "mean L_ind in the measured range");
}

// Colour bleeding: the box faces that look at the red wall get red light,
// those that look at the green wall greener light.
void CheckColourBleeding(const CornellRegions& r)
{
  Check(
    r.TowardsRed.Pixels > 200 && r.TowardsGreen.Pixels > 200, "box faces on both sides are seen");
  Check(r.TowardsRed.Mean(0) > 4.0 * r.TowardsRed.Mean(1),
    "faces towards the red wall get red light (L_ind red / green > 4)");
  Check(r.TowardsGreen.Mean(0) < r.TowardsGreen.Mean(1),
    "faces towards the green wall get greener light (red / green < 1)");
}
}

int TestDeepRadiosityCornellImage(int argc, char* argv[])
{
  const std::string data = DeepGITestData::Folder(argc, argv, "TestDeepRadiosityCornellImage");
  if (!DeepGITestData::Require(data,
        { "scenes/cornell-original/CornellBox-Original.obj",
          "scenes/cornell-original/CornellBox-Original.mtl" },
        "TestDeepRadiosityCornellImage"))
  {
    return EXIT_FAILURE;
  }
  constexpr int W = 256, H = 256, frames = 20;
  constexpr double Exposure = 4.0;
  auto window = MakeWindow(2 * W, H);
  vtkNew<vtkRenderer> lit, view;
  lit->SetViewport(0.0, 0.0, 0.5, 1.0);
  view->SetViewport(0.5, 0.0, 1.0, 1.0);
  window->AddRenderer(lit);
  window->AddRenderer(view);
  if (!PopulateCornellBox(data, lit, Exposure))
  {
    return EXIT_FAILURE;
  }
  vtkNew<vtkDeepRadiosityPass> pass;
  pass->SetPresetToBalanced();
  pass->SetTemporalAlpha(0.0);
  // A gather radius of 0.3 of the diagonal (1.06, half the room): with the
  // default 0.1 the walls' colour reaches only 0.35 into the white surfaces.
  pass->SetAutomaticRadiusFraction(0.3);
  lit->SetPass(pass);

  // The L_ind viewport: image pixel (i, j) at viewport pixel (i, j).
  vtkSmartPointer<vtkImageData> rgb = ShowImagePixelForPixel(view, W, H, 3);

  for (int k = 0; k < frames; ++k)
  {
    window->Render();
  }
  vtkNew<vtkImageData> radiosity, layers;
  if (!pass->CaptureIrradiance(radiosity, lit) ||
    !pass->GetGBufferPass()->CaptureLayers(layers, lit))
  {
    Check(false, "the irradiance and the layers are captured");
    return EXIT_FAILURE;
  }
  {
    vtkDataArray* l = radiosity->GetPointData()->GetArray(
      vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0).c_str());
    ShowValues(l, 4.0, rgb);
  }
  window->Render();

  const CornellRegions regions = MeasureRegions(layers, radiosity, W, H);
  Check(AllFinite(radiosity) && AllFinite(layers), "finite captures (no NaN)");
  Check(Minimum(radiosity,
          vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0)) >= 0.0,
    "L_ind >= 0");
  CheckLampIsEmissive(regions.Lamp);
  CheckCeilingLitIndirectly(regions);
  CheckColourBleeding(regions);
  CheckRegressionImage(argc, argv, window, 0.5);
  pass->ReleaseGraphicsResources(window);
  return ExitStatus();
}
