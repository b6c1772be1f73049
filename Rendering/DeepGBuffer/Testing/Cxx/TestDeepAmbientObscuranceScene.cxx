// vtkDeepAmbientObscurancePass in a VTK scene with subplots, several
// renderers, a surface extracted from a volume, volume rendering and a
// translucent prop. One pass instance is set on two renderers that split a
// 400 x 200 window into two 200 x 200 viewports:
// - left: the iso-surface (vtkFlyingEdges3D, value 160) of VTK's wavelet
//   source, the same wavelet volume-rendered (vtkSmartVolumeMapper, a faint
//   transfer function) and an opaque quad in front of part of both;
// - right: a floor/wall corner and a translucent sphere (opacity 0.4).
// Both use dz = 0.64 (about the automatic value). Expectations:
// - each renderer's AV equals the AV of the same opaque props rendered alone
//   in a 200 x 200 window without the volume and the sphere (mean difference
//   <= 1e-4, max <= 0.02: the default estimator's sectors turn float
//   rounding of the inputs, about 2e-5, into a whole sector at a few
//   pixels): viewports, per-renderer state and the translucent/volumetric
//   steps do not disturb the obscurance;
// - the AV of both renderers shows obscurance (minimum < 0.8) and is finite;
// - the volume changes more than 5 % of the left viewport's pixels, none of
//   the right viewport's, and none of the pixels covered by the opaque quad
//   (it is composited against layer 0's depth);
// - the sphere changes more than 2 % of the right viewport's pixels and none
//   of the left viewport's;
// - no error events from either pass.

#include "DeepGBufferTestUtilities.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDeepAmbientObscurancePass.h"
#include "vtkDeepGBufferPass.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkFlyingEdges3D.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlaneSource.h"
#include "vtkRTAnalyticSource.h"
#include "vtkSmartVolumeMapper.h"
#include "vtkSphereSource.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <functional>

using namespace DeepGBufferTest;
using namespace DeepGITest;

namespace
{
constexpr int ViewportSize = 200;

struct SceneParts
{
  vtkSmartPointer<vtkVolume> Volume;
  vtkSmartPointer<vtkActor> Sphere;
};

vtkActor* AddQuad(vtkRenderer* renderer, const double o[3], const double p1[3], const double p2[3])
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(o[0], o[1], o[2]);
  plane->SetPoint1(p1[0], p1[1], p1[2]);
  plane->SetPoint2(p2[0], p2[1], p2[2]);
  return AddSourceActor(renderer, plane);
}

// The left scene: iso-surface, occluding quad and (optionally) the volume.
void BuildVolumeScene(vtkRenderer* renderer, SceneParts* parts)
{
  vtkNew<vtkRTAnalyticSource> wavelet;
  wavelet->SetWholeExtent(-10, 10, -10, 10, -10, 10);
  vtkNew<vtkFlyingEdges3D> iso;
  iso->SetInputConnection(wavelet->GetOutputPort());
  iso->SetValue(0, 160.0);
  iso->ComputeNormalsOn();
  AddSourceActor(renderer, iso)->GetProperty()->SetColor(0.9, 0.85, 0.8);
  // An opaque quad in front of the lower part of the view.
  const double o[3] = { -14, -14, 12 }, p1[3] = { 14, -14, 12 }, p2[3] = { -14, -6, 12 };
  AddQuad(renderer, o, p1, p2)->GetProperty()->SetColor(0.3, 0.5, 0.8);
  if (parts)
  {
    vtkNew<vtkSmartVolumeMapper> mapper;
    mapper->SetInputConnection(wavelet->GetOutputPort());
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(37.0, 0.0);
    opacity->AddPoint(120.0, 0.0);
    opacity->AddPoint(276.0, 0.08);
    vtkNew<vtkColorTransferFunction> color;
    color->AddRGBPoint(37.0, 1.0, 0.2, 0.1);
    color->AddRGBPoint(276.0, 1.0, 0.9, 0.2);
    vtkNew<vtkVolumeProperty> property;
    property->SetScalarOpacity(opacity);
    property->SetColor(color);
    property->SetInterpolationTypeToLinear();
    parts->Volume = vtkSmartPointer<vtkVolume>::New();
    parts->Volume->SetMapper(mapper);
    parts->Volume->SetProperty(property);
    renderer->AddVolume(parts->Volume);
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 0.0, 45.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(40.0);
  renderer->ResetCameraClippingRange();
}

// The right scene: the floor/wall corner and (optionally) a translucent sphere.
void BuildCornerScene(vtkRenderer* renderer, SceneParts* parts)
{
  const double f0[3] = { -4, 0, 4 }, f1[3] = { 4, 0, 4 }, f2[3] = { -4, 0, -2 };
  AddQuad(renderer, f0, f1, f2)->GetProperty()->SetColor(0.9, 0.8, 0.6);
  const double w0[3] = { -4, 0, -2 }, w1[3] = { 4, 0, -2 }, w2[3] = { -4, 4, -2 };
  AddQuad(renderer, w0, w1, w2)->GetProperty()->SetColor(0.9, 0.8, 0.6);
  if (parts)
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(0.5, 1.0, 0.5);
    sphere->SetRadius(0.8);
    sphere->SetThetaResolution(32);
    sphere->SetPhiResolution(16);
    parts->Sphere = AddSourceActor(renderer, sphere);
    parts->Sphere->GetProperty()->SetColor(0.2, 0.9, 0.3);
    parts->Sphere->GetProperty()->SetOpacity(0.4);
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 2.5, 4.0);
  camera->SetFocalPoint(0.0, 0.3, -1.5);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(40.0);
  renderer->ResetCameraClippingRange();
}

