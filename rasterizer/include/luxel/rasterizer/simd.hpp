#pragma once
// The lane abstraction: every SIMD type and every ISA-specific instruction of luxel lives here.
//
// Lanes are pixels. A *stamp* is one SIMD batch of pixels: kLanes/4 2x2 quads side by side,
// kStampWidth x 2 pixels. Lane order is quad-major: lane 4q+0 is the quad's top-left pixel, 4q+1
// top-right, 4q+2 bottom-left, 4q+3 bottom-right. Derivatives (ddx/ddy) are taken per quad.
//
// AVX2 gives 8 float lanes (a stamp is 4x2 pixels), AVX-512 16 (8x2): the build's LUXEL_ARCH
// decides, the default being the build machine's own ISA.

#include <xsimd/xsimd.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <utility>

#if defined(__AVX2__) || defined(__AVX512F__)
#include <immintrin.h>
#endif

/// Forces inlining of the small functions per-pixel work is made of (the lane language, texture
/// filtering, the stamp path), as Mitsuba's and Enoki's ENOKI_INLINE does: in a translation unit
/// that instantiates many shaders, GCC's unit-growth limits otherwise leave them out of line,
/// which made SIMD shaders up to 10x slower. Sanitizer builds leave inlining to the compiler:
/// there, forced inlining of instrumented code multiplied compile times (over 10 minutes for one
/// file) and buys nothing.
#if defined(LUXEL_SANITIZE_BUILD)
#define LUXEL_INLINE inline
#define LUXEL_INLINE_LAMBDA
#else
#define LUXEL_INLINE [[gnu::always_inline]] inline
/// The same for a lambda: `[&](int i) LUXEL_INLINE_LAMBDA { ... }`.
#define LUXEL_INLINE_LAMBDA __attribute__((always_inline))
#endif

