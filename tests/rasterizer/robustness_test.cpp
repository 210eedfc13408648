// Robustness: bad input is dropped or rejected with std::invalid_argument, never crashes, and
// never writes outside what a draw may write.

#include "coverage_support.hpp"
#include "raster_support.hpp"

#include "luxel/rasterizer/detail/triangle_setup.hpp"  // clip_polygon
#include "luxel/rasterizer/limits.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <climits>
#include <cstring>
#include <limits>
#include <random>

namespace luxel::rasterizer::test {
namespace {

const glm::vec4 kFull[3] = {{-1, 1, 0.5f, 1}, {3, 1, 0.5f, 1}, {-1, -3, 0.5f, 1}};  // covers the viewport

TEST(Robustness, NonFinitePositionsDropTheTriangle) {
  const float bad_values[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                              -std::numeric_limits<float>::infinity()};
  std::vector<glm::vec4> pos;
  const ViewportMap map(Viewport{}, 32, 32);
  const glm::dvec2 good[3] = {{2, 3}, {20.5, 4}, {7, 25}};
  for (int v = 0; v < 3; ++v)
    for (int c = 0; c < 4; ++c)
      for (float bad : bad_values) {
        glm::vec4 tri[3] = {map.clip_from_screen(1, 1), map.clip_from_screen(30, 1), map.clip_from_screen(1, 30)};
        tri[v][c] = bad;
        pos.insert(pos.end(), tri, tri + 3);
      }
  const size_t bad_count = pos.size() / 3;
  for (const auto& g : good) pos.push_back(map.clip_from_screen(g.x, g.y));
  for (int S : {1, 4}) {
    Context ctx(2);
    ColorTarget target(32, 32, S);
    clear_color(ctx, target, glm::vec4(0.0f));
    PipelineState st;
    st.rasterizer.cull = CullMode::None;
    draw(ctx, Framebuffer{&target, nullptr}, st, Geometry::non_indexed(uint32_t(pos.size())), PositionVS{pos.data()},
         ConstantPS{glm::vec4(1.0f)});
    const std::vector<uint32_t> v = read_color(ctx, target);
    EXPECT_EQ(ctx.stats().non_finite, bad_count);
    EXPECT_EQ(ctx.stats().triangles, bad_count + 1);
    const RefPrimitive p = make_exact_primitive(good, CullMode::None);
    std::vector<uint32_t> expect(v.size(), 0);
    for_each_sample(p, {0, 0, 32, 32}, S, [&](int x, int y, int s, Cover) { expect[sample_index(32, S, x, y, s)] = ~0u; });
    EXPECT_TRUE(v == expect) << "only the finite triangle may draw";
  }
}

TEST(Robustness, OutOfRangeIndicesDropTheTriangle) {
  const ViewportMap map(Viewport{}, 16, 16);
  const glm::vec4 pos[4] = {map.clip_from_screen(1, 1), map.clip_from_screen(15, 1), map.clip_from_screen(1, 15),
                            map.clip_from_screen(15, 15)};
  PipelineState st;
  st.rasterizer.cull = CullMode::None;
  Context ctx(1);
  ColorTarget target(16, 16, 1);
  // 16-bit: the good triangle (0, 1, 2) between bad ones; a trailing partial triangle is ignored.
  const uint16_t i16[] = {0, 1, 4, 0, 1, 2, 65535, 0, 1, 3, 3, 3, 0, 1};
  clear_color(ctx, target, glm::vec4(0.0f));
  draw(ctx, Framebuffer{&target, nullptr}, st, Geometry::indexed(std::span<const uint16_t>(i16), 4), PositionVS{pos},
       ConstantPS{glm::vec4(1.0f)});
  ctx.flush();
  EXPECT_EQ(ctx.stats().triangles, 4u);
  EXPECT_EQ(ctx.stats().bad_index, 2u);
  EXPECT_EQ(ctx.stats().degenerate, 1u);  // (3, 3, 3)
  EXPECT_EQ(target.sample(3, 3, 0), ~0u);
  EXPECT_EQ(target.sample(13, 13, 0), 0u);
  // 32-bit, including indices that overflow a signed int and the largest value.
  const uint32_t i32[] = {0, 1, 0x80000000u, 0xffffffffu, 2, 3, 3, 2, 1, 4, 4, 4};
  ctx.reset_stats();
  clear_color(ctx, target, glm::vec4(0.0f));
  draw(ctx, Framebuffer{&target, nullptr}, st, Geometry::indexed(std::span<const uint32_t>(i32), 4), PositionVS{pos},
       ConstantPS{glm::vec4(1.0f)});
  ctx.flush();
  EXPECT_EQ(ctx.stats().triangles, 4u);
  EXPECT_EQ(ctx.stats().bad_index, 3u);
  EXPECT_EQ(target.sample(3, 3, 0), 0u);
  EXPECT_EQ(target.sample(13, 13, 0), ~0u);
}

TEST(Robustness, AbsurdTargetSizesThrow) {
  const int sizes[][2] = {{0, 1}, {1, 0}, {-5, 5}, {5, -5}, {kMaxTargetSize + 1, 1}, {1, kMaxTargetSize + 1},
                          {INT_MAX, INT_MAX}, {INT_MIN, 3}};
  for (const auto& s : sizes) {
    EXPECT_THROW(ColorTarget(s[0], s[1], 1), std::invalid_argument) << s[0] << "x" << s[1];
    EXPECT_THROW(DepthStencilTarget(s[0], s[1], 1), std::invalid_argument) << s[0] << "x" << s[1];
    EXPECT_THROW(SurfaceLayout(s[0], s[1], 4), std::invalid_argument);
  }
  for (int samples : {0, 3, 5, 16, -1, INT_MAX}) {
    EXPECT_THROW(ColorTarget(8, 8, samples), std::invalid_argument) << samples;
    EXPECT_THROW(DepthStencilTarget(8, 8, samples), std::invalid_argument) << samples;
  }
  EXPECT_NO_THROW(SurfaceLayout(kMaxTargetSize, kMaxTargetSize, 8));
}

TEST(Robustness, ExtremeButValidTargets) {
  Context ctx(2);
  PipelineState st;
  st.rasterizer.cull = CullMode::None;
  for (auto [w, h, S] : {std::tuple{1, 1, 8}, {kMaxTargetSize, 1, 1}, {1, kMaxTargetSize, 2}, {65, 1, 4}}) {
    ColorTarget target(w, h, S);
    DepthStencilTarget ds(w, h, S);
    clear_color(ctx, target, glm::vec4(0.0f));
    clear_depth_stencil(ctx, ds, 1.0f, 0);
    OcclusionQuery q;
    ctx.begin_query(q);
    draw(ctx, Framebuffer{&target, &ds}, st, Geometry::non_indexed(3), PositionVS{kFull}, ConstantPS{glm::vec4(1.0f)});
    ctx.end_query();
    EXPECT_EQ(ctx.query_result(q), uint64_t(w) * h * S) << w << "x" << h;
    const Image img = resolve(ctx, target);
    EXPECT_EQ(img.pixel(w - 1, h - 1)[0], 255);
    EXPECT_EQ(img.pixel(0, 0)[3], 255);
  }
}

TEST(Robustness, InvalidFramebuffersAndStatesThrow) {
  Context ctx(1);
  ColorTarget c1(8, 8, 1), c4(8, 8, 4), c9(8, 9, 1);
  DepthStencilTarget d1(8, 8, 1), d4(8, 8, 4);
  const PipelineState st;
  auto try_draw = [&](const Framebuffer& fb, const PipelineState& s) {
    draw(ctx, fb, s, Geometry::non_indexed(3), PositionVS{kFull}, ConstantPS{});
  };
  EXPECT_THROW(try_draw({&c1, &d4}, st), std::invalid_argument);
  EXPECT_THROW(try_draw({&c4, &d1}, st), std::invalid_argument);
  EXPECT_THROW(try_draw({&c9, &d1}, st), std::invalid_argument);
  EXPECT_THROW(try_draw({nullptr, nullptr}, st), std::invalid_argument);
  EXPECT_NO_THROW(try_draw({&c4, &d4}, st));
  EXPECT_NO_THROW(try_draw({nullptr, &d1}, st));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const Viewport bad_viewports[] = {
      {0, 0, 0, 0, 0.6f, 0.5f}, {0, 0, 0, 0, -0.1f, 1}, {0, 0, 0, 0, 0, 1.5f}, {0, 0, 0, 0, nan, 1},
      {0, 0, 0, 0, 0, nan},     {nan, 0, 8, 8, 0, 1},   {0, 1e9f, 8, 8, 0, 1}, {0, 0, 1e9f, 8, 0, 1},
      {0, 0, 8, std::numeric_limits<float>::infinity(), 0, 1},
  };
  for (const Viewport& vp : bad_viewports) {
    PipelineState s;
    s.viewport = vp;
    EXPECT_THROW(try_draw({&c1, nullptr}, s), std::invalid_argument)
        << vp.x << " " << vp.y << " " << vp.width << " " << vp.height << " " << vp.min_depth << " " << vp.max_depth;
  }
  ctx.flush();
}

TEST(Robustness, ZeroTriangleDraws) {
  Context ctx(2);
  ColorTarget target(16, 16, 2);
  clear_color(ctx, target, glm::vec4(0.0f));
  PipelineState st;
  st.rasterizer.cull = CullMode::None;
  const Framebuffer fb{&target, nullptr};
  for (uint32_t n : {0u, 1u, 2u}) draw(ctx, fb, st, Geometry::non_indexed(n), PositionVS{kFull}, ConstantPS{});
  draw(ctx, fb, st, Geometry{3, Geometry::IndexFormat::U16, nullptr, 0}, PositionVS{kFull}, ConstantPS{});
  const uint32_t two[] = {0, 1};
  draw(ctx, fb, st, Geometry::indexed(std::span<const uint32_t>(two), 3), PositionVS{kFull}, ConstantPS{});
  // Four vertices: one triangle, the fourth vertex ignored.
  const glm::vec4 four[4] = {kFull[0], kFull[1], kFull[2], {std::nanf(""), 0, 0, 1}};
  OcclusionQuery q;
  ctx.begin_query(q);
  draw(ctx, fb, st, Geometry::non_indexed(4), PositionVS{four}, ConstantPS{});
  ctx.end_query();
  EXPECT_EQ(ctx.query_result(q), 16u * 16 * 2);
  EXPECT_EQ(ctx.stats().triangles, 1u);
  // Flushing an empty frame, twice, is harmless.
  ctx.flush();
  ctx.flush();
}

// Random bit patterns as positions (NaN, Inf, denormals, huge, tiny w, negative w...): no
// crash, and nothing written outside the viewport and scissor.
TEST(Robustness, GarbagePositionsNeverEscapeTheScissor) {
  Context ctx(2);
  std::mt19937 rng(666);
  const int W = 90, H = 70;
  for (int round = 0; round < budget(8, 2); ++round) {
    const int S = 1 << (round % 4);
    ColorTarget target(W, H, S);
    clear_color(ctx, target, glm::vec4(0.0f));
    PipelineState st;
    st.rasterizer.cull = CullMode(round % 3);
    st.viewport = {float(rng() % 40) - 20, float(rng() % 40) - 20, float(16 + rng() % 100), float(16 + rng() % 100)};
    st.scissor = {true, int(rng() % 50) - 5, int(rng() % 50) - 5, int(rng() % 100), int(rng() % 100)};
    ctx.reset_stats();
    std::vector<glm::vec4> pos(3 * size_t(budget(30000, 3000)));
    auto garbage = [&]() {
      switch (rng() % 6) {
        case 0: return std::bit_cast<float>(uint32_t(rng()));                        // anything
        case 1: return std::bit_cast<float>(uint32_t(rng() & 0x807fffffu));          // denormal
        case 2: return float(std::uniform_real_distribution<double>(-3, 3)(rng));    // ordinary
        case 3: return float(std::ldexp(double(int32_t(rng())), int(rng() % 200) - 100));  // 2^-100 .. 2^131
        case 4: return (rng() & 1) ? 1e-30f : -1e-30f;
        default: return float(std::uniform_real_distribution<double>(-1e5, 1e5)(rng));
      }
    };
    for (glm::vec4& p : pos) p = {garbage(), garbage(), garbage(), garbage()};
    draw(ctx, Framebuffer{&target, nullptr}, st, Geometry::non_indexed(uint32_t(pos.size())), PositionVS{pos.data()},
         ConstantPS{glm::vec4(1.0f)});
    const std::vector<uint32_t> v = read_color(ctx, target);
    const PixelRect rect = writable_rect(st, W, H);
    int escaped = 0, written = 0;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x)
        for (int s = 0; s < S; ++s) {
          const uint32_t a = v[sample_index(W, S, x, y, s)];
          written += a != 0;
          if (a != 0 && !rect.contains(x, y)) ++escaped;
        }
    EXPECT_EQ(escaped, 0) << "round " << round;
    EXPECT_EQ(ctx.stats().triangles, pos.size() / 3);
  }
}

// The clipper's bound (triangle_setup.hpp, kMaxClipVertices): a plane adds at most one vertex to
// a convex polygon, but a polygon that rounding left non-convex can cross a plane many times. No
// triangle found (by a random and a hill-climbing search over near-degenerate triangles at the
// guard band's corners with w near 0) reaches more than kMaxClipVertices, so the bound is tested
// on clip_polygon directly with the polygons such rounding would make: zigzags across the plane.
TEST(Clipper, PolygonsBeyondTheBoundAreRefused) {
  const glm::vec4 plane(1, 0, 0, 0);  // x >= 0
  const int floats = 4 * (1 + kMaxVaryings);
  auto zigzag = [](int n) {  // vertices alternately inside (x = 1) and outside (x = -1)
    std::vector<detail::ClipVertex> p(n);
    for (int i = 0; i < n; ++i) {
      std::fill(std::begin(p[i].v), std::end(p[i].v), float(i));
      p[i].v[0] = i % 2 ? -1.0f : 1.0f;
      p[i].v[3] = 1.0f;
    }
    return p;
  };
  // On the heap with no slack: ASan sees a write past the last vertex.
  std::vector<detail::ClipVertex> out(detail::kMaxClipVertices);
  // n inside vertices and crossings: 6 -> 3 + 6 = 9 fits, 7 -> 4 + 6 = 10 and 8 -> 4 + 8 do not.
  EXPECT_EQ(detail::clip_polygon(plane, zigzag(6).data(), 6, out.data(), floats), 9);
  EXPECT_EQ(out[1].v[0], 0.0f);  // the first crossing, half way
  EXPECT_EQ(out[1].v[4], 0.5f);
  EXPECT_EQ(detail::clip_polygon(plane, zigzag(7).data(), 7, out.data(), floats), -1);
  EXPECT_EQ(detail::clip_polygon(plane, zigzag(8).data(), 8, out.data(), floats), -1);
  EXPECT_EQ(detail::clip_polygon(plane, zigzag(9).data(), 9, out.data(), floats), -1);
  // A convex polygon of kMaxClipVertices - 1 vertices cut off at one corner: exactly the bound.
  std::vector<detail::ClipVertex> convex(detail::kMaxClipVertices - 1);
  for (int i = 0; i < int(convex.size()); ++i) {
    const double a = 2 * 3.14159265358979 * i / convex.size();
    convex[i].v[0] = float(std::cos(a)) + 0.9f;  // vertex 4 (x = -0.1) alone outside
    convex[i].v[1] = float(std::sin(a));
    convex[i].v[3] = 1.0f;
  }
  EXPECT_EQ(detail::clip_polygon(plane, convex.data(), int(convex.size()), out.data(), 4), detail::kMaxClipVertices);
}

// Triangles built to stress the clipper's rounding: nearly degenerate, straddling the near plane
// with w close to 0 at a corner of the guard band, where every plane meets the polygon. None may
// crash or write past the clipper's buffers (run under ASan), each is drawn, dropped as outside,
// degenerate or non-finite, or counted in clip_overflow; the first is one that clips to exactly
// kMaxClipVertices vertices (found by search).
TEST(Clipper, AdversarialTrianglesAtTheGuardBandCorners) {
  Context ctx(2);
  const int W = 64, H = 64;
  ColorTarget target(W, H, 4);
  DepthStencilTarget depth(W, H, 4);
  PipelineState st;
  st.rasterizer.cull = CullMode::None;
  std::vector<glm::vec4> pos = {
      {0x1.bbep-26f, 0x1.bdp-26f, 0.0f, 0.0f},
      {0x1.f58bb2p-15f, 0x1.26dc9p-11f, 0x1.c28d78p-10f, 0x1.e9b14p-10f},
      {0x1.25e8e4p-13f, 0x1.fb8d38p-12f, 0x1.c1a07p-10f, 0x1.c1a07p-10f},
  };
  // The guard band's corners in NDC, as plan_draw computes them for this viewport.
  const float g = float(kGuardBand - 1), half = W * 0.5f;
  const float gmin = -g / half - 1.0f, gmax = g / half - 1.0f;
  std::mt19937 rng(2024);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::uniform_int_distribution<int> exponent(-40, 10);
  for (int i = 0; i < budget(60000, 6000); ++i) {
    // Vertex 0 at a corner of the guard band with w near 0 (on the near plane or just off it),
    // vertex 1 inside the view volume (so that the triangle is not trivially rejected), vertex 2
    // nearly on the line between them or near vertex 0.
    const float w = std::ldexp(unit(rng), exponent(rng));
    const glm::vec4 corner((i & 1 ? gmax : gmin) * w, (i & 2 ? gmax : gmin) * w, i & 4 ? w : 0.0f, w);
    const float scale = std::ldexp(1.0f, exponent(rng)), thin = std::ldexp(1.0f, exponent(rng) / 2 - 10);
    const glm::vec4 inside = glm::vec4(unit(rng), unit(rng), 0.5f + 0.5f * unit(rng), 1.0f) * scale;
    glm::vec4 jitter;
    for (int k = 0; k < 4; ++k) jitter[k] = unit(rng) * std::max(std::fabs(w), scale) * thin;
    const float t = i & 8 ? 0.5f + 0.5f * unit(rng) : std::ldexp(1.0f, exponent(rng) / 2 - 4);
    pos.push_back(corner + jitter);
    pos.push_back(inside);
    pos.push_back(corner + t * (inside - corner) - jitter * unit(rng));
  }
  std::vector<std::array<glm::vec4, 1>> varyings(pos.size());
  for (size_t i = 0; i < pos.size(); ++i) varyings[i][0] = glm::vec4(float(i % 7), 1.0f, -2.0f, 0.5f);
  clear_color(ctx, target, glm::vec4(0.0f));
  clear_depth_stencil(ctx, depth, 1.0f, 0);
  ctx.reset_stats();
  draw(ctx, Framebuffer{&target, &depth}, st, Geometry::non_indexed(uint32_t(pos.size())),
       ArrayVS<1>{pos.data(), varyings.data()}, VaryingPS{});
  ctx.flush();
  const DrawStats& s = ctx.stats();
  EXPECT_EQ(s.triangles, pos.size() / 3);
  EXPECT_GT(s.clipped, s.triangles / 4);  // the others: wholly outside (w < 0 half the time)
  EXPECT_LE(s.clip_overflow, s.clipped);
  RecordProperty("clip_overflow", std::to_string(s.clip_overflow));
}

// context.hpp, "The deferred frame": destroying a target or query that a pending frame refers to
// flushes that frame first. The doomed objects live on the heap, so that ASan reports any command
// that still reads or writes them after they are gone.
TEST(DeferredFrame, DestroyingATargetFlushesItsPendingFrameFirst) {
  Context ctx(2);
  PipelineState st;
  st.rasterizer.cull = CullMode::None;
  ColorTarget kept(64, 48, 4);
  auto depth = std::make_unique<DepthStencilTarget>(64, 48, 4);
  clear_color(ctx, kept, glm::vec4(1, 0, 0, 1));
  clear_depth_stencil(ctx, *depth, 1.0f, 0);
  ctx.reset_stats();
  draw(ctx, Framebuffer{&kept, depth.get()}, st, Geometry::non_indexed(3), PositionVS{kFull},
       ConstantPS{glm::vec4(0, 1, 0, 1)});
  depth.reset();
  // The draw ran before the depth target went: its effect on the color target is there (read
  // without a flush) and its counters are complete.
  EXPECT_EQ(ctx.stats().rasterized, 1u);
  int green = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x)
      for (int s = 0; s < 4; ++s) green += kept.sample(x, y, s) == rgba8(0, 255, 0, 255);
  EXPECT_EQ(green, 64 * 48 * 4);

