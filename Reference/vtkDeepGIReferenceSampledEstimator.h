/**
 * @class   vtkDeepGIReferenceSampledEstimator
 * @brief   abstract base of the Monte Carlo reference estimators: samples
 *          per pixel, the seed and the noise of the last update
 *
 * What vtkDeepGIReferenceObscurance and vtkDeepGIReferenceIrradiance add to
 * vtkDeepGIReferenceEstimator: a pixel's value is the mean of
 * SamplesPerPixel independent (not stratified) samples, so the reported
 * standard error (sample standard deviation / sqrt(SamplesPerPixel)) is an
 * honest estimate of the noise. A sample's random numbers are a
 * counter-based hash of (Seed, pixel, sample, dimension)
 * (vtkDeepGIRayTracer::Random): the same seed, capture and scene give
 * bit-identical results for any number of threads.
 *
 * @sa vtkDeepGIReferenceEstimator vtkDeepGIRayTracer
 */

#ifndef vtkDeepGIReferenceSampledEstimator_h
#define vtkDeepGIReferenceSampledEstimator_h

#include "vtkDeepGIReferenceEstimator.h"
#include "vtkDeepGIReferenceModule.h" // for export macro

class VTKDEEPGIREFERENCE_EXPORT vtkDeepGIReferenceSampledEstimator
  : public vtkDeepGIReferenceEstimator
{
public:
  vtkTypeMacro(vtkDeepGIReferenceSampledEstimator, vtkDeepGIReferenceEstimator);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Monte Carlo samples (rays from X) per pixel, [1, 1048576]; default 256.
   * The noise (standard error) falls as 1 / sqrt(SamplesPerPixel).
   *
   * @unit rays
   * @range 1..1048576, clamped
   * @default 256
   */
  vtkSetClampMacro(SamplesPerPixel, int, 1, 1048576);
  vtkGetMacro(SamplesPerPixel, int);
  ///@}

  ///@{
  /**
   * Seed of the counter-based random sequence (any value; default 0). The
   * same seed, capture and scene give bit-identical results for any number
   * of threads.
   *
   * @range any
   * @default 0
   */
  vtkSetMacro(Seed, unsigned int);
  vtkGetMacro(Seed, unsigned int);
  ///@}

  ///@{
  /**
   * Noise of the last update: mean and maximum over valid pixels of the
   * per-pixel standard error (of its largest component for a colour) (0
   * when no pixel was valid).
   */
  double GetMeanStandardError();
  double GetMaximumStandardError();
  ///@}

protected:
  vtkDeepGIReferenceSampledEstimator();
  ~vtkDeepGIReferenceSampledEstimator() override;

  unsigned int GetRandomSeed() override { return this->Seed; }

  int SamplesPerPixel;
  unsigned int Seed;

private:
  vtkDeepGIReferenceSampledEstimator(const vtkDeepGIReferenceSampledEstimator&) = delete;
  void operator=(const vtkDeepGIReferenceSampledEstimator&) = delete;
};

#endif
