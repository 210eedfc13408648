// luxel cost [--shader all|<family>] [--pixels N] [--repeats R]: every Source shader variant of
// the shading catalog (catalog.hpp), fog variants included, on every card the SDK's rules allow
// it on — pixel shaders on ps_2_0 / ps_2_b / ps_3_0, the per-vertex VertexLitGeneric vertex
// shader (--shader vertexlit_vs) on vs_2_0 / vs_3_0 — with the SDK binary that card runs
// (binaries.hpp: a ps_3_0 card runs LightmappedGeneric's ps20b), that binary's counted DX9 slots,
// temps, constants, its model's limits, whether it fits and why not, and ns per pixel (per vertex
// for vertex shaders) on the SIMD and scalar lanes (the combine stage: texture sampling excluded),
// then the ambient cube's counts beside Valve's published ones. A report, not a benchmark:
// bench/shading_source_bench.cpp has the careful numbers.
//
// luxel cost --scene SCENE [--model M] [render's size, MSAA, thread and bake options] [--repeats R]:
// instead, what one frame of the scene costs on each pixel-shader model (or M): the pixels each
// shader combo shaded with its counted slots and slots x pixels (the frame's passes, post passes
// included) with the binary each ran, the median ms of each pass and of the frame over R frames
// after one, and the totals.
// Measured as `luxel compare` measures (frame_measurement.hpp), so its numbers are compare's.
//
// Rows are '|'-separated columns, so that scripts and the test (tests/cli/cost_test.cpp) can read
// them; the first lines say which CPU and lanes the times are from.

#include "commands.hpp"
#include "frame_measurement.hpp"
#include "frame_options.hpp"

#include "luxel/rasterizer/cpu_model.hpp"
#include "luxel/shading/source/catalog.hpp"
#include "luxel/shading/source/common.hpp"
#include "luxel/shading/source/spherical_harmonics.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace luxel::cli {

