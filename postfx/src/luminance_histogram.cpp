#include "luxel/postfx/luminance_histogram.hpp"

#include "counted_draw.hpp"
#include "screen_rectangle.hpp"

#include "luxel/rasterizer/draw_definition.hpp"
#include "luxel/rasterizer/srgb.hpp"

#include <array>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>

namespace luxel::postfx {
namespace {

using shading::source::LuminancePass;
using shading::source::LuminanceRangeCombo;
using shading::source::LuminanceRangeParams;
using shading::source::LuminanceReject;

/// dev/no_pixel_write: the stencil method's counting draw; the stencil alone decides.
struct NoPixelWrite {
  static constexpr bool kCanDiscard = false, kWritesDepth = false;
  void operator()(const rasterizer::PixelInput<1>&, rasterizer::PixelOutput& out) const {
    const rasterizer::simd::Float zero(0.0f);
    out.color = {zero, zero, zero, zero};
  }
};

/// DrawScreenSpaceRectangle over the region: the viewport is the region, each pixel reads its own
/// texel of the frame.
struct RegionDraw {
  rasterizer::Viewport viewport;
  ScreenRectangle<1> rectangle;
  RegionDraw(int width, int height, const HistogramRegion& r)
      : viewport{float(r.x0), float(r.y0), float(r.x1 - r.x0), float(r.y1 - r.y0)},
        rectangle(screen_rectangle(r.x1 - r.x0, r.y1 - r.y0, TexelRect{float(r.x0), float(r.y0), float(r.x1 - 1), float(r.y1 - 1), width, height})) {}

