// luxel compare --scene SCENE [--models ps_2_0,ps_2_b,ps_3_0] [--width --height --msaa --threads --camera N
//   --bake full|quick] [--frames N] [--explain] --out PREFIX
// Renders the scene as each shader model and compares every pair (frame/image_difference.hpp) of
// first frames, the frames `luxel render --model` writes:
//   PREFIX.png   the frames labelled with their model, then a heat map per pair ("ps_2_0 vs ps_2_b")
//                and the heat map's legend (compare_sheet.hpp);
//   PREFIX.json  per model: ms per frame (median of --frames timed frames after one warm-up), the
//                counted slots per pixel and the shader combos behind them; per pair: PSNR, max and
//                mean error in 8-bit steps, the share of pixels that differ, each side's ms and
//                slots per pixel;
//   stdout       the pair table; stderr: one summary line.
// With --explain, each pair's differing pixels attributed to the SDK rule behind them
// (compare_explain.hpp): a third row of the sheet colours them by cause, with its legend; the
// JSON's pair gains "explain" (pixels per cause, and per rule the pixels it has a part in); stdout
// a second table of the counts.
// Slots per pixel = sum(pixels x slots) / sum(pixels) over the combos the frame ran
// (frame::Renderer::shader_uses); null in JSON and "n/a" in the table when the frame counted none.
// A PSNR is null in JSON ("inf" in the table) when the two frames are identical.

#include "commands.hpp"
#include "compare_explain.hpp"
#include "compare_sheet.hpp"
#include "frame_measurement.hpp"
#include "frame_options.hpp"

#include "luxel/frame/image_difference.hpp"
#include "luxel/frame/renderer.hpp"
#include "luxel/shading/source/binaries.hpp"
#include "luxel/scenes/image_io.hpp"
#include "luxel/shading/shader_model.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace luxel::cli {

