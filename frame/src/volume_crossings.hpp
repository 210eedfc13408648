#pragma once
// Private: when the eye enters and leaves each of the scene's color-correction volumes
// (scenes::ColorCorrectionVolume), as Source's trigger sees the player. The eye's place is tested
// at every think tick of the scene's clock, 0, 0.01 s, 0.02 s, ... (colorcorrectionvolume.cpp
// thinks every 0.01 s, docs/fidelity.md#color-correction), bounds inclusive, the eye outside every
// volume before 0; a tick where the answer changes is an enter or a leave at that tick's time.
//
// The crossings are a function of the eye's path alone. They are found by replaying the path
// tick by tick from 0 (no rendering), kept, and extended when the clock goes further, so the
// weights made from them do not depend on which frames were rendered before (`luxel render
// --frame N`, `--frames A:B` and `--sequence` agree at the same frame). Once the eye stands still
// nothing changes, so the ticks after that are not replayed.

#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace luxel::frame {

/// Where the eye is at each time on the scene's clock.
struct EyePath {
  std::function<glm::vec3(float time)> at;
  float still_from = 0.0f;  ///< from this time on the eye does not move
};

/// An axis-aligned box, bounds inclusive.
struct Box {
  glm::vec3 min{0.0f}, max{0.0f};
};

class VolumeCrossings {
 public:
  /// Think ticks per second of the scene's clock.
  static constexpr int kTicksPerSecond = 100;

  VolumeCrossings(std::vector<Box> volumes, EyePath eye);

  /// The times at which the eye crossed into or out of volume `index` up to `time` (seconds),
  /// in order: an enter, a leave, an enter...
  std::span<const double> crossings(size_t index, double time);

 private:
  /// Tests every tick after the last one tested up to `last` (inclusive).
  void replay_to(int64_t last);

  std::vector<Box> volumes_;
  EyePath eye_;
  std::vector<std::vector<double>> crossings_;  ///< per volume
  std::vector<bool> inside_;                    ///< per volume, at the last tick tested
  int64_t next_tick_ = 0;
};

}  // namespace luxel::frame
