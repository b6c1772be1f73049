// Regression image of vtkDeepAmbientObscurancePass on the skin of the
// headsq CT volume (Testing/Data/volumes/headsq, iso-value 500 through
// vtkDeepGISceneLoader, its default light and the documented face-on
// view): left the AO-composited image, right the ambient visibility (see
// DeepAmbientObscuranceImageTest.h). Automatic radius, the defaults.
// Threshold 0.5 and the margins of the numeric ranges: as in
// TestDeepAmbientObscuranceDemoImage. Measured when the baseline was made
// (estimator SOLID_ANGLE, N = 16): mean AV 0.965, dark fraction 0.027, 6.7 %
// fully unoccluded (AV > 0.999); with the default VISIBILITY_BITMASK
// (N = 12): mean AV 0.969, dark fraction 0.026, and the skin iso-surface,
// rippled (the quarter-resolution CT), is fully unoccluded on 3.3 % (no
// bias hides its small dents): required >= 2 %.

#include "DeepAmbientObscuranceImageTest.h"
#include "DeepGITestData.h"
#include "vtkDeepGISceneLoader.h"

int TestDeepAmbientObscuranceHeadImage(int argc, char* argv[])
{
  const std::string data = DeepGITestData::Folder(argc, argv, "TestDeepAmbientObscuranceHeadImage");
  if (!DeepGITestData::Require(data,
        { "volumes/headsq/quarter.nhdr", "volumes/headsq/quarter.1", "volumes/headsq/quarter.93" },
        "TestDeepAmbientObscuranceHeadImage"))
  {
    return EXIT_FAILURE;
  }
  return DeepGBufferTest::RunAOImageTest(
    argc, argv,
    [&data](vtkRenderer* renderer)
    {
      vtkNew<vtkDeepGISceneLoader> loader;
      loader->SetIsoValue(500.0);
      if (!loader->Load((data + "/volumes/headsq/quarter").c_str()) ||
        loader->Populate(renderer) == 0)
      {
        std::printf("could not load %s/volumes/headsq/quarter\n", data.c_str());
        return false;
      }
      loader->SetViewDirection(0.0, -1.0, 0.0);
      loader->SetViewUp(0.0, 0.0, -1.0);
      loader->ResetCamera(renderer);
      return true;
    },
    [](vtkDeepAmbientObscurancePass*) {}, { 0.935, 0.995, 0.02, 0.018 }, 0.5);
}
