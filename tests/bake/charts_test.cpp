// Charts for meshes without uv1: a welded cube (8 shared vertices) becomes six charts that do not
// overlap, every luxel of each face is written, bilinear reads stay inside written luxels, and a
// tessellated plane is one chart.

#include "bake_support.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace luxel::bake::test {
namespace {

/// A welded cube of side 64 around the origin, faces outward, no uv1, lit by a sky.
scenes::Scene welded_cube() {
  scenes::Scene s;
  s.name = "test:welded";
  s.materials = {lightmapped(glm::vec3(0.5f))};
  s.lightmap_luxel_size = 8;
  s.background = glm::vec3(1.0f);
  scenes::Mesh m = empty_mesh("cube", 0);
  for (int i = 0; i < 8; ++i) m.positions.push_back(glm::vec3(i & 1 ? 32 : -32, i & 2 ? 32 : -32, i & 4 ? 32 : -32));
  const uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  auto& idx = std::get<std::vector<uint32_t>>(m.indices);
  for (const auto& q : quads)
    for (uint32_t k : {0, 1, 2, 0, 2, 3}) idx.push_back(q[k]);
  s.meshes = {m};
  return s;
}

TEST(BakeCharts, AWeldedCubeGetsSixChartsThatDoNotOverlap) {
  const scenes::Scene s = welded_cube();
  const GeneratedCharts g = plan_charts(s, BakeSettings{});
  EXPECT_EQ(g.charts, 6u);
  ASSERT_TRUE(g.meshes[0]);
  EXPECT_EQ(g.meshes[0]->positions.size(), 36u);  // unwelded
  EXPECT_EQ(g.meshes[0]->uv1.size(), 36u);
  EXPECT_EQ(g.atlas_size % 4, 0);
  // 8 x 8 luxels a face plus padding: (10 x 10) x 6 fits in 28 x 28 (shelves of 2 or 3).
  EXPECT_LE(g.atlas_size, 32);

  BakeSettings settings;
  settings.samples = 16;
  const BakeResult r = bake(s, settings);
  for (const auto& w : r.warnings) EXPECT_THAT(w, ::testing::Not(::testing::HasSubstr("overlapping"))) << w;
  EXPECT_EQ(covered(r.lightmaps).size(), 6u * 64u);  // every face: 8 x 8 luxels, each written
  // Every face sees some sky, so every luxel is lit.
  for (size_t i : covered(r.lightmaps)) EXPECT_GT(r.lightmaps.maps[0][i].r, 0.0f);

  // attach() puts the charted mesh in the scene; it stays valid.
  scenes::Scene attached = s;
  attach(attached, r);
  EXPECT_EQ(attached.meshes[0].uv1.size(), 36u);
  EXPECT_NO_THROW(scenes::validate(attached));
}

TEST(BakeCharts, ATessellatedPlaneIsOneChartAndMeshesWithUv1AreLeftAloneWhenAllHaveIt) {
  scenes::Scene s;
  s.name = "test:plane";
  s.materials = {lightmapped(glm::vec3(0.5f))};
  s.lightmap_luxel_size = 4;
  scenes::Mesh m = empty_mesh("plane", 0);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) add_quad(m, {x * 16.0f, y * 16.0f, 0}, {16, 0, 0}, {0, 16, 0}, x, y, 4, 4);
  s.meshes = {m};
  EXPECT_EQ(plan_charts(s, BakeSettings{}).atlas_size, 0);  // uv1 present: no charts
  s.meshes[0].uv1.clear();
  const GeneratedCharts g = plan_charts(s, BakeSettings{});
  EXPECT_EQ(g.charts, 1u);
  EXPECT_EQ(g.atlas_size, 20);  // 16 luxels + 2 padding, rounded up to a multiple of 4
}

TEST(BakeCharts, AChartBeyondTheAtlasLimitIsAnError) {
  scenes::Scene s = welded_cube();
  s.lightmap_luxel_size = 1e-3f;
  try {
    bake(s, BakeSettings{});
    FAIL() << "no error";
  } catch (const BakeError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("test:welded: mesh 0 'cube' has a chart"));
  }
}

}  // namespace
}  // namespace luxel::bake::test
