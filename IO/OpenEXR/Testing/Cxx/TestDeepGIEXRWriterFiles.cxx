// vtkDeepGIEXRWriter and the file system: the file is written under a
// temporary name and renamed onto FileName once complete.
// 1. A symbolic link at FileName is replaced by the new file; its target
//    keeps its content.
// 2. A full disk (simulated with RLIMIT_FSIZE, which fails writes past the
//    limit with EFBIG as a full disk fails them with ENOSPC): Write()
//    returns 0 with OutOfDiskSpaceError, an older file of that name keeps
//    its bytes, a new name is not created, and no temporary file is left.
// 3. A directory that does not exist: an error, nothing created.

#include "DeepGITestChecks.h"

#include "vtkCommand.h"
#include "vtkDeepGIEXRReader.h"
#include "vtkDeepGIEXRWriter.h"
#include "vtkErrorCode.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include <dirent.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

namespace
{
using DeepGITest::Check;

// A w x h image whose float values do not compress (a hash of the index).
vtkSmartPointer<vtkImageData> NoiseImage(int w, int h)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  vtkNew<vtkFloatArray> values;
  values->SetName("RGB");
  values->SetNumberOfComponents(3);
  values->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  unsigned int state = 12345u;
  for (vtkIdType i = 0; i < values->GetNumberOfValues(); ++i)
  {
    state = state * 1664525u + 1013904223u;
    values->SetValue(i, static_cast<float>(state >> 8) / 16777216.0f);
  }
  image->GetPointData()->AddArray(values);
  return image;
}

std::string Contents(const std::string& file)
{
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

bool IsRegularFile(const std::string& path)
{
  struct stat info;
  return lstat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode);
}

bool Exists(const std::string& path)
{
  struct stat info;
  return lstat(path.c_str(), &info) == 0;
}

// Number of entries of `directory` whose name contains ".partial-".
int TemporaryFiles(const std::string& directory)
{
  int count = 0;
  if (DIR* listing = opendir(directory.c_str()))
  {
    while (const dirent* entry = readdir(listing))
    {
      count += std::string(entry->d_name).find(".partial-") != std::string::npos ? 1 : 0;
    }
    closedir(listing);
  }
  return count;
}

// Writes with errors counted rather than printed as failures of the test.
struct Writer
{
  vtkNew<vtkDeepGIEXRWriter> Object;
  int Errors = 0;
  unsigned long Tag = 0;

  Writer()
  {
    this->Tag = this->Object->AddObserver(vtkCommand::ErrorEvent, this, &Writer::OnError);
  }
  void OnError(vtkObject*, unsigned long, void*) { ++this->Errors; }
  int Write(vtkImageData* image, const std::string& file)
  {
    this->Object->SetInputData(image);
    this->Object->SetFileName(file.c_str());
    return this->Object->Write();
  }
};

void TestSymbolicLink(const std::string& directory)
{
  const std::string target = directory + "/TestDeepGIEXRWriterFiles-target.txt";
  const std::string link = directory + "/TestDeepGIEXRWriterFiles-link.exr";
  std::remove(link.c_str());
  std::ofstream(target) << "the target of a link, never written\n";
  Check(symlink(target.c_str(), link.c_str()) == 0, "a symbolic link to a text file");
  Writer writer;
  Check(writer.Write(NoiseImage(8, 6), link) == 1 && writer.Errors == 0,
    "written through the link's name");
  Check(
    Contents(target) == "the target of a link, never written\n", "the link's target is unchanged");
  Check(IsRegularFile(link), "the link was replaced by a regular file");
  vtkNew<vtkDeepGIEXRReader> reader;
  reader->SetFileName(link.c_str());
  reader->Update();
  int dims[3] = { 0, 0, 0 };
  reader->GetOutput()->GetDimensions(dims);
  Check(dims[0] == 8 && dims[1] == 6, "the new file reads back");
  Check(TemporaryFiles(directory) == 0, "no temporary file left");
}

void TestFullDisk(const std::string& directory)
{
  // An older, complete file and a name that does not exist yet.
  const std::string older = directory + "/TestDeepGIEXRWriterFiles-older.exr";
  const std::string fresh = directory + "/TestDeepGIEXRWriterFiles-fresh.exr";
  std::remove(fresh.c_str());
  Writer small;
  Check(small.Write(NoiseImage(4, 4), older) == 1, "a small file written");
  const std::string olderBytes = Contents(older);

  // Writes past 64 KiB fail with EFBIG (SIGXFSZ ignored), like a full disk.
  rlimit saved;
  getrlimit(RLIMIT_FSIZE, &saved);
  rlimit limited = saved;
  limited.rlim_cur = 64 * 1024;
  void (*previous)(int) = std::signal(SIGXFSZ, SIG_IGN);
  const bool set = setrlimit(RLIMIT_FSIZE, &limited) == 0;
  Writer big;
  const auto image = NoiseImage(256, 256); // 768 KiB of floats that do not compress
  const int overOlder = big.Write(image, older);
  const int overOlderCode = static_cast<int>(big.Object->GetErrorCode());
  const int overFresh = big.Write(image, fresh);
  setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, previous);

  Check(set, "file size limit set");
  Check(overOlder == 0 && big.Errors >= 1 && overOlderCode == vtkErrorCode::OutOfDiskSpaceError,
    "a write that fills the disk fails with OutOfDiskSpaceError");
  Check(Contents(older) == olderBytes, "the older file of that name keeps its bytes");
  Check(overFresh == 0 && !Exists(fresh), "a new name is not created");
  Check(TemporaryFiles(directory) == 0, "no temporary file left");
  Writer again;
  Check(again.Write(image, fresh) == 1 && Exists(fresh), "without the limit the file is written");
}

void TestMissingDirectory(const std::string& directory)
{
  const std::string file = directory + "/no-such-directory/TestDeepGIEXRWriterFiles.exr";
  Writer writer;
  Check(writer.Write(NoiseImage(4, 4), file) == 0 && writer.Errors == 1 && !Exists(file),
    "a missing directory: one error, nothing written");
}
}

int TestDeepGIEXRWriterFiles(int argc, char* argv[])
{
  const std::string directory = DeepGITest::Argument(argc, argv, "-T", ".");
  TestSymbolicLink(directory);
  TestFullDisk(directory);
  TestMissingDirectory(directory);
  return DeepGITest::ExitStatus();
}
