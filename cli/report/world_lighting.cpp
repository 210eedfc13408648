// The report's section "world_lighting": how well a bump-mapped world surface's lightmaps give the
// light arriving for its bumped normal. Radiosity normal mapping (three directional maps combined
// as LightmappedGeneric does, docs/fidelity.md#lightmappedgeneric: d_i = sat(n . b_i)^2,
// sum d_i LM_i / sum d_i) and the flat lightmap (what the surface gets without its bump map) against
// the light computed per point for the bumped normal by the bake's own rule (bake::irradiance_at: the
// same rays, sky, emitters, final flat map and lights, without the basis).
//
// Points: kPointsPerGroup per group of surfaces (walls: |n_z| < 0.5 of the triangle's geometric
// normal; floors: n_z >= 0.5; ceilings: n_z <= -0.5), spread over the world's bump-mapped
// LightmappedGeneric triangles by area (counter-based random numbers: the same points every run).
// At each: the bump map read at level 0 with its sampler (full detail, as a close-up shows it: the
// comparison is of the basis, not of the texture's filtering), the four lightmaps read bilinear
// from the frame's own lightmap page (half floats, as the shader reads them), the tangent frame as
// the bake builds a luxel's (the tangent made orthogonal to the interpolated normal, the bitangent
// w cross(n, t)).
// Error: of luminance (Rec. 709 weights) in the lightmaps' unit (irradiance / pi), before albedo
// and tone mapping. mean = sum |a - r| / sum r over the group's points; bias = sum (a - r) / sum r;
// p95 = the 95th percentile of |a - r| / max(r, 5 % of the group's mean r), so that points in
// deep shade do not decide it. The reference's own noise: the same computation with another seed,
// its row judged like the others. Cost: lightmaps read per pixel, bytes per luxel as a BSP stores
// them (RGBE8888: one map for a flat face, four for a bumped one), the combo's counted ps_2_0
// slots.

#include "report/findings.hpp"
#include "report/report_scene.hpp"
#include "report/sections.hpp"

#include "luxel/bake/bake.hpp"
#include "luxel/bake/random.hpp"
#include "luxel/rasterizer/texture.hpp"
#include "luxel/shading/source/catalog.hpp"
#include "luxel/shading/source/common.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace luxel::cli {

namespace {

constexpr int kPointsPerGroup = 1000;
constexpr int kReferenceRays = 1024;
constexpr uint64_t kPointSeed = 0x776f726c64ull;  // "world"

// The rows' variants the findings compare.
constexpr const char* kFlatLightmap = "flat lightmap";
constexpr const char* kEngineRnm = "RNM (the engine's)";
constexpr const char* kReferenceNoise = "reference, another seed";

/// A point on a bump-mapped world surface, and what each way of lighting it reads.
struct WorldPoint {
  bake::SurfacePoint surface;  ///< normal: the bumped normal in world space, unit
  glm::dvec3 flat{0.0}, rnm{0.0}, rnm_rescaled{0.0};
};

/// A group of surfaces by the direction their geometric normal faces.
struct SurfaceGroup {
  const char* name;
  bool (*holds)(glm::vec3 geometric_normal);
};
const SurfaceGroup kGroups[] = {{"walls", [](glm::vec3 n) { return std::abs(n.z) < 0.5f; }},
                                {"floors", [](glm::vec3 n) { return n.z >= 0.5f; }},
                                {"ceilings", [](glm::vec3 n) { return n.z <= -0.5f; }}};

/// One triangle of a bump-mapped world mesh.
struct Triangle {
  size_t mesh, first_corner;
  double area;
};

/// The bump-mapped world LightmappedGeneric triangles of `group` (the meshes the bake gives luxels,
/// bake/src/inputs.cpp's rule, that also have a bump map, tangents and normals).
std::vector<Triangle> bumped_world_triangles(const scenes::Scene& scene, const SurfaceGroup& group) {
  const std::vector<char> in_model = scenes::meshes_in_models(scene);
  std::vector<Triangle> out;
  for (size_t i = 0; i < scene.meshes.size(); ++i) {
    const scenes::Mesh& mesh = scene.meshes[i];
    if (in_model[i] || mesh.material < 0 || size_t(mesh.material) >= scene.materials.size()) continue;
    const scenes::Material& m = scene.materials[size_t(mesh.material)];
    const size_t n = mesh.positions.size();
    if (m.family != scenes::ShaderFamily::lightmapped_generic || !m.bump.bound() || m.alpha == scenes::AlphaMode::blend ||
        m.translucent || mesh.uv1.size() != n || mesh.uv0.size() != n || mesh.tangents.size() != n || mesh.normals.size() != n)
      continue;
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
      const glm::vec3 p0 = mesh.positions[mesh.vertex_of_corner(3 * t)], p1 = mesh.positions[mesh.vertex_of_corner(3 * t + 1)],
                      p2 = mesh.positions[mesh.vertex_of_corner(3 * t + 2)];
      const glm::vec3 c = glm::cross(p1 - p0, p2 - p0);
      const float len = glm::length(c);
      if (len > 0 && group.holds(c / len)) out.push_back({i, 3 * t, 0.5 * double(len)});
    }
  }
  return out;
}

