// Regression image of vtkDeepAmbientObscurancePass on the skin of the
// headsq CT volume (Testing/Data/volumes/headsq, iso-value 500 through
// vtkDeepGISceneLoader, its default light and the documented face-on
// view): left the AO-composited image, right the ambient visibility (see
// DeepAmbientObscuranceImageTest.h). Automatic radius, N = 16.
// Threshold 0.5 and the margins of the numeric ranges: as in
// TestDeepAmbientObscuranceDemoImage. Measured when the baseline was made
// (default estimator SOLID_ANGLE): mean AV 0.965, dark fraction 0.027; the
// skin iso-surface is rippled (the quarter-resolution CT), so only 6.7 % of
// it is fully unoccluded (AV > 0.999): required >= 4.5 %.

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
    [](vtkDeepAmbientObscurancePass*) {}, { 0.935, 0.995, 0.045, 0.018 }, 0.5);
}
