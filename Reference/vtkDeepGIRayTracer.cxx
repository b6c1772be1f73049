#include "vtkDeepGIRayTracer.h"
#include "vtkDeepGICaptureNames.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkDeepGIRayTracer);

namespace
{
// splitmix64 finaliser: a bijective 64-bit mix.
inline std::uint64_t Mix64(std::uint64_t z)
{
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

void EmbreeError(void*, RTCError code, const char* message)
{
  vtkGenericWarningMacro(
    "Embree error " << static_cast<int>(code) << ": " << (message ? message : ""));
}

// Orthonormal basis (t, b) around unit n (Duff et al. 2017).
void Basis(const double n[3], double t[3], double b[3])
{
  const double sign = std::copysign(1.0, n[2]);
  const double a = -1.0 / (sign + n[2]);
  const double c = n[0] * n[1] * a;
  t[0] = 1.0 + sign * n[0] * n[0] * a;
  t[1] = sign * c;
  t[2] = -sign * n[0];
  b[0] = c;
  b[1] = sign + n[1] * n[1] * a;
  b[2] = -n[1];
}

// An Embree ray from a world-space origin, in the scene's centred frame.
void SetRay(RTCRay& ray, const double centre[3], const double origin[3], const double direction[3],
  double tmax)
{
  ray.org_x = static_cast<float>(origin[0] - centre[0]);
  ray.org_y = static_cast<float>(origin[1] - centre[1]);
  ray.org_z = static_cast<float>(origin[2] - centre[2]);
  ray.dir_x = static_cast<float>(direction[0]);
  ray.dir_y = static_cast<float>(direction[1]);
  ray.dir_z = static_cast<float>(direction[2]);
  ray.tnear = 0.0f;
  ray.tfar = static_cast<float>(std::min(tmax, static_cast<double>(FLT_MAX)));
  ray.time = 0.0f;
  ray.mask = 0xFFFFFFFFu;
  ray.id = 0;
  ray.flags = 0;
}
}

// Layer `Layer` of a capture: its per-pixel arrays (owned by the capture),
// the matrices that take its pixels back to world space and the camera.
struct vtkDeepGIRayTracer::CaptureLayer
{
  int Dimensions[3] = { 0, 0, 0 };
  vtkIdType Pixels = 0;
  vtkDataArray* Depth = nullptr;
  vtkDataArray* Normal = nullptr;
  vtkDataArray* Valid = nullptr;      // optional
  vtkNew<vtkMatrix4x4> View;          // world to camera
  vtkNew<vtkMatrix4x4> CameraToWorld; // inverse view
  vtkNew<vtkMatrix4x4> NDCToCamera;   // inverse projection
  double Eye[3] = { 0, 0, 0 };
  double ViewDirection[3] = { 0, 0, -1 };
  bool Parallel = false;
};

// Per-thread scratch of the Monte Carlo estimate of one pixel: running sums
// of the sample values and of their squares, then mean and standard error.
struct vtkDeepGIRayTracer::PixelEstimate
{
  explicit PixelEstimate(int components)
    : Sum(components)
    , Sum2(components)
    , Values(components)
    , Mean(components)
    , Error(components)
  {
  }
  std::vector<double> Sum, Sum2, Values, Mean, Error;
};

struct vtkDeepGIRayTracer::Internals
{
  RTCDevice Device = nullptr;
  RTCScene Scene = nullptr;
  vtkSmartPointer<vtkPolyData> BuiltFor;
  vtkMTimeType BuiltTime = 0;
  std::vector<vtkIdType> TriangleToCell;
  // Scene point ids of each fan triangle (3 per triangle), for HitRecord.
  std::vector<unsigned int> Indices;
  double Centre[3] = { 0, 0, 0 };
  double Diagonal = 0.0;

  CaptureLayer Layer;
  Sampling Settings = { 0, 0, 0.0 };
  // The largest standard-error component of each pixel, as stored (float).
  std::vector<float> LargestError;

