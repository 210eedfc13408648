// Viewport and scissor: the pixel rectangle a draw may write, the D3D9 half-pixel mapping that
// state.hpp documents, and consistency of the viewport edge for MSAA.

#include "coverage_support.hpp"
#include "raster_support.hpp"

#include <gtest/gtest.h>

#include <array>
#include <limits>
#include <random>

namespace luxel::rasterizer::test {
namespace {

/// Point-samples a W x H "texture" at uv: writes the texel's coordinates (as r, g).
struct TexelPS {
  static constexpr bool kCanDiscard = false, kWritesDepth = false;
  int w, h;
  void operator()(const PixelInput<1>& in, PixelOutput& out) const {
    const auto u = lanes_of(in.varyings[0].x), v = lanes_of(in.varyings[0].y);
    std::array<float, simd::kLanes> r, g;
    for (int l = 0; l < simd::kLanes; ++l) {
      r[l] = float(std::floor(u[l] * w)) / 255.0f;
      g[l] = float(std::floor(v[l] * h)) / 255.0f;
    }
    out.color = {from_lanes(r), from_lanes(g), simd::Float(0.0f), simd::Float(1.0f)};
  }
};

/// Draws the classic D3D9 texel-aligned full-screen quad: D3D9 screen coordinates [-0.5, W-0.5]
/// x [-0.5, H-0.5] (pixel centers on integers in D3D9), uv 0..1, through `vp_offset`.
/// Under D3D9 rules ("Directly Mapping Texels to Pixels") every pixel is covered once and pixel
/// (i, j) samples texel (i, j) at its center.
void d3d9_quad(float vp_offset, int W, int H, int& uncovered, int& wrong_texel) {
  Context ctx(1);
  ColorTarget target(W, H, 1);
  clear_color(ctx, target, glm::vec4(0.0f));
  PipelineState st;
  st.rasterizer.cull = CullMode::None;
  st.viewport = {vp_offset, vp_offset, float(W), float(H)};
  // NDC of the D3D9 screen position s: s = (ndc + 1) * W/2 for a D3D9 viewport at X = 0.
  auto nx = [&](double s) { return float(s / (W / 2.0) - 1); };
  auto ny = [&](double s) { return float(1 - s / (H / 2.0)); };
  const glm::vec4 pos[4] = {{nx(-0.5), ny(-0.5), 0.5f, 1}, {nx(W - 0.5), ny(-0.5), 0.5f, 1},
                            {nx(W - 0.5), ny(H - 0.5), 0.5f, 1}, {nx(-0.5), ny(H - 0.5), 0.5f, 1}};
  const std::array<glm::vec4, 1> uv[4] = {{glm::vec4(0, 0, 0, 0)}, {glm::vec4(1, 0, 0, 0)}, {glm::vec4(1, 1, 0, 0)},
                                          {glm::vec4(0, 1, 0, 0)}};
  const uint32_t idx[6] = {0, 1, 2, 0, 2, 3};
  draw(ctx, Framebuffer{&target, nullptr}, st, Geometry::indexed(std::span<const uint32_t>(idx), 4),
       ArrayVS<1>{pos, uv}, TexelPS{W, H});
  ctx.flush();
  uncovered = wrong_texel = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const uint32_t v = target.sample(x, y, 0);
      if (v == 0) {
        ++uncovered;
      } else if (v != rgba8(x, y, 0, 255)) {
        ++wrong_texel;
      }
    }
}

// state.hpp: "a D3D9 application gets its exact mapping with Viewport::x = y = +0.5".
constexpr float kDocumentedD3D9Offset = +0.5f;

TEST(Viewport, D3D9HalfPixelMappingAsDocumented) {
  int uncovered, wrong;
  d3d9_quad(kDocumentedD3D9Offset, 64, 32, uncovered, wrong);
  EXPECT_EQ(uncovered, 0) << "pixels the D3D9 quad leaves uncovered (last column and row)";
  EXPECT_EQ(wrong, 0) << "pixels that sample the neighbouring texel instead of their own";
  // The other sign, the usual mistake, shifts every pixel onto its neighbour's texel.
  d3d9_quad(-kDocumentedD3D9Offset, 64, 32, uncovered, wrong);
  EXPECT_GT(uncovered + wrong, 0);
}

TEST(Viewport, FullScreenTriangleFillsExactlyTheViewportAndScissor) {
  const glm::vec4 full[3] = {{-1, 1, 0.5f, 1}, {3, 1, 0.5f, 1}, {-1, -3, 0.5f, 1}};
  std::mt19937 rng(12);
  const int W = 70, H = 50;
  for (int round = 0; round < budget(200, 40); ++round) {
    PipelineState st;
    st.rasterizer.cull = CullMode::None;
    const int vx = int(rng() % 120) - 60, vy = int(rng() % 100) - 50;
    st.viewport = {float(vx), float(vy), float(1 + rng() % 128), float(1 + rng() % 128)};
    if (rng() & 1) st.scissor = {true, int(rng() % 90) - 10, int(rng() % 70) - 10, int(rng() % 90) - 10, int(rng() % 70) - 10};
    const int S = 1 << (round % 4);
    Context ctx(1);
    ColorTarget target(W, H, S);
    clear_color(ctx, target, glm::vec4(0.0f));
    draw(ctx, Framebuffer{&target, nullptr}, st, Geometry::non_indexed(3), PositionVS{full}, ConstantPS{glm::vec4(1.0f)});
    ctx.flush();
    // Integer viewport: exactly the pixels of [x, x + w) x [y, y + h), the target and the scissor.
    PixelRect r{std::max(0, vx), std::max(0, vy), std::min(W, vx + int(st.viewport.width)),
                std::min(H, vy + int(st.viewport.height))};
    if (st.scissor.enable) {
      r.x0 = std::max(r.x0, st.scissor.x0);
      r.y0 = std::max(r.y0, st.scissor.y0);
      r.x1 = std::min(r.x1, st.scissor.x1);
      r.y1 = std::min(r.y1, st.scissor.y1);
    }
    int bad = 0;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x)
        for (int s = 0; s < S; ++s) bad += (target.sample(x, y, s) != 0) != r.contains(x, y);
    EXPECT_EQ(bad, 0) << "viewport " << vx << ", " << vy << ", " << st.viewport.width << "x" << st.viewport.height
                      << " scissor " << st.scissor.enable << " " << st.scissor.x0 << "," << st.scissor.y0 << " - "
                      << st.scissor.x1 << "," << st.scissor.y1;
  }
}

