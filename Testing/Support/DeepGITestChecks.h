// The one way every C++ test of the project reports what it checks: each
// check prints "ok: what" or "FAILED: what" (with the measured values in
// `what`, so that a failing run says by how much), and the test's exit
// status comes from the number of failed checks. A setup failure that makes
// the remaining checks meaningless (a missing file, no OpenGL) may return
// EXIT_FAILURE early, after printing why.
#ifndef DeepGITestChecks_h
#define DeepGITestChecks_h

#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <sstream>
#include <string>

namespace DeepGITest
{
/**
 * The value following `flag` on the command line, or `fallback`.
 */
inline std::string Argument(int argc, char* argv[], const char* flag, const char* fallback = "")
{
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (std::string(argv[i]) == flag)
    {
      return argv[i + 1];
    }
  }
  return fallback;
}

/**
 * The number of checks that failed so far in this test process.
 */
inline int& CheckFailures()
{
  static int failures = 0;
  return failures;
}

/**
 * Reports one check: prints "ok: what" or "FAILED: what" and counts a
 * failure. Returns `ok`, so that a test can skip what depends on it.
 */
inline bool Check(bool ok, const std::string& what)
{
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what.c_str());
  std::fflush(stdout);
  if (!ok)
  {
    ++CheckFailures();
  }
  return ok;
}

/**
 * printf-style formatting for check descriptions that carry measured values.
 */
inline std::string Format(const char* format, ...)
{
  va_list arguments;
  va_start(arguments, format);
  va_list copy;
  va_copy(copy, arguments);
  const int length = std::vsnprintf(nullptr, 0, format, copy);
  va_end(copy);
  std::string text(length > 0 ? static_cast<size_t>(length) : 0, '\0');
  if (length > 0)
  {
    std::vsnprintf(&text[0], text.size() + 1, format, arguments);
  }
  va_end(arguments);
  return text;
}

/**
 * The arguments written one after the other as std::ostream writes them,
 * for check descriptions that mix text, numbers and strings.
 */
template <typename... Parts>
std::string Text(const Parts&... parts)
{
  std::ostringstream text;
  (void)std::initializer_list<int>{ ((void)(text << parts), 0)... };
  return text.str();
}

/**
 * The test's exit status: prints the number of failed checks and returns
 * EXIT_SUCCESS when there is none, else EXIT_FAILURE.
 */
inline int ExitStatus()
{
  std::printf("%d check(s) failed\n", CheckFailures());
  return CheckFailures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
} // namespace DeepGITest

#endif
