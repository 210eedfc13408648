#pragma once
// Renders a built-in scene through frame::Renderer: the helper every frame test uses.

#include "luxel/frame/renderer.hpp"
#include "luxel/scenes/builtin.hpp"

#include <string_view>

namespace luxel::frame {

struct RenderedFrame {
  rasterizer::Image image;
  rasterizer::DrawStats stats;
};

/// Builds builtin:`name` for the settings' size, renders `frames` frames with `options`, and
/// returns the last (checking that every frame gave the same bytes).
RenderedFrame render_builtin(std::string_view name, const FrameSettings& settings,
                             const rasterizer::ContextOptions& options, int frames = 1);

}  // namespace luxel::frame
