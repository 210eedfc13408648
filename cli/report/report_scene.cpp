#include "report/report_scene.hpp"

namespace luxel::cli {

std::string ReportScene::resolution() const { return std::to_string(settings.width) + "x" + std::to_string(settings.height); }

std::unique_ptr<frame::Renderer> ReportScene::renderer(const frame::FrameSettings& s) const {
  return std::make_unique<frame::Renderer>(*scene, s, textures);
}

FrameMeasurement ReportScene::measure(const frame::FrameSettings& s, int timed_frames) const {
  return *measure_frame([this](const frame::FrameSettings& f) { return renderer(f); }, s, timed_frames, *ctx);
}

}  // namespace luxel::cli