/// The light RNM and the flat lightmap give at `p`, bilinear from the frame's lightmap page.
void read_lightmaps(const ReportScene& scene, glm::vec2 uv1, glm::vec3 bump_tangent, WorldPoint& p) {
  const frame::GpuTexture& page = *scene.textures->lightmaps;
  glm::dvec3 maps[4];
  for (int k = 0; k < 4; ++k) {
    const glm::vec3 at(scene.textures->page.offset[size_t(k)] + scene.textures->page.scale * uv1.x, uv1.y, 0.0f);
    maps[k] = glm::dvec3(glm::vec3(rasterizer::sample_reference(page.texture, page.sampler, at, 0.0f)));
  }
  p.flat = maps[0];
  // The shader's weights (on the float lane), its combine in double.
  const shading::float3<float> w = shading::source::rnm_weights(shading::float3<float>(bump_tangent.x, bump_tangent.y, bump_tangent.z));
  const double d[3] = {w.x, w.y, w.z}, sum = d[0] + d[1] + d[2];
  p.rnm = sum > 0 ? (d[0] * maps[1] + d[1] * maps[2] + d[2] * maps[3]) / sum : glm::dvec3(0.0);
  // vrad's LinearToBumpedLightmap (docs/fidelity.md#bake-vrad, never called by vrad): each channel of
  // the three maps scaled so that their mean is the flat map's, here on the filtered values.
  const glm::dvec3 mean = (maps[1] + maps[2] + maps[3]) / 3.0;
  for (int c = 0; c < 3; ++c) p.rnm_rescaled[c] = mean[c] > 0 ? p.rnm[c] * maps[0][c] / mean[c] : p.flat[c];
}

/// kPointsPerGroup points over `triangles` by area, each with what the lightmaps give there.
std::vector<WorldPoint> sample_points(const ReportScene& scene, const std::vector<Triangle>& triangles, int group) {
  const scenes::Scene& s = *scene.scene;
  std::vector<double> cumulative;
  double total = 0;
  for (const Triangle& t : triangles) cumulative.push_back(total += t.area);
  std::vector<WorldPoint> out;
  for (int i = 0; i < kPointsPerGroup; ++i) {
    const bake::RandomKey key{kPointSeed, uint32_t(group), uint64_t(i), 0, 0};
    const double pick = double(bake::random01(key, 0)) * total;
    const Triangle& tri = triangles[size_t(std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin()) %
                                    triangles.size()];
    // Uniform over the triangle: the square-root warp of two uniform numbers.
    const float r1 = std::sqrt(bake::random01(key, 1)), r2 = bake::random01(key, 2);
    const float w[3] = {1.0f - r1, r1 * (1.0f - r2), r1 * r2};
    const scenes::Mesh& mesh = s.meshes[tri.mesh];
    const scenes::Material& material = s.materials[size_t(mesh.material)];
    uint32_t v[3];
    for (int k = 0; k < 3; ++k) v[k] = mesh.vertex_of_corner(tri.first_corner + size_t(k));
    auto lerp3 = [&](const auto& attr) { return w[0] * attr[v[0]] + w[1] * attr[v[1]] + w[2] * attr[v[2]]; };
    WorldPoint p;
    p.surface.position = lerp3(mesh.positions);
    p.surface.geometric_normal = glm::normalize(glm::cross(mesh.positions[v[1]] - mesh.positions[v[0]], mesh.positions[v[2]] - mesh.positions[v[0]]));
    // The luxel's tangent frame (lightmaps.hpp): the bump map's normal is in it.
    const glm::vec3 n = glm::normalize(lerp3(mesh.normals));
    const glm::vec4 t4 = lerp3(mesh.tangents);
    const glm::vec3 x = glm::normalize(glm::vec3(t4) - n * glm::dot(n, glm::vec3(t4)));
    const glm::vec3 y = (mesh.tangents[v[0]].w < 0 ? -1.0f : 1.0f) * glm::cross(n, x);
    const glm::vec2 uv = scenes::UvTransform::of(material.bump)(material.bump.uv_set == 1 ? lerp3(mesh.uv1) : lerp3(mesh.uv0));
    const frame::GpuTexture& bump = scene.textures->textures[size_t(material.bump.texture)];
    const glm::vec3 tex(rasterizer::sample_reference(bump.texture, bump.sampler, glm::vec3(uv, 0.0f), 0.0f));
    const glm::vec3 bumped = tex * 2.0f - 1.0f;  // as the shader: no renormalisation
    p.surface.normal = glm::normalize(bumped.x * x + bumped.y * y + bumped.z * n);
    read_lightmaps(scene, lerp3(mesh.uv1), bumped, p);
    out.push_back(p);
  }
  return out;
}

