// Helpers shared by the deep G-buffer tests: windows, scenes and numeric
// measurements on captured layers (reported through DeepGITestChecks.h).
#ifndef DeepGBufferTestUtilities_h
#define DeepGBufferTestUtilities_h

#include "DeepGITestChecks.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkCubeSource.h"
#include "vtkDataArray.h"
#include "vtkDeepGBufferPass.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIDemoScene.h"
#include "vtkDeepGIRenderWindowFactory.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkImageActor.h"
#include "vtkImageData.h"
#include "vtkImageProperty.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSmartVolumeMapper.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace DeepGBufferTest
{
// Adds an actor drawing `source`'s output with default properties.
inline vtkActor* AddSourceActor(vtkRenderer* renderer, vtkAlgorithm* source)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  return actor;
}

// Adds a quad (vtkPlaneSource from origin to p1 and p2; its normal is
// (p1 - origin) x (p2 - origin)) with default properties.
inline vtkActor* AddQuad(
  vtkRenderer* renderer, const double origin[3], const double p1[3], const double p2[3])
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(origin[0], origin[1], origin[2]);
  plane->SetPoint1(p1[0], p1[1], p1[2]);
  plane->SetPoint2(p2[0], p2[1], p2[2]);
  return AddSourceActor(renderer, plane);
}

// Adds an axis-aligned box with default properties.
inline vtkActor* AddBox(vtkRenderer* renderer, const double center[3], const double size[3])
{
  vtkNew<vtkCubeSource> cube;
  cube->SetCenter(center[0], center[1], center[2]);
  cube->SetXLength(size[0]);
  cube->SetYLength(size[1]);
  cube->SetZLength(size[2]);
  return AddSourceActor(renderer, cube);
}

// Populates `renderer` with the demo scene (vtkDeepGIDemoScene) of
// about `triangles` triangles, seen from its default view.
inline bool AddDemoScene(vtkRenderer* renderer, int triangles = 20000)
{
  vtkNew<vtkDeepGIDemoScene> scene;
  scene->SetTargetNumberOfTriangles(triangles);
  scene->Populate(renderer);
  scene->SetCameraToDefaultView(renderer->GetActiveCamera());
  renderer->ResetCameraClippingRange();
  return true;
}

// A corner: floor y = 0 (x in [-4, 4], z in [-2, 4]) and wall z = -2 (height
// 4), optionally a 1 x 1.5 x 1 box in front of the wall (two layers where
// the box hides the floor and the wall), seen from (0, 2.5, 4) at 40 degrees.
inline void AddCornerScene(vtkRenderer* renderer, bool box)
{
  const double floor[3][3] = { { -4, 0, 4 }, { 4, 0, 4 }, { -4, 0, -2 } };
  AddQuad(renderer, floor[0], floor[1], floor[2]);
  const double wall[3][3] = { { -4, 0, -2 }, { 4, 0, -2 }, { -4, 4, -2 } };
  AddQuad(renderer, wall[0], wall[1], wall[2]);
  if (box)
  {
    const double center[3] = { 0.5, 0.75, 0.0 }, size[3] = { 1.0, 1.5, 1.0 };
    AddBox(renderer, center, size);
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 2.5, 4.0);
  camera->SetFocalPoint(0.0, 0.3, -1.5);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(40.0);
}

// Draws the bone of a CT volume (headsq: values above 1000) in `volume`
// through vtkSmartVolumeMapper: transparent up to 1000, `boneColor` at 1150
// turning white at 3926, opacity `opacity` at 1400 rising to twice that at
// 3926. Returns the mapper.
inline vtkSmartVolumeMapper* ShowBone(
  vtkVolume* volume, vtkAlgorithm* reader, const double boneColor[3], double opacity)
{
  vtkNew<vtkSmartVolumeMapper> mapper;
  mapper->SetInputConnection(reader->GetOutputPort());
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.0, 0.0, 0.0);
  color->AddRGBPoint(1150.0, boneColor[0], boneColor[1], boneColor[2]);
  color->AddRGBPoint(3926.0, 1.0, 1.0, 1.0);
  vtkNew<vtkPiecewiseFunction> opacities;
  opacities->AddPoint(0.0, 0.0);
  opacities->AddPoint(1000.0, 0.0);
  opacities->AddPoint(1400.0, opacity);
  opacities->AddPoint(3926.0, 2.0 * opacity);
  volume->SetMapper(mapper);
  volume->GetProperty()->SetColor(color);
  volume->GetProperty()->SetScalarOpacity(opacities);
  return mapper;
}

