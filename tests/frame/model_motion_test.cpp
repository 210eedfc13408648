// Models moving along their paths and their lighting averaged across the frames of a sequence
// (renderer.hpp): the documented time constant, the two local lights the significance rule
// keeps, their cross-fade when the rule changes its choice, and a model at rest lit exactly as
// without averaging.

#include "frame/frame_support.hpp"

#include "luxel/frame/renderer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace luxel::frame {
namespace {

constexpr int kMotionSize = 32;
constexpr float kFps = 30.0f;


/// A 2 x 2 square at the origin facing +Z, filling the view of an orthographic camera above it,
/// and a two-sample irradiance volume along X whose +Z sides differ: dark at x = 0, bright at
/// x = 100.
scenes::Scene walker_scene() {
  scenes::Scene s = top_down();
  s.name = "walker";
  scenes::Material m;  // VertexLitGeneric, untextured
  m.color = {0.8f, 0.6f, 0.4f, 1.0f};
  s.materials = {m};
  s.meshes = {square(-1, -1, 1, 1, 0, 0)};
  scenes::IrradianceVolume v;
  v.min = {0, 0, 0};
  v.spacing = glm::vec3(100.0f);
  v.counts = {2, 1, 1};
  v.max = {100, 0, 0};
  scenes::AmbientCube dark, bright;
  dark.fill(glm::vec3(0.02f));
  bright.fill(glm::vec3(0.02f));
  dark[4] = {0.05f, 0.04f, 0.03f};
  bright[4] = {0.6f, 0.5f, 0.9f};
  v.cubes = {dark, bright};
  s.irradiance_volume = v;
  return s;
}

/// The square as a model, its centroid at `centroid`, moving along `path`.
scenes::Model walker(glm::vec3 centroid = glm::vec3(0.0f), std::vector<scenes::ModelKey> path = {}) {
  scenes::Model model;
  model.name = "walker";
  model.meshes = {0};
  model.centroid = centroid;
  model.path = std::move(path);
  return model;
}

/// Makes the square a model that moves from the dark sample to the bright one between t = 1 and
/// t = 1.01.
void add_jump(scenes::Scene& s) {
  s.models = {walker(glm::vec3(0.0f), {{1.0f, glm::vec3(0.0f)}, {1.01f, glm::vec3(100.0f, 0.0f, 0.0f)}})};
}

TEST(ModelMotion, AmbientFollowsTheDocumentedTimeConstant) {
  scenes::Scene s = walker_scene();
  add_jump(s);
  for (float fps : {kFps, 2 * kFps}) {
    FrameSettings f{kMotionSize, kMotionSize, 1};
    Renderer r(s, f);
    const glm::vec3 dark = s.irradiance_volume->cubes[0][4], bright = s.irradiance_volume->cubes[1][4];
    EXPECT_EQ(r.model_lighting().at(0).volume[4], dark);
    // The target turns bright at the first frame past the midpoint (t = 1.005); from the frame
    // before it, the cube closes exp(-dt / tau) of the remaining gap per frame.
    float last_dark = 0.0f;
    for (int n = 1; n <= static_cast<int>(fps * 2.0f); ++n) {
      const float t = static_cast<float>(n) / fps;
      r.set_time(t);
      if (t <= 1.005f) {
        last_dark = t;
        EXPECT_EQ(r.model_lighting()[0].volume[4], dark) << "t " << t;
        continue;
      }
      EXPECT_FLOAT_EQ(r.model_lighting()[0].centroid.x, 100.0f);
      const double remaining = std::exp(-(double(t) - last_dark) / 0.2);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(r.model_lighting()[0].volume[4][c], bright[c] + (dark[c] - bright[c]) * remaining, 1e-5)
            << "t " << t << " fps " << fps;
    }
  }
}

TEST(ModelMotion, TheAveragedAmbientReachesThePixels) {
  // The square walks from the dark sample into the bright one at once (t = 0 to 0.01), where the
  // camera looks.
  scenes::Scene s = walker_scene();
  s.models = {walker(glm::vec3(0.0f), {{0.0f, glm::vec3(0.0f)}, {0.01f, glm::vec3(100.0f, 0.0f, 0.0f)}})};
  s.cameras[0].position = {100, 0, 10};
  s.cameras[0].target = {100, 0, 0};
  FrameSettings f{kMotionSize, kMotionSize, 1};
  f.time = 0.01f;
  Renderer settled(s, f);  // the first frame starts at its values: bright
  rasterizer::Context ctx(2);
  const double albedo[3] = {0.8, 0.6, 0.4};
  const glm::vec3 dark = s.irradiance_volume->cubes[0][4], bright = s.irradiance_volume->cubes[1][4];
  settled.render(ctx);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(settled.image().pixel(kMotionSize / 2, kMotionSize / 2)[c], 255 * srgb_encode(albedo[c] * bright[c]), 1.0);
  f.time = 0.0f;
  Renderer walking(s, f);  // starts dark (off screen)
  for (int n = 1; n <= 6; ++n) walking.set_time(static_cast<float>(n) / kFps);
  walking.render(ctx);
  // Dark at t = 0, the target bright from the first step on: six steps of 1/30 s towards it.
  const double remaining = std::exp(-(6.0 / kFps) / 0.2);
  int differs = 0;
  for (int c = 0; c < 3; ++c) {
    const double expected = 255 * srgb_encode(albedo[c] * (bright[c] + (dark[c] - bright[c]) * remaining));
    EXPECT_NEAR(walking.image().pixel(kMotionSize / 2, kMotionSize / 2)[c], expected, 1.0) << c;
    differs += std::abs(expected - 255 * srgb_encode(albedo[c] * bright[c])) > 3.0;
  }
  EXPECT_GT(differs, 0) << "the averaging must be visible for the test to mean anything";
}

/// Four point lights around the origin; the brightest color is the farthest, so that ranking by
/// color alone would pick differently from the delivered luminance.
std::vector<scenes::Light> four_lights() {
  auto point = [](glm::vec3 at, glm::vec3 color) {
    scenes::Light l;
    l.position = at;
    l.color = color;
    l.constant = 0.0f;
    l.linear = 0.0f;
    l.quadratic = 1.0f;
    return l;
  };
  return {point({60, 0, 10}, {900, 900, 900}),   // far and bright
          point({-6, 2, 8}, {60, 40, 20}),       // near, reddish
          point({0, -8, 6}, {10, 80, 10}),       // near, green: less power than the red one, more luminance
          point({5, 5, 5}, {20, 20, 20})};       // middling
}

/// The delivered luminance at `p` (light_folding.hpp's metric), written out here.
double delivered(const scenes::Light& l, glm::vec3 p) {
  const double d2 = double(glm::dot(l.position - p, l.position - p));
  return (0.2125 * l.color.r + 0.7154 * l.color.g + 0.0721 * l.color.b) / d2;
}

TEST(ModelMotion, TheTwoLocalLightsAreTheTwoTheRulePicks) {
  scenes::Scene s = walker_scene();
  s.irradiance_volume.reset();
  s.lights = four_lights();
  s.models = {walker(glm::vec3{0.5f, -0.25f, 0.0f})};
  std::vector<int> order = {0, 1, 2, 3};
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return delivered(s.lights[a], s.models[0].centroid) > delivered(s.lights[b], s.models[0].centroid); });
  Renderer r(s, {kMotionSize, kMotionSize, 1});
  const ModelLightingState& state = r.model_lighting().at(0);
  ASSERT_EQ(state.local_lights.size(), 2u);
  EXPECT_EQ(state.local_lights[0], order[0]);
  EXPECT_EQ(state.local_lights[1], order[1]);
  EXPECT_EQ(order, (std::vector<int>{2, 1, 3, 0})) << "neither the brightest color nor the most power ranks first";
  for (int i = 0; i < 4; ++i) EXPECT_EQ(state.light_shares[i], i == order[0] || i == order[1] ? 1.0f : 0.0f);
}