double luminance(const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

/// mean, bias and p95 (the file's comment) of `approx` against `reference`.
std::vector<double> errors(const std::vector<double>& approx, const std::vector<double>& reference) {
  double abs_sum = 0, signed_sum = 0, ref_sum = 0;
  for (size_t i = 0; i < approx.size(); ++i) {
    abs_sum += std::abs(approx[i] - reference[i]);
    signed_sum += approx[i] - reference[i];
    ref_sum += reference[i];
  }
  const double floor = 0.05 * ref_sum / double(std::max<size_t>(reference.size(), 1));
  std::vector<double> relative;
  for (size_t i = 0; i < approx.size(); ++i) relative.push_back(std::abs(approx[i] - reference[i]) / std::max(reference[i], floor));
  std::sort(relative.begin(), relative.end());
  const double p95 = relative.empty() ? 0.0 : relative[std::min(relative.size() - 1, size_t(0.95 * double(relative.size())))];
  if (!(ref_sum > 0)) return {0.0, 0.0, p95};
  return {abs_sum / ref_sum, signed_sum / ref_sum, p95};
}

/// The counted ps_2_0 slots of LightmappedGeneric's combo `variant`.
double lightmapped_slots(const std::string& variant) {
  for (const shading::source::ShaderVariant& v : shading::source::shader_catalog())
    if (v.family == "LightmappedGeneric" && v.variant == variant) return double(v.measure(shading::ShaderModel::ps_2_0).total_slots());
  return std::numeric_limits<double>::quiet_NaN();
}

/// "too bright" or "too dark" as a bias says.
const char* bias_direction(double bias) { return bias > 0 ? "too bright" : bias < 0 ? "too dark" : "unbiased"; }

/// Per group of surfaces: RNM's mean error against the flat map's, which way each is biased, and
/// the reference's own noise.
std::vector<std::string> world_lighting_findings(const SectionResult& r) {
  std::vector<std::string> findings;
  for (const std::string& group : distinct(r, &ReportRow::scene, any_row)) {
    const ReportRow* flat = first_row(r, both(scene_is(group), variant_is(kFlatLightmap)));
    const ReportRow* rnm = first_row(r, both(scene_is(group), variant_is(kEngineRnm)));
    const ReportRow* noise = first_row(r, both(scene_is(group), variant_is(kReferenceNoise)));
    if (!flat || !rnm || !noise) continue;
    const double rnm_mean = value_of(r, *rnm, "mean_error"), flat_mean = value_of(r, *flat, "mean_error");
    const double rnm_bias = value_of(r, *rnm, "bias"), flat_bias = value_of(r, *flat, "bias");
    findings.push_back(group + ": RNM's mean error of luminance is " + text_of(r, "mean_error", rnm_mean) + " %, " +
                       ratio_text(rnm_mean, flat_mean) + " times the flat map's " + text_of(r, "mean_error", flat_mean) +
                       " %; RNM is " + bias_direction(rnm_bias) + " (bias " + text_of(r, "bias", rnm_bias) + " %), the flat map " +
                       bias_direction(flat_bias) + " (" + text_of(r, "bias", flat_bias) + " %); the reference's own noise is " +
                       text_of(r, "mean_error", value_of(r, *noise, "mean_error")) + " %");
  }
  return findings;
}

SectionResult run_world_lighting(const ReportSettings& s) {
  const ReportScene& scene = *s.scene;
  SectionResult out;
  out.title = "a bump-mapped world surface's light: radiosity normal mapping and the flat lightmap against the light for the "
              "bumped normal computed per point";
  out.columns = {{"lightmaps_per_pixel", "maps/px", ColumnKind::cost, "%.0f"},
                 {"bytes_per_luxel", "bytes/luxel", ColumnKind::cost, "%.0f"},
                 {"slots", "slots ps_2_0", ColumnKind::cost, "%.0f"},
                 {"mean_error", "mean error %", ColumnKind::error, "%.2f", 100.0},
                 {"bias", "bias %", ColumnKind::error, "%+.2f", 100.0},
                 {"p95_error", "p95 error %", ColumnKind::error, "%.2f", 100.0}};
  out.plot = {"World lighting: the lightmaps against the light for the bumped normal", "DX9 slots (LightmappedGeneric, ps_2_0)",
              "mean error of luminance (%)", "slots", "mean_error", 100.0, false};
  if (!scene.scene->lightmaps || !scene.textures->lightmaps) {
    out.notes.push_back(scene.name + " has no lightmaps: nothing to compare.");
    return out;
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double flat_slots = lightmapped_slots("flat"), bump_slots = lightmapped_slots("bump");
  const std::string reference = "bake::irradiance_at: " + std::to_string(kReferenceRays) +
                                " rays a point over the hemisphere, weighted by the bumped normal's cosine, plus the lights";
  for (int g = 0; g < int(std::size(kGroups)); ++g) {
    const SurfaceGroup& group = kGroups[g];
    const std::vector<Triangle> triangles = bumped_world_triangles(*scene.scene, group);
    if (triangles.empty()) continue;
    s.progress(std::string("world_lighting: ") + group.name + ", " + std::to_string(kPointsPerGroup) + " points");
    const std::vector<WorldPoint> points = sample_points(scene, triangles, g);
    std::vector<bake::SurfacePoint> surface;
    for (const WorldPoint& p : points) surface.push_back(p.surface);
    bake::BakeSettings settings;
    settings.samples = kReferenceRays;
    const std::vector<glm::vec3> exact = bake::irradiance_at(*scene.scene, settings, surface);
    settings.seed += 1;
    const std::vector<glm::vec3> again = bake::irradiance_at(*scene.scene, settings, surface);

    std::vector<double> reference_y, flat_y, rnm_y, rescaled_y, again_y;
    for (size_t i = 0; i < points.size(); ++i) {
      reference_y.push_back(luminance(glm::dvec3(exact[i])));
      again_y.push_back(luminance(glm::dvec3(again[i])));
      flat_y.push_back(luminance(points[i].flat));
      rnm_y.push_back(luminance(points[i].rnm));
      rescaled_y.push_back(luminance(points[i].rnm_rescaled));
    }
    const std::string where = scene.name + " " + group.name;
    const std::string count = std::to_string(points.size()) + " points";
    auto row = [&](const char* variant, const char* label, std::vector<double> cost, const std::vector<double>& values) {
      for (double e : errors(values, reference_y)) cost.push_back(e);
      out.rows.push_back({where, count, variant, std::string(group.name) + ", " + label, reference, cost});
    };
    row(kFlatLightmap, "flat", {1, 4, flat_slots}, flat_y);
    row(kEngineRnm, "RNM", {3, 16, bump_slots}, rnm_y);
    row("RNM, maps averaging the flat one", "RNM rescaled", {3, 16, bump_slots}, rescaled_y);
    row(kReferenceNoise, "reference noise", {0, nan, nan}, again_y);
  }
  if (out.rows.empty()) {
    out.notes.push_back(scene.name + " has no bump-mapped world surface: nothing to compare.");
    return out;
  }
  out.notes.push_back("Each group: " + std::to_string(kPointsPerGroup) + " points over the world's bump-mapped LightmappedGeneric "
                      "triangles by area (walls |n_z| < 0.5, floors n_z >= 0.5, ceilings n_z <= -0.5). The bump map at full "
                      "detail (level 0), the lightmaps bilinear from the frame's lightmap page; luminance in the lightmaps' unit "
                      "(irradiance / pi), before albedo and tone mapping.");
  out.notes.push_back("mean = sum|a - r| / sum r; bias = sum(a - r) / sum r; p95: the 95th percentile of |a - r| / max(r, 5% of "
                      "the mean r). bytes/luxel: as a BSP stores them (RGBE8888, one map for a flat face, four for a bumped one). "
                      "The reference-noise row is the reference computed again with another seed: errors near it are noise.");
  out.findings = world_lighting_findings(out);
  return out;
}

}  // namespace

ReportSection world_lighting_section() {
  return {"world_lighting",
          "radiosity normal mapping and the flat lightmap against the light for the bumped normal, on --scene's bump-mapped "
          "world surfaces",
          run_world_lighting, true};
}

}  // namespace luxel::cli
