#pragma once
// Helpers for the Source shader tests: run one shader body on the SIMD lane and on the scalar lane
// with the same random inputs, and compare the 8-bit values the output merger would store.

#include "lanes.hpp"
#include "luxel/rasterizer/texture.hpp"
#include "luxel/shading/source/common.hpp"
#include "luxel/shading/source/fog.hpp"
#include "luxel/shading/source/registry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace luxel::shading::source::testing {

using shading::testing::lane_of;

/// kMax combos spread evenly through a registry space (its first and last included), or all of it
/// when it has no more: what the per-combo template tests walk, each combo compiled for both
/// lanes. Every combo of every space is compared through the catalog's entry points
/// (registry_test.cpp).
template <auto kSpace, size_t kMax>
constexpr auto spread() {
  constexpr size_t kCount = kSpace.size() < kMax ? kSpace.size() : kMax;
  std::array<typename decltype(kSpace)::value_type, kCount> out{};
  for (size_t i = 0; i < kCount; ++i) out[i] = kSpace[kCount == 1 ? 0 : i * (kSpace.size() - 1) / (kCount - 1)];
  return out;
}

inline constexpr auto kLightmappedSampled = spread<kLightmappedSpace, 18>();
inline constexpr auto kVertexLitSampled = spread<kVertexLitSpace, 36>();
inline constexpr auto kUnlitSampled = spread<kUnlitSpace, 18>();
inline constexpr auto kWaterSampled = spread<kWaterSpace, 12>();

/// Inputs that break things: zeros, denormals, ±1, huge (HDR up to 1e30), NaN, infinities.
inline const std::vector<float>& hard_values() {
  static const std::vector<float> v = {0.0f, -0.0f, 1.0f, -1.0f, 0.5f, 1e-40f, -1e-42f, FLT_MIN, 1000.0f, 4096.0f,
                                       -1000.0f, 65504.0f, 1e30f, -1e30f, std::numeric_limits<float>::quiet_NaN(),
                                       std::numeric_limits<float>::infinity(), 150.0f, 0.70710678f};
  return v;
}

/// A draw in [lo, hi], or one in `hard_every` a hard value.
struct Draw {
  float lo = 0.0f, hi = 1.0f;
  int hard_every = 0;
  float operator()(std::mt19937& rng) const {
    if (hard_every > 0 && std::uniform_int_distribution<int>(0, hard_every - 1)(rng) == 0) {
      return hard_values()[std::uniform_int_distribution<size_t>(0, hard_values().size() - 1)(rng)];
    }
    return std::uniform_real_distribution<float>(lo, hi)(rng);
  }
};

struct LaneComparison {
  int max_step = 0;        ///< max |simd byte - scalar byte| over all channels
  int max_step_vs_double = 0;  ///< max |scalar byte - double-precision encode of the scalar value|
  long bit_mismatches = 0; ///< channels whose SIMD and scalar floats differ in bits (NaN = NaN)
  long pixels = 0;
  double sum_sq = 0.0;     ///< of byte differences SIMD vs scalar
  double psnr() const {
    if (sum_sq == 0.0) return std::numeric_limits<double>::infinity();
    return 10.0 * std::log10(255.0 * 255.0 / (sum_sq / (4.0 * pixels)));
  }
};

/// One stamp: in[i][l] is input i of lane l. Adds what it finds to r.
template <int K, class Shade>
void compare_stamp(Shade&& shade, const float (&in)[K][simd::kLanes], LaneComparison& r) {
  const auto simd_get = [&](int i) { return simd::Float::load_unaligned(in[i]); };
  const float4<simd::Float> fast_value = shade.template operator()<simd::Float>(simd_get);
  const float4<simd::Float> fast = encode_srgb8(fast_value);
  for (int l = 0; l < simd::kLanes; ++l) {
    const auto scalar_get = [&](int i) { return in[i][l]; };
    const float4<float> value = shade.template operator()<float>(scalar_get);
    const float4<float> ref = encode_srgb8(value);
    for (int c = 0; c < 4; ++c) {
      const float fb = lane_of(fast[c], l);
      EXPECT_TRUE(fb >= 0.0f && fb <= 255.0f && fb == std::floor(fb)) << "garbage byte " << fb;
      const int d = std::abs(static_cast<int>(fb) - static_cast<int>(ref[c]));
      r.max_step = std::max(r.max_step, d);
      r.sum_sq += static_cast<double>(d) * d;
      if (!shading::testing::same_float(lane_of(fast_value[c], l), value[c])) ++r.bit_mismatches;
      const int exact = c < 3 ? srgb8_reference(value[c])
                              : static_cast<int>(std::floor(std::clamp(std::isnan(value[c]) ? 0.0 : double(value[c]),
                                                                       0.0, 1.0) * 255.0 + 0.5));
      r.max_step_vs_double = std::max(r.max_step_vs_double, std::abs(exact - static_cast<int>(ref[c])));
    }
    ++r.pixels;
  }
}

