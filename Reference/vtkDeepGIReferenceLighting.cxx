#include "vtkDeepGIReferenceLighting.h"

#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
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

// Position and focal point of a headlight or camera light, as VTK places
// them to follow `camera`.
void FollowCamera(vtkLight* light, vtkCamera* camera, double position[3], double focal[3])
{
  if (light->LightTypeIsHeadlight())
  {
    camera->GetPosition(position);
    camera->GetFocalPoint(focal);
    return;
  }
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

// The scene's normals of `count` tuples as floats; empty when it has none
// of that size.
void CopyNormals(vtkDataArray* normals, vtkIdType count, std::vector<float>& out)
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
}

// The unit direction l from y towards `light`, the distance to it (infinite
// for a directional light) and VTK's attenuation a_k: 1 / (c0 + c1 d +
// c2 d^2) times the spot factor cos^Exponent inside the cone (0 outside)
// for positional lights, 1 for directional ones. False where y is at the
// light's position.
bool TowardsLight(const vtkDeepGIReferenceLighting::Light& light, const double y[3], double l[3],
  double& distance, double& attenuation)
{
  attenuation = 1.0;
  distance = std::numeric_limits<double>::infinity();
  if (!light.Positional)
  {
    for (int c = 0; c < 3; ++c)
    {
      l[c] = -light.Direction[c];
    }
    return true;
  }
  vtkMath::Subtract(light.Position, y, l);
  distance = vtkMath::Normalize(l);
  if (!(distance > 0.0))
  {
    return false;
  }
  attenuation = 1.0 /
    (light.Attenuation[0] + light.Attenuation[1] * distance +
      light.Attenuation[2] * distance * distance);
  if (light.Spot)
  {
    // Cosine between the light's axis and the direction light -> Y.
    const double coneDot = -vtkMath::Dot(l, light.Direction);
    attenuation = coneDot >= light.CosCone ? attenuation * std::pow(coneDot, light.Exponent) : 0.0;
  }
  return true;
}
}

//------------------------------------------------------------------------------
bool vtkDeepGIReferenceLighting::Resolve(
  vtkLight* light, vtkCamera* camera, Placement placement, Light& out, std::string& why)
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
    FollowCamera(light, camera, position, focal);
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

//------------------------------------------------------------------------------
void vtkDeepGIReferenceLighting::SetLightsFromRenderer(vtkRenderer* renderer, vtkObject* reporter)
{
  this->Lights.clear();
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
    Light resolved;
    std::string why;
    if (Resolve(light, camera, placement, resolved, why))
    {
      this->Lights.push_back(resolved);
    }
    else
    {
      vtkWarningWithObjectMacro(reporter, "Light of the renderer skipped: " << why << ".");
    }
  }
  // vtkOpenGLRenderer::UpdateLights creates a white headlight of intensity 1
  // when no light is on; the rendered image (the screen-space input) has it.
  if (switchedOn == 0 && renderer->GetAutomaticLightCreation())
  {
    vtkNew<vtkLight> headlight;
    headlight->SetLightTypeToHeadlight();
    Light resolved;
    std::string why;
    if (Resolve(headlight, camera, Placement::FollowCamera, resolved, why))
    {
      this->Lights.push_back(resolved);
    }
  }
}

//------------------------------------------------------------------------------
void vtkDeepGIReferenceLighting::Prepare(vtkPolyData* scene, const Settings& settings,
  const vtkDeepGIRayTracer* tracer, vtkObject* reporter)
{
  this->Current = settings;
  this->Tracer = tracer;
  this->PrepareEmission(scene, reporter);
  if (this->Lights.empty() && this->CellEmission.empty())
  {
    vtkWarningWithObjectMacro(reporter,
      "No lights (SetLightsFromRenderer or AddLight) and no emission: the indirect irradiance "
      "is 0 everywhere.");
  }
  this->PrepareAlbedo(scene, reporter);
  this->PrepareNormals(scene);
}

//------------------------------------------------------------------------------
// Albedo per cell: "Colors" (unsigned char / 255, other types as they are)
// times the diffuse coefficient.
void vtkDeepGIReferenceLighting::PrepareAlbedo(vtkPolyData* scene, vtkObject* reporter)
{
  const vtkIdType cells = scene->GetNumberOfCells();
  vtkDataArray* colors = scene->GetCellData()->GetArray("Colors");
  if (colors && colors->GetNumberOfTuples() != cells)
  {
    vtkWarningWithObjectMacro(reporter,
      "The scene's \"Colors\" cell array has " << colors->GetNumberOfTuples() << " tuples for "
                                               << cells << " cells; using white.");
    colors = nullptr;
  }
  else if (!colors)
  {
    vtkWarningWithObjectMacro(
      reporter, "The scene has no \"Colors\" cell array; using a white albedo.");
  }
  vtkDataArray* diffuseCells = scene->GetCellData()->GetArray("Diffuse");
  if (diffuseCells && diffuseCells->GetNumberOfTuples() != cells)
  {
    vtkWarningWithObjectMacro(
      reporter, "The scene's \"Diffuse\" cell array does not match its cells; ignored.");
    diffuseCells = nullptr;
  }
  double diffuse = this->Current.DiffuseCoefficient;
  vtkDataArray* diffuseField = scene->GetFieldData()->GetArray("Diffuse");
  if (!diffuseCells && diffuseField && diffuseField->GetNumberOfTuples() > 0)
  {
    diffuse = diffuseField->GetComponent(0, 0);
  }
  const double scale = colors && colors->GetDataType() == VTK_UNSIGNED_CHAR ? 1.0 / 255.0 : 1.0;
  this->CellAlbedo.assign(3 * static_cast<size_t>(cells), 0.0f);
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
      this->CellAlbedo[3 * c + i] =
        std::isfinite(rho) ? static_cast<float>(std::max(0.0, rho)) : 0.0f;
    }
  }
}

