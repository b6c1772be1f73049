// The oracles under motion (paper Figure 3). Along the demo scene's camera
// path, with a sphere moving through the room, each frame's layer 1 from a
// single-pass oracle is compared with DEPTH_PEEL's layer 1 for the same
// frame (for DELAY: the previous frame, whose scene it shows). The test
// prints, per oracle, the fraction of layer-1 pixels that differ and the
// share of those lying within SilhouetteRadius (4) pixels of a layer-0
// silhouette. It requires:
// - DELAY: no pixel differs (it is exact, at one frame of latency), except
//   rounding ties: a surface within 1e-5 (relative) of the threshold d0 + dz,
//   which the geometry-shader path and the peeling path may round apart;
// - REPROJECT: at most MaximumReprojectFraction of the pixels differ on
//   average, most of them near silhouettes, and clearly fewer than with
//   PREVIOUS (PREDICT is printed: on this smooth path its constant-velocity
//   extrapolation is nearly exact).

#include "DeepGBufferTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIDemoScene.h"
#include "vtkPolyDataMapper.h"
#include "vtkSphereSource.h"

#include <vector>

using namespace DeepGBufferTest;
using namespace DeepGITest;

namespace
{
constexpr int Width = 320;
constexpr int Height = 240;
constexpr int PathFrames = 90; // a full loop of the camera path
constexpr int RenderedFrames = 16;
// REPROJECT decides visibility in the previous frame, so it errs in bands
// as wide as the frame-to-frame parallax on both sides of silhouettes
// (a few pixels along this path); the columns are narrow, so these bands
// are a sizeable part of layer 1 behind them.
constexpr int SilhouetteRadius = 4;
constexpr double MaximumReprojectFraction = 0.2;
constexpr double MaximumReprojectToPreviousRatio = 0.6;
constexpr double MinimumReprojectSilhouetteShare = 0.6;

// 1 where a pixel lies within `radius` pixels of a layer-0 silhouette: a
// depth jump larger than dz between neighbours, or the edge of the geometry.
std::vector<unsigned char> SilhouetteMask(vtkImageData* capture, double dz, int radius)
{
  vtkDataArray* depth = Layer(capture, vtkDeepGICaptureNames::Depth, 0);
  vtkDataArray* valid = Layer(capture, vtkDeepGICaptureNames::Valid, 0);
  std::vector<unsigned char> edge(Width * Height, 0), near(Width * Height, 0);
  for (int y = 0; y < Height; ++y)
  {
    for (int x = 0; x < Width; ++x)
    {
      const int p = y * Width + x;
      for (int n : { p + 1, p + Width })
      {
        if ((n == p + 1 && x + 1 >= Width) || (n == p + Width && y + 1 >= Height))
        {
          continue;
        }
        const bool jump = valid->GetTuple1(p) != valid->GetTuple1(n) ||
          std::abs(depth->GetTuple1(p) - depth->GetTuple1(n)) > dz;
        if (jump)
        {
          edge[p] = edge[n] = 1;
        }
      }
    }
  }
  for (int y = 0; y < Height; ++y)
  {
    for (int x = 0; x < Width; ++x)
    {
      if (!edge[y * Width + x])
      {
        continue;
      }
      for (int dy = -radius; dy <= radius; ++dy)
      {
        for (int dx = -radius; dx <= radius; ++dx)
        {
          const int xx = x + dx, yy = y + dy;
          if (xx >= 0 && yy >= 0 && xx < Width && yy < Height)
          {
            near[yy * Width + xx] = 1;
          }
        }
      }
    }
  }
  return near;
}

struct OracleMotion
{
  double MeanFraction = 0.0;
  double MaximumFraction = 0.0;
  double SilhouetteShare = 1.0;
  long Different = 0;
  long Ties = 0;
};

OracleMotion RunPath(int oracle, double dz)
{
  auto window = MakeWindow(Width, Height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkDeepGIDemoScene> scene;
  scene->SetTargetNumberOfTriangles(20000);
  scene->Populate(renderer);

  // A prop that moves on its own, so the per-prop previous matrices matter.
  vtkNew<vtkSphereSource> sphereSource;
  sphereSource->SetRadius(0.45);
  sphereSource->SetThetaResolution(48);
  sphereSource->SetPhiResolution(24);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphereSource->GetOutputPort());
  vtkNew<vtkActor> sphere;
  sphere->SetMapper(sphereMapper);
  sphere->GetProperty()->SetColor(0.9, 0.9, 0.2);
  renderer->AddActor(sphere);
  double bounds[6];
  scene->GetBounds(bounds);
  const double center[3] = { 0.5 * (bounds[0] + bounds[1]),
    bounds[2] + 0.3 * (bounds[3] - bounds[2]), 0.5 * (bounds[4] + bounds[5]) };

  vtkNew<vtkDeepGBufferPass> reference, pass;
  reference->SetOracleToDepthPeel();
  reference->SetMinimumSeparation(dz);
  pass->SetOracle(oracle);
  pass->SetMinimumSeparation(dz);

  OracleMotion result;
  long differentAtSilhouettes = 0;
  int compared = 0;
  vtkSmartPointer<vtkImageData> previousReference;
  for (int f = 0; f < RenderedFrames; ++f)
  {
    scene->SetCameraToPathFrame(renderer->GetActiveCamera(), f, PathFrames);
    sphere->SetPosition(center[0] + 0.25 * (bounds[1] - bounds[0]) * std::sin(0.02 * f), center[1],
      center[2] + 0.15 * (bounds[5] - bounds[4]) * std::cos(0.02 * f));
    renderer->ResetCameraClippingRange();

    auto referenceCapture = vtkSmartPointer<vtkImageData>::New();
    renderer->SetPass(reference);
    window->Render();
    reference->CaptureLayers(referenceCapture, renderer);

    vtkNew<vtkImageData> capture;
    renderer->SetPass(pass);
    window->Render();
    pass->CaptureLayers(capture, renderer);

    vtkSmartPointer<vtkImageData> expected =
      oracle == vtkDeepGBufferPass::DELAY ? previousReference : referenceCapture;
    previousReference = referenceCapture;
    if (f == 0 || !expected)
    {
      continue; // the first frame has no history and peels
    }
    std::vector<unsigned char> different;
    LayerDifference d = CompareLayer(capture, expected, 1, 1e-5, &different, dz);
    result.Ties += d.Ties;
    std::vector<unsigned char> silhouette = SilhouetteMask(expected, dz, SilhouetteRadius);
    for (size_t p = 0; p < different.size(); ++p)
    {
      differentAtSilhouettes += different[p] && silhouette[p];
    }
    result.Different += d.Different();
    result.MeanFraction += d.Fraction();
    result.MaximumFraction = std::max(result.MaximumFraction, d.Fraction());
    ++compared;
  }
  result.MeanFraction /= std::max(compared, 1);
  result.SilhouetteShare =
    result.Different ? static_cast<double>(differentAtSilhouettes) / result.Different : 1.0;
  reference->ReleaseGraphicsResources(window);
  pass->ReleaseGraphicsResources(window);
  return result;
}
}

