// The occlusion-query histogram: the region the SDK measures, the one-bucket-per-frame schedule
// with its latency, and counts that equal a direct count of the same pixels (both counting
// methods, both rejects, 1 and 4 samples, 1 and 2 threads).

#include "luxel/postfx/luminance_histogram.hpp"

#include <gtest/gtest.h>

#include <random>

namespace luxel::postfx {
namespace {

/// Random colors, with a few exact greys (black, white) among them.
rasterizer::Image random_frame(int w, int h, unsigned seed) {
  rasterizer::Image image(w, h);
  std::mt19937 rng(seed);
  for (size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = uint8_t(rng() & 0xff);
  for (int x = 0; x < 8; ++x) {
    uint8_t* p = image.pixel(w / 2 + x, h / 2);
    p[0] = p[1] = p[2] = x < 4 ? 0 : 255;
  }
  return image;
}

TEST(LuminanceHistogram, RegionIsTheSdksFloatBorderTruncated) {
  // 0.5f * (1 - 0.9f) = 0.050000012 (0.9f is below 0.9), so 1280 keeps a border of 64;
  // 0.5f * (1 - 0.85f) = 0.074999988 (0.85f is above 0.85), so 720 keeps 53, not 54.
  const HistogramRegion r = histogram_region(1280, 720, 0.9f, 0.85f);
  EXPECT_EQ(r.x0, 64);
  EXPECT_EQ(r.x1, 1216);
  EXPECT_EQ(r.y0, 53);
  EXPECT_EQ(r.y1, 667);
  EXPECT_EQ(r.pixels(), 1152 * 614);
  const HistogramRegion s = histogram_region(100, 100, 0.9f, 0.85f);
  EXPECT_EQ(s.x0, 5);
  EXPECT_EQ(s.y0, 7);  // 7.4999988
  const HistogramRegion whole = histogram_region(31, 17, 1.0f, 1.0f);
  EXPECT_EQ(whole.pixels(), 31 * 17);
}

TEST(LuminanceHistogram, OneBucketPerFrameReadAfterTheLatency) {
  const rasterizer::Image frame = random_frame(40, 24, 7);
  rasterizer::Context ctx(1);
  rasterizer::DepthStencilTarget target(frame.width, frame.height);
  for (int latency : {1, 2, 3, 5}) {
    HistogramSettings s;
    s.query_latency = latency;
    LuminanceHistogram h(s);
    std::vector<int> valid_from(17, 0);
    for (int f = 1; f <= 40; ++f) {
      h.update(ctx, frame, target);
      if (f <= 17) {
        EXPECT_EQ(h.last_issued(), f - 1) << "frame " << f << ": unmeasured buckets first, in order";
      }
      for (int b = 0; b < 17; ++b) {
        if (h.buckets()[size_t(b)].valid() && valid_from[size_t(b)] == 0) valid_from[size_t(b)] = f;
      }
    }
    for (int b = 0; b < 17; ++b) {
      EXPECT_EQ(valid_from[size_t(b)], b + 1 + latency) << "bucket " << b << " issued at frame " << b + 1 << ", latency " << latency;
    }
  }
}

TEST(LuminanceHistogram, ReissuesTheOldestCountAndWaitsWhenNoneIsBack) {
  const rasterizer::Image frame = random_frame(16, 16, 9);
  rasterizer::Context ctx(1);
  rasterizer::DepthStencilTarget target(16, 16);
  HistogramSettings s;
  s.query_latency = 3;
  LuminanceHistogram h(s);
  for (int f = 1; f <= 17; ++f) h.update(ctx, frame, target);
  for (int f = 18; f <= 60; ++f) {
    h.update(ctx, frame, target);
    EXPECT_EQ(h.last_issued(), (f - 18) % 17) << "frame " << f << ": the oldest count is measured again";
  }
  // A latency longer than the bucket count leaves frames with nothing back to re-measure.
  s.query_latency = 20;
  LuminanceHistogram slow(s);
  for (int f = 1; f <= 17; ++f) slow.update(ctx, frame, target);
  for (int f = 18; f <= 20; ++f) {
    slow.update(ctx, frame, target);
    EXPECT_EQ(slow.last_issued(), -1) << "frame " << f << ": bucket 0 is not back before frame 21";
  }
  slow.update(ctx, frame, target);
  EXPECT_EQ(slow.last_issued(), 0);
}

TEST(LuminanceHistogram, CountsEqualTheExactHistogramOnceEveryBucketIsBack) {
  const int w = 72, h = 40;
  const rasterizer::Image frame = random_frame(w, h, 1234);
  for (ExposureAlgorithm algorithm : {ExposureAlgorithm::percentile, ExposureAlgorithm::mean}) {
    const HistogramRegion region = histogram_region(w, h, 0.9f, 0.85f);
    const std::vector<uint64_t> exact = exact_histogram(frame, region, algorithm);
    EXPECT_EQ(exact.back(), uint64_t(region.pixels())) << "the calibration bucket counts every pixel";
    for (HistogramCount count : {HistogramCount::direct_query, HistogramCount::stencil}) {
      for (auto reject : {shading::source::LuminanceReject::alpha_test, shading::source::LuminanceReject::texkill}) {
        for (int samples : {1, 4}) {
          for (int threads : {1, 2}) {
            HistogramSettings s;
            s.algorithm = algorithm;
            s.count = count;
            s.reject = reject;
            LuminanceHistogram histogram(s);
            rasterizer::Context ctx(threads);
            rasterizer::DepthStencilTarget target(w, h, samples);
            const int buckets = int(exact.size());
            for (int f = 0; f < buckets + s.query_latency; ++f) histogram.update(ctx, frame, target);
            for (int b = 0; b < buckets; ++b) {
              const BucketCount& c = histogram.buckets()[size_t(b)];
              ASSERT_TRUE(c.valid()) << b;
              EXPECT_EQ(c.in_range, exact[size_t(b)] * uint64_t(samples))
                  << "bucket " << b << " [" << c.range.min << ", " << c.range.max << "] count " << int(count) << " reject "
                  << int(reject) << " samples " << samples << " threads " << threads;
            }
            EXPECT_EQ(histogram.viewport_pixels(), uint64_t(w * h));
          }
        }
      }
    }
  }
}

TEST(LuminanceHistogram, CountsTheSameFromTheFramesSharedCopy) {
  // The renderer copies the frame once (full_frame.hpp) for every post pass: the histogram reads
  // that RGBA8 copy with sRGB read on, and counts what it counts from the image.
  const int w = 48, h = 30;
  rasterizer::Context ctx(2);
  rasterizer::DepthStencilTarget target(w, h, 4);
  LuminanceHistogram from_image({}), from_copy({});
  FullFrameTexture copy;
  for (int f = 0; f < 24; ++f) {
    const rasterizer::Image frame = random_frame(w, h, 100 + unsigned(f) / 6);  // the frame changes now and then
    copy.update(frame);
    from_image.update(ctx, frame, target);
    from_copy.update(ctx, copy.texture(), target);
    ASSERT_EQ(from_copy.last_issued(), from_image.last_issued());
    for (size_t b = 0; b < from_image.buckets().size(); ++b) {
      EXPECT_EQ(from_copy.buckets()[b].in_range, from_image.buckets()[b].in_range) << "frame " << f << " bucket " << b;
      EXPECT_EQ(from_copy.buckets()[b].valid(), from_image.buckets()[b].valid());
    }
  }
  EXPECT_GT(from_copy.buckets()[3].in_range, 0u) << "test setup: a bucket with pixels in it";
  // A copy of another size than the target, or with mips, is refused.
  rasterizer::DepthStencilTarget other(w + 1, h);
  EXPECT_THROW(from_copy.update(ctx, copy.texture(), other), std::invalid_argument);
  const rasterizer::Texture mipped = rasterizer::Texture::create_2d(w, h, rasterizer::TextureFormat::RGBA8);
  EXPECT_THROW(from_copy.update(ctx, mipped, target), std::invalid_argument);
  EXPECT_THROW(FullFrameTexture().texture(), std::logic_error);
  rasterizer::Image bad(4, 4);
  bad.rgba.pop_back();
  EXPECT_THROW(copy.update(bad), std::invalid_argument);
}

TEST(LuminanceHistogram, WhiteIsInTheTopPercentileBucketAndInNoMeanBucket) {
  rasterizer::Image white(20, 20);
  std::fill(white.rgba.begin(), white.rgba.end(), uint8_t(255));
  const HistogramRegion all{0, 0, 20, 20};
  const std::vector<uint64_t> p = exact_histogram(white, all, ExposureAlgorithm::percentile);
  EXPECT_EQ(p[15], 400u);
  EXPECT_EQ(p[14], 0u);
  const std::vector<uint64_t> m = exact_histogram(white, all, ExposureAlgorithm::mean);
  for (int b = 0; b < 30; ++b) EXPECT_EQ(m[size_t(b)], 0u) << b;
  EXPECT_EQ(m[30], 400u);
}

TEST(LuminanceHistogram, RefusesBadSettingsAndATargetOfAnotherSize) {
  rasterizer::Context ctx(1);
  rasterizer::DepthStencilTarget target(8, 8);
  LuminanceHistogram h({});
  EXPECT_THROW(h.update(ctx, random_frame(8, 9, 1), target), std::invalid_argument);
  HistogramSettings s;
  s.query_latency = 0;
  EXPECT_THROW(LuminanceHistogram{s}, std::invalid_argument);
  s = {};
  s.center_region_x = 0.0f;
  EXPECT_THROW(LuminanceHistogram{s}, std::invalid_argument);
  s = {};
  s.center_region_y = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(LuminanceHistogram{s}, std::invalid_argument);
}

}  // namespace
}  // namespace luxel::postfx
