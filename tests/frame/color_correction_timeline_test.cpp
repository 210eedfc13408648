// Color-correction nodes faded by their inputs and volumes ramped as the eye crosses them, in the
// frame: each frame is the plain frame blended by postfx::color_correct at a weight worked out
// here from docs/fidelity.md#color-correction (not by the code under test); a frame's weights depend on
// the clock's time alone, not on the frames rendered before; a camera path through a volume changes
// the weight, and the picture, by a bounded step per frame.

#include "frame/frame_support.hpp"

#include "luxel/frame/renderer.hpp"
#include "luxel/postfx/color_correction.hpp"
#include "luxel/postfx/lut_source.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace luxel::frame {
namespace {

constexpr int kTimelineSize = 32;
constexpr double kFps = 30.0;

using Kind = scenes::ColorCorrectionInput::Kind;

/// The color ramp seen from a camera rising 1 inch a second from z = 10 at t = 0: keys a second
/// and an inch apart from t = -1 to 10, through which the Catmull-Rom path is a straight line
/// (each key's tangent is the chord to the next). The view is orthographic, straight down: the
/// picture never changes, only the eye's height.
scenes::Scene rising() {
  scenes::Scene s = color_ramp();
  for (int t = -1; t <= 10; ++t) {
    scenes::CameraKey key{float(t), s.cameras[0]};
    key.camera.position.z = 10.0f + float(t);
    s.camera_path.push_back(key);
  }
  return s;
}

/// A volume the rising eye enters at z = `bottom` and leaves above `top`.
scenes::ColorCorrectionVolume slab(float bottom, float top, float fade) { return {"builtin:archival", {-5, -5, bottom}, {5, 5, top}, fade}; }

FrameSettings settings_at(const scenes::Scene& s, double time, bool color_correction = true) {
  FrameSettings f{kTimelineSize, kTimelineSize, 1};
  f.camera_path = !s.camera_path.empty();
  f.time = float(time);
  f.color_correction = color_correction;
  return f;
}

rasterizer::Image frame_at(const scenes::Scene& s, double time, bool color_correction = true) {
  return render_frame(s, settings_at(s, time, color_correction));
}

/// `plain` blended with builtin LUT `lut` at `weight` by the engine's pass (nothing at 0).
rasterizer::Image graded(const rasterizer::Image& plain, const char* lut, double weight) {
  if (weight <= 0.0) return plain;
  const postfx::Lut l = postfx::resolve_lut(lut);
  const postfx::WeightedLut w{&l, float(weight)};
  rasterizer::Context ctx(1);
  return postfx::color_correct(ctx, plain, {&w, 1});
}

int largest_difference(const rasterizer::Image& a, const rasterizer::Image& b) {
  int largest = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) largest = std::max(largest, std::abs(int(a.rgba[i]) - int(b.rgba[i])));
  return largest;
}

TEST(FrameColorCorrectionTimeline, AVolumeRampsUpFromTheTickTheEyeEntersIt) {
  // The eye reaches z = 10.495 at t = 0.495; the volume thinks every 0.01 s, so it sees the eye
  // enter at t = 0.5 and ramps 0 + (t - 0.5) / ((1 - 0) x 2).
  scenes::Scene s = rising();
  s.color_correction_volumes = {slab(10.495f, 30.0f, 2.0f)};
  const rasterizer::Image plain = frame_at(s, 0.0, false);
  EXPECT_EQ(frame_at(s, 0.49, false).rgba, plain.rgba) << "the picture does not change as the eye rises";
  EXPECT_EQ(frame_at(s, 0.49).rgba, plain.rgba) << "not entered yet";
  EXPECT_EQ(frame_at(s, 0.875).rgba, graded(plain, "builtin:archival", 0.1875).rgba);
  EXPECT_EQ(frame_at(s, 1.25).rgba, graded(plain, "builtin:archival", 0.375).rgba);
  EXPECT_EQ(frame_at(s, 3.0).rgba, graded(plain, "builtin:archival", 1.0).rgba) << "capped at 1 from t = 2.5";
}

TEST(FrameColorCorrectionTimeline, ANodeFadesAsItsInputsSay) {
  // StartDisabled, maxweight 0.8, fade in 3 s, fade out 1 s; Enable at 1, Disable at 2.
  scenes::Scene s = color_ramp();
  scenes::ColorCorrection node;
  node.lut = "builtin:archival";  // falloffs 0, 0: seen everywhere
  node.max_weight = 0.8f, node.fade_in = 3.0f, node.fade_out = 1.0f, node.start_disabled = true;
  node.inputs = {{1.0f, Kind::enable}, {2.0f, Kind::disable}};
  s.color_corrections = {node};
  const rasterizer::Image plain = frame_at(s, 0.0, false);
  EXPECT_EQ(frame_at(s, 0.5).rgba, plain.rgba) << "disabled until enabled";
  // Enabled at 1 from 0: 0.8 x (t - 1) / 3.
  EXPECT_EQ(frame_at(s, 1.75).rgba, graded(plain, "builtin:archival", 0.8 * 0.75 / 3).rgba);
  EXPECT_EQ(frame_at(s, 2.0).rgba, graded(plain, "builtin:archival", 0.8 / 3).rgba);
  // Disabled at 2 from a third of the way up: the 1 s fade out shortened to 1/3 s, so 0.25 s in
  // the weight is (0.8 / 3) x (1 - 0.25 / (1/3)) = 0.8 / 12.
  EXPECT_EQ(frame_at(s, 2.25).rgba, graded(plain, "builtin:archival", 0.8 / 12).rgba);
  EXPECT_EQ(frame_at(s, 2.5).rgba, plain.rgba) << "faded out at 2 + 1/3";
}

