#include "vtkDeepGISceneLighting.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDeepGIKeys.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>

namespace vtkDeepGISceneLighting
{
namespace
{
using vtkDeepGISceneMesh::Brightest;
using vtkDeepGISceneMesh::Part;

// Area, area-weighted centroid and area-weighted normal (from the
// triangles' winding) of an emitting surface.
struct Emitter
{
  double Area = 0.0;
  double Centroid[3] = { 0.0, 0.0, 0.0 };
  double Normal[3] = { 0.0, 0.0, 0.0 };
};

Emitter MeasureEmitter(vtkPolyData* mesh)
{
  Emitter e;
  vtkPoints* points = mesh->GetPoints();
  auto cells = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    cells->GetCurrentCell(n, ids);
    if (n != 3)
    {
      continue; // the parts are triangulated
    }
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      points->GetPoint(ids[k], p[k]);
    }
    double e1[3], e2[3], cross[3];
    vtkMath::Subtract(p[1], p[0], e1);
    vtkMath::Subtract(p[2], p[0], e2);
    vtkMath::Cross(e1, e2, cross);
    const double a = 0.5 * vtkMath::Norm(cross);
    e.Area += a;
    for (int c = 0; c < 3; ++c)
    {
      e.Centroid[c] += a * (p[0][c] + p[1][c] + p[2][c]) / 3.0;
      e.Normal[c] += 0.5 * cross[c];
    }
  }
  for (int c = 0; c < 3 && e.Area > 0.0; ++c)
  {
    e.Centroid[c] /= e.Area;
  }
  return e;
}

// A flat Lambertian emitter of radiance Ke and area A sends the radiant
// intensity Ke A cos(theta) into its front half-space. VTK's diffuse term
// has no 1 / pi (radiance = Kd E / pi is written Kd x intensity x cos / d^2),
// so the intensity is max(Ke) A / pi, and a spot light (exponent 1: the
// cos(theta) falloff) with a cone just under 90 degrees lights that
// half-space. It sits a hair in front of the emitter, so the surface the
// emitter lies on is not lit at grazing.
void MakeSpotLight(vtkLight* light, const Emitter& e, double brightest, double diagonal)
{
  light->SetIntensity(brightest * e.Area / vtkMath::Pi());
  light->SetConeAngle(89.0);
  light->SetExponent(1.0);
  const double offset = 1e-4 * std::max(diagonal, 1e-12);
  double position[3];
  for (int c = 0; c < 3; ++c)
  {
    position[c] = e.Centroid[c] + offset * e.Normal[c];
  }
  light->SetPosition(position);
  light->SetFocalPoint(
    position[0] + e.Normal[0], position[1] + e.Normal[1], position[2] + e.Normal[2]);
}

// A curved emitter: a point light of the same power (Ke pi A in all
// directions, i.e. intensity Ke A / 4, / pi in VTK's units).
void MakePointLight(vtkLight* light, const Emitter& e, double brightest)
{
  light->SetIntensity(brightest * e.Area / (4.0 * vtkMath::Pi()));
  light->SetConeAngle(180.0);
  light->SetPosition(e.Centroid);
  light->SetFocalPoint(e.Centroid[0], e.Centroid[1] - 1.0, e.Centroid[2]);
}
} // anonymous namespace

