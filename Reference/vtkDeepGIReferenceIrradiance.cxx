#include "vtkDeepGIReferenceIrradiance.h"
#include "vtkDeepGICaptureNames.h"

#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkDeepGIReferenceIrradiance);

namespace
{
// A light resolved to world space, with the parameters VTK 9.1's polydata
// shader uses (vtkOpenGLRenderer::UpdateLightingUniforms and the
// //VTK::Light::Impl code of vtkOpenGLPolyDataMapper).
struct ResolvedLight
{
  double Position[3];
  double Direction[3]; // unit, from position towards focal point
  double Color[3];     // diffuse colour times intensity
  bool Positional;
  double Attenuation[3];
  bool Spot; // VTK applies the cone only below 90 degrees
  double CosCone;
  double Exponent;
};

bool AllFinite(const double* v, int n)
{
  for (int i = 0; i < n; ++i)
  {
    if (!std::isfinite(v[i]))
    {
      return false;
    }
  }
  return true;
}

// How a light's position and focal point are obtained.
enum class Placement
{
  FollowCamera, // VTK's UpdateLightsGeometryToFollowCamera with `camera`
  AsStored      // the light's transformed position/focal point as they are
};
}

struct vtkDeepGIReferenceIrradiance::Lighting
{
  std::vector<ResolvedLight> Lights;

  // Filled by PrepareCompute, read by the worker threads.
  std::vector<float> CellAlbedo;   // rho per scene cell (RGB), Diffuse included
  std::vector<float> CellEmission; // L_emitted per scene cell (RGB), empty if none
  std::vector<float> PointNormals; // per scene point (xyz), empty if none
  std::vector<float> CellNormals;  // per scene cell (xyz), empty if none
  vtkSmartPointer<vtkDataArray> CaptureAlbedo;
  // The capture's camera, for DIRECT_RADIANCE: eye and viewing direction in
  // world space, and whether the projection is parallel.
  double Eye[3] = { 0, 0, 0 };
  double ViewDirection[3] = { 0, 0, -1 };
  bool Parallel = false;
  vtkFloatArray* Direct = nullptr;
  vtkFloatArray* Irradiance = nullptr;
  vtkFloatArray* IrradianceError = nullptr;
  vtkFloatArray* Radiance = nullptr;
  vtkFloatArray* RadianceError = nullptr;

