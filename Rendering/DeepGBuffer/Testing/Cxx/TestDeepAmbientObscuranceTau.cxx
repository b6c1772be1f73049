// The spiral turns tau(N) of vtkDeepAmbientObscurancePass equal the paper's
// Listing 3 (Mara et al. 2016, "Discrepancy-minimizing number of turns",
// tau[N - 1] for N = 1..98), written out here independently of the class's
// table. N = 99 has no entry in the paper: GetSpiralTurns(99) is 0 and
// SetNumberOfSamples(99) clamps to 98 with one warning; N = 0 likewise
// clamps to 1.
// Also the parameter checks that need no window: NaN, infinite and negative
// radii and intensities are warned about and replaced, and PrintSelf prints
// every parameter.

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDeepAmbientObscurancePass.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkNew.h"

#include <cstdio>
#include <limits>
#include <sstream>

int TestDeepAmbientObscuranceTau(int, char*[])
{
  // Copied from the paper's text, 15 values per row as printed there.
  const int listing3[] = { 1, 1, 2, 3, 2, 5, 2, 3, 2, 3, 3, 5, 5, 3, 4, 7, 5, 5, 7, 9, 8, 5, 5, 7,
    7, 7, 8, 5, 8, 11, 12, 7, 10, 13, 8, 11, 8, 7, 14, 11, 11, 13, 12, 13, 19, 17, 13, 11, 18, 19,
    11, 11, 14, 17, 21, 15, 16, 17, 18, 13, 17, 11, 17, 19, 18, 25, 18, 19, 19, 29, 21, 19, 27, 31,
    29, 21, 18, 17, 29, 31, 31, 23, 18, 25, 26, 25, 23, 19, 34, 19, 27, 21, 25, 39, 29, 17, 21,
    27 };
  const int count = static_cast<int>(sizeof(listing3) / sizeof(listing3[0]));
  int failures = 0;
  if (count != 98 || vtkDeepAmbientObscurancePass::MAXIMUM_NUMBER_OF_SAMPLES != 98)
  {
    std::printf("Listing 3 has %d entries, the class allows %d samples (expected 98)\n", count,
      vtkDeepAmbientObscurancePass::MAXIMUM_NUMBER_OF_SAMPLES);
    ++failures;
  }
  for (int n = 1; n <= count; ++n)
  {
    const int tau = vtkDeepAmbientObscurancePass::GetSpiralTurns(n);
    if (tau != listing3[n - 1])
    {
      std::printf("tau(%d) = %d, Listing 3 says %d\n", n, tau, listing3[n - 1]);
      ++failures;
    }
  }
  for (int n : { -1, 0, 99, 100 })
  {
    if (vtkDeepAmbientObscurancePass::GetSpiralTurns(n) != 0)
    {
      std::printf("tau(%d) = %d, expected 0 (no value in the paper)\n", n,
        vtkDeepAmbientObscurancePass::GetSpiralTurns(n));
      ++failures;
    }
  }

  vtkNew<vtkDeepAmbientObscurancePass> pass;
  int warnings = 0;
  vtkNew<vtkCallbackCommand> onWarning;
  onWarning->SetClientData(&warnings);
  onWarning->SetCallback(
    [](vtkObject*, unsigned long, void* data, void*) { ++*static_cast<int*>(data); });
  pass->AddObserver(vtkCommand::WarningEvent, onWarning);
  pass->SetNumberOfSamples(99);
  if (pass->GetNumberOfSamples() != 98 || warnings != 1)
  {
    std::printf("N = 99 gave %d with %d warnings, expected 98 with 1\n", pass->GetNumberOfSamples(),
      warnings);
    ++failures;
  }
  pass->SetNumberOfSamples(0);
  if (pass->GetNumberOfSamples() != 1 || warnings != 2)
  {
    std::printf(
      "N = 0 gave %d with %d warnings, expected 1 with 2\n", pass->GetNumberOfSamples(), warnings);
    ++failures;
  }
  pass->SetNumberOfSamples(9);
  if (pass->GetNumberOfSamples() != 9 || warnings != 2)
  {
    std::printf("N = 9 gave %d with %d warnings\n", pass->GetNumberOfSamples(), warnings);
    ++failures;
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  pass->SetRadius(2.0);
  pass->SetRadius(nan);
  pass->SetRadius(std::numeric_limits<double>::infinity());
  if (pass->GetRadius() != 2.0 || pass->GetAutomaticRadius() || warnings != 4)
  {
    std::printf("non-finite radius: %g, %d warnings\n", pass->GetRadius(), warnings);
    ++failures;
  }
  pass->SetRadius(-1.0);
  if (pass->GetRadius() != 0.0 || warnings != 5)
  {
    std::printf("negative radius: %g, %d warnings\n", pass->GetRadius(), warnings);
    ++failures;
  }
  pass->SetIntensity(-2.0);
  if (pass->GetIntensity() != 0.0 || warnings != 6)
  {
    std::printf("negative intensity: %g, %d warnings\n", pass->GetIntensity(), warnings);
    ++failures;
  }
  pass->SetIntensity(nan);
  if (pass->GetIntensity() != 0.0 || warnings != 7)
  {
    std::printf("NaN intensity: %g, %d warnings\n", pass->GetIntensity(), warnings);
    ++failures;
  }
  // Presets set exactly their documented values, in one call.
  const struct
  {
    int Preset, Samples, Blur;
    double Threshold;
    int Levels;
  } presets[] = { { vtkDeepAmbientObscurancePass::HIGH_PERFORMANCE, 8, 2, 4.0, 5 },
    { vtkDeepAmbientObscurancePass::BALANCED, 16, 4, 8.0, 5 },
    { vtkDeepAmbientObscurancePass::HIGH_QUALITY, 32, 6, 16.0, 5 } };
  for (const auto& p : presets)
  {
    const vtkMTimeType before = pass->GetMTime();
    pass->SetPreset(p.Preset);
    if (pass->GetNumberOfSamples() != p.Samples || pass->GetBlurRadius() != p.Blur ||
      pass->GetMipThreshold() != p.Threshold || pass->GetMaximumMipLevel() != p.Levels ||
      pass->GetMTime() <= before)
    {
      std::printf("preset %d does not set its values\n", p.Preset);
      ++failures;
    }
  }
  const int warningsBeforeUnknown = warnings;
  pass->SetPreset(7);
  if (warnings != warningsBeforeUnknown + 1 || pass->GetNumberOfSamples() != 32)
  {
    std::printf("an unknown preset must warn and change nothing\n");
    ++failures;
  }
  // The deprecated names of an earlier release still work.
  pass->SetQualityToLow();
  if (pass->GetNumberOfSamples() != 8 ||
    vtkDeepAmbientObscurancePass::PRESET_HIGH != vtkDeepAmbientObscurancePass::HIGH_QUALITY)
  {
    std::printf("the deprecated preset names must still set the presets\n");
    ++failures;
  }
  pass->SetPresetToBalanced();
  std::ostringstream printed;
  pass->Print(printed);
  for (const char* name :
    { "GBufferPass", vtkDeepGICaptureNames::Radius, "AutomaticRadius", "AutomaticRadiusFraction",
      "EffectiveRadius", "Bias", "Epsilon", "Intensity", vtkDeepGICaptureNames::NumberOfSamples,
      "UseSecondLayer", "BlurRadius", "BlurPlaneTolerance", "BlurNormalPower", "Composition" })
  {
    if (printed.str().find(std::string(name) + ":") == std::string::npos)
    {
      std::printf("PrintSelf does not print %s\n", name);
      ++failures;
    }
  }
  std::printf("%s\n", failures ? "FAILED" : "tau(1..98) = Listing 3; N = 99 -> 98 with a warning");
  return failures ? 1 : 0;
}
