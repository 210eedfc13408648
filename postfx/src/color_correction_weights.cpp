// Color-correction entity weights (color_correction_weights.hpp, docs/fidelity.md#color-correction).

#include "luxel/postfx/color_correction_weights.hpp"

#include "luxel/postfx/color_correction.hpp"

#include <algorithm>
#include <numeric>

namespace luxel::postfx {

EntityFade::EntityFade(const Settings& settings)
    : settings_(settings), start_weight_(settings.start_disabled ? 0.0f : 1.0f) {}

void EntityFade::enable(double time) {
  start_weight_ = weight(time);
  start_time_ = time;
  phase_ = settings_.fade_in > 0.0f ? Phase::fading_in : Phase::steady;
  if (phase_ == Phase::steady) start_weight_ = settings_.max_weight;
}

void EntityFade::disable(double time) {
  start_weight_ = weight(time);
  start_time_ = time;
  phase_ = settings_.fade_out > 0.0f ? Phase::fading_out : Phase::steady;
  if (phase_ == Phase::steady) start_weight_ = 0.0f;
}

float EntityFade::weight(double time) const {
  const float max = settings_.max_weight;
  const float start = std::clamp(start_weight_, 0.0f, 1.0f);
  const float elapsed = static_cast<float>(time - start_time_);
  if (phase_ == Phase::fading_in) {
    if (max == 0.0f || start_weight_ >= max) return start_weight_;  // nothing to fade
    const float duration =
        start_weight_ > 0.0f ? settings_.fade_in * (1.0f - std::clamp(start_weight_ / max, 0.0f, 0.99f)) : settings_.fade_in;
    const float t = std::clamp(elapsed / duration, 0.0f, 1.0f);
    return start + (max - start) * t;
  }
  if (phase_ == Phase::fading_out) {
    if (max == 0.0f || start_weight_ <= 0.0f) return start_weight_;
    const float duration = start_weight_ < max ? settings_.fade_out * std::clamp(start_weight_ / max, 0.01f, 1.0f)
                                               : settings_.fade_out;
    const float t = std::clamp(elapsed / duration, 0.0f, 1.0f);
    return (1.0f - t) * start;
  }
  return start_weight_;
}

float falloff_weight(float current_weight, float min_falloff, float max_falloff, float distance) {
  if (min_falloff == -1.0f || max_falloff == -1.0f || min_falloff == max_falloff) return current_weight;
  const float t = std::clamp((distance - min_falloff) / (max_falloff - min_falloff), 0.0f, 1.0f);
  return current_weight * (1.0f - t);
}

void VolumeFade::enter(double time) {
  last_weight_ = weight(time);
  last_time_ = time;
  inside_ = true;
}

void VolumeFade::leave(double time) {
  last_weight_ = weight(time);
  last_time_ = time;
  inside_ = false;
}

float VolumeFade::weight(double time) const {
  if (!(fade_ > 0.0f)) return inside_ ? 1.0f : 0.0f;  // no ramp
  const float elapsed = static_cast<float>(time - last_time_);
  if (inside_) {
    if (last_weight_ >= 1.0f) return 1.0f;
    return std::min(1.0f, last_weight_ + elapsed / ((1.0f - last_weight_) * fade_));
  }
  if (last_weight_ <= 0.0f) return 0.0f;
  return 1.0f - std::min(1.0f, (1.0f - last_weight_) + elapsed / (last_weight_ * fade_));
}

std::vector<int> heaviest_lookups(std::span<const float> weights) {
  std::vector<float> key(weights.size());  // NaN and negatives as 0: a strict weak order to sort by
  for (size_t i = 0; i < weights.size(); ++i) key[i] = weights[i] > 0.0f ? weights[i] : 0.0f;
  std::vector<int> order(weights.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key[a] > key[b]; });
  std::vector<int> chosen;
  for (int i : order) {
    if (chosen.size() == size_t(kMaxLuts) || key[i] == 0.0f) break;
    chosen.push_back(i);
  }
  return chosen;
}

}  // namespace luxel::postfx
