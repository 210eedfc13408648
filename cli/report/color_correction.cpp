// The report's section "color_correction": the engine's color correction (postfx/color_correction.hpp:
// the LUT resampled on the 32^3 lattice with 8-bit entries, trilinear in colorcorrection_ps2x, 8 bits
// in and out) of the report's frame, for each built-in grade preset at full weight, and the same
// with lattices of 16^3 and 64^3, against the grade applied exactly in float (color_correct_exact,
// what `luxel grade --exact` writes) and rounded to 8 bits once. Cost: the LUT's bytes as the
// volume texture, the pass's counted slots per pixel and ms per pass; error: frame_error.hpp's
// columns.

#include "report/findings.hpp"
#include "report/frame_error.hpp"
#include "report/report_scene.hpp"
#include "report/sections.hpp"

#include "luxel/postfx/color_correction.hpp"
#include "luxel/postfx/grade.hpp"
#include "luxel/postfx/lut_source.hpp"

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

namespace luxel::cli {

namespace {

/// The exact grade's floats rounded to 8 bits (postfx::to_unorm8), alpha included.
rasterizer::Image rounded(const std::vector<float>& rgba, int width, int height) {
  rasterizer::Image image(width, height);
  std::transform(rgba.begin(), rgba.end(), image.rgba.begin(), postfx::to_unorm8);
  return image;
}

/// Per lattice, the largest and the mean difference from the exact grades over the presets.
std::vector<std::string> color_correction_findings(const SectionResult& r) {
  std::vector<std::string> findings;
  for (const std::string& lattice : distinct(r, &ReportRow::variant, any_row)) {
    const std::optional<Span> max = span_of(r, "max_steps", variant_is(lattice));
    const std::optional<Span> mean = span_of(r, "mean_steps", variant_is(lattice));
    if (!max || !mean) continue;
    findings.push_back(lattice + ": within " + counted(text_of(r, "max_steps", max->max), "step", "steps") + " of the exact grade on " +
                       std::to_string(rows_where(r, variant_is(lattice)).size()) + " presets, mean " +
                       span_text(r, "mean_steps", *mean) + " steps");
  }
  return findings;
}

SectionResult run_color_correction(const ReportSettings& s) {
  const ReportScene& scene = *s.scene;
  SectionResult out;
  out.title = "the engine's 32^3 8-bit color-correction LUT, and 16^3 and 64^3 ones, against the grade applied exactly, per "
              "built-in preset";
  out.columns = {{"lut_kib", "LUT KiB", ColumnKind::cost, "%.0f"},
                 {"slots_per_pixel", "slots/px", ColumnKind::cost, "%.0f"},
                 {"ms_per_pass", "ms/pass", ColumnKind::timing, "%.3f"}};
  for (const ReportColumn& c : frame_error_columns()) out.columns.push_back(c);
  out.plot = {"Color correction: the LUT against the exact grade, per lattice size", "LUT volume (KiB, RGBA8)",
              "mean error (8-bit steps)", "lut_kib", "mean_steps", 1.0, false};
  s.progress("color_correction: the frame");
  const std::unique_ptr<frame::Renderer> renderer = scene.renderer(scene.settings);
  renderer->render(*scene.ctx);
  const rasterizer::Image& frame = renderer->image();
  for (int size : {16, postfx::kLutSize, 64}) {
    for (const std::string& preset : postfx::grade_preset_names()) {
      const std::string lattice = std::to_string(size) + "^3";
      s.progress("color_correction: builtin:" + preset + ", " + lattice);
      const postfx::ColorTransform transform = postfx::color_transform_named("builtin:" + preset);
      const postfx::Lut lut = postfx::sample_lut(transform, size);
      const postfx::WeightedLut weighted_lut[] = {{&lut, 1.0f}};
      const postfx::WeightedTransform weighted_transform[] = {{&transform, 1.0f}};
      std::vector<shading::source::ShaderUse> uses;
      const rasterizer::Image engine = postfx::color_correct(*scene.ctx, frame, weighted_lut, {&uses, scene.settings.model});
      std::vector<double> ms;
      for (int i = 0; i < s.timing_repeats; ++i) {
        const auto start = std::chrono::steady_clock::now();
        postfx::color_correct(*scene.ctx, frame, weighted_lut);
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
      }
      std::sort(ms.begin(), ms.end());
      const rasterizer::Image exact = rounded(postfx::color_correct_exact(frame, weighted_transform), frame.width, frame.height);
      std::vector<double> values = {double(size) * size * size * 4 / 1024.0, uses.empty() ? 0.0 : double(uses.front().slots),
                                    median_of_sorted(ms)};
      for (double e : frame_error_values(engine, exact)) values.push_back(e);
      out.rows.push_back({scene.name, scene.resolution(),
                          lattice + " 8-bit LUT" + (size == postfx::kLutSize ? " (the engine's)" : ""), preset,
                          "builtin:" + preset + " (" + transform.description + ") applied in float to each pixel of " +
                              scene.name + "'s frame (postfx::color_correct_exact), rounded to 8 bits once",
                          values});
    }
  }
  out.notes.push_back("Frame: the first of the sequence, the shaders' pixels (no bloom, no color correction of its own, no film "
                      "grain), " + std::to_string(scene.settings.samples) + " samples per pixel, shader model " +
                      std::string(shading::caps(scene.settings.model).name) + "; each preset at weight 1.");
  out.notes.push_back("slots/px: the color-correction draw's counted slots on that model. ms/pass: median of " +
                      std::to_string(s.timing_repeats) + " passes after the counted one.");
  out.findings = color_correction_findings(out);
  return out;
}

}  // namespace

ReportSection color_correction_section() {
  return {"color_correction", "the engine's 32^3 8-bit LUT against each built-in grade applied exactly, on a frame of --scene",
          run_color_correction, true};
}

}  // namespace luxel::cli
