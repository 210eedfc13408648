// VertexLitGeneric: ambient cube, local lights (point, spot inside and between its cones,
// directional) with the SDK's attenuation, squared Half-Lambert, Phong at intermediate Fresnel
// values on the skin shader's full and fast paths, the exponent's and the tint's choices,
// $basemapalphaphongmask, boost and rim (masked and not) against double math;
// light folding into the ambient cube; SIMD vs scalar on random and hard inputs; every combo's
// DX9 budget; the ambient cube's count beside Valve's published ones.

#include "phong_reference.hpp"
#include "source_support.hpp"

#include "luxel/shading/source/light_folding.hpp"
#include "luxel/shading/source/vertexlit_generic.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace luxel::shading::source {
namespace {

using testing::compare_lanes;
using testing::Draw;

AmbientCube test_cube() {
  AmbientCube c;
  c.color = {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1), glm::vec3(1, 1, 0), glm::vec3(0, 1, 1),
             glm::vec3(1, 0, 1)};
  return c;
}

template <VertexLitCombo C>
float4<float> shade(const VertexLitParams& p, const float3<float>& pos, const float3<float>& normal,
                    const VertexLitTexels<float>& t = {}) {
  VertexLitInputs<float> in;
  in.world_pos = pos;
  in.normal = normal;
  in.tangent = float3<float>(1.0f, 0.0f, 0.0f);
  in.binormal = float3<float>(0.0f, 1.0f, 0.0f);
  return vertexlit_combine<C>(t, in, p);
}

constexpr VertexLitCombo kAmbientOnly{0, false, false, false, true, true};
constexpr VertexLitCombo kTwoLights{2, false, false, false, true, true};
constexpr VertexLitCombo kTwoLambert{2, false, false, false, false, true};

TEST(SourceVertexLit, AmbientCubeAxisNormalsAndDiagonal) {
  VertexLitParams p;
  p.ambient = test_cube();
  for (int j = 0; j < 6; ++j) {
    float3<float> n(0.0f);
    n[j / 2] = (j % 2 == 0) ? 2.0f : -2.0f;  // not unit: the shader normalizes
    const float4<float> c = shade<kAmbientOnly>(p, float3<float>(0.0f), n);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k], p.ambient.color[j][k], 1e-6f) << "side " << j;
  }
  const float4<float> d = shade<kAmbientOnly>(p, float3<float>(0.0f), float3<float>(1.0f, -1.0f, 0.0f));
  EXPECT_NEAR(d.x, 0.5f * 1 + 0.5f * 1, 1e-6f);  // +X red + -Y yellow
  EXPECT_NEAR(d.y, 0.5f, 1e-6f);
  const float4<float> zero = shade<kAmbientOnly>(p, float3<float>(0.0f), float3<float>(0.0f));
  EXPECT_EQ(zero.x, 0.0f) << "zero-length normal: normalize(0) = 0, no ambient";
}

TEST(SourceVertexLit, PointLightAttenuationAndHalfLambert) {
  VertexLitParams p;
  LightDesc d;
  d.position = glm::vec3(0.0f, 0.0f, 10.0f);
  d.color = glm::vec3(100.0f);
  d.attenuation = glm::vec3(1.0f, 0.5f, 0.02f);
  p.lights[0] = to_local_light(d);
  const float expected_atten = 100.0f / (1.0f + 5.0f + 2.0f);
  // N·L = 1: half-Lambert 1. N·L = -1: 0. N ⟂ L: 0.25.
  EXPECT_NEAR(shade<kTwoLights>(p, float3<float>(0.0f), float3<float>(0, 0, 1)).x, expected_atten, 1e-4f);
  EXPECT_NEAR(shade<kTwoLights>(p, float3<float>(0.0f), float3<float>(0, 0, -1)).x, 0.0f, 1e-6f);
  EXPECT_NEAR(shade<kTwoLights>(p, float3<float>(0.0f), float3<float>(1, 0, 0)).x, expected_atten * 0.25f, 1e-4f);
  EXPECT_NEAR(shade<kTwoLambert>(p, float3<float>(0.0f), float3<float>(1, 0, 0)).x, 0.0f, 1e-6f);
  EXPECT_NEAR(vertex_light_attenuation(glm::vec3(0.0f), p.lights[0]), 1.0f / 8.0f, 1e-6f);
  // A light exactly on the surface: L = normalize(0) = 0, distance factor 1/a0, N·L = 0.
  d.position = glm::vec3(0.0f);
  p.lights[0] = to_local_light(d);
  const float4<float> on = shade<kTwoLights>(p, float3<float>(0.0f), float3<float>(0, 0, 1));
  EXPECT_NEAR(on.x, 100.0f * 0.25f, 1e-4f);
}

TEST(SourceVertexLit, SpotConeAndDirectionalLight) {
  VertexLitParams p;
  LightDesc s;
  s.type = LightDesc::Type::spot;
  s.position = glm::vec3(0.0f, 0.0f, 10.0f);
  s.direction = glm::vec3(0.0f, 0.0f, -1.0f);
  s.color = glm::vec3(1.0f);
  s.spot_exponent = 1.0f;
  p.lights[0] = to_local_light(s);
  EXPECT_NEAR(shade<kTwoLights>(p, float3<float>(0.0f), float3<float>(0, 0, 1)).x, 1.0f, 1e-5f) << "on the axis";
  // Far outside the cone: the SDK's 1e-4 floor, raised to the exponent (1): not exactly 0.
  const float outside = shade<kTwoLights>(p, float3<float>(100.0f, 0.0f, 9.0f), float3<float>(0, 0, 1)).x;
  EXPECT_LT(outside, 1e-4f);
  LightDesc d;
  d.type = LightDesc::Type::directional;
  d.direction = glm::vec3(0.0f, 0.0f, -1.0f);  // travels down: lights +Z normals
  d.color = glm::vec3(0.5f);
  p.lights[0] = to_local_light(d);
  EXPECT_NEAR(shade<kTwoLights>(p, float3<float>(1e4f, -3e3f, 7.0f), float3<float>(0, 0, 1)).x, 0.5f, 1e-6f);
}

