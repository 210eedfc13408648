#pragma once
// An 8x8 transpose of 32-bit elements in AVX2 registers: what transpose_to_rows and
// gather_two_fours build on in the AVX2 and AVX-512 files (simd.hpp).

#include <immintrin.h>

namespace luxel::rasterizer::simd::detail {

/// out[l][f] = in[f][l]: pairs, then fours, then the two 128-bit halves (elements l, l + 4).
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

}  // namespace luxel::rasterizer::simd::detail
