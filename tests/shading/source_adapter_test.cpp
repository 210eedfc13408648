// Each Source shader family as the frame draws it (shading/source/adapter.hpp, through the
// rasterizer: clipping, perspective-correct interpolation, MSAA, the sRGB write, the resolve)
// against its scalar reference: the same draw with every covered pixel shaded alone on the float
// lane (ScalarReference). The images must be the same bytes: 0 steps.
//
// The textures are point-sampled without mips, where the float lane's sampler reads the texels
// the stamps read (with bilinear filtering the float lane's sampler is the texture module's
// double-precision reference, textures.hpp, and may round differently). The scene: three
// triangles with different w at each corner, partly overlapping, partly off the target, over a
// target of odd size (partial stamps), every attribute different at every corner.

#include "source_support.hpp"

#include "luxel/rasterizer/draw_definition.hpp"
#include "luxel/rasterizer/framebuffer.hpp"
#include "luxel/shading/source/adapter.hpp"
#include "luxel/shading/source/normalization_cube.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace luxel::shading::source {
namespace {

constexpr int kWidth = 61, kHeight = 47;
constexpr int kVertices = 6;

constexpr glm::vec4 kClip[kVertices] = {
    {-0.9f, -0.8f, 0.30f, 1.0f},  {1.28f, -1.44f, 0.80f, 1.6f}, {0.6f, 0.65f, 0.25f, 0.8f},
    {-1.6f, 1.5f, 1.20f, 2.0f},   {-0.3f, -1.2f, 0.10f, 1.1f}, {1.4f, 0.2f, 0.90f, 1.3f},
};
constexpr std::array<uint16_t, 9> kIndices = {0, 1, 2, 0, 2, 3, 4, 5, 2};

/// Per-vertex values of every attribute, different at every corner; unit normals and an
/// orthonormal tangent frame, as the frame's vertex stage writes them.
float attribute_value(Attribute a, int v) {
  const float t = static_cast<float>(v);
  const glm::vec3 n = glm::normalize(glm::vec3(0.3f + 0.1f * t, -0.2f + 0.15f * t, 0.9f - 0.05f * t));
  const glm::vec3 tangent = glm::normalize(glm::cross(glm::vec3(0.1f * t, 1.0f, 0.2f), n));
  const glm::vec3 binormal = glm::cross(n, tangent);
  switch (a) {
    case Attribute::world_x: return 10.0f + 13.0f * t;
    case Attribute::world_y: return -20.0f + 7.0f * t * t;
    case Attribute::world_z: return -8.0f + 6.0f * t;
    case Attribute::proj_z: return 40.0f + 70.0f * t;
    case Attribute::normal_x: return n.x;
    case Attribute::normal_y: return n.y;
    case Attribute::normal_z: return n.z;
    case Attribute::tangent_x: return tangent.x;
    case Attribute::tangent_y: return tangent.y;
    case Attribute::tangent_z: return tangent.z;
    case Attribute::binormal_x: return binormal.x;
    case Attribute::binormal_y: return binormal.y;
    case Attribute::binormal_z: return binormal.z;
    case Attribute::base_u: return 0.1f + 0.37f * t;
    case Attribute::base_v: return 0.9f - 0.29f * t;
    case Attribute::lightmap_u: return 0.05f + 0.17f * t;
    case Attribute::lightmap_v: return 0.8f - 0.13f * t;
    case Attribute::color_r: return 0.2f + 0.15f * t;
    case Attribute::color_g: return 0.9f - 0.1f * t;
    case Attribute::color_b: return 0.5f;
    case Attribute::color_a: return 0.6f + 0.05f * t;
    case Attribute::attenuation_0: return 0.3f + 0.1f * t;
    case Attribute::attenuation_1: return 0.8f - 0.1f * t;
    case Attribute::attenuation_2: return 0.5f;
    case Attribute::attenuation_3: return 0.1f;
    case Attribute::light_r: return 1.4f - 0.3f * t;
    case Attribute::light_g: return 0.7f + 0.2f * t;
    case Attribute::light_b: return 0.3f;
    case Attribute::fog_visibility: return 0.2f + 0.15f * t;
  }
  return 0.0f;
}

template <AttributeList L>
struct TestVertices {
  static constexpr int kVaryings = L.varyings();
  void operator()(uint32_t i, rasterizer::VertexOutput<kVaryings>& out) const {
    out.position = kClip[i];
    for (auto& v : out.varyings) v = glm::vec4(0.0f);
    for (int k = 0; k < L.count; ++k) out.varyings[static_cast<size_t>(k / 4)][k % 4] = attribute_value(L.items[static_cast<size_t>(k)], static_cast<int>(i));
  }
};

template <class PS>
rasterizer::Image render(const PS& ps, int samples, int threads) {
  rasterizer::Context ctx(threads);
  rasterizer::ColorTarget color(kWidth, kHeight, samples);
  rasterizer::DepthStencilTarget depth(kWidth, kHeight, samples);
  rasterizer::clear_color(ctx, color, glm::vec4(0.1f, 0.2f, 0.3f, 1.0f));
  rasterizer::clear_depth(ctx, depth, 1.0f);
  rasterizer::PipelineState state;
  state.rasterizer.cull = rasterizer::CullMode::None;
  state.blend.srgb_write = true;
  rasterizer::draw(ctx, rasterizer::Framebuffer{&color, &depth}, state,
                   rasterizer::Geometry::indexed(std::span<const uint16_t>(kIndices), kVertices), TestVertices<PS::kAttributes>{}, ps);
  rasterizer::Image image;
  rasterizer::resolve_into(ctx, color, image);
  return image;
}

/// The stamps' image against the scalar reference's: the same bytes, for 1 and 4 samples, 1 and 2
/// threads; and an image with enough distinct colors that a wrong lane could not hide.
template <class PS>
void expect_scalar_reference_bytes(const PS& ps, const std::string& what) {
  for (int samples : {1, 4}) {
    const rasterizer::Image stamps = render(ps, samples, 2);
    const rasterizer::Image scalar = render(ScalarReference<PS>{ps}, samples, 1);
    ASSERT_EQ(stamps.rgba.size(), scalar.rgba.size());
    int max_step = 0;
    long differing = 0;
    for (size_t i = 0; i < stamps.rgba.size(); ++i) {
      const int d = std::abs(int(stamps.rgba[i]) - int(scalar.rgba[i]));
      max_step = std::max(max_step, d);
      differing += d != 0;
    }
    EXPECT_EQ(max_step, 0) << what << ", " << samples << " sample(s): " << differing << " bytes differ";
    std::set<uint32_t> colors;
    for (size_t i = 0; i < stamps.rgba.size(); i += 4)
      colors.insert(uint32_t(stamps.rgba[i]) | uint32_t(stamps.rgba[i + 1]) << 8 | uint32_t(stamps.rgba[i + 2]) << 16);
    EXPECT_GT(colors.size(), 60u) << what << ": too flat an image to tell lanes apart";
  }
}

rasterizer::Sampler point_no_mips() {
  rasterizer::Sampler s;
  s.min = s.mag = rasterizer::Filter::Point;
  s.mip = rasterizer::MipFilter::None;
  return s;
}

/// A random texture without mips: values in [lo, hi], alpha in [0, 1].
rasterizer::Texture random_2d(int w, int h, rasterizer::TextureFormat f, float lo, float hi, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> value(lo, hi), alpha(0.0f, 1.0f);
  std::vector<glm::vec4> texels(size_t(w) * h);
  for (glm::vec4& t : texels) t = glm::vec4(value(rng), value(rng), value(rng), alpha(rng));
  rasterizer::Texture tex = rasterizer::Texture::create_2d(w, h, f, 1);
  tex.upload(0, texels);
  return tex;
}

/// A random tangent-space normal map (z toward the surface's outside), without mips.
rasterizer::Texture random_normals(uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> xy(-0.6f, 0.6f), alpha(0.0f, 1.0f);
  std::vector<glm::vec4> texels(32 * 32);
  for (glm::vec4& t : texels) {
    const glm::vec3 n = glm::normalize(glm::vec3(xy(rng), xy(rng), 1.0f));
    t = glm::vec4(n * 0.5f + 0.5f, alpha(rng));
  }
  rasterizer::Texture tex = rasterizer::Texture::create_2d(32, 32, rasterizer::TextureFormat::RGBA8, 1);
  tex.upload(0, texels);
  return tex;
}

rasterizer::Texture random_cube(uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> value(0.0f, 1.5f);
  rasterizer::Texture cube = rasterizer::Texture::create_cube(8, rasterizer::TextureFormat::RGBA16F, 1);
  for (int f = 0; f < 6; ++f) {
    std::vector<glm::vec4> texels(64);
    for (glm::vec4& t : texels) t = glm::vec4(value(rng), value(rng), value(rng), 1.0f);
    cube.upload(0, texels, f);
  }
  return cube;
}

struct Textures {
  rasterizer::Texture base = random_2d(32, 32, rasterizer::TextureFormat::RGBA8_sRGB, 0.0f, 1.0f, 1);
  rasterizer::Texture bump = random_normals(2);
  rasterizer::Texture lightmap_page = random_2d(64, 32, rasterizer::TextureFormat::RGBA16F, 0.0f, 1.5f, 3);
  rasterizer::Texture envmap = random_cube(4);
  rasterizer::Texture exponent = random_2d(32, 32, rasterizer::TextureFormat::RGBA8, 0.0f, 1.0f, 5);
  rasterizer::Texture sky = random_2d(32, 32, rasterizer::TextureFormat::RGBA16F, 0.0f, 2.0f, 6);
  rasterizer::Texture normalization_cube = normalization_cube_map();
};

template <SamplerKind K>
void bind(TextureBinding<K>& b, const rasterizer::Texture& t) {
  b.texture = &t;
  b.state = point_no_mips();
}

const glm::vec3 kEye(30.0f, -60.0f, 80.0f);

template <LightmappedCombo C>
void lightmapped(const Textures& t, const std::string& what) {
  LightmappedPixelShader<C> ps;
  bind(ps.params.base, t.base);
  bind(ps.params.bump, t.bump);
  bind(ps.params.lightmap, t.lightmap_page);
  bind(ps.params.envmap, t.envmap);
  ps.params.tint_lightmap_scale = glm::vec4(0.9f, 1.1f, 1.0f, 1.0f);
  ps.params.envmap_tint = glm::vec4(0.7f, 0.5f, 0.9f, 0.0f);
  ps.params.envmap_contrast_saturation = glm::vec4(0.4f, 0.6f, 0.0f, 0.0f);
  ps.params.fresnel = glm::vec4(0.0f, 0.0f, 0.8f, 0.2f);
  ps.params.tonemap = ToneMapConstants::for_scale(1.3f);
  ps.params.fog = testing::lane_test_fog();
  ps.eye = kEye;
  expect_scalar_reference_bytes(ps, what);
}

TEST(SourceAdapter, LightmappedGenericMatchesItsScalarReference) {
  const Textures t;
  lightmapped<LightmappedCombo{.bump = true, .envmap = true, .mask = EnvmapMask::normal_alpha, .path = EnvmapPath::full, .fog = Fog::range}>(
      t, "LightmappedGeneric bump envmap normal-alpha full range fog");
  lightmapped<LightmappedCombo{.bump = false, .envmap = true, .mask = EnvmapMask::base_alpha_inverted, .fog = Fog::vertex_range}>(
      t, "LightmappedGeneric flat envmap base-alpha vertex fog (ps_2_0)");
  lightmapped<LightmappedCombo{.bump = true, .envmap = false}>(t, "LightmappedGeneric bump, no envmap");
}

template <VertexLitCombo C>
void vertexlit(const Textures& t, const std::string& what) {
  VertexLitPixelShader<C> ps;
  bind(ps.params.base, t.base);
  bind(ps.params.bump, t.bump);
  bind(ps.params.phong_exponent, t.exponent);
  bind(ps.params.normalization_cube, t.normalization_cube);
  ps.params.ambient.color = {glm::vec3(0.2f, 0.1f, 0.05f), glm::vec3(0.05f, 0.1f, 0.3f), glm::vec3(0.4f, 0.3f, 0.1f),
                             glm::vec3(0.0f, 0.2f, 0.1f), glm::vec3(0.6f, 0.6f, 0.7f), glm::vec3(0.1f, 0.05f, 0.0f)};
  LocalLight point;
  point.color = glm::vec4(900.0f, 700.0f, 500.0f, 0.0f);
  point.position = glm::vec4(40.0f, -10.0f, 60.0f, 1.0f);
  point.attenuation = glm::vec4(0.0f, 0.5f, 0.02f, 0.0f);
  LocalLight spot;
  spot.color = glm::vec4(300.0f, 500.0f, 800.0f, 0.0f);
  spot.position = glm::vec4(-30.0f, 20.0f, 50.0f, 1.0f);
  spot.spot_direction = glm::vec4(glm::normalize(glm::vec3(0.6f, -0.3f, -1.0f)), 1.0f);
  spot.spot_params = glm::vec4(2.0f, 0.0f, 0.5f, 1.0f / (0.95f - 0.5f));
  spot.attenuation = glm::vec4(0.0f, 0.2f, 0.05f, 0.0f);
  ps.params.lights = {point, spot, LocalLight{}, LocalLight{}};
  ps.params.eye_position = glm::vec4(kEye, 1.0f);
  ps.params.modulation = glm::vec4(0.9f, 0.8f, 1.0f, 0.7f);
  ps.params.phong_tint_boost = glm::vec4(1.0f, 0.9f, 0.8f, 2.0f);
  ps.params.phong_params = glm::vec4(12.0f, 3.0f, 1.5f, 1.0f);
  ps.params.fresnel_ranges = encode_fresnel_ranges(0.1f, 0.5f, 1.0f);
  ps.params.tonemap = ToneMapConstants::for_scale(1.3f);
  ps.params.fog = testing::lane_test_fog();
  expect_scalar_reference_bytes(ps, what);
}

TEST(SourceAdapter, VertexLitGenericMatchesItsScalarReference) {
  const Textures t;
  vertexlit<VertexLitCombo{.lights = 2, .bump = true, .phong = true, .rim = true,
                           .half_lambert = true, .pixel_attenuation = true, .fog = Fog::range}>(
      t, "VertexLitGeneric ps_3_0 hero: bump phong exponent rim, range fog");
  vertexlit<VertexLitCombo{.lights = 2, .bump = false, .half_lambert = false, .pixel_attenuation = false,
                           .fog = Fog::vertex_range, .normalization_cube = true}>(
      t, "VertexLitGeneric ps_2_0: per-vertex attenuation, normalization cube, vertex fog");
}

TEST(SourceAdapter, UnlitGenericMatchesItsScalarReference) {
  const Textures t;
  UnlitPixelShader<UnlitCombo{.envmap = true, .mask = UnlitEnvmapMask::base_alpha_inverted, .vertex_color = true, .fog = Fog::range}> ps;
  bind(ps.params.base, t.base);
  bind(ps.params.envmap, t.envmap);
  ps.params.envmap_tint = glm::vec4(0.6f, 0.8f, 0.4f, 0.0f);
  ps.params.modulation = glm::vec4(0.8f, 0.9f, 0.7f, 0.9f);
  ps.params.tonemap = ToneMapConstants::for_scale(1.3f);
  ps.params.fog = testing::lane_test_fog();
  ps.eye = kEye;
  expect_scalar_reference_bytes(ps, "UnlitGeneric envmap base-alpha mask, vertex color, range fog");
  UnlitPixelShader<UnlitCombo{.diffuse_lighting = true, .fog = Fog::height}> lit;
  bind(lit.params.base, t.base);
  lit.params.modulation = glm::vec4(0.8f, 0.9f, 0.7f, 0.9f);
  lit.params.tonemap = ToneMapConstants::for_scale(1.3f);
  lit.params.fog = testing::lane_test_fog();
  expect_scalar_reference_bytes(lit, "VertexLitGeneric lit per vertex (DIFFUSELIGHTING), height fog");
}

TEST(SourceAdapter, WaterMatchesItsScalarReference) {
  const Textures t;
  // The reflection and refraction targets as the water reads them (8-bit sRGB; the refraction's
  // alpha is the water's depth), and its normal map.
  const rasterizer::Texture reflection = random_2d(kWidth, kHeight, rasterizer::TextureFormat::RGBA8_sRGB, 0.0f, 1.0f, 7);
  const rasterizer::Texture refraction = random_2d(kWidth, kHeight, rasterizer::TextureFormat::RGBA8_sRGB, 0.0f, 1.0f, 8);
  WaterMaterial material;
  material.reflect_tint = glm::vec3(0.9f, 0.8f, 0.7f);
  material.refract_tint = glm::vec3(0.6f, 0.8f, 0.9f);
  material.fog_color = glm::vec3(0.1f, 0.3f, 0.35f);
  material.reflect_amount = 0.3f;
  material.refract_amount = 0.2f;
  material.exposure = WaterReflectionExposure::sdk_fixed;
  WaterPixelShader<WaterCombo{.reflect = true, .refract = true, .above_water = true, .multitexture = true, .fog = Fog::range}> ps;
  ps.params = water_constants(material, HdrType::integer, ToneMapConstants::for_scale(1.3f));
  bind(ps.params.reflection, reflection);
  bind(ps.params.refraction, refraction);
  bind(ps.params.normal, t.bump);
  ps.params.pixel_fog = testing::lane_test_fog();
  ps.constants.scroll_offsets = glm::vec4(0.13f, -0.07f, 0.0f, 0.0f);
  ps.constants.inverse_size = glm::vec2(1.0f / kWidth, 1.0f / kHeight);
  ps.eye = kEye;
  expect_scalar_reference_bytes(ps, "Water reflect+refract+above+multitexture, range fog");
}

TEST(SourceAdapter, SkyMatchesItsScalarReference) {
  const Textures t;
  SkyPixelShader ps;
  bind(ps.params.base, t.sky);
  ps.params.input_scale = glm::vec4(1.2f, 1.2f, 1.2f, 1.0f);
  ps.params.tonemap = ToneMapConstants::for_scale(0.6f);
  expect_scalar_reference_bytes(ps, "Sky_HDR hdr16");
}

}  // namespace
}  // namespace luxel::shading::source
