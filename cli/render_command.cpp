// luxel render --scene FILE.gltf|FILE.glb|builtin:NAME [--model ps_2_0|ps_2_b|ps_3_0] [--width --height --msaa
//   --threads --camera N --camera-path --frame N | --frames A:B --fps F --bake full|quick --out FILE --stats]
// --frames A:B renders frames A to B of the sequence into --out, which holds one %d (or %0Nd): the
// frame's number.
// LUXEL_NO_FASTPATH=name,... (or all) turns rasterizer fast paths off (fast_paths.hpp).

#include "commands.hpp"
#include "frame_options.hpp"

#include "luxel/frame/renderer.hpp"
#include "luxel/rasterizer/fast_paths.hpp"
#include "luxel/rasterizer/image.hpp"
#include "luxel/scenes/image_io.hpp"

#include <cctype>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

namespace luxel::cli {

namespace {
struct RenderOptions {
  FrameOptions frame;
  std::string model = "ps_3_0";
  std::string out = "out.png";
  std::string frames;  ///< A:B, or empty for one frame
  bool stats = false;
};

/// `pattern` with its one %d or %0Nd replaced by `n`; nullopt when it holds none, or more.
std::optional<std::string> numbered(const std::string& pattern, int n) {
  const size_t at = pattern.find('%');
  if (at == std::string::npos) return std::nullopt;
  size_t i = at + 1;
  int width = 0;
  if (i < pattern.size() && pattern[i] == '0')
    while (++i < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[i])) && width < 10)
      width = 10 * width + (pattern[i] - '0');
  if (i >= pattern.size() || pattern[i] != 'd' || pattern.find('%', i) != std::string::npos) return std::nullopt;
  std::string digits = std::to_string(n);
  if (static_cast<int>(digits.size()) < width) digits.insert(0, size_t(width) - digits.size(), '0');
  return pattern.substr(0, at) + digits + pattern.substr(i + 1);
}

/// The range of --frames A:B (0 <= A <= B), or nullopt after one line on stderr.
std::optional<std::pair<int, int>> frame_range(const std::string& text) {
  int a = -1, b = -1;
  char sep = 0;
  std::istringstream in(text);
  if (in >> a >> sep >> b && sep == ':' && in.peek() == std::char_traits<char>::eof() && a >= 0 && b >= a && b <= 1000000)
    return std::pair{a, b};
  std::cerr << "luxel render: --frames: '" << text << "' is not A:B with 0 <= A <= B <= 1000000\n";
  return std::nullopt;
}

/// --stats: what the draws of the last frame did, per shader combo, per pass.
void print_stats(const frame::Renderer& renderer, const rasterizer::ContextOptions& context_options) {
  const rasterizer::DrawStats& s = renderer.stats();
  std::cout << "triangles=" << s.triangles << " rasterized=" << s.rasterized << " clipped=" << s.clipped
            << " clip_overflow=" << s.clip_overflow
            << " culled=" << s.culled << " outside=" << s.outside << " degenerate=" << s.degenerate
            << " small_walks=" << s.small_walks << " constant_depth=" << s.constant_depth
            << " blocks_full=" << s.blocks_full
            << " non_finite=" << s.non_finite << " bad_index=" << s.bad_index << " stamps_full=" << s.stamps_full
            << " stamps_partial=" << s.stamps_partial << " stamps_wide_edges=" << s.stamps_wide_edges
            << " stamps_shaded=" << s.stamps_shaded
            << " fast_paths_off=" << rasterizer::fast_paths_off_names(context_options.fast_paths) << "\n";
  for (const frame::ShaderUse& u : renderer.shader_uses())
    std::cout << "shader=" << u.family << " combo=" << u.combo << " pixels=" << u.pixels << " slots=" << u.slots
              << " slot_pixels=" << u.pixels * static_cast<uint64_t>(u.slots) << "\n";
  for (const frame::PassTime& p : renderer.pass_times())
    std::cout << "pass=" << p.pass << " draws=" << p.draws << " ms=" << p.ms << "\n";
  if (const postfx::AutoExposure* a = renderer.auto_exposure()) {
    std::cout << "exposure=" << renderer.exposure() << " goal=" << a->goal() << " target=" << a->last_target()
              << " bucket=" << a->histogram().last_issued() << "\n";
  } else {
    std::cout << "exposure=" << renderer.exposure() << " fixed\n";
  }
}

}  // namespace

