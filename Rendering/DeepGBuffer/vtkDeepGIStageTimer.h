/**
 * @class   vtkDeepGIStageTimer
 * @brief   Wall-clock time of each stage of the deep G-buffer passes.
 *
 * Attached to a vtkDeepGBufferPass (SetStageTimer), it times every stage of
 * the passes that share that G-buffer: building the layers, each effect's
 * sub-passes (obscurance gather, blur, temporal filter; radiosity bounce
 * input, gather, blur, temporal filter; the reflection trace) and the
 * composites. Each stage is bracketed by glFinish, so the time is what the
 * OpenGL implementation spent on it, on a GPU and on a CPU renderer (Mesa
 * llvmpipe) alike, but the frame is serialized: attach a timer to profile,
 * not to measure frame rates (detached, the passes never call glFinish).
 *
 * Stages nest: a stage started while another runs pauses it, so each time
 * is the stage's own (exclusive) and the times add up to the time spent in
 * all stages. Times add up over frames until Reset; the stages are listed
 * in the order they first ran.
 *
 * Under Valgrind's callgrind, DumpCallgrindCounts makes every stage
 * boundary dump callgrind's counts, labelled with the stage the
 * instructions since the last boundary belong to (GetOutsideStagesLabel()
 * between stages): scripts/count-instructions.sh --stages adds them up
 * into instructions per stage, free of a shared machine's clock noise on a
 * CPU renderer.
 *
 * @sa vtkDeepGBufferPass::SetStageTimer
 */

#ifndef vtkDeepGIStageTimer_h
#define vtkDeepGIStageTimer_h

#include "vtkDeepGIRenderingModule.h" // for export macro
#include "vtkObject.h"

#include <string> // for Stage
#include <vector> // for Stages

class VTKDEEPGIRENDERING_EXPORT vtkDeepGIStageTimer : public vtkObject
{
public:
  static vtkDeepGIStageTimer* New();
  vtkTypeMacro(vtkDeepGIStageTimer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Starts timing `stage` (after glFinish), pausing the stage that runs.
  void StartStage(const char* stage);

  /// Stops the innermost running stage (after glFinish), adds its time and
  /// resumes the stage it paused; nothing when none runs.
  void StopStage();

  /// Forgets every stage and its times.
  void Reset();

  ///@{
  /// The stages timed since Reset, in the order they first ran: name, total
  /// milliseconds and the number of times each ran. Out of range: null, 0.
  int GetNumberOfStages() const { return static_cast<int>(this->Stages.size()); }
  const char* GetStageName(int stage) const;
  double GetStageMilliseconds(int stage) const;
  int GetStageCount(int stage) const;
  ///@}

  /// The sum of every stage's milliseconds.
  double GetTotalMilliseconds() const;

  /// The label of the instructions counted while no stage runs.
  static const char* GetOutsideStagesLabel() { return "outside the stages"; }

  ///@{
  /**
   * Whether each stage boundary (after its glFinish) dumps Valgrind
   * callgrind's counts with CALLGRIND_DUMP_STATS_AT, labelled with the
   * name of the stage that ran since the last boundary, or
   * GetOutsideStagesLabel(). Off by default; outside Valgrind a dump does
   * nothing. It needs
   * Valgrind's header when the library is built (CanDumpCallgrindCounts);
   * without it, turning it on is refused with an error.
   */
  void SetDumpCallgrindCounts(bool dump);
  vtkGetMacro(DumpCallgrindCounts, bool);
  vtkBooleanMacro(DumpCallgrindCounts, bool);
  static bool CanDumpCallgrindCounts();
  ///@}

protected:
  vtkDeepGIStageTimer() = default;
  ~vtkDeepGIStageTimer() override = default;

private:
  vtkDeepGIStageTimer(const vtkDeepGIStageTimer&) = delete;
  void operator=(const vtkDeepGIStageTimer&) = delete;

  struct Stage
  {
    std::string Name;
    double Milliseconds = 0.0;
    int Count = 0;
  };
  std::vector<Stage> Stages;
  std::vector<int> Running; // innermost last
  double StartSeconds = 0.0;
  bool DumpCallgrindCounts = false;
  // What ran since the last boundary goes to the running stage.
  void EndInterval();
};

#endif
