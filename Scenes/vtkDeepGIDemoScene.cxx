#include "vtkDeepGIDemoScene.h"

#include "vtkActor.h"
#include "vtkAppendPolyData.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

vtkStandardNewMacro(vtkDeepGIDemoScene);

namespace
{
// The lighting coefficients of every actor made here (VTK's Ambient and
// Diffuse); the scene polydata carries the diffuse one as field data.
constexpr double MaterialAmbient = 0.1;
constexpr double MaterialDiffuse = 0.9;

// GLM's double vector: the scene is built in double precision (glm::dvec3
// adds, scales and measures like the shaders' vec3).
using Vec3 = glm::dvec3;

struct MaterialInfo
{
  const char* Name;
  double Color[3];
};

// Diffuse albedos: saturated walls (paper Figure 2 and the Cornell-style
// colour bleeding cases), distinct colours for every material so that the
// albedo layer shows which surface each pixel belongs to.
const MaterialInfo Materials[vtkDeepGIDemoScene::NUMBER_OF_MATERIALS] = {
  { "floor", { 0.75, 0.75, 0.72 } },
  { "ceiling", { 0.88, 0.88, 0.86 } },
  { "left wall", { 0.75, 0.08, 0.06 } },
  { "right wall", { 0.08, 0.18, 0.75 } },
  { "back wall", { 0.10, 0.58, 0.14 } },
  { "columns", { 0.82, 0.78, 0.68 } },
  { "gold banners", { 0.90, 0.62, 0.08 } },
  { "purple banners", { 0.48, 0.10, 0.58 } },
  { "mouldings", { 0.96, 0.94, 0.84 } },
  { "decal", { 0.98, 0.90, 0.10 } },
  { "panel", { 0.35, 0.75, 0.90 } },
  { "sphere", { 0.10, 0.62, 0.58 } },
  { "box", { 0.92, 0.45, 0.08 } },
};

struct NamedView
{
  const char* Name;
  double Position[3];
  double FocalPoint[3];
  double ViewAngle;
};

// Unscaled camera setups (see SetCameraToNamedView).
const NamedView NamedViews[] = {
  { "default", { 0.6, 1.7, 3.3 }, { -0.3, 1.65, -4.0 }, 60.0 },
  { "overview", { 4.4, 3.6, 3.9 }, { -1.0, 0.9, -2.0 }, 60.0 },
  { "columns", { 4.4, 1.5, -0.6 }, { -3.5, 1.9, -3.4 }, 55.0 },
  { "decal", { 0.6, 1.7, 3.0 }, { 5.0, 1.9, -0.7 }, 55.0 },
  { "panel", { -1.2, 1.8, 3.4 }, { -5.0, 2.2, 0.6 }, 55.0 },
};
const int NumberOfNamedViews = static_cast<int>(sizeof(NamedViews) / sizeof(NamedViews[0]));

// Triangles of one material, or just their count (the edge length search
// runs the layout many times without building anything).
class MeshBuilder
{
public:
  using Surface = std::function<Vec3(double u, double v)>;

  void Reset(bool countOnly, double scale)
  {
    this->CountOnly = countOnly;
    this->Scale = scale;
    this->NumberOfPoints = 0;
    this->NumberOfTriangles = 0;
    this->Points = nullptr;
    this->Polys = nullptr;
    if (!countOnly)
    {
      this->Points = vtkSmartPointer<vtkPoints>::New();
      this->Polys = vtkSmartPointer<vtkCellArray>::New();
    }
  }

  void Allocate(vtkIdType numberOfPoints, vtkIdType numberOfTriangles)
  {
    if (!this->CountOnly)
    {
      this->Points->Allocate(numberOfPoints);
      this->Polys->AllocateExact(numberOfTriangles, 3 * numberOfTriangles);
    }
  }

