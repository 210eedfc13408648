// Coverage per sample against a brute-force oracle (raster_support.hpp): vertices snapped to
// 1/256 pixel with round-half-even, three edge functions evaluated exactly in int64 at every
// sample of every pixel, top-left rule with y down, D3D10.1 sample positions, viewport and
// scissor as pixel rectangles. Triangles the library has to clip (near plane, guard band) or
// divide by w in float are compared against the exact (double) clipped polygon, except within a
// stated distance of its boundary (FuzzyPolygon::eps).

#include "coverage_support.hpp"
#include "raster_support.hpp"

#include "luxel/rasterizer/limits.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace luxel::rasterizer::test {
namespace {

// Thousands of seeded random triangles of every kind (TriKind), every configuration, 1/2/4/8
// samples, cull none/cw/ccw, both windings, both winding conventions; half the batches count
// each triangle's coverage through its own bit, half check that the last covering triangle wins.
TEST(Coverage, RandomTrianglesMatchTheOracle) {
  const int batches = budget(48, 3);  // of 32 triangles, per configuration and sample count
  Context ctx(2);
  uint64_t unknown = 0, covered = 0, wide_checked = 0, triangles = 0, small_walks = 0, generic_stamps = 0;
  int failed_batches = 0;
  uint32_t seed = 1;
  for (const CoverageConfig& base : coverage_configs(true)) {
    for (int S : {1, 2, 4, 8}) {
      ColorTarget target(base.width, base.height, S);
      TriangleGenerator gen(seed++ * 7919u, base);
      for (int b = 0; b < batches && failed_batches < 5; ++b) {
        CoverageConfig cfg = base;
        cfg.state.rasterizer.cull = static_cast<CullMode>(gen.rng()() % 3);
        cfg.state.rasterizer.front_counter_clockwise = gen.rng()() & 1;
        std::vector<TestTriangle> batch;
        for (int k = 0; k < 32; ++k) batch.push_back(gen.random());
        const BatchMode mode = b % 2 ? BatchMode::LastWins : BatchMode::Bits;
        ctx.reset_stats();
        draw_coverage_batch(ctx, target, cfg, batch, mode);
        std::vector<std::string> messages;
        const int bad = check_coverage_batch(ctx, target, cfg, batch, mode, messages, 6, &unknown, &covered);
        triangles += batch.size();
        small_walks += ctx.stats().small_walks;
        generic_stamps += ctx.stats().stamps_wide_edges + ctx.stats().blocks_full;
        EXPECT_EQ(ctx.stats().triangles, batch.size());
        if (bad) {
          ++failed_batches;
          ADD_FAILURE() << bad << " samples differ from the oracle (" << (mode == BatchMode::Bits ? "bits" : "last-wins")
                        << " batch " << b << "):\n" << join(messages);
        }
        // Exact triangles with an edge beyond the 32-bit bound must go through the 64-bit stamp
        // path wherever a stamp (simd::kStampWidth x 2 pixels, aligned) is partly covered: a
        // stamp with both covered and uncovered samples inside the clip rectangle can be neither
        // trivially accepted nor rejected.
        const PixelRect rect = writable_rect(cfg.state, cfg.width, cfg.height);
        bool expect_wide = false;
        for (const TestTriangle& t : batch) {
          if (!t.ref.exact || !t.wide) continue;
          const RefPrimitive p = with_cull(t.ref, cfg.state.rasterizer.cull);
          if (p.culled) continue;
          const auto pattern = d3d_pattern(S);
          for (int sy = rect.y0 & ~1; sy < rect.y1 && !expect_wide; sy += 2)
            for (int sx = rect.x0 & ~(simd::kStampWidth - 1); sx < rect.x1 && !expect_wide; sx += simd::kStampWidth) {
              int in = 0, out = 0;
              for (int y = sy; y < sy + 2; ++y)
                for (int x = sx; x < sx + simd::kStampWidth; ++x)
                  if (rect.contains(x, y))
                    for (int s = 0; s < S; ++s) (p.cover(x, y, pattern[s]) == Cover::In ? in : out)++;
              expect_wide = in && out;
            }
        }
        wide_checked += expect_wide;
        if (expect_wide) {
          EXPECT_GT(ctx.stats().stamps_wide_edges, 0u) << cfg.name << ", batch " << b;
        }
      }
    }
  }
  std::printf("[          ] %llu triangles, %llu covered samples, %llu unknown, %llu batches with a wide-edge stamp\n",
              (unsigned long long)triangles, (unsigned long long)covered, (unsigned long long)unknown,
              (unsigned long long)wide_checked);
  EXPECT_GT(triangles, 1000u * (kReducedRun ? 0 : 1));
  EXPECT_GT(wide_checked, 0u) << "no wide-edge triangle covered a sample: the 64-bit path went untested";
  // Both walks are checked: the 32-bit small-triangle path and the generic one (blocks, wide edges).
  EXPECT_GT(small_walks, 100u) << "the small-triangle path went untested";
  EXPECT_GT(generic_stamps, 100u) << "the generic path went untested";
  // The fuzzy oracle must stay meaningful: few samples near clipped boundaries.
  EXPECT_LT(unknown, covered / 50) << unknown << " unknown vs " << covered << " covered samples";
}

// A hand-checked case for the oracle and the library at once: two triangles sharing a diagonal
// through pixel centers, with edges through pixel centers on all sides (1 sample per pixel).
TEST(Coverage, HandCheckedFillRule) {
  Context ctx(1);
  ColorTarget target(8, 8, 1);
  const ViewportMap map(Viewport{}, 8, 8);
  PipelineState state;
  state.rasterizer.cull = CullMode::None;
  clear_color(ctx, target, glm::vec4(0.0f));
  // Upper-left: top edge y = .5 and left edge x = .5 are in, the diagonal x + y = 5 is a right
  // edge and out: pixels with i + j <= 3.
  const glm::vec4 a[3] = {map.clip_from_screen(0.5, 0.5), map.clip_from_screen(4.5, 0.5), map.clip_from_screen(0.5, 4.5)};
  // Lower-right: the diagonal is its left edge (in), x = 4.5 (right) and y = 4.5 (bottom) out.
  const glm::vec4 b[3] = {map.clip_from_screen(4.5, 4.5), map.clip_from_screen(0.5, 4.5), map.clip_from_screen(4.5, 0.5)};
  draw(ctx, Framebuffer{&target, nullptr}, state, Geometry::non_indexed(3), PositionVS{a, nullptr}, ConstantPS{{1.0f / 255, 0, 0, 0}});
  draw(ctx, Framebuffer{&target, nullptr}, state, Geometry::non_indexed(3), PositionVS{b, nullptr}, ConstantPS{{0, 1.0f / 255, 0, 0}});
  ctx.flush();
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      const bool in_a = x + y <= 3;
      const bool in_b = x + y >= 4 && x <= 3 && y <= 3;
      EXPECT_EQ(target.sample(x, y, 0), rgba8(in_a, in_b, 0, 0)) << "pixel " << x << ", " << y;
    }
}