TEST(FrameColorCorrectionTimeline, ANodeWithoutInputsHoldsItsMaxWeight) {
  scenes::Scene s = color_ramp();
  scenes::ColorCorrection node;
  node.lut = "builtin:archival";
  node.max_weight = 0.6f, node.fade_in = 2.0f, node.fade_out = 2.0f;
  s.color_corrections = {node};
  const rasterizer::Image plain = frame_at(s, 0.0, false);
  EXPECT_EQ(frame_at(s, 0.0).rgba, graded(plain, "builtin:archival", 0.6).rgba);
  EXPECT_EQ(frame_at(s, 7.5).rgba, graded(plain, "builtin:archival", 0.6).rgba);
}

TEST(FrameColorCorrectionTimeline, AFrameDoesNotDependOnTheFramesRenderedBeforeIt) {
  scenes::Scene s = rising();
  s.color_correction_volumes = {slab(10.495f, 11.2f, 0.75f)};  // entered at 0.5, left at 1.21
  scenes::ColorCorrection node;
  node.lut = "builtin:warm";
  node.fade_in = 0.5f, node.fade_out = 0.5f, node.start_disabled = true;
  node.inputs = {{0.3f, Kind::enable}, {1.1f, Kind::disable}};
  s.color_corrections = {node};
  auto time = [](int frame) { return double(frame) / kFps; };
  constexpr int kLast = 45;
  Renderer sequence(s, settings_at(s, 0.0));
  rasterizer::Context ctx(2);
  std::vector<rasterizer::Image> frames;
  for (int f = 0; f <= kLast; ++f) {
    sequence.set_time(float(time(f)));
    sequence.render(ctx);
    frames.push_back(sequence.image());
  }
  EXPECT_NE(frames[12].rgba, frames[0].rgba) << "the weights do change along the way";
  for (int f : {12, 20, 33, 36, kLast}) EXPECT_EQ(frame_at(s, time(f)).rgba, frames[size_t(f)].rgba) << "frame " << f << " alone";
  // From the middle of the sequence on (--frames A:B), and back in time.
  Renderer later(s, settings_at(s, time(30)));
  for (int f = 30; f <= kLast; ++f) {
    later.set_time(float(time(f)));
    later.render(ctx);
    EXPECT_EQ(later.image().rgba, frames[size_t(f)].rgba) << "frame " << f << " after frame 30";
  }
  later.set_time(float(time(17)));
  later.render(ctx);
  EXPECT_EQ(later.image().rgba, frames[17].rgba) << "frame 17 after frame 45";
}

TEST(FrameColorCorrectionTimeline, ACameraPathThroughAVolumeChangesTheFramesSmoothly) {
  // The eye passes z = 11.005 at t = 1.005 and z = 13.005 at t = 3.005: the volume sees it enter
  // at the tick 1.01 and leave at 3.01. Fade 1.5 s: up to 1 by 2.51, down from 1 to 0 by 4.51.
  constexpr double kFade = 1.5;
  scenes::Scene s = rising();
  s.color_correction_volumes = {slab(11.005f, 13.005f, float(kFade))};
  auto expected = [&](double t) {
    if (t >= 3.01) return 1.0 - std::min(1.0, (t - 3.01) / kFade);
    if (t >= 1.01) return std::min(1.0, (t - 1.01) / kFade);
    return 0.0;
  };
  const rasterizer::Image plain = frame_at(s, 0.0, false);
  Renderer r(s, settings_at(s, 0.0));
  rasterizer::Context ctx(2);
  rasterizer::Image previous;
  double previous_weight = 0.0, highest = 0.0;
  for (int f = 0; f <= 150; ++f) {
    const float t = float(double(f) / kFps);
    r.set_time(t);
    r.render(ctx);
    const double w = expected(double(t));
    highest = std::max(highest, w);
    // The frame's float arithmetic and this double one may round a pixel apart.
    ASSERT_LE(largest_difference(r.image(), graded(plain, "builtin:archival", w)), 1) << "frame " << f << " at weight " << w;
    if (f > 0) {
      // The weight moves at most 1 / (30 x 1.5) a frame (and the float clock's rounding); a
      // channel of the blend at most 255 times that (|LUT(c) - c| <= 1), and a step more for the
      // rounding to 8 bits.
      EXPECT_LE(std::abs(w - previous_weight), 1.0 / (kFps * kFade) + 1e-6) << "frame " << f;
      EXPECT_LE(largest_difference(r.image(), previous), int(std::ceil(255.0 / (kFps * kFade))) + 1) << "frame " << f;
    }
    previous = r.image();
    previous_weight = w;
  }
  EXPECT_EQ(highest, 1.0);
  EXPECT_EQ(previous.rgba, plain.rgba) << "faded out after leaving";
}

}  // namespace
}  // namespace luxel::frame
