// The eye's crossings of the color-correction volumes, tick by tick (volume_crossings.hpp).

#include "volume_crossings.hpp"

#include "luxel/scenes/scene.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace luxel::frame {

namespace {

double tick_time(int64_t tick) { return double(tick) / VolumeCrossings::kTicksPerSecond; }

}  // namespace

VolumeCrossings::VolumeCrossings(std::vector<Box> volumes, EyePath eye)
    : volumes_(std::move(volumes)), eye_(std::move(eye)), crossings_(volumes_.size()), inside_(volumes_.size(), false) {}

void VolumeCrossings::replay_to(int64_t last) {
  for (; next_tick_ <= last; ++next_tick_) {
    const glm::vec3 eye = eye_.at(static_cast<float>(tick_time(next_tick_)));
    for (size_t v = 0; v < volumes_.size(); ++v) {
      const bool inside = scenes::box_holds(volumes_[v].min, volumes_[v].max, eye);
      if (inside != inside_[v]) crossings_[v].push_back(tick_time(next_tick_));
      inside_[v] = inside;
    }
  }
}

std::span<const double> VolumeCrossings::crossings(size_t index, double time) {
  if (time >= 0.0 && !volumes_.empty()) {
    // Up to the first tick at or after `time` (ticks past it are left out below, so the rounding
    // of time x ticks per second cannot lose one), but no further than the first tick at which
    // the eye stands still.
    const double still = std::ceil(std::max(double(eye_.still_from), 0.0) * kTicksPerSecond);
    replay_to(static_cast<int64_t>(std::min(std::ceil(time * kTicksPerSecond), still)));
  }
  const std::vector<double>& all = crossings_[index];
  return {all.data(), size_t(std::upper_bound(all.begin(), all.end(), time) - all.begin())};
}

}  // namespace luxel::frame