TEST(SourceVertexLit, PhongFresnelRangesAndExponentQuirks) {
  constexpr VertexLitCombo kPhong{2, false, true, false, true, true};
  VertexLitParams p;
  p.eye_position = glm::vec4(0.0f, 0.0f, 10.0f, 1.0f);
  LightDesc d;
  d.type = LightDesc::Type::directional;
  d.direction = glm::vec3(0.0f, 0.0f, -1.0f);
  d.color = glm::vec3(1.0f);
  p.lights[0] = to_local_light(d);
  p.fresnel_ranges = encode_fresnel_ranges(0.2f, 0.5f, 1.0f);
  VertexLitTexels<float> t;
  t.base = float4<float>(0.0f, 0.0f, 0.0f, 1.0f);  // black albedo: only specular; base alpha = mask
  // Head on: R = L, s = 1; Fresnel f = 0 -> min = 0.2.
  EXPECT_NEAR(shade<kPhong>(p, float3<float>(0.0f), float3<float>(0, 0, 1), t).x, 0.2f, 1e-5f);
  // Exponent 0 (the fast path's undefined $phongexponent): pow(x, 0) = 1, pow(0, 0) = 1.
  p.phong_params.x = 0.0f;
  p.eye_position = glm::vec4(10.0f, 0.0f, 0.0f, 1.0f);  // grazing view: R·L = 0, f = 1 -> max
  EXPECT_NEAR(shade<kPhong>(p, float3<float>(0.0f), float3<float>(0, 0, 1), t).x, 1.0f, 1e-5f);
  p.phong_params.x = 150.0f;
  EXPECT_NEAR(shade<kPhong>(p, float3<float>(0.0f), float3<float>(0, 0, 1), t).x, 0.0f, 1e-6f);
}

TEST(SourceVertexLit, SpotBetweenItsConesFollowsTheFalloffExponent) {
  // docs/fidelity.md#model-lights:
  // atten = 1 / (a0 + a1 d + a2 d²) · sat(max(1e-4, (cos θ − cos outer) / (cos inner − cos
  // outer))^exponent), with θ between the cones so that the fringe is neither 0 nor 1 and an
  // exponent of 1 or a missing pow would show. Lambert, normal toward the light: N·L = 1.
  constexpr double kInner = 0.95, kOuter = 0.80;
  for (double exponent : {2.0, 5.0, 0.5}) {
    LightDesc s;
    s.type = LightDesc::Type::spot;
    s.position = glm::vec3(0.0f, 0.0f, 4.0f);
    s.direction = glm::vec3(0.0f, 0.0f, -1.0f);
    s.color = glm::vec3(2.0f, 1.0f, 0.5f);
    s.attenuation = glm::vec3(0.5f, 0.1f, 0.05f);
    s.cos_inner = float(kInner);
    s.cos_outer = float(kOuter);
    s.spot_exponent = float(exponent);
    VertexLitParams p;
    p.lights[0] = to_local_light(s);
    for (double cos_theta : {0.83, 0.875, 0.93}) {
      // The point is d from the light, θ off the axis; float rounding of cos θ - cos outer, raised
      // to the exponent, allows 2e-4 relative.
      const double d = 5.0;
      const double sin_theta = std::sqrt(1.0 - cos_theta * cos_theta);
      const glm::dvec3 point(d * sin_theta, 0.0, 4.0 - d * cos_theta);
      const glm::dvec3 to_light = glm::normalize(glm::dvec3(s.position) - point);
      const double fringe = (cos_theta - kOuter) / (kInner - kOuter);
      const double atten = std::pow(fringe, exponent) / (0.5 + 0.1 * d + 0.05 * d * d);
      const float4<float> c = shade<kTwoLambert>(p, float3<float>(float(point.x), float(point.y), float(point.z)),
                                                 float3<float>(float(to_light.x), float(to_light.y), float(to_light.z)));
      EXPECT_NEAR(c.x, 2.0 * atten, 2e-4 * 2.0 * atten) << "cos θ " << cos_theta << ", exponent " << exponent;
      EXPECT_NEAR(c.z, 0.5 * atten, 2e-4 * 0.5 * atten) << "cos θ " << cos_theta << ", exponent " << exponent;
    }
  }
}

// ---- Phong against double math ---------------------------------------------------------------

/// The shader's parameters for the same material, lit by one directional light.
VertexLitParams phong_params(const testing::PhongReference& ref, const glm::dvec3& eye) {
  VertexLitParams p;
  LightDesc d;
  d.type = LightDesc::Type::directional;
  d.direction = -glm::vec3(ref.light_dir);
  d.color = glm::vec3(ref.light_color);
  p.lights[0] = to_local_light(d);
  p.eye_position = glm::vec4(glm::vec3(eye), 1.0f);
  p.phong_tint_boost = glm::vec4(glm::vec3(ref.tint), float(ref.boost));
  p.phong_params = glm::vec4(float(ref.exponent_constant), float(ref.rim_exponent), float(ref.rim_boost),
                             ref.rim_mask ? 1.0f : 0.0f);
  p.fresnel_ranges = encode_fresnel_ranges(float(ref.fresnel_min), float(ref.fresnel_mid), float(ref.fresnel_max));
  const glm::vec3 a(ref.rim_ambient);
  p.ambient.color = {a, a, a, a, a, a};
  return p;
}

/// The skin shader's full path (it reads the normal map; here a flat texel unless told) and
/// FASTPATH_NOBUMP.
constexpr VertexLitCombo kSkin{2, true, true, false, true, true};
constexpr VertexLitCombo kSkinFastPath{2, false, true, false, true, true};

