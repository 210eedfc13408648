// RNM lightmaps against answers known in closed form: a white furnace (uniform sky over a lone
// quad), one distant light from each RNM basis direction and between them, a point light's and a
// spot light's falloff with a blocker's hard shadow, the radiosity of a closed box (the geometric
// series of bounces), and borders that bilinear filtering may read.

#include "bake_support.hpp"

#include "luxel/bake/rnm_basis.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace luxel::bake::test {
namespace {

/// One 64 x 64 inch quad at z = 0 facing +Z, tangent +X, 16 x 16 luxels in a one-cell atlas.
scenes::Scene lone_quad(glm::vec3 albedo, glm::vec4 tangent = {1, 0, 0, 1}) {
  scenes::Scene s;
  s.name = "test:quad";
  s.materials = {lightmapped(albedo)};
  s.lightmap_luxel_size = 4;
  scenes::Mesh m = empty_mesh("quad", 0);
  add_quad(m, {-32, -32, 0}, {64, 0, 0}, {0, 64, 0}, 0, 0, 1, 16);
  for (glm::vec4& t : m.tangents) t = tangent;
  s.meshes = {m};
  return s;
}

TEST(BakeLightmaps, WhiteFurnaceGivesTheSkyInTheFlatMapAndVradsSkyFactorInTheBasisMaps) {
  scenes::Scene s = lone_quad(glm::vec3(1.0f));
  const glm::vec3 sky(0.75f, 0.5f, 1.25f);
  s.background = sky;
  const BakeResult r = bake(s, quick_bake(1024));
  ASSERT_EQ(r.lightmaps.width, 18);
  const auto luxels = covered(r.lightmaps);
  ASSERT_EQ(luxels.size(), 256u);
  // vrad's sky in a basis map (lightmaps.hpp): the mean of the basis cosine over the lune both
  // hemispheres see (its integral pi (1 + cos b) / 2 over its area 2 (pi - b)) over the mean of the
  // normal's cosine over its hemisphere (1/2); cos b = 1/sqrt 3. Worked out here, not read from
  // the library: 1.1333, where the clipped integral would give 0.7887.
  const double b = std::acos(1.0 / std::sqrt(3.0));
  const double vrad_factor = (3.14159265358979 * (1.0 + std::cos(b)) / 2.0) / (2.0 * (3.14159265358979 - b)) / 0.5;
  for (size_t i : luxels) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(r.lightmaps.maps[0][i][c], sky[c], 1e-4 * sky[c]) << "flat, texel " << i;
      const float want = float(vrad_factor * sky[c]);
      // A ratio of counts over the lune's edge, per luxel: within 2.5 % at 1024 rays.
      for (int k = 1; k < 4; ++k) EXPECT_NEAR(r.lightmaps.maps[size_t(k)][i][c], want, 0.025 * want) << "basis " << k - 1;
    }
  }
  // A planar quad sees only the sky: one bounce that adds nothing ends the bake.
  EXPECT_EQ(r.stats.bounces, 1);
}

/// A sky cube in D3D face order whose texels hold max(0, z) of their own direction (the table of
/// rasterizer/texture.hpp "Cube maps", as the courtyard's sky is built): "how far up".
int add_upness_sky(scenes::Scene& s, int size) {
  scenes::Texture t;
  t.name = "test:upness";
  t.shape = scenes::TextureShape::cube;
  t.color_space = scenes::ColorSpace::linear;
  for (int f = 0; f < 6; ++f) {
    scenes::PixelImage img;
    img.width = img.height = size;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const float a = 2 * (x + 0.5f) / size - 1, b = 2 * (y + 0.5f) / size - 1;
        const glm::vec3 dirs[6] = {{1, -b, -a}, {-1, -b, a}, {a, 1, b}, {a, -1, -b}, {a, -b, 1}, {-a, -b, -1}};
        const float up = std::max(0.0f, glm::normalize(dirs[f]).z);
        img.rgba32f.insert(img.rgba32f.end(), {up, up, up, 1.0f});
      }
    t.faces.push_back(img);
  }
  s.textures.push_back(t);
  return int(s.textures.size()) - 1;
}

