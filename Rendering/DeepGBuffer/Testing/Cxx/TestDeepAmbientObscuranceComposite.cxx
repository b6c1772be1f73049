// COMPOSITE_AMBIENT of vtkDeepAmbientObscurancePass on the floor/wall corner
// (240 x 200, r = 1):
// - with props of Ambient 0.4 / Diffuse 0.6, every pixel of layer 0 shows
//   radiance - (1 - AV) ambient of the G-buffer's RADIANCE and AMBIENT
//   (captured, float) within 2 of 255 levels (the framebuffer's rounding),
//   and the corner is darkened by more than 5 levels somewhere;
// - with VTK's default Ambient = 0 the image equals the plain G-buffer
//   radiance (1 level): direct light is never darkened;
// - background pixels keep the background; AV is finite.

#include "DeepGBufferTestUtilities.h"

#include "vtkCamera.h"
#include "vtkDeepAmbientObscurancePass.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"

#include <algorithm>

using namespace DeepGBufferTest;

namespace
{
void AddQuad(vtkRenderer* renderer, const double o[3], const double p1[3], const double p2[3],
  double ambient)
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

// Returns the worst |image - expected| in levels and the largest darkening
// (radiance - image) in levels.
void Run(double ambient, double& worst, double& darkening, long& valid)
{
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
  pass->SetCompositionToAmbient();
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
  vtkDataArray* av = ao->GetPointData()->GetArray("AmbientVisibility");
  vtkDataArray* ok = ao->GetPointData()->GetArray("Valid");
  vtkDataArray* radiance = Layer(layers, "Radiance", 0);
  vtkDataArray* amb = Layer(layers, "Ambient", 0);
  vtkDataArray* image = rgb->GetPointData()->GetScalars();
  worst = darkening = 0.0;
  valid = 0;
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
    ++valid;
    for (int c = 0; c < 3; ++c)
    {
      const double r = std::min(1.0, std::max(0.0, radiance->GetComponent(p, c)));
      const double e = std::min(1.0,
        std::max(0.0, radiance->GetComponent(p, c) - (1.0 - av->GetTuple1(p)) * amb->GetComponent(p, c)));
      worst = std::max(worst, std::abs(image->GetComponent(p, c) - 255.0 * e));
      darkening = std::max(darkening, 255.0 * r - image->GetComponent(p, c));
    }
  }
  std::printf("ambient %.1f: %ld px, max |image - (radiance - (1 - AV) ambient)| = %.2f levels, "
              "largest darkening %.1f levels, background error %.2f\n",
    ambient, valid, worst, darkening, background);
  Check(background <= 1.0, "background kept");
  pass->ReleaseGraphicsResources(window);
}
}

int TestDeepAmbientObscuranceComposite(int, char*[])
{
  double worst, darkening;
  long valid;
  Run(0.4, worst, darkening, valid);
  Check(valid > 1000 && worst <= 2.0, "image = radiance - (1 - AV) ambient");
  Check(darkening > 5.0, "the ambient term is darkened near the corner");
  Run(0.0, worst, darkening, valid);
  Check(valid > 1000 && worst <= 2.0 && darkening <= 1.0, "Ambient = 0: the plain radiance");
  std::printf("%s\n", CheckFailures() ? "FAILED" : "passed");
  return CheckFailures() ? 1 : 0;
}
