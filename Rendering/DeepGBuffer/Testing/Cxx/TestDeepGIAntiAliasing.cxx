// Anti-aliasing of the GI image. The deep G-buffer has one sample per
// pixel, so edges are jagged unless the frame is anti-aliased. A white
// square turned 20 degrees in the image plane over a white floor, on
// black, with the one-line vtkDeepGIPass at 160 x 120 (Converge, 6 frames):
// - without UseFXAA and without multisampling: not anti-aliased;
// - with the renderer's UseFXAA on, and with a window that asks for 4
//   samples: anti-aliased (GetLastFrameAntiAliased), and on the edge
//   pixels (where the supersampled image's luminance changes by more than
//   0.1 to a neighbour) the RMSE against the same scene rendered at
//   640 x 480 and averaged over 4 x 4 blocks is at most 0.8 of the
//   unfiltered one (measured: 0.144 unfiltered, 0.056 with UseFXAA, 0.059
//   on the multisampled window, whose colour is resolved before FXAA:
//   VTK 9.1's own UseFXAA on such a window gives a black image);
// - Converge() reaches its tolerance with FXAA on (the change it measures is
//   that of the anti-aliased window).

#include "DeepGBufferTestUtilities.h"

#include "vtkCamera.h"
#include "vtkDeepGIPass.h"
#include "vtkImageShrink3D.h"

#include <cmath>

using namespace DeepGBufferTest;
using namespace DeepGITest;

namespace
{
constexpr int W = 160, H = 120, Supersampling = 4;

struct Settings
{
  int Scale = 1;
  bool FXAA = false;
  int MultiSamples = 0;
};

// Renders the scene with the GI pass; returns whether the frame was
// anti-aliased and whether Converge reached its tolerance.
void RenderScene(const Settings& settings, vtkImageData* image, bool& antiAliased, bool& converged)
{
  auto window = MakeWindow(W * settings.Scale, H * settings.Scale);
  window->SetMultiSamples(settings.MultiSamples);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.0, 0.0, 0.0);
  renderer->SetUseFXAA(settings.FXAA);
  window->AddRenderer(renderer);
  const double f0[3] = { -3, 0, 3 }, f1[3] = { 3, 0, 3 }, f2[3] = { -3, 0, -3 };
  AddQuad(renderer, f0, f1, f2);
  const double c = std::cos(vtkMath::RadiansFromDegrees(20.0));
  const double s = std::sin(vtkMath::RadiansFromDegrees(20.0));
  const double q0[3] = { -c, 0.2 - s, 0.5 }, q1[3] = { c, 0.2 + s, 0.5 },
               q2[3] = { s, 1.4 + 0.2 - c, 0.5 };
  AddQuad(renderer, q0, q1, q2);
  SetCamera(renderer, 0.0, 1.2, 4.0, 0.0, 0.4, 0.0);
  renderer->ResetCameraClippingRange();
  vtkNew<vtkDeepGIPass> gi;
  renderer->SetPass(gi);
  gi->Converge(renderer, 6, 0.5 / 255.0);
  converged = gi->GetLastConvergenceReached();
  antiAliased = gi->GetGBufferPass()->GetLastFrameAntiAliased();
  ReadWindow(window, image, nullptr);
  gi->ReleaseGraphicsResources(window);
}

double Luminance(vtkImageData* image, vtkIdType p)
{
  vtkDataArray* rgb = image->GetPointData()->GetScalars();
  return (0.2126 * rgb->GetComponent(p, 0) + 0.7152 * rgb->GetComponent(p, 1) +
           0.0722 * rgb->GetComponent(p, 2)) /
    255.0;
}

// RMSE of `image` against `truth` over the pixels where the truth's
// luminance changes by more than 0.1 to a 4-neighbour.
double EdgeError(vtkImageData* image, vtkImageData* truth, long& edges)
{
  double sum = 0.0;
  edges = 0;
  for (int j = 1; j < H - 1; ++j)
  {
    for (int i = 1; i < W - 1; ++i)
    {
      const vtkIdType p = i + static_cast<vtkIdType>(j) * W;
      const double t = Luminance(truth, p);
      const bool edge = std::abs(t - Luminance(truth, p - 1)) > 0.1 ||
        std::abs(t - Luminance(truth, p + 1)) > 0.1 ||
        std::abs(t - Luminance(truth, p - W)) > 0.1 || std::abs(t - Luminance(truth, p + W)) > 0.1;
      if (edge)
      {
        const double d = Luminance(image, p) - t;
        sum += d * d;
        ++edges;
      }
    }
  }
  return edges ? std::sqrt(sum / edges) : 0.0;
}
}

int TestDeepGIAntiAliasing(int, char*[])
{
  vtkNew<vtkImageData> large, plain, fxaa, multisampled;
  bool antiAliased = false, converged = false;
  RenderScene({ Supersampling, false, 0 }, large, antiAliased, converged);
  vtkNew<vtkImageShrink3D> shrink;
  shrink->SetInputData(large);
  shrink->SetShrinkFactors(Supersampling, Supersampling, 1);
  shrink->AveragingOn();
  shrink->Update();
  vtkImageData* truth = shrink->GetOutput();
  Check(truth->GetDimensions()[0] == W && truth->GetDimensions()[1] == H, "supersampled size");

  RenderScene({ 1, false, 0 }, plain, antiAliased, converged);
  Check(!antiAliased, "no UseFXAA, no multisampling: not anti-aliased");
  RenderScene({ 1, true, 0 }, fxaa, antiAliased, converged);
  Check(antiAliased, "UseFXAA: anti-aliased");
  Check(converged, "Converge reaches its tolerance with FXAA");
  RenderScene({ 1, false, 4 }, multisampled, antiAliased, converged);
  Check(antiAliased, "a multisampled window: anti-aliased");

  long edges = 0;
  const double plainError = EdgeError(plain, truth, edges);
  const double fxaaError = EdgeError(fxaa, truth, edges);
  const double multisampledError = EdgeError(multisampled, truth, edges);
  std::printf("edge pixels %ld: RMSE against %dx supersampling: none %.4f, UseFXAA %.4f (%.2f), "
              "multisampled window %.4f (%.2f)\n",
    edges, Supersampling, plainError, fxaaError, fxaaError / plainError, multisampledError,
    multisampledError / plainError);
  Check(edges > 100, "the scene has edges");
  Check(fxaaError <= 0.8 * plainError, "UseFXAA: edge error at most 0.8 of the unfiltered one");
  Check(multisampledError <= 0.8 * plainError,
    "multisampled window: edge error at most 0.8 of the unfiltered one");
  return ExitStatus();
}