// Edges longer than the 32-bit stamp bound, crossing the target, at every sample count.
TEST(Coverage, WideEdgesTakeThe64BitPathAndMatchTheOracle) {
  Context ctx(2);
  CoverageConfig cfg;
  cfg.name = "wide";
  cfg.width = 128;
  cfg.height = 64;
  cfg.state.rasterizer.cull = CullMode::None;
  TriangleGenerator gen(99, cfg);
  const glm::dvec2 tris[][3] = {
      {{-12000.5, -9000.25}, {12000, 9100.5}, {60.125, 40.0625}},      // sliver through the middle
      {{-16000, 20}, {16000, 30.5}, {64, 50.00390625}},                 // nearly horizontal, 32000 px long
      {{30.5, -16000}, {31.5, 16000}, {100.25, 33}},                   // nearly vertical
      {{-16000, -16000}, {16000, -15999}, {-15999, 16000}},             // covers everything
  };
  for (int S : {1, 2, 4, 8}) {
    ColorTarget target(cfg.width, cfg.height, S);
    std::vector<TestTriangle> batch;
    for (const auto& t : tris) {
      batch.push_back(gen.from_screen(TriKind::Wide, t));
      EXPECT_TRUE(batch.back().wide);
    }
    ctx.reset_stats();
    draw_coverage_batch(ctx, target, cfg, batch, BatchMode::Bits);
    std::vector<std::string> messages;
    EXPECT_EQ(check_coverage_batch(ctx, target, cfg, batch, BatchMode::Bits, messages, 6), 0) << join(messages);
    EXPECT_GT(ctx.stats().stamps_wide_edges, 0u) << S << " samples";
  }
}

