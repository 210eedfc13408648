// irradiance_at, the light arriving at a surface point for a shading normal (bake.hpp), against
// answers known in closed form: a uniform sky over a lone floor gives the tilted-plane factor
// (1 + cos b) / 2 for a normal tilted by b; a distant light gives its color x the cosine to the
// shading normal, and nothing when it is below the geometric surface whatever the shading normal
// says. Then against the bake itself: at luxel centers, with the luxel's normal it is the flat
// map, with a basis direction the basis map (within the Monte Carlo noise of both).

#include "bake_support.hpp"

#include "luxel/bake/rnm_basis.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace luxel::bake::test {
namespace {

BakeSettings with_samples(int samples) {
  BakeSettings b;
  b.samples = samples;
  b.threads = 2;
  return b;
}

/// A 64-inch floor quad at z = 0 facing +Z (16 x 16 luxels in cell (0, 0) of a 2 x 1 atlas), and
/// when `wall`, a 64-inch wall standing on its far edge (y = 32) facing it, in cell (1, 0).
scenes::Scene floor_scene(glm::vec3 albedo, bool wall) {
  scenes::Scene s;
  s.name = "test:floor";
  s.materials = {lightmapped(albedo)};
  s.lightmap_luxel_size = 4;
  scenes::Mesh m = empty_mesh("floor", 0);
  add_quad(m, {-32, -32, 0}, {64, 0, 0}, {0, 64, 0}, 0, 0, 2, 16);
  if (wall) add_quad(m, {-32, 32, 0}, {64, 0, 0}, {0, 0, 64}, 1, 0, 2, 16);
  s.meshes = {m};
  return s;
}

/// The world point at the center of the floor's luxel (x, y) (1..16: the chart inside its pad).
glm::vec3 floor_luxel_center(int x, int y) { return {-32.0f + 4.0f * float(x - 1) + 2.0f, 32.0f - 4.0f * float(y - 1) - 2.0f, 0.0f}; }

/// A unit normal tilted by `tilt` from +Z toward azimuth `azimuth` (radians).
glm::vec3 tilted(float tilt, float azimuth) {
  return {std::sin(tilt) * std::cos(azimuth), std::sin(tilt) * std::sin(azimuth), std::cos(tilt)};
}

scenes::Scene baked(const scenes::Scene& s, const BakeSettings& settings) {
  scenes::Scene out = s;
  attach(out, bake(s, settings));
  return out;
}

TEST(BakeIrradianceAt, AUniformSkyGivesTheTiltedPlaneFactorForAnyNormal) {
  // Nothing above the floor: every ray sees the sky, 0.75 (exact in half). The self-normalized
  // estimate is then exact: 0.75 (1 + cos tilt) / 2.
  scenes::Scene s = floor_scene(glm::vec3(0.5f), false);
  s.background = glm::vec3(0.75f);
  const BakeSettings settings = with_samples(64);
  const scenes::Scene b = baked(s, settings);
  const float tilts[] = {0.0f, 0.3f, 1.0f, 1.5707963f, 2.2f};
  std::vector<SurfacePoint> points;
  for (int i = 0; i < 5; ++i) points.push_back({{float(3 * i), -5.0f, 0.0f}, {0, 0, 1}, tilted(tilts[i], 0.7f * float(i))});
  const std::vector<glm::vec3> e = irradiance_at(b, settings, points);
  ASSERT_EQ(e.size(), points.size());
  for (size_t i = 0; i < e.size(); ++i)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(e[i][c], 0.75f * 0.5f * (1.0f + std::cos(tilts[i])), 1e-5f) << "tilt " << tilts[i];
}

TEST(BakeIrradianceAt, ADistantLightByItsCosineToTheShadingNormalWhenAboveTheSurface) {
  scenes::Scene s = floor_scene(glm::vec3(0.5f), false);
  struct Case {
    glm::vec3 to_light, normal;
  };
  const glm::vec3 above = glm::normalize(glm::vec3(1.0f, 0.5f, 1.0f));
  const Case cases[] = {
      {above, glm::vec3(0, 0, 1)},
      {above, glm::normalize(glm::vec3(0.3f, -0.2f, 1.0f))},
      {above, glm::normalize(glm::vec3(-1.0f, -0.5f, 0.4f))},  // the bump faces away: nothing
      // Just below the floor's plane: the shading normal faces the light, the surface shadows it.
      {glm::normalize(glm::vec3(1.0f, 0.0f, -0.1f)), glm::normalize(glm::vec3(1.0f, 0.0f, 0.3f))},
  };
  for (const Case& c : cases) {
    scenes::Light sun;
    sun.type = scenes::LightType::directional;
    sun.direction = -c.to_light;
    sun.color = glm::vec3(2.0f, 1.0f, 0.5f);
    s.lights = {sun};
    const BakeSettings settings = with_samples(16);
    const std::vector<SurfacePoint> points = {{{5.0f, 7.0f, 0.0f}, {0, 0, 1}, c.normal}};
    const glm::vec3 e = irradiance_at(baked(s, settings), settings, points).at(0);
    const float cosine = c.to_light.z > 0 ? std::max(0.0f, glm::dot(c.normal, c.to_light)) : 0.0f;
    for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(e[ch], sun.color[ch] * cosine, 1e-5f) << c.normal.x << " " << c.normal.z;
  }
}

/// At luxel centers of a floor beside a wall under a point light and `sky`: irradiance_at for the
/// luxel's normal against the flat map, and for each basis direction against its basis map.
/// Direct light is exact in both, sky and the bounce between floor and wall Monte Carlo in both
/// (1024 rays a luxel, 4096 a point).
void compare_with_the_maps(glm::vec3 sky, bool basis_maps) {
  scenes::Scene s = floor_scene(glm::vec3(0.6f), true);
  s.background = sky;
  scenes::Light l;
  l.type = scenes::LightType::point;
  l.position = {-10, 5, 40};
  l.color = glm::vec3(3000.0f, 2500.0f, 2000.0f);
  s.lights = {l};
  BakeSettings settings = with_samples(1024);
  settings.supersample = 1;  // each luxel's direct light at its center
  const BakeResult r = bake(s, settings);
  scenes::Scene b = s;
  attach(b, r);

  const int luxels[][2] = {{2, 3}, {8, 8}, {15, 2}, {5, 14}};
  const auto& basis = rnm_basis();
  std::vector<SurfacePoint> points;
  for (const auto& xy : luxels) {
    const glm::vec3 p = floor_luxel_center(xy[0], xy[1]);
    points.push_back({p, {0, 0, 1}, {0, 0, 1}});
    for (const glm::vec3& v : basis) points.push_back({p, {0, 0, 1}, v});  // tangent +X: world = tangent space
  }
  settings.samples = 4096;
  const std::vector<glm::vec3> e = irradiance_at(b, settings, points);
  const int side = r.lightmaps.width;
  for (size_t i = 0; i < std::size(luxels); ++i) {
    const size_t texel = size_t(luxels[i][1]) * size_t(side) + size_t(luxels[i][0]);
    ASSERT_EQ(r.lightmaps.coverage[texel], LuxelCoverage::covered);
    for (int k = 0; k < (basis_maps ? 4 : 1); ++k) {
      const glm::vec3 map = r.lightmaps.maps[size_t(k)][texel];
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(e[4 * i + size_t(k)][c], map[c], 0.02f * map[c] + 1e-3f) << "luxel " << i << ", map " << k << ", channel " << c;
    }
  }

  // Any thread count, the same bytes; an unbaked scene is refused.
  settings.threads = 1;
  EXPECT_EQ(irradiance_at(b, settings, points), e);
  EXPECT_THROW(irradiance_at(s, settings, points), BakeError);
}

TEST(BakeIrradianceAt, AtLuxelCentersItIsTheFlatMapForTheLuxelsNormal) { compare_with_the_maps({0.1f, 0.15f, 0.3f}, false); }

// The basis maps hold the sky by vrad's rule, not the clipped integral (lightmaps.hpp): without a
// sky they hold what irradiance_at gives for the basis directions.
TEST(BakeIrradianceAt, WithoutASkyItIsTheBasisMapsForTheBasisDirections) { compare_with_the_maps(glm::vec3(0.0f), true); }

}  // namespace
}  // namespace luxel::bake::test
