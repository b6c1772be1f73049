// A real deep G-buffer capture (demo scene, two layers, 160 x 120) saved with
// vtkDeepGIEXRWriter and reloaded with vtkDeepGIEXRReader:
// - FLOAT: every array of every layer bit-identical (the unsigned char
//   Valid_j as float 0/1), the field data (matrices, separation, layer count,
//   oracle) exact;
// - HALF: every value within half precision (2^-11 relative + 2^-24);
// - the reloaded capture drives vtkDeepGIReferenceObscurance to bit-identical
//   results.

#include "DeepGBufferTestUtilities.h"

#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIDemoScene.h"
#include "vtkDeepGIEXRReader.h"
#include "vtkDeepGIEXRWriter.h"
#include "vtkDeepGIReferenceObscurance.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkStringArray.h"

#include <cstring>

using namespace DeepGBufferTest;
using namespace DeepGITest;

namespace
{
vtkSmartPointer<vtkImageData> RoundTrip(vtkImageData* capture, const std::string& file, int type)
{
  vtkNew<vtkDeepGIEXRWriter> writer;
  writer->SetInputData(capture);
  writer->SetFileName(file.c_str());
  writer->SetPixelType(type);
  Check(writer->Write() == 1, "written: " + file);
  vtkNew<vtkDeepGIEXRReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(reader->GetOutput());
  return image;
}

// Largest error of `actual` against `expected` over all point arrays, in
// units of the tolerance (exact: any difference counts as infinity).
double Compare(vtkImageData* expected, vtkImageData* actual, bool half, int& missing)
{
  double worst = 0.0;
  missing = 0;
  for (int a = 0; a < expected->GetPointData()->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* e = expected->GetPointData()->GetArray(a);
    auto r = vtkFloatArray::SafeDownCast(actual->GetPointData()->GetArray(e->GetName()));
    if (!r || r->GetNumberOfComponents() != e->GetNumberOfComponents() ||
      r->GetNumberOfTuples() != e->GetNumberOfTuples())
    {
      ++missing;
      continue;
    }
    for (vtkIdType i = 0; i < e->GetNumberOfTuples(); ++i)
    {
      for (int c = 0; c < e->GetNumberOfComponents(); ++c)
      {
        const float x = static_cast<float>(e->GetComponent(i, c));
        const float y = r->GetTypedComponent(i, c);
        if (half)
        {
          worst = std::max(worst,
            std::fabs(static_cast<double>(x) - y) /
              (std::ldexp(std::fabs(x), -11) + std::ldexp(1.0, -24)));
        }
        else if (std::memcmp(&x, &y, sizeof(float)) != 0)
        {
          worst = HUGE_VAL;
        }
      }
    }
  }
  return worst;
}
}

int TestDeepGIEXRCapture(int argc, char* argv[])
{
  const std::string directory = Argument(argc, argv, "-T", ".");
  auto window = MakeWindow(160, 120);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkDeepGIDemoScene> scene;
  scene->SetTargetNumberOfTriangles(20000);
  scene->Populate(renderer);
  scene->SetCameraToDefaultView(renderer->GetActiveCamera());
  renderer->ResetCameraClippingRange();
  vtkNew<vtkDeepGBufferPass> pass;
  renderer->SetPass(pass);
  window->Render();
  vtkNew<vtkImageData> capture;
  Check(pass->CaptureLayers(capture, renderer), "capture");

  int missing = 0;
  auto exact =
    RoundTrip(capture, directory + "/TestDeepGIEXRCapture-float.exr", vtkDeepGIEXRWriter::FLOAT);
  const double floatError = Compare(capture, exact, false, missing);
  std::printf(
    "FLOAT: %d arrays, %d missing\n", capture->GetPointData()->GetNumberOfArrays(), missing);
  Check(missing == 0 && floatError == 0.0, "FLOAT: every array bit-identical");
  vtkFieldData* a = capture->GetFieldData();
  vtkFieldData* b = exact->GetFieldData();
  bool sameField = true;
  for (const char* name :
    { vtkDeepGICaptureNames::ViewMatrix, vtkDeepGICaptureNames::ProjectionMatrix,
      vtkDeepGICaptureNames::MinimumSeparation, vtkDeepGICaptureNames::NumberOfLayers })
  {
    vtkDataArray* x = a->GetArray(name);
    vtkDataArray* y = b->GetArray(name);
    sameField = sameField && x && y && x->GetNumberOfComponents() == y->GetNumberOfComponents();
    for (int k = 0; sameField && k < x->GetNumberOfComponents(); ++k)
    {
      sameField = x->GetComponent(0, k) == y->GetComponent(0, k);
    }
  }
  auto oracle = vtkStringArray::SafeDownCast(b->GetAbstractArray(vtkDeepGICaptureNames::Oracle));
  auto oracleIn = vtkStringArray::SafeDownCast(a->GetAbstractArray(vtkDeepGICaptureNames::Oracle));
  Check(sameField && oracle && oracleIn && oracle->GetValue(0) == oracleIn->GetValue(0),
    "FLOAT: field data exact");

  auto rounded =
    RoundTrip(capture, directory + "/TestDeepGIEXRCapture-half.exr", vtkDeepGIEXRWriter::HALF);
  const double halfError = Compare(capture, rounded, true, missing);
  std::printf("HALF: largest error / (2^-11 |a| + 2^-24) = %.3f\n", halfError);
  Check(missing == 0 && halfError <= 1.0, "HALF: every value within half precision");

  vtkNew<vtkDeepGIReferenceObscurance> original, reloaded;
  original->SetInputData(capture);
  reloaded->SetInputData(exact);
  for (vtkDeepGIReferenceObscurance* r : { original.Get(), reloaded.Get() })
  {
    r->SetSceneData(scene->GetScenePolyData());
    r->SetSamplesPerPixel(4);
    r->SetRadius(0.5);
    r->Update();
  }
  Check(original->GetOutput()->GetNumberOfPoints() > 0 &&
      reloaded->GetOutput()->GetNumberOfPoints() > 0,
    "reference on both captures");
  auto x =
    vtkFloatArray::SafeDownCast(original->GetOutput()->GetPointData()->GetArray("Obscurance"));
  auto y =
    vtkFloatArray::SafeDownCast(reloaded->GetOutput()->GetPointData()->GetArray("Obscurance"));
  Check(x && y && x->GetNumberOfValues() == y->GetNumberOfValues() &&
      std::memcmp(x->GetPointer(0), y->GetPointer(0), sizeof(float) * x->GetNumberOfValues()) == 0,
    "the reference gives identical obscurance on the reloaded capture");
  return ExitStatus();
}
