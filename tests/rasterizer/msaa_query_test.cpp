// MSAA sample positions (the D3D10.1 tables, as data and as behaviour), occlusion queries
// (exact sample counts against the brute-force oracle), resolve and clear packing.

#include "coverage_support.hpp"
#include "pipeline_support.hpp"
#include "raster_support.hpp"

#include "luxel/rasterizer/msaa.hpp"

#include <gtest/gtest.h>

#include <random>

namespace luxel::rasterizer::test {
namespace {

TEST(Msaa, StandardOffsetsAreTheD3D10_1Tables) {
  for (int S : {1, 2, 4, 8}) {
    const SampleOffset* lib = standard_sample_offsets(S);
    ASSERT_NE(lib, nullptr) << S;
    const auto ref = d3d_pattern(S);
    for (int s = 0; s < S; ++s) {
      EXPECT_EQ(lib[s].x, ref[s].x) << S << " samples, sample " << s;
      EXPECT_EQ(lib[s].y, ref[s].y) << S << " samples, sample " << s;
      EXPECT_EQ(sample_subpixel(lib[s].x), 128 + 16 * ref[s].x);
    }
  }
  for (int bad : {0, 3, 5, 16, -1}) {
    EXPECT_EQ(standard_sample_offsets(bad), nullptr) << bad;
    EXPECT_FALSE(is_valid_sample_count(bad)) << bad;
  }
}

// Behaviour: a triangle a few 1/256 pixel wide around one sample position of a pixel covers that
// sample (stored in plane s) and no other, in every pixel of a small grid of positions.
TEST(Msaa, EachSampleIsCoveredWhereTheTableSaysAndStoredInItsPlane) {
  Context ctx(1);
  const int W = 16, H = 16;
  const ViewportMap map(Viewport{}, W, H);
  for (int S : {1, 2, 4, 8}) {
    const auto pattern = d3d_pattern(S);
    ColorTarget target(W, H, S);
    for (int s = 0; s < S; ++s) {
      clear_color(ctx, target, glm::vec4(0.0f));
      PipelineState st;
      st.rasterizer.cull = CullMode::None;
      for (int px = 1; px < W; px += 5)
        for (int py = 2; py < H; py += 4) {
          const double cx = px + (128 + 16 * pattern[s].x) / 256.0, cy = py + (128 + 16 * pattern[s].y) / 256.0;
          const double e = 3 / 256.0;
          // Legs of 9/256 pixel; the sample lies 3/256 inside every edge.
          const glm::vec4 c[3] = {map.clip_from_screen(cx - e, cy - e), map.clip_from_screen(cx + 2 * e, cy - e),
                                  map.clip_from_screen(cx - e, cy + 2 * e)};
          draw(ctx, Framebuffer{&target, nullptr}, st, Geometry::non_indexed(3), PositionVS{c}, ConstantPS{glm::vec4(1.0f)});
        }
      ctx.flush();
      for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
          for (int t = 0; t < S; ++t) {
            const bool expect = t == s && (x - 1) % 5 == 0 && (y - 2) % 4 == 0;
            EXPECT_EQ(target.sample(x, y, t), expect ? 0xffffffffu : 0u)
                << S << " samples: triangle around sample " << s << ", pixel (" << x << ", " << y << ") plane " << t;
          }
    }
  }
}

// The query counts samples (not pixels) that pass everything, exactly, for random exact
// triangles: the count must equal the oracle's count of covered samples.
TEST(OcclusionQuery, CountsEveryCoveredSample) {
  Context ctx(2);
  const int rounds = budget(24, 4);
  for (const CoverageConfig& base : coverage_configs(false))
    for (int S : {1, 2, 4, 8}) {
      TriangleGenerator gen(uint32_t(31 * S + base.width), base);
      ColorTarget target(base.width, base.height, S);
      for (int r = 0; r < rounds; ++r) {
        CoverageConfig cfg = base;
        cfg.state.rasterizer.cull = static_cast<CullMode>(gen.rng()() % 3);
        std::vector<TestTriangle> batch;
        while (batch.size() < 8) {
          TestTriangle t = gen.random();
          if (t.ref.exact) batch.push_back(t);
        }
        OcclusionQuery q;
        ctx.begin_query(q);
        draw_coverage_batch(ctx, target, cfg, batch, BatchMode::LastWins);
        ctx.end_query();
        const PixelRect rect = writable_rect(cfg.state, cfg.width, cfg.height);
        uint64_t expect = 0;
        for (const TestTriangle& t : batch)
          for_each_sample(with_cull(t.ref, cfg.state.rasterizer.cull), rect, S, [&](int, int, int, Cover) { ++expect; });
        EXPECT_EQ(ctx.query_result(q), expect) << cfg.name << ", " << S << " samples, round " << r;
      }
    }
}

// Depth, stencil, texkill and alpha test each reject some samples; only survivors count. The
// expected counts come from the scalar reference (pipeline_support.hpp); compare_scene checks
// them along with colors, depth and stencil.
TEST(OcclusionQuery, RejectedSamplesDoNotCount) {
  Context ctx(2);
  int checked = 0;
  for (uint32_t seed = 0; seed < uint32_t(budget(400, 40)); ++seed) {
    Scene scene = random_scene(50000 + seed, seed % 2 ? 4 : 1);
    // Count every draw, and make each draw use one rejection mechanism on purpose.
    for (size_t i = 0; i < scene.draws.size(); ++i) {
      SceneDraw& d = scene.draws[i];
      d.counted = true;
      d.state.alpha_test.enable = i % 4 == 0;
      d.shade.discard = i % 4 == 1;
      d.state.depth_stencil.stencil_enable = i % 4 == 2;
      d.state.depth_stencil.depth_enable = i % 4 == 3 || d.state.depth_stencil.depth_enable;
    }
    const SceneReference ref = reference_scene(scene);
    const SceneOutput out = render_scene(ctx, scene);
    EXPECT_EQ(out.query, ref.query) << "seed " << 50000 + seed << "\n" << scene.describe();
    checked += ref.query > 0;
  }
  EXPECT_GT(checked, 10);
}

TEST(OcclusionQuery, SpansFlushesAndRestarts) {
  Context ctx(2);
  const int W = 64, H = 32, S = 4;
  ColorTarget target(W, H, S);
  DepthStencilTarget ds(W, H, S);
  const ViewportMap map(Viewport{}, W, H);
  PipelineState st;
  st.rasterizer.cull = CullMode::None;
  st.depth_stencil.depth_func = CompareFunc::Less;
  const glm::vec4 full[3] = {map.clip_from_screen(-1, -1, 0.5f), map.clip_from_screen(200, -1, 0.5f),
                             map.clip_from_screen(-1, 200, 0.5f)};
  const Framebuffer fb{&target, &ds};
  const uint64_t all = uint64_t(W) * H * S;
  clear_depth_stencil(ctx, ds, 1.0f, 0);
  OcclusionQuery q;
  EXPECT_EQ(ctx.query_result(q), 0u);
  ctx.begin_query(q);
  EXPECT_EQ(ctx.active_query(), &q);
  draw(ctx, fb, st, Geometry::non_indexed(3), PositionVS{full}, ConstantPS{});
  ctx.flush();  // the query spans the flush
  draw(ctx, fb, st, Geometry::non_indexed(3), PositionVS{full}, ConstantPS{});  // fails Less: 0 more
  clear_depth_stencil(ctx, ds, 1.0f, 0);
  draw(ctx, fb, st, Geometry::non_indexed(3), PositionVS{full}, ConstantPS{});
  ctx.end_query();
  EXPECT_EQ(ctx.active_query(), nullptr);
  draw(ctx, fb, st, Geometry::non_indexed(3), PositionVS{full}, ConstantPS{});  // not counted
  EXPECT_EQ(ctx.query_result(q), 2 * all);
  // Restarting resets the count; a query whose draws are still pending gets them first.
  clear_depth_stencil(ctx, ds, 1.0f, 0);
  ctx.begin_query(q);
  draw(ctx, fb, st, Geometry::non_indexed(3), PositionVS{full}, ConstantPS{});
  ctx.end_query();
  OcclusionQuery other;
  ctx.begin_query(other);
  clear_depth_stencil(ctx, ds, 1.0f, 0);
  draw(ctx, fb, st, Geometry::non_indexed(3), PositionVS{full}, ConstantPS{});
  draw(ctx, fb, st, Geometry::non_indexed(3), PositionVS{full}, ConstantPS{});
  ctx.end_query();
  ctx.begin_query(q);  // restart while its previous draw is pending
  ctx.end_query();
  EXPECT_EQ(ctx.query_result(q), 0u);
  EXPECT_EQ(ctx.query_result(other), all);
  // Color writes off and no color target still count.
  st.blend.write_mask = 0;
  clear_depth_stencil(ctx, ds, 1.0f, 0);
  ctx.begin_query(q);
  draw(ctx, Framebuffer{nullptr, &ds}, st, Geometry::non_indexed(3), PositionVS{full}, ConstantPS{});
  ctx.end_query();
  EXPECT_EQ(ctx.query_result(q), all);
}

TEST(Resolve, RoundedMeanOfTheSamples) {
  Context ctx(2);
  std::mt19937 rng(3);
  for (int S : {1, 2, 4, 8}) {
    const int W = 70, H = 67;  // partial tiles
    ColorTarget target(W, H, S);
    ctx.flush();
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x)
        for (int s = 0; s < S; ++s) target.set_sample(x, y, s, rng());
    // ResolveAlpha::opaque: the same color, alpha 255 whatever the samples hold.
    for (const ResolveAlpha alpha : {ResolveAlpha::samples, ResolveAlpha::opaque}) {
      const Image img = resolve(ctx, target, alpha);
      ASSERT_EQ(img.width, W);
      ASSERT_EQ(img.height, H);
      int bad = 0;
      for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
          for (int c = 0; c < 4; ++c) {
            int sum = 0;
            for (int s = 0; s < S; ++s) sum += channel(target.sample(x, y, s), c);
            int expect = int(std::floor(double(sum) / S + 0.5));  // halves round up
            if (c == 3 && alpha == ResolveAlpha::opaque) expect = 255;
            if (img.pixel(x, y)[c] != expect && bad++ < 5)
              ADD_FAILURE() << S << " samples, pixel " << x << ", " << y << " channel " << c << ": "
                            << int(img.pixel(x, y)[c]) << " vs " << expect;
          }
      EXPECT_EQ(bad, 0) << (alpha == ResolveAlpha::opaque ? "opaque" : "samples");
    }
  }
}

TEST(Clear, PacksRoundToNearestClampsAndZeroesNaN) {
  Context ctx(1);
  ColorTarget target(3, 3, 2);
  DepthStencilTarget ds(3, 3, 2);
  clear_color(ctx, target, {0.2f, -1.0f, 7.0f, std::nanf("")});
  clear_depth_stencil(ctx, ds, 0.375f, 0xa7);
  ctx.flush();
  for (int s = 0; s < 2; ++s) {
    EXPECT_EQ(target.sample(2, 1, s), rgba8(51, 0, 255, 0));
    EXPECT_EQ(ds.depth(1, 2, s), 0.375f);
    EXPECT_EQ(ds.stencil(1, 2, s), 0xa7);
  }
  EXPECT_EQ(pack_rgba8({0.11f, 0.5019608f, 0.998f, 0.0019f}), rgba8(28, 128, 254, 0));
  const glm::vec4 u = unpack_rgba8(rgba8(0, 51, 255, 128));
  EXPECT_EQ(u, glm::vec4(0.0f, 0.2f, 1.0f, 128 / 255.0f));
  // Depth clears clamp to [0, 1].
  clear_depth_stencil(ctx, ds, 1.5f, 0);
  ctx.flush();
  EXPECT_EQ(ds.depth(0, 0, 0), 1.0f);
  // A depth-only clear leaves stencil as it was.
  clear_depth_stencil(ctx, ds, 0.5f, 0x3c);
  clear_depth(ctx, ds, 0.25f);
  ctx.flush();
  for (int s = 0; s < 2; ++s) {
    EXPECT_EQ(ds.depth(2, 2, s), 0.25f);
    EXPECT_EQ(ds.stencil(2, 2, s), 0x3c);
  }
}

// A region limits clears and resolves to the tiles holding some of it; the rest keeps its values.
TEST(Clear, ARegionTouchesOnlyTheTilesHoldingIt) {
  Context ctx(2);
  const int W = 200, H = 150;  // tiles of kTileSize: 4 x 3, the last ones partial
  ColorTarget target(W, H, 4);
  DepthStencilTarget ds(W, H, 4);
  clear_color(ctx, target, {1, 0, 0, 1});
  clear_depth_stencil(ctx, ds, 0.5f, 9);
  const Scissor region{true, kTileSize + 3, kTileSize - 1, 2 * kTileSize + 1, kTileSize + 5};  // tiles x 1-2, y 0-1
  clear_color(ctx, target, {0, 0, 1, 1}, region);
  clear_depth_stencil(ctx, ds, 0.25f, 3, region);
  clear_depth(ctx, ds, 0.75f);
  clear_depth(ctx, ds, 0.25f, region);
  Image image(W, H);
  std::fill(image.rgba.begin(), image.rgba.end(), uint8_t(7));
  resolve_into(ctx, target, image, ResolveAlpha::samples, region);
  for (int y = 0; y < H; ++y) {
    for (int x = 0; x < W; ++x) {
      const int tx = x / kTileSize, ty = y / kTileSize;
      const bool held = tx >= 1 && tx <= 2 && ty <= 1;
      ASSERT_EQ(target.sample(x, y, 3), held ? rgba8(0, 0, 255, 255) : rgba8(255, 0, 0, 255)) << x << ", " << y;
      ASSERT_EQ(ds.depth(x, y, 2), held ? 0.25f : 0.75f) << x << ", " << y;
      ASSERT_EQ(ds.stencil(x, y, 1), held ? 3 : 9) << x << ", " << y;
      ASSERT_EQ(image.pixel(x, y)[2], held ? 255 : 7) << x << ", " << y;
    }
  }
}

}  // namespace
}  // namespace luxel::rasterizer::test
