#pragma once
// One frame of a scene measured as `luxel compare`, `luxel cost --scene` and `luxel report` measure
// it: the shader combos it ran with their counted slots (from a renderer that counts), the first
// frame's image, and the wall time of the frames after it (and of each pass, when asked). Shared
// so that the commands' "slots per pixel" and "ms per frame" are the same numbers.

#include "luxel/frame/renderer.hpp"
#include "luxel/rasterizer/context.hpp"
#include "luxel/rasterizer/image.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace luxel::cli {

struct FrameMeasurement {
  rasterizer::Image image;               ///< the first frame of a renderer that does not count
  std::vector<double> ms;                ///< the timed frames after it, sorted
  std::vector<frame::ShaderUse> uses;    ///< what the counted frame's shader combos did
  std::vector<frame::PassTime> passes;   ///< per pass, the median ms of the timed frames (when timed)

  /// median_of_sorted(ms).
  double median_ms() const;
  /// sum(pixels) and sum(pixels x slots) over `uses`.
  struct ShadingTotals {
    uint64_t pixels = 0, slot_pixels = 0;
  };
  ShadingTotals shading_totals() const;
  /// slot_pixels / pixels of shading_totals(), or nullopt when the frame counted no shading.
  std::optional<double> slots_per_pixel() const;
};

/// The median of sorted values (the mean of the middle two for an even count; at least one value).
double median_of_sorted(const std::vector<double>& sorted);

/// Makes a renderer with the settings given, or returns null after saying why (the caller's way).
using RendererFactory = std::function<std::unique_ptr<frame::Renderer>(const frame::FrameSettings&)>;

/// One counted frame (settings.count_shading set) for the shader uses, then on a renderer that
/// does not count, one frame (the image: a frame carries state into the next, the time-averaged
/// lighting, so a later one would depend on `timed_frames`) and `timed_frames` timed ones. With
/// `time_passes` those also time each pass (FrameSettings::time_passes: each pass then runs to its
/// end before the next, a little slower). nullopt when `make` returns null.
std::optional<FrameMeasurement> measure_frame(const RendererFactory& make, frame::FrameSettings settings, int timed_frames,
                                              rasterizer::Context& ctx, bool time_passes = false);

}  // namespace luxel::cli