//------------------------------------------------------------------------------
vtkSmartPointer<vtkActor> MakeActor(const Part& part)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(part.PolyData);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  vtkProperty* property = actor->GetProperty();
  property->SetDiffuseColor(part.Color[0], part.Color[1], part.Color[2]);
  property->SetAmbientColor(part.Color[0], part.Color[1], part.Color[2]);
  property->SetAmbient(MaterialAmbient);
  property->SetDiffuse(MaterialDiffuse);
  property->SetSpecular(0.0);
  property->SetInterpolationToPhong();
  const double brightest = Brightest(part);
  if (brightest > 0.0)
  {
    // An emitter (MTL Ke): drawn self-lit, with its colour Ke / max(Ke) as
    // VTK's ambient term (its displayable radiance; Ke itself is usually
    // far above 1), no diffuse or specular term, and marked EMISSIVE so
    // the deep G-buffer keeps that term in the direct radiance B(Y) that
    // vtkDeepRadiosityPass gathers. Its light reaches the scene through
    // the spot light EmitterLight puts on it.
    property->SetAmbientColor(
      part.Emission[0] / brightest, part.Emission[1] / brightest, part.Emission[2] / brightest);
    property->SetAmbient(1.0);
    property->SetDiffuse(0.0);
    vtkNew<vtkInformation> keys;
    keys->Set(vtkDeepGIKeys::EMISSIVE(), 1);
    actor->SetPropertyKeys(keys);
  }
  return actor;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkLight> EmitterLight(const Part& part, double diagonal)
{
  const double brightest = Brightest(part);
  vtkPolyData* mesh = part.PolyData;
  if (!(brightest > 0.0) || !mesh || !mesh->GetPoints() || mesh->GetNumberOfPolys() == 0)
  {
    return nullptr;
  }
  Emitter e = MeasureEmitter(mesh);
  if (!(e.Area > 0.0))
  {
    return nullptr;
  }
  // |sum of a_i n_i| = area for a flat emitter, less for a curved one.
  const double flatness = vtkMath::Normalize(e.Normal) / e.Area;
  auto light = vtkSmartPointer<vtkLight>::New();
  light->SetLightTypeToSceneLight();
  light->SetPositional(true);
  light->SetColor(
    part.Emission[0] / brightest, part.Emission[1] / brightest, part.Emission[2] / brightest);
  // 1 / d^2 falloff, as light from a small area emitter falls off.
  light->SetAttenuationValues(0.0, 0.0, 1.0);
  if (flatness > 0.9)
  {
    MakeSpotLight(light, e, brightest, diagonal);
  }
  else
  {
    MakePointLight(light, e, brightest);
  }
  return light;
}

//------------------------------------------------------------------------------
void AddDefaultLights(vtkRenderer* renderer, const double bounds[6], const double viewUp[3])
{
  // Key light in camera coordinates (the camera at (0, 0, 1) looking at the
  // origin): from above left of the viewer, so any model is lit on the side
  // it is seen from.
  vtkNew<vtkLight> key;
  key->SetLightTypeToCameraLight();
  key->SetPositional(false);
  key->SetPosition(-0.4, 0.6, 1.0);
  key->SetFocalPoint(0.0, 0.0, 0.0);
  key->SetColor(1.0, 1.0, 1.0);
  key->SetIntensity(0.6);
  renderer->AddLight(key);

  // Point light just below the top of the loaded geometry (along ViewUp):
  // inside a room or a Cornell box it lights the floor and the walls the
  // way a ceiling lamp does; above an object it lights it from above.
  if (!vtkMath::AreBoundsInitialized(bounds))
  {
    return;
  }
  double up[3] = { viewUp[0], viewUp[1], viewUp[2] };
  if (vtkMath::Normalize(up) == 0.0)
  {
    up[1] = 1.0;
  }
  double position[3];
  for (int i = 0; i < 3; ++i)
  {
    const double center = 0.5 * (bounds[2 * i] + bounds[2 * i + 1]);
    const double extent = bounds[2 * i + 1] - bounds[2 * i];
    position[i] = center + 0.45 * extent * up[i];
  }
  vtkNew<vtkLight> lamp;
  lamp->SetLightTypeToSceneLight();
  lamp->SetPositional(true);
  lamp->SetConeAngle(180.0); // >= 90: a point light, not a spot light
  lamp->SetAttenuationValues(1.0, 0.0, 0.0);
  lamp->SetPosition(position);
  lamp->SetFocalPoint(position[0] - up[0], position[1] - up[1], position[2] - up[2]);
  lamp->SetColor(1.0, 0.96, 0.9);
  lamp->SetIntensity(0.7);
  renderer->AddLight(lamp);
}
}
