// The spiral turns tau(N) of vtkDeepAmbientObscurancePass equal the paper's
// Listing 3 (Mara et al. 2016, "Discrepancy-minimizing number of turns",
// tau[N - 1] for N = 1..98), written out here independently of the class's
// table. N = 99 has no entry in the paper: GetSpiralTurns(99) is 0 and
// SetNumberOfSamples(99) clamps to 98 with one warning; N = 0 likewise
// clamps to 1.
// Also the parameter checks that need no window: NaN, infinite and negative
// radii and intensities are warned about and replaced, and PrintSelf prints
// every parameter.

#include "DeepGITestChecks.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDeepAmbientObscurancePass.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkNew.h"

#include <cstdio>
#include <limits>
#include <sstream>

namespace
{
using DeepGITest::Check;
using DeepGITest::Format;

void CheckSpiralTurnsEqualListing3()
{
  // Copied from the paper's text, 15 values per row as printed there.
  const int listing3[] = { 1, 1, 2, 3, 2, 5, 2, 3, 2, 3, 3, 5, 5, 3, 4, 7, 5, 5, 7, 9, 8, 5, 5, 7,
    7, 7, 8, 5, 8, 11, 12, 7, 10, 13, 8, 11, 8, 7, 14, 11, 11, 13, 12, 13, 19, 17, 13, 11, 18, 19,
    11, 11, 14, 17, 21, 15, 16, 17, 18, 13, 17, 11, 17, 19, 18, 25, 18, 19, 19, 29, 21, 19, 27, 31,
    29, 21, 18, 17, 29, 31, 31, 23, 18, 25, 26, 25, 23, 19, 34, 19, 27, 21, 25, 39, 29, 17, 21,
    27 };
  const int count = static_cast<int>(sizeof(listing3) / sizeof(listing3[0]));
  Check(count == 98 && vtkDeepAmbientObscurancePass::MAXIMUM_NUMBER_OF_SAMPLES == 98,
    Format("Listing 3 has %d entries, the class allows %d samples (98 both)", count,
      vtkDeepAmbientObscurancePass::MAXIMUM_NUMBER_OF_SAMPLES));
  int mismatches = 0;
  for (int n = 1; n <= count; ++n)
  {
    const int tau = vtkDeepAmbientObscurancePass::GetSpiralTurns(n);
    if (tau != listing3[n - 1])
    {
      std::printf("tau(%d) = %d, Listing 3 says %d\n", n, tau, listing3[n - 1]);
      ++mismatches;
    }
  }
  Check(mismatches == 0, Format("tau(1..%d) = Listing 3 (%d differ)", count, mismatches));
  for (int n : { -1, 0, 99, 100 })
  {
    Check(vtkDeepAmbientObscurancePass::GetSpiralTurns(n) == 0,
      Format("tau(%d) = %d, 0 expected (no value in the paper)", n,
        vtkDeepAmbientObscurancePass::GetSpiralTurns(n)));
  }
}

// N = 99 clamps to 98 and N = 0 to 1, each with one warning.
void CheckSampleCountClamped(vtkDeepAmbientObscurancePass* pass, const int& warnings)
{
  pass->SetNumberOfSamples(99);
  Check(pass->GetNumberOfSamples() == 98 && warnings == 1,
    Format("N = 99 gave %d with %d warnings (98 with 1)", pass->GetNumberOfSamples(), warnings));
  pass->SetNumberOfSamples(0);
  Check(pass->GetNumberOfSamples() == 1 && warnings == 2,
    Format("N = 0 gave %d with %d warnings (1 with 2)", pass->GetNumberOfSamples(), warnings));
  pass->SetNumberOfSamples(9);
  Check(pass->GetNumberOfSamples() == 9 && warnings == 2,
    Format("N = 9 gave %d with %d warnings (9 with 2)", pass->GetNumberOfSamples(), warnings));
}

// NaN, infinite and negative radii and intensities are warned about and
// replaced.
void CheckRadiusAndIntensityValidated(vtkDeepAmbientObscurancePass* pass, const int& warnings)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  pass->SetRadius(2.0);
  pass->SetRadius(nan);
  pass->SetRadius(std::numeric_limits<double>::infinity());
  Check(pass->GetRadius() == 2.0 && !pass->GetAutomaticRadius() && warnings == 4,
    Format("non-finite radius ignored: %g, %d warnings", pass->GetRadius(), warnings));
  pass->SetRadius(-1.0);
  Check(pass->GetRadius() == 0.0 && warnings == 5,
    Format("negative radius replaced by 0: %g, %d warnings", pass->GetRadius(), warnings));
  pass->SetIntensity(-2.0);
  Check(pass->GetIntensity() == 0.0 && warnings == 6,
    Format("negative intensity replaced by 0: %g, %d warnings", pass->GetIntensity(), warnings));
  pass->SetIntensity(nan);
  Check(pass->GetIntensity() == 0.0 && warnings == 7,
    Format("NaN intensity replaced by 0: %g, %d warnings", pass->GetIntensity(), warnings));
}

