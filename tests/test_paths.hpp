#pragma once
// Where the tests find their files: the source tree's tests/data and tests/tools, and the `luxel`
// program under test. Defined out of line (test_paths.cpp.in, configured per build), so that the
// test files themselves are the same text in every clone and their objects come from the compiler
// cache (CMakeLists.txt).

#include <string>

namespace luxel::test {

/// tests/data: the assets, LUT files and fuzz inputs copied in with their licenses.
const std::string& data_dir();
/// tests/tools: the glTF-Validator's npm package (scripts/install-deps).
const std::string& tools_dir();
/// The `luxel` program of this build (empty where the build has none).
const std::string& luxel_binary();

}  // namespace luxel::test
