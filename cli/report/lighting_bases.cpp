// The report's section "lighting_bases": the ambient term of models three ways — the ambient cube
// (6 colors, VRAD's fit, ps_2_0 and up), linear SH (4 colors, bands 0-1) and SH9 (9 colors,
// ps_3_0) — for each environment: R&H 2001's three published probes (always) and every .hdr light
// probe under --probes (angular maps and lat-long, environment_image.hpp). Per variant its counted
// ps_3_0 slots and constant registers, ns per pixel on both lanes, and per environment its error
// against ground-truth irradiance (sphere_quadrature.hpp, irradiance_error.hpp). And, when
// grace_probe.hdr is among the probes, R&H's Grace Cathedral coefficients reproduced from it.
//
// Not yet: the courtyard's own ambient (radiance around a point of builtin:courtyard needs the
// bake's gather, which bake/ keeps internal).

#include "report/environment_image.hpp"
#include "report/findings.hpp"
#include "report/lane_timing.hpp"
#include "report/sections.hpp"

#include "luxel/scenes/image_io.hpp"
#include "luxel/shading/cost.hpp"
#include "luxel/shading/source/common.hpp"
#include "luxel/shading/source/irradiance_error.hpp"
#include "luxel/shading/source/ramamoorthi2001.hpp"
#include "luxel/shading/source/sphere_quadrature.hpp"
#include "luxel/shading/source/spherical_harmonics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <limits>
#include <optional>
#include <tuple>

