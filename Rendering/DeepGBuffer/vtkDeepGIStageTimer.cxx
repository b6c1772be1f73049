#include "vtkDeepGIStageTimer.h"

#include "vtkObjectFactory.h"
#include "vtk_glew.h"

#include <chrono>

// Valgrind's client requests: a few no-op instructions outside Valgrind.
// Optional: without the header, stage boundaries cannot dump counts.
#if defined(__has_include)
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define VTK_DEEPGI_HAS_CALLGRIND 1
#endif
#endif

vtkStandardNewMacro(vtkDeepGIStageTimer);

namespace
{
double NowSeconds()
{
  using Clock = std::chrono::steady_clock;
  return std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
}
}

//------------------------------------------------------------------------------
void vtkDeepGIStageTimer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DumpCallgrindCounts: " << this->DumpCallgrindCounts << "\n";
  for (const Stage& stage : this->Stages)
  {
    os << indent << stage.Name << ": " << stage.Milliseconds << " ms in " << stage.Count
       << " runs\n";
  }
}

//------------------------------------------------------------------------------
void vtkDeepGIStageTimer::StartStage(const char* stage)
{
  this->EndInterval();
  const std::string name = stage ? stage : "";
  int index = 0;
  while (index < this->GetNumberOfStages() && this->Stages[index].Name != name)
  {
    ++index;
  }
  if (index == this->GetNumberOfStages())
  {
    this->Stages.push_back(Stage{ name });
  }
  this->Running.push_back(index);
}

//------------------------------------------------------------------------------
void vtkDeepGIStageTimer::StopStage()
{
  if (this->Running.empty())
  {
    return;
  }
  this->EndInterval();
  ++this->Stages[this->Running.back()].Count;
  this->Running.pop_back();
}

//------------------------------------------------------------------------------
void vtkDeepGIStageTimer::EndInterval()
{
  // What was queued before belongs to the stage that ran before.
  glFinish();
  const double now = NowSeconds();
  if (!this->Running.empty())
  {
    this->Stages[this->Running.back()].Milliseconds += 1000.0 * (now - this->StartSeconds);
  }
  this->StartSeconds = now;
#ifdef VTK_DEEPGI_HAS_CALLGRIND
  if (this->DumpCallgrindCounts)
  {
    CALLGRIND_DUMP_STATS_AT(this->Running.empty()
        ? GetOutsideStagesLabel()
        : this->Stages[this->Running.back()].Name.c_str());
  }
#endif
}

//------------------------------------------------------------------------------
bool vtkDeepGIStageTimer::CanDumpCallgrindCounts()
{
#ifdef VTK_DEEPGI_HAS_CALLGRIND
  return true;
#else
  return false;
#endif
}

//------------------------------------------------------------------------------
void vtkDeepGIStageTimer::SetDumpCallgrindCounts(bool dump)
{
  if (dump && !CanDumpCallgrindCounts())
  {
    vtkErrorMacro("Cannot dump callgrind's counts: this library was built without Valgrind's "
                  "valgrind/callgrind.h.");
    return;
  }
  if (this->DumpCallgrindCounts != dump)
  {
    this->DumpCallgrindCounts = dump;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkDeepGIStageTimer::Reset()
{
  this->Stages.clear();
  this->Running.clear();
}

//------------------------------------------------------------------------------
const char* vtkDeepGIStageTimer::GetStageName(int stage) const
{
  return stage >= 0 && stage < this->GetNumberOfStages() ? this->Stages[stage].Name.c_str()
                                                         : nullptr;
}

//------------------------------------------------------------------------------
double vtkDeepGIStageTimer::GetStageMilliseconds(int stage) const
{
  return stage >= 0 && stage < this->GetNumberOfStages() ? this->Stages[stage].Milliseconds : 0.0;
}

//------------------------------------------------------------------------------
int vtkDeepGIStageTimer::GetStageCount(int stage) const
{
  return stage >= 0 && stage < this->GetNumberOfStages() ? this->Stages[stage].Count : 0;
}

//------------------------------------------------------------------------------
double vtkDeepGIStageTimer::GetTotalMilliseconds() const
{
  double total = 0.0;
  for (const Stage& stage : this->Stages)
  {
    total += stage.Milliseconds;
  }
  return total;
}
