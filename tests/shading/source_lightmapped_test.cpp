// The tone-map epilogue and LightmappedGeneric: closed-form cases, the fast-path quirk, LDR
// lightmap encoding, SIMD vs scalar on random and hard inputs, and every combo's DX9 budget.

#include "source_support.hpp"

#include "luxel/shading/source/lightmapped_generic.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace luxel::shading::source {
namespace {

using testing::compare_lanes;
using testing::Draw;

// ---- Epilogue ---------------------------------------------------------------------------------

TEST(SourceEpilogue, LinearToneMapScalesRgbOnly) {
  const ToneMapConstants tm = ToneMapConstants::for_scale(2.0f);
  const float4<float> c = final_output<ToneMap::linear>(float4<float>(0.25f, 0.5f, 1.0f, 0.5f), tm);
  EXPECT_FLOAT_EQ(c.x, 0.5f);
  EXPECT_FLOAT_EQ(c.z, 2.0f);
  EXPECT_FLOAT_EQ(c.w, 0.5f);
  const float4<float> g = final_output<ToneMap::gamma>(float4<float>(1.0f), tm);
  EXPECT_NEAR(g.x, std::pow(2.0f, 1.0f / 2.2f), 1e-6f);
  const float4<float> n = final_output<ToneMap::none>(float4<float>(3.0f), tm);
  EXPECT_EQ(n.x, 3.0f);
}

TEST(SourceEpilogue, Srgb8MatchesTheExactCurveOnBothLanes) {
  int worst = 0;
  for (int i = 0; i <= 100000; ++i) {
    const float x = i / 100000.0f;
    const float b = encode_srgb8(float4<float>(x)).x;
    worst = std::max(worst, std::abs(static_cast<int>(b) - srgb8_reference(x)));
  }
  EXPECT_LE(worst, 1) << "within one step of the double-precision curve";
  const auto v = simd::lanes<simd::Float>([](int l) { return l / float(simd::kLanes - 1); });
  const float4<simd::Float> s = encode_srgb8(float4<simd::Float>(v));
  for (int l = 0; l < simd::kLanes; ++l) {
    EXPECT_EQ(testing::lane_of(s.x, l), encode_srgb8(float4<float>(l / float(simd::kLanes - 1))).x);
  }
}

TEST(SourceEpilogue, NaNAndInfinitiesGiveDefinedBytes) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const float4<float> b = encode_srgb8(float4<float>(nan, inf, -inf, nan));
  EXPECT_EQ(b.x, 0.0f) << "NaN -> 0 (saturate(NaN) = 0), as the output merger writes NaN";
  EXPECT_EQ(b.y, 255.0f);
  EXPECT_EQ(b.z, 0.0f);
  EXPECT_EQ(b.w, 0.0f);
  EXPECT_EQ(encode_srgb8(float4<float>(1000.0f)).x, 255.0f) << "HDR above 1 clips";
}

// ---- LightmappedGeneric closed forms ----------------------------------------------------------

template <LightmappedCombo C>
float4<float> combine(const LightmappedTexels<float>& t, const LightmappedGenericParams& p,
                      const LightmappedInputs<float>& in = {}) {
  return lightmapped_generic_combine<C>(t, in, p, [](const float3<float>& r) { return testing::analytic_env(r); });
}

constexpr LightmappedCombo kBump{true, false, EnvmapMask::none, EnvmapPath::fast};
constexpr LightmappedCombo kFlat{false, false, EnvmapMask::none, EnvmapPath::fast};

TEST(SourceLightmapped, FlatBumpTexelAveragesTheThreeLightmaps) {
  LightmappedGenericParams p;
  p.tint_lightmap_scale = glm::vec4(2.0f, 2.0f, 2.0f, 1.0f);
  LightmappedTexels<float> t;
  t.bump = float4<float>(0.5f, 0.5f, 1.0f, 1.0f);  // n = (0, 0, 1): each weight (1/√3)² = 1/3
  t.lightmap[1] = float3<float>(0.3f, 0.0f, 0.0f);
  t.lightmap[2] = float3<float>(0.0f, 0.6f, 0.0f);
  t.lightmap[3] = float3<float>(0.0f, 0.0f, 0.9f);
  const float4<float> c = combine<kBump>(t, p);
  EXPECT_NEAR(c.x, 0.2f, 1e-6f);
  EXPECT_NEAR(c.y, 0.4f, 1e-6f);
  EXPECT_NEAR(c.z, 0.6f, 1e-6f);
}

