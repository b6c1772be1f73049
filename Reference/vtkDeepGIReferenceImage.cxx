#include "vtkDeepGIReferenceImage.h"
#include "vtkDeepGICaptureNames.h"

#include "vtkActor.h"
#include "vtkAppendPolyData.h"
#include "vtkCellData.h"
#include "vtkDeepGIReferenceIrradiance.h"
#include "vtkDeepGIReferenceObscurance.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkDeepGIReferenceImage);

//------------------------------------------------------------------------------
vtkDeepGIReferenceImage::vtkDeepGIReferenceImage()
  : Obscurance(vtkSmartPointer<vtkDeepGIReferenceObscurance>::New())
  , Irradiance(vtkSmartPointer<vtkDeepGIReferenceIrradiance>::New())
  , Output(vtkSmartPointer<vtkImageData>::New())
{
  // The quantity itself: eq. 2 without the screen-space estimator's
  // regularisation, and indirect light from any distance.
  this->Obscurance->SetBias(0.0);
  this->Obscurance->SetEpsilon(0.0);
  this->Irradiance->SetNumberOfBounces(4);
}

//------------------------------------------------------------------------------
vtkDeepGIReferenceImage::~vtkDeepGIReferenceImage() = default;

//------------------------------------------------------------------------------
void vtkDeepGIReferenceImage::SetScene(vtkPolyData* scene)
{
  this->Obscurance->SetSceneData(scene);
  this->Irradiance->SetSceneData(scene);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkDeepGIReferenceImage::SetLightsFromRenderer(vtkRenderer* renderer)
{
  this->Irradiance->SetLightsFromRenderer(renderer);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkDeepGIReferenceImage::SetObscuranceRadius(double radius)
{
  this->Obscurance->SetRadius(radius);
  this->Modified();
}

double vtkDeepGIReferenceImage::GetObscuranceRadius()
{
  return this->Obscurance->GetRadius();
}

//------------------------------------------------------------------------------
void vtkDeepGIReferenceImage::SetNumberOfBounces(int bounces)
{
  this->Irradiance->SetNumberOfBounces(bounces);
  this->Modified();
}

int vtkDeepGIReferenceImage::GetNumberOfBounces()
{
  return this->Irradiance->GetNumberOfBounces();
}

//------------------------------------------------------------------------------
void vtkDeepGIReferenceImage::SetSamplesPerPixel(int samples)
{
  this->Obscurance->SetSamplesPerPixel(samples);
  this->Irradiance->SetSamplesPerPixel(samples);
  this->Modified();
}

int vtkDeepGIReferenceImage::GetSamplesPerPixel()
{
  return this->Irradiance->GetSamplesPerPixel();
}

//------------------------------------------------------------------------------
vtkDeepGIReferenceObscurance* vtkDeepGIReferenceImage::GetObscurance()
{
  return this->Obscurance;
}

vtkDeepGIReferenceIrradiance* vtkDeepGIReferenceImage::GetIrradiance()
{
  return this->Irradiance;
}

vtkImageData* vtkDeepGIReferenceImage::GetOutput()
{
  return this->Output;
}

//------------------------------------------------------------------------------
namespace
{
// Runs one reference estimator on `capture`; false when the update failed
// (an error of the estimator or of its executive).
bool Estimate(vtkImageAlgorithm* estimator, vtkImageData* capture)
{
  estimator->SetInputData(0, capture);
  return estimator->GetExecutive()->Update() != 0;
}
}

//------------------------------------------------------------------------------
bool vtkDeepGIReferenceImage::Compute(vtkImageData* capture)
{
  this->Output->Initialize();
  this->MeanStandardError = 0.0;
  this->MaximumStandardError = 0.0;
  if (!this->CheckCapture(capture))
  {
    return false;
  }
  this->Obscurance->SetLayer(0);
  this->Irradiance->SetLayer(0);
  if (!Estimate(this->Obscurance, capture) || !Estimate(this->Irradiance, capture))
  {
    vtkErrorMacro("A reference failed; no reference image.");
    return false;
  }
  this->Compose(capture);
  return true;
}

//------------------------------------------------------------------------------
bool vtkDeepGIReferenceImage::CheckCapture(vtkImageData* capture)
{
  if (!capture)
  {
    vtkErrorMacro("No capture.");
    return false;
  }
  vtkPointData* pd = capture->GetPointData();
  for (const std::string& name : { vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Radiance, 0),
         vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Ambient, 0),
         vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Albedo, 0) })
  {
    if (!pd->GetArray(name.c_str()))
    {
      vtkErrorMacro("The capture has no " << name << " array.");
      return false;
    }
  }
  if (pd->GetArray(vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Reflectivity, 0).c_str()))
  {
    vtkErrorMacro("Mirror reflections are not part of the reference image; "
                  "capture without reflecting props.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
namespace
{
vtkSmartPointer<vtkFloatArray> NewOutputArray(const char* name, int components, vtkIdType pixels)
{
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(pixels);
  array->Fill(0.0);
  return array;
}
}

//------------------------------------------------------------------------------
// L = RADIANCE - (1 - AV) AMBIENT + I or AV RADIANCE + I per valid pixel,
// with the standard errors of AV and I combined (independent estimates).
void vtkDeepGIReferenceImage::Compose(vtkImageData* capture)
{
  vtkPointData* in = capture->GetPointData();
  vtkDataArray* radiance =
    in->GetArray(vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Radiance, 0).c_str());
  vtkDataArray* ambient =
    in->GetArray(vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Ambient, 0).c_str());
  vtkPointData* obscurance = this->Obscurance->GetOutput()->GetPointData();
  vtkPointData* irradiance = this->Irradiance->GetOutput()->GetPointData();
  vtkDataArray* av = obscurance->GetArray(vtkDeepGICaptureNames::AmbientVisibility);
  vtkDataArray* avError = obscurance->GetArray("StandardError");
  vtkDataArray* indirect = irradiance->GetArray(vtkDeepGICaptureNames::IndirectRadiance);
  vtkDataArray* indirectError = irradiance->GetArray("IndirectRadianceStandardError");
  vtkDataArray* valid = irradiance->GetArray(vtkDeepGICaptureNames::Valid);

  const vtkIdType pixels = capture->GetNumberOfPoints();
  this->Output->SetDimensions(capture->GetDimensions());
  auto colour = NewOutputArray(vtkDeepGICaptureNames::Radiance, 3, pixels);
  auto error = NewOutputArray("RadianceStandardError", 3, pixels);
  auto visibility = NewOutputArray(vtkDeepGICaptureNames::AmbientVisibility, 1, pixels);
  auto indirectOut = NewOutputArray(vtkDeepGICaptureNames::IndirectRadiance, 3, pixels);
  vtkNew<vtkUnsignedCharArray> validOut;
  validOut->SetName(vtkDeepGICaptureNames::Valid);
  validOut->SetNumberOfTuples(pixels);
  validOut->Fill(0);

  const bool scalesRadiance = this->Visibility == AV_SCALES_RADIANCE;
  double errorSum = 0.0;
  vtkIdType validCount = 0;
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    if (valid->GetComponent(p, 0) == 0.0 || av->GetComponent(p, 0) < 0.0)
    {
      continue;
    }
    const double a = av->GetComponent(p, 0);
    const double aError = avError->GetComponent(p, 0);
    double largestError = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      const double scaled =
        scalesRadiance ? radiance->GetComponent(p, c) : ambient->GetComponent(p, c);
      const double local =
        scalesRadiance ? a * scaled : radiance->GetComponent(p, c) - (1.0 - a) * scaled;
      const double i = indirect->GetComponent(p, c);
      const double iError = indirectError->GetComponent(p, c);
      const double e = std::sqrt(scaled * scaled * aError * aError + iError * iError);
      colour->SetComponent(p, c, local + i);
      indirectOut->SetComponent(p, c, i);
      error->SetComponent(p, c, e);
      largestError = std::max(largestError, e);
    }
    visibility->SetComponent(p, 0, a);
    validOut->SetValue(p, 1);
    errorSum += largestError;
    this->MaximumStandardError = std::max(this->MaximumStandardError, largestError);
    ++validCount;
  }
  this->MeanStandardError = validCount ? errorSum / validCount : 0.0;
  vtkPointData* out = this->Output->GetPointData();
  out->AddArray(colour);
  out->AddArray(error);
  out->AddArray(visibility);
  out->AddArray(indirectOut);
  out->AddArray(validOut);
}

