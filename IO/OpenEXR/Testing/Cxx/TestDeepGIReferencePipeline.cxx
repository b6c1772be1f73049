// vtkDeepGIReferenceObscurance in a VTK pipeline, driven by Update() only:
// a capture saved as .vti (a floor beside a tall wall, seen from above, as
// in TestDeepGIReferenceObscurance) is read by vtkXMLImageDataReader, the
// reference (the scene on input port 1) estimates its ambient visibility
// and vtkDeepGIEXRWriter writes the estimate as one FLOAT OpenEXR file:
//  1. the file holds AmbientVisibility, Obscurance, StandardError and Valid
//     bit-identical to the reference run on the capture in memory
//     (SetInputData), with the same statistics;
//  2. AV matches the closed form of the wall within 4.5 standard errors +
//     1e-4 per pixel, and the mean difference lies within 4 standard
//     errors of the mean;
//  3. an Update() of an unchanged pipeline does not run the reference
//     again; a new radius does, and the file changes.

#include "DeepGIReferenceTestUtilities.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIEXRReader.h"
#include "vtkDeepGIEXRWriter.h"
#include "vtkDeepGIReferenceObscurance.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkXMLImageDataReader.h"
#include "vtkXMLImageDataWriter.h"

#include <cmath>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

using namespace DeepGIReferenceTest;
using namespace DeepGITest;

namespace
{
constexpr int Width = 24;
constexpr int Height = 24;
constexpr double Radius = 1.0;
constexpr double Extent = 20.0;

// The floor z = 0 on the side x > 0 of the wall x = 0, both Extent long.
vtkSmartPointer<vtkPolyData> WallScene()
{
  auto scene = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  const double quads[2][4][3] = { { { 0, -Extent, 0 }, { Extent, -Extent, 0 },
                                    { Extent, Extent, 0 }, { 0, Extent, 0 } },
    { { 0, -Extent, 0 }, { 0, Extent, 0 }, { 0, Extent, Extent }, { 0, -Extent, Extent } } };
  for (const auto& quad : quads)
  {
    vtkIdType ids[4];
    for (int k = 0; k < 4; ++k)
    {
      ids[k] = points->InsertNextPoint(quad[k]);
    }
    polys->InsertNextCell(4, ids);
  }
  scene->SetPoints(points);
  scene->SetPolys(polys);
  return scene;
}

// Layer 0 of the floor seen straight down from (0.6, 0, 3.6): exact depth
// and normal where the pixel's ray meets the floor on the wall's side
// (Valid_0 1), nothing elsewhere; `distances` gets each pixel's distance to
// the wall (-1 where invalid).
vtkSmartPointer<vtkImageData> FloorCapture(std::vector<double>& distances)
{
  vtkNew<vtkCamera> camera;
  camera->SetPosition(0.6, 0.0, 3.6);
  camera->SetFocalPoint(0.6, 0.0, 0.0);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(40.0);
  camera->SetClippingRange(0.36, 7.2);
  Layer0Capture capture(Width, Height, camera);
  const double up[4] = { 0, 0, 1, 0 };
  double normal[4];
  capture.View->MultiplyPoint(up, normal);
  distances.assign(Width * Height, -1.0);
  for (int j = 0; j < Height; ++j)
  {
    for (int i = 0; i < Width; ++i)
    {
      const vtkIdType p = j * Width + i;
      const double ndcX = (i + 0.5) / Width * 2 - 1, ndcY = (j + 0.5) / Height * 2 - 1;
      double a[4] = { ndcX, ndcY, -1, 1 }, b[4] = { ndcX, ndcY, 1, 1 };
      double wa[4], wb[4];
      capture.InverseProjection->MultiplyPoint(a, a);
      capture.InverseProjection->MultiplyPoint(b, b);
      capture.InverseView->MultiplyPoint(a, wa);
      capture.InverseView->MultiplyPoint(b, wb);
      double x[4] = { 0, 0, 0, 1 };
      const double f = (0.0 - wa[2] / wa[3]) / (wb[2] / wb[3] - wa[2] / wa[3]);
      for (int c = 0; c < 3; ++c)
      {
        x[c] = wa[c] / wa[3] + f * (wb[c] / wb[3] - wa[c] / wa[3]);
      }
      double xc[4];
      capture.View->MultiplyPoint(x, xc);
      const bool onFloor = x[0] > 0.0;
      distances[p] = onFloor ? x[0] : -1.0;
      capture.Depth->SetValue(p, onFloor ? static_cast<float>(-xc[2]) : 0.0f);
      capture.Valid->SetValue(p, onFloor ? 1 : 0);
      for (int c = 0; c < 3; ++c)
      {
        capture.Normal->SetComponent(p, c, onFloor ? normal[c] : 0.0);
        capture.Albedo->SetComponent(p, c, 0.5);
      }
    }
  }
  return capture.Image;
}

vtkSmartPointer<vtkImageData> ReadEXR(const std::string& file)
{
  vtkNew<vtkDeepGIEXRReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->ShallowCopy(reader->GetOutput());
  return image;
}

// Whether `name` holds the same values (bit for bit, as float) in a and b.
bool SameValues(vtkImageData* a, vtkImageData* b, const char* name)
{
  vtkDataArray* x = a->GetPointData()->GetArray(name);
  vtkDataArray* y = b->GetPointData()->GetArray(name);
  if (!x || !y || x->GetNumberOfValues() != y->GetNumberOfValues())
  {
    return false;
  }
  for (vtkIdType k = 0; k < x->GetNumberOfValues(); ++k)
  {
    const float u = static_cast<float>(x->GetVariantValue(k).ToDouble());
    const float v = static_cast<float>(y->GetVariantValue(k).ToDouble());
    if (std::memcmp(&u, &v, sizeof(float)) != 0)
    {
      return false;
    }
  }
  return true;
}

// 1. The file against the reference run on the capture in memory.
void CheckFileMatchesInMemoryRun(vtkImageData* written, vtkImageData* capture, vtkPolyData* scene,
  vtkDeepGIReferenceObscurance* piped)
{
  vtkNew<vtkDeepGIReferenceObscurance> direct;
  direct->SetSceneData(scene);
  direct->SetRadius(Radius);
  Check(Estimate(direct, capture), "in memory: update succeeds");
  for (const char* name : { vtkDeepGICaptureNames::AmbientVisibility, "Obscurance", "StandardError",
         vtkDeepGICaptureNames::Valid })
  {
    Check(SameValues(written, direct->GetOutput(), name),
      std::string("file: ") + name + " bit-identical to the in-memory run");
  }
  Check(piped->GetMeanStandardError() == direct->GetMeanStandardError() &&
      piped->GetNumberOfRays() == direct->GetNumberOfRays() && piped->GetNumberOfRays() > 0,
    Format("pipeline statistics as in memory: mean SE %g, %lld rays", piped->GetMeanStandardError(),
      static_cast<long long>(piped->GetNumberOfRays())));
}

// 2. AV in the file against the closed form.
void CheckFileMatchesClosedForm(vtkImageData* written, const std::vector<double>& distances)
{
  vtkDataArray* av = written->GetPointData()->GetArray(vtkDeepGICaptureNames::AmbientVisibility);
  vtkDataArray* se = written->GetPointData()->GetArray("StandardError");
  if (!av || !se)
  {
    Check(false, "file: AmbientVisibility and StandardError present");
    return;
  }
  int n = 0, beyond = 0;
  double sumDiff = 0.0, sumVariance = 0.0;
  for (vtkIdType p = 0; p < av->GetNumberOfTuples(); ++p)
  {
    if (distances[p] < 0.0)
    {
      continue;
    }
    const double diff = av->GetComponent(p, 0) - (1.0 - WallObscurance(distances[p], Radius));
    const double e = se->GetComponent(p, 0);
    beyond += std::fabs(diff) > 4.5 * e + 1e-4;
    sumDiff += diff;
    sumVariance += e * e;
    ++n;
  }
  const double meanDiff = sumDiff / n, meanError = std::sqrt(sumVariance) / n;
  std::cout << "wall: " << n << " pixels, mean AV - exact " << meanDiff << " (its standard error "
            << meanError << ")\n";
  Check(n > 100, Format("file: %d floor pixels", n));
  Check(beyond == 0, Format("file: %d pixels beyond 4.5 standard errors + 1e-4", beyond));
  Check(std::fabs(meanDiff) < 4.0 * meanError + 1e-4,
    Format(
      "file: mean difference %g within 4 standard errors of the mean (%g)", meanDiff, meanError));
}
}

