// vtkDeepReflectionPass under conditions that must not break it:
// - no reflective prop: no rays, no REFLECTIVITY texture, and the image is
//   exactly vtkDeepGBufferPass's; a prop that stops reflecting frees it;
// - bad parameters (NaN, negative, zero, huge): a warning and a clamped
//   value, and every capture stays finite;
// - ReleaseGraphicsResources, then rendering again gives the same result;
// - a resize;
// - two renderers sharing the pass keep their own results.
// 160 x 120 px.

#include "DeepReflectionTestUtilities.h"

#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepReflectionPass.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkSphereSource.h"
#include "vtkTextureUnitManager.h"

#include <limits>
#include <sstream>

using namespace DeepGBufferTest;
using namespace DeepReflectionTest;
using namespace DeepGITest;

namespace
{
// Floor (a mirror when `mirror`), a constant-colour wall and a sphere.
vtkActor* BuildScene(vtkRenderer* renderer, bool mirror)
{
  vtkActor* floor = AddQuad(renderer, { -4, 0, 4 }, { 4, 0, 4 }, { -4, 0, -3 });
  if (mirror)
  {
    MakeMirror(floor);
  }
  MakeConstant(AddQuad(renderer, { -4, 0, -3 }, { 4, 0, -3 }, { -4, 4, -3 }), 0.9, 0.6, 0.1);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0.8, 0.7, -0.5);
  sphere->SetRadius(0.7);
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(24);
  AddSourceActor(renderer, sphere);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 2.0, 5.0);
  camera->SetFocalPoint(0.0, 0.8, -2.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  renderer->ResetCameraClippingRange();
  return floor;
}

struct Summary
{
  long Traced = 0, Hits = 0, Environment = 0;
  bool Finite = false;
};

Summary Summarize(vtkDeepReflectionPass* pass, vtkRenderer* renderer, vtkImageData* capture)
{
  Summary s;
  if (!pass->CaptureReflections(capture, renderer))
  {
    return s;
  }
  s.Finite = AllFinite(capture);
  vtkDataArray* valid = capture->GetPointData()->GetArray(vtkDeepGICaptureNames::Valid);
  vtkDataArray* layer = capture->GetPointData()->GetArray(vtkDeepGICaptureNames::HitLayer);
  for (vtkIdType p = 0; p < valid->GetNumberOfTuples(); ++p)
  {
    if (valid->GetTuple1(p))
    {
      ++s.Traced;
      (layer->GetTuple1(p) >= 0.0 ? s.Hits : s.Environment)++;
    }
  }
  return s;
}

// 1. Nothing reflects (VTK's default Specular 0): exactly the G-buffer's image.
void CheckNothingReflectiveDrawsTheGBufferImage(vtkRenderWindow* window, vtkRenderer* renderer,
  vtkDeepReflectionPass* pass, vtkImageData* plainImage)
{
  vtkNew<vtkImageData> reflectionImage;
  renderer->SetPass(pass);
  window->Render();
  ReadWindow(window, reflectionImage, nullptr);
  Check(!pass->GetLastFrameTraced(), "no reflective prop: no rays traced");
  Check(!pass->GetGBufferPass()->GetWriteReflectivity() &&
      pass->GetGBufferPass()->GetTextureHandle(renderer, vtkDeepGBufferPass::REFLECTIVITY) == 0,
    "no reflective prop: no REFLECTIVITY texture");
  const double difference = MaximumColorDifference(plainImage, reflectionImage);
  std::printf("largest colour difference to vtkDeepGBufferPass: %g\n", difference);
  Check(difference == 0.0, "no reflective prop: the image equals vtkDeepGBufferPass's exactly");
  // The debug display of REFLECTIVITY falls back to RADIANCE when it is not written.
  pass->GetGBufferPass()->SetDisplayQuantity(vtkDeepGBufferPass::REFLECTIVITY);
  window->Render();
  vtkNew<vtkImageData> fallbackImage;
  ReadWindow(window, fallbackImage, nullptr);
  Check(MaximumColorDifference(plainImage, fallbackImage) == 0.0,
    "display of an unwritten REFLECTIVITY shows RADIANCE");
  pass->GetGBufferPass()->SetDisplayQuantity(vtkDeepGBufferPass::RADIANCE);
}

