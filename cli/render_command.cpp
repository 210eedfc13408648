// luxel render --scene FILE.gltf|FILE.glb|builtin:NAME [--model ps_2_0|ps_2_b|ps_3_0] [--width --height --msaa
//   --threads --camera N --camera-path --frame N --fps F --bake full|quick --out FILE --stats]
// LUXEL_NO_FASTPATH=name,... (or all) turns rasterizer fast paths off (fast_paths.hpp).

#include "commands.hpp"
#include "frame_options.hpp"

#include "luxel/frame/renderer.hpp"
#include "luxel/rasterizer/fast_paths.hpp"
#include "luxel/rasterizer/image.hpp"
#include "luxel/scenes/image_io.hpp"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

namespace luxel::cli {

namespace {
struct RenderOptions {
  FrameOptions frame;
  std::string model = "ps_3_0";
  std::string out = "out.png";
  bool stats = false;
};
}  // namespace

Runner add_render_command(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene to an image file");
  options->frame.add_to(*cmd);
  cmd->add_option("--model", options->model, "Pixel-shader model the Source shaders are drawn as")
      ->check(CLI::IsMember({"ps_2_0", "ps_2_b", "ps_3_0"}))
      ->capture_default_str();
  cmd->add_option("--out", options->out, "Output image (PNG, TIFF, EXR... by extension)")->capture_default_str();
  cmd->add_flag("--stats", options->stats,
                "Print what the draws did, the pixels and counted slots x pixels of each shader combo, and ms per pass "
                "(each pass then runs to its end before the next, a little slower)");
  return [cmd, options]() -> int {
    if (!cmd->parsed()) return -1;
    int code = 0;
    const auto context_options = options->frame.context_options("render", code);
    if (!context_options) return code;
    // The scene, then the renderer that reads it: both outlive the frame.
    frame::FrameSettings settings = options->frame.settings;
    settings.model = shading::parse_pixel_model(options->model);
    settings.count_shading = options->stats;
    settings.time_passes = options->stats;
    const std::optional<scenes::Scene> scene = options->frame.prepare_scene("render", settings, options->out, code);
    if (!scene) return code;
    const std::unique_ptr<frame::Renderer> renderer = options->frame.make_renderer("render", *scene, settings, code);
    if (!renderer) return code;
    rasterizer::Context ctx(*context_options);
    const auto t0 = std::chrono::steady_clock::now();
    renderer->render(ctx);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    try {
      const rasterizer::Image& image = renderer->image();
      scenes::write_image(image.width, image.height, image.rgba, options->out);
    } catch (const std::exception& e) {
      std::cerr << "luxel render: " << e.what() << "\n";
      return 1;
    }
    if (options->stats) {
      const rasterizer::DrawStats& s = renderer->stats();
      std::cout << "triangles=" << s.triangles << " rasterized=" << s.rasterized << " clipped=" << s.clipped
                << " clip_overflow=" << s.clip_overflow
                << " culled=" << s.culled << " outside=" << s.outside << " degenerate=" << s.degenerate
                << " small_walks=" << s.small_walks << " constant_depth=" << s.constant_depth
                << " blocks_full=" << s.blocks_full
                << " non_finite=" << s.non_finite << " bad_index=" << s.bad_index << " stamps_full=" << s.stamps_full
                << " stamps_partial=" << s.stamps_partial << " stamps_wide_edges=" << s.stamps_wide_edges
                << " stamps_shaded=" << s.stamps_shaded
                << " fast_paths_off=" << rasterizer::fast_paths_off_names(context_options->fast_paths) << "\n";
      for (const frame::ShaderUse& u : renderer->shader_uses())
        std::cout << "shader=" << u.family << " combo=" << u.combo << " pixels=" << u.pixels << " slots=" << u.slots
                  << " slot_pixels=" << u.pixels * static_cast<uint64_t>(u.slots) << "\n";
      for (const frame::PassTime& p : renderer->pass_times())
        std::cout << "pass=" << p.pass << " draws=" << p.draws << " ms=" << p.ms << "\n";
    }
    const std::string when =
        options->frame.frame > 0 ? ", frame " + std::to_string(options->frame.frame) + " (" + std::to_string(renderer->time()) + " s)" : "";
    std::fprintf(stderr, "luxel render: %s as %s%s, %dx%d, %d samples: %.1f ms, %llu stamps shaded -> %s\n",
                 scene->name.c_str(), options->model.c_str(), when.c_str(), settings.width, settings.height, settings.samples, ms,
                 static_cast<unsigned long long>(renderer->stats().stamps_shaded), options->out.c_str());
    return 0;
  };
}

}  // namespace luxel::cli
