// The report's section "texture_sampling": the frame with its texture reads filtered by the
// hardware rules (what DX9-era cards did: a LOD per quad, 8-bit weights and LOD fraction, 8-bit
// texels in fixed point, sRGB decoded after filtering) against the same frame filtered by the ideal
// rules (float, a LOD per pixel): rasterizer/texture.hpp, "Sampling rules"; docs/fidelity.md,
// "Texture sampling". Cost: ms per frame, measured as `luxel compare` measures it; error:
// frame_error.hpp's columns.

#include "report/frame_error.hpp"
#include "report/report_scene.hpp"
#include "report/sections.hpp"

#include <tuple>
#include <utility>
#include <vector>

namespace luxel::cli {

namespace {

using rasterizer::SamplingRules;

SectionResult run_texture_sampling(const ReportSettings& s) {
  const ReportScene& scene = *s.scene;
  SectionResult out;
  out.title = "texture reads by the hardware rules against the ideal rules";
  out.columns = {{"weight_bits", "weight bits", ColumnKind::cost, "%.0f"}, {"ms_per_frame", "ms/frame", ColumnKind::timing, "%.2f"}};
  for (const ReportColumn& c : frame_error_columns()) out.columns.push_back(c);
  out.plot = {"Texture sampling: error against the ideal rules", "bits of the filter weights", "mean error (8-bit steps)",
              "weight_bits", "mean_steps", 1.0, false};
  // The bits of a bilinear weight: 8 (16.8 fixed point), or a float's 24.
  const std::tuple<SamplingRules, const char*, double> rule_sets[] = {{SamplingRules::hardware, "hardware", 8.0},
                                                                      {SamplingRules::ideal, "ideal", 24.0}};
  std::vector<std::tuple<const char*, double, FrameMeasurement>> runs;
  for (const auto& [rules, name, bits] : rule_sets) {
    s.progress(std::string("texture_sampling: ") + name);
    frame::FrameSettings f = scene.settings;
    f.sampling = rules;
    runs.emplace_back(name, bits, scene.measure(f, s.timing_repeats));
  }
  const rasterizer::Image& reference = std::get<2>(runs.back()).image;
  const std::string how = scene.name + " with the ideal rules";
  for (const auto& [name, bits, m] : runs) {
    std::vector<double> values = {bits, m.median_ms()};
    for (double e : frame_error_values(m.image, reference)) values.push_back(e);
    out.rows.push_back({scene.name, scene.resolution(), name, name, how, values});
  }
  out.notes.push_back("Frames: the first of the sequence, the shaders' pixels (no bloom, no color correction, no film grain), " +
                      std::to_string(scene.settings.samples) +
                      " samples per pixel; the rules apply to every texture read of the 3D passes.");
  out.notes.push_back("weight bits: of a bilinear weight and of the LOD's fraction (16.8 fixed point, or a float's 24). "
                      "ms/frame: median of " + std::to_string(s.timing_repeats) + " frames after one untimed.");
  out.findings = findings_against_last_row(out);
  return out;
}

}  // namespace

ReportSection texture_sampling_section() {
  return {"texture_sampling", "--scene's frame with texture reads by the hardware rules against the ideal rules",
          run_texture_sampling, true};
}

}  // namespace luxel::cli
