// The report's section "shader_models": the frame drawn as ps_2_0, ps_2_b and ps_3_0
// (FrameSettings::model: each Source shader's combo as that model runs it, renderer.hpp), against
// the ps_3_0 frame, the most complete of the three. Cost: the counted DX9 slots per pixel and ms
// per frame, measured as `luxel compare` measures them (frame_measurement.hpp); error:
// frame_error.hpp's columns, the numbers `luxel compare` prints for the pair.

#include "report/findings.hpp"
#include "report/frame_error.hpp"
#include "report/report_scene.hpp"
#include "report/sections.hpp"

#include "luxel/shading/shader_model.hpp"

#include <limits>
#include <utility>
#include <vector>

namespace luxel::cli {

namespace {

using shading::ShaderModel;

/// Each model against ps_3_0, and what each costs.
std::vector<std::string> shader_models_findings(const SectionResult& r) {
  std::vector<std::string> findings = findings_against_last_row(r);
  if (span_of(r, "slots_per_pixel", any_row)) findings.push_back("slots per pixel: " + listing(r, "slots_per_pixel", any_row));
  return findings;
}

SectionResult run_shader_models(const ReportSettings& s) {
  const ReportScene& scene = *s.scene;
  SectionResult out;
  out.title = "the frame as ps_2_0, ps_2_b and ps_3_0 against the ps_3_0 frame";
  out.columns = {{"slots_per_pixel", "slots/px", ColumnKind::cost, "%.2f"}, {"ms_per_frame", "ms/frame", ColumnKind::timing, "%.2f"}};
  for (const ReportColumn& c : frame_error_columns()) out.columns.push_back(c);
  out.plot = {"Shader models: mean error against the ps_3_0 frame", "DX9 slots per pixel (counted)", "mean error (8-bit steps)",
              "slots_per_pixel", "mean_steps", 1.0, false};
  std::vector<std::pair<ShaderModel, FrameMeasurement>> runs;
  for (ShaderModel model : {ShaderModel::ps_2_0, ShaderModel::ps_2_b, ShaderModel::ps_3_0}) {
    s.progress("shader_models: " + std::string(shading::caps(model).name));
    frame::FrameSettings f = scene.settings;
    f.model = model;
    runs.emplace_back(model, scene.measure(f, s.timing_repeats));
  }
  const rasterizer::Image& reference = runs.back().second.image;
  const std::string how = scene.name + " drawn as ps_3_0 with the same settings";
  for (const auto& [model, m] : runs) {
    const std::string name(shading::caps(model).name);
    std::vector<double> values = {m.slots_per_pixel().value_or(std::numeric_limits<double>::quiet_NaN()), m.median_ms()};
    for (double e : frame_error_values(m.image, reference)) values.push_back(e);
    out.rows.push_back({scene.name, scene.resolution(), name, name, how, values});
  }
  out.notes.push_back("Frames: the first of the sequence, the shaders' pixels (no bloom, no color correction, no film grain), " +
                      std::to_string(scene.settings.samples) + " samples per pixel.");
  out.notes.push_back("slots/px: sum(pixels x counted slots) / sum(pixels) over the shader combos the frame ran, post passes "
                      "included (luxel compare's number; nan when the frame counts none). ms/frame: median of " +
                      std::to_string(s.timing_repeats) + " frames after one untimed.");
  out.findings = shader_models_findings(out);
  return out;
}

}  // namespace

ReportSection shader_models_section() {
  return {"shader_models", "ps_2_0, ps_2_b and ps_3_0 frames of --scene against the ps_3_0 frame", run_shader_models, true};
}

}  // namespace luxel::cli
