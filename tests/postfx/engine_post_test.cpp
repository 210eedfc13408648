// Bloom and color correction in one pass (Engine_Post, docs/fidelity.md#bloom): against a reference
// written here in double from the formulas (the frame plus the bloom texture stretched over it,
// the unrounded sum looked up trilinearly in each LUT, clamped at the volume's edges), the same
// bytes for any thread count, and where the sum passes 1 the result differs from adding first and
// correcting the rounded frame afterwards, as the engine's one pass does.

#include "image_plane.hpp"
#include "lut_support.hpp"

#include "luxel/postfx/bloom.hpp"
#include "luxel/postfx/color_correction.hpp"
#include "luxel/postfx/full_frame.hpp"
#include "luxel/postfx/lut_source.hpp"
#include "luxel/rasterizer/framebuffer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

namespace luxel::postfx {
namespace {

/// Bright discs on a mid-grey noise: the bloom is strong, and frame plus bloom passes 1 near them.
rasterizer::Image bright_frame(int width, int height, uint32_t seed) {
  rasterizer::Image image(width, height);
  std::mt19937 rng(seed);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      uint8_t* p = image.pixel(x, y);
      const bool disc = std::hypot(x - width * 0.35, y - height * 0.5) < height * 0.2;
      p[0] = disc ? 250 : uint8_t(90 + rng() % 100);
      p[1] = disc ? 240 : uint8_t(60 + rng() % 120);
      p[2] = disc ? 225 : uint8_t(40 + rng() % 140);
      p[3] = 255;
    }
  return image;
}

glm::dvec3 lookup(const test::Lattice& lut, glm::dvec3 color) {
  return test::hardware_trilinear(lut, color) / 255.0;  // clamped to the lattice, as the volume's sampler
}

TEST(EnginePost, MatchesADoubleReferenceOfTheUnroundedSumWithinOneStep) {
  const Lut night = resolve_lut("builtin:day-for-night"), warm = resolve_lut("builtin:warm");
  const WeightedLut luts[] = {{&night, 0.45f}, {&warm, 0.35f}};  // the frame keeps 0.2
  const rasterizer::Image frame = bright_frame(160, 90, 7);
  rasterizer::Context ctx(2);
  Bloom bloom;
  ASSERT_TRUE(bloom.blur(ctx, frame, 1.5f));
  const rasterizer::Image out = color_correct(ctx, bloom, luts);

  const test::Lattice night_lattice = test::lut_lattice(night), warm_lattice = test::lut_lattice(warm);
  const test::Plane f = test::plane_of(frame), b = test::plane_of(bloom.small_image());
  const int W = frame.width, H = frame.height, w = b.width, h = b.height;
  const double ax = double(w - 1) / (W - 1), ay = (h - 1 + 0.5) / (H - 1);  // texels (0, -0.5) to (w-1, h-1)
  int worst = 0, above_one = 0, changed = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const glm::dvec3 sum = f.at(x, y) + b.sample((0.5 + x * ax) / w, (y * ay) / h);
      const glm::dvec3 expected = sum * 0.2 + lookup(night_lattice, sum) * 0.45 + lookup(warm_lattice, sum) * 0.35;
      above_one += sum.x > 1.0 || sum.y > 1.0 || sum.z > 1.0;
      for (int c = 0; c < 3; ++c) {
        const int e = int(std::lround(std::clamp(expected[c], 0.0, 1.0) * 255.0));
        worst = std::max(worst, std::abs(int(out.pixel(x, y)[c]) - e));
        changed += out.pixel(x, y)[c] != frame.pixel(x, y)[c];
      }
      EXPECT_EQ(out.pixel(x, y)[3], frame.pixel(x, y)[3]) << "alpha is the frame's";
    }
  EXPECT_LE(worst, 1);
  EXPECT_GT(above_one, W * H / 20) << "the test reaches sums above 1, where the one pass differs from two";
  EXPECT_GT(changed, W * H * 2) << "bloom and correction are visible";
  std::printf("Engine_Post vs double (%dx%d): max %d step, %d pixels sum above 1\n", W, H, worst, above_one);
}

TEST(EnginePost, DiffersFromAddingThenCorrectingOnlyWhereTheRoundedSumLosesSomething) {
  const Lut night = resolve_lut("builtin:day-for-night");
  const WeightedLut luts[] = {{&night, 0.6f}};
  const rasterizer::Image frame = bright_frame(128, 72, 3);
  rasterizer::Context ctx(2);
  Bloom bloom;
  ASSERT_TRUE(bloom.blur(ctx, frame, 1.5f));
  const rasterizer::Image one_pass = color_correct(ctx, bloom, luts);
  rasterizer::Image added = frame;
  Bloom(BloomOptions{}).apply(ctx, added, 1.5f);
  const rasterizer::Image two_passes = color_correct(ctx, added, luts);
  int far_below_one = 0, far_differs = 0, above_one_differs = 0;
  for (int y = 0; y < frame.height; ++y)
    for (int x = 0; x < frame.width; ++x) {
      const uint8_t* a = added.pixel(x, y);
      const bool saturated = a[0] == 255 || a[1] == 255 || a[2] == 255;
      for (int c = 0; c < 3; ++c) {
        const int d = std::abs(int(one_pass.pixel(x, y)[c]) - int(two_passes.pixel(x, y)[c]));
        if (!saturated) {
          ++far_below_one;
          far_differs += d > 1;  // only the sum's 8-bit rounding separates them
        } else {
          above_one_differs += d > 1;
        }
      }
    }
  EXPECT_GT(far_below_one, 1000);
  EXPECT_EQ(far_differs, 0);
  EXPECT_GT(above_one_differs, 0) << "a sum above 1 keeps its share of the frame's weight";
}