  vtkIdType NumberOfValidPixels = 0;
  vtkIdType NumberOfRays = 0;
  double MeanStandardError = 0.0;
  double MaximumStandardError = 0.0;
  double ComputeTime = 0.0;

  void ResetStatistics()
  {
    this->NumberOfValidPixels = this->NumberOfRays = 0;
    this->MeanStandardError = this->MaximumStandardError = this->ComputeTime = 0.0;
  }
  // The centre of the points' bounds (the origin of the Embree scene's
  // coordinates) and the diagonal of the bounds.
  void SetFrame(vtkPoints* points)
  {
    double bounds[6];
    points->GetBounds(bounds);
    for (int c = 0; c < 3; ++c)
    {
      this->Centre[c] = 0.5 * (bounds[2 * c] + bounds[2 * c + 1]);
    }
    this->Diagonal = std::sqrt(vtkMath::Distance2BetweenPoints(
      std::array<double, 3>{ bounds[0], bounds[2], bounds[4] }.data(),
      std::array<double, 3>{ bounds[1], bounds[3], bounds[5] }.data()));
  }

  // Fan-triangulates the polygons into Indices and TriangleToCell; cell ids
  // follow the polydata's cell order (verts and lines come first there).
  void Triangulate(vtkPolyData* scene)
  {
    const vtkIdType cellOffset = scene->GetNumberOfVerts() + scene->GetNumberOfLines();
    auto iter = vtk::TakeSmartPointer(scene->GetPolys()->NewIterator());
    vtkIdType cell = 0;
    for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell(), ++cell)
    {
      vtkIdType npts;
      const vtkIdType* pts;
      iter->GetCurrentCell(npts, pts);
      for (vtkIdType k = 1; k + 1 < npts; ++k)
      {
        this->Indices.push_back(static_cast<unsigned int>(pts[0]));
        this->Indices.push_back(static_cast<unsigned int>(pts[k]));
        this->Indices.push_back(static_cast<unsigned int>(pts[k + 1]));
        this->TriangleToCell.push_back(cellOffset + cell);
      }
    }
  }

  // One Embree triangle geometry of the points (relative to Centre, in
  // float) and Indices, committed as Scene; false when Embree cannot
  // allocate its buffers.
  bool Commit(vtkPoints* points)
  {
    const vtkIdType npoints = points->GetNumberOfPoints();
    this->Scene = rtcNewScene(this->Device);
    rtcSetSceneBuildQuality(this->Scene, RTC_BUILD_QUALITY_HIGH);
    RTCGeometry geometry = rtcNewGeometry(this->Device, RTC_GEOMETRY_TYPE_TRIANGLE);
    float* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), npoints));
    unsigned int* triangles =
      static_cast<unsigned int*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0,
        RTC_FORMAT_UINT3, 3 * sizeof(unsigned int), this->Indices.size() / 3));
    if (!vertices || !triangles)
    {
      rtcReleaseGeometry(geometry);
      return false;
    }
    for (vtkIdType p = 0; p < npoints; ++p)
    {
      double x[3];
      points->GetPoint(p, x);
      for (int c = 0; c < 3; ++c)
      {
        vertices[3 * p + c] = static_cast<float>(x[c] - this->Centre[c]);
      }
    }
    std::copy(this->Indices.begin(), this->Indices.end(), triangles);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(this->Scene, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(this->Scene);
    return true;
  }

  void Release()
  {
    if (this->Scene)
    {
      rtcReleaseScene(this->Scene);
      this->Scene = nullptr;
    }
    this->BuiltFor = nullptr;
    this->TriangleToCell.clear();
    this->Indices.clear();
  }
  ~Internals()
  {
    this->Release();
    if (this->Device)
    {
      rtcReleaseDevice(this->Device);
    }
  }
};