  // A color target with a pending clear and draw, destroyed; then the context goes on.
  auto doomed = std::make_unique<ColorTarget>(64, 48, 4);
  clear_color(ctx, *doomed, glm::vec4(0, 0, 1, 1));
  draw(ctx, Framebuffer{doomed.get(), nullptr}, st, Geometry::non_indexed(3), PositionVS{kFull}, ConstantPS{});
  clear_color(ctx, kept, glm::vec4(0, 0, 1, 1));  // pending too: flushed with the doomed target's frame
  doomed.reset();
  EXPECT_EQ(kept.sample(63, 47, 3), rgba8(0, 0, 255, 255));
  draw(ctx, Framebuffer{&kept, nullptr}, st, Geometry::non_indexed(3), PositionVS{kFull}, ConstantPS{});
  EXPECT_EQ(resolve(ctx, kept).pixel(10, 10)[0], 255);

  // Moving a target with pending work runs it first: the moved-to target holds the result.
  ColorTarget source(64, 48, 4);
  clear_color(ctx, source, glm::vec4(0, 1, 1, 1));
  ColorTarget moved = std::move(source);
  EXPECT_EQ(moved.sample(5, 5, 0), rgba8(0, 255, 255, 255));
  clear_color(ctx, moved, glm::vec4(1, 1, 0, 1));
  moved = ColorTarget(64, 48, 4);  // assigning over a pending target runs its frame, then replaces it
  EXPECT_EQ(resolve(ctx, moved).pixel(5, 5)[0], 0);
}

