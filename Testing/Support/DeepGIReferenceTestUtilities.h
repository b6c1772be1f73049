// Helpers shared by the tests of the ray-traced references and the OpenEXR
// I/O: an observer counting error and warning events, the update of a
// reference estimator on a capture, hand-made layer-0
// captures in the layout of vtkDeepGBufferPass::CaptureLayers, the
// closed-form view factor from a point to a parallel square and the closed
// form of the obscurance of a floor point beside a wall.
#ifndef DeepGIReferenceTestUtilities_h
#define DeepGIReferenceTestUtilities_h

#include "DeepGITestChecks.h"

#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageAlgorithm.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <utility>

namespace DeepGIReferenceTest
{
/// Counts the ErrorEvents and WarningEvents of the objects it observes.
class EventCounter : public vtkCommand
{
public:
  static EventCounter* New() { return new EventCounter; }
  void Execute(vtkObject*, unsigned long event, void*) override
  {
    this->Errors += event == vtkCommand::ErrorEvent;
    this->Warnings += event == vtkCommand::WarningEvent;
  }
  int Errors = 0;
  int Warnings = 0;
};

/// Runs a reference estimator (vtkDeepGIReferenceObscurance, ...Irradiance,
/// ...Reflection: the capture on input port 0, the scene already on port 1)
/// on `capture` through the pipeline; false when the update failed (a
/// missing input, or an error of the estimator, which leaves its output
/// empty).
inline bool Estimate(vtkImageAlgorithm* reference, vtkImageData* capture)
{
  reference->SetInputData(0, capture);
  return reference->GetExecutive()->Update() != 0 &&
    reference->GetOutput()->GetNumberOfPoints() > 0;
}

/// Stores a camera's ViewMatrix and ProjectionMatrix (16 values each) in the
/// field data of `capture`, as vtkDeepGBufferPass::CaptureLayers does.
inline void AddCameraMatrices(vtkImageData* capture, vtkMatrix4x4* view, vtkMatrix4x4* projection)
{
  for (auto m : { std::make_pair(vtkDeepGICaptureNames::ViewMatrix, view),
         std::make_pair(vtkDeepGICaptureNames::ProjectionMatrix, projection) })
  {
    vtkNew<vtkDoubleArray> values;
    values->SetName(m.first);
    values->SetNumberOfComponents(16);
    values->InsertNextTuple(&m.second->Element[0][0]);
    capture->GetFieldData()->AddArray(values);
  }
}

/// A w x h capture with layer 0 only: the arrays Depth_0, Normal_0 (3
/// components), Albedo_0 (3) and Valid_0, for the caller to fill, and the
/// field data ViewMatrix and ProjectionMatrix of `camera` at the aspect
/// w / h. InverseView and InverseProjection turn pixels back into rays.
struct Layer0Capture
{
  Layer0Capture(int w, int h, vtkCamera* camera)
  {
    this->View->DeepCopy(camera->GetModelViewTransformMatrix());
    this->Projection->DeepCopy(
      camera->GetProjectionTransformMatrix(static_cast<double>(w) / h, -1, 1));
    vtkMatrix4x4::Invert(this->View, this->InverseView);
    vtkMatrix4x4::Invert(this->Projection, this->InverseProjection);
    this->Image->SetDimensions(w, h, 1);
    const vtkIdType n = static_cast<vtkIdType>(w) * h;
    vtkPointData* pd = this->Image->GetPointData();
    for (auto array : { std::make_pair(this->Depth.GetPointer(),
                          vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Depth, 0)),
           std::make_pair(this->Normal.GetPointer(),
             vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Normal, 0)),
           std::make_pair(this->Albedo.GetPointer(),
             vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Albedo, 0)) })
    {
      array.first->SetName(array.second.c_str());
      array.first->SetNumberOfComponents(array.first == this->Depth ? 1 : 3);
      array.first->SetNumberOfTuples(n);
      pd->AddArray(array.first);
    }
    this->Valid->SetName(vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 0).c_str());
    this->Valid->SetNumberOfTuples(n);
    pd->AddArray(this->Valid);
    AddCameraMatrices(this->Image, this->View, this->Projection);
  }

  vtkSmartPointer<vtkImageData> Image = vtkSmartPointer<vtkImageData>::New();
  vtkNew<vtkFloatArray> Depth, Normal, Albedo;
  vtkNew<vtkUnsignedCharArray> Valid;
  vtkNew<vtkMatrix4x4> View, Projection, InverseView, InverseProjection;
};

/// View factor from a differential area to a parallel rectangle at height
/// h whose corner lies straight above it, sides a and b (signed: a corner
/// rectangle on the far side of the point subtracts).
inline double CornerViewFactor(double a, double b, double h)
{
  const double x = a / h, y = b / h;
  const double sx = std::sqrt(1 + x * x), sy = std::sqrt(1 + y * y);
  return (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy)) / (2 * vtkMath::Pi());
}

/// ... to the square [-s, s]^2 at height h from the point (px, py) (the
/// corner sides are signed, so points beside the square work too).
inline double SquareViewFactor(double px, double py, double s, double h)
{
  double f = 0;
  for (double a : { s - px, s + px })
  {
    for (double b : { s - py, s + py })
    {
      f += CornerViewFactor(a, b, h);
    }
  }
  return f;
}

/// Closed form of A of vtkDeepGIReferenceObscurance (eq. 2 with Bias and
/// Epsilon 0) for a floor point at distance d from one infinite wall,
/// radius r: A(s) = (2/pi) [pi/4 - 3/2 s sqrt(1-s^2) - (1/2 + s^2) asin(s) +
/// pi/2 s^2], s = min(d/r, 1).
inline double WallObscurance(double d, double r)
{
  const double s = std::min(1.0, d / r);
  const double q = std::sqrt(std::max(0.0, 1.0 - s * s));
  return 2.0 / vtkMath::Pi() *
    (vtkMath::Pi() / 4 - 1.5 * s * q - (0.5 + s * s) * std::asin(s) + vtkMath::Pi() / 2 * s * s);
}
}

#endif
