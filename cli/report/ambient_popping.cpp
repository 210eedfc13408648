// The report's section "ambient_popping": how much a moving model's ambient light jumps from one
// frame to the next along the scene's sequence, and how far it is from the exact ambient light at
// the model, for the nearest irradiance-volume sample (the engine's) and the trilinear blend, each
// with the renderer's time averaging of the models' lighting (FrameSettings::lighting_time_constant,
// the seed's fix for popping) and without it.
// A frame's jump for a model: the largest change of a channel of its ambient cube's six faces
// (Renderer::model_lighting, after averaging) over the cube's brightest channel the frame before;
// the row keeps the largest jump over models and frames, and the mean of each frame's largest.
// The error: the largest difference of a channel from the exact cube at the model's centroid
// that frame, over the exact cube's brightest channel; largest and mean of each frame's largest
// as for the jump. The exact cube is bake::ambient_cubes_at with kExactRays rays at the centroid:
// the volume's own rule (the same rays' radiance from sky, emitters and the final flat lightmap)
// without the grid, its nearest sample or its blend, so it judges the lookup, not the bake. Its
// own row gives the jumps the light itself makes along the path. Cost: volume samples read per
// model, and the time constant.

#include "report/findings.hpp"
#include "report/report_scene.hpp"
#include "report/sections.hpp"

#include "luxel/bake/bake.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace luxel::cli {

