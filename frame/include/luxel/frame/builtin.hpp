#pragma once
// Built-in scenes that need no files: the peer benchmark workloads `fill` and `tris`, and
// `demo`, a small depth-tested, textured, perspective scene.
//
// A BuiltinScene prepares its data once (the 48 MB of `tris` vertices, textures) and then renders
// any number of frames, each exactly what the llvmpipe peer calls a frame: clear, draw, resolve.

#include "luxel/rasterizer/context.hpp"
#include "luxel/rasterizer/draw.hpp"
#include "luxel/rasterizer/image.hpp"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace luxel::frame {

struct FrameSettings {
  int width = 1280;
  int height = 720;
  int samples = 4;
};

class BuiltinScene {
 public:
  virtual ~BuiltinScene() = default;
  /// Renders one frame and resolves it into image().
  virtual void render(rasterizer::Context& ctx) = 0;
  const rasterizer::Image& image() const { return image_; }
  /// What the draws of the last frame did, summed.
  const rasterizer::DrawStats& stats() const { return stats_; }

 protected:
  rasterizer::Image image_;
  rasterizer::DrawStats stats_;
};

/// Names accepted by make_builtin_scene, in display order.
std::vector<std::string> builtin_scene_names();

/// Throws std::invalid_argument for an unknown name or bad settings.
std::unique_ptr<BuiltinScene> make_builtin_scene(std::string_view name, const FrameSettings& settings);

}  // namespace luxel::frame
