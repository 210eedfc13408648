// The lane helpers of simd.hpp that the front end and the tile walks are built on, each against
// its per-lane definition, on seeded random inputs (bx style: the ISA path against a scalar one).

#include "luxel/rasterizer/simd.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

namespace luxel::rasterizer {
namespace {

using simd::Double;
using simd::Float;
using simd::Int;
using simd::Int4;
using simd::kLanes;

constexpr int kRounds = 1000;

Int load(const int32_t* v) { return Int::load_unaligned(v); }

TEST(Simd, DotHalvesIsTwoSignedProductsPerLane) {
  std::mt19937 rng(1);
  std::uniform_int_distribution<int32_t> half(-(1 << 14), (1 << 14) - 1);
  for (int round = 0; round < kRounds; ++round) {
    int32_t a[kLanes], b[kLanes], got[kLanes];
    int16_t alo[kLanes], ahi[kLanes], blo[kLanes], bhi[kLanes];
    for (int l = 0; l < kLanes; ++l) {
      alo[l] = static_cast<int16_t>(half(rng)), ahi[l] = static_cast<int16_t>(half(rng));
      blo[l] = static_cast<int16_t>(half(rng)), bhi[l] = static_cast<int16_t>(half(rng));
      a[l] = int32_t(uint32_t(uint16_t(alo[l])) | uint32_t(uint16_t(ahi[l])) << 16);
      b[l] = int32_t(uint32_t(uint16_t(blo[l])) | uint32_t(uint16_t(bhi[l])) << 16);
    }
    simd::dot_halves(load(a), load(b)).store_unaligned(got);
    for (int l = 0; l < kLanes; ++l) ASSERT_EQ(got[l], alo[l] * blo[l] + ahi[l] * bhi[l]) << "lane " << l;
  }
}

TEST(Simd, Int4LaneBroadcastAndSignBits) {
  std::mt19937 rng(2);
  for (int round = 0; round < kRounds; ++round) {
    alignas(16) int32_t v[4];
    for (int32_t& x : v) x = static_cast<int32_t>(rng());
    const Int4 q = Int4::load_aligned(v);
    simd::LaneBits expected = 0;
    for (int i = 0; i < 4; ++i) expected |= simd::LaneBits(v[i] < 0) << i;
    ASSERT_EQ(simd::sign_bits(q), expected);
    int32_t got[kLanes];
    simd::broadcast_lane<0>(q).store_unaligned(got);
    for (int l = 0; l < kLanes; ++l) ASSERT_EQ(got[l], v[0]);
    simd::broadcast_lane<1>(q).store_unaligned(got);
    for (int l = 0; l < kLanes; ++l) ASSERT_EQ(got[l], v[1]);
    simd::broadcast_lane<2>(q).store_unaligned(got);
    for (int l = 0; l < kLanes; ++l) ASSERT_EQ(got[l], v[2]);
    simd::broadcast_lane<3>(q).store_unaligned(got);
    for (int l = 0; l < kLanes; ++l) ASSERT_EQ(got[l], v[3]);
  }
}

TEST(Simd, RowMajorOrderIsThePixelsRowByRow) {
  std::mt19937 rng(5);
  for (int round = 0; round < 10; ++round) {
    int32_t v[kLanes], got[kLanes];
    for (int l = 0; l < kLanes; ++l) v[l] = static_cast<int32_t>(rng());
    simd::to_row_major(load(v)).store_unaligned(got);
    for (int l = 0; l < kLanes; ++l)  // lane l's pixel is at row lane_y(l), column lane_x(l)
      ASSERT_EQ(got[simd::lane_y(l) * simd::kStampWidth + simd::lane_x(l)], v[l]) << "lane " << l;
  }
}

TEST(Simd, DoubleHalvesAreExactAndRoundBack) {
  std::mt19937 rng(4);
  constexpr int kHalf = static_cast<int>(Double::size);
  for (int round = 0; round < kRounds; ++round) {
    int32_t ints[kLanes];
    float floats[kLanes];
    for (int l = 0; l < kLanes; ++l) {
      ints[l] = static_cast<int32_t>(rng());
      uint32_t bits = static_cast<uint32_t>(rng()) & 0xbf7fffffu;  // finite
      std::memcpy(&floats[l], &bits, 4);
    }
    Double lo, hi;
    double got[2 * kHalf];
    simd::to_doubles(load(ints), lo, hi);
    lo.store_unaligned(got);
    hi.store_unaligned(got + kHalf);
    for (int l = 0; l < kLanes; ++l) ASSERT_EQ(got[l], double(ints[l]));
    simd::to_doubles(Float::load_unaligned(floats), lo, hi);
    lo.store_unaligned(got);
    hi.store_unaligned(got + kHalf);
    for (int l = 0; l < kLanes; ++l) ASSERT_EQ(got[l], double(floats[l]));
    // Back to float: round to nearest, as a static_cast does.
    for (int l = 0; l < kLanes; ++l) got[l] = double(ints[l]) / 3.0;
    float back[kLanes];
    simd::to_float(Double::load_unaligned(got), Double::load_unaligned(got + kHalf)).store_unaligned(back);
    for (int l = 0; l < kLanes; ++l) ASSERT_EQ(back[l], static_cast<float>(got[l]));
    // Lane bits of a pair of double masks: low lanes first.
    const simd::LaneBits bits = simd::to_bits(Double::load_unaligned(got) < Double(0.0),
                                              Double::load_unaligned(got + kHalf) < Double(0.0));
    simd::LaneBits expected = 0;
    for (int l = 0; l < kLanes; ++l) expected |= simd::LaneBits(got[l] < 0.0) << l;
    ASSERT_EQ(bits, expected);
  }
}

TEST(Simd, TransposeRowsPutsRowLInLaneL) {
  float rows[kLanes][4];
  const float* pointers[kLanes];
  for (int l = 0; l < kLanes; ++l) {
    for (int c = 0; c < 4; ++c) rows[l][c] = static_cast<float>(10 * l + c);
    pointers[l] = rows[l];
  }
  Float x, y, z, w;
  simd::transpose_rows(pointers, x, y, z, w);
  float got[4][kLanes];
  x.store_unaligned(got[0]);
  y.store_unaligned(got[1]);
  z.store_unaligned(got[2]);
  w.store_unaligned(got[3]);
  for (int l = 0; l < kLanes; ++l)
    for (int c = 0; c < 4; ++c) EXPECT_EQ(got[c][l], rows[l][c]) << "lane " << l << ", component " << c;
}

TEST(Simd, TransposeToRowsPutsLaneLInRowL) {
  // The inverse direction: field f of record l is lane l of fields[f].
  Int fields[8];
  for (int f = 0; f < 8; ++f) fields[f] = simd::lanes<Int>([&](int l) { return 100 * l + f; });
  alignas(32) int32_t rows[kLanes][8];
  simd::transpose_to_rows(fields, rows);
  for (int l = 0; l < kLanes; ++l)
    for (int f = 0; f < 8; ++f) EXPECT_EQ(rows[l][f], 100 * l + f) << "lane " << l << ", field " << f;
}

}  // namespace
}  // namespace luxel::rasterizer