template <VertexLitCombo C>
void expect_phong(const testing::PhongReference& ref, const glm::dvec3& normal, const glm::dvec3& eye, const char* what,
                  const glm::vec3& bump_texel = glm::vec3(0.5f, 0.5f, 1.0f)) {
  static_assert(C.phong);
  ASSERT_EQ(ref.fast_path, !C.bump) << what;
  VertexLitTexels<float> t;
  t.base = float4<float>(float(ref.base.x), float(ref.base.y), float(ref.base.z), float(ref.base_alpha));
  t.bump = float4<float>(bump_texel.x, bump_texel.y, bump_texel.z, float(ref.normal_alpha));
  t.exponent = float4<float>(float(ref.exponent_texel.x), float(ref.exponent_texel.y), float(ref.exponent_texel.z),
                             float(ref.exponent_texel.w));
  VertexLitParams p = phong_params(ref, eye);
  p.shader_controls.x = ref.base_map_alpha_phong_mask ? 1.0f : 0.0f;
  if (ref.exponent_factor != 0.0) {
    // skin_dx9_helper.cpp's PHONG_USE_EXPONENT_FACTOR binary, as luxel's one binary reads it.
    p.phong_params.x = -1.0f;
    p.shader_controls.y = float(ref.exponent_factor);
  }
  const float4<float> got = shade<C>(p, float3<float>(0.0f), float3<float>(float(normal.x), float(normal.y), float(normal.z)), t);
  // The normal the shader lights with: the texel's, 2 t - 1 in the frame tangent (1, 0, 0),
  // binormal (0, 1, 0), normal `normal` (shade()), or `normal` itself where the normal map is not
  // read or is overridden. The uniform ambient cube also lights the diffuse: albedo × ambient.
  const glm::dvec3 tn = 2.0 * glm::dvec3(bump_texel) - 1.0;
  const glm::dvec3 lit_normal =
      ref.fast_path || ref.base_map_alpha_phong_mask ? normal : glm::dvec3(tn.x, tn.y, 0.0) + tn.z * normal;
  const glm::dvec3 want = ref(lit_normal, eye) + ref.base * ref.rim_ambient;
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(got[c], want[c], 2e-5 * std::max(1.0, want[c])) << what << ", channel " << c << ", eye (" << eye.x
                                                                << ", " << eye.y << ", " << eye.z << ")";
}

// Eyes at 30°..75° from a tilted normal, on both sides of the reflection, so that the Fresnel
// value f = (1 − N·V)² takes intermediate values on both sides of 0.5 (0.018 .. 0.55).
const glm::dvec3 kPhongNormal = glm::normalize(glm::dvec3(0.2, -0.1, 1.0));
std::vector<glm::dvec3> phong_eyes() {
  std::vector<glm::dvec3> eyes;
  const glm::dvec3 side = glm::normalize(glm::cross(kPhongNormal, glm::dvec3(1.0, 0.3, 0.0)));
  for (double degrees : {30.0, 50.0, 62.0, 75.0}) {
    const double a = degrees * 3.14159265358979323846 / 180.0;
    for (double sign : {1.0, -1.0}) eyes.push_back(4.0 * (std::cos(a) * kPhongNormal + sign * std::sin(a) * side));
  }
  return eyes;
}

testing::PhongReference phong_material() {
  testing::PhongReference ref;
  ref.light_dir = glm::normalize(glm::dvec3(0.5, 0.3, 0.8));
  ref.light_color = glm::dvec3(1.5, 1.0, 0.7);
  ref.base = glm::dvec3(0.3, 0.2, 0.1);
  ref.normal_alpha = 0.8;  // the full path's mask
  ref.base_alpha = 0.55;   // the fast path's and $basemapalphaphongmask's
  ref.exponent_constant = 6.0;
  ref.tint = glm::dvec3(1.0, 0.8, 0.5);
  ref.boost = 2.5;
  ref.fresnel_min = 0.2;
  ref.fresnel_mid = 0.6;
  ref.fresnel_max = 0.9;
  return ref;
}

TEST(SourceVertexLit, PhongAtIntermediateFresnelWithBoostAndTint) {
  testing::PhongReference ref = phong_material();
  for (const glm::dvec3& eye : phong_eyes()) expect_phong<kSkin>(ref, kPhongNormal, eye, "phong");
  // FASTPATH_NOBUMP: the mask is the base alpha, $phongtint is not applied, and the exponent is the
  // constant (0 when unset: every lit pixel gets the whole specular).
  ref.fast_path = true;
  for (const glm::dvec3& eye : phong_eyes()) expect_phong<kSkinFastPath>(ref, kPhongNormal, eye, "fast path");
  ref.exponent_constant = -1.0;
  for (const glm::dvec3& eye : phong_eyes()) expect_phong<kSkinFastPath>(ref, kPhongNormal, eye, "fast path, unset");
}

TEST(SourceVertexLit, PhongExponentConstantOverTheTextureAnd150WhenUnset) {
  testing::PhongReference ref = phong_material();
  ref.exponent_constant = -1.0;  // $phongexponent unset: 1 + 149 r
  for (double red : {0.0, 0.02, 0.1, 1.0}) {  // 1.0: the white texture bound when there is none (150)
    ref.exponent_texel = glm::dvec4(red, 0.0, 0.0, 1.0);
    for (const glm::dvec3& eye : phong_eyes()) expect_phong<kSkin>(ref, kPhongNormal, eye, "exponent texture");
  }
  ref.exponent_constant = 6.0;  // a constant above 0 overrides the texture
  ref.exponent_texel = glm::dvec4(0.02, 0.0, 0.0, 1.0);
  for (const glm::dvec3& eye : phong_eyes()) expect_phong<kSkin>(ref, kPhongNormal, eye, "constant over the texture");
}

TEST(SourceVertexLit, PhongExponentFactorScalesTheExponentTexture) {
  // skin_ps20b.fxc's PHONG_USE_EXPONENT_FACTOR: 1 + factor r, whatever $phongexponent says.
  testing::PhongReference ref = phong_material();
  for (double factor : {4.0, 20.0})
    for (double red : {0.1, 0.5}) {
      ref.exponent_factor = factor;
      ref.exponent_texel = glm::dvec4(red, 0.0, 0.0, 1.0);
      for (const glm::dvec3& eye : phong_eyes()) expect_phong<kSkin>(ref, kPhongNormal, eye, "exponent factor");
    }
}

