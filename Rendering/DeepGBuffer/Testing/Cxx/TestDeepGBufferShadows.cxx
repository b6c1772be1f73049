// VTK's shadow maps in the deep G-buffer (vtkDeepGBufferPass::SetShadowMapPass).
// Scene: a white floor y = 0 (6 x 6, ambient 0.1), a white box 1 x 3 x 1
// standing on it, a red wall z = -3 facing +z, and a spot light at
// (4, 10, 6) aimed at the origin (cone 60 degrees, exponent 1, no
// attenuation: VTK casts shadows from spot lights with cones under 90
// degrees). The box's shadow runs towards the red wall; the camera sees part
// of it, and the box hides another part: there layer 1 (back faces culled)
// is shadowed floor.
// - on the floor inside the spot's cone, "shadowed" pixels have a direct
//   radiance RADIANCE - AMBIENT below 5 % of VTK's unshadowed value
//   cos(theta) x cone dot: layer 0 has >= 300 of them and layer 1 >= 50
//   (after 3 frames, i.e. through the single-pass geometry shader), >= 3000
//   and >= 50 lit ones (above 50 %); within 2 of the box every shadowed
//   pixel lies where the box blocks the light (with a 0.15 margin); AMBIENT
//   is the floor's 0.1 in light and shadow (VTK's ambient term is not
//   shadowed). The lit floor is not compared with cos(theta) exactly: VTK
//   9.1's exponential shadow maps darken it by up to 30 % at grazing light,
//   and by a different amount from a different camera (measured with VTK's
//   own pipeline: 124 against 200 of 255 at (1.29, 0, -1.17));
// - layer 0's RADIANCE equals what VTK's own shadow pipeline (vtkCameraPass
//   -> vtkSequencePass(baker, vtkShadowMapPass)) draws: at most 0.5 % of the
//   pixels differ by more than 2/255 (8-bit window against RGBA16F);
// - vtkDeepRadiosityPass with the shadowed G-buffer: on the shadowed floor
//   near the red wall (z < -1.2), the indirect radiance L_ind is
//   non-zero and red (mean red > 0.01 and > 2 x mean green), i.e. light
//   bleeds into the shadow;
// - without shadow maps no layer-1 floor pixel in the cone is dark;
// - without a shadow pass the G-buffer is unchanged: a pass that had shadows
//   and lost them (SetShadowMapPass(nullptr)) captures bit-identical layers
//   to a pass that never had them, and a shadow pass with no shadowing light
//   (a headlight) changes no bit either;
// - the other oracles (DEPTH_PEEL, PREVIOUS, PREDICT, DELAY) give the same
//   shadowed pixel count in layer 0 and within 10 % in layer 1;
// - ReleaseGraphicsResources, then rendering again, gives the same layers.

#include "DeepRadiosityTest.h"

#include "vtkCameraPass.h"
#include "vtkDeepGBufferPass.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkRenderPassCollection.h"
#include "vtkSequencePass.h"
#include "vtkShadowMapBakerPass.h"
#include "vtkShadowMapPass.h"

#include "vtkLight.h"
#include "vtkMath.h"

#include <algorithm>
#include <cmath>

using namespace DeepRadiosityTest;
using namespace DeepGITest;

