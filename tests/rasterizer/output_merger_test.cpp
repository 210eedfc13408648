// Depth, stencil, alpha test, blending and sRGB against the scalar D3D9 reference of
// pipeline_support.hpp (random scenes, every sample compared), plus literal truth tables for the
// pieces, so that the reference itself is pinned to the D3D9 documentation.

#include "pipeline_support.hpp"
#include "raster_support.hpp"

#include "luxel/rasterizer/detail/command_queue.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace luxel::rasterizer::test {
namespace {

TEST(OutputMerger, RandomScenesMatchTheScalarReference) {
  const int scenes = budget(800, 60);
  Context ctx(2);
  int failures = 0;
  uint64_t ambiguous = 0, samples = 0, counted = 0;
  for (int i = 0; i < scenes && failures < 3; ++i) {
    const int S = (i % 5 == 4) ? 8 : (i % 5 == 3) ? 2 : (i % 2 ? 4 : 1);
    const Scene scene = random_scene(1000 + i, S);
    const SceneOutput out = render_scene(ctx, scene);
    const SceneReference ref = reference_scene(scene);
    std::vector<std::string> messages;
    const int bad = compare_scene(scene, out, ref, messages, 8);
    ambiguous += ref.ambiguous_samples;
    samples += ref.color.size();
    counted += ref.query;
    if (bad) {
      ++failures;
      ADD_FAILURE() << "scene " << i << " (seed " << 1000 + i << "): " << bad << " mismatches\n"
                    << join(messages) << scene.describe();
    }
  }
  // The reference keeps two candidates only near rounding boundaries: that must stay rare, or
  // the comparison would say little.
  EXPECT_LT(ambiguous, samples / 50) << ambiguous << " of " << samples << " samples ambiguous";
  EXPECT_GT(counted, 0u);
}

// A draw whose records exceed the queue's budget is recorded in parts with flushes in between
// (ContextOptions::max_pending_record_bytes, kTrianglesPerPart): order-dependent blending,
// stencil counting and the occlusion query must come out as if it were one.
TEST(OutputMerger, DrawLargerThanTheQueueMatchesTheReference) {
  Scene scene;
  scene.width = 160;
  scene.height = 120;
  scene.samples = 4;
  scene.clear_color = {0.2f, 0.4f, 0.6f, 0.8f};
  SceneDraw d;
  d.counted = true;
  d.state.viewport = {0, 0, 256, 256};  // a power of two: screen points are exact in NDC
  d.state.rasterizer.cull = CullMode::None;
  d.state.depth_stencil.depth_func = CompareFunc::LessEqual;
  d.state.depth_stencil.stencil_enable = true;
  d.state.depth_stencil.front.pass = StencilOp::Incr;
  d.state.depth_stencil.back.pass = StencilOp::Incr;
  d.state.blend.enable = true;
  d.state.blend.src = BlendFactor::SrcAlpha;
  d.state.blend.dst = BlendFactor::InvSrcAlpha;
  d.shade.allow_nan = false;
  d.shade.seed = 7;
  std::mt19937 rng(2024);
  static constexpr float kZ[] = {0.125f, 0.25f, 0.5f, 0.75f};
  const int n = static_cast<int>(kTrianglesPerPart) * 2 + 3001;
  for (int i = 0; i < n; ++i) {
    // Triangles of a few pixels on the 1/16 pixel grid, anywhere on the target.
    const double x = int(rng() % (160 * 16)) / 16.0, y = int(rng() % (120 * 16)) / 16.0;
    auto leg = [&] { return int(rng() % 49) / 16.0 - 1.5; };
    d.triangles.push_back({{{x, y}, {x + leg(), y + leg()}, {x + leg(), y + leg()}}, kZ[rng() % 4]});
  }
  scene.draws.push_back(std::move(d));
  ContextOptions options;
  options.threads = 2;
  options.max_pending_record_bytes = 1 << 20;  // less than a part's records
  Context ctx(options);
  const SceneOutput out = render_scene(ctx, scene);
  EXPECT_GE(ctx.flush_count(), 3u);  // in the draw, twice, and at the end
  const SceneReference ref = reference_scene(scene);
  std::vector<std::string> messages;
  EXPECT_EQ(compare_scene(scene, out, ref, messages, 8), 0) << join(messages);
  EXPECT_GT(ref.query, uint64_t(n));
}

// --- Literal truth tables (D3D9 documentation) --------------------------------------------------

Scene one_pixel_scene() {
  Scene s;
  s.width = 4;
  s.height = 4;
  s.samples = 1;
  return s;
}

/// A draw of one triangle covering the whole 4x4 target at constant depth z.
SceneDraw full_draw(float z) {
  SceneDraw d;
  d.state.viewport = {0, 0, 4, 4};
  d.state.rasterizer.cull = CullMode::None;
  d.shade.allow_nan = false;
  d.triangles.push_back({{{-1, -1}, {12, -1}, {-1, 12}}, z});
  return d;
}

TEST(OutputMerger, DepthCompareTruthTable) {
  // Rows: func; columns: incoming depth less than / equal to / greater than the stored 0.5.
  const struct {
    CompareFunc f;
    bool lt, eq, gt;
  } table[] = {{CompareFunc::Never, 0, 0, 0},     {CompareFunc::Less, 1, 0, 0},      {CompareFunc::Equal, 0, 1, 0},
               {CompareFunc::LessEqual, 1, 1, 0}, {CompareFunc::Greater, 0, 0, 1},   {CompareFunc::NotEqual, 1, 0, 1},
               {CompareFunc::GreaterEqual, 0, 1, 1}, {CompareFunc::Always, 1, 1, 1}};
  Context ctx(1);
  for (const auto& row : table)
    for (bool write : {false, true})
      for (int rel = 0; rel < 3; ++rel) {
        const float z = rel == 0 ? 0.25f : rel == 1 ? 0.5f : 0.75f;
        const bool pass = rel == 0 ? row.lt : rel == 1 ? row.eq : row.gt;
        Scene s = one_pixel_scene();
        s.clear_depth = 0.5f;
        SceneDraw d = full_draw(z);
        d.state.depth_stencil.depth_func = row.f;
        d.state.depth_stencil.depth_write = write;
        d.counted = true;
        s.draws.push_back(d);
        const SceneOutput out = render_scene(ctx, s);
        SCOPED_TRACE(testing::Message() << "func " << int(row.f) << " write " << write << " z " << z);
        EXPECT_EQ(out.query, pass ? 16u : 0u);
        EXPECT_EQ(out.depth[0], pass && write ? z : 0.5f);
      }
}

TEST(OutputMerger, DepthDisabledNeitherTestsNorWrites) {
  Context ctx(1);
  Scene s = one_pixel_scene();
  s.clear_depth = 0.25f;
  SceneDraw d = full_draw(0.75f);
  d.state.depth_stencil.depth_enable = false;  // D3D9 ZENABLE = FALSE, even with ZWRITEENABLE
  d.state.depth_stencil.depth_write = true;
  d.state.depth_stencil.depth_func = CompareFunc::Never;
  d.counted = true;
  s.draws.push_back(d);
  const SceneOutput out = render_scene(ctx, s);
  EXPECT_EQ(out.query, 16u);
  EXPECT_EQ(out.depth[5], 0.25f);
}

TEST(OutputMerger, StencilOpTruthTable) {
  struct Row {
    StencilOp op;
    uint8_t v, ref, expect;
  };
  const Row rows[] = {
      {StencilOp::Keep, 0x37, 0x5a, 0x37},    {StencilOp::Zero, 0x37, 0x5a, 0x00},    {StencilOp::Replace, 0x37, 0x5a, 0x5a},
      {StencilOp::IncrSat, 0x37, 0, 0x38},    {StencilOp::IncrSat, 0xff, 0, 0xff},    {StencilOp::DecrSat, 0x37, 0, 0x36},
      {StencilOp::DecrSat, 0x00, 0, 0x00},    {StencilOp::Invert, 0x5a, 0, 0xa5},     {StencilOp::Incr, 0xff, 0, 0x00},
      {StencilOp::Incr, 0x7f, 0, 0x80},       {StencilOp::Decr, 0x00, 0, 0xff},       {StencilOp::Decr, 0x80, 0, 0x7f},
  };
  Context ctx(1);
  for (const Row& r : rows)
    for (int stage = 0; stage < 3; ++stage)  // fail, depth fail, pass
      for (uint8_t write_mask : {uint8_t(0xff), uint8_t(0x0f)}) {
        Scene s = one_pixel_scene();
        s.clear_stencil = r.v;
        s.clear_depth = 0.5f;
        SceneDraw d = full_draw(stage == 1 ? 0.75f : 0.25f);  // depth fails only in stage 1
        DepthStencilState& ds = d.state.depth_stencil;
        ds.depth_func = CompareFunc::Less;
        ds.stencil_enable = true;
        ds.stencil_ref = r.ref;
        ds.stencil_write_mask = write_mask;
        ds.front.func = stage == 0 ? CompareFunc::Never : CompareFunc::Always;
        ds.front.fail = stage == 0 ? r.op : StencilOp::Keep;
        ds.front.depth_fail = stage == 1 ? r.op : StencilOp::Keep;
        ds.front.pass = stage == 2 ? r.op : StencilOp::Keep;
        s.draws.push_back(d);
        const SceneOutput out = render_scene(ctx, s);
        const uint8_t expect = uint8_t((r.v & ~write_mask) | (r.expect & write_mask));
        EXPECT_EQ(int(out.stencil[0]), int(expect))
            << "op " << int(r.op) << " on 0x" << std::hex << int(r.v) << " stage " << stage << " mask " << int(write_mask);
      }
}

TEST(OutputMerger, StencilCompareUsesMaskedReferenceOnTheLeft) {
  // D3D9: pass when (ref & mask) func (stencil & mask).
  Context ctx(1);
  const struct {
    CompareFunc f;
    uint8_t ref, mask, stored;
    bool pass;
  } rows[] = {
      {CompareFunc::Less, 0x10, 0xff, 0x20, true},      {CompareFunc::Less, 0x20, 0xff, 0x10, false},
      {CompareFunc::Greater, 0x20, 0xff, 0x10, true},   {CompareFunc::Equal, 0x1f, 0x0f, 0xaf, true},
      {CompareFunc::Equal, 0x1f, 0xff, 0xaf, false},    {CompareFunc::LessEqual, 0xf3, 0x0f, 0x03, true},
      {CompareFunc::GreaterEqual, 0x01, 0xf0, 0x0f, true}, {CompareFunc::NotEqual, 0x80, 0x7f, 0x00, false},
  };
  for (const auto& r : rows) {
    Scene s = one_pixel_scene();
    s.clear_stencil = r.stored;
    SceneDraw d = full_draw(0.5f);
    DepthStencilState& ds = d.state.depth_stencil;
    ds.depth_enable = false;
    ds.stencil_enable = true;
    ds.stencil_ref = r.ref;
    ds.stencil_read_mask = r.mask;
    ds.front.func = r.f;
    d.counted = true;
    s.draws.push_back(d);
    EXPECT_EQ(render_scene(ctx, s).query, r.pass ? 16u : 0u)
        << "func " << int(r.f) << " ref " << int(r.ref) << " mask " << int(r.mask) << " stored " << int(r.stored);
  }
}

TEST(OutputMerger, TwoSidedStencilPicksTheFaceByWinding) {
  Context ctx(1);
  for (bool front_ccw : {false, true})
    for (bool clockwise : {false, true}) {
      Scene s = one_pixel_scene();
      SceneDraw d = full_draw(0.5f);
      if (!clockwise) std::swap(d.triangles[0].screen[1], d.triangles[0].screen[2]);
      d.state.rasterizer.front_counter_clockwise = front_ccw;
      DepthStencilState& ds = d.state.depth_stencil;
      ds.stencil_enable = true;
      ds.two_sided_stencil = true;
      ds.stencil_ref = 7;
      ds.front.pass = StencilOp::Replace;
      ds.back.pass = StencilOp::Invert;
      s.draws.push_back(d);
      const bool front = clockwise != front_ccw;
      EXPECT_EQ(int(render_scene(ctx, s).stencil[0]), front ? 7 : 0xff)
          << "front_ccw " << front_ccw << " clockwise " << clockwise;
    }
}

struct AlphaPS {
  static constexpr bool kCanDiscard = false, kWritesDepth = false;
  float alpha;
  void operator()(const PixelInput<1>&, PixelOutput& out) const {
    out.color = {simd::Float(1.0f), simd::Float(1.0f), simd::Float(1.0f), simd::Float(alpha)};
  }
};

TEST(OutputMerger, AlphaTestTruthTable) {
  Context ctx(1);
  for (int f = 0; f < 8; ++f)
    for (int a : {0, 99, 100, 101, 255})
      for (uint8_t ref : {uint8_t(0), uint8_t(100), uint8_t(255)}) {
        ColorTarget target(4, 4, 1);
        clear_color(ctx, target, glm::vec4(0.0f));
        PipelineState st;
        st.rasterizer.cull = CullMode::None;
        st.alpha_test = {true, CompareFunc(f), ref};
        const ViewportMap map(st.viewport, 4, 4);
        const glm::vec4 c[3] = {map.clip_from_screen(-1, -1), map.clip_from_screen(12, -1), map.clip_from_screen(-1, 12)};
        OcclusionQuery q;
        ctx.begin_query(q);
        draw(ctx, Framebuffer{&target, nullptr}, st, Geometry::non_indexed(3), PositionVS{c}, AlphaPS{a / 255.0f});
        ctx.end_query();
        const bool pass = (f == 1 && a < ref) || (f == 2 && a == ref) || (f == 3 && a <= ref) || (f == 4 && a > ref) ||
                          (f == 5 && a != ref) || (f == 6 && a >= ref) || f == 7;
        EXPECT_EQ(ctx.query_result(q), pass ? 16u : 0u) << "func " << f << " alpha " << a << " ref " << int(ref);
        EXPECT_EQ(target.sample(1, 1, 0), pass ? rgba8(255, 255, 255, a) : 0u);
      }
}

/// Writes src over a cleared dst with one BlendState, returns the packed result.
uint32_t blend_once(Context& ctx, const BlendState& b, glm::vec4 dst, glm::vec4 src) {
  ColorTarget target(4, 4, 1);
  clear_color(ctx, target, dst);
  PipelineState st;
  st.rasterizer.cull = CullMode::None;
  st.blend = b;
  const ViewportMap map(st.viewport, 4, 4);
  const glm::vec4 c[3] = {map.clip_from_screen(-1, -1), map.clip_from_screen(12, -1), map.clip_from_screen(-1, 12)};
  draw(ctx, Framebuffer{&target, nullptr}, st, Geometry::non_indexed(3), PositionVS{c}, ConstantPS{src});
  ctx.flush();
  return target.sample(2, 2, 0);
}

TEST(OutputMerger, BlendLiterals) {
  Context ctx(1);
  const glm::vec4 dst(153 / 255.0f, 51 / 255.0f, 204 / 255.0f, 102 / 255.0f);  // .6 .2 .8 .4
  const glm::vec4 src(51 / 255.0f, 204 / 255.0f, 102 / 255.0f, 153 / 255.0f);  // .2 .8 .4 .6
  BlendState b;
  b.enable = true;
  // Classic alpha blending: src * .6 + dst * .4 (alpha too).
  b.src = BlendFactor::SrcAlpha;
  b.dst = BlendFactor::InvSrcAlpha;
  EXPECT_EQ(blend_once(ctx, b, dst, src), rgba8(92, 143, 143, 133));  // .36 .56 .56 .52 -> 91.8 142.8 142.8 132.6
  // Min/max ignore the factors (D3DBLENDOP_MIN/MAX).
  b.src = BlendFactor::Zero;
  b.dst = BlendFactor::Zero;
  b.op = BlendOp::Min;
  EXPECT_EQ(blend_once(ctx, b, dst, src), rgba8(51, 51, 102, 102));
  b.op = BlendOp::Max;
  EXPECT_EQ(blend_once(ctx, b, dst, src), rgba8(153, 204, 204, 153));
  // Subtract and reverse subtract clamp at 0.
  b.src = b.dst = BlendFactor::One;
  b.op = BlendOp::Subtract;
  EXPECT_EQ(blend_once(ctx, b, dst, src), rgba8(0, 153, 0, 51));
  b.op = BlendOp::RevSubtract;
  EXPECT_EQ(blend_once(ctx, b, dst, src), rgba8(102, 0, 102, 0));
  // Add clamps at 1.
  b.op = BlendOp::Add;
  EXPECT_EQ(blend_once(ctx, b, dst, src), rgba8(204, 255, 255, 255));
  // SrcAlphaSat: f = min(As, 1 - Ad) = min(.6, .6) = .6 on RGB, 1 on alpha; dst * 0.
  b.src = BlendFactor::SrcAlphaSat;
  b.dst = BlendFactor::Zero;
  EXPECT_EQ(blend_once(ctx, b, dst, src), rgba8(31, 122, 61, 153));  // 30.6 122.4 61.2 153
  // Constant blend factor and its inverse.
  b.blend_factor = {51 / 255.0f, 102 / 255.0f, 0.0f, 1.0f};  // .2 .4 0 1
  b.src = BlendFactor::BlendFactor;
  b.dst = BlendFactor::InvBlendFactor;
  EXPECT_EQ(blend_once(ctx, b, dst, src), rgba8(133, 112, 204, 153));  // .52 .44 .8 .6
  // Separate alpha: RGB keep dst, alpha takes src.
  b.src = BlendFactor::Zero;
  b.dst = BlendFactor::One;
  b.separate_alpha = true;
  b.src_alpha = BlendFactor::One;
  b.dst_alpha = BlendFactor::Zero;
  EXPECT_EQ(blend_once(ctx, b, dst, src), rgba8(153, 51, 204, 153));
  // Write mask: only green and alpha.
  BlendState m;
  m.write_mask = kWriteGreen | kWriteAlpha;
  EXPECT_EQ(blend_once(ctx, m, dst, src), rgba8(153, 204, 204, 153));
}

TEST(OutputMerger, SrgbWriteEncodesAfterBlendingInLinearSpace) {
  Context ctx(1);
  BlendState b;
  b.srgb_write = true;
  // Linear 0.5 encodes to 0.7354 -> 187.5 -> 188; alpha stays linear (127.5 -> 128).
  EXPECT_EQ(blend_once(ctx, b, glm::vec4(0.0f), glm::vec4(0.5f)), rgba8(188, 188, 188, 128));
  // Half-and-half of black over white blends the decoded values: linear 0.5 -> 188, not 128.
  b.enable = true;
  b.src = BlendFactor::SrcAlpha;
  b.dst = BlendFactor::InvSrcAlpha;
  EXPECT_EQ(blend_once(ctx, b, glm::vec4(1.0f), glm::vec4(0, 0, 0, 0.5f)), rgba8(188, 188, 188, 191));
  // Adding nothing leaves an sRGB value unchanged (decode then encode round-trips every byte).
  b.src = BlendFactor::Zero;
  b.dst = BlendFactor::One;
  for (int v = 0; v < 256; v += 5) {
    const float f = v / 255.0f;
    EXPECT_EQ(blend_once(ctx, b, glm::vec4(f, f, f, f), glm::vec4(0.3f)), rgba8(v, v, v, v)) << v;
  }
}

// Depth of a sloped triangle is interpolated per sample (at the sample positions), linearly in
// screen space, with D3D9 slope-scaled bias, and clamped to the viewport depth range.
TEST(OutputMerger, DepthInterpolatedAtSamplePositions) {
  Context ctx(2);
  const int W = 64, H = 64;
  for (int S : {1, 4, 8})
    for (float slope_bias : {0.0f, 0.5f}) {
      DepthStencilTarget ds(W, H, S);
      clear_depth_stencil(ctx, ds, 1.0f, 0);
      PipelineState st;
      st.rasterizer.cull = CullMode::None;
      st.viewport.min_depth = 0.125f;
      st.viewport.max_depth = 0.875f;
      st.depth_stencil.depth_func = CompareFunc::Always;
      st.rasterizer.depth_bias = 0.01f;
      st.rasterizer.slope_scaled_depth_bias = slope_bias;
      const ViewportMap map(st.viewport, W, H);
      const glm::dvec2 v[3] = {{-3.5, 2.25}, {62, 10.5}, {20.75, 66}};
      const float nz[3] = {0.0f, 1.0f, 0.5f};
      const glm::vec4 c[3] = {map.clip_from_screen(v[0].x, v[0].y, nz[0]), map.clip_from_screen(v[1].x, v[1].y, nz[1]),
                              map.clip_from_screen(v[2].x, v[2].y, nz[2])};
      draw(ctx, Framebuffer{nullptr, &ds}, st, Geometry::non_indexed(3), PositionVS{c}, ConstantPS{});
      ctx.flush();
      // Plane through the (exactly snapped) vertices, in double.
      double z[3];
      for (int k = 0; k < 3; ++k) z[k] = 0.125 + nz[k] * 0.75;
      const double det = (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[2].x - v[0].x) * (v[1].y - v[0].y);
      const double dzdx = ((z[1] - z[0]) * (v[2].y - v[0].y) - (z[2] - z[0]) * (v[1].y - v[0].y)) / det;
      const double dzdy = ((z[2] - z[0]) * (v[1].x - v[0].x) - (z[1] - z[0]) * (v[2].x - v[0].x)) / det;
      const double bias = 0.01 + slope_bias * std::max(std::abs(dzdx), std::abs(dzdy));
      const RefPrimitive p = make_exact_primitive(v, CullMode::None);
      const auto pattern = d3d_pattern(S);
      double worst = 0;
      int clamped = 0;
      for_each_sample(p, {0, 0, W, H}, S, [&](int x, int y, int s, Cover) {
        const double sx = x + (128 + 16 * pattern[s].x) / 256.0, sy = y + (128 + 16 * pattern[s].y) / 256.0;
        const double raw = z[0] + dzdx * (sx - v[0].x) + dzdy * (sy - v[0].y) + bias;
        const double expect = std::clamp(raw, 0.125, 0.875);
        clamped += raw > 0.875;
        worst = std::max(worst, std::abs(ds.depth(x, y, s) - expect));
      });
      // float evaluation of a plane with |z| <= 1 over 100 pixels: a few ulps of 1.
      EXPECT_LT(worst, 4e-7) << S << " samples, slope bias " << slope_bias;
      EXPECT_GT(clamped, 0) << "test setup: the bias should push some samples past max_depth";
    }
}

// A pixel functor that declares itself trivial (draw.hpp) is also run on stamps that early depth
// left without a live sample: it must write exactly what the branching path writes, and count
// the same samples. Hundreds of small triangles at random depths, 4 samples, depth test Less.
struct TrivialVaryingPS : VaryingPS {
  static constexpr bool kTrivial = true;
};

TEST(EarlyDepth, TrivialPixelFunctorWritesWhatTheBranchingPathWrites) {
  const int W = 96, H = 64, S = 4, kTriangles = 3000;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<glm::vec4> positions;
  std::vector<std::array<glm::vec4, 1>> colors;
  for (int t = 0; t < kTriangles; ++t) {
    const float cx = unit(rng) * 2 - 1, cy = unit(rng) * 2 - 1, z = unit(rng), r = 0.02f + 0.05f * unit(rng);
    const glm::vec4 color(unit(rng), unit(rng), unit(rng), 1.0f);
    for (int k = 0; k < 3; ++k) {
      const float angle = unit(rng) * 6.2831853f;
      positions.push_back({cx + r * std::cos(angle), cy + r * std::sin(angle), z, 1.0f});
      colors.push_back({color});
    }
  }
  PipelineState st;
  st.rasterizer.cull = CullMode::None;
  st.depth_stencil.depth_enable = true;
  st.depth_stencil.depth_func = CompareFunc::Less;
  struct Result {
    std::vector<uint32_t> color;
    std::vector<float> depth;
    uint64_t passed = 0, shaded = 0;  // occlusion count, pixel functor invocations
  };
  auto render = [&](auto pixel_shader) {
    Context ctx(2);
    ColorTarget target(W, H, S);
    DepthStencilTarget ds(W, H, S);
    clear_color(ctx, target, {0, 0, 0, 1});
    clear_depth(ctx, ds, 1.0f);
    ctx.reset_stats();
    OcclusionQuery q;
    ctx.begin_query(q);
    draw(ctx, Framebuffer{&target, &ds}, st, Geometry::non_indexed(uint32_t(positions.size())),
         ArrayVS<1>{positions.data(), colors.data()}, pixel_shader);
    ctx.end_query();
    Result r;
    r.color = read_color(ctx, target);
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x)
        for (int s = 0; s < S; ++s) r.depth.push_back(ds.depth(x, y, s));
    r.passed = ctx.query_result(q);
    r.shaded = ctx.stats().stamps_shaded;
    return r;
  };
  const Result branching = render(VaryingPS{}), trivial = render(TrivialVaryingPS{});
  EXPECT_EQ(trivial.color, branching.color);
  EXPECT_EQ(trivial.depth, branching.depth);
  EXPECT_EQ(trivial.passed, branching.passed);
  // The scene is deep enough that early depth kills whole stamps, which only the trivial
  // functor still runs on.
  EXPECT_GT(trivial.shaded, branching.shaded);
  EXPECT_GT(branching.passed, 0u);
}

}  // namespace
}  // namespace luxel::rasterizer::test
