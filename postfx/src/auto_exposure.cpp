#include "luxel/postfx/auto_exposure.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace luxel::postfx {
namespace {

void check(float value, const char* what) {
  if (!(std::isfinite(value) && value >= 0.0f))
    throw std::invalid_argument(std::string("auto exposure: ") + what + " " + std::to_string(value) + " is not a finite number >= 0");
}

/// The 16 (or 30) luminance buckets, without the calibration bucket.
std::span<const BucketCount> luminance_buckets(std::span<const BucketCount> buckets) {
  return buckets.first(buckets.size() - 1);
}

}  // namespace

float percent_bright_location(std::span<const BucketCount> all, ExposureAlgorithm algorithm, float percent, float snap_percent) {
  if (algorithm != ExposureAlgorithm::percentile) return -1.0f;
  const std::span<const BucketCount> buckets = luminance_buckets(all);
  int total = 0;  // the SDK counts in int
  for (const BucketCount& b : buckets) {
    if (b.valid()) total += int(b.in_range);
  }
  if (total == 0) return -1.0f;
  float range_tested = 0.0f, pixels_tested = 0.0f;
  for (size_t k = buckets.size(); k-- > 0;) {  // from the bright end
    const BucketCount& b = buckets[k];
    if (!b.valid()) return -1.0f;
    const float needed = percent / 100.0f - pixels_tested;
    const float share = float(b.in_range) / float(total);
    const float width = b.range.max - b.range.min;
    if (share >= needed) {
      if (snap_percent >= 0.0f && b.range.min <= snap_percent / 100.0f && b.range.max >= snap_percent / 100.0f)
        return snap_percent / 100.0f;
      const float border = 1.0f - (range_tested + width * (needed / share));
      return std::max(b.range.min, std::min(b.range.max, border));
    }
    pixels_tested += share;
    range_tested += width;
  }
  return -1.0f;
}

float target_scale(std::span<const BucketCount> buckets, const AutoExposureSettings& s, float current_scale, uint64_t viewport_pixels) {
  if (s.histogram.algorithm == ExposureAlgorithm::percentile) {
    float location = percent_bright_location(buckets, s.histogram.algorithm, s.percent_bright, s.percent_target);
    if (location < 0.0f) location = s.percent_target / 100.0f;  // no answer: pretend we are at the target
    location = std::max(0.0001f, location);
    float target = (s.percent_target / 100.0f) / location;
    const float median = percent_bright_location(buckets, s.histogram.algorithm, 50.0f);
    if (median > 0.0f) target = std::max(target, (s.min_average_luminance / 100.0f) / median);  // only ever brightens
    return std::max(0.001f, target * current_scale);
  }
  // The original algorithm: the calibration bucket scales counts to the viewport's pixels.
  const BucketCount& calibration = buckets.back();
  float scale_value = 1.0f;
  if (calibration.valid()) scale_value = float(viewport_pixels) * (1.0f / float(calibration.in_range));
  if (!std::isfinite(scale_value)) scale_value = 1.0f;
  float total = 0.0f;
  int total_pixels = 0;
  for (const BucketCount& b : luminance_buckets(buckets)) {
    if (!b.valid()) continue;
    total += scale_value * float(b.in_range) * (0.5f * (b.range.min + b.range.max));
    total_pixels += int(viewport_pixels);
  }
  float average = total_pixels > 0 ? float(double(total) * (1.0 / total_pixels)) : 0.5f;
  average = std::max(0.0001f, average);
  return float(0.005 / average);
}

float exact_target(const rasterizer::Image& frame, const AutoExposureSettings& settings, float drawn_scale) {
  const HistogramSettings& h = settings.histogram;
  const std::vector<uint64_t> counts =
      exact_histogram(frame, histogram_region(frame.width, frame.height, h.center_region_x, h.center_region_y), h.algorithm);
  const std::span<const HistogramBucket> ranges = histogram_buckets(h.algorithm);
  std::vector<BucketCount> buckets(ranges.size());
  for (size_t i = 0; i < buckets.size(); ++i) buckets[i] = {ranges[i], BucketCount::State::done, counts[i], 0};
  return target_scale(buckets, settings, drawn_scale, uint64_t(frame.width) * uint64_t(frame.height));
}