// Materials that cannot reflect: lighting off, black specular colour, PBR
// roughness 1. A smooth metal reflects; when it stops, the texture is freed
// again.
void CheckOnlyReflectiveMaterialsTrace(
  vtkRenderWindow* window, vtkRenderer* renderer, vtkDeepReflectionPass* pass, vtkActor* floor)
{
  floor->GetProperty()->SetSpecular(1.0);
  floor->GetProperty()->LightingOff();
  window->Render();
  const bool unlit = pass->GetLastFrameTraced();
  floor->GetProperty()->LightingOn();
  floor->GetProperty()->SetSpecularColor(0.0, 0.0, 0.0);
  window->Render();
  const bool black = pass->GetLastFrameTraced();
  floor->GetProperty()->SetInterpolationToPBR();
  floor->GetProperty()->SetRoughness(1.0);
  window->Render();
  const bool rough = pass->GetLastFrameTraced();
  Check(
    !unlit && !black && !rough, "unlit, black-specular and roughness-1 PBR props do not reflect");

  // A smooth metal reflects; when it stops, the texture is freed again.
  floor->GetProperty()->SetRoughness(0.0);
  floor->GetProperty()->SetMetallic(1.0);
  floor->GetProperty()->SetColor(0.8, 0.8, 0.8);
  window->Render();
  vtkNew<vtkImageData> capture;
  const Summary metal = Summarize(pass, renderer, capture);
  double pbrReflectivity = 0.0;
  vtkDataArray* reflectivity =
    capture->GetPointData()->GetArray(vtkDeepGICaptureNames::Reflectivity);
  for (vtkIdType p = 0; p < reflectivity->GetNumberOfTuples(); ++p)
  {
    pbrReflectivity = std::max(pbrReflectivity, reflectivity->GetComponent(p, 0));
  }
  std::printf("PBR metal, roughness 0, base colour 0.8: %ld traced, reflectivity %.4f\n",
    metal.Traced, pbrReflectivity);
  // F0 = mix(0.04, 0.8, 1) = 0.8, (1 - 0)^2 = 1: 0.8 in RGBA8 is 204 / 255.
  Check(pass->GetLastFrameTraced() && metal.Traced > 1000 &&
      std::abs(pbrReflectivity - 204.0 / 255.0) < 1e-6,
    "a PBR metal reflects with F0 = base colour");
  // The result texture for composite passes.
  vtkTextureUnitManager* units =
    vtkOpenGLRenderWindow::SafeDownCast(window)->GetTextureUnitManager();
  const int unit = pass->ActivateReflectionTexture(renderer);
  const bool bound = unit >= 0 && units->IsAllocated(unit);
  pass->DeactivateReflectionTexture(renderer);
  Check(pass->GetReflectionTextureHandle(renderer) != 0 && bound && !units->IsAllocated(unit),
    "the reflection texture can be activated and deactivated");
  floor->GetProperty()->SetRoughness(1.0);
  window->Render();
  Check(!pass->GetLastFrameTraced() &&
      pass->GetGBufferPass()->GetTextureHandle(renderer, vtkDeepGBufferPass::REFLECTIVITY) == 0,
    "when nothing reflects any more, REFLECTIVITY is freed");
  Check(pass->GetReflectionTextureHandle(renderer) == 0 &&
      pass->ActivateReflectionTexture(renderer) == -1,
    "... and the pass keeps no reflection texture");
}

// Without a reflective prop the pass draws what vtkDeepGBufferPass draws.
void CheckNonReflectiveScenes()
{
  auto window = MakeWindow(160, 120);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.3, 0.3, 0.4);
  window->AddRenderer(renderer);
  vtkActor* floor = BuildScene(renderer, false);
  vtkNew<vtkDeepGBufferPass> plain;
  renderer->SetPass(plain);
  window->Render();
  vtkNew<vtkImageData> plainImage;
  ReadWindow(window, plainImage, nullptr);
  vtkNew<vtkDeepReflectionPass> pass;
  CheckNothingReflectiveDrawsTheGBufferImage(window, renderer, pass, plainImage);
  CheckOnlyReflectiveMaterialsTrace(window, renderer, pass, floor);
  pass->ReleaseGraphicsResources(window);
  plain->ReleaseGraphicsResources(window);
}