TEST(SourceVertexLit, PhongTintBelowZeroTintsWithTheAlbedo) {
  testing::PhongReference ref = phong_material();
  ref.tint = glm::dvec3(-1.0);
  ref.exponent_texel = glm::dvec4(1.0, 0.6, 0.0, 1.0);  // g: how much albedo
  for (const glm::dvec3& eye : phong_eyes()) expect_phong<kSkin>(ref, kPhongNormal, eye, "albedo tint");
}

TEST(SourceVertexLit, BaseMapAlphaPhongMaskDropsTheNormalMapAndMasksWithTheBase) {
  testing::PhongReference ref = phong_material();
  ref.base_alpha = 0.3;
  ref.normal_alpha = 0.9;
  ref.base_map_alpha_phong_mask = true;
  const glm::vec3 tilted(0.8f, 0.3f, 0.7f);  // a normal-map texel far from flat: ignored
  for (const glm::dvec3& eye : phong_eyes()) expect_phong<kSkin>(ref, kPhongNormal, eye, "base alpha mask", tilted);
  // The alpha out is $alpha alone, the base alpha being the mask.
  VertexLitParams p = phong_params(ref, phong_eyes()[0]);
  p.modulation.w = 0.6f;
  VertexLitTexels<float> t;
  t.base.w = 0.3f;
  p.shader_controls.x = 1.0f;
  EXPECT_FLOAT_EQ(shade<kSkin>(p, float3<float>(0.0f), float3<float>(0, 0, 1), t).w, 0.6f);
  p.shader_controls.x = 0.0f;
  EXPECT_NEAR(shade<kSkin>(p, float3<float>(0.0f), float3<float>(0, 0, 1), t).w, 0.18f, 1e-6f);
  // Without the flag the texel is the normal and the normal map's alpha the mask.
  ref.base_map_alpha_phong_mask = false;
  for (const glm::dvec3& eye : phong_eyes()) expect_phong<kSkin>(ref, kPhongNormal, eye, "normal map", tilted);
}

TEST(SourceVertexLit, RimLightWithAndWithoutItsMask) {
  constexpr VertexLitCombo kRim{2, true, true, true, true, true};
  testing::PhongReference ref = phong_material();
  ref.exponent_constant = -1.0;
  ref.exponent_texel = glm::dvec4(0.05, 0.0, 0.0, 0.35);  // a: the rim mask
  ref.rim = true;
  ref.rim_exponent = 2.0;
  ref.rim_boost = 1.7;
  ref.rim_ambient = glm::dvec3(0.4, 0.5, 0.6);
  ref.boost = 0.3;  // a weak specular, so that max(specular, rim) picks the rim at grazing eyes
  ref.light_dir = glm::normalize(glm::dvec3(-0.4, 0.2, 0.5));
  int rim_wins = 0;
  for (bool masked : {false, true}) {
    ref.rim_mask = masked;
    for (const glm::dvec3& eye : phong_eyes()) {
      expect_phong<kRim>(ref, kPhongNormal, eye, masked ? "rim, masked" : "rim");
      testing::PhongReference no_rim = ref;
      no_rim.rim = false;
      if (ref(kPhongNormal, eye).x > no_rim(kPhongNormal, eye).x + 1e-3) ++rim_wins;
    }
  }
  EXPECT_GE(rim_wins, 4) << "the cases exercise the rim, not only the specular";
}

// ---- Env maps on models ----------------------------------------------------------------------

/// The tests' cube map: a color that turns with the direction (so a wrong reflection vector
/// reads another color), in double for the reference and on the float lane for the shader.
glm::dvec3 test_env(const glm::dvec3& r) {
  const glm::dvec3 d = glm::normalize(r);
  return glm::dvec3(0.5 + 0.5 * d.x, 0.5 + 0.4 * d.y, 0.5 - 0.3 * d.z);
}

/// What combo C adds to combo `Without` (the same but for the env map) at the origin: its env map.
template <VertexLitCombo C, VertexLitCombo Without>
glm::dvec3 env_term(const VertexLitParams& p, const glm::dvec3& normal, const VertexLitTexels<float>& t) {
  static_assert(C.envmap && !Without.envmap);
  auto env = [](const float3<float>& r) {
    const float3<float> d = normalize(r);
    return float3<float>(0.5f + 0.5f * d.x, 0.5f + 0.4f * d.y, 0.5f - 0.3f * d.z);
  };
  VertexLitInputs<float> in;
  in.world_pos = float3<float>(0.0f);
  in.normal = float3<float>(float(normal.x), float(normal.y), float(normal.z));
  in.tangent = float3<float>(1.0f, 0.0f, 0.0f);
  in.binormal = float3<float>(0.0f, 1.0f, 0.0f);
  const float4<float> with = vertexlit_combine<C>(t, in, p, env);
  const float4<float> without = vertexlit_combine<Without>(t, in, p, env);
  return glm::dvec3(with.x - without.x, with.y - without.y, with.z - without.z);
}

void expect_env(const glm::dvec3& got, const glm::dvec3& want, const std::string& what) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 3e-6 + 2e-5 * std::abs(want[c])) << what << ", channel " << c;
}

