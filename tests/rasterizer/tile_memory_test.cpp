// Tile memory (FastPath::TileMemory, framebuffer.hpp): a frame that clears a target whole first
// and discards it before its flush keeps the target's tiles in each thread's own memory. The
// resolves and query counts are the bytes of the same frame kept in the target's memory, on any
// thread count; a frame split by the queue's own flushes keeps every sample; and what discard()
// forbids fails the same way with the fast path on or off.

#include "pipeline_support.hpp"
#include "raster_support.hpp"

#include "luxel/rasterizer/fast_paths.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace luxel::rasterizer::test {
namespace {

Context make_context(int threads, FastPaths paths = FastPaths(), size_t record_budget = ContextOptions{}.max_pending_record_bytes) {
  ContextOptions options;
  options.threads = threads;
  options.fast_paths = paths;
  options.max_pending_record_bytes = record_budget;
  return Context(options);
}

/// The pipeline oracle's random scenes (depth functions, stencil, blending, discard in the
/// shader, shader depth, queries; 1, 2, 4 and 8 samples), resolved and counted, ended the way
/// `end` says.
std::vector<SceneOutput> render_scenes(Context& ctx, SceneEnd end) {
  std::vector<SceneOutput> out;
  for (uint32_t seed = 0; seed < uint32_t(budget(32, 8)); ++seed)
    out.push_back(render_scene(ctx, random_scene(5151 + seed, 1 << (seed % 4)), end));
  return out;
}

void expect_same_resolves(const std::vector<SceneOutput>& a, const std::vector<SceneOutput>& b, const char* what) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_TRUE(a[i].resolved == b[i].resolved) << what << ", scene " << i;
    EXPECT_EQ(a[i].query, b[i].query) << what << ", scene " << i;
  }
}

TEST(TileMemory, DiscardedFramesResolveAsFramesKeptInTheirTargets) {
  Context kept_ctx = make_context(2);
  const std::vector<SceneOutput> kept = render_scenes(kept_ctx, SceneEnd::keep);
  EXPECT_EQ(kept_ctx.stats().tile_memory_targets, 0u);  // nothing discarded: nothing in tile memory

  for (int threads : {1, 2, 3}) {
    Context ctx = make_context(threads);
    ctx.reset_stats();
    expect_same_resolves(kept, render_scenes(ctx, SceneEnd::discard), "tile memory");
    EXPECT_GT(ctx.stats().tile_memory_targets, 0u) << threads << " threads";
  }
  Context off = make_context(2, FastPaths::all_but(FastPath::TileMemory));
  off.reset_stats();
  expect_same_resolves(kept, render_scenes(off, SceneEnd::discard), "tile memory off");
  EXPECT_EQ(off.stats().tile_memory_targets, 0u);
}

// A record budget of one byte makes the queue flush by itself before every draw part after the
// first: those flushes keep the samples (in the targets' own memory), whatever discard() said,
// and the frames still resolve to the same bytes.
TEST(TileMemory, FramesTheQueueSplitsKeepTheirSamples) {
  Context whole = make_context(2);
  Context split = make_context(2, FastPaths(), 1);
  const std::vector<SceneOutput> a = render_scenes(whole, SceneEnd::discard);
  split.reset_stats();
  const std::vector<SceneOutput> b = render_scenes(split, SceneEnd::discard);
  expect_same_resolves(a, b, "split frames");
  EXPECT_GT(split.flush_count(), whole.flush_count());
}

/// One triangle over the whole target.
struct CoverVS {
  static constexpr int kVaryings = 0;
  void operator()(uint32_t i, VertexOutput<0>& out) const {
    const float x[3] = {-1.0f, 3.0f, -1.0f}, y[3] = {-1.0f, -1.0f, 3.0f};
    out.position = {x[i], y[i], 0.5f, 1.0f};
  }
};
struct WhitePS {
  static constexpr bool kCanDiscard = false, kWritesDepth = false;
  void operator()(const PixelInput<0>&, PixelOutput& out) const {
    const simd::Float one(1.0f);
    out.color = {one, one, one, one};
  }
};

void draw_cover(Context& ctx, ColorTarget& color, DepthStencilTarget& ds) {
  PipelineState st;
  st.rasterizer.cull = CullMode::None;
  draw(ctx, Framebuffer{&color, &ds}, st, Geometry::non_indexed(3), CoverVS{}, WhitePS{});
}