TEST(BakeLightmaps, TheSkyCubeIsReadInTheDirectionTheRayLeaves) {
  // Facing up, the flat map is (1/pi) integral of cos(theta) cos(theta) over the hemisphere = 2/3;
  // facing down it sees only texels of downward directions: 0. A face or an axis read the wrong
  // way round breaks one or the other.
  for (float facing : {1.0f, -1.0f}) {
    scenes::Scene s = lone_quad(glm::vec3(0.0f));
    s.sky_texture = add_upness_sky(s, 64);
    if (facing < 0)
      for (auto& p : s.meshes[0].positions) p.y = -p.y;  // mirror: the winding flips, the quad faces down
    for (auto& n : s.meshes[0].normals) n = {0, 0, facing};
    const BakeResult r = bake(s, quick_bake(1024));
    double mean = 0;
    const auto luxels = covered(r.lightmaps);
    for (size_t i : luxels) mean += r.lightmaps.maps[0][i].r;
    mean /= double(luxels.size());
    if (facing > 0) EXPECT_NEAR(mean, 2.0 / 3.0, 0.01);
    else EXPECT_EQ(mean, 0.0);
  }
}

struct DirectCase {
  glm::vec3 to_light;       // tangent space (also world: the quad's frame is the identity)
  glm::vec4 expected;       // flat, basis 0, 1, 2, per unit light color
};

TEST(BakeLightmaps, ADistantLightLandsInTheBasisMapsByItsCosinesToTheBasis) {
  const auto& b = rnm_basis();
  const float s3 = 1.0f / std::sqrt(3.0f), s2 = 1.0f / std::sqrt(2.0f);
  const glm::vec3 mid01 = glm::normalize(b[0] + b[1]);
  const glm::vec3 mid012 = glm::vec3(0, 0, 1);
  const DirectCase cases[] = {
      {b[0], {s3, 1, 0, 0}},
      {b[1], {s3, 0, 1, 0}},
      {b[2], {s3, 0, 0, 1}},
      {mid01, {mid01.z, s2, s2, 0}},                                    // between two: 1/sqrt 2 each
      {mid012, {1, s3, s3, s3}},                                        // the normal: all three equal
      {glm::normalize(glm::vec3(1, 0, 0.2f)), {0, 0, 0, 0}},            // filled below: see the fix-up
      {glm::normalize(glm::vec3(0.3f, 0.2f, -0.5f)), {0, 0, 0, 0}},     // from below the surface: nothing
  };
  for (DirectCase c : cases) {
    if (c.expected == glm::vec4(0) && c.to_light.z > 0) {
      c.expected = {c.to_light.z, std::max(0.0f, glm::dot(b[0], c.to_light)), std::max(0.0f, glm::dot(b[1], c.to_light)),
                    std::max(0.0f, glm::dot(b[2], c.to_light))};
    }
    scenes::Scene s = lone_quad(glm::vec3(0.0f));
    scenes::Light sun;
    sun.type = scenes::LightType::directional;
    sun.direction = -c.to_light;
    sun.color = glm::vec3(2.0f, 1.0f, 0.5f);
    s.lights = {sun};
    const BakeResult r = bake(s, quick_bake(16));
    for (size_t i : covered(r.lightmaps))
      for (int k = 0; k < 4; ++k)
        for (int ch = 0; ch < 3; ++ch) {
          const float want = c.expected[k] * sun.color[ch];
          EXPECT_NEAR(r.lightmaps.maps[size_t(k)][i][ch], want, 2e-3f * std::max(want, 1e-3f) + 1e-6f)
              << "light toward (" << c.to_light.x << ", " << c.to_light.y << ", " << c.to_light.z << "), map " << k;
        }
  }
}

