// vtkDeepGISceneText.h: the text helpers the scene readers share
// (vtkDeepGIOBJReader and vtkDeepGINrrdReader). Private to DeepGI::Scenes; not
// installed.
#ifndef vtkDeepGISceneText_h
#define vtkDeepGISceneText_h

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace vtkDeepGISceneText
{
inline std::string Lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// `s` without leading and trailing white space.
inline std::string Trim(const std::string& s)
{
  const size_t b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos)
  {
    return std::string();
  }
  const size_t e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

// Splits `s` at white space.
inline std::vector<std::string> Words(const std::string& s)
{
  std::vector<std::string> words;
  std::istringstream in(s);
  std::string w;
  while (in >> w)
  {
    words.push_back(w);
  }
  return words;
}

// Parses a whole word as a decimal integer (no overflow, nothing left over).
inline bool ParseInteger(const std::string& word, long long& value)
{
  if (word.empty())
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  value = std::strtoll(word.c_str(), &end, 10);
  return errno == 0 && end == word.c_str() + word.size();
}
}

#endif