// What discard() forbids throws std::logic_error with the fast path on and off alike, and a
// whole clear makes the target usable again.
TEST(TileMemory, DiscardedTargetsMustBeClearedWholeBeforeAnyUse) {
  for (FastPaths paths : {FastPaths(), FastPaths::all_but(FastPath::TileMemory)}) {
    SCOPED_TRACE(fast_paths_off_names(paths));
    Context ctx = make_context(2, paths);
    ColorTarget color(100, 70, 4);
    DepthStencilTarget ds(100, 70, 4);
    clear_color(ctx, color, glm::vec4(0.0f));
    clear_depth_stencil(ctx, ds, 1.0f, 0);
    draw_cover(ctx, color, ds);
    discard(ctx, color);
    discard(ctx, ds);
    EXPECT_THROW(draw_cover(ctx, color, ds), std::logic_error);  // in the frame that discards
    const Image first = resolve(ctx, color);                    // allowed: ends the frame
    EXPECT_EQ(first.rgba[0], 255);

    EXPECT_THROW(resolve(ctx, color), std::logic_error);
    EXPECT_THROW(draw_cover(ctx, color, ds), std::logic_error);
    EXPECT_THROW(color.sample(0, 0, 0), std::logic_error);
    EXPECT_THROW(ds.depth(0, 0, 0), std::logic_error);
    Scissor part;
    part.enable = true, part.x0 = 0, part.y0 = 0, part.x1 = 10, part.y1 = 10;
    EXPECT_THROW(clear_color(ctx, color, glm::vec4(0.0f), part), std::logic_error);
    EXPECT_THROW(clear_depth(ctx, ds, 1.0f), std::logic_error);  // leaves the stencil undefined

    clear_color(ctx, color, glm::vec4(0.0f));
    clear_depth_stencil(ctx, ds, 1.0f, 0);
    draw_cover(ctx, color, ds);
    ctx.flush();
    EXPECT_EQ(color.sample(50, 35, 3), 0xffffffffu);
    EXPECT_EQ(ds.depth(50, 35, 3), 0.5f);

    // A discard with nothing pending takes effect when the frame ends; a whole clear in the same
    // frame after a discard starts samples that are kept.
    discard(ctx, color);
    EXPECT_EQ(color.sample(50, 35, 3), 0xffffffffu);
    ctx.flush();
    EXPECT_THROW(color.sample(0, 0, 0), std::logic_error);
    clear_color(ctx, color, glm::vec4(0.0f));
    clear_depth_stencil(ctx, ds, 1.0f, 0);
    discard(ctx, color);
    clear_color(ctx, color, glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
    ctx.flush();
    EXPECT_EQ(color.sample(3, 3, 0), 0xff0000ffu);
  }
}

// Frames that do not start with a whole clear run in the targets' own memory: a region clear,
// a depth clear that leaves the stencil, a draw first. A load_image is a whole clear, and so is a
// clear after a discard() at the start of a frame (the glInvalidateFramebuffer pattern).
TEST(TileMemory, OnlyFramesThatStartWithAWholeClearLiveInTileMemory) {
  struct Case {
    const char* name;
    uint64_t in_tile_memory;  // targets kept in tile memory
    void (*start)(Context&, ColorTarget&, DepthStencilTarget&);
  };
  static const Image image = [] {
    Image im(100, 70);
    for (size_t i = 0; i < im.rgba.size(); ++i) im.rgba[i] = uint8_t(i * 37 % 251);
    return im;
  }();
  const Case cases[] = {
      {"whole clears", 2, [](Context& c, ColorTarget& t, DepthStencilTarget& d) {
         clear_color(c, t, glm::vec4(0.25f)), clear_depth_stencil(c, d, 1.0f, 0);
       }},
      {"a region clear", 1, [](Context& c, ColorTarget& t, DepthStencilTarget& d) {
         Scissor r;
         r.enable = true, r.x0 = 0, r.y0 = 0, r.x1 = 100, r.y1 = 70;
         clear_color(c, t, glm::vec4(0.25f), r), clear_depth_stencil(c, d, 1.0f, 0);
       }},
      {"depth without stencil", 1, [](Context& c, ColorTarget& t, DepthStencilTarget& d) {
         clear_color(c, t, glm::vec4(0.25f)), clear_depth(c, d, 1.0f);
       }},
      {"a draw first", 0, [](Context& c, ColorTarget& t, DepthStencilTarget& d) { draw_cover(c, t, d); }},
      {"load_image", 2, [](Context& c, ColorTarget& t, DepthStencilTarget& d) {
         load_image(c, image, t), clear_depth_stencil(c, d, 0.75f, 3);
       }},
      {"discard, then clear", 2, [](Context& c, ColorTarget& t, DepthStencilTarget& d) {
         discard(c, t), discard(c, d);
         clear_color(c, t, glm::vec4(0.25f)), clear_depth_stencil(c, d, 1.0f, 0);
       }},
  };
  for (const Case& k : cases) {
    std::vector<uint8_t> resolved[2];
    for (int end = 0; end < 2; ++end) {
      Context ctx = make_context(2);
      ColorTarget color(100, 70, 4);
      DepthStencilTarget ds(100, 70, 4);
      ctx.reset_stats();
      k.start(ctx, color, ds);
      PipelineState st;
      st.rasterizer.cull = CullMode::None;
      st.depth_stencil.depth_func = CompareFunc::Greater;  // reads what the start left
      draw(ctx, Framebuffer{&color, &ds}, st, Geometry::non_indexed(3), CoverVS{}, WhitePS{});
      if (end == 1) discard(ctx, color), discard(ctx, ds);
      resolved[end] = resolve(ctx, color).rgba;
      EXPECT_EQ(ctx.stats().tile_memory_targets, end == 1 ? k.in_tile_memory : 0u) << k.name;
    }
    EXPECT_TRUE(resolved[0] == resolved[1]) << k.name;
  }
}

// A discard() that a frame split by the context (here: a target of another size) carries on is
// applied when the frame ends; a target that goes away meanwhile leaves nothing behind.
TEST(TileMemory, ADiscardOutlivesTheFlushesTheContextMakes) {
  Context ctx = make_context(2);
  ColorTarget a(100, 70, 4), b(30, 20, 1);
  clear_color(ctx, a, glm::vec4(1.0f));
  ctx.flush();
  discard(ctx, a);
  clear_color(ctx, b, glm::vec4(0.0f));  // another tiling: the context flushes a's frame
  EXPECT_EQ(a.sample(1, 1, 0), 0xffffffffu);
  resolve(ctx, b);  // ends the frame
  EXPECT_THROW(a.sample(1, 1, 0), std::logic_error);
  {
    ColorTarget c(100, 70, 4);
    discard(ctx, c);
    clear_color(ctx, b, glm::vec4(0.0f));
  }  // c goes while its discard is carried on
  resolve(ctx, b);
  ColorTarget d(100, 70, 4);
  discard(ctx, d);
  clear_color(ctx, b, glm::vec4(0.0f));
  ColorTarget e = std::move(d);  // takes the discard along
  resolve(ctx, e);               // a resolve may follow a discard
  EXPECT_THROW(resolve(ctx, e), std::logic_error);
}

// invalidate() stands for a whole clear without its fill: a frame whose draws read nothing of the
// target (no depth or stencil test; the luminance histogram's counting draw) keeps it in tile
// memory and counts every sample, on any thread count, with the fast path on and off; and it
// makes a discarded target usable again, as a whole clear does.
TEST(TileMemory, AnInvalidatedTargetCountsLikeAClearedOneWithoutTheFill) {
  const int W = 100, H = 70, S = 4;
  PipelineState st;
  st.rasterizer.cull = CullMode::None;
  st.depth_stencil.depth_enable = false;
  st.blend.write_mask = 0;
  for (FastPaths paths : {FastPaths(), FastPaths::all_but(FastPath::TileMemory)}) {
    for (int threads : {1, 2}) {
      Context ctx = make_context(threads, paths);
      DepthStencilTarget ds(W, H, S);
      for (int frame = 0; frame < 2; ++frame) {  // the second starts from the first's discard
        ctx.reset_stats();
        OcclusionQuery q;
        invalidate(ctx, ds);
        ctx.begin_query(q);
        draw(ctx, Framebuffer{nullptr, &ds}, st, Geometry::non_indexed(3), CoverVS{}, WhitePS{});
        ctx.end_query();
        discard(ctx, ds);
        EXPECT_EQ(ctx.query_result(q), uint64_t(W) * H * S) << threads << " threads, frame " << frame;
        EXPECT_EQ(ctx.stats().tile_memory_targets, paths.on(FastPath::TileMemory) ? 1u : 0u) << threads << " threads";
      }
    }
  }
}

// A color target invalidated, drawn over whole and discarded lives in tile memory without a
// fill, and resolves to what the draw wrote, after a frame that left other samples there.
TEST(TileMemory, AnInvalidatedColorTargetResolvesToWhatTheDrawWrote) {
  const int W = 100, H = 70;
  PipelineState st;
  st.rasterizer.cull = CullMode::None;
  st.depth_stencil.depth_enable = false;
  for (int threads : {1, 2}) {
    Context ctx = make_context(threads);
    ColorTarget earlier(W, H, 4), target(W, H, 1);
    clear_color(ctx, earlier, glm::vec4(1, 0, 1, 1));
    discard(ctx, earlier);
    (void)resolve(ctx, earlier);
    ctx.reset_stats();
    invalidate(ctx, target);
    draw(ctx, Framebuffer{&target, nullptr}, st, Geometry::non_indexed(3), CoverVS{}, WhitePS{});
    discard(ctx, target);
    const Image image = resolve(ctx, target);
    EXPECT_EQ(ctx.stats().tile_memory_targets, 1u) << threads << " threads";
    EXPECT_EQ(image.rgba, std::vector<uint8_t>(size_t(W) * H * 4, 255)) << threads << " threads";
  }
}

}  // namespace
}  // namespace luxel::rasterizer::test
