// Output files of the command-line programs (deepgi-render and the
// deepgi-benchmark-* programs): every file is written under a temporary
// name in its own directory and renamed onto its name once complete, so
// that
// - a failed write (a full disk, a read-only directory) never leaves a
//   partial file, nor replaces an older complete one;
// - a symbolic link at the output's name is replaced by the new file, its
//   target is never written;
// - every failure is reported, with the reason, in `error`.
#ifndef DeepGIOutput_h
#define DeepGIOutput_h

#include <functional>
#include <string>

class vtkImageData;

namespace DeepGIOutput
{
/**
 * Makes `directory` (and its parents) a directory this process can create
 * files in: false, with `error` set, when the path is a file, cannot be
 * created, or a file cannot be created in it.
 */
bool PrepareDirectory(const std::string& directory, std::string& error);

/**
 * Writes `path` through `write`, which receives a temporary file name in
 * the same directory (the file exists, empty, with the permissions the
 * umask gives new files) and returns whether it wrote the whole file.
 * Then the temporary file is renamed onto `path` (replacing `path` itself,
 * also when it is a symbolic link). On failure the temporary file is
 * removed, `path` is untouched and `error` says why.
 */
bool WriteAtomically(const std::string& path,
  const std::function<bool(const std::string& temporary)>& write, std::string& error);

/// Writes `size` bytes (every write and the close checked) atomically.
bool WriteBytes(const std::string& path, const void* data, size_t size, std::string& error);

/// Writes `text` atomically.
bool WriteText(const std::string& path, const std::string& text, std::string& error);

/// Encodes `image` as a PNG in memory (vtkPNGWriter) and writes it atomically.
bool WritePNG(vtkImageData* image, const std::string& path, std::string& error);
} // namespace DeepGIOutput

#endif
