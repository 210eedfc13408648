#pragma once
// Test helpers: one value on every lane, and reading lanes back, for both numeric lane types.

#include "luxel/shading/hlsl.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace luxel::shading::testing {

inline constexpr float kInf = std::numeric_limits<float>::infinity();
inline constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

template <class L>
inline constexpr int kWidth = std::is_same_v<L, float> ? 1 : simd::kLanes;

/// Lane i of a value (the value itself for the float lane).
inline float lane_of(float v, int) { return v; }
inline float lane_of(const simd::Float& v, int i) {
  alignas(64) float a[simd::kLanes];
  v.store_aligned(a);
  return a[i];
}
inline bool lane_of(bool m, int) { return m; }
inline bool lane_of(const simd::FloatMask& m, int i) { return (simd::to_bits(m) >> i) & 1u; }

/// A lane value whose lane i is fn(i).
template <class L, class Fn>
L make_lanes(Fn fn) {
  if constexpr (std::is_same_v<L, float>) {
    return fn(0);
  } else {
    return simd::lanes<simd::Float>([&](int i) { return fn(i); });
  }
}

/// Same bits, or both NaN.
inline bool same_float(float a, float b) {
  if (std::isnan(a) && std::isnan(b)) return true;
  return std::bit_cast<uint32_t>(a) == std::bit_cast<uint32_t>(b);
}

/// Distance in units in the last place between two finite floats of the same sign region.
inline int64_t ulp_distance(float a, float b) {
  auto ordered = [](float f) {
    const int32_t i = std::bit_cast<int32_t>(f);
    return i < 0 ? static_cast<int64_t>(INT32_MIN) - i : static_cast<int64_t>(i);
  };
  const int64_t d = ordered(a) - ordered(b);
  return d < 0 ? -d : d;
}

}  // namespace luxel::shading::testing
