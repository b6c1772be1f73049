/**
 * @file   vtkDeepGISceneMessages.h
 * @brief  How vtkDeepGISceneLoader turns the messages of the readers it runs
 *         into its own (private to DeepGI::Scenes).
 *
 * The loader reports every failed load with one error of its own, and the
 * warnings of its readers as its own warnings, in the order they arise: the
 * readers' messages are collected here instead of being printed.
 */

#ifndef vtkDeepGISceneMessages_h
#define vtkDeepGISceneMessages_h

#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

namespace vtkDeepGISceneMessages
{
/**
 * The text of a VTK message: without the "ERROR: In FILE, line N" line and,
 * for a message of `className`, without its "CLASS (0x...): " prefix;
 * trailing white space removed.
 */
std::string Text(const char* message, const char* className = nullptr);

/// Collects the error (and, when watched, warning) messages of readers.
class Collector : public vtkCommand
{
public:
  static Collector* New();
  void Execute(vtkObject* caller, unsigned long event, void* callData) override;
  void Watch(vtkObject* object);
  /// Warnings too, for readers whose warnings mean lost data.
  void WatchAll(vtkObject* object);
  /// The errors (and watched warnings) so far, joined with "; ".
  std::string Messages;
  /// Each error and warning text alone, without the class prefix.
  std::vector<std::string> Errors, Warnings;
};

/**
 * Records the messages VTK sends to its output window while it exists
 * (generic warnings such as vtkDataReader's "Error reading binary data!"
 * have no object to observe), then puts the previous window back.
 */
class ScopedOutputTrap
{
public:
  ScopedOutputTrap();
  ~ScopedOutputTrap();
  const std::string& Messages() const;

private:
  vtkSmartPointer<vtkOutputWindow> Previous;
  vtkSmartPointer<vtkOutputWindow> Trap;
};
}

#endif
// VTK-HeaderTest-Exclude: vtkDeepGISceneMessages.h