void Configure(vtkDeepAmbientObscurancePass* pass)
{
  pass->SetRadius(2.0);
  pass->SetCompositionToMultiply();
  // The automatic dz follows the visible props' bounds, which the volume
  // widens; with back faces in layer 1 (the obscurance's default) the
  // iso-surface's AV depends on dz, so both renders use the same.
  pass->GetGBufferPass()->SetMinimumSeparation(0.64);
}

// AV of `build`'s opaque props alone, in a window of the viewport's size.
vtkSmartPointer<vtkImageData> RenderAlone(const std::function<void(vtkRenderer*)>& build)
{
  auto window = MakeWindow(ViewportSize, ViewportSize);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  build(renderer);
  vtkNew<vtkDeepAmbientObscurancePass> pass;
  Configure(pass);
  renderer->SetPass(pass);
  for (int i = 0; i < 3; ++i)
  {
    window->Render();
  }
  auto av = vtkSmartPointer<vtkImageData>::New();
  Check(pass->CaptureAmbientVisibility(av, renderer), "capture AV alone");
  pass->ReleaseGraphicsResources(window);
  return av;
}

struct Difference
{
  double Maximum = VTK_DOUBLE_MAX;
  double Mean = VTK_DOUBLE_MAX;
};

Difference Compare(vtkImageData* a, vtkImageData* b, const char* name)
{
  vtkDataArray* x = a->GetPointData()->GetArray(name);
  vtkDataArray* y = b->GetPointData()->GetArray(name);
  Difference d;
  if (!x || !y || x->GetNumberOfTuples() != y->GetNumberOfTuples() || x->GetNumberOfTuples() == 0)
  {
    return d;
  }
  double maximum = 0.0, sum = 0.0;
  for (vtkIdType p = 0; p < x->GetNumberOfTuples(); ++p)
  {
    const double e = std::abs(x->GetTuple1(p) - y->GetTuple1(p));
    maximum = std::max(maximum, e);
    sum += e;
  }
  d.Maximum = maximum;
  d.Mean = sum / x->GetNumberOfTuples();
  return d;
}

double MinimumValue(vtkImageData* image, const char* name)
{
  double range[2];
  image->GetPointData()->GetArray(name)->GetRange(range);
  return range[0];
}

// Pixels whose colour differs by more than 2 levels, counted in the left
// and right halves of the window; `masked` pixels (left half only) are
// counted separately.
struct ChangeCount
{
  long Left = 0, Right = 0, Masked = 0;
};

ChangeCount CountChanges(vtkImageData* a, vtkImageData* b, const std::vector<bool>& masked)
{
  ChangeCount count;
  vtkDataArray* x = a->GetPointData()->GetScalars();
  vtkDataArray* y = b->GetPointData()->GetScalars();
  const int width = a->GetDimensions()[0];
  for (vtkIdType p = 0; p < x->GetNumberOfTuples(); ++p)
  {
    double difference = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      difference = std::max(difference, std::abs(x->GetComponent(p, c) - y->GetComponent(p, c)));
    }
    if (difference <= 2.0)
    {
      continue;
    }
    if (p % width >= ViewportSize)
    {
      ++count.Right;
    }
    else if (masked[p])
    {
      ++count.Masked;
    }
    else
    {
      ++count.Left;
    }
  }
  return count;
}
}

