// A glTF primitive of ten million triangles through `luxel render`: it renders, covering what it
// must, within the default memory limit, and a limit below what it needs refuses it in one line
// naming the file, before its triangles are read.

#include "cli/run_luxel.hpp"

#include "luxel/scenes/image_io.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace luxel::cli::test {
namespace {

namespace fs = std::filesystem;

// Under AddressSanitizer the ten million triangles' front end takes about a minute; there the
// primitive keeps one tenth of them (the same grid, repeated less often), which the memory limit
// and the coverage test just the same.
#if defined(__SANITIZE_ADDRESS__)
constexpr uint64_t kTriangles = 1'000'000;
#else
constexpr uint64_t kTriangles = 10'000'000;
#endif

/// The grid: kSide x kSide vertices over [-0.5, 0.5]^2 meters at z = 0, (kSide - 1)^2 quads of
/// two triangles, their 16-bit indices repeated until the primitive holds kTriangles triangles
/// (the copies lie on the first and fail the depth test): 60 MB of indices, 780 KB of positions,
/// instead of the 240 MB of a grid of ten million distinct triangles.
constexpr int kSide = 256;

/// The .glb: the grid's one primitive (unlit white), an orthographic camera at z = 1 looking down
/// -Z that sees [-1, 1]^2, a black background.
void write_grid_glb(const std::string& path) {
  std::vector<float> positions;
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x) positions.insert(positions.end(), {x / float(kSide - 1) - 0.5f, y / float(kSide - 1) - 0.5f, 0.0f});
  std::vector<uint16_t> grid;
  for (int y = 0; y + 1 < kSide; ++y)
    for (int x = 0; x + 1 < kSide; ++x) {
      const auto v = [](int i, int j) { return uint16_t(j * kSide + i); };
      grid.insert(grid.end(), {v(x, y), v(x + 1, y), v(x + 1, y + 1), v(x, y), v(x + 1, y + 1), v(x, y + 1)});
    }
  std::vector<uint16_t> indices(3 * kTriangles);
  for (size_t i = 0; i < indices.size(); ++i) indices[i] = grid[i % grid.size()];
  const size_t position_bytes = positions.size() * sizeof(float), index_bytes = indices.size() * sizeof(uint16_t);
  const nlohmann::json doc = {
      {"asset", {{"version", "2.0"}}},
      {"extensionsUsed", {"KHR_materials_unlit"}},
      {"scene", 0},
      {"scenes", {{{"nodes", {0, 1}}, {"extras", {{"luxel", {{"background", {0, 0, 0}}}}}}}}},
      {"nodes", {{{"mesh", 0}}, {{"camera", 0}, {"translation", {0, 0, 1}}}}},
      {"cameras", {{{"type", "orthographic"}, {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}}}},
      {"materials", {{{"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 1}}}}, {"extensions", {{"KHR_materials_unlit", nlohmann::json::object()}}}}}},
      {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"material", 0}}}}}}},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", 5126}, {"count", kSide * kSide}, {"type", "VEC3"}, {"min", {-0.5, -0.5, 0}}, {"max", {0.5, 0.5, 0}}},
        {{"bufferView", 1}, {"componentType", 5123}, {"count", indices.size()}, {"type", "SCALAR"}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", position_bytes}},
        {{"buffer", 0}, {"byteOffset", position_bytes}, {"byteLength", index_bytes}}}},
      {"buffers", {{{"byteLength", position_bytes + index_bytes}}}}};
  std::string text = doc.dump();
  text.resize((text.size() + 3) / 4 * 4, ' ');
  const uint32_t json_length = uint32_t(text.size()), bin_length = uint32_t((position_bytes + index_bytes + 3) / 4 * 4);
  const uint32_t header[3] = {0x46546C67u, 2, 12 + 8 + json_length + 8 + bin_length};
  const uint32_t json_chunk[2] = {json_length, 0x4E4F534Au}, bin_chunk[2] = {bin_length, 0x004E4942u};
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(header), sizeof header);
  out.write(reinterpret_cast<const char*>(json_chunk), sizeof json_chunk);
  out.write(text.data(), std::streamsize(text.size()));
  out.write(reinterpret_cast<const char*>(bin_chunk), sizeof bin_chunk);
  out.write(reinterpret_cast<const char*>(positions.data()), std::streamsize(position_bytes));
  out.write(reinterpret_cast<const char*>(indices.data()), std::streamsize(index_bytes));
  out.write("\0\0\0", std::streamsize(bin_length - position_bytes - index_bytes));
}