namespace luxel::rasterizer::simd {

using Arch = xsimd::default_arch;
using Float = xsimd::batch<float, Arch>;
using Int = xsimd::batch<int32_t, Arch>;
using UInt = xsimd::batch<uint32_t, Arch>;
using FloatMask = xsimd::batch_bool<float, Arch>;
using IntMask = xsimd::batch_bool<int32_t, Arch>;

inline constexpr int kLanes = static_cast<int>(Float::size);

/// The instruction set the lanes were compiled for (chosen at build time: LUXEL_ARCH).
inline constexpr const char* kIsaName =
#if defined(__AVX512F__)
    "avx512";
#elif defined(__AVX2__)
    "avx2";
#elif defined(__SSE4_2__)
    "sse4.2";
#else
    "portable";
#endif
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
/// The lane at row-major position i of a stamp (x = i % kStampWidth, y = i / kStampWidth).
constexpr uint32_t row_major_lane(std::size_t i, std::size_t width) {
  return static_cast<uint32_t>(4 * ((i % width) / 2) + (i % width) % 2 + 2 * (i / width));
}
template <std::size_t... I>
inline Float row_major(const Float& v, std::index_sequence<I...>) {
  return xsimd::swizzle(v, xsimd::batch_constant<UInt, row_major_lane(I, kLanes / 2)...>());
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

/// v's lanes in the stamp's row-major pixel order: the top row left to right, then the bottom
/// row (a stamp's pixels as an image stores them).
inline Int to_row_major(const Int& v) {
  return xsimd::bitwise_cast<Int>(detail::row_major(xsimd::bitwise_cast<Float>(v), std::make_index_sequence<kLanes>()));
}

/// Stores a stamp's 32-bit pixels in row-major order (to_row_major) as the image rows they
/// cover: lanes [0, kStampWidth) at `top`, the others at `bottom` (unaligned), with no trip
/// through memory in between (a wide store read back in halves waits for it to retire).
inline void store_stamp_rows(const Int& row_major, void* top, void* bottom) {
#if defined(__AVX512F__)
  _mm256_storeu_si256(static_cast<__m256i*>(top), _mm512_castsi512_si256(row_major));
  _mm256_storeu_si256(static_cast<__m256i*>(bottom), _mm512_extracti64x4_epi64(row_major, 1));
#elif defined(__AVX2__)
  _mm_storeu_si128(static_cast<__m128i*>(top), _mm256_castsi256_si128(row_major));
  _mm_storeu_si128(static_cast<__m128i*>(bottom), _mm256_extracti128_si256(row_major, 1));
#else
  alignas(64) int32_t v[kLanes];
  row_major.store_aligned(v);
  __builtin_memcpy(top, v, sizeof(int32_t) * kStampWidth);
  __builtin_memcpy(bottom, v + kStampWidth, sizeof(int32_t) * kStampWidth);
#endif
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

/// The mask of no lanes, made in a register: xsimd's batch_bool(bool) is a call where a large
/// translation unit leaves it out of line, and a call costs its caller every live vector register.
inline IntMask no_lanes() {
#if defined(__AVX512F__)
  return IntMask(__mmask16(0));
#elif defined(__AVX2__)
  return IntMask(_mm256_setzero_si256());
#else
  return IntMask(false);
#endif
}

/// Four int32 lanes, whatever kLanes is: a triangle's three edges side by side (the fourth lane
/// unused), stepped and tested together.
using Int4 = xsimd::make_sized_batch_t<int32_t, 4>;
static_assert(!std::is_void_v<Int4>, "the target has 4-lane integer vectors");

/// Lane bits of the negative lanes of v. (A template only so that it can step aside where Int4
/// is Int, 4-lane targets: sign_bits(const Int&) below then serves both.)
template <class V, std::enable_if_t<std::is_same_v<V, Int4> && !std::is_same_v<Int4, Int>, int> = 0>
inline LaneBits sign_bits(const V& v) {
#if defined(__SSE2__)
  return static_cast<LaneBits>(_mm_movemask_ps(_mm_castsi128_ps(v)));
#else
  LaneBits bits = 0;
  for (int i = 0; i < 4; ++i) bits |= LaneBits(v.get(i) < 0) << i;
  return bits;
#endif
}

/// Every lane holds lane `Lane` of v.
template <int Lane>
inline Int broadcast_lane(const Int4& v) {
  static_assert(Lane >= 0 && Lane < 4);
#if defined(__AVX512F__)
  return Int(_mm512_broadcastd_epi32(_mm_shuffle_epi32(v, Lane * 0x55)));
#elif defined(__AVX2__)
  return Int(_mm256_broadcastd_epi32(_mm_shuffle_epi32(v, Lane * 0x55)));
#else
  return Int(v.get(Lane));
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

// Lane masks as integer vectors: a lane is all ones (true) or zero (false). Cheaper to combine
// with coverage and comparison results than bits, and they select directly.

/// All-ones lanes where `m` is true.
inline Int mask_of(const FloatMask& m) {
#if defined(__AVX512F__)
  return Int(_mm512_movm_epi32(m.data));
#elif defined(__AVX2__)
  return Int(_mm256_castps_si256(m.data));
#else
  return xsimd::bitwise_cast<Int>(xsimd::select(m, xsimd::bitwise_cast<Float>(Int(-1)), Float(0.0f)));
#endif
}
inline Int mask_of(const IntMask& m) {
#if defined(__AVX512F__)
  return Int(_mm512_movm_epi32(m.data));
#elif defined(__AVX2__)
  return Int(m.data);
#else
  return xsimd::select(m, Int(-1), Int(0));
#endif
}
/// `a` where `mask` lanes are all ones, else `b`.
inline Float select(const Int& mask, const Float& a, const Float& b) {
#if defined(__AVX512F__)
  return Float(_mm512_mask_blend_ps(_mm512_movepi32_mask(mask), b, a));
#elif defined(__AVX2__)
  return Float(_mm256_blendv_ps(b, a, _mm256_castsi256_ps(mask)));
#else
  // xsimd selects floats by a float mask: the integer lanes go through as bits.
  return xsimd::bitwise_cast<Float>(xsimd::select(mask != Int(0), xsimd::bitwise_cast<Int>(a), xsimd::bitwise_cast<Int>(b)));
#endif
}
inline Int select(const Int& mask, const Int& a, const Int& b) {
#if defined(__AVX512F__)
  return Int(_mm512_mask_blend_epi32(_mm512_movepi32_mask(mask), b, a));
#elif defined(__AVX2__)
  return Int(_mm256_blendv_epi8(b, a, mask));
#else
  return xsimd::select(mask != Int(0), a, b);
#endif
}

/// The mask whose lane l is bit l of `bits`.
/// (The lane bits are built in place, not kept in a function-local static: the compiler folds
/// them into a constant, where a static costs its guard's check on every call.)
inline IntMask int_mask(LaneBits bits) {
  return (Int(static_cast<int32_t>(bits)) & lanes<Int>([](int l) { return 1 << l; })) != Int(0);
}
inline FloatMask float_mask(LaneBits bits) {
  return xsimd::to_float(Int(static_cast<int32_t>(bits)) & lanes<Int>([](int l) { return 1 << l; })) != Float(0.0f);
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

/// Byte kByte (0 = the lowest) of each lane, zero-extended. The bytes above the lowest come by
/// one byte shuffle (port 5 on Intel cores, where the shift-and-mask pair would take two of the
/// ports the conversions and FMAs of texture filtering already crowd; one cheap op on AMD's).
template <int kByte>
inline Int byte_of(const Int& v) {
  static_assert(kByte >= 0 && kByte < 4);
  if constexpr (kByte == 0) {
    return v & Int(0xff);
  } else {
#if defined(__AVX512BW__) || (defined(__AVX2__) && !defined(__AVX512F__))
    // Within each 128-bit block, lane l's byte kByte to its lowest byte, zeros above (-1).
    const __m128i pick = _mm_setr_epi8(kByte, -1, -1, -1, 4 + kByte, -1, -1, -1, 8 + kByte, -1, -1, -1, 12 + kByte, -1, -1, -1);
#if defined(__AVX512BW__)
    return Int(_mm512_shuffle_epi8(v, _mm512_broadcast_i32x4(pick)));
#else
    return Int(_mm256_shuffle_epi8(v, _mm256_broadcastsi128_si256(pick)));
#endif
#else
    return (v >> (8 * kByte)) & Int(0xff);
#endif
  }
}

/// base[index[l]] in each lane l. (xsimd 8.1's batch<int32_t>::gather never picks the AVX2
/// instruction, its enable_if makes that overload unusable, and inserts lanes one by one.)
inline Int gather(const int32_t* base, const Int& index) {
#if defined(__AVX512F__)
  return Int(_mm512_i32gather_epi32(index, base, 4));
#elif defined(__AVX2__)
  return Int(_mm256_i32gather_epi32(base, index, 4));
#else
  return Int::gather(base, index);
#endif
}
inline Float gather(const float* base, const Int& index) {
#if defined(__AVX512F__)
  return Float(_mm512_i32gather_ps(index, base, 4));
#elif defined(__AVX2__)
  return Float(_mm256_i32gather_ps(base, index, 4));
#else
  return Float::gather(base, index);
#endif
}

/// The 8 bytes at base + index[l] (index in 32-bit words) in each lane l: `low` gets
/// base[index[l]], `high` base[index[l] + 1].
inline void gather_pairs(const int32_t* base, const Int& index, Int& low, Int& high) {
#if defined(__AVX512F__)
  // Two gathers of eight 64-bit elements, not two of sixteen 32-bit ones: a gather costs about a
  // load per element on AMD and Intel cores alike, and two permutes put the halves back in lane
  // order (bench/README.md).
  const __m512i first = _mm512_i32gather_epi64(_mm512_castsi512_si256(index), base, 4);
  const __m512i second = _mm512_i32gather_epi64(_mm512_extracti64x4_epi64(index, 1), base, 4);
  const __m512i even = _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30);
  low = Int(_mm512_permutex2var_epi32(first, even, second));
  high = Int(_mm512_permutex2var_epi32(first, _mm512_add_epi32(even, _mm512_set1_epi32(1)), second));
#else
  // (At 8 lanes the two 32-bit gathers measured faster than 64-bit ones and their shuffles.)
  low = gather(base, index);
  high = gather(base, index + Int(1));
#endif
}

/// table[index[l]] in each lane l, for a table of 256 floats and indices in [0, 255]: the decode of
/// a byte through a curve (lookup_bytes3 without AVX-512 VBMI). At 16 lanes the table is read as eight
/// two-register halves of 32 entries, each permuted by the index's low five bits, and merged by its
/// top three bits: eight permutes and seven blends in place of a gather, which costs about a load
/// per lane on AMD and Intel cores alike (bench/README.md).
inline Float lookup_byte(const float* table, const Int& index) {
#if defined(__AVX512F__)
  static_assert(kLanes == 16);
  __m512 part[8];
  for (int k = 0; k < 8; ++k)
    part[k] = _mm512_permutex2var_ps(_mm512_loadu_ps(table + 32 * k), index, _mm512_loadu_ps(table + 32 * k + 16));
  const __mmask16 bit5 = _mm512_test_epi32_mask(index, _mm512_set1_epi32(32));
  const __mmask16 bit6 = _mm512_test_epi32_mask(index, _mm512_set1_epi32(64));
  const __mmask16 bit7 = _mm512_test_epi32_mask(index, _mm512_set1_epi32(128));
  __m512 quarter[4];
  for (int k = 0; k < 4; ++k) quarter[k] = _mm512_mask_blend_ps(bit5, part[2 * k], part[2 * k + 1]);
  const __m512 low = _mm512_mask_blend_ps(bit6, quarter[0], quarter[1]);
  const __m512 high = _mm512_mask_blend_ps(bit6, quarter[2], quarter[3]);
  return Float(_mm512_mask_blend_ps(bit7, low, high));
#else
  return gather(table, index);
#endif
}

/// A table of 256 floats, as lookup_bytes3 reads it: the entries, and their bytes as four planes
/// (plane k holds byte k of every entry's bits).
struct ByteTable {
  std::array<float, 256> entries;
  alignas(64) std::array<std::array<uint8_t, 256>, 4> planes;
};

constexpr ByteTable byte_table(const std::array<float, 256>& entries) {
  ByteTable t{entries, {}};
  for (size_t i = 0; i < 256; ++i) {
    const uint32_t bits = std::bit_cast<uint32_t>(entries[i]);
    for (size_t k = 0; k < 4; ++k) t.planes[k][i] = uint8_t(bits >> (8 * k));
  }
  return t;
}

/// table.entries[byte k of word[l]] in each lane l, for bytes k = 0, 1, 2 (the decode of an RGBA8
/// texel's color through a curve: texture sampling's sRGB). With AVX-512 VBMI all 64 bytes of the
/// words are looked up at once, a byte plane at a time (two 128-byte permutes merged by the byte's
/// top bit), and the planes' bytes transposed back into floats by unpacks: fewer shuffles than
/// three lookup_byte, and a third of their table loads (bench/README.md).
inline void lookup_bytes3(const ByteTable& table, const Int& words, Float& b0, Float& b1, Float& b2) {
#if defined(__AVX512VBMI__)
  static_assert(kLanes == 16);
  const __m512i w = words;
  const __mmask64 high = _mm512_movepi8_mask(w);
  __m512i p[4];
  for (int k = 0; k < 4; ++k) {
    const uint8_t* plane = table.planes[size_t(k)].data();
    const __m512i low_half = _mm512_permutex2var_epi8(_mm512_load_si512(plane), w, _mm512_load_si512(plane + 64));
    const __m512i high_half = _mm512_permutex2var_epi8(_mm512_load_si512(plane + 128), w, _mm512_load_si512(plane + 192));
    p[k] = _mm512_mask_blend_epi8(high, low_half, high_half);
  }
  // Within each 128-bit block (lanes 4c..4c+3), byte 4j + i of plane k is byte k of the entry of
  // lane 4c + j's byte i. Bytes 0-1 and 2-3 of each entry paired into words, then words into
  // dwords: u[j] holds lane 4c + j's four entries in order.
  const __m512i t01_low = _mm512_unpacklo_epi8(p[0], p[1]), t01_high = _mm512_unpackhi_epi8(p[0], p[1]);
  const __m512i t23_low = _mm512_unpacklo_epi8(p[2], p[3]), t23_high = _mm512_unpackhi_epi8(p[2], p[3]);
  const __m512i u0 = _mm512_unpacklo_epi16(t01_low, t23_low), u1 = _mm512_unpackhi_epi16(t01_low, t23_low);
  const __m512i u2 = _mm512_unpacklo_epi16(t01_high, t23_high), u3 = _mm512_unpackhi_epi16(t01_high, t23_high);
  // A 4 x 4 transpose of dwords per block: lane j's entry i to channel i's lane j.
  const __m512i v01 = _mm512_unpacklo_epi32(u0, u1), v23 = _mm512_unpacklo_epi32(u2, u3);
  const __m512i v01_high = _mm512_unpackhi_epi32(u0, u1), v23_high = _mm512_unpackhi_epi32(u2, u3);
  b0 = Float(_mm512_castsi512_ps(_mm512_unpacklo_epi64(v01, v23)));
  b1 = Float(_mm512_castsi512_ps(_mm512_unpackhi_epi64(v01, v23)));
  b2 = Float(_mm512_castsi512_ps(_mm512_unpacklo_epi64(v01_high, v23_high)));
#else
  b0 = lookup_byte(table.entries.data(), byte_of<0>(words));
  b1 = lookup_byte(table.entries.data(), byte_of<1>(words));
  b2 = lookup_byte(table.entries.data(), byte_of<2>(words));
#endif
}

/// How many words past its first lane's index gather_stamp_rows may read for a stamp row (0: it
/// never reads windows). Memory it reads through must extend this far past the last index.
inline constexpr int kStampRowWindowWords =
#if defined(__AVX512F__)
    32;
#elif defined(__AVX2__)
    8;
#else
    0;
#endif

/// base[index[l]] in each lane l, as gather() returns it, read without a gather when the indices
/// of each stamp row lie close together: when every lane's index is at most kStampRowWindowWords
/// - 1 words past the index of its row's first lane (lane 0 for the top row, lane 2 for the
/// bottom one), the words are loaded as one window per row and permuted into the lanes; returns
/// false, with `out` untouched, otherwise. Reads of a screen-aligned copy (a texel or less per
/// pixel) are such: a gather costs about a load per lane on AMD and Intel cores alike, a window
/// of 16 words one load and its share of a permute. Memory must be readable up to
/// kStampRowWindowWords words past each row's first index.
inline bool gather_stamp_rows(const int32_t* base, const Int& index, Int& out) {
#if defined(__AVX512F__)
  static_assert(kLanes == 16);
  const __m512i first = _mm512_permutexvar_epi32(_mm512_setr_epi32(0, 0, 2, 2, 0, 0, 2, 2, 0, 0, 2, 2, 0, 0, 2, 2), index);
  const __m512i offset = _mm512_sub_epi32(index, first);  // below the row's first: huge unsigned
  constexpr __mmask16 kBottomRow = 0xcccc;
  const __m128i firsts = _mm512_castsi512_si128(index);
  const int32_t* top = base + _mm_cvtsi128_si32(firsts);
  const int32_t* bottom = base + _mm_extract_epi32(firsts, 2);
  if (_mm512_cmplt_epu32_mask(offset, _mm512_set1_epi32(16)) == 0xffff) {
    // Windows of 16: the bottom row's words are the permute's second source.
    const __m512i pick = _mm512_mask_add_epi32(offset, kBottomRow, offset, _mm512_set1_epi32(16));
    out = Int(_mm512_permutex2var_epi32(_mm512_loadu_si512(top), pick, _mm512_loadu_si512(bottom)));
    return true;
  }
  if (_mm512_cmplt_epu32_mask(offset, _mm512_set1_epi32(32)) == 0xffff) {
    // Windows of 32 (a stamp row over a footprint up to four texels per pixel): a permute per row.
    const __m512i t = _mm512_permutex2var_epi32(_mm512_loadu_si512(top), offset, _mm512_loadu_si512(top + 16));
    const __m512i b = _mm512_permutex2var_epi32(_mm512_loadu_si512(bottom), offset, _mm512_loadu_si512(bottom + 16));
    out = Int(_mm512_mask_blend_epi32(kBottomRow, t, b));
    return true;
  }
  return false;
#elif defined(__AVX2__)
  static_assert(kLanes == 8);
  const __m256i first = _mm256_permutevar8x32_epi32(index, _mm256_setr_epi32(0, 0, 2, 2, 0, 0, 2, 2));
  const __m256i offset = _mm256_sub_epi32(index, first);
  const __m256i seven = _mm256_set1_epi32(7);  // offset <= 7 unsigned: AVX2 compares only signed
  if (_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(_mm256_min_epu32(offset, seven), offset))) != 0xff)
    return false;
  const __m128i firsts = _mm256_castsi256_si128(index);
  const __m256i t = _mm256_permutevar8x32_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(base + _mm_cvtsi128_si32(firsts))), offset);
  const __m256i b = _mm256_permutevar8x32_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(base + _mm_extract_epi32(firsts, 2))), offset);
  out = Int(_mm256_blend_epi32(t, b, 0xcc));
  return true;
