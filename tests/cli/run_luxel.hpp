#pragma once
// Runs the `luxel` binary under test (test_paths.hpp) through the shell.

#include "test_paths.hpp"
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace luxel::cli::test {

struct Process {
  int exit_code = -1;
  std::string out;  ///< what it printed on stdout (and on stderr when `args` ends in 2>&1)
};

/// `luxel ARGS`, ARGS being shell words (redirections allowed).
inline Process run_luxel(const std::string& args) {
  Process r;
  FILE* pipe = popen((luxel::test::luxel_binary() + " " + args).c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf;
  size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) r.out.append(buf.data(), n);
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

/// The whole of a file the command wrote ("" when there is none).
inline std::string file_text(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

/// `v` through printf format `format`, as `luxel report` prints a number of its tables and findings.
inline std::string printed(double v, const char* format) {
  std::array<char, 64> text;
  std::snprintf(text.data(), text.size(), format, v);
  return text.data();
}

}  // namespace luxel::cli::test