TEST(SourceLightmapped, NormalAlongABasisVectorSeesOnlyItsLightmap) {
  LightmappedGenericParams p;
  for (int i = 0; i < 3; ++i) {
    LightmappedTexels<float> t;
    t.bump = float4<float>(kBumpBasis[i][0] * 0.5f + 0.5f, kBumpBasis[i][1] * 0.5f + 0.5f, kBumpBasis[i][2] * 0.5f + 0.5f, 1.0f);
    for (int k = 0; k < 3; ++k) t.lightmap[k + 1] = float3<float>(k == 0 ? 1.0f : 0.0f, k == 1 ? 1.0f : 0.0f, k == 2 ? 1.0f : 0.0f);
    const float4<float> c = combine<kBump>(t, p);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k], k == i ? 1.0f : 0.0f, 1e-6f) << "basis " << i;
  }
}

TEST(SourceLightmapped, FlatPathIsLightmapTimesC12TimesBase) {
  LightmappedGenericParams p;
  p.tint_lightmap_scale = glm::vec4(1.0f, 0.5f, 2.0f, 0.75f);
  p.tonemap = ToneMapConstants::for_scale(1.5f);
  LightmappedTexels<float> t;
  t.base = float4<float>(0.5f, 1.0f, 0.25f, 0.5f);
  t.lightmap[0] = float3<float>(2.0f, 2.0f, 2.0f);
  const float4<float> c = combine<kFlat>(t, p);
  EXPECT_FLOAT_EQ(c.x, 0.5f * 2.0f * 1.0f * 1.5f);
  EXPECT_FLOAT_EQ(c.y, 1.0f * 2.0f * 0.5f * 1.5f);
  EXPECT_FLOAT_EQ(c.z, 0.25f * 2.0f * 2.0f * 1.5f);
  EXPECT_FLOAT_EQ(c.w, 0.5f * 0.75f);
}

TEST(SourceLightmapped, NormalFacingAwayFromEveryBasisIsNaNAndEncodesBlack) {
  // n = (0, 0, -1): every sat(dot) is 0, the SDK divides 0 by 0. Defined result: byte 0.
  LightmappedGenericParams p;
  LightmappedTexels<float> t;
  t.bump = float4<float>(0.5f, 0.5f, 0.0f, 1.0f);
  t.lightmap[1] = t.lightmap[2] = t.lightmap[3] = float3<float>(1.0f);
  const float4<float> c = combine<kBump>(t, p);
  EXPECT_TRUE(std::isnan(c.x));
  EXPECT_EQ(encode_srgb8(c).x, 0.0f);
}

TEST(SourceLightmapped, EnvmapReflectsAndMasksWithInvertedBaseAlpha) {
  constexpr LightmappedCombo kEnv{false, true, EnvmapMask::base_alpha_inverted, EnvmapPath::fast};
  LightmappedGenericParams p;
  p.tonemap.c30 = glm::vec4(1.0f, 1.0f, 0.5f, 1.0f);  // ENV_MAP_SCALE 0.5
  LightmappedTexels<float> t;
  t.base = float4<float>(0.0f, 0.0f, 0.0f, 0.25f);
  LightmappedInputs<float> in;
  in.normal = float3<float>(0.0f, 0.0f, 2.0f);  // unnormalised: R's direction does not care
  in.eye_vector = float3<float>(0.0f, 0.0f, 3.0f);
  const float4<float> c = combine<kEnv>(t, p, in);
  // R = (0,0,+): env = (8.1, 0.5, 0.5); x 0.5 x (1 - 0.25)
  EXPECT_NEAR(c.x, 8.1f * 0.5f * 0.75f, 1e-5f);
  EXPECT_NEAR(c.y, 0.5f * 0.5f * 0.75f, 1e-6f);
}