// A point light with constant, linear and quadratic terms and a spot light across its cone over a
// black floor (no bounce), a black blocker between the point light and part of the floor: at
// each luxel centre the flat map is, from vrad's rules worked out here (docs/fidelity.md#bake-vrad),
// the sum over the lights the luxel sees of color x 1 / (a0 + a1 d + a2 d^2) x cos to the normal,
// the spot's also x sat((cos a - cos outer) / (cos inner - cos outer))^exponent x cos a inside its
// outer cone; a luxel in the blocker's umbra gets none of the point light.
TEST(BakeLightmaps, PointAndSpotLightsFallOffAndABlockerCastsAHardShadow) {
  scenes::Scene s;
  s.name = "test:lit floor";
  s.materials = {lightmapped(glm::vec3(0.0f))};
  s.lightmap_luxel_size = 4;
  scenes::Mesh m = empty_mesh("floor and blocker", 0);
  add_quad(m, {-32, -32, 0}, {64, 0, 0}, {0, 64, 0}, 0, 0, 2, 16);    // the floor, cell (0, 0)
  add_quad(m, {-24, -4, 20}, {0, 12, 0}, {13.5f, 0, 0}, 1, 0, 2, 16);  // facing down, cell (1, 0)
  s.meshes = {m};
  scenes::Light point, spot;
  point.position = {-10, 5, 40};
  point.color = {300, 200, 100};
  point.constant = 0.5f, point.linear = 0.02f, point.quadratic = 0.05f;
  spot.type = scenes::LightType::spot;
  spot.position = {20, -15, 30};
  spot.direction = glm::normalize(glm::vec3(-0.3f, 0.2f, -1.0f));
  spot.color = {4000, 5000, 6000};
  spot.inner_cone = 0.2f, spot.outer_cone = 0.45f, spot.spot_exponent = 1.5f;
  s.lights = {point, spot};
  BakeSettings settings = quick_bake(16);
  settings.supersample = 1;  // each luxel's direct light at its centre
  const BakeResult r = bake(s, settings);

  auto falloff = [](const scenes::Light& l, double d) {
    d = std::max(d, 1.0);
    return 1.0 / (double(l.constant) + double(l.linear) * d + double(l.quadratic) * d * d);
  };
  // Whether the segment from p to the light crosses the blocker (z = 20, x in [-24, -10.5], y in [-4, 8]):
  // no luxel's ray passes within half an inch of its edges.
  auto blocked = [](const glm::dvec3& p, const glm::dvec3& light) {
    const double t = (20.0 - p.z) / (light.z - p.z);
    if (t <= 0.0 || t >= 1.0) return false;
    const glm::dvec3 q = p + t * (light - p);
    return q.x > -24.0 && q.x < -10.5 && q.y > -4.0 && q.y < 8.0;
  };
  int shadowed = 0, in_cone = 0, checked = 0;
  const int side = r.lightmaps.width;
  for (int y = 1; y <= 16; ++y)
    for (int x = 1; x <= 16; ++x) {
      const glm::dvec3 p(-32.0 + 4.0 * (x - 1) + 2.0, 32.0 - 4.0 * (y - 1) - 2.0, 0.0);
      glm::dvec3 want(0.0);
      bool edge = false;  // a luxel whose centre's ray grazes the blocker's edge, or the cone's
      for (const scenes::Light& l : s.lights) {
        const glm::dvec3 v = glm::dvec3(l.position) - p;
        const double d = glm::length(v);
        const glm::dvec3 to_light = v / d;
        double a = falloff(l, d) * std::max(0.0, to_light.z);
        if (l.type == scenes::LightType::spot) {
          const double cos_a = glm::dot(glm::dvec3(l.direction), -to_light);
          const double cos_inner = std::cos(double(l.inner_cone)), cos_outer = std::cos(double(l.outer_cone));
          edge = edge || std::abs(cos_a - cos_outer) < 1e-3;
          if (cos_a <= cos_outer) continue;
          ++in_cone;
          a *= std::pow(std::clamp((cos_a - cos_outer) / (cos_inner - cos_outer), 0.0, 1.0), double(l.spot_exponent)) * cos_a;
        } else if (blocked(p, glm::dvec3(l.position))) {
          ++shadowed;
          continue;
        }
        want += glm::dvec3(l.color) * a;
      }
      if (edge) continue;
      const size_t texel = size_t(y) * size_t(side) + size_t(x);
      ASSERT_EQ(r.lightmaps.coverage[texel], LuxelCoverage::covered);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(r.lightmaps.maps[0][texel][c], want[c], 1e-3 * want[c] + 1e-4) << "luxel (" << x << ", " << y << "), channel " << c;
      ++checked;
    }
  EXPECT_GT(shadowed, 10) << "the blocker's umbra covers some luxels";
  EXPECT_GT(in_cone, 10) << "the spot's cone covers some luxels";
  EXPECT_LT(in_cone, checked) << "and not all";
  std::printf("point and spot: %d luxels checked, %d in the umbra, %d in the cone\n", checked, shadowed, in_cone);
}

TEST(BakeLightmaps, TheBasisFollowsTheTangentFrame) {
  // Tangent +Y with handedness -1: bitangent = -cross(n, t) = +X. Basis 0 in world is then
  // sqrt(2/3) (0, 1, 0) + (0, 0, 1/sqrt 3).
  scenes::Scene s = lone_quad(glm::vec3(0.0f), {0, 1, 0, -1});
  const auto& b = rnm_basis();
  const glm::vec3 t(0, 1, 0), bt(1, 0, 0), n(0, 0, 1);
  for (int k = 0; k < 3; ++k) {
    const glm::vec3 world = b[size_t(k)].x * t + b[size_t(k)].y * bt + b[size_t(k)].z * n;
    scenes::Light sun;
    sun.type = scenes::LightType::directional;
    sun.direction = -world;
    sun.color = glm::vec3(1.0f);
    s.lights = {sun};
    const BakeResult r = bake(s, quick_bake(4));
    for (size_t i : covered(r.lightmaps))
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(r.lightmaps.maps[size_t(j) + 1][i].r, j == k ? 1.0f : 0.0f, 2e-3f) << k << " " << j;
  }
}

