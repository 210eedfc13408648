// The built-in scenes: each validates, is deterministic, and `courtyard` holds what its comparison
// of shader models needs, checked from its data with math of the test's own.

#include "luxel/scenes/builtin.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>
#include <string>

namespace luxel::scenes {
namespace {

// Small enough for fast tests; tris is a million triangles whatever its size.
constexpr BuiltinOptions kSmall{160, 90};

TEST(BuiltinScenes, NamesAreTheFour) {
  EXPECT_EQ(builtin_scene_names(), (std::vector<std::string>{"courtyard", "demo", "fill", "tris"}));
}

TEST(BuiltinScenes, EachValidatesAndHasACamera) {
  for (const std::string& name : builtin_scene_names()) {
    const Scene s = make_builtin_scene(name, kSmall);
    EXPECT_EQ(s.name, "builtin:" + name);
    EXPECT_NO_THROW(validate(s)) << name;
    EXPECT_FALSE(s.cameras.empty()) << name;
    EXPECT_FALSE(s.meshes.empty()) << name;
    EXPECT_FALSE(bounds_of(s).empty) << name;
  }
}

TEST(BuiltinScenes, UnknownNamesAndBadSizesThrow) {
  try {
    make_builtin_scene("nope");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "unknown built-in scene 'nope' (known: courtyard, demo, fill, tris)");
  }
  EXPECT_THROW(make_builtin_scene("builtin:demo"), std::invalid_argument);  // the prefix is the caller's
  EXPECT_THROW(make_builtin_scene("tris", {0, 10}), std::invalid_argument);
  EXPECT_THROW(make_builtin_scene("tris", {10, 100000}), std::invalid_argument);
}

template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

bool same_arrays(const Scene& a, const Scene& b) {
  if (a.textures.size() != b.textures.size() || a.meshes.size() != b.meshes.size()) return false;
  for (size_t i = 0; i < a.textures.size(); ++i) {
    if (a.textures[i].faces.size() != b.textures[i].faces.size()) return false;
    for (size_t f = 0; f < a.textures[i].faces.size(); ++f)
      if (!same_bytes(a.textures[i].faces[f].rgba8, b.textures[i].faces[f].rgba8) ||
          !same_bytes(a.textures[i].faces[f].rgba32f, b.textures[i].faces[f].rgba32f))
        return false;
  }
  for (size_t i = 0; i < a.meshes.size(); ++i) {
    const Mesh &x = a.meshes[i], &y = b.meshes[i];
    if (!same_bytes(x.positions, y.positions) || !same_bytes(x.normals, y.normals) ||
        !same_bytes(x.tangents, y.tangents) || !same_bytes(x.uv0, y.uv0) || !same_bytes(x.uv1, y.uv1) ||
        !same_bytes(x.colors, y.colors) || x.indices.index() != y.indices.index() ||
        !std::visit([&](const auto& v) { return same_bytes(v, std::get<std::decay_t<decltype(v)>>(y.indices)); },
                    x.indices))
      return false;
  }
  return true;
}

TEST(BuiltinScenes, BuildingTwiceGivesTheSameBytes) {
  for (const std::string& name : builtin_scene_names())
    EXPECT_TRUE(same_arrays(make_builtin_scene(name, kSmall), make_builtin_scene(name, kSmall))) << name;
}

TEST(BuiltinScenes, TrisIsTheSizeItWasBuiltFor) {
  const Scene s = make_builtin_scene("tris", {320, 180});
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(s.meshes[0].triangle_count(), 1'000'000u);
  EXPECT_FALSE(s.meshes[0].indexed());
  const Bounds b = bounds_of(s);
  // Triangle centers are uniform over the image; their vertices reach at most R = 1.75 px out.
  EXPECT_GT(b.min.x, -2.0f);
  EXPECT_LT(b.max.x, 322.0f);
  EXPECT_GT(b.min.y, -2.0f);
  EXPECT_GT(b.max.y, 178.0f);
  EXPECT_GE(b.min.z, -1.0f);
  EXPECT_LE(b.max.z, 1.0f);
}

// --- courtyard ---

class Courtyard : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { scene_ = new Scene(make_builtin_scene("courtyard")); }
  static void TearDownTestSuite() { delete scene_; }
  static const Scene& s() { return *scene_; }
  static const Material& material_of(const Mesh& m) { return s().materials.at(m.material); }
  static inline Scene* scene_ = nullptr;
};

