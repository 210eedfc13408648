// The tone-map epilogue and LightmappedGeneric: closed-form cases, the fast-path quirk, LDR
// lightmap encoding, SIMD vs scalar on random and hard inputs, and every combo's DX9 budget.

#include "source_support.hpp"

#include "luxel/shading/source/lightmapped_generic.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <utility>
#include <vector>

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

// The RNM combine (docs/fidelity.md#lightmappedgeneric) in double, from the formula:
// n = 2 tex - 1, d_i = sat(n · b_i)², diffuse = Σ d_i LM_i / Σ d_i × c12 × albedo. The basis is
// the exact one (√(2/3), 1/√6, 1/√2, 1/√3), not the shader's float literals.
glm::dvec3 rnm_reference(const glm::vec4& bump_texel, const glm::dvec3 (&lightmaps)[3], const glm::dvec3& c12,
                         const glm::dvec3& albedo) {
  const double basis[3][3] = {{std::sqrt(2.0 / 3.0), 0.0, 1.0 / std::sqrt(3.0)},
                              {-1.0 / std::sqrt(6.0), 1.0 / std::sqrt(2.0), 1.0 / std::sqrt(3.0)},
                              {-1.0 / std::sqrt(6.0), -1.0 / std::sqrt(2.0), 1.0 / std::sqrt(3.0)}};
  const glm::dvec3 n = glm::dvec3(bump_texel) * 2.0 - 1.0;
  glm::dvec3 sum(0.0);
  double weights = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double d = std::clamp(n.x * basis[i][0] + n.y * basis[i][1] + n.z * basis[i][2], 0.0, 1.0);
    sum += d * d * lightmaps[i];
    weights += d * d;
  }
  return sum / weights * c12 * albedo;
}

TEST(SourceLightmapped, OffAxisNormalsWeighTheLightmapsBySquaredClampedCosines) {
  // Normals where squared and plain weights, or clamped and unclamped ones, give different
  // colors: between two basis vectors at unequal distances, inside the basis cone, past one basis
  // vector (one weight clamped to 0), and a texel so long that a dot exceeds 1 (clamped to 1).
  const glm::dvec3 b0(std::sqrt(2.0 / 3.0), 0.0, 1.0 / std::sqrt(3.0));
  const glm::dvec3 b1(-1.0 / std::sqrt(6.0), 1.0 / std::sqrt(2.0), 1.0 / std::sqrt(3.0));
  const glm::dvec3 between = glm::normalize(0.8 * b0 + 0.3 * b1);
  const glm::dvec3 normals[] = {between, glm::normalize(glm::dvec3(0.3, 0.2, 0.9)),
                                glm::normalize(glm::dvec3(0.7, -0.1, 0.3)), glm::normalize(glm::dvec3(-0.6, 0.5, 0.4)),
                                glm::dvec3(1.0, 1.0, 1.0)};
  const glm::dvec3 lightmaps[3] = {{0.9, 0.2, 0.1}, {0.1, 1.7, 0.3}, {0.4, 0.3, 2.5}};
  const glm::dvec3 c12(1.3, 0.9, 1.1), albedo(0.6, 0.8, 0.5);
  LightmappedGenericParams p;
  p.tint_lightmap_scale = glm::vec4(glm::vec3(c12), 1.0f);
  for (const glm::dvec3& n : normals) {
    LightmappedTexels<float> t;
    const glm::vec4 texel(glm::vec3(n * 0.5 + 0.5), 1.0f);
    t.bump = float4<float>(texel.x, texel.y, texel.z, texel.w);
    t.base = float4<float>(float(albedo.x), float(albedo.y), float(albedo.z), 1.0f);
    for (int k = 0; k < 3; ++k)
      t.lightmap[k + 1] = float3<float>(float(lightmaps[k].x), float(lightmaps[k].y), float(lightmaps[k].z));
    const glm::dvec3 want = rnm_reference(texel, lightmaps, c12, albedo);
    const float4<float> got = combine<kBump>(t, p);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(got[c], want[c], 2e-6 * std::max(1.0, want[c])) << "normal (" << n.x << ", " << n.y << ", " << n.z
                                                                 << ") channel " << c;
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

// A cube map whose color says which way it was read: each channel a different affine function
// of the unit direction, over the lane, and the same in double for the references.
template <Lane L>
float3<L> direction_env(const float3<L>& r) {
  const float3<L> d = normalize(r);
  return float3<L>((d.x * 0.5f + 0.6f) * 2.0f, d.y * 0.5f + 0.6f, (d.z * 0.5f + 0.6f) * 3.0f);
}
glm::dvec3 direction_env_reference(const glm::dvec3& r) {
  const glm::dvec3 d = glm::normalize(r);
  return {(d.x * 0.5 + 0.6) * 2.0, d.y * 0.5 + 0.6, (d.z * 0.5 + 0.6) * 3.0};
}

/// The world env map in double from the formula: R = 2(N·E)N − (N·N)E, spec = ENV_MAP_SCALE · cube(R) ·
/// mask · tint, then (full path) contrast, saturation and Fresnel (1 − N·Ê)^5 (1 − R0) + R0.
struct EnvmapReference {
  glm::dvec3 mask{1.0}, tint{1.0};
  double envmap_scale = 1.0, contrast = 0.0, saturation = 1.0, r0 = 1.0;
  bool full = false, square = false;
  glm::dvec3 operator()(const glm::dvec3& n, const glm::dvec3& e) const {
    const glm::dvec3 r = 2.0 * glm::dot(n, e) * n - glm::dot(n, n) * e;
    glm::dvec3 spec = direction_env_reference(r) * envmap_scale * mask * tint;
    if (square) spec = spec * spec;
    if (full) {
      spec = spec + (spec * spec - spec) * contrast;
      const double grey = glm::dot(spec, glm::dvec3(0.299, 0.587, 0.114));
      spec = grey + (spec - grey) * saturation;
      spec *= std::pow(1.0 - glm::dot(n, glm::normalize(e)), 5.0) * (1.0 - r0) + r0;
    }
    return spec;
  }
};

template <LightmappedCombo C>
float4<float> combine_direction_env(const LightmappedTexels<float>& t, const LightmappedGenericParams& p,
                                    const LightmappedInputs<float>& in) {
  return lightmapped_generic_combine<C>(t, in, p, [](const float3<float>& r) { return direction_env(r); });
}

float3<float> f3(const glm::dvec3& v) { return float3<float>(float(v.x), float(v.y), float(v.z)); }
glm::dvec3 d3(const float3<float>& v) { return glm::dvec3(v.x, v.y, v.z); }

void expect_rgb_near(const float4<float>& got, const glm::dvec3& want, const char* what) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-5 * std::max(1.0, std::abs(want[c]))) << what << " channel " << c;
}

