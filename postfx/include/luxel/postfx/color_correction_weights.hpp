#pragma once
// The weights of Source's color-correction entities (docs/fidelity.md#color-correction), which the pass
// (color_correction.hpp) blends. Times are in seconds; the SDK updates the fades on think ticks
// (the volume every 0.01 s), luxel evaluates them at the frame's time.
//
// color_correction (a point entity, scenes::ColorCorrection):
//   - its current weight spawns at 1, or 0 with StartDisabled;
//   - enabling fades it from where it is to max_weight over fade_in, shortened in proportion to
//     the weight already there (fade_in * (1 - start / max), the ratio clamped to [0, 0.99]);
//     without a fade_in it jumps to max_weight;
//   - disabling fades it from where it is to 0 over fade_out * start / max (the ratio clamped
//     to [0.01, 1]), or at once without a fade_out;
//   - the eye at `distance` sees current * (1 - sat((distance - min_falloff) / (max_falloff -
//     min_falloff))) when the falloffs differ and neither is -1; otherwise the current weight.
// color_correction_volume (a trigger volume):
//   - entering at time t0 with weight w0 ramps w0 + (t - t0) / ((1 - w0) fade), capped at 1;
//   - leaving at t1 with weight w1 ramps 1 - min(1, (1 - w1) + (t - t1) / (w1 fade)), so down to 0;
//   - a fade of 0 (or less) jumps: 1 inside, 0 outside.
// The engine blends at most four lookups; which four when more entities weigh in is closed
// (NOT IN SDK): luxel takes the four heaviest, the earlier entity first on a tie.

#include <span>
#include <vector>

namespace luxel::postfx {

/// A color_correction entity's current weight through its enable and disable fades.
class EntityFade {
 public:
  struct Settings {
    float max_weight = 1.0f;
    float fade_in = 0.0f, fade_out = 0.0f;  ///< seconds for a full 0 -> max and max -> 0
    bool start_disabled = false;
  };
  explicit EntityFade(const Settings& settings);

  /// Input Enable / Disable at `time`; each starts from the weight at that time.
  void enable(double time);
  void disable(double time);
  /// The current weight at `time` (not before the last enable or disable).
  float weight(double time) const;

 private:
  Settings settings_;
  enum class Phase { steady, fading_in, fading_out } phase_ = Phase::steady;
  float start_weight_;  ///< the weight the current phase started from (steady: the weight)
  double start_time_ = 0.0;
};

/// The weight the eye sees at `distance` from the entity (-1 for a falloff: none).
float falloff_weight(float current_weight, float min_falloff, float max_falloff, float distance);

/// A color_correction_volume's weight as the eye enters and leaves it.
class VolumeFade {
 public:
  explicit VolumeFade(float fade_duration) : fade_(fade_duration) {}
  void enter(double time);
  void leave(double time);
  float weight(double time) const;

 private:
  float fade_;
  bool inside_ = false;
  float last_weight_ = 0.0f;  ///< the weight when the eye last entered or left
  double last_time_ = 0.0;
};

/// The entities the pass blends: indices into `weights` of the (at most) four heaviest non-zero
/// weights, heaviest first, the lower index first on a tie.
std::vector<int> heaviest_lookups(std::span<const float> weights);

}  // namespace luxel::postfx