ToneMapScale::ToneMapScale(const AutoExposureSettings& s) {
  set_controls(s);
  if (!(std::isfinite(s.initial_scale) && s.initial_scale > 0.0f))
    throw std::invalid_argument("auto exposure: initial scale " + std::to_string(s.initial_scale) + " is not positive and finite");
  current_ = goal_ = s.initial_scale;
}

void ToneMapScale::set_controls(const AutoExposureSettings& s) {
  check(s.min_scale, "min scale");
  check(s.max_scale, "max scale");
  check(s.rate, "rate");
  check(s.accelerate_down, "accelerate-down factor");
  check(s.percent_target, "percent target");
  check(s.percent_bright, "percent of bright pixels");
  check(s.min_average_luminance, "minimum average luminance");
  settings_ = s;
  settings_.max_scale = std::max(s.min_scale, s.max_scale);  // GetExposureRange: min <= max
}

void ToneMapScale::push(float target, float dt) {
  if (!std::isfinite(target)) return;  // the SDK ignores a non-finite target
  target = std::max(0.001f, std::clamp(target, settings_.min_scale, settings_.max_scale));
  if (in_history_ < int(history_.size())) {
    history_[size_t(in_history_++)] = target;
  } else {
    std::copy(history_.begin() + 1, history_.end(), history_.begin());
    history_.back() = target;
  }
  goal_ = target;
  if (in_history_ == int(history_.size())) {
    float average = 0.0f, weights = 0.0f;
    const int middle = int(history_.size()) / 2;
    for (int i = 0; i < int(history_.size()); ++i) {
      const float w = float(std::abs(i - middle)) * (1.0f / float(history_.size() / 2));
      weights += w;
      average += w * history_[size_t(i)];
    }
    average *= 1.0f / weights;
    goal_ = std::clamp(average, settings_.min_scale, settings_.max_scale);
  }

  const bool percentile = settings_.histogram.algorithm == ExposureAlgorithm::percentile;
  float rate = settings_.rate * (percentile ? 2.0f : 1.0f);
  if (rate == 0.0f) {
    current_ = goal_;
    return;
  }
  if (goal_ < current_) {
    const float fast = settings_.accelerate_down * rate;
    rate = std::min(fast, rate + (fast - rate) * (current_ - goal_) / 1.5f);
  }
  float rate_times_time = rate * std::max(dt, 0.0f);
  if (percentile) rate_times_time = std::min(rate_times_time, (1.0f / 16.0f) * 0.25f);
  const float alpha = std::clamp(rate_times_time, 0.0f, 1.0f);
  current_ = goal_ * alpha + current_ * (1.0f - alpha);
  if (!std::isfinite(current_)) current_ = goal_;
}

AutoExposure::AutoExposure(const AutoExposureSettings& settings)
    : settings_(settings), histogram_(settings.histogram), scale_(settings) {}

void AutoExposure::set_controls(const AutoExposureSettings& controls) {
  AutoExposureSettings s = controls;
  s.histogram = settings_.histogram;
  s.initial_scale = settings_.initial_scale;
  scale_.set_controls(s);
  settings_ = s;
}

void AutoExposure::measure(rasterizer::Context& ctx, const rasterizer::Texture& frame, const rasterizer::DepthStencilTarget& target,
                           float dt, const ShaderTally& tally) {
  histogram_.update(ctx, frame, target, tally);
  move_scale(dt);
}

void AutoExposure::measure(rasterizer::Context& ctx, const rasterizer::Image& frame, const rasterizer::DepthStencilTarget& target,
                           float dt, const ShaderTally& tally) {
  histogram_.update(ctx, frame, target, tally);
  move_scale(dt);
}

void AutoExposure::move_scale(float dt) {
  last_target_ = target_scale(histogram_.buckets(), settings_, scale_.current(), histogram_.viewport_pixels());
  scale_.push(last_target_, dt);
}

}  // namespace luxel::postfx
