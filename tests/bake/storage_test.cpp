// Bakes on disk: saved and loaded back bit for bit, reused only while the inputs are unchanged,
// a damaged index is an error naming the file; attach() wires the maps into the scene.

#include "bake_support.hpp"

#include "luxel/bake/folder_lock.hpp"
#include "luxel/bake/storage.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <iterator>
#include <optional>
#include <thread>

namespace luxel::bake::test {
namespace {

class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() / ("luxel-bake-" + std::string(info->name()) + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  std::string path() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

scenes::Scene lit_box() {
  scenes::Scene s = closed_box(64, 8, lightmapped(glm::vec3(0.5f)), lightmapped(glm::vec3(0.5f), glm::vec3(2.0f)));
  scenes::IrradianceVolume v;
  v.min = glm::vec3(-16), v.max = glm::vec3(16), v.counts = {2, 2, 2}, v.spacing = glm::vec3(32);
  s.irradiance_volume = v;
  return s;
}

BakeSettings small_bake() {
  BakeSettings b;
  b.samples = 16;
  b.cube_samples = 16;
  return b;
}

TEST(BakeStorage, ABakeLoadsBackBitForBitWhileItsInputsAreUnchanged) {
  TempDir dir;
  scenes::Scene s = lit_box();
  const BakeResult r = bake(s, small_bake());
  save_bake(r, s, small_bake(), dir.path());
  const auto loaded = load_bake(dir.path(), s, small_bake());
  ASSERT_TRUE(loaded);
  for (int k = 0; k < 4; ++k)
    EXPECT_EQ(0, std::memcmp(loaded->lightmaps.maps[size_t(k)].data(), r.lightmaps.maps[size_t(k)].data(),
                             r.lightmaps.maps[size_t(k)].size() * sizeof(glm::vec3)));
  EXPECT_EQ(loaded->lightmaps.coverage, r.lightmaps.coverage);
  ASSERT_TRUE(loaded->cubes);
  EXPECT_EQ(loaded->cubes->volume.cubes, r.cubes->volume.cubes);

  // What the bake reads changes: no reuse.
  scenes::Scene moved = s;
  moved.meshes[1].positions[0].x += 1;
  EXPECT_FALSE(load_bake(dir.path(), moved, small_bake()));
  scenes::Scene relit = s;
  relit.materials[1].emissive *= 2.0f;
  EXPECT_FALSE(load_bake(dir.path(), relit, small_bake()));
  BakeSettings more = small_bake();
  more.samples = 64;
  EXPECT_FALSE(load_bake(dir.path(), s, more));
  // Threads never change a byte, so they are not part of the hash.
  BakeSettings threads = small_bake();
  threads.threads = 7;
  EXPECT_TRUE(load_bake(dir.path(), s, threads));
  // What the bake does not read (a camera) does not matter.
  scenes::Scene viewed = s;
  viewed.cameras.push_back({});
  EXPECT_TRUE(load_bake(dir.path(), viewed, small_bake()));
}

std::string bytes_of(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

TEST(BakeStorage, TheSameBakeWrittenTwiceIsTheSameFiles) {
  // A second apart: a time stamp in the EXR header would show (OpenImageIO writes one unless told).
  TempDir dir;
  const scenes::Scene s = lit_box();
  BakeSettings one = small_bake(), two = small_bake();
  one.threads = 1, two.threads = 2;
  save_bake(bake(s, one), s, one, dir.path() + "/a");
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  save_bake(bake(s, two), s, two, dir.path() + "/b");
  for (const char* f : {"lightmap_flat.exr", "lightmap_basis0.exr", "lightmap_basis1.exr", "lightmap_basis2.exr"}) {
    const std::string a = bytes_of(dir.path() + "/a/" + f);
    EXPECT_FALSE(a.empty()) << f;
    EXPECT_TRUE(a == bytes_of(dir.path() + "/b/" + f)) << f;
  }
}

TEST(BakeStorage, ADamagedIndexIsAnErrorNamingTheFile) {
  TempDir dir;
  const scenes::Scene s = lit_box();
  save_bake(bake(s, small_bake()), s, small_bake(), dir.path());
  { std::ofstream(dir.path() + "/bake.json") << "{ not json"; }
  try {
    load_bake(dir.path(), s, small_bake());
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("bake.json: not a bake index"));
  }
  EXPECT_FALSE(load_bake(dir.path() + "/nothing-here", s, small_bake()));
}

TEST(BakeStorage, AttachWiresTheFourMapsAndTheCubesIntoTheScene) {
  scenes::Scene s = lit_box();
  const BakeResult r = bake(s, small_bake());
  const size_t textures = s.textures.size();
  attach(s, r);
  ASSERT_TRUE(s.lightmaps);
  EXPECT_EQ(s.lightmaps->flat, int(textures));
  EXPECT_EQ(s.lightmaps->textures, (std::array<int, 3>{int(textures) + 1, int(textures) + 2, int(textures) + 3}));
  EXPECT_EQ(s.textures[textures].faces[0].width, r.lightmaps.width);
  EXPECT_EQ(s.textures[textures + 2].faces[0].rgba32f[0], r.lightmaps.maps[2][0].r);
  EXPECT_EQ(s.irradiance_volume->cubes.size(), 8u);
  EXPECT_NO_THROW(scenes::validate(s));
}

// Two holders of one folder's lock, as two processes would be (flock locks belong to the open
// file, so two opens in one process exclude each other the same way): the second says it waits,
// and gets the lock only once the first lets it go.
TEST(BakeFolderLock, ASecondHolderWaitsUntilTheFirstReleases) {
  TempDir dir;
  std::optional<FolderLock> first(std::in_place, dir.path() + "/nested");  // created with the folder
  ASSERT_TRUE(first->held());
  std::atomic<bool> waiting = false, acquired = false;
  std::thread second([&] {
    const FolderLock lock(dir.path() + "/nested", [&] { waiting = true; });
    acquired = true;
  });
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!waiting && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  ASSERT_TRUE(waiting) << "the second holder never said it waits";
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_FALSE(acquired) << "the second holder got the lock while the first held it";
  first.reset();
  second.join();
  EXPECT_TRUE(acquired);
  bool called = false;
  const FolderLock free_lock(dir.path() + "/nested", [&] { called = true; });
  EXPECT_FALSE(called) << "a free lock is not waited for";
}

TEST(BakeFolderLock, AFolderThatCannotBeCreatedIsAnErrorNamingIt) {
  TempDir dir;
  std::filesystem::create_directories(dir.path());
  std::ofstream(dir.path() + "/file") << "not a folder";
  EXPECT_THAT([&] { FolderLock lock(dir.path() + "/file/bake"); },
              ::testing::ThrowsMessage<std::runtime_error>(::testing::HasSubstr("file/bake: cannot create the bake folder")));
}

}  // namespace
}  // namespace luxel::bake::test