int TestDeepGIReferencePipeline(int argc, char* argv[])
{
  const std::string directory = Argument(argc, argv, "-T", ".");
  const std::string captureFile = directory + "/TestDeepGIReferencePipeline-capture.vti";
  const std::string estimateFile = directory + "/TestDeepGIReferencePipeline-estimate.exr";
  std::vector<double> distances;
  vtkSmartPointer<vtkImageData> capture = FloorCapture(distances);
  vtkSmartPointer<vtkPolyData> scene = WallScene();
  vtkNew<vtkXMLImageDataWriter> saver;
  saver->SetInputData(capture);
  saver->SetFileName(captureFile.c_str());
  Check(saver->Write() == 1, "capture saved as .vti");

  vtkNew<vtkXMLImageDataReader> reader;
  reader->SetFileName(captureFile.c_str());
  vtkNew<vtkDeepGIReferenceObscurance> reference;
  reference->SetInputConnection(reader->GetOutputPort());
  reference->SetSceneData(scene);
  reference->SetRadius(Radius);
  vtkNew<vtkDeepGIEXRWriter> writer;
  writer->SetInputConnection(reference->GetOutputPort());
  writer->SetFileName(estimateFile.c_str());
  writer->SetPixelTypeToFloat();
  writer->Update();

  vtkSmartPointer<vtkImageData> written = ReadEXR(estimateFile);
  Check(written->GetNumberOfPoints() == Width * Height, "the estimate written by Update()");
  CheckFileMatchesInMemoryRun(written, capture, scene, reference);
  CheckFileMatchesClosedForm(written, distances);

  // 3. Update() runs what changed only.
  const vtkMTimeType first = reference->GetOutput()->GetMTime();
  writer->Update();
  Check(reference->GetOutput()->GetMTime() == first, "unchanged pipeline: no new estimate");
  reference->SetRadius(0.5 * Radius);
  writer->Update();
  vtkSmartPointer<vtkImageData> smaller = ReadEXR(estimateFile);
  Check(reference->GetOutput()->GetMTime() > first &&
      !SameValues(smaller, written, vtkDeepGICaptureNames::AmbientVisibility),
    "a new radius: a new estimate in the file");
  return ExitStatus();
}
