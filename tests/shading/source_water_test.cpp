// Water: Fresnel blend of reflection and refraction, the depth fades, the normal-map distortion of
// the screen-space coordinates, the reflection exposure of INTEGER HDR (0.25 x scale into an 8-bit
// sRGB target, x4 in the tint) through a real texture, the blurry variant's quirks, SIMD vs
// scalar, and the DX9 budget of every combo.

#include "source_support.hpp"

#include "luxel/shading/source/water.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace luxel::shading::source {
namespace {

using testing::compare_lanes;
using testing::Draw;

constexpr WaterCombo kBoth{true, true, true, false, false};
constexpr WaterCombo kBelow{true, true, false, false, false};
constexpr WaterCombo kBlurry{true, true, true, false, true};

/// Flat water seen from `eye` (tangent space), projective coordinates already divided (w = 1).
WaterInputs<float> flat_inputs(const glm::vec3& eye) {
  WaterInputs<float> in;
  in.tangent_eye = float3<float>(eye.x, eye.y, eye.z);
  in.reflect_refract = float4<float>(0.25f, 0.5f, 0.75f, 0.125f);
  in.w = 1.0f;
  in.proj_z = 0.0f;
  return in;
}

WaterNormalTexels<float> flat_normal() { return {}; }

/// The water with constant render targets: refraction (rgb, depth in alpha), reflection rgb.
template <WaterCombo C>
float4<float> with_constant_targets(const WaterInputs<float>& in, const WaterParams& p, const glm::vec4& refraction,
                                    const glm::vec3& reflection, const WaterNormalTexels<float>& n = {}) {
  return water_combine<C>(
      n, in, p, [&](const float2<float>&) { return float4<float>(refraction.x, refraction.y, refraction.z, refraction.w); },
      [&](const float2<float>&) { return float4<float>(reflection.x, reflection.y, reflection.z, 1.0f); });
}

TEST(SourceWater, FresnelBlendsRefractionToReflectionFromHeadOnToGrazing) {
  WaterParams p;
  p.fog_color = glm::vec4(0.0f);
  const glm::vec4 refraction(0.2f, 0.4f, 0.6f, 0.05f);  // depth 0.05: no fog, and no reflection at all
  const glm::vec3 reflection(1.0f, 0.5f, 0.25f);
  const glm::vec4 deep(0.2f, 0.4f, 0.6f, 1.0f);
  // Head on: F = 0 -> refraction (fogged by sat(depth - 0.05)).
  EXPECT_NEAR(with_constant_targets<kBoth>(flat_inputs({0, 0, 3}), p, refraction, reflection).x, 0.2f, 1e-7f);
  // Grazing, deep: F = 1 -> reflection; shallow (depth 0.05): F faded to 0.
  EXPECT_NEAR(with_constant_targets<kBoth>(flat_inputs({1, 0, 0}), p, deep, reflection).y, 0.5f, 1e-6f);
  EXPECT_NEAR(with_constant_targets<kBoth>(flat_inputs({1, 0, 0}), p, refraction, reflection).y, 0.4f, 1e-6f);
  // 60 degrees from the normal: F = (1 - 0.5)^5 = 1/32; depth 0.1: F x sat(0.05 x 20) = F, fog 0.05.
  p.fog_color = glm::vec4(1.0f, 1.0f, 1.0f, 1.0f);
  p.tonemap = ToneMapConstants::for_scale(2.0f);
  const glm::vec4 mid(0.2f, 0.4f, 0.6f, 0.1f);
  const float4<float> c = with_constant_targets<kBoth>(flat_inputs({std::sqrt(3.0f), 0, 1}), p, mid, reflection);
  const double fog = 0.1 - 0.05, f = 1.0 / 32.0;
  const double refract = 0.2 + (1.0 * 2.0 - 0.2) * fog;  // fog color x LINEAR_LIGHT_SCALE
  EXPECT_NEAR(c.x, refract + (1.0 - refract) * f, 2e-6);
  EXPECT_EQ(c.w, 1.0f);
  // Depth 0.075: the reflection fade is sat(0.025 x 20) = 0.5.
  const float4<float> half = with_constant_targets<kBoth>(flat_inputs({1, 0, 0}), p, glm::vec4(0.2f, 0.4f, 0.6f, 0.075f), reflection);
  const double r2 = 0.2 + (2.0 - 0.2) * 0.025;
  EXPECT_NEAR(half.x, r2 + (1.0 - r2) * 0.5, 2e-6);
}

TEST(SourceWater, BelowWaterFogsByProjectedDepth) {
  WaterParams p;
  p.fog_color = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
  p.fog_params = glm::vec4(100.0f, 400.0f, 1.0f, 0.0f);  // start 100, end 500
  WaterInputs<float> in = flat_inputs({0, 0, 1});
  in.proj_z = 300.0f;
  const float4<float> c = with_constant_targets<kBelow>(in, p, glm::vec4(0.1f, 0.1f, 0.1f, 0.0f), glm::vec3(1.0f));
  EXPECT_NEAR(c.x, 0.1 + (0.5 - 0.1) * 0.5, 1e-6) << "refraction alpha is ignored below water; fog (300-100)/400";
}

TEST(SourceWater, NormalMapShiftsBothCoordinatesByItsXYTimesAlphaTimesAmount) {
  WaterParams p;
  p.reflect_refract_scale = glm::vec4(0.1f, 0.1f, 0.04f, 0.04f);
  WaterNormalTexels<float> n;
  n.n0 = float4<float>(0.75f, 0.25f, 1.0f, 0.5f);  // n.xy = (0.5, -0.5), alpha 0.5
  WaterInputs<float> in = flat_inputs({0, 0, 1});
  in.reflect_refract = float4<float>(0.5f, 1.0f, 1.5f, 0.25f);
  in.w = 2.0f;
  float2<float> reflect_uv, refract_uv, depth_uv;
  int refraction_reads = 0;
  water_combine<kBoth>(
      n, in, p,
      [&](const float2<float>& uv) {
        (refraction_reads++ == 0 ? depth_uv : refract_uv) = uv;
        return float4<float>(0.0f, 0.0f, 0.0f, 0.5f);  // depth 0.5 scales the distortion
      },
      [&](const float2<float>& uv) {
        reflect_uv = uv;
        return float4<float>(0.0f);
      });
  EXPECT_EQ(refraction_reads, 2) << "the undistorted depth read, then the refraction";
  EXPECT_FLOAT_EQ(depth_uv.x, 0.125f);  // refract .wz / w
  EXPECT_FLOAT_EQ(depth_uv.y, 0.75f);
  EXPECT_FLOAT_EQ(reflect_uv.x, 0.25f + 0.5f * 0.5f * 0.1f * 0.5f);
  EXPECT_FLOAT_EQ(reflect_uv.y, 0.5f - 0.5f * 0.5f * 0.1f * 0.5f);
  EXPECT_FLOAT_EQ(refract_uv.x, 0.125f + 0.5f * 0.5f * 0.04f * 0.5f);
  EXPECT_FLOAT_EQ(refract_uv.y, 0.75f - 0.5f * 0.5f * 0.04f * 0.5f);
}

TEST(SourceWater, IntegerHdrReflectionKeepsFourTimesOverbrightThroughAnSrgbTarget) {
  // A reflected surface of linear radiance L, tone-map scale s: the reflection view renders it at
  // 0.25 s into an 8-bit sRGB target; the water reads it back and multiplies by the x4 tint.
  const float s = 1.5f;
  WaterMaterial m;
  m.reflect_tint = glm::vec3(1.0f);
  m.exposure = WaterReflectionExposure::sdk_fixed;
  const WaterParams p = water_constants(m, HdrType::integer, ToneMapConstants::for_scale(s));
  EXPECT_EQ(p.reflect_tint, glm::vec4(4.0f, 4.0f, 4.0f, 1.0f));
  EXPECT_EQ(water_reflection_scale(s, HdrType::integer, m), 0.25f * s);
  EXPECT_EQ(water_reflection_scale(s, HdrType::none, m), s);
  for (float radiance : {0.05f, 0.5f, 1.0f, 2.0f, 2.6f, 5.0f}) {
    rasterizer::Texture target = rasterizer::Texture::create_2d(4, 4, rasterizer::TextureFormat::RGBA8_sRGB, 1);
    const float written = water_reflection_scale(s, HdrType::integer, m) * radiance;  // FinalOutput of the reflection view
    target.upload(0, std::vector<glm::vec4>(16, glm::vec4(written, written, written, 1.0f)));
    WaterParams q = p;
    q.reflection.texture = &target;
    const float4<float> c = water_combine<WaterCombo{true, false, false, false, false}>(
        flat_normal(), flat_inputs({0, 0, 1}), q, [](const float2<float>&) { return float4<float>(0.0f); },
        [&](const float2<float>& uv) { return tex2D(q.reflection, uv); });
    const double expect = std::min(double(s) * radiance, 4.0);
    EXPECT_NEAR(c.x, expect, expect * 0.02 + 4.0 * 0.0005) << "radiance " << radiance << ": s L up to 4, then clipped";
  }
  // LDR: no 0.25, no x4: the reflection clips at 1.
  const WaterParams ldr = water_constants(m, HdrType::none, ToneMapConstants{});
  EXPECT_EQ(ldr.reflect_tint, glm::vec4(1.0f));
  EXPECT_EQ(ldr.fog_params.z, 1.0f);
}

TEST(SourceWater, TintsGoThroughMathlibGammaToLinear) {
  WaterMaterial m;
  m.reflect_tint = glm::vec3(0.5f, 0.96f, 0.0f);
  m.refract_tint = glm::vec3(0.5f, 2.0f, 0.95f);
  m.exposure = WaterReflectionExposure::sdk_fixed;
  const WaterParams p = water_constants(m, HdrType::integer, ToneMapConstants{});
  EXPECT_NEAR(p.reflect_tint.x, 4.0 * std::pow(128.0 / 255.0, 2.2), 1e-6) << "table entry round(0.5 x 255) = 128";
  EXPECT_EQ(p.reflect_tint.y, 4.0f) << "0.95 and up is exactly 1";
  EXPECT_EQ(p.refract_tint.y, 2.0f) << "above 1: taken as linear";
  EXPECT_EQ(p.refract_tint.z, 1.0f);
  EXPECT_EQ(mathlib_gamma_to_linear(-0.1f), 0.0f);
}

TEST(SourceWater, RefractTintAndOverbrightApplyOnlyOnTheBlurryPath) {
  WaterMaterial m;
  m.refract_tint = glm::vec3(0.5f);
  m.exposure = WaterReflectionExposure::sdk_fixed;
  const WaterParams p = water_constants(m, HdrType::integer, ToneMapConstants{});
  const glm::vec4 refraction(0.5f, 0.5f, 0.5f, 0.05f);  // shallow: F = 0 -> pure refraction, no fog
  const float sharp = with_constant_targets<kBoth>(flat_inputs({1, 0, 0}), p, refraction, glm::vec3(0.1f)).x;
  const float blurry = with_constant_targets<kBlurry>(flat_inputs({1, 0, 0}), p, refraction, glm::vec3(0.1f)).x;
  EXPECT_FLOAT_EQ(sharp, 0.5f) << "no refract tint without BLURRY_REFRACT (SDK quirk)";
  EXPECT_NEAR(blurry, 0.5 * std::pow(128.0 / 255.0, 2.2), 1e-6);
  // Grazing and deep: pure reflection. Blurry + INTEGER: x4 tint and x4 overbright = 16.
  const glm::vec4 deep(0.0f, 0.0f, 0.0f, 1.0f);
  EXPECT_NEAR(with_constant_targets<kBoth>(flat_inputs({1, 0, 0}), p, deep, glm::vec3(0.1f)).x, 0.4f, 1e-6f);
  EXPECT_NEAR(with_constant_targets<kBlurry>(flat_inputs({1, 0, 0}), p, deep, glm::vec3(0.1f)).x, 1.6f, 1e-5f);
  const WaterParams fixed = water_constants(m, HdrType::integer, ToneMapConstants{}, false);
  EXPECT_NEAR(with_constant_targets<kBlurry>(flat_inputs({1, 0, 0}), fixed, deep, glm::vec3(0.1f)).x, 0.4f, 1e-6f);
}

TEST(SourceWater, BlurryRefractionAveragesAFiveByFiveGrid) {
  WaterParams p;
  std::vector<float2<float>> taps;
  water_combine<kBlurry>(
      flat_normal(), flat_inputs({0, 0, 1}), p,
      [&](const float2<float>& uv) {
        taps.push_back(uv);
        return float4<float>(0.0f, 0.0f, 0.0f, 1.0f);
      },
      [](const float2<float>&) { return float4<float>(0.0f); });
  ASSERT_EQ(taps.size(), 25u) << "no undistorted depth read on the blurry path";
  EXPECT_NEAR(taps.front().x, 0.125f - 0.01f, 1e-7f);
  EXPECT_NEAR(taps.back().y, 0.75f + 0.01f, 1e-7f);
}

// ---- SIMD vs scalar ---------------------------------------------------------------------------

template <WaterCombo C>
testing::LaneComparison compare_water(int hard_every, uint32_t seed) {
  WaterMaterial m;
  m.reflect_tint = glm::vec3(0.9f, 0.8f, 0.7f);
  m.refract_tint = glm::vec3(0.7f, 0.9f, 0.8f);
  m.fog_color = glm::vec3(0.1f, 0.2f, 0.3f);
  m.refract_amount = 0.05f;
  m.fog_end = 300.0f;
  WaterParams p = water_constants(m, HdrType::integer, ToneMapConstants::for_scale(0.9f));
  p.pixel_fog = testing::lane_test_fog();
  auto shade = [&]<class L>(const auto& get) -> float4<L> {
    WaterNormalTexels<L> t;
    t.n0 = float4<L>(get(0), get(1), get(2), get(3));
    t.n1 = float4<L>(get(4), get(5), get(6), get(7));
    t.n2 = float4<L>(get(8), get(9), get(10), get(11));
    WaterInputs<L> in;
    in.tangent_eye = float3<L>(get(12), get(13), get(14));
    in.reflect_refract = float4<L>(get(15), get(16), get(17), get(18));
    in.w = get(19);
    in.proj_z = get(20);
    in.world_z = get(21);
    // Smooth analytic render targets of the coordinates (alpha = depth in [0, 1]).
    auto refraction = [](const float2<L>& uv) {
      return float4<L>(saturate(uv.x), saturate(uv.y), L(0.5f), saturate(uv.x * 0.5f + uv.y * 0.5f));
    };
    auto reflection = [](const float2<L>& uv) { return float4<L>(saturate(uv.y), L(0.25f), saturate(uv.x), L(1.0f)); };
    return water_combine<C>(t, in, p, refraction, reflection);
  };
  std::vector<Draw> draws(21, Draw{0.0f, 1.0f, hard_every});
  for (int i = 12; i < 15; ++i) draws[i] = Draw{-1.0f, 1.0f, hard_every};
  draws[19] = Draw{0.5f, 2.0f, hard_every};
  draws[20] = Draw{0.0f, 400.0f, hard_every};
  draws.push_back(Draw{-10.0f, 30.0f, hard_every});
  return compare_lanes<22>(shade, draws, 256, seed);
}

TEST(SourceWater, SimdAgreesWithScalarBitForBitForEveryCombo) {
  uint32_t seed = 91;
  for_each_combo<testing::kWaterSampled>([&]<WaterCombo C>() {
    const auto random = compare_water<C>(0, seed++);
    const auto hard = compare_water<C>(3, seed++);
    testing::expect_bit_identical(random, C.name());
    testing::expect_bit_identical(hard, C.name() + " (hard inputs)");
    std::printf("Water %-40s simd-vs-scalar max %d step(s) (hard: %d)\n", C.name().c_str(), random.max_step, hard.max_step);
  });
}

TEST(SourceWater, EveryComboFitsTheModelsItExistsOn) {
  int measured = 0;
  for (const WaterCombo& c : kWaterSpace) {
    for (ShaderModel m : kPixelModels) {
      if (!c.valid(m)) continue;
      const Cost cost = counted_cost(c, m);
      const Verdict v = fits(cost, caps(m));
      EXPECT_TRUE(v) << c.name() << " on " << caps(m).name << ": " << v.reason << " (" << describe(cost) << ")";
      // BLURRY: 25 refraction taps, one normal map read and the reflection where it reflects.
      EXPECT_GE(cost.texture_slots, c.blurry_refract ? (c.reflect ? 27 : 26) : 2) << c.name();
      ++measured;
    }
  }
  EXPECT_FALSE(kBlurry.valid(ShaderModel::ps_2_0)) << "BLURRY_REFRACT is a ps20b combo";
  EXPECT_GT(measured, 15);
}

}  // namespace
}  // namespace luxel::shading::source