namespace {

struct CompareOptions {
  FrameOptions frame;
  std::string models = "ps_2_0,ps_2_b,ps_3_0";
  int frames = 5;
  bool explain = false;
  std::string out;
};

/// What one model's frame gave.
struct ModelRun : FrameMeasurement {
  std::string name;
};

nlohmann::json optional_number(std::optional<double> v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }

std::string fixed(std::optional<double> v, int decimals) {
  if (!v) return "n/a";
  if (std::isinf(*v)) return "inf";
  char b[64];
  std::snprintf(b, sizeof b, "%.*f", decimals, *v);
  return b;
}

struct Pair {
  const ModelRun* a;
  const ModelRun* b;
  frame::ImageDifference difference;
  rasterizer::Image heat;
  std::optional<Explanation> explanation;  ///< with --explain
  std::string label() const { return a->name + " vs " + b->name; }
};

/// Per cause, its count in `counts`, keyed by cause_name.
nlohmann::json cause_counts(const std::array<uint64_t, kCauses>& counts, int causes = kCauses) {
  nlohmann::json j = nlohmann::json::object();
  for (int c = 0; c < causes; ++c) j[std::string(cause_name(Cause(c)))] = counts[size_t(c)];
  return j;
}

nlohmann::json to_json(const CompareOptions& o, const std::vector<ModelRun>& runs, const std::vector<Pair>& pairs) {
  nlohmann::json j;
  j["scene"] = o.frame.scene;
  j["width"] = o.frame.settings.width;
  j["height"] = o.frame.settings.height;
  j["msaa"] = o.frame.settings.samples;
  j["camera"] = o.frame.settings.camera;
  j["threads"] = o.frame.threads;
  j["frames"] = o.frames;
  j["models"] = nlohmann::json::array();
  for (const ModelRun& r : runs) {
    nlohmann::json uses = nlohmann::json::array();
    for (const frame::ShaderUse& u : r.uses)
      uses.push_back({{"family", u.family},
                      {"combo", u.combo},
                      {"binary", std::string(shading::source::binary_name(u.binary))},
                      {"pixels", u.pixels},
                      {"slots", u.slots}});
    j["models"].push_back({{"model", r.name},
                           {"ms_per_frame", r.median_ms()},
                           {"ms_min", r.ms.front()},
                           {"ms_max", r.ms.back()},
                           {"slots_per_pixel", optional_number(r.slots_per_pixel())},
                           {"shader_uses", uses}});
  }
  j["pairs"] = nlohmann::json::array();
  for (const Pair& p : pairs) {
    const frame::ImageDifference& d = p.difference;
    j["pairs"].push_back({{"a", p.a->name},
                          {"b", p.b->name},
                          {"psnr_db", d.identical() ? nlohmann::json(nullptr) : nlohmann::json(d.psnr_db)},
                          {"max_error_steps", d.max_error},
                          {"mean_error_steps", d.mean_error},
                          {"differing_pixels", d.differing_pixels},
                          {"differing_share", d.differing_share()},
                          {"ms_per_frame", {p.a->median_ms(), p.b->median_ms()}},
                          {"slots_per_pixel", {optional_number(p.a->slots_per_pixel()), optional_number(p.b->slots_per_pixel())}}});
    if (p.explanation)
      j["pairs"].back()["explain"] = {{"differing_pixels", p.explanation->differing},
                                      {"pixels", cause_counts(p.explanation->pixels)},
                                      {"involved", cause_counts(p.explanation->involved, int(Cause::several))}};
  }
  return j;
}

void print_table(const std::vector<Pair>& pairs) {
  std::printf("%-18s %8s %4s %10s %8s %19s %19s\n", "pair", "PSNR dB", "max", "mean steps", "differ", "ms/frame a / b",
              "slots/pixel a / b");
  for (const Pair& p : pairs) {
    const frame::ImageDifference& d = p.difference;
    const std::string ms = fixed(p.a->median_ms(), 2) + " / " + fixed(p.b->median_ms(), 2);
    const std::string slots = fixed(p.a->slots_per_pixel(), 1) + " / " + fixed(p.b->slots_per_pixel(), 1);
    std::printf("%-18s %8s %4d %10.4f %7.3f%% %19s %19s\n", p.label().c_str(), fixed(d.psnr_db, 2).c_str(), d.max_error,
                d.mean_error, 100 * d.differing_share(), ms.c_str(), slots.c_str());
  }
}

void print_explanations(const std::vector<Pair>& pairs) {
  std::printf("\n%-18s %9s", "pixels by cause", "differ");
  for (int c = 0; c < kCauses; ++c) std::printf(" %14s", std::string(cause_name(Cause(c))).c_str());
  std::printf("\n");
  for (const Pair& p : pairs) {
    std::printf("%-18s %9llu", p.label().c_str(), static_cast<unsigned long long>(p.explanation->differing));
    for (uint64_t n : p.explanation->pixels) std::printf(" %14llu", static_cast<unsigned long long>(n));
    std::printf("\n");
  }
}

Legend cause_legend() {
  Legend l{"cause:", {}};
  for (int c = 0; c < kCauses; ++c) l.swatches.emplace_back(std::string(cause_name(Cause(c))), cause_colour(Cause(c)));
  return l;
}

/// Renders the scene as `model`, measured as frame_measurement.hpp says: the frame compared is the
/// first, as `luxel render --model` writes it; the models share the scene's textures and their
/// auto exposure's start (the first model's settled scale, so that the images differ by their
/// shaders alone).
std::optional<ModelRun> run_model(const FrameOptions& options, const scenes::Scene& scene, frame::FrameSettings settings,
                                  shading::ShaderModel model, int frames, rasterizer::Context& ctx, int& code,
                                  SharedRendering& shared) {
  settings.model = model;
  std::optional<FrameMeasurement> m = measure_frame(
      [&](const frame::FrameSettings& s) { return options.make_renderer("compare", scene, s, ctx, code, &shared); }, settings,
      frames, ctx);
  if (!m) return std::nullopt;
  return ModelRun{std::move(*m), std::string(shading::caps(model).name)};
}

}  // namespace

