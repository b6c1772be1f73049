// deepgi-benchmark-reflection: accuracy of the screen-space mirror hits of
// vtkDeepReflectionPass against ray-traced hits (vtkDeepGIReferenceReflection),
// one-layer and two-layer G-buffer, on two scenes:
//
// - demo-mirror: the demo room (vtkDeepGIDemoScene, default view) with
//   its floor a perfect mirror (Specular 1, white SpecularColor);
// - figure13: the paper's Figure 13 set-up (as TestDeepReflectionSecondLayer):
//   a mirror floor, a grey panel leaving a gap above the floor and a red box
//   behind the panel, visible only in the mirror.
//
// For every pixel where the pass traced a ray (its capture's "Valid"), the
// reference traces the same mirror ray (from layer 0's X and normal of the
// same frame's G-buffer capture) up to the pass's effective maximum
// distance t_max. A screen-space hit matches when the reference also hits
// and the two hit distances along the ray differ by less than
// MatchTolerance (5 %) of the reference distance plus the pass's hit
// thickness dz. Fractions of the traced pixels where the truth hits:
// matched in layer 0, matched in layer 1, missed (the pass returns the
// environment), wrong hit (the pass hits another point); and of the pixels
// where the truth misses: false hits.
//
// Outputs in --output DIR: benchmark-reflection.md and .csv.

#include "DeepGIBenchmarkCommon.h"
#include "DeepGIOutput.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkAppendPolyData.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkDataArray.h"
#include "vtkDeepGBufferPass.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIDemoScene.h"
#include "vtkDeepGIReferenceReflection.h"
#include "vtkDeepGIRenderWindowFactory.h"
#include "vtkDeepRadiosityPass.h"
#include "vtkDeepReflectionPass.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace
{
using namespace DeepGIBenchmark;
const char* const Program = "deepgi-benchmark-reflection";

/// Hit distances closer than this fraction of the reference distance (plus
/// the pass's thickness dz) are the same surface point.
constexpr double MatchTolerance = 0.05;

struct Options
{
  int Width = 320;
  int Height = 240;
  int Frames = 3;
  int Backend = vtkDeepGIRenderWindowFactory::BACKEND_AUTO;
  std::string Output = "output";
  std::vector<std::string> Scenes = { "demo-mirror", "figure13" };
};

void Usage()
{
  std::printf("Usage: deepgi-benchmark-reflection [options]\n"
              "Screen-space mirror hits of vtkDeepReflectionPass (1 and 2 layers) against\n"
              "ray-traced hits (vtkDeepGIReferenceReflection).\n"
              "  --size WxH      image size in pixels (default 320x240)\n"
              "  --frames N      frames rendered before the capture (default 3)\n"
              "  --scenes LIST   comma list of demo-mirror, figure13 (default both)\n"
              "  --backend NAME  auto, x11 or egl (default auto)\n"
              "  --output DIR    output directory (default output)\n"
              "  --help          this text\n");
}

bool ParseOptions(int argc, char* argv[], Options& o)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h")
    {
      Usage();
      std::exit(0);
    }
    if (arg != "--size" && arg != "--frames" && arg != "--scenes" && arg != "--backend" &&
      arg != "--output")
    {
      std::fprintf(stderr, "%s: unknown option %s\n", Program, arg.c_str());
      return false;
    }
    if (i + 1 >= argc)
    {
      std::fprintf(stderr, "%s: %s needs a value\n", Program, arg.c_str());
      return false;
    }
    const std::string value = argv[++i];
    bool ok = true;
    if (arg == "--size")
    {
      ok = ParseSize(value, o.Width, o.Height);
    }
    else if (arg == "--frames")
    {
      ok = ParseInt(value, o.Frames) && o.Frames >= 1 && o.Frames <= 1000;
    }
    else if (arg == "--scenes")
    {
      o.Scenes = Split(value, ',');
      ok = !o.Scenes.empty() &&
        std::all_of(o.Scenes.begin(), o.Scenes.end(),
          [](const std::string& s) { return s == "demo-mirror" || s == "figure13"; });
    }
    else if (arg == "--backend")
    {
      o.Backend = vtkDeepGIRenderWindowFactory::GetBackendFromString(value.c_str());
      ok = o.Backend >= 0;
    }
    else
    {
      ok = !value.empty();
      o.Output = value;
    }
    if (!ok)
    {
      std::fprintf(stderr, "%s: bad value '%s' for %s\n", Program, value.c_str(), arg.c_str());
      return false;
    }
  }
  return true;
}

