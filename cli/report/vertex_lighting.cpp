// The report's section "vertex_lighting": the models' two local lights attenuated per vertex
// (what the SDK's bumped and skin shaders do on every model, interpolating the attenuation
// across each triangle) against per pixel (FrameSettings::pixel_attenuation, luxel's option where
// the combo fits), on ps_2_b and ps_3_0, each against the per-pixel frame of the same model.
// ps_2_0 attenuates per vertex either way, its per-pixel combos rarely fitting its 64 arithmetic
// slots. Cost: counted
// slots per pixel and ms per frame, measured as `luxel compare` measures; error: frame_error.hpp's
// columns.

#include "report/findings.hpp"
#include "report/frame_error.hpp"
#include "report/report_scene.hpp"
#include "report/sections.hpp"

#include "luxel/shading/shader_model.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace luxel::cli {

namespace {

using shading::ShaderModel;

// The two ways of attenuating, the rows' variants, which the findings pair by their reference.
constexpr const char* kPerPixel = "per pixel";
constexpr const char* kPerVertex = "per vertex";

/// Per model, what attenuating per vertex saves in slots and changes in pixels against per pixel
/// (the per-pixel row of the same reference).
std::vector<std::string> vertex_lighting_findings(const SectionResult& r) {
  std::vector<std::string> findings;
  for (const ReportRow* vertex : rows_where(r, variant_is(kPerVertex))) {
    const ReportRow* pixel = first_row(r, [&](const ReportRow& row) { return row.variant == kPerPixel && row.reference == vertex->reference; });
    if (!pixel) continue;
    std::string text = vertex->label + ": " + frame_difference_text(r, *vertex);
    const double saved = value_of(r, *pixel, "slots_per_pixel") - value_of(r, *vertex, "slots_per_pixel");
    if (std::isfinite(saved))
      text += ", at " + text_of(r, "slots_per_pixel", std::abs(saved)) + (saved >= 0 ? " fewer" : " more") +
              " slots per pixel than the per-pixel frame";
    findings.push_back(text);
  }
  return findings;
}

SectionResult run_vertex_lighting(const ReportSettings& s) {
  const ReportScene& scene = *s.scene;
  SectionResult out;
  out.title = "the models' local lights attenuated per vertex against per pixel, on ps_2_b and ps_3_0";
  out.columns = {{"slots_per_pixel", "slots/px", ColumnKind::cost, "%.2f"}, {"ms_per_frame", "ms/frame", ColumnKind::timing, "%.2f"}};
  for (const ReportColumn& c : frame_error_columns()) out.columns.push_back(c);
  out.plot = {"Per-vertex against per-pixel attenuation: mean error against the per-pixel frame", "DX9 slots per pixel (counted)",
              "mean error (8-bit steps)", "slots_per_pixel", "mean_steps", 1.0, false};
  for (ShaderModel model : {ShaderModel::ps_2_b, ShaderModel::ps_3_0}) {
    const std::string name(shading::caps(model).name);
    frame::FrameSettings f = scene.settings;
    f.model = model;
    f.pixel_attenuation = true;
    s.progress("vertex_lighting: " + name + ", per pixel");
    const FrameMeasurement per_pixel = scene.measure(f, s.timing_repeats);
    f.pixel_attenuation = false;
    s.progress("vertex_lighting: " + name + ", per vertex");
    const FrameMeasurement per_vertex = scene.measure(f, s.timing_repeats);
    const std::string how = scene.name + " drawn as " + name + " with the lights attenuated per pixel";
    for (const auto& [m, variant] : {std::pair{&per_pixel, kPerPixel}, std::pair{&per_vertex, kPerVertex}}) {
      std::vector<double> values = {m->slots_per_pixel().value_or(std::numeric_limits<double>::quiet_NaN()), m->median_ms()};
      for (double e : frame_error_values(m->image, per_pixel.image)) values.push_back(e);
      out.rows.push_back({scene.name, scene.resolution(), std::string(variant), name + ", " + variant, how, values});
    }
  }
  out.notes.push_back("Frames: the first of the sequence, the shaders' pixels (no bloom, no color correction, no film grain), " +
                      std::to_string(scene.settings.samples) + " samples per pixel. Only models change: world surfaces are "
                      "lit by their lightmaps either way.");
  out.notes.push_back("slots/px: sum(pixels x counted slots) / sum(pixels) over the frame's shader combos, post passes "
                      "included. ms/frame: median of " + std::to_string(s.timing_repeats) + " frames after one untimed.");
  out.findings = vertex_lighting_findings(out);
  return out;
}

}  // namespace

ReportSection vertex_lighting_section() {
  return {"vertex_lighting", "the models' lights attenuated per vertex against per pixel, on ps_2_b and ps_3_0 frames of --scene",
          run_vertex_lighting, true};
}

}  // namespace luxel::cli
