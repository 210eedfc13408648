#pragma once
// What the report's frame sections (renders_frames in report.hpp) render: the scene named
// by --scene, prepared once by the command (loaded, its bake made or loaded as `luxel render`
// does), its textures uploaded once and shared by every renderer, and one rasterizer context.
//
// The frames are the shaders' own pixels: the first frame of the scene's sequence (time 0), no
// bloom, no color correction, no film grain, so that an approximation's error is its own and not
// a post pass's reaction to it. Each section changes one setting of `settings` and says so.

#include "frame_measurement.hpp"

#include "luxel/frame/renderer.hpp"
#include "luxel/frame/textures.hpp"
#include "luxel/rasterizer/context.hpp"
#include "luxel/scenes/scene.hpp"

#include <memory>
#include <string>

namespace luxel::cli {

struct ReportScene {
  std::string name;                ///< the --scene argument ("builtin:courtyard", a file)
  const scenes::Scene* scene = nullptr;
  std::shared_ptr<const frame::SceneTextures> textures;
  frame::FrameSettings settings;   ///< --width x --height, the frame's default MSAA and model; the post passes off
  rasterizer::Context* ctx = nullptr;

  /// "320x180".
  std::string resolution() const;
  /// A renderer of the scene with `s` (the shared textures).
  std::unique_ptr<frame::Renderer> renderer(const frame::FrameSettings& s) const;
  /// measure_frame with `s`: its counted slots, its first image, `timed_frames` timed frames.
  FrameMeasurement measure(const frame::FrameSettings& s, int timed_frames) const;
};

}  // namespace luxel::cli