#else
  (void)base, (void)index, (void)out;
  return false;
#endif
}

/// Each lane of `packed` holds two IEEE halves; returns them as floats (exactly, denormals, inf
/// and NaN included, whatever the FTZ/DAZ mode): `low` from bits 0-15, `high` from bits 16-31.
/// (Texture sampling of RGBA16F; F16C is part of x86-64-v3.)
inline void unpack_halves(const Int& packed, Float& low, Float& high) {
#if defined(__AVX512F__)
  low = Float(_mm512_cvtph_ps(_mm512_cvtepi32_epi16(packed)));
  high = Float(_mm512_cvtph_ps(_mm512_cvtepi32_epi16(_mm512_srli_epi32(packed, 16))));
#elif defined(__AVX2__) && defined(__F16C__)
  // Per 128-bit half: the four low halves into bytes 0-7, the four high halves into bytes 8-15;
  // then qwords (0, 2, 1, 3) put all eight low halves below all eight high ones.
  const __m256i split = _mm256_set_epi8(15, 14, 11, 10, 7, 6, 3, 2, 13, 12, 9, 8, 5, 4, 1, 0,
                                        15, 14, 11, 10, 7, 6, 3, 2, 13, 12, 9, 8, 5, 4, 1, 0);
  const __m256i grouped = _mm256_permute4x64_epi64(_mm256_shuffle_epi8(packed, split), 0xd8);
  low = Float(_mm256_cvtph_ps(_mm256_castsi256_si128(grouped)));
  high = Float(_mm256_cvtph_ps(_mm256_extracti128_si256(grouped, 1)));
#else
  alignas(64) int32_t p[kLanes];
  alignas(64) float lo[kLanes], hi[kLanes];
  packed.store_aligned(p);
  auto decode = [](uint32_t h) {
    const uint32_t sign = (h & 0x8000u) << 16, em = h & 0x7fffu;
    uint32_t bits;
    if (em >= 0x7c00u) {
      bits = 0x7f800000u | ((em & 0x3ffu) << 13);  // inf / NaN
    } else if (em >= 0x400u) {
      bits = (em << 13) + 0x38000000u;  // normal: rebias the exponent
    } else {
      const float denormal = static_cast<float>(em) * 5.9604644775390625e-8f;  // em * 2^-24, a normal float
      bits = __builtin_bit_cast(uint32_t, denormal);
    }
    return __builtin_bit_cast(float, bits | sign);
  };
  for (int i = 0; i < kLanes; ++i) {
    lo[i] = decode(static_cast<uint32_t>(p[i]) & 0xffffu);
    hi[i] = decode(static_cast<uint32_t>(p[i]) >> 16);
  }
  low = Float::load_aligned(lo);
  high = Float::load_aligned(hi);
#endif
}

