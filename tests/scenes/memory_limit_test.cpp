// The memory limit (memory_limit.hpp): how sizes are written and read, its one-line refusal, and
// that glTF import and image reading refuse from sizes alone, before allocating.

#include "gltf_support.hpp"

#include "luxel/scenes/image_io.hpp"
#include "luxel/scenes/memory_limit.hpp"

#include <cstdlib>
#include <fstream>

namespace luxel::scenes::test {
namespace {

TEST(MemoryLimit, SizesAreBytesOrPowersOf1024) {
  EXPECT_EQ(parse_memory_size("1073741824"), uint64_t{1} << 30);
  EXPECT_EQ(parse_memory_size("512M"), uint64_t{512} << 20);
  EXPECT_EQ(parse_memory_size("8G"), uint64_t{8} << 30);
  EXPECT_EQ(parse_memory_size("8GiB"), uint64_t{8} << 30);
  EXPECT_EQ(parse_memory_size("8gb"), uint64_t{8} << 30);
  EXPECT_EQ(parse_memory_size("1.5G"), uint64_t{3} << 29);
  EXPECT_EQ(parse_memory_size("2T"), uint64_t{2} << 40);
  EXPECT_EQ(parse_memory_size("100B"), 100u);
  for (const char* bad : {"", "0", "0.1", "-1G", "G", "8X", "8 G", "1e3", "nan", "inf", "99999999999T", "1..5G"}) {
    try {
      parse_memory_size(bad);
      ADD_FAILURE() << "'" << bad << "' parsed";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()), "'" + std::string(bad) + "' is not a size (bytes, or a number with K, M, G or T: 512M, 8G)");
    }
  }
}

TEST(MemoryLimit, SizesAreWrittenAsPeopleReadThem) {
  EXPECT_EQ(format_bytes(100), "100 bytes");
  EXPECT_EQ(format_bytes(4096), "4 KiB");
  EXPECT_EQ(format_bytes(4696), "4.6 KiB");
  EXPECT_EQ(format_bytes(uint64_t{4} << 30), "4 GiB");
  EXPECT_EQ(format_bytes(uint64_t(9.1 * double(uint64_t{1} << 30))), "9.1 GiB");
  EXPECT_EQ(format_bytes(uint64_t{300} << 20), "300 MiB");
}

TEST(MemoryLimit, TheEnvironmentVariableOrTheDefault) {
  ::unsetenv(kMemoryLimitVariable);
  EXPECT_EQ(memory_limit_from_environment(), kDefaultMemoryLimit);
  EXPECT_EQ(kDefaultMemoryLimit, uint64_t{4} << 30);
  ::setenv(kMemoryLimitVariable, "", 1);
  EXPECT_EQ(memory_limit_from_environment(), kDefaultMemoryLimit);
  ::setenv(kMemoryLimitVariable, "16G", 1);
  EXPECT_EQ(memory_limit_from_environment(), uint64_t{16} << 30);
  ::setenv(kMemoryLimitVariable, "lots", 1);
  try {
    memory_limit_from_environment();
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "LUXEL_MEMORY_LIMIT: 'lots' is not a size (bytes, or a number with K, M, G or T: 512M, 8G)");
  }
  ::unsetenv(kMemoryLimitVariable);
}

TEST(MemoryLimit, ARefusalIsOneLineNamingWhatAndHowMuch) {
  EXPECT_NO_THROW(check_memory("scene.glb", 100, "anything", 100));
  try {
    check_memory("scene.glb", uint64_t(9.1 * double(uint64_t{1} << 30)), "10000000 triangles", uint64_t{4} << 30);
    ADD_FAILURE() << "no error";
  } catch (const MemoryLimitError& e) {
    EXPECT_EQ(std::string(e.what()), "scene.glb: needs about 9.1 GiB (10000000 triangles), beyond the memory limit of 4 GiB "
                                     "(raise it with --memory-limit or LUXEL_MEMORY_LIMIT)");
  }
}

/// A triangle with 16-bit indices, everything in one buffer.
GltfBuilder indexed_triangle() {
  GltfBuilder b;
  const int pos = b.add_positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
  const int idx = b.add_accessor(std::vector<uint16_t>{0, 1, 2}, 5123, "SCALAR", 1);
  b.add_node({{"mesh", b.add_mesh({{"POSITION", pos}}, idx)}});
  return b;
}

// Geometry is estimated before it is read: 3 x 2^18 vertices with normals of accessors without a
// buffer view (zeros; 42 MiB as read and kept, with their 32-bit corners) refused at a 16 MiB
// limit, loaded at the default.
TEST(MemoryLimit, GltfGeometryIsRefusedFromItsCounts) {
  TempDir dir;
  GltfBuilder b = indexed_triangle();
  b.doc["accessors"].push_back({{"componentType", 5126}, {"count", 3u << 18}, {"type", "VEC3"}});
  b.doc["accessors"].push_back({{"componentType", 5126}, {"count", 3u << 18}, {"type", "VEC3"}});
  b.add_node({{"mesh", b.add_mesh({{"POSITION", 2}, {"NORMAL", 3}})}});
  const std::string path = b.write(dir);
  GltfImportOptions low;
  low.memory_limit = uint64_t{16} << 20;
  const std::string m = expect_gltf_error(path, "needs about 42 MiB (262145 triangles, 786435 vertices, 0 images, ", [&] { load_gltf(path, low); });
  EXPECT_NE(m.find("beyond the memory limit of 16 MiB (raise it with --memory-limit or LUXEL_MEMORY_LIMIT)"), std::string::npos) << m;
  EXPECT_NO_THROW(load_gltf(path));
}

// Images count from their headers: a 1024 x 1024 PNG is refused at 4 MiB (its 4 MiB of RGBA,
// plus the channels as read), read at the default.
TEST(MemoryLimit, GltfImagesAndImageFilesAreRefusedFromTheirHeaders) {
  TempDir dir;
  PixelImage big;
  big.width = big.height = 1024;
  big.rgba8.assign(size_t(4) << 20, 128);
  write_image(big, dir.file("big.png"));
  try {
    read_image(dir.file("big.png"), uint64_t{4} << 20);
    ADD_FAILURE() << "no error";
  } catch (const MemoryLimitError& e) {
    EXPECT_EQ(std::string(e.what()), dir.file("big.png") + ": needs about 8 MiB (a 1024x1024 8-bit image), beyond the memory "
                                                            "limit of 4 MiB (raise it with --memory-limit or LUXEL_MEMORY_LIMIT)");
  }
  GltfBuilder b = indexed_triangle();
  b.doc["images"] = {{{"uri", "big.png"}}};
  b.doc["textures"] = {{{"source", 0}}};
  b.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  b.doc["meshes"][0]["primitives"][0]["material"] = 0;
  const std::string path = b.write(dir);
  GltfImportOptions low;
  low.memory_limit = uint64_t{4} << 20;
  expect_gltf_error(path, "image 0: " + dir.file("big.png") + ": needs about 8 MiB (a 1024x1024 8-bit image)", [&] { load_gltf(path, low); });
  EXPECT_EQ(load_gltf(path).textures.size(), 1u);
}

}  // namespace
}  // namespace luxel::scenes::test
