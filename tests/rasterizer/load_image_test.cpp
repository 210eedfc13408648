// load_image: an image comes back into every sample of a target, on tiles cut at the image's edge,
// in the order the frame records it (after a clear recorded before it), and refuses a size mismatch.

#include "luxel/rasterizer/context.hpp"
#include "luxel/rasterizer/framebuffer.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <stdexcept>

namespace luxel::rasterizer {
namespace {

Image random_image(int width, int height, uint32_t seed) {
  Image image(width, height);
  std::mt19937 rng(seed);
  for (uint8_t& b : image.rgba) b = static_cast<uint8_t>(rng() & 0xff);
  return image;
}

TEST(LoadImage, EverySampleTakesItsPixelAndResolveGivesTheImageBack) {
  Context ctx(2);
  for (int samples : {1, 4}) {
    // Not a multiple of the tile size: the last column and row of tiles are cut.
    const Image image = random_image(kTileSize + 13, kTileSize + 7, 5u + samples);
    ColorTarget target(image.width, image.height, samples);
    clear_color(ctx, target, glm::vec4(1.0f, 0.0f, 1.0f, 0.0f));  // recorded first, so overwritten
    load_image(ctx, image, target);
    ctx.flush();
    int wrong = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        uint32_t expected;
        std::memcpy(&expected, image.pixel(x, y), 4);
        for (int s = 0; s < samples; ++s) wrong += target.sample(x, y, s) != expected;
      }
    EXPECT_EQ(wrong, 0) << samples << " samples";
    EXPECT_EQ(resolve(ctx, target).rgba, image.rgba) << samples << " samples";
  }
}

TEST(LoadImage, RefusesAnImageOfAnotherSize) {
  Context ctx(1);
  ColorTarget target(8, 8);
  EXPECT_THROW(load_image(ctx, Image(8, 9), target), std::invalid_argument);
}

}  // namespace
}  // namespace luxel::rasterizer
