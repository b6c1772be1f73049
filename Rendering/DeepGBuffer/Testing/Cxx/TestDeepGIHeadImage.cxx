// Regression image of vtkDeepGIPass on a volume scene: the headsq CT
// (Testing/Data/volumes/headsq) as an opaque skin iso-surface
// (vtkFlyingEdges3D at 500, ambient 0.2) and, in the same renderer, the
// same volume through vtkSmartVolumeMapper (bone, translucent), seen from
// the side at 300 x 300, HIGH_PERFORMANCE preset, converged over 12 frames.
// Checked: the effects that ran (ambient obscurance and radiosity; no
// specular prop, so no reflections), no error event, the volume changes
// the image (the same frame without it differs in more than 500 pixels by
// more than 8/255) and GI changes the skin against the plain G-buffer
// image (mean change and the fraction changed by more than 4/255 in the
// ranges measured when
// the baseline was made: margins about 20 %, at least 0.4/255). Threshold
// 0.5 as for the other images (VTK's metric sums per-pixel excesses over
// 105 of 255).
// Measured (the default estimators: SOLID_ANGLE for obscurance and for
// radiosity; the radiosity's default radius, half the diagonal): 7492 skin
// px, mean change +1.59/255, 0.171 of the skin changed by more than 4/255
// (obscurance on the truth's scale darkens only the folds; with
// obscurance's eq. 1 the mean is about -4.3/255 on half the skin, eq. 1's
// broad grey shadow); the volume changes 7696 px.

#include "DeepGITestData.h"
#include "DeepGITestHeadsq.h"
#include "DeepRadiosityTest.h"

#include "vtkColorTransferFunction.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIPass.h"
#include "vtkFlyingEdges3D.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRegressionTestImage.h"
#include "vtkSmartVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolume16Reader.h"
#include "vtkVolumeProperty.h"

using namespace DeepRadiosityTest;
using namespace DeepGITest;

namespace
{
constexpr int W = 300, H = 300;
// Measured when the baseline was made (see the header comment).
constexpr double MEAN_LOW = 1.25, MEAN_HIGH = 1.95, FRACTION_LOW = 0.135, FRACTION_HIGH = 0.205;
}

int TestDeepGIHeadImage(int argc, char* argv[])
{
  const std::string data = DeepGITestData::Folder(argc, argv, "TestDeepGIHeadImage");
  if (!DeepGITestData::Require(data,
        { "volumes/headsq/quarter.nhdr", "volumes/headsq/quarter.1", "volumes/headsq/quarter.93" },
        "TestDeepGIHeadImage"))
  {
    return EXIT_FAILURE;
  }
  vtkSmartPointer<vtkVolume16Reader> reader = DeepGITestData::ReadHeadsq(data);
  if (!reader)
  {
    return EXIT_FAILURE;
  }

  auto window = MakeWindow(W, H);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.32, 0.34, 0.43);
  window->AddRenderer(renderer);
  vtkNew<vtkFlyingEdges3D> skin;
  skin->SetInputConnection(reader->GetOutputPort());
  skin->SetValue(0, 500.0);
  vtkActor* skinActor = AddSourceActor(renderer, skin);
  skinActor->GetMapper()->ScalarVisibilityOff();
  skinActor->GetProperty()->SetColor(0.92, 0.78, 0.68);
  skinActor->GetProperty()->SetAmbient(0.2);
  skinActor->GetProperty()->SetOpacity(1.0);

  vtkNew<vtkVolume> volume;
  const double boneColor[3] = { 0.9, 0.9, 1.0 };
  vtkSmartVolumeMapper* volumeMapper = ShowBone(volume, reader, boneColor, 0.25);
  volume->GetProperty()->ShadeOff();
  // The translucent volume sits beside the skin so both are seen.
  volume->SetPosition(210.0, 0.0, 0.0);
  renderer->AddVolume(volume);

  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 1.0, 0.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 0.0, -1.0);
  renderer->ResetCamera();
  camera->Azimuth(20.0);
  camera->Elevation(10.0);
  renderer->ResetCameraClippingRange();

  vtkNew<vtkDeepGBufferPass> plainPass;
  renderer->SetPass(plainPass);
  window->Render();
  vtkNew<vtkImageData> plain, plainLayers;
  ReadWindow(window, plain, nullptr);
  plainPass->CaptureLayers(plainLayers, renderer);
  plainPass->ReleaseGraphicsResources(window);

  vtkNew<vtkDeepGIPass> gi;
  gi->SetPresetToHighPerformance();
  renderer->SetPass(gi);
  EventCounter errors(gi, vtkCommand::ErrorEvent);
  EventCounter windowErrors(window, vtkCommand::ErrorEvent);
  EventCounter mapperErrors(volumeMapper, vtkCommand::ErrorEvent);
  gi->Converge(renderer, 12);
  vtkNew<vtkImageData> image, noVolume;
  ReadWindow(window, image, nullptr);
  volume->VisibilityOff();
  window->Render();
  ReadWindow(window, noVolume, nullptr);
  volume->VisibilityOn();
  gi->Converge(renderer, 2);

  vtkDataArray* valid = plainLayers->GetPointData()->GetArray(
    vtkDeepGICaptureNames::Layer(vtkDeepGICaptureNames::Valid, 0).c_str());
  vtkDataArray* a = image->GetPointData()->GetScalars();
  vtkDataArray* b = plain->GetPointData()->GetScalars();
  vtkDataArray* v = noVolume->GetPointData()->GetScalars();
  long surface = 0, changed = 0, volumePixels = 0;
  double change = 0.0;
  for (vtkIdType p = 0; p < a->GetNumberOfTuples(); ++p)
  {
    double d = 0.0, volumeDifference = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      d += (a->GetComponent(p, k) - b->GetComponent(p, k)) / 3.0;
      volumeDifference =
        std::max(volumeDifference, std::abs(a->GetComponent(p, k) - v->GetComponent(p, k)));
    }
    volumePixels += volumeDifference > 8.0 ? 1 : 0;
    if (valid->GetTuple1(p) == 0)
    {
      continue;
    }
    ++surface;
    change += d;
    changed += std::abs(d) > 4.0 ? 1 : 0;
  }
  change /= std::max(surface, 1L);
  const double changedFraction = static_cast<double>(changed) / std::max(surface, 1L);
  std::printf("head: effects %s, %d layers; %ld skin px, mean change vs plain %.2f/255, changed by "
              "> 4/255 on %.3f; the volume changes %ld px; errors %d\n",
    vtkDeepGIPass::GetEffectsAsString(gi->GetLastFrameEffects()).c_str(),
    gi->GetLastFrameNumberOfLayers(), surface, change, changedFraction, volumePixels,
    errors.Count + windowErrors.Count + mapperErrors.Count);
  Check((gi->GetLastFrameEffects() & 7) ==
      (vtkDeepGIPass::AMBIENT_OBSCURANCE | vtkDeepGIPass::RADIOSITY),
    "AO and radiosity, no reflections");
  Check(errors.Count + windowErrors.Count + mapperErrors.Count == 0, "no error events");
  Check(volumePixels > 500, "the translucent volume is drawn with the GI pass");
  Check(surface > W * H / 20, "the skin fills part of the view");
  Check(change >= MEAN_LOW && change <= MEAN_HIGH, "mean change vs plain in the measured range");
  Check(changedFraction >= FRACTION_LOW && changedFraction <= FRACTION_HIGH,
    "changed fraction in the measured range");
  CheckRegressionImage(argc, argv, window, 0.5);
  gi->ReleaseGraphicsResources(window);
  return ExitStatus();
}