TEST(SourceVertexLit, SkinEnvMapTakesTheFresnelRangesAndTheBaseAlphaAsItsMask) {
  // skin_ps20b: c30.z · lerp(1, Fresnel ranges, $envmapfresnel) · mask · cube(2 N (N·V) − V) ·
  // $envmaptint, the mask the base alpha unless $normalmapalphaenvmapmask (tint.w) makes it the
  // Phong mask (the normal map's alpha on the full path, the base alpha on FASTPATH_NOBUMP).
  constexpr VertexLitCombo kSkinEnv{2, true, true, false, true, true, false, Fog::none, false, true};
  constexpr VertexLitCombo kFastEnv{2, false, true, false, true, true, false, Fog::none, false, true};
  testing::PhongReference ref = phong_material();  // base alpha 0.55, normal alpha 0.8: masks that differ
  const glm::dvec3 tint(0.9, 0.7, 0.5);
  for (bool fast : {false, true})
    for (bool phong_mask : {false, true})
      for (bool invert : {false, true})  // $invertphongmask: lerp(mask, 1 - mask, invert)
      for (double envmap_fresnel : {0.0, 0.6, 1.0})
        for (const glm::dvec3& eye : phong_eyes()) {
          ref.fast_path = fast;
          VertexLitParams p = phong_params(ref, eye);
          p.shader_controls.w = invert ? 1.0f : 0.0f;
          p.tonemap.c30.z = 1.5f;  // ENV_MAP_SCALE
          p.envmap_tint = glm::vec4(glm::vec3(tint), phong_mask ? 1.0f : 0.0f);
          p.envmap_fresnel.x = float(envmap_fresnel);
          VertexLitTexels<float> t;
          t.base = float4<float>(0.3f, 0.2f, 0.1f, float(ref.base_alpha));
          t.bump.w = float(ref.normal_alpha);
          const glm::dvec3 got = fast ? env_term<kFastEnv, kSkinFastPath>(p, kPhongNormal, t)
                                      : env_term<kSkinEnv, kSkin>(p, kPhongNormal, t);
          const glm::dvec3 n = kPhongNormal, v = glm::normalize(eye);
          const glm::dvec3 r = 2.0 * glm::dot(n, v) * n - v;
          const double unmasked = phong_mask ? ref.mask() : ref.base_alpha;
          const double mask = invert ? 1.0 - unmasked : unmasked;
          const double scale = 1.5 * (1.0 + (ref.fresnel(n, v) - 1.0) * envmap_fresnel) * mask;
          expect_env(got, scale * test_env(r) * tint,
                     std::string(fast ? "fast path" : "full path") + (phong_mask ? ", Phong mask" : ", base alpha") +
                         (invert ? ", inverted" : "") + ", $envmapfresnel " + std::to_string(envmap_fresnel));
        }
}

TEST(SourceVertexLit, BumpedEnvMapReflectsThePixelNormalAndMasksOnlyOnItsCombo) {
  // vertexlit_and_unlit_generic_bump_ps2x: c30.z · cube(2 (N·E) N − (N·N) E) · mask · $envmaptint,
  // the mask the normal map's alpha on the NORMALMAPALPHAENVMAPMASK combo, else 1 (tint.w, the
  // skin shader's control, is not read); then contrast and saturation.
  constexpr VertexLitCombo kBump{2, true, false, false, true, true};
  constexpr VertexLitCombo kBumpEnv{2, true, false, false, true, true, false, Fog::none, false, true};
  constexpr VertexLitCombo kBumpEnvMasked{2, true, false, false, true, true, false, Fog::none, false, true, true};
  const glm::dvec3 tint(0.9, 0.7, 0.5);
  const double contrast = 0.4, saturation = 0.6, normal_alpha = 0.3;
  const glm::dvec3 texel(0.7, 0.4, 0.9);  // a tilted normal: the reflection is the pixel's
  for (bool masked : {false, true})
    for (const glm::dvec3& eye : phong_eyes()) {
      VertexLitParams p = phong_params(phong_material(), eye);
      p.tonemap.c30.z = 1.5f;
      p.envmap_tint = glm::vec4(glm::vec3(tint), 1.0f);
      p.envmap_contrast = glm::vec4(float(contrast));
      p.envmap_saturation = glm::vec4(float(saturation));
      VertexLitTexels<float> t;
      t.base.w = 0.55f;
      t.bump = float4<float>(float(texel.x), float(texel.y), float(texel.z), float(normal_alpha));
      const glm::dvec3 got =
          masked ? env_term<kBumpEnvMasked, kBump>(p, kPhongNormal, t) : env_term<kBumpEnv, kBump>(p, kPhongNormal, t);
      const glm::dvec3 tn = 2.0 * texel - 1.0;
      const glm::dvec3 n = glm::normalize(glm::dvec3(tn.x, tn.y, 0.0) + tn.z * kPhongNormal);
      const glm::dvec3 r = 2.0 * glm::dot(n, eye) * n - glm::dot(n, n) * eye;
      glm::dvec3 s = 1.5 * test_env(r) * (masked ? normal_alpha : 1.0) * tint;
      s = glm::mix(s, s * s, contrast);
      const double grey = glm::dot(s, glm::dvec3(0.299, 0.587, 0.114));
      s = glm::mix(glm::dvec3(grey), s, saturation);
      expect_env(got, s, masked ? "masked by the normal alpha" : "unmasked");
    }
}

TEST(SourceVertexLit, FoldedDirectionalLightIsExactForAxisNormals) {
  for (bool hl : {true, false}) {
    LightDesc d;
    d.type = LightDesc::Type::directional;
    d.direction = glm::normalize(glm::vec3(-0.3f, 0.5f, -0.8f));
    d.color = glm::vec3(0.7f, 0.4f, 0.2f);
    LightDesc strong = d;
    strong.color = glm::vec3(5.0f);
    const LightDesc lights[] = {d, strong};
    const FoldedLights f = fold_lights(lights, 1, glm::vec3(0.0f), AmbientCube{}, hl);
    ASSERT_EQ(f.kept.size(), 1u);
    EXPECT_EQ(f.kept[0].color.x, 5.0f) << "the brighter light is kept";
    VertexLitParams folded;
    folded.ambient = f.cube;
    constexpr VertexLitCombo kHL{2, false, false, false, true, true};
    constexpr VertexLitCombo kL{2, false, false, false, false, true};
    VertexLitParams direct;
    direct.lights[0] = to_local_light(d);
    for (int j = 0; j < 6; ++j) {
      float3<float> n(0.0f);
      n[j / 2] = (j % 2 == 0) ? 1.0f : -1.0f;
      const float4<float> a = shade<kAmbientOnly>(folded, float3<float>(0.0f), n);
      const float4<float> b = hl ? shade<kHL>(direct, float3<float>(0.0f), n) : shade<kL>(direct, float3<float>(0.0f), n);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], 1e-5f) << "axis " << j << (hl ? " half-Lambert" : " Lambert");
    }
  }
}