// The bloom's and the color correction's targets are invalidated, not cleared: their draws must
// write every pixel. After a frame that left magenta in every thread's tile memory, the passes
// give the bytes of a fresh context.
TEST(EnginePost, ThePassesWriteEveryPixelOfTheirInvalidatedTargets) {
  const Lut warm = resolve_lut("builtin:warm");
  const WeightedLut luts[] = {{&warm, 0.7f}};
  const rasterizer::Image frame = bright_frame(301, 170, 11);  // not whole tiles or stamps
  const auto passes = [&](rasterizer::Context& ctx) {
    Bloom bloom;
    EXPECT_TRUE(bloom.blur(ctx, frame, 1.0f));
    return color_correct(ctx, bloom, luts).rgba;
  };
  rasterizer::Context fresh(2), used(2);
  rasterizer::ColorTarget magenta(301, 170, 4);  // four samples: more tile memory than the passes use
  rasterizer::clear_color(used, magenta, glm::vec4(1, 0, 1, 1));
  rasterizer::discard(used, magenta);
  const rasterizer::Image filled = rasterizer::resolve(used, magenta);
  ASSERT_EQ(filled.pixel(300, 169)[1], 0);
  EXPECT_EQ(used.stats().tile_memory_targets, 1u);
  EXPECT_EQ(passes(used), passes(fresh));
}

TEST(EnginePost, SameBytesForAnyThreadCount) {
  const Lut warm = resolve_lut("builtin:warm"), cool = resolve_lut("builtin:cool"), night = resolve_lut("builtin:day-for-night"),
            archival = resolve_lut("builtin:archival");
  const WeightedLut luts[] = {{&warm, 0.3f}, {&cool, 0.2f}, {&night, 0.2f}, {&archival, 0.2f}};
  const rasterizer::Image frame = bright_frame(301, 170, 5);
  std::vector<uint8_t> first;
  for (int threads : {1, 2, 3}) {
    rasterizer::Context ctx(threads);
    Bloom bloom;
    ASSERT_TRUE(bloom.blur(ctx, frame, 1.0f));
    for (int n = 1; n <= 4; ++n) {
      const rasterizer::Image out = color_correct(ctx, bloom, std::span<const WeightedLut>(luts, size_t(n)));
      if (threads == 1 && n == 4) first = out.rgba;
      if (threads > 1 && n == 4) {
        EXPECT_EQ(out.rgba, first) << threads << " threads";
      }
    }
  }
}

TEST(EnginePost, TheFramesSharedCopyGivesTheSameBytes) {
  // The renderer's post passes read one copy of the frame (full_frame.hpp) instead of each its
  // own: bloom (with and without the add), color correction with and without the bloom.
  const Lut warm = resolve_lut("builtin:warm");
  const WeightedLut luts[] = {{&warm, 0.7f}};
  const rasterizer::Image frame = bright_frame(96, 54, 11);
  rasterizer::Context ctx(2);
  FullFrameTexture copy;
  copy.update(frame);

  Bloom own, shared;
  ASSERT_TRUE(own.blur(ctx, frame, 1.2f));
  ASSERT_TRUE(shared.blur(ctx, copy.texture(), 1.2f));
  EXPECT_EQ(&shared.frame_texture(), &copy.texture()) << "read, not copied";
  EXPECT_EQ(shared.small_image().rgba, own.small_image().rgba);
  EXPECT_EQ(color_correct(ctx, shared, luts).rgba, color_correct(ctx, own, luts).rgba);

  rasterizer::Image added = frame, added_shared = frame;
  Bloom().apply(ctx, added, 1.2f);
  shared.add(ctx, added_shared);
  EXPECT_EQ(added_shared.rgba, added.rgba);
  EXPECT_NE(added.rgba, frame.rgba) << "test setup: the bloom shows";

  EXPECT_EQ(color_correct(ctx, copy.texture(), luts).rgba, color_correct(ctx, frame, luts).rgba);
  const rasterizer::Texture srgb = rasterizer::Texture::create_2d(96, 54, rasterizer::TextureFormat::RGBA8_sRGB, 1);
  EXPECT_THROW(color_correct(ctx, srgb, luts), std::invalid_argument) << "the copy is read as gamma values";
  EXPECT_THROW(Bloom().blur(ctx, srgb, 1.0f), std::invalid_argument);
}

TEST(EnginePost, ArgumentsAreChecked) {
  const Lut warm = resolve_lut("builtin:warm");
  const WeightedLut luts[] = {{&warm, 1.0f}};
  rasterizer::Context ctx(1);
  Bloom bloom;
  EXPECT_THROW(color_correct(ctx, bloom, luts), std::logic_error) << "no frame blurred yet";
  EXPECT_FALSE(bloom.blur(ctx, bright_frame(16, 16, 1), 0.0f)) << "amount 0 runs nothing, as the SDK";
  ASSERT_TRUE(bloom.blur(ctx, bright_frame(16, 16, 1), 1.0f));
  const WeightedLut negative[] = {{&warm, -0.5f}};
  EXPECT_THROW(color_correct(ctx, bloom, negative), std::invalid_argument);
  EXPECT_THROW(color_correct(ctx, bloom, std::span<const WeightedLut>()), std::invalid_argument);
}

}  // namespace
}  // namespace luxel::postfx