namespace luxel::cli {

namespace {

namespace src = shading::source;
using shading::float3;

struct Environment {
  std::string scene, resolution, label, reference;
  src::SampledRadiance samples;
};

/// What each variant is fitted to: the environment's three fits.
struct Fits {
  src::AmbientCube cube;
  src::Sh4Ambient sh4;
  src::Sh9Ambient sh9;
};

/// A basis: its name, its shader code on the float lane (what the errors are measured on), its
/// counted cost and its times.
struct Variant {
  std::string name;
  std::function<float3<float>(const float3<float>&, const Fits&)> scalar;
  shading::Cost cost;
  double simd_ns = 0.0, scalar_ns = 0.0;
};

// The bases' variant names, which the findings pick rows by.
constexpr const char* kCubeBasis = "ambient cube (ps_2_0+)";
constexpr const char* kSh4Basis = "linear SH4 (ps_2_0+)";
constexpr const char* kSh9Basis = "SH9 (ps_3_0)";
// The start of the published environments' resolution, which tells their rows from the probes'.
constexpr const char* kAnalyticResolution = "analytic";

/// The three variants with their counted ps_3_0 costs and their times. The times do not depend on
/// the constants' values, so one made-up set serves every environment.
std::vector<Variant> variants(int repeats) {
  Fits f;
  for (size_t i = 0; i < 6; ++i) f.cube.color[i] = glm::vec3(0.1f * float(i + 1));
  for (size_t i = 0; i < 4; ++i) f.sh4.k[i] = glm::vec3(0.05f * float(i + 1));
  for (size_t i = 0; i < 9; ++i) f.sh9.k[i] = glm::vec3(0.05f * float(i + 1));
  auto cube = [&f](const auto& n) { return src::ambient_light(n, f.cube); };
  auto sh4 = [&f](const auto& n) { return src::sh4_ambient_light(n, f.sh4); };
  auto sh9 = [&f](const auto& n) { return src::sh9_ambient_light(n, f.sh9); };
  auto measure = [](const auto& eval) {
    return shading::measure(shading::ShaderModel::ps_3_0, [&](shading::CountedInputs& in) { return eval(in.vector<3>()); });
  };
  std::vector<Variant> v = {
      {kCubeBasis, [](const float3<float>& n, const Fits& x) { return src::ambient_light(n, x.cube); }, measure(cube)},
      {kSh4Basis, [](const float3<float>& n, const Fits& x) { return src::sh4_ambient_light(n, x.sh4); }, measure(sh4)},
      {kSh9Basis, [](const float3<float>& n, const Fits& x) { return src::sh9_ambient_light(n, x.sh9); }, measure(sh9)}};
  std::tie(v[0].simd_ns, v[0].scalar_ns) = time_normal_function(cube, repeats);
  std::tie(v[1].simd_ns, v[1].scalar_ns) = time_normal_function(sh4, repeats);
  std::tie(v[2].simd_ns, v[2].scalar_ns) = time_normal_function(sh9, repeats);
  return v;
}

// ---- Environments ------------------------------------------------------------------------------

std::string grid_reference(int rows, int normals) {
  return "E(n) = sum of L max(0, n.w) dw over an equal-area grid of " + std::to_string(rows) + "x" + std::to_string(2 * rows) +
         " cells, double (sphere_quadrature.hpp; closed forms: tests/shading/sphere_quadrature_test.cpp); " +
         std::to_string(normals) + " Fibonacci normals";
}

std::string image_reference(size_t pixels, int normals) {
  return "E(n) = sum over the image's " + std::to_string(pixels) +
         " pixels of L max(0, n.w) x the pixel's solid angle, double (sphere_quadrature.hpp, environment_image.hpp; "
         "closed forms: tests/shading/sphere_quadrature_test.cpp, tests/cli/environment_image_test.cpp); " +
         std::to_string(normals) + " Fibonacci normals";
}

std::vector<Environment> published_environments(const ReportSettings& s) {
  std::vector<Environment> r;
  for (const src::PublishedProbe& p : src::kRamamoorthi2001Probes) {
    const src::Sh9 sh = src::physical_radiance(src::published_radiance(p));
    r.push_back({std::string(p.name) + " (R&H 2001 SH9, lifted)",
                 std::string(kAnalyticResolution) + ", " + std::to_string(s.grid_rows) + "x" + std::to_string(2 * s.grid_rows) + " grid",
                 std::string(p.name) + " R&H",
                 grid_reference(s.grid_rows, s.normals),
                 src::sample_sphere_grid([&](const glm::dvec3& d) { return src::evaluate(sh, d); }, s.grid_rows)});
  }
  return r;
}

/// The .hdr files under the folder, sorted; a note when there is none.
std::vector<std::filesystem::path> probe_files(const std::string& folder, std::vector<std::string>& notes) {
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  if (folder.empty()) {
    notes.push_back("probes: none given; the probe rows are skipped (--probes DIR)");
    return files;
  }
  if (!std::filesystem::is_directory(folder, ec)) {
    notes.push_back("probes: " + folder + " is not a folder; the probe rows are skipped (--probes DIR)");
    return files;
  }
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder))
    if (entry.is_regular_file() && entry.path().extension() == ".hdr") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  if (files.empty()) notes.push_back("probes: no .hdr file under " + folder + "; the probe rows are skipped");
  return files;
}

Environment probe_environment(const std::filesystem::path& file, const std::string& folder, int normals) {
  const scenes::PixelImage image = scenes::read_image(file.string());
  const EnvironmentMapping mapping = mapping_of(image, file.string());
  Environment e;
  e.scene = std::filesystem::relative(file, folder).generic_string();
  e.resolution = std::to_string(image.width) + "x" + std::to_string(image.height) + " " + mapping_name(mapping);
  e.label = file.stem().string();
  e.samples = environment_samples(image, mapping, file.string());
  e.reference = image_reference(e.samples.size(), normals);
  return e;
}

// ---- R&H 2001's Grace Cathedral, reproduced ------------------------------------------------------

