// libFuzzer target: the scene readers on one file of the format
// DEEPGI_FUZZ_FORMAT (obj, mtl, nhdr, nrrd, ply, stl, vtk). The input is
// written to a temporary file and read: by vtkDeepGIOBJReader (obj, mtl) or
// vtkDeepGINrrdReader (nhdr, nrrd) in a pipeline, then by
// vtkDeepGISceneLoader, which runs them and turns their output into parts;
// the other formats by the loader alone. Each must return (an output, empty
// on error; true or false), never crash, hang or leak. Built by
// scripts/fuzz.sh.
//
// - obj, ply, stl, vtk, nrrd (attached data): the input is the whole file;
// - mtl: the input is the MTL file of a fixed one-triangle OBJ (mtllib);
// - nhdr: the input is a detached header; the data files it may name
//   (data.raw, 16 KiB, and s.1 .. s.4, 8 KiB each) exist next to it.

#include "vtkDeepGINrrdReader.h"
#include "vtkDeepGIOBJReader.h"
#include "vtkDeepGISceneLoader.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPolyData.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>

namespace
{
std::string Directory()
{
  static std::string dir;
  if (dir.empty())
  {
    char pattern[] = "/tmp/deepgi-fuzz-XXXXXX";
    const char* made = mkdtemp(pattern);
    if (!made)
    {
      std::abort();
    }
    dir = made;
    // Data files a detached NRRD header may name, and the OBJ of the MTL target.
    std::ofstream(dir + "/data.raw", std::ios::binary) << std::string(16384, '\x01');
    for (int i = 1; i <= 4; ++i)
    {
      std::ofstream(dir + "/s." + std::to_string(i), std::ios::binary) << std::string(8192, '\x02');
    }
    std::ofstream(dir + "/scene.obj")
      << "mtllib input.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\nusemtl b\nf 3 2 1\n";
  }
  return dir;
}

// The reader of the format as a VTK algorithm, on its own: Update, then the
// output's sizes (an empty output on error).
void ReadWithAlgorithm(const std::string& format, const std::string& path)
{
  if (format == "obj" || format == "mtl")
  {
    vtkNew<vtkDeepGIOBJReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    reader->GetOutput()->GetNumberOfCells();
  }
  else if (format == "nhdr" || format == "nrrd")
  {
    vtkNew<vtkDeepGINrrdReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    reader->GetOutput()->GetNumberOfPoints();
  }
}
}

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  // The loader's messages are expected: not printed, but still raised (with
  // GlobalWarningDisplayOff VTK would not raise them, and the loader would
  // miss its readers' errors).
  vtkOutputWindow::GetInstance()->SetDisplayMode(vtkOutputWindow::NEVER);
  Directory();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string format = DEEPGI_FUZZ_FORMAT;
  const std::string input = Directory() + "/input." + format;
  {
    std::ofstream out(input, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  const std::string path = format == "mtl" ? Directory() + "/scene.obj" : input;
  ReadWithAlgorithm(format, path);
  vtkNew<vtkDeepGISceneLoader> loader;
  loader->SetIsoValue(1.5);
  if (loader->Load(path.c_str()))
  {
    double bounds[6];
    loader->GetBounds(bounds);
    loader->GetScenePolyData();
  }
  return 0;
}