TEST(SourceLightmapped, FresnelContrastAndSaturationOnTheFullPath) {
  constexpr LightmappedCombo kFull{false, true, EnvmapMask::none, EnvmapPath::full};
  LightmappedGenericParams p;
  p.envmap_contrast_saturation = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);  // spec², then full grey
  p.fresnel = fresnel_constant(0.25f);
  LightmappedTexels<float> t;
  t.base = float4<float>(0.0f, 0.0f, 0.0f, 1.0f);
  LightmappedInputs<float> in;
  in.normal = float3<float>(0.0f, 0.0f, 1.0f);
  in.eye_vector = float3<float>(0.0f, 0.0f, 1.0f);  // head on: Fresnel = R0
  const float4<float> c = combine<kFull>(t, p, in);
  const float grey = 0.299f * 8.1f * 8.1f + 0.587f * 0.25f + 0.114f * 0.25f;
  EXPECT_NEAR(c.x, grey * 0.25f, 1e-4f);
  EXPECT_NEAR(c.y, grey * 0.25f, 1e-4f);
  // Grazing: N·Ê = 0 -> Fresnel 1.
  in.eye_vector = float3<float>(1.0f, 0.0f, 0.0f);
  const float4<float> g = combine<kFull>(t, p, in);
  EXPECT_TRUE(std::isfinite(g.x));
}

TEST(SourceLightmapped, FastPathQuirkIsOnByDefault) {
  LightmappedMaterial m;
  m.envmap = true;
  m.envmap_contrast = 0.5f;  // default saturation: Valve's helper stays on the fast path
  EXPECT_EQ(choose_lightmapped_combo(m).path, EnvmapPath::fast);
  EXPECT_EQ(choose_lightmapped_combo(m, false).path, EnvmapPath::full);
  m.envmap_contrast = 1.0f;
  EXPECT_EQ(choose_lightmapped_combo(m).path, EnvmapPath::fast_contrast);
  m.envmap_contrast = 0.0f;
  m.envmap_saturation = 0.5f;  // ignored with contrast 0
  EXPECT_EQ(choose_lightmapped_combo(m).path, EnvmapPath::fast);
  EXPECT_EQ(choose_lightmapped_combo(m, false).path, EnvmapPath::full);
  m.envmap_contrast = 0.5f;
  EXPECT_EQ(choose_lightmapped_combo(m).path, EnvmapPath::full);
  m = {};
  m.envmap = true;
  m.fresnel_reflection = 0.2f;
  EXPECT_EQ(choose_lightmapped_combo(m).path, EnvmapPath::full);
  m.mask = EnvmapMask::texture;  // with a bump map the helper drops $envmapmask
  EXPECT_EQ(choose_lightmapped_combo(m).mask, EnvmapMask::none);
  for (const LightmappedCombo& c : kLightmappedCombos) EXPECT_TRUE(c.valid()) << c.name();
}

TEST(SourceLightmapped, LdrLightmapRoundTripThroughSrgbRead) {
  // VRAD encodes 0.5 L^(1/2.2); the sampler decodes exact sRGB; c12 multiplies by 2^2.2.
  // The sRGB curve is not the 2.2 power, so the round trip is off by a few percent at the
  // dark end: measured, not hidden.
  auto srgb_decode8 = [](double s) { return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4); };
  double worst_raw = 0.0, worst = 0.0;
  for (float L : {0.05f, 0.1f, 0.25f, 0.5f, 1.0f, 2.0f, 3.5f}) {
    const auto e = encode_ldr_lightmap(glm::vec3(L));
    const double raw = srgb_decode8(e[0] / 255.0) * lightmap_scale_factor(LightmapFormat::ldr_srgb8);
    worst_raw = std::max(worst_raw, std::abs(raw - L) / L);
    const double upload = ldr_lightmap_upload_value(e)[0];  // stored as 8-bit sRGB, decoded on read
    const double decoded = srgb_decode8(srgb8_reference(upload) / 255.0) * lightmap_scale_factor(LightmapFormat::ldr_srgb8);
    worst = std::max(worst, std::abs(decoded - L) / L);
  }
  std::printf("LDR lightmap round trip: worst relative error %.3f (VRAD bytes read as sRGB: %.3f)\n", worst, worst_raw);
  EXPECT_GT(worst_raw, 0.2) << "reading VRAD's bytes as sRGB is visibly wrong in the dark";
  EXPECT_LT(worst, 0.05);
  EXPECT_EQ(lightmap_scale_factor(LightmapFormat::hdr_float16), 1.0f);
  const auto big = encode_ldr_lightmap(glm::vec3(100.0f, 1.0f, 0.0f));
  EXPECT_LE(big[0], 255);
  EXPECT_EQ(big[2], 0);
}