int TestDeepAmbientObscuranceScene(int, char*[])
{
  auto window = MakeWindow(2 * ViewportSize, ViewportSize);
  vtkNew<vtkRenderer> left, right;
  left->SetViewport(0.0, 0.0, 0.5, 1.0);
  right->SetViewport(0.5, 0.0, 1.0, 1.0);
  right->SetBackground(0.2, 0.2, 0.25);
  window->AddRenderer(left);
  window->AddRenderer(right);
  SceneParts parts;
  BuildVolumeScene(left, &parts);
  BuildCornerScene(right, &parts);

  vtkNew<vtkDeepAmbientObscurancePass> pass;
  Configure(pass);
  EventCounter errors(pass, vtkCommand::ErrorEvent);
  EventCounter gbufferErrors(pass->GetGBufferPass(), vtkCommand::ErrorEvent);
  left->SetPass(pass);
  right->SetPass(pass);

  // Images with and without the volume and the sphere, same cameras.
  auto render = [&](bool volume, bool sphere)
  {
    parts.Volume->SetVisibility(volume);
    parts.Sphere->SetVisibility(sphere);
    for (int i = 0; i < 3; ++i)
    {
      window->Render();
    }
    auto rgb = vtkSmartPointer<vtkImageData>::New();
    ReadWindow(window, rgb, nullptr);
    return rgb;
  };
  auto plain = render(false, false);
  auto withVolume = render(true, false);
  auto withSphere = render(false, true);
  auto full = render(true, true);

  vtkNew<vtkImageData> leftAV, rightAV, layers;
  Check(pass->CaptureAmbientVisibility(leftAV, left), "capture left AV");
  Check(pass->CaptureAmbientVisibility(rightAV, right), "capture right AV");
  Check(AllFinite(leftAV) && AllFinite(rightAV), "AV finite");
  const int* dims = leftAV->GetDimensions();
  Check(dims[0] == ViewportSize && dims[1] == ViewportSize, "AV has the viewport's size");

  // Pixels of the opaque quad: its albedo in layer 0 of the left renderer.
  Check(pass->GetGBufferPass()->CaptureLayers(layers, left), "capture left layers");
  vtkDataArray* albedo = Layer(layers, vtkDeepGICaptureNames::Albedo, 0);
  std::vector<bool> masked(static_cast<size_t>(2 * ViewportSize * ViewportSize), false);
  long quadPixels = 0;
  for (int y = 0; y < ViewportSize; ++y)
  {
    for (int x = 0; x < ViewportSize; ++x)
    {
      const vtkIdType p = y * ViewportSize + x;
      if (std::abs(albedo->GetComponent(p, 0) - 0.3) < 0.02 &&
        std::abs(albedo->GetComponent(p, 2) - 0.8) < 0.02)
      {
        masked[static_cast<size_t>(y * 2 * ViewportSize + x)] = true;
        ++quadPixels;
      }
    }
  }

  auto leftAlone = RenderAlone([](vtkRenderer* r) { BuildVolumeScene(r, nullptr); });
  auto rightAlone = RenderAlone([](vtkRenderer* r) { BuildCornerScene(r, nullptr); });
  const Difference leftDifference =
    Compare(leftAV, leftAlone, vtkDeepGICaptureNames::AmbientVisibility);
  const Difference rightDifference =
    Compare(rightAV, rightAlone, vtkDeepGICaptureNames::AmbientVisibility);
  std::printf("AV vs the same opaque props alone: left max %.2g mean %.2g, right max %.2g mean "
              "%.2g; minimum AV left %.3f, right %.3f\n",
    leftDifference.Maximum, leftDifference.Mean, rightDifference.Maximum, rightDifference.Mean,
    MinimumValue(leftAV, vtkDeepGICaptureNames::AmbientVisibility),
    MinimumValue(rightAV, vtkDeepGICaptureNames::AmbientVisibility));
  Check(leftDifference.Mean <= 1e-4 && leftDifference.Maximum <= 0.02,
    "left AV equals the iso-surface's AV alone");
  Check(rightDifference.Mean <= 1e-4 && rightDifference.Maximum <= 0.02,
    "right AV equals the corner's AV alone");
  Check(MinimumValue(leftAV, vtkDeepGICaptureNames::AmbientVisibility) < 0.8 &&
      MinimumValue(rightAV, vtkDeepGICaptureNames::AmbientVisibility) < 0.8,
    "both renderers show obscurance");

  const long viewportPixels = ViewportSize * ViewportSize;
  const ChangeCount volume = CountChanges(plain, withVolume, masked);
  const ChangeCount sphere = CountChanges(plain, withSphere, masked);
  const ChangeCount both = CountChanges(withVolume, full, masked);
  std::printf("volume changes %ld left px (of %ld), %ld right px, %ld of %ld quad px; sphere "
              "changes %ld right px, %ld left px; sphere over volume frame: %ld right px\n",
    volume.Left, viewportPixels - quadPixels, volume.Right, volume.Masked, quadPixels, sphere.Right,
    sphere.Left + sphere.Masked, both.Right);
  Check(quadPixels > viewportPixels / 20, "the opaque quad covers part of the left view");
  Check(volume.Left > viewportPixels / 20, "the volume is drawn");
  Check(volume.Right == 0, "the volume stays in its viewport");
  Check(volume.Masked == 0, "the volume is hidden behind the opaque quad");
  Check(sphere.Right > viewportPixels / 50, "the translucent sphere is drawn");
  Check(sphere.Left + sphere.Masked == 0, "the sphere stays in its viewport");
  Check(both.Right == sphere.Right, "the sphere is drawn the same with the volume present");
  Check(errors.Count == 0 && gbufferErrors.Count == 0, "no errors");
  pass->ReleaseGraphicsResources(window);
  return ExitStatus();
}
