// Texel windows: the texels of a stamp's bilinear footprints picked from a few rows loaded once,
// where a magnified read's stamp lies within them. A lane-level primitive like those of simd.hpp,
// kept apart because only the texture sampler reads it.
#pragma once

#include "luxel/rasterizer/simd.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>

#if defined(__AVX2__) || defined(__AVX512F__)
#include <immintrin.h>
#endif

namespace luxel::rasterizer::simd {

/// The smallest value over the lanes.
inline int32_t lowest(const Int& v) {
#if defined(__AVX512F__)
  return _mm512_reduce_min_epi32(v);
#elif defined(__AVX2__)
  __m128i m = _mm_min_epi32(_mm256_castsi256_si128(v), _mm256_extracti128_si256(v, 1));
  m = _mm_min_epi32(m, _mm_shuffle_epi32(m, 0x4e));
  return _mm_cvtsi128_si32(_mm_min_epi32(m, _mm_shuffle_epi32(m, 0xb1)));
#else
  alignas(64) int32_t lanes[kLanes];
  v.store_aligned(lanes);
  return *std::min_element(lanes, lanes + kLanes);
#endif
}

/// Four rows of four 8-byte texels (a bilinear footprint's neighbourhood when a stamp magnifies a
/// texture), loaded once, from which each lane's texel is picked as gather_pairs would read it.
/// At 16 lanes the window is two registers and a texel is two permutes instead of two gathers;
/// elsewhere it is a copy gathered from (correct, and no faster: kPairWindowsPay says whether to
/// use it).
class PairWindow {
 public:
  /// `rows[r]` points at the first word of row r's four texels (eight 32-bit words).
  explicit PairWindow(const int32_t* const rows[4]) {
#if defined(__AVX512F__)
    top_ = _mm512_inserti64x4(_mm512_castsi256_si512(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(rows[0]))),
                              _mm256_loadu_si256(reinterpret_cast<const __m256i*>(rows[1])), 1);
    bottom_ = _mm512_inserti64x4(_mm512_castsi256_si512(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(rows[2]))),
                                 _mm256_loadu_si256(reinterpret_cast<const __m256i*>(rows[3])), 1);
#else
    for (int r = 0; r < 4; ++r) std::memcpy(words_ + 8 * r, rows[r], 8 * sizeof(int32_t));
#endif
  }
  /// The two words of texel `texel` (row * 4 + column, in [0, 16)) of each lane.
  void pairs(const Int& texel, Int& low, Int& high) const {
    const Int word = texel + texel;
#if defined(__AVX512F__)
    low = Int(_mm512_permutex2var_epi32(top_, word, bottom_));
    high = Int(_mm512_permutex2var_epi32(top_, _mm512_add_epi32(word, _mm512_set1_epi32(1)), bottom_));
#else
    low = gather(words_, word);
    high = gather(words_, word + Int(1));
#endif
  }

 private:
#if defined(__AVX512F__)
  __m512i top_, bottom_;
#else
  alignas(32) int32_t words_[32];
#endif
};
#if defined(__AVX512F__)
inline constexpr bool kPairWindowsPay = true;
#else
inline constexpr bool kPairWindowsPay = false;
#endif

}  // namespace luxel::rasterizer::simd