// ---- SIMD vs scalar ---------------------------------------------------------------------------

template <LightmappedCombo C>
testing::LaneComparison compare_lightmapped(int hard_every, uint32_t seed) {
  LightmappedGenericParams p;
  p.tint_lightmap_scale = glm::vec4(1.3f, 1.0f, 0.8f, 1.0f);
  p.envmap_contrast_saturation = glm::vec4(0.4f, 0.6f, 0.0f, 0.0f);
  p.fresnel = fresnel_constant(0.1f);
  p.tonemap = ToneMapConstants::for_scale(0.8f, 1.0f, 1.0f);
  p.fog = testing::lane_test_fog();
  auto shade = [&]<class L>(const auto& get) -> float4<L> {
    LightmappedTexels<L> t;
    t.base = float4<L>(get(0), get(1), get(2), get(3));
    t.bump = float4<L>(get(4), get(5), get(6), get(7));
    t.mask = float3<L>(get(8), get(9), get(10));
    for (int k = 0; k < 4; ++k) t.lightmap[k] = float3<L>(get(11 + 3 * k), get(12 + 3 * k), get(13 + 3 * k));
    LightmappedInputs<L> in;
    in.tangent = float3<L>(get(23), get(24), get(25));
    in.binormal = float3<L>(get(26), get(27), get(28));
    in.normal = float3<L>(get(29), get(30), get(31));
    in.eye_vector = float3<L>(get(32), get(33), get(34));
    in.fog = FogInputs<L>{get(35), get(36)};
    return lightmapped_generic_combine<C>(t, in, p, [](const float3<L>& r) { return testing::analytic_env(r); });
  };
  std::vector<Draw> draws(37, Draw{0.0f, 1.0f, hard_every});
  for (int i = 11; i < 23; ++i) draws[i] = Draw{0.0f, 4.0f, hard_every};
  for (int i = 23; i < 35; ++i) draws[i] = Draw{-1.0f, 1.0f, hard_every};
  draws[35] = Draw{-10.0f, 30.0f, hard_every};
  draws[36] = Draw{0.0f, 400.0f, hard_every};
  return compare_lanes<37>(shade, draws, 256, seed);
}

TEST(SourceLightmapped, SimdWithinOneStepOfScalarForEveryCombo) {
  uint32_t seed = 11;
  for_each_lightmapped_combo([&]<LightmappedCombo C>() {
    const auto random = compare_lightmapped<C>(0, seed++);
    const auto hard = compare_lightmapped<C>(3, seed++);
    EXPECT_LE(random.max_step, 1) << C.name();
    EXPECT_LE(hard.max_step, 1) << C.name() << " (hard inputs)";
    EXPECT_LE(random.max_step_vs_double, 1) << C.name() << ": the lane encode vs the exact curve";
    std::printf("LightmappedGeneric %-40s simd-vs-scalar max %d step(s) (hard: %d), PSNR %s\n", C.name().c_str(),
                random.max_step, hard.max_step, std::isinf(random.psnr()) ? "inf (bit-identical)" : "finite");
  });
}

// ---- Budgets ----------------------------------------------------------------------------------

TEST(SourceLightmapped, EveryComboFitsEveryPixelShaderModel) {
  for_each_lightmapped_combo([&]<LightmappedCombo C>() {
    for (ShaderModel m : kPixelModels) {
      if (!C.valid(m)) continue;
      const Cost cost = measure_lightmapped_generic<C>(m);
      const Verdict v = fits(cost, caps(m));
      EXPECT_TRUE(v) << C.name() << ": " << v.reason << " (" << describe(cost) << ")";
      EXPECT_GE(cost.texture_slots, C.bump ? 5 : 2) << C.name();
    }
  });
}

}  // namespace
}  // namespace luxel::shading::source