TEST(SourceLightmapped, EnvmapAtObliqueEyesReflectsAboutTheUnnormalisedNormal) {
  // Flat surface, $envmapmask texture, fast path: N (not unit) and E oblique, so that R = N,
  // R = E, R = 2(N·E)N − E or a renormalised N would each read another direction.
  constexpr LightmappedCombo kMasked{false, true, EnvmapMask::texture, EnvmapPath::fast};
  LightmappedGenericParams p;
  p.tonemap.c30 = glm::vec4(1.25f, 1.0f, 0.7f, 1.0f);
  p.envmap_tint = glm::vec4(0.9f, 0.5f, 0.3f, 0.0f);
  LightmappedTexels<float> t;
  t.base = float4<float>(0.0f, 0.0f, 0.0f, 1.0f);
  t.mask = float3<float>(0.8f, 0.4f, 0.6f);
  const glm::dvec3 normals[] = {{0.3, -0.2, 1.4}, {-0.5, 0.4, 0.7}, {0.9, 0.1, 0.35}};
  const glm::dvec3 eyes[] = {{2.0, 1.0, 3.0}, {-1.5, 0.25, 0.5}, {0.1, -2.0, 1.2}};
  EnvmapReference ref;
  ref.mask = d3(t.mask);
  ref.tint = glm::dvec3(glm::vec3(p.envmap_tint));
  ref.envmap_scale = p.tonemap.c30.z;
  for (const glm::dvec3& n : normals) {
    for (const glm::dvec3& e : eyes) {
      LightmappedInputs<float> in;
      in.normal = f3(n);
      in.eye_vector = f3(e);
      const float4<float> got = combine_direction_env<kMasked>(t, p, in);
      expect_rgb_near(got, ref(d3(in.normal), d3(in.eye_vector)) * double(p.tonemap.c30.x), "flat envmap");
    }
  }
}