// The triangles of one draw land in several front-end chunks (kTrianglesPerChunk): the tile
// replays them in submission order, so the last covering triangle must win everywhere.
TEST(Coverage, SubmissionOrderAcrossChunks) {
  const int count = 2 * kTrianglesPerChunk + 3001;
  CoverageConfig cfg;
  cfg.width = 96;
  cfg.height = 64;
  cfg.state.viewport = {0, 0, 128, 64};
  cfg.state.rasterizer.cull = CullMode::None;
  TriangleGenerator gen(4242, cfg);
  std::vector<glm::vec4> positions;
  std::vector<std::array<glm::vec4, 1>> colors;
  std::vector<RefPrimitive> refs;
  for (int i = 0; i < count; ++i) {
    glm::dvec2 s[3];
    const glm::dvec2 c(std::uniform_real_distribution<double>(-4, 100)(gen.rng()),
                       std::uniform_real_distribution<double>(-4, 68)(gen.rng()));
    for (auto& v : s)
      v = glm::round((c + glm::dvec2(std::uniform_real_distribution<double>(-6, 6)(gen.rng()),
                                     std::uniform_real_distribution<double>(-6, 6)(gen.rng()))) * 1024.0) / 1024.0;
    const TestTriangle t = gen.from_screen(TriKind::Small, s);
    refs.push_back(t.ref);
    const uint32_t id = uint32_t(i + 1);
    const glm::vec4 color(float(id & 255) / 255, float((id >> 8) & 255) / 255, float(id >> 16) / 255, 1.0f);
    for (int k = 0; k < 3; ++k) {
      positions.push_back(t.clip[k]);
      colors.push_back({color});
    }
  }
  const int S = 4;
  ColorTarget target(cfg.width, cfg.height, S);
  Context ctx(2);
  clear_color(ctx, target, glm::vec4(0.0f));
  draw(ctx, Framebuffer{&target, nullptr}, cfg.state, Geometry::non_indexed(uint32_t(positions.size())),
       ArrayVS<1>{positions.data(), colors.data()}, VaryingPS{});
  const std::vector<uint32_t> actual = read_color(ctx, target);
  std::vector<uint32_t> expected(actual.size(), 0);
  const PixelRect rect = writable_rect(cfg.state, cfg.width, cfg.height);
  for (int i = 0; i < count; ++i)
    for_each_sample(refs[i], rect, S, [&](int x, int y, int s, Cover) {
      expected[sample_index(cfg.width, S, x, y, s)] = uint32_t(i + 1) | 0xff000000u;
    });
  int bad = 0;
  for (size_t i = 0; i < actual.size(); ++i)
    if (actual[i] != expected[i] && bad++ < 5)
      ADD_FAILURE() << "sample " << i << ": triangle " << int(actual[i] & 0xffffff) - 1 << " wins, expected "
                    << int(expected[i] & 0xffffff) - 1;
  EXPECT_EQ(bad, 0);
}

struct FacingPS {
  static constexpr bool kCanDiscard = false, kWritesDepth = false;
  void operator()(const PixelInput<1>& in, PixelOutput& out) const {
    const float f = in.front_facing ? 1.0f : 0.0f;
    out.color = {simd::Float(1.0f - f), simd::Float(f), simd::Float(0.0f), simd::Float(1.0f)};
  }
};

