// Helpers shared by the vtkDeepReflectionPass tests: quads with the
// materials the tests need, and the geometry of captured pixels.
#ifndef DeepReflectionTestUtilities_h
#define DeepReflectionTestUtilities_h

#include "DeepGBufferTestUtilities.h"

#include "vtkDataArray.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"

#include <array>
#include <cmath>

namespace DeepReflectionTest
{
using Vector = std::array<double, 3>;

// A quad with corners o, a, b (and a + b - o), `resolution` cells a side.
inline vtkActor* AddQuad(
  vtkRenderer* renderer, const Vector& o, const Vector& a, const Vector& b, int resolution = 1)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(o[0], o[1], o[2]);
  plane->SetPoint1(a[0], a[1], a[2]);
  plane->SetPoint2(b[0], b[1], b[2]);
  plane->SetResolution(resolution, resolution);
  return DeepGBufferTest::AddSourceActor(renderer, plane);
}

// A perfect Phong mirror: Specular 1 with a white SpecularColor gives
// REFLECTIVITY 1; a dark diffuse colour under it.
inline void MakeMirror(vtkActor* actor)
{
  vtkProperty* p = actor->GetProperty();
  p->SetColor(0.1, 0.1, 0.1);
  p->SetSpecular(1.0);
  p->SetSpecularColor(1.0, 1.0, 1.0);
  p->SetSpecularPower(50.0);
}

// A surface whose radiance is exactly `color` under any light: VTK's ambient
// term only (Ambient 1, Diffuse 0, Specular 0).
inline void MakeConstant(vtkActor* actor, double r, double g, double b)
{
  vtkProperty* p = actor->GetProperty();
  p->SetAmbientColor(r, g, b);
  p->SetDiffuseColor(r, g, b);
  p->SetAmbient(1.0);
  p->SetDiffuse(0.0);
  p->SetSpecular(0.0);
}

// The camera of a capture (vtkDeepGBufferPass::CaptureLayers or
// vtkDeepReflectionPass::CaptureReflections): pixel + distance -> world.
struct Camera
{
  double View[16], Projection[16], InverseView[16];
  int Width = 0, Height = 0;

  explicit Camera(vtkImageData* capture)
  {
    capture->GetFieldData()->GetArray(vtkDeepGICaptureNames::ViewMatrix)->GetTuple(0, this->View);
    capture->GetFieldData()
      ->GetArray(vtkDeepGICaptureNames::ProjectionMatrix)
      ->GetTuple(0, this->Projection);
    vtkMatrix4x4::Invert(this->View, this->InverseView);
    int dims[3];
    capture->GetDimensions(dims);
    this->Width = dims[0];
    this->Height = dims[1];
  }

  static Vector Apply(const double m[16], const Vector& p, double w = 1.0)
  {
    Vector r;
    for (int i = 0; i < 3; ++i)
    {
      r[i] = m[4 * i] * p[0] + m[4 * i + 1] * p[1] + m[4 * i + 2] * p[2] + m[4 * i + 3] * w;
    }
    return r;
  }

  // World position of the surface at distance d (camera-space -z) seen
  // through the centre of pixel (i, j) (perspective projection).
  Vector World(int i, int j, double d) const
  {
    const double* P = this->Projection;
    const double ndc[2] = { (i + 0.5) / this->Width * 2.0 - 1.0,
      (j + 0.5) / this->Height * 2.0 - 1.0 };
    const double z = -d;
    const double w = P[14] * z + P[15];
    const Vector c = { (ndc[0] * w - P[2] * z - P[3]) / P[0], (ndc[1] * w - P[6] * z - P[7]) / P[5],
      z };
    return Apply(this->InverseView, c);
  }

  Vector Eye() const { return Apply(this->InverseView, { 0.0, 0.0, 0.0 }); }

  // Camera-space distance and pixel of world point p; false if outside.
  bool Project(const Vector& p, int& i, int& j, double& distance) const
  {
    const Vector c = Apply(this->View, p);
    double clip[4];
    for (int r = 0; r < 4; ++r)
    {
      clip[r] = this->Projection[4 * r] * c[0] + this->Projection[4 * r + 1] * c[1] +
        this->Projection[4 * r + 2] * c[2] + this->Projection[4 * r + 3];
    }
    if (clip[3] <= 0.0)
    {
      return false;
    }
    const double x = (clip[0] / clip[3] * 0.5 + 0.5) * this->Width;
    const double y = (clip[1] / clip[3] * 0.5 + 0.5) * this->Height;
    i = static_cast<int>(std::floor(x));
    j = static_cast<int>(std::floor(y));
    distance = -c[2];
    return i >= 0 && j >= 0 && i < this->Width && j < this->Height;
  }
};

inline Vector Normalized(const Vector& v)
{
  const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return { v[0] / l, v[1] / l, v[2] / l };
}

inline Vector Reflect(const Vector& v, const Vector& n)
{
  const double d = 2.0 * (v[0] * n[0] + v[1] * n[1] + v[2] * n[2]);
  return { v[0] - d * n[0], v[1] - d * n[1], v[2] - d * n[2] };
}
}

#endif