Runner add_compare_command(CLI::App& app) {
  auto o = std::make_shared<CompareOptions>();
  CLI::App* cmd = app.add_subcommand("compare", "Render a scene as several shader models and compare the images");
  o->frame.add_to(*cmd);
  cmd->add_option("--models", o->models, "Pixel-shader models to compare, comma-separated (at least two)")->capture_default_str();
  cmd->add_option("--frames", o->frames, "Timed frames per model, after one warm-up (ms per frame is their median)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd->add_flag("--explain", o->explain,
                "Attribute each pair's differing pixels to the SDK rule behind them (fog per vertex, the skin shader, the "
                "light count, water blur, the ps20 binary's normalization cube), found by drawing the pair again with rules "
                "made equal: a row of cause maps on the sheet, counts in the JSON and on stdout");
  cmd->add_option("--out", o->out, "Writes PREFIX.png (images and heat maps) and PREFIX.json (the numbers)")->required();
  return [cmd, o]() -> int {
    if (!cmd->parsed()) return -1;
    const auto start = std::chrono::steady_clock::now();
    int code = 0;
    const auto models = parse_models("compare", "--models", o->models, 2);
    if (!models) return 2;
    const auto context_options = o->frame.context_options("compare", code);
    if (!context_options) return code;
    frame::FrameSettings settings = o->frame.settings;
    const std::string png = o->out + ".png", json = o->out + ".json";
    const std::optional<scenes::Scene> scene = o->frame.prepare_scene("compare", settings, {png, json}, code);
    if (!scene) return code;

    rasterizer::Context ctx(*context_options);
    std::vector<ModelRun> runs;
    SharedRendering shared;  // the models' textures, and where their auto exposure starts
    for (shading::ShaderModel m : *models) {
      std::optional<ModelRun> run = run_model(o->frame, *scene, settings, m, o->frames, ctx, code, shared);
      if (!run) return code;
      runs.push_back(std::move(*run));
    }
    std::vector<Pair> pairs;
    for (size_t i = 0; i < runs.size(); ++i)
      for (size_t k = i + 1; k < runs.size(); ++k)
        pairs.push_back({&runs[i], &runs[k], frame::image_difference(runs[i].image, runs[k].image),
                         frame::difference_heat_map(runs[i].image, runs[k].image), std::nullopt});
    if (o->explain) {
      const FrameDrawer draw = [&](const scenes::Scene& s, const frame::FrameSettings& f) -> std::optional<rasterizer::Image> {
        const std::unique_ptr<frame::Renderer> r = o->frame.make_renderer("compare", s, f, ctx, code, &shared);
        if (!r) return std::nullopt;
        r->render(ctx);
        return r->image();
      };
      for (Pair& p : pairs) {
        std::fprintf(stderr, "luxel compare: explaining %s\n", p.label().c_str());
        const shading::ShaderModel a = (*models)[size_t(&*p.a - runs.data())], b = (*models)[size_t(&*p.b - runs.data())];
        const bool a_lower = int(a) < int(b);
        p.explanation = explain_pair(a_lower ? p.a->image : p.b->image, a_lower ? p.b->image : p.a->image, a_lower ? a : b,
                                     a_lower ? b : a, *scene, settings, draw);
        if (!p.explanation) return code;
      }
    }

    try {
      std::vector<std::vector<SheetCell>> rows(2);
      for (const ModelRun& r : runs) rows[0].push_back({r.name, &r.image});
      for (const Pair& p : pairs) rows[1].push_back({p.label(), &p.heat});
      std::vector<Legend> legends{heat_legend()};
      if (o->explain) {
        rows.emplace_back();
        for (const Pair& p : pairs) rows[2].push_back({p.label() + ": causes", &p.explanation->map});
        legends.push_back(cause_legend());
      }
      const rasterizer::Image sheet = compose_sheet(rows, legends);
      scenes::write_image(sheet.width, sheet.height, sheet.rgba, png);
      std::ofstream file(json);
      file << to_json(*o, runs, pairs).dump(2) << "\n";
      if (!file.flush()) throw std::runtime_error(json + ": cannot write it");
    } catch (const std::exception& e) {
      std::cerr << "luxel compare: " << e.what() << "\n";
      return 1;
    }
    print_table(pairs);
    if (o->explain) print_explanations(pairs);
    std::fflush(stdout);  // the table before the summary line, where both go to one terminal
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "luxel compare: %s at %dx%d, %dx MSAA: %zu models, %zu pairs, %d timed frames each -> %s, %s (%.1f s)\n",
                 o->frame.scene.c_str(), o->frame.settings.width, o->frame.settings.height, o->frame.settings.samples,
                 runs.size(), pairs.size(), o->frames, png.c_str(), json.c_str(), seconds);
    return 0;
  };
}

}  // namespace luxel::cli