void MakeMirror(vtkProperty* p)
{
  p->SetSpecular(1.0);
  p->SetSpecularColor(1.0, 1.0, 1.0);
  p->SetSpecularPower(50.0);
}

vtkActor* AddSource(vtkRenderer* renderer, vtkAlgorithm* source, vtkAppendPolyData* scene)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  scene->AddInputConnection(source->GetOutputPort());
  return actor;
}

/// Populates `renderer`; returns the scene's triangles for the reference.
vtkSmartPointer<vtkPolyData> LoadScene(
  const std::string& name, vtkRenderer* renderer, vtkSmartPointer<vtkObject>& keep)
{
  if (name == "demo-mirror")
  {
    auto demo = vtkSmartPointer<vtkDeepGIDemoScene>::New();
    demo->SetTargetNumberOfTriangles(100000);
    demo->Populate(renderer);
    demo->SetCameraToDefaultView(renderer->GetActiveCamera());
    double floorColor[3] = { -1, -1, -1 };
    for (int m = 0; m < demo->GetNumberOfMaterials(); ++m)
    {
      if (std::string(demo->GetMaterialName(m)) == "floor")
      {
        demo->GetMaterialColor(m, floorColor);
      }
    }
    vtkActorCollection* actors = renderer->GetActors();
    actors->InitTraversal();
    while (vtkActor* actor = actors->GetNextActor())
    {
      const double* c = actor->GetProperty()->GetDiffuseColor();
      if (c[0] == floorColor[0] && c[1] == floorColor[1] && c[2] == floorColor[2])
      {
        MakeMirror(actor->GetProperty());
      }
    }
    renderer->ResetCameraClippingRange();
    keep = demo;
    return demo->GetScenePolyData();
  }
  auto scene = vtkSmartPointer<vtkAppendPolyData>::New();
  vtkNew<vtkPlaneSource> floor, panel;
  floor->SetOrigin(-10, 0, 10);
  floor->SetPoint1(10, 0, 10);
  floor->SetPoint2(-10, 0, -10);
  panel->SetOrigin(-2, 0.5, 0);
  panel->SetPoint1(2, 0.5, 0);
  panel->SetPoint2(-2, 3, 0);
  vtkNew<vtkCubeSource> box;
  box->SetCenter(0.0, 1.0, -2.0);
  vtkActor* floorActor = AddSource(renderer, floor, scene);
  floorActor->GetProperty()->SetColor(0.1, 0.1, 0.1);
  MakeMirror(floorActor->GetProperty());
  AddSource(renderer, panel, scene)->GetProperty()->SetColor(0.5, 0.5, 0.5);
  AddSource(renderer, box, scene)->GetProperty()->SetColor(1.0, 0.0, 0.0);
  scene->Update();
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 3.0, 8.0);
  camera->SetFocalPoint(0.0, 0.5, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(40.0);
  renderer->ResetCameraClippingRange();
  keep = scene;
  return scene->GetOutput();
}

struct Result
{
  std::string Scene;
  int Layers = 0;
  double GuardBand = 0.0;
  long Traced = 0, TruthHits = 0, MatchedLayer0 = 0, MatchedLayer1 = 0, Missed = 0, Wrong = 0,
       TruthMisses = 0, FalseHits = 0;
  double MaximumDistance = 0, Thickness = 0, FrameMs = 0;
};