// 2. Bad parameters: a warning and a clamped value, and every capture stays
// finite.
void CheckBadParametersAreClamped(vtkRenderWindow* window, vtkRenderer* renderer,
  vtkDeepReflectionPass* pass, EventCounter& warnings)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();

  pass->SetMaximumDistance(nan);
  Check(warnings.Count == 1 && pass->GetAutomaticMaximumDistance(),
    "MaximumDistance NaN: warning, automatic distance kept");
  pass->SetMaximumDistance(-3.0);
  Check(warnings.Count == 2 && pass->GetMaximumDistance() == 0.0, "MaximumDistance -3: warning, 0");
  window->Render();
  vtkNew<vtkImageData> capture;
  Summary s = Summarize(pass, renderer, capture);
  std::printf("MaximumDistance 0: %ld traced, %ld hits\n", s.Traced, s.Hits);
  Check(s.Finite && s.Traced > 1000 && s.Hits == 0,
    "MaximumDistance 0: every ray takes the environment");

  pass->SetNumberOfSteps(0);
  Check(warnings.Count == 3 && pass->GetNumberOfSteps() == 1, "NumberOfSteps 0: warning, 1");
  pass->SetNumberOfSteps(1 << 30);
  Check(warnings.Count == 4 &&
      pass->GetNumberOfSteps() == vtkDeepReflectionPass::MAXIMUM_NUMBER_OF_STEPS,
    "NumberOfSteps 2^30: warning, the maximum");
  pass->SetThickness(inf);
  Check(
    warnings.Count == 5 && pass->GetAutomaticThickness(), "Thickness inf: warning, automatic kept");
  pass->SetThickness(-1.0);
  Check(warnings.Count == 6 && pass->GetThickness() == 0.0, "Thickness -1: warning, 0");
  pass->SetPixelStride(0.0);
  pass->SetPixelStride(nan);
  Check(
    warnings.Count == 8 && pass->GetPixelStride() == 2.0, "PixelStride 0 and NaN: warnings, kept");
  pass->SetPixelStride(1e-9);
  Check(warnings.Count == 9 && pass->GetPixelStride() == 0.01, "PixelStride 1e-9: warning, 0.01");
  pass->SetMaximumDistance(1e30);
  Check(warnings.Count == 9, "MaximumDistance 1e30 is accepted (the frustum cuts the ray)");
  window->Render();
  s = Summarize(pass, renderer, capture);
  std::printf(
    "thickness 0, 1024 steps, 0.01 px, distance 1e30: %ld traced, %ld hits\n", s.Traced, s.Hits);
  Check(s.Finite && s.Traced > 1000, "extreme settings: finite captures");
  pass->SetMaximumDistance(inf);
  pass->AutomaticThicknessOn();
  pass->SetPixelStride(1e6);
  window->Render();
  s = Summarize(pass, renderer, capture);
  std::printf("distance inf, stride 1e6 px: %ld traced, %ld hits, %ld environment\n", s.Traced,
    s.Hits, s.Environment);
  Check(s.Finite && s.Hits > 100, "infinite distance: finite captures and hits");
}

// With the default settings, the wall and sphere are reflected, and the
// debug display of REFLECTIVITY shows white (1) on the mirror, black
// elsewhere. `before` receives the capture.
void CheckDefaultReflectionsAndDisplay(
  vtkRenderWindow* window, vtkRenderer* renderer, vtkDeepReflectionPass* pass, vtkImageData* before)
{
  pass->AutomaticMaximumDistanceOn();
  pass->SetNumberOfSteps(64);
  pass->SetPixelStride(2.0);
  window->Render();
  const Summary s = Summarize(pass, renderer, before);
  Check(s.Finite && s.Hits > 1000, "default settings: the wall and sphere are reflected");

  // The debug display of REFLECTIVITY: white (1) on the mirror, black elsewhere.
  pass->GetGBufferPass()->SetDisplayQuantity(vtkDeepGBufferPass::REFLECTIVITY);
  window->Render();
  vtkNew<vtkImageData> reflectivityImage;
  ReadWindow(window, reflectivityImage, nullptr);
  pass->GetGBufferPass()->SetDisplayQuantity(vtkDeepGBufferPass::RADIANCE);
  long displayOk = 0, displayTraced = 0;
  vtkDataArray* tracedMask = before->GetPointData()->GetArray(vtkDeepGICaptureNames::Valid);
  vtkDataArray* shown = reflectivityImage->GetPointData()->GetScalars();
  for (vtkIdType p = 0; p < tracedMask->GetNumberOfTuples(); ++p)
  {
    const bool traced = tracedMask->GetTuple1(p) != 0;
    displayTraced += traced ? 1 : 0;
    // Reflectivity 1 on the mirror; 0 on the other props and the (black) background.
    const double expected = traced ? 255.0 : 0.0;
    bool ok = true;
    for (int c = 0; c < 3; ++c)
    {
      ok = ok && shown->GetComponent(p, c) == expected;
    }
    displayOk += ok ? 1 : 0;
  }
  std::printf("REFLECTIVITY display: %ld of %ld pixels as expected (%ld traced)\n", displayOk,
    static_cast<long>(tracedMask->GetNumberOfTuples()), displayTraced);
  Check(displayOk == tracedMask->GetNumberOfTuples(),
    "REFLECTIVITY display: 1 on the mirror, 0 elsewhere");
}

