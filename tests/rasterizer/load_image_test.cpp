// load_image: an image comes back into every sample of a target, on tiles cut at the image's edge,
// in the order the frame records it (after a clear recorded before it), and refuses a size mismatch.

#include "luxel/rasterizer/context.hpp"
#include "luxel/rasterizer/framebuffer.hpp"
#include "luxel/rasterizer/texture.hpp"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <algorithm>
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

// A whole resolve into a texture finds opaque() from the pixels the tiles write: one pixel's
// alpha below 255, inside a whole stamp or on a partial one at the edge, is enough to lose it.
TEST(ResolveIntoTexture, OpaqueFollowsTheAlphaOfEveryPixel) {
  Context ctx(2);
  const int W = 2 * kTileSize + 9, H = kTileSize + 21;
  for (int samples : {1, 4}) {
    for (const glm::ivec2 below : {glm::ivec2(-1, -1), glm::ivec2(70, 3), glm::ivec2(W - 1, H - 1), glm::ivec2(0, H - 2)}) {
      Image image = random_image(W, H, 7);
      for (size_t p = 3; p < image.rgba.size(); p += 4) image.rgba[p] = 255;
      if (below.x >= 0) image.pixel(below.x, below.y)[3] = 254;
      ColorTarget target(W, H, samples);
      load_image(ctx, image, target);
      Texture texture = Texture::create_2d(W, H, TextureFormat::RGBA8, 1);
      resolve_into(ctx, target, texture, ResolveAlpha::samples);
      EXPECT_EQ(texture.opaque(), below.x < 0) << samples << " samples, alpha 254 at " << below.x << ", " << below.y;
    }
  }
}

TEST(ResolveIntoTexture, WritesTheImagesBytesInPlaceAndKeepsOpaqueTrue) {
  // A 4-sample target whose samples differ within each pixel (an image in sample 0's place, its
  // bytes reversed in the others) resolves into a texture to the bytes it resolves to in an
  // image; with a region, only the region's tiles' rows change, and opaque() follows the alpha
  // (one row of them below 255 is enough to lose it).
  Context ctx(2);
  const int W = 2 * kTileSize + 9, H = kTileSize + 21;
  Image image = random_image(W, H, 99);
  ColorTarget target(W, H, 4);
  load_image(ctx, image, target);
  ctx.flush();
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      for (int s = 1; s < 4; ++s) target.set_sample(x, y, s, ~target.sample(x, y, 0));
  for (ResolveAlpha alpha : {ResolveAlpha::samples, ResolveAlpha::opaque}) {
    for (TextureFormat format : {TextureFormat::RGBA8, TextureFormat::RGBA8_sRGB}) {
      Texture texture = Texture::create_2d(W, H, format, 1);
      resolve_into(ctx, target, texture, alpha);
      const Image expected = resolve(ctx, target, alpha);
      ASSERT_TRUE(std::equal(expected.rgba.begin(), expected.rgba.end(), texture.level_bytes(0).begin()));
      EXPECT_EQ(texture.opaque(), alpha == ResolveAlpha::opaque) << "random alpha is not opaque";
    }
  }
  // A region: the tile holding it (row 0, column 1) is written whole,
  // the other texels keep what an opaque upload left.
  Image grey(W, H);
  std::fill(grey.rgba.begin(), grey.rgba.end(), uint8_t(255));
  Texture texture = Texture::create_2d(W, H, TextureFormat::RGBA8, 1);
  texture.upload(0, grey.rgba);
  ASSERT_TRUE(texture.opaque());
  const Scissor region{true, kTileSize + 3, 5, kTileSize + 20, 30};
  resolve_into(ctx, target, texture, ResolveAlpha::opaque, region);
  const Image resolved = resolve(ctx, target, ResolveAlpha::opaque);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const bool held = x >= kTileSize && x < 2 * kTileSize && y < kTileSize;
      const uint8_t* got = texture.level_bytes(0).data() + (size_t(y) * W + x) * 4;
      ASSERT_EQ(std::memcmp(got, held ? resolved.pixel(x, y) : grey.pixel(x, y), 4), 0) << x << ", " << y;
    }
  EXPECT_TRUE(texture.opaque()) << "opaque rows into an opaque level";
  resolve_into(ctx, target, texture, ResolveAlpha::samples, region);
  EXPECT_FALSE(texture.opaque());
  // Only a one-level RGBA8 2D texture of the target's size.
  Texture mipped = Texture::create_2d(W, H, TextureFormat::RGBA8);
  Texture smaller = Texture::create_2d(W - 1, H, TextureFormat::RGBA8, 1);
  Texture half = Texture::create_2d(W, H, TextureFormat::RGBA16F, 1);
  Texture cube = Texture::create_cube(16, TextureFormat::RGBA8, 1);
  for (Texture* bad : {&mipped, &smaller, &half, &cube}) EXPECT_THROW(resolve_into(ctx, target, *bad), std::invalid_argument);
}

TEST(LoadImage, RefusesAnImageOfAnotherSize) {
  Context ctx(1);
  ColorTarget target(8, 8);
  EXPECT_THROW(load_image(ctx, Image(8, 9), target), std::invalid_argument);
}

}  // namespace
}  // namespace luxel::rasterizer
