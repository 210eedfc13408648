#include "frame_measurement.hpp"

#include <algorithm>
#include <chrono>
#include <map>

namespace luxel::cli {

double median_of_sorted(const std::vector<double>& sorted) {
  const size_t n = sorted.size();
  return n % 2 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
}

double FrameMeasurement::median_ms() const { return median_of_sorted(ms); }

FrameMeasurement::ShadingTotals FrameMeasurement::shading_totals() const {
  ShadingTotals t;
  for (const frame::ShaderUse& u : uses) t.pixels += u.pixels, t.slot_pixels += u.pixels * uint64_t(u.slots);
  return t;
}

std::optional<double> FrameMeasurement::slots_per_pixel() const {
  const ShadingTotals t = shading_totals();
  if (t.pixels == 0) return std::nullopt;
  return double(t.slot_pixels) / double(t.pixels);
}

std::optional<FrameMeasurement> measure_frame(const RendererFactory& make, frame::FrameSettings settings, int timed_frames,
                                              rasterizer::Context& ctx, bool time_passes) {
  FrameMeasurement m;
  settings.count_shading = true;
  {
    const std::unique_ptr<frame::Renderer> counted = make(settings);
    if (!counted) return std::nullopt;
    counted->render(ctx);
    m.uses = counted->shader_uses();
  }
  settings.count_shading = false;
  settings.time_passes = time_passes;
  const std::unique_ptr<frame::Renderer> timed = make(settings);
  if (!timed) return std::nullopt;
  timed->render(ctx);
  m.image = timed->image();
  // A pass's time in each timed frame (0 in a frame without it: "views" runs only when the clock
  // or the exposure moved), by name in the order passes first ran.
  std::map<std::string, std::vector<double>> pass_ms;
  for (int i = 0; i < timed_frames; ++i) {
    const auto start = std::chrono::steady_clock::now();
    timed->render(ctx);
    m.ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    for (const frame::PassTime& p : timed->pass_times()) {
      std::vector<double>& ms = pass_ms[p.pass];
      if (ms.empty()) m.passes.push_back({p.pass, 0.0, p.draws});
      ms.resize(size_t(timed_frames), 0.0);
      ms[size_t(i)] += p.ms;
    }
  }
  std::sort(m.ms.begin(), m.ms.end());
  for (frame::PassTime& p : m.passes) {
    std::vector<double>& ms = pass_ms[p.pass];
    std::sort(ms.begin(), ms.end());
    p.ms = median_of_sorted(ms);
  }
  return m;
}

}  // namespace luxel::cli
