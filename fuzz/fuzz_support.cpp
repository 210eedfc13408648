#include "fuzz_support.hpp"

#include "inputs.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace luxel::fuzz {

namespace {
bool throwing = false;
}  // namespace

void throw_findings() { throwing = true; }

void finding(const std::string& what) {
  if (throwing) throw Finding(what);
  std::fprintf(stderr, "luxel fuzz finding: %s\n", what.c_str());
  std::abort();
}

std::string scratch_path(const std::string& name) {
  static const std::filesystem::path folder = [] {
    const char* tmp = std::getenv("TMPDIR");
    std::filesystem::path p = std::filesystem::path(tmp && *tmp ? tmp : "/tmp") / ("luxel-fuzz-" + std::to_string(getpid()));
    std::filesystem::create_directories(p);
    return p;
  }();
  return (folder / name).string();
}

void write_file(const std::string& path, const uint8_t* data, size_t size) {
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  if (!file.flush()) finding(path + ": cannot write this scratch file");
}

void expect_one_line_naming(const std::exception& e, const std::string& name) {
  const std::string what = e.what();
  if (what.find('\n') != std::string::npos) finding("an error of more than one line: " + what);
  if (what.find(name) == std::string::npos) finding("an error that does not name " + name + ": " + what);
}

}  // namespace luxel::fuzz
