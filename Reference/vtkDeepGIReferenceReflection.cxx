#include "vtkDeepGIReferenceReflection.h"
#include "vtkDeepGICaptureNames.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkDeepGIReferenceReflection);

vtkDeepGIReferenceReflection::vtkDeepGIReferenceReflection()
  : MaximumDistance(std::numeric_limits<double>::infinity())
{
}

vtkDeepGIReferenceReflection::~vtkDeepGIReferenceReflection() = default;

bool vtkDeepGIReferenceReflection::CheckParameters()
{
  if (!(this->MaximumDistance > 0.0)) // also catches NaN
  {
    vtkErrorMacro(
      "MaximumDistance must be positive (or infinite), not " << this->MaximumDistance << ".");
    return false;
  }
  return true;
}

bool vtkDeepGIReferenceReflection::PrepareCompute(vtkImageData* capture)
{
  // Compute() validated the matrices: the eye is the inverse view matrix's
  // translation, the view direction its -z axis.
  vtkDataArray* view = capture->GetFieldData()->GetArray(vtkDeepGICaptureNames::ViewMatrix);
  vtkDataArray* projection =
    capture->GetFieldData()->GetArray(vtkDeepGICaptureNames::ProjectionMatrix);
  vtkNew<vtkMatrix4x4> viewMatrix, cameraToWorld;
  for (int k = 0; k < 16; ++k)
  {
    viewMatrix->SetElement(k / 4, k % 4, view->GetComponent(0, k));
  }
  vtkMatrix4x4::Invert(viewMatrix, cameraToWorld);
  for (int c = 0; c < 3; ++c)
  {
    this->Eye[c] = cameraToWorld->GetElement(c, 3);
    this->ViewDirection[c] = -cameraToWorld->GetElement(c, 2);
  }
  vtkMath::Normalize(this->ViewDirection);
  // A perspective projection's last row is (0, 0, -1, 0), a parallel one's
  // (0, 0, 0, 1).
  this->Parallel = projection->GetComponent(0, 14) == 0.0;
  return true;
}

void vtkDeepGIReferenceReflection::EvaluateSample(
  const SurfacePoint& x, const double*, const HitRecord&, int, double* values) const
{
  std::fill(values, values + 8, 0.0);
  double v[3] = { 0.0, 0.0, 0.0 };
  if (this->Parallel)
  {
    std::copy(this->ViewDirection, this->ViewDirection + 3, v);
  }
  else
  {
    vtkMath::Subtract(x.Position, this->Eye, v);
    vtkMath::Normalize(v);
  }
  // Section 3.6: the mirror direction about the shading normal.
  const double vn = vtkMath::Dot(v, x.Normal);
  double d[3];
  for (int c = 0; c < 3; ++c)
  {
    d[c] = v[c] - 2.0 * vn * x.Normal[c];
  }
  vtkMath::Normalize(d);
  std::copy(d, d + 3, values + 5);
  HitRecord hit;
  // The ray starts at x.Origin (X lifted along n); the distance test below
  // is on |Y - X|, so the ray may run a little beyond MaximumDistance.
  const double offset = this->GetRayOffset(x.Position);
  if (!this->TraceRay(x.Origin, d, this->MaximumDistance + 2.0 * offset, hit))
  {
    return;
  }
  double y[3];
  for (int c = 0; c < 3; ++c)
  {
    y[c] = x.Origin[c] + hit.Distance * d[c];
  }
  const double distance = std::sqrt(vtkMath::Distance2BetweenPoints(y, x.Position));
  if (distance > this->MaximumDistance)
  {
    return;
  }
  values[0] = 1.0;
  values[1] = distance;
  std::copy(y, y + 3, values + 2);
}

void vtkDeepGIReferenceReflection::AllocateOutput(vtkImageData* output, vtkIdType pixels)
{
  vtkPointData* pd = output->GetPointData();
  vtkNew<vtkUnsignedCharArray> hit;
  hit->SetName("Hit");
  hit->SetNumberOfTuples(pixels);
  pd->AddArray(hit);
  struct
  {
    const char* Name;
    int Components;
  } const arrays[] = { { vtkDeepGICaptureNames::HitDistance, 1 }, { "HitPosition", 3 },
    { "MirrorDirection", 3 }, { "StandardError", 1 } };
  for (const auto& a : arrays)
  {
    vtkNew<vtkFloatArray> array;
    array->SetName(a.Name);
    array->SetNumberOfComponents(a.Components);
    array->SetNumberOfTuples(pixels);
    pd->AddArray(array);
  }
}

void vtkDeepGIReferenceReflection::FinishPixel(
  vtkImageData* output, vtkIdType pixel, const double* mean, const double*)
{
  vtkPointData* pd = output->GetPointData();
  const double zero[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
  const double* v = mean ? mean : zero;
  vtkUnsignedCharArray::SafeDownCast(pd->GetArray("Hit"))->SetValue(pixel, v[0] > 0.5 ? 1 : 0);
  pd->GetArray(vtkDeepGICaptureNames::HitDistance)->SetTuple1(pixel, v[1]);
  pd->GetArray("HitPosition")->SetTuple(pixel, v + 2);
  pd->GetArray("MirrorDirection")->SetTuple(pixel, v + 5);
  pd->GetArray("StandardError")->SetTuple1(pixel, 0.0);
}

void vtkDeepGIReferenceReflection::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaximumDistance: " << this->MaximumDistance << "\n";
}
