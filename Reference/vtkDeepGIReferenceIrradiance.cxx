#include "vtkDeepGIReferenceIrradiance.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIRayTracer.h"
#include "vtkDeepGIReferenceLighting.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

vtkStandardNewMacro(vtkDeepGIReferenceIrradiance);

using HitRecord = vtkDeepGIRayTracer::HitRecord;
using SurfacePoint = vtkDeepGIRayTracer::SurfacePoint;
using Light = vtkDeepGIReferenceLighting::Light;

// The estimator the tracer runs: E(X) (or L_k with bounces) by
// cosine-weighted path tracing, or the direct radiance of X itself.
struct vtkDeepGIReferenceIrradiance::Sampler : public vtkDeepGIRayTracer::Estimator
{
  Sampler(vtkDeepGIReferenceIrradiance& self)
    : Self(self)
    , Tracer(*self.Tracer)
    , Lighting(*self.Lighting)
  {
  }

  bool Prepare(vtkImageData* capture, vtkPolyData* scene, vtkImageData* output) override;
  int GetNumberOfComponents() const override { return 3; }
  int GetNumberOfSamples() const override
  {
    return this->Self.Quantity == DIRECT_RADIANCE ? 1 : this->Self.SamplesPerPixel;
  }
  void EvaluateSample(const SurfacePoint& x, int sample, double* values) const override;
  void FinishPixel(vtkIdType pixel, const double* mean, const double* standardError) override;

  void PrepareCaptureAlbedo(vtkImageData* capture);
  void AllocateOutput(vtkImageData* output);
  void SampleDirectRadiance(const SurfacePoint& x, double radiance[3]) const;
  void SampleIrradiance(const SurfacePoint& x, int sample, double values[3]) const;
  void AddBounces(vtkIdType pixel, int sample, const double y[3], const double w[3],
    const HitRecord& hit, double radiance[3]) const;

  vtkDeepGIReferenceIrradiance& Self;
  const vtkDeepGIRayTracer& Tracer;
  vtkDeepGIReferenceLighting& Lighting;
  vtkDataArray* CaptureAlbedo = nullptr;
  vtkFloatArray* Direct = nullptr;
  vtkFloatArray* Irradiance = nullptr;
  vtkFloatArray* IrradianceError = nullptr;
  vtkFloatArray* Radiance = nullptr;
  vtkFloatArray* RadianceError = nullptr;
};

//------------------------------------------------------------------------------
vtkDeepGIReferenceIrradiance::vtkDeepGIReferenceIrradiance()
  : Quantity(INDIRECT_IRRADIANCE)
  , Shadows(false)
  , TwoSidedLighting(true)
  , MaximumDistance(std::numeric_limits<double>::infinity())
  , DiffuseCoefficient(1.0)
  , EmissionArrayName(nullptr)
  , NumberOfBounces(1)
  , BounceDamping(1.0)
  , Lighting(new vtkDeepGIReferenceLighting)
{
  this->SetEmissionArrayName("Emission");
}

vtkDeepGIReferenceIrradiance::~vtkDeepGIReferenceIrradiance()
{
  this->SetEmissionArrayName(nullptr);
}

//------------------------------------------------------------------------------
bool vtkDeepGIReferenceIrradiance::AddLight(vtkLight* light, vtkCamera* camera)
{
  if (!light)
  {
    vtkErrorMacro("AddLight: null light.");
    return false;
  }
  Light resolved;
  std::string why;
  if (!vtkDeepGIReferenceLighting::Resolve(
        light, camera, vtkDeepGIReferenceLighting::Placement::FollowCamera, resolved, why))
  {
    if (!why.empty())
    {
      vtkWarningMacro("Light skipped: " << why << ".");
    }
    return false;
  }
  this->Lighting->Lights.push_back(resolved);
  this->Modified();
  return true;
}

void vtkDeepGIReferenceIrradiance::SetLightsFromRenderer(vtkRenderer* renderer)
{
  this->RemoveAllLights();
  if (!renderer)
  {
    vtkErrorMacro("SetLightsFromRenderer: null renderer.");
    return;
  }
  this->Lighting->SetLightsFromRenderer(renderer, this);
  this->Modified();
}

void vtkDeepGIReferenceIrradiance::RemoveAllLights()
{
  if (!this->Lighting->Lights.empty())
  {
    this->Lighting->Lights.clear();
    this->Modified();
  }
}