// state.hpp: a width or height of 0 is the target's, per axis (the default viewport is the whole
// target); a negative, NaN or infinite one is an error, not the whole target.
TEST(Viewport, SizeIsZeroForTheTargetOrPositive) {
  const glm::vec4 full[3] = {{-1, 1, 0.5f, 1}, {3, 1, 0.5f, 1}, {-1, -3, 0.5f, 1}};
  const int W = 70, H = 50;
  Context ctx(1);
  ColorTarget target(W, H, 1);
  auto covered = [&](const Viewport& vp) {
    PipelineState st;
    st.rasterizer.cull = CullMode::None;
    st.viewport = vp;
    clear_color(ctx, target, glm::vec4(0.0f));
    draw(ctx, Framebuffer{&target, nullptr}, st, Geometry::non_indexed(3), PositionVS{full}, ConstantPS{});
    ctx.flush();
    PixelRect r{W, H, 0, 0};  // the bounding box of the written pixels
    int count = 0;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x)
        if (target.sample(x, y, 0) != 0) {
          ++count;
          r = {std::min(r.x0, x), std::min(r.y0, y), std::max(r.x1, x + 1), std::max(r.y1, y + 1)};
        }
    EXPECT_EQ(count, (r.x1 - r.x0) * (r.y1 - r.y0)) << "not a rectangle";
    return std::array<int, 4>{r.x0, r.y0, r.x1, r.y1};
  };
  using Rect = std::array<int, 4>;
  EXPECT_EQ(covered(Viewport{}), (Rect{0, 0, W, H}));
  EXPECT_EQ(covered(Viewport{0, 0, 0, 20}), (Rect{0, 0, W, 20}));
  EXPECT_EQ(covered(Viewport{0, 0, 30, 0}), (Rect{0, 0, 30, H}));
  EXPECT_EQ(covered(Viewport{10, 5, 0, 0}), (Rect{10, 5, W, H}));  // the target's size from the origin
  EXPECT_EQ(covered(Viewport{0, 0, -0.0f, -0.0f}), (Rect{0, 0, W, H}));

  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  for (const float bad : {nan, -nan, -1.0f, -1e-30f, -inf, inf}) {
    for (const bool on_width : {true, false}) {
      PipelineState st;
      (on_width ? st.viewport.width : st.viewport.height) = bad;
      EXPECT_THROW(draw(ctx, Framebuffer{&target, nullptr}, st, Geometry::non_indexed(3), PositionVS{full},
                        ConstantPS{}),
                   std::invalid_argument)
          << (on_width ? "width " : "height ") << bad;
    }
  }
}