// D3D9 culling names the winding on screen; front_counter_clockwise only changes which side is
// reported as front (and which stencil face two-sided stencil uses), never what is culled.
TEST(Coverage, CullModesAndFrontFacing) {
  const ViewportMap map(Viewport{}, 16, 8);
  // Clockwise on screen (y down): right along the top, then down-left.
  const glm::vec4 cw[3] = {map.clip_from_screen(1, 1), map.clip_from_screen(7, 1), map.clip_from_screen(1, 7)};
  const glm::vec4 ccw[3] = {map.clip_from_screen(9, 1), map.clip_from_screen(9, 7), map.clip_from_screen(15, 1)};
  const uint32_t red = rgba8(255, 0, 0, 255), green = rgba8(0, 255, 0, 255);
  for (CullMode cull : {CullMode::None, CullMode::CW, CullMode::CCW})
    for (bool front_ccw : {false, true}) {
      SCOPED_TRACE(testing::Message() << "cull " << int(cull) << ", front_counter_clockwise " << front_ccw);
      Context ctx(1);
      ColorTarget target(16, 8, 1);
      clear_color(ctx, target, glm::vec4(0.0f));
      PipelineState state;
      state.rasterizer.cull = cull;
      state.rasterizer.front_counter_clockwise = front_ccw;
      draw(ctx, Framebuffer{&target, nullptr}, state, Geometry::non_indexed(3), PositionVS{cw, nullptr}, FacingPS{});
      draw(ctx, Framebuffer{&target, nullptr}, state, Geometry::non_indexed(3), PositionVS{ccw, nullptr}, FacingPS{});
      ctx.flush();
      const uint32_t cw_pixel = target.sample(2, 2, 0), ccw_pixel = target.sample(10, 2, 0);
      EXPECT_EQ(cw_pixel, cull == CullMode::CW ? 0u : (front_ccw ? red : green));
      EXPECT_EQ(ccw_pixel, cull == CullMode::CCW ? 0u : (front_ccw ? green : red));
      EXPECT_EQ(ctx.stats().culled, cull == CullMode::None ? 0u : 1u);
      EXPECT_EQ(ctx.stats().triangles, 2u);
    }
}

// The D3D9 default state culls counter-clockwise triangles.
TEST(Coverage, DefaultStateIsD3D9) {
  const PipelineState s;
  EXPECT_EQ(s.rasterizer.cull, CullMode::CCW);
  EXPECT_FALSE(s.rasterizer.front_counter_clockwise);
  EXPECT_TRUE(s.depth_stencil.depth_enable);
  EXPECT_TRUE(s.depth_stencil.depth_write);
  EXPECT_EQ(s.depth_stencil.depth_func, CompareFunc::LessEqual);
  EXPECT_FALSE(s.depth_stencil.stencil_enable);
  EXPECT_EQ(s.depth_stencil.stencil_read_mask, 0xff);
  EXPECT_EQ(s.depth_stencil.stencil_write_mask, 0xff);
  EXPECT_EQ(s.depth_stencil.front.func, CompareFunc::Always);
  EXPECT_FALSE(s.blend.enable);
  EXPECT_EQ(s.blend.src, BlendFactor::One);
  EXPECT_EQ(s.blend.dst, BlendFactor::Zero);
  EXPECT_EQ(s.blend.write_mask, kWriteAll);
  EXPECT_FALSE(s.alpha_test.enable);
  EXPECT_EQ(s.viewport.min_depth, 0.0f);
  EXPECT_EQ(s.viewport.max_depth, 1.0f);
}

// Zero-area triangles (after snapping) draw nothing and are counted as degenerate.
TEST(Coverage, DegenerateTrianglesAreCounted) {
  const ViewportMap map(Viewport{}, 64, 64);
  const glm::dvec2 tris[][3] = {
      {{10, 10}, {20, 20}, {40, 40}},                      // collinear
      {{10.5, 3}, {10.5, 3}, {30, 50}},                    // repeated vertex
      {{5, 5}, {5, 5}, {5, 5}},                            // a point
      {{1, 1}, {33, 17}, {17.0009765625, 9.0}},            // collinear after snapping (1/1024 off)
  };
  Context ctx(1);
  ColorTarget target(64, 64, 4);
  clear_color(ctx, target, glm::vec4(0.0f));
  PipelineState state;
  state.rasterizer.cull = CullMode::None;
  for (const auto& t : tris) {
    const glm::vec4 c[3] = {map.clip_from_screen(t[0].x, t[0].y), map.clip_from_screen(t[1].x, t[1].y),
                            map.clip_from_screen(t[2].x, t[2].y)};
    EXPECT_EQ(ExactTriangle::from_screen(t).area2, 0) << "test setup";
    draw(ctx, Framebuffer{&target, nullptr}, state, Geometry::non_indexed(3), PositionVS{c, nullptr}, ConstantPS{});
  }
  const std::vector<uint32_t> v = read_color(ctx, target);
  EXPECT_EQ(std::count(v.begin(), v.end(), 0u), std::ptrdiff_t(v.size()));
  EXPECT_EQ(ctx.stats().degenerate, 4u);
  EXPECT_EQ(ctx.stats().rasterized, 0u);
}

}  // namespace
}  // namespace luxel::rasterizer::test
