#pragma once
// The lane abstraction: every SIMD type and every ISA-specific instruction of luxel lives here and
// in the one file per instruction set it includes at its end (simd/avx512.inl, simd/avx2.inl,
// simd/portable.inl), as bx keeps simd128_sse.inl beside simd_ref.inl. This file is the
// interface: the types, what each operation returns, and the operations every ISA shares; an ISA's
// file defines the operations declared here with that ISA's instructions.
//
// Lanes are pixels. A *stamp* is one SIMD batch of pixels: kLanes/4 2x2 quads side by side,
// kStampWidth x 2 pixels. Lane order is quad-major: lane 4q+0 is the quad's top-left pixel, 4q+1
// top-right, 4q+2 bottom-left, 4q+3 bottom-right. Derivatives (ddx/ddy) are taken per quad.
//
// AVX2 gives 8 float lanes (a stamp is 4x2 pixels), AVX-512 16 (8x2), the portable file's
// operations whatever xsimd's default batch holds (4 with SSE4.2): the build's LUXEL_ARCH decides,
// the default being the build machine's own ISA. Every ISA computes the same bits.

#include <xsimd/xsimd.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <utility>

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

// Defined by the ISA's file:
//   kIsaName: the instruction set the lanes were compiled for (chosen at build time: LUXEL_ARCH).
//   kStampRowWindowWords: how many words past its first lane's index gather_stamp_rows may read
//     for a stamp row (0: it never reads windows). Memory it reads through must extend this far
//     past the last index.

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

/// Four int32 lanes, whatever kLanes is: a triangle's three edges side by side (the fourth lane
/// unused), stepped and tested together.
using Int4 = xsimd::make_sized_batch_t<int32_t, 4>;
static_assert(!std::is_void_v<Int4>, "the target has 4-lane integer vectors");

/// Half as many double lanes as Float has: triangle setup's exact products of subpixel
/// coordinates (up to 2^48) take doubles, one batch for the low lanes and one for the high.
using Double = xsimd::batch<double, Arch>;
static_assert(2 * Double::size == Float::size);

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

/// Coarse derivatives (one value per quad, as DX9 hardware computes them): d/dx is the top row's
/// difference, d/dy the left column's.
inline Float ddx(const Float& v) { return quad_corner<1>(v) - quad_corner<0>(v); }
inline Float ddy(const Float& v) { return quad_corner<2>(v) - quad_corner<0>(v); }

// --- Operations each ISA's file defines -------------------------------------------------------

/// Stores a stamp's 32-bit pixels in row-major order (to_row_major) as the image rows they
/// cover: lanes [0, kStampWidth) at `top`, the others at `bottom` (unaligned), with no trip
/// through memory in between (a wide store read back in halves waits for it to retire).
inline void store_stamp_rows(const Int& row_major, void* top, void* bottom);

/// The lane bits of a mask (bit l set when lane l is true).
template <class T>
inline LaneBits to_bits(const xsimd::batch_bool<T, Arch>& m);
/// The lane bits of a pair of double masks, `low` for the low lanes.
inline LaneBits to_bits(const xsimd::batch_bool<double, Arch>& low, const xsimd::batch_bool<double, Arch>& high);

/// The mask of no lanes, made in a register: xsimd's batch_bool(bool) is a call where a large
/// translation unit leaves it out of line, and a call costs its caller every live vector register.
inline IntMask no_lanes();

/// Lanes whose sign bit is set (negative integers).
inline LaneBits sign_bits(const Int& v);
/// The same for Int4 where it is not Int (wider targets).
template <class V>
  requires(std::is_same_v<V, Int4> && !std::is_same_v<Int4, Int>)
inline LaneBits sign_bits(const V& v);

/// Every lane holds lane `Lane` of v.
template <int Lane>
inline Int broadcast_lane(const Int4& v);

// Lane masks as integer vectors: a lane is all ones (true) or zero (false). Cheaper to combine
// with coverage and comparison results than bits, and they select directly.

/// All-ones lanes where `m` is true.
inline Int mask_of(const FloatMask& m);
inline Int mask_of(const IntMask& m);
/// `a` where `mask` lanes are all ones, else `b`.
inline Float select(const Int& mask, const Float& a, const Float& b);
inline Int select(const Int& mask, const Int& a, const Int& b);

/// kLanes bytes at p, widened to 32-bit lanes.
inline Int load_bytes(const uint8_t* p);
/// Stores the low byte of each lane to p[0..kLanes).
inline void store_bytes(uint8_t* p, const Int& v);

/// Byte kByte (0 = the lowest) of each lane, zero-extended.
template <int kByte>
inline Int byte_of(const Int& v);

/// base[index[l]] in each lane l. (xsimd 8.1's batch<int32_t>::gather never picks the AVX2
/// instruction, its enable_if makes that overload unusable, and inserts lanes one by one.)
inline Int gather(const int32_t* base, const Int& index);
inline Float gather(const float* base, const Int& index);

/// The 8 bytes at base + index[l] (index in 32-bit words) in each lane l: `low` gets
/// base[index[l]], `high` base[index[l] + 1].
inline void gather_pairs(const int32_t* base, const Int& index, Int& low, Int& high);