  /**
   * A (nu x nv)-quad grid over the unit square, mapped through f; every quad
   * is split into two triangles (p00, p10, p11) and (p00, p11, p01), whose
   * normal is df/du x df/dv. wrapU/wrapV share the seam points of closed
   * surfaces; collapseV0/collapseV1 make the row v = 0 / v = 1 a single
   * point (poles, disc centres), where the degenerate triangles are skipped.
   */
  void Grid(
    int nu, int nv, bool wrapU, bool wrapV, bool collapseV0, bool collapseV1, const Surface& f)
  {
    if (wrapV)
    {
      collapseV0 = collapseV1 = false;
    }
    const int rows = wrapV ? nv : nv + 1;
    const int cols = wrapU ? nu : nu + 1;
    auto collapsed = [&](int j) { return (j == 0 && collapseV0) || (j == nv && collapseV1); };

    vtkIdType points = 0;
    for (int j = 0; j < rows; ++j)
    {
      points += collapsed(j) ? 1 : cols;
    }
    const vtkIdType triangles =
      2 * static_cast<vtkIdType>(nu) * nv - (collapseV0 ? nu : 0) - (collapseV1 ? nu : 0);
    this->NumberOfPoints += points;
    this->NumberOfTriangles += triangles;
    if (this->CountOnly)
    {
      return;
    }

    std::vector<vtkIdType> rowStart(rows);
    for (int j = 0; j < rows; ++j)
    {
      const double v = static_cast<double>(j) / nv;
      rowStart[j] = this->Points->GetNumberOfPoints();
      const int n = collapsed(j) ? 1 : cols;
      for (int i = 0; i < n; ++i)
      {
        const Vec3 p = f(static_cast<double>(i) / nu, v);
        this->Points->InsertNextPoint(this->Scale * p[0], this->Scale * p[1], this->Scale * p[2]);
      }
    }
    auto id = [&](int i, int j) -> vtkIdType
    {
      const int jj = wrapV ? j % rows : j;
      if (collapsed(jj))
      {
        return rowStart[jj];
      }
      return rowStart[jj] + (wrapU ? i % nu : i);
    };
    for (int j = 0; j < nv; ++j)
    {
      const bool collapsedBelow = collapsed(j);
      const bool collapsedAbove = !wrapV && collapsed(j + 1);
      for (int i = 0; i < nu; ++i)
      {
        const vtkIdType p00 = id(i, j), p10 = id(i + 1, j);
        const vtkIdType p11 = id(i + 1, j + 1), p01 = id(i, j + 1);
        if (!collapsedBelow)
        {
          const vtkIdType tri[3] = { p00, p10, p11 };
          this->Polys->InsertNextCell(3, tri);
        }
        if (!collapsedAbove)
        {
          const vtkIdType tri[3] = { p00, p11, p01 };
          this->Polys->InsertNextCell(3, tri);
        }
      }
    }
  }