TEST_F(Courtyard, HasASunAndFourLocalLights) {
  int sun = 0, local = 0;
  for (const Light& l : s().lights) {
    if (l.type == LightType::directional) {
      ++sun;
      EXPECT_NEAR(glm::length(l.direction), 1.0f, 1e-5f);
      EXPECT_LT(l.direction.z, 0.0f) << "the sun shines down";
    } else {
      ++local;
      // Inside the walls, above the floor, and lit with Source's falloff.
      EXPECT_LT(std::abs(l.position.x), 512.0f) << l.name;
      EXPECT_LT(std::abs(l.position.y), 512.0f) << l.name;
      EXPECT_GT(l.position.z, 0.0f) << l.name;
      EXPECT_GT(l.quadratic, 0.0f) << l.name;
    }
  }
  EXPECT_GE(sun, 1);
  EXPECT_GE(local, 4);
  EXPECT_TRUE(std::any_of(s().lights.begin(), s().lights.end(), [](const Light& l) { return l.type == LightType::spot; }));
  EXPECT_TRUE(std::any_of(s().lights.begin(), s().lights.end(), [](const Light& l) { return l.type == LightType::point; }));
}

TEST_F(Courtyard, UsesEachFamilyItNeeds) {
  std::set<ShaderFamily> used;
  for (const Mesh& m : s().meshes) used.insert(material_of(m).family);
  for (ShaderFamily f : {ShaderFamily::lightmapped_generic, ShaderFamily::vertexlit_generic, ShaderFamily::unlit_generic,
                         ShaderFamily::water})
    EXPECT_TRUE(used.count(f)) << int(f);
}

TEST_F(Courtyard, WorldSurfacesAreBumpedLightmappedAndMasked) {
  int with_envmap = 0;
  bool normal_alpha_mask = false, texture_mask = false;
  for (const Material& m : s().materials) {
    if (m.family != ShaderFamily::lightmapped_generic || m.envmap == EnvmapSource::none) continue;
    ++with_envmap;
    EXPECT_TRUE(m.bump.bound()) << m.name;
    EXPECT_NE(m.envmap_mask, EnvmapMask::base_alpha) << m.name << ": with a bump map, a combo the SDK never compiles";
    if (m.envmap_mask == EnvmapMask::normal_alpha) {
      // The mask varies: the normal map's alpha is not one value.
      const std::vector<uint8_t>& texels = s().textures[m.bump.texture].faces[0].rgba8;
      std::set<uint8_t> alphas;
      for (size_t i = 3; i < texels.size(); i += 4) alphas.insert(texels[i]);
      EXPECT_GT(alphas.size(), 10u) << m.name;
      normal_alpha_mask = true;
    }
    if (m.envmap_mask == EnvmapMask::texture) texture_mask = m.envmap_mask_texture.bound();
  }
  EXPECT_GE(with_envmap, 2);
  EXPECT_TRUE(normal_alpha_mask);
  EXPECT_TRUE(texture_mask);
}

TEST_F(Courtyard, HasAHeroAndOtherModelsBumpedAndNot) {
  int heroes = 0, bumped = 0, plain = 0;
  for (const Model& model : s().models) {
    ASSERT_FALSE(model.meshes.empty());
    const Material& m = material_of(s().meshes[model.meshes[0]]);
    EXPECT_EQ(m.family, ShaderFamily::vertexlit_generic) << model.name;
    if (m.hero_boost > 1.0f) {
      ++heroes;
      // Bumped, with the normal map's alpha as its Phong mask: $basemapalphaphongmask would drop
      // the normal map's detail (skin_ps20b.fxc).
      EXPECT_TRUE(m.phong && m.rim && m.rim_mask && !m.base_map_alpha_phong_mask) << m.name;
      EXPECT_TRUE(m.phong_exponent_texture.bound() && m.bump.bound()) << m.name;
    } else {
      (m.bump.bound() ? bumped : plain) += 1;
    }
    // The centroid is the mean of the model's vertices, computed here again.
    glm::dvec3 sum(0);
    size_t n = 0;
    for (int i : model.meshes)
      for (const glm::vec3& p : s().meshes[i].positions) sum += glm::dvec3(p), ++n;
    const glm::vec3 mean(sum / double(n));
    EXPECT_LT(glm::length(mean - model.centroid), 1e-3f) << model.name;
  }
  EXPECT_EQ(heroes, 1);
  EXPECT_GE(bumped, 1);
  EXPECT_GE(plain, 1);
  EXPECT_GE(bumped + plain, 4);
}

