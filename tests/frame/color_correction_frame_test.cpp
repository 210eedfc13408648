// The frame's color-correction pass: the scene's nodes weighted by the eye's distance through
// their falloffs and blended by postfx::color_correct after everything else; no pass where every
// weight is 0; a node whose LUT cannot be had is refused with its index and the file.

#include "frame/frame_support.hpp"

#include "luxel/frame/renderer.hpp"
#include "luxel/postfx/color_correction.hpp"
#include "luxel/postfx/lut_source.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace luxel::frame {
namespace {

constexpr int kGradedSize = 32;

/// The color ramp (frame_support.hpp), the eye at (0, 0, 10), and a warm node `distance` above
/// the eye, fading out from 0 to 128 inches.
scenes::Scene graded(float distance) {
  scenes::Scene s = color_ramp();
  scenes::ColorCorrection warm;
  warm.lut = "builtin:warm";
  warm.position = {0, 0, 10 + distance};
  warm.min_falloff = 0, warm.max_falloff = 128;
  warm.max_weight = 0.8f;
  s.color_corrections = {warm};
  return s;
}

rasterizer::Image render(const scenes::Scene& s, bool color_correction, std::vector<PassTime>* passes = nullptr) {
  FrameSettings f{kGradedSize, kGradedSize, 4};
  f.color_correction = color_correction;
  f.time_passes = passes != nullptr;
  Renderer r(s, f);
  rasterizer::Context ctx(2);
  r.render(ctx);
  if (passes) *passes = r.pass_times();
  return r.image();
}

bool has_pass(const std::vector<PassTime>& passes, const std::string& name) {
  return std::any_of(passes.begin(), passes.end(), [&](const PassTime& p) { return p.pass == name; });
}

TEST(FrameColorCorrection, TheNodeIsBlendedAtTheWeightItsFalloffGivesTheEye) {
  const scenes::Scene s = graded(32.0f);
  std::vector<PassTime> passes;
  const rasterizer::Image corrected = render(s, true, &passes);
  EXPECT_TRUE(has_pass(passes, "color correction"));
  const rasterizer::Image plain = render(s, false);
  // 32 of the 128 inches of falloff: 0.8 x (1 - 0.25).
  const postfx::Lut warm = postfx::resolve_lut("builtin:warm");
  const postfx::WeightedLut lut{&warm, 0.8f * 0.75f};
  rasterizer::Context ctx(1);
  EXPECT_EQ(corrected.rgba, postfx::color_correct(ctx, plain, {&lut, 1}).rgba);
  EXPECT_NE(corrected.rgba, plain.rgba);
}

TEST(FrameColorCorrection, NoPassBeyondTheFalloffNorWhenTurnedOff) {
  std::vector<PassTime> passes;
  const rasterizer::Image far = render(graded(200.0f), true, &passes);
  EXPECT_FALSE(has_pass(passes, "color correction")) << "weight 0 beyond max_falloff";
  EXPECT_EQ(far.rgba, render(graded(200.0f), false).rgba);
  render(graded(0.0f), false, &passes);
  EXPECT_FALSE(has_pass(passes, "color correction"));
}

TEST(FrameColorCorrection, ANodeWithoutItsLutIsRefused) {
  scenes::Scene s = graded(0.0f);
  s.color_corrections[0].lut = "builtin:sepia-ish";
  FrameSettings f{kGradedSize, kGradedSize, 4};
  try {
    Renderer r(s, f);
    FAIL() << "an unknown built-in LUT was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("color correction 0: builtin:sepia-ish"), std::string::npos) << e.what();
  }
  s.color_corrections[0].lut = "/nonexistent/grade.cube";
  try {
    Renderer r(s, f);
    FAIL() << "a missing LUT file was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/grade.cube"), std::string::npos) << e.what();
  }
  f.color_correction = false;
  EXPECT_NO_THROW(Renderer(s, f)) << "nodes are not read when the pass is off";
}

}  // namespace
}  // namespace luxel::frame