/// table[index[l]] in each lane l, for a table of 256 floats and indices in [0, 255]: the decode of
/// a byte through a curve (lookup_bytes3 without AVX-512 VBMI).
inline Float lookup_byte(const float* table, const Int& index);

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
/// texel's color through a curve: texture sampling's sRGB).
inline void lookup_bytes3(const ByteTable& table, const Int& words, Float& b0, Float& b1, Float& b2);

/// base[index[l]] in each lane l, as gather() returns it, read without a gather when the indices
/// of each stamp row lie close together: when every lane's index is at most kStampRowWindowWords
/// - 1 words past the index of its row's first lane (lane 0 for the top row, lane 2 for the
/// bottom one), the words are loaded as one window per row and permuted into the lanes; returns
/// false, with `out` untouched, otherwise. Reads of a screen-aligned copy (a texel or less per
/// pixel) are such: a gather costs about a load per lane on AMD and Intel cores alike, a window
/// of 16 words one load and its share of a permute. Memory must be readable up to
/// kStampRowWindowWords words past each row's first index.
inline bool gather_stamp_rows(const int32_t* base, const Int& index, Int& out);

/// Two runs of four consecutive words per lane: words[k] gets base[index[l] + k] and words[k + 4]
/// base[index[l] + second + k] in each lane l (k < 4), what eight gathers would give (texture
/// sampling's trilinear cells, two slices of four texels: texture.hpp).
inline void gather_two_fours(const int32_t* base, const Int& index, int32_t second, Int (&words)[8]);

/// Each lane of `packed` holds two IEEE halves; returns them as floats (exactly, denormals, inf
/// and NaN included, whatever the FTZ/DAZ mode): `low` from bits 0-15, `high` from bits 16-31.
/// (Texture sampling of RGBA16F.)
inline void unpack_halves(const Int& packed, Float& low, Float& high);

/// Lane l: lo(a) * lo(b) + hi(a) * hi(b), where lo and hi are the lane's signed 16-bit halves
/// (x86 `pmaddwd`): two products and their sum in one instruction, exact whenever the sum fits.
inline Int dot_halves(const Int& a, const Int& b);

/// a * b + c, rounded once (fused), on every ISA. (xsimd 8.1's fma is fused on FMA3 targets but
/// a multiply and an add for AVX-512: the same draw gave other bytes on the two.)
inline Float fma(const Float& a, const Float& b, const Float& c);

/// Four channels to 8-bit UNORM, r | g << 8 | b << 16 | a << 24 in each lane: clamped to [0, 1]
/// (NaN to 0), times 255 in float, rounded to nearest even (D3D10's UNORM conversion).
inline Int pack_unorm8(const Float4& c);

/// Transposes kLanes float4 rows into four batches: lane l of x, y, z, w is rows[l][offset + 0..3]
/// (vertex positions or varyings into the front end's lanes). Rows need no alignment.
inline void transpose_rows(const float* const* rows, Float& x, Float& y, Float& z, Float& w, int offset = 0);

/// The way back from lanes to records: rows[l][f] = lane l of fields[f], for eight 32-bit
/// fields (triangle setup computes kLanes records side by side, a field per batch, and writes
/// them out record by record). Rows are 32-byte aligned.
inline void transpose_to_rows(const Int (&fields)[8], int32_t (*rows)[8]);

/// v's low and high lanes as doubles (exact).
inline void to_doubles(const Int& v, Double& low, Double& high);
inline void to_doubles(const Float& v, Double& low, Double& high);
/// The floats nearest to `low` and `high`'s lanes, as one batch (the inverse of to_doubles).
inline Float to_float(const Double& low, const Double& high);

// --- Operations every ISA shares ---------------------------------------------------------------

/// The mask whose lane l is bit l of `bits`.
/// (The lane bits are built in place, not kept in a function-local static: the compiler folds
/// them into a constant, where a static costs its guard's check on every call.)
inline IntMask int_mask(LaneBits bits) {
  return (Int(static_cast<int32_t>(bits)) & lanes<Int>([](int l) { return 1 << l; })) != Int(0);
}
inline FloatMask float_mask(LaneBits bits) {
  return xsimd::to_float(Int(static_cast<int32_t>(bits)) & lanes<Int>([](int l) { return 1 << l; })) != Float(0.0f);
}

/// c - a * b, rounded once.
inline Float fnma(const Float& a, const Float& b, const Float& c) { return fma(-a, b, c); }

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

namespace detail {
// Operations built from others, for the ISAs that have no quicker way.

/// gather_pairs as two 32-bit gathers.
inline void gather_pairs_by_words(const int32_t* base, const Int& index, Int& low, Int& high) {
  low = gather(base, index);
  high = gather(base, index + Int(1));
}

/// lookup_bytes3 as three lookup_byte.
inline void lookup_bytes3_by_byte(const ByteTable& table, const Int& words, Float& b0, Float& b1, Float& b2) {
  b0 = lookup_byte(table.entries.data(), byte_of<0>(words));
  b1 = lookup_byte(table.entries.data(), byte_of<1>(words));
  b2 = lookup_byte(table.entries.data(), byte_of<2>(words));
}
}  // namespace detail

}  // namespace luxel::rasterizer::simd

#if defined(__AVX512F__)
#include "luxel/rasterizer/simd/avx512.inl"
#elif defined(__AVX2__)
#include "luxel/rasterizer/simd/avx2.inl"
#else
#include "luxel/rasterizer/simd/portable.inl"
#endif