// 3. ReleaseGraphicsResources, then render again: the same result; a
// resize reallocates the targets.
void CheckReleaseAndResize(
  vtkRenderWindow* window, vtkRenderer* renderer, vtkDeepReflectionPass* pass, vtkImageData* before)
{
  vtkNew<vtkImageData> after;
  pass->ReleaseGraphicsResources(window);
  window->Render();
  Summarize(pass, renderer, after);
  Check(SameArrays(before, after), "after ReleaseGraphicsResources the same reflections");

  // A resize reallocates the targets.
  window->SetSize(120, 90);
  window->Render();
  vtkNew<vtkImageData> resized;
  const Summary small = Summarize(pass, renderer, resized);
  int smallDims[3];
  resized->GetDimensions(smallDims);
  std::printf("after a resize to 120 x 90: capture %d x %d, %ld hits\n", smallDims[0], smallDims[1],
    small.Hits);
  Check(small.Finite && smallDims[0] == 120 && smallDims[1] == 90 && small.Hits > 500,
    "after a resize the reflections follow the new size");
  window->SetSize(160, 120);
}

// 4. Two renderers sharing the pass: the left one has a mirror, the right one not.
void CheckRenderersKeepTheirOwnReflections(
  vtkRenderWindow* window, vtkRenderer* renderer, vtkDeepReflectionPass* pass)
{
  renderer->SetViewport(0.0, 0.0, 0.5, 1.0);
  vtkNew<vtkRenderer> right;
  right->SetViewport(0.5, 0.0, 1.0, 1.0);
  BuildScene(right, false);
  right->SetPass(pass);
  window->AddRenderer(right);
  window->Render();
  window->Render();
  vtkNew<vtkImageData> leftCapture, rightCapture;
  const Summary l = Summarize(pass, renderer, leftCapture);
  const Summary r = Summarize(pass, right, rightCapture);
  int dims[3];
  leftCapture->GetDimensions(dims);
  std::printf("two renderers: left %dx%d %ld traced %ld hits, right %ld traced\n", dims[0], dims[1],
    l.Traced, l.Hits, r.Traced);
  Check(dims[0] == 80 && dims[1] == 120 && l.Hits > 500 && r.Traced == 0 &&
      rightCapture->GetFieldData()->GetArray(vtkDeepGICaptureNames::Traced)->GetTuple1(0) == 0,
    "each renderer keeps its own reflections");
}
}

int TestDeepReflectionRobustness(int, char*[])
{
  CheckNonReflectiveScenes();

  auto window = MakeWindow(160, 120);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  BuildScene(renderer, true);
  vtkNew<vtkDeepReflectionPass> pass;
  renderer->SetPass(pass);
  EventCounter warnings(pass, vtkCommand::WarningEvent);
  CheckBadParametersAreClamped(window, renderer, pass, warnings);
  vtkNew<vtkImageData> before;
  CheckDefaultReflectionsAndDisplay(window, renderer, pass, before);
  CheckReleaseAndResize(window, renderer, pass, before);
  CheckRenderersKeepTheirOwnReflections(window, renderer, pass);
  Check(warnings.Count == 9, "no further warnings");

  std::ostringstream printed;
  pass->Print(printed);
  Check(printed.str().find("EffectiveThickness") != std::string::npos &&
      printed.str().find("RefinementSteps") != std::string::npos,
    "PrintSelf prints the parameters and the frame's state");
  pass->ReleaseGraphicsResources(window);
  return ExitStatus();
}