// A camera at p looking at f, y up, 40 degree view angle (parallel scale 3).
inline void SetCamera(vtkRenderer* renderer, double px, double py, double pz, double fx, double fy,
  double fz, bool parallel = false)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(px, py, pz);
  camera->SetFocalPoint(fx, fy, fz);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(40.0);
  camera->SetParallelProjection(parallel);
  camera->SetParallelScale(3.0);
}

// An offscreen window without multisampling, so images are deterministic:
// X11 when a display answers, else the project's EGL window.
inline vtkSmartPointer<vtkRenderWindow> MakeWindow(int width, int height)
{
  auto window = vtkSmartPointer<vtkRenderWindow>::Take(
    vtkDeepGIRenderWindowFactory::NewRenderWindow(vtkDeepGIRenderWindowFactory::BACKEND_AUTO));
  if (!window)
  {
    std::printf("no render window could be created\n");
    std::exit(EXIT_FAILURE);
  }
  window->SetMultiSamples(0);
  window->SetSize(width, height);
  return window;
}

// True if every value of every point-data array is finite.
inline bool AllFinite(vtkImageData* image)
{
  vtkPointData* pd = image->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t)
    {
      for (int c = 0; c < array->GetNumberOfComponents(); ++c)
      {
        if (!std::isfinite(array->GetComponent(t, c)))
        {
          std::printf(
            "non-finite value in %s at %lld\n", array->GetName(), static_cast<long long>(t));
          return false;
        }
      }
    }
  }
  return true;
}

inline vtkDataArray* Layer(vtkImageData* image, const char* quantity, int layer)
{
  return image->GetPointData()->GetArray(
    (std::string(quantity) + "_" + std::to_string(layer)).c_str());
}

// Camera-space position of the centre of texel (floor(i), floor(j)) of
// layer `layer` of a vtkDeepGBufferPass::CaptureLayers image, reconstructed
// from its depth and ProjectionMatrix as the shaders do; false where empty.
inline bool CameraPosition(vtkImageData* layers, int layer, double i, double j, double out[3])
{
  const int* dims = layers->GetDimensions();
  const int ii = static_cast<int>(std::floor(i)), jj = static_cast<int>(std::floor(j));
  const double d = Layer(layers, vtkDeepGICaptureNames::Depth, layer)
                     ->GetTuple1(static_cast<vtkIdType>(jj) * dims[0] + ii);
  if (!(d > 0.0))
  {
    return false;
  }
  const double* P = vtkDoubleArray::SafeDownCast(
    layers->GetFieldData()->GetArray(vtkDeepGICaptureNames::ProjectionMatrix))
                      ->GetPointer(0);
  const double ndc[2] = { (ii + 0.5) / dims[0] * 2.0 - 1.0, (jj + 0.5) / dims[1] * 2.0 - 1.0 };
  const double z = -d, w = P[14] * z + P[15];
  out[0] = (ndc[0] * w - P[2] * z - P[3]) / P[0];
  out[1] = (ndc[1] * w - P[6] * z - P[7]) / P[5];
  out[2] = z;
  return true;
}

// World position of texel (i, j) of layer `layer` (CameraPosition through
// the inverse of the capture's ViewMatrix); false where empty.
inline bool WorldPosition(vtkImageData* layers, int layer, int i, int j, double world[3])
{
  double c[4] = { 0, 0, 0, 1 };
  if (!CameraPosition(layers, layer, i, j, c))
  {
    return false;
  }
  vtkNew<vtkMatrix4x4> view;
  view->DeepCopy(vtkDoubleArray::SafeDownCast(
    layers->GetFieldData()->GetArray(vtkDeepGICaptureNames::ViewMatrix))
                   ->GetPointer(0));
  view->Invert();
  double out[4];
  view->MultiplyPoint(c, out);
  for (int k = 0; k < 3; ++k)
  {
    world[k] = out[k] / out[3];
  }
  return true;
}

struct SeparationReport
{
  long Pixels = 0;            // valid pixels of layer j
  long Violations = 0;        // valid pixels of layer j closer than dz behind layer j - 1
  double WorstExcess = 1e300; // min over pixels of depth_j - depth_{j-1} - dz
};