TEST(DeferredFrame, DestroyingAQueryFlushesAndEndsIt) {
  Context ctx(2);
  PipelineState st;
  st.rasterizer.cull = CullMode::None;
  ColorTarget target(32, 32, 2);
  clear_color(ctx, target, glm::vec4(0.0f));
  // Pending, ended.
  auto query = std::make_unique<OcclusionQuery>();
  ctx.begin_query(*query);
  draw(ctx, Framebuffer{&target, nullptr}, st, Geometry::non_indexed(3), PositionVS{kFull}, ConstantPS{});
  ctx.end_query();
  query.reset();
  EXPECT_EQ(target.sample(31, 31, 1), rgba8(255, 255, 255, 255));
  // Pending and still active: destroying it ends it, later draws count into nothing.
  query = std::make_unique<OcclusionQuery>();
  ctx.begin_query(*query);
  draw(ctx, Framebuffer{&target, nullptr}, st, Geometry::non_indexed(3), PositionVS{kFull}, ConstantPS{});
  query.reset();
  EXPECT_EQ(ctx.active_query(), nullptr);
  draw(ctx, Framebuffer{&target, nullptr}, st, Geometry::non_indexed(3), PositionVS{kFull}, ConstantPS{});
  ctx.flush();
  // Active but nothing pending: the context's destructor must not touch it afterwards.
  OcclusionQuery survivor;
  {
    Context other(1);
    other.begin_query(survivor);
  }
  OcclusionQuery copy = survivor;
  (void)copy;
  // A query counting in one context and begun in another ends in the first.
  OcclusionQuery shared;
  ctx.begin_query(shared);
  draw(ctx, Framebuffer{&target, nullptr}, st, Geometry::non_indexed(3), PositionVS{kFull}, ConstantPS{});
  Context other(1);
  other.begin_query(shared);
  EXPECT_EQ(ctx.active_query(), nullptr);
  EXPECT_EQ(other.active_query(), &shared);
  other.end_query();
  EXPECT_EQ(other.query_result(shared), 0u);
}

