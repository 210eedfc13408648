#include "fuzz_support.hpp"

#include "inputs.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace luxel::fuzz {

extern "C" void __sanitizer_set_report_fd(void* fd) __attribute__((weak));  // in sanitizer builds only

namespace {
bool throwing = false;

/// The process's stderr as it was at start. Image reads close fd 2 for their duration
/// (scenes/image_io.hpp): a finding, or a sanitizer's report of a crash inside the read, must not
/// go there.
const int report_fd = [] {
  const int fd = dup(STDERR_FILENO);
  if (fd >= 0 && __sanitizer_set_report_fd) __sanitizer_set_report_fd(reinterpret_cast<void*>(intptr_t(fd)));
  return fd;
}();
}  // namespace

void throw_findings() { throwing = true; }

void finding(const std::string& what) {
  if (throwing) throw Finding(what);
  dprintf(report_fd >= 0 ? report_fd : STDERR_FILENO, "luxel fuzz finding: %s\n", what.c_str());
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
