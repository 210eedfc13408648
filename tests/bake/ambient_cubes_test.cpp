// Ambient cubes: a white furnace gives the sky on every face, a symmetric scene symmetric cubes
// with each face looking the right way, samples inside solid geometry are detected and filled.

#include "bake_support.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace luxel::bake::test {
namespace {

BakeSettings fast(int samples) {
  BakeSettings b;
  b.samples = samples;
  b.cube_samples = samples;
  b.threads = 2;
  return b;
}

/// A 256-inch floor quad centered at the origin (albedo `albedo`) and a volume above it.
scenes::Scene floor_with_volume(glm::vec3 albedo, glm::ivec3 counts, glm::vec3 min, glm::vec3 max) {
  scenes::Scene s;
  s.name = "test:floor";
  s.materials = {lightmapped(albedo)};
  s.lightmap_luxel_size = 8;
  scenes::Mesh m = empty_mesh("floor", 0);
  add_quad(m, {-128, -128, 0}, {256, 0, 0}, {0, 256, 0}, 0, 0, 1, 32);
  s.meshes = {m};
  scenes::IrradianceVolume v;
  v.min = min, v.max = max, v.counts = counts;
  v.spacing = (max - min) / glm::max(glm::vec3(counts - 1), glm::vec3(1.0f));
  s.irradiance_volume = v;
  return s;
}

TEST(BakeAmbientCubes, WhiteFurnaceGivesTheSkyOnEveryFace) {
  // The floor reflects albedo x its flat map = the sky (0.75 is exact in half), so every ray sees
  // the same radiance and every face is that radiance (vrad's normalized weights).
  scenes::Scene s = floor_with_volume(glm::vec3(1.0f), {3, 3, 2}, {-64, -64, 16}, {64, 64, 80});
  s.background = glm::vec3(0.75f);
  const BakeResult r = bake(s, fast(64));
  ASSERT_TRUE(r.cubes);
  ASSERT_EQ(r.cubes->volume.cubes.size(), 18u);
  for (const auto& cube : r.cubes->volume.cubes)
    for (const glm::vec3& f : cube)
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[c], 0.75f, 0.75f * 1e-4f);
}

TEST(BakeAmbientCubes, ASymmetricSceneBakesSymmetricCubesFacingTheRightWay) {
  // A light above the middle of the floor; samples mirrored in x and in y. All-light mode, so the
  // direct part (exact) dominates and the gathered floor light (Monte Carlo) adds a little noise.
  scenes::Scene s = floor_with_volume(glm::vec3(0.5f), {4, 4, 1}, {-96, -96, 48}, {96, 96, 48});
  scenes::Light l;
  l.type = scenes::LightType::point;
  l.position = {0, 0, 100};
  l.color = glm::vec3(10000.0f);
  s.lights = {l};
  BakeSettings settings = fast(256);
  settings.cube_samples = 1024;
  settings.cubes_all_light = true;
  const BakeResult r = bake(s, settings);
  ASSERT_TRUE(r.cubes);
  const auto& cubes = r.cubes->volume.cubes;
  auto at = [&](int x, int y) -> const scenes::AmbientCube& { return cubes[size_t(y * 4 + x)]; };
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      const auto& a = at(x, y);
      const auto& mx = at(3 - x, y);  // mirrored in x: +X <-> -X
      const auto& my = at(x, 3 - y);  // mirrored in y: +Y <-> -Y
      const int swap_x[6] = {1, 0, 2, 3, 4, 5}, swap_y[6] = {0, 1, 3, 2, 4, 5};
      float brightest = 0;
      for (const glm::vec3& f : a) brightest = std::max(brightest, f.r);
      // Within 2 % of the cube's brightest face: the gathered part's Monte Carlo noise.
      for (int f = 0; f < 6; ++f) {
        EXPECT_NEAR(a[size_t(f)].r, mx[size_t(swap_x[f])].r, 0.02f * brightest) << x << y << f;
        EXPECT_NEAR(a[size_t(f)].r, my[size_t(swap_y[f])].r, 0.02f * brightest) << x << y << f;
      }
      // The light is toward the middle and above: the face looking at it is the brighter.
      EXPECT_GT(a[x < 2 ? 0 : 1].r, a[x < 2 ? 1 : 0].r) << "x faces at " << x << y;
      EXPECT_GT(a[y < 2 ? 2 : 3].r, a[y < 2 ? 3 : 2].r) << "y faces at " << x << y;
      EXPECT_GT(a[4].r, a[5].r) << "z faces at " << x << y;
    }
}

TEST(BakeAmbientCubes, IndirectOnlyLeavesTheLightsOut) {
  scenes::Scene s = floor_with_volume(glm::vec3(0.0f), {2, 2, 1}, {-64, -64, 48}, {64, 64, 48});
  scenes::Light l;
  l.type = scenes::LightType::point;
  l.position = {0, 0, 100};
  l.color = glm::vec3(10000.0f);
  s.lights = {l};
  const BakeResult r = bake(s, fast(16));  // black floor, black sky: nothing but the light
  for (const auto& cube : r.cubes->volume.cubes)
    for (const glm::vec3& f : cube) EXPECT_EQ(f, glm::vec3(0.0f));
}

TEST(BakeAmbientCubes, SamplesInsideSolidGeometryTakeTheNearestValidCube) {
  // A closed box (lit inside by its floor) with a volume whose samples straddle its walls: those
  // outside see the boxes' back faces and take the cube of the nearest sample inside.
  scenes::Scene s = closed_box(64, 8, lightmapped(glm::vec3(0.5f)), lightmapped(glm::vec3(0.5f), glm::vec3(1.0f)));
  scenes::IrradianceVolume v;
  v.min = {-16, 0, 0}, v.max = {48, 0, 0}, v.counts = {3, 1, 1}, v.spacing = {32, 1, 1};  // x = -16, 16, 48
  s.irradiance_volume = v;
  const BakeResult r = bake(s, fast(64));
  ASSERT_TRUE(r.cubes);
  EXPECT_EQ(r.cubes->valid, (std::vector<char>{1, 1, 0}));
  EXPECT_EQ(r.stats.cube_samples_inside, 1u);
  EXPECT_EQ(r.cubes->volume.cubes[2], r.cubes->volume.cubes[1]);
  EXPECT_GT(r.cubes->volume.cubes[0][5].r, 0.0f);  // looking down at the glowing floor
}

}  // namespace
}  // namespace luxel::bake::test