namespace
{
const double LightPosition[3] = { 4.0, 10.0, 6.0 };
constexpr double ConeAngle = 60.0;
const double BoxMin[3] = { -0.5, 0.0, -0.5 }, BoxMax[3] = { 0.5, 3.0, 0.5 };

void ShadowScene(vtkRenderer* renderer, bool spot = true)
{
  const double f0[3] = { -3, 0, 3 }, f1[3] = { 3, 0, 3 }, f2[3] = { -3, 0, -3 };
  vtkActor* floor = Diffuse(AddQuad(renderer, f0, f1, f2), 1, 1, 1);
  floor->GetProperty()->SetAmbient(0.1);
  const double center[3] = { 0, 1.5, 0 }, size[3] = { 1, 3, 1 };
  Diffuse(AddBox(renderer, center, size), 1, 1, 1);
  const double w0[3] = { -3, 0, -3 }, w1[3] = { 3, 0, -3 }, w2[3] = { -3, 2.5, -3 };
  Diffuse(AddQuad(renderer, w0, w1, w2), 1, 0, 0);
  if (spot)
  {
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPositional(true);
    light->SetConeAngle(ConeAngle);
    light->SetPosition(LightPosition[0], LightPosition[1], LightPosition[2]);
    light->SetFocalPoint(0.0, 0.0, 0.0);
    renderer->AddLight(light);
  }
  SetCamera(renderer, -4.5, 4.5, 6, -0.3, 0.3, -0.8);
}

// VTK's direct radiance of the white floor (Diffuse 1) at p without shadow:
// cos(theta) x the spot's cone dot (exponent 1); -1 off the floor, outside
// the cone or within 0.02 of its edge, and within 0.05 of the box (whose
// pixels at the floor may reconstruct to y ~ 0).
double SpotDirect(const double p[3])
{
  if (std::abs(p[1]) > 1e-3 || std::abs(p[0]) > 2.9 || std::abs(p[2]) > 2.9 ||
    (std::abs(p[0]) < 0.55 && std::abs(p[2]) < 0.55))
  {
    return -1.0;
  }
  double toLight[3], axis[3] = { -LightPosition[0], -LightPosition[1], -LightPosition[2] };
  vtkMath::Subtract(LightPosition, p, toLight);
  vtkMath::Normalize(toLight);
  vtkMath::Normalize(axis);
  const double coneDot = -vtkMath::Dot(toLight, axis);
  const double edge = std::cos(vtkMath::RadiansFromDegrees(ConeAngle));
  return coneDot < edge + 0.02 ? -1.0 : toLight[1] * coneDot;
}

// Whether the segment from floor point p to the light misses the box with
// a margin: from p and from four points 0.15 away.
bool Unoccluded(const double p[3])
{
  const double offsets[5][2] = { { 0, 0 }, { 0.15, 0 }, { -0.15, 0 }, { 0, 0.15 }, { 0, -0.15 } };
  for (const auto& o : offsets)
  {
    const double q[3] = { p[0] + o[0], 0.0, p[2] + o[1] };
    double d[3];
    vtkMath::Subtract(LightPosition, q, d);
    double t0 = 0.0, t1 = vtkMath::Normalize(d);
    for (int k = 0; k < 3; ++k)
    {
      const double a = (BoxMin[k] - q[k]) / d[k], b = (BoxMax[k] - q[k]) / d[k];
      t0 = std::max(t0, std::min(a, b));
      t1 = std::min(t1, std::max(a, b));
    }
    if (t0 < t1)
    {
      return false;
    }
  }
  return true;
}

// Direct radiance RADIANCE - AMBIENT (red) of pixel q of a layer.
double Direct(vtkImageData* layers, int layer, vtkIdType q)
{
  return Layer(layers, vtkDeepGICaptureNames::Radiance, layer)->GetComponent(q, 0) -
    Layer(layers, vtkDeepGICaptureNames::Ambient, layer)->GetComponent(q, 0);
}

struct FloorStats
{
  long Floor = 0, Shadowed = 0, Lit = 0, BadAmbient = 0, FalseShadows = 0;
};

// Floor pixels of a layer inside the spot's cone: shadowed where the direct
// radiance is below 5 % of the unshadowed value, lit above 50 %; the
// ambient term must be the floor's 0.1 either way. A false shadow is a
// shadowed pixel whose light the box does not block, within 2 of the box
// (VTK's spot shadow map also darkens the floor's far corners, outside its
// light camera's depth range).
FloorStats Classify(vtkImageData* layers, int layer)
{
  FloorStats st;
  const int* dims = layers->GetDimensions();
  for (int j = 0; j < dims[1]; ++j)
  {
    for (int i = 0; i < dims[0]; ++i)
    {
      double p[3];
      if (!WorldPosition(layers, layer, i, j, p))
      {
        continue;
      }
      const double unshadowed = SpotDirect(p);
      if (unshadowed <= 0.0)
      {
        continue;
      }
      const vtkIdType q = static_cast<vtkIdType>(j) * dims[0] + i;
      const double direct = Direct(layers, layer, q);
      ++st.Floor;
      st.Shadowed += direct < 0.05 * unshadowed ? 1 : 0;
      st.FalseShadows +=
        direct < 0.05 * unshadowed && std::abs(p[0]) < 2.0 && std::abs(p[2]) < 2.0 && Unoccluded(p)
        ? 1
        : 0;
      st.Lit += direct > 0.5 * unshadowed ? 1 : 0;
      st.BadAmbient +=
        std::abs(Layer(layers, vtkDeepGICaptureNames::Ambient, layer)->GetComponent(q, 0) - 0.1) >
        2e-3;
    }
  }
  return st;
}

// Renders `frames` frames of the G-buffer alone (with the spot light or
// VTK's headlight); `between` runs before the last two frames (to change the
// shadow pass). Releases the pass's and `shadows`' resources.
void RenderGBuffer(vtkDeepGBufferPass* pass, bool spot, int frames, vtkImageData* layers,
  const std::function<void()>& between = nullptr, vtkShadowMapPass* shadows = nullptr)
{
  auto window = MakeWindow(200, 150);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  ShadowScene(renderer, spot);
  renderer->ResetCameraClippingRange();
  renderer->SetPass(pass);
  for (int k = 0; k < frames; ++k)
  {
    if (between && k == frames - 2)
    {
      between();
    }
    window->Render();
  }
  Check(pass->CaptureLayers(layers, renderer), "capture");
  pass->ReleaseGraphicsResources(window);
  if (shadows)
  {
    shadows->ReleaseGraphicsResources(window);
  }
}

// Both layers: shadowed and lit floor in the cone, the shadows where the
// box blocks the light, ambient unshadowed.
void CheckShadowedFloor(vtkImageData* layers)
{
  for (int layer = 0; layer < 2; ++layer)
  {
    FloorStats st = Classify(layers, layer);
    std::printf("layer %d: %ld floor pixels in the cone, %ld shadowed (%ld where the box does not "
                "block the light), %ld lit, ambient wrong at %ld\n",
      layer, st.Floor, st.Shadowed, st.FalseShadows, st.Lit, st.BadAmbient);
    const std::string l = "layer " + std::to_string(layer) + ": ";
    Check(st.Shadowed >= (layer == 0 ? 300 : 50), l + "shadowed floor pixels");
    Check(st.Lit >= (layer == 0 ? 3000 : 50), l + "lit floor pixels");
    Check(st.FalseShadows == 0, l + "the shadowed pixels lie in the box's shadow");
    Check(st.BadAmbient == 0, l + "ambient 0.1 in light and shadow");
  }
}

// The other oracles draw the layers through the same shadow hooks: the
// same shadowed floor (layer 0 drawn the same way: bit-identical counts;
// layer 1 within 10 % of REPROJECT's).
void CheckOraclesCastTheSameShadows(vtkImageData* layers)
{
  const FloorStats reference0 = Classify(layers, 0), reference1 = Classify(layers, 1);
  for (int oracle : { vtkDeepGBufferPass::DEPTH_PEEL, vtkDeepGBufferPass::PREVIOUS,
         vtkDeepGBufferPass::PREDICT, vtkDeepGBufferPass::DELAY })
  {
    vtkNew<vtkDeepGBufferPass> other;
    other->SetOracle(oracle);
    vtkNew<vtkImageData> captured;
    vtkNew<vtkShadowMapPass> otherShadows;
    other->SetShadowMapPass(otherShadows);
    RenderGBuffer(other, true, 3, captured, nullptr, otherShadows);
    const FloorStats l0 = Classify(captured, 0), l1 = Classify(captured, 1);
    std::printf("%s: layer 0 %ld shadowed, layer 1 %ld shadowed of %ld\n",
      vtkDeepGBufferPass::GetOracleAsString(oracle), l0.Shadowed, l1.Shadowed, l1.Floor);
    Check(l0.Shadowed == reference0.Shadowed && l0.FalseShadows == 0 &&
        std::abs(l1.Shadowed - reference1.Shadowed) <= reference1.Shadowed / 10 &&
        l1.FalseShadows == 0,
      std::string(vtkDeepGBufferPass::GetOracleAsString(oracle)) + ": the same shadows");
  }
}

// Layer 0 against VTK's own shadow pipeline.
void CheckLayerZeroMatchesVTKShadows(vtkImageData* layers)
{
  auto vtkWindow = MakeWindow(200, 150);
  vtkNew<vtkRenderer> vtkRen;
  vtkWindow->AddRenderer(vtkRen);
  ShadowScene(vtkRen);
  vtkRen->ResetCameraClippingRange();
  vtkNew<vtkShadowMapPass> vtkShadows;
  vtkNew<vtkRenderPassCollection> steps;
  steps->AddItem(vtkShadows->GetShadowMapBakerPass());
  steps->AddItem(vtkShadows);
  vtkNew<vtkSequencePass> sequence;
  sequence->SetPasses(steps);
  vtkNew<vtkCameraPass> cameraPass;
  cameraPass->SetDelegatePass(sequence);
  vtkRen->SetPass(cameraPass);
  vtkWindow->Render();
  vtkNew<vtkImageData> rgb;
  ReadWindow(vtkWindow, rgb, nullptr);
  vtkDataArray* colors = rgb->GetPointData()->GetScalars();
  vtkDataArray* radiance = Layer(layers, vtkDeepGICaptureNames::Radiance, 0);
  vtkDataArray* valid = Layer(layers, vtkDeepGICaptureNames::Valid, 0);
  long compared = 0, different = 0;
  double worst = 0.0;
  for (vtkIdType p = 0; p < colors->GetNumberOfTuples(); ++p)
  {
    if (valid->GetComponent(p, 0) == 0)
    {
      continue;
    }
    ++compared;
    double d = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      const double mine = std::min(1.0, radiance->GetComponent(p, c)) * 255.0;
      d = std::max(d, std::abs(mine - colors->GetComponent(p, c)));
    }
    worst = std::max(worst, d);
    different += d > 2.0 ? 1 : 0;
  }
  std::printf("layer 0 against VTK's shadows: %ld of %ld pixels differ by > 2/255 (largest "
              "%.1f/255)\n",
    different, compared, worst);
  Check(
    compared > 10000 && different <= compared / 200, "layer 0 radiance is VTK's shadowed image");
  vtkShadows->ReleaseGraphicsResources(vtkWindow);
}