/// Our projection of grace_probe.hdr against the published coefficients: they agree up to the
/// exposure of the copy (the probe's copies differ in exposure), so a least-squares scale
/// published ≈ s × ours, per channel too, then each coefficient after scaling.
void reproduce_grace(const Environment& e, std::vector<std::string>& notes, nlohmann::json& details) {
  static const char* kNames[9] = {"L00", "L1-1", "L10", "L11", "L2-2", "L2-1", "L20", "L21", "L22"};
  const src::Sh9 ours = src::project_sh9(e.samples);
  const src::PublishedProbe& published = src::kRamamoorthi2001Probes[0];
  double pm = 0.0, mm = 0.0;
  glm::dvec3 pm_c(0.0), mm_c(0.0);
  for (size_t i = 0; i < 9; ++i) {
    pm += glm::dot(published.radiance[i], ours.c[i]), mm += glm::dot(ours.c[i], ours.c[i]);
    pm_c += published.radiance[i] * ours.c[i], mm_c += ours.c[i] * ours.c[i];
  }
  const double scale = pm / mm;
  const glm::dvec3 per_channel = pm_c / mm_c;
  double worst = 0.0;
  int signs = 0;
  nlohmann::json rows = nlohmann::json::array();
  std::vector<std::string> lines;
  for (size_t i = 0; i < 9; ++i) {
    const glm::dvec3 scaled = ours.c[i] * scale, p = published.radiance[i];
    std::string line = "  " + std::string(kNames[i]) + std::string(5 - std::string(kNames[i]).size(), ' ');
    for (int c = 0; c < 3; ++c) {
      worst = std::max(worst, std::abs(scaled[c] - p[c]));
      signs += (scaled[c] >= 0.0) == (p[c] >= 0.0);
      line += number(ours.c[i][c], " %9.5f") + " ->" + number(scaled[c], " %8.5f") + " (" + number(p[c], "%8.5f") + ")";
    }
    lines.push_back(line);
    rows.push_back({{"coefficient", kNames[i]},
                    {"ours", {ours.c[i].x, ours.c[i].y, ours.c[i].z}},
                    {"published", {p.x, p.y, p.z}}});
  }
  notes.push_back("R&H 2001 Grace Cathedral from " + e.scene + " (its pixels projected on the SH9 basis): published = " +
                  number(scale, "%.5f") + " x ours (least squares; per channel " + number(per_channel.x, "%.4f") + " " +
                  number(per_channel.y, "%.4f") + " " + number(per_channel.z, "%.4f") + "), largest difference after scaling " +
                  number(worst, "%.4f") + ", " + std::to_string(signs) + " of 27 signs agree");
  notes.push_back("  coeff  R: ours -> scaled (published)           G                                B");
  notes.insert(notes.end(), lines.begin(), lines.end());
  details["rh2001_grace"] = {{"file", e.scene}, {"scale", scale}, {"scale_per_channel", {per_channel.x, per_channel.y, per_channel.z}},
                             {"max_difference_after_scaling", worst}, {"signs_agreeing", signs}, {"coefficients", rows}};
}

// ---- The section ----------------------------------------------------------------------------------

std::vector<ReportColumn> columns() {
  return {{"slots", "slots", ColumnKind::cost, "%.0f"},
          {"constant_registers", "consts", ColumnKind::cost, "%.0f"},
          {"ns_per_pixel_simd", "ns/px simd", ColumnKind::timing, "%.2f"},
          {"ns_per_pixel_scalar", "ns/px scal", ColumnKind::timing, "%.2f"},
          {"max_relative", "max %", ColumnKind::error, "%.3f", 100.0},
          {"mean_relative", "mean %", ColumnKind::error, "%.3f", 100.0},
          {"rms_relative", "rms %", ColumnKind::error, "%.3f", 100.0},
          {"max_of_peak", "max/peak %", ColumnKind::error, "%.3f", 100.0},
          {"max_steps", "8-bit steps", ColumnKind::error, "%.0f"}};
}

