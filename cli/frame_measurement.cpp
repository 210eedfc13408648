#include "frame_measurement.hpp"

#include <algorithm>
#include <chrono>

namespace luxel::cli {

double median_of_sorted(const std::vector<double>& sorted) {
  const size_t n = sorted.size();
  return n % 2 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
}

double FrameMeasurement::median_ms() const { return median_of_sorted(ms); }

std::optional<double> FrameMeasurement::slots_per_pixel() const {
  double pixels = 0, slots = 0;
  for (const frame::ShaderUse& u : uses) {
    pixels += double(u.pixels);
    slots += double(u.pixels) * u.slots;
  }
  if (pixels == 0) return std::nullopt;
  return slots / pixels;
}

std::optional<FrameMeasurement> measure_frame(const RendererFactory& make, frame::FrameSettings settings, int timed_frames,
                                              rasterizer::Context& ctx) {
  FrameMeasurement m;
  settings.count_shading = true;
  {
    const std::unique_ptr<frame::Renderer> counted = make(settings);
    if (!counted) return std::nullopt;
    counted->render(ctx);
    m.uses = counted->shader_uses();
  }
  settings.count_shading = false;
  const std::unique_ptr<frame::Renderer> timed = make(settings);
  if (!timed) return std::nullopt;
  timed->render(ctx);
  m.image = timed->image();
  for (int i = 0; i < timed_frames; ++i) {
    const auto start = std::chrono::steady_clock::now();
    timed->render(ctx);
    m.ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(m.ms.begin(), m.ms.end());
  return m;
}

}  // namespace luxel::cli