/// Lane l: lo(a) * lo(b) + hi(a) * hi(b), where lo and hi are the lane's signed 16-bit halves
/// (x86 `pmaddwd`): two products and their sum in one instruction, exact whenever the sum fits.
inline Int dot_halves(const Int& a, const Int& b) {
#if defined(__AVX512BW__)
  return Int(_mm512_madd_epi16(a, b));
#elif defined(__AVX2__) && !defined(__AVX512F__)
  return Int(_mm256_madd_epi16(a, b));
#else
  return ((a << 16) >> 16) * ((b << 16) >> 16) + (a >> 16) * (b >> 16);
#endif
}

/// a * b + c, rounded once (fused), on every ISA. (xsimd 8.1's fma is fused on FMA3 targets but
/// a multiply and an add for AVX-512: the same draw gave other bytes on the two.)
inline Float fma(const Float& a, const Float& b, const Float& c) {
#if defined(__AVX512F__)
  return Float(_mm512_fmadd_ps(a, b, c));
#elif defined(__FMA__) && defined(__AVX2__)
  return Float(_mm256_fmadd_ps(a, b, c));
#else
  alignas(64) float x[kLanes], y[kLanes], z[kLanes];
  a.store_aligned(x);
  b.store_aligned(y);
  c.store_aligned(z);
  for (int l = 0; l < kLanes; ++l) x[l] = std::fma(x[l], y[l], z[l]);
  return Float::load_aligned(x);
#endif
}
/// c - a * b, rounded once.
inline Float fnma(const Float& a, const Float& b, const Float& c) { return fma(-a, b, c); }