TEST_F(Courtyard, HasWaterSkyFogColorCorrectionsAndProbes) {
  EXPECT_TRUE(std::any_of(s().meshes.begin(), s().meshes.end(), [](const Mesh& m) {
    return material_of(m).family == ShaderFamily::water && material_of(m).water_normal.bound();
  }));
  ASSERT_GE(s().sky_texture, 0);
  const Texture& sky = s().textures[s().sky_texture];
  EXPECT_EQ(sky.shape, TextureShape::cube);
  float brightest = 0;
  for (const PixelImage& f : sky.faces) {
    ASSERT_TRUE(f.is_hdr());
    for (float v : f.rgba32f) brightest = std::max(brightest, v);
  }
  EXPECT_GT(brightest, 4.0f) << "an HDR sky holds a sun brighter than white";
  EXPECT_NE(s().fog.mode, FogMode::none);
  EXPECT_LT(s().fog.start, s().fog.end);
  ASSERT_EQ(s().color_corrections.size(), 2u);
  EXPECT_EQ(s().color_corrections[0].lut, "builtin:warm");
  EXPECT_EQ(s().color_corrections[1].lut, "builtin:cool");
  EXPECT_GE(s().cubemap_samples.size(), 2u);
  ASSERT_TRUE(s().irradiance_volume.has_value());
  const IrradianceVolume& v = *s().irradiance_volume;
  for (int a = 0; a < 3; ++a)  // samples at both bounds, `spacing` apart
    EXPECT_FLOAT_EQ(v.min[a] + (v.counts[a] - 1) * v.spacing[a], v.max[a]) << a;
  EXPECT_TRUE(v.cubes.empty()) << "not baked";
}

TEST_F(Courtyard, HasACameraPathThroughTheYard) {
  ASSERT_GE(s().camera_path.size(), 2u);
  for (size_t i = 1; i < s().camera_path.size(); ++i)
    EXPECT_GT(s().camera_path[i].time, s().camera_path[i - 1].time);
  for (const CameraKey& k : s().camera_path) {
    EXPECT_LT(std::abs(k.camera.position.x), 512.0f);
    EXPECT_LT(std::abs(k.camera.position.y), 512.0f);
    EXPECT_GT(k.camera.position.z, 0.0f);
  }
}

TEST_F(Courtyard, IsInInchesAndZUp) {
  const Bounds b = bounds_of(s());
  EXPECT_NEAR(b.size().x, 1088.0f, 1.0f);  // 1024 inside the walls, 32 inches thick
  EXPECT_NEAR(b.size().y, 1088.0f, 1.0f);
  EXPECT_NEAR(b.min.z, 0.0f, 1e-3f);       // the floor
  EXPECT_NEAR(b.max.z, 256.0f, 1e-3f);     // the walls' tops
}

