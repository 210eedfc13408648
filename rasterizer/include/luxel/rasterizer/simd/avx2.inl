#pragma once
// The lane operations of simd.hpp with AVX2: 8 lanes, a stamp of 4x2 pixels. Included by simd.hpp
// alone. Needs FMA and F16C beside AVX2 (x86-64-v3: every core with AVX2 has them).

#if !defined(__FMA__) || !defined(__F16C__)
#error "luxel's AVX2 lanes need FMA and F16C (x86-64-v3)"
#endif

#include "luxel/rasterizer/simd/transpose_8x8.inl"

#include <immintrin.h>

namespace luxel::rasterizer::simd {

static_assert(kLanes == 8);

inline constexpr const char* kIsaName = "avx2";
inline constexpr int kStampRowWindowWords = 8;

inline void store_stamp_rows(const Int& row_major, void* top, void* bottom) {
  _mm_storeu_si128(static_cast<__m128i*>(top), _mm256_castsi256_si128(row_major));
  _mm_storeu_si128(static_cast<__m128i*>(bottom), _mm256_extracti128_si256(row_major, 1));
}

template <class T>
inline LaneBits to_bits(const xsimd::batch_bool<T, Arch>& m) {
  if constexpr (std::is_same_v<T, float>) {
    return static_cast<LaneBits>(_mm256_movemask_ps(m.data));
  } else {
    static_assert(sizeof(T) == 4);
    return static_cast<LaneBits>(_mm256_movemask_ps(_mm256_castsi256_ps(m.data)));
  }
}
inline LaneBits to_bits(const xsimd::batch_bool<double, Arch>& low, const xsimd::batch_bool<double, Arch>& high) {
  return static_cast<LaneBits>(_mm256_movemask_pd(low.data) | _mm256_movemask_pd(high.data) << Double::size);
}

inline IntMask no_lanes() { return IntMask(_mm256_setzero_si256()); }

inline LaneBits sign_bits(const Int& v) { return static_cast<LaneBits>(_mm256_movemask_ps(_mm256_castsi256_ps(v))); }
template <class V>
  requires(std::is_same_v<V, Int4> && !std::is_same_v<Int4, Int>)
inline LaneBits sign_bits(const V& v) {
  return static_cast<LaneBits>(_mm_movemask_ps(_mm_castsi128_ps(v)));
}

template <int Lane>
inline Int broadcast_lane(const Int4& v) {
  static_assert(Lane >= 0 && Lane < 4);
  return Int(_mm256_broadcastd_epi32(_mm_shuffle_epi32(v, Lane * 0x55)));
}

inline Int mask_of(const FloatMask& m) { return Int(_mm256_castps_si256(m.data)); }
inline Int mask_of(const IntMask& m) { return Int(m.data); }
inline Float select(const Int& mask, const Float& a, const Float& b) {
  return Float(_mm256_blendv_ps(b, a, _mm256_castsi256_ps(mask)));
}
inline Int select(const Int& mask, const Int& a, const Int& b) { return Int(_mm256_blendv_epi8(b, a, mask)); }

inline Int load_bytes(const uint8_t* p) {
  return Int(_mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(p))));
}
inline void store_bytes(uint8_t* p, const Int& v) {
  const __m256i packed16 = _mm256_packus_epi32(v, v);            // lanes 0-3,0-3 | 4-7,4-7 (16 bit)
  const __m256i packed8 = _mm256_packus_epi16(packed16, packed16);  // bytes 0-3 .. | 4-7 ..
  const uint32_t lo = static_cast<uint32_t>(_mm256_extract_epi32(packed8, 0));
  const uint32_t hi = static_cast<uint32_t>(_mm256_extract_epi32(packed8, 4));
  const uint64_t both = lo | (uint64_t(hi) << 32);
  __builtin_memcpy(p, &both, 8);
}

/// The bytes above the lowest come by one byte shuffle (port 5 on Intel cores, where the
/// shift-and-mask pair would take two of the ports the conversions and FMAs of texture filtering
/// already crowd; one cheap op on AMD's).
template <int kByte>
inline Int byte_of(const Int& v) {
  static_assert(kByte >= 0 && kByte < 4);
  if constexpr (kByte == 0) {
    return v & Int(0xff);
  } else {
    // Within each 128-bit block, lane l's byte kByte to its lowest byte, zeros above (-1).
    const __m128i pick = _mm_setr_epi8(kByte, -1, -1, -1, 4 + kByte, -1, -1, -1, 8 + kByte, -1, -1, -1, 12 + kByte, -1, -1, -1);
    return Int(_mm256_shuffle_epi8(v, _mm256_broadcastsi128_si256(pick)));
  }
}

inline Int gather(const int32_t* base, const Int& index) { return Int(_mm256_i32gather_epi32(base, index, 4)); }
inline Float gather(const float* base, const Int& index) { return Float(_mm256_i32gather_ps(base, index, 4)); }