/// Float to int32 with round-to-nearest-even (the conversion D3D10 prescribes for UNORM writes).
inline Int round_to_int(const Float& x) { return xsimd::nearbyint_as_int(x); }

/// Four channels to 8-bit UNORM, r | g << 8 | b << 16 | a << 24 in each lane: clamped to [0, 1]
/// (NaN to 0), times 255 in float, rounded to nearest even (D3D10's UNORM conversion).
inline Int pack_unorm8(const Float4& c) {
#if defined(__AVX512BW__) || (defined(__AVX2__) && !defined(__AVX512F__))
  // min(1, x) keeps a NaN x (the second operand is returned), which converts to INT_MIN as any
  // value too large for int32 does; the packs saturate, signed to unsigned, so that every
  // negative lane becomes 0 and none exceeds 255: the clamp of the generic branch, without its
  // max and shifts. Per 128 bits the packs leave the bytes of four pixels channel by channel,
  // r0 r1 r2 r3 g0 ...: the shuffle transposes them to r0 g0 b0 a0 r1 ...
#if defined(__AVX512BW__)
  const __m512 one = _mm512_set1_ps(1.0f), scale = _mm512_set1_ps(255.0f);
  auto q = [&](const Float& x) { return _mm512_cvtps_epi32(_mm512_mul_ps(_mm512_min_ps(one, x), scale)); };
  const __m512i bytes = _mm512_packus_epi16(_mm512_packus_epi32(q(c.x), q(c.y)), _mm512_packus_epi32(q(c.z), q(c.w)));
  const __m512i transpose = _mm512_broadcast_i32x4(_mm_setr_epi8(0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15));
  return Int(_mm512_shuffle_epi8(bytes, transpose));
#else
  const __m256 one = _mm256_set1_ps(1.0f), scale = _mm256_set1_ps(255.0f);
  auto q = [&](const Float& x) { return _mm256_cvtps_epi32(_mm256_mul_ps(_mm256_min_ps(one, x), scale)); };
  const __m256i bytes = _mm256_packus_epi16(_mm256_packus_epi32(q(c.x), q(c.y)), _mm256_packus_epi32(q(c.z), q(c.w)));
  const __m256i transpose =
      _mm256_broadcastsi128_si256(_mm_setr_epi8(0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15));
  return Int(_mm256_shuffle_epi8(bytes, transpose));
#endif
#else
  auto q = [](const Float& x) { return round_to_int(xsimd::min(xsimd::max(x, Float(0.0f)), Float(1.0f)) * Float(255.0f)); };
  return q(c.x) | (q(c.y) << 8) | (q(c.z) << 16) | (q(c.w) << 24);
#endif
}

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

