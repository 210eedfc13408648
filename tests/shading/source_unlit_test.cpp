// UnlitGeneric: closed forms of the base x $color x vertex color product, both detail modes, the
// envmap with its masks, contrast and saturation, the alpha rules; the real shader with textures
// on both lanes; SIMD vs scalar; the DX9 budget of every combo.

#include "source_support.hpp"

#include "luxel/shading/source/material_color.hpp"
#include "luxel/shading/source/unlit_generic.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace luxel::shading::source {
namespace {

using testing::compare_lanes;
using testing::Draw;

template <UnlitCombo C>
float4<float> combine(const UnlitTexels<float>& t, const UnlitGenericParams& p, const UnlitInputs<float>& in = {}) {
  return unlit_generic_combine<C>(t, in, p, [](const float3<float>& r) { return testing::analytic_env(r); });
}

constexpr UnlitCombo kBase{};
constexpr UnlitCombo kVertexColor{UnlitDetail::none, false, UnlitEnvmapMask::none, true};
constexpr UnlitCombo kMod2x{UnlitDetail::mod2x, false, UnlitEnvmapMask::none, false};
constexpr UnlitCombo kAdditive{UnlitDetail::additive, false, UnlitEnvmapMask::none, false};

TEST(SourceUnlit, BaseTimesColorTimesToneMapScale) {
  UnlitGenericParams p;
  p.modulation = glm::vec4(material_gamma_to_linear(glm::vec3(0.5f, 1.0f, 2.0f)), 0.5f);
  p.tonemap = ToneMapConstants::for_scale(1.25f);
  UnlitTexels<float> t;
  t.base = float4<float>(0.8f, 0.4f, 0.2f, 0.6f);
  const float4<float> c = combine<kBase>(t, p);
  EXPECT_NEAR(c.x, 0.8 * std::pow(128.0 / 255.0, 2.2) * 1.25, 1e-6);
  EXPECT_FLOAT_EQ(c.y, 0.4f * 1.25f);
  EXPECT_FLOAT_EQ(c.z, 0.2f * 2.0f * 1.25f) << "$color above 1 is taken as linear";
  EXPECT_FLOAT_EQ(c.w, 0.6f * 0.5f) << "alpha: $alpha x base alpha, not tone-mapped";
}

TEST(SourceUnlit, VertexColorMultipliesAndVertexAlphaIsOptIn) {
  UnlitGenericParams p;
  UnlitTexels<float> t;
  t.base = float4<float>(0.5f, 0.5f, 0.5f, 0.8f);
  UnlitInputs<float> in;
  in.vertex_color = float4<float>(1.0f, 0.5f, 0.0f, 0.25f);
  float4<float> c = combine<kVertexColor>(t, p, in);
  EXPECT_FLOAT_EQ(c.y, 0.25f);
  EXPECT_FLOAT_EQ(c.z, 0.0f);
  EXPECT_FLOAT_EQ(c.w, 0.8f) << "vertex alpha ignored unless c12.w = 1 ($vertexalpha)";
  p.shader_controls.w = 1.0f;
  c = combine<kVertexColor>(t, p, in);
  EXPECT_FLOAT_EQ(c.w, 0.2f);
}

TEST(SourceUnlit, DetailMod2xIsNeutralAtHalfGreyAndAdditiveAdds) {
  UnlitGenericParams p;
  UnlitTexels<float> t;
  t.base = float4<float>(0.4f, 0.4f, 0.4f, 1.0f);
  t.detail = float4<float>(0.5f, 1.0f, 0.0f, 1.0f);
  float4<float> c = combine<kMod2x>(t, p);
  EXPECT_FLOAT_EQ(c.x, 0.4f);
  EXPECT_FLOAT_EQ(c.y, 0.8f);
  EXPECT_FLOAT_EQ(c.z, 0.0f);
  p.detail_blend.w = 0.5f;  // lerp(1, 2 detail, 0.5)
  c = combine<kMod2x>(t, p);
  EXPECT_FLOAT_EQ(c.y, 0.4f * 1.5f);
  EXPECT_FLOAT_EQ(c.z, 0.4f * 0.5f);
  p.detail_tint = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
  c = combine<kAdditive>(t, p);
  EXPECT_FLOAT_EQ(c.x, 0.4f + 0.5f * 0.5f * 0.5f);
  EXPECT_FLOAT_EQ(c.y, 0.4f + 1.0f * 0.5f * 0.5f);
}

TEST(SourceUnlit, EnvmapReflectsMasksTintsAndSaturates) {
  constexpr UnlitCombo kEnvMask{UnlitDetail::none, true, UnlitEnvmapMask::texture, false};
  constexpr UnlitCombo kEnvBaseAlpha{UnlitDetail::none, true, UnlitEnvmapMask::base_alpha_inverted, false};
  UnlitGenericParams p;
  p.tonemap.c30 = glm::vec4(1.0f, 1.0f, 0.5f, 1.0f);  // ENV_MAP_SCALE 0.5
  p.envmap_tint = glm::vec4(1.0f, 2.0f, 1.0f, 0.0f);
  UnlitTexels<float> t;
  t.base = float4<float>(0.0f, 0.0f, 0.0f, 0.25f);
  t.mask = float3<float>(0.5f, 1.0f, 1.0f);
  UnlitInputs<float> in;
  in.normal = float3<float>(0.0f, 0.0f, 2.0f);
  in.eye_vector = float3<float>(0.0f, 0.0f, 3.0f);  // R = +Z: env (8.1, 0.5, 0.5)
  float4<float> c = combine<kEnvMask>(t, p, in);
  EXPECT_NEAR(c.x, 8.1f * 0.5f * 0.5f, 1e-5f);
  EXPECT_NEAR(c.y, 0.5f * 0.5f * 2.0f, 1e-6f);
  EXPECT_FLOAT_EQ(c.w, 0.25f);
  c = combine<kEnvBaseAlpha>(t, p, in);
  EXPECT_NEAR(c.x, 8.1f * 0.5f * 0.75f, 1e-5f);
  EXPECT_FLOAT_EQ(c.w, 1.0f) << "base alpha is the mask, not opacity";
  // Contrast 1 squares, saturation 0 greys (no fast path on models).
  p.envmap_contrast = glm::vec4(1.0f);
  p.envmap_saturation = glm::vec4(0.0f);
  c = combine<kEnvMask>(t, p, in);
  const float sx = 8.1f * 0.5f * 0.5f, sy = 0.5f, sz = 0.25f;
  const float grey = 0.299f * sx * sx + 0.587f * sy * sy + 0.114f * sz * sz;
  EXPECT_NEAR(c.x, grey, 1e-4f);
  EXPECT_NEAR(c.z, grey, 1e-4f);
}

TEST(SourceUnlit, RealShaderWithTexturesOnBothLanes) {
  using rasterizer::TextureFormat;
  const rasterizer::Texture base = testing::uniform_2d(TextureFormat::RGBA8_sRGB, glm::vec4(0.5f, 0.25f, 1.0f, 1.0f));
  const rasterizer::Texture detail = testing::uniform_2d(TextureFormat::RGBA8, glm::vec4(1.0f, 0.5f, 0.5f, 1.0f));
  const rasterizer::Texture mask = testing::uniform_2d(TextureFormat::RGBA8, glm::vec4(1.0f, 1.0f, 0.0f, 1.0f));
  const rasterizer::Texture cube = testing::face_colored_cube();
  UnlitGenericParams p;
  p.base.texture = &base;
  p.detail.texture = &detail;
  p.envmap_mask.texture = &mask;
  p.envmap.texture = &cube;
  constexpr UnlitCombo C{UnlitDetail::mod2x, true, UnlitEnvmapMask::texture, true};
  auto make = [](auto zero) {
    using L = decltype(zero);
    UnlitInputs<L> in;
    in.base_uv = float2<L>(zero + 0.3f, zero + 0.6f);
    in.detail_uv = float2<L>(zero + 0.1f, zero + 0.9f);
    in.vertex_color = float4<L>(L(1.0f), L(1.0f), L(0.5f), L(1.0f));
    in.normal = float3<L>(L(0.0f), L(0.0f), L(1.0f));
    in.eye_vector = float3<L>(L(0.0f), L(0.0f), L(5.0f));
    return in;
  };
  const float4<float> s = unlit_generic<C>(make(0.0f), p);
  const float4<simd::Float> v = unlit_generic<C>(make(simd::Float(0.0f)), p);
  for (int c = 0; c < 4; ++c)
    for (int l = 0; l < simd::kLanes; ++l) EXPECT_NEAR(testing::lane_of(v[c], l), s[c], 1e-5f);
  // base 0.5 x mod2x(detail 1) = 1.0, + env +Z face (0.4, 0.2, 0.3) x mask (1, 1, 0);
  // blue: 1.0 x mod2x(128/255) x vertex 0.5 (+ 0). 8-bit quantisation of base and detail: 0.01.
  EXPECT_NEAR(s.x, 1.0 + 0.4, 0.01);
  EXPECT_NEAR(s.y, 0.25 * 2.0 * 128.0 / 255.0 + 0.2, 0.01);
  EXPECT_NEAR(s.z, 1.0 * 2.0 * 128.0 / 255.0 * 0.5, 0.01);
}

template <UnlitCombo C>
testing::LaneComparison compare_unlit(int hard_every, uint32_t seed) {
  UnlitGenericParams p;
  p.modulation = glm::vec4(0.9f, 0.7f, 1.2f, 0.8f);
  p.envmap_tint = glm::vec4(0.5f, 0.6f, 0.7f, 0.0f);
  p.envmap_contrast = glm::vec4(0.3f);
  p.envmap_saturation = glm::vec4(0.7f);
  p.detail_blend.w = 0.8f;
  p.shader_controls.w = 1.0f;
  p.tonemap = ToneMapConstants::for_scale(1.1f);
  p.fog = testing::lane_test_fog();
  auto shade = [&]<class L>(const auto& get) -> float4<L> {
    UnlitTexels<L> t;
    t.base = float4<L>(get(0), get(1), get(2), get(3));
    t.detail = float4<L>(get(4), get(5), get(6), get(7));
    t.mask = float3<L>(get(8), get(9), get(10));
    UnlitInputs<L> in;
    in.vertex_color = float4<L>(get(11), get(12), get(13), get(14));
    in.eye_vector = float3<L>(get(15), get(16), get(17));
    in.normal = float3<L>(get(18), get(19), get(20));
    in.fog = FogInputs<L>{get(21), get(22)};
    return unlit_generic_combine<C>(t, in, p, [](const float3<L>& r) { return testing::analytic_env(r); });
  };
  std::vector<Draw> draws(23, Draw{0.0f, 1.0f, hard_every});
  for (int i = 15; i < 21; ++i) draws[i] = Draw{-1.0f, 1.0f, hard_every};
  draws[21] = Draw{-10.0f, 30.0f, hard_every};
  draws[22] = Draw{0.0f, 400.0f, hard_every};
  return compare_lanes<23>(shade, draws, 256, seed);
}

TEST(SourceUnlit, SimdAgreesWithScalarBitForBitForEveryCombo) {
  uint32_t seed = 51;
  for_each_combo<testing::kUnlitSampled>([&]<UnlitCombo C>() {
    const auto random = compare_unlit<C>(0, seed++);
    const auto hard = compare_unlit<C>(3, seed++);
    testing::expect_bit_identical(random, C.name());
    testing::expect_bit_identical(hard, C.name() + " (hard inputs)");
    EXPECT_LE(random.max_step_vs_double, 1) << C.name();
    std::printf("UnlitGeneric %-44s simd-vs-scalar max %d step(s) (hard: %d)\n", C.name().c_str(), random.max_step,
                hard.max_step);
  });
}

TEST(SourceUnlit, EveryComboFitsEveryPixelShaderModel) {
  for (const UnlitCombo& c : kUnlitSpace) {
    EXPECT_TRUE(c.valid()) << c.name();
    for (ShaderModel m : kPixelModels) {
      if (!c.valid(m)) continue;
      const Cost cost = counted_cost(c, m);
      const Verdict v = fits(cost, caps(m));
      EXPECT_TRUE(v) << c.name() << ": " << v.reason << " (" << describe(cost) << ")";
      const int fetches = 1 + (c.detail != UnlitDetail::none) + c.envmap + (c.mask == UnlitEnvmapMask::texture);
      EXPECT_EQ(cost.texture_slots, fetches) << c.name();
    }
  }
  EXPECT_FALSE((UnlitCombo{UnlitDetail::none, false, UnlitEnvmapMask::texture, false}.valid()));
}

}  // namespace
}  // namespace luxel::shading::source