  // Resolves `light`; returns false with `why` set (empty: silently ignored).
  static bool Resolve(
    vtkLight* light, vtkCamera* camera, Placement placement, ResolvedLight& out, std::string& why)
  {
    if (!light->GetSwitch())
    {
      return false;
    }
    double position[3], focal[3];
    if (placement == Placement::FollowCamera && !light->LightTypeIsSceneLight())
    {
      if (!camera)
      {
        why = "a headlight or camera light needs a camera";
        return false;
      }
      if (light->LightTypeIsHeadlight())
      {
        camera->GetPosition(position);
        camera->GetFocalPoint(focal);
      }
      else
      {
        // Camera lights live in the camera's light frame: VTK sets their
        // transform to vtkCamera::GetCameraLightTransformMatrix().
        vtkMatrix4x4* m = camera->GetCameraLightTransformMatrix();
        double p[4] = { 0, 0, 0, 1 }, f[4] = { 0, 0, 0, 1 };
        light->GetPosition(p);
        light->GetFocalPoint(f);
        m->MultiplyPoint(p, p);
        m->MultiplyPoint(f, f);
        for (int c = 0; c < 3; ++c)
        {
          position[c] = p[c] / p[3];
          focal[c] = f[c] / f[3];
        }
      }
    }
    else
    {
      light->GetTransformedPosition(position);
      light->GetTransformedFocalPoint(focal);
    }
    vtkMath::Subtract(focal, position, out.Direction);
    const double length = vtkMath::Normalize(out.Direction);
    const double intensity = light->GetIntensity();
    const double* colour = light->GetDiffuseColor();
    for (int c = 0; c < 3; ++c)
    {
      out.Position[c] = position[c];
      out.Color[c] = colour[c] * intensity;
      out.Attenuation[c] = light->GetAttenuationValues()[c];
    }
    out.Positional = light->GetPositional() != 0;
    out.Spot = out.Positional && light->GetConeAngle() < 90.0;
    out.CosCone = std::cos(vtkMath::RadiansFromDegrees(light->GetConeAngle()));
    out.Exponent = light->GetExponent();
    if (!(length > 0.0) || !AllFinite(out.Position, 3) || !AllFinite(out.Direction, 3) ||
      !AllFinite(out.Color, 3) || !AllFinite(out.Attenuation, 3) || !std::isfinite(out.CosCone) ||
      !std::isfinite(out.Exponent))
    {
      why = "its position, focal point, colour, intensity, attenuation, cone or exponent is not "
            "finite, or its focal point equals its position";
      return false;
    }
    return true;
  }
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
  , Data(new Lighting)
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
  ResolvedLight resolved;
  std::string why;
  if (!Lighting::Resolve(light, camera, Placement::FollowCamera, resolved, why))
  {
    if (!why.empty())
    {
      vtkWarningMacro("Light skipped: " << why << ".");
    }
    return false;
  }
  this->Data->Lights.push_back(resolved);
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
  const Placement placement =
    renderer->GetLightFollowCamera() ? Placement::FollowCamera : Placement::AsStored;
  vtkCamera* camera = renderer->GetActiveCamera();
  vtkLightCollection* lights = renderer->GetLights();
  int switchedOn = 0;
  vtkCollectionSimpleIterator it;
  vtkLight* light;
  for (lights->InitTraversal(it); (light = lights->GetNextLight(it));)
  {
    if (!light->GetSwitch())
    {
      continue;
    }
    ++switchedOn;
    ResolvedLight resolved;
    std::string why;
    if (Lighting::Resolve(light, camera, placement, resolved, why))
    {
      this->Data->Lights.push_back(resolved);
    }
    else
    {
      vtkWarningMacro("Light of the renderer skipped: " << why << ".");
    }
  }
  // vtkOpenGLRenderer::UpdateLights creates a white headlight of intensity 1
  // when no light is on; the rendered image (the screen-space input) has it.
  if (switchedOn == 0 && renderer->GetAutomaticLightCreation())
  {
    vtkNew<vtkLight> headlight;
    headlight->SetLightTypeToHeadlight();
    ResolvedLight resolved;
    std::string why;
    if (Lighting::Resolve(headlight, camera, Placement::FollowCamera, resolved, why))
    {
      this->Data->Lights.push_back(resolved);
    }
  }
  this->Modified();
}

void vtkDeepGIReferenceIrradiance::RemoveAllLights()
{
  if (!this->Data->Lights.empty())
  {
    this->Data->Lights.clear();
    this->Modified();
  }
}

int vtkDeepGIReferenceIrradiance::GetNumberOfLights() const
{
  return static_cast<int>(this->Data->Lights.size());
}