// Shadowed direct light enters the radiosity as B(Y): red light in the shadow.
void CheckLightBleedsIntoShadow()
{
  vtkNew<vtkDeepRadiosityPass> radiosity;
  vtkNew<vtkShadowMapPass> radiosityShadows;
  radiosity->GetGBufferPass()->SetShadowMapPass(radiosityShadows);
  Frame f;
  RenderFrames([](vtkRenderer* r) { ShadowScene(r); }, radiosity, 10, f, 200, 150);
  long n = 0;
  double red = 0.0, green = 0.0, direct = 0.0;
  for (int j = 0; j < f.Height; ++j)
  {
    for (int i = 0; i < f.Width; ++i)
    {
      double p[3];
      if (!WorldPosition(f.Layers, 0, i, j, p) || SpotDirect(p) <= 0.0 || p[2] > -1.2)
      {
        continue;
      }
      const double d = Direct(f.Layers, 0, static_cast<vtkIdType>(j) * f.Width + i);
      if (d >= 0.05 * SpotDirect(p))
      {
        continue;
      }
      ++n;
      red += At(f.Radiosity,
        vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0), i, j, 0);
      green += At(f.Radiosity,
        vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0), i, j, 1);
      direct = std::max(direct, d);
    }
  }
  red /= std::max(1L, n);
  green /= std::max(1L, n);
  std::printf("shadowed floor near the red wall: %ld pixels, largest direct %.4f, mean L_ind "
              "red %.4f green %.4f\n",
    n, direct, red, green);
  Check(n >= 50, "shadowed floor near the red wall is seen");
  Check(red > 0.01 && red > 2.0 * green, "red light bleeds into the shadow");
  Check(AllFinite(f.Radiosity), "finite radiosity");
  radiosity->ReleaseGraphicsResources(f.Window);
}

