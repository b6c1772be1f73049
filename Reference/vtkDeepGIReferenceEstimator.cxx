#include "vtkDeepGIReferenceEstimator.h"

#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkPolyData.h"

//------------------------------------------------------------------------------
vtkDeepGIReferenceEstimator::vtkDeepGIReferenceEstimator()
  : Layer(0)
  , RelativeOffset(1e-5)
{
  this->SetNumberOfInputPorts(2);
}

vtkDeepGIReferenceEstimator::~vtkDeepGIReferenceEstimator() = default;

//------------------------------------------------------------------------------
void vtkDeepGIReferenceEstimator::SetSceneData(vtkPolyData* scene)
{
  this->SetInputData(1, scene);
}

void vtkDeepGIReferenceEstimator::SetSceneConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

vtkPolyData* vtkDeepGIReferenceEstimator::GetScene()
{
  return vtkPolyData::SafeDownCast(this->GetInputDataObject(1, 0));
}

bool vtkDeepGIReferenceEstimator::Compute(vtkImageData* capture)
{
  this->SetInputData(0, capture);
  return this->GetExecutive()->Update() != 0 && this->GetOutput()->GetNumberOfPoints() > 0;
}

//------------------------------------------------------------------------------
int vtkDeepGIReferenceEstimator::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 0 ? "vtkImageData" : "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
// The tracer checks the inputs (a missing capture or scene, or one it cannot
// use, is its error with this algorithm as the reporter) and empties the
// output when the run fails.
int vtkDeepGIReferenceEstimator::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  std::unique_ptr<vtkDeepGIRayTracer::Estimator> estimator = this->NewEstimator();
  return this->Tracer->Run(vtkImageData::GetData(inputVector[0]),
    vtkPolyData::GetData(inputVector[1]),
    { this->Layer, this->GetRandomSeed(), this->RelativeOffset }, *estimator,
    vtkImageData::GetData(outputVector), this);
}

//------------------------------------------------------------------------------
vtkIdType vtkDeepGIReferenceEstimator::GetNumberOfValidPixels()
{
  return this->Tracer->GetNumberOfValidPixels();
}

vtkIdType vtkDeepGIReferenceEstimator::GetNumberOfRays()
{
  return this->Tracer->GetNumberOfRays();
}

double vtkDeepGIReferenceEstimator::GetComputeTime()
{
  return this->Tracer->GetComputeTime();
}

//------------------------------------------------------------------------------
void vtkDeepGIReferenceEstimator::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Layer: " << this->Layer << "\n";
  os << indent << "RelativeOffset: " << this->RelativeOffset << "\n";
  os << indent << "Tracer:\n";
  this->Tracer->PrintSelf(os, indent.GetNextIndent());
}