namespace {

constexpr int kFrames = 240;
constexpr float kFps = 30.0f;
constexpr int kExactRays = 4096;

using frame::AmbientSampling;

/// The largest channel of a cube.
float brightest(const std::array<glm::vec3, 6>& cube) {
  float m = 0.0f;
  for (const glm::vec3& f : cube) m = std::max({m, f.x, f.y, f.z});
  return m;
}

/// The largest difference of a channel between two cubes, over `scale`.
double cube_difference(const std::array<glm::vec3, 6>& a, const std::array<glm::vec3, 6>& b, float scale) {
  double d = 0;
  for (int k = 0; k < 6; ++k)
    for (int c = 0; c < 3; ++c) d = std::max(d, double(std::fabs(a[size_t(k)][c] - b[size_t(k)][c])));
  return d / double(scale);
}

/// Largest and mean (over frames) of each frame's largest value.
struct FrameStats {
  double max = 0, sum = 0;
  int frames = 0;
  void add(double frame_largest) { max = std::max(max, frame_largest), sum += frame_largest, ++frames; }
  double mean() const { return frames ? sum / frames : 0.0; }
};

/// The scene's models that move along a path (Scene::models, which Renderer::model_lighting follows).
std::vector<size_t> moving_models(const scenes::Scene& scene) {
  std::vector<size_t> out;
  for (size_t m = 0; m < scene.models.size(); ++m)
    if (!scene.models[m].path.empty()) out.push_back(m);
  return out;
}

/// What `f`'s renderer gives each moving model at each frame (its clock moved frame by frame,
/// nothing drawn): `what` of its ModelLightingState.
template <class What>
auto per_frame(const ReportScene& scene, const frame::FrameSettings& f, const std::vector<size_t>& models, What what) {
  const std::unique_ptr<frame::Renderer> renderer = scene.renderer(f);
  std::vector<std::vector<decltype(what(frame::ModelLightingState{}))>> out;
  for (int n = 0; n < kFrames; ++n) {
    if (n > 0) renderer->set_time(float(n) / kFps);
    out.emplace_back();
    for (size_t m : models) out.back().push_back(what(renderer->model_lighting().at(m)));
  }
  return out;
}

/// The exact cube at the centroids `at` (per frame, per model of `models`): bake::ambient_cubes_at,
/// each distinct point once, the rays passing through the model's own meshes.
std::vector<std::vector<std::array<glm::vec3, 6>>> exact_cubes(const scenes::Scene& scene, const std::vector<size_t>& models,
                                                              const std::vector<std::vector<glm::vec3>>& at) {
  bake::BakeSettings settings;
  settings.cube_samples = kExactRays;
  std::vector<std::vector<std::array<glm::vec3, 6>>> out(at.size());
  for (size_t i = 0; i < models.size(); ++i) {
    std::map<std::tuple<float, float, float>, size_t> index;
    std::vector<glm::vec3> points;
    for (const auto& frame : at)
      if (index.emplace(std::tuple{frame[i].x, frame[i].y, frame[i].z}, points.size()).second) points.push_back(frame[i]);
    const bake::PointCubes cubes = bake::ambient_cubes_at(scene, settings, points, scene.models[models[i]].meshes);
    for (size_t n = 0; n < at.size(); ++n) out[n].push_back(cubes.cubes[index.at(std::tuple{at[n][i].x, at[n][i].y, at[n][i].z})]);
  }
  return out;
}

/// The rows that read the irradiance volume (the exact row reads none).
bool volume_lookup(const SectionResult& r, const ReportRow& row) { return value_of(r, row, "volume_samples") > 0; }

/// Every reading's largest jump; the lookups' mean and largest error against the exact cube, per
/// way of sampling.
std::vector<std::string> ambient_popping_findings(const SectionResult& r) {
  std::vector<std::string> findings;
  if (r.rows.empty()) return findings;
  findings.push_back("the largest frame-to-frame jump, in % of the cube's brightest channel: " + listing(r, "max_jump", any_row));
  const RowTest lookups = [&r](const ReportRow& row) { return volume_lookup(r, row); };
  std::string errors;
  for (const char* sampling : {"trilinear", "nearest"})
    if (const std::optional<Span> mean = span_of(r, "mean_error", both(lookups, variant_starts_with(sampling))))
      errors += (errors.empty() ? "" : ", ") + std::string(sampling) + " " + span_text(r, "mean_error", *mean) + " %";
  if (const std::optional<Span> max = span_of(r, "max_error", lookups))
    findings.push_back("against the exact cube at the model the mean error is " + errors + "; every lookup's largest error is " +
                       span_text(r, "max_error", *max) + " %");
  return findings;
}

SectionResult run_ambient_popping(const ReportSettings& s) {
  const ReportScene& scene = *s.scene;
  SectionResult out;
  out.title = "a moving model's ambient cube, frame to frame and against the exact ambient light at the model: nearest and "
              "trilinear, with and without time averaging";
  out.columns = {{"volume_samples", "samples read", ColumnKind::cost, "%.0f"},
                 {"time_constant_s", "tau s", ColumnKind::cost, "%.2f"},
                 {"max_jump", "max jump %", ColumnKind::error, "%.2f", 100.0},
                 {"mean_jump", "mean jump %", ColumnKind::error, "%.3f", 100.0},
                 {"max_error", "max error %", ColumnKind::error, "%.2f", 100.0},
                 {"mean_error", "mean error %", ColumnKind::error, "%.2f", 100.0}};
  out.plot = {"Ambient popping: the largest frame-to-frame jump of a model's ambient cube", "irradiance-volume samples read per model",
              "largest jump (% of the cube's brightest channel)", "volume_samples", "max_jump", 100.0, false};
  const std::vector<size_t> models = moving_models(*scene.scene);
  if (models.empty() || !scene.scene->irradiance_volume) {
    out.notes.push_back(scene.name + " has no model moving through an irradiance volume: nothing pops.");
    return out;
  }
  frame::FrameSettings base = scene.settings;
  base.camera_path = !scene.scene->camera_path.empty();
  s.progress("ambient_popping: the exact cubes at the models");
  const auto at = per_frame(scene, base, models, [](const frame::ModelLightingState& m) { return m.centroid; });
  const std::vector<std::vector<std::array<glm::vec3, 6>>> exact = exact_cubes(*scene.scene, models, at);
  const std::string sequence = std::to_string(kFrames) + " frames at " + std::to_string(int(kFps)) + " fps";
  const std::string reference = "bake::ambient_cubes_at: " + std::to_string(kExactRays) +
                                " rays at the model's centroid each frame (the jump needs none: it is the artefact)";

  // How far `cubes` (per frame, per model) jump and stray from the exact ones.
  auto judge = [&](const std::vector<std::vector<std::array<glm::vec3, 6>>>& cubes) {
    FrameStats jump, error;
    for (int n = 0; n < kFrames; ++n) {
      double frame_jump = 0, frame_error = 0;
      for (size_t m = 0; m < cubes[size_t(n)].size(); ++m) {
        const float exact_scale = brightest(exact[size_t(n)][m]);
        if (exact_scale > 0.0f) frame_error = std::max(frame_error, cube_difference(cubes[size_t(n)][m], exact[size_t(n)][m], exact_scale));
        if (n == 0 || m >= cubes[size_t(n) - 1].size()) continue;
        const float scale = brightest(cubes[size_t(n) - 1][m]);
        if (scale > 0.0f) frame_jump = std::max(frame_jump, cube_difference(cubes[size_t(n)][m], cubes[size_t(n) - 1][m], scale));
      }
      if (n > 0) jump.add(frame_jump);
      error.add(frame_error);
    }
    return std::pair{jump, error};
  };

  const float averaged = frame::FrameSettings{}.lighting_time_constant;
  struct Variant {
    AmbientSampling sampling;
    float tau;
    const char* name;
    int samples_read;
  };
  const Variant variants[] = {{AmbientSampling::nearest, 0.0f, "nearest, not averaged", 1},
                              {AmbientSampling::nearest, averaged, "nearest, averaged (the engine's)", 1},
                              {AmbientSampling::trilinear, 0.0f, "trilinear, not averaged", 8},
                              {AmbientSampling::trilinear, averaged, "trilinear, averaged", 8}};
  for (const Variant& v : variants) {
    s.progress(std::string("ambient_popping: ") + v.name);
    frame::FrameSettings f = base;
    f.ambient = v.sampling;
    f.lighting_time_constant = v.tau;
    const auto [jump, error] = judge(per_frame(scene, f, models, [](const frame::ModelLightingState& m) { return m.volume; }));
    out.rows.push_back({scene.name, sequence, v.name,
                        std::string(v.sampling == AmbientSampling::nearest ? "nearest" : "trilinear") +
                            (v.tau > 0 ? ", tau " + number(v.tau, "%.2f") : ", no averaging"),
                        reference, {double(v.samples_read), double(v.tau), jump.max, jump.mean(), error.max, error.mean()}});
  }
  const auto [jump, error] = judge(exact);
  out.rows.push_back({scene.name, sequence, "exact (the reference)",
                      std::to_string(kExactRays) + " rays at the centroid, no volume", reference,
                      {0.0, 0.0, jump.max, jump.mean(), error.max, error.mean()}});
  out.notes.push_back("The scene's moving models along their paths over " + std::to_string(kFrames) + " frames (the camera along its "
                      "path); the cube is the model's irradiance-volume cube after the averaging, before lights are folded in "
                      "(the renderer's clock moved frame by frame, no frame drawn). The exact row's jumps are the light's own "
                      "changes along the path; a lookup's jumps beyond them are popping.");
  out.findings = ambient_popping_findings(out);
  return out;
}

}  // namespace

ReportSection ambient_popping_section() {
  return {"ambient_popping",
          "the largest frame-to-frame jump of a moving model's ambient cube: nearest and trilinear, with and without time "
          "averaging",
          run_ambient_popping, true};
}

}  // namespace luxel::cli
