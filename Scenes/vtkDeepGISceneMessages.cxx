#include "vtkDeepGISceneMessages.h"

#include <cctype>

namespace vtkDeepGISceneMessages
{
namespace
{
// The messages VTK sends to its output window, without duplicates.
class OutputTrap : public vtkOutputWindow
{
public:
  static OutputTrap* New() { return new OutputTrap; }
  void DisplayErrorText(const char* text) override { this->Add(text); }
  void DisplayWarningText(const char* text) override { this->Add(text); }
  void DisplayGenericWarningText(const char* text) override { this->Add(text); }
  void DisplayText(const char*) override {}
  void DisplayDebugText(const char*) override {}
  void Add(const char* text)
  {
    const std::string message = Text(text);
    if (!message.empty() && this->Messages.find(message) == std::string::npos)
    {
      this->Messages += (this->Messages.empty() ? "" : "; ") + message;
    }
  }
  std::string Messages;
};
}

//------------------------------------------------------------------------------
std::string Text(const char* message, const char* className)
{
  std::string text = message ? message : "";
  // VTK's messages start with "ERROR: In FILE, line N\n" (or "Warning: ..."
  // or "Generic Warning: ...").
  const size_t newline = text.find('\n');
  if (newline != std::string::npos &&
    (text.compare(0, 6, "ERROR:") == 0 || text.find("Warning:") < newline))
  {
    text = text.substr(newline + 1);
  }
  const std::string prefix = className ? std::string(className) + " (" : std::string();
  const size_t end = text.find("): ");
  if (!prefix.empty() && text.compare(0, prefix.size(), prefix) == 0 && end != std::string::npos)
  {
    text = text.substr(end + 3);
  }
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
  {
    text.pop_back();
  }
  return text;
}

//------------------------------------------------------------------------------
Collector* Collector::New()
{
  return new Collector;
}

//------------------------------------------------------------------------------
void Collector::Execute(vtkObject* caller, unsigned long event, void* callData)
{
  const char* message = static_cast<const char*>(callData);
  const std::string text = Text(message);
  if (!text.empty())
  {
    this->Messages += (this->Messages.empty() ? "" : "; ") + text;
  }
  const std::string alone = Text(message, caller ? caller->GetClassName() : nullptr);
  if (!alone.empty())
  {
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings).push_back(alone);
  }
}

//------------------------------------------------------------------------------
void Collector::Watch(vtkObject* object)
{
  object->AddObserver(vtkCommand::ErrorEvent, this);
}

//------------------------------------------------------------------------------
void Collector::WatchAll(vtkObject* object)
{
  this->Watch(object);
  object->AddObserver(vtkCommand::WarningEvent, this);
}

//------------------------------------------------------------------------------
ScopedOutputTrap::ScopedOutputTrap()
  : Previous(vtkOutputWindow::GetInstance())
  , Trap(vtkSmartPointer<OutputTrap>::New())
{
  vtkOutputWindow::SetInstance(this->Trap);
}

//------------------------------------------------------------------------------
ScopedOutputTrap::~ScopedOutputTrap()
{
  vtkOutputWindow::SetInstance(this->Previous);
}

//------------------------------------------------------------------------------
const std::string& ScopedOutputTrap::Messages() const
{
  return static_cast<OutputTrap*>(this->Trap.Get())->Messages;
}
}
