// Source .raw LUT files: bytes laid out red fastest read into the lattice at the right entries,
// the exact transform the trilinear interpolation of those entries, a written file the same
// bytes, the resolver's pick by extension, and one-line errors for files of another size.

#include "lut_support.hpp"
#include "scenes/temp_dir.hpp"

#include "luxel/postfx/lut_source.hpp"
#include "luxel/postfx/raw_lut_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <random>

namespace luxel::postfx {
namespace {

using scenes::test::TempDir;

/// Distinct bytes per axis, so a swapped axis reads different values.
Lut::Color24 entry_of(int r, int g, int b) {
  return {uint8_t(r * 8 + b % 8), uint8_t(255 - g * 8), uint8_t((b * 5 + r) % 256)};
}

std::string raw_bytes() {
  std::string bytes;
  for (int b = 0; b < 32; ++b)
    for (int g = 0; g < 32; ++g)
      for (int r = 0; r < 32; ++r)
        for (uint8_t v : entry_of(r, g, b)) bytes.push_back(char(v));
  return bytes;
}

TEST(RawLutFile, ReadsRedFastestThenGreenThenBlue) {
  const TempDir dir;
  std::ofstream(dir.file("look.raw"), std::ios::binary) << raw_bytes();
  const Lut lut = read_raw_lut(dir.file("look.raw"));
  for (const auto [r, g, b] : {std::array{0, 0, 0}, std::array{31, 0, 0}, std::array{1, 2, 3}, std::array{30, 17, 31}})
    EXPECT_EQ(lut.at(r, g, b), entry_of(r, g, b)) << r << " " << g << " " << b;
}

TEST(RawLutFile, ExactTransformInterpolatesTheEntriesTrilinearly) {
  const TempDir dir;
  std::ofstream(dir.file("look.raw"), std::ios::binary) << raw_bytes();
  const ColorTransform t = color_transform_named(dir.file("look.raw"));
  EXPECT_EQ(t.description, "Source .raw 32^3, trilinear");
  test::Lattice lattice{32, std::vector<glm::vec3>(kLutEntries)};
  const Lut lut = read_raw_lut(dir.file("look.raw"));
  for (size_t i = 0; i < lut.entries.size(); ++i)
    lattice.values[i] = glm::vec3(lut.entries[i][0], lut.entries[i][1], lut.entries[i][2]) / 255.0f;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> d(0.0f, 1.0f);
  std::vector<glm::vec3> colors(2000);
  for (glm::vec3& c : colors) c = glm::vec3(d(rng), d(rng), d(rng));
  std::vector<glm::vec3> out = colors;
  t.apply(out);
  double worst = 0.0;
  for (size_t i = 0; i < colors.size(); ++i) {
    const glm::dvec3 want = test::trilinear(lattice, glm::dvec3(colors[i]));
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(out[i][c] - want[c]));
  }
  EXPECT_LE(worst, 1e-5);
  EXPECT_EQ(sample_lut(t), lut) << "the engine's lattice is the file's";
}

TEST(RawLutFile, WritesTheSameBytes) {
  const TempDir dir;
  std::ofstream(dir.file("look.raw"), std::ios::binary) << raw_bytes();
  write_raw_lut(read_raw_lut(dir.file("look.raw")), dir.file("copy.raw"));
  std::ifstream copy(dir.file("copy.raw"), std::ios::binary);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(copy), std::istreambuf_iterator<char>()), raw_bytes());
  EXPECT_THROW(write_raw_lut(Lut::identity(), dir.file("no/such/folder/x.raw")), std::runtime_error);
}

TEST(RawLutFile, OnlyTheEnginesSizeIsWritten) {
  const scenes::test::TempDir dir;
  EXPECT_THROW(write_raw_lut(Lut::identity(16), dir.file("small.raw")), std::invalid_argument);
}

TEST(RawLutFile, FilesOfAnotherSizeGiveOneLineNamingThem) {
  const TempDir dir;
  std::ofstream(dir.file("short.raw"), std::ios::binary) << std::string(100, 'x');
  std::ofstream(dir.file("long.RAW"), std::ios::binary) << raw_bytes() << 'x';
  auto message = [](const std::string& path) -> std::string {
    try {
      color_transform_named(path);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "read";
  };
  EXPECT_EQ(message(dir.file("short.raw")), dir.file("short.raw") + ": 100 bytes; a Source .raw LUT has 98304 (32^3 RGB)");
  EXPECT_EQ(message(dir.file("long.RAW")), dir.file("long.RAW") + ": 98305 bytes; a Source .raw LUT has 98304 (32^3 RGB)");
  EXPECT_EQ(message(dir.file("missing.raw")), dir.file("missing.raw") + ": cannot open it");
}

}  // namespace
}  // namespace luxel::postfx
