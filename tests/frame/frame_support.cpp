#include "frame/frame_support.hpp"

#include <gtest/gtest.h>

namespace luxel::frame {

RenderedFrame render_builtin(std::string_view name, const FrameSettings& settings,
                             const rasterizer::ContextOptions& options, int frames) {
  const scenes::Scene scene = scenes::make_builtin_scene(name, {settings.width, settings.height});
  Renderer renderer(scene, settings);
  rasterizer::Context ctx(options);
  RenderedFrame f;
  for (int i = 0; i < frames; ++i) {
    renderer.render(ctx);
    if (i > 0) {
      EXPECT_TRUE(renderer.image().rgba == f.image.rgba) << name << ": frame " << i << " differs from frame 0";
    }
    f.image = renderer.image();
    f.stats = renderer.stats();
  }
  return f;
}

}  // namespace luxel::frame