bool vtkDeepGIReferenceIrradiance::GetLight(
  int index, double position[3], double direction[3], double color[3], bool& positional) const
{
  if (index < 0 || index >= this->GetNumberOfLights())
  {
    return false;
  }
  const ResolvedLight& light = this->Data->Lights[index];
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
int vtkDeepGIReferenceIrradiance::GetNumberOfSamplesPerPixel() const
{
  return this->Quantity == DIRECT_RADIANCE ? 1 : this->SamplesPerPixel;
}

double vtkDeepGIReferenceIrradiance::GetMaximumRayDistance() const
{
  if (this->Quantity == DIRECT_RADIANCE)
  {
    return 0.0; // EvaluateSample traces its own ray; the hemisphere ray is unused
  }
  // Rays start RelativeOffset-sized distances above X; EvaluateSample applies
  // the exact |Y - X| <= MaximumDistance test, so any bound above it will do.
  return 2.0 * this->MaximumDistance;
}

bool vtkDeepGIReferenceIrradiance::CheckParameters()
{
  if (!(this->MaximumDistance > 0.0)) // also catches NaN
  {
    vtkErrorMacro(
      "MaximumDistance must be positive (or infinite), not " << this->MaximumDistance << ".");
    return false;
  }
  return true;
}

bool vtkDeepGIReferenceIrradiance::PrepareCompute(vtkImageData* capture)
{
  Lighting& d = *this->Data;
  this->PrepareEmission();
  if (d.Lights.empty() && d.CellEmission.empty())
  {
    vtkWarningMacro("No lights (SetLightsFromRenderer or AddLight) and no emission: the indirect "
                    "irradiance is 0 everywhere.");
  }
  vtkPolyData* scene = this->Scene;
  const vtkIdType cells = scene->GetNumberOfCells();
  const vtkIdType points = scene->GetNumberOfPoints();

  // Albedo per cell: "Colors" (unsigned char / 255, other types as they are)
  // times the diffuse coefficient.
  vtkDataArray* colors = scene->GetCellData()->GetArray("Colors");
  if (colors && colors->GetNumberOfTuples() != cells)
  {
    vtkWarningMacro("The scene's \"Colors\" cell array has "
      << colors->GetNumberOfTuples() << " tuples for " << cells << " cells; using white.");
    colors = nullptr;
  }
  else if (!colors)
  {
    vtkWarningMacro("The scene has no \"Colors\" cell array; using a white albedo.");
  }
  vtkDataArray* diffuseCells = scene->GetCellData()->GetArray("Diffuse");
  if (diffuseCells && diffuseCells->GetNumberOfTuples() != cells)
  {
    vtkWarningMacro("The scene's \"Diffuse\" cell array does not match its cells; ignored.");
    diffuseCells = nullptr;
  }
  double diffuse = this->DiffuseCoefficient;
  vtkDataArray* diffuseField = scene->GetFieldData()->GetArray("Diffuse");
  if (!diffuseCells && diffuseField && diffuseField->GetNumberOfTuples() > 0)
  {
    diffuse = diffuseField->GetComponent(0, 0);
  }
  const double scale = colors && colors->GetDataType() == VTK_UNSIGNED_CHAR ? 1.0 / 255.0 : 1.0;
  d.CellAlbedo.assign(3 * static_cast<size_t>(cells), 0.0f);
  for (vtkIdType c = 0; c < cells; ++c)
  {
    const double k = diffuseCells ? diffuseCells->GetComponent(c, 0) : diffuse;
    for (int i = 0; i < 3; ++i)
    {
      double rho = 1.0;
      if (colors)
      {
        rho = scale * colors->GetComponent(c, colors->GetNumberOfComponents() >= 3 ? i : 0);
      }
      rho *= k;
      // Negative or non-finite albedos cannot come from VTK's colouring.
      d.CellAlbedo[3 * c + i] = std::isfinite(rho) ? static_cast<float>(std::max(0.0, rho)) : 0.0f;
    }
  }

  // Shading normals, the ones VTK's mapper would use: point normals, else
  // cell normals (else the winding normal of the hit triangle).
  auto copyNormals = [](vtkDataArray* normals, vtkIdType count, std::vector<float>& out)
  {
    out.clear();
    if (!normals || normals->GetNumberOfComponents() != 3 || normals->GetNumberOfTuples() != count)
    {
      return;
    }
    out.resize(3 * static_cast<size_t>(count));
    for (vtkIdType p = 0; p < count; ++p)
    {
      for (int c = 0; c < 3; ++c)
      {
        out[3 * p + c] = static_cast<float>(normals->GetComponent(p, c));
      }
    }
  };
  copyNormals(scene->GetPointData()->GetNormals(), points, d.PointNormals);
  copyNormals(
    d.PointNormals.empty() ? scene->GetCellData()->GetNormals() : nullptr, cells, d.CellNormals);

  // The camera (Compute() validated the matrices): the eye is
  // the inverse view matrix's translation, the view direction its -z axis.
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
    d.Eye[c] = cameraToWorld->GetElement(c, 3);
    d.ViewDirection[c] = -cameraToWorld->GetElement(c, 2);
  }
  vtkMath::Normalize(d.ViewDirection);
  // A perspective projection's last row is (0, 0, -1, 0), a parallel one's
  // (0, 0, 0, 1).
  d.Parallel = projection->GetComponent(0, 14) == 0.0;
  if (this->Quantity == DIRECT_RADIANCE)
  {
    d.CaptureAlbedo = nullptr;
    return true;
  }

  // rho_X for the reflected radiance.
  const std::string name = vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Albedo, this->Layer);
  d.CaptureAlbedo = capture->GetPointData()->GetArray(name.c_str());
  if (d.CaptureAlbedo &&
    (d.CaptureAlbedo->GetNumberOfComponents() < 3 ||
      d.CaptureAlbedo->GetNumberOfTuples() != capture->GetNumberOfPoints()))
  {
    d.CaptureAlbedo = nullptr;
  }
  if (!d.CaptureAlbedo)
  {
    vtkWarningMacro("The capture has no RGB " << name << " array: no IndirectRadiance output.");
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkDeepGIReferenceIrradiance::PrepareEmission()
{
  Lighting& d = *this->Data;
  d.CellEmission.clear();
  if (!this->EmissionArrayName || !*this->EmissionArrayName)
  {
    return;
  }
  const vtkIdType cells = this->Scene->GetNumberOfCells();
  vtkDataArray* emission = this->Scene->GetCellData()->GetArray(this->EmissionArrayName);
  if (!emission)
  {
    return; // a scene without emitters
  }
  const int components = emission->GetNumberOfComponents();
  if (emission->GetNumberOfTuples() != cells || (components != 1 && components != 3))
  {
    vtkWarningMacro("The scene's \"" << this->EmissionArrayName << "\" cell array has "
                                     << emission->GetNumberOfTuples() << " tuples of " << components
                                     << " components for " << cells
                                     << " cells (expected RGB or grey per cell); ignored.");
    return;
  }
  // Like "Colors": 8-bit values are a colour in [0, 1].
  const double scale = emission->GetDataType() == VTK_UNSIGNED_CHAR ? 1.0 / 255.0 : 1.0;
  d.CellEmission.assign(3 * static_cast<size_t>(cells), 0.0f);
  vtkIdType clamped = 0;
  bool emits = false;
  for (vtkIdType c = 0; c < cells; ++c)
  {
    for (int i = 0; i < 3; ++i)
    {
      const double value = scale * emission->GetComponent(c, components == 3 ? i : 0);
      // Radiance is finite and non-negative; anything else would make E
      // NaN, infinite or negative.
      if (!std::isfinite(value) || value < 0.0)
      {
        ++clamped;
        continue;
      }
      d.CellEmission[3 * c + i] = static_cast<float>(value);
      emits = emits || value > 0.0;
    }
  }
  if (clamped > 0)
  {
    vtkWarningMacro("The scene's \"" << this->EmissionArrayName << "\" cell array has " << clamped
                                     << " NaN, infinite or negative values; set to 0.");
  }
  if (!emits)
  {
    d.CellEmission.clear();
  }
}

//------------------------------------------------------------------------------
void vtkDeepGIReferenceIrradiance::OutgoingRadiance(
  const double y[3], const double w[3], const HitRecord& hit, double radiance[3]) const
{
  this->DirectRadiance(y, w, hit, radiance);
  const Lighting& d = *this->Data;
  if (d.CellEmission.empty())
  {
    return;
  }
  // VTK draws the ambient term (the emission of an EMISSIVE prop) on both
  // sides; one-sided lighting makes back faces send nothing at all.
  const bool backFace = vtkMath::Dot(hit.Normal, w) > 0.0;
  if (backFace && !this->TwoSidedLighting)
  {
    return;
  }
  for (int c = 0; c < 3; ++c)
  {
    radiance[c] += d.CellEmission[3 * hit.Cell + c];
  }
}

bool vtkDeepGIReferenceIrradiance::ShadingNormal(
  const double w[3], const HitRecord& hit, double n[3]) const
{
  const Lighting& d = *this->Data;
  // The ray arrives on the triangle's back when it travels along the
  // winding normal (gl_FrontFacing false for a viewer at the ray's origin).
  const bool backFace = vtkMath::Dot(hit.Normal, w) > 0.0;
  if (backFace && !this->TwoSidedLighting)
  {
    return false;
  }
  std::copy(hit.Normal, hit.Normal + 3, n);
  if (!d.PointNormals.empty())
  {
    for (int c = 0; c < 3; ++c)
    {
      n[c] = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        n[c] += hit.Weights[k] * d.PointNormals[3 * hit.PointIds[k] + c];
      }
    }
    if (vtkMath::Normalize(n) == 0.0)
    {
      return false;
    }
  }
  else if (!d.CellNormals.empty())
  {
    for (int c = 0; c < 3; ++c)
    {
      n[c] = d.CellNormals[3 * hit.Cell + c];
    }
    if (vtkMath::Normalize(n) == 0.0)
    {
      return false;
    }
  }
  // VTK flips the shading normal of back faces (two-sided lighting).
  const double side = backFace ? -1.0 : 1.0;
  for (int c = 0; c < 3; ++c)
  {
    n[c] *= side;
  }
  return true;
}