namespace luxel::shading::source {
namespace {

/// The reflection through a real 8-bit sRGB target: the view writes scale x radiance (grey), the
/// water reads it back and tints it.
float4<float> reflected(const WaterMaterial& m, float s, float radiance) {
  rasterizer::Texture target = rasterizer::Texture::create_2d(4, 4, rasterizer::TextureFormat::RGBA8_sRGB, 1);
  const float written = water_reflection_scale(s, HdrType::integer, m) * radiance;
  target.upload(0, std::vector<glm::vec4>(16, glm::vec4(written, written, written, 1.0f)));
  WaterParams p = water_constants(m, HdrType::integer, ToneMapConstants::for_scale(s));
  p.reflection.texture = &target;
  return water_combine<WaterCombo{true, false, false, false, false}>(
      WaterNormalTexels<float>{}, flat_inputs({0, 0, 1}), p, [](const float2<float>&) { return float4<float>(0.0f); },
      [&](const float2<float>& uv) { return tex2D(p.reflection, uv); });
}

TEST(SourceWater, ReflectivityExposureRendersTheViewAtScaleTimesTheTintsLargestChannel) {
  WaterMaterial m;
  m.reflect_tint = glm::vec3(0.5f, 0.8f, 0.3f);  // gamma; reflectivity = the green channel's
  EXPECT_EQ(m.exposure, WaterReflectionExposure::reflectivity) << "the default";
  const double t[3] = {std::pow(128.0 / 255.0, 2.2), std::pow(204.0 / 255.0, 2.2), std::pow(77.0 / 255.0, 2.2)};
  const double rho = t[1];
  const float s = 1.5f;
  EXPECT_NEAR(water_reflectivity(m), rho, 1e-6);
  EXPECT_NEAR(water_reflection_scale(s, HdrType::integer, m), s * rho, 1e-6);
  EXPECT_EQ(water_reflection_scale(s, HdrType::none, m), s) << "LDR keeps the frame's exposure";
  const WaterParams p = water_constants(m, HdrType::integer, ToneMapConstants::for_scale(s));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(p.reflect_tint[c], t[c] / rho, 1e-6) << c;
  EXPECT_EQ(p.fog_params.z, 1.0f) << "no x4 to undo";
  // In range (s rho L = 0.46): the water shows t s L, to the target's 8-bit precision.
  const float4<float> in_range = reflected(m, s, 0.5f);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(in_range[c], t[c] * s * 0.5, t[c] * s * 0.5 * 0.01) << c;
  // Past the display's range for green (t_g s L = 1.1): green shows exactly 1, where the
  // display clips it anyway; red and blue stop at t / rho.
  const float4<float> over = reflected(m, s, 1.2f);
  EXPECT_FLOAT_EQ(over.y, 1.0f);
  EXPECT_NEAR(over.x, t[0] / rho, 1e-6);
  // The SDK's pair keeps the 4x headroom instead: red is still t_r s L there.
  WaterMaterial fixed = m;
  fixed.exposure = WaterReflectionExposure::sdk_fixed;
  EXPECT_NEAR(water_reflection_scale(s, HdrType::integer, fixed), 0.25 * s, 1e-7);
  EXPECT_NEAR(reflected(fixed, s, 1.2f).x, t[0] * s * 1.2, t[0] * s * 1.2 * 0.01);
}

TEST(SourceWater, IntegerSdkPathClampsTintsAboveOneLdrAndReflectivityDoNot) {
  WaterMaterial m;
  m.reflect_tint = glm::vec3(2.0f, 0.5f, 2.0f);  // red and blue above 1: linear as authored
  const double g = std::pow(128.0 / 255.0, 2.2);
  const WaterParams ldr = water_constants(m, HdrType::none, ToneMapConstants{});
  EXPECT_EQ(ldr.reflect_tint.x, 2.0f) << "BaseVSShader passes values above 1 through";
  WaterMaterial fixed = m;
  fixed.exposure = WaterReflectionExposure::sdk_fixed;
  const WaterParams integer = water_constants(fixed, HdrType::integer, ToneMapConstants{});
  EXPECT_EQ(integer.reflect_tint.x, 4.0f) << "mathlib GammaToLinear: 1 from 0.95 up, then x4";
  EXPECT_NEAR(integer.reflect_tint.y, 4.0 * g, 1e-6);
  // Net gain of the red channel (tint x the view's exposure / s): LDR 2, INTEGER sdk_fixed 1.
  EXPECT_NEAR(integer.reflect_tint.x * water_reflection_scale(1.0f, HdrType::integer, fixed), 1.0, 1e-7);
  const WaterParams by_reflectivity = water_constants(m, HdrType::integer, ToneMapConstants{});
  EXPECT_NEAR(by_reflectivity.reflect_tint.x * water_reflection_scale(1.0f, HdrType::integer, m), 2.0, 1e-6);
  EXPECT_NEAR(by_reflectivity.reflect_tint.y * water_reflection_scale(1.0f, HdrType::integer, m), g, 1e-6);
}

}  // namespace
}  // namespace luxel::shading::source
