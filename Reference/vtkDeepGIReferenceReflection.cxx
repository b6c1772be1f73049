#include "vtkDeepGIReferenceReflection.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIRayTracer.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkDeepGIReferenceReflection);

namespace
{
// The values of a pixel: hit (0 or 1), distance, hit position (3),
// direction (3).
constexpr int NumberOfValues = 8;
}

// The estimator the tracer runs: one exact mirror ray per pixel.
struct vtkDeepGIReferenceReflection::Sampler : public vtkDeepGIRayTracer::Estimator
{
  Sampler(vtkDeepGIReferenceReflection& self)
    : Self(self)
  {
  }

  bool Prepare(vtkImageData*, vtkPolyData*, vtkImageData* output) override;
  int GetNumberOfComponents() const override { return NumberOfValues; }
  int GetNumberOfSamples() const override { return 1; }
  void EvaluateSample(
    const vtkDeepGIRayTracer::SurfacePoint& x, int, double* values) const override;
  void FinishPixel(vtkIdType pixel, const double* mean, const double*) override;

  vtkDeepGIReferenceReflection& Self;
  vtkUnsignedCharArray* Hit = nullptr;
  vtkFloatArray* Distance = nullptr;
  vtkFloatArray* Position = nullptr;
  vtkFloatArray* Direction = nullptr;
  vtkFloatArray* Error = nullptr;
};

//------------------------------------------------------------------------------
vtkDeepGIReferenceReflection::vtkDeepGIReferenceReflection()
  : MaximumDistance(std::numeric_limits<double>::infinity())
{
}

vtkDeepGIReferenceReflection::~vtkDeepGIReferenceReflection() = default;

// The mirror ray needs no random numbers: the base's seed 0 is irrelevant.
std::unique_ptr<vtkDeepGIRayTracer::Estimator> vtkDeepGIReferenceReflection::NewEstimator()
{
  return std::unique_ptr<vtkDeepGIRayTracer::Estimator>(new Sampler(*this));
}

//------------------------------------------------------------------------------
bool vtkDeepGIReferenceReflection::Sampler::Prepare(
  vtkImageData*, vtkPolyData*, vtkImageData* output)
{
  if (!(this->Self.MaximumDistance > 0.0)) // also catches NaN
  {
    vtkErrorWithObjectMacro(&this->Self,
      "MaximumDistance must be positive (or infinite), not " << this->Self.MaximumDistance << ".");
    return false;
  }
  const vtkIdType pixels = output->GetNumberOfPoints();
  vtkPointData* pd = output->GetPointData();
  vtkNew<vtkUnsignedCharArray> hit;
  hit->SetName("Hit");
  hit->SetNumberOfTuples(pixels);
  pd->AddArray(hit);
  this->Hit = hit;
  auto add = [&](const char* name, int components)
  {
    vtkNew<vtkFloatArray> array;
    array->SetName(name);
    array->SetNumberOfComponents(components);
    array->SetNumberOfTuples(pixels);
    pd->AddArray(array);
    return array.GetPointer();
  };
  this->Distance = add(vtkDeepGICaptureNames::HitDistance, 1);
  this->Position = add("HitPosition", 3);
  this->Direction = add("MirrorDirection", 3);
  this->Error = add("StandardError", 1);
  return true;
}

//------------------------------------------------------------------------------
void vtkDeepGIReferenceReflection::Sampler::EvaluateSample(
  const vtkDeepGIRayTracer::SurfacePoint& x, int, double* values) const
{
  const vtkDeepGIRayTracer& tracer = *this->Self.Tracer;
  std::fill(values, values + NumberOfValues, 0.0);
  double v[3];
  tracer.ViewRay(x.Position, v);
  // Section 3.6: the mirror direction about the shading normal.
  const double vn = vtkMath::Dot(v, x.Normal);
  double d[3];
  for (int c = 0; c < 3; ++c)
  {
    d[c] = v[c] - 2.0 * vn * x.Normal[c];
  }
  vtkMath::Normalize(d);
  std::copy(d, d + 3, values + 5);
  vtkDeepGIRayTracer::HitRecord hit;
  // The ray starts at x.Origin (X lifted along n); the distance test below
  // is on |Y - X|, so the ray may run a little beyond MaximumDistance.
  const double maximum = this->Self.MaximumDistance;
  const double offset = tracer.GetRayOffset(x.Position);
  if (!tracer.TraceRay(x.Origin, d, maximum + 2.0 * offset, hit))
  {
    return;
  }
  double y[3];
  for (int c = 0; c < 3; ++c)
  {
    y[c] = x.Origin[c] + hit.Distance * d[c];
  }
  const double distance = std::sqrt(vtkMath::Distance2BetweenPoints(y, x.Position));
  if (distance > maximum)
  {
    return;
  }
  values[0] = 1.0;
  values[1] = distance;
  std::copy(y, y + 3, values + 2);
}

void vtkDeepGIReferenceReflection::Sampler::FinishPixel(
  vtkIdType pixel, const double* mean, const double*)
{
  const double zero[NumberOfValues] = { 0, 0, 0, 0, 0, 0, 0, 0 };
  const double* v = mean ? mean : zero;
  this->Hit->SetValue(pixel, v[0] > 0.5 ? 1 : 0);
  this->Distance->SetTuple1(pixel, v[1]);
  this->Position->SetTuple(pixel, v + 2);
  this->Direction->SetTuple(pixel, v + 5);
  this->Error->SetTuple1(pixel, 0.0);
}

//------------------------------------------------------------------------------
void vtkDeepGIReferenceReflection::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaximumDistance: " << this->MaximumDistance << "\n";
}