namespace {

namespace src = shading::source;
using shading::Cost;
using shading::ShaderModel;

struct CostOptions {
  std::string shader = "all";
  int pixels = 1 << 16;
  int repeats = 5;
  FrameOptions frame;  ///< --scene and what renders it
  std::string model = "ps_2_0,ps_2_b,ps_3_0";
};

std::string limit(int v) { return v >= shading::kUnlimited ? "-" : std::to_string(v); }

/// The model's budget as "arith/tex/temps/consts" (ps_2_0) or "total/temps/consts".
std::string limits_of(const shading::ShaderModelCaps& k) {
  const std::string slots = k.arithmetic_slots >= shading::kUnlimited
                                ? std::to_string(k.total_slots)
                                : limit(k.arithmetic_slots) + "+" + limit(k.texture_slots);
  return slots + "/" + std::to_string(k.temps) + "/" + std::to_string(k.constants);
}

void print_header(const CostOptions& o) {
  std::printf("cpu: %s\n", rasterizer::cpu_model().c_str());
  std::printf("lanes: %s, %d floats; ns/pixel (vertex shaders: ns/vertex): median of %d runs of %d pixels, combine stage "
              "only (texel values as inputs, texture sampling excluded)\n",
              rasterizer::simd::kIsaName, rasterizer::simd::kLanes, o.repeats, o.pixels);
  std::printf("%-19s | %-46s | %-6s | %-6s | %5s | %3s | %5s | %6s | %5s | %-16s | %-4s | %8s | %8s | %s\n", "shader",
              "variant", "card", "binary", "arith", "tex", "temps", "consts", "indir", "limits slots/t/c", "fits", "ns simd",
              "ns scal", "why not");
}

/// One card's row: the binary it runs (`binary`), counted (`c`) and checked against that binary's limits.
void print_row(const src::ShaderVariant& v, ShaderModel card, ShaderModel binary, const Cost& c, const src::LaneTimes& t) {
  const shading::ShaderModelCaps& k = shading::caps(binary);
  const shading::Verdict verdict = shading::fits(c, k);
  std::printf("%-19s | %-46s | %-6s | %-6s | %5d | %3d | %5d | %6d | %5d | %-16s | %-4s | %8.1f | %8.1f | %s\n",
              v.family.c_str(), v.variant.c_str(), std::string(shading::caps(card).name).c_str(),
              std::string(src::binary_name(binary)).c_str(), c.arithmetic_slots, c.texture_slots,
              c.temps, c.constant_registers(), c.texture_indirections, limits_of(k).c_str(), verdict ? "yes" : "NO",
              t.simd_ns, t.scalar_ns, verdict.reason.c_str());
}

void report_ambient_cube() {
  src::AmbientCube cube;
  auto body = [&](shading::CountedInputs& in) { return src::ambient_light<shading::Counted>(in.vector<3>(), cube); };
  const int ps30 = shading::measure(ShaderModel::ps_3_0, body).arithmetic_slots;
  const int ps20 = shading::measure(ShaderModel::ps_2_0, body).arithmetic_slots;
  const int vs20 = shading::measure(ShaderModel::vs_2_0, body).arithmetic_slots;
  std::printf("\nambient cube: ps_3_0 %d, ps_2_0 %d (+mov oC0), vs_2_0 %d slots | published: 11 PS / 6 VS (2006 notes), "
              "9 PS (SDK comment)\n",
              ps30, ps20, vs20);
  std::printf("  PS = the SDK's 9 (mul, cmp, cmp, mul, mad x5; the notes' 11 predate it); VS 6 needs relative "
              "addressing (mova), we select with slt/sge + lrp instead.\n");
  const src::Sh9Ambient sh9;
  const shading::Cost sh = shading::measure(ShaderModel::ps_3_0, [&](shading::CountedInputs& in) {
    return src::sh9_ambient_light<shading::Counted>(in.vector<3>(), sh9);
  });
  std::printf("SH9 ambient (ps_3_0 option): %d slots, %d constant registers (cube: %d slots, 6 registers); "
              "error vs ground truth: luxel report speed-error\n",
              sh.arithmetic_slots, sh.uniform_registers, ps30);
}

/// One model's frame: its combos, its passes and its totals, as rows of three tables.
struct FrameCost {
  std::string model;
  FrameMeasurement m;
};

void print_frame_costs(const std::vector<FrameCost>& costs, const CostOptions& o, int threads) {
  const frame::FrameSettings& s = o.frame.settings;
  std::printf("cpu: %s\n", rasterizer::cpu_model().c_str());
  std::printf("frame: %s, %dx%d, %d samples per pixel, %d threads; ms: median of %d frames after one, each pass run to its "
              "end before the next\n",
              o.frame.scene.c_str(), s.width, s.height, s.samples, threads, o.repeats);
  std::printf("\n%-6s | %-20s | %-54s | %-6s | %10s | %5s | %14s | %6s\n", "model", "shader", "combo", "binary", "pixels",
              "slots", "slots x pixels", "share");
  for (const FrameCost& c : costs) {
    const uint64_t total = c.m.shading_totals().slot_pixels;
    for (const frame::ShaderUse& u : c.m.uses) {
      const uint64_t sp = u.pixels * uint64_t(u.slots);
      std::printf("%-6s | %-20s | %-54s | %-6s | %10llu | %5d | %14llu | %5.1f%%\n", c.model.c_str(), u.family.c_str(),
                  u.combo.c_str(), std::string(src::binary_name(u.binary)).c_str(), static_cast<unsigned long long>(u.pixels),
                  u.slots, static_cast<unsigned long long>(sp),
                  total ? 100.0 * double(sp) / double(total) : 0.0);
    }
  }
  std::printf("\n%-6s | %-20s | %5s | %9s\n", "model", "pass", "draws", "ms");
  for (const FrameCost& c : costs)
    for (const frame::PassTime& p : c.m.passes)
      std::printf("%-6s | %-20s | %5d | %9.3f\n", c.model.c_str(), p.pass.c_str(), p.draws, p.ms);
  std::printf("\n%-6s | %13s | %14s | %11s | %17s | %12s\n", "model", "pixels shaded", "slots x pixels", "slots/pixel",
              "slots x px/screen", "ms per frame");
  for (const FrameCost& c : costs) {
    const FrameMeasurement::ShadingTotals t = c.m.shading_totals();
    std::printf("%-6s | %13llu | %14llu | %11.2f | %17.2f | %12.3f\n", c.model.c_str(), static_cast<unsigned long long>(t.pixels),
                static_cast<unsigned long long>(t.slot_pixels), c.m.slots_per_pixel().value_or(0.0),
                double(t.slot_pixels) / (double(s.width) * double(s.height)), c.m.median_ms());
  }
}

/// `luxel cost --scene`: the frame costs of each model; the exit code.
int run_frame_costs(CostOptions& o) {
  int code = 0;
  const auto models = parse_models("cost", "--model", o.model, 1);
  if (!models) return 2;
  const auto context_options = o.frame.context_options("cost", code);
  if (!context_options) return code;
  frame::FrameSettings settings = o.frame.settings;
  const std::optional<scenes::Scene> scene = o.frame.prepare_scene("cost", settings, {}, code);
  if (!scene) return code;
  rasterizer::Context ctx(*context_options);
  std::vector<FrameCost> costs;
  SharedRendering shared;  // the models' textures, and where their auto exposure starts
  for (ShaderModel model : *models) {
    settings.model = model;
    std::optional<FrameMeasurement> m = measure_frame(
        [&](const frame::FrameSettings& s) { return o.frame.make_renderer("cost", *scene, s, ctx, code, &shared); }, settings,
        o.repeats, ctx, true);
    if (!m) return code;
    costs.push_back({std::string(shading::caps(model).name), std::move(*m)});
  }
  print_frame_costs(costs, o, ctx.thread_count());
  return 0;
}

std::vector<std::string> shader_options() {
  std::vector<std::string> names = {"all"};
  for (const src::ShaderVariant& v : src::shader_catalog())
    if (std::find(names.begin(), names.end(), v.option) == names.end()) names.push_back(v.option);
  return names;
}

}  // namespace

