// The same bake twice, and with 1 and 2 threads: identical bytes.

#include "bake_support.hpp"

#include <gtest/gtest.h>

#include <cstring>

namespace luxel::bake::test {
namespace {

/// A closed box lit by a point light, with a diffuse block (a model) casting shadows and
/// reflecting its direct light, and a volume: every path of the bake runs.
scenes::Scene busy_scene() {
  scenes::Scene s = closed_box(128, 16, lightmapped(glm::vec3(0.6f)), lightmapped(glm::vec3(0.4f, 0.5f, 0.6f)));
  scenes::Material model;
  model.family = scenes::ShaderFamily::vertexlit_generic;
  model.color = glm::vec4(0.8f, 0.2f, 0.2f, 1.0f);
  s.materials.push_back(model);
  scenes::Mesh block = empty_mesh("block", 2);
  // A 32-inch cube on the floor (faces outward), uv1 left empty: it is a model.
  const float z0 = -64, z1 = -32;
  add_quad(block, {-16, -16, z1}, {32, 0, 0}, {0, 32, 0}, 0, 0, 1, 4);
  add_quad(block, {-16, -16, z0}, {32, 0, 0}, {0, 0, 32}, 0, 0, 1, 4);
  add_quad(block, {16, -16, z0}, {0, 32, 0}, {0, 0, 32}, 0, 0, 1, 4);
  add_quad(block, {16, 16, z0}, {-32, 0, 0}, {0, 0, 32}, 0, 0, 1, 4);
  add_quad(block, {-16, 16, z0}, {0, -32, 0}, {0, 0, 32}, 0, 0, 1, 4);
  block.uv1.clear();
  s.meshes.push_back(block);
  s.models.push_back({"block", {2}, {0, 0, -48}, {}});
  scenes::Light l;
  l.type = scenes::LightType::point;
  l.position = {20, 30, 40};
  l.color = glm::vec3(3000.0f);
  s.lights = {l};
  scenes::IrradianceVolume v;
  v.min = glm::vec3(-48), v.max = glm::vec3(48), v.counts = {3, 3, 3}, v.spacing = glm::vec3(48);
  s.irradiance_volume = v;
  return s;
}

void expect_same_bytes(const BakeResult& a, const BakeResult& b) {
  ASSERT_EQ(a.lightmaps.width, b.lightmaps.width);
  for (int k = 0; k < 4; ++k) {
    ASSERT_EQ(a.lightmaps.maps[size_t(k)].size(), b.lightmaps.maps[size_t(k)].size());
    EXPECT_EQ(0, std::memcmp(a.lightmaps.maps[size_t(k)].data(), b.lightmaps.maps[size_t(k)].data(),
                             a.lightmaps.maps[size_t(k)].size() * sizeof(glm::vec3)))
        << "map " << k;
  }
  ASSERT_TRUE(a.cubes && b.cubes);
  ASSERT_EQ(a.cubes->volume.cubes.size(), b.cubes->volume.cubes.size());
  EXPECT_EQ(0, std::memcmp(a.cubes->volume.cubes.data(), b.cubes->volume.cubes.data(),
                           a.cubes->volume.cubes.size() * sizeof(scenes::AmbientCube)));
  EXPECT_EQ(a.stats.bounces, b.stats.bounces);
  EXPECT_EQ(a.stats.rays, b.stats.rays);
}

TEST(BakeDeterminism, TheSameBakeTwiceAndWithOneOrTwoThreadsGivesTheSameBytes) {
  const scenes::Scene s = busy_scene();
  BakeSettings settings;
  settings.samples = 16;
  settings.cube_samples = 16;
  settings.threads = 1;
  const BakeResult one = bake(s, settings);
  settings.threads = 2;
  const BakeResult two = bake(s, settings);
  const BakeResult again = bake(s, settings);
  settings.threads = 3;  // more threads than chunks of some phases
  const BakeResult three = bake(s, settings);
  EXPECT_GT(one.stats.supersampled, 0u);  // the block's shadow edge
  EXPECT_GT(one.stats.bounces, 1);
  expect_same_bytes(one, two);
  expect_same_bytes(two, again);
  expect_same_bytes(one, three);
}

TEST(BakeDeterminism, TheSeedChangesTheNoiseOnly) {
  const scenes::Scene s = busy_scene();
  BakeSettings settings;
  settings.samples = 16;
  settings.cube_samples = 16;
  const BakeResult a = bake(s, settings);
  settings.seed = 1;
  const BakeResult b = bake(s, settings);
  EXPECT_NE(0, std::memcmp(a.lightmaps.maps[0].data(), b.lightmaps.maps[0].data(), a.lightmaps.maps[0].size() * sizeof(glm::vec3)));
}

}  // namespace
}  // namespace luxel::bake::test