  bool CountOnly = true;
  double Scale = 1.0;
  vtkIdType NumberOfPoints = 0;
  vtkIdType NumberOfTriangles = 0;
  vtkSmartPointer<vtkPoints> Points;
  vtkSmartPointer<vtkCellArray> Polys;
};

// Number of segments of length at most h along `length`.
int Segments(double length, double h, int minimum)
{
  double n = std::ceil(length / h - 1e-9);
  if (!(n < 1.0e6)) // also catches NaN
  {
    n = 1.0e6;
  }
  return std::max(minimum, static_cast<int>(n));
}

// Unit axes and right-handed frames (e1 x e2 = axis) for cylinders, tori,
// spheres and discs.
const Vec3 X{ 1, 0, 0 }, Y{ 0, 1, 0 }, Z{ 0, 0, 1 };

// Planar parallelogram o + u a + v c, facing a x c.
void Quad(
  MeshBuilder& b, double h, const Vec3& o, const Vec3& a, const Vec3& c, int minU = 1, int minV = 1)
{
  b.Grid(Segments(glm::length(a), h, minU), Segments(glm::length(c), h, minV), false, false, false,
    false, [=](double u, double v) { return o + u * a + v * c; });
}

enum BoxFace
{
  X_MIN = 1,
  X_MAX = 2,
  Y_MIN = 4,
  Y_MAX = 8,
  Z_MIN = 16,
  Z_MAX = 32
};

// Box of `size` around `center`, rotated by angleY degrees about +y, faces
// facing outwards, each face its own grid (hard edges); faces in `omit`
// (BoxFace bits) are left out.
void Box(MeshBuilder& b, double h, const Vec3& center, const Vec3& size, double angleY,
  unsigned int omit = 0)
{
  const double ca = std::cos(vtkMath::RadiansFromDegrees(angleY));
  const double sa = std::sin(vtkMath::RadiansFromDegrees(angleY));
  auto rot = [=](const Vec3& p) -> Vec3 {
    return { ca * p[0] + sa * p[2], p[1], -sa * p[0] + ca * p[2] };
  };
  const Vec3 axes[3] = { X, Y, Z };
  for (int k = 0; k < 3; ++k)
  {
    for (int side = 0; side < 2; ++side)
    {
      if (omit & (1u << (2 * k + side)))
      {
        continue;
      }
      const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
      Vec3 a = size[k1] * axes[k1];
      Vec3 c = size[k2] * axes[k2];
      const double s = side ? 1.0 : -1.0;
      if (!side)
      {
        std::swap(a, c); // a x c = -axes[k]
      }
      const Vec3 o = (0.5 * s * size[k]) * axes[k] - 0.5 * a - 0.5 * c;
      Quad(b, h, center + rot(o), rot(a), rot(c));
    }
  }
}

// Disc of radius r around c, facing e1 x e2, with nu segments around.
void Disc(MeshBuilder& b, double h, const Vec3& c, const Vec3& e1, const Vec3& e2, double r, int nu)
{
  b.Grid(nu, Segments(r, h, 1), true, false, false, true,
    [=](double u, double v)
    {
      const double t = 2.0 * vtkMath::Pi() * u;
      const double rho = r * (1.0 - v);
      return c + (rho * std::cos(t)) * e1 + (rho * std::sin(t)) * e2;
    });
}

// Cylinder of radius r from `base` along axis (= e1 x e2) for `length`,
// facing outwards, with optional discs closing the start and the end.
void Cylinder(MeshBuilder& b, double h, const Vec3& base, const Vec3& axis, const Vec3& e1,
  const Vec3& e2, double r, double length, bool capStart, bool capEnd)
{
  const int nu = Segments(2.0 * vtkMath::Pi() * r, h, 20);
  b.Grid(nu, Segments(length, h, 1), true, false, false, false,
    [=](double u, double v)
    {
      const double t = 2.0 * vtkMath::Pi() * u;
      return base + (r * std::cos(t)) * e1 + (r * std::sin(t)) * e2 + (v * length) * axis;
    });
  if (capEnd)
  {
    Disc(b, h, base + length * axis, e1, e2, r, nu);
  }
  if (capStart)
  {
    Disc(b, h, base, e2, e1, r, nu);
  }
}

// Torus around axis (= e1 x e2) through c: ring radius R, tube radius r.
void Torus(MeshBuilder& b, double h, const Vec3& c, const Vec3& axis, const Vec3& e1,
  const Vec3& e2, double R, double r)
{
  b.Grid(Segments(2.0 * vtkMath::Pi() * (R + r), h, 24), Segments(2.0 * vtkMath::Pi() * r, h, 8),
    true, true, false, false,
    [=](double u, double v)
    {
      const double t = 2.0 * vtkMath::Pi() * u;
      const double p = 2.0 * vtkMath::Pi() * v;
      const Vec3 radial = std::cos(t) * e1 + std::sin(t) * e2;
      return c + (R + r * std::cos(p)) * radial + (r * std::sin(p)) * axis;
    });
}

// Sphere of radius r around c, poles on axis (= e1 x e2).
void Sphere(MeshBuilder& b, double h, const Vec3& c, const Vec3& axis, const Vec3& e1,
  const Vec3& e2, double r)
{
  b.Grid(Segments(2.0 * vtkMath::Pi() * r, h, 24), Segments(vtkMath::Pi() * r, h, 12), true, false,
    true, true,
    [=](double u, double v)
    {
      const double t = 2.0 * vtkMath::Pi() * u;
      const double psi = vtkMath::Pi() * v; // 0 at the -axis pole
      const Vec3 radial = std::cos(t) * e1 + std::sin(t) * e2;
      return c + (r * std::sin(psi)) * radial - (r * std::cos(psi)) * axis;
    });
}

// Room geometry (unscaled units). The same function counts and builds.
void Layout(std::vector<MeshBuilder>& m, double h, bool ceiling)
{
  using S = vtkDeepGIDemoScene;
  const double W = 10.0, H = 4.0, D = 8.0;
  const double x0 = -0.5 * W, x1 = 0.5 * W, z0 = -0.5 * D;

  // Room shell, every face towards the inside.
  Quad(m[S::FLOOR], h, { x0, 0, z0 }, { 0, 0, D }, { W, 0, 0 });
  if (ceiling)
  {
    Quad(m[S::CEILING], h, { x0, H, z0 }, { W, 0, 0 }, { 0, 0, D });
  }
  Quad(m[S::LEFT_WALL], h, { x0, 0, z0 }, { 0, H, 0 }, { 0, 0, D });
  Quad(m[S::RIGHT_WALL], h, { x1, 0, z0 }, { 0, 0, D }, { 0, H, 0 });
  Quad(m[S::BACK_WALL], h, { x0, 0, z0 }, { W, 0, 0 }, { 0, H, 0 });

  // Banners hanging 0.15 in front of the back wall, with shallow folds, and
  // a column in front of each (paper Figures 2 and 16).
  const double columnX[4] = { -3.6, -1.2, 1.2, 3.6 };
  const double bannerZ = z0 + 0.15, bannerWidth = 1.3, bannerBottom = 0.9, bannerTop = 3.5;
  const double columnZ = -2.7;
  for (int i = 0; i < 4; ++i)
  {
    const double left = columnX[i] - 0.5 * bannerWidth;
    MeshBuilder& banner = m[i % 2 ? S::BANNERS_PURPLE : S::BANNERS_GOLD];
    banner.Grid(Segments(bannerWidth, h, 24), Segments(bannerTop - bannerBottom, h, 1), false,
      false, false, false,
      [=](double u, double v) -> Vec3
      {
        return { left + u * bannerWidth, bannerBottom + v * (bannerTop - bannerBottom),
          bannerZ + 0.03 * std::sin(2.0 * vtkMath::Pi() * 3.0 * u) };
      });
    // Rod the banner hangs from.
    Cylinder(m[S::MOULDINGS], h, { left - 0.1, bannerTop + 0.03, bannerZ }, X, Y, Z, 0.03,
      bannerWidth + 0.2, true, true);

    // Column: plinth, two base rings, shaft, two capital rings, abacus.
    MeshBuilder& col = m[S::COLUMNS];
    const double cx = columnX[i];
    Box(col, h, { cx, 0.1, columnZ }, { 0.7, 0.2, 0.7 }, 0.0, Y_MIN);
    Torus(col, h, { cx, 0.26, columnZ }, Y, Z, X, 0.25, 0.06);
    Torus(col, h, { cx, 0.37, columnZ }, Y, Z, X, 0.23, 0.04);
    Cylinder(col, h, { cx, 0.2, columnZ }, Y, Z, X, 0.22, 3.5, false, false);
    Torus(col, h, { cx, 3.53, columnZ }, Y, Z, X, 0.23, 0.04);
    Torus(col, h, { cx, 3.64, columnZ }, Y, Z, X, 0.25, 0.06);
    Box(col, h, { cx, 3.84, columnZ }, { 0.6, 0.28, 0.6 }, 0.0,
      ceiling ? static_cast<unsigned>(Y_MAX) : 0u);
  }

  // Mouldings: baseboards and crown mouldings on the three walls, a chair
  // rail on the left wall (local structure the separation skips). The round
  // ones touch the wall along a line, leaving a crevice; nothing crosses the
  // walls, so the room's bounds are the scene's bounds. Faces against a
  // wall are left out.
  MeshBuilder& mould = m[S::MOULDINGS];
  Box(mould, h, { x0 + 0.02, 0.08, 0.0 }, { 0.04, 0.16, D }, 0.0, X_MIN | Y_MIN | Z_MIN);
  Box(mould, h, { x1 - 0.02, 0.08, 0.0 }, { 0.04, 0.16, D }, 0.0, X_MAX | Y_MIN | Z_MIN);
  Box(mould, h, { 0.0, 0.08, z0 + 0.02 }, { W - 0.08, 0.16, 0.04 }, 0.0,
    X_MIN | X_MAX | Y_MIN | Z_MIN);
  const double crown = 0.08, rail = 0.05;
  Cylinder(mould, h, { x0 + crown, H - crown, z0 }, Z, X, Y, crown, D, false, true);
  Cylinder(mould, h, { x1 - crown, H - crown, z0 }, Z, X, Y, crown, D, false, true);
  Cylinder(mould, h, { x0, H - crown, z0 + crown }, X, Y, Z, crown, W, false, false);
  Cylinder(mould, h, { x0 + rail, 1.0, z0 }, Z, X, Y, rail, D, false, true);

  // Thin panel (a painting) whose back is 0.05 in front of the left wall.
  Box(m[S::PANEL], h, { x0 + 0.05 + 0.01, 2.3, 0.8 }, { 0.02, 1.2, 2.0 }, 0.0);

  // Decal: a quad 0.002 x room width in front of the right wall.
  const double decalGap = 0.002 * W;
  Quad(m[S::DECAL], h, { x1 - decalGap, 1.3, -1.4 }, { 0, 0, 1.4 }, { 0, 1.4, 0 });

  // Objects on the floor.
  Sphere(m[S::SPHERE], h, { 2.4, 0.5, -0.8 }, Y, Z, X, 0.5);
  Box(m[S::BOX], h, { -2.2, 0.45, 0.9 }, { 0.9, 0.9, 0.9 }, 30.0, Y_MIN);
}

vtkIdType CountTriangles(std::vector<MeshBuilder>& m, double h, bool ceiling)
{
  for (auto& b : m)
  {
    b.Reset(true, 1.0);
  }
  Layout(m, h, ceiling);
  vtkIdType n = 0;
  for (auto& b : m)
  {
    n += b.NumberOfTriangles;
  }
  return n;
}
// The largest edge length h whose tessellation reaches `target` triangles.
// The count is monotone (non-increasing) in h, so bisect in log space.
double EdgeLengthForTarget(std::vector<MeshBuilder>& builders, vtkIdType target, bool ceiling)
{
  double h = 20.0;
  if (CountTriangles(builders, h, ceiling) >= target)
  {
    return h;
  }
  double ok = h;
  for (int i = 0; i < 80 && CountTriangles(builders, ok, ceiling) < target; ++i)
  {
    ok *= 0.5;
  }
  double notOk = 2.0 * ok;
  for (int i = 0; i < 40; ++i)
  {
    const double mid = std::sqrt(ok * notOk);
    if (CountTriangles(builders, mid, ceiling) >= target)
    {
      ok = mid;
    }
    else
    {
      notOk = mid;
    }
  }
  return ok;
}

// The triangles of material `material` built by `builder`, with point
// normals when `computeNormals`, and the per-triangle albedo "Colors" and
// "MaterialId" that ray tracers and captures read.
vtkSmartPointer<vtkPolyData> MaterialMesh(
  const MeshBuilder& builder, int material, bool computeNormals, double featureAngle)
{
  vtkNew<vtkPolyData> raw;
  raw->SetPoints(builder.Points);
  raw->SetPolys(builder.Polys);
  vtkSmartPointer<vtkPolyData> pd = raw.Get();
  if (computeNormals && raw->GetNumberOfPolys() > 0)
  {
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputData(raw);
    normals->SetFeatureAngle(featureAngle);
    normals->SplittingOn();
    normals->ConsistencyOff(); // the layout orients every triangle itself
    normals->AutoOrientNormalsOff();
    normals->ComputePointNormalsOn();
    normals->ComputeCellNormalsOff();
    normals->Update();
    pd = normals->GetOutput();
  }
  const vtkIdType nCells = pd->GetNumberOfCells();
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("Colors");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(nCells);
  unsigned char rgb[3];
  for (int c = 0; c < 3; ++c)
  {
    rgb[c] = static_cast<unsigned char>(std::lround(255.0 * Materials[material].Color[c]));
  }
  vtkNew<vtkIntArray> ids;
  ids->SetName("MaterialId");
  ids->SetNumberOfTuples(nCells);
  for (vtkIdType c = 0; c < nCells; ++c)
  {
    colors->SetTypedTuple(c, rgb);
    ids->SetValue(c, material);
  }
  pd->GetCellData()->AddArray(colors);
  pd->GetCellData()->AddArray(ids);
  return pd;
}
} // anonymous namespace