//------------------------------------------------------------------------------
vtkDeepGIRayTracer::vtkDeepGIRayTracer()
  : Internal(new Internals)
{
}

vtkDeepGIRayTracer::~vtkDeepGIRayTracer() = default;

//------------------------------------------------------------------------------
bool vtkDeepGIRayTracer::Run(vtkImageData* capture, vtkPolyData* scene, const Sampling& sampling,
  Estimator& estimator, vtkImageData* output, vtkObject* reporter)
{
  const auto start = std::chrono::steady_clock::now();
  Internals& in = *this->Internal;
  in.ResetStatistics();
  in.Settings = sampling;
  output->Initialize();
  if (!capture || !scene)
  {
    vtkErrorWithObjectMacro(reporter, << (!capture ? "No capture." : "No scene."));
    return false;
  }
  if (!this->ReadCapture(capture, sampling.Layer, reporter) || !this->BuildScene(scene, reporter))
  {
    return false;
  }
  this->PrepareOutput(capture, output);
  if (!estimator.Prepare(capture, scene, output))
  {
    output->Initialize();
    return false;
  }
  vtkNew<vtkUnsignedCharArray> valid;
  valid->SetName(vtkDeepGICaptureNames::Valid);
  valid->SetNumberOfTuples(in.Layer.Pixels);
  output->GetPointData()->AddArray(valid);
  this->EstimateRows(estimator, output);
  this->GatherStatistics(output, estimator.GetNumberOfSamples());
  in.ComputeTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return true;
}

//------------------------------------------------------------------------------
// Finds the arrays of layer `layer` and the camera matrices; false with
// an error when the capture lacks them.
bool vtkDeepGIRayTracer::ReadCapture(vtkImageData* capture, int layerIndex, vtkObject* reporter)
{
  CaptureLayer& layer = this->Internal->Layer;
  capture->GetDimensions(layer.Dimensions);
  layer.Pixels = capture->GetNumberOfPoints();
  const vtkIdType pixels = layer.Pixels;
  const std::string suffix = "_" + std::to_string(layerIndex);
  vtkPointData* pd = capture->GetPointData();
  layer.Depth = pd->GetArray((vtkDeepGICaptureNames::Depth + suffix).c_str());
  layer.Normal = pd->GetArray((vtkDeepGICaptureNames::Normal + suffix).c_str());
  layer.Valid = pd->GetArray((vtkDeepGICaptureNames::Valid + suffix).c_str());
  if (pixels <= 0 || layer.Dimensions[2] != 1 || !layer.Depth || !layer.Normal ||
    layer.Normal->GetNumberOfComponents() != 3 || layer.Depth->GetNumberOfTuples() != pixels ||
    layer.Normal->GetNumberOfTuples() != pixels ||
    (layer.Valid && layer.Valid->GetNumberOfTuples() != pixels))
  {
    vtkErrorWithObjectMacro(reporter,
      "The capture has no 2D layer " << layerIndex << " (arrays Depth" << suffix << ", Normal"
                                     << suffix << ").");
    return false;
  }
  vtkDataArray* view = capture->GetFieldData()->GetArray(vtkDeepGICaptureNames::ViewMatrix);
  vtkDataArray* projection =
    capture->GetFieldData()->GetArray(vtkDeepGICaptureNames::ProjectionMatrix);
  if (!view || !projection || view->GetNumberOfValues() < 16 ||
    projection->GetNumberOfValues() < 16)
  {
    vtkErrorWithObjectMacro(reporter, "The capture has no ViewMatrix/ProjectionMatrix field data.");
    return false;
  }
  // Camera to world (inverse view) and NDC to camera (inverse projection).
  vtkNew<vtkMatrix4x4> projectionMatrix;
  for (int k = 0; k < 16; ++k)
  {
    layer.View->SetElement(k / 4, k % 4, view->GetComponent(0, k));
    projectionMatrix->SetElement(k / 4, k % 4, projection->GetComponent(0, k));
  }
  vtkMatrix4x4::Invert(layer.View, layer.CameraToWorld);
  vtkMatrix4x4::Invert(projectionMatrix, layer.NDCToCamera);
  // The eye is the inverse view matrix's translation, the view direction
  // its -z axis. A perspective projection's last row is (0, 0, -1, 0), a
  // parallel one's (0, 0, 0, 1).
  for (int c = 0; c < 3; ++c)
  {
    layer.Eye[c] = layer.CameraToWorld->GetElement(c, 3);
    layer.ViewDirection[c] = -layer.CameraToWorld->GetElement(c, 2);
  }
  vtkMath::Normalize(layer.ViewDirection);
  layer.Parallel = projection->GetComponent(0, 14) == 0.0;
  return true;
}