void add_rows(const Environment& e, const std::vector<Variant>& vars, int normal_count, SectionResult& out) {
  const std::vector<glm::dvec3> normals = src::fibonacci_normals(normal_count);
  std::vector<glm::dvec3> truth;
  truth.reserve(normals.size());
  for (const glm::dvec3& n : normals) truth.push_back(src::irradiance(e.samples, n));
  const src::Sh9 irradiance = src::convolve_cosine(src::project_sh9(e.samples));
  const Fits fits{src::fit_ambient_cube(e.samples), src::sh4_ambient_constants(irradiance), src::sh9_ambient_constants(irradiance)};
  for (const Variant& v : vars) {
    std::vector<glm::dvec3> approx;
    for (const glm::dvec3& n : normals) {
      const float3<float> a = v.scalar(float3<float>(float(n.x), float(n.y), float(n.z)), fits);
      approx.emplace_back(a.x, a.y, a.z);
    }
    const src::IrradianceError err = src::irradiance_error(truth, approx);
    out.rows.push_back({e.scene, e.resolution, v.name, e.label, e.reference,
                        {double(v.cost.arithmetic_slots), double(v.cost.uniform_registers), v.simd_ns, v.scalar_ns,
                         err.max_relative, err.mean_relative, err.rms_relative, err.max_of_peak, double(err.max_steps)}});
  }
}

// ---- Findings --------------------------------------------------------------------------------------

/// The bases in the order the findings name them, with the name they are given there.
constexpr std::pair<const char*, const char*> kBasesNamed[] = {{kSh9Basis, "SH9"}, {kCubeBasis, "the cube"}, {kSh4Basis, "SH4"}};

bool published_row(const ReportRow& row) { return row.resolution.starts_with(kAnalyticResolution); }
bool probe_row(const ReportRow& row) { return !published_row(row); }

/// "SH9's A to B %, the cube's C to D %, SH4's E to F %": each basis's largest error over the peak
/// irradiance, over the rows that pass `environments`.
std::string max_of_peak_per_basis(const SectionResult& r, const RowTest& environments) {
  std::string text;
  for (const auto& [variant, name] : kBasesNamed)
    if (const std::optional<Span> span = span_of(r, "max_of_peak", both(environments, variant_is(variant))))
      text += (text.empty() ? "" : ", ") + std::string(name) + "'s " + span_text(r, "max_of_peak", *span) + " %";
  return text;
}

/// On how many of the environments that pass `environments` SH9's largest error over the peak is
/// below both other bases', and by how much (the smaller of the other two over SH9's).
std::string sh9_smallest(const SectionResult& r, const RowTest& environments) {
  const std::vector<std::string> scenes = distinct(r, &ReportRow::scene, environments);
  std::vector<double> ratios;
  int smallest = 0;
  for (const std::string& scene : scenes) {
    auto basis = [&](const char* variant) {
      const ReportRow* row = first_row(r, both(scene_is(scene), variant_is(variant)));
      return row ? value_of(r, *row, "max_of_peak") : std::numeric_limits<double>::quiet_NaN();
    };
    const double sh9 = basis(kSh9Basis), others = std::min(basis(kCubeBasis), basis(kSh4Basis));
    if (!(sh9 < others)) continue;
    ++smallest;
    if (sh9 > 0) ratios.push_back(others / sh9);
  }
  std::string text = "SH9's is the smallest of the three on " + std::to_string(smallest) + " of them";
  if (const std::optional<Span> times = span_of(ratios))
    text += ", the better of the other two " + number(times->min, "%.1f") + " to " + number(times->max, "%.1f") + " times it there";
  return text;
}

/// What each basis costs: "SH9 takes 11 ps_3_0 slots and 9 constant registers, the cube 9 and 6, SH4 3 and 4".
std::string bases_cost(const SectionResult& r) {
  std::string text;
  for (const auto& [variant, name] : kBasesNamed) {
    const ReportRow* row = first_row(r, variant_is(variant));
    if (!row) continue;
    const std::string slots = text_of(r, "slots", value_of(r, *row, "slots")),
                      registers = text_of(r, "constant_registers", value_of(r, *row, "constant_registers"));
    text += text.empty() ? std::string(name) + " takes " + slots + " ps_3_0 slots and " + registers + " constant registers"
                         : ", " + std::string(name) + " " + slots + " and " + registers;
  }
  return text;
}

