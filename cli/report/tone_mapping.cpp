// The report's section "tone_mapping": Source's integer-HDR way, the tone-map scale applied in the
// shader and the result clamped and sRGB-encoded into the 8-bit target, against a float target
// (HDR_TYPE_FLOAT: Renderer::render_float, the linear color each shader wrote at scale 1) scaled,
// clamped and encoded afterwards in double (shading::source::srgb8_reference), at fixed scales
// a stop apart around 1. render_float draws only what a cube-map capture draws (the world and the
// sky, unfogged, nothing blended, one sample), so both sides are the report's view drawn as a
// capture. Cost: the target's bytes per pixel and ms per frame of the 8-bit frame; error:
// frame_error.hpp's columns.

#include "report/findings.hpp"
#include "report/frame_error.hpp"
#include "report/report_scene.hpp"
#include "report/sections.hpp"

#include "luxel/shading/source/common.hpp"

#include <cstdio>
#include <string>
#include <vector>

namespace luxel::cli {

namespace {

/// The float frame at scale 1 times `scale`, clamped and encoded in double; alpha 255.
rasterizer::Image encoded_afterwards(const std::vector<glm::vec4>& linear, float scale, int width, int height) {
  rasterizer::Image image(width, height);
  for (size_t i = 0; i < linear.size(); ++i) {
    for (int c = 0; c < 3; ++c) image.rgba[i * 4 + size_t(c)] = shading::source::srgb8_reference(double(linear[i][c]) * scale);
    image.rgba[i * 4 + 3] = 255;
  }
  return image;
}

std::string scale_name(float scale) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", double(scale));
  return text;
}

/// The largest difference from the float target over every scale measured.
std::vector<std::string> tone_mapping_findings(const SectionResult& r) {
  const std::optional<Span> steps = span_of(r, "max_steps", any_row);
  const std::optional<Span> share = span_of(r, "differing_share", any_row);
  if (!steps || !share) return {};
  std::string scales;
  for (const ReportRow& row : r.rows) scales += (scales.empty() ? "" : ", ") + row.label;
  if (steps->max == 0) return {"the 8-bit target gives the float target's bytes at every scale measured (" + scales + ")"};
  return {"the 8-bit target is within " + counted(text_of(r, "max_steps", steps->max), "step", "steps") +
          " of the float target at every scale measured (" + scales + "), on " + span_text(r, "differing_share", *share) +
          " % of the pixels"};
}

SectionResult run_tone_mapping(const ReportSettings& s) {
  const ReportScene& scene = *s.scene;
  SectionResult out;
  out.title = "tone mapping in the shader into the 8-bit target against a float target tone-mapped afterwards";
  out.columns = {{"target_bytes_per_pixel", "target B/px", ColumnKind::cost, "%.0f"},
                 {"ms_per_frame", "ms/frame", ColumnKind::timing, "%.2f"}};
  for (const ReportColumn& c : frame_error_columns()) out.columns.push_back(c);
  out.plot = {"Tone mapping: the 8-bit target against a float target tone-mapped afterwards", "render target bytes per pixel",
              "mean error (8-bit steps)", "target_bytes_per_pixel", "mean_steps", 1.0, false};
  frame::FrameSettings capture = scene.settings;
  capture.cubemap_capture = true, capture.samples = 1, capture.exposure = 1.0f;
  s.progress("tone_mapping: the float target");
  const std::vector<glm::vec4> linear = scene.renderer(capture)->render_float(*scene.ctx);
  for (float scale : {0.5f, 1.0f, 2.0f}) {
    s.progress("tone_mapping: scale " + scale_name(scale));
    capture.exposure = scale;
    const FrameMeasurement m = scene.measure(capture, s.timing_repeats);
    std::vector<double> values = {4.0, m.median_ms()};
    for (double e : frame_error_values(m.image, encoded_afterwards(linear, scale, capture.width, capture.height)))
      values.push_back(e);
    out.rows.push_back({scene.name, scene.resolution(), "8-bit target, tone map in the shader at scale " + scale_name(scale),
                        "scale " + scale_name(scale),
                        scene.name + " drawn as a cube-map capture of the view into a float target at scale 1 "
                                     "(Renderer::render_float), times the scale, clamped and sRGB-encoded in double",
                        values});
  }
  out.notes.push_back("Both sides: the view drawn as a cube-map capture (world and sky, no models, no fog, nothing blended, 1 "
                      "sample, shader model " + std::string(shading::caps(scene.settings.model).name) +
                      "), the only frame render_float draws; fixed scales, no auto exposure. A float target holds 16 bytes "
                      "per pixel (RGBA32F) against the 8-bit target's 4.");
  out.findings = tone_mapping_findings(out);
  return out;
}

}  // namespace

ReportSection tone_mapping_section() {
  return {"tone_mapping", "the 8-bit target's in-shader tone map against a float target tone-mapped afterwards, on --scene",
          run_tone_mapping, true};
}

}  // namespace luxel::cli
