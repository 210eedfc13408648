#pragma once
// The lane operations of simd.hpp with AVX-512: 16 lanes, a stamp of 8x2 pixels. Included by
// simd.hpp alone. Needs AVX512F, BW and DQ (every AVX-512 core since Skylake-SP, x86-64-v4);
// lookup_bytes3 also uses VBMI where the core has it (Ice Lake, Zen 4 and later).

#if !defined(__AVX512BW__) || !defined(__AVX512DQ__)
#error "luxel's AVX-512 lanes need AVX512BW and AVX512DQ: build with LUXEL_ARCH=x86-64-v3 on this CPU"
#endif

#include "luxel/rasterizer/simd/transpose_8x8.inl"

#include <immintrin.h>

namespace luxel::rasterizer::simd {

static_assert(kLanes == 16);

inline constexpr const char* kIsaName = "avx512";
inline constexpr int kStampRowWindowWords = 32;

inline void store_stamp_rows(const Int& row_major, void* top, void* bottom) {
  _mm256_storeu_si256(static_cast<__m256i*>(top), _mm512_castsi512_si256(row_major));
  _mm256_storeu_si256(static_cast<__m256i*>(bottom), _mm512_extracti64x4_epi64(row_major, 1));
}

template <class T>
inline LaneBits to_bits(const xsimd::batch_bool<T, Arch>& m) {
  return static_cast<LaneBits>(m.data);
}
inline LaneBits to_bits(const xsimd::batch_bool<double, Arch>& low, const xsimd::batch_bool<double, Arch>& high) {
  return static_cast<LaneBits>(low.data) | static_cast<LaneBits>(high.data) << Double::size;
}

inline IntMask no_lanes() { return IntMask(__mmask16(0)); }

inline LaneBits sign_bits(const Int& v) { return static_cast<LaneBits>(_mm512_movepi32_mask(v)); }
template <class V>
  requires(std::is_same_v<V, Int4> && !std::is_same_v<Int4, Int>)
inline LaneBits sign_bits(const V& v) {
  return static_cast<LaneBits>(_mm_movemask_ps(_mm_castsi128_ps(v)));
}

template <int Lane>
inline Int broadcast_lane(const Int4& v) {
  static_assert(Lane >= 0 && Lane < 4);
  return Int(_mm512_broadcastd_epi32(_mm_shuffle_epi32(v, Lane * 0x55)));
}

inline Int mask_of(const FloatMask& m) { return Int(_mm512_movm_epi32(m.data)); }
inline Int mask_of(const IntMask& m) { return Int(_mm512_movm_epi32(m.data)); }
inline Float select(const Int& mask, const Float& a, const Float& b) {
  return Float(_mm512_mask_blend_ps(_mm512_movepi32_mask(mask), b, a));
}
inline Int select(const Int& mask, const Int& a, const Int& b) {
  return Int(_mm512_mask_blend_epi32(_mm512_movepi32_mask(mask), b, a));
}

inline Int load_bytes(const uint8_t* p) {
  return Int(_mm512_cvtepu8_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p))));
}
inline void store_bytes(uint8_t* p, const Int& v) {
  _mm_storeu_si128(reinterpret_cast<__m128i*>(p), _mm512_cvtepi32_epi8(v));
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
    return Int(_mm512_shuffle_epi8(v, _mm512_broadcast_i32x4(pick)));
  }
}

inline Int gather(const int32_t* base, const Int& index) { return Int(_mm512_i32gather_epi32(index, base, 4)); }
inline Float gather(const float* base, const Int& index) { return Float(_mm512_i32gather_ps(index, base, 4)); }

/// Two gathers of eight 64-bit elements, not two of sixteen 32-bit ones: a gather costs about a
/// load per element on AMD and Intel cores alike, and two permutes put the halves back in lane
/// order (bench/README.md).
inline void gather_pairs(const int32_t* base, const Int& index, Int& low, Int& high) {
  const __m512i first = _mm512_i32gather_epi64(_mm512_castsi512_si256(index), base, 4);
  const __m512i second = _mm512_i32gather_epi64(_mm512_extracti64x4_epi64(index, 1), base, 4);
  const __m512i even = _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30);
  low = Int(_mm512_permutex2var_epi32(first, even, second));
  high = Int(_mm512_permutex2var_epi32(first, _mm512_add_epi32(even, _mm512_set1_epi32(1)), second));
}

/// The table is read as eight two-register halves of 32 entries, each permuted by the index's low
/// five bits, and merged by its top three bits: eight permutes and seven blends in place of a
/// gather, which costs about a load per lane on AMD and Intel cores alike (bench/README.md).
inline Float lookup_byte(const float* table, const Int& index) {
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
}

