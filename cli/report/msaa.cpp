// The report's section "msaa": the frame at 1, 2, 4 and 8 samples per pixel (FrameSettings::samples,
// the rasterizer's D3D sample patterns and box resolve) against a supersampled reference: the same
// frame drawn kReferenceFactor times wider and taller with one sample per pixel and box-filtered
// down in the space the resolve averages in (box_filter.hpp). Cost: samples per pixel (counted)
// and ms per frame (timed); error: frame_error.hpp's columns.
//
// The reference shades every sub-pixel, MSAA once per pixel: what MSAA leaves alone (shading
// aliasing, textures read at the pixel's mip rather than the sub-pixel's) stays in every row's
// error, the floor the rows fall towards as the samples rise.

#include "report/box_filter.hpp"
#include "report/frame_error.hpp"
#include "report/report_scene.hpp"
#include "report/sections.hpp"

#include "luxel/rasterizer/limits.hpp"

#include <algorithm>

namespace luxel::cli {

namespace {

constexpr int kReferenceFactor = 8;

/// The largest factor up to kReferenceFactor that keeps the reference within the rasterizer's
/// largest target.
int reference_factor(const frame::FrameSettings& s) {
  return std::max(1, std::min(kReferenceFactor, rasterizer::kMaxTargetSize / std::max(s.width, s.height)));
}

rasterizer::Image supersampled_reference(const ReportScene& scene, int factor) {
  frame::FrameSettings big = scene.settings;
  big.width *= factor, big.height *= factor, big.samples = 1;
  const std::unique_ptr<frame::Renderer> renderer = scene.renderer(big);
  renderer->render(*scene.ctx);
  return box_filter_down(renderer->image(), factor);
}

SectionResult run_msaa(const ReportSettings& s) {
  const ReportScene& scene = *s.scene;
  const int factor = reference_factor(scene.settings);
  const std::string k = std::to_string(factor);
  SectionResult out;
  out.title = "MSAA at 1, 2, 4 and 8 samples per pixel against a " + k + "x" + k + " supersampled frame";
  out.columns = {{"samples", "samples", ColumnKind::cost, "%.0f"}, {"ms_per_frame", "ms/frame", ColumnKind::timing, "%.2f"}};
  for (const ReportColumn& c : frame_error_columns()) out.columns.push_back(c);
  out.plot = {"MSAA: mean error against a " + k + "x" + k + " supersampled frame", "samples per pixel",
              "mean error (8-bit steps)", "samples", "mean_steps", 1.0, false};
  s.progress("msaa: the " + k + "x" + k + " supersampled reference");
  const rasterizer::Image reference = supersampled_reference(scene, factor);
  const std::string how = scene.name + " drawn at " + std::to_string(scene.settings.width * factor) + "x" +
                          std::to_string(scene.settings.height * factor) + " with 1 sample per pixel, each " + k + "x" + k +
                          " block averaged in its 8-bit (sRGB-encoded) values and rounded half up, as the MSAA resolve "
                          "averages a pixel's samples (cli/report/box_filter.hpp)";
  for (int samples : {1, 2, 4, 8}) {
    s.progress("msaa: " + std::to_string(samples) + " samples per pixel");
    frame::FrameSettings f = scene.settings;
    f.samples = samples;
    const FrameMeasurement m = scene.measure(f, s.timing_repeats);
    std::vector<double> values = {double(samples), m.median_ms()};
    for (double e : frame_error_values(m.image, reference)) values.push_back(e);
    out.rows.push_back({scene.name, scene.resolution(), "MSAA", std::to_string(samples) + "x", how, values});
  }
  out.notes.push_back("Frames: the first of the sequence, the shaders' pixels (no bloom, no color correction, no film grain), "
                      "shader model " + std::string(shading::caps(scene.settings.model).name) + ".");
  out.notes.push_back("The reference shades every sub-pixel, MSAA once per pixel: shading aliasing and textures read at the "
                      "pixel's mip stay in every row's error. ms/frame: median of " + std::to_string(s.timing_repeats) +
                      " frames after one untimed.");
  return out;
}

}  // namespace

ReportSection msaa_section() {
  return {"msaa", "MSAA 1/2/4/8 samples against a supersampled frame of --scene", run_msaa, true};
}

}  // namespace luxel::cli