std::vector<std::string> lighting_bases_findings(const SectionResult& r) {
  std::vector<std::string> findings;
  const size_t published = distinct(r, &ReportRow::scene, published_row).size(),
               probes = distinct(r, &ReportRow::scene, probe_row).size();
  if (published > 0)
    findings.push_back("on R&H 2001's " + std::to_string(published) +
                       " published probes (band-limited) the largest error over the peak irradiance is " +
                       max_of_peak_per_basis(r, published_row));
  if (probes > 0)
    findings.push_back("on the " + std::to_string(probes) + " measured probes it is " + max_of_peak_per_basis(r, probe_row) + "; " +
                       sh9_smallest(r, probe_row));
  if (!r.rows.empty()) findings.push_back(bases_cost(r));
  return findings;
}

SectionResult run_lighting_bases(const ReportSettings& s) {
  SectionResult out;
  out.title = "the ambient term of models: ambient cube, linear SH4, SH9 against ground-truth irradiance";
  out.columns = columns();
  out.plot = {"Lighting bases: mean relative error against ground-truth irradiance", "ps_3_0 slots (counted)",
              "mean relative error (%)", "slots", "mean_relative", 100.0, true};
  s.progress("lighting_bases: timing the three bases (" + std::to_string(s.timing_repeats) + " runs each)");
  const std::vector<Variant> vars = variants(s.timing_repeats);
  std::vector<std::string> probe_notes;
  nlohmann::json details = nlohmann::json::object();
  for (const Environment& e : published_environments(s)) {
    s.progress("lighting_bases: " + e.scene);
    add_rows(e, vars, s.normals, out);
  }
  for (const std::filesystem::path& file : probe_files(s.probes, probe_notes)) {
    s.progress("lighting_bases: " + file.string());
    const Environment e = probe_environment(file, s.probes, s.normals);
    if (file.filename() == "grace_probe.hdr") reproduce_grace(e, out.notes, details);
    add_rows(e, vars, s.normals, out);
  }
  out.notes.insert(out.notes.end(), probe_notes.begin(), probe_notes.end());
  out.notes.push_back("Fits, from the same samples as the reference: the cube is VRAD's cosine-weighted mean radiance per "
                      "side (docs/fidelity.md#bake-vrad, dense-ray limit); SH4 and SH9 project the radiance on bands 0-1 / 0-2 and "
                      "convolve with the clamped cosine (R&H 2001); each is evaluated by its shader code on the float lane.");
  out.notes.push_back("Errors: |dE|/E per normal and channel; max/peak: max |dE| over the brightest E; 8-bit steps after the "
                      "linear tone map that puts the brightest true E/pi at 1.0 and sRGB encoding. Frame of the probes: +y up, "
                      "+z at the image's centre, +x to its right (environment_image.hpp).");
  out.notes.push_back("Slots and constant registers: counted on ps_3_0 (Counted lane). ns/px: median of " +
                      std::to_string(s.timing_repeats) + " runs over " + std::to_string(kTimingNormals) +
                      " normals again and again, the ambient term alone.");
  out.notes.push_back("Not yet: the courtyard's own ambient (radiance around a point of builtin:courtyard needs the bake's gather).");
  if (!details.empty()) out.details = details;
  out.findings = lighting_bases_findings(out);
  return out;
}

}  // namespace

ReportSection lighting_bases_section() {
  return {"lighting_bases", "ambient cube, linear SH4 and SH9 against ground-truth irradiance, per light probe",
          run_lighting_bases};
}

}  // namespace luxel::cli