/// At 8 lanes the two 32-bit gathers measured faster than 64-bit ones and their shuffles.
inline void gather_pairs(const int32_t* base, const Int& index, Int& low, Int& high) {
  detail::gather_pairs_by_words(base, index, low, high);
}

inline Float lookup_byte(const float* table, const Int& index) { return gather(table, index); }

inline void lookup_bytes3(const ByteTable& table, const Int& words, Float& b0, Float& b1, Float& b2) {
  detail::lookup_bytes3_by_byte(table, words, b0, b1, b2);
}

/// A window of 8 words per row, permuted into the row's lanes.
inline bool gather_stamp_rows(const int32_t* base, const Int& index, Int& out) {
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
}

/// Each lane's words are two 16-byte loads and a transpose puts them in lanes: a gather costs
/// about a load per lane on AMD and Intel cores alike, so this is a quarter of the loads for three
/// shuffles per word (bench/README.md).
inline void gather_two_fours(const int32_t* base, const Int& index, int32_t second, Int (&words)[8]) {
  alignas(32) int32_t at[kLanes];
  index.store_aligned(at);
  __m256i in[8], out[8];
  const auto four = [&](int32_t i) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(base + i)); };
  for (int l = 0; l < 8; ++l)
    in[l] = _mm256_inserti128_si256(_mm256_castsi128_si256(four(at[l])), four(at[l] + second), 1);
  detail::transpose_8x8(in, out);
  for (int k = 0; k < 8; ++k) words[k] = Int(out[k]);
}

inline void unpack_halves(const Int& packed, Float& low, Float& high) {
  // Per 128-bit half: the four low halves into bytes 0-7, the four high halves into bytes 8-15;
  // then qwords (0, 2, 1, 3) put all eight low halves below all eight high ones.
  const __m256i split = _mm256_set_epi8(15, 14, 11, 10, 7, 6, 3, 2, 13, 12, 9, 8, 5, 4, 1, 0,
                                        15, 14, 11, 10, 7, 6, 3, 2, 13, 12, 9, 8, 5, 4, 1, 0);
  const __m256i grouped = _mm256_permute4x64_epi64(_mm256_shuffle_epi8(packed, split), 0xd8);
  low = Float(_mm256_cvtph_ps(_mm256_castsi256_si128(grouped)));
  high = Float(_mm256_cvtph_ps(_mm256_extracti128_si256(grouped, 1)));
}

inline Int dot_halves(const Int& a, const Int& b) { return Int(_mm256_madd_epi16(a, b)); }

inline Float fma(const Float& a, const Float& b, const Float& c) { return Float(_mm256_fmadd_ps(a, b, c)); }

/// min(1, x) keeps a NaN x (the second operand is returned), which converts to INT_MIN as any
/// value too large for int32 does; the packs saturate, signed to unsigned, so that every negative
/// lane becomes 0 and none exceeds 255: the clamp of the portable way, without its max and shifts.
/// Per 128 bits the packs leave the bytes of four pixels channel by channel, r0 r1 r2 r3 g0 ...:
/// the shuffle transposes them to r0 g0 b0 a0 r1 ...
inline Int pack_unorm8(const Float4& c) {
  const __m256 one = _mm256_set1_ps(1.0f), scale = _mm256_set1_ps(255.0f);
  auto q = [&](const Float& x) { return _mm256_cvtps_epi32(_mm256_mul_ps(_mm256_min_ps(one, x), scale)); };
  const __m256i bytes = _mm256_packus_epi16(_mm256_packus_epi32(q(c.x), q(c.y)), _mm256_packus_epi32(q(c.z), q(c.w)));
  const __m256i transpose =
      _mm256_broadcastsi128_si256(_mm_setr_epi8(0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15));
  return Int(_mm256_shuffle_epi8(bytes, transpose));
}

inline void transpose_rows(const float* const* rows, Float& x, Float& y, Float& z, Float& w, int offset) {
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
}

inline void transpose_to_rows(const Int (&fields)[8], int32_t (*rows)[8]) {
  const __m256i eight[8] = {fields[0], fields[1], fields[2], fields[3], fields[4], fields[5], fields[6], fields[7]};
  detail::transpose_8x8_to_rows(eight, rows);
}

inline void to_doubles(const Int& v, Double& low, Double& high) {
  low = Double(_mm256_cvtepi32_pd(_mm256_castsi256_si128(v)));
  high = Double(_mm256_cvtepi32_pd(_mm256_extracti128_si256(v, 1)));
}
inline void to_doubles(const Float& v, Double& low, Double& high) {
  low = Double(_mm256_cvtps_pd(_mm256_castps256_ps128(v)));
  high = Double(_mm256_cvtps_pd(_mm256_extractf128_ps(v, 1)));
}
inline Float to_float(const Double& low, const Double& high) {
  return Float(_mm256_set_m128(_mm256_cvtpd_ps(high), _mm256_cvtpd_ps(low)));
}

}  // namespace luxel::rasterizer::simd