/// With VBMI all 64 bytes of the words are looked up at once, a byte plane at a time (two
/// 128-byte permutes merged by the byte's top bit), and the planes' bytes transposed back into
/// floats by unpacks: fewer shuffles than three lookup_byte, and a third of their table loads
/// (bench/README.md).
inline void lookup_bytes3(const ByteTable& table, const Int& words, Float& b0, Float& b1, Float& b2) {
#if defined(__AVX512VBMI__)
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
  detail::lookup_bytes3_by_byte(table, words, b0, b1, b2);
#endif
}

/// Windows of 16 words when the row's indices allow, else of 32.
inline bool gather_stamp_rows(const int32_t* base, const Int& index, Int& out) {
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
}

/// Each lane's words are two 16-byte loads and a transpose puts them in lanes: a gather costs
/// about a load per lane on AMD and Intel cores alike, so this is a quarter of the loads for three
/// shuffles per word (bench/README.md).
inline void gather_two_fours(const int32_t* base, const Int& index, int32_t second, Int (&words)[8]) {
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
}

inline void unpack_halves(const Int& packed, Float& low, Float& high) {
  low = Float(_mm512_cvtph_ps(_mm512_cvtepi32_epi16(packed)));
  high = Float(_mm512_cvtph_ps(_mm512_cvtepi32_epi16(_mm512_srli_epi32(packed, 16))));
}

inline Int dot_halves(const Int& a, const Int& b) { return Int(_mm512_madd_epi16(a, b)); }

inline Float fma(const Float& a, const Float& b, const Float& c) { return Float(_mm512_fmadd_ps(a, b, c)); }

/// min(1, x) keeps a NaN x (the second operand is returned), which converts to INT_MIN as any
/// value too large for int32 does; the packs saturate, signed to unsigned, so that every negative
/// lane becomes 0 and none exceeds 255: the clamp of the portable way, without its max and shifts.
/// Per 128 bits the packs leave the bytes of four pixels channel by channel, r0 r1 r2 r3 g0 ...:
/// the shuffle transposes them to r0 g0 b0 a0 r1 ...
inline Int pack_unorm8(const Float4& c) {
  const __m512 one = _mm512_set1_ps(1.0f), scale = _mm512_set1_ps(255.0f);
  auto q = [&](const Float& x) { return _mm512_cvtps_epi32(_mm512_mul_ps(_mm512_min_ps(one, x), scale)); };
  const __m512i bytes = _mm512_packus_epi16(_mm512_packus_epi32(q(c.x), q(c.y)), _mm512_packus_epi32(q(c.z), q(c.w)));
  const __m512i transpose = _mm512_broadcast_i32x4(_mm_setr_epi8(0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15));
  return Int(_mm512_shuffle_epi8(bytes, transpose));
}

inline void transpose_rows(const float* const* rows, Float& x, Float& y, Float& z, Float& w, int offset) {
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
}

inline void transpose_to_rows(const Int (&fields)[8], int32_t (*rows)[8]) {
  __m256i low[8], high[8];  // lanes 0-7 and 8-15
  for (int f = 0; f < 8; ++f) {
    low[f] = _mm512_castsi512_si256(fields[f]);
    high[f] = _mm512_extracti64x4_epi64(fields[f], 1);
  }
  detail::transpose_8x8_to_rows(low, rows);
  detail::transpose_8x8_to_rows(high, rows + 8);
}

inline void to_doubles(const Int& v, Double& low, Double& high) {
  low = Double(_mm512_cvtepi32_pd(_mm512_castsi512_si256(v)));
  high = Double(_mm512_cvtepi32_pd(_mm512_extracti64x4_epi64(v, 1)));
}
inline void to_doubles(const Float& v, Double& low, Double& high) {
  low = Double(_mm512_cvtps_pd(_mm512_castps512_ps256(v)));
  high = Double(_mm512_cvtps_pd(_mm256_castpd_ps(_mm512_extractf64x4_pd(_mm512_castps_pd(v), 1))));
}
inline Float to_float(const Double& low, const Double& high) {
  const __m512d both = _mm512_insertf64x4(_mm512_castpd256_pd512(_mm256_castps_pd(_mm512_cvtpd_ps(low))),
                                          _mm256_castps_pd(_mm512_cvtpd_ps(high)), 1);
  return Float(_mm512_castpd_ps(both));
}

}  // namespace luxel::rasterizer::simd
