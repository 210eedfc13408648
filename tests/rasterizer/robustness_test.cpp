// Robustness: bad input is dropped or rejected with std::invalid_argument, never crashes, and
// never writes outside what a draw may write.

#include "coverage_support.hpp"
#include "raster_support.hpp"

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