void vtkDeepGIReferenceIrradiance::AddBounces(vtkIdType pixel, int sample, const double y0[3],
  const double w0[3], const HitRecord& hit0, double radiance[3]) const
{
  const Lighting& d = *this->Data;
  const double maximum = this->MaximumDistance;
  double y[3], w[3];
  std::copy(y0, y0 + 3, y);
  std::copy(w0, w0 + 3, w);
  HitRecord hit = hit0;
  // Product of delta rho_i along the path: the weight of the light that
  // reaches the first hit after the bounces so far.
  double throughput[3] = { 1.0, 1.0, 1.0 };
  for (int bounce = 1; bounce < this->NumberOfBounces; ++bounce)
  {
    double n[3];
    if (!this->ShadingNormal(w, hit, n))
    {
      return; // Y sends no light, reflected light included
    }
    const float* rho = &d.CellAlbedo[3 * hit.Cell];
    for (int c = 0; c < 3; ++c)
    {
      throughput[c] *= this->BounceDamping * rho[c];
    }
    if (throughput[0] == 0.0 && throughput[1] == 0.0 && throughput[2] == 0.0)
    {
      return;
    }
    // rho E(Y) / pi with one cosine-weighted direction about n_Y: E ~
    // pi L(Y'), so the reflected radiance is rho L(Y'). The sample's own
    // random dimensions for this level (0 and 1 are the ray from X).
    const double u1 = this->Random(pixel, sample, 2 * bounce);
    const double u2 = this->Random(pixel, sample, 2 * bounce + 1);
    double next[3];
    CosineDirection(n, u1, u2, next);
    // The side of the triangle the path arrived on; a direction below it
    // (shading and winding normals disagree) would go through the surface.
    const double side = vtkMath::Dot(hit.Normal, w) > 0.0 ? -1.0 : 1.0;
    if (side * vtkMath::Dot(hit.Normal, next) <= 0.0)
    {
      return;
    }
    const double offset = this->GetRayOffset(y);
    double origin[3];
    for (int c = 0; c < 3; ++c)
    {
      origin[c] = y[c] + offset * side * hit.Normal[c];
    }
    HitRecord nextHit;
    if (!this->TraceRay(origin, next, 2.0 * maximum, nextHit))
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
    this->OutgoingRadiance(nextY, next, nextHit, leaving);
    for (int c = 0; c < 3; ++c)
    {
      radiance[c] += throughput[c] * leaving[c];
    }
    std::copy(nextY, nextY + 3, y);
    std::copy(next, next + 3, w);
    hit = nextHit;
  }
}

