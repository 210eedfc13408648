// The histogram's buckets against docs/fidelity.md#auto-exposure's rules, computed here in double.

#include "luxel/postfx/histogram_buckets.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace luxel::postfx {
namespace {

TEST(HistogramBuckets, PercentileBucketsArePowersOfOneAndAHalf) {
  const auto b = histogram_buckets(ExposureAlgorithm::percentile);
  ASSERT_EQ(b.size(), 17u);
  for (int i = 0; i < 16; ++i) {
    EXPECT_NEAR(b[i].min, std::pow(i / 16.0, 1.5), 1e-6) << i;
    EXPECT_NEAR(b[i].max, std::pow((i + 1) / 16.0, 1.5), 1e-6) << i;
    if (i > 0) {
      EXPECT_EQ(b[i].min, b[i - 1].max) << "contiguous at " << i;
    }
  }
  EXPECT_NEAR(b[9].max, 0.4941, 5e-5);  // the table's boundary 10
  EXPECT_EQ(b[15].max, 1.0f) << "exactly 1: the top bucket takes everything brighter";
  EXPECT_EQ(range_test_max(b[15]), 10000.0f);
  EXPECT_EQ(b[16].min, 0.0f);
  EXPECT_EQ(b[16].max, 100000.0f);
}

TEST(HistogramBuckets, MeanBucketsAreLogSpacedAndTheTopStopsShortOfOne) {
  const auto b = histogram_buckets(ExposureAlgorithm::mean);
  ASSERT_EQ(b.size(), 31u);
  const double table[] = {0, 0.00166, 0.0036, 0.00586, 0.0085, 0.01158, 0.01517, 0.01935, 0.02424, 0.02993, 0.03657,
                          0.04431, 0.05335, 0.06388, 0.07617, 0.0905, 0.10721, 0.1267, 0.14944, 0.17595, 0.20688,
                          0.24294, 0.28501, 0.33407, 0.39129, 0.45802, 0.53586, 0.62663, 0.73251, 0.85599, 1.0};
  for (int i = 0; i < 30; ++i) {
    const double lo = -0.01 + std::exp(std::log(0.01) + (std::log(1.01) - std::log(0.01)) * i / 30.0);
    EXPECT_NEAR(b[i].min, lo, 1e-6) << i;
    EXPECT_NEAR(b[i].min, table[i], 6e-6) << i;
    EXPECT_NEAR(b[i].max, table[i + 1], 6e-6) << i;
  }
  EXPECT_NEAR(b[0].min, 0.0f, 1e-8);
  EXPECT_LT(b[29].max, 1.0f) << "float rounding: white is in no bucket (docs/fidelity.md#auto-exposure)";
  EXPECT_EQ(range_test_max(b[29]), b[29].max);
  EXPECT_EQ(b[30].max, 100000.0f);
}

}  // namespace
}  // namespace luxel::postfx