TEST(SourceVertexLit, ALightSplitBetweenASlotAndTheCubeKeepsItsEnergyOnTheAxes) {
  // The frame's time averaging (frame/renderer.hpp) draws a light at s x its color and folds
  // (1 - s) of it: for the six axis normals the sum is the light drawn whole, for any s.
  for (bool hl : {true, false}) {
    LightDesc d;
    d.type = LightDesc::Type::directional;
    d.direction = glm::normalize(glm::vec3(0.6f, -0.2f, -0.75f));
    d.color = glm::vec3(0.9f, 0.5f, 0.3f);
    constexpr VertexLitCombo kHL{2, false, false, false, true, true};
    constexpr VertexLitCombo kL{2, false, false, false, false, true};
    VertexLitParams whole;
    whole.lights[0] = to_local_light(d);
    for (float share : {0.25f, 0.7f}) {
      VertexLitParams split;
      LightDesc part = d;
      part.color *= share;
      split.lights[0] = to_local_light(part);
      fold_light(split.ambient, d, glm::vec3(0.0f), hl, 1.0 - share);
      AmbientCube once;
      fold_light(once, d, glm::vec3(0.0f), hl);
      for (int j = 0; j < 6; ++j) {
        for (int k = 0; k < 3; ++k)
          EXPECT_NEAR(split.ambient.color[j][k], (1.0f - share) * once.color[j][k], 1e-6f) << "a share folds that share";
        float3<float> n(0.0f);
        n[j / 2] = (j % 2 == 0) ? 1.0f : -1.0f;
        const float4<float> a = hl ? shade<kHL>(split, float3<float>(0.0f), n) : shade<kL>(split, float3<float>(0.0f), n);
        const float4<float> b = hl ? shade<kHL>(whole, float3<float>(0.0f), n) : shade<kL>(whole, float3<float>(0.0f), n);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], 1e-5f) << "axis " << j << " share " << share;
      }
    }
  }
}

TEST(SourceVertexLit, SignificanceRanksByDeliveredLuminance) {
  LightDesc near_dim, far_bright;
  near_dim.position = glm::vec3(1.0f, 0.0f, 0.0f);
  near_dim.color = glm::vec3(1.0f);
  near_dim.attenuation = glm::vec3(0.0f, 0.0f, 1.0f);
  far_bright = near_dim;
  far_bright.position = glm::vec3(100.0f, 0.0f, 0.0f);
  far_bright.color = glm::vec3(1000.0f);
  EXPECT_GT(light_significance(near_dim, glm::vec3(0.0f)), light_significance(far_bright, glm::vec3(0.0f)));
  const LightDesc lights[] = {far_bright, near_dim};
  const FoldedLights f = fold_lights(lights, 1, glm::vec3(0.0f), AmbientCube{}, true);
  EXPECT_EQ(f.kept[0].position.x, 1.0f);
  EXPECT_GT(f.cube.color[0].x, 0.0f) << "the far light went into the +X side";
}

// ---- SIMD vs scalar ---------------------------------------------------------------------------

/// cube_filter: how the ps_2_0 combos read the normalization cube. Point for the bit-for-bit
/// comparison (the float lane samples with the texture module's reference, which agrees with the
/// SIMD sampler bit for bit through point sampling, within a step through bilinear); the
/// production sampler (normalization_cube_sampler(): bilinear) for the within-a-step one.
VertexLitParams lane_test_params(rasterizer::Filter cube_filter = rasterizer::Filter::Point) {
  VertexLitParams p;
  p.ambient = test_cube();
  p.ambient_sh9 = sh9_ambient_constants(sh9_from_ambient_cube(p.ambient));  // the +sh9 combos
  p.eye_position = glm::vec4(0.5f, 2.0f, 3.0f, 1.0f);
  LightDesc a, b, c, d;
  a.position = glm::vec3(1.0f, 1.0f, 1.0f);
  a.color = glm::vec3(3.0f, 2.0f, 1.0f);
  a.attenuation = glm::vec3(0.0f, 0.0f, 1.0f);
  b.type = LightDesc::Type::spot;
  b.position = glm::vec3(0.0f, 0.0f, 2.0f);
  b.direction = glm::vec3(0.0f, 0.0f, -1.0f);
  b.cos_inner = 0.9f;
  b.cos_outer = 0.5f;
  b.color = glm::vec3(1200.0f);  // HDR
  b.attenuation = glm::vec3(1.0f, 0.0f, 0.5f);
  c.type = LightDesc::Type::directional;
  c.direction = glm::vec3(0.0f, -1.0f, 0.0f);
  d.position = glm::vec3(-1.0f, 0.0f, 0.0f);
  p.lights = {to_local_light(a), to_local_light(b), to_local_light(c), to_local_light(d)};
  p.phong_params = glm::vec4(150.0f, 4.0f, 1.0f, 1.0f);
  p.fresnel_ranges = encode_fresnel_ranges(0.1f, 0.5f, 1.0f);
  p.tonemap = ToneMapConstants::for_scale(0.7f);
  p.fog = testing::lane_test_fog();
  static const rasterizer::Texture normalization_cube = normalization_cube_map();  // the ps_2_0 combos
  p.normalization_cube.texture = &normalization_cube;
  p.normalization_cube.state.min = p.normalization_cube.state.mag = cube_filter;
  // The env-map combos reflect in the same cube (signed texels: the sums go both ways).
  p.envmap.texture = &normalization_cube;
  p.envmap.state.min = p.envmap.state.mag = cube_filter;
  p.envmap_tint = glm::vec4(0.8f, 0.6f, 0.4f, 1.0f);
  p.envmap_fresnel.x = 0.7f;
  p.envmap_contrast = glm::vec4(0.3f);
  p.envmap_saturation = glm::vec4(0.7f);
  return p;
}

/// Inputs: base 0-3, bump 4-7, exponent 8-11, world_pos 12-14, normal 15-17, tangent 18-20,
/// binormal 21-23, per-vertex attenuation 24-27, projected z 28 (fog; world z is world_pos.z).
constexpr int kVertexLitInputs = 29;

