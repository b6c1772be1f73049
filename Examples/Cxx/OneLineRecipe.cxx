/**
 * OneLineRecipe [gi.png [plain.png]]: global illumination on a default VTK
 * scene, a sphere resting on a plane, through vtkDeepGIPass put on the
 * renderer in one line; writes the converged image as a PNG. plain.png, when
 * given, is the same scene rendered by VTK without the pass, to compare: the
 * pass darkens where the sphere touches the plane and lights the sphere's
 * underside with the light the plane reflects.
 */

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDeepGIPass.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkWindowToImageFilter.h"

namespace
{
void WritePNG(vtkRenderWindow* window, const char* fileName)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff(); // the image just rendered, not one more frame
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(fileName);
  writer->Write();
}
}

int main(int argc, char* argv[])
{
  // The scene: a sphere of radius 0.5 at the origin on a 4 x 4 plane whose
  // normal points up, with VTK's default actors, lights and background.
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(32);
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-2, -0.5, 2);
  plane->SetPoint1(2, -0.5, 2);
  plane->SetPoint2(-2, -0.5, -2);
  vtkNew<vtkRenderer> renderer;
  vtkPolyDataAlgorithm* sources[] = { sphere, plane };
  for (vtkPolyDataAlgorithm* source : sources)
  {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(source->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    renderer->AddActor(actor);
  }
  // Aimed at the point of contact, at the centre of the image.
  renderer->GetActiveCamera()->SetFocalPoint(0, -0.5, 0);
  renderer->GetActiveCamera()->SetPosition(0, 1.2, 4.5);
  renderer->ResetCameraClippingRange();

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(400, 300);
  window->AddRenderer(renderer);
  if (argc > 2)
  {
    window->Render();
    WritePNG(window, argv[2]);
  }

  vtkNew<vtkDeepGIPass> gi;
  renderer->SetPass(gi); // the one line
  // A still image: frames at this camera until one no longer changes it
  // (each adds a bounce of light), at most 16.
  gi->Converge(renderer, 16, 0.07 / 255);
  WritePNG(window, argc > 1 ? argv[1] : "gi.png");
  return 0;
}