Runner add_render_command(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene to an image file");
  options->frame.add_to(*cmd);
  cmd->add_option("--model", options->model, "Pixel-shader model the Source shaders are drawn as")
      ->check(CLI::IsMember({"ps_2_0", "ps_2_b", "ps_3_0"}))
      ->capture_default_str();
  cmd->add_option("--out", options->out, "Output image (PNG, TIFF, EXR... by extension)")->capture_default_str();
  CLI::Option* frames = cmd->add_option(
      "--frames", options->frames,
      "Render frames A to B of the sequence (A:B), each into --out with its number for the %d (or %04d) in it");
  frames->excludes(cmd->get_option("--frame"));
  cmd->add_flag("--stats", options->stats,
                "Print what the draws did, the pixels and counted slots x pixels of each shader combo, and ms per pass "
                "(each pass then runs to its end before the next, a little slower)");
  return [cmd, options]() -> int {
    if (!cmd->parsed()) return -1;
    int code = 0;
    const auto context_options = options->frame.context_options("render", code);
    if (!context_options) return code;
    std::optional<std::pair<int, int>> range;
    if (!options->frames.empty()) {
      range = frame_range(options->frames);
      if (!range) return 2;
      if (!numbered(options->out, 0)) {
        std::cerr << "luxel render: --out " << options->out << " must hold one %d or %0Nd for the frame's number (--frames)\n";
        return 2;
      }
      options->frame.frame = range->first;
    }
    const std::string first_out = range ? *numbered(options->out, range->first) : options->out;
    // The scene, then the renderer that reads it: both outlive the frame.
    frame::FrameSettings settings = options->frame.settings;
    settings.model = shading::parse_pixel_model(options->model);
    settings.count_shading = options->stats;
    settings.time_passes = options->stats;
    const std::optional<scenes::Scene> scene = options->frame.prepare_scene("render", settings, first_out, code);
    if (!scene) return code;
    rasterizer::Context ctx(*context_options);
    const std::unique_ptr<frame::Renderer> renderer = options->frame.make_renderer("render", *scene, settings, ctx, code);
    if (!renderer) return code;
    const int first = options->frame.frame, last = range ? range->second : first;
    for (int n = first; n <= last; ++n) {
      if (n > first) renderer->set_time(static_cast<float>(double(n) / options->frame.fps));
      const std::string out = range ? *numbered(options->out, n) : options->out;
      const auto t0 = std::chrono::steady_clock::now();
      renderer->render(ctx);
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      try {
        const rasterizer::Image& image = renderer->image();
        scenes::write_image(image.width, image.height, image.rgba, out);
      } catch (const std::exception& e) {
        std::cerr << "luxel render: " << e.what() << "\n";
        return 1;
      }
      if (options->stats) print_stats(*renderer, *context_options);
      // One line per frame: a sequence's progress.
      const std::string when =
          n > 0 || range ? ", frame " + std::to_string(n) + " (" + std::to_string(renderer->time()) + " s)" : "";
      std::fprintf(stderr, "luxel render: %s as %s%s, %dx%d, %d samples: %.1f ms, %llu stamps shaded -> %s\n",
                   scene->name.c_str(), options->model.c_str(), when.c_str(), settings.width, settings.height,
                   settings.samples, ms, static_cast<unsigned long long>(renderer->stats().stamps_shaded), out.c_str());
    }
    return 0;
  };
}

}  // namespace luxel::cli