// Presets set exactly their documented values, in one call.
void CheckPresetsSetTheirValues(vtkDeepAmbientObscurancePass* pass, const int& warnings)
{
  const struct
  {
    int Preset, Samples, Blur;
    double Threshold;
    int Levels;
  } presets[] = { { vtkDeepAmbientObscurancePass::HIGH_PERFORMANCE, 8, 2, 4.0, 5 },
    { vtkDeepAmbientObscurancePass::BALANCED, 12, 3, 8.0, 5 },
    { vtkDeepAmbientObscurancePass::HIGH_QUALITY, 32, 3, 16.0, 5 } };
  for (const auto& p : presets)
  {
    const vtkMTimeType before = pass->GetMTime();
    pass->SetPreset(p.Preset);
    Check(pass->GetNumberOfSamples() == p.Samples && pass->GetBlurRadius() == p.Blur &&
        pass->GetMipThreshold() == p.Threshold && pass->GetMaximumMipLevel() == p.Levels &&
        pass->GetMTime() > before,
      Format("preset %d sets its values", p.Preset));
  }
  const int warningsBeforeUnknown = warnings;
  pass->SetPreset(7);
  Check(warnings == warningsBeforeUnknown + 1 && pass->GetNumberOfSamples() == 32,
    "an unknown preset warns and changes nothing");
  // The deprecated names of an earlier release still work.
  pass->SetQualityToLow();
  Check(pass->GetNumberOfSamples() == 8 &&
      vtkDeepAmbientObscurancePass::PRESET_HIGH == vtkDeepAmbientObscurancePass::HIGH_QUALITY,
    "the deprecated preset names still set the presets");
}

void CheckPrintSelfPrintsEveryParameter(vtkDeepAmbientObscurancePass* pass)
{
  std::ostringstream printed;
  pass->Print(printed);
  for (const char* name :
    { "GBufferPass", vtkDeepGICaptureNames::Radius, "AutomaticRadius", "AutomaticRadiusFraction",
      "EffectiveRadius", "Bias", "Epsilon", "Intensity", vtkDeepGICaptureNames::NumberOfSamples,
      "UseSecondLayer", "BlurRadius", "BlurPlaneTolerance", "BlurNormalPower", "Composition" })
  {
    Check(printed.str().find(std::string(name) + ":") != std::string::npos,
      Format("PrintSelf prints %s", name));
  }
}
}

int TestDeepAmbientObscuranceTau(int, char*[])
{
  CheckSpiralTurnsEqualListing3();

  vtkNew<vtkDeepAmbientObscurancePass> pass;
  int warnings = 0;
  vtkNew<vtkCallbackCommand> onWarning;
  onWarning->SetClientData(&warnings);
  onWarning->SetCallback(
    [](vtkObject*, unsigned long, void* data, void*) { ++*static_cast<int*>(data); });
  pass->AddObserver(vtkCommand::WarningEvent, onWarning);
  CheckSampleCountClamped(pass, warnings);
  CheckRadiusAndIntensityValidated(pass, warnings);
  CheckPresetsSetTheirValues(pass, warnings);
  pass->SetPresetToBalanced();
  CheckPrintSelfPrintsEveryParameter(pass);
  return DeepGITest::ExitStatus();
}