/// Lightmap charts: connected groups of triangles in uv1 of all lightmapped meshes. Each lies in
/// [0, 1]^2, and no two charts' boxes meet (the charts are rectangles, so their boxes are them).
TEST_F(Courtyard, LightmapChartsAreInsideTheUnitSquareAndDoNotOverlap) {
  struct Box {
    glm::vec2 lo{2.0f}, hi{-2.0f};
  };
  std::vector<Box> charts;
  for (const Mesh& m : s().meshes) {
    if (material_of(m).family != ShaderFamily::lightmapped_generic) continue;
    ASSERT_EQ(m.uv1.size(), m.positions.size()) << m.name;
    // Union-find over shared vertices.
    std::vector<uint32_t> parent(m.vertex_count());
    std::iota(parent.begin(), parent.end(), 0u);
    auto find = [&](uint32_t x) {
      while (parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    for (size_t k = 0; k < m.index_count(); k += 3)
      for (int e = 1; e < 3; ++e) parent[find(m.vertex_of_corner(k + e))] = find(m.vertex_of_corner(k));
    std::map<uint32_t, Box> boxes;
    for (size_t k = 0; k < m.index_count(); ++k) {
      const uint32_t v = m.vertex_of_corner(k);
      Box& b = boxes[find(v)];
      b.lo = glm::min(b.lo, m.uv1[v]);
      b.hi = glm::max(b.hi, m.uv1[v]);
    }
    for (const auto& [root, b] : boxes) charts.push_back(b);
  }
  ASSERT_GE(charts.size(), 20u);
  for (const Box& b : charts) {
    EXPECT_GE(b.lo.x, 0.0f);
    EXPECT_GE(b.lo.y, 0.0f);
    EXPECT_LE(b.hi.x, 1.0f);
    EXPECT_LE(b.hi.y, 1.0f);
    EXPECT_GT(b.hi.x - b.lo.x, 0.0f);
    EXPECT_GT(b.hi.y - b.lo.y, 0.0f);
  }
  int overlaps = 0;
  for (size_t i = 0; i < charts.size(); ++i)
    for (size_t j = i + 1; j < charts.size(); ++j) {
      const Box &a = charts[i], &b = charts[j];
      overlaps += a.lo.x < b.hi.x && b.lo.x < a.hi.x && a.lo.y < b.hi.y && b.lo.y < a.hi.y;
    }
  EXPECT_EQ(overlaps, 0);
}

/// Tangent frames: unit tangents across unit normals, handedness +-1, and the handedness right:
/// w cross(n, t) points up the image (-v), as each triangle's own uv derivatives say.
TEST_F(Courtyard, TangentFramesAreOrthonormalWithHandedness) {
  for (const Mesh& m : s().meshes) {
    const Material& mat = material_of(m);
    if (mat.bump.bound() || mat.water_normal.bound()) {
      ASSERT_FALSE(m.tangents.empty()) << m.name;
    }
    if (m.tangents.empty()) continue;
    ASSERT_EQ(m.tangents.size(), m.vertex_count());
    for (size_t i = 0; i < m.vertex_count(); ++i) {
      const glm::vec3 t(m.tangents[i]), n = m.normals[i];
      EXPECT_NEAR(glm::length(t), 1.0f, 1e-4f) << m.name << " " << i;
      EXPECT_NEAR(glm::length(n), 1.0f, 1e-4f) << m.name << " " << i;
      EXPECT_NEAR(glm::dot(t, n), 0.0f, 1e-4f) << m.name << " " << i;
      EXPECT_TRUE(m.tangents[i].w == 1.0f || m.tangents[i].w == -1.0f) << m.name << " " << i;
    }
    size_t checked = 0, wrong = 0;
    for (size_t k = 0; k < m.index_count(); k += 3) {
      const uint32_t i0 = m.vertex_of_corner(k), i1 = m.vertex_of_corner(k + 1), i2 = m.vertex_of_corner(k + 2);
      const glm::dvec3 e1(m.positions[i1] - m.positions[i0]), e2(m.positions[i2] - m.positions[i0]);
      const glm::dvec2 d1(m.uv0[i1] - m.uv0[i0]), d2(m.uv0[i2] - m.uv0[i0]);
      const double det = d1.x * d2.y - d2.x * d1.y;
      if (std::abs(det) < 1e-9) continue;
      const glm::dvec3 dpdv = (e2 * d1.x - e1 * d2.x) / det;
      for (uint32_t v : {i0, i1, i2}) {
        const glm::dvec3 b = double(m.tangents[v].w) * glm::cross(glm::dvec3(m.normals[v]), glm::dvec3(m.tangents[v]));
        ++checked;
        wrong += glm::dot(b, -dpdv) <= 0;
      }
    }
    EXPECT_GT(checked, 0u) << m.name;
    EXPECT_EQ(wrong, 0u) << m.name;
  }
}

/// Normal maps decode to unit vectors leaning out of the surface; base textures are sRGB.
TEST_F(Courtyard, NormalMapsAreUnitAndOutward) {
  std::set<int> normal_maps, bases;
  for (const Material& m : s().materials) {
    if (m.bump.bound()) normal_maps.insert(m.bump.texture);
    if (m.water_normal.bound()) normal_maps.insert(m.water_normal.texture);
    if (m.base.bound()) bases.insert(m.base.texture);
  }
  ASSERT_GE(normal_maps.size(), 4u);
  for (int t : normal_maps) {
    EXPECT_EQ(s().textures[t].color_space, ColorSpace::linear);
    const std::vector<uint8_t>& texels = s().textures[t].faces[0].rgba8;
    bool bumpy = false;
    for (size_t i = 0; i < texels.size(); i += 4) {
      const glm::vec3 n = glm::vec3(texels[i], texels[i + 1], texels[i + 2]) / 127.5f - 1.0f;
      ASSERT_NEAR(glm::length(n), 1.0f, 0.02f) << s().textures[t].name << " texel " << i / 4;
      ASSERT_GT(n.z, 0.0f) << s().textures[t].name;
      bumpy |= n.z < 0.98f;
    }
    EXPECT_TRUE(bumpy) << s().textures[t].name << " is flat";
  }
  for (int t : bases) EXPECT_EQ(s().textures[t].color_space, ColorSpace::srgb) << s().textures[t].name;
}

}  // namespace
}  // namespace luxel::scenes