//------------------------------------------------------------------------------
vtkDeepGIDemoScene::vtkDeepGIDemoScene()
{
  this->SetNumberOfInputPorts(0);
}

vtkDeepGIDemoScene::~vtkDeepGIDemoScene() = default;

//------------------------------------------------------------------------------
void vtkDeepGIDemoScene::SetScaleFactor(double scale)
{
  if (!std::isfinite(scale) || scale <= 0.0)
  {
    vtkErrorMacro("ScaleFactor must be finite and positive, got " << scale << "; keeping "
                                                                  << this->ScaleFactor);
    return;
  }
  if (scale != this->ScaleFactor)
  {
    this->ScaleFactor = scale;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkDeepGIDemoScene::Build()
{
  if (!this->MaterialPolyData.empty() && this->BuildTime > this->GetMTime())
  {
    return;
  }

  std::vector<MeshBuilder> builders(NUMBER_OF_MATERIALS);
  const double h = EdgeLengthForTarget(builders, this->TargetNumberOfTriangles, this->Ceiling);
  this->EdgeLength = h;

  // Exact sizes for the allocation, then the real build.
  CountTriangles(builders, h, this->Ceiling);
  std::vector<std::pair<vtkIdType, vtkIdType>> sizes;
  for (auto& b : builders)
  {
    sizes.emplace_back(b.NumberOfPoints, b.NumberOfTriangles);
    b.Reset(false, this->ScaleFactor);
  }
  for (size_t i = 0; i < builders.size(); ++i)
  {
    builders[i].Allocate(sizes[i].first, sizes[i].second);
  }
  Layout(builders, h, this->Ceiling);

  this->MaterialPolyData.clear();
  this->ScenePolyData = nullptr;
  for (int i = 0; i < NUMBER_OF_MATERIALS; ++i)
  {
    this->MaterialPolyData.push_back(
      MaterialMesh(builders[i], i, this->ComputeNormals, this->FeatureAngle));
  }
  this->BuildTime.Modified();
}

//------------------------------------------------------------------------------
int vtkDeepGIDemoScene::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData::GetData(outputVector)->ShallowCopy(this->GetScenePolyData());
  return 1;
}

//------------------------------------------------------------------------------
vtkIdType vtkDeepGIDemoScene::GetNumberOfTriangles()
{
  this->Build();
  vtkIdType n = 0;
  for (const auto& pd : this->MaterialPolyData)
  {
    n += pd->GetNumberOfPolys();
  }
  return n;
}

//------------------------------------------------------------------------------
vtkIdType vtkDeepGIDemoScene::GetNumberOfPoints()
{
  this->Build();
  vtkIdType n = 0;
  for (const auto& pd : this->MaterialPolyData)
  {
    n += pd->GetNumberOfPoints();
  }
  return n;
}

//------------------------------------------------------------------------------
double vtkDeepGIDemoScene::GetEdgeLength()
{
  this->Build();
  return this->EdgeLength;
}

//------------------------------------------------------------------------------
vtkPolyData* vtkDeepGIDemoScene::GetMaterialPolyData(int material)
{
  if (material < 0 || material >= NUMBER_OF_MATERIALS)
  {
    vtkErrorMacro("No material " << material);
    return nullptr;
  }
  this->Build();
  return this->MaterialPolyData[material];
}

//------------------------------------------------------------------------------
vtkPolyData* vtkDeepGIDemoScene::GetScenePolyData()
{
  this->Build();
  if (!this->ScenePolyData || this->ScenePolyData->GetMTime() < this->BuildTime)
  {
    vtkNew<vtkAppendPolyData> append;
    for (const auto& pd : this->MaterialPolyData)
    {
      if (pd->GetNumberOfCells() > 0)
      {
        append->AddInputData(pd);
      }
    }
    append->Update();
    this->ScenePolyData = vtkSmartPointer<vtkPolyData>::New();
    this->ScenePolyData->ShallowCopy(append->GetOutput());
    // The actors' diffuse coefficient, for references that light the scene.
    vtkNew<vtkDoubleArray> diffuse;
    diffuse->SetName("Diffuse");
    diffuse->InsertNextValue(MaterialDiffuse);
    this->ScenePolyData->GetFieldData()->AddArray(diffuse);
  }
  return this->ScenePolyData;
}

//------------------------------------------------------------------------------
void vtkDeepGIDemoScene::GetBounds(double bounds[6])
{
  this->Build();
  vtkMath::UninitializeBounds(bounds);
  bool first = true;
  for (const auto& pd : this->MaterialPolyData)
  {
    if (pd->GetNumberOfPoints() == 0)
    {
      continue;
    }
    double b[6];
    pd->GetBounds(b);
    for (int i = 0; i < 3; ++i)
    {
      bounds[2 * i] = first ? b[2 * i] : std::min(bounds[2 * i], b[2 * i]);
      bounds[2 * i + 1] = first ? b[2 * i + 1] : std::max(bounds[2 * i + 1], b[2 * i + 1]);
    }
    first = false;
  }
}

//------------------------------------------------------------------------------
const char* vtkDeepGIDemoScene::GetMaterialName(int material)
{
  if (material < 0 || material >= NUMBER_OF_MATERIALS)
  {
    return nullptr;
  }
  return Materials[material].Name;
}

//------------------------------------------------------------------------------
void vtkDeepGIDemoScene::GetMaterialColor(int material, double rgb[3])
{
  for (int c = 0; c < 3; ++c)
  {
    rgb[c] = (material < 0 || material >= NUMBER_OF_MATERIALS) ? 0.0 : Materials[material].Color[c];
  }
}

//------------------------------------------------------------------------------
void vtkDeepGIDemoScene::Populate(vtkRenderer* renderer)
{
  this->AddActors(renderer);
  this->AddLights(renderer);
}

//------------------------------------------------------------------------------
void vtkDeepGIDemoScene::AddActors(vtkRenderer* renderer)
{
  if (!renderer)
  {
    vtkErrorMacro("AddActors: no renderer");
    return;
  }
  this->Build();
  for (int i = 0; i < NUMBER_OF_MATERIALS; ++i)
  {
    vtkPolyData* pd = this->MaterialPolyData[i];
    if (pd->GetNumberOfCells() == 0)
    {
      continue;
    }
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(pd);
    mapper->ScalarVisibilityOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    vtkProperty* property = actor->GetProperty();
    property->SetDiffuseColor(Materials[i].Color[0], Materials[i].Color[1], Materials[i].Color[2]);
    property->SetAmbientColor(Materials[i].Color[0], Materials[i].Color[1], Materials[i].Color[2]);
    property->SetAmbient(MaterialAmbient);
    property->SetDiffuse(MaterialDiffuse);
    property->SetSpecular(0.0);
    property->SetInterpolationToPhong();
    renderer->AddActor(actor);
  }
}

//------------------------------------------------------------------------------
void vtkDeepGIDemoScene::AddLights(vtkRenderer* renderer)
{
  if (!renderer)
  {
    vtkErrorMacro("AddLights: no renderer");
    return;
  }
  const double s = this->ScaleFactor;

  vtkNew<vtkLight> point;
  point->SetLightTypeToSceneLight();
  point->SetPositional(true);
  point->SetConeAngle(180.0); // >= 90: a point light, not a spot light
  point->SetAttenuationValues(1.0, 0.0, 0.0);
  point->SetPosition(0.0, 3.0 * s, 0.5 * s);
  point->SetFocalPoint(0.0, 0.0, 0.5 * s);
  point->SetColor(1.0, 0.95, 0.85);
  point->SetIntensity(0.75);
  renderer->AddLight(point);

  vtkNew<vtkLight> fill;
  fill->SetLightTypeToSceneLight();
  fill->SetPositional(false);
  fill->SetPosition(-2.0 * s, 5.0 * s, 3.5 * s);
  fill->SetFocalPoint(0.0, 0.0, 0.0);
  fill->SetColor(0.85, 0.9, 1.0);
  fill->SetIntensity(0.35);
  renderer->AddLight(fill);
}

//------------------------------------------------------------------------------
void vtkDeepGIDemoScene::SetCamera(
  vtkCamera* camera, const double position[3], const double focalPoint[3], double viewAngle)
{
  const double s = this->ScaleFactor;
  camera->SetFocalPoint(s * focalPoint[0], s * focalPoint[1], s * focalPoint[2]);
  camera->SetPosition(s * position[0], s * position[1], s * position[2]);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->OrthogonalizeViewUp();
  camera->SetViewAngle(viewAngle);
  camera->SetClippingRange(0.05 * s, 30.0 * s);
}

//------------------------------------------------------------------------------
void vtkDeepGIDemoScene::SetCameraToDefaultView(vtkCamera* camera)
{
  this->SetCameraToNamedView(camera, "default");
}

//------------------------------------------------------------------------------
void vtkDeepGIDemoScene::SetCameraToPathFrame(vtkCamera* camera, int frame, int numberOfFrames)
{
  if (!camera)
  {
    vtkErrorMacro("SetCameraToPathFrame: no camera");
    return;
  }
  const long long n = std::max(1, numberOfFrames);
  const long long f = ((static_cast<long long>(frame) % n) + n) % n;
  const double phi = 2.0 * vtkMath::Pi() * static_cast<double>(f) / static_cast<double>(n);
  // An ellipse in front of the column row; looking at the back wall a little
  // towards the side the camera is on, so the columns sweep over the banners.
  const double position[3] = { 2.6 * std::sin(phi), 1.7 + 0.15 * std::sin(2.0 * phi),
    2.4 + 0.5 * std::cos(phi) };
  const double focalPoint[3] = { 0.4 * position[0], 1.6, -4.0 };
  this->SetCamera(camera, position, focalPoint, 60.0);
}

//------------------------------------------------------------------------------
bool vtkDeepGIDemoScene::SetCameraToNamedView(vtkCamera* camera, const char* name)
{
  if (!camera || !name)
  {
    vtkErrorMacro("SetCameraToNamedView: no camera or no name");
    return false;
  }
  for (const auto& view : NamedViews)
  {
    if (std::string(view.Name) == name)
    {
      this->SetCamera(camera, view.Position, view.FocalPoint, view.ViewAngle);
      return true;
    }
  }
  std::string known;
  for (const auto& view : NamedViews)
  {
    known += std::string(known.empty() ? "" : ", ") + view.Name;
  }
  vtkErrorMacro("Unknown view \"" << name << "\"; known views: " << known);
  return false;
}

//------------------------------------------------------------------------------
int vtkDeepGIDemoScene::GetNumberOfNamedViews()
{
  return NumberOfNamedViews;
}

//------------------------------------------------------------------------------
const char* vtkDeepGIDemoScene::GetNamedViewName(int index)
{
  return (index >= 0 && index < NumberOfNamedViews) ? NamedViews[index].Name : nullptr;
}

//------------------------------------------------------------------------------
void vtkDeepGIDemoScene::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TargetNumberOfTriangles: " << this->TargetNumberOfTriangles << "\n";
  os << indent << "ScaleFactor: " << this->ScaleFactor << "\n";
  os << indent << "Ceiling: " << (this->Ceiling ? "On" : "Off") << "\n";
  os << indent << "ComputeNormals: " << (this->ComputeNormals ? "On" : "Off") << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "EdgeLength (last build): " << this->EdgeLength << "\n";
  vtkIdType triangles = 0;
  for (const auto& pd : this->MaterialPolyData)
  {
    triangles += pd->GetNumberOfPolys();
  }
  os << indent << "NumberOfTriangles (last build): " << triangles << "\n";
}
