// The fuzz targets' checks (fuzz/inputs.hpp) on every input kept for them: the inputs a fuzzer
// found a defect with (tests/data/fuzz/TARGET, the regressions), and the seeds scripts/fuzz starts
// from (tests/data: glTF assets, LUTs, images). Each must be read, or refused with its reader's
// one-line error naming the file; a Finding names the input.

#include "test_paths.hpp"
#include "fuzz_support.hpp"
#include "inputs.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

namespace luxel::fuzz {
namespace {

namespace fs = std::filesystem;

const fs::path kData = luxel::test::data_dir();

std::vector<uint8_t> bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

/// Every regular file under `dir` (recursively) whose extension is one of `extensions` (all when
/// empty), in name order.
std::vector<fs::path> files_under(const fs::path& dir, const std::vector<std::string>& extensions = {}) {
  std::vector<fs::path> files;
  if (!fs::is_directory(dir)) return files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file() || entry.path().filename() == "README.md") continue;
    const std::string ext = entry.path().extension().string();
    if (extensions.empty() || std::find(extensions.begin(), extensions.end(), ext) != extensions.end()) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

void replay(const std::vector<fs::path>& files, const std::function<void(std::span<const uint8_t>)>& read,
            const std::function<std::vector<uint8_t>(const fs::path&)>& input = bytes_of) {
  throw_findings();
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    const std::vector<uint8_t> bytes = input(file);
    EXPECT_NO_THROW(read(bytes));
  }
}

/// A LUT file as the LUT target's input: its extension's index first.
std::vector<uint8_t> lut_input(const fs::path& file) {
  const std::string ext = file.extension().string().substr(1);
  uint8_t index = 0;
  while (index < std::size(kLutExtensions) && ext != kLutExtensions[index]) ++index;
  std::vector<uint8_t> bytes = bytes_of(file);
  bytes.insert(bytes.begin(), index);
  return bytes;
}

TEST(FuzzReplay, GltfRegressions) { replay(files_under(kData / "fuzz/gltf"), read_gltf_input); }
TEST(FuzzReplay, ImageRegressions) { replay(files_under(kData / "fuzz/image"), read_image_input); }
TEST(FuzzReplay, LutRegressions) { replay(files_under(kData / "fuzz/lut"), read_lut_input); }
TEST(FuzzReplay, BakeRegressions) { replay(files_under(kData / "fuzz/bake"), read_bake_input); }
TEST(FuzzReplay, CliRegressions) { replay(files_under(kData / "fuzz/cli"), read_cli_input); }

TEST(FuzzReplay, GltfSeeds) {
  const std::vector<fs::path> files = files_under(kData / "gltf", {".gltf", ".glb"});
  ASSERT_GE(files.size(), 5u);
  replay(files, read_gltf_input);
  replay(files_under(kData / "gltf-bad", {".gltf", ".glb"}), read_gltf_input);
}

TEST(FuzzReplay, ImageSeeds) {
  const std::vector<fs::path> files = files_under(kData, {".png"});
  ASSERT_GE(files.size(), 2u);
  replay(files, read_image_input);
}

TEST(FuzzReplay, LutSeeds) {
  const std::vector<fs::path> files = files_under(kData / "luts", {".cube", ".3dl"});
  ASSERT_GE(files.size(), 4u);
  replay(files, read_lut_input, lut_input);
}

TEST(FuzzReplay, CliSeeds) {
  const fs::path dir = scratch_path("cli-seeds");
  fs::create_directories(dir);
  write_cli_seeds(dir.string());
  const std::vector<fs::path> files = files_under(dir);
  ASSERT_GE(files.size(), 10u);
  replay(files, read_cli_input);
}

// The checks can fail: an error of two lines, or one not naming its file, is a finding.
TEST(FuzzReplay, ErrorsOfMoreThanOneLineOrNotNamingTheFileAreFindings) {
  throw_findings();
  EXPECT_NO_THROW(expect_one_line_naming(std::runtime_error("dir/a.cube: bad size"), "dir/a.cube"));
  EXPECT_THROW(expect_one_line_naming(std::runtime_error("dir/a.cube: bad\nsize"), "dir/a.cube"), Finding);
  EXPECT_THROW(expect_one_line_naming(std::runtime_error("bad size"), "dir/a.cube"), Finding);
}

}  // namespace
}  // namespace luxel::fuzz