double Percent(long a, long b)
{
  return b ? 100.0 * a / b : 0.0;
}

/// Sorts every pixel where the pass traced a ray (its capture
/// `reflections`) and the reference traced the same ray (`truth`) into
/// r's counts.
void CompareHits(vtkImageData* reflections, vtkImageData* truth, Result& r)
{
  vtkPointData* ss = reflections->GetPointData();
  vtkDataArray* traced = ss->GetArray(vtkDeepGICaptureNames::Valid);
  vtkDataArray* hitLayer = ss->GetArray(vtkDeepGICaptureNames::HitLayer);
  vtkDataArray* hitDistance = ss->GetArray(vtkDeepGICaptureNames::HitDistance);
  vtkDataArray* refValid = truth->GetPointData()->GetArray(vtkDeepGICaptureNames::Valid);
  vtkDataArray* refHit = truth->GetPointData()->GetArray("Hit");
  vtkDataArray* refDistance = truth->GetPointData()->GetArray(vtkDeepGICaptureNames::HitDistance);
  for (vtkIdType p = 0; p < traced->GetNumberOfTuples(); ++p)
  {
    if (!(traced->GetComponent(p, 0) > 0) || !(refValid->GetComponent(p, 0) > 0))
    {
      continue;
    }
    ++r.Traced;
    const int layer = static_cast<int>(hitLayer->GetComponent(p, 0));
    const bool truthHits = refHit->GetComponent(p, 0) > 0;
    if (!truthHits)
    {
      ++r.TruthMisses;
      r.FalseHits += layer >= 0;
      continue;
    }
    ++r.TruthHits;
    const double t = refDistance->GetComponent(p, 0);
    if (layer < 0)
    {
      ++r.Missed;
    }
    else if (std::fabs(hitDistance->GetComponent(p, 0) - t) < MatchTolerance * t + r.Thickness)
    {
      (layer == 0 ? r.MatchedLayer0 : r.MatchedLayer1)++;
    }
    else
    {
      ++r.Wrong;
    }
  }
}

/// The pass with `layers` G-buffer layers and `guardBand` on `sceneName`:
/// its frames (timed), its capture, and the reference's hits of the same
/// rays.
bool MeasureConfiguration(
  const Options& o, const std::string& sceneName, int layers, double guardBand, Result& r)
{
  View view;
  if (!OpenView(Program, o.Backend, o.Width, o.Height, view))
  {
    return false;
  }
  view.Renderer->SetBackground(0.1, 0.1, 0.15);
  vtkSmartPointer<vtkObject> keep;
  vtkSmartPointer<vtkPolyData> geometry = LoadScene(sceneName, view.Renderer, keep);
  vtkNew<vtkDeepReflectionPass> pass;
  pass->GetGBufferPass()->SetNumberOfLayers(layers);
  pass->GetGBufferPass()->SetGuardBand(guardBand);
  const std::vector<double> ms = TimePassesInRounds(view, { pass }, 1, 0, o.Frames)[0];
  vtkNew<vtkImageData> reflections, capture;
  if (!pass->CaptureReflections(reflections, view.Renderer) ||
    !pass->GetGBufferPass()->CaptureLayers(capture, view.Renderer))
  {
    return Report(Program, "capture failed on " + sceneName);
  }
  vtkNew<vtkDeepGIReferenceReflection> reference;
  reference->SetInputData(capture);
  reference->SetSceneData(geometry);
  reference->SetMaximumDistance(pass->GetEffectiveMaximumDistance());
  reference->Update();
  if (reference->GetOutput()->GetNumberOfPoints() == 0)
  {
    return Report(Program, "the reference failed on " + sceneName);
  }
  r.Scene = sceneName;
  r.Layers = layers;
  r.GuardBand = guardBand;
  r.MaximumDistance = pass->GetEffectiveMaximumDistance();
  r.Thickness = pass->GetEffectiveThickness();
  r.FrameMs = Median(ms);
  CompareHits(reflections, reference->GetOutput(), r);
  return true;
}

