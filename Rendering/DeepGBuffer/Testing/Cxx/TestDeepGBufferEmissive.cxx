// vtkDeepGBufferPass::EMISSIVE(): a self-lit panel (Ambient 1, AmbientColor
// (1, 0.5, 0.25), Diffuse 0) standing on a white floor (Diffuse 1, Ambient 0)
// lit by nothing (the only light, a spot light, points at the sky),
// 160 x 120.
// - without the key the panel's colour is VTK's ambient term: RADIANCE =
//   AMBIENT = the colour, direct radiance 0, and vtkDeepRadiosityPass finds
//   nothing to gather: L_ind exactly 0 everywhere;
// - with the key (set on the same actor between frames: no shader rebuild
//   is needed) RADIANCE is unchanged, AMBIENT is 0 and RADIANCE - AMBIENT is
//   the colour (within RGBA16F rounding, 1e-3), and the floor next to the
//   panel receives its light: mean L_ind over the floor within 1 of the
//   panel is > 0.01 in red, and red > green > blue as the panel's colour
//   (measured (0.4145, 0.2072, 0.1036): the panel's colour x 0.41);
// - seen from behind, the panel's back face holds the same RADIANCE - AMBIENT
//   (VTK 9.1 draws the ambient term on both sides), which is what
//   vtkDeepGIReferenceIrradiance's emission does with TwoSidedLighting on.

#include "DeepRadiosityTest.h"

#include "vtkDeepGICaptureNames.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"

using namespace DeepRadiosityTest;
using namespace DeepGITest;

namespace
{
// The self-lit panel on the white floor, under a spot light aimed at the sky;
// returns the panel.
vtkActor* AddPanelScene(vtkRenderer* renderer)
{
  const double colour[3] = { 1.0, 0.5, 0.25 };
  const double f0[3] = { -2, 0, 2 }, f1[3] = { 2, 0, 2 }, f2[3] = { -2, 0, -2 };
  Diffuse(AddQuad(renderer, f0, f1, f2), 1, 1, 1);
  const double p0[3] = { -1, 0, 0 }, p1[3] = { 1, 0, 0 }, p2[3] = { -1, 1, 0 };
  vtkActor* panel = AddQuad(renderer, p0, p1, p2);
  panel->GetProperty()->SetAmbientColor(colour[0], colour[1], colour[2]);
  panel->GetProperty()->SetAmbient(1.0);
  panel->GetProperty()->SetDiffuse(0.0);
  panel->GetProperty()->SetSpecular(0.0);
  // A spot light aimed at the sky lights nothing here. A light must be
  // on: without one VTK draws every prop unlit (ambient + diffuse colour)
  // and vtkDeepRadiosityPass bounces nothing.
  vtkNew<vtkLight> dark;
  dark->SetLightTypeToSceneLight();
  dark->SetPositional(true);
  dark->SetConeAngle(20.0);
  dark->SetPosition(0.0, 3.0, 0.0);
  dark->SetFocalPoint(0.0, 10.0, 0.0);
  renderer->AddLight(dark);
  SetCamera(renderer, 0, 2.5, 4, 0, 0.3, 0);
  return panel;
}

// Floor pixels within 1 of the panel (in front of it), and the panel's
// pixels, of layer 0.
void Measure(Frame& f, double floorMean[3], double panelDirect[3], double panelAmbient[3])
{
  long floor = 0, lamp = 0;
  for (int c = 0; c < 3; ++c)
  {
    floorMean[c] = panelDirect[c] = panelAmbient[c] = 0.0;
  }
  for (int j = 0; j < f.Height; ++j)
  {
    for (int i = 0; i < f.Width; ++i)
    {
      double p[3];
      if (!WorldPosition(f.Layers, 0, i, j, p))
      {
        continue;
      }
      const bool onFloor = std::abs(p[1]) < 1e-3 && p[2] > 0.05 && p[2] < 1.0 && std::abs(p[0]) < 1;
      const bool onPanel =
        std::abs(p[2]) < 1e-3 && p[1] > 0.05 && p[1] < 0.95 && std::abs(p[0]) < 0.95;
      for (int c = 0; c < 3; ++c)
      {
        if (onFloor)
        {
          floorMean[c] += At(f.Radiosity,
            vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0), i, j, c);
        }
        if (onPanel)
        {
          panelDirect[c] +=
            At(
              f.Layers, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Radiance, 0), i, j, c) -
            At(f.Layers, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Ambient, 0), i, j, c);
          panelAmbient[c] +=
            At(f.Layers, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Ambient, 0), i, j, c);
        }
      }
      floor += onFloor ? 1 : 0;
      lamp += onPanel ? 1 : 0;
    }
  }
  for (int c = 0; c < 3; ++c)
  {
    floorMean[c] /= std::max(1L, floor);
    panelDirect[c] /= std::max(1L, lamp);
    panelAmbient[c] /= std::max(1L, lamp);
  }
  Check(floor > 500 && lamp > 500, "floor and panel seen");
}

