// DrawStats: a counter for every path, checked against what the test can count itself.

#include "raster_support.hpp"

#include <gtest/gtest.h>

#include <atomic>

namespace luxel::rasterizer::test {
namespace {

struct CountingPS {
  static constexpr bool kCanDiscard = false, kWritesDepth = false;
  std::atomic<uint64_t>* calls;
  uint64_t* lanes_live;  // only touched with one thread
  void operator()(const PixelInput<1>& in, PixelOutput& out) const {
    calls->fetch_add(1, std::memory_order_relaxed);
    *lanes_live += std::popcount(in.live);
    out.color = {simd::Float(1.0f), simd::Float(1.0f), simd::Float(1.0f), simd::Float(1.0f)};
  }
};

// draw.hpp: stamps_shaded counts pixel functor invocations (stamps).
TEST(Stats, StampsShadedCountsPixelFunctorInvocations) {
  Context ctx(1);
  const ViewportMap map(Viewport{}, 128, 64);
  ColorTarget target(128, 64, 4);
  PipelineState st;
  st.rasterizer.cull = CullMode::None;
  const glm::vec4 tri[6] = {map.clip_from_screen(3, 2), map.clip_from_screen(120.5, 9), map.clip_from_screen(40, 60),
                            map.clip_from_screen(-10, -10), map.clip_from_screen(300, -10), map.clip_from_screen(-10, 300)};
  std::atomic<uint64_t> calls{0};
  uint64_t live = 0;
  ctx.reset_stats();
  draw(ctx, Framebuffer{&target, nullptr}, st, Geometry::non_indexed(6), PositionVS{tri}, CountingPS{&calls, &live});
  ctx.flush();
  const DrawStats& s = ctx.stats();
  EXPECT_GT(calls.load(), 0u);
  EXPECT_EQ(s.stamps_shaded, calls.load());
  // Nothing rejects after coverage here: every stamp with coverage is shaded once.
  EXPECT_EQ(s.stamps_full + s.stamps_partial, calls.load());
  EXPECT_EQ(s.rasterized, 2u);
  // The second triangle covers the whole target: at least its stamps are full.
  EXPECT_GE(s.stamps_full, uint64_t(128 * 64 / (simd::kStampWidth * simd::kStampHeight)));
  // Every pixel of the second triangle is live exactly once, plus the first one's.
  EXPECT_GT(live, uint64_t(128 * 64));
}

TEST(Stats, RejectAndClipCounters) {
  Context ctx(1);
  ColorTarget target(64, 64, 1);
  PipelineState st;
  st.rasterizer.cull = CullMode::None;
  const glm::vec4 tris[] = {
      {2, 0, 0.5f, 1},   {3, 0, 0.5f, 1},   {2, 1, 0.5f, 1},     // right of the view volume: outside
      {0, 0, -0.5f, 1},  {1, 0, -0.5f, 1},  {0, 1, -0.5f, 1},    // in front of the near plane: outside
      {0, 0, 2, 1},      {1, 0, 2, 1},      {0, 1, 2, 1},        // beyond the far plane: outside
      {-0.5f, -0.5f, -0.5f, 1}, {0.5f, -0.5f, 0.5f, 1}, {0, 0.5f, 0.5f, 1},  // crosses near: clipped to a quad
      {-0.5f, -0.5f, 0.5f, 1}, {600, -0.5f, 0.5f, 1}, {0, 0.5f, 0.5f, 1},     // beyond the guard band: clipped
      {-0.5f, -0.5f, 0.5f, 1}, {0.5f, -0.5f, 0.5f, 1}, {0, 0.5f, 0.5f, 1},    // plain
  };
  ctx.reset_stats();
  draw(ctx, Framebuffer{&target, nullptr}, st, Geometry::non_indexed(18), PositionVS{tris}, ConstantPS{});
  ctx.flush();
  const DrawStats& s = ctx.stats();
  EXPECT_EQ(s.triangles, 6u);
  EXPECT_EQ(s.outside, 3u);
  EXPECT_EQ(s.clipped, 2u);
  EXPECT_GE(s.rasterized, 1u + 2u + 2u);  // near: a quad = 2 pieces; guard band: >= 2 pieces
  EXPECT_EQ(s.culled, 0u);
  EXPECT_EQ(s.non_finite + s.bad_index, 0u);
}

}  // namespace
}  // namespace luxel::rasterizer::test