//------------------------------------------------------------------------------
namespace
{
// One actor's triangles in world coordinates with its property's colour
// and diffuse coefficient as cell data; null when it has none.
vtkSmartPointer<vtkPolyData> ActorTriangles(vtkActor* actor, bool& approximatedColour)
{
  vtkMapper* mapper = actor->GetMapper();
  vtkPolyData* input =
    vtkPolyData::SafeDownCast(mapper ? mapper->GetInputDataObject(0, 0) : nullptr);
  if (!input || input->GetNumberOfCells() == 0)
  {
    return nullptr;
  }
  vtkNew<vtkTransform> transform;
  vtkNew<vtkMatrix4x4> matrix;
  actor->GetMatrix(matrix);
  transform->SetMatrix(matrix);
  vtkNew<vtkTransformPolyDataFilter> world;
  world->SetInputData(input);
  world->SetTransform(transform);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(world->GetOutputPort());
  triangles->PassLinesOff();
  triangles->PassVertsOff();
  triangles->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(triangles->GetOutput());
  const vtkIdType cells = mesh->GetNumberOfCells();
  if (cells == 0)
  {
    return nullptr;
  }

  vtkProperty* property = actor->GetProperty();
  vtkNew<vtkDoubleArray> colors;
  colors->SetName("Colors");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(cells);
  vtkNew<vtkDoubleArray> diffuse;
  diffuse->SetName("Diffuse");
  diffuse->SetNumberOfTuples(cells);
  for (int c = 0; c < 3; ++c)
  {
    colors->FillComponent(c, property->GetDiffuseColor()[c]);
  }
  diffuse->Fill(property->GetDiffuse());
  approximatedColour |= (mapper->GetScalarVisibility() && input->GetPointData()->GetScalars()) ||
    actor->GetTexture() != nullptr;

  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->SetPoints(mesh->GetPoints());
  result->SetPolys(mesh->GetPolys());
  result->GetPointData()->SetNormals(mesh->GetPointData()->GetNormals());
  result->GetCellData()->AddArray(colors);
  result->GetCellData()->AddArray(diffuse);
  return result;
}
}