int TestDeepGBufferOracleMotion(int, char*[])
{
  const double dz = 0.15;
  OracleMotion results[vtkDeepGBufferPass::DELAY + 1];
  for (int oracle = vtkDeepGBufferPass::PREVIOUS; oracle <= vtkDeepGBufferPass::DELAY; ++oracle)
  {
    results[oracle] = RunPath(oracle, dz);
    std::printf(
      "%-9s layer-1 pixels differing from DEPTH_PEEL: mean %.4f, max %.4f per frame "
      "(%ld pixels in all, %ld rounding ties); %.1f%% of them within %d px of a silhouette\n",
      vtkDeepGBufferPass::GetOracleAsString(oracle), results[oracle].MeanFraction,
      results[oracle].MaximumFraction, results[oracle].Different, results[oracle].Ties,
      100.0 * results[oracle].SilhouetteShare, SilhouetteRadius);
  }
  const OracleMotion& delay = results[vtkDeepGBufferPass::DELAY];
  const OracleMotion& reproject = results[vtkDeepGBufferPass::REPROJECT];
  const OracleMotion& previous = results[vtkDeepGBufferPass::PREVIOUS];
  Check(delay.Different == 0,
    Format("DELAY equals DEPTH_PEEL of the frame it shows (%ld pixels differ)", delay.Different));
  Check(reproject.MeanFraction <= MaximumReprojectFraction,
    Format("REPROJECT differs on %.4f of layer 1 per frame (<= %.2f)", reproject.MeanFraction,
      MaximumReprojectFraction));
  Check(reproject.SilhouetteShare >= MinimumReprojectSilhouetteShare,
    Format("REPROJECT's differences concentrated at silhouettes (%.1f%% >= %.0f%%)",
      100.0 * reproject.SilhouetteShare, 100.0 * MinimumReprojectSilhouetteShare));
  Check(reproject.MeanFraction <= MaximumReprojectToPreviousRatio * previous.MeanFraction,
    Format("REPROJECT below %.1f x PREVIOUS (%.4f vs %.4f)", MaximumReprojectToPreviousRatio,
      reproject.MeanFraction, previous.MeanFraction));
  return ExitStatus();
}
