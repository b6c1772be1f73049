// vtkDeepRadiosityPass's estimators (SetEstimator) on the demo scene,
// 160 x 120, single bounce (Damping 0, TemporalAlpha 0), BALANCED:
// - ALL_TAPS is eq. 4 times M / N: its raw gather equals ACCEPTED_TAPS's raw
//   gather times the raw confidence (relative 1e-3 + 1e-5 absolute, float
//   arithmetic), with the same confidence;
// - against the ray-traced one-bounce irradiance limited to the gather
//   radius r (vtkDeepGIReferenceIrradiance, 32 rays per pixel), the RMSE of
//   the luminance of E (after the filter) of SOLID_ANGLE is below half that
//   of ACCEPTED_TAPS, and ALL_TAPS's too (measured: 0.70 for eq. 4, 0.12
//   ALL_TAPS, 0.14 SOLID_ANGLE; the reference's mean standard error 0.047),
//   at a gather radius of 0.1 of the diagonal (at the default 0.5: 0.64,
//   0.48 and 0.21, standard error 0.11: SOLID_ANGLE keeps its lead, ALL_TAPS
//   does not);
// - the default is SOLID_ANGLE; an estimator outside the enum is clamped;
//   GetEstimatorAsString names it.

#include "DeepRadiosityReferenceTest.h"

#include "vtkDeepGBufferPass.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepRadiosityPass.h"

#include <cstdio>

using namespace DeepRadiosityReferenceTest;
using namespace DeepGITest;

int TestDeepRadiosityEstimator(int, char*[])
{
  auto window = MakeWindow(160, 120);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0, 0, 0);
  window->AddRenderer(renderer);
  vtkSmartPointer<vtkObject> keep;
  vtkSmartPointer<vtkPolyData> scene = PopulateScene("demo", std::string(), renderer, keep);
  vtkNew<vtkDeepRadiosityPass> pass;
  pass->SetDamping(0.0);
  pass->SetAutomaticRadiusFraction(0.1);
  pass->SetTemporalAlpha(0.0);
  Check(pass->GetEstimator() == vtkDeepRadiosityPass::SOLID_ANGLE, "default: SOLID_ANGLE");
  renderer->SetPass(pass);

  vtkSmartPointer<vtkImageData> captures[3];
  vtkNew<vtkImageData> layers;
  for (int estimator = 0; estimator < 3; ++estimator)
  {
    pass->SetEstimator(estimator);
    window->Render();
    captures[estimator] = vtkSmartPointer<vtkImageData>::New();
    Check(pass->CaptureIrradiance(captures[estimator], renderer), "capture");
  }
  Check(pass->GetGBufferPass()->CaptureLayers(layers, renderer), "layers");

  // ALL_TAPS = ACCEPTED_TAPS x M / N.
  vtkDataArray* rawM = captures[0]->GetPointData()->GetArray(
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::RawIrradiance, 0).c_str());
  vtkDataArray* rawN = captures[1]->GetPointData()->GetArray(
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::RawIrradiance, 0).c_str());
  vtkDataArray* confM = captures[0]->GetPointData()->GetArray(
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::RawConfidence, 0).c_str());
  vtkDataArray* confN = captures[1]->GetPointData()->GetArray(
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::RawConfidence, 0).c_str());
  long mismatches = 0, lit = 0;
  for (vtkIdType p = 0; p < rawM->GetNumberOfTuples(); ++p)
  {
    mismatches += confM->GetComponent(p, 0) != confN->GetComponent(p, 0);
    for (int c = 0; c < 3; ++c)
    {
      // Three values read from RGBA16F targets, each rounded by at most
      // 2^-11 (4.9e-4) relative.
      const double expected = rawM->GetComponent(p, c) * confM->GetComponent(p, 0);
      mismatches += std::fabs(rawN->GetComponent(p, c) - expected) > 2e-3 * expected + 1e-5;
      lit += expected > 0.01;
    }
  }
  std::printf(
    "ALL_TAPS vs ACCEPTED_TAPS x M / N: %ld mismatches over %ld lit components\n", mismatches, lit);
  Check(lit > 10000 && mismatches == 0, "ALL_TAPS = eq. 4 x M / N");

  double standardError = 0;
  const std::vector<double> ref =
    ReferenceIrradiance(scene, renderer, layers, pass->GetEffectiveRadius(), 32, standardError);
  vtkDataArray* valid = layers->GetPointData()->GetArray(
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 0).c_str());
  double rmse[3];
  for (int estimator = 0; estimator < 3; ++estimator)
  {
    const std::vector<double> e = Luminance(
      captures[estimator], vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Irradiance, 0));
    double s2 = 0;
    long n = 0;
    for (size_t i = 0; i < e.size() && ref.size() == e.size(); ++i)
    {
      if (valid->GetComponent(i, 0) > 0)
      {
        s2 += (e[i] - ref[i]) * (e[i] - ref[i]);
        ++n;
      }
    }
    rmse[estimator] = n ? std::sqrt(s2 / n) : 0.0;
    std::printf("%s: RMSE of E vs the reference within r = %.4f\n",
      vtkDeepRadiosityPass::GetEstimatorAsString(estimator), rmse[estimator]);
  }
  std::printf("reference mean standard error %.4f\n", standardError);
  Check(rmse[0] > 0 && rmse[2] < 0.5 * rmse[0], "SOLID_ANGLE RMSE < half of eq. 4's");
  Check(rmse[0] > 0 && rmse[1] < 0.5 * rmse[0], "ALL_TAPS RMSE < half of eq. 4's");

  pass->SetEstimator(-3);
  Check(pass->GetEstimator() == vtkDeepRadiosityPass::ACCEPTED_TAPS, "estimator clamped up");
  pass->SetEstimator(7);
  Check(pass->GetEstimator() == vtkDeepRadiosityPass::SOLID_ANGLE, "estimator clamped down");
  Check(std::string(vtkDeepRadiosityPass::GetEstimatorAsString(vtkDeepRadiosityPass::ALL_TAPS)) ==
      "ALL_TAPS",
    "estimator name");
  return ExitStatus();
}
