// libFuzzer target: vtkDeepGIEXRReader on one file. The input is written to
// a temporary .exr file and read; the reader must succeed or report an
// error, never crash, hang, leak or allocate without bound. Built by
// scripts/fuzz.sh.

#include "vtkDeepGIEXRReader.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  vtkOutputWindow::GetInstance()->SetDisplayMode(vtkOutputWindow::NEVER);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  static std::string path;
  if (path.empty())
  {
    char pattern[] = "/tmp/deepgi-fuzz-exr-XXXXXX";
    const char* made = mkdtemp(pattern);
    if (!made)
    {
      std::abort();
    }
    path = std::string(made) + "/input.exr";
  }
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  vtkNew<vtkDeepGIEXRReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return 0;
}
