// The archival look (frame/look.hpp): its grade blended at full weight over the scene's nodes
// within the pass's four lookups, its stronger grain; the frame is desaturated and grainy, the
// grain moves from frame to frame, and the bytes do not depend on the thread count.

#include "frame/frame_support.hpp"

#include "luxel/frame/look.hpp"
#include "luxel/frame/renderer.hpp"
#include "luxel/postfx/color_correction.hpp"
#include "luxel/postfx/film_grain.hpp"
#include "luxel/postfx/lut_source.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <vector>

namespace luxel::frame {
namespace {

constexpr int kLookSize = 64;

FrameSettings archival(float time = 0.0f) {
  FrameSettings f{kLookSize, kLookSize, 1};
  f.look = Look::archival;
  f.time = time;
  return f;
}

/// A global node (no falloff) of `lut` holding `weight`.
scenes::ColorCorrection global_node(const char* lut, float weight) {
  scenes::ColorCorrection c;
  c.lut = lut;
  c.max_weight = weight;
  return c;
}

/// What the archival frame at `time` must be: `plain` through the pass with `lookups` (LUT, weight),
/// then the archival grain of the frame at that time.
rasterizer::Image expected(const rasterizer::Image& plain, const std::vector<std::pair<postfx::Lut, float>>& lookups, float time) {
  std::vector<postfx::WeightedLut> weighted;
  for (const auto& [lut, weight] : lookups) weighted.push_back({&lut, weight});
  rasterizer::Context ctx(1);
  rasterizer::Image out = postfx::color_correct(ctx, plain, weighted);
  postfx::FilmGrain(*look_film_grain(Look::archival, std::nullopt)).apply(ctx, out, std::bit_cast<uint32_t>(time));
  return out;
}

TEST(FrameLook, ArchivalGradesOverTheScenesNodesWithinFourLookups) {
  const postfx::ColorTransform grade = postfx::color_transform_named("builtin:archival");
  const postfx::Lut alone = postfx::sample_lut(grade);
  const postfx::Lut warm = postfx::compose(postfx::resolve_lut("builtin:warm"), grade);
  const postfx::Lut cool = postfx::compose(postfx::resolve_lut("builtin:cool"), grade);
  scenes::Scene s = color_ramp();
  const rasterizer::Image plain = render_frame(s, FrameSettings{kLookSize, kLookSize, 1});

  // No nodes: the grade alone, at 1.
  EXPECT_EQ(render_frame(s, archival()).rgba, expected(plain, {{alone, 1.0f}}, 0.0f).rgba);
  // One node at 0.5: it keeps its weight, composed with the grade; the grade takes the rest.
  s.color_corrections = {global_node("builtin:warm", 0.5f)};
  EXPECT_EQ(render_frame(s, archival()).rgba, expected(plain, {{warm, 0.5f}, {alone, 0.5f}}, 0.0f).rgba);
  // Four nodes at 0.2: the three heaviest (the earlier on a tie), the grade the fourth at 0.4.
  s.color_corrections = {global_node("builtin:warm", 0.2f), global_node("builtin:cool", 0.2f),
                         global_node("builtin:warm", 0.2f), global_node("builtin:cool", 0.2f)};
  EXPECT_EQ(render_frame(s, archival()).rgba, expected(plain, {{warm, 0.2f}, {cool, 0.2f}, {warm, 0.2f}, {alone, 0.4f}}, 0.0f).rgba);
  // Five at 0.4: the three heaviest weigh 1.2, nothing is left for the grade alone: four nodes.
  s.color_corrections = {global_node("builtin:cool", 0.4f), global_node("builtin:warm", 0.4f),
                         global_node("builtin:cool", 0.4f), global_node("builtin:warm", 0.4f),
                         global_node("builtin:cool", 0.4f)};
  EXPECT_EQ(render_frame(s, archival()).rgba, expected(plain, {{cool, 0.4f}, {warm, 0.4f}, {cool, 0.4f}, {warm, 0.4f}}, 0.0f).rgba);
  // Without the scene's nodes (mat_colorcorrection 0) the look still grades.
  FrameSettings no_nodes = archival();
  no_nodes.color_correction = false;
  EXPECT_EQ(render_frame(s, no_nodes).rgba, expected(plain, {{alone, 1.0f}}, 0.0f).rgba);
}

/// Mean over the pixels of max(r, g, b) - min(r, g, b), in 8-bit steps.
double mean_chroma(const rasterizer::Image& image) {
  double sum = 0.0;
  for (size_t i = 0; i < image.rgba.size(); i += 4) {
    const auto [lo, hi] = std::minmax({image.rgba[i], image.rgba[i + 1], image.rgba[i + 2]});
    sum += hi - lo;
  }
  return sum / (double(image.rgba.size()) / 4);
}

/// Standard deviation over every channel of a - b, in 8-bit steps.
double noise(const rasterizer::Image& a, const rasterizer::Image& b) {
  double sum = 0.0, squares = 0.0;
  size_t n = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) {
    if (i % 4 == 3) continue;
    const double d = double(a.rgba[i]) - double(b.rgba[i]);
    sum += d, squares += d * d, ++n;
  }
  const double mean = sum / double(n);
  return std::sqrt(squares / double(n) - mean * mean);
}

TEST(FrameLook, ArchivalIsDesaturatedAndGrainy) {
  const scenes::Scene s = color_ramp();
  const rasterizer::Image plain = render_frame(s, FrameSettings{kLookSize, kLookSize, 1});
  const rasterizer::Image old = render_frame(s, archival());
  // Saturation 0.1 leaves a tenth of the chroma; the sepia balance adds at most 0.06 (15 steps)
  // between red and blue and the grain is the same in every channel, so under 0.1 x plain + 15:
  // with the ramp's mean chroma near 48, under 20, where the plain frame is above 40.
  const double plain_chroma = mean_chroma(plain), old_chroma = mean_chroma(old);
  EXPECT_GT(plain_chroma, 40.0) << "the ramp is colorful";
  EXPECT_LT(old_chroma, 0.1 * plain_chroma + 15.0) << plain_chroma;

  // Grain: the frame minus the same grade without grain. A pixel f takes (0.12 + 0.15 f) n from
  // the archival grain's uniform n, (0.1 + 0.1 f) n from the default's: at mid grey 0.195 x 255
  // steps (a standard deviation of 14) against 0.15 x 255 (11), in ratio 1.25 to 1.33 over this
  // ramp's levels.
  const postfx::Lut grade = postfx::resolve_lut("builtin:archival");
  const postfx::WeightedLut full{&grade, 1.0f};
  rasterizer::Context ctx(1);
  const rasterizer::Image graded = postfx::color_correct(ctx, plain, {&full, 1});
  FrameSettings grainy{kLookSize, kLookSize, 1};
  grainy.film_grain = postfx::FilmGrainOptions{};
  const double archival_noise = noise(old, graded), default_noise = noise(render_frame(s, grainy), plain);
  EXPECT_GT(archival_noise, 10.0);
  EXPECT_GT(archival_noise, 1.2 * default_noise) << default_noise;
}

TEST(FrameLook, ArchivalGrainMovesEachFrameAndIsTheSameOnAnyThreadCount) {
  const scenes::Scene s = color_ramp();
  const rasterizer::Image first = render_frame(s, archival(0.0f), 1);
  EXPECT_EQ(render_frame(s, archival(0.0f), 2).rgba, first.rgba);
  const rasterizer::Image next = render_frame(s, archival(1.0f / 30.0f), 1);
  EXPECT_EQ(render_frame(s, archival(1.0f / 30.0f), 2).rgba, next.rgba);
  EXPECT_GT(noise(first, next), 10.0) << "each frame its own grain";
  // A seed of its own (luxel render --film-grain SEED) gives other grain at the same strength.
  FrameSettings seeded = archival(0.0f);
  seeded.film_grain = postfx::FilmGrainOptions{7};
  EXPECT_NE(render_frame(s, seeded).rgba, first.rgba);
}

}  // namespace
}  // namespace luxel::frame
