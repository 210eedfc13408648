#pragma once
// The luminance histogram of Source's auto exposure, counted as the engine counts it
// (docs/fidelity.md#auto-exposure; viewpostprocess.cpp, CLuminanceHistogramSystem):
//
//  - What is measured: the finished frame, tone-mapped, fogged, 8-bit, before bloom (the copy
//    to _rt_FullFrameFB), read with sRGB decode: luminance is linear.
//  - Where: the viewport minus a border of 0.5 x (1 - region) of its size on each side,
//    mat_exposure_center_region_x 0.9 and _y 0.85, computed in float and truncated to whole
//    pixels as the SDK does (so 1280x720 keeps x 64..1215 and y 53..666).
//  - How: one bucket's range test per frame (shading/source/luminance_range.hpp) drawn over that
//    rectangle inside an occlusion query; directly, or (mat_tonemapping_occlusion_use_stencil 1)
//    marking the stencil first and counting where it is set. The query counts samples; the
//    calibration bucket tells how many per pixel. The engine draws into its multisampled back
//    buffer; luxel draws into a one-sample target of its own and counts each passing pixel as
//    the frame's samples per pixel. That is the same count: the rectangle is whole pixels, and
//    the test passes or fails a pixel as a whole (its shader runs once per pixel, and every
//    sample of a pixel sees the same stencil), for a quarter of the coverage and stencil work at
//    4x MSAA.
//  - When: each update, buckets never measured are issued first, in order, one per frame;
//    a query is read back once it is `query_latency` frames old (the engine's 3: "current frame
//    > queued frame + 2"); then, if nothing was issued, the bucket whose last count is oldest is
//    measured again. A bucket's count is its latest; it is valid from its first result on,
//    also while it is being measured again.
//
// luxel's queries are exact and finished when read; the latency is kept by holding each count
// until its frame comes. exact_histogram() counts the same region of the same image directly,
// without queries or latency: the reference the occlusion histogram converges to.

#include "luxel/postfx/full_frame.hpp"
#include "luxel/postfx/histogram_buckets.hpp"
#include "luxel/postfx/shader_tally.hpp"
#include "luxel/rasterizer/context.hpp"
#include "luxel/rasterizer/framebuffer.hpp"
#include "luxel/rasterizer/image.hpp"
#include "luxel/rasterizer/texture.hpp"
#include "luxel/shading/source/luminance_range.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace luxel::postfx {

/// How the in-range samples are counted.
enum class HistogramCount {
  direct_query,  ///< the range test inside the query (mat_tonemapping_occlusion_use_stencil 0, the default)
  stencil,       ///< the range test marks the stencil, a second draw counts stencil == 1 inside the query
};

struct HistogramSettings {
  ExposureAlgorithm algorithm = ExposureAlgorithm::percentile;
  HistogramCount count = HistogramCount::direct_query;
  shading::source::LuminanceReject reject = shading::source::LuminanceReject::alpha_test;
  int query_latency = 3;         ///< frames before a query's count is read, >= 1
  float center_region_x = 0.9f;  ///< mat_exposure_center_region_x
  float center_region_y = 0.85f; ///< mat_exposure_center_region_y
};

/// The measured rectangle, whole pixels [x0, x1) x [y0, y1).
struct HistogramRegion {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int64_t pixels() const { return int64_t(x1 - x0) * (y1 - y0); }
};

/// The region of a width x height viewport (the SDK's float arithmetic, above).
HistogramRegion histogram_region(int width, int height, float center_region_x, float center_region_y);

/// One bucket as the engine keeps it.
struct BucketCount {
  enum class State { initial, first_query_in_flight, query_in_flight, done };
  HistogramBucket range;
  State state = State::initial;
  uint64_t in_range = 0;      ///< the latest count read back, in samples
  int64_t frame_queued = 0;   ///< the update that last issued its query
  /// ContainsValidData: a count has been read (and may be being measured again).
  bool valid() const { return state == State::done || state == State::query_in_flight; }
};

class LuminanceHistogram {
 public:
  /// Throws std::invalid_argument for a latency below 1 or a region outside (0, 1].
  explicit LuminanceHistogram(const HistogramSettings& settings);

  /// One frame's update (above) on `frame`: the frame's copy (full_frame.hpp), its finished 8-bit
  /// image, sRGB-encoded, which the range test reads with sRGB read on. `target` is the frame's
  /// depth-stencil target, the size of the frame: the engine's range test draws into it, and the
  /// counts are in its samples. luxel draws into a one-sample target of its own (above) and
  /// leaves `target` untouched. The range test's shader goes to `tally` (its counting draw, the
  /// stencil's dev/no_pixel_write, is no shader of the catalog).
  void update(rasterizer::Context& ctx, const rasterizer::Texture& frame, const rasterizer::DepthStencilTarget& target,
              const ShaderTally& tally = {});
  /// The same on the frame's image, copied in first.
  void update(rasterizer::Context& ctx, const rasterizer::Image& frame, const rasterizer::DepthStencilTarget& target,
              const ShaderTally& tally = {});

  const HistogramSettings& settings() const { return settings_; }
  /// The buckets, the calibration bucket last.
  std::span<const BucketCount> buckets() const { return buckets_; }
  /// Updates so far.
  int64_t frame() const { return frame_; }
  /// The bucket issued by the last update, or -1.
  int last_issued() const { return last_issued_; }
  /// m_npixels: the pixels of the whole viewport (not the region), which the mean algorithm's
  /// calibration compares with.
  uint64_t viewport_pixels() const { return viewport_pixels_; }

 private:
  void issue(rasterizer::Context& ctx, const rasterizer::Texture& frame, int samples, int bucket, const ShaderTally& tally);

  HistogramSettings settings_;
  std::vector<BucketCount> buckets_;
  std::vector<std::optional<uint64_t>> pending_;  ///< per bucket: the count its query will report
  int64_t frame_ = 0;
  int last_issued_ = -1;
  uint64_t viewport_pixels_ = 0;
  FullFrameTexture copy_;  ///< update(Image)'s copy of the frame
  /// What the range test draws into: one sample per pixel, the frame's size; cleared whole before
  /// each count and discarded after, so it lives in tile memory (rasterizer/framebuffer.hpp).
  std::optional<rasterizer::DepthStencilTarget> pixel_target_;
};

/// Per bucket of `algorithm`, the pixels of `region` whose luminance (in double from the sRGB
/// codes, with the histogram's weights) passes its range test: the calibration bucket counts
/// every pixel. In pixels, not samples.
std::vector<uint64_t> exact_histogram(const rasterizer::Image& frame, const HistogramRegion& region,
                                      ExposureAlgorithm algorithm);

}  // namespace luxel::postfx
