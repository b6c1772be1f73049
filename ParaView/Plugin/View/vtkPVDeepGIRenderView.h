/**
 * @class vtkPVDeepGIRenderView
 * @brief ParaView's render view with deep G-buffer global illumination.
 *
 * A vtkPVRenderView whose renderer draws through vtkDeepGIPass when
 * UseDeepGI is on: the pass is handed to ParaView's synchronized renderers
 * as their render pass (the slot ParaView's ray tracing uses), so ParaView's
 * own camera pass, FXAA and tone mapping wrap it as they wrap the default
 * pass. ParaView's SSAO is switched off while the deep GI is on (both would
 * occlude the ambient term).
 *
 * The properties map one to one onto vtkDeepGIPass (Documentation/paraview.md
 * lists them beside their pvpython names):
 * - UseDeepGI: on/off (off: ParaView's own default pass, nothing of the deep
 *   G-buffer runs);
 * - Preset: vtkDeepGIPass::Preset;
 * - AmbientObscurance, Radiosity, Reflections: the effect switches;
 * - ObscuranceRadius, RadiosityRadius: the gather radii as fractions of the
 *   diagonal of the view's geometry bounds (the passes'
 *   AutomaticRadiusFraction, with vtkDeepGIKeys::SCENE_BOUNDS set to
 *   ParaView's bounds of the visible data);
 * - ConvergeStills, ConvergeMaximumFrames, ConvergeTolerance: still renders
 *   (screenshots, pvbatch, the GUI after interaction) first run
 *   vtkDeepGIPass::Converge, so the radiosity's bounces settle; interactive
 *   renders are single frames.
 *
 * Distributed rendering (several processes, ParaView's parallel rendering
 * on): the G-buffer's layers are composited across the processes before the
 * effects run (vtkPVDeepGILayerExchange, a distributed depth peel), every
 * automatic length is a fraction of the whole scene's size (ParaView's
 * global geometry bounds, vtkDeepGIKeys::SCENE_BOUNDS), every process
 * renders two layers (the adaptive layer count is per process) and renders
 * even with no data of its own (the exchange is collective). Every process
 * then shades the same layers, so IceT's compositing of their images
 * changes nothing, and the image is the one a single process would render.
 * A still then renders exactly ConvergeMaximumFrames frames: the tolerance
 * test reads back each process's window, which the processes cannot be
 * relied on to agree about.
 */
#ifndef vtkPVDeepGIRenderView_h
#define vtkPVDeepGIRenderView_h

#include "vtkDeepGIParaViewViewModule.h" // for export macro
#include "vtkDeepGISetGet.h"             // for vtkDeepGISetClampMacro
#include "vtkNew.h"                      // for vtkNew
#include "vtkPVRenderView.h"

#include <string> // for std::string

class vtkDeepGIPass;
class vtkPVDeepGILayerExchange;

class VTKDEEPGIPARAVIEWVIEW_EXPORT vtkPVDeepGIRenderView : public vtkPVRenderView
{
public:
  static vtkPVDeepGIRenderView* New();
  vtkTypeMacro(vtkPVDeepGIRenderView, vtkPVRenderView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Deep GI on or off (default on).
  vtkSetMacro(UseDeepGI, bool);
  vtkGetMacro(UseDeepGI, bool);
  ///@}

  ///@{
  /// The pass's settings (see the class description).
  void SetPreset(int preset);
  int GetPreset();
  void SetAmbientObscurance(bool on);
  void SetRadiosity(bool on);
  void SetReflections(bool on);
  void SetObscuranceRadius(double fraction);
  void SetRadiosityRadius(double fraction);
  ///@}

  ///@{
  /// Still renders converge first (default on, at most 16 frames, tolerance
  /// 0.07/255 of the full scale, deepgi-render's default).
  vtkSetMacro(ConvergeStills, bool);
  vtkGetMacro(ConvergeStills, bool);
  vtkSetClampMacro(ConvergeMaximumFrames, int, 1, 1000);
  vtkGetMacro(ConvergeMaximumFrames, int);
  vtkDeepGISetClampMacro(ConvergeTolerance, double, 0.0, 1.0);
  vtkGetMacro(ConvergeTolerance, double);
  ///@}

  /// The composite pass itself, for settings the properties do not reach.
  vtkDeepGIPass* GetDeepGIPass();

  /// The effects of the last frame (vtkDeepGIPass::GetEffectsAsString;
  /// "NONE" while UseDeepGI is off): the information property
  /// DeepGILastFrameEffects.
  const char* GetLastFrameEffectsAsString();

  /// Bytes this process sent to composite the G-buffer's layers during the
  /// last render (its converging frames included; 0 on one process): the
  /// information property DeepGILayerExchangeBytes.
  vtkTypeInt64 GetLayerExchangeBytes();

protected:
  vtkPVDeepGIRenderView();
  ~vtkPVDeepGIRenderView() override;

  /// Puts the pass into (or takes it out of) the synchronized renderers'
  /// pass chain before every render, and converges still renders.
  void AboutToRenderOnLocalProcess(bool interactive) override;

private:
  vtkPVDeepGIRenderView(const vtkPVDeepGIRenderView&) = delete;
  void operator=(const vtkPVDeepGIRenderView&) = delete;

  void InstallPass();
  bool ConfigureDistribution();
  void ConvergeStill(bool distributed);

  vtkNew<vtkDeepGIPass> GIPass;
  vtkNew<vtkPVDeepGILayerExchange> LayerExchange;
  bool UseDeepGI = true;
  bool PassInstalled = false;
  bool ConvergeStills = true;
  bool Converging = false;
  int ConvergeMaximumFrames = 16;
  double ConvergeTolerance = 0.07 / 255.0;
  std::string LastFrameEffects;
};

#endif