  template <class PixelShader>
  void draw(rasterizer::Context& ctx, rasterizer::DepthStencilTarget& target, rasterizer::PipelineState state,
            const PixelShader& ps) const {
    state.viewport = viewport;
    rasterizer::draw(ctx, rasterizer::Framebuffer{nullptr, &target}, state, rasterizer::Geometry::non_indexed(6), rectangle, ps);
  }
};

/// The samples of `target` in the region that fall in one bucket's range, counted the way
/// `count` says with the range test's combo C: the test inside the query, or the test marking the
/// stencil and a counting draw inside the query.
template <LuminanceRangeCombo C>
uint64_t count_in_range(rasterizer::Context& ctx, rasterizer::DepthStencilTarget& target, HistogramCount count,
                        const RegionDraw& region, const LuminanceRangeParams& params, const ShaderTally& tally) {
  using shading::source::luminance_range_pipeline_state;
  using Test = shading::source::LuminanceRangePixelShader<C>;
  uint64_t in_range = 0;
  counted_draw<Test>(tally, C.name(), shading::source::measure_luminance_range<C>, [&](std::atomic<uint64_t>* pixels) {
    rasterizer::OcclusionQuery query;
    // The target's samples are not needed after the count, so they live in tile memory
    // (rasterizer/framebuffer.hpp). The engine clears the stencil at the start of each frame,
    // which the stencil method's counting draw reads; the direct query's draw tests neither depth
    // nor stencil, so its target's samples are left undefined rather than filled.
    if (count == HistogramCount::direct_query) {
      rasterizer::invalidate(ctx, target);
      ctx.begin_query(query);
      region.draw(ctx, target, luminance_range_pipeline_state(C.reject, LuminancePass::query), Test{&params, pixels});
      ctx.end_query();
    } else {
      rasterizer::clear_depth_stencil(ctx, target, 1.0f, 0);
      region.draw(ctx, target, luminance_range_pipeline_state(C.reject, LuminancePass::stencil_mark), Test{&params, pixels});
      ctx.begin_query(query);
      region.draw(ctx, target, luminance_range_pipeline_state(C.reject, LuminancePass::stencil_count), NoPixelWrite{});
      ctx.end_query();
    }
    rasterizer::discard(ctx, target);
    in_range = ctx.query_result(query);  // flushes: `params` and `pixels` outlive the draws
  });
  return in_range;
}

/// The sRGB curve in double for each 8-bit code: the exact histogram decodes three codes per pixel,
/// and a pow per code made it the slowest part of settling a still's exposure.
const std::array<double, 256>& srgb_decoded() {
  static const std::array<double, 256> table = [] {
    std::array<double, 256> t{};
    for (int code = 0; code < 256; ++code) t[size_t(code)] = rasterizer::srgb_to_linear(code / 255.0);
    return t;
  }();
  return table;
}

}  // namespace

HistogramRegion histogram_region(int width, int height, float center_region_x, float center_region_y) {
  // viewpostprocess.cpp: skip = int((1 + max - min) * 0.5f * (1 - region)), all in float.
  const int skip_x = int(float(width) * (0.5f * (1.0f - center_region_x)));
  const int skip_y = int(float(height) * (0.5f * (1.0f - center_region_y)));
  return HistogramRegion{skip_x, skip_y, width - skip_x, height - skip_y};
}

LuminanceHistogram::LuminanceHistogram(const HistogramSettings& settings) : settings_(settings) {
  if (settings.query_latency < 1)
    throw std::invalid_argument("histogram query latency " + std::to_string(settings.query_latency) + " is not at least 1 frame");
  for (float r : {settings.center_region_x, settings.center_region_y}) {
    if (!(r > 0.0f && r <= 1.0f)) throw std::invalid_argument("exposure center region " + std::to_string(r) + " is not in (0, 1]");
  }
  for (const HistogramBucket& b : histogram_buckets(settings.algorithm)) buckets_.push_back(BucketCount{b});
  pending_.resize(buckets_.size());
}

void LuminanceHistogram::update(rasterizer::Context& ctx, const rasterizer::Image& frame, const rasterizer::DepthStencilTarget& target,
                                const ShaderTally& tally) {
  copy_.update(frame);
  update(ctx, copy_.texture(), target, tally);
}

void LuminanceHistogram::update(rasterizer::Context& ctx, const rasterizer::Texture& frame,
                                const rasterizer::DepthStencilTarget& target, const ShaderTally& tally) {
  check_frame_copy(frame, "histogram");
  if (target.width() != frame.width() || target.height() != frame.height())
    throw std::invalid_argument("histogram: a " + std::to_string(target.width()) + "x" + std::to_string(target.height()) +
                                " target for a " + std::to_string(frame.width()) + "x" + std::to_string(frame.height()) +
                                " frame");
  ++frame_;
  last_issued_ = -1;
  bool issued = false;
  for (size_t i = 0; i < buckets_.size(); ++i) {
    BucketCount& b = buckets_[i];
    if (b.state == BucketCount::State::initial) {
      if (!issued) {
        issue(ctx, frame, target.samples(), int(i), tally);
        issued = true;
      }
    } else if (b.state != BucketCount::State::done && frame_ >= b.frame_queued + settings_.query_latency) {
      b.in_range = *pending_[i];
      pending_[i].reset();
      b.state = BucketCount::State::done;
    }
  }
  if (issued) return;
  int oldest = -1;
  for (size_t i = 0; i < buckets_.size(); ++i) {
    if (buckets_[i].state == BucketCount::State::done && (oldest < 0 || buckets_[i].frame_queued < buckets_[size_t(oldest)].frame_queued))
      oldest = int(i);
  }
  if (oldest >= 0) issue(ctx, frame, target.samples(), oldest, tally);
}

void LuminanceHistogram::issue(rasterizer::Context& ctx, const rasterizer::Texture& frame, int samples, int bucket,
                               const ShaderTally& tally) {
  const int w = frame.width(), h = frame.height();
  viewport_pixels_ = uint64_t(w) * uint64_t(h);
  if (!pixel_target_ || pixel_target_->width() != w || pixel_target_->height() != h) pixel_target_.emplace(w, h);

  BucketCount& b = buckets_[size_t(bucket)];
  LuminanceRangeParams params;
  params.frame.texture = &frame;
  params.frame.state.srgb_read = true;  // dev/lumcompare's screenspace_general default
  params.frame.state.min = params.frame.state.mag = rasterizer::Filter::Point;
  params.frame.state.mip = rasterizer::MipFilter::None;
  params.frame.state.u = params.frame.state.v = rasterizer::Address::Clamp;
  params.min_max_scale = shading::source::luminance_range_constant(b.range.min, b.range.max);
  const RegionDraw region(w, h, histogram_region(w, h, settings_.center_region_x, settings_.center_region_y));

  const uint64_t pixels =
      settings_.reject == LuminanceReject::alpha_test
          ? count_in_range<LuminanceRangeCombo{LuminanceReject::alpha_test}>(ctx, *pixel_target_, settings_.count, region, params, tally)
          : count_in_range<LuminanceRangeCombo{LuminanceReject::texkill}>(ctx, *pixel_target_, settings_.count, region, params, tally);
  pending_[size_t(bucket)] = pixels * uint64_t(samples);
  b.state = b.state == BucketCount::State::initial ? BucketCount::State::first_query_in_flight : BucketCount::State::query_in_flight;
  b.frame_queued = frame_;
  last_issued_ = bucket;
}

std::vector<uint64_t> exact_histogram(const rasterizer::Image& frame, const HistogramRegion& region, ExposureAlgorithm algorithm) {
  const std::span<const HistogramBucket> buckets = histogram_buckets(algorithm);
  std::vector<uint64_t> counts(buckets.size(), 0);
  const std::array<double, 256>& decoded = srgb_decoded();
  for (int y = region.y0; y < region.y1; ++y) {
    for (int x = region.x0; x < region.x1; ++x) {
      const uint8_t* p = frame.pixel(x, y);
      const double luminance = 0.2125 * decoded[p[0]] + 0.7154 * decoded[p[1]] + 0.0721 * decoded[p[2]];
      for (size_t b = 0; b < buckets.size(); ++b) {
        counts[b] += luminance >= double(buckets[b].min) && luminance <= double(range_test_max(buckets[b]));
      }
    }
  }
  return counts;
}

}  // namespace luxel::postfx