//------------------------------------------------------------------------------
bool vtkDeepGIRayTracer::BuildScene(vtkPolyData* scene, vtkObject* reporter)
{
  Internals& in = *this->Internal;
  if (in.Scene && in.BuiltFor == scene && in.BuiltTime >= scene->GetMTime())
  {
    return true;
  }
  in.Release();
  if (!in.Device)
  {
    in.Device = rtcNewDevice(nullptr);
    if (!in.Device)
    {
      vtkErrorWithObjectMacro(reporter, "Cannot create an Embree device.");
      return false;
    }
    rtcSetDeviceErrorFunction(in.Device, EmbreeError, nullptr);
  }
  vtkPoints* points = scene->GetPoints();
  vtkCellArray* polys = scene->GetPolys();
  if (!points || !polys || polys->GetNumberOfCells() == 0)
  {
    vtkErrorWithObjectMacro(reporter, "The scene has no polygons.");
    return false;
  }
  in.SetFrame(points);
  in.Triangulate(scene);
  if (in.Indices.empty())
  {
    vtkErrorWithObjectMacro(reporter, "The scene has no polygons with three or more points.");
    return false;
  }
  if (!in.Commit(points))
  {
    vtkErrorWithObjectMacro(reporter, "Embree could not allocate the scene buffers.");
    in.Release();
    return false;
  }
  in.BuiltFor = scene;
  in.BuiltTime = scene->GetMTime();
  return true;
}

//------------------------------------------------------------------------------
bool vtkDeepGIRayTracer::TraceRay(
  const double origin[3], const double direction[3], double tmax, HitRecord& hit) const
{
  const Internals& in = *this->Internal;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh;
  SetRay(rh.ray, in.Centre, origin, direction, tmax);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(in.Scene, &context, &rh);
  hit.Hit = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
  if (!hit.Hit)
  {
    hit.Distance = std::numeric_limits<double>::infinity();
    hit.Cell = -1;
    for (int k = 0; k < 3; ++k)
    {
      hit.Normal[k] = hit.Weights[k] = 0.0;
      hit.PointIds[k] = -1;
    }
    return false;
  }
  hit.Distance = rh.ray.tfar;
  hit.Cell = in.TriangleToCell[rh.hit.primID];
  // Embree's (u, v) weight vertices 1 and 2; vertex 0 gets 1 - u - v.
  for (int k = 0; k < 3; ++k)
  {
    hit.PointIds[k] = in.Indices[3 * static_cast<size_t>(rh.hit.primID) + k];
  }
  hit.Weights[1] = rh.hit.u;
  hit.Weights[2] = rh.hit.v;
  hit.Weights[0] = 1.0 - hit.Weights[1] - hit.Weights[2];
  // The winding normal (p1 - p0) x (p2 - p0), the side OpenGL and VTK call
  // front facing, from the double-precision points rather than Embree's
  // float Ng (whose orientation convention is Embree's own).
  double p[3][3];
  for (int k = 0; k < 3; ++k)
  {
    in.BuiltFor->GetPoints()->GetPoint(hit.PointIds[k], p[k]);
  }
  double e1[3], e2[3];
  vtkMath::Subtract(p[1], p[0], e1);
  vtkMath::Subtract(p[2], p[0], e2);
  vtkMath::Cross(e1, e2, hit.Normal);
  vtkMath::Normalize(hit.Normal);
  return true;
}