// Recording a target in a second context runs the first context's pending frame on it first, so
// the frames apply in the order they were recorded.
TEST(DeferredFrame, ATargetIsPendingInOneContextAtATime) {
  Context first(1), second(2);
  PipelineState st;
  st.rasterizer.cull = CullMode::None;
  ColorTarget target(64, 64, 1);
  clear_color(first, target, glm::vec4(1, 0, 0, 1));
  draw(second, Framebuffer{&target, nullptr}, st, Geometry::non_indexed(3), PositionVS{kFull},
       ConstantPS{glm::vec4(0, 1, 0, 1)});
  second.flush();
  first.flush();  // nothing left: the clear ran when the draw was recorded, not now over it
  const Image image = resolve(first, target);
  EXPECT_EQ(image.pixel(7, 7)[0], 0);
  EXPECT_EQ(image.pixel(7, 7)[1], 255);
}

// A frame that alternates between targets of different tilings flushes by itself in between.
TEST(Robustness, InterleavedTargetsOfDifferentLayouts) {
  Context ctx(2);
  ColorTarget a(64, 64, 1), b(40, 24, 4);
  const ViewportMap ma(Viewport{}, 64, 64);
  PipelineState st;
  st.rasterizer.cull = CullMode::None;
  clear_color(ctx, a, glm::vec4(0.0f));
  clear_color(ctx, b, glm::vec4(0.0f));
  draw(ctx, Framebuffer{&a, nullptr}, st, Geometry::non_indexed(3), PositionVS{kFull}, ConstantPS{{1, 0, 0, 1}});
  draw(ctx, Framebuffer{&b, nullptr}, st, Geometry::non_indexed(3), PositionVS{kFull}, ConstantPS{{0, 1, 0, 1}});
  const glm::vec4 half[3] = {ma.clip_from_screen(0, 0), ma.clip_from_screen(64, 0), ma.clip_from_screen(0, 64)};
  draw(ctx, Framebuffer{&a, nullptr}, st, Geometry::non_indexed(3), PositionVS{half}, ConstantPS{{0, 0, 1, 1}});
  ctx.flush();
  EXPECT_EQ(a.sample(2, 2, 0), rgba8(0, 0, 255, 255));
  EXPECT_EQ(a.sample(60, 60, 0), rgba8(255, 0, 0, 255));
  EXPECT_EQ(b.sample(39, 23, 3), rgba8(0, 255, 0, 255));
}