TEST(SourceLightmapped, FullEnvmapPathAtObliqueEyes) {
  // Bump map in a rotated tangent frame, mask from the normal map's alpha, contrast 0.4,
  // saturation 0.6, R0 = 0.1, and eyes from 20° to 80° off the normal (Fresnel 1e-7 .. 0.4).
  constexpr LightmappedCombo kFull{true, true, EnvmapMask::normal_alpha, EnvmapPath::full};
  LightmappedGenericParams p;
  p.envmap_tint = glm::vec4(0.9f, 1.1f, 0.6f, 0.0f);
  p.envmap_contrast_saturation = glm::vec4(0.4f, 0.6f, 0.0f, 0.0f);
  p.fresnel = fresnel_constant(0.1f);
  p.tonemap.c30 = glm::vec4(1.0f, 1.0f, 0.8f, 1.0f);
  LightmappedTexels<float> t;
  t.base = float4<float>(0.0f, 0.0f, 0.0f, 1.0f);
  t.bump = float4<float>(0.62f, 0.41f, 0.97f, 0.7f);  // n = (0.24, -0.18, 0.94): |n| = 0.99
  for (int k = 1; k < 4; ++k) t.lightmap[k] = float3<float>(0.0f);
  // A frame rotated 30° about X, so that world N is not the tangent-space n.
  const double c = std::cos(0.5235987755982988), s = std::sin(0.5235987755982988);
  const glm::dvec3 tangent(1.0, 0.0, 0.0), binormal(0.0, c, s), normal(0.0, -s, c);
  LightmappedInputs<float> in;
  in.tangent = f3(tangent);
  in.binormal = f3(binormal);
  in.normal = f3(normal);
  const glm::dvec3 n = glm::dvec3(t.bump.x, t.bump.y, t.bump.z) * 2.0 - 1.0;
  const glm::dvec3 world_n = n.x * d3(in.tangent) + n.y * d3(in.binormal) + n.z * d3(in.normal);
  EnvmapReference ref;
  ref.full = true;
  ref.mask = glm::dvec3(t.bump.w);
  ref.tint = glm::dvec3(glm::vec3(p.envmap_tint));
  ref.envmap_scale = p.tonemap.c30.z;
  ref.contrast = 0.4;
  ref.saturation = 0.6;
  ref.r0 = 0.1;
  const glm::dvec3 side = glm::normalize(glm::cross(world_n, glm::dvec3(0.3, 1.0, 0.2)));
  for (double degrees : {20.0, 45.0, 60.0, 80.0}) {
    const double a = degrees * 3.14159265358979323846 / 180.0;
    in.eye_vector = f3(3.0 * (std::cos(a) * glm::normalize(world_n) + std::sin(a) * side));
    const float4<float> got = combine_direction_env<kFull>(t, p, in);
    const glm::dvec3 want = ref(world_n, d3(in.eye_vector));
    expect_rgb_near(got, want, "full envmap");
    EXPECT_GT(want.x, 1e-4) << "the Fresnel term leaves a measurable value at " << degrees << "°";
  }
}

TEST(SourceLightmapped, InvertedBaseAlphaMaskWithContrastOneAtAnObliqueEye) {
  constexpr LightmappedCombo kSquared{false, true, EnvmapMask::base_alpha_inverted, EnvmapPath::fast_contrast};
  LightmappedGenericParams p;
  p.envmap_tint = glm::vec4(0.7f, 0.9f, 0.4f, 0.0f);
  LightmappedTexels<float> t;
  t.base = float4<float>(0.0f, 0.0f, 0.0f, 0.3f);
  LightmappedInputs<float> in;
  in.normal = float3<float>(0.2f, 0.5f, 0.8f);
  in.eye_vector = float3<float>(-1.0f, 0.3f, 0.9f);
  EnvmapReference ref;
  ref.mask = glm::dvec3(1.0 - double(t.base.w));
  ref.tint = glm::dvec3(glm::vec3(p.envmap_tint));
  ref.square = true;
  const float4<float> got = combine_direction_env<kSquared>(t, p, in);
  expect_rgb_near(got, ref(d3(in.normal), d3(in.eye_vector)), "inverted base alpha, contrast 1");
  EXPECT_EQ(got.w, 1.0f) << "the base alpha is a mask, not opacity";
}

