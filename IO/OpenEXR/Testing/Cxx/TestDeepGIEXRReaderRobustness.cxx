// vtkDeepGIEXRReader on OpenEXR headers that claim huge images
// (Testing/Data/robustness/claim2gb_1ch.exr, claim8gb_1ch.exr: 12 and 23 KB
// files whose data windows need 2 and 8 GB; fuzz_line_buffer.exr, 318
// bytes found by fuzzing, whose lines made OpenEXR allocate 2 GB of line
// buffers while opening it). The reader allocated that much before reading
// a pixel; it must refuse them with one error each (naming the file),
// before allocating. Argument: --data DIR (Testing/Data).

#include "DeepGITestChecks.h"
#include "DeepGITestData.h"

#include "vtkCommand.h"
#include "vtkDeepGIEXRReader.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkNew.h"

#include <iostream>
#include <string>
#include <vector>

namespace
{
class Messages : public vtkCommand
{
public:
  static Messages* New() { return new Messages; }
  void Execute(vtkObject*, unsigned long, void* callData) override
  {
    this->Texts.emplace_back(callData ? static_cast<const char*>(callData) : "");
  }
  std::vector<std::string> Texts;
};
}

int TestDeepGIEXRReaderRobustness(int argc, char* argv[])
{
  const std::string data = DeepGITestData::Folder(argc, argv, "TestDeepGIEXRReaderRobustness");
  if (data.empty())
  {
    return EXIT_FAILURE;
  }
  for (const char* name : { "claim2gb_1ch.exr", "claim8gb_1ch.exr", "fuzz_line_buffer.exr" })
  {
    const std::string path = data + "/robustness/" + name;
    vtkNew<vtkDeepGIEXRReader> reader;
    vtkNew<Messages> errors;
    reader->AddObserver(vtkCommand::ErrorEvent, errors);
    reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
    reader->SetFileName(path.c_str());
    reader->Update();
    size_t fromReader = 0;
    std::string text;
    for (const std::string& t : errors->Texts)
    {
      if (t.find(path) != std::string::npos)
      {
        ++fromReader;
        text = t;
      }
    }
    const vtkIdType pixels = reader->GetOutput()->GetNumberOfPoints();
    if (DeepGITest::Check(fromReader == 1 && pixels == 0,
          DeepGITest::Format("%s: one error naming the file (got %zu) and no pixels (got %lld)",
            name, fromReader, static_cast<long long>(pixels))))
    {
      std::cout << name << ": " << text.substr(text.find('\n') + 1);
    }
  }
  return DeepGITest::ExitStatus();
}
