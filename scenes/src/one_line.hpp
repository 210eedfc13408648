#pragma once
// Errors are one line (docs/cli.md, "Exit codes and bad input"); what they quote from a file (a name, a
// URI) or from a library (OpenImageIO's messages) may hold line breaks and other control
// characters.

#include <algorithm>
#include <string>

namespace luxel::scenes {

/// `s` with every control character a space, and no trailing spaces.
inline std::string one_line(std::string s) {
  std::replace_if(s.begin(), s.end(), [](char c) { return (unsigned char)c < 0x20 || c == 0x7f; }, ' ');
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

}  // namespace luxel::scenes
