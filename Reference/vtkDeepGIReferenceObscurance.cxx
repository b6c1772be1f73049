#include "vtkDeepGIReferenceObscurance.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIRayTracer.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkDeepGIReferenceObscurance);

// The estimator the tracer runs: one cosine-weighted ray per sample, eq. 2
// on its first hit within Radius.
struct vtkDeepGIReferenceObscurance::Sampler : public vtkDeepGIRayTracer::Estimator
{
  Sampler(vtkDeepGIReferenceObscurance& self)
    : Self(self)
  {
  }

  bool Prepare(vtkImageData*, vtkPolyData*, vtkImageData* output) override;
  int GetNumberOfComponents() const override { return 1; }
  int GetNumberOfSamples() const override { return this->Self.SamplesPerPixel; }
  void EvaluateSample(
    const vtkDeepGIRayTracer::SurfacePoint& x, int sample, double* values) const override;
  void FinishPixel(vtkIdType pixel, const double* mean, const double* standardError) override;

  vtkDeepGIReferenceObscurance& Self;
  vtkFloatArray* Visibility = nullptr;
  vtkFloatArray* Obscurance = nullptr;
  vtkFloatArray* Error = nullptr;
};

//------------------------------------------------------------------------------
vtkDeepGIReferenceObscurance::vtkDeepGIReferenceObscurance()
  : Radius(1.0)
  , Bias(0.0)
  , Epsilon(0.0)
{
}

vtkDeepGIReferenceObscurance::~vtkDeepGIReferenceObscurance() = default;

std::unique_ptr<vtkDeepGIRayTracer::Estimator> vtkDeepGIReferenceObscurance::NewEstimator()
{
  return std::unique_ptr<vtkDeepGIRayTracer::Estimator>(new Sampler(*this));
}

//------------------------------------------------------------------------------
bool vtkDeepGIReferenceObscurance::Sampler::Prepare(
  vtkImageData*, vtkPolyData*, vtkImageData* output)
{
  const double radius = this->Self.Radius;
  if (!(std::isfinite(radius) && radius > 0.0))
  {
    vtkErrorWithObjectMacro(
      &this->Self, "Radius must be a positive finite number, not " << radius << ".");
    return false;
  }
  const vtkIdType pixels = output->GetNumberOfPoints();
  auto add = [&](const char* name)
  {
    vtkNew<vtkFloatArray> array;
    array->SetName(name);
    array->SetNumberOfTuples(pixels);
    output->GetPointData()->AddArray(array);
    return array.GetPointer();
  };
  this->Visibility = add(vtkDeepGICaptureNames::AmbientVisibility);
  this->Obscurance = add("Obscurance");
  this->Error = add("StandardError");
  return true;
}

//------------------------------------------------------------------------------
// One cosine-weighted sample of A = (1 / pi) integral O(w) dw (eq. 2 on the
// first hit, see the header) divided by its density cos / pi.
void vtkDeepGIReferenceObscurance::Sampler::EvaluateSample(
  const vtkDeepGIRayTracer::SurfacePoint& x, int sample, double* values) const
{
  const vtkDeepGIReferenceObscurance& self = this->Self;
  double direction[3];
  vtkDeepGIRayTracer::HitRecord hit;
  self.Tracer->TraceCosineRay(x, sample, self.Radius, direction, hit);
  values[0] = 0.0;
  if (!hit.Hit || hit.Distance >= self.Radius)
  {
    return;
  }
  const double cosine = vtkMath::Dot(direction, x.Normal);
  if (cosine <= 0.0)
  {
    return;
  }
  // v = Y - X, measured from the shading point (not the offset origin).
  double v[3];
  for (int c = 0; c < 3; ++c)
  {
    v[c] = x.Origin[c] + hit.Distance * direction[c] - x.Position[c];
  }
  const double vv = vtkMath::Dot(v, v);
  const double falloff = 1.0 - vv / (self.Radius * self.Radius);
  if (falloff <= 0.0)
  {
    return;
  }
  const double denominator = std::sqrt(vv + self.Epsilon);
  double geometric = 1.0; // (v.n - beta)/sqrt(v.v + eps) divided by cos
  if (self.Bias > 0.0 || self.Epsilon > 0.0)
  {
    geometric = denominator > 0.0
      ? std::max(0.0, (vtkMath::Dot(v, x.Normal) - self.Bias) / denominator) / cosine
      : 0.0;
  }
  values[0] = falloff * std::min(1.0, geometric);
}

//------------------------------------------------------------------------------
void vtkDeepGIReferenceObscurance::Sampler::FinishPixel(
  vtkIdType pixel, const double* mean, const double* standardError)
{
  if (!mean)
  {
    this->Visibility->SetValue(pixel, -1.0f);
    this->Obscurance->SetValue(pixel, -1.0f);
    this->Error->SetValue(pixel, 0.0f);
    return;
  }
  this->Visibility->SetValue(pixel, static_cast<float>(1.0 - mean[0]));
  this->Obscurance->SetValue(pixel, static_cast<float>(mean[0]));
  this->Error->SetValue(pixel, static_cast<float>(standardError[0]));
}

//------------------------------------------------------------------------------
void vtkDeepGIReferenceObscurance::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "Bias: " << this->Bias << "\n";
  os << indent << "Epsilon: " << this->Epsilon << "\n";
}