void vtkDeepGIReferenceIrradiance::DirectRadiance(
  const double y[3], const double w[3], const HitRecord& hit, double radiance[3]) const
{
  const Lighting& d = *this->Data;
  radiance[0] = radiance[1] = radiance[2] = 0.0;
  const float* rho = &d.CellAlbedo[3 * hit.Cell];
  if (d.Lights.empty() || (rho[0] == 0.0f && rho[1] == 0.0f && rho[2] == 0.0f))
  {
    return;
  }
  double n[3];
  if (!this->ShadingNormal(w, hit, n))
  {
    return;
  }
  const double side = vtkMath::Dot(hit.Normal, w) > 0.0 ? -1.0 : 1.0;
  // Shadow rays start just off the surface on the side the ray came from.
  double origin[3];
  const double offset = this->Shadows ? this->GetRayOffset(y) : 0.0;
  for (int c = 0; c < 3; ++c)
  {
    origin[c] = y[c] + offset * side * hit.Normal[c];
  }
  for (const ResolvedLight& light : d.Lights)
  {
    double l[3];
    double attenuation = 1.0;
    double distance = std::numeric_limits<double>::infinity();
    if (light.Positional)
    {
      vtkMath::Subtract(light.Position, y, l);
      distance = vtkMath::Normalize(l);
      if (!(distance > 0.0))
      {
        continue;
      }
      attenuation = 1.0 /
        (light.Attenuation[0] + light.Attenuation[1] * distance +
          light.Attenuation[2] * distance * distance);
      if (light.Spot)
      {
        // Cosine between the light's axis and the direction light -> Y.
        const double coneDot = -vtkMath::Dot(l, light.Direction);
        attenuation =
          coneDot >= light.CosCone ? attenuation * std::pow(coneDot, light.Exponent) : 0.0;
      }
    }
    else
    {
      for (int c = 0; c < 3; ++c)
      {
        l[c] = -light.Direction[c];
      }
    }
    const double df = std::max(0.0, attenuation * vtkMath::Dot(n, l));
    if (!(df > 0.0) || !std::isfinite(df))
    {
      continue;
    }
    if (this->Shadows && this->IsOccluded(origin, l, std::max(0.0, distance - offset)))
    {
      continue;
    }
    for (int c = 0; c < 3; ++c)
    {
      radiance[c] += df * light.Color[c];
    }
  }
  for (int c = 0; c < 3; ++c)
  {
    radiance[c] *= rho[c];
  }
}

