// vbsp's env-map assignment for world surfaces (luxel/frame/world_envmaps.hpp,
// docs/fidelity.md#world-env-maps-vbsp): the nearest sample in front of a face group's plane from
// the mean of its vertices, else the nearest overall, ties to the lower index; no samples, no env
// map. Each case is built so that the rule it checks picks another sample than the rules it
// replaces (the nearest overall, the bounding-box centre, a strict plane test, the sky).

#include "frame/frame_support.hpp"

#include "luxel/frame/renderer.hpp"
#include "luxel/frame/world_envmaps.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace luxel::frame {
namespace {

std::vector<scenes::CubemapSample> samples_at(std::initializer_list<glm::vec3> positions) {
  std::vector<scenes::CubemapSample> s;
  for (const glm::vec3& p : positions) s.push_back(scenes::CubemapSample{p, 16, -1});
  return s;
}

TEST(WorldEnvmaps, TheNearestSampleInFrontOfThePlaneWinsOverANearerOneBehind) {
  const auto samples = samples_at({{0, 0, -1}, {0, 0, 5}});  // 1 behind, 5 in front
  EXPECT_EQ(envmap_sample_for(glm::vec3(0.0f), glm::vec3(0, 0, 1), samples), 1);
  EXPECT_EQ(envmap_sample_for(glm::vec3(0.0f), glm::vec3(0, 0, -1), samples), 0);
}

TEST(WorldEnvmaps, NoSampleInFrontTakesTheNearestOverall) {
  const auto samples = samples_at({{0, 0, -5}, {0, 0, -2}, {0, 3, -4}});
  EXPECT_EQ(envmap_sample_for(glm::vec3(0.0f), glm::vec3(0, 0, 1), samples), 1);
}

TEST(WorldEnvmaps, ASampleInThePlaneIsInFrontAndTiesGoToTheLowerIndex) {
  // dot(normalize(sample - centre), normal) >= 0: the sample in the plane (dot 0) counts.
  EXPECT_EQ(envmap_sample_for(glm::vec3(0.0f), glm::vec3(0, 0, 1), samples_at({{0, 0, 4}, {1, 0, 0}})), 1);
  // A sample at the centre itself: the zero vector, in front.
  EXPECT_EQ(envmap_sample_for(glm::vec3(2.0f), glm::vec3(0, 0, 1), samples_at({{2, 2, 3}, {2, 2, 2}})), 1);
  // Equal distances: the lower index, whichever order the positions come in.
  EXPECT_EQ(envmap_sample_for(glm::vec3(0.0f), glm::vec3(0, 0, 1), samples_at({{3, 0, 4}, {0, 3, 4}, {0, 0, 9}})), 0);
  EXPECT_EQ(envmap_sample_for(glm::vec3(0.0f), glm::vec3(0, 0, 1), samples_at({{0, 0, 9}, {0, 3, 4}, {3, 0, 4}})), 1);
  EXPECT_EQ(envmap_sample_for(glm::vec3(0.0f), glm::vec3(0, 0, 1), {}), -1);
}

/// A floor at z = 0 facing up whose vertices crowd at x in [0, 1] with one reaching x = 10 (vertex
/// mean x 2.4, bounding-box centre x 5), and a wall at x = -1 facing -x behind every sample.
scenes::Mesh floor_and_wall() {
  scenes::Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {10, 0, 0},  // floor
                 {-1, 0, 0}, {-1, 0, 2}, {-1, 2, 0}};                     // wall
  m.indices = std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 1, 4, 2, 5, 6, 7};
  return m;
}

TEST(WorldEnvmaps, FaceGroupsTakeTheirPlanesVertexMeanAndTheFallback) {
  // Sample 0 is 3 above the floor's vertex mean (2.4, 0.4), sample 1 2.9 above its bounding-box
  // centre (5, 0.5): from the vertex mean 0 is nearer (the box centre would pick 1). Sample 2,
  // below the floor, is nearer still (2.98): the plane test leaves it out (the nearest overall
  // would pick it).
  const auto samples = samples_at({{2.4f, 0.4f, 3.0f}, {5.0f, 0.5f, 2.9f}, {-0.5f, 0.7f, -0.6f}});
  const std::vector<EnvmapFaceGroup> groups = envmap_face_groups(floor_and_wall(), samples);
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0].sample, 0);
  EXPECT_EQ(groups[0].indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 1, 4, 2}));
  // The wall (normal -x, vertex mean (-1, 0.67, 0.67)): every sample is behind it, so the nearest
  // overall, sample 2.
  EXPECT_EQ(groups[1].sample, 2);
  EXPECT_EQ(groups[1].indices, (std::vector<uint32_t>{5, 6, 7}));
  EXPECT_TRUE(envmap_face_groups(floor_and_wall(), {}).empty()) << "no samples: no env map";
}

TEST(WorldEnvmaps, EveryTriangleLandsInExactlyOneGroup) {
  scenes::Mesh m = floor_and_wall();
  m.positions.push_back({3, 3, 3});
  std::get<std::vector<uint32_t>>(m.indices).insert(std::get<std::vector<uint32_t>>(m.indices).end(), {8, 8, 8});  // degenerate
  const auto groups = envmap_face_groups(m, samples_at({{0, 0, 5}, {3, 3, 4}, {-3, 0, 0}}));
  std::vector<uint32_t> all;
  for (const EnvmapFaceGroup& g : groups) {
    EXPECT_EQ(g.indices.size() % 3, 0u);
    all.insert(all.end(), g.indices.begin(), g.indices.end());
  }
  EXPECT_EQ(all.size(), std::get<std::vector<uint32_t>>(m.indices).size());
  // The degenerate triangle goes with the sample nearest it (1).
  const auto with_it = std::find_if(groups.begin(), groups.end(), [](const EnvmapFaceGroup& g) {
    return std::find(g.indices.begin(), g.indices.end(), 8u) != g.indices.end();
  });
  ASSERT_NE(with_it, groups.end());
  EXPECT_EQ(with_it->sample, 1);
}

TEST(WorldEnvmaps, WorldWithoutSamplesDrawsNoEnvMap) {
  // The engine drops a LightmappedGeneric `env_cubemap` that vbsp could not assign: with the
  // samples removed, the courtyard's paving and bricks draw as if they had no env map.
  scenes::Scene without_samples = *builtin_scene("courtyard", 160, 90);
  without_samples.cubemap_samples.clear();
  scenes::Scene without_envmaps = without_samples;
  int world_envmaps = 0;
  for (scenes::Material& m : without_envmaps.materials)
    if (m.family == scenes::ShaderFamily::lightmapped_generic && m.envmap != scenes::EnvmapSource::none) {
      m.envmap = scenes::EnvmapSource::none;
      ++world_envmaps;
    }
  ASSERT_GE(world_envmaps, 2);
  FrameSettings f{160, 90, 4};
  f.color_correction = false;
  EXPECT_TRUE(render_frame(without_samples, f).rgba == render_frame(without_envmaps, f).rgba);
}

}  // namespace
}  // namespace luxel::frame
