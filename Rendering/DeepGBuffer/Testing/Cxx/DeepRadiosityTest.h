// Scenes and helpers shared by the vtkDeepRadiosityPass tests: lit planes
// and boxes with explicit colours, a frame loop that captures the radiosity
// and the G-buffer layers, and per-pixel accessors.
#ifndef DeepRadiosityTest_h
#define DeepRadiosityTest_h

#include "DeepGBufferTestUtilities.h"

#include "vtkDeepRadiosityPass.h"
#include "vtkLight.h"

#include <functional>

namespace DeepRadiosityTest
{
using namespace DeepGBufferTest;
constexpr double Pi = 3.14159265358979323846;

// Pure diffuse colour: albedo = colour, no ambient or specular term, so the
// G-buffer's radiance is the direct light only.
inline vtkActor* Diffuse(vtkActor* actor, double r, double g, double b)
{
  actor->GetProperty()->SetColor(r, g, b);
  actor->GetProperty()->SetDiffuse(1.0);
  actor->GetProperty()->SetAmbient(0.0);
  actor->GetProperty()->SetSpecular(0.0);
  return actor;
}

// A white directional scene light shining from `from` towards the origin.
inline void AddSun(vtkRenderer* renderer, double x, double y, double z)
{
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->PositionalOff();
  light->SetPosition(x, y, z);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  light->SetIntensity(1.0);
  renderer->AddLight(light);
}

// A white floor y = 0 (x in [0, 4], z in [-3, 3]) beside a red wall x = 0
// (height 2) facing +x; the sun from (3, 4, 1) lights both (cosines 0.78
// and 0.59). Every length times s.
inline void RedWallScene(vtkRenderer* renderer, double s = 1.0)
{
  const double f0[3] = { 0, 0, 3 * s }, f1[3] = { 4 * s, 0, 3 * s }, f2[3] = { 0, 0, -3 * s };
  Diffuse(AddQuad(renderer, f0, f1, f2), 1, 1, 1);
  const double w0[3] = { 0, 0, 3 * s }, w1[3] = { 0, 0, -3 * s }, w2[3] = { 0, 2 * s, 3 * s };
  Diffuse(AddQuad(renderer, w0, w1, w2), 1, 0, 0);
  AddSun(renderer, 3, 4, 1);
  SetCamera(renderer, 5 * s, 2.5 * s, 4 * s, 0.8 * s, 0.4 * s, 0);
}

// RedWallScene with an ambient term of 0.3 on every actor, so that the
// obscurance runs besides the radiosity.
inline void RedWallSceneWithAmbient(vtkRenderer* renderer)
{
  RedWallScene(renderer);
  vtkActorCollection* actors = renderer->GetActors();
  vtkCollectionSimpleIterator it;
  actors->InitTraversal(it);
  while (vtkActor* actor = actors->GetNextActor(it))
  {
    actor->GetProperty()->SetAmbient(0.3);
  }
  renderer->ResetCameraClippingRange();
}

// A white floor y = 0 (x in [0, 4], z in [-3, 3]) and a blue panel x = 2.5
// (y in [0, 1.5], z in [-1, 1]) whose lit face looks +x, AWAY from the
// floor at x < 2.5; the sun from (5, 4, 0.5) lights the floor and that
// face; the camera sees the lit face.
inline void BlueBackScene(vtkRenderer* renderer)
{
  const double f0[3] = { 0, 0, 3 }, f1[3] = { 4, 0, 3 }, f2[3] = { 0, 0, -3 };
  Diffuse(AddQuad(renderer, f0, f1, f2), 1, 1, 1);
  const double b0[3] = { 2.5, 0, 1 }, b1[3] = { 2.5, 0, -1 }, b2[3] = { 2.5, 1.5, 1 };
  Diffuse(AddQuad(renderer, b0, b1, b2), 0, 0, 1);
  AddSun(renderer, 5, 4, 0.5);
  SetCamera(renderer, 6, 4, 5, 1.5, 0.0, 0.0);
}

struct Frame
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkNew<vtkImageData> Radiosity;
  vtkNew<vtkImageData> Layers;
  int Width = 0;
  int Height = 0;
};

using Scene = std::function<void(vtkRenderer*)>;

// Builds `scene` in a new width x height window with `pass`, renders
// `frames` frames and captures the radiosity and the layers. The camera's
// clipping range is reset to the scene, or set to `clippingRange` (near,
// far) when given.
inline bool RenderFrames(const Scene& scene, vtkDeepRadiosityPass* pass, int frames, Frame& f,
  int width = 160, int height = 120, const double* clippingRange = nullptr)
{
  f.Width = width;
  f.Height = height;
  f.Window = MakeWindow(width, height);
  f.Renderer = vtkSmartPointer<vtkRenderer>::New();
  f.Renderer->SetBackground(0.0, 0.0, 0.0);
  f.Window->AddRenderer(f.Renderer);
  scene(f.Renderer);
  if (clippingRange)
  {
    f.Renderer->GetActiveCamera()->SetClippingRange(clippingRange[0], clippingRange[1]);
  }
  else
  {
    f.Renderer->ResetCameraClippingRange();
  }
  f.Renderer->SetPass(pass);
  for (int k = 0; k < frames; ++k)
  {
    f.Window->Render();
  }
  const bool ok = pass->CaptureIrradiance(f.Radiosity, f.Renderer) &&
    pass->GetGBufferPass()->CaptureLayers(f.Layers, f.Renderer);
  DeepGITest::Check(ok, "capture");
  return ok;
}

// Component c of array `name` at pixel (i, j).
inline double At(vtkImageData* image, const std::string& name, int i, int j, int c = 0)
{
  const int w = image->GetDimensions()[0];
  return image->GetPointData()
    ->GetArray(name.c_str())
    ->GetComponent(static_cast<vtkIdType>(j) * w + i, c);
}

// Sum of the RGB components of `name` over every pixel.
inline double Total(vtkImageData* image, const std::string& name)
{
  vtkDataArray* a = image->GetPointData()->GetArray(name.c_str());
  double sum = 0.0;
  for (vtkIdType p = 0; p < a->GetNumberOfTuples(); ++p)
  {
    for (int c = 0; c < a->GetNumberOfComponents(); ++c)
    {
      sum += a->GetComponent(p, c);
    }
  }
  return sum;
}

// Largest component of `name` over every pixel.
inline double Maximum(vtkImageData* image, const std::string& name)
{
  vtkDataArray* a = image->GetPointData()->GetArray(name.c_str());
  double maximum = 0.0;
  for (int c = 0; c < a->GetNumberOfComponents(); ++c)
  {
    maximum = std::max(maximum, a->GetRange(c)[1]);
  }
  return maximum;
}

// Smallest component of `name` over every pixel.
inline double Minimum(vtkImageData* image, const std::string& name)
{
  vtkDataArray* a = image->GetPointData()->GetArray(name.c_str());
  double minimum = 0.0;
  for (int c = 0; c < a->GetNumberOfComponents(); ++c)
  {
    minimum = std::min(minimum, a->GetRange(c)[0]);
  }
  return minimum;
}
}

#endif
