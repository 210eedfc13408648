// The SIMD lane agrees with the scalar reference bit for bit, on thousands of seeded random
// inputs and on the hard cases (zero-length and denormal vectors, pow(0, 0), exponent 150,
// values > 1000, NaN and infinities), with and without flush-to-zero.

#include "lanes.hpp"

#include "luxel/shading/source/registry.hpp"
#include "luxel/shading/source/fog.hpp"
#include "luxel/shading/source/light_folding.hpp"
#include "luxel/shading/source/vertexlit_vertex_shader.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cfloat>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace luxel::shading {
namespace {

using testing::lane_of;

using testing::kInf;
using testing::kNaN;

/// Values every operand draws from besides random ones.
const std::vector<float>& hard_values() {
  static const std::vector<float> v = {
      0.0f, -0.0f, 1.0f, -1.0f, 0.5f, 2.0f, 150.0f, 149.0f, 1000.0f, 1234.5f, -4096.0f, 65504.0f,
      1e-20f, 1e-30f, FLT_MIN, -FLT_MIN, FLT_MIN / 2, 1e-40f, -1e-42f, FLT_TRUE_MIN, FLT_MAX, -FLT_MAX,
      kInf, -kInf, kNaN, 128.0f, -150.0f, -151.0f, 127.99f, 0.999999f, 1.000001f, 1.41421356f, 0.70710678f};
  return v;
}

/// An input: mostly random (over several magnitudes), one in eight a hard value.
float draw(std::mt19937& rng) {
  std::uniform_int_distribution<int> kind(0, 7);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::uniform_int_distribution<int> exponent(-40, 40);
  std::uniform_int_distribution<size_t> pick(0, hard_values().size() - 1);
  switch (kind(rng)) {
    case 0: return hard_values()[pick(rng)];
    case 1: return unit(rng) * 2000.0f;
    case 2: return std::ldexp(unit(rng), exponent(rng));
    default: return unit(rng) * 4.0f;
  }
}

/// Runs `simd_fn` on a stamp of inputs and `scalar_fn` on each lane's inputs; every output
/// component must have the same bits (or both be NaN).
template <int kArgs, int kOut>
void expect_lanes_agree(const std::string& name, int batches,
                        const std::function<std::array<simd::Float, kOut>(const std::array<simd::Float, kArgs>&)>& simd_fn,
                        const std::function<std::array<float, kOut>(const std::array<float, kArgs>&)>& scalar_fn,
                        uint32_t seed) {
  std::mt19937 rng(seed);
  int failures = 0;
  for (int b = 0; b < batches && failures < 5; ++b) {
    alignas(64) float in[kArgs][simd::kLanes];
    for (int a = 0; a < kArgs; ++a)
      for (int l = 0; l < simd::kLanes; ++l) in[a][l] = draw(rng);
    std::array<simd::Float, kArgs> args;
    for (int a = 0; a < kArgs; ++a) args[a] = simd::Float::load_aligned(in[a]);
    const auto fast = simd_fn(args);
    for (int l = 0; l < simd::kLanes; ++l) {
      std::array<float, kArgs> s;
      for (int a = 0; a < kArgs; ++a) s[a] = in[a][l];
      const auto ref = scalar_fn(s);
      for (int o = 0; o < kOut; ++o) {
        if (!testing::same_float(lane_of(fast[o], l), ref[o])) {
          ++failures;
          std::string inputs;
          for (int a = 0; a < kArgs; ++a) inputs += std::to_string(s[a]) + " ";
          ADD_FAILURE() << name << "(" << inputs << ") output " << o << ": simd " << lane_of(fast[o], l) << " vs scalar "
                        << ref[o];
        }
      }
    }
  }
}

/// One intrinsic on scalars, as a template over the lane: instantiated for both.
#define LUXEL_AGREE_1(NAME, EXPR)                                                                   \
  expect_lanes_agree<1, 1>(                                                                        \
      NAME, kBatches, [](const std::array<simd::Float, 1>& a) { using L = simd::Float; const L& x = a[0]; \
        return std::array<simd::Float, 1>{EXPR}; },                                                 \
      [](const std::array<float, 1>& a) { using L = float; const L& x = a[0]; return std::array<float, 1>{EXPR}; }, \
      seed++)
#define LUXEL_AGREE_2(NAME, EXPR)                                                                   \
  expect_lanes_agree<2, 1>(                                                                        \
      NAME, kBatches,                                                                              \
      [](const std::array<simd::Float, 2>& a) { using L = simd::Float; const L& x = a[0]; const L& y = a[1]; \
        return std::array<simd::Float, 1>{EXPR}; },                                                 \
      [](const std::array<float, 2>& a) { using L = float; const L& x = a[0]; const L& y = a[1];      \
        return std::array<float, 1>{EXPR}; },                                                       \
      seed++)

constexpr int kBatches = 2048;  // x 8 lanes: 16k inputs per intrinsic

void check_scalar_intrinsics() {
  uint32_t seed = 1;
  LUXEL_AGREE_1("saturate", saturate(x));
  LUXEL_AGREE_1("abs", abs(x));
  LUXEL_AGREE_1("frac", frac(x));
  LUXEL_AGREE_1("floor", floor(x));
  LUXEL_AGREE_1("rcp", rcp(x));
  LUXEL_AGREE_1("rsqrt", rsqrt(x));
  LUXEL_AGREE_1("sqrt", sqrt(x));
  LUXEL_AGREE_1("exp2", exp2(x));
  LUXEL_AGREE_1("exp2 small", exp2(x * 40.0f));
  LUXEL_AGREE_1("log2", log2(x));
  LUXEL_AGREE_1("step", step(L(0.25f), x));
  LUXEL_AGREE_1("smoothstep", smoothstep(L(-1.0f), L(3.0f), x));
  LUXEL_AGREE_1("sin", sin(x));
  LUXEL_AGREE_1("cos", cos(x * 100.0f));
  LUXEL_AGREE_2("min", min(x, y));
  LUXEL_AGREE_2("max", max(x, y));
  LUXEL_AGREE_2("clamp", clamp(x, y, L(2.0f)));
  LUXEL_AGREE_2("pow", pow(x, y));
  LUXEL_AGREE_2("pow exponent 150", pow(saturate(x), y * 0.0f + 150.0f));
  LUXEL_AGREE_2("pow exponent up to 150", pow(abs(x), abs(y) * 37.5f));
  LUXEL_AGREE_2("lerp", lerp(x, y, L(0.3f)));
  LUXEL_AGREE_2("divide", x / y);
  LUXEL_AGREE_2("select", select(x < y, x * 2.0f, y - 1.0f));
}

void check_vector_intrinsics() {
  uint32_t seed = 1000;
  auto vec3 = [](const auto& a, int first) {
    using L = std::remove_cvref_t<decltype(a[0])>;
    return float3<L>(a[first], a[first + 1], a[first + 2]);
  };
  expect_lanes_agree<3, 3>(
      "normalize", kBatches,
      [&](const std::array<simd::Float, 3>& a) {
        const auto n = normalize(vec3(a, 0));
        return std::array<simd::Float, 3>{n.x, n.y, n.z};
      },
      [&](const std::array<float, 3>& a) {
        const auto n = normalize(vec3(a, 0));
        return std::array<float, 3>{n.x, n.y, n.z};
      },
      seed++);
  expect_lanes_agree<6, 3>(
      "cross", kBatches,
      [&](const std::array<simd::Float, 6>& a) {
        const auto c = cross(vec3(a, 0), vec3(a, 3));
        return std::array<simd::Float, 3>{c.x, c.y, c.z};
      },
      [&](const std::array<float, 6>& a) {
        const auto c = cross(vec3(a, 0), vec3(a, 3));
        return std::array<float, 3>{c.x, c.y, c.z};
      },
      seed++);
  expect_lanes_agree<6, 3>(
      "reflect, length, dot", kBatches,
      [&](const std::array<simd::Float, 6>& a) {
        const auto r = reflect(vec3(a, 0), normalize(vec3(a, 3)));
        return std::array<simd::Float, 3>{r.y, length(vec3(a, 0)), dot(vec3(a, 0), vec3(a, 3))};
      },
      [&](const std::array<float, 6>& a) {
        const auto r = reflect(vec3(a, 0), normalize(vec3(a, 3)));
        return std::array<float, 3>{r.y, length(vec3(a, 0)), dot(vec3(a, 0), vec3(a, 3))};
      },
      seed++);
  // A Phong-like snippet: everything composed.
  auto phong = [&](const auto& a) {
    using L = std::remove_cvref_t<decltype(a[0])>;
    const float3<L> n = normalize(vec3(a, 0));
    const float3<L> l = normalize(vec3(a, 3));
    const float3<L> v = normalize(float3<L>(a[1], a[5], L(1.0f)));
    const float3<L> r = reflect(-v, n);
    const L spec = pow(saturate(dot(r, l)), L(150.0f));
    const L half_lambert = saturate(dot(n, l) * 0.5f + 0.5f);
    const float3<L> c = lerp(float3<L>(0.2f, 0.3f, 0.4f), float3<L>(half_lambert * half_lambert), L(0.75f)) + spec;
    return std::array<L, 3>{c.x, c.y, c.z};
  };
  expect_lanes_agree<6, 3>(
      "phong snippet", kBatches, [&](const std::array<simd::Float, 6>& a) { return phong(a); },
      [&](const std::array<float, 6>& a) { return phong(a); }, seed++);
}

// The Source pieces that are arithmetic only: fog (both pixel types, the blend, the vertex
// factor and the fixed-function blend) and the per-vertex lighting vertex shader, every output.
void check_source_pieces() {
  uint32_t seed = 5000;
  source::FogSettings settings;
  settings.start = 10.0f;
  settings.end = 300.0f;
  settings.max_density = 0.9f;
  settings.color = glm::vec3(0.3f, 0.5f, 0.8f);
  settings.water_z = 1.5f;
  const source::FogConstants fog = source::fog_constants(settings, glm::vec3(0.0f, 0.0f, 3.0f), 1.2f);
  const glm::vec4 c16 = source::vertex_fog_constant(settings);
  const source::ToneMapConstants tm = source::ToneMapConstants::for_scale(0.8f);
  auto fog_body = [&](const auto& a) {
    using L = std::remove_cvref_t<decltype(a[0])>;
    const source::FogInputs<L> in{a[0], a[1] * 100.0f};
    const float4<L> color(a[2], a[3], a[4], a[5]);
    const float4<L> range = source::fogged_output<source::ToneMap::linear, source::Fog::range>(color, tm, in, fog);
    const float4<L> height = source::fogged_output<source::ToneMap::linear, source::Fog::height>(color, tm, in, fog);
    const L v = source::vertex_fog(in.proj_z, c16);
    const float4<L> fixed = source::fixed_function_fog(color, v, fog);
    return std::array<L, 10>{range.x, range.y, range.z, range.w, height.x, height.y, height.z, v, fixed.x, fixed.z};
  };
  expect_lanes_agree<6, 10>(
      "fog", kBatches, [&](const std::array<simd::Float, 6>& a) { return fog_body(a); },
      [&](const std::array<float, 6>& a) { return fog_body(a); }, seed++);

  source::VertexLitVsParams vs;
  vs.model = {glm::vec4(0.8f, -0.6f, 0.0f, 1.0f), glm::vec4(0.6f, 0.8f, 0.0f, -2.0f), glm::vec4(0.0f, 0.0f, 1.0f, 0.5f)};
  vs.view_proj[2][2] = 1.5f;
  vs.view_proj[3][2] = 20.0f;
  vs.eye_position = glm::vec4(1.0f, -4.0f, 2.0f, 1.0f);
  vs.fog = c16;
  for (int j = 0; j < 6; ++j) vs.ambient.color[j] = glm::vec3(0.1f * j, 0.3f, 0.05f * (6 - j));
  source::LightDesc point, spot, sun, far;
  point.position = glm::vec3(1.0f, 2.0f, 1.0f);
  point.color = glm::vec3(3.0f, 2.0f, 1.0f);
  point.attenuation = glm::vec3(0.0f, 0.0f, 1.0f);
  spot.type = source::LightDesc::Type::spot;
  spot.position = glm::vec3(0.0f, 0.0f, 3.0f);
  spot.cos_inner = 0.9f;
  spot.cos_outer = 0.5f;
  spot.color = glm::vec3(50.0f);
  sun.type = source::LightDesc::Type::directional;
  sun.direction = glm::vec3(0.3f, -1.0f, -0.2f);
  far.position = glm::vec3(-5.0f, 0.0f, 0.0f);
  vs.lights = {source::to_local_light(point), source::to_local_light(spot), source::to_local_light(sun),
               source::to_local_light(far)};
  auto vs_body = [&]<source::VertexLitVsCombo C>(const auto& a) {
    using L = std::remove_cvref_t<decltype(a[0])>;
    source::VertexLitVsInputs<L> in;
    in.position = float4<L>(a[0], a[1], a[2], L(1.0f));
    in.normal = float3<L>(a[3], a[4], a[5]);
    const source::VertexLitVsOutputs<L> o = source::vertexlit_vertex_shader<C>(in, vs);
    return std::array<L, 9>{o.proj_pos.z, o.lighting.x, o.lighting.y, o.lighting.z, o.eye_vector.x,
                            o.world_normal.y, o.world_pos_proj_z.w, o.fog, o.proj_pos.w};
  };
  source::for_each_combo<source::kVertexLitVsSpace>([&]<source::VertexLitVsCombo C>() {
    expect_lanes_agree<6, 9>(
        "vertexlit vertex shader " + C.name(), kBatches,
        [&](const std::array<simd::Float, 6>& a) { return vs_body.template operator()<C>(a); },
        [&](const std::array<float, 6>& a) { return vs_body.template operator()<C>(a); }, seed++);
  });
}

TEST(LanesAgree, ScalarIntrinsicsBitExact) { check_scalar_intrinsics(); }
TEST(LanesAgree, SourceFogAndVertexLightingBitExact) { check_source_pieces(); }
TEST(LanesAgree, VectorIntrinsicsBitExact) { check_vector_intrinsics(); }

TEST(LanesAgree, BitExactWithFlushToZeroToo) {
  simd::ScopedFlushDenormals ftz;  // the mode every rasterizer worker shades in
  check_scalar_intrinsics();
  check_vector_intrinsics();
  check_source_pieces();
}

TEST(LanesAgree, ZeroLengthAndDenormalVectors) {
  // Spelled out: these are the values normalize() must agree on in both lanes.
  for (const float v : {0.0f, 1e-40f, 1e-21f, 1e-23f, FLT_MIN}) {
    const float3<float> s = normalize(float3<float>(v, 0.0f, 0.0f));
    const float3<simd::Float> f = normalize(float3<simd::Float>(simd::Float(v), simd::Float(0.0f), simd::Float(0.0f)));
    EXPECT_TRUE(testing::same_float(s.x, lane_of(f.x, 0))) << v;
  }
  // dot = 0 exactly: v * FLT_MAX (nrm), so 0 stays 0 and a denormal becomes tiny but finite.
  EXPECT_EQ(normalize(float3<float>(0.0f)).x, 0.0f);
  EXPECT_EQ(normalize(float3<float>(1e-40f, 0.0f, 0.0f)).x, 1e-40f * FLT_MAX);
  // 1e-21 squared is a denormal (not zero): normalization still works, to denormal precision.
  EXPECT_NEAR(normalize(float3<float>(1e-21f, 0.0f, 0.0f)).x, 1.0f, 0.01f);
  // 1e-23 squared underflows to zero: the FLT_MAX rule applies.
  EXPECT_EQ(normalize(float3<float>(1e-23f, 0.0f, 0.0f)).x, 1e-23f * FLT_MAX);
}

}  // namespace
}  // namespace luxel::shading