template <VertexLitCombo C>
auto vertexlit_lane_shader(const VertexLitParams& p) {
  return [&p]<class L>(const auto& get) -> float4<L> {
    VertexLitTexels<L> t;
    t.base = float4<L>(get(0), get(1), get(2), get(3));
    t.bump = float4<L>(get(4), get(5), get(6), get(7));
    t.exponent = float4<L>(get(8), get(9), get(10), get(11));
    VertexLitInputs<L> in;
    in.world_pos = float3<L>(get(12), get(13), get(14));
    in.normal = float3<L>(get(15), get(16), get(17));
    in.tangent = float3<L>(get(18), get(19), get(20));
    in.binormal = float3<L>(get(21), get(22), get(23));
    in.attenuation = float4<L>(get(24), get(25), get(26), get(27));
    in.proj_z = get(28);
    return vertexlit_combine<C>(t, in, p);
  };
}

template <VertexLitCombo C>
testing::LaneComparison compare_vertexlit(int hard_every, uint32_t seed,
                                          rasterizer::Filter cube_filter = rasterizer::Filter::Point) {
  const VertexLitParams p = lane_test_params(cube_filter);
  std::vector<Draw> draws(kVertexLitInputs, Draw{0.0f, 1.0f, hard_every});
  for (int i = 12; i < 15; ++i) draws[i] = Draw{-2.0f, 2.0f, hard_every};
  for (int i = 15; i < 24; ++i) draws[i] = Draw{-1.0f, 1.0f, hard_every};
  draws[28] = Draw{0.0f, 400.0f, hard_every};
  return compare_lanes<kVertexLitInputs>(vertexlit_lane_shader<C>(p), draws, 256, seed);
}

/// Pixels built to sit on the edges of the math, for lane_test_params()'s lights and eye.
std::vector<std::array<float, kVertexLitInputs>> vertexlit_hard_pixels() {
  using Pixel = std::array<float, kVertexLitInputs>;
  Pixel plain{};
  const float defaults[kVertexLitInputs] = {0.6f, 0.5f, 0.4f, 0.9f, 0.5f, 0.5f, 1.0f, 0.8f, 0.3f, 0.5f, 0.5f, 0.6f,
                                            0.1f, 0.2f, 0.0f, 0.0f, 0.0f, 1.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f,
                                            0.7f, 0.4f, 0.2f, 1.0f, 150.0f};
  std::copy(std::begin(defaults), std::end(defaults), plain.begin());
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<Pixel> pixels;
  auto with = [&](std::initializer_list<std::pair<int, float>> changes) {
    Pixel q = plain;
    for (const auto& [i, v] : changes) q[static_cast<size_t>(i)] = v;
    pixels.push_back(q);
  };
  with({});
  with({{15, 0.0f}, {16, 0.0f}, {17, 0.0f}, {4, 0.5f}, {5, 0.5f}, {6, 0.5f}});  // zero-length normal, bump too
  with({{15, 1e-40f}, {16, 0.0f}, {17, 0.0f}, {18, 1e-40f}, {21, 0.0f}, {22, 1e-40f}});  // denormal normal and frame
  with({{15, 3e-39f}, {16, -2e-39f}, {17, 1e-39f}});
  // Light a at (1,1,1), the point at the origin: L = (1,1,1)/√3 and N = (1,-1,0)/√2, N·L = 0.
  with({{12, 0.0f}, {13, 0.0f}, {14, 0.0f}, {15, 1.0f}, {16, -1.0f}, {17, 0.0f}});
  // The eye (0.5, 2, 3) level with the point: V ⟂ N = +Z, N·V = 0 (grazing), and just past it.
  with({{12, 0.5f}, {13, -1.0f}, {14, 3.0f}});
  with({{12, 0.5f}, {13, -1.0f}, {14, 3.0001f}});
  with({{12, -1.5f}, {13, 2.0f}, {14, 3.0f}, {15, 1.0f}, {16, 0.0f}, {17, 0.0f}});
  // A point on a light, and on the eye.
  with({{12, 1.0f}, {13, 1.0f}, {14, 1.0f}});
  with({{12, 0.5f}, {13, 2.0f}, {14, 3.0f}});
  // HDR texels and far points.
  with({{0, 1e30f}, {1, 1e30f}, {2, 1e30f}, {3, 1e30f}});
  with({{12, 1e30f}, {13, -1e30f}, {14, 1e30f}});
  with({{24, 1e30f}, {25, 1e30f}, {26, 1e30f}, {27, 1e30f}});
  with({{8, 1e30f}, {11, 1e30f}});
  // NaN texels, NaN normals, NaN positions.
  with({{0, nan}, {3, nan}});
  with({{4, nan}, {7, nan}});
  with({{15, nan}});
  with({{12, nan}, {13, nan}, {14, nan}});
  with({{8, nan}, {11, nan}, {24, nan}});
  // Infinite normal (normalize(inf) is NaN) and negative zero normal.
  with({{15, std::numeric_limits<float>::infinity()}});
  with({{15, -0.0f}, {16, -0.0f}, {17, -0.0f}, {4, 0.5f}, {5, 0.5f}, {6, 0.5f}});
  // Fog (lane_test_fog: eye at z = 20, water plane z = 5, start 10, end 300; world z is input 14).
  with({{28, 0.0f}});                 // at the eye plane: no range fog
  with({{28, 1e30f}});                // far past the end: max density
  with({{14, 20.0f}, {28, 300.0f}});  // level with the fog's eye: 1 / 0 through the water plane
  with({{14, 5.0f}, {28, 40.0f}});    // on the water plane
  with({{14, -10.0f}, {28, 400.0f}}); // deep below it, far
  with({{28, nan}});
  return pixels;
}

TEST(SourceVertexLit, SimdAgreesWithScalarBitForBitForEveryCombo) {
  uint32_t seed = 101;
  const VertexLitParams p = lane_test_params();
  const auto hard_pixels = vertexlit_hard_pixels();
  for_each_combo<testing::kVertexLitSampled>([&]<VertexLitCombo C>() {
    const auto random = compare_vertexlit<C>(0, seed++);
    const auto hard = compare_vertexlit<C>(3, seed++);
    const auto constructed = testing::compare_lanes_at<kVertexLitInputs>(vertexlit_lane_shader<C>(p), hard_pixels);
    testing::expect_bit_identical(random, C.name());
    testing::expect_bit_identical(hard, C.name() + " (hard inputs)");
    testing::expect_bit_identical(constructed, C.name() + " (constructed edge cases)");
    EXPECT_LE(random.max_step_vs_double, 1) << C.name();
    std::printf("VertexLitGeneric %-36s simd-vs-scalar max %d step(s) (hard: %d, constructed: %d)\n", C.name().c_str(),
                random.max_step, hard.max_step, constructed.max_step);
  });
}

