#pragma once
// The lane abstraction: every SIMD type and every ISA-specific instruction of luxel lives here.
//
// Lanes are pixels. A *stamp* is one SIMD batch of pixels: kLanes/4 2x2 quads side by side,
// kStampWidth x 2 pixels. Lane order is quad-major: lane 4q+0 is the quad's top-left pixel, 4q+1
// top-right, 4q+2 bottom-left, 4q+3 bottom-right. Derivatives (ddx/ddy) are taken per quad.
//
// The default build (x86-64-v3) gives 8 float lanes (AVX2): a stamp is 4x2 pixels.

#include <xsimd/xsimd.hpp>

#include <cstdint>
#include <type_traits>
#include <utility>

#if defined(__AVX2__) || defined(__AVX512F__)
#include <immintrin.h>
#endif

namespace luxel::rasterizer::simd {

using Arch = xsimd::default_arch;
using Float = xsimd::batch<float, Arch>;
using Int = xsimd::batch<int32_t, Arch>;
using UInt = xsimd::batch<uint32_t, Arch>;
using FloatMask = xsimd::batch_bool<float, Arch>;
using IntMask = xsimd::batch_bool<int32_t, Arch>;

inline constexpr int kLanes = static_cast<int>(Float::size);
static_assert(kLanes >= 4 && kLanes % 4 == 0, "a stamp holds whole 2x2 quads");
inline constexpr int kQuadsPerStamp = kLanes / 4;
inline constexpr int kStampWidth = kLanes / 2;
inline constexpr int kStampHeight = 2;
/// One bit per lane.
using LaneBits = uint32_t;
inline constexpr LaneBits kAllLanes = kLanes == 32 ? ~0u : ((1u << kLanes) - 1u);

/// Four float lanes: a varying, a color, a position.
struct Float4 {
  Float x, y, z, w;
};

/// Pixel x offset of lane l inside its stamp.
constexpr int lane_x(int l) { return 2 * (l / 4) + (l & 1); }
/// Pixel y offset of lane l inside its stamp.
constexpr int lane_y(int l) { return (l >> 1) & 1; }

namespace detail {
template <class Batch, class Fn, std::size_t... I>
inline Batch make_lanes(Fn fn, std::index_sequence<I...>) {
  return Batch{static_cast<typename Batch::value_type>(fn(static_cast<int>(I)))...};
}
template <int Corner, std::size_t... I>
inline Float quad_broadcast(const Float& v, std::index_sequence<I...>) {
  return xsimd::swizzle(v, xsimd::batch_constant<UInt, static_cast<uint32_t>((I / 4) * 4 + Corner)...>());
}
}  // namespace detail

/// A batch whose lane l is fn(l).
template <class Batch = Float, class Fn>
inline Batch lanes(Fn fn) {
  return detail::make_lanes<Batch>(fn, std::make_index_sequence<Batch::size>());
}

/// Lane l holds v's value at corner `Corner` (0..3) of lane l's quad.
template <int Corner>
inline Float quad_corner(const Float& v) {
  return detail::quad_broadcast<Corner>(v, std::make_index_sequence<kLanes>());
}

/// Coarse derivatives (one value per quad, as DX9 hardware computes them): d/dx is the top row's
/// difference, d/dy the left column's.
inline Float ddx(const Float& v) { return quad_corner<1>(v) - quad_corner<0>(v); }
inline Float ddy(const Float& v) { return quad_corner<2>(v) - quad_corner<0>(v); }

/// The lane bits of a mask (bit l set when lane l is true).
template <class T>
inline LaneBits to_bits(const xsimd::batch_bool<T, Arch>& m) {
#if defined(__AVX512F__)
  return static_cast<LaneBits>(m.data);
#elif defined(__AVX2__)
  if constexpr (std::is_same_v<T, float>) {
    return static_cast<LaneBits>(_mm256_movemask_ps(m.data));
  } else {
    static_assert(sizeof(T) == 4);
    return static_cast<LaneBits>(_mm256_movemask_ps(_mm256_castsi256_ps(m.data)));
  }
#else
  alignas(64) bool b[xsimd::batch_bool<T, Arch>::size];
  m.store_aligned(b);
  LaneBits bits = 0;
  for (std::size_t i = 0; i < xsimd::batch_bool<T, Arch>::size; ++i) bits |= LaneBits(b[i]) << i;
  return bits;
#endif
}

/// Lanes whose sign bit is set (negative integers).
inline LaneBits sign_bits(const Int& v) {
#if defined(__AVX512F__)
  return static_cast<LaneBits>(_mm512_movepi32_mask(v));
#elif defined(__AVX2__)
  return static_cast<LaneBits>(_mm256_movemask_ps(_mm256_castsi256_ps(v)));
#else
  return to_bits(v < Int(0));
#endif
}

/// The mask whose lane l is bit l of `bits`.
inline IntMask int_mask(LaneBits bits) {
  static const Int lane_bit = lanes<Int>([](int l) { return 1 << l; });
  return (Int(static_cast<int32_t>(bits)) & lane_bit) != Int(0);
}
inline FloatMask float_mask(LaneBits bits) {
  static const Int lane_bit = lanes<Int>([](int l) { return 1 << l; });
  return xsimd::to_float(Int(static_cast<int32_t>(bits)) & lane_bit) != Float(0.0f);
}

/// kLanes bytes at p, widened to 32-bit lanes.
inline Int load_bytes(const uint8_t* p) {
#if defined(__AVX512F__)
  return Int(_mm512_cvtepu8_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p))));
#elif defined(__AVX2__)
  return Int(_mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(p))));
#else
  alignas(64) int32_t v[kLanes];
  for (int i = 0; i < kLanes; ++i) v[i] = p[i];
  return Int::load_aligned(v);
#endif
}

/// Stores the low byte of each lane to p[0..kLanes).
inline void store_bytes(uint8_t* p, const Int& v) {
#if defined(__AVX512F__)
  _mm_storeu_si128(reinterpret_cast<__m128i*>(p), _mm512_cvtepi32_epi8(v));
#elif defined(__AVX2__)
  const __m256i packed16 = _mm256_packus_epi32(v, v);            // lanes 0-3,0-3 | 4-7,4-7 (16 bit)
  const __m256i packed8 = _mm256_packus_epi16(packed16, packed16);  // bytes 0-3 .. | 4-7 ..
  const uint32_t lo = static_cast<uint32_t>(_mm256_extract_epi32(packed8, 0));
  const uint32_t hi = static_cast<uint32_t>(_mm256_extract_epi32(packed8, 4));
  const uint64_t both = lo | (uint64_t(hi) << 32);
  __builtin_memcpy(p, &both, 8);
#else
  alignas(64) int32_t v2[kLanes];
  v.store_aligned(v2);
  for (int i = 0; i < kLanes; ++i) p[i] = static_cast<uint8_t>(v2[i]);
#endif
}

/// Float to int32 with round-to-nearest-even (the conversion D3D10 prescribes for UNORM writes).
inline Int round_to_int(const Float& x) { return xsimd::nearbyint_as_int(x); }

/// Sets flush-to-zero and denormals-are-zero on this thread (D3D10 flushes float32 denormals) and
/// restores the previous mode on destruction. Every worker runs shaders in this mode.
class ScopedFlushDenormals {
 public:
  ScopedFlushDenormals();
  ~ScopedFlushDenormals();
  ScopedFlushDenormals(const ScopedFlushDenormals&) = delete;
  ScopedFlushDenormals& operator=(const ScopedFlushDenormals&) = delete;

 private:
  unsigned saved_;
};

}  // namespace luxel::rasterizer::simd
