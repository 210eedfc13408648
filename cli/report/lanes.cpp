// The report's section "lanes": every variant of the shading catalog (catalog.hpp) on the SIMD
// lane against the same shader on the scalar lane, one pixel at a time in float, on the same
// inputs. luxel's frames run the SIMD lane; the scalar lane is the reference its tests read
// shaders against. The two run the same arithmetic in the same order, so the error is 0 but where
// a variant samples a texture in its combine stage (the ps_2_0 normalization cube): the scalar lane
// samples with the rasterizer's reference (filtering in double), the SIMD lane with its float32
// sampler, a few float roundings apart (tests/rasterizer/texture_test.cpp bounds them at 1e-6).
// Cost: the variant's counted slots (ps_3_0, or the last model the variant runs on) and ns per
// pixel on each lane.

#include "report/findings.hpp"
#include "report/sections.hpp"

#include "luxel/rasterizer/simd.hpp"
#include "luxel/shading/source/catalog.hpp"

#include <string>

namespace luxel::cli {

namespace {

namespace src = shading::source;

/// Pixels each variant's lanes are compared on, and timed on: one 64x64 tile, as the shader
/// benchmark times (there are hundreds of variants; `luxel cost --pixels` times longer runs).
constexpr int kComparedPixels = 4096;
constexpr int kTimedPixels = 4096;

/// The rows whose lanes differ on some pixel.
RowTest differing_lanes(const SectionResult& r) {
  return [&r](const ReportRow& row) { return value_of(r, row, "differing_share") > 0; };
}

/// How many variants give the same bits on both lanes, and how far the others are apart.
std::vector<std::string> lanes_findings(const SectionResult& r) {
  const RowTest differ = differing_lanes(r);
  const std::vector<const ReportRow*> differing = rows_where(r, differ);
  std::vector<std::string> findings = {std::to_string(r.rows.size() - differing.size()) + " of " + std::to_string(r.rows.size()) +
                                       " variants give the same bits on both lanes for every pixel"};
  if (differing.empty()) return findings;
  std::string names;
  for (const ReportRow* row : differing) names += (names.empty() ? "" : ", ") + row->scene;
  const Span abs = *span_of(r, "max_abs", differ), steps = *span_of(r, "max_steps", differ), share = *span_of(r, "differing_share", differ);
  findings.push_back("the other " + std::to_string(differing.size()) + " differ by at most " + text_of(r, "max_abs", abs.max) + ", " +
                     counted(text_of(r, "max_steps", steps.max), "step", "steps") + " once stored in 8 bits, on " +
                     span_text(r, "differing_share", share) + " % of the pixels: " + names);
  return findings;
}

SectionResult run_lanes(const ReportSettings& s) {
  SectionResult out;
  out.title = "every shader variant on the SIMD lane against the same shader on the scalar lane (the reference)";
  out.columns = {{"slots", "slots", ColumnKind::cost, "%.0f"},
                 {"ns_per_pixel_simd", "ns/px simd", ColumnKind::timing, "%.2f"},
                 {"ns_per_pixel_scalar", "ns/px scal", ColumnKind::timing, "%.2f"},
                 {"max_abs", "max |diff|", ColumnKind::error, "%.3g"},
                 {"max_steps", "8-bit steps", ColumnKind::error, "%.0f"},
                 {"differing_share", "differ %", ColumnKind::error, "%.2f", 100.0}};
  out.plot = {"SIMD lane against the scalar lane, per shader variant (0: the same bits)", "slots (ps_3_0, counted)",
              "largest difference of a channel", "slots", "max_abs", 1.0, false};
  const std::string lanes = std::string(rasterizer::simd::kIsaName) + ", " + std::to_string(rasterizer::simd::kLanes) + " floats";
  for (const src::ShaderVariant& v : src::shader_catalog()) {
    s.progress("lanes: " + v.family + " " + v.variant);
    const src::LaneAgreement a = src::compare_lanes(v, kComparedPixels);
    const src::LaneTimes t = src::time_lanes(v, kTimedPixels, s.timing_repeats);
    shading::ShaderModel model = v.models.back();
    for (shading::ShaderModel m : v.models)
      if (m == shading::ShaderModel::ps_3_0) model = m;
    // The combo is what was measured; only the variants whose lanes differ are named in the plot
    // (95 labels at 0 would hide each other).
    out.rows.push_back({v.family + " " + v.variant, std::to_string(a.pixels) + " random pixels", v.family,
                        a.differing > 0 ? v.variant : "",
                        "the scalar lane (float, one pixel at a time) on the same inputs, texel and interpolant values "
                        "drawn in [0.05, 1]; SIMD lane " + lanes,
                        {double(v.measure(*v.builds.binary_for(model)).total_slots()), t.simd_ns, t.scalar_ns, a.max_abs, double(a.max_steps),
                         a.pixels ? double(a.differing) / double(a.pixels) : 0.0}});
  }
  if (first_row(out, differing_lanes(out)))
    out.notes.push_back("The variants whose lanes differ sample a texture in their combine stage, which the scalar lane does with "
                        "the rasterizer's reference sampler (filtering in double) and the SIMD lane with its float32 sampler.");
  out.notes.push_back("The combine stage of each variant (texture reads excluded, as luxel cost times it), fed the same " +
                      std::to_string(kComparedPixels) + " pixels of inputs on both lanes; ns per pixel: median of " +
                      std::to_string(s.timing_repeats) + " runs of " + std::to_string(kTimedPixels) + " pixels.");
  out.notes.push_back("8-bit steps: after each result is clamped to [0, 1] and rounded, as the 8-bit target stores it.");
  out.findings = lanes_findings(out);
  return out;
}

}  // namespace

ReportSection lanes_section() {
  return {"lanes", "every shader variant on the SIMD lane against the scalar lane on the same inputs (should be 0)", run_lanes,
          false};
}

}  // namespace luxel::cli
