// The rgba32f color target (framebuffer.hpp): draws and clears keep every float bit for bit
// (values 8 bits cannot hold: thousandths, values above 1, negative values, -0, denormals, NaN
// payloads), the depth test decides which draw's floats stay, write masks keep channels, tile
// memory keeps the same bits, and what the target cannot do (samples, blending, sRGB, 8-bit
// access) is refused by name.

#include "raster_support.hpp"

#include <glm/vec4.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace luxel::rasterizer::test {
namespace {

constexpr int kFloatW = 100, kFloatH = 40;  // two tiles across, the second partly outside
/// The draws' viewport: wider than the target, so that every corner below is exact in clip space.
const Viewport kFloatViewport{0, 0, 128, kFloatH};

/// The two triangles of the rectangle [x0, x1) x [0, kFloatH) at depth z: pixels whose center is
/// inside, columns x0 .. x1 - 1.
struct FloatRect {
  glm::vec4 corners[4];
  FloatRect(int x0, int x1, float z) {
    const ViewportMap map(kFloatViewport, kFloatW, kFloatH);
    corners[0] = map.clip_from_screen(x0, 0, z);
    corners[1] = map.clip_from_screen(x1, 0, z);
    corners[2] = map.clip_from_screen(x1, kFloatH, z);
    corners[3] = map.clip_from_screen(x0, kFloatH, z);
  }
};

void draw_float_rect(Context& ctx, const Framebuffer& fb, const PipelineState& st, const FloatRect& rect, glm::vec4 color) {
  static constexpr uint16_t kQuad[6] = {0, 1, 2, 0, 2, 3};
  draw(ctx, fb, st, Geometry::indexed(std::span<const uint16_t>(kQuad), 4), ArrayVS<0>{rect.corners}, ConstantPS{color});
}

PipelineState float_state() {
  PipelineState st;
  st.viewport = kFloatViewport;
  st.rasterizer.cull = CullMode::None;
  return st;
}

std::vector<glm::vec4> float_pixels(Context& ctx, const ColorTarget& target) {
  std::vector<glm::vec4> pixels;
  resolve_into(ctx, target, pixels);
  return pixels;
}

/// Counts the pixels of column range [x0, x1) whose four channels do not have `want`'s bits.
int float_pixels_off(const std::vector<glm::vec4>& pixels, int x0, int x1, glm::vec4 want) {
  int off = 0;
  for (int y = 0; y < kFloatH; ++y)
    for (int x = x0; x < x1; ++x) {
      bool same = true;
      for (int c = 0; c < 4; ++c)
        same &= std::bit_cast<uint32_t>(pixels[size_t(y) * kFloatW + x][c]) == std::bit_cast<uint32_t>(want[c]);
      off += !same;
    }
  return off;
}

const float kNanPayload = std::bit_cast<float>(0x7fc12345u);
const float kDenormal = std::bit_cast<float>(0x00000123u);

TEST(FloatTarget, DrawsAndClearsKeepEveryBit) {
  const glm::vec4 background(-2.5f, kNanPayload, 1e30f, -0.0f);
  const glm::vec4 drawn(1e-3f, 37.25f, -4.0f, kDenormal);
  for (int threads : {1, 2}) {
    Context ctx(threads);
    ColorTarget target(kFloatW, kFloatH, 1, ColorFormat::rgba32f);
    clear_color(ctx, target, background);
    draw_float_rect(ctx, Framebuffer{&target, nullptr}, float_state(), FloatRect(0, 35, 0.5f), drawn);
    const std::vector<glm::vec4> pixels = float_pixels(ctx, target);
    ASSERT_EQ(pixels.size(), size_t(kFloatW) * kFloatH);
    EXPECT_EQ(float_pixels_off(pixels, 0, 35, drawn), 0) << threads << " threads";
    EXPECT_EQ(float_pixels_off(pixels, 35, kFloatW, background), 0) << threads << " threads";
  }
}

TEST(FloatTarget, TheDepthTestDecidesWhichFloatsStay) {
  Context ctx(2);
  ColorTarget target(kFloatW, kFloatH, 1, ColorFormat::rgba32f);
  DepthStencilTarget depth(kFloatW, kFloatH, 1);
  const Framebuffer fb{&target, &depth};
  clear_color(ctx, target, glm::vec4(0.0f));
  clear_depth_stencil(ctx, depth, 1.0f, 0);
  const glm::vec4 near(100.5f, -1.0f, 0.001f, 2.0f), far(-7.0f, 3.0f, 5.0f, 0.5f), nearest(0.25f, 1e-3f, 8.0f, -3.0f);
  draw_float_rect(ctx, fb, float_state(), FloatRect(0, 50, 0.25f), near);
  draw_float_rect(ctx, fb, float_state(), FloatRect(0, kFloatW, 0.75f), far);  // behind `near`'s columns
  draw_float_rect(ctx, fb, float_state(), FloatRect(0, 20, 0.1f), nearest);
  // Only red and alpha written: green and blue keep `far`'s.
  PipelineState masked = float_state();
  masked.blend.write_mask = kWriteRed | kWriteAlpha;
  const glm::vec4 red_alpha(-0.5f, 99.0f, 99.0f, 0.125f);
  draw_float_rect(ctx, fb, masked, FloatRect(60, kFloatW, 0.5f), red_alpha);
  const std::vector<glm::vec4> pixels = float_pixels(ctx, target);
  EXPECT_EQ(float_pixels_off(pixels, 0, 20, nearest), 0);
  EXPECT_EQ(float_pixels_off(pixels, 20, 50, near), 0);
  EXPECT_EQ(float_pixels_off(pixels, 50, 60, far), 0);
  EXPECT_EQ(float_pixels_off(pixels, 60, kFloatW, glm::vec4(-0.5f, far.g, far.b, 0.125f)), 0);
}

TEST(FloatTarget, TileMemoryKeepsTheSameBits) {
  const glm::vec4 background(0.5f, -0.5f, 1e-3f, 4.0f), drawn(37.25f, 1e-3f, -1e-3f, 65504.5f);
  auto render = [&](Context& ctx, bool discarded) {
    ColorTarget target(kFloatW, kFloatH, 1, ColorFormat::rgba32f);
    DepthStencilTarget depth(kFloatW, kFloatH, 1);
    clear_color(ctx, target, background);
    clear_depth_stencil(ctx, depth, 1.0f, 0);
    draw_float_rect(ctx, Framebuffer{&target, &depth}, float_state(), FloatRect(10, 45, 0.5f), drawn);
    if (discarded) {
      discard(ctx, target);
      discard(ctx, depth);
    }
    return float_pixels(ctx, target);
  };
  Context kept_ctx(2);
  const std::vector<glm::vec4> kept = render(kept_ctx, false);
  EXPECT_EQ(float_pixels_off(kept, 10, 45, drawn), 0);
  EXPECT_EQ(float_pixels_off(kept, 0, 10, background) + float_pixels_off(kept, 45, kFloatW, background), 0);
  for (int threads : {1, 3}) {
    Context ctx(threads);
    ctx.reset_stats();
    const std::vector<glm::vec4> discarded = render(ctx, true);
    EXPECT_EQ(ctx.stats().tile_memory_targets, 2u) << threads << " threads";
    EXPECT_EQ(std::memcmp(discarded.data(), kept.data(), kept.size() * sizeof(glm::vec4)), 0) << threads << " threads";
  }
}

/// Runs `fn`, expecting an exception of type E whose message holds `words`.
template <class E, class Fn>
void expect_refused(Fn fn, const std::string& words) {
  try {
    fn();
    ADD_FAILURE() << "not refused: " << words;
  } catch (const E& e) {
    EXPECT_THAT(e.what(), testing::HasSubstr(words));
  }
}

TEST(FloatTarget, RefusesWhatItCannotHoldByName) {
  Context ctx(1);
  expect_refused<std::invalid_argument>([] { ColorTarget(8, 8, 4, ColorFormat::rgba32f); }, "multisampled float targets");
  ColorTarget target(kFloatW, kFloatH, 1, ColorFormat::rgba32f);
  clear_color(ctx, target, glm::vec4(1.0f));
  PipelineState blended = float_state();
  blended.blend.enable = true;
  expect_refused<std::invalid_argument>(
      [&] { draw_float_rect(ctx, Framebuffer{&target, nullptr}, blended, FloatRect(0, 8, 0.5f), glm::vec4(1.0f)); },
      "blending into an rgba32f color target");
  PipelineState srgb = float_state();
  srgb.blend.srgb_write = true;
  expect_refused<std::invalid_argument>(
      [&] { draw_float_rect(ctx, Framebuffer{&target, nullptr}, srgb, FloatRect(0, 8, 0.5f), glm::vec4(1.0f)); },
      "no sRGB write");
  expect_refused<std::invalid_argument>([&] { resolve(ctx, target); }, "resolves an rgba8 color target, not an rgba32f");
  Image image(kFloatW, kFloatH);
  expect_refused<std::invalid_argument>([&] { load_image(ctx, image, target); }, "rgba32f, not rgba8");
  ctx.flush();
  expect_refused<std::logic_error>([&] { (void)target.sample(0, 0, 0); }, "rgba32f color target was read as 8-bit");
  ColorTarget bytes(kFloatW, kFloatH, 1);
  std::vector<glm::vec4> pixels;
  expect_refused<std::invalid_argument>([&] { resolve_into(ctx, bytes, pixels); },
                                        "resolves an rgba32f color target, not an rgba8");
}

}  // namespace
}  // namespace luxel::rasterizer::test