//------------------------------------------------------------------------------
bool vtkDeepGIRayTracer::IsOccluded(
  const double origin[3], const double direction[3], double tmax) const
{
  const Internals& in = *this->Internal;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray;
  SetRay(ray, in.Centre, origin, direction, tmax);
  rtcOccluded1(in.Scene, &context, &ray);
  // rtcOccluded1 sets tfar to -inf when it finds a hit.
  return ray.tfar < 0.0f;
}

//------------------------------------------------------------------------------
double vtkDeepGIRayTracer::GetRayOffset(const double point[3]) const
{
  const Internals& in = *this->Internal;
  const double rel[3] = { point[0] - in.Centre[0], point[1] - in.Centre[1],
    point[2] - in.Centre[2] };
  return in.Settings.RelativeOffset * (in.Diagonal + vtkMath::Norm(rel));
}

//------------------------------------------------------------------------------
double vtkDeepGIRayTracer::Random(vtkIdType pixel, int sample, int dimension) const
{
  std::uint64_t h =
    Mix64(static_cast<std::uint64_t>(this->Internal->Settings.Seed) ^ 0x5851f42d4c957f2dULL);
  h = Mix64(h ^ static_cast<std::uint64_t>(pixel));
  h = Mix64(h ^
    ((static_cast<std::uint64_t>(static_cast<std::uint32_t>(sample)) << 8) |
      static_cast<std::uint64_t>(dimension & 0xff)));
  return static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0);
}

void vtkDeepGIRayTracer::CosineDirection(const double n[3], double u1, double u2, double w[3])
{
  // Malley's method: uniform on the disc, projected up onto the hemisphere.
  double t[3], b[3];
  Basis(n, t, b);
  const double radius = std::sqrt(u1);
  const double phi = 2.0 * vtkMath::Pi() * u2;
  const double lx = radius * std::cos(phi), ly = radius * std::sin(phi);
  const double lz = std::sqrt(std::max(0.0, 1.0 - u1));
  for (int c = 0; c < 3; ++c)
  {
    w[c] = lx * t[c] + ly * b[c] + lz * n[c];
  }
  vtkMath::Normalize(w);
}

void vtkDeepGIRayTracer::TraceCosineRay(
  const SurfacePoint& x, int sample, double tmax, double w[3], HitRecord& hit) const
{
  CosineDirection(x.Normal, this->Random(x.Pixel, sample, 0), this->Random(x.Pixel, sample, 1), w);
  this->TraceRay(x.Origin, w, tmax, hit);
}

//------------------------------------------------------------------------------
double vtkDeepGIRayTracer::ViewRay(const double point[3], double v[3]) const
{
  const CaptureLayer& layer = this->Internal->Layer;
  if (layer.Parallel)
  {
    std::copy(layer.ViewDirection, layer.ViewDirection + 3, v);
    double toPoint[3];
    vtkMath::Subtract(point, layer.Eye, toPoint);
    return std::fabs(vtkMath::Dot(toPoint, v));
  }
  vtkMath::Subtract(point, layer.Eye, v);
  return vtkMath::Normalize(v);
}

//------------------------------------------------------------------------------
// The output on the capture's grid, without arrays yet.
void vtkDeepGIRayTracer::PrepareOutput(vtkImageData* capture, vtkImageData* output)
{
  output->SetExtent(capture->GetExtent());
  output->SetSpacing(capture->GetSpacing());
  output->SetOrigin(capture->GetOrigin());
}

