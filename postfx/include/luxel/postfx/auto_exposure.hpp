#pragma once
// Source's auto exposure (docs/fidelity.md#auto-exposure): the tone-map scale each frame is drawn with,
// measured from the frames before it.
//
// After each frame (viewpostprocess.cpp, DoEnginePostProcessing):
//  1. the histogram's update on the finished frame (luminance_histogram.hpp);
//  2. the target scale from the buckets counted so far:
//     - percentile (mat_tonemap_algorithm 1): where the brightest `percent_bright` % of the
//       region's pixels begin, walking down from the top bucket and interpolating inside the
//       bucket that completes them; a bucket holding the `percent_target` luminance (0.60) keeps
//       the scale (the "sticky bin"); no answer (no count yet, or an unmeasured bucket on the way)
//       counts as being at the target. target = 0.60 / location, raised to 0.03 / median when
//       that is larger (dark frames), then x the scale the measured frame was drawn with;
//     - mean (mat_tonemap_algorithm 0): 0.005 / (the sum over valid buckets of their share of the
//       region x their center, divided by the number of valid buckets), not x the current scale;
//  3. clamped to [min_scale, max_scale] and >= 0.001, pushed into a 10-frame history; once the
//     history is full, the goal is its average weighted |i - 5| / 5 from the oldest (1.0, 0.8,
//     ... 0.0 at the sixth, ... 0.8), clamped again; until then the goal is the new target;
//  4. the current scale moves towards the goal for the frame's duration dt:
//       alpha = clamp(rate x dt, 0, 1), current = goal x alpha + current x (1 - alpha),
//     rate = `rate` (mat_hdr_manual_tonemap_rate), x 2 for the percentile algorithm; going down
//     it rises towards `accelerate_down` x rate as the gap grows to 1.5 (min(3r, lerp(r, 3r,
//     gap / 1.5))); for the percentile algorithm rate x dt is capped at 1/64 per frame so that the
//     scale does not ride the histogram as it is rebuilt. rate 0 jumps to the goal.
// The HL2-era chase is in closed materialsystem code. Step 4 is the chase Valve published
// with the same two knobs in a later branch's client (Alien Swarm SDK, 2010: viewpostprocess.cpp,
// CTonemapSystem::SetTonemapScale); luxel takes it as the documented choice. Like the engine's,
// it depends on the frame rate (alpha is linear in dt, and the cap is per frame).

#include "luxel/postfx/luminance_histogram.hpp"

#include <array>
#include <span>

namespace luxel::postfx {

struct AutoExposureSettings {
  HistogramSettings histogram;
  float min_scale = 0.5f;              ///< mat_autoexposure_min, or the map's env_tonemap_controller
  float max_scale = 2.0f;              ///< mat_autoexposure_max (raised to min_scale when below it)
  float rate = 1.0f;                   ///< mat_hdr_manual_tonemap_rate, per second; 0: no chase
  float accelerate_down = 3.0f;        ///< mat_accelerate_adjust_exposure_down
  float percent_target = 60.0f;        ///< mat_tonemap_percent_target
  float percent_bright = 2.0f;         ///< mat_tonemap_percent_bright_pixels
  float min_average_luminance = 3.0f;  ///< mat_tonemap_min_avglum, percent
  float initial_scale = 1.0f;          ///< the scale of the first frame (ResetToneMapping's 1.0)
};

/// FindLocationOfPercentBrightPixels: the luminance above which `percent` % of the counted pixels
/// lie, or -1 for no answer; with `snap_percent` >= 0, that value / 100 when it falls in the same
/// bucket (the sticky bin). Percentile algorithm only (the mean algorithm has no answer: -1).
float percent_bright_location(std::span<const BucketCount> buckets, ExposureAlgorithm algorithm, float percent,
                              float snap_percent = -1.0f);

/// GetTargetTonemapScalar (step 2), before clamping. `current_scale` is the scale the measured
/// frames were drawn with; `viewport_pixels` is LuminanceHistogram::viewport_pixels().
float target_scale(std::span<const BucketCount> buckets, const AutoExposureSettings& settings, float current_scale,
                   uint64_t viewport_pixels);

/// The target the exact histogram of `frame` gives (exact_histogram over the region, every bucket
/// counted and current), for a frame drawn at `drawn_scale`: what step 2 would say without
/// occlusion queries, their latency and one bucket per frame. For tests and reports.
float exact_target(const rasterizer::Image& frame, const AutoExposureSettings& settings, float drawn_scale);

/// Steps 3 and 4: the history, the goal and the current scale.
class ToneMapScale {
 public:
  /// Throws std::invalid_argument for scales, rates or percentages that are negative or not finite.
  explicit ToneMapScale(const AutoExposureSettings& settings);
  /// The scale the next frame is drawn with.
  float current() const { return current_; }
  float goal() const { return goal_; }
  /// A new target (step 3, clamped here), then the chase over `dt` seconds (step 4).
  void push(float target, float dt);
  /// New controls (range, rate, acceleration) from the next push on; the history, goal and
  /// current scale carry on. Checked as the constructor checks them.
  void set_controls(const AutoExposureSettings& settings);

 private:
  AutoExposureSettings settings_;
  float current_ = 1.0f, goal_ = 1.0f;
  std::array<float, 10> history_{};
  int in_history_ = 0;
};

/// Steps 1 to 4 carried from frame to frame.
class AutoExposure {
 public:
  explicit AutoExposure(const AutoExposureSettings& settings);
  /// The tone-map scale the next frame is drawn with.
  float scale() const { return scale_.current(); }
  float goal() const { return scale_.goal(); }
  /// The unclamped target of the last measure(), or 0 before it.
  float last_target() const { return last_target_; }
  /// New designer controls (everything but the histogram's settings and the initial scale) from
  /// the next measure() on, as an env_tonemap_controller input changes them in Source: the
  /// histogram, the history and the scale carry on.
  void set_controls(const AutoExposureSettings& controls);
  /// After a frame drawn at scale(): measures it (LuminanceHistogram::update on the frame's copy,
  /// counting in the samples of the frame's depth-stencil `target`, its range test's shader to
  /// `tally`) and moves the scale for the frame's duration `dt` (seconds, >= 0).
  void measure(rasterizer::Context& ctx, const rasterizer::Texture& frame, const rasterizer::DepthStencilTarget& target,
               float dt, const ShaderTally& tally = {});
  /// The same on the frame's image (LuminanceHistogram::update copies it in).
  void measure(rasterizer::Context& ctx, const rasterizer::Image& frame, const rasterizer::DepthStencilTarget& target, float dt,
               const ShaderTally& tally = {});
  const LuminanceHistogram& histogram() const { return histogram_; }
  const AutoExposureSettings& settings() const { return settings_; }

 private:
  /// The target of the histogram as it now stands, and the scale moved toward it over `dt`.
  void move_scale(float dt);

  AutoExposureSettings settings_;
  LuminanceHistogram histogram_;
  ToneMapScale scale_;
  float last_target_ = 0.0f;
};

}  // namespace luxel::postfx
