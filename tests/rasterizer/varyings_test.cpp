// Flat varyings (the same finite value at all three vertices) are stored once per triangle and
// handed to the pixel functor as they are; the others are interpolated.

#include "raster_support.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <limits>

namespace luxel::rasterizer::test {
namespace {

/// Counts live lanes whose varying 0 differs from `expected`, and records the range of .x.
struct CheckingPS {
  static constexpr bool kCanDiscard = false, kWritesDepth = false;
  glm::vec4 expected;
  std::atomic<uint64_t>* mismatches;
  std::atomic<uint64_t>* live_lanes;
  float* min_x;  // only touched with one thread
  float* max_x;
  void operator()(const PixelInput<1>& in, PixelOutput& out) const {
    const auto x = lanes_of(in.varyings[0].x), y = lanes_of(in.varyings[0].y), z = lanes_of(in.varyings[0].z),
               w = lanes_of(in.varyings[0].w);
    for (int l = 0; l < simd::kLanes; ++l) {
      if (!(in.live >> l & 1)) continue;
      live_lanes->fetch_add(1);
      if (x[l] != expected.x || y[l] != expected.y || z[l] != expected.z || w[l] != expected.w) mismatches->fetch_add(1);
      *min_x = std::min(*min_x, x[l]);
      *max_x = std::max(*max_x, x[l]);
    }
    out.color = {simd::Float(1.0f), simd::Float(1.0f), simd::Float(1.0f), simd::Float(1.0f)};
  }
};

struct Result {
  uint64_t mismatches, live;
  float min_x, max_x;
};

Result draw_with_varyings(const std::array<glm::vec4, 1> varyings[3], bool perspective, glm::vec4 expected) {
  Context ctx(1);
  const ViewportMap map(Viewport{}, 64, 64);
  ColorTarget target(64, 64, 4);
  PipelineState st;
  st.rasterizer.cull = CullMode::None;
  const float w[3] = {1.0f, perspective ? 4.0f : 1.0f, perspective ? 0.5f : 1.0f};
  const glm::vec4 pos[3] = {map.clip_from_screen(3.25, 2.75, 0.5f, w[0]), map.clip_from_screen(50.5, 9.125, 0.5f, w[1]),
                            map.clip_from_screen(20.375, 60.75, 0.5f, w[2])};
  std::atomic<uint64_t> mismatches{0}, live{0};
  float min_x = std::numeric_limits<float>::infinity(), max_x = -min_x;
  draw(ctx, Framebuffer{&target, nullptr}, st, Geometry::non_indexed(3), ArrayVS<1>{pos, varyings},
       CheckingPS{expected, &mismatches, &live, &min_x, &max_x});
  ctx.flush();
  return {mismatches.load(), live.load(), min_x, max_x};
}

TEST(Varyings, FlatVaryingsReachThePixelFunctorUnchanged) {
  const glm::vec4 v(0.3f, -2.5f, 1e20f, 7.0f);
  const std::array<glm::vec4, 1> varyings[3] = {{v}, {v}, {v}};
  for (bool perspective : {false, true}) {
    const Result r = draw_with_varyings(varyings, perspective, v);
    EXPECT_GT(r.live, 500u);
    EXPECT_EQ(r.mismatches, 0u) << "perspective " << perspective;
  }
}

TEST(Varyings, VaryingsThatDifferAreInterpolated) {
  const glm::vec4 v(0.3f, -2.5f, 1e20f, 7.0f);
  // Only .x differs at one vertex: the triangle is not flat, .x ramps from 0.3 to 0.9.
  const std::array<glm::vec4, 1> varyings[3] = {{v}, {v}, {glm::vec4(0.9f, v.y, v.z, v.w)}};
  for (bool perspective : {false, true}) {
    const Result r = draw_with_varyings(varyings, perspective, v);
    EXPECT_GT(r.live, 500u);
    EXPECT_GT(r.mismatches, r.live / 2) << "perspective " << perspective;
    // Pixel centers of partly covered pixels may lie outside the triangle (no centroid
    // sampling in DX9): values extrapolate a little beyond the vertices' range.
    EXPECT_GE(r.min_x, 0.2f);
    EXPECT_LE(r.max_x, 1.0f);
    EXPECT_GT(r.max_x - r.min_x, 0.3f);
  }
}

}  // namespace
}  // namespace luxel::rasterizer::test
