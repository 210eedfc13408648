// luxel render --scene builtin:NAME [--width --height --msaa --threads --out FILE]
// LUXEL_NO_FASTPATH=name,... (or all) turns rasterizer fast paths off (fast_paths.hpp).

#include "commands.hpp"

#include "luxel/frame/builtin.hpp"
#include "luxel/rasterizer/fast_paths.hpp"
#include "luxel/scenes/image_io.hpp"

#include <cstdlib>

#include <iostream>
#include <memory>
#include <string>

namespace luxel::cli {

namespace {
struct RenderOptions {
  std::string scene = "builtin:demo";
  frame::FrameSettings settings;
  int threads = 0;
  std::string out = "out.png";
  bool stats = false;
};
}  // namespace

Runner add_render_command(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene to an image file");
  cmd->add_option("--scene", options->scene, "Scene to render: builtin:NAME (demo, fill, tris)")->capture_default_str();
  cmd->add_option("--width", options->settings.width, "Image width in pixels")->check(CLI::Range(1, 8192))->capture_default_str();
  cmd->add_option("--height", options->settings.height, "Image height in pixels")->check(CLI::Range(1, 8192))->capture_default_str();
  cmd->add_option("--msaa", options->settings.samples, "Samples per pixel: 1, 2, 4 or 8")
      ->check(CLI::IsMember({1, 2, 4, 8}))
      ->capture_default_str();
  cmd->add_option("--threads", options->threads, "Worker threads (0 = one per core)")->check(CLI::Range(0, 256))->capture_default_str();
  cmd->add_option("--out", options->out, "Output image (PNG, TIFF, EXR... by extension)")->capture_default_str();
  cmd->add_flag("--stats", options->stats, "Print what the draws did");
  return [cmd, options]() -> int {
    if (!cmd->parsed()) return -1;
    const std::string prefix = "builtin:";
    if (options->scene.rfind(prefix, 0) != 0) {
      std::cerr << "luxel render: --scene " << options->scene << ": only builtin:NAME scenes are supported so far\n";
      return 2;
    }
    rasterizer::ContextOptions context_options;
    context_options.threads = options->threads;
    if (const char* off = std::getenv("LUXEL_NO_FASTPATH")) {
      try {
        context_options.fast_paths = rasterizer::parse_fast_paths_off(off);
      } catch (const std::invalid_argument& e) {
        std::cerr << "luxel render: LUXEL_NO_FASTPATH: " << e.what() << "\n";
        return 2;
      }
    }
    std::unique_ptr<frame::BuiltinScene> scene;
    try {
      scene = frame::make_builtin_scene(options->scene.substr(prefix.size()), options->settings);
    } catch (const std::invalid_argument& e) {
      std::cerr << "luxel render: " << e.what() << "\n";
      return 2;
    }
    rasterizer::Context ctx(context_options);
    scene->render(ctx);
    try {
      const rasterizer::Image& image = scene->image();
      scenes::write_image(image.width, image.height, image.rgba, options->out);
    } catch (const std::exception& e) {
      std::cerr << "luxel render: " << e.what() << "\n";
      return 1;
    }
    if (options->stats) {
      const rasterizer::DrawStats& s = scene->stats();
      std::cout << "triangles=" << s.triangles << " rasterized=" << s.rasterized << " clipped=" << s.clipped
                << " clip_overflow=" << s.clip_overflow
                << " culled=" << s.culled << " outside=" << s.outside << " degenerate=" << s.degenerate
                << " small_walks=" << s.small_walks << " constant_depth=" << s.constant_depth
                << " blocks_full=" << s.blocks_full
                << " non_finite=" << s.non_finite << " bad_index=" << s.bad_index << " stamps_full=" << s.stamps_full
                << " stamps_partial=" << s.stamps_partial << " stamps_wide_edges=" << s.stamps_wide_edges
                << " stamps_shaded=" << s.stamps_shaded
                << " fast_paths_off=" << rasterizer::fast_paths_off_names(context_options.fast_paths) << "\n";
    }
    return 0;
  };
}

}  // namespace luxel::cli
