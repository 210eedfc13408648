// Bad scenes give a clear error or warning naming the scene, never a crash or an endless bake.

#include "bake_support.hpp"

#include <gtest/gtest.h>
#include <gmock/gmock.h>

#include <limits>

namespace luxel::bake::test {
namespace {

using ::testing::HasSubstr;

scenes::Scene quad_scene() {
  scenes::Scene s;
  s.name = "test:bad";
  s.materials = {lightmapped(glm::vec3(0.5f))};
  s.lightmap_luxel_size = 4;
  scenes::Mesh m = empty_mesh("quad", 0);
  add_quad(m, {-32, -32, 0}, {64, 0, 0}, {0, 64, 0}, 0, 0, 1, 16);
  s.meshes = {m};
  scenes::Light sun;
  sun.type = scenes::LightType::directional;
  s.lights = {sun};
  return s;
}

std::string all(const std::vector<std::string>& warnings) {
  std::string s;
  for (const auto& w : warnings) s += w + "\n";
  return s;
}

std::string error_of(const scenes::Scene& s, const BakeSettings& settings) {
  try {
    bake(s, settings);
  } catch (const BakeError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(BakeBadScenes, NoLightsNoSkyNoEmissionWarnsAndBakesBlack) {
  scenes::Scene s = quad_scene();
  s.lights.clear();
  const BakeResult r = bake(s, quick_bake(4));
  EXPECT_THAT(all(r.warnings), HasSubstr("test:bad: no lights, no sky and no emissive surfaces"));
  for (size_t i : covered(r.lightmaps)) EXPECT_EQ(r.lightmaps.maps[0][i], glm::vec3(0.0f));
  EXPECT_EQ(r.stats.bounces, 0);
}

TEST(BakeBadScenes, DegenerateTrianglesAreSkippedWithAWarning) {
  scenes::Scene s = quad_scene();
  auto& m = s.meshes[0];
  m.positions.push_back({0, 0, 0}), m.positions.push_back({1, 1, 0}), m.positions.push_back({2, 2, 0});  // collinear
  for (int i = 0; i < 3; ++i) m.normals.push_back({0, 0, 1}), m.tangents.push_back({1, 0, 0, 1}), m.uv0.push_back({0, 0}),
                                  m.uv1.push_back({0.1f * i, 0.5f});
  for (uint32_t i : {4u, 5u, 6u}) std::get<std::vector<uint32_t>>(m.indices).push_back(i);
  const BakeResult r = bake(s, quick_bake(4));
  EXPECT_THAT(all(r.warnings), HasSubstr("test:bad: 1 lightmapped triangles have no area"));
  EXPECT_EQ(covered(r.lightmaps).size(), 256u);
}

TEST(BakeBadScenes, UvOutOfRangeIsClippedWithAWarning) {
  scenes::Scene s = quad_scene();
  s.meshes[0].uv1[2] = {1.5f, -0.25f};
  const BakeResult r = bake(s, quick_bake(4));
  EXPECT_THAT(all(r.warnings), HasSubstr("uv1 outside [0, 1]"));
  // Far outside (an int overflow if converted unclamped; UBSan watches) and not finite at all.
  s.meshes[0].uv1[2] = {1e30f, -1e30f};
  EXPECT_THAT(all(bake(s, quick_bake(4)).warnings), HasSubstr("uv1 outside [0, 1]"));
  // NaN on a vertex both triangles share: no triangle has a uv area left, so no lightmap at all.
  s.meshes[0].uv1[2] = {std::numeric_limits<float>::quiet_NaN(), 0.5f};
  EXPECT_THAT(all(bake(s, quick_bake(4)).warnings), HasSubstr("no lightmapped triangle has both area and uv1 area"));
}

TEST(BakeBadScenes, OverlappingUvIsReported) {
  scenes::Scene s = quad_scene();
  scenes::Mesh copy = s.meshes[0];
  for (glm::vec3& p : copy.positions) p.z += 100;  // the same chart used twice
  s.meshes.push_back(copy);
  const BakeResult r = bake(s, quick_bake(4));
  EXPECT_THAT(all(r.warnings), HasSubstr("luxels are covered by overlapping uv1 triangles"));
}

TEST(BakeBadScenes, ZeroOrNonFiniteLuxelSizeIsAnError) {
  scenes::Scene s = quad_scene();
  s.lightmap_luxel_size = 0;
  EXPECT_THAT(error_of(s, quick_bake(4)), HasSubstr("test:bad: the luxel size"));
  s.lightmap_luxel_size = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THAT(error_of(s, quick_bake(4)), HasSubstr("is not a positive number"));
  s.lightmap_luxel_size = 4;
  BakeSettings settings = quick_bake(4);
  settings.luxel_size = -1;  // negative: the scene's size is used
  EXPECT_EQ(error_of(s, settings), "(no error)");
}

TEST(BakeBadScenes, AHugeLuxelSizeGivesATinyAtlasWithAWarning) {
  scenes::Scene s = quad_scene();
  s.lightmap_luxel_size = 1e9f;
  const BakeResult r = bake(s, quick_bake(4));
  EXPECT_EQ(r.lightmaps.width, 1);
  EXPECT_THAT(all(r.warnings), HasSubstr("only 1 x 1 luxels"));
}

TEST(BakeBadScenes, AnAtlasBeyondTheSideLimitOrTheMemoryCapIsAnError) {
  scenes::Scene s = quad_scene();
  s.lightmap_luxel_size = 1e-4f;  // 64 inches / 1e-4 * 18/16: 11 million luxels a side
  EXPECT_THAT(error_of(s, quick_bake(4)), HasSubstr("luxels on a side, more than 16384"));
  s.lightmap_luxel_size = 0.05f;  // 1440 a side: fine by side, not by a 64 MiB cap
  BakeSettings settings = quick_bake(4);
  settings.max_memory_bytes = uint64_t(64) << 20;
  EXPECT_THAT(error_of(s, settings), HasSubstr("beyond the memory limit of 64 MiB"));
}

TEST(BakeBadScenes, BouncesThatDoNotConvergeStopAtTheCapWithAWarning) {
  // Albedo 1 in a closed box: every bounce returns all the light; the cap ends it.
  scenes::Scene s = closed_box(64, 4, lightmapped(glm::vec3(1.0f)), lightmapped(glm::vec3(1.0f), glm::vec3(1.0f)));
  BakeSettings settings = quick_bake(4);
  settings.max_bounces = 5;
  const BakeResult r = bake(s, settings);
  EXPECT_EQ(r.stats.bounces, 5);
  EXPECT_THAT(all(r.warnings), HasSubstr("within 5 bounces"));
}

TEST(BakeBadScenes, AnInvalidSceneOrBadSettingsAreErrors) {
  scenes::Scene s = quad_scene();
  std::get<std::vector<uint32_t>>(s.meshes[0].indices)[0] = 99;
  EXPECT_THAT(error_of(s, quick_bake(4)), HasSubstr("test:bad"));
  s = quad_scene();
  BakeSettings settings = quick_bake(4);
  settings.stop_fraction = 0;
  EXPECT_THAT(error_of(s, settings), HasSubstr("stopping fraction"));
  settings = quick_bake(4);
  settings.samples = 0;
  EXPECT_THAT(error_of(s, settings), HasSubstr("samples"));
}

TEST(BakeBadScenes, ASceneWithoutLightmappedMeshesBakesOnlyCubes) {
  scenes::Scene s = quad_scene();
  s.materials[0].family = scenes::ShaderFamily::vertexlit_generic;
  scenes::IrradianceVolume v;
  v.min = glm::vec3(0, 0, 10), v.max = glm::vec3(0, 0, 10), v.counts = {1, 1, 1};
  s.irradiance_volume = v;
  const BakeResult r = bake(s, quick_bake(4));
  EXPECT_EQ(r.lightmaps.width, 0);
  ASSERT_TRUE(r.cubes);
  EXPECT_EQ(r.cubes->volume.cubes.size(), 1u);
}

}  // namespace
}  // namespace luxel::bake::test
