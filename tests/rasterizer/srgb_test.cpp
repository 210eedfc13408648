// The sRGB curve's one home (srgb.hpp) against IEC 61966-2-1 written out here in double: the
// exact functions at and around the breakpoints, every entry of the decode and encode tables.

#include "luxel/rasterizer/srgb.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace luxel::rasterizer {
namespace {

// IEC 61966-2-1, from the standard's text (not from srgb.hpp).
double iec_decode(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }
double iec_encode(double l) { return l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055; }

TEST(Srgb, ExactCurveMatchesTheStandardAroundItsBreakpoints) {
  for (double v : {0.0, 0.001, 0.04, 0.04045, 0.0405, 0.1, 0.5, 0.73, 0.99, 1.0}) {
    EXPECT_DOUBLE_EQ(srgb_to_linear(v), iec_decode(v)) << v;
  }
  for (double l : {0.0, 1e-5, 0.003, 0.0031308, 0.00314, 0.018, 0.2, 0.5, 0.9, 1.0}) {
    EXPECT_DOUBLE_EQ(linear_to_srgb(l), iec_encode(l)) << l;
  }
  // Known values: mid grey 0.5 linear encodes to 0.735357; 0.5 encoded decodes to 0.214041.
  EXPECT_NEAR(linear_to_srgb(0.5), 0.7353569830524495, 1e-12);
  EXPECT_NEAR(srgb_to_linear(0.5), 0.21404114048223255, 1e-12);
  for (int i = 0; i <= 1000; ++i) EXPECT_NEAR(srgb_to_linear(linear_to_srgb(i / 1000.0)), i / 1000.0, 1e-12);
}

TEST(Srgb, DecodeTableIsTheCurveRoundedToFloat) {
  for (int c = 0; c < 256; ++c) {
    EXPECT_EQ(kSrgbToLinear[c], static_cast<float>(iec_decode(c / 255.0))) << "byte " << c;
  }
}

TEST(Srgb, EncodeTableIsTheCurveOfTheQuantizedValueRounded) {
  const std::array<uint8_t, 65536>& table = srgb_encode_table();
  int mismatches = 0;
  for (int i = 0; i < 65536; ++i) {
    const int want = static_cast<int>(std::floor(iec_encode(i / 65535.0) * 255.0 + 0.5));
    if (table[i] != want) ++mismatches;
    EXPECT_EQ(table[i], want) << "entry " << i;
    if (mismatches > 10) break;
  }
  EXPECT_EQ(table[0], 0);
  EXPECT_EQ(table[65535], 255);
}

}  // namespace
}  // namespace luxel::rasterizer
