#pragma once
// What the readers of fuzz inputs (inputs.hpp) share: a scratch folder per process for the readers
// that take paths, and the check every reader's error must pass.

#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>

namespace luxel::fuzz {

/// `name` inside this process's scratch folder (made on first use, under TMPDIR or /tmp).
std::string scratch_path(const std::string& name);

/// Writes the bytes to `path`, replacing the file.
void write_file(const std::string& path, const uint8_t* data, size_t size);

/// A finding unless `e.what()` is one line that names `name` (where the error says which file is
/// bad).
void expect_one_line_naming(const std::exception& e, const std::string& name);

}  // namespace luxel::fuzz
