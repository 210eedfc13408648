// How close exp2, log2 and pow are to the exact values (double precision, rounded): the stated
// bounds in intrinsics.hpp, checked. The SIMD lane is bit-identical to the scalar one
// (lanes_agree_test), so the scalar lane is measured here.

#include "lanes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

namespace luxel::shading {
namespace {

TEST(Accuracy, Exp2WithinOneUlpOverTheNormalRange) {
  int64_t worst = 0;
  float worst_x = 0.0f;
  for (float x = -126.0f; x < 128.0f; x += 1.0f / 1024.0f) {
    const float exact = static_cast<float>(std::exp2(static_cast<double>(x)));
    const int64_t d = testing::ulp_distance(exp2(x), exact);
    if (d > worst) worst = d, worst_x = x;
  }
  EXPECT_LE(worst, 1) << "at x = " << worst_x;
  // Denormal results: exact to the denormal step (one rounding of an accurate 2^f).
  for (float x = -149.0f; x < -126.0f; x += 1.0f / 64.0f) {
    const float exact = static_cast<float>(std::exp2(static_cast<double>(x)));
    EXPECT_LE(testing::ulp_distance(exp2(x), exact), 1) << x;
  }
}

TEST(Accuracy, Log2WithinTwoUlpOrTwoToTheMinus23Absolute) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<uint32_t> bits(1, 0x7f7fffffu);  // every positive finite float
  int64_t worst = 0;
  double worst_abs = 0.0;
  for (int i = 0; i < 400000; ++i) {
    const float x = std::bit_cast<float>(bits(rng));
    const double exact = std::log2(static_cast<double>(x));
    const float got = log2(x);
    if (std::fabs(exact) >= 1.0) {
      worst = std::max(worst, testing::ulp_distance(got, static_cast<float>(exact)));
    } else {
      worst_abs = std::max(worst_abs, std::fabs(got - exact));
    }
  }
  // Near 1 the result is tiny and e + log2(m) is one rounding away: absolute error instead.
  for (float x = 0.5f; x < 2.0f; x = std::nextafter(x, 4.0f) + 1e-6f) {
    const double exact = std::log2(static_cast<double>(x));
    worst_abs = std::max(worst_abs, std::fabs(log2(x) - exact) / std::max(1.0, std::fabs(exact)));
  }
  EXPECT_LE(worst, 2);
  EXPECT_LE(worst_abs, std::ldexp(1.0, -23));
}

TEST(Accuracy, PowRelativeErrorGrowsWithTheExponentLikeTheHardwares) {
  // pow(x, y) = exp2(y log2 x): the log's absolute error is multiplied by y. For the Phong range
  // (x in (0, 1], y up to 150) the relative error stays under (|y log2 x| + 4) * 2^-22, i.e. about
  // 2^-17 at the worst Phong exponent: better than the 15 bits DX9 asks of vs_2_0's pow.
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> base(1e-3f, 1.0f);
  std::uniform_real_distribution<float> exponent(0.0f, 150.0f);
  double worst_ratio = 0.0;
  for (int i = 0; i < 200000; ++i) {
    const float x = base(rng);
    const float y = exponent(rng);
    const double exact = std::pow(static_cast<double>(x), static_cast<double>(y));
    if (exact < 1e-37) continue;  // denormal results: absolute error, covered by exp2's test
    const double rel = std::fabs(pow(x, y) - exact) / exact;
    const double bound = (std::fabs(y * std::log2(static_cast<double>(x))) + 4.0) * std::ldexp(1.0, -22);
    worst_ratio = std::max(worst_ratio, rel / bound);
  }
  EXPECT_LE(worst_ratio, 1.0);
}

TEST(Accuracy, SinCosErrorIsTheReductionsRounding) {
  // r = frac(x / 2 pi + 1/2) rounds twice (and 1 / 2 pi is itself rounded), so the angle is off
  // by up to about |x| 2^-23, plus the polynomial's few ulp: absolute error under (|x| + 1) 2^-22.
  double worst_ratio = 0.0;
  for (float x = -200.0f; x < 200.0f; x += 0.000733f) {
    const double bound = (std::fabs(x) + 1.0) * std::ldexp(1.0, -22);
    worst_ratio = std::max(worst_ratio, std::fabs(sin(x) - std::sin(static_cast<double>(x))) / bound);
    worst_ratio = std::max(worst_ratio, std::fabs(cos(x) - std::cos(static_cast<double>(x))) / bound);
  }
  EXPECT_LE(worst_ratio, 1.0);
}

}  // namespace
}  // namespace luxel::shading
