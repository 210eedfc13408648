// The report's section "msaa": the frame at 1, 2, 4 and 8 samples per pixel (FrameSettings::samples,
// the rasterizer's D3D sample patterns and box resolve) against two supersampled references, the
// same frame drawn kReferenceFactor times wider and taller with one sample per pixel and
// box-filtered down (box_filter.hpp): in the space the resolve averages in (the stored sRGB-encoded
// bytes: what MSAA converges to), and in linear light (what a float target's resolve would give:
// the second series adds the engine's gamma-space averaging to the error). Cost: samples per pixel
// and ms per frame (timed); error: frame_error.hpp's columns.
//
// The references read their textures at the mips of the frame they stand for (a LOD bias of
// log2 of the factor, FrameSettings::texture_lod_bias): drawn without it, every textured pixel of
// the reference is sharper than any MSAA frame can be, and that difference, not the edges, made
// most of every row's error. The references still shade every sub-pixel, MSAA once per pixel:
// what MSAA leaves alone (shading aliasing, the variation of a texture within a pixel at its mip)
// stays in every row's error, the floor the rows fall towards as the samples rise.

#include "report/box_filter.hpp"
#include "report/findings.hpp"
#include "report/frame_error.hpp"
#include "report/report_scene.hpp"
#include "report/sections.hpp"

#include "luxel/rasterizer/limits.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace luxel::cli {

namespace {

constexpr int kReferenceFactor = 8;

/// The largest factor up to kReferenceFactor that keeps the reference within the rasterizer's
/// largest target.
int reference_factor(const frame::FrameSettings& s) {
  return std::max(1, std::min(kReferenceFactor, rasterizer::kMaxTargetSize / std::max(s.width, s.height)));
}

/// The frame drawn `factor` times larger with one sample per pixel.
rasterizer::Image supersampled_frame(const ReportScene& scene, int factor) {
  frame::FrameSettings big = scene.settings;
  big.width *= factor, big.height *= factor, big.samples = 1;
  big.texture_lod_bias = std::log2(float(factor));
  const std::unique_ptr<frame::Renderer> renderer = scene.renderer(big);
  renderer->render(*scene.ctx);
  return renderer->image();
}

struct Reference {
  const char* variant;
  rasterizer::Image image;
  std::string how;
};

/// Per reference, how the mean error moves from the fewest samples to the most, and how many
/// pixels still differ at the most.
std::vector<std::string> msaa_findings(const SectionResult& r) {
  std::vector<std::string> findings;
  const std::optional<Span> samples = span_of(r, "samples", any_row);
  if (!samples) return findings;
  for (const std::string& variant : distinct(r, &ReportRow::variant, any_row)) {
    const ReportRow* fewest = first_row(r, both(variant_is(variant), value_is(r, "samples", samples->min)));
    const ReportRow* most = first_row(r, both(variant_is(variant), value_is(r, "samples", samples->max)));
    if (!fewest || !most) continue;
    const double from = value_of(r, *fewest, "mean_steps"), to = value_of(r, *most, "mean_steps");
    findings.push_back(variant + ": the mean error goes from " + text_of(r, "mean_steps", from) + " steps at " +
                       counted(text_of(r, "samples", samples->min), "sample", "samples") + " to " + text_of(r, "mean_steps", to) +
                       " at " + text_of(r, "samples", samples->max) + " (" + change_text(from, to) + "); at " +
                       text_of(r, "samples", samples->max) + " samples " +
                       text_of(r, "differing_share", value_of(r, *most, "differing_share")) + " % of the pixels still differ");
  }
  return findings;
}

SectionResult run_msaa(const ReportSettings& s) {
  const ReportScene& scene = *s.scene;
  const int factor = reference_factor(scene.settings);
  const std::string k = std::to_string(factor);
  SectionResult out;
  out.title = "MSAA at 1, 2, 4 and 8 samples per pixel against a " + k + "x" + k + " supersampled frame, box-filtered in "
              "sRGB (as the resolve) and in linear light";
  out.columns = {{"samples", "samples", ColumnKind::cost, "%.0f"}, {"ms_per_frame", "ms/frame", ColumnKind::timing, "%.2f"}};
  for (const ReportColumn& c : frame_error_columns()) out.columns.push_back(c);
  out.plot = {"MSAA: mean error against a " + k + "x" + k + " supersampled frame", "samples per pixel",
              "mean error (8-bit steps)", "samples", "mean_steps", 1.0, false};
  s.progress("msaa: the " + k + "x" + k + " supersampled references");
  const rasterizer::Image big = supersampled_frame(scene, factor);
  const std::string drawn = scene.name + " drawn at " + std::to_string(big.width) + "x" + std::to_string(big.height) +
                            " with 1 sample per pixel and its textures at the mips of the " + scene.resolution() +
                            " frame (LOD bias log2 " + k + "), each " + k + "x" + k + " block ";
  const Reference references[] = {
      {"MSAA vs sRGB-space box", box_filter_down(big, factor, BoxSpace::stored),
       drawn + "averaged in its stored 8-bit (sRGB-encoded) values, rounded half up, as the MSAA resolve averages a "
               "pixel's samples (cli/report/box_filter.hpp)"},
      {"MSAA vs linear-light box", box_filter_down(big, factor, BoxSpace::linear_light),
       drawn + "averaged in linear light: each color byte decoded as sRGB, the mean encoded again in double and rounded "
               "(cli/report/box_filter.hpp; $linearwrite pixels are decoded as sRGB too)"}};
  std::vector<std::pair<int, FrameMeasurement>> runs;
  for (int samples : {1, 2, 4, 8}) {
    s.progress("msaa: " + std::to_string(samples) + " samples per pixel");
    frame::FrameSettings f = scene.settings;
    f.samples = samples;
    runs.emplace_back(samples, scene.measure(f, s.timing_repeats));
  }
  for (const Reference& r : references)
    for (const auto& [samples, m] : runs) {
      std::vector<double> values = {double(samples), m.median_ms()};
      for (double e : frame_error_values(m.image, r.image)) values.push_back(e);
      out.rows.push_back({scene.name, scene.resolution(), r.variant, std::to_string(samples) + "x", r.how, values});
    }
  out.notes.push_back("Frames: the first of the sequence, the shaders' pixels (no bloom, no color correction, no film grain), "
                      "shader model " + std::string(shading::caps(scene.settings.model).name) + ".");
  out.notes.push_back("The reference shades every sub-pixel, MSAA once per pixel: shading aliasing and textures read at the "
                      "pixel's mip stay in every row's error. ms/frame: median of " + std::to_string(s.timing_repeats) +
                      " frames after one untimed.");
  out.findings = msaa_findings(out);
  return out;
}

}  // namespace

ReportSection msaa_section() {
  return {"msaa", "MSAA 1/2/4/8 samples against a supersampled frame of --scene", run_msaa, true};
}

}  // namespace luxel::cli
