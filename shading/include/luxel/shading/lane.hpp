#pragma once
// Lanes: the scalar types shader code is written over, once (Mitsuba's `Float`).
//
//   float        the scalar reference: one pixel, plain C++ float arithmetic;
//   simd::Float  the fast path: one SIMD lane per pixel, a stamp of 2x2 quads (simd.hpp);
//   Counted      no numbers at all: records the DX9 instructions the code would compile to
//                (counted.hpp), so budgets come from the real shader code.
//
// Shader code never branches per lane: a per-lane `if` is a mask and `select`. Compare raw
// simd::Float values with ==, <, <=, >, >= only: xsimd 8's `a != b` is the ordered compare, false
// when either is NaN, unlike the scalar lane's; write !(a == b) (the vector types do). This header holds
// the few primitives the two numeric lanes implement differently (select, bit casts, rounding);
// everything above it (vector.hpp, intrinsics.hpp) is written once over them. The SIMD overloads
// only call xsimd, never an ISA intrinsic, and use no approximate instruction (no rcpps/rsqrtps),
// so both lanes perform the same IEEE operations in the same order and agree bit for bit.

#include "luxel/rasterizer/simd.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <type_traits>

namespace luxel::shading {

namespace simd = rasterizer::simd;

class Counted;
class CountedMask;

/// What each lane type brings: its mask type (`bool1` in HLSL terms) and, for the numeric lanes,
/// the matching 32-bit integer lane. Specialised for Counted in counted.hpp.
template <class L>
struct LaneTraits;

template <>
struct LaneTraits<float> {
  using Mask = bool;
  using Int = int32_t;
};

template <>
struct LaneTraits<simd::Float> {
  using Mask = simd::FloatMask;
  using Int = simd::Int;
};

template <class L>
concept Lane = requires { typename LaneTraits<L>::Mask; };

/// The per-lane boolean of lane type L.
template <Lane L>
using Mask = typename LaneTraits<L>::Mask;

template <class L>
inline constexpr bool kIsCounted = std::is_same_v<L, Counted>;

template <class L>
concept NumericLane = std::is_same_v<L, float> || std::is_same_v<L, simd::Float>;

/// Primitives of the numeric lanes. Same names, same IEEE results, per lane.
namespace lane {

LUXEL_INLINE float select(bool m, float a, float b) { return m ? a : b; }
LUXEL_INLINE simd::Float select(const simd::FloatMask& m, const simd::Float& a, const simd::Float& b) {
  return xsimd::select(m, a, b);
}
LUXEL_INLINE int32_t select(bool m, int32_t a, int32_t b) { return m ? a : b; }

LUXEL_INLINE float sqrt(float x) { return std::sqrt(x); }
LUXEL_INLINE simd::Float sqrt(const simd::Float& x) { return xsimd::sqrt(x); }

LUXEL_INLINE float floor(float x) { return std::floor(x); }
LUXEL_INLINE simd::Float floor(const simd::Float& x) { return xsimd::floor(x); }

/// Round to nearest, ties to even (the default rounding mode of both lanes).
LUXEL_INLINE float round_even(float x) { return std::nearbyint(x); }
LUXEL_INLINE simd::Float round_even(const simd::Float& x) { return xsimd::nearbyint(x); }

/// |x| by clearing the sign bit (NaN stays NaN).
LUXEL_INLINE float abs(float x) { return std::fabs(x); }
LUXEL_INLINE simd::Float abs(const simd::Float& x) { return xsimd::abs(x); }

/// NaN test. Not `x != x`: xsimd 8's != on batches is the ordered compare (NaN != NaN is false).
LUXEL_INLINE bool is_nan(float x) { return std::isnan(x); }
LUXEL_INLINE simd::FloatMask is_nan(const simd::Float& x) { return xsimd::isnan(x); }

/// The IEEE bits of x, and back.
LUXEL_INLINE int32_t bits(float x) { return std::bit_cast<int32_t>(x); }
LUXEL_INLINE simd::Int bits(const simd::Float& x) { return xsimd::bitwise_cast<simd::Int>(x); }
LUXEL_INLINE float from_bits(int32_t b) { return std::bit_cast<float>(b); }
LUXEL_INLINE simd::Float from_bits(const simd::Int& b) { return xsimd::bitwise_cast<simd::Float>(b); }

/// Conversions between float and int lanes; `to_int_exact` expects an integral value.
LUXEL_INLINE float to_float(int32_t i) { return static_cast<float>(i); }
LUXEL_INLINE simd::Float to_float(const simd::Int& i) { return xsimd::to_float(i); }
LUXEL_INLINE int32_t to_int_exact(float x) { return static_cast<int32_t>(x); }
LUXEL_INLINE simd::Int to_int_exact(const simd::Float& x) { return xsimd::to_int(x); }

}  // namespace lane
}  // namespace luxel::shading
