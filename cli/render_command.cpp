// luxel render --scene FILE.gltf|FILE.glb|builtin:NAME [--model ps_2_0|ps_2_b|ps_3_0] [--width --height --msaa
//   --threads --camera N --out FILE --stats]
// LUXEL_NO_FASTPATH=name,... (or all) turns rasterizer fast paths off (fast_paths.hpp).

#include "baking.hpp"
#include "commands.hpp"

#include "luxel/frame/renderer.hpp"
#include "luxel/rasterizer/fast_paths.hpp"
#include "luxel/rasterizer/image.hpp"
#include "luxel/scenes/builtin.hpp"
#include "luxel/scenes/image_io.hpp"
#include "luxel/scenes/load.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <iostream>
#include <memory>
#include <string>
#include <utility>

namespace luxel::cli {

namespace {
struct RenderOptions {
  std::string scene = "builtin:demo";
  frame::FrameSettings settings;
  std::string model = "ps_3_0";
  int threads = 0;
  std::string out = "out.png";
  std::string bake = "full";
  bool stats = false;
};
}  // namespace

Runner add_render_command(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene to an image file");
  std::string names;
  for (const std::string& n : scenes::builtin_scene_names()) names += (names.empty() ? "" : ", ") + n;
  cmd->add_option("--scene", options->scene, "Scene to render: FILE.gltf, FILE.glb or builtin:NAME (" + names + ")")->capture_default_str();
  cmd->add_option("--width", options->settings.width, "Image width in pixels")->check(CLI::Range(1, 8192))->capture_default_str();
  cmd->add_option("--height", options->settings.height, "Image height in pixels")->check(CLI::Range(1, 8192))->capture_default_str();
  cmd->add_option("--msaa", options->settings.samples, "Samples per pixel: 1, 2, 4 or 8")
      ->check(CLI::IsMember({1, 2, 4, 8}))
      ->capture_default_str();
  cmd->add_option("--camera", options->settings.camera, "Which of the scene's cameras to look through (0 = the first)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--model", options->model, "Pixel-shader model the Source shaders are drawn as")
      ->check(CLI::IsMember({"ps_2_0", "ps_2_b", "ps_3_0"}))
      ->capture_default_str();
  cmd->add_option("--threads", options->threads, "Worker threads (0 = one per core)")->check(CLI::Range(0, 256))->capture_default_str();
  cmd->add_option("--out", options->out, "Output image (PNG, TIFF, EXR... by extension)")->capture_default_str();
  cmd->add_option("--bake", options->bake,
                  "When the scene needs a bake it lacks (kept as `luxel bake` keeps it): full, or quick (a preview in seconds)")
      ->check(CLI::IsMember({"full", "quick"}))
      ->capture_default_str();
  cmd->add_flag("--stats", options->stats, "Print what the draws did and the pixels each shader combo shaded");
  return [cmd, options]() -> int {
    if (!cmd->parsed()) return -1;
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
    // The scene, then the renderer that reads it: both outlive the frame. A file's camera N is
    // made its first on import (as `luxel info` and `export` do); a built-in's is picked here.
    frame::FrameSettings settings = options->settings;
    settings.model = shading::parse_pixel_model(options->model);
    scenes::GltfImportOptions gltf;
    const bool file = options->scene.rfind("builtin:", 0) != 0;
    if (file) gltf.camera = std::exchange(settings.camera, 0);
    scenes::Scene scene;
    try {
      scene = scenes::load_scene(options->scene, gltf, {settings.width, settings.height});
    } catch (const scenes::SceneArgumentError& e) {
      std::cerr << "luxel render: --scene " << e.what() << "\n";
      return 2;
    } catch (const std::exception& e) {
      std::cerr << "luxel render: " << e.what() << "\n";
      return 1;
    }
    // What can fail quickly fails before a bake: the camera, the output folder.
    try {
      frame::frame_camera(scene, settings);
    } catch (const std::invalid_argument& e) {
      std::cerr << "luxel render: " << e.what() << "\n";
      return 2;
    }
    if (const std::filesystem::path dir = std::filesystem::path(options->out).parent_path();
        !dir.empty() && !std::filesystem::is_directory(dir)) {
      std::cerr << "luxel render: " << options->out << ": no such folder to write into\n";
      return 1;
    }
    if (needs_bake(scene)) {
      const std::string folder = default_bake_folder(options->scene);
      if (folder.empty()) {
        std::cerr << "luxel render: " << options->scene << " needs a bake and there is no HOME or XDG_CACHE_HOME to keep it in; run luxel bake --out DIR\n";
        return 2;
      }
      bake::BakeSettings bake_settings = options->bake == "quick" ? bake::BakeSettings::quick() : bake::BakeSettings{};
      bake_settings.threads = options->threads;
      try {
        bake_and_attach(scene, folder, bake_settings, "luxel render");
      } catch (const std::exception& e) {
        std::cerr << "luxel render: " << e.what() << "\n";
        return 1;
      }
    }
    settings.count_shading = options->stats;
    std::unique_ptr<frame::Renderer> renderer;
    try {
      renderer = std::make_unique<frame::Renderer>(scene, settings);
    } catch (const std::invalid_argument& e) {
      std::cerr << "luxel render: " << e.what() << "\n";
      return 2;
    }
    rasterizer::Context ctx(context_options);
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
                << " fast_paths_off=" << rasterizer::fast_paths_off_names(context_options.fast_paths) << "\n";
      for (const frame::ShaderUse& u : renderer->shader_uses())
        std::cout << "shader=" << u.family << " combo=" << u.combo << " pixels=" << u.pixels << " slots=" << u.slots << "\n";
    }
    std::fprintf(stderr, "luxel render: %s as %s, %dx%d, %d samples: %.1f ms, %llu stamps shaded -> %s\n",
                 scene.name.c_str(), options->model.c_str(), settings.width, settings.height, settings.samples, ms,
                 static_cast<unsigned long long>(renderer->stats().stamps_shaded), options->out.c_str());
    return 0;
  };
}

}  // namespace luxel::cli