// $alpha reaches the pixel twice (lightmappedgeneric_ps2_3_x.h: alpha x= i.vertexColor.a x c12.w,
// the vertex color's alpha being cModulationColor.a): base alpha x $alpha², or $alpha² where the
// base alpha is the env-map mask.
TEST(SourceLightmapped, AlphaIsAppliedTwice) {
  LightmappedGenericParams p;
  p.tint_lightmap_scale.w = 0.5f;
  p.vertex_alpha.x = 0.5f;
  LightmappedTexels<float> t;
  t.base = float4<float>(0.2f, 0.3f, 0.4f, 0.8f);
  LightmappedInputs<float> in;
  in.normal = float3<float>(0.0f, 0.0f, 1.0f);
  in.eye_vector = float3<float>(0.0f, 0.0f, 1.0f);
  constexpr LightmappedCombo kFlat{false, false};
  EXPECT_FLOAT_EQ(lightmapped_generic_combine<kFlat>(t, in, p, [](const float3<float>& r) { return r; }).w, 0.8f * 0.25f);
  constexpr LightmappedCombo kMasked{false, true, EnvmapMask::base_alpha_inverted, EnvmapPath::fast};
  EXPECT_FLOAT_EQ(lightmapped_generic_combine<kMasked>(t, in, p, [](const float3<float>& r) { return r; }).w, 0.25f);
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
  for (const LightmappedCombo& c : kLightmappedSpace) EXPECT_TRUE(c.valid()) << c.name();
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

LightmappedGenericParams lane_test_params() {
  LightmappedGenericParams p;
  p.tint_lightmap_scale = glm::vec4(1.3f, 1.0f, 0.8f, 1.0f);
  p.envmap_contrast_saturation = glm::vec4(0.4f, 0.6f, 0.0f, 0.0f);
  p.fresnel = fresnel_constant(0.1f);
  p.tonemap = ToneMapConstants::for_scale(0.8f, 1.0f, 1.0f);
  p.fog = testing::lane_test_fog();
  return p;
}

/// Inputs: base 0-3, bump 4-7, mask 8-10, lightmaps 11-22 (flat, bump 1, 2, 3), tangent 23-25,
/// binormal 26-28, normal 29-31, eye vector 32-34, fog: world z 35, projected z 36.
constexpr int kLightmappedInputs = 37;

template <LightmappedCombo C>
auto lightmapped_lane_shader(const LightmappedGenericParams& p) {
  return [&p]<class L>(const auto& get) -> float4<L> {
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
}

template <LightmappedCombo C>
testing::LaneComparison compare_lightmapped(int hard_every, uint32_t seed) {
  const LightmappedGenericParams p = lane_test_params();
  std::vector<Draw> draws(kLightmappedInputs, Draw{0.0f, 1.0f, hard_every});
  for (int i = 11; i < 23; ++i) draws[i] = Draw{0.0f, 4.0f, hard_every};
  for (int i = 23; i < 35; ++i) draws[i] = Draw{-1.0f, 1.0f, hard_every};
  draws[35] = Draw{-10.0f, 30.0f, hard_every};
  draws[36] = Draw{0.0f, 400.0f, hard_every};
  return compare_lanes<kLightmappedInputs>(lightmapped_lane_shader<C>(p), draws, 256, seed);
}

/// Pixels built to sit on the edges of the math.
std::vector<std::array<float, kLightmappedInputs>> lightmapped_hard_pixels() {
  using Pixel = std::array<float, kLightmappedInputs>;
  const float defaults[kLightmappedInputs] = {0.6f, 0.5f, 0.4f, 0.3f, 0.55f, 0.45f, 0.9f, 0.8f, 0.7f, 0.6f, 0.5f, 1.0f,
                                              0.9f, 0.8f, 0.5f, 0.4f, 0.3f, 0.2f, 1.1f, 0.6f, 1.5f, 0.2f, 0.1f, 1.0f,
                                              0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.3f, -0.2f, 2.0f,
                                              12.0f, 150.0f};
  Pixel plain{};
  std::copy(std::begin(defaults), std::end(defaults), plain.begin());
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<Pixel> pixels;
  auto with = [&](std::initializer_list<std::pair<int, float>> changes) {
    Pixel q = plain;
    for (const auto& [i, v] : changes) q[static_cast<size_t>(i)] = v;
    pixels.push_back(q);
  };
  with({});
  with({{4, 0.5f}, {5, 0.5f}, {6, 0.0f}});  // n = (0, 0, -1): every weight 0, 0 / 0
  with({{4, 0.5f}, {5, 0.5f}, {6, 0.5f}});  // n = 0
  with({{4, 0.5f}, {5, 1.0f}, {6, 0.5f}});  // n = (0, 1, 0): n · basis 0 exactly 0
  with({{4, 1.0f}, {5, 1.0f}, {6, 1.0f}});  // |n| = √3: dots past 1, clamped
  with({{29, 0.0f}, {30, 0.0f}, {31, 0.0f}, {23, 0.0f}, {27, 0.0f}});  // zero-length world frame
  with({{29, 1e-40f}, {30, 0.0f}, {31, 1e-40f}, {23, 1e-40f}, {27, 1e-40f}});  // denormal frame
  with({{32, 0.0f}, {33, 0.0f}, {34, 0.0f}});  // the eye on the surface: E = 0
  with({{32, 0.0f}, {33, 0.0f}, {34, 5.0f}});  // head on (N parallel to E)
  with({{32, 1.0f}, {33, 0.0f}, {34, 0.0f}});  // grazing: N·E = 0
  with({{32, 1.0f}, {33, 0.0f}, {34, -1e-7f}});  // just behind
  with({{32, 1e-40f}, {33, 1e-40f}, {34, 1e-40f}});  // denormal eye
  with({{11, 1e30f}, {14, 1e30f}, {17, 1e30f}, {20, 1e30f}});  // HDR lightmaps
  with({{0, 1e30f}, {1, 1e30f}, {3, 1e30f}});
  with({{32, 1e30f}, {33, 1e30f}, {34, 1e30f}});  // N·E overflows
  with({{8, 1e30f}, {9, 1e30f}});
  with({{0, nan}, {3, nan}});
  with({{4, nan}, {7, nan}});
  with({{11, nan}, {14, nan}, {20, nan}});
  with({{29, nan}, {32, nan}});
  with({{34, std::numeric_limits<float>::infinity()}});
  // Fog (lane_test_fog: eye at z = 20, water plane z = 5, start 10, end 300).
  with({{36, 0.0f}});           // at the eye plane: no range fog
  with({{36, 10.0f}});          // near the fog's start
  with({{36, 1e30f}});          // far past the end: max density
  with({{35, 20.0f}});          // level with the eye: 1 / 0 through the water plane
  with({{35, 5.0f}});           // on the water plane
  with({{35, -10.0f}, {36, 400.0f}});  // deep below it, far
  with({{35, nan}, {36, nan}});
  return pixels;
}

TEST(SourceLightmapped, SimdAgreesWithScalarBitForBitForEveryCombo) {
  uint32_t seed = 11;
  const LightmappedGenericParams p = lane_test_params();
  const auto hard_pixels = lightmapped_hard_pixels();
  for_each_combo<testing::kLightmappedSampled>([&]<LightmappedCombo C>() {
    const auto random = compare_lightmapped<C>(0, seed++);
    const auto hard = compare_lightmapped<C>(3, seed++);
    const auto constructed = testing::compare_lanes_at<kLightmappedInputs>(lightmapped_lane_shader<C>(p), hard_pixels);
    testing::expect_bit_identical(random, C.name());
    testing::expect_bit_identical(hard, C.name() + " (hard inputs)");
    testing::expect_bit_identical(constructed, C.name() + " (constructed edge cases)");
    EXPECT_LE(random.max_step_vs_double, 1) << C.name() << ": the lane encode vs the exact curve";
    std::printf("LightmappedGeneric %-40s simd-vs-scalar max %d step(s) (hard: %d, constructed: %d)\n",
                C.name().c_str(), random.max_step, hard.max_step, constructed.max_step);
  });
}

// ---- Budgets ----------------------------------------------------------------------------------

TEST(SourceLightmapped, EveryComboFitsEveryPixelShaderModel) {
  for (const LightmappedCombo& c : kLightmappedSpace) {
    for (ShaderModel m : kPixelModels) {
      if (!c.valid(m)) continue;
      const Cost cost = counted_cost(c, m);
      const Verdict v = fits(cost, caps(m));
      EXPECT_TRUE(v) << c.name() << ": " << v.reason << " (" << describe(cost) << ")";
      EXPECT_GE(cost.texture_slots, c.bump ? 5 : 2) << c.name();
    }
  }
}

}  // namespace
}  // namespace luxel::shading::source
