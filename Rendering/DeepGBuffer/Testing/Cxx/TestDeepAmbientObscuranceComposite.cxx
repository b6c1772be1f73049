// The compositions of vtkDeepAmbientObscurancePass on the floor/wall corner
// (240 x 200, r = 1):
// - COMPOSITE_AMBIENT with props of Ambient 0.4 / Diffuse 0.6: every pixel
//   of layer 0 shows radiance - (1 - AV) ambient of the G-buffer's RADIANCE
//   and AMBIENT (captured, float) within 2 of 255 levels (the framebuffer's
//   rounding), and the corner is darkened by more than 5 levels somewhere;
// - COMPOSITE_AMBIENT with VTK's default Ambient = 0: the image equals the
//   plain G-buffer radiance (1 level): direct light is never darkened;
// - COMPOSITE_AUTOMATIC (the default) is AMBIENT (same image, effective
//   composition reported) with Ambient 0.4, and MULTIPLY (image = radiance x
//   AV within 2 levels, darkened by more than 5 levels) with Ambient 0;
// - background pixels keep the background; AV is finite.

#include "DeepGBufferTestUtilities.h"

#include "vtkCamera.h"
#include "vtkDeepAmbientObscurancePass.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"

#include <algorithm>

using namespace DeepGBufferTest;
using namespace DeepGITest;

namespace
{
void AddQuad(
  vtkRenderer* renderer, const double o[3], const double p1[3], const double p2[3], double ambient)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(o[0], o[1], o[2]);
  plane->SetPoint1(p1[0], p1[1], p1[2]);
  plane->SetPoint2(p2[0], p2[1], p2[2]);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.9, 0.8, 0.6);
  actor->GetProperty()->SetAmbient(ambient);
  actor->GetProperty()->SetDiffuse(1.0 - ambient);
  renderer->AddActor(actor);
}

struct CompositeResult
{
  double WorstAmbient = 0.0;  // max |image - (radiance - (1 - AV) ambient)|, levels
  double WorstMultiply = 0.0; // max |image - radiance x AV|, levels
  double Darkening = 0.0;     // max (radiance - image), levels
  long Valid = 0;
  int EffectiveComposition = -1;
};

CompositeResult Run(double ambient, int composition)
{
  CompositeResult result;
  auto window = MakeWindow(240, 200);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.2, 0.3);
  window->AddRenderer(renderer);
  const double f0[3] = { -4, 0, 4 }, f1[3] = { 4, 0, 4 }, f2[3] = { -4, 0, -2 };
  AddQuad(renderer, f0, f1, f2, ambient);
  const double w0[3] = { -4, 0, -2 }, w1[3] = { 4, 0, -2 }, w2[3] = { -4, 4, -2 };
  AddQuad(renderer, w0, w1, w2, ambient);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 2.5, 4.0);
  camera->SetFocalPoint(0.0, 0.3, -1.5);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(40.0);
  renderer->ResetCameraClippingRange();
  vtkNew<vtkDeepAmbientObscurancePass> pass;
  pass->SetRadius(1.0);
  Check(pass->GetComposition() == vtkDeepAmbientObscurancePass::COMPOSITE_AUTOMATIC,
    "the default composition is automatic");
  pass->SetComposition(composition);
  renderer->SetPass(pass);
  for (int i = 0; i < 3; ++i)
  {
    window->Render();
  }
  vtkNew<vtkImageData> ao, layers, rgb;
  Check(pass->CaptureAmbientVisibility(ao, renderer), "capture AV");
  Check(pass->GetGBufferPass()->CaptureLayers(layers, renderer), "capture layers");
  Check(AllFinite(ao), "AV finite");
  ReadWindow(window, rgb, nullptr);
  vtkDataArray* av = ao->GetPointData()->GetArray(vtkDeepGICaptureNames::AmbientVisibility);
  vtkDataArray* ok = ao->GetPointData()->GetArray(vtkDeepGICaptureNames::Valid);
  vtkDataArray* radiance = Layer(layers, vtkDeepGICaptureNames::Radiance, 0);
  vtkDataArray* amb = Layer(layers, vtkDeepGICaptureNames::Ambient, 0);
  vtkDataArray* image = rgb->GetPointData()->GetScalars();
  double background = 0.0;
  const double bg[3] = { 0.1, 0.2, 0.3 };
  for (vtkIdType p = 0; p < image->GetNumberOfTuples(); ++p)
  {
    if (!ok->GetTuple1(p))
    {
      for (int c = 0; c < 3; ++c)
      {
        background = std::max(background, std::abs(image->GetComponent(p, c) - 255.0 * bg[c]));
      }
      continue;
    }
    ++result.Valid;
    const double a = av->GetTuple1(p);
    for (int c = 0; c < 3; ++c)
    {
      const double value = image->GetComponent(p, c);
      const double r = std::min(1.0, std::max(0.0, radiance->GetComponent(p, c)));
      const double e = std::min(
        1.0, std::max(0.0, radiance->GetComponent(p, c) - (1.0 - a) * amb->GetComponent(p, c)));
      result.WorstAmbient = std::max(result.WorstAmbient, std::abs(value - 255.0 * e));
      result.WorstMultiply = std::max(result.WorstMultiply, std::abs(value - 255.0 * r * a));
      result.Darkening = std::max(result.Darkening, 255.0 * r - value);
    }
  }
  result.EffectiveComposition = pass->GetEffectiveComposition();
  std::printf("%s, ambient %.1f: effective %s, %ld px, max |image - (radiance - (1 - AV) "
              "ambient)| = %.2f levels, max |image - radiance AV| = %.2f levels, largest "
              "darkening %.1f levels, background error %.2f\n",
    vtkDeepAmbientObscurancePass::GetCompositionAsString(composition), ambient,
    vtkDeepAmbientObscurancePass::GetCompositionAsString(result.EffectiveComposition), result.Valid,
    result.WorstAmbient, result.WorstMultiply, result.Darkening, background);
  Check(background <= 1.0, "background kept");
  pass->ReleaseGraphicsResources(window);
  return result;
}
}

int TestDeepAmbientObscuranceComposite(int, char*[])
{
  using Pass = vtkDeepAmbientObscurancePass;
  CompositeResult r = Run(0.4, Pass::COMPOSITE_AMBIENT);
  Check(r.Valid > 1000 && r.WorstAmbient <= 2.0, "image = radiance - (1 - AV) ambient");
  Check(r.Darkening > 5.0, "the ambient term is darkened near the corner");
  Check(r.EffectiveComposition == Pass::COMPOSITE_AMBIENT, "AMBIENT reported");
  r = Run(0.0, Pass::COMPOSITE_AMBIENT);
  Check(r.Valid > 1000 && r.WorstAmbient <= 2.0 && r.Darkening <= 1.0,
    "Ambient = 0: the plain radiance");
  r = Run(0.4, Pass::COMPOSITE_AUTOMATIC);
  Check(
    r.EffectiveComposition == Pass::COMPOSITE_AMBIENT && r.WorstAmbient <= 2.0 && r.Darkening > 5.0,
    "automatic with an ambient term: the ambient composition");
  r = Run(0.0, Pass::COMPOSITE_AUTOMATIC);
  Check(r.EffectiveComposition == Pass::COMPOSITE_MULTIPLY && r.WorstMultiply <= 2.0 &&
      r.Darkening > 5.0,
    "automatic without an ambient term: radiance x AV");
  return ExitStatus();
}
