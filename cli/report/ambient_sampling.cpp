// The report's section "ambient_sampling": how a model's ambient cube is read from the irradiance
// volume (FrameSettings::ambient): the nearest sample's cube (the engine's) against the trilinear
// blend of the eight samples around the model's centroid. The bake keeps its gather internal, so
// the exact ambient at a centroid is not at hand: the trilinear frame is the reference, the
// smooth reading of the same samples, and its own row is 0 by construction. Cost: volume samples
// read per model and ms per frame; error: frame_error.hpp's columns.

#include "report/frame_error.hpp"
#include "report/report_scene.hpp"
#include "report/sections.hpp"

#include <string>
#include <utility>
#include <vector>

namespace luxel::cli {

namespace {

using frame::AmbientSampling;

SectionResult run_ambient_sampling(const ReportSettings& s) {
  const ReportScene& scene = *s.scene;
  SectionResult out;
  out.title = "a model's ambient cube from the irradiance volume: nearest sample against trilinear";
  out.columns = {{"volume_samples", "samples read", ColumnKind::cost, "%.0f"},
                 {"ms_per_frame", "ms/frame", ColumnKind::timing, "%.2f"}};
  for (const ReportColumn& c : frame_error_columns()) out.columns.push_back(c);
  out.plot = {"Ambient sampling: mean error against the trilinear frame", "irradiance-volume samples read per model",
              "mean error (8-bit steps)", "volume_samples", "mean_steps", 1.0, false};
  struct Variant {
    AmbientSampling sampling;
    const char* name;
    int samples_read;
  };
  std::vector<std::pair<Variant, FrameMeasurement>> runs;
  const Variant variants[] = {{AmbientSampling::nearest, "nearest (the engine's)", 1}, {AmbientSampling::trilinear, "trilinear", 8}};
  for (const Variant& v : variants) {
    s.progress(std::string("ambient_sampling: ") + v.name);
    frame::FrameSettings f = scene.settings;
    f.ambient = v.sampling;
    runs.emplace_back(v, scene.measure(f, s.timing_repeats));
  }
  const rasterizer::Image& reference = runs.back().second.image;
  const std::string how = scene.name + " drawn with trilinear ambient sampling, the same settings otherwise (not ground truth: "
                                       "the same volume samples, blended)";
  for (const auto& [v, m] : runs) {
    std::vector<double> values = {double(v.samples_read), m.median_ms()};
    for (double e : frame_error_values(m.image, reference)) values.push_back(e);
    out.rows.push_back({scene.name, scene.resolution(), v.name, v.name, how, values});
  }
  out.notes.push_back("Frames: the first of the sequence, the shaders' pixels (no bloom, no color correction, no film grain), " +
                      std::to_string(scene.settings.samples) + " samples per pixel, shader model " +
                      std::string(shading::caps(scene.settings.model).name) + "; " + std::to_string(scene.scene->models.size()) +
                      " models in the scene (a scene without models or without an irradiance volume gives two equal frames).");
  out.findings = findings_against_last_row(out);
  return out;
}

}  // namespace

ReportSection ambient_sampling_section() {
  return {"ambient_sampling", "nearest against trilinear ambient cubes from the irradiance volume, frames of --scene",
          run_ambient_sampling, true};
}

}  // namespace luxel::cli
