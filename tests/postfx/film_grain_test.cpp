// Film grain (docs/fidelity.md#film-grain): the tile is a function of (seed, frame) alone and looks
// like uniform noise; the blend on a frame matches the shader's formula in double; the same bytes for
// 1 and 2 threads; alpha kept.

#include "luxel/postfx/film_grain.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace luxel::postfx {
namespace {

double fraction_differing(const rasterizer::Image& a, const rasterizer::Image& b) {
  int differ = 0;
  for (size_t i = 0; i < a.rgba.size(); i += 4) differ += a.rgba[i] != b.rgba[i];
  return differ / double(a.rgba.size() / 4);
}

TEST(FilmGrain, TileDependsOnSeedAndFrameOnly) {
  FilmGrainOptions options;
  options.seed = 42;
  const rasterizer::Image a = grain_tile(options, 7);
  EXPECT_EQ(grain_tile(options, 7).rgba, a.rgba) << "deterministic";
  EXPECT_GT(fraction_differing(a, grain_tile(options, 8)), 0.99) << "each frame its own grain";
  FilmGrainOptions other = options;
  other.seed = 43;
  EXPECT_GT(fraction_differing(a, grain_tile(other, 7)), 0.99) << "each seed its own grain";
  // A fixed value pins the hash down across compilers and machines.
  EXPECT_EQ(a.pixel(0, 0)[3], 255);
  std::printf("grain tile (seed 42, frame 7) texel (0,0) = %d, (255,255) = %d\n", a.pixel(0, 0)[0], a.pixel(255, 255)[0]);
}

TEST(FilmGrain, TileIsUniformNoiseMonochromeOrNot) {
  FilmGrainOptions options;
  const rasterizer::Image mono = grain_tile(options, 0);
  double sum = 0.0;
  int histogram[4] = {};
  for (int y = 0; y < mono.height; ++y)
    for (int x = 0; x < mono.width; ++x) {
      const uint8_t* p = mono.pixel(x, y);
      EXPECT_TRUE(p[0] == p[1] && p[1] == p[2]);
      sum += p[0];
      ++histogram[p[0] / 64];
    }
  const double n = double(mono.width) * mono.height;
  EXPECT_NEAR(sum / n, 127.5, 1.5) << "mean of uniform bytes (standard error 0.29)";
  for (int q : histogram) EXPECT_NEAR(q / n, 0.25, 0.01) << "each quarter of the range";
  options.monochrome = false;
  const rasterizer::Image colour = grain_tile(options, 0);
  int grey = 0;
  for (int y = 0; y < colour.height; ++y)
    for (int x = 0; x < colour.width; ++x) grey += colour.pixel(x, y)[0] == colour.pixel(x, y)[1];
  EXPECT_LT(grey, colour.width * colour.height / 100) << "independent channels";
  options.tile_size = 0;
  EXPECT_THROW(grain_tile(options, 0), std::invalid_argument);
}

rasterizer::Image test_frame(int width, int height) {
  rasterizer::Image image(width, height);
  std::mt19937 rng(99);
  for (size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = static_cast<uint8_t>(rng() & 0xff);
  return image;
}

TEST(FilmGrain, BlendMatchesTheFormulaInDouble) {
  for (glm::vec4 scale : {glm::vec4(0.1f, 0.1f, 0.1f, 0.9f), glm::vec4(0.3f, 0.2f, 0.5f, 0.0f), glm::vec4(0.25f, 0.25f, 0.25f, 1.0f)}) {
    FilmGrainOptions options;
    options.seed = 5;
    options.noise_scale = scale;
    options.tile_size = 64;  // smaller than the frame: the tile repeats
    options.monochrome = false;
    const rasterizer::Image source = test_frame(150, 100);
    rasterizer::Image frame = source;
    rasterizer::Context ctx(2);
    FilmGrain(options).apply(ctx, frame, 3);
    const rasterizer::Image tile = grain_tile(options, 3);
    int worst = 0, off = 0;
    for (int y = 0; y < frame.height; ++y)
      for (int x = 0; x < frame.width; ++x) {
        const uint8_t* n = tile.pixel(x % tile.width, y % tile.height);
        const double src_alpha = n[0] / 255.0 * (1.0 - scale.w) + scale.w;
        for (int c = 0; c < 3; ++c) {
          const double out = n[c] / 255.0 * scale[c] + source.pixel(x, y)[c] / 255.0 * src_alpha;
          const double scaled = std::clamp(out, 0.0, 1.0) * 255.0;
          const int d = std::abs(frame.pixel(x, y)[c] - static_cast<int>(std::nearbyint(scaled)));
          worst = std::max(worst, d);
          // An exact tie (n / 4 + d with scale 0.25) rounds either way in float.
          const bool tie = std::abs(scaled - std::floor(scaled) - 0.5) < 1e-6;
          off += d != 0 && !tie;
        }
        EXPECT_EQ(frame.pixel(x, y)[3], source.pixel(x, y)[3]) << "alpha kept";
      }
    // The float blend can land a hair on the other side of a rounding boundary.
    EXPECT_LE(worst, 1);
    EXPECT_LT(off, frame.width * frame.height * 3 / 200) << "off by one away from ties";
    std::printf("grain blend vs double (scale %.2f %.2f %.2f %.2f): max %d step, %d channels off (ties aside)\n", scale.x, scale.y,
                scale.z, scale.w, worst, off);
  }
}

TEST(FilmGrain, SameBytesForOneAndTwoThreadsAndOnMultisampledTargets) {
  const rasterizer::Image source = test_frame(200, 130);
  rasterizer::Image one = source, two = source;
  rasterizer::Context ctx1(1), ctx2(2);
  FilmGrain grain(FilmGrainOptions{});
  grain.apply(ctx1, one, 12);
  grain.apply(ctx2, two, 12);
  EXPECT_EQ(one.rgba, two.rgba);
  EXPECT_NE(one.rgba, source.rgba);
  rasterizer::ColorTarget target(source.width, source.height, 4);
  rasterizer::load_image(ctx2, source, target);
  grain.apply(ctx2, target, 12);
  EXPECT_EQ(rasterizer::resolve(ctx2, target).rgba, one.rgba) << "every sample gets the same grain";
}

}  // namespace
}  // namespace luxel::postfx