class BigScene : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("luxel-BigScene-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    write_grid_glb((dir_ / "grid.glb").string());
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }
  static std::string file(const std::string& name) { return (dir_ / name).string(); }
  static fs::path dir_;
};
fs::path BigScene::dir_;

// The camera sees [-1, 1]^2 meters on 64 x 64 pixels, 1/32 meter a pixel; the grid's edges at
// +-0.5 fall between pixel centers (15.5 and 16.5 pixels from the edge: -0.516 and -0.484), so
// exactly pixels 16 to 47 on each axis are white and every other pixel black.
TEST_F(BigScene, TenMillionTrianglesRenderTheirCoverage) {
  const std::string png = file("grid.png");
  const auto t0 = std::chrono::steady_clock::now();
  const Process p = run_luxel("render --scene " + file("grid.glb") + " --width 64 --height 64 --msaa 1 --exposure 1 --no-bloom --out " +
                              png + " --stats 2>&1");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_EQ(p.exit_code, 0) << p.out;
  EXPECT_NE(p.out.find("triangles=" + std::to_string(kTriangles) + " "), std::string::npos) << p.out;
  std::printf("%llu triangles loaded and rendered in %.2f s\n", static_cast<unsigned long long>(kTriangles), seconds);
  const scenes::PixelImage image = scenes::read_image(png);
  ASSERT_EQ(image.width, 64);
  ASSERT_EQ(image.height, 64);
  int wrong = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const bool inside = x >= 16 && x < 48 && y >= 16 && y < 48;
      const uint8_t* px = &image.rgba8[size_t(4 * (y * 64 + x))];
      const uint8_t expected = inside ? 255 : 0;
      if (px[0] != expected || px[1] != expected || px[2] != expected) ++wrong;
    }
  EXPECT_EQ(wrong, 0) << "pixels that are not white inside the grid's square and black outside it";
}

// The file is 58 MiB, read and parsed twice that; its triangle corners, as read and as kept, another
// 229 MiB (a tenth of each under ASan): a 200 MiB limit (20 MiB under ASan) lets the file be read
// and refuses its triangles, in one line that names the file and says what it needs.
TEST_F(BigScene, ALimitBelowWhatItNeedsRefusesItInOneLine) {
  const std::string limit = kTriangles >= 10'000'000 ? "200M" : "20M";
  const Process p = run_luxel("render --scene " + file("grid.glb") + " --width 64 --height 64 --memory-limit " + limit +
                              " --out " + file("never.png") + " 2>&1 >/dev/null");
  EXPECT_EQ(p.exit_code, 1) << p.out;
  EXPECT_EQ(p.out.rfind("luxel render: " + file("grid.glb") + ": needs about ", 0), 0u) << p.out;
  const std::string counts = std::to_string(kTriangles) + " triangles, 65536 vertices";
  EXPECT_NE(p.out.find(counts), std::string::npos) << p.out;
  EXPECT_NE(p.out.find("beyond the memory limit of " + std::string(limit == "200M" ? "200 MiB" : "20 MiB") +
                       " (raise it with --memory-limit or LUXEL_MEMORY_LIMIT)\n"),
            std::string::npos)
      << p.out;
  EXPECT_EQ(p.out.find('\n'), p.out.size() - 1) << "one line: " << p.out;
  EXPECT_FALSE(fs::exists(file("never.png")));
}

}  // namespace
}  // namespace luxel::cli::test