// Every valid pixel of layer j must lie at least dz behind layer j - 1
// (up to `relativeTolerance` of its depth: the float arithmetic of the test).
inline SeparationReport CheckSeparation(
  vtkImageData* image, int layer, double dz, double relativeTolerance)
{
  SeparationReport report;
  vtkDataArray* front = Layer(image, vtkDeepGICaptureNames::Depth, layer - 1);
  vtkDataArray* back = Layer(image, vtkDeepGICaptureNames::Depth, layer);
  vtkDataArray* frontValid = Layer(image, vtkDeepGICaptureNames::Valid, layer - 1);
  vtkDataArray* backValid = Layer(image, vtkDeepGICaptureNames::Valid, layer);
  for (vtkIdType p = 0; p < back->GetNumberOfTuples(); ++p)
  {
    if (backValid->GetTuple1(p) == 0)
    {
      continue;
    }
    ++report.Pixels;
    const double d1 = back->GetTuple1(p);
    const double d0 = frontValid->GetTuple1(p) ? front->GetTuple1(p) : -1e300;
    const double excess = d1 - d0 - dz;
    report.WorstExcess = std::min(report.WorstExcess, excess);
    if (frontValid->GetTuple1(p) == 0 || excess < -relativeTolerance * d1)
    {
      ++report.Violations;
    }
  }
  return report;
}

struct LayerDifference
{
  long Compared = 0;        // pixels valid in either capture
  long MaskMismatches = 0;  // valid in one capture only
  long DepthMismatches = 0; // valid in both, depths differ beyond the tolerance
  long Ties = 0;            // differing pixels whose surface lies within rounding of d0 + dz
  long Different() const { return this->MaskMismatches + this->DepthMismatches; }
  double Fraction() const
  {
    return this->Compared ? static_cast<double>(this->Different()) / this->Compared : 0.0;
  }
};

// Compares layer j of two captures pixel by pixel. With dz >= 0, a pixel
// where either capture's layer-j surface lies within `relativeTolerance` of
// the separation threshold (layer j - 1 of `b` plus dz) is a tie: the two
// captures computed the same comparison with different rounding, so it is
// counted in Ties, not as a difference. `different` (optional) receives 1
// where they differ.
inline LayerDifference CompareLayer(vtkImageData* a, vtkImageData* b, int layer,
  double relativeTolerance, std::vector<unsigned char>* different = nullptr, double dz = -1.0)
{
  LayerDifference d;
  vtkDataArray* da = Layer(a, vtkDeepGICaptureNames::Depth, layer);
  vtkDataArray* db = Layer(b, vtkDeepGICaptureNames::Depth, layer);
  vtkDataArray* va = Layer(a, vtkDeepGICaptureNames::Valid, layer);
  vtkDataArray* vb = Layer(b, vtkDeepGICaptureNames::Valid, layer);
  vtkDataArray* front = layer > 0 ? Layer(b, vtkDeepGICaptureNames::Depth, layer - 1) : nullptr;
  if (different)
  {
    different->assign(da->GetNumberOfTuples(), 0);
  }
  for (vtkIdType p = 0; p < da->GetNumberOfTuples(); ++p)
  {
    const bool inA = va->GetTuple1(p) != 0, inB = vb->GetTuple1(p) != 0;
    if (!inA && !inB)
    {
      continue;
    }
    ++d.Compared;
    const bool maskMismatch = inA != inB;
    const bool depthMismatch = !maskMismatch &&
      std::abs(da->GetTuple1(p) - db->GetTuple1(p)) >
        relativeTolerance * std::abs(db->GetTuple1(p));
    if (!maskMismatch && !depthMismatch)
    {
      continue;
    }
    if (dz >= 0.0 && front)
    {
      const double threshold = front->GetTuple1(p) + dz;
      auto nearThreshold = [&](double depth)
      { return std::abs(depth - threshold) <= relativeTolerance * depth; };
      if ((inA && nearThreshold(da->GetTuple1(p))) || (inB && nearThreshold(db->GetTuple1(p))))
      {
        ++d.Ties;
        continue;
      }
    }
    (maskMismatch ? d.MaskMismatches : d.DepthMismatches)++;
    if (different)
    {
      (*different)[p] = 1;
    }
  }
  return d;
}

// Counts the events (vtkCommand::WarningEvent, ErrorEvent) an object emits;
// observed messages are not printed.
struct EventCounter
{
  int Count = 0;
  vtkNew<vtkCallbackCommand> Callback;
  EventCounter(vtkObject* object, unsigned long event)
  {
    this->Callback->SetClientData(this);
    this->Callback->SetCallback([](vtkObject*, unsigned long, void* self, void*)
      { ++static_cast<EventCounter*>(self)->Count; });
    object->AddObserver(event, this->Callback);
  }
};

