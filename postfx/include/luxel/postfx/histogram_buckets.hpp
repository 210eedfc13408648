#pragma once
// The luminance buckets of Source's auto-exposure histogram (docs/fidelity.md#auto-exposure), for both
// of its target algorithms (mat_tonemap_algorithm):
//  - percentile (1, "new", the default): 16 buckets [(i/16)^1.5, ((i+1)/16)^1.5]; the top one
//    ends at exactly 1.0, so its range test also takes everything brighter;
//  - mean (0, "original": Day of Defeat, Counter-Strike and Lost Coast): 30 log-spaced buckets,
//    min_i = -0.01 + exp(lerp(ln 0.01, ln 1.01, i/30)), computed in float as the SDK does, so the
//    top bound is 0.99999982 and takes nothing brighter (pure white lands in no bucket).
// Both end with the calibration bucket [0, 100000] ("all pixels"), whose count tells how many
// samples the query counts per pixel of the region.

#include <span>

namespace luxel::postfx {

enum class ExposureAlgorithm {
  percentile,  ///< mat_tonemap_algorithm 1: the 98th percentile and the median term
  mean,        ///< mat_tonemap_algorithm 0: the mean of the bucket centers
};

/// One range test, inclusive at both ends.
struct HistogramBucket {
  float min = 0.0f, max = 0.0f;
};

/// The algorithm's buckets, darkest first, the calibration bucket last (17 or 31 in all).
std::span<const HistogramBucket> histogram_buckets(ExposureAlgorithm algorithm);

/// The upper bound the range test uses for a bucket: a max of exactly 1.0 becomes 10000.
inline float range_test_max(const HistogramBucket& b) { return b.max == 1.0f ? 10000.0f : b.max; }

}  // namespace luxel::postfx