//------------------------------------------------------------------------------
// The emission array into the per-cell table (empty: nothing emits).
void vtkDeepGIReferenceLighting::PrepareEmission(vtkPolyData* scene, vtkObject* reporter)
{
  this->CellEmission.clear();
  const char* name = this->Current.EmissionArrayName;
  if (!name || !*name)
  {
    return;
  }
  const vtkIdType cells = scene->GetNumberOfCells();
  vtkDataArray* emission = scene->GetCellData()->GetArray(name);
  if (!emission)
  {
    return; // a scene without emitters
  }
  const int components = emission->GetNumberOfComponents();
  if (emission->GetNumberOfTuples() != cells || (components != 1 && components != 3))
  {
    vtkWarningWithObjectMacro(reporter,
      "The scene's \"" << name << "\" cell array has " << emission->GetNumberOfTuples()
                       << " tuples of " << components << " components for " << cells
                       << " cells (expected RGB or grey per cell); ignored.");
    return;
  }
  // Like "Colors": 8-bit values are a colour in [0, 1].
  const double scale = emission->GetDataType() == VTK_UNSIGNED_CHAR ? 1.0 / 255.0 : 1.0;
  this->CellEmission.assign(3 * static_cast<size_t>(cells), 0.0f);
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
      this->CellEmission[3 * c + i] = static_cast<float>(value);
      emits = emits || value > 0.0;
    }
  }
  if (clamped > 0)
  {
    vtkWarningWithObjectMacro(reporter,
      "The scene's \"" << name << "\" cell array has " << clamped
                       << " NaN, infinite or negative values; set to 0.");
  }
  if (!emits)
  {
    this->CellEmission.clear();
  }
}

//------------------------------------------------------------------------------
// Shading normals, the ones VTK's mapper would use: point normals, else
// cell normals (else the winding normal of the hit triangle).
void vtkDeepGIReferenceLighting::PrepareNormals(vtkPolyData* scene)
{
  CopyNormals(scene->GetPointData()->GetNormals(), scene->GetNumberOfPoints(), this->PointNormals);
  CopyNormals(this->PointNormals.empty() ? scene->GetCellData()->GetNormals() : nullptr,
    scene->GetNumberOfCells(), this->CellNormals);
}

//------------------------------------------------------------------------------
void vtkDeepGIReferenceLighting::OutgoingRadiance(const double y[3], const double w[3],
  const vtkDeepGIRayTracer::HitRecord& hit, double radiance[3]) const
{
  this->DirectRadiance(y, w, hit, radiance);
  if (this->CellEmission.empty())
  {
    return;
  }
  // VTK draws the ambient term (the emission of an EMISSIVE prop) on both
  // sides; one-sided lighting makes back faces send nothing at all.
  const bool backFace = vtkMath::Dot(hit.Normal, w) > 0.0;
  if (backFace && !this->Current.TwoSidedLighting)
  {
    return;
  }
  for (int c = 0; c < 3; ++c)
  {
    radiance[c] += this->CellEmission[3 * hit.Cell + c];
  }
}

//------------------------------------------------------------------------------
bool vtkDeepGIReferenceLighting::ShadingNormal(
  const double w[3], const vtkDeepGIRayTracer::HitRecord& hit, double n[3]) const
{
  // The ray arrives on the triangle's back when it travels along the
  // winding normal (gl_FrontFacing false for a viewer at the ray's origin).
  const bool backFace = vtkMath::Dot(hit.Normal, w) > 0.0;
  if (backFace && !this->Current.TwoSidedLighting)
  {
    return false;
  }
  std::copy(hit.Normal, hit.Normal + 3, n);
  if (!this->PointNormals.empty())
  {
    for (int c = 0; c < 3; ++c)
    {
      n[c] = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        n[c] += hit.Weights[k] * this->PointNormals[3 * hit.PointIds[k] + c];
      }
    }
    if (vtkMath::Normalize(n) == 0.0)
    {
      return false;
    }
  }
  else if (!this->CellNormals.empty())
  {
    for (int c = 0; c < 3; ++c)
    {
      n[c] = this->CellNormals[3 * hit.Cell + c];
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

//------------------------------------------------------------------------------
void vtkDeepGIReferenceLighting::DirectRadiance(const double y[3], const double w[3],
  const vtkDeepGIRayTracer::HitRecord& hit, double radiance[3]) const
{
  radiance[0] = radiance[1] = radiance[2] = 0.0;
  const float* rho = this->GetAlbedo(hit.Cell);
  if (this->Lights.empty() || (rho[0] == 0.0f && rho[1] == 0.0f && rho[2] == 0.0f))
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
  const bool shadows = this->Current.Shadows;
  double origin[3];
  const double offset = shadows ? this->Tracer->GetRayOffset(y) : 0.0;
  for (int c = 0; c < 3; ++c)
  {
    origin[c] = y[c] + offset * side * hit.Normal[c];
  }
  for (const Light& light : this->Lights)
  {
    double l[3], distance, attenuation;
    if (!TowardsLight(light, y, l, distance, attenuation))
    {
      continue;
    }
    const double df = std::max(0.0, attenuation * vtkMath::Dot(n, l));
    if (!(df > 0.0) || !std::isfinite(df))
    {
      continue;
    }
    if (shadows && this->Tracer->IsOccluded(origin, l, std::max(0.0, distance - offset)))
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

//------------------------------------------------------------------------------
void vtkDeepGIReferenceLighting::Print(ostream& os, vtkIndent indent) const
{
  os << indent << "NumberOfLights: " << this->Lights.size() << "\n";
  for (const Light& light : this->Lights)
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