// Without shadows nothing changes.
void CheckWithoutShadowsNothingChanges()
{
  vtkNew<vtkDeepGBufferPass> plain, lost, headlit, headlitPlain;
  vtkNew<vtkImageData> a, b, c, d;
  RenderGBuffer(plain, true, 4, a);
  vtkNew<vtkShadowMapPass> s1, s2;
  lost->SetShadowMapPass(s1);
  RenderGBuffer(
    lost, true, 4, b, [&]() { lost->SetShadowMapPass(nullptr); }, s1);
  Check(SameArrays(a, b), "shadow pass removed: bit-identical layers");
  const FloorStats unshadowed = Classify(a, 1);
  std::printf("without shadows, layer 1: %ld floor pixels in the cone, %ld dark\n",
    unshadowed.Floor, unshadowed.Shadowed);
  Check(unshadowed.Shadowed == 0, "without shadow maps no floor pixel of layer 1 is dark");
  headlit->SetShadowMapPass(s2);
  RenderGBuffer(headlit, false, 4, c);
  RenderGBuffer(headlitPlain, false, 4, d);
  Check(SameArrays(c, d), "no shadowing light: bit-identical layers");
}
}

int TestDeepGBufferShadows(int, char*[])
{
  // Shadowed layers, both layers.
  vtkNew<vtkDeepGBufferPass> gbuffer;
  vtkNew<vtkShadowMapPass> shadows;
  gbuffer->SetShadowMapPass(shadows);
  vtkNew<vtkImageData> layers;
  auto window = MakeWindow(200, 150);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  ShadowScene(renderer);
  renderer->ResetCameraClippingRange();
  renderer->SetPass(gbuffer);
  EventCounter errors(gbuffer, vtkCommand::ErrorEvent);
  EventCounter shadowErrors(shadows, vtkCommand::ErrorEvent);
  EventCounter bakerErrors(shadows->GetShadowMapBakerPass(), vtkCommand::ErrorEvent);
  for (int k = 0; k < 3; ++k)
  {
    window->Render();
  }
  Check(gbuffer->CaptureLayers(layers, renderer), "capture with shadows");
  Check(AllFinite(layers), "finite layers");
  Check(gbuffer->GetEffectiveNumberOfLayers() == 2, "two layers");
  CheckShadowedFloor(layers);
  CheckOraclesCastTheSameShadows(layers);

  // ReleaseGraphicsResources, then the same frames again: the shadow maps
  // are baked anew (VTK's baker alone would not) and the layers are the same.
  {
    gbuffer->ReleaseGraphicsResources(window);
    for (int k = 0; k < 3; ++k)
    {
      window->Render();
    }
    vtkNew<vtkImageData> again;
    Check(gbuffer->CaptureLayers(again, renderer) && SameArrays(layers, again),
      "after ReleaseGraphicsResources: the same shadowed layers");
  }

  CheckLayerZeroMatchesVTKShadows(layers);
  CheckLightBleedsIntoShadow();
  Check(errors.Count == 0 && shadowErrors.Count == 0 && bakerErrors.Count == 0,
    "no errors (OpenGL errors included) from the G-buffer, the shadow pass and its baker");
  CheckWithoutShadowsNothingChanges();

  gbuffer->ReleaseGraphicsResources(window);
  return ExitStatus();
}
