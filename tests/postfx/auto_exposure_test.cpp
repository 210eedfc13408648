// Source's auto exposure against independent math: the percentile walk, both target rules, the
// 10-frame history and the chase (a double-precision re-statement of auto_exposure.hpp's rules),
// and the whole loop on frames whose luminance is known in closed form: it settles where the
// rule says, follows a step in brightness at its rate, and gives the same scales on 1 and 2
// threads.

#include "luxel/postfx/auto_exposure.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <numeric>

namespace luxel::postfx {
namespace {

/// The buckets of `algorithm` with these counts (calibration: their sum unless given), all valid.
std::vector<BucketCount> counted(ExposureAlgorithm algorithm, std::vector<uint64_t> counts, int64_t calibration = -1) {
  const auto ranges = histogram_buckets(algorithm);
  std::vector<BucketCount> b(ranges.size());
  counts.resize(ranges.size() - 1, 0);
  for (size_t i = 0; i < b.size(); ++i) {
    b[i].range = ranges[i];
    b[i].state = BucketCount::State::done;
    b[i].in_range = i + 1 < b.size() ? counts[i] : calibration >= 0 ? uint64_t(calibration) : std::accumulate(counts.begin(), counts.end(), uint64_t(0));
  }
  return b;
}

double width(const BucketCount& b) { return double(b.range.max) - double(b.range.min); }

TEST(AutoExposure, PercentileLocationInterpolatesInsideTheBucketThatCompletesIt) {
  // 1000 pixels: 5 in bucket 15, 30 in bucket 14, the rest low. 2 %: all 5 of bucket 15 (0.5 %)
  // and 15 of bucket 14's 30.
  std::vector<uint64_t> counts(16, 0);
  counts[15] = 5, counts[14] = 30, counts[3] = 600, counts[2] = 365;
  const auto b = counted(ExposureAlgorithm::percentile, counts);
  const double expected = double(b[14].range.max) - width(b[14]) * (0.02 - 0.005) / 0.030;
  EXPECT_NEAR(percent_bright_location(b, ExposureAlgorithm::percentile, 2.0f), expected, 1e-6);
  // 50 %: 5 + 30 + 600 reach it in bucket 3, needing 465 of its 600.
  const double median = double(b[3].range.max) - width(b[3]) * (0.5 - 0.035) / 0.6;
  EXPECT_NEAR(percent_bright_location(b, ExposureAlgorithm::percentile, 50.0f), median, 1e-6);
  EXPECT_EQ(percent_bright_location(b, ExposureAlgorithm::mean, 2.0f), -1.0f) << "the mean rule has no percentile";
}

TEST(AutoExposure, PercentileLocationSnapsInTheTargetsBinAndNeedsEveryBucketAbove) {
  std::vector<uint64_t> counts(16, 0);
  counts[11] = 100;  // [0.5700, 0.6495] holds 0.60
  auto b = counted(ExposureAlgorithm::percentile, counts);
  EXPECT_EQ(percent_bright_location(b, ExposureAlgorithm::percentile, 2.0f, 60.0f), 0.6f);
  EXPECT_NEAR(percent_bright_location(b, ExposureAlgorithm::percentile, 2.0f), double(b[11].range.max) - width(b[11]) * 0.02, 1e-6);
  b[13].state = BucketCount::State::first_query_in_flight;  // above the answer: no answer
  EXPECT_EQ(percent_bright_location(b, ExposureAlgorithm::percentile, 2.0f), -1.0f);
  b[13].state = BucketCount::State::done;
  b[2].state = BucketCount::State::initial;  // below it: irrelevant
  EXPECT_NEAR(percent_bright_location(b, ExposureAlgorithm::percentile, 2.0f), double(b[11].range.max) - width(b[11]) * 0.02, 1e-6);
  b[2].state = BucketCount::State::query_in_flight;  // measured again: still valid
  EXPECT_TRUE(b[2].valid());
}

TEST(AutoExposure, PercentileTargetUsesTheMedianOnlyToBrighten) {
  AutoExposureSettings s;
  // Mid-grey frame in bucket 8 [0.3536, 0.4219]: 0.60 / the 98th percentile, x the current 1.5.
  std::vector<uint64_t> mid(16, 0);
  mid[8] = 1000;
  auto b = counted(ExposureAlgorithm::percentile, mid);
  const double loc = double(b[8].range.max) - width(b[8]) * 0.02;
  EXPECT_NEAR(target_scale(b, s, 1.5f, 0), 0.6 / loc * 1.5, 1e-5);
  // Dark with a few highlights: 97 % in bucket 0, 3 % in bucket 15. 0.60 / ~0.95 would darken;
  // the median term 0.03 / median brightens instead.
  std::vector<uint64_t> dark(16, 0);
  dark[0] = 970, dark[15] = 30;
  b = counted(ExposureAlgorithm::percentile, dark);
  const double median = double(b[0].range.max) - width(b[0]) * (0.5 - 0.03) / 0.97;
  EXPECT_NEAR(target_scale(b, s, 1.0f, 0), 0.03 / median, 1e-4);
  EXPECT_GT(0.03 / median, 0.6 / (double(b[15].range.max) - width(b[15]) * (0.02 / 0.03)));
  // No counts at all: as if at the target, so the current scale.
  std::vector<BucketCount> none = counted(ExposureAlgorithm::percentile, {});
  for (BucketCount& c : none) c.state = BucketCount::State::initial;
  EXPECT_EQ(target_scale(none, s, 1.25f, 0), 1.25f);
}

TEST(AutoExposure, MeanTargetIsTheCentersMeanOverTheValidBuckets) {
  AutoExposureSettings s;
  s.histogram.algorithm = ExposureAlgorithm::mean;
  // 4x MSAA counts: the calibration bucket holds 4 x the region's 500 pixels; the viewport is 800.
  std::vector<uint64_t> counts(30, 0);
  counts[5] = 4 * 300, counts[20] = 4 * 200;
  auto b = counted(ExposureAlgorithm::mean, counts, 4 * 500);
  const auto center = [&](int i) { return 0.5 * (double(b[size_t(i)].range.min) + double(b[size_t(i)].range.max)); };
  const double mean = (300.0 * center(5) + 200.0 * center(20)) / 500.0;  // the region's true mean
  EXPECT_NEAR(target_scale(b, s, 1.7f, 800), 0.005 / (mean / 30.0), 1e-3 * 0.005 / (mean / 30.0)) << "not x the current scale";
  // Ten valid buckets: the mean is divided by 10, not 30.
  for (int i = 10; i < 30; ++i) b[size_t(i)].state = BucketCount::State::initial;
  EXPECT_NEAR(target_scale(b, s, 1.0f, 800), 0.005 / (300.0 * center(5) / 500.0 / 10.0), 1e-3 * 0.005 / (300.0 * center(5) / 5000.0));
}

/// Steps 3 and 4 of auto_exposure.hpp, restated in double.
struct ReferenceScale {
  AutoExposureSettings s;
  double current, goal;
  std::deque<double> history;
  explicit ReferenceScale(const AutoExposureSettings& settings) : s(settings), current(settings.initial_scale), goal(current) {}
  void push(double target, double dt) {
    target = std::max(0.001, std::clamp(target, double(s.min_scale), double(s.max_scale)));
    history.push_back(target);
    if (history.size() > 10) history.pop_front();
    goal = target;
    if (history.size() == 10) {
      const double w[10] = {1.0, 0.8, 0.6, 0.4, 0.2, 0.0, 0.2, 0.4, 0.6, 0.8};
      double sum = 0.0;
      for (int i = 0; i < 10; ++i) sum += w[i] * history[size_t(i)];
      goal = std::clamp(sum / 5.0, double(s.min_scale), double(s.max_scale));
    }
    const bool percentile = s.histogram.algorithm == ExposureAlgorithm::percentile;
    double rate = s.rate * (percentile ? 2.0 : 1.0);
    if (goal < current) rate = std::min(3.0 * rate, rate + 2.0 * rate * (current - goal) / 1.5);
    double alpha = rate * dt;
    if (percentile) alpha = std::min(alpha, 1.0 / 64.0);
    alpha = std::clamp(alpha, 0.0, 1.0);
    current = goal * alpha + current * (1.0 - alpha);
  }
};

TEST(AutoExposure, HistoryAndChaseFollowTheDocumentedRules) {
  for (ExposureAlgorithm algorithm : {ExposureAlgorithm::percentile, ExposureAlgorithm::mean}) {
    for (float dt : {1.0f / 30.0f, 1.0f / 5.0f}) {
      AutoExposureSettings s;
      s.histogram.algorithm = algorithm;
      s.min_scale = 0.25f, s.max_scale = 6.0f, s.rate = 1.5f;
      ToneMapScale scale(s);
      ReferenceScale reference(s);
      for (int f = 0; f < 60; ++f) {
        // Up, far up (clamped), then down steeply (the accelerated chase), with a wobble.
        const double target = f < 15 ? 3.0 + 0.3 * std::sin(f) : f < 30 ? 40.0 : 0.3 + 0.1 * std::cos(f);
        scale.push(float(target), dt);
        reference.push(target, dt);
        EXPECT_NEAR(scale.goal(), reference.goal, 2e-6 * reference.goal) << "frame " << f;
        EXPECT_NEAR(scale.current(), reference.current, 2e-5 * reference.current) << "frame " << f;
      }
    }
  }
  AutoExposureSettings s;
  s.rate = 0.0f;
  ToneMapScale jump(s);
  jump.push(1.75f, 0.01f);
  EXPECT_EQ(jump.current(), 1.75f) << "rate 0 jumps to the goal";
  jump.push(std::numeric_limits<float>::quiet_NaN(), 0.01f);
  EXPECT_EQ(jump.current(), 1.75f) << "a non-finite target is ignored";
  s.max_scale = 0.25f;  // below min: max is raised to min
  ToneMapScale raised(s);
  raised.push(0.1f, 1.0f);
  EXPECT_EQ(raised.goal(), 0.5f);
}

/// A frame of uniform pre-exposure luminance `y` drawn at `scale`: grey, sRGB-encoded, clipped.
rasterizer::Image grey_frame(int w, int h, double y, float scale) {
  const double linear = std::min(1.0, y * double(scale));
  const double s = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
  rasterizer::Image image(w, h);
  const uint8_t code = uint8_t(std::lround(s * 255.0));
  for (size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = i % 4 == 3 ? 255 : code;
  return image;
}

double decoded(const rasterizer::Image& image) {
  const double s = image.rgba[0] / 255.0;
  return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
}

/// Runs the loop at 30 fps for `frames` on grey of luminance y(frame); returns the scales.
template <class Y>
std::vector<float> run(AutoExposure& exposure, rasterizer::Context& ctx, int frames, Y&& y) {
  std::vector<float> scales;
  rasterizer::DepthStencilTarget target(32, 20, 4);
  for (int f = 0; f < frames; ++f) {
    const rasterizer::Image frame = grey_frame(32, 20, y(f), exposure.scale());
    exposure.measure(ctx, frame, target, 1.0f / 30.0f);
    scales.push_back(exposure.scale());
  }
  return scales;
}

TEST(AutoExposure, PercentileSettlesInTheTargetsBinAndFollowsAStepAtItsRate) {
  AutoExposureSettings s;
  s.max_scale = 16.0f;
  rasterizer::Context ctx(1);
  auto settle = [&](float rate) {
    s.rate = rate;
    AutoExposure exposure(s);
    const std::vector<float> scales = run(exposure, ctx, 2400, [](int f) { return f < 1200 ? 0.30 : 0.15; });
    // Settled: the frame's luminance is in the bucket that holds 0.60, and the scale holds still.
    const double before = decoded(grey_frame(1, 1, 0.30, scales[1199])), after = decoded(grey_frame(1, 1, 0.15, scales[2399]));
    EXPECT_GE(before, 0.5700) << "rate " << rate;
    EXPECT_LE(before, 0.6495) << "rate " << rate;
    EXPECT_GE(after, 0.5700) << "rate " << rate;
    EXPECT_LE(after, 0.6495) << "rate " << rate;
    EXPECT_NEAR(scales[2399], scales[2300], 1e-4);
    // Frames after the step until the scale is within 5 % of where it settles.
    int f = 1200;
    while (std::abs(scales[size_t(f)] - scales[2399]) > 0.05f * scales[2399]) ++f;
    return f - 1200;
  };
  // The scene darkens, so the scale rises (no acceleration). At 30 fps the percentile rule's
  // per-frame cap (1/64) binds from rate 0.24 up (2 x rate / 30), so the rate shows below it; at
  // the default rate 1 every frame moves 1/64 of the way.
  const int slow = settle(0.1f), fast = settle(0.2f), capped = settle(1.0f), also_capped = settle(4.0f);
  EXPECT_GT(slow, fast) << "a higher rate follows the step sooner";
  EXPECT_GT(fast, capped);
  EXPECT_EQ(capped, also_capped) << "above the cap the rate no longer matters";
  std::printf("step 0.30 -> 0.15 at 30 fps: within 5 %% after %d frames at rate 0.1, %d at 0.2, %d at 1 and 4\n", slow, fast,
              capped);
}

TEST(AutoExposure, MeanSettlesWhereTheBucketCenterRuleHasItsFixedPoint) {
  // Pre-exposure luminance 0.34: at s = 0.15 / center(bucket 20) = 0.6669 the frame's 0.2268
  // lies in bucket 20 [0.2069, 0.2429] itself, so the rule's target is s again.
  AutoExposureSettings s;
  s.histogram.algorithm = ExposureAlgorithm::mean;
  AutoExposure exposure(s);
  rasterizer::Context ctx(2);
  const std::vector<float> scales = run(exposure, ctx, 900, [](int) { return 0.34; });
  const auto& b = histogram_buckets(ExposureAlgorithm::mean)[20];
  const double fixed_point = 0.005 * 30.0 / (0.5 * (double(b.min) + double(b.max)));
  EXPECT_NEAR(scales.back(), fixed_point, 0.01 * fixed_point);
}

TEST(AutoExposure, ExactTargetIsTheOcclusionTargetOnceEveryBucketIsBack) {
  // A frame of four greys; once every bucket's query is back, the occlusion histogram counts what
  // the exact one does, so both rules give the same target.
  rasterizer::Image frame(48, 32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 48; ++x) {
      uint8_t* p = frame.pixel(x, y);
      p[0] = p[1] = p[2] = uint8_t(40 + 60 * ((x / 12 + y / 16) % 4));
      p[3] = 255;
    }
  for (ExposureAlgorithm algorithm : {ExposureAlgorithm::percentile, ExposureAlgorithm::mean}) {
    AutoExposureSettings s;
    s.histogram.algorithm = algorithm;
    LuminanceHistogram histogram(s.histogram);
    rasterizer::Context ctx(2);
    rasterizer::DepthStencilTarget target(48, 32, 4);
    for (int f = 0; f < 40; ++f) histogram.update(ctx, frame, target);
    const float occlusion = target_scale(histogram.buckets(), s, 1.3f, histogram.viewport_pixels());
    EXPECT_NEAR(exact_target(frame, s, 1.3f), occlusion, 1e-6f * occlusion);
    EXPECT_NE(occlusion, 1.3f) << "the frame is not at the target";
  }
}

TEST(AutoExposure, SameScalesOnOneAndTwoThreads) {
  for (ExposureAlgorithm algorithm : {ExposureAlgorithm::percentile, ExposureAlgorithm::mean}) {
    for (HistogramCount count : {HistogramCount::direct_query, HistogramCount::stencil}) {
      AutoExposureSettings s;
      s.histogram.algorithm = algorithm;
      s.histogram.count = count;
      auto y = [](int f) { return 0.05 + 0.02 * (f % 7); };
      rasterizer::Context one(1), two(2);
      AutoExposure a(s), b(s);
      EXPECT_EQ(run(a, one, 30, y), run(b, two, 30, y));
    }
  }
}

}  // namespace
}  // namespace luxel::postfx