TEST(ModelMotion, LocalLightsCrossFadeWhenTheRuleChangesItsChoice) {
  // A and C low on either side, B high overhead; the model walks from beside A to beside C, and
  // the rule's choice changes from {A, B} to {C, B}.
  scenes::Scene s = walker_scene();
  s.irradiance_volume.reset();
  auto point = [](glm::vec3 at, float power) {
    scenes::Light l;
    l.position = at;
    l.color = glm::vec3(power);
    return l;
  };
  s.lights = {point({-50, 0, 5}, 400), point({0, 0, 400}, 5e4f), point({50, 0, 5}, 400)};  // A, B (overhead), C
  s.models = {walker(glm::vec3{-45, 0, 0}, {{0.0f, glm::vec3(0.0f)}, {0.01f, glm::vec3(90, 0, 0)}})};
  Renderer r(s, {kMotionSize, kMotionSize, 1});
  ASSERT_EQ(r.model_lighting()[0].local_lights, (std::vector<int>{0, 1}));
  for (int n = 1; n <= 12; ++n) {
    const float t = static_cast<float>(n) / kFps;
    r.set_time(t);
    const ModelLightingState& state = r.model_lighting()[0];
    const double leaving = std::exp(-double(t) / 0.2);  // the target changed at the first step from t = 0
    EXPECT_NEAR(state.light_shares[0], leaving, 1e-6) << "A fades out, t " << t;
    EXPECT_NEAR(state.light_shares[2], 1.0 - leaving, 1e-6) << "C fades in, t " << t;
    EXPECT_EQ(state.light_shares[1], 1.0f) << "B stays";
    // The two largest shares are the slots: B, then whichever of A and C is ahead.
    ASSERT_EQ(state.local_lights.size(), 2u);
    EXPECT_EQ(state.local_lights[0], 1);
    EXPECT_EQ(state.local_lights[1], leaving > 0.5 ? 0 : 2) << "t " << t;
  }
}