// Whether two images hold the same point-data arrays with bit-identical
// values (e.g. two vtkDeepGBufferPass::CaptureLayers images); the first
// difference is printed.
inline bool SameArrays(vtkImageData* a, vtkImageData* b)
{
  vtkPointData* pa = a->GetPointData();
  vtkPointData* pb = b->GetPointData();
  if (pa->GetNumberOfArrays() != pb->GetNumberOfArrays() || pa->GetNumberOfArrays() == 0)
  {
    return false;
  }
  for (int k = 0; k < pa->GetNumberOfArrays(); ++k)
  {
    vtkDataArray* x = pa->GetArray(k);
    vtkDataArray* y = pb->GetArray(x->GetName());
    if (!y || x->GetNumberOfValues() != y->GetNumberOfValues())
    {
      return false;
    }
    for (vtkIdType v = 0; v < x->GetNumberOfValues(); ++v)
    {
      if (x->GetVariantValue(v) != y->GetVariantValue(v))
      {
        std::printf("  %s differs at value %lld\n", x->GetName(), static_cast<long long>(v));
        return false;
      }
    }
  }
  return true;
}

// Largest per-channel difference (0..255) between two RGB images.
inline double MaximumColorDifference(vtkImageData* a, vtkImageData* b)
{
  vtkDataArray* x = a->GetPointData()->GetScalars();
  vtkDataArray* y = b->GetPointData()->GetScalars();
  double maximum = 0.0;
  for (vtkIdType p = 0; p < x->GetNumberOfTuples(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      maximum = std::max(maximum, std::abs(x->GetComponent(p, c) - y->GetComponent(p, c)));
    }
  }
  return maximum;
}

// Compares the window with the test's baseline image (-V on the command
// line) as one check. The threshold is VTK 9.1's summed metric (see
// VTK91-NOTES.md), chosen per test.
inline bool CheckRegressionImage(int argc, char* argv[], vtkRenderWindow* window, double threshold)
{
  const int result = vtkRegressionTester::Test(argc, argv, window, threshold);
  return DeepGITest::Check(result == vtkRegressionTester::PASSED,
    DeepGITest::Format("the image matches the baseline (VTK threshold %g)", threshold));
}

// An 8-bit image of `components` channels, width x height, shown pixel for
// pixel in `renderer`: nearest-neighbour, colour window 255, and a parallel
// camera showing image pixel (i, j) at viewport pixel (i, j). It is black
// until the test writes into it (an image actor needs an input).
inline vtkSmartPointer<vtkImageData> ShowImagePixelForPixel(
  vtkRenderer* renderer, int width, int height, int components)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, components);
  std::fill_n(
    static_cast<unsigned char*>(image->GetScalarPointer()), components * width * height, 0);
  vtkNew<vtkImageActor> actor;
  actor->SetInputData(image);
  actor->InterpolateOff();
  actor->GetProperty()->SetColorWindow(255.0);
  actor->GetProperty()->SetColorLevel(127.5);
  renderer->AddActor(actor);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(0.5 * (width - 1), 0.5 * (height - 1), 0.0);
  camera->SetPosition(0.5 * (width - 1), 0.5 * (height - 1), 1000.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetParallelScale(0.5 * height);
  camera->SetClippingRange(1.0, 2000.0);
  return image;
}

// Writes `scale` x `values`, clamped to [0, 1], into the 8-bit image `shown`
// (as many channels as it has), and marks it modified.
inline void ShowValues(vtkDataArray* values, double scale, vtkImageData* shown)
{
  const int components = shown->GetNumberOfScalarComponents();
  unsigned char* out = static_cast<unsigned char*>(shown->GetScalarPointer());
  for (vtkIdType p = 0; p < values->GetNumberOfTuples(); ++p)
  {
    for (int c = 0; c < components; ++c)
    {
      out[components * p + c] = static_cast<unsigned char>(
        std::lround(255.0 * std::min(1.0, std::max(0.0, scale * values->GetComponent(p, c)))));
    }
  }
  shown->Modified();
}

// Reads the colour and depth buffers of a rendered window.
inline void ReadWindow(vtkRenderWindow* window, vtkImageData* rgb, vtkImageData* depth)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->SetInputBufferTypeToRGB();
  grab->Update();
  rgb->DeepCopy(grab->GetOutput());
  if (depth)
  {
    vtkNew<vtkWindowToImageFilter> grabDepth;
    grabDepth->SetInput(window);
    grabDepth->ReadFrontBufferOff();
    grabDepth->SetInputBufferTypeToZBuffer();
    grabDepth->Update();
    depth->DeepCopy(grabDepth->GetOutput());
  }
}
}

#endif
