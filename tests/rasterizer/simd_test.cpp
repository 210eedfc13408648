// The lane helpers of simd.hpp that the front end and the tile walks are built on, each against
// its per-lane definition, on seeded random inputs (bx style: the ISA path against a scalar one).

#include "luxel/rasterizer/simd.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

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

TEST(Simd, ByteOfIsEachLanesByteZeroExtended) {
  std::mt19937 rng(2);
  for (int round = 0; round < kRounds; ++round) {
    int32_t v[kLanes], got[4][kLanes];
    for (int l = 0; l < kLanes; ++l) v[l] = static_cast<int32_t>(rng());
    simd::byte_of<0>(load(v)).store_unaligned(got[0]);
    simd::byte_of<1>(load(v)).store_unaligned(got[1]);
    simd::byte_of<2>(load(v)).store_unaligned(got[2]);
    simd::byte_of<3>(load(v)).store_unaligned(got[3]);
    for (int k = 0; k < 4; ++k)
      for (int l = 0; l < kLanes; ++l)
        ASSERT_EQ(got[k][l], int32_t((uint32_t(v[l]) >> (8 * k)) & 0xffu)) << "byte " << k << ", lane " << l;
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

TEST(Simd, StoreStampRowsWritesTheTopHalfThenTheBottomHalfAndNothingElse) {
  // Two rows of an image with a guard word around each stamp row, at every misalignment.
  std::mt19937 rng(6);
  constexpr int kRowWords = 3 * simd::kStampWidth;
  for (int shift = 0; shift < simd::kStampWidth; ++shift) {
    int32_t v[kLanes];
    for (int l = 0; l < kLanes; ++l) v[l] = static_cast<int32_t>(rng());
    std::vector<int32_t> image(2 * kRowWords, -7);
    int32_t* top = image.data() + 1 + shift;
    simd::store_stamp_rows(load(v), top, top + kRowWords);
    for (int i = 0; i < 2 * kRowWords; ++i) {
      const int row = i / kRowWords, x = i % kRowWords - 1 - shift;
      const int32_t want = x >= 0 && x < simd::kStampWidth ? v[row * simd::kStampWidth + x] : -7;
      ASSERT_EQ(image[size_t(i)], want) << "shift " << shift << ", row " << row << ", word " << x;
    }
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

/// D3D10's float to UNORM8 as the library does it: NaN to 0, clamped to [0, 1], times 255 in
/// float (so 2.5 / 255 becomes 2.5, and rounds to 2, where the exact product would give 3),
/// nearest even.
uint32_t unorm8(float x) {
  if (std::isnan(x)) return 0;
  const float v = std::clamp(x, 0.0f, 1.0f) * 255.0f;
  return static_cast<uint32_t>(std::nearbyint(v));
}

TEST(Simd, PackUnorm8RoundsClampsAndPlacesEachChannel) {
  // The hard cases first: NaN, infinities, huge and negative values, exact halves of a step
  // (which round to the even step), the ends of the range; then random values around [0, 1].
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  std::vector<float> values = {nan,   -nan,  inf,    -inf,     1e30f,   -1e30f, 3e9f, -3e9f, 0.0f, -0.0f, 1.0f,
                               1.5f, -0.5f, 0.5f / 255, 1.5f / 255, 2.5f / 255, 254.5f / 255, 0.499f / 255,
                               std::numeric_limits<float>::denorm_min(), 1.0f - 1e-7f};
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> around(-0.25f, 1.25f);
  while (values.size() < 4096) values.push_back(around(rng));
  for (size_t i = 0; i + 4 * kLanes <= values.size(); i += kLanes) {
    float ch[4][kLanes];
    for (int c = 0; c < 4; ++c)
      for (int l = 0; l < kLanes; ++l) ch[c][l] = values[(i + l + c * 7) % values.size()];
    const simd::Float4 color{Float::load_unaligned(ch[0]), Float::load_unaligned(ch[1]), Float::load_unaligned(ch[2]),
                             Float::load_unaligned(ch[3])};
    int32_t got[kLanes];
    simd::pack_unorm8(color).store_unaligned(got);
    for (int l = 0; l < kLanes; ++l) {
      const uint32_t want = unorm8(ch[0][l]) | unorm8(ch[1][l]) << 8 | unorm8(ch[2][l]) << 16 | unorm8(ch[3][l]) << 24;
      ASSERT_EQ(uint32_t(got[l]), want) << "lane " << l << ": " << ch[0][l] << " " << ch[1][l] << " " << ch[2][l] << " "
                                        << ch[3][l];
    }
  }
}

TEST(Simd, IntSelectTakesWholeLanes) {
  // Masks are all ones or zero per lane; the values have every byte different, so that a blend
  // by bytes of a wrong mask would show.
  int32_t mask[kLanes], a[kLanes], b[kLanes], got[kLanes];
  for (int round = 0; round < 64; ++round) {
    for (int l = 0; l < kLanes; ++l) {
      mask[l] = ((round >> (l % 6)) & 1) ? -1 : 0;
      a[l] = int32_t(0x01020304u * uint32_t(l + 1) + uint32_t(round));
      b[l] = int32_t(0x80a0c0e0u ^ uint32_t(a[l]));
    }
    simd::select(load(mask), load(a), load(b)).store_unaligned(got);
    for (int l = 0; l < kLanes; ++l) ASSERT_EQ(got[l], mask[l] ? a[l] : b[l]) << "lane " << l;
  }
}

TEST(Simd, FmaRoundsOnce) {
  // (1 + 2^-23)^2 - (1 + 2^-22) is exactly 2^-46: a multiply rounded before the add gives 0.
  const float a = 1.0f + 0x1p-23f, c = -(1.0f + 0x1p-22f);
  float got[kLanes];
  simd::fma(Float(a), Float(a), Float(c)).store_unaligned(got);
  for (int l = 0; l < kLanes; ++l) EXPECT_EQ(got[l], 0x1p-46f) << "lane " << l;
  simd::fnma(Float(a), Float(a), Float(-c)).store_unaligned(got);
  for (int l = 0; l < kLanes; ++l) EXPECT_EQ(got[l], -0x1p-46f) << "lane " << l;
  // Random lanes against std::fma.
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-4.0f, 4.0f);
  for (int round = 0; round < kRounds; ++round) {
    float x[kLanes], y[kLanes], z[kLanes];
    for (int l = 0; l < kLanes; ++l) x[l] = u(rng), y[l] = u(rng), z[l] = u(rng);
    simd::fma(Float::load_unaligned(x), Float::load_unaligned(y), Float::load_unaligned(z)).store_unaligned(got);
    for (int l = 0; l < kLanes; ++l) ASSERT_EQ(got[l], std::fma(x[l], y[l], z[l])) << "lane " << l;
  }
}

// gather_stamp_rows reads windows exactly when every lane lies within kStampRowWindowWords words
// past its row's first lane, and then returns what a gather returns; otherwise it leaves `out`.
TEST(Simd, GatherStampRowsReadsWindowsExactlyWhenTheRowsAllowIt) {
  constexpr int kWindow = simd::kStampRowWindowWords;
  constexpr int kWords = 4096;
  std::vector<int32_t> words(kWords + kWindow);
  std::mt19937 rng(12);
  for (int32_t& w : words) w = static_cast<int32_t>(rng());
  const auto first_of_row = [](int l) { return simd::lane_y(l) == 0 ? 0 : 2; };
  const auto check = [&](const int32_t (&index)[kLanes], const char* what) {
    bool near = kWindow > 0;
    for (int l = 0; l < kLanes; ++l) {
      const int64_t offset = int64_t{index[l]} - index[first_of_row(l)];
      near = near && offset >= 0 && offset < kWindow;
    }
    Int out(-7);
    const bool read = simd::gather_stamp_rows(words.data(), load(index), out);
    ASSERT_EQ(read, near) << what;
    int32_t got[kLanes];
    out.store_unaligned(got);
    for (int l = 0; l < kLanes; ++l) ASSERT_EQ(got[l], read ? words[size_t(index[l])] : -7) << what << ", lane " << l;
  };
  const auto at = [&](auto offset_of_pixel, int32_t top, int32_t bottom) {
    int32_t index[kLanes];
    for (int l = 0; l < kLanes; ++l) index[l] = (simd::lane_y(l) == 0 ? top : bottom) + offset_of_pixel(simd::lane_x(l));
    return std::to_array(index);
  };
  const auto run = [&](const std::array<int32_t, kLanes>& a, const char* what) {
    int32_t index[kLanes];
    std::copy(a.begin(), a.end(), index);
    check(index, what);
  };
  // A texel per pixel, a texel per four pixels, and rows in either order in memory.
  run(at([](int x) { return x; }, 100, 1380), "a texel per pixel");
  run(at([](int x) { return x / 4; }, 2000, 37), "stretched four times");
  run(at([](int x) { return 0 * x; }, kWords - 1, kWords - 1), "the last word");
  // The window's edge: the last pixel of the top row at offset kWindow - 1, then kWindow; the
  // AVX-512 path's narrower window's edge (15, 16) inside it.
  for (int last : {15, 16, kWindow - 1, kWindow}) {
    auto index = at([](int x) { return x; }, 500, 900);
    for (int l = 0; l < kLanes; ++l)
      if (simd::lane_y(l) == 0 && simd::lane_x(l) == simd::kStampWidth - 1) index[size_t(l)] = 500 + last;
    run(index, "the window's edge");
  }
  // A lane before its row's first: no window.
  auto before = at([](int x) { return x; }, 500, 900);
  before[1] = 499;
  run(before, "a lane before its row's first");
  // Random rows: clustered (offsets within the window, sometimes one past it) and scattered.
  for (int round = 0; round < kRounds; ++round) {
    const int32_t top = int32_t(rng() % kWords), bottom = int32_t(rng() % kWords);
    std::array<int32_t, kLanes> index{};
    for (int l = 0; l < kLanes; ++l) {
      const int32_t first = simd::lane_y(l) == 0 ? top : bottom;
      const int32_t spread = round % 3 == 0 ? kWords : kWindow + (round % 3 == 1 ? 0 : 1);
      index[size_t(l)] = std::min<int32_t>(first + int32_t(rng() % uint32_t(std::max(spread, 1))), kWords - 1);
    }
    index[0] = top, index[2] = bottom;
    run(index, "random rows");
  }
}

// gather_two_fours returns in words[k] what a gather of index + k returns and in words[k + 4]
// what one of index + second + k does, lane for lane: lanes reading the same words, neighbouring
// ones, far apart, the first and the last runs of the memory; the second run after the first,
// before it, overlapping it, and far from it.
TEST(Simd, GatherTwoFoursIsEightGathersOfTwoRuns) {
  constexpr int kWords = 4096;
  std::vector<int32_t> words(kWords + 8);
  std::mt19937 rng(21);
  for (int32_t& w : words) w = static_cast<int32_t>(rng());
  const auto check = [&](const std::array<int32_t, kLanes>& index, int32_t second, const char* what) {
    int32_t raw[kLanes];
    std::copy(index.begin(), index.end(), raw);
    Int got[8];
    simd::gather_two_fours(words.data(), load(raw), second, got);
    for (int k = 0; k < 8; ++k) {
      int32_t lanes_of_word[kLanes];
      got[k].store_unaligned(lanes_of_word);
      for (int l = 0; l < kLanes; ++l) {
        const int32_t at = index[size_t(l)] + (k < 4 ? k : second + k - 4);
        ASSERT_EQ(lanes_of_word[l], words[size_t(at)]) << what << ", second " << second << ", word " << k << ", lane " << l;
      }
    }
  };
  for (const int32_t second : {4, 1000, -4, 2, 0}) {
    const int32_t low = std::max(0, -second), high = kWords - 4 - std::max(0, second);
    std::array<int32_t, kLanes> index{};
    index.fill(high);
    check(index, second, "every lane the last runs");
    index.fill(low);
    check(index, second, "every lane the first runs");
    for (int l = 0; l < kLanes; ++l) index[size_t(l)] = low + 8 * l;
    check(index, second, "runs side by side");
    for (int l = 0; l < kLanes; ++l) index[size_t(l)] = high - 37 * l;
    check(index, second, "runs overlapping, backwards");
    for (int round = 0; round < kRounds; ++round) {
      for (int32_t& i : index) i = low + int32_t(rng() % uint32_t(high - low + 1));
      check(index, second, "random runs");
    }
  }
}

/// 256 floats of random bits, NaN payloads included.
std::array<float, 256> random_float_table(std::mt19937& rng) {
  std::array<float, 256> table{};
  for (float& t : table) {
    const uint32_t bits = static_cast<uint32_t>(rng());
    std::memcpy(&t, &bits, 4);
  }
  return table;
}

// lookup_byte returns the table's entry for every index in every lane, bit for bit.
TEST(Simd, LookupByteIsTheTablesEntryInEveryLane) {
  std::mt19937 rng(13);
  const std::array<float, 256> table = random_float_table(rng);
  for (int round = 0; round < 256 + kRounds; ++round) {
    int32_t index[kLanes];
    // First every index in every lane (a rotation per round), then random ones.
    for (int l = 0; l < kLanes; ++l) index[l] = round < 256 ? (round + 37 * l) & 255 : int32_t(rng() & 255);
    float got[kLanes];
    simd::lookup_byte(table.data(), load(index)).store_unaligned(got);
    for (int l = 0; l < kLanes; ++l) ASSERT_EQ(std::memcmp(&got[l], &table[size_t(index[l])], 4), 0) << "index " << index[l];
  }
}

// lookup_bytes3 returns, in every lane, the table's entries at the word's bytes 0, 1 and 2, bit
// for bit, whatever byte 3 holds.
TEST(Simd, LookupBytes3IsTheTablesEntriesAtEachWordsFirstThreeBytes) {
  std::mt19937 rng(17);
  const std::array<float, 256> entries = random_float_table(rng);
  const simd::ByteTable table = simd::byte_table(entries);
  for (int round = 0; round < 256 + kRounds; ++round) {
    int32_t word[kLanes];
    // First every byte value at every position in every lane (rotations per round), then random.
    for (int l = 0; l < kLanes; ++l) {
      const uint32_t b0 = (round + 37 * l) & 255, b1 = (round * 7 + 11 * l + 1) & 255, b2 = (255 - round + 5 * l) & 255;
      word[l] = round < 256 ? int32_t(b0 | b1 << 8 | b2 << 16 | (rng() & 255u) << 24) : int32_t(rng());
    }
    simd::Float got[3];
    simd::lookup_bytes3(table, load(word), got[0], got[1], got[2]);
    for (int k = 0; k < 3; ++k) {
      float lanes[kLanes];
      got[k].store_unaligned(lanes);
      for (int l = 0; l < kLanes; ++l) {
        const size_t index = (uint32_t(word[l]) >> (8 * k)) & 255u;
        ASSERT_EQ(std::memcmp(&lanes[l], &entries[index], 4), 0) << "lane " << l << " byte " << k << " = " << index;
      }
    }
  }
}

}  // namespace
}  // namespace luxel::rasterizer
