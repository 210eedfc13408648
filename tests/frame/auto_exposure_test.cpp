// Auto exposure through the frame: each frame is drawn at the scale the frames before it chose,
// a grey scene settles where the percentile rule says, a clock that goes back starts the exposure
// again, a still's exposure found at rest is where the sequence stays, and a courtyard sequence
// gives the same bytes on 1 and 2 threads.

#include "frame/frame_support.hpp"

#include "luxel/frame/renderer.hpp"
#include "luxel/frame/textures.hpp"
#include "luxel/scenes/paths.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace luxel::frame {
namespace {

constexpr int kExposureSize = 32;
constexpr double kGrey = 0.15;  // the scene's linear luminance before the tone map

/// An unlit grey square filling the view: the frame's luminance is kGrey x the scale.
scenes::Scene grey_scene() {
  scenes::Scene s = grey_square(kGrey);
  s.exposure.min_scale = 0.5f;
  s.exposure.max_scale = 8.0f;
  return s;
}

double decode(uint8_t code) {
  const double v = code / 255.0;
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

TEST(FrameAutoExposure, EachFrameIsDrawnAtTheScaleTheFramesBeforeChose) {
  const scenes::Scene s = grey_scene();
  Renderer r(s, {kExposureSize, kExposureSize, 4});
  ASSERT_NE(r.auto_exposure(), nullptr);
  rasterizer::Context ctx(2);
  EXPECT_EQ(r.exposure(), 1.0f) << "the first frame: 1 in the range";
  for (int f = 0; f < 900; ++f) {
    r.set_time(float(f) / 30.0f);
    const float scale = r.exposure();
    r.render(ctx);
    const uint8_t code = r.image().pixel(kExposureSize / 2, kExposureSize / 2)[1];
    EXPECT_EQ(code, uint8_t(std::lround(255.0 * srgb_encode(std::min(1.0, kGrey * scale))))) << "frame " << f;
    if (::testing::Test::HasFailure()) break;
  }
  // Settled in the percentile rule's sticky bin [0.5700, 0.6495], which holds 0.60.
  const double settled = decode(r.image().pixel(kExposureSize / 2, kExposureSize / 2)[1]);
  EXPECT_GE(settled, 0.5700);
  EXPECT_LE(settled, 0.6495);
  EXPECT_GT(r.exposure(), 0.56 / kGrey);
  EXPECT_LT(r.exposure(), 0.66 / kGrey);
  std::printf("grey %.2f settles at scale %.4f (luminance %.4f)\n", kGrey, r.exposure(), settled);

  // The clock goes back: the exposure starts again, and frame 0 is frame 0 again.
  Renderer fresh(s, {kExposureSize, kExposureSize, 4});
  fresh.render(ctx);
  r.set_time(0.0f);
  r.render(ctx);
  EXPECT_EQ(r.image().rgba, fresh.image().rgba);
}

TEST(FrameAutoExposure, EnteringAnExposureZoneChangesTheControlsWithoutAJump) {
  // The camera rises along its path (an orthographic view: the image does not change) and enters
  // a zone fixing the scale at 1 after 4 s; outside, the range lets the grey settle near 3.8.
  scenes::Scene s = grey_scene();
  for (float t : {0.0f, 10.0f}) {
    scenes::CameraKey key{t, s.cameras[0]};
    key.camera.position.z = 10.0f + 0.5f * t;
    s.camera_path.push_back(key);
  }
  scenes::ExposureZone zone{{-5, -5, 12}, {5, 5, 20}, {}};
  zone.exposure.min_scale = zone.exposure.max_scale = 1.0f;
  s.exposure_zones = {zone};
  FrameSettings settings{kExposureSize, kExposureSize, 4};
  settings.camera_path = true;
  Renderer r(s, settings);
  rasterizer::Context ctx(2);
  std::vector<float> scales;
  for (int f = 0; f < 600; ++f) {
    r.set_time(float(f) / 30.0f);
    scales.push_back(r.exposure());
    r.render(ctx);
  }
  EXPECT_EQ(scales[0], 1.0f);
  EXPECT_GT(scales[119], 1.5f) << "outside the zone the scale rose";
  // From the frame the camera enters, the scale falls towards 1, each frame by at most 1/64 of
  // the gap (the percentile rule's cap): no jump.
  int entered = 0;
  while (scenes::camera_at(s.camera_path, float(entered) / 30.0f).position.z < 12.0f) ++entered;
  int turned = 0;
  for (int f = 1; f + 1 < 600 && turned == 0; ++f)
    if (scales[size_t(f) + 1] < scales[size_t(f)]) turned = f;
  EXPECT_EQ(turned, entered) << "the frame drawn inside the zone sets the new goal";
  for (int f = turned; f + 1 < 600; ++f) {
    EXPECT_LE(scales[size_t(f)] - scales[size_t(f) + 1], (scales[size_t(f)] - 1.0f) / 64.0f + 1e-5f) << "frame " << f;
    EXPECT_GE(scales[size_t(f) + 1], 1.0f - 1e-5f) << "frame " << f;
  }
  EXPECT_NEAR(scales[599], 1.0f, 0.01f) << "settled at the zone's fixed scale";
}

TEST(FrameAutoExposure, SettlingFindsTheScaleTheSequenceStaysAt) {
  const scenes::Scene s = grey_scene();
  Renderer r(s, {kExposureSize, kExposureSize, 4});
  rasterizer::Context ctx(2);
  const SettledExposure settled = r.settle_exposure(ctx);
  EXPECT_TRUE(settled.settled);
  EXPECT_LE(settled.draws, 8);
  EXPECT_EQ(r.exposure(), settled.scale);
  // In the percentile rule's sticky bin, as the 900-frame sequence above ends: the grey's
  // luminance kGrey x scale in [0.5700, 0.6495].
  EXPECT_GE(kGrey * settled.scale, 0.5700);
  EXPECT_LE(kGrey * settled.scale, 0.6495);
  std::printf("grey %.2f: settled at scale %.4f after %d draws\n", kGrey, settled.scale, settled.draws);
  // At rest: ten seconds of frames from there keep the scale (the histogram fills and agrees).
  for (int f = 0; f < 300; ++f) {
    r.set_time(float(f) / 30.0f);
    r.render(ctx);
    ASSERT_NEAR(r.exposure(), settled.scale, 0.01f * settled.scale) << "frame " << f;
  }
  // A clock that goes back starts the exposure again, at the settled scale.
  r.set_time(0.0f);
  r.render(ctx);
  EXPECT_EQ(r.exposure(), settled.scale);
}

TEST(FrameAutoExposure, SettlingStopsAtTheRange) {
  // The grey wants a scale near 4; a range up to 2 keeps it at 2, which is then at rest.
  scenes::Scene s = grey_scene();
  s.exposure.max_scale = 2.0f;
  Renderer r(s, {kExposureSize, kExposureSize, 4});
  rasterizer::Context ctx(1);
  const SettledExposure settled = r.settle_exposure(ctx);
  EXPECT_TRUE(settled.settled);
  EXPECT_EQ(settled.scale, 2.0f);
  // A fixed exposure has nothing to settle.
  FrameSettings fixed_settings{kExposureSize, kExposureSize, 4};
  fixed_settings.exposure = 3.0f;
  const scenes::Scene grey = grey_scene();
  Renderer fixed(grey, fixed_settings);
  EXPECT_EQ(fixed.settle_exposure(ctx).draws, 0);
  EXPECT_EQ(fixed.exposure(), 3.0f);
  EXPECT_THROW(r.start_exposure_at(0.0f), std::invalid_argument);
  EXPECT_THROW(r.start_exposure_at(std::nanf("")), std::invalid_argument);
}

TEST(FrameAutoExposure, CourtyardSettlesAlikeOnOneAndTwoThreads) {
  scenes::Scene scene = scenes::make_builtin_scene("courtyard", {96, 54});
  attach_test_bake(scene);
  const auto textures = std::make_shared<const SceneTextures>(scene);
  Renderer one(scene, {96, 54, 4}, textures), two(scene, {96, 54, 4}, textures);
  rasterizer::Context ctx1(1), ctx2(2);
  const SettledExposure a = one.settle_exposure(ctx1), b = two.settle_exposure(ctx2);
  EXPECT_EQ(a.scale, b.scale);
  EXPECT_EQ(a.draws, b.draws);
  EXPECT_TRUE(a.settled) << "after " << a.draws << " draws at " << a.scale;
  EXPECT_LT(a.scale, 1.0f) << "the sunlit courtyard is brighter than the first frame's scale wants";
  one.render(ctx1);
  two.render(ctx2);
  EXPECT_EQ(one.image().rgba, two.image().rgba);
}

TEST(FrameAutoExposure, CourtyardSequenceWithEveryPassIsTheSameOnOneAndTwoThreads) {
  scenes::Scene scene = scenes::make_builtin_scene("courtyard", {96, 54});
  attach_test_bake(scene);
  FrameSettings settings{96, 54, 4};
  settings.camera_path = true;
  settings.histogram.count = postfx::HistogramCount::stencil;
  settings.bloom = postfx::BloomOptions{};
  settings.film_grain = postfx::FilmGrainOptions{42};  // and the courtyard's color-correction nodes
  const auto textures = std::make_shared<const SceneTextures>(scene);
  Renderer one(scene, settings, textures), two(scene, settings, textures);
  ASSERT_NE(one.auto_exposure(), nullptr) << "the courtyard has an exposure range";
  rasterizer::Context ctx1(1), ctx2(2);
  for (int f = 0; f < 30; ++f) {
    one.set_time(float(f) / 30.0f);
    two.set_time(float(f) / 30.0f);
    one.render(ctx1);
    two.render(ctx2);
    ASSERT_EQ(one.image().rgba, two.image().rgba) << "frame " << f;
    ASSERT_EQ(one.exposure(), two.exposure()) << "frame " << f;
  }
  EXPECT_NE(one.exposure(), 1.0f) << "the exposure moved within the second";
}

}  // namespace
}  // namespace luxel::frame