TEST(ModelMotion, AModelAtRestIsLitAsWithoutAveraging) {
  scenes::Scene s = walker_scene();
  s.lights = four_lights();
  s.models = {walker(glm::vec3{20, 0, 0})};
  FrameSettings no_averaging{kMotionSize, kMotionSize, 4};
  no_averaging.lighting_time_constant = 0.0f;
  rasterizer::Context ctx(2);
  Renderer plain(s, no_averaging);
  plain.render(ctx);
  Renderer averaged(s, {kMotionSize, kMotionSize, 4});
  for (int n = 0; n < 4; ++n) {
    averaged.set_time(static_cast<float>(n) * 0.37f);
    averaged.render(ctx);
    EXPECT_EQ(averaged.image().rgba, plain.image().rgba) << "frame " << n;
  }
}

TEST(ModelMotion, MovingModelsMoveOnScreenAndSequencesRepeat) {
  scenes::Scene s = walker_scene();
  s.lights = four_lights();
  s.models = {walker(glm::vec3(0.0f), {{0.0f, glm::vec3(0.0f)}, {1.0f, glm::vec3(0.5f, 0.0f, 0.0f)}})};
  auto sequence = [&](int threads) {
    Renderer r(s, {kMotionSize, kMotionSize, 4});
    rasterizer::Context ctx(threads);
    std::vector<std::vector<uint8_t>> frames;
    for (int n = 0; n <= 30; n += 10) {
      r.set_time(static_cast<float>(n) / kFps);
      r.render(ctx);
      frames.push_back(r.image().rgba);
    }
    return frames;
  };
  const auto one = sequence(1), two = sequence(2);
  EXPECT_EQ(one, two);
  EXPECT_NE(one.front(), one.back());
  // At t = 1 the square spans x in [-0.5, 1.5]: the camera's left quarter (x < -0.5) is background.
  Renderer r(s, {kMotionSize, kMotionSize, 1});
  r.set_time(1.0f);
  rasterizer::Context ctx(1);
  r.render(ctx);
  EXPECT_EQ(r.image().pixel(2, kMotionSize / 2)[0], 0) << "left of the moved square: the black background";
  EXPECT_GT(r.image().pixel(kMotionSize - 3, kMotionSize / 2)[0], 0) << "the moved square";
}

TEST(ModelMotion, BadTimesAndPathsAreRefused) {
  scenes::Scene s = walker_scene();
  add_jump(s);
  FrameSettings f{kMotionSize, kMotionSize, 1};
  f.time = std::nanf("");
  EXPECT_THROW(Renderer(s, f), std::invalid_argument);
  f.time = 0.0f;
  f.lighting_time_constant = -1.0f;
  EXPECT_THROW(Renderer(s, f), std::invalid_argument);
  Renderer r(s, {kMotionSize, kMotionSize, 1});
  EXPECT_THROW(r.set_time(INFINITY), std::invalid_argument);
  s.models[0].path[1].time = 1.0f;  // not later than the key before
  EXPECT_THROW(Renderer(s, {kMotionSize, kMotionSize, 1}), std::invalid_argument);
}

}  // namespace
}  // namespace luxel::frame
