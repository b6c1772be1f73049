#include "DeepGIOutput.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkUnsignedCharArray.h"

#include <vtksys/SystemTools.hxx>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace DeepGIOutput
{
namespace
{
std::string Reason(int error)
{
  return std::strerror(error);
}

// Creates an empty file of a unique name next to `path` (O_EXCL: never
// an existing file or link) with the permissions of a new file under the
// process's umask. Returns its name, or an empty string with the reason.
std::string CreateTemporary(const std::string& path, std::string& reason)
{
  std::vector<char> name(path.begin(), path.end());
  const char suffix[] = ".partial-XXXXXX";
  name.insert(name.end(), suffix, suffix + sizeof(suffix)); // with the terminating 0
  const int fd = mkstemp(name.data());
  if (fd < 0)
  {
    reason = Reason(errno);
    return std::string();
  }
  const mode_t mask = umask(0);
  umask(mask);
  fchmod(fd, 0666 & ~mask);
  close(fd);
  return std::string(name.data());
}
} // anonymous namespace

//------------------------------------------------------------------------------
bool PrepareDirectory(const std::string& directory, std::string& error)
{
  if (directory.empty())
  {
    error = "the output directory name is empty";
    return false;
  }
  if (vtksys::SystemTools::FileExists(directory) &&
    !vtksys::SystemTools::FileIsDirectory(directory))
  {
    error = "the output directory " + directory + " exists and is not a directory";
    return false;
  }
  const vtksys::Status made = vtksys::SystemTools::MakeDirectory(directory);
  if (!made)
  {
    error = "cannot create the output directory " + directory + ": " + made.GetString();
    return false;
  }
  // A probe file: permissions, read-only file systems, quotas.
  std::string reason;
  const std::string probe = CreateTemporary(directory + "/.deepgi-probe", reason);
  if (probe.empty())
  {
    error = "cannot write into the output directory " + directory + ": " + reason;
    return false;
  }
  std::remove(probe.c_str());
  return true;
}

//------------------------------------------------------------------------------
bool WriteAtomically(const std::string& path,
  const std::function<bool(const std::string& temporary)>& write, std::string& error)
{
  std::string reason;
  const std::string temporary = CreateTemporary(path, reason);
  if (temporary.empty())
  {
    error = "cannot write " + path + ": " + reason;
    return false;
  }
  if (!write(temporary))
  {
    std::remove(temporary.c_str());
    error = "cannot write " + path + " (the write failed; nothing was written)";
    return false;
  }
  // rename() replaces the directory entry `path`: a symbolic link there is
  // replaced, its target is left alone.
  if (std::rename(temporary.c_str(), path.c_str()) != 0)
  {
    const int saved = errno;
    std::remove(temporary.c_str());
    error = "cannot write " + path + ": " + Reason(saved);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool WriteBytes(const std::string& path, const void* data, size_t size, std::string& error)
{
  int failure = 0;
  const bool ok = WriteAtomically(
    path,
    [&](const std::string& temporary)
    {
      std::FILE* file = std::fopen(temporary.c_str(), "wb");
      if (!file)
      {
        failure = errno;
        return false;
      }
      bool written = size == 0 || std::fwrite(data, 1, size, file) == size;
      written = std::fflush(file) == 0 && written;
      // The data reach the disk before the rename makes them visible.
      written = fsync(fileno(file)) == 0 && written;
      failure = written ? 0 : errno;
      written = std::fclose(file) == 0 && written;
      failure = written || failure ? failure : errno;
      return written;
    },
    error);
  if (!ok && failure)
  {
    error = "cannot write " + path + ": " + Reason(failure);
  }
  return ok;
}

//------------------------------------------------------------------------------
bool WriteText(const std::string& path, const std::string& text, std::string& error)
{
  return WriteBytes(path, text.data(), text.size(), error);
}

//------------------------------------------------------------------------------
bool WritePNG(vtkImageData* image, const std::string& path, std::string& error)
{
  if (!image)
  {
    error = "cannot write " + path + ": no image";
    return false;
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->WriteToMemoryOn();
  writer->Write();
  vtkUnsignedCharArray* png = writer->GetResult();
  if (writer->GetErrorCode() != 0 || !png || png->GetNumberOfValues() == 0)
  {
    error = "cannot write " + path + ": the PNG encoding failed";
    return false;
  }
  return WriteBytes(path, png->GetPointer(0), static_cast<size_t>(png->GetNumberOfValues()), error);
}
} // namespace DeepGIOutput
