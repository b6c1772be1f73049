#include "vtkDeepGIStageTimer.h"

#include "vtkObjectFactory.h"
#include "vtk_glew.h"

#include <chrono>

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
  for (const Stage& stage : this->Stages)
  {
    os << indent << stage.Name << ": " << stage.Milliseconds << " ms in " << stage.Count
       << " runs\n";
  }
}

//------------------------------------------------------------------------------
void vtkDeepGIStageTimer::StartStage(const char* stage)
{
  // What was queued before belongs to the stage that ran before.
  glFinish();
  const double now = NowSeconds();
  this->AddElapsed(now);
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
  this->StartSeconds = now;
}

//------------------------------------------------------------------------------
void vtkDeepGIStageTimer::StopStage()
{
  if (this->Running.empty())
  {
    return;
  }
  glFinish();
  const double now = NowSeconds();
  this->AddElapsed(now);
  ++this->Stages[this->Running.back()].Count;
  this->Running.pop_back();
  this->StartSeconds = now;
}

//------------------------------------------------------------------------------
void vtkDeepGIStageTimer::AddElapsed(double now)
{
  if (!this->Running.empty())
  {
    this->Stages[this->Running.back()].Milliseconds += 1000.0 * (now - this->StartSeconds);
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