/// `shade` is a generic lambda `[&]<class L>(const auto& get) -> float4<L>` where get(i) is the
/// i-th input as lane L. Runs `batches` SIMD stamps and every lane again as scalar.
template <int K, class Shade>
LaneComparison compare_lanes(Shade&& shade, const std::vector<Draw>& draws, int batches, uint32_t seed) {
  std::mt19937 rng(seed);
  LaneComparison r;
  for (int b = 0; b < batches; ++b) {
    float in[K][simd::kLanes];
    for (int i = 0; i < K; ++i)
      for (int l = 0; l < simd::kLanes; ++l) in[i][l] = draws[static_cast<size_t>(i) % draws.size()](rng);
    compare_stamp<K>(shade, in, r);
  }
  return r;
}

/// Fog constants with every term in play (start, a max density below 1, a non-grey color, a water
/// plane between the eye and the drawn points), for the fog combos of the lane comparisons; fog
/// inputs drawn from [-10, 30] (world z) and [0, 400] (projected z) cover both sides of each.
inline FogConstants lane_test_fog() {
  FogSettings s;
  s.start = 10.0f;
  s.end = 300.0f;
  s.max_density = 0.9f;
  s.color = glm::vec3(0.3f, 0.5f, 0.8f);
  s.water_z = 5.0f;
  return fog_constants(s, glm::vec3(1.0f, 2.0f, 20.0f), 1.2f);
}

/// The same on given pixels (K inputs each), kLanes to a stamp; the last stamp is filled up with
/// the first pixel.
template <int K, class Shade>
LaneComparison compare_lanes_at(Shade&& shade, const std::vector<std::array<float, K>>& pixels) {
  LaneComparison r;
  for (size_t first = 0; first < pixels.size(); first += simd::kLanes) {
    float in[K][simd::kLanes];
    for (int l = 0; l < simd::kLanes; ++l) {
      const size_t p = first + l < pixels.size() ? first + l : 0;
      for (int i = 0; i < K; ++i) in[i][l] = pixels[p][i];
    }
    compare_stamp<K>(shade, in, r);
  }
  return r;
}

/// The SIMD/scalar verdict every shader family's test asserts: the same bits (the design's
/// promise, lane.hpp), hence the same bytes.
inline void expect_bit_identical(const LaneComparison& r, const std::string& what) {
  EXPECT_EQ(r.bit_mismatches, 0) << what << ": SIMD and scalar results differ in bits";
  EXPECT_EQ(r.max_step, 0) << what << ": SIMD and scalar bytes differ";
}

/// A smooth analytic stand-in for the cube map, over the lane: bright toward +Z, HDR up to 8.
template <Lane L>
inline float3<L> analytic_env(const float3<L>& r) {
  const float3<L> d = normalize(r);
  return float3<L>(saturate(d.z) * 8.0f + 0.1f, saturate(d.x * 0.5f + 0.5f), saturate(d.y * 0.5f + 0.5f));
}

/// A 4x4 2D texture of one color, with mips.
inline rasterizer::Texture uniform_2d(rasterizer::TextureFormat f, const glm::vec4& c) {
  rasterizer::Texture t = rasterizer::Texture::create_2d(4, 4, f);
  t.upload(0, std::vector<glm::vec4>(16, c));
  t.generate_mips();
  return t;
}

/// A 4x4 RGBA16F cube map whose face f is (0.1 f, 0.2, 0.3, 1), with mips.
inline rasterizer::Texture face_colored_cube() {
  rasterizer::Texture cube = rasterizer::Texture::create_cube(4, rasterizer::TextureFormat::RGBA16F);
  for (int f = 0; f < 6; ++f) cube.upload(0, std::vector<glm::vec4>(16, glm::vec4(0.1f * f, 0.2f, 0.3f, 1.0f)), f);
  cube.generate_mips();
  return cube;
}

}  // namespace luxel::shading::source::testing
