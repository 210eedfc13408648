// The real shaders, texture fetches included, on both numeric lanes. Closed forms on uniform
// textures (so the LOD does not matter), and SIMD against scalar through real sampling of random
// textures for every combo: with point filtering both lanes read the same texels and must give
// the same bits; with bilinear filtering the float lane's sampler is the texture module's double-
// precision reference (textures.hpp), so the bits may differ by its rounding and the bytes by one
// step at most.

#include "phong_reference.hpp"
#include "source_support.hpp"

#include "luxel/shading/source/lightmapped_generic.hpp"
#include "luxel/shading/source/unlit_generic.hpp"
#include "luxel/shading/source/vertexlit_generic.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <vector>

namespace luxel::shading::source {
namespace {

using rasterizer::TextureFormat;
using testing::Draw;

TEST(SourceTextured, LightmappedGenericBumpEnvmapOnBothLanes) {
  const rasterizer::Texture base = testing::uniform_2d(TextureFormat::RGBA8_sRGB, glm::vec4(0.5f, 0.25f, 1.0f, 0.0f));
  const rasterizer::Texture bump = testing::uniform_2d(TextureFormat::RGBA8, glm::vec4(0.5f, 0.5f, 1.0f, 1.0f));
  const rasterizer::Texture lightmap = testing::uniform_2d(TextureFormat::RGBA16F, glm::vec4(3.0f, 2.0f, 1.0f, 1.0f));
  const rasterizer::Texture cube = testing::face_colored_cube();
  LightmappedGenericParams p;
  p.base.texture = &base;
  p.bump.texture = &bump;
  p.lightmap.texture = &lightmap;
  p.envmap.texture = &cube;
  constexpr LightmappedCombo C{true, true, EnvmapMask::none, EnvmapPath::fast};
  auto make = [](auto zero) {
    using L = decltype(zero);
    LightmappedInputs<L> in;
    in.base_uv = float2<L>(zero + 0.3f, zero + 0.6f);
    in.lightmap_uv12 = float4<L>(zero + 0.1f, zero + 0.2f, zero + 0.3f, zero + 0.4f);
    in.lightmap_uv3 = float2<L>(zero + 0.5f, zero + 0.5f);
    in.tangent = float3<L>(L(1.0f), L(0.0f), L(0.0f));
    in.binormal = float3<L>(L(0.0f), L(1.0f), L(0.0f));
    in.normal = float3<L>(L(0.0f), L(0.0f), L(1.0f));
    in.eye_vector = float3<L>(L(0.0f), L(0.0f), L(5.0f));
    return in;
  };
  const float4<float> s = lightmapped_generic<C>(make(0.0f), p);
  const float4<simd::Float> v = lightmapped_generic<C>(make(simd::Float(0.0f)), p);
  for (int c = 0; c < 4; ++c)
    for (int l = 0; l < simd::kLanes; ++l) EXPECT_TRUE(shading::testing::same_float(testing::lane_of(v[c], l), s[c]));
  // Flat normal: average lightmap (3,2,1) x base (uploaded linear 0.5, stored sRGB, decoded on
  // read) + envmap +Z face (0.4,0.2,0.3), unmasked. 8-bit bump/base quantisation: 0.02.
  const double base_r = 0.5;
  EXPECT_NEAR(s.x, 3.0 * base_r + 0.4, 0.02);
  EXPECT_NEAR(s.z, 1.0 * 1.0 + 0.3, 0.02);
}

TEST(SourceTextured, VertexLitGenericPhongOnBothLanes) {
  // Point light with no distance falloff at (0, 0, 3), eye at (0, 1, 4), the point at (0.1, 0, 0);
  // the textures' 8-bit values are what the double reference is fed.
  const rasterizer::Texture base = testing::uniform_2d(TextureFormat::RGBA8_sRGB, glm::vec4(0.8f, 0.6f, 0.4f, 1.0f));
  const rasterizer::Texture bump = testing::uniform_2d(TextureFormat::RGBA8, glm::vec4(0.5f, 0.5f, 1.0f, 0.6f));
  const rasterizer::Texture expo = testing::uniform_2d(TextureFormat::RGBA8, glm::vec4(0.2f, 0.0f, 0.0f, 1.0f));
  VertexLitParams p;
  p.base.texture = &base;
  p.bump.texture = &bump;
  p.phong_exponent.texture = &expo;
  p.lights[0].color = glm::vec4(2.0f, 2.0f, 2.0f, 0.0f);
  p.lights[0].position = glm::vec4(0.0f, 0.0f, 3.0f, 1.0f);
  p.eye_position = glm::vec4(0.0f, 1.0f, 4.0f, 1.0f);
  p.fresnel_ranges = encode_fresnel_ranges(1.0f, 1.0f, 1.0f);  // Fresnel 1 at this near-normal eye
  constexpr VertexLitCombo C{2, true, true, true, true, true};
  auto make = [](auto zero) {
    using L = decltype(zero);
    VertexLitInputs<L> in;
    in.uv = float2<L>(zero + 0.5f, zero + 0.5f);
    in.world_pos = float3<L>(zero + 0.1f, zero, zero);
    in.normal = float3<L>(L(0.0f), L(0.0f), L(1.0f));
    in.tangent = float3<L>(L(1.0f), L(0.0f), L(0.0f));
    in.binormal = float3<L>(L(0.0f), L(1.0f), L(0.0f));
    return in;
  };
  const float4<float> s = vertexlit_generic<C>(make(0.0f), p);
  const float4<simd::Float> v = vertexlit_generic<C>(make(simd::Float(0.0f)), p);
  for (int c = 0; c < 4; ++c)
    for (int l = 0; l < simd::kLanes; ++l) EXPECT_TRUE(shading::testing::same_float(testing::lane_of(v[c], l), s[c]));

  const double bump_byte = 128.0 / 255.0;  // 0.5 stored in 8 bits
  testing::PhongReference ref;
  const glm::dvec3 point(0.1, 0.0, 0.0);
  ref.light_dir = glm::normalize(glm::dvec3(0.0, 0.0, 3.0) - point);
  ref.light_color = glm::dvec3(2.0);
  ref.base = glm::dvec3(base.load(0, 0));  // the stored 8-bit sRGB value, decoded
  ref.normal_alpha = 153.0 / 255.0;         // the bump map's alpha 0.6 in 8 bits: the mask
  ref.exponent_texel = glm::dvec4(51.0 / 255.0, 0.0, 0.0, 1.0);  // r = 0.2: exponent 30.8
  ref.rim = true;
  ref.fresnel_min = ref.fresnel_mid = ref.fresnel_max = 1.0;
  const glm::dvec3 n = glm::normalize(glm::dvec3(bump_byte * 2.0 - 1.0, bump_byte * 2.0 - 1.0, 1.0));
  const glm::dvec3 want = ref(n, glm::dvec3(0.0, 1.0, 4.0) - point);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(s[c], want[c], 2e-5 * std::max(1.0, want[c])) << "channel " << c;
  testing::PhongReference diffuse_only = ref;
  diffuse_only.boost = 0.0;
  EXPECT_GT(want.x - diffuse_only(n, glm::dvec3(0.0, 1.0, 4.0) - point).x, 0.1) << "the specular is a large part";
}

// ---- SIMD against scalar through real sampling ------------------------------------------------

/// A 16x16 (cube: 8x8 per face) texture of one mip level with random texels in [lo, hi].
rasterizer::Texture random_texture(bool cube, TextureFormat format, float lo, float hi, std::mt19937& rng) {
  rasterizer::Texture t = cube ? rasterizer::Texture::create_cube(8, format, 1) : rasterizer::Texture::create_2d(16, 16, format, 1);
  std::uniform_real_distribution<float> d(lo, hi);
  for (int face = 0; face < (cube ? 6 : 1); ++face) {
    std::vector<glm::vec4> texels(static_cast<size_t>(t.width(0)) * t.height(0));
    for (glm::vec4& c : texels) c = glm::vec4(d(rng), d(rng), d(rng), d(rng));
    t.upload(0, texels, face);
  }
  return t;
}

/// One level and the same filter for minification and magnification: the LOD, which the lanes
/// compute differently (quad derivatives vs the caller's), selects nothing.
rasterizer::Sampler sampler_for(rasterizer::Filter filter) {
  rasterizer::Sampler s;
  s.min = s.mag = filter;
  s.mip = rasterizer::MipFilter::None;
  return s;
}

struct RandomTextures {
  std::mt19937 rng{2026};
  rasterizer::Texture base = random_texture(false, TextureFormat::RGBA8_sRGB, 0.0f, 1.0f, rng);
  rasterizer::Texture bump = random_texture(false, TextureFormat::RGBA8, 0.0f, 1.0f, rng);
  rasterizer::Texture mask = random_texture(false, TextureFormat::RGBA8, 0.0f, 1.0f, rng);
  rasterizer::Texture lightmap = random_texture(false, TextureFormat::RGBA16F, 0.0f, 4.0f, rng);
  rasterizer::Texture cube = random_texture(true, TextureFormat::RGBA16F, 0.0f, 8.0f, rng);
  rasterizer::Texture normalization_cube = normalization_cube_map();  // VertexLitGeneric's ps_2_0 combos
};

template <LightmappedCombo C>
testing::LaneComparison compare_lightmapped_sampled(const RandomTextures& tex, rasterizer::Filter filter, int hard_every,
                                                    uint32_t seed) {
  LightmappedGenericParams p;
  p.base.texture = &tex.base;
  p.bump.texture = &tex.bump;
  p.envmap_mask.texture = &tex.mask;
  p.lightmap.texture = &tex.lightmap;
  p.envmap.texture = &tex.cube;
  for (auto* s : {&p.base, &p.bump, &p.envmap_mask, &p.lightmap}) s->state = sampler_for(filter);
  p.envmap.state = sampler_for(filter);
  p.envmap_contrast_saturation = glm::vec4(0.4f, 0.6f, 0.0f, 0.0f);
  p.fresnel = fresnel_constant(0.1f);
  p.fog = testing::lane_test_fog();  // the fog combos
  auto shade = [&]<class L>(const auto& get) -> float4<L> {
    LightmappedInputs<L> in;
    in.base_uv = float2<L>(get(0), get(1));
    in.lightmap_uv0 = float2<L>(get(2), get(3));
    in.lightmap_uv12 = float4<L>(get(4), get(5), get(6), get(7));
    in.lightmap_uv3 = float2<L>(get(8), get(9));
    in.tangent = float3<L>(get(10), get(11), get(12));
    in.binormal = float3<L>(get(13), get(14), get(15));
    in.normal = float3<L>(get(16), get(17), get(18));
    in.eye_vector = float3<L>(get(19), get(20), get(21));
    in.fog = FogInputs<L>{get(22), get(23)};
    return lightmapped_generic<C>(in, p);
  };
  std::vector<Draw> draws(24, Draw{-1.0f, 2.0f, 0});
  for (int i = 10; i < 22; ++i) draws[i] = Draw{-1.0f, 1.0f, hard_every};
  draws[22] = Draw{-10.0f, 30.0f, hard_every};  // world z
  draws[23] = Draw{0.0f, 400.0f, hard_every};   // projected z
  return testing::compare_lanes<24>(shade, draws, 64, seed);
}

template <VertexLitCombo C>
testing::LaneComparison compare_vertexlit_sampled(const RandomTextures& tex, rasterizer::Filter filter, int hard_every,
                                                  uint32_t seed) {
  VertexLitParams p;
  p.base.texture = &tex.base;
  p.bump.texture = &tex.bump;
  p.phong_exponent.texture = &tex.mask;
  for (auto* s : {&p.base, &p.bump, &p.phong_exponent}) s->state = sampler_for(filter);
  p.ambient.color = {glm::vec3(0.2f, 0.1f, 0.0f), glm::vec3(0.0f, 0.1f, 0.2f), glm::vec3(0.3f), glm::vec3(0.05f),
                     glm::vec3(0.5f, 0.4f, 0.3f), glm::vec3(0.0f)};
  p.eye_position = glm::vec4(0.5f, 2.0f, 3.0f, 1.0f);
  p.lights[0] = LocalLight{glm::vec4(3.0f, 2.0f, 1.0f, 0.0f), glm::vec4(1.0f, 1.0f, 1.0f, 1.0f), glm::vec4(0.0f),
                           glm::vec4(0.0f), glm::vec4(0.0f, 0.0f, 1.0f, 0.0f)};
  p.lights[1] = LocalLight{glm::vec4(0.5f, 0.5f, 0.7f, 1.0f), glm::vec4(0.0f, 0.6f, 0.8f, 0.0f), glm::vec4(0.0f),
                           glm::vec4(0.0f), glm::vec4(1.0f, 0.0f, 0.0f, 0.0f)};
  p.lights[2] = p.lights[3] = p.lights[0];
  p.phong_params = glm::vec4(20.0f, 4.0f, 1.0f, 1.0f);
  p.fresnel_ranges = encode_fresnel_ranges(0.1f, 0.5f, 1.0f);
  p.fog = testing::lane_test_fog();                // the fog combos
  p.normalization_cube.texture = &tex.normalization_cube;  // the ps_2_0 combos, read like the others
  p.normalization_cube.state = sampler_for(filter);
  p.envmap.texture = &tex.cube;  // the env-map combos
  p.envmap.state = sampler_for(filter);
  p.envmap_tint = glm::vec4(0.8f, 0.6f, 0.4f, 1.0f);
  p.envmap_fresnel.x = 0.7f;
  p.envmap_contrast = glm::vec4(0.3f);
  p.envmap_saturation = glm::vec4(0.7f);
  auto shade = [&]<class L>(const auto& get) -> float4<L> {
    VertexLitInputs<L> in;
    in.uv = float2<L>(get(0), get(1));
    in.world_pos = float3<L>(get(2), get(3), get(4));
    in.normal = float3<L>(get(5), get(6), get(7));
    in.tangent = float3<L>(get(8), get(9), get(10));
    in.binormal = float3<L>(get(11), get(12), get(13));
    in.attenuation = float4<L>(get(14), get(15), get(16), get(17));
    in.proj_z = get(18);
    return vertexlit_generic<C>(in, p);
  };
  std::vector<Draw> draws(19, Draw{-1.0f, 1.0f, hard_every});
  draws[0] = draws[1] = Draw{-1.0f, 2.0f, 0};
  for (int i = 14; i < 18; ++i) draws[i] = Draw{0.0f, 1.0f, hard_every};
  draws[18] = Draw{0.0f, 400.0f, hard_every};  // projected z
  return testing::compare_lanes<19>(shade, draws, 64, seed);
}

template <UnlitCombo C>
testing::LaneComparison compare_unlit_sampled(const RandomTextures& tex, rasterizer::Filter filter, int hard_every,
                                              uint32_t seed) {
  UnlitGenericParams p;
  p.base.texture = &tex.base;
  p.detail.texture = &tex.bump;
  p.envmap_mask.texture = &tex.mask;
  p.envmap.texture = &tex.cube;
  for (auto* s : {&p.base, &p.detail, &p.envmap_mask}) s->state = sampler_for(filter);
  p.envmap.state = sampler_for(filter);
  p.envmap_contrast = glm::vec4(0.3f);
  p.envmap_saturation = glm::vec4(0.7f);
  p.detail_blend.w = 0.8f;
  p.fog = testing::lane_test_fog();  // the fog combos
  auto shade = [&]<class L>(const auto& get) -> float4<L> {
    UnlitInputs<L> in;
    in.base_uv = float2<L>(get(0), get(1));
    in.detail_uv = float2<L>(get(2), get(3));
    in.vertex_color = float4<L>(get(4), get(5), get(6), get(7));
    in.eye_vector = float3<L>(get(8), get(9), get(10));
    in.normal = float3<L>(get(11), get(12), get(13));
    in.fog = FogInputs<L>{get(14), get(15)};
    return unlit_generic<C>(in, p);
  };
  std::vector<Draw> draws(16, Draw{-1.0f, 1.0f, hard_every});
  for (int i = 0; i < 4; ++i) draws[i] = Draw{-1.0f, 2.0f, 0};
  draws[14] = Draw{-10.0f, 30.0f, hard_every};  // world z
  draws[15] = Draw{0.0f, 400.0f, hard_every};   // projected z
  return testing::compare_lanes<16>(shade, draws, 64, seed);
}

TEST(SourceTextured, SimdAgreesWithScalarThroughPointSamplingForEveryCombo) {
  const RandomTextures tex;
  uint32_t seed = 500;
  for_each_combo<testing::kLightmappedSampled>([&]<LightmappedCombo C>() {
    for (int hard_every : {0, 3})
      testing::expect_bit_identical(compare_lightmapped_sampled<C>(tex, rasterizer::Filter::Point, hard_every, seed++),
                                    "LightmappedGeneric " + C.name());
  });
  for_each_combo<testing::kVertexLitSampled>([&]<VertexLitCombo C>() {
    for (int hard_every : {0, 3})
      testing::expect_bit_identical(compare_vertexlit_sampled<C>(tex, rasterizer::Filter::Point, hard_every, seed++),
                                    "VertexLitGeneric " + C.name());
  });
  for_each_combo<testing::kUnlitSampled>([&]<UnlitCombo C>() {
    for (int hard_every : {0, 3})
      testing::expect_bit_identical(compare_unlit_sampled<C>(tex, rasterizer::Filter::Point, hard_every, seed++),
                                    "UnlitGeneric " + C.name());
  });
}

TEST(SourceTextured, SimdWithinOneStepOfScalarThroughBilinearSampling) {
  const RandomTextures tex;
  uint32_t seed = 900;
  int worst = 0;
  long mismatched = 0, channels = 0;
  for_each_combo<testing::kLightmappedSampled>([&]<LightmappedCombo C>() {
    const auto r = compare_lightmapped_sampled<C>(tex, rasterizer::Filter::Linear, 0, seed++);
    EXPECT_LE(r.max_step, 1) << "LightmappedGeneric " << C.name();
    worst = std::max(worst, r.max_step);
    mismatched += r.bit_mismatches;
    channels += 4 * r.pixels;
  });
  for_each_combo<testing::kVertexLitSampled>([&]<VertexLitCombo C>() {
    const auto r = compare_vertexlit_sampled<C>(tex, rasterizer::Filter::Linear, 0, seed++);
    EXPECT_LE(r.max_step, 1) << "VertexLitGeneric " << C.name();
    worst = std::max(worst, r.max_step);
    mismatched += r.bit_mismatches;
    channels += 4 * r.pixels;
  });
  for_each_combo<testing::kUnlitSampled>([&]<UnlitCombo C>() {
    const auto r = compare_unlit_sampled<C>(tex, rasterizer::Filter::Linear, 0, seed++);
    EXPECT_LE(r.max_step, 1) << "UnlitGeneric " << C.name();
    worst = std::max(worst, r.max_step);
    mismatched += r.bit_mismatches;
    channels += 4 * r.pixels;
  });
  std::printf("bilinear sampling, SIMD vs the double reference sampler: max %d step(s), %ld of %ld channels differ "
              "in bits\n",
              worst, mismatched, channels);
}

}  // namespace
}  // namespace luxel::shading::source