// Without the key the panel's colour is VTK's ambient term and the radiosity
// finds nothing to gather.
void CheckWithoutKeyPanelIsAmbient(Frame& f)
{
  double floorMean[3], panelDirect[3], panelAmbient[3];
  Measure(f, floorMean, panelDirect, panelAmbient);
  std::printf("without the key: panel direct (%.4f, %.4f, %.4f) ambient (%.4f, %.4f, %.4f), "
              "largest L_ind %.3g\n",
    panelDirect[0], panelDirect[1], panelDirect[2], panelAmbient[0], panelAmbient[1],
    panelAmbient[2],
    Maximum(f.Radiosity, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0)));
  Check(std::abs(panelAmbient[0] - 1.0) < 1e-2 && std::abs(panelAmbient[1] - 0.5) < 1e-2 &&
      std::abs(panelAmbient[2] - 0.25) < 1e-2 && std::abs(panelDirect[0]) < 1e-2,
    "without the key the panel's colour is AMBIENT, its direct radiance 0");
  Check(Maximum(f.Radiosity,
          vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 0)) == 0.0 &&
      Maximum(f.Radiosity,
        vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::IndirectRadiance, 1)) == 0.0,
    "without the key nothing is gathered: L_ind exactly 0");
}

// With the key RADIANCE is unchanged, AMBIENT 0, and the floor receives the
// panel's light.
void CheckWithKeyPanelEmits(Frame& f, vtkDeepRadiosityPass* radiosity, vtkActor* panel)
{
  double floorMean[3], panelDirect[3], panelAmbient[3];
  vtkNew<vtkInformation> keys;
  keys->Set(vtkDeepGBufferPass::EMISSIVE(), 1);
  panel->SetPropertyKeys(keys);
  for (int k = 0; k < 10; ++k)
  {
    f.Window->Render();
  }
  Check(radiosity->CaptureIrradiance(f.Radiosity, f.Renderer) &&
      radiosity->GetGBufferPass()->CaptureLayers(f.Layers, f.Renderer),
    "capture with the key");
  Measure(f, floorMean, panelDirect, panelAmbient);
  std::printf("with the key: panel direct (%.4f, %.4f, %.4f) ambient (%.4f, %.4f, %.4f), floor "
              "L_ind (%.4f, %.4f, %.4f)\n",
    panelDirect[0], panelDirect[1], panelDirect[2], panelAmbient[0], panelAmbient[1],
    panelAmbient[2], floorMean[0], floorMean[1], floorMean[2]);
  Check(std::abs(panelDirect[0] - 1.0) < 1e-3 && std::abs(panelDirect[1] - 0.5) < 1e-3 &&
      std::abs(panelDirect[2] - 0.25) < 1e-3 && panelAmbient[0] == 0.0 && panelAmbient[1] == 0.0 &&
      panelAmbient[2] == 0.0,
    "with the key AMBIENT is 0 and RADIANCE - AMBIENT the panel's colour");
  Check(floorMean[0] > 0.01 && floorMean[0] > floorMean[1] && floorMean[1] > floorMean[2],
    "the floor receives the panel's light through the radiosity");
  Check(AllFinite(f.Radiosity) && AllFinite(f.Layers), "finite");
}

// Seen from behind: VTK draws the ambient term on back faces too (no
// backface property), so the G-buffer stores the same emission there.
void CheckBackFaceEmits(Frame& f, vtkDeepRadiosityPass* radiosity)
{
  SetCamera(f.Renderer, 0, 2.5, -4, 0, 0.3, 0);
  f.Window->Render();
  Check(radiosity->GetGBufferPass()->CaptureLayers(f.Layers, f.Renderer), "capture from behind");
  double backDirect[3] = { 0, 0, 0 }, backAmbient[3] = { 0, 0, 0 };
  long back = 0;
  for (int j = 0; j < f.Height; ++j)
  {
    for (int i = 0; i < f.Width; ++i)
    {
      double p[3];
      if (!WorldPosition(f.Layers, 0, i, j, p) || std::abs(p[2]) > 1e-3 || p[1] < 0.05 ||
        p[1] > 0.95 || std::abs(p[0]) > 0.95)
      {
        continue;
      }
      for (int c = 0; c < 3; ++c)
      {
        backDirect[c] +=
          At(f.Layers, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Radiance, 0), i, j, c) -
          At(f.Layers, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Ambient, 0), i, j, c);
        backAmbient[c] +=
          At(f.Layers, vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Ambient, 0), i, j, c);
      }
      ++back;
    }
  }
  for (int c = 0; c < 3; ++c)
  {
    backDirect[c] /= std::max(1L, back);
    backAmbient[c] /= std::max(1L, back);
  }
  std::printf("from behind: %ld panel pixels, direct (%.4f, %.4f, %.4f) ambient (%.4f, %.4f, "
              "%.4f)\n",
    back, backDirect[0], backDirect[1], backDirect[2], backAmbient[0], backAmbient[1],
    backAmbient[2]);
  Check(back > 500 && std::abs(backDirect[0] - 1.0) < 1e-3 &&
      std::abs(backDirect[1] - 0.5) < 1e-3 && std::abs(backDirect[2] - 0.25) < 1e-3 &&
      backAmbient[0] == 0.0 && backAmbient[1] == 0.0 && backAmbient[2] == 0.0,
    "the panel's back face stores the same emission: RADIANCE - AMBIENT the colour");
}
}

int TestDeepGBufferEmissive(int, char*[])
{
  vtkActor* panel = nullptr;
  vtkNew<vtkDeepRadiosityPass> radiosity;
  radiosity->SetTemporalAlpha(0.0);
  Frame f;
  RenderFrames([&](vtkRenderer* renderer) { panel = AddPanelScene(renderer); }, radiosity, 2, f);
  CheckWithoutKeyPanelIsAmbient(f);
  CheckWithKeyPanelEmits(f, radiosity, panel);
  CheckBackFaceEmits(f, radiosity);
  radiosity->ReleaseGraphicsResources(f.Window);
  return ExitStatus();
}