/// The mean flat luxel of a closed box, albedo rho, the floor emitting L_e: every luxel has the
/// same area, so by energy conservation (each bounce's irradiance integral is rho times the one
/// before, reciprocity) the mean is (A_floor / A) L_e sum_{k=0..K} rho^k, K = bounces done.
double box_error(int samples, double* mean_out = nullptr, int* bounces = nullptr) {
  const float rho = 0.5f;
  const scenes::Scene s = closed_box(64, 16, lightmapped(glm::vec3(rho)), lightmapped(glm::vec3(rho), glm::vec3(1.0f)));
  BakeSettings settings = quick_bake(samples);
  settings.stop_fraction = 0.001f;
  const BakeResult r = bake(s, settings);
  const auto luxels = covered(r.lightmaps);
  EXPECT_EQ(luxels.size(), 6u * 256u);
  double mean = 0;
  for (size_t i : luxels) mean += r.lightmaps.maps[0][i].g;
  mean /= double(luxels.size());
  double series = 0;
  for (int k = 0; k <= r.stats.bounces; ++k) series += std::pow(double(rho), k);
  const double want = series / 6.0;
  if (mean_out) *mean_out = mean;
  if (bounces) *bounces = r.stats.bounces;
  return std::abs(mean - want) / want;
}

TEST(BakeLightmaps, AClosedBoxMatchesTheGeometricSeriesOfBouncesWithinAToleranceThatShrinksWithSamples) {
  double mean16 = 0, mean256 = 0;
  int bounces = 0;
  const double e16 = box_error(16, &mean16, &bounces);
  const double e256 = box_error(256, &mean256);
  // rho = 0.5 and a 0.1 % stopping rule: 10 bounces (0.5^10 < 0.001 of the sum).
  EXPECT_GE(bounces, 9);
  EXPECT_LE(bounces, 11);
  // The relative error of the mean over 1536 luxels stays under 0.05 / sqrt(samples) (seen:
  // 0.0077 at 16 rays, 0.00079 at 256: the self-normalized estimator's bias falls as 1/samples).
  EXPECT_LT(e16, 0.05 / std::sqrt(16.0)) << mean16;
  EXPECT_LT(e256, 0.05 / std::sqrt(256.0)) << mean256;
}

TEST(BakeLightmaps, BilinearFilteringInsideAChartReadsOnlyWrittenLuxels) {
  const scenes::Scene s = closed_box(64, 16, lightmapped(glm::vec3(0.5f)), lightmapped(glm::vec3(0.5f), glm::vec3(1.0f)));
  const BakeResult r = bake(s, quick_bake(4));
  const LightmapAtlas& a = r.lightmaps;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u01(0.0f, 1.0f);
  for (const scenes::Mesh& m : s.meshes)
    for (size_t t = 0; t < m.triangle_count(); ++t) {
      const glm::vec2 p0 = m.uv1[m.vertex_of_corner(3 * t)], p1 = m.uv1[m.vertex_of_corner(3 * t + 1)],
                      p2 = m.uv1[m.vertex_of_corner(3 * t + 2)];
      for (int k = 0; k < 2000; ++k) {
        float b1 = u01(rng), b2 = u01(rng);
        if (b1 + b2 > 1) b1 = 1 - b1, b2 = 1 - b2;
        const glm::vec2 uv = p0 + b1 * (p1 - p0) + b2 * (p2 - p0);
        // Bilinear taps: the texels around uv * size - 0.5.
        const float x = uv.x * a.width - 0.5f, y = uv.y * a.height - 0.5f;
        const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
        for (int dy = 0; dy <= 1; ++dy)
          for (int dx = 0; dx <= 1; ++dx) {
            const int xx = std::clamp(x0 + dx, 0, a.width - 1), yy = std::clamp(y0 + dy, 0, a.height - 1);
            ASSERT_NE(a.coverage[size_t(yy) * size_t(a.width) + size_t(xx)], LuxelCoverage::empty)
                << "uv (" << uv.x << ", " << uv.y << ") reads texel (" << xx << ", " << yy << ")";
            ASSERT_GT(a.maps[0][size_t(yy) * size_t(a.width) + size_t(xx)].r, 0.0f);
          }
      }
    }
}

}  // namespace
}  // namespace luxel::bake::test