//------------------------------------------------------------------------------
// Every pixel of the layer, rows in parallel. The random numbers of a sample
// depend only on (Seed, pixel, sample, dimension), so the result does not
// depend on how vtkSMPTools splits the rows.
void vtkDeepGIRayTracer::EstimateRows(Estimator& estimator, vtkImageData* output)
{
  Internals& in = *this->Internal;
  const int width = in.Layer.Dimensions[0];
  const int components = estimator.GetNumberOfComponents();
  auto valid = vtkUnsignedCharArray::SafeDownCast(
    output->GetPointData()->GetArray(vtkDeepGICaptureNames::Valid));
  in.LargestError.assign(in.Layer.Pixels, 0.0f);
  vtkSMPTools::For(0, in.Layer.Dimensions[1],
    [&](vtkIdType rowBegin, vtkIdType rowEnd)
    {
      PixelEstimate estimate(components);
      for (vtkIdType row = rowBegin; row < rowEnd; ++row)
      {
        for (int col = 0; col < width; ++col)
        {
          const vtkIdType pixel = row * width + col;
          SurfacePoint x;
          const bool isValid = this->ReconstructSurface(row, col, x);
          valid->SetValue(pixel, isValid ? 1 : 0);
          if (!isValid)
          {
            estimator.FinishPixel(pixel, nullptr, nullptr);
            continue;
          }
          this->EstimatePixel(estimator, x, estimate);
          estimator.FinishPixel(pixel, estimate.Mean.data(), estimate.Error.data());
          float largest = 0.0f;
          for (double e : estimate.Error)
          {
            largest = std::max(largest, static_cast<float>(e));
          }
          in.LargestError[pixel] = largest;
        }
      }
    });
}

//------------------------------------------------------------------------------
// X, n and the ray origin of pixel (col, row) from the layer's depth and
// camera-space normal; false for pixels without a usable surface.
bool vtkDeepGIRayTracer::ReconstructSurface(vtkIdType row, int col, SurfacePoint& x) const
{
  const CaptureLayer& layer = this->Internal->Layer;
  const int width = layer.Dimensions[0];
  const int height = layer.Dimensions[1];
  const vtkIdType pixel = row * width + col;
  const double distance = layer.Depth->GetComponent(pixel, 0);
  double n[3] = { layer.Normal->GetComponent(pixel, 0), layer.Normal->GetComponent(pixel, 1),
    layer.Normal->GetComponent(pixel, 2) };
  const bool isValid = (!layer.Valid || layer.Valid->GetComponent(pixel, 0) != 0) &&
    std::isfinite(distance) && distance > 0.0 && std::isfinite(n[0]) && std::isfinite(n[1]) &&
    std::isfinite(n[2]) && vtkMath::Norm(n) > 0.5;
  if (!isValid)
  {
    return false;
  }
  // The pixel's viewing ray in camera space: unproject the NDC points at the
  // near and far planes, then pick the point with z = -depth.
  const double ndcX = (col + 0.5) / width * 2.0 - 1.0;
  const double ndcY = (row + 0.5) / height * 2.0 - 1.0;
  double a[4] = { ndcX, ndcY, -1.0, 1.0 }, b[4] = { ndcX, ndcY, 1.0, 1.0 };
  layer.NDCToCamera->MultiplyPoint(a, a);
  layer.NDCToCamera->MultiplyPoint(b, b);
  for (int c = 0; c < 3; ++c)
  {
    a[c] /= a[3];
    b[c] /= b[3];
  }
  const double s = (-distance - a[2]) / (b[2] - a[2]);
  double camera[4] = { a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), -distance, 1.0 };
  double world[4];
  layer.CameraToWorld->MultiplyPoint(camera, world);
  x.Pixel = pixel;
  for (int c = 0; c < 3; ++c)
  {
    x.Position[c] = world[c] / world[3];
    // Normals go from camera to world with the transpose of the view
    // matrix's 3x3 (inverse transpose of camera-to-world).
    x.Normal[c] = layer.View->GetElement(0, c) * n[0] + layer.View->GetElement(1, c) * n[1] +
      layer.View->GetElement(2, c) * n[2];
  }
  vtkMath::Normalize(x.Normal);
  const double offset = this->GetRayOffset(x.Position);
  for (int c = 0; c < 3; ++c)
  {
    x.Origin[c] = x.Position[c] + offset * x.Normal[c];
  }
  return true;
}

