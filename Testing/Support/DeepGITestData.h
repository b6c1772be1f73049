// The project's test data (Testing/Data, listed in its MANIFEST.md) as the
// tests find it: the folder comes from the command line (--data DIR, set by
// CMake), and a missing file stops the test with one line naming it.
#ifndef DeepGITestData_h
#define DeepGITestData_h

#include <vtksys/SystemTools.hxx>

#include <cstdio>
#include <initializer_list>
#include <string>

namespace DeepGITestData
{
/**
 * The folder given after --data, or "" (with a message) when there is none.
 */
inline std::string Folder(int argc, char* argv[], const char* testName)
{
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (std::string(argv[i]) == "--data")
    {
      return argv[i + 1];
    }
  }
  std::fprintf(
    stderr, "%s: no test data folder (--data DIR, normally <source>/Testing/Data)\n", testName);
  return std::string();
}

/**
 * True when every one of `files` (paths relative to `folder`) is a readable
 * file; otherwise prints one line per missing file and returns false, so
 * that the test fails with that message before it loads anything.
 */
inline bool Require(
  const std::string& folder, std::initializer_list<const char*> files, const char* testName)
{
  if (folder.empty())
  {
    return false;
  }
  bool all = true;
  for (const char* file : files)
  {
    const std::string path = folder + "/" + file;
    if (!vtksys::SystemTools::FileExists(path, /*isFile=*/true))
    {
      std::fprintf(stderr, "%s: missing test data file %s (see Testing/Data/MANIFEST.md)\n",
        testName, path.c_str());
      all = false;
    }
  }
  return all;
}
} // namespace DeepGITestData

#endif