/// Transposes kLanes float4 rows into four batches: lane l of x, y, z, w is rows[l][offset + 0..3]
/// (vertex positions or varyings into the front end's lanes). Rows need no alignment.
inline void transpose_rows(const float* const* rows, Float& x, Float& y, Float& z, Float& w, int offset = 0) {
#if defined(__AVX512F__)
  static_assert(kLanes == 16);
  auto quad = [&](int l) {  // rows l, l + 4, l + 8, l + 12 in the four 128-bit lanes
    __m512 v = _mm512_castps128_ps512(_mm_loadu_ps(rows[l] + offset));
    v = _mm512_insertf32x4(v, _mm_loadu_ps(rows[l + 4] + offset), 1);
    v = _mm512_insertf32x4(v, _mm_loadu_ps(rows[l + 8] + offset), 2);
    return _mm512_insertf32x4(v, _mm_loadu_ps(rows[l + 12] + offset), 3);
  };
  const __m512 r0 = quad(0), r1 = quad(1), r2 = quad(2), r3 = quad(3);
  const __m512 xy01 = _mm512_unpacklo_ps(r0, r1), zw01 = _mm512_unpackhi_ps(r0, r1);
  const __m512 xy23 = _mm512_unpacklo_ps(r2, r3), zw23 = _mm512_unpackhi_ps(r2, r3);
  x = _mm512_shuffle_ps(xy01, xy23, 0x44);
  y = _mm512_shuffle_ps(xy01, xy23, 0xee);
  z = _mm512_shuffle_ps(zw01, zw23, 0x44);
  w = _mm512_shuffle_ps(zw01, zw23, 0xee);
#elif defined(__AVX__)
  static_assert(kLanes == 8);
  auto pair = [&](int l) {  // rows l and l + 4 in the two 128-bit halves
    return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(rows[l] + offset)),
                                _mm_loadu_ps(rows[l + 4] + offset), 1);
  };
  const __m256 r04 = pair(0), r15 = pair(1), r26 = pair(2), r37 = pair(3);
  const __m256 xy01 = _mm256_unpacklo_ps(r04, r15), zw01 = _mm256_unpackhi_ps(r04, r15);
  const __m256 xy23 = _mm256_unpacklo_ps(r26, r37), zw23 = _mm256_unpackhi_ps(r26, r37);
  x = _mm256_shuffle_ps(xy01, xy23, 0x44);
  y = _mm256_shuffle_ps(xy01, xy23, 0xee);
  z = _mm256_shuffle_ps(zw01, zw23, 0x44);
  w = _mm256_shuffle_ps(zw01, zw23, 0xee);
#else
  x = lanes([&](int l) { return rows[l][offset]; });
  y = lanes([&](int l) { return rows[l][offset + 1]; });
  z = lanes([&](int l) { return rows[l][offset + 2]; });
  w = lanes([&](int l) { return rows[l][offset + 3]; });
#endif
}

#if defined(__AVX2__)
namespace detail {
/// An 8x8 transpose of 32-bit elements, out[l][f] = in[f][l]: pairs, then fours, then the two
/// 128-bit halves (elements l, l + 4).
inline void transpose_8x8(const __m256i (&fields)[8], __m256i (&out)[8]) {
  __m256i pairs[8], fours[8];
  for (int f = 0; f < 8; f += 2) {
    pairs[f] = _mm256_unpacklo_epi32(fields[f], fields[f + 1]);      // lanes 0, 1 | 4, 5
    pairs[f + 1] = _mm256_unpackhi_epi32(fields[f], fields[f + 1]);  // lanes 2, 3 | 6, 7
  }
  for (int h = 0; h < 8; h += 4) {  // fields 0-3, then 4-7
    fours[h] = _mm256_unpacklo_epi64(pairs[h], pairs[h + 2]);          // lane 0 | 4
    fours[h + 1] = _mm256_unpackhi_epi64(pairs[h], pairs[h + 2]);      // lane 1 | 5
    fours[h + 2] = _mm256_unpacklo_epi64(pairs[h + 1], pairs[h + 3]);  // lane 2 | 6
    fours[h + 3] = _mm256_unpackhi_epi64(pairs[h + 1], pairs[h + 3]);  // lane 3 | 7
  }
  for (int l = 0; l < 4; ++l) {
    out[l] = _mm256_permute2x128_si256(fours[l], fours[l + 4], 0x20);
    out[l + 4] = _mm256_permute2x128_si256(fours[l], fours[l + 4], 0x31);
  }
}

/// The same into eight 32-byte aligned rows.
inline void transpose_8x8_to_rows(const __m256i (&fields)[8], int32_t (*rows)[8]) {
  __m256i out[8];
  transpose_8x8(fields, out);
  for (int l = 0; l < 8; ++l) _mm256_store_si256(reinterpret_cast<__m256i*>(rows[l]), out[l]);
}
}  // namespace detail
#endif