// The front end's bins keep their streams from one tiling to the next (ChunkBins::reset): draws
// after a smaller tiling and back find every stream empty, the tiles the smaller one did not have
// included.
TEST(Robustness, BinsOfAnEarlierTilingLeaveNoRecords) {
  Context ctx(2);
  ColorTarget big(256, 256, 1), small(64, 64, 1);  // 16 tiles, then 1
  PipelineState st;
  st.rasterizer.cull = CullMode::None;
  const auto fill = [&](ColorTarget& target, const glm::vec4 (&triangle)[3], glm::vec4 color) {
    clear_color(ctx, target, glm::vec4(0.0f));
    draw(ctx, Framebuffer{&target, nullptr}, st, Geometry::non_indexed(3), PositionVS{triangle}, ConstantPS{color});
    ctx.flush();
  };
  fill(big, kFull, {1, 0, 0, 1});  // every tile binned
  EXPECT_EQ(big.sample(250, 250, 0), rgba8(255, 0, 0, 255));
  fill(small, kFull, {0, 1, 0, 1});
  const ViewportMap map(Viewport{}, 256, 256);
  const glm::vec4 corner[3] = {map.clip_from_screen(0, 0), map.clip_from_screen(32, 0), map.clip_from_screen(0, 32)};
  fill(big, corner, {0, 0, 1, 1});  // the first tile only
  EXPECT_EQ(big.sample(2, 2, 0), rgba8(0, 0, 255, 255));
  EXPECT_EQ(big.sample(250, 250, 0), rgba8(0, 0, 0, 0));
  EXPECT_EQ(big.sample(100, 100, 0), rgba8(0, 0, 0, 0));
  fill(big, kFull, {0, 1, 0, 1});  // every tile again, each stream from its start
  EXPECT_EQ(big.sample(250, 250, 0), rgba8(0, 255, 0, 255));
  EXPECT_EQ(big.sample(100, 100, 0), rgba8(0, 255, 0, 255));
}

