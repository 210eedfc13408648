// The report's section "cubemaps": the HDR cube maps luxel bakes the seed's way (frame/cubemaps.hpp:
// each face rendered through the 8-bit target at a bracket of exposures and merged, as Source's
// buildcubemaps and an HDR camera would), for brackets 1 to 4 stops apart and for the middle
// exposure alone, against the same faces rendered to a float target (capture_face_float: no
// 8-bit rounding, no clamp). Error in stops, |log2(merged / float)| per channel, over the channels
// the bracket can see (at least one code above the merge's dark floor at the brightest exposure).
// Cost: captures per face, and ms per cube.

#include "report/findings.hpp"
#include "report/report_scene.hpp"
#include "report/sections.hpp"

#include "luxel/frame/cubemaps.hpp"
#include "luxel/frame/exposure_merge.hpp"
#include "luxel/rasterizer/texture.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

namespace luxel::cli {

namespace {

constexpr int kFaceSize = 16;

struct StopErrors {
  std::vector<double> errors;  ///< per channel seen, sorted when summarized
  double lo = INFINITY, hi = 0;
};

/// "max A to B stops, p99 C to D stops, mean E to F stops" over the rows that pass `rows`.
std::string stop_errors(const SectionResult& r, const RowTest& rows) {
  constexpr std::pair<const char*, const char*> kStopColumns[] = {{"max_stops", "max"}, {"p99_stops", "p99"}, {"mean_stops", "mean"}};
  std::string text;
  for (const auto& [key, name] : kStopColumns)
    if (const std::optional<Span> span = span_of(r, key, rows))
      text += (text.empty() ? "" : ", ") + std::string(name) + " " + span_text(r, key, *span) + " stops";
  return text;
}

/// The merged brackets' errors against one exposure's.
std::vector<std::string> cubemaps_findings(const SectionResult& r) {
  std::vector<std::string> findings;
  const RowTest brackets = [&r](const ReportRow& row) { return value_of(r, row, "captures_per_face") > 1; };
  const RowTest single = [&r](const ReportRow& row) { return value_of(r, row, "captures_per_face") == 1; };
  const std::vector<std::string> bracket_names = distinct(r, &ReportRow::variant, brackets);
  if (!bracket_names.empty())
    findings.push_back("merged brackets (" + bracket_names.front() + " to " + bracket_names.back() +
                       ") against the float captures: " + stop_errors(r, brackets));
  if (first_row(r, single)) findings.push_back("one exposure alone: " + stop_errors(r, single));
  return findings;
}

SectionResult run_cubemaps(const ReportSettings& s) {
  const ReportScene& scene = *s.scene;
  SectionResult out;
  out.title = "HDR cube maps merged from 8-bit captures at a bracket of exposures against float captures of the same faces";
  out.columns = {{"captures_per_face", "captures", ColumnKind::cost, "%.0f"},
                 {"ms_per_cube", "ms/cube", ColumnKind::timing, "%.1f"},
                 {"max_stops", "max stops", ColumnKind::error, "%.4f"},
                 {"p99_stops", "p99 stops", ColumnKind::error, "%.4f"},
                 {"mean_stops", "mean stops", ColumnKind::error, "%.4f"}};
  out.plot = {"HDR cube maps: the exposure merge against float captures", "captures per face (8-bit renders)",
              "p99 |log2(merged / float)| (stops)", "captures_per_face", "p99_stops", 1.0, true};
  const std::vector<scenes::CubemapSample>& samples = scene.scene->cubemap_samples;
  if (samples.empty()) {
    out.notes.push_back(scene.name + " has no cube-map samples: nothing to measure.");
    return out;
  }
  const shading::ShaderModel model = shading::ShaderModel::ps_3_0;
  // The float faces once: the reference of every row.
  std::vector<std::vector<glm::vec4>> reference;
  for (const scenes::CubemapSample& sample : samples)
    for (int f = 0; f < 6; ++f)
      reference.push_back(frame::capture_face_float(*scene.scene, sample.position, rasterizer::CubeFace(f), kFaceSize, model,
                                                    *scene.ctx, scene.textures));
  for (float stops : {1.0f, 2.0f, 3.0f, 4.0f, 0.0f}) {  // 0: the middle exposure of the 2-stop bracket alone
    const std::vector<float> bracket = frame::exposure_bracket(*scene.scene, stops > 0 ? stops : 2.0f);
    const std::vector<float> exposures = stops > 0 ? bracket : std::vector<float>{bracket[bracket.size() / 2]};
    const std::string variant = stops > 0 ? std::to_string(int(stops)) + " stops apart" : "one exposure";
    s.progress("cubemaps: " + variant);
    // Channels the bracket can see: above the dark floor at its brightest exposure.
    const float floor = rasterizer::kSrgbToLinear[frame::kDarkCode + 1] / bracket.back();
    StopErrors e;
    std::vector<double> ms;
    size_t face = 0;
    for (const scenes::CubemapSample& sample : samples) {
      const auto start = std::chrono::steady_clock::now();
      std::vector<std::vector<glm::vec4>> merged;
      for (int f = 0; f < 6; ++f) {
        std::vector<rasterizer::Image> images;
        for (float exposure : exposures)
          images.push_back(frame::capture_face(*scene.scene, sample.position, rasterizer::CubeFace(f), kFaceSize, exposure, model,
                                               *scene.ctx, scene.textures));
        merged.push_back(frame::merge_exposures(images, exposures));
      }
      ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
      for (const std::vector<glm::vec4>& m : merged) {
        const std::vector<glm::vec4>& want = reference[face++];
        for (size_t i = 0; i < m.size(); ++i)
          for (int c = 0; c < 3; ++c) {
            if (!(want[i][c] >= floor)) continue;
            e.errors.push_back(m[i][c] > 0 ? std::fabs(std::log2(double(m[i][c]) / double(want[i][c]))) : INFINITY);
            e.lo = std::min(e.lo, double(want[i][c])), e.hi = std::max(e.hi, double(want[i][c]));
          }
      }
    }
    std::sort(e.errors.begin(), e.errors.end());
    std::sort(ms.begin(), ms.end());
    double sum = 0;
    for (double x : e.errors) sum += x;
    const bool any = !e.errors.empty();
    out.rows.push_back({scene.name,
                        std::to_string(samples.size()) + " samples x 6 faces of " + std::to_string(kFaceSize) + "x" +
                            std::to_string(kFaceSize),
                        variant, stops > 0 ? std::to_string(exposures.size()) + " x " + std::to_string(int(stops)) : "1",
                        "the same faces rendered to a float target at tone-map scale 1 (frame::capture_face_float), over "
                        "the channels above the merge's dark floor (" + number(any ? std::log2(e.hi / e.lo) : 0.0, "%.1f") +
                            " stops of range)",
                        {double(exposures.size()), median_of_sorted(ms), any ? e.errors.back() : 0.0,
                         any ? e.errors[e.errors.size() * 99 / 100] : 0.0, any ? sum / double(e.errors.size()) : 0.0}});
  }
  out.notes.push_back("Each face: the world and the sky as a cube-map capture draws them (unfogged, no MSAA), as ps_3_0, "
                      "through the tone-map epilogue into 8 bits at each exposure of the bracket (frame::exposure_bracket: "
                      "powers of two from the scene's brightest sky to its darkest albedo), merged by "
                      "frame::merge_exposures. ms/cube: median over the samples, all six faces.");
  out.notes.push_back("\"one exposure\": the 2-stop bracket's middle exposure alone, what a capture without a bracket keeps.");
  out.findings = cubemaps_findings(out);
  return out;
}

}  // namespace

ReportSection cubemaps_section() {
  return {"cubemaps", "HDR cube maps merged from 8-bit exposure brackets against float captures of --scene's cube-map samples",
          run_cubemaps, true};
}

}  // namespace luxel::cli