/// The way back from lanes to records: rows[l][f] = lane l of fields[f], for eight 32-bit
/// fields (triangle setup computes kLanes records side by side, a field per batch, and writes
/// them out record by record). Rows are 32-byte aligned.
inline void transpose_to_rows(const Int (&fields)[8], int32_t (*rows)[8]) {
#if defined(__AVX512F__)
  static_assert(kLanes == 16);
  __m256i low[8], high[8];  // lanes 0-7 and 8-15
  for (int f = 0; f < 8; ++f) {
    low[f] = _mm512_castsi512_si256(fields[f]);
    high[f] = _mm512_extracti64x4_epi64(fields[f], 1);
  }
  detail::transpose_8x8_to_rows(low, rows);
  detail::transpose_8x8_to_rows(high, rows + 8);
#elif defined(__AVX2__)
  static_assert(kLanes == 8);
  const __m256i eight[8] = {fields[0], fields[1], fields[2], fields[3], fields[4], fields[5], fields[6], fields[7]};
  detail::transpose_8x8_to_rows(eight, rows);
#else
  for (int f = 0; f < 8; ++f) {
    alignas(64) int32_t lanes_of_field[kLanes];
    fields[f].store_aligned(lanes_of_field);
    for (int l = 0; l < kLanes; ++l) rows[l][f] = lanes_of_field[l];
  }
#endif
}

/// Two runs of four consecutive words per lane: words[k] gets base[index[l] + k] and words[k + 4]
/// base[index[l] + second + k] in each lane l (k < 4), what eight gathers would give. Each lane's
/// words are two 16-byte loads and a transpose puts them in lanes: a gather costs about a load
/// per lane on AMD and Intel cores alike, so this is a quarter of the loads for three shuffles per
/// word (texture sampling's trilinear cells, two slices of four texels: texture.hpp;
/// bench/README.md).
inline void gather_two_fours(const int32_t* base, const Int& index, int32_t second, Int (&words)[8]) {
#if defined(__AVX512F__)
  static_assert(kLanes == 16);
  alignas(64) int32_t at[kLanes];
  index.store_aligned(at);
  // Read back from memory: a store and sixteen loads, which GCC would otherwise make sixteen
  // extracts, shuffles that compete with the transpose's.
  __asm__("" : "+m"(at));
  const auto four = [&](int32_t i) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(base + i)); };
  const auto row = [&](int l) { return _mm256_inserti128_si256(_mm256_castsi128_si256(four(at[l])), four(at[l] + second), 1); };
  // Two lanes' words per register, so that one transpose per 256-bit half, its 128-bit quarters
  // then picked across the two halves, leaves the lanes in order: registers 0-3 hold lanes k and
  // k + 4, registers 4-7 lanes k + 4 and k + 8.
  __m512i in[8];
  for (int k = 0; k < 4; ++k) in[k] = _mm512_inserti64x4(_mm512_castsi256_si512(row(k)), row(k + 4), 1);
  for (int k = 4; k < 8; ++k) in[k] = _mm512_inserti64x4(_mm512_castsi256_si512(row(k + 4)), row(k + 8), 1);
  __m512i pairs[8], fours[8];
  for (int r = 0; r < 8; r += 2) {
    pairs[r] = _mm512_unpacklo_epi32(in[r], in[r + 1]);
    pairs[r + 1] = _mm512_unpackhi_epi32(in[r], in[r + 1]);
  }
  for (int h = 0; h < 8; h += 4) {  // quarter q of fours[h + k]: word k (q even) or k + 4 (q odd) of four registers
    fours[h] = _mm512_unpacklo_epi64(pairs[h], pairs[h + 2]);
    fours[h + 1] = _mm512_unpackhi_epi64(pairs[h], pairs[h + 2]);
    fours[h + 2] = _mm512_unpacklo_epi64(pairs[h + 1], pairs[h + 3]);
    fours[h + 3] = _mm512_unpackhi_epi64(pairs[h + 1], pairs[h + 3]);
  }
  for (int k = 0; k < 4; ++k) {
    words[k] = Int(_mm512_shuffle_i64x2(fours[k], fours[k + 4], 0x88));      // quarters 0, 2 of each
    words[k + 4] = Int(_mm512_shuffle_i64x2(fours[k], fours[k + 4], 0xdd));  // quarters 1, 3 of each
  }