TEST(SourceVertexLit, NormalizationCubeCombosWithinOneStepOfScalarThroughBilinearSampling) {
  // The ps_2_0 combos read the cube map bilinearly (normalization_cube_sampler()); there the float
  // lane's reference sampler and the SIMD sampler agree within a step, not bit for bit.
  uint32_t seed = 701;
  int combos = 0;
  for_each_combo<testing::kVertexLitSampled>([&]<VertexLitCombo C>() {
    if constexpr (C.normalization_cube) {
      const auto random = compare_vertexlit<C>(0, seed++, rasterizer::Filter::Linear);
      const auto hard = compare_vertexlit<C>(3, seed++, rasterizer::Filter::Linear);
      EXPECT_LE(random.max_step, 1) << C.name();
      EXPECT_LE(hard.max_step, 1) << C.name() << " (hard inputs)";
      std::printf("VertexLitGeneric %-36s bilinear normalization cube: simd-vs-scalar max %d step(s) (hard: %d)\n",
                  C.name().c_str(), random.max_step, hard.max_step);
      ++combos;
    }
  });
  EXPECT_GE(combos, 3);
}

// ---- Budgets ----------------------------------------------------------------------------------

TEST(SourceVertexLit, TheCountAloneKeepsPixelAttenuationOffPs20) {
  // The SDK attenuates per vertex on ps_2_0; luxel's per-pixel attenuation is allowed there by the
  // rules (valid()) and kept off only by the count: every valid combo fits ps_2_b and ps_3_0, and
  // on ps_2_0 every combo without per-pixel attenuation fits, while per-pixel-attenuated ones
  // compile exactly when their counted arithmetic fits the 64 slots. Both outcomes must occur,
  // so neither a rule refusing them all nor one allowing them all passes. Every combo of the
  // registry's space, through its counts.
  int measured = 0, refused = 0, fitting_pixel_attenuated = 0;
  for (const VertexLitCombo& c : kVertexLitSpace) {
    for (ShaderModel m : kPixelModels) {
      if (!c.valid(m)) continue;
      const Cost cost = counted_cost(c, m);
      const Verdict v = fits(cost, caps(m));
      const bool pixel_attenuated_ps20 = m == ShaderModel::ps_2_0 && c.lights > 0 && c.pixel_attenuation;
      if (!pixel_attenuated_ps20) {
        EXPECT_TRUE(v) << c.name() << " on " << caps(m).name << ": " << v.reason << " (" << describe(cost) << ")";
      } else if (v) {
        ++fitting_pixel_attenuated;
      } else {
        EXPECT_GT(cost.arithmetic_slots, caps(m).arithmetic_slots) << c.name() << ": " << v.reason;
        ++refused;
      }
      EXPECT_EQ(vertexlit_fits(c, m), static_cast<bool>(v)) << c.name() << " on " << caps(m).name;
      ++measured;
    }
  }
  EXPECT_GE(measured, 25);
  EXPECT_GE(refused, 3);
  // Every per-pixel-attenuated combo the SDK has a source for is bumped or Phong, and over ps_2_0's
  // arithmetic; the budget is no blanket rule: two Lambert lights without a bump map (a combo the
  // SDK lights per vertex, so not in the space) fit.
  EXPECT_EQ(fitting_pixel_attenuated, 0);
  constexpr VertexLitCombo kPlainLambert{2, false, false, false, false, true, false, Fog::none, true};
  EXPECT_TRUE(fits(measure_vertexlit_generic<kPlainLambert>(ShaderModel::ps_2_0), caps(ShaderModel::ps_2_0)));
}

TEST(SourceVertexLit, FourLightsWithPixelAttenuationWouldNotFitPs2b) {
  // Why the SDK attenuates per vertex: 4 x 5 light registers + the rest > 32 constants.
  constexpr VertexLitCombo kFourPixel{4, true, true, true, true, true};
  static_assert(!kFourPixel.valid(ShaderModel::ps_2_b));
  const Cost cost = measure_vertexlit_generic<kFourPixel>(ShaderModel::ps_2_b);
  EXPECT_FALSE(fits(cost, caps(ShaderModel::ps_2_b))) << describe(cost);
}

TEST(SourceVertexLit, AmbientCubeCountBesideThePublishedOnes) {
  const AmbientCube cube = test_cube();
  auto body = [&](CountedInputs& in) { return ambient_light<Counted>(in.vector<3>(), cube); };
  const Cost ps20 = measure(ShaderModel::ps_2_0, body);
  const Cost ps30 = measure(ShaderModel::ps_3_0, body);
  const Cost vs20 = measure(ShaderModel::vs_2_0, body);
  std::printf("ambient cube: ps_3_0 %d, ps_2_0 %d (incl. mov oC0), vs_2_0 %d slots; published: 11 PS / 6 VS "
              "(2006 notes), 9 PS (SDK comment)\n",
              ps30.arithmetic_slots, ps20.arithmetic_slots, vs20.arithmetic_slots);
  // ps: mul n², cmp, cmp, mul, mad x5 = 9, exactly the SDK comment's list; the 2006 notes' 11
  // predate that rewrite. The VS's 6 uses relative constant addressing (slt, mova, then indexed
  // reads: mul, mul, mad, mad), which our lane language does not express: we select with
  // sge/slt + lrp instead, so our vertex count is higher.
  EXPECT_EQ(ps30.arithmetic_slots, 9);
  EXPECT_EQ(ps20.arithmetic_slots, 10);
  EXPECT_GT(vs20.arithmetic_slots, 6);
}

}  // namespace
}  // namespace luxel::shading::source