/// The run's settings and a row per scene and configuration.
std::string Markdown(const Options& o, const std::vector<Result>& results)
{
  std::ostringstream md;
  md << "Images " << o.Width << "x" << o.Height << ", " << o.Frames
     << " frames before the capture. A screen-space hit matches the ray-traced one when the hit "
        "distances differ by less than "
     << 100.0 * MatchTolerance
     << " % of the traced distance + dz. Percentages of the traced pixels where the truth hits "
        "(matched layer 0, matched layer 1, missed, wrong point) and of those where it misses "
        "(false hits).\n\n"
     << "| scene | layers | guard band | t_max | dz | traced px | truth hits | matched layer 0 "
        "[%] | matched layer 1 [%] | matched [%] | missed [%] | wrong point [%] | truth misses | "
        "false hits [%] |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Result& r : results)
  {
    char b[1024];
    std::snprintf(b, sizeof(b),
      "| %s | %d | %.2g | %.4g | %.4g | %ld | %ld | %.1f | %.1f | %.1f | %.1f | %.1f | %ld | "
      "%.1f |\n",
      r.Scene.c_str(), r.Layers, r.GuardBand, r.MaximumDistance, r.Thickness, r.Traced, r.TruthHits,
      Percent(r.MatchedLayer0, r.TruthHits), Percent(r.MatchedLayer1, r.TruthHits),
      Percent(r.MatchedLayer0 + r.MatchedLayer1, r.TruthHits), Percent(r.Missed, r.TruthHits),
      Percent(r.Wrong, r.TruthHits), r.TruthMisses, Percent(r.FalseHits, r.TruthMisses));
    md << b;
  }
  return md.str();
}

/// The CSV file: the counts of every scene and configuration.
std::string Csv(const std::vector<Result>& results)
{
  std::ostringstream csv;
  csv << "scene,layers,guard_band,max_distance,thickness,traced,truth_hits,matched_layer0,"
         "matched_layer1,missed,wrong,truth_misses,false_hits\n";
  for (const Result& r : results)
  {
    char b[1024];
    std::snprintf(b, sizeof(b), "%s,%d,%.3g,%.5g,%.5g,%ld,%ld,%ld,%ld,%ld,%ld,%ld,%ld\n",
      r.Scene.c_str(), r.Layers, r.GuardBand, r.MaximumDistance, r.Thickness, r.Traced, r.TruthHits,
      r.MatchedLayer0, r.MatchedLayer1, r.Missed, r.Wrong, r.TruthMisses, r.FalseHits);
    csv << b;
  }
  return csv.str();
}
}

int main(int argc, char* argv[])
{
  Options options;
  if (!ParseOptions(argc, argv, options))
  {
    Usage();
    return 2;
  }
  // The outputs are checked before the measuring.
  if (!PrepareOutputs(Program, options.Output, false))
  {
    return 1;
  }
  std::vector<Result> results;
  for (const std::string& sceneName : options.Scenes)
  {
    // 1 layer, 2 layers, and 2 layers with the G-buffer guard band of the
    // radiosity and GI passes (rays that leave the frame can hit the band).
    const std::pair<int, double> configurations[] = { { 1, 0.0 }, { 2, 0.0 },
      { 2, vtkDeepRadiosityPass::DEFAULT_GUARD_BAND } };
    for (const auto& configuration : configurations)
    {
      Result r;
      if (!MeasureConfiguration(options, sceneName, configuration.first, configuration.second, r))
      {
        return 1;
      }
      results.push_back(r);
      std::fprintf(stderr, "%s: %s, %d layer(s), guard band %g done\n", Program, sceneName.c_str(),
        configuration.first, configuration.second);
    }
  }
  return WriteTables(Program, options.Output, "benchmark-reflection", Markdown(options, results),
           Csv(results))
    ? 0
    : 1;
}