#elif defined(__AVX2__)
  static_assert(kLanes == 8);
  alignas(32) int32_t at[kLanes];
  index.store_aligned(at);
  __m256i in[8], out[8];
  const auto four = [&](int32_t i) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(base + i)); };
  for (int l = 0; l < 8; ++l)
    in[l] = _mm256_inserti128_si256(_mm256_castsi128_si256(four(at[l])), four(at[l] + second), 1);
  detail::transpose_8x8(in, out);
  for (int k = 0; k < 8; ++k) words[k] = Int(out[k]);
#else
  for (int k = 0; k < 4; ++k) {
    words[k] = gather(base, index + Int(k));
    words[k + 4] = gather(base, index + Int(second + k));
  }
#endif
}

/// Half as many double lanes as Float has: triangle setup's exact products of subpixel
/// coordinates (up to 2^48) take doubles, one batch for the low lanes and one for the high.
using Double = xsimd::batch<double, Arch>;
static_assert(2 * Double::size == Float::size);

namespace detail {
template <class Batch>
inline void to_doubles_by_lane(const Batch& v, Double& low, Double& high) {
  alignas(64) typename Batch::value_type lanes_of_v[kLanes];
  v.store_aligned(lanes_of_v);
  low = lanes<Double>([&](int l) { return double(lanes_of_v[l]); });
  high = lanes<Double>([&](int l) { return double(lanes_of_v[l + Double::size]); });
}
}  // namespace detail

/// v's low and high lanes as doubles (exact).
inline void to_doubles(const Int& v, Double& low, Double& high) {
#if defined(__AVX512F__)
  low = Double(_mm512_cvtepi32_pd(_mm512_castsi512_si256(v)));
  high = Double(_mm512_cvtepi32_pd(_mm512_extracti64x4_epi64(v, 1)));
#elif defined(__AVX2__)
  low = Double(_mm256_cvtepi32_pd(_mm256_castsi256_si128(v)));
  high = Double(_mm256_cvtepi32_pd(_mm256_extracti128_si256(v, 1)));
#else
  detail::to_doubles_by_lane(v, low, high);
#endif
}
inline void to_doubles(const Float& v, Double& low, Double& high) {
#if defined(__AVX512F__)
  low = Double(_mm512_cvtps_pd(_mm512_castps512_ps256(v)));
  high = Double(_mm512_cvtps_pd(_mm256_castpd_ps(_mm512_extractf64x4_pd(_mm512_castps_pd(v), 1))));
#elif defined(__AVX2__)
  low = Double(_mm256_cvtps_pd(_mm256_castps256_ps128(v)));
  high = Double(_mm256_cvtps_pd(_mm256_extractf128_ps(v, 1)));
#else
  detail::to_doubles_by_lane(v, low, high);
#endif
}
/// The floats nearest to `low` and `high`'s lanes, as one batch (the inverse of to_doubles).
inline Float to_float(const Double& low, const Double& high) {
#if defined(__AVX512F__)
  const __m512d both = _mm512_insertf64x4(_mm512_castpd256_pd512(_mm256_castps_pd(_mm512_cvtpd_ps(low))),
                                          _mm256_castps_pd(_mm512_cvtpd_ps(high)), 1);
  return Float(_mm512_castpd_ps(both));
#elif defined(__AVX2__)
  return Float(_mm256_set_m128(_mm256_cvtpd_ps(high), _mm256_cvtpd_ps(low)));
#else
  alignas(64) double lo[Double::size], hi[Double::size];
  low.store_aligned(lo);
  high.store_aligned(hi);
  return lanes([&](int l) { return float(l < int(Double::size) ? lo[l] : hi[l - Double::size]); });
#endif
}
/// The lane bits of a pair of double masks, `low` for the low lanes.
inline LaneBits to_bits(const xsimd::batch_bool<double, Arch>& low, const xsimd::batch_bool<double, Arch>& high) {
#if defined(__AVX512F__)
  return static_cast<LaneBits>(low.data) | static_cast<LaneBits>(high.data) << Double::size;
#elif defined(__AVX2__)
  return static_cast<LaneBits>(_mm256_movemask_pd(low.data) | _mm256_movemask_pd(high.data) << Double::size);
#else
  alignas(64) bool lo[Double::size], hi[Double::size];
  low.store_aligned(lo);
  high.store_aligned(hi);
  LaneBits bits = 0;
  for (std::size_t i = 0; i < Double::size; ++i) bits |= LaneBits(lo[i]) << i | LaneBits(hi[i]) << (i + Double::size);
  return bits;
#endif
}

/// Asks for the cache line holding p, to be read soon. Never faults, whatever p is.
inline void prefetch(const void* p) { __builtin_prefetch(p, 0, 3); }
/// Asks for the cache line holding p, to be written soon. Never faults, whatever p is.
inline void prefetch_for_write(const void* p) { __builtin_prefetch(p, 1, 3); }

/// Tells the CPU this is a spin-wait loop (x86 `pause`: saves power, frees the sibling thread).
inline void spin_pause() {
#if defined(__x86_64__)
  __builtin_ia32_pause();
#endif
}

/// Fills n 32-bit words (clears of whole tiles). On x86-64 this is `rep stosd`: its fast-string
/// path writes whole cache lines without first reading them from memory, which vector stores
/// must (read for ownership).
inline void fill_u32(uint32_t* dst, uint32_t value, std::size_t n) {
#if defined(__x86_64__)
  asm volatile("rep stosl" : "+D"(dst), "+c"(n) : "a"(value) : "memory");
#else
  std::fill_n(dst, n, value);
#endif
}

}  // namespace luxel::rasterizer::simd