// Random triangles under random scissors (the oracle restricted to the scissor rectangle).
TEST(Viewport, RandomTrianglesUnderRandomScissors) {
  std::mt19937 rng(321);
  Context ctx(2);
  for (int round = 0; round < budget(100, 8); ++round) {
    CoverageConfig cfg;
    cfg.name = "random scissor";
    cfg.width = 100;
    cfg.height = 60;
    cfg.state.viewport = {-14, -2, 128, 64};
    cfg.state.scissor = {true, int(rng() % 120) - 10, int(rng() % 80) - 10, int(rng() % 120) - 10, int(rng() % 80) - 10};
    cfg.state.rasterizer.cull = CullMode::None;
    const int S = 1 << (round % 4);
    ColorTarget target(cfg.width, cfg.height, S);
    TriangleGenerator gen(rng(), cfg);
    std::vector<TestTriangle> batch;
    for (int k = 0; k < 32; ++k) batch.push_back(gen.random());
    draw_coverage_batch(ctx, target, cfg, batch, BatchMode::Bits);
    std::vector<std::string> messages;
    const int bad = check_coverage_batch(ctx, target, cfg, batch, BatchMode::Bits, messages, 4);
    EXPECT_EQ(bad, 0) << (messages.empty() ? "" : messages[0]);
  }
}

// A fractional viewport (state.hpp: the pixels its rectangle overlaps may be written) leaves
// samples outside the viewport rectangle in writable pixels. Whatever the rule for them (clipped
// as outside the view volume, or kept because their pixel may be written), it must not depend
// on whether the triangle that contains them also reaches into the viewport (a triangle wholly
// outside the viewport must not be rejected while one crossing its edge is drawn unclipped).
int covered_inside(const PipelineState& st, int W, int H, int S, const glm::dvec2 (&t)[3], const RefPrimitive& region,
                   int column) {
  const ViewportMap map(st.viewport, W, H);
  Context ctx(1);
  ColorTarget target(W, H, S);
  clear_color(ctx, target, glm::vec4(0.0f));
  const glm::vec4 c[3] = {map.clip_from_screen(t[0].x, t[0].y), map.clip_from_screen(t[1].x, t[1].y),
                          map.clip_from_screen(t[2].x, t[2].y)};
  draw(ctx, Framebuffer{&target, nullptr}, st, Geometry::non_indexed(3), PositionVS{c}, ConstantPS{glm::vec4(1.0f)});
  ctx.flush();
  const auto pattern = d3d_pattern(S);
  int n = 0, total = 0;
  for (int y = 0; y < H; ++y)
    for (int s = 0; s < S; ++s)
      if (region.cover(column, y, pattern[s]) == Cover::In && !inside_viewport(map, column, y, pattern[s])) {
        ++total;
        n += target.sample(column, y, s) != 0;
      }
  EXPECT_GT(total, 5) << "test setup";
  return n;
}

TEST(Viewport, FractionalViewportEdgeIsConsistent) {
  PipelineState st;
  st.rasterizer.cull = CullMode::None;
  {
    // Left edge at x = 0.5, 8 samples: pixel 0's samples left of 0.5. A lies entirely left of
    // the edge; B contains A and reaches into the viewport.
    st.viewport = {0.5f, 0, 16, 16};
    const glm::dvec2 a[3] = {{0.03125, 2}, {0.4375, 2}, {0.03125, 14}};
    const glm::dvec2 b[3] = {{0.03125, 2}, {12, 2}, {0.03125, 14}};
    const RefPrimitive in_a = make_exact_primitive(a, CullMode::None);
    EXPECT_EQ(covered_inside(st, 16, 16, 8, a, in_a, 0), covered_inside(st, 16, 16, 8, b, in_a, 0))
        << "8 samples, left edge: samples inside both triangles, covered by A vs by B";
  }
  {
    // Right edge at x = 16.25, 1 sample: pixel 16's center (16.5) is outside the viewport but the
    // pixel is overlapped, so writable.
    st.viewport = {0.25f, 0, 16, 16};
    const glm::dvec2 a[3] = {{16.3125, 1}, {17.5, 1}, {16.3125, 15}};
    const glm::dvec2 b[3] = {{8, 1}, {17.5, 1}, {16.3125, 15}};
    const RefPrimitive in_a = make_exact_primitive(a, CullMode::None);
    EXPECT_EQ(covered_inside(st, 20, 16, 1, a, in_a, 16), covered_inside(st, 20, 16, 1, b, in_a, 16))
        << "1 sample, right edge: pixel centers inside both triangles, covered by A vs by B";
  }
}

}  // namespace
}  // namespace luxel::rasterizer::test