//------------------------------------------------------------------------------
bool vtkDeepGIReferenceImage::SceneFromRenderer(vtkRenderer* renderer, vtkPolyData* scene)
{
  vtkNew<vtkAppendPolyData> append;
  bool approximatedColour = false;
  int parts = 0;
  vtkActorCollection* actors = renderer ? renderer->GetActors() : nullptr;
  vtkCollectionSimpleIterator it;
  if (actors)
  {
    actors->InitTraversal(it);
  }
  while (vtkActor* actor = actors ? actors->GetNextActor(it) : nullptr)
  {
    if (!actor->GetVisibility() || !actor->HasOpaqueGeometry())
    {
      continue;
    }
    if (auto part = ActorTriangles(actor, approximatedColour))
    {
      append->AddInputData(part);
      ++parts;
    }
    else
    {
      vtkWarningWithObjectMacro(renderer,
        "An actor without polygonal vtkPolyData input is not "
        "part of the reference scene.");
    }
  }
  if (approximatedColour)
  {
    vtkWarningWithObjectMacro(renderer,
      "Actors coloured by scalars or textures keep their "
      "property's colour in the reference scene.");
  }
  scene->Initialize();
  if (parts == 0)
  {
    return false;
  }
  append->Update();
  scene->ShallowCopy(append->GetOutput());
  return true;
}

//------------------------------------------------------------------------------
void vtkDeepGIReferenceImage::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Visibility: "
     << (this->Visibility == AV_SCALES_AMBIENT ? "AV_SCALES_AMBIENT" : "AV_SCALES_RADIANCE")
     << "\n";
  os << indent << "MeanStandardError: " << this->MeanStandardError << "\n";
  os << indent << "MaximumStandardError: " << this->MaximumStandardError << "\n";
  os << indent << "Obscurance:\n";
  this->Obscurance->PrintSelf(os, indent.GetNextIndent());
  os << indent << "Irradiance:\n";
  this->Irradiance->PrintSelf(os, indent.GetNextIndent());
}
