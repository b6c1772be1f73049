// vtkDeepGIReferenceReflection against the analytic mirror: a floor y = 0
// (x, z in [-2, 2]) in front of a wall z = -2 (x in [-2, 2], y in [0, 2]),
// captured by a two-layer vtkDeepGBufferPass at 160 x 120. For every floor
// pixel of layer 0, the reference's mirror direction is the reflection of
// the viewing direction about the capture's (Oct16) normal, within 1e-5, and
// that normal is the floor's within 1 degree; where that ray meets the wall
// plane inside the wall (5 cm margin), the reference reports a hit at the
// analytic point X + t d (t = (-2 - X_z) / d_z) and distance t within 1e-3
// world units, and where it meets the plane outside the wall or not at all,
// a miss. MaximumDistance 0.04, shorter than every hit, gives no hit.

#include "DeepGBufferTestUtilities.h"

#include "vtkAppendPolyData.h"
#include "vtkDeepGBufferPass.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIReferenceReflection.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"

#include <algorithm>
#include <cstdio>
#include <vector>

using namespace DeepGBufferTest;
using namespace DeepGITest;

int TestDeepGIReferenceReflectionWall(int, char*[])
{
  vtkNew<vtkPlaneSource> floorSource, wallSource;
  floorSource->SetOrigin(-2, 0, 2);
  floorSource->SetPoint1(2, 0, 2);
  floorSource->SetPoint2(-2, 0, -2);
  wallSource->SetOrigin(-2, 0, -2);
  wallSource->SetPoint1(2, 0, -2);
  wallSource->SetPoint2(-2, 2, -2);
  vtkNew<vtkAppendPolyData> append;
  append->AddInputConnection(floorSource->GetOutputPort());
  append->AddInputConnection(wallSource->GetOutputPort());
  append->Update();
  vtkPolyData* scene = append->GetOutput();

  auto window = MakeWindow(160, 120);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(scene);
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  SetCamera(renderer, 0.3, 1.2, 3.0, 0.0, 0.4, -1.0);
  vtkNew<vtkDeepGBufferPass> gbuffer;
  renderer->SetPass(gbuffer);
  window->Render();
  vtkNew<vtkImageData> capture;
  if (!gbuffer->CaptureLayers(capture, renderer))
  {
    Check(false, "capture");
    return EXIT_FAILURE;
  }

  vtkNew<vtkDeepGIReferenceReflection> reference;
  reference->SetInputData(capture);
  reference->SetSceneData(scene);
  reference->Update();
  Check(reference->GetOutput()->GetNumberOfPoints() > 0, "reference computed");
  vtkPointData* out = reference->GetOutput()->GetPointData();
  vtkDataArray* hitArray = out->GetArray("Hit");
  vtkDataArray* distanceArray = out->GetArray(vtkDeepGICaptureNames::HitDistance);
  vtkDataArray* positionArray = out->GetArray("HitPosition");
  vtkDataArray* directionArray = out->GetArray("MirrorDirection");
  const double eye[3] = { 0.3, 1.2, 3.0 };
  const int* dims = capture->GetDimensions();
  std::vector<vtkIdType> checked; // the floor pixels
  long floorPixels = 0, hits = 0, misses = 0, wrongHits = 0, wrongMisses = 0;
  double worstPosition = 0, worstDirection = 0, worstNormal = 0, maxT = 0;
  for (int j = 0; j < dims[1]; ++j)
  {
    for (int i = 0; i < dims[0]; ++i)
    {
      double X[3];
      if (!WorldPosition(capture, 0, i, j, X) || std::fabs(X[1]) > 1e-3 || std::fabs(X[0]) > 1.95 ||
        std::fabs(X[2]) > 1.95)
      {
        continue;
      }
      ++floorPixels;
      const vtkIdType p = static_cast<vtkIdType>(j) * dims[0] + i;
      checked.push_back(p);
      // The capture's normal in world coordinates, as the reference reads it.
      double nc[3], n[3];
      Layer(capture, vtkDeepGICaptureNames::Normal, 0)->GetTuple(p, nc);
      vtkNew<vtkMatrix4x4> view;
      view->DeepCopy(vtkDoubleArray::SafeDownCast(
        capture->GetFieldData()->GetArray(vtkDeepGICaptureNames::ViewMatrix))
                       ->GetPointer(0));
      for (int c = 0; c < 3; ++c)
      {
        n[c] = view->GetElement(0, c) * nc[0] + view->GetElement(1, c) * nc[1] +
          view->GetElement(2, c) * nc[2];
      }
      vtkMath::Normalize(n);
      worstNormal =
        std::max(worstNormal, vtkMath::DegreesFromRadians(std::acos(std::min(1.0, n[1]))));
      double v[3], d[3], dRef[3];
      vtkMath::Subtract(X, eye, v);
      vtkMath::Normalize(v);
      const double vn = vtkMath::Dot(v, n);
      for (int c = 0; c < 3; ++c)
      {
        d[c] = v[c] - 2.0 * vn * n[c];
      }
      vtkMath::Normalize(d);
      directionArray->GetTuple(p, dRef);
      worstDirection =
        std::max(worstDirection, std::sqrt(vtkMath::Distance2BetweenPoints(d, dRef)));
      const bool refHit = hitArray->GetComponent(p, 0) > 0;
      if (!(d[2] < 0.0))
      {
        wrongHits += refHit;
        continue;
      }
      const double t = (-2.0 - X[2]) / d[2];
      const double Y[3] = { X[0] + t * d[0], X[1] + t * d[1], X[2] + t * d[2] };
      const bool inside = std::fabs(Y[0]) < 1.95 && Y[1] > 0.05 && Y[1] < 1.95;
      const bool outside = std::fabs(Y[0]) > 2.05 || Y[1] > 2.05;
      if (inside)
      {
        ++hits;
        wrongMisses += !refHit;
        if (refHit)
        {
          double y[3];
          positionArray->GetTuple(p, y);
          worstPosition = std::max(worstPosition, std::sqrt(vtkMath::Distance2BetweenPoints(Y, y)));
          worstPosition = std::max(worstPosition, std::fabs(distanceArray->GetComponent(p, 0) - t));
          maxT = std::max(maxT, t);
        }
      }
      else if (outside)
      {
        ++misses;
        wrongHits += refHit;
      }
    }
  }
  std::printf("floor pixels %ld: %ld on the wall, %ld missing it; worst normal angle %.3f deg, "
              "worst direction difference %.3g, worst hit-point difference %.3g (t up to %.3f); "
              "wrong hits %ld, wrong misses %ld\n",
    floorPixels, hits, misses, worstNormal, worstDirection, worstPosition, maxT, wrongHits,
    wrongMisses);
  Check(floorPixels > 3000 && hits > 1000 && misses > 100, "enough floor pixels of each kind");
  Check(worstNormal < 1.0, "Oct16 floor normal within 1 degree");
  Check(worstDirection < 1e-5, "mirror direction");
  Check(worstPosition < 1e-3, "hit point and distance on the analytic wall");
  Check(wrongHits == 0 && wrongMisses == 0, "hits and misses as the analytic wall says");

  // A maximum distance shorter than every hit (the floor points checked lie
  // at least 5 cm in front of the wall): no hit at all.
  reference->SetMaximumDistance(0.04);
  reference->Update();
  Check(reference->GetOutput()->GetNumberOfPoints() > 0, "reference with MaximumDistance 0.04");
  vtkDataArray* shortHits = reference->GetOutput()->GetPointData()->GetArray("Hit");
  Check(std::none_of(checked.begin(), checked.end(),
          [&](vtkIdType p) { return shortHits->GetComponent(p, 0) > 0; }),
    "no floor hit within 0.04");
  return ExitStatus();
}