void vtkDeepGIReferenceIrradiance::EvaluateSample(const SurfacePoint& x, const double direction[3],
  const HitRecord& hit, int sample, double* values) const
{
  values[0] = values[1] = values[2] = 0.0;
  if (this->Quantity == DIRECT_RADIANCE)
  {
    // Find X's triangle along the viewing ray, starting just in front of X
    // (1e-4 of the viewing distance plus the ray offset: far less than any
    // layer separation, so nearer layers do not block it).
    const Lighting& d = *this->Data;
    double w[3], toX[3];
    vtkMath::Subtract(x.Position, d.Eye, toX);
    double distance;
    if (d.Parallel)
    {
      std::copy(d.ViewDirection, d.ViewDirection + 3, w);
      distance = std::fabs(vtkMath::Dot(toX, w));
    }
    else
    {
      std::copy(toX, toX + 3, w);
      distance = vtkMath::Normalize(w);
    }
    const double margin = 1e-4 * distance + this->GetRayOffset(x.Position);
    double origin[3];
    for (int c = 0; c < 3; ++c)
    {
      origin[c] = x.Position[c] - margin * w[c];
    }
    HitRecord own;
    if (this->TraceRay(origin, w, 2.0 * margin, own))
    {
      double y[3];
      for (int c = 0; c < 3; ++c)
      {
        y[c] = origin[c] + own.Distance * w[c];
      }
      this->OutgoingRadiance(y, w, own, values);
    }
    return;
  }
  if (!hit.Hit)
  {
    return;
  }
  double y[3];
  for (int c = 0; c < 3; ++c)
  {
    y[c] = x.Origin[c] + hit.Distance * direction[c];
  }
  if (std::isfinite(this->MaximumDistance) &&
    vtkMath::Distance2BetweenPoints(x.Position, y) > this->MaximumDistance * this->MaximumDistance)
  {
    return;
  }
  double radiance[3];
  this->OutgoingRadiance(y, direction, hit, radiance);
  if (this->NumberOfBounces > 1)
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
void vtkDeepGIReferenceIrradiance::AllocateOutput(vtkImageData* output, vtkIdType pixels)
{
  Lighting& d = *this->Data;
  d.Direct = d.Irradiance = d.IrradianceError = d.Radiance = d.RadianceError = nullptr;
  auto add = [&](const char* name)
  {
    vtkNew<vtkFloatArray> array;
    array->SetName(name);
    array->SetNumberOfComponents(3);
    array->SetNumberOfTuples(pixels);
    output->GetPointData()->AddArray(array);
    return array.GetPointer();
  };
  if (this->Quantity == DIRECT_RADIANCE)
  {
    d.Direct = add("DirectRadiance");
    return;
  }
  d.Irradiance = add("IndirectIrradiance");
  d.IrradianceError = add("IndirectIrradianceStandardError");
  d.Radiance = d.CaptureAlbedo ? add(vtkDeepGICaptureNames::IndirectRadiance) : nullptr;
  d.RadianceError = d.CaptureAlbedo ? add("IndirectRadianceStandardError") : nullptr;
}

void vtkDeepGIReferenceIrradiance::FinishPixel(
  vtkImageData*, vtkIdType pixel, const double* mean, const double* standardError)
{
  const Lighting& d = *this->Data;
  if (d.Direct)
  {
    for (int c = 0; c < 3; ++c)
    {
      d.Direct->SetTypedComponent(pixel, c, mean ? static_cast<float>(mean[c]) : 0.0f);
    }
    return;
  }
  for (int c = 0; c < 3; ++c)
  {
    const double e = mean ? mean[c] : 0.0;
    const double se = mean ? standardError[c] : 0.0;
    d.Irradiance->SetTypedComponent(pixel, c, static_cast<float>(e));
    d.IrradianceError->SetTypedComponent(pixel, c, static_cast<float>(se));
    if (d.Radiance)
    {
      // Lambertian reflection: L = (rho / pi) E.
      const double k = mean ? d.CaptureAlbedo->GetComponent(pixel, c) / vtkMath::Pi() : 0.0;
      d.Radiance->SetTypedComponent(pixel, c, static_cast<float>(k * e));
      d.RadianceError->SetTypedComponent(pixel, c, static_cast<float>(k * se));
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
  os << indent << "NumberOfLights: " << this->GetNumberOfLights() << "\n";
  for (const ResolvedLight& light : this->Data->Lights)
  {
    os << indent.GetNextIndent() << (light.Positional ? "positional" : "directional")
       << " light: position (" << light.Position[0] << ", " << light.Position[1] << ", "
       << light.Position[2] << "), direction (" << light.Direction[0] << ", " << light.Direction[1]
       << ", " << light.Direction[2] << "), colour x intensity (" << light.Color[0] << ", "
       << light.Color[1] << ", " << light.Color[2] << ")";
    if (light.Positional)
    {
      os << ", attenuation (" << light.Attenuation[0] << ", " << light.Attenuation[1] << ", "
         << light.Attenuation[2] << ")";
      if (light.Spot)
      {
        os << ", spot cos(cone) " << light.CosCone << ", exponent " << light.Exponent;
      }
    }
    os << "\n";
  }
}
