// luxel render --scene FILE.gltf|FILE.glb|builtin:NAME [--model ps_2_0|ps_2_b|ps_3_0] [--width --height --msaa
//   --threads --camera N --camera-path --frame N | --frames A:B --fps F --bake full|quick --out FILE --stats]
// --frames A:B renders frames A to B of the sequence into --out, which holds one %d (or %0Nd): the
// frame's number. --sequence N renders frames 0 to N-1 along the scene's camera path (when it has
// one) into the folder --out as frame_0000.png..., with a progress bar on a terminal, and writes
// there exposure.json (per frame: time, the scale it was drawn with, the goal, the occlusion
// histogram's target and the exact histogram's) and, with auto exposure, exposure.png (the same
// over time).
// LUXEL_NO_FASTPATH=name,... (or all) turns rasterizer fast paths off (fast_paths.hpp).

#include "commands.hpp"
#include "frame_options.hpp"
#include "line_plot.hpp"

#include "luxel/frame/renderer.hpp"
#include "luxel/shading/source/binaries.hpp"
#include "luxel/rasterizer/fast_paths.hpp"
#include "luxel/rasterizer/image.hpp"
#include "luxel/scenes/image_io.hpp"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>
#include <unistd.h>

namespace luxel::cli {

namespace {
struct RenderOptions {
  FrameOptions frame;
  std::string model = "ps_3_0";
  std::string out = "out.png";
  std::string frames;  ///< A:B, or empty for one frame
  int sequence = 0;    ///< N frames into the folder `out`, or 0
  bool stats = false;
};

/// One frame of a --sequence, for exposure.json and exposure.png.
struct SequenceFrame {
  double time = 0.0;
  float drawn = 1.0f;                  ///< the scale the frame was drawn with
  std::optional<float> goal, target;   ///< after the frame: the goal, the occlusion histogram's target
  std::optional<float> exact_target;   ///< the exact histogram's target for the frame
};

/// exposure.json and (with auto exposure) exposure.png in `folder`; false after one line on stderr.
bool write_exposure_report(const std::string& folder, const std::vector<SequenceFrame>& frames, bool automatic) {
  nlohmann::json j;
  j["auto_exposure"] = automatic;
  for (const SequenceFrame& f : frames) {
    nlohmann::json row{{"time", f.time}, {"scale", f.drawn}};
    if (f.goal) row["goal"] = *f.goal;
    if (f.target) row["target"] = *f.target;
    if (f.exact_target) row["exact_target"] = *f.exact_target;
    j["frames"].push_back(row);
  }
  const std::string json_path = folder + "/exposure.json", png_path = folder + "/exposure.png";
  std::ofstream out(json_path);
  out << j.dump(1) << "\n";
  if (!out) {
    std::cerr << "luxel render: " << json_path << ": cannot write it\n";
    return false;
  }
  if (!automatic) return true;
  LinePlot plot;
  plot.title = "Auto exposure over the sequence";
  plot.x_label = "time (s)";
  plot.y_label = "tone-map scale";
  plot.series = {{"scale drawn with", {255, 255, 255}, {}, PlotStyle::lines, {}},
                 {"goal (10-frame history)", {80, 200, 255}, {}, PlotStyle::lines, {}},
                 {"target: occlusion histogram", {255, 150, 40}, {}, PlotStyle::lines, {}},
                 {"target: exact histogram", {90, 220, 90}, {}, PlotStyle::lines, {}}};
  for (const SequenceFrame& f : frames) {
    plot.series[0].points.emplace_back(f.time, f.drawn);
    if (f.goal) plot.series[1].points.emplace_back(f.time, *f.goal);
    if (f.target) plot.series[2].points.emplace_back(f.time, *f.target);
    if (f.exact_target) plot.series[3].points.emplace_back(f.time, *f.exact_target);
  }
  try {
    const rasterizer::Image image = draw_line_plot(plot);
    scenes::write_image(image.width, image.height, image.rgba, png_path);
  } catch (const std::exception& e) {
    std::cerr << "luxel render: " << e.what() << "\n";
    return false;
  }
  return true;
}

/// The bar of a sequence on a terminal: [#####.....] n/N.
void progress_bar(int done, int total) {
  constexpr int kWidth = 30;
  const int filled = total > 0 ? done * kWidth / total : kWidth;
  std::fprintf(stderr, "\rluxel render: [%s%s] %d/%d frames", std::string(size_t(filled), '#').c_str(),
               std::string(size_t(kWidth - filled), '.').c_str(), done, total);
  if (done == total) std::fprintf(stderr, "\n");
}

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
            << " stamps_shaded=" << s.stamps_shaded << " tile_memory_targets=" << s.tile_memory_targets
            << " fast_paths_off=" << rasterizer::fast_paths_off_names(context_options.fast_paths) << "\n";
  for (const frame::ShaderUse& u : renderer.shader_uses())
    std::cout << "shader=" << u.family << " combo=" << u.combo << " binary=" << shading::source::binary_name(u.binary)
              << " pixels=" << u.pixels << " slots=" << u.slots
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
  cmd->add_option("--sequence", options->sequence,
                  "Render N frames from 0 along the scene's camera path (when it has one) into the folder --out "
                  "(frame_0000.png...), with exposure.json and, with auto exposure, exposure.png")
      ->check(CLI::Range(1, 100000))
      ->excludes(frames)
      ->excludes(cmd->get_option("--frame"));
  cmd->add_flag("--stats", options->stats,
                "Print what the draws did, the pixels and counted slots x pixels of each shader combo, and ms per pass "
                "(each pass then runs to its end before the next, a little slower)");
  return [cmd, options]() -> int {
    if (!cmd->parsed()) return -1;
    int code = 0;
    const auto context_options = options->frame.context_options("render", code);
    if (!context_options) return code;
    std::optional<std::pair<int, int>> range;
    const bool sequence = options->sequence > 0;
    if (sequence) {
      std::error_code error;
      std::filesystem::create_directory(options->out, error);
      if (error || !std::filesystem::is_directory(options->out)) {
        std::cerr << "luxel render: " << options->out << ": cannot create the folder for the sequence\n";
        return 1;
      }
      range = std::pair{0, options->sequence - 1};
      options->out = (std::filesystem::path(options->out) / "frame_%04d.png").string();
    } else if (!options->frames.empty()) {
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
    const std::optional<scenes::Scene> scene = options->frame.prepare_scene("render", settings, {first_out}, code);
    if (!scene) return code;
    if (sequence && !scene->camera_path.empty()) settings.camera_path = true;
    rasterizer::Context ctx(*context_options);
    const std::unique_ptr<frame::Renderer> renderer = options->frame.make_renderer("render", *scene, settings, ctx, code);
    if (!renderer) return code;
    const int first = options->frame.frame, last = range ? range->second : first;
    const bool bar = sequence && isatty(STDERR_FILENO);
    std::vector<SequenceFrame> report;
    for (int n = first; n <= last; ++n) {
      if (n > first) renderer->set_time(static_cast<float>(double(n) / options->frame.fps));
      const std::string out = range ? *numbered(options->out, n) : options->out;
      SequenceFrame row{renderer->time(), renderer->exposure(), {}, {}, {}};
      const auto t0 = std::chrono::steady_clock::now();
      renderer->render(ctx);
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      if (sequence) {
        if (const postfx::AutoExposure* a = renderer->auto_exposure()) {
          row.goal = a->goal();
          row.target = a->last_target();
          row.exact_target = postfx::exact_target(renderer->image(), a->settings(), row.drawn);
        }
        report.push_back(row);
      }
      try {
        const rasterizer::Image& image = renderer->image();
        scenes::write_image(image.width, image.height, image.rgba, out);
      } catch (const std::exception& e) {
        std::cerr << "luxel render: " << e.what() << "\n";
        return 1;
      }
      if (options->stats) print_stats(*renderer, *context_options);
      if (bar) {
        progress_bar(n - first + 1, last - first + 1);
        continue;
      }
      // One line per frame: a sequence's progress.
      const std::string when =
          n > 0 || range ? ", frame " + std::to_string(n) + " (" + std::to_string(renderer->time()) + " s)" : "";
      std::fprintf(stderr, "luxel render: %s as %s%s, %dx%d, %d samples: %.1f ms, %llu stamps shaded -> %s\n",
                   scene->name.c_str(), options->model.c_str(), when.c_str(), settings.width, settings.height,
                   settings.samples, ms, static_cast<unsigned long long>(renderer->stats().stamps_shaded), out.c_str());
    }
    if (sequence && !write_exposure_report(std::filesystem::path(options->out).parent_path().string(), report,
                                           renderer->auto_exposure() != nullptr))
      return 1;
    return 0;
  };
}

}  // namespace luxel::cli
