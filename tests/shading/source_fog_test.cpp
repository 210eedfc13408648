// Fog (fog.hpp): range fog f² at an intermediate depth and at its density cap, height fog through
// a water plane, ps_2_0's fixed-function vertex fog, which models have which, and that every
// fogged pixel shader blends its own unfogged color. Expected values are the SDK's formulas
// written out in double.

#include "source_support.hpp"

#include "luxel/shading/source/fog.hpp"
#include "luxel/shading/source/lightmapped_generic.hpp"
#include "luxel/shading/source/unlit_generic.hpp"
#include "luxel/shading/source/vertexlit_generic.hpp"
#include "luxel/shading/source/water.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace luxel::shading::source {
namespace {

// start 100, end 600 (range 500), cap 0.8, a blue-green fog, tone-map scale 1.5.
FogSettings test_settings() {
  FogSettings s;
  s.start = 100.0f;
  s.end = 600.0f;
  s.max_density = 0.8f;
  s.color = glm::vec3(0.2f, 0.45f, 0.9f);
  s.water_z = 5.0f;
  return s;
}
constexpr double kScale = 1.5;
const glm::vec3 kFogTestEye(0.0f, 0.0f, 20.0f);
const float4<float> kColor(0.6f, 0.3f, 0.1f, 0.7f);

double clamp01(double x) { return std::clamp(x, 0.0, 1.0); }

/// The expected fogged channel: the tone-mapped color blended toward fog x scale by `amount`.
double blended(int c, double amount) {
  const double shaded = kColor[c] * kScale;
  const double fog = test_settings().color[c] * kScale;
  return shaded + (fog - shaded) * amount;
}

float4<float> fogged(Fog f, float world_z, float proj_z) {
  const FogConstants fog = fog_constants(test_settings(), kFogTestEye, float(kScale));
  const ToneMapConstants tm = ToneMapConstants::for_scale(float(kScale));
  const FogInputs<float> in{world_z, proj_z};
  switch (f) {
    case Fog::range: return fogged_output<ToneMap::linear, Fog::range>(kColor, tm, in, fog);
    case Fog::height: return fogged_output<ToneMap::linear, Fog::height>(kColor, tm, in, fog);
    case Fog::vertex_range: return fogged_output<ToneMap::linear, Fog::vertex_range>(kColor, tm, in, fog);
    default: return fogged_output<ToneMap::linear, Fog::none>(kColor, tm, in, fog);
  }
}

TEST(SourceFog, RangeFogSquaresTheFactorAndCapsItAtMaxDensity) {
  // projZ 350: f = 350/500 - 100/500 = 0.5, under the cap; blended by f² = 0.25.
  const float4<float> mid = fogged(Fog::range, 0.0f, 350.0f);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(mid[c], blended(c, 0.25), 1e-6) << c;
  EXPECT_EQ(mid.w, 0.7f) << "fog leaves alpha alone";
  // projZ 550: f = 0.9, capped at 0.8, blended by 0.64.
  const float4<float> far = fogged(Fog::range, 0.0f, 550.0f);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(far[c], blended(c, 0.64), 1e-6) << c;
  // Before the start: f < 0, saturated to 0.
  const float4<float> near = fogged(Fog::range, 0.0f, 60.0f);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(near[c], blended(c, 0.0), 1e-6) << c;
}

TEST(SourceFog, HeightFogIsTheUnderwaterPartOfTheSegmentLinearly) {
  // Eye z 20, water z 5, point z -10: half the eye-to-point segment is under water (15 of 30);
  // f = 0.5 x 240 / 500 = 0.24, blended linearly.
  const float4<float> under = fogged(Fog::height, -10.0f, 240.0f);
  const double f = clamp01(clamp01((5.0 - -10.0) / (20.0 - -10.0)) * 240.0 / 500.0);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(under[c], blended(c, f), 1e-6) << c;
  // A point above the water plane gets none, however far.
  const float4<float> above = fogged(Fog::height, 8.0f, 5000.0f);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(above[c], blended(c, 0.0), 1e-6) << c;
}

TEST(SourceFog, Ps20RangeFogIsFixedFunctionByTheVertexFactor) {
  EXPECT_FALSE(fog_valid(Fog::range, ShaderModel::ps_2_0)) << "CalcRangeFog returns 0 on ps_2_0";
  EXPECT_TRUE(fog_valid(Fog::vertex_range, ShaderModel::ps_2_0));
  EXPECT_FALSE(fog_valid(Fog::vertex_range, ShaderModel::ps_2_b));
  for (ShaderModel m : kPixelModels) EXPECT_TRUE(fog_valid(Fog::height, m)) << caps(m).name;
  EXPECT_EQ(range_fog_for_model(ShaderModel::ps_2_0), Fog::vertex_range);
  EXPECT_EQ(range_fog_for_model(ShaderModel::ps_3_0), Fog::range);
  // The pixel shader leaves the color as the unfogged combo does.
  const float4<float> shader = fogged(Fog::vertex_range, 0.0f, 350.0f);
  const float4<float> none = fogged(Fog::none, 0.0f, 350.0f);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(shader[c], none[c]);
  // Vertex visibility max(1 - 0.8, (600 - z) / 500): z = 350 -> 0.5, z = 590 -> 0.02 -> 0.2.
  const glm::vec4 c16 = vertex_fog_constant(test_settings());
  EXPECT_NEAR(vertex_fog<float>(350.0f, c16), 0.5, 1e-6);
  EXPECT_NEAR(vertex_fog<float>(590.0f, c16), 0.2, 1e-6);
  EXPECT_NEAR(vertex_fog<float>(20.0f, c16), (600.0 - 20.0) / 500.0, 1e-6) << "> 1 before the start: the fog unit clamps";
  // The fog unit: v rgb + (1 - v) fog; v clamped to [0, 1].
  const FogConstants fog = fog_constants(test_settings(), kFogTestEye, float(kScale));
  const float4<float> out = fixed_function_fog(shader, vertex_fog<float>(350.0f, c16), fog);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(out[c], 0.5 * kColor[c] * kScale + 0.5 * test_settings().color[c] * kScale, 1e-6);
  const float4<float> clear = fixed_function_fog(shader, vertex_fog<float>(20.0f, c16), fog);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(clear[c], kColor[c] * kScale, 1e-6) << "visibility above 1 is clear";
}

TEST(SourceFog, NoFogByDefault) {
  const FogConstants fog = fog_constants(FogSettings{}, kFogTestEye);
  const FogInputs<float> in{-100.0f, 1e6f};
  const float4<float> c = fogged_output<ToneMap::none, Fog::range>(kColor, ToneMapConstants{}, in, fog);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(c[i], kColor[i]) << "max density 0";
  EXPECT_EQ(vertex_fog<float>(1e6f, vertex_fog_constant(FogSettings{})), 1.0f) << "vertex visibility floor 1 - 0";
}

// Every pixel shader's fog combo is its unfogged combo's color blended by the fog formula.
template <class Shade>
void expect_shader_fogs(const char* name, Shade&& shade) {
  const FogConstants fog = fog_constants(test_settings(), kFogTestEye, float(kScale));
  const FogInputs<float> at{-10.0f, 350.0f};
  const float4<float> plain = shade(Fog::none, fog, at);
  const float4<float> range = shade(Fog::range, fog, at);
  const float4<float> height = shade(Fog::height, fog, at);
  const double f_height = clamp01(clamp01(15.0 / 30.0) * 350.0 / 500.0);
  for (int c = 0; c < 3; ++c) {
    const double fc = test_settings().color[c] * kScale;
    EXPECT_NEAR(range[c], plain[c] + (fc - plain[c]) * 0.25, 1e-5) << name << " range, channel " << c;
    EXPECT_NEAR(height[c], plain[c] + (fc - plain[c]) * f_height, 1e-5) << name << " height, channel " << c;
  }
  EXPECT_GT(std::abs(range.x - plain.x), 1e-3) << name << ": the test point is fogged";
}

template <template <Fog> class Pick>
auto by_fog(Fog f, const auto& call) {
  switch (f) {
    case Fog::range: return call.template operator()<Pick<Fog::range>::value>();
    case Fog::height: return call.template operator()<Pick<Fog::height>::value>();
    default: return call.template operator()<Pick<Fog::none>::value>();
  }
}

template <Fog F>
struct LightmappedWithFog {
  static constexpr LightmappedCombo value{true, true, EnvmapMask::normal_alpha, EnvmapPath::full, F};
};
template <Fog F>
struct UnlitWithFog {
  static constexpr UnlitCombo value{UnlitDetail::none, false, UnlitEnvmapMask::none, false, true, F};
};
template <Fog F>
struct VertexLitWithFog {
  static constexpr VertexLitCombo value{2, true, false, false, true, false, false, F};
};
template <Fog F>
struct WaterWithFog {
  static constexpr WaterCombo value{true, true, true, false, false, F};
};

TEST(SourceFog, EveryFoggedPixelShaderBlendsItsOwnColor) {
  expect_shader_fogs("LightmappedGeneric", [](Fog f, const FogConstants& fog, const FogInputs<float>& at) {
    LightmappedGenericParams p;
    p.fog = fog;
    p.tonemap = ToneMapConstants::for_scale(float(kScale));
    LightmappedTexels<float> t;
    t.base = float4<float>(0.7f, 0.5f, 0.3f, 1.0f);
    t.bump = float4<float>(0.6f, 0.45f, 0.9f, 0.5f);
    for (int i = 0; i < 4; ++i) t.lightmap[i] = float3<float>(0.4f * (i + 1), 0.3f, 0.2f);
    LightmappedInputs<float> in;
    in.tangent = float3<float>(1, 0, 0);
    in.binormal = float3<float>(0, 1, 0);
    in.normal = float3<float>(0, 0, 1);
    in.eye_vector = float3<float>(0.3f, 0.2f, 1.0f);
    in.fog = at;
    return by_fog<LightmappedWithFog>(f, [&]<LightmappedCombo C>() {
      return lightmapped_generic_combine<C>(t, in, p, [](const float3<float>& r) { return testing::analytic_env(r); });
    });
  });
  expect_shader_fogs("UnlitGeneric (vertex lit)", [](Fog f, const FogConstants& fog, const FogInputs<float>& at) {
    UnlitGenericParams p;
    p.fog = fog;
    p.tonemap = ToneMapConstants::for_scale(float(kScale));
    UnlitTexels<float> t;
    t.base = float4<float>(0.7f, 0.5f, 0.3f, 1.0f);
    UnlitInputs<float> in;
    in.vertex_color = float4<float>(0.9f, 0.6f, 0.4f, 1.0f);
    in.fog = at;
    return by_fog<UnlitWithFog>(f, [&]<UnlitCombo C>() {
      return unlit_generic_combine<C>(t, in, p, [](const float3<float>& r) { return r; });
    });
  });
  expect_shader_fogs("VertexLitGeneric", [](Fog f, const FogConstants& fog, const FogInputs<float>& at) {
    VertexLitParams p;
    p.fog = fog;
    p.tonemap = ToneMapConstants::for_scale(float(kScale));
    p.ambient.color.fill(glm::vec3(0.3f, 0.2f, 0.1f));
    VertexLitTexels<float> t;
    t.base = float4<float>(0.7f, 0.5f, 0.3f, 1.0f);
    VertexLitInputs<float> in;
    in.normal = float3<float>(0, 0, 1);
    in.tangent = float3<float>(1, 0, 0);
    in.binormal = float3<float>(0, 1, 0);
    in.world_pos = float3<float>(0.0f, 0.0f, at.world_z);
    in.proj_z = at.proj_z;
    return by_fog<VertexLitWithFog>(f, [&]<VertexLitCombo C>() { return vertexlit_combine<C>(t, in, p); });
  });
  expect_shader_fogs("Water", [](Fog f, const FogConstants& fog, const FogInputs<float>& at) {
    WaterParams p;
    p.pixel_fog = fog;
    WaterInputs<float> in;
    in.tangent_eye = float3<float>(0.5f, 0.0f, 1.0f);
    in.reflect_refract = float4<float>(0.25f, 0.5f, 0.75f, 0.125f);
    in.w = 1.0f;
    in.proj_z = at.proj_z;
    in.world_z = at.world_z;
    auto target = [](const float2<float>& uv) { return float4<float>(uv.x, uv.y, 0.5f, 0.6f); };
    return by_fog<WaterWithFog>(f, [&]<WaterCombo C>() {
      return water_combine<C>(WaterNormalTexels<float>{}, in, p, target, target);
    });
  });
}

}  // namespace
}  // namespace luxel::shading::source
