// Bloom over a sequence of frames against the bloom computed here from the un-bloomed frames: a
// uniform grey frame, whose bloom reduces to a few scalars per frame (the SDK's shaped
// downsample, the two 13-tap blurs, the add in gamma space, each rounded to the 8-bit target
// it is drawn into), with the bloom amount's smoothing from frame to frame written out from
// viewpostprocess.cpp's GetBloomAmount, as the camera enters a zone with a larger bloom scale.
// The exposure the frames are drawn at must be the same with and without bloom: the histogram
// counts the frame before the bloom is added (docs/fidelity.md#bloom, #auto-exposure).

#include "frame/frame_support.hpp"

#include "luxel/frame/renderer.hpp"
#include "luxel/scenes/paths.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace luxel::frame {
namespace {

constexpr int kBloomFrameSize = 32;
constexpr int kBloomFrames = 240;
constexpr double kBloomGrey = 0.15;  // linear, before the tone map

/// D3D's UNORM write: times 255, rounded to nearest (even at the half).
double unorm8(double v) { return std::nearbyint(std::clamp(v, 0.0, 1.0) * 255.0) / 255.0; }

/// An unlit grey square filling an orthographic view; the camera rises along its path and enters,
/// after 4 s, a zone whose controls are the scene's but for a bloom scale of 2.
scenes::Scene bloom_zone_scene() {
  scenes::Scene s = grey_square(kBloomGrey);
  // A narrow range: the scale moves from 1 to 1.2 and stays below where grey plus bloom clips.
  s.exposure.min_scale = 0.5f;
  s.exposure.max_scale = 1.2f;
  for (float t : {0.0f, 10.0f}) {
    scenes::CameraKey key{t, s.cameras[0]};
    key.camera.position.z = 10.0f + 0.5f * t;
    s.camera_path.push_back(key);
  }
  scenes::ExposureZone zone{{-5, -5, 12}, {5, 5, 40}, s.exposure};
  zone.exposure.bloom_scale = 2.0f;
  s.exposure_zones = {zone};
  return s;
}

/// The frames' centre pixel (green) and the exposure each was drawn at.
struct BloomSequence {
  std::vector<int> codes;
  std::vector<float> scales;
};

BloomSequence run_bloom_sequence(const scenes::Scene& s, bool bloom) {
  FrameSettings settings{kBloomFrameSize, kBloomFrameSize, 4};
  settings.camera_path = true;
  if (bloom) settings.bloom = postfx::BloomOptions{};
  Renderer r(s, settings);
  rasterizer::Context ctx(2);
  BloomSequence out;
  for (int f = 0; f < kBloomFrames; ++f) {
    r.set_time(float(f) / 30.0f);
    out.scales.push_back(r.exposure());
    r.render(ctx);
    out.codes.push_back(r.image().pixel(kBloomFrameSize / 2, kBloomFrameSize / 2)[1]);
  }
  return out;
}

TEST(FrameBloom, OverFramesIsTheSdksBloomOfTheUnbloomedFramesAtTheSmoothedAmount) {
  const scenes::Scene s = bloom_zone_scene();
  const BloomSequence plain = run_bloom_sequence(s, false);
  const BloomSequence bloomed = run_bloom_sequence(s, true);

  // The exposure sequence does not see the bloom.
  ASSERT_EQ(bloomed.scales, plain.scales) << "the histogram must count the frame before the bloom is added";
  EXPECT_GT(plain.scales.back(), plain.scales.front()) << "the exposure moved: the check above compared a sequence";

  // Bloom amount (GetBloomAmount): smoothed = scale 0.05 + 0.95 smoothed, once per frame, from the
  // scale at the first frame's eye; INTEGER HDR: no LDR factor.
  double smoothed = 1.0;  // the scene's own bloom scale where the camera starts
  // The blur's weights (BlurFilter_ps2x.fxc: centre and six pairs) on a uniform texture.
  const double blur_sum = 0.2013 + 2.0 * (0.2185 + 0.0821 + 0.0461 + 0.0262 + 0.0162 + 0.0102);
  int entered = -1, worst = 0;
  for (int f = 0; f < kBloomFrames; ++f) {
    const bool inside = scenes::camera_at(s.camera_path, float(f) / 30.0f).position.z >= 12.0f;
    if (inside && entered < 0) entered = f;
    smoothed = (inside ? 2.0 : 1.0) * 0.05 + 0.95 * smoothed;
    const double g = plain.codes[size_t(f)] / 255.0;  // the frame, read with sRGB off
    // Downsample_nohdr: each tap p^2.2 dot(p, (0.3, 0.59, 0.11)), four averaged; a grey p: p^3.2.
    const double down = unorm8(std::pow(g, 2.2) * g);
    const double across = unorm8(down * blur_sum);
    const double up = unorm8(across * blur_sum * smoothed);  // the vertical pass times the amount
    const int want = int(std::lround(unorm8(g + up) * 255.0));  // bloomadd: ONE/ONE on gamma values
    const int got = bloomed.codes[size_t(f)];
    worst = std::max(worst, std::abs(got - want));
    EXPECT_LE(std::abs(got - want), 1) << "frame " << f << ": un-bloomed " << plain.codes[size_t(f)] << ", amount "
                                       << smoothed;
    if (::testing::Test::HasFailure()) break;
  }
  ASSERT_GT(entered, 0);
  // The bloom grows as the amount does: the smoothing, not a jump to the zone's scale.
  const int before = bloomed.codes[size_t(entered)] - plain.codes[size_t(entered)];
  const int later = bloomed.codes.back() - plain.codes.back();
  EXPECT_GT(later, before + 10) << "the amount rose towards 2 over the frames after the zone was entered";
  std::printf("bloom over %d frames: zone entered at frame %d, bloom adds %d codes there and %d at the end; "
              "max %d step(s) from the bloom computed here\n",
              kBloomFrames, entered, before, later, worst);
}

}  // namespace
}  // namespace luxel::frame
