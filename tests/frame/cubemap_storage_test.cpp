// Baked cube maps kept on disk (bake/cubemap_storage.hpp) under the hash of what they read
// (frame/cubemaps.hpp): saved and reloaded to the same bytes, found again only for the same
// inputs, a damaged index one error.

#include "frame/frame_support.hpp"
#include "scenes/temp_dir.hpp"

#include "luxel/bake/cubemap_storage.hpp"
#include "luxel/frame/cubemaps.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>

namespace luxel::frame {
namespace {

using scenes::test::TempDir;

CubemapSettings tiny() {
  CubemapSettings s = CubemapSettings::quick();
  s.face_size = 4;
  return s;
}

void expect_same_textures(const scenes::Scene& a, const scenes::Scene& b) {
  ASSERT_EQ(a.textures.size(), b.textures.size());
  for (size_t i = 0; i < a.textures.size(); ++i) {
    const scenes::Texture &x = a.textures[i], &y = b.textures[i];
    EXPECT_EQ(x.name, y.name);
    EXPECT_TRUE(x.shape == y.shape && x.color_space == y.color_space && x.wrap_u == y.wrap_u && x.wrap_v == y.wrap_v &&
                x.mag == y.mag && x.min == y.min && x.mipmaps == y.mipmaps)
        << "texture " << i << " " << x.name;
    ASSERT_EQ(x.faces.size(), y.faces.size());
    for (size_t f = 0; f < x.faces.size(); ++f) {
      EXPECT_EQ(x.faces[f].rgba32f, y.faces[f].rgba32f) << "texture " << i << " face " << f;
      EXPECT_EQ(x.faces[f].rgba8, y.faces[f].rgba8) << "texture " << i << " face " << f;
    }
  }
  for (size_t i = 0; i < a.cubemap_samples.size(); ++i) EXPECT_EQ(a.cubemap_samples[i].texture, b.cubemap_samples[i].texture);
}

TEST(CubemapStorage, SavedAndReloadedToTheSameBytes) {
  TempDir dir;
  const scenes::Scene scene = baked_courtyard();
  rasterizer::Context ctx(2);
  const uint64_t hash = cubemap_input_hash(scene, tiny());
  bake::StoredCubemaps stored{bake_cubemaps(scene, tiny(), ctx), exposure_bracket(scene, tiny().stops_apart)};
  bake::save_cubemaps(stored, hash, dir.file(""));
  const std::optional<bake::StoredCubemaps> loaded = bake::load_cubemaps(dir.file(""), hash);
  ASSERT_TRUE(loaded);
  EXPECT_EQ(loaded->exposures, stored.exposures);
  scenes::Scene baked = scene, reloaded = scene;
  attach_cubemaps(baked, stored.cubes);
  attach_cubemaps(reloaded, loaded->cubes);
  expect_same_textures(baked, reloaded);
  EXPECT_FALSE(bake::load_cubemaps(dir.file(""), hash + 1)) << "cubes of other inputs are not reused";
  EXPECT_EQ(cubemap_input_hash(baked, tiny()), hash) << "the samples' own cubes are not an input";
}

TEST(CubemapStorage, TheHashChangesWithWhatTheCubesRead) {
  const scenes::Scene scene = baked_courtyard();
  const uint64_t hash = cubemap_input_hash(scene, tiny());
  auto changed = [&](auto&& change) {
    scenes::Scene s = scene;
    CubemapSettings settings = tiny();
    change(s, settings);
    return cubemap_input_hash(s, settings) != hash;
  };
  EXPECT_TRUE(changed([](scenes::Scene& s, CubemapSettings&) { s.cubemap_samples[2].position.z += 1; }));
  EXPECT_TRUE(changed([](scenes::Scene& s, CubemapSettings&) { s.cubemap_samples[2].size = 32; }));
  EXPECT_TRUE(changed([](scenes::Scene& s, CubemapSettings&) { s.materials[0].envmap_tint *= 0.5f; }));
  EXPECT_TRUE(changed([](scenes::Scene& s, CubemapSettings&) { s.meshes[0].positions[0].x += 1; }));
  EXPECT_TRUE(changed([](scenes::Scene& s, CubemapSettings&) {
    s.textures[size_t(s.lightmaps->flat)].faces[0].rgba32f[0] += 1;  // a re-bake of the lightmaps
  }));
  EXPECT_TRUE(changed([](scenes::Scene& s, CubemapSettings&) { s.textures[size_t(s.sky_texture)].faces[3].rgba32f[5] += 1; }));
  EXPECT_TRUE(changed([](scenes::Scene&, CubemapSettings& c) { c.stops_apart = 2; }));
  EXPECT_TRUE(changed([](scenes::Scene&, CubemapSettings& c) { c.face_size = 8; }));
  EXPECT_FALSE(changed([](scenes::Scene& s, CubemapSettings&) { s.cameras[0].position.x += 1; })) << "cameras are not read";
}

TEST(CubemapStorage, ADamagedIndexIsOneError) {
  TempDir dir;
  std::ofstream(dir.file("cubemaps.json")) << "{ not json";
  try {
    bake::load_cubemaps(dir.file(""), 1);
    FAIL() << "a damaged index must throw";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cubemaps.json: damaged cube maps"), std::string::npos) << e.what();
  }
  std::ofstream(dir.file("cubemaps.json"), std::ios::trunc)
      << R"({"format": "luxel-cubemaps", "version": 1, "hash": "0000000000000001", "names": ["a"], "files": ["missing.exr"]})";
  EXPECT_THROW(bake::load_cubemaps(dir.file(""), 1), std::runtime_error);
  EXPECT_FALSE(bake::load_cubemaps(dir.file("nowhere"), 1));
}

}  // namespace
}  // namespace luxel::frame
