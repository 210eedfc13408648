#include "luxel/postfx/histogram_buckets.hpp"

#include <array>
#include <cmath>

namespace luxel::postfx {
namespace {

constexpr HistogramBucket kCalibration{0.0f, 100000.0f};

std::array<HistogramBucket, 17> percentile_buckets() {
  std::array<HistogramBucket, 17> b{};
  for (int i = 0; i < 16; ++i) b[i] = {std::pow(i / 16.0f, 1.5f), std::pow((i + 1) / 16.0f, 1.5f)};
  b[16] = kCalibration;
  return b;
}

// The SDK's expression, - 0.01 + exp(FLerp(log(.01), log(.01 + 1), 0, 30, i)), with its types:
// the logs in double rounded to FLerp's float parameters, FLerp and exp in float, the sum in
// double rounded to the float it is stored in.
float log_bound(int i) {
  const float lo = float(std::log(0.01)), hi = float(std::log(0.01 + 1));
  const float lerped = lo + (hi - lo) * (float(i) - 0.0f) / (30.0f - 0.0f);
  return float(-0.01 + double(std::exp(lerped)));
}

std::array<HistogramBucket, 31> mean_buckets() {
  std::array<HistogramBucket, 31> b{};
  for (int i = 0; i < 30; ++i) b[i] = {log_bound(i), log_bound(i + 1)};
  b[30] = kCalibration;
  return b;
}

}  // namespace

std::span<const HistogramBucket> histogram_buckets(ExposureAlgorithm algorithm) {
  static const std::array<HistogramBucket, 17> percentile = percentile_buckets();
  static const std::array<HistogramBucket, 31> mean = mean_buckets();
  if (algorithm == ExposureAlgorithm::percentile) return percentile;
  return mean;
}

}  // namespace luxel::postfx
