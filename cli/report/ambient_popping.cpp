// The report's section "ambient_popping": how much a moving model's ambient light jumps from one
// frame to the next along the scene's sequence, for the nearest irradiance-volume sample (the
// engine's) and the trilinear blend, each with the renderer's time averaging of the models'
// lighting (FrameSettings::lighting_time_constant, the seed's fix for popping) and without it.
// A frame's jump for a model: the largest change of a channel of its ambient cube's six faces
// (Renderer::model_lighting, after averaging) over the cube's brightest channel the frame before;
// the row keeps the largest jump over models and frames, and the mean of each frame's largest.
// There is no reference frame: a jump is the artefact itself. Cost: samples read per model, and
// the time constant.

#include "report/report_scene.hpp"
#include "report/sections.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace luxel::cli {

namespace {

constexpr int kFrames = 240;
constexpr float kFps = 30.0f;

using frame::AmbientSampling;

/// The largest channel of a cube.
float brightest(const std::array<glm::vec3, 6>& cube) {
  float m = 0.0f;
  for (const glm::vec3& f : cube) m = std::max({m, f.x, f.y, f.z});
  return m;
}

SectionResult run_ambient_popping(const ReportSettings& s) {
  const ReportScene& scene = *s.scene;
  SectionResult out;
  out.title = "a moving model's ambient cube, frame to frame: nearest and trilinear, with and without time averaging";
  out.columns = {{"volume_samples", "samples read", ColumnKind::cost, "%.0f"},
                 {"time_constant_s", "tau s", ColumnKind::cost, "%.2f"},
                 {"max_jump", "max jump %", ColumnKind::error, "%.2f", 100.0},
                 {"mean_jump", "mean jump %", ColumnKind::error, "%.3f", 100.0}};
  out.plot = {"Ambient popping: the largest frame-to-frame jump of a model's ambient cube", "irradiance-volume samples read per model",
              "largest jump (% of the cube's brightest channel)", "volume_samples", "max_jump", 100.0, false};
  bool moving = false;
  for (const scenes::Model& m : scene.scene->models) moving = moving || !m.path.empty();
  if (!moving || !scene.scene->irradiance_volume) {
    out.notes.push_back(scene.name + " has no model moving through an irradiance volume: nothing pops.");
    return out;
  }
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
    frame::FrameSettings f = scene.settings;
    f.ambient = v.sampling;
    f.lighting_time_constant = v.tau;
    f.camera_path = !scene.scene->camera_path.empty();
    const std::unique_ptr<frame::Renderer> renderer = scene.renderer(f);
    std::vector<frame::ModelLightingState> before;
    double max_jump = 0, jump_sum = 0;
    for (int n = 0; n < kFrames; ++n) {
      if (n > 0) renderer->set_time(float(n) / kFps);  // moves the models and their lighting: nothing to draw
      const std::vector<frame::ModelLightingState>& now = renderer->model_lighting();
      if (n > 0) {
        double frame_jump = 0;
        for (size_t m = 0; m < now.size() && m < before.size(); ++m) {
          const float scale = brightest(before[m].volume);
          if (!(scale > 0.0f)) continue;
          for (int k = 0; k < 6; ++k)
            for (int c = 0; c < 3; ++c)
              frame_jump = std::max(frame_jump, double(std::fabs(now[m].volume[size_t(k)][c] - before[m].volume[size_t(k)][c])) / scale);
        }
        max_jump = std::max(max_jump, frame_jump);
        jump_sum += frame_jump;
      }
      before = now;
    }
    out.rows.push_back({scene.name, std::to_string(kFrames) + " frames at " + std::to_string(int(kFps)) + " fps", v.name,
                        std::string(v.sampling == AmbientSampling::nearest ? "nearest" : "trilinear") +
                            (v.tau > 0 ? ", tau " + number(v.tau, "%.2f") : ", no averaging"),
                        "none: the jump between consecutive frames is the artefact (no reference)",
                        {double(v.samples_read), double(v.tau), max_jump, jump_sum / double(kFrames - 1)}});
  }
  out.notes.push_back("The scene's models along their paths over " + std::to_string(kFrames) + " frames (the camera along its "
                      "path); the cube is the model's irradiance-volume cube after the averaging, before lights are folded in "
                      "(the renderer's clock moved frame by frame, no frame drawn).");
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