//------------------------------------------------------------------------------
// Monte Carlo estimate at X: the mean of the estimator's samples and its
// standard error (sample standard deviation / sqrt(samples)).
void vtkDeepGIRayTracer::EstimatePixel(
  const Estimator& estimator, const SurfacePoint& x, PixelEstimate& estimate) const
{
  const int components = static_cast<int>(estimate.Sum.size());
  const int samples = estimator.GetNumberOfSamples();
  std::fill(estimate.Sum.begin(), estimate.Sum.end(), 0.0);
  std::fill(estimate.Sum2.begin(), estimate.Sum2.end(), 0.0);
  for (int i = 0; i < samples; ++i)
  {
    estimator.EvaluateSample(x, i, estimate.Values.data());
    for (int c = 0; c < components; ++c)
    {
      estimate.Sum[c] += estimate.Values[c];
      estimate.Sum2[c] += estimate.Values[c] * estimate.Values[c];
    }
  }
  for (int c = 0; c < components; ++c)
  {
    const double mean = estimate.Sum[c] / samples;
    const double variance = samples > 1
      ? std::max(0.0, (estimate.Sum2[c] - estimate.Sum[c] * mean) / (samples - 1))
      : 0.0;
    estimate.Mean[c] = mean;
    estimate.Error[c] = std::sqrt(variance / samples);
  }
}

//------------------------------------------------------------------------------
// Noise and ray counts over the valid pixels, serially so that the sums are
// taken in a deterministic order.
void vtkDeepGIRayTracer::GatherStatistics(vtkImageData* output, int samples)
{
  Internals& in = *this->Internal;
  vtkDataArray* valid = output->GetPointData()->GetArray(vtkDeepGICaptureNames::Valid);
  double total = 0.0;
  for (vtkIdType p = 0; p < in.Layer.Pixels; ++p)
  {
    if (valid->GetComponent(p, 0) != 0.0)
    {
      ++in.NumberOfValidPixels;
      const double e = in.LargestError[p];
      total += e;
      in.MaximumStandardError = std::max(in.MaximumStandardError, e);
    }
  }
  in.MeanStandardError = in.NumberOfValidPixels ? total / in.NumberOfValidPixels : 0.0;
  in.NumberOfRays = in.NumberOfValidPixels * static_cast<vtkIdType>(samples);
}

//------------------------------------------------------------------------------
vtkIdType vtkDeepGIRayTracer::GetNumberOfValidPixels() const
{
  return this->Internal->NumberOfValidPixels;
}

vtkIdType vtkDeepGIRayTracer::GetNumberOfRays() const
{
  return this->Internal->NumberOfRays;
}

double vtkDeepGIRayTracer::GetMeanStandardError() const
{
  return this->Internal->MeanStandardError;
}

double vtkDeepGIRayTracer::GetMaximumStandardError() const
{
  return this->Internal->MaximumStandardError;
}

double vtkDeepGIRayTracer::GetComputeTime() const
{
  return this->Internal->ComputeTime;
}

//------------------------------------------------------------------------------
void vtkDeepGIRayTracer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const Internals& in = *this->Internal;
  os << indent << "Scene: " << in.BuiltFor.Get() << "\n";
  os << indent << "NumberOfValidPixels: " << in.NumberOfValidPixels << "\n";
  os << indent << "NumberOfRays: " << in.NumberOfRays << "\n";
  os << indent << "MeanStandardError: " << in.MeanStandardError << "\n";
  os << indent << "MaximumStandardError: " << in.MaximumStandardError << "\n";
  os << indent << "ComputeTime: " << in.ComputeTime << "\n";
}
