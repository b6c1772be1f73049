#include "vtkDeepGIReferenceSampledEstimator.h"

//------------------------------------------------------------------------------
vtkDeepGIReferenceSampledEstimator::vtkDeepGIReferenceSampledEstimator()
  : SamplesPerPixel(256)
  , Seed(0)
{
}

vtkDeepGIReferenceSampledEstimator::~vtkDeepGIReferenceSampledEstimator() = default;

//------------------------------------------------------------------------------
double vtkDeepGIReferenceSampledEstimator::GetMeanStandardError()
{
  return this->Tracer->GetMeanStandardError();
}

double vtkDeepGIReferenceSampledEstimator::GetMaximumStandardError()
{
  return this->Tracer->GetMaximumStandardError();
}

//------------------------------------------------------------------------------
void vtkDeepGIReferenceSampledEstimator::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SamplesPerPixel: " << this->SamplesPerPixel << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
}