/// Triangle t covers the center sample of pixel (5, 7) of a 32x32 target when t % 16384 == 0, and
/// lies off-screen otherwise (computed on the fly: millions of triangles, no memory).
struct SparseTinyVS {
  static constexpr int kVaryings = 1;
  static constexpr uint32_t kEvery = 16384;
  void operator()(uint32_t i, VertexOutput<1>& out) const {
    const float x = (5.5f / 32) * 2 - 1, y = 1 - (7.5f / 32) * 2, e = 1.0f / 256;
    const int k = i % 3;
    const float off = (i / 3) % kEvery == 0 ? 0.0f : 10.0f;
    out.position = {x + off + (k == 1 ? 2 * e : -e), y + (k == 2 ? -2 * e : e), 0.5f, 1.0f};
    out.varyings[0] = glm::vec4(0.0f);
  }
};

// Records beyond the pending frame's budget make the next draw flush the frame first; the
// result is the same as one frame's (additive blending counts every visible triangle).
TEST(Robustness, DrawsBeyondThePendingRecordBudget) {
  ContextOptions options;
  options.threads = 2;
  options.max_pending_record_bytes = 1;  // whatever a draw binned is over it
  Context ctx(options);
  const int W = 32, H = 32;
  ColorTarget target(W, H, 1);
  PipelineState st;
  st.rasterizer.cull = CullMode::None;
  st.blend.enable = true;
  st.blend.src = st.blend.dst = BlendFactor::One;
  clear_color(ctx, target, glm::vec4(0.0f));
  const Framebuffer fb{&target, nullptr};
  draw(ctx, fb, st, Geometry::non_indexed(3), PositionVS{kFull}, ConstantPS{{1 / 255.0f, 0, 0, 0}});
  // Three draws of two parts each, mostly off screen: every part but the first draw's flushes
  // what came before it, in the middle of a draw too.
  const uint32_t n = kTrianglesPerPart + 7;
  draw(ctx, fb, st, Geometry::non_indexed(3 * n), SparseTinyVS{}, ConstantPS{{0, 1 / 255.0f, 0, 0}});
  draw(ctx, fb, st, Geometry::non_indexed(3 * n), SparseTinyVS{}, ConstantPS{{0, 0, 1 / 255.0f, 0}});
  draw(ctx, fb, st, Geometry::non_indexed(3 * n), SparseTinyVS{}, ConstantPS{{0, 0, 0, 1 / 255.0f}});
  ctx.flush();
  EXPECT_EQ(ctx.flush_count(), 7u);  // 6 before parts, 1 at the end
  const int visible = int((n + SparseTinyVS::kEvery - 1) / SparseTinyVS::kEvery);
  EXPECT_EQ(target.sample(5, 7, 0), rgba8(1, visible, visible, visible));
  EXPECT_EQ(target.sample(6, 7, 0), rgba8(1, 0, 0, 0));
  EXPECT_EQ(ctx.stats().triangles, 1 + 3 * uint64_t(n));
}

// kVaryings = 0 is documented as valid (draw.hpp).
TEST(Robustness, ZeroVaryingVertexFunctor) {
  Context ctx(1);
  ColorTarget target(8, 8, 2);
  clear_color(ctx, target, glm::vec4(0.0f));
  PipelineState st;
  st.rasterizer.cull = CullMode::None;
  const uint16_t idx[3] = {0, 1, 2};
  draw(ctx, Framebuffer{&target, nullptr}, st, Geometry::non_indexed(3), ArrayVS<0>{kFull, nullptr}, ConstantPS{});
  draw(ctx, Framebuffer{&target, nullptr}, st, Geometry::indexed(std::span<const uint16_t>(idx), 3), ArrayVS<0>{kFull, nullptr},
       ConstantPS{});
  ctx.flush();
  EXPECT_EQ(target.sample(7, 7, 1), ~0u);
  EXPECT_EQ(ctx.stats().rasterized, 2u);
}

}  // namespace
}  // namespace luxel::rasterizer::test
