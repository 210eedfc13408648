// Ambient cubes: a white furnace gives the sky on every face, a symmetric scene symmetric cubes
// with each face looking the right way, samples inside solid geometry are detected and filled.

#include "bake_support.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace luxel::bake::test {
namespace {

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
  const BakeResult r = bake(s, quick_bake(64));
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
  BakeSettings settings = quick_bake(256);
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
  const BakeResult r = bake(s, quick_bake(16));  // black floor, black sky: nothing but the light
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
  const BakeResult r = bake(s, quick_bake(64));
  ASSERT_TRUE(r.cubes);
  EXPECT_EQ(r.cubes->valid, (std::vector<char>{1, 1, 0}));
  EXPECT_EQ(r.stats.cube_samples_inside, 1u);
  EXPECT_EQ(r.cubes->volume.cubes[2], r.cubes->volume.cubes[1]);
  EXPECT_GT(r.cubes->volume.cubes[0][5].r, 0.0f);  // looking down at the glowing floor
}

// ambient_cubes_at, from independent math: 1 inch above the middle of a 256-inch white floor lit
// straight down by a directional light of 0.75 (flat map 0.75, exact in half), black sky, no
// bounce (nothing above to bounce from). Below the point the floor fills the hemisphere but for a
// rim within 0.7 degrees of the horizon: face -Z sees 0.75, +Z sees the black sky, and each side face
// half of its weight on the floor, 0.375.
TEST(BakeAmbientCubesAt, AboveALitFloorFromTheAttachedLightmaps) {
  scenes::Scene s = floor_with_volume(glm::vec3(1.0f), {2, 2, 1}, {-64, -64, 32}, {64, 64, 32});
  scenes::Light l;
  l.type = scenes::LightType::directional;
  l.direction = {0, 0, -1};
  l.color = glm::vec3(0.75f);
  s.lights = {l};
  BakeSettings settings = quick_bake(64);
  const BakeResult r = bake(s, settings);
  scenes::Scene baked = s;
  attach(baked, r);
  settings.cube_samples = 4096;
  const std::vector<glm::vec3> points = {{0, 0, 1}, {10, -20, 1}};
  const PointCubes at = ambient_cubes_at(baked, settings, points);
  ASSERT_EQ(at.cubes.size(), 2u);
  EXPECT_EQ(at.valid, (std::vector<char>{1, 1}));
  const float expected[6] = {0.375f, 0.375f, 0.375f, 0.375f, 0.0f, 0.75f};
  for (const scenes::AmbientCube& cube : at.cubes)
    for (int f = 0; f < 6; ++f)
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(cube[size_t(f)][c], expected[f], 0.01f) << "face " << f;

  // The same threads or not, the same cubes; the unbaked scene is refused.
  settings.threads = 1;
  EXPECT_EQ(ambient_cubes_at(baked, settings, points).cubes, at.cubes);
  EXPECT_THROW(ambient_cubes_at(s, settings, points), BakeError);
}

// At a grid point, the cube at that point agrees with the volume's (their rays differ: within the
// Monte Carlo noise of 1024 rays); a point under the floor sees its back face and is not valid.
TEST(BakeAmbientCubesAt, AgreesWithTheVolumeAtItsSamples) {
  scenes::Scene s = floor_with_volume(glm::vec3(0.5f), {2, 1, 1}, {-64, 0, 48}, {64, 0, 48});
  scenes::Light l;
  l.type = scenes::LightType::point;
  l.position = {30, 10, 100};
  l.color = glm::vec3(10000.0f);
  s.lights = {l};
  s.background = glm::vec3(0.2f, 0.3f, 0.4f);
  BakeSettings settings = quick_bake(256);
  settings.cube_samples = 1024;
  const BakeResult r = bake(s, settings);
  scenes::Scene baked = s;
  attach(baked, r);
  // The grid's points, moved 1 inch inward on x (the volume's faces), and one below the floor.
  const std::vector<glm::vec3> points = {{-63, 0, 48}, {63, 0, 48}, {0, 0, -10}};
  const PointCubes at = ambient_cubes_at(baked, settings, points);
  EXPECT_EQ(at.valid, (std::vector<char>{1, 1, 0}));
  for (size_t i = 0; i < 2; ++i) {
    const scenes::AmbientCube& volume = r.cubes->volume.cubes[i];
    float brightest = 0;
    for (const glm::vec3& f : volume) brightest = std::max({brightest, f.r, f.g, f.b});
    for (int f = 0; f < 6; ++f)
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(at.cubes[i][size_t(f)][c], volume[size_t(f)][c], 0.03f * brightest) << i << f << c;
  }
}

}  // namespace
}  // namespace luxel::bake::test