Runner add_cost_command(CLI::App& app) {
  auto options = std::make_shared<CostOptions>();
  CLI::App* cmd = app.add_subcommand("cost", "Print DX9 slot counts, limits and ns/pixel of every Source shader variant");
  const std::vector<std::string> names = shader_options();
  std::string help;
  for (const std::string& n : names) help += (help.empty() ? "" : ", ") + n;
  cmd->add_option("--shader", options->shader, help)->check(CLI::IsMember(names))->capture_default_str();
  cmd->add_option("--pixels", options->pixels, "Pixels per timing run")->check(CLI::Range(64, 1 << 24))->capture_default_str();
  cmd->add_option("--repeats", options->repeats,
                  "Timing runs per variant and lane; with --scene, timed frames per model (the median is printed)")
      ->check(CLI::Range(1, 101))
      ->capture_default_str();
  options->frame.add_to(*cmd);
  CLI::Option* scene = cmd->get_option("--scene");
  scene->description("Print what one frame of this scene costs on each model instead: pixels and slots x pixels per "
                     "shader combo, ms per pass and per frame");
  cmd->add_option("--model", options->model, "With --scene: the pixel-shader models measured, comma-separated")
      ->needs(scene)
      ->capture_default_str();
  return [cmd, options, scene]() -> int {
    if (!cmd->parsed()) return -1;
    if (scene->count() > 0) return run_frame_costs(*options);
    print_header(*options);
    for (const src::ShaderVariant& v : src::shader_catalog()) {
      if (options->shader != "all" && options->shader != v.option) continue;
      const src::LaneTimes t = src::time_lanes(v, options->pixels, options->repeats);
      for (ShaderModel card : v.models) {
        const ShaderModel binary = *v.builds.binary_for(card);
        print_row(v, card, binary, v.measure(binary), t);
      }
    }
    report_ambient_cube();
    return 0;
  };
}

}  // namespace luxel::cli