int vtkDeepGIReferenceIrradiance::GetNumberOfLights() const
{
  return static_cast<int>(this->Lighting->Lights.size());
}

bool vtkDeepGIReferenceIrradiance::GetLight(
  int index, double position[3], double direction[3], double color[3], bool& positional) const
{
  if (index < 0 || index >= this->GetNumberOfLights())
  {
    return false;
  }
  const Light& light = this->Lighting->Lights[index];
  for (int c = 0; c < 3; ++c)
  {
    position[c] = light.Position[c];
    direction[c] = light.Direction[c];
    color[c] = light.Color[c];
  }
  positional = light.Positional;
  return true;
}

//------------------------------------------------------------------------------
void vtkDeepGIReferenceIrradiance::SetNumberOfBounces(int bounces)
{
  const int clamped = std::min(16, std::max(1, bounces));
  if (clamped != bounces)
  {
    vtkWarningMacro(
      "NumberOfBounces " << bounces << " is outside [1, 16]; using " << clamped << ".");
  }
  if (clamped != this->NumberOfBounces)
  {
    this->NumberOfBounces = clamped;
    this->Modified();
  }
}

void vtkDeepGIReferenceIrradiance::SetBounceDamping(double delta)
{
  if (std::isnan(delta))
  {
    vtkWarningMacro("BounceDamping NaN ignored; keeping " << this->BounceDamping << ".");
    return;
  }
  const double clamped = std::min(1.0, std::max(0.0, delta));
  if (clamped != delta)
  {
    vtkWarningMacro("BounceDamping " << delta << " is outside [0, 1]; using " << clamped << ".");
  }
  if (clamped != this->BounceDamping)
  {
    this->BounceDamping = clamped;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
std::unique_ptr<vtkDeepGIRayTracer::Estimator> vtkDeepGIReferenceIrradiance::NewEstimator()
{
  return std::unique_ptr<vtkDeepGIRayTracer::Estimator>(new Sampler(*this));
}

//------------------------------------------------------------------------------
bool vtkDeepGIReferenceIrradiance::Sampler::Prepare(
  vtkImageData* capture, vtkPolyData* scene, vtkImageData* output)
{
  vtkDeepGIReferenceIrradiance& self = this->Self;
  if (!(self.MaximumDistance > 0.0)) // also catches NaN
  {
    vtkErrorWithObjectMacro(
      &self, "MaximumDistance must be positive (or infinite), not " << self.MaximumDistance << ".");
    return false;
  }
  this->Lighting.Prepare(scene,
    { self.Shadows, self.TwoSidedLighting, self.DiffuseCoefficient, self.EmissionArrayName },
    &this->Tracer, &self);
  if (self.Quantity == INDIRECT_IRRADIANCE)
  {
    this->PrepareCaptureAlbedo(capture);
  }
  this->AllocateOutput(output);
  return true;
}

// rho_X for the reflected radiance: the capture's Albedo_j, if it has one.
void vtkDeepGIReferenceIrradiance::Sampler::PrepareCaptureAlbedo(vtkImageData* capture)
{
  const std::string name =
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Albedo, this->Self.Layer);
  this->CaptureAlbedo = capture->GetPointData()->GetArray(name.c_str());
  if (this->CaptureAlbedo &&
    (this->CaptureAlbedo->GetNumberOfComponents() < 3 ||
      this->CaptureAlbedo->GetNumberOfTuples() != capture->GetNumberOfPoints()))
  {
    this->CaptureAlbedo = nullptr;
  }
  if (!this->CaptureAlbedo)
  {
    vtkWarningWithObjectMacro(
      &this->Self, "The capture has no RGB " << name << " array: no IndirectRadiance output.");
  }
}

void vtkDeepGIReferenceIrradiance::Sampler::AllocateOutput(vtkImageData* output)
{
  const vtkIdType pixels = output->GetNumberOfPoints();
  auto add = [&](const char* name)
  {
    vtkNew<vtkFloatArray> array;
    array->SetName(name);
    array->SetNumberOfComponents(3);
    array->SetNumberOfTuples(pixels);
    output->GetPointData()->AddArray(array);
    return array.GetPointer();
  };
  if (this->Self.Quantity == DIRECT_RADIANCE)
  {
    this->Direct = add("DirectRadiance");
    return;
  }
  this->Irradiance = add("IndirectIrradiance");
  this->IrradianceError = add("IndirectIrradianceStandardError");
  if (this->CaptureAlbedo)
  {
    this->Radiance = add(vtkDeepGICaptureNames::IndirectRadiance);
    this->RadianceError = add("IndirectRadianceStandardError");
  }
}

//------------------------------------------------------------------------------
void vtkDeepGIReferenceIrradiance::Sampler::EvaluateSample(
  const SurfacePoint& x, int sample, double* values) const
{
  values[0] = values[1] = values[2] = 0.0;
  if (this->Self.Quantity == DIRECT_RADIANCE)
  {
    this->SampleDirectRadiance(x, values);
  }
  else
  {
    this->SampleIrradiance(x, sample, values);
  }
}

// L = L_emitted + L_direct of X's own triangle, found along the viewing ray
// from just in front of X (1e-4 of the viewing distance plus the ray offset:
// far less than any layer separation, so nearer layers do not block it).
void vtkDeepGIReferenceIrradiance::Sampler::SampleDirectRadiance(
  const SurfacePoint& x, double radiance[3]) const
{
  double w[3];
  const double distance = this->Tracer.ViewRay(x.Position, w);
  const double margin = 1e-4 * distance + this->Tracer.GetRayOffset(x.Position);
  double origin[3];
  for (int c = 0; c < 3; ++c)
  {
    origin[c] = x.Position[c] - margin * w[c];
  }
  HitRecord own;
  if (this->Tracer.TraceRay(origin, w, 2.0 * margin, own))
  {
    double y[3];
    for (int c = 0; c < 3; ++c)
    {
      y[c] = origin[c] + own.Distance * w[c];
    }
    this->Lighting.OutgoingRadiance(y, w, own, radiance);
  }
}

// One cosine-weighted sample of E(X) = int L(Y(w)) cos dw: pi L(Y), L with
// the bounces beyond the first (see "Multiple bounces" in the header).
void vtkDeepGIReferenceIrradiance::Sampler::SampleIrradiance(
  const SurfacePoint& x, int sample, double values[3]) const
{
  const double maximum = this->Self.MaximumDistance;
  // Rays start RelativeOffset-sized distances above X; the exact
  // |Y - X| <= MaximumDistance test follows, so any bound above it will do.
  double direction[3];
  HitRecord hit;
  this->Tracer.TraceCosineRay(x, sample, 2.0 * maximum, direction, hit);
  if (!hit.Hit)
  {
    return;
  }
  double y[3];
  for (int c = 0; c < 3; ++c)
  {
    y[c] = x.Origin[c] + hit.Distance * direction[c];
  }
  if (std::isfinite(maximum) && vtkMath::Distance2BetweenPoints(x.Position, y) > maximum * maximum)
  {
    return;
  }
  double radiance[3];
  this->Lighting.OutgoingRadiance(y, direction, hit, radiance);
  if (this->Self.NumberOfBounces > 1)
  {
    this->AddBounces(x.Pixel, sample, y, direction, hit, radiance);
  }
  // A cosine-weighted sample of E = int L cos dw is L cos / (cos / pi).
  for (int c = 0; c < 3; ++c)
  {
    values[c] = vtkMath::Pi() * radiance[c];
  }
}

//------------------------------------------------------------------------------
// Adds to `radiance` (what leaves the first hit y0 along w0) the bounces
// 2..NumberOfBounces by diffuse path tracing from y0.
void vtkDeepGIReferenceIrradiance::Sampler::AddBounces(vtkIdType pixel, int sample,
  const double y0[3], const double w0[3], const HitRecord& hit0, double radiance[3]) const
{
  const vtkDeepGIReferenceIrradiance& self = this->Self;
  const double maximum = self.MaximumDistance;
  double y[3], w[3];
  std::copy(y0, y0 + 3, y);
  std::copy(w0, w0 + 3, w);
  HitRecord hit = hit0;
  // Product of delta rho_i along the path: the weight of the light that
  // reaches the first hit after the bounces so far.
  double throughput[3] = { 1.0, 1.0, 1.0 };
  for (int bounce = 1; bounce < self.NumberOfBounces; ++bounce)
  {
    double n[3];
    if (!this->Lighting.ShadingNormal(w, hit, n))
    {
      return; // Y sends no light, reflected light included
    }
    const float* rho = this->Lighting.GetAlbedo(hit.Cell);
    for (int c = 0; c < 3; ++c)
    {
      throughput[c] *= self.BounceDamping * rho[c];
    }
    if (throughput[0] == 0.0 && throughput[1] == 0.0 && throughput[2] == 0.0)
    {
      return;
    }
    // rho E(Y) / pi with one cosine-weighted direction about n_Y: E ~
    // pi L(Y'), so the reflected radiance is rho L(Y'). The sample's own
    // random dimensions for this level (0 and 1 are the ray from X).
    const double u1 = this->Tracer.Random(pixel, sample, 2 * bounce);
    const double u2 = this->Tracer.Random(pixel, sample, 2 * bounce + 1);
    double next[3];
    vtkDeepGIRayTracer::CosineDirection(n, u1, u2, next);
    // The side of the triangle the path arrived on; a direction below it
    // (shading and winding normals disagree) would go through the surface.
    const double side = vtkMath::Dot(hit.Normal, w) > 0.0 ? -1.0 : 1.0;
    if (side * vtkMath::Dot(hit.Normal, next) <= 0.0)
    {
      return;
    }
    const double offset = this->Tracer.GetRayOffset(y);
    double origin[3];
    for (int c = 0; c < 3; ++c)
    {
      origin[c] = y[c] + offset * side * hit.Normal[c];
    }
    HitRecord nextHit;
    if (!this->Tracer.TraceRay(origin, next, 2.0 * maximum, nextHit))
    {
      return;
    }
    double nextY[3];
    for (int c = 0; c < 3; ++c)
    {
      nextY[c] = origin[c] + nextHit.Distance * next[c];
    }
    // Every bounce is gathered within MaximumDistance (see the class
    // description).
    if (std::isfinite(maximum) && vtkMath::Distance2BetweenPoints(y, nextY) > maximum * maximum)
    {
      return;
    }
    double leaving[3];
    this->Lighting.OutgoingRadiance(nextY, next, nextHit, leaving);
    for (int c = 0; c < 3; ++c)
    {
      radiance[c] += throughput[c] * leaving[c];
    }
    std::copy(nextY, nextY + 3, y);
    std::copy(next, next + 3, w);
    hit = nextHit;
  }
}

//------------------------------------------------------------------------------
void vtkDeepGIReferenceIrradiance::Sampler::FinishPixel(
  vtkIdType pixel, const double* mean, const double* standardError)
{
  if (this->Direct)
  {
    for (int c = 0; c < 3; ++c)
    {
      this->Direct->SetTypedComponent(pixel, c, mean ? static_cast<float>(mean[c]) : 0.0f);
    }
    return;
  }
  for (int c = 0; c < 3; ++c)
  {
    const double e = mean ? mean[c] : 0.0;
    const double se = mean ? standardError[c] : 0.0;
    this->Irradiance->SetTypedComponent(pixel, c, static_cast<float>(e));
    this->IrradianceError->SetTypedComponent(pixel, c, static_cast<float>(se));
    if (this->Radiance)
    {
      // Lambertian reflection: L = (rho / pi) E.
      const double k = mean ? this->CaptureAlbedo->GetComponent(pixel, c) / vtkMath::Pi() : 0.0;
      this->Radiance->SetTypedComponent(pixel, c, static_cast<float>(k * e));
      this->RadianceError->SetTypedComponent(pixel, c, static_cast<float>(k * se));
    }
  }
}

//------------------------------------------------------------------------------
void vtkDeepGIReferenceIrradiance::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Quantity: "
     << (this->Quantity == DIRECT_RADIANCE ? "DIRECT_RADIANCE" : "INDIRECT_IRRADIANCE") << "\n";
  os << indent << "Shadows: " << (this->Shadows ? "On" : "Off") << "\n";
  os << indent << "TwoSidedLighting: " << (this->TwoSidedLighting ? "On" : "Off") << "\n";
  os << indent << "MaximumDistance: " << this->MaximumDistance << "\n";
  os << indent << "DiffuseCoefficient: " << this->DiffuseCoefficient << "\n";
  os << indent
     << "EmissionArrayName: " << (this->EmissionArrayName ? this->EmissionArrayName : "(none)")
     << "\n";
  os << indent << "NumberOfBounces: " << this->NumberOfBounces << "\n";
  os << indent << "BounceDamping: " << this->BounceDamping << "\n";
  this->Lighting->Print(os, indent);
}
