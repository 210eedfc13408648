// Determinism: every scene of this suite renders to identical bytes (every sample of color,
// depth and stencil), identical occlusion counts and identical stats with 1, 2, 3 and 8 threads.
// (The frame-level built-in scenes are checked in tests/frame/determinism_test.cpp.)

#include "coverage_support.hpp"
#include "mesh_support.hpp"
#include "pipeline_support.hpp"
#include "raster_support.hpp"

#include "luxel/rasterizer/limits.hpp"
#include "luxel/rasterizer/texture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <random>

namespace luxel::rasterizer::test {
namespace {

/// What a scene produced: bytes to compare, and a name for messages.
struct Output {
  std::vector<uint8_t> bytes;
  std::vector<uint8_t> samples;  ///< the same without the stats, which depend on the stamp size (ISA)
  void add(const void* p, size_t n) {
    const auto* b = static_cast<const uint8_t*>(p);
    bytes.insert(bytes.end(), b, b + n);
    samples.insert(samples.end(), b, b + n);
  }
  template <class T>
  void add(const std::vector<T>& v) {
    add(v.data(), v.size() * sizeof(T));
  }
  void add_stats(const DrawStats& s) {
    const auto* b = reinterpret_cast<const uint8_t*>(&s);
    bytes.insert(bytes.end(), b, b + sizeof(s));
  }
};

using SceneFn = std::function<void(Context&, Output&)>;

void coverage_scene(Context& ctx, Output& out) {
  for (const CoverageConfig& base : coverage_configs(false))
    for (int S : {1, 4, 8}) {
      TriangleGenerator gen(uint32_t(S * 100 + base.width), base);
      ColorTarget target(base.width, base.height, S);
      for (int b = 0; b < 2; ++b) {
        CoverageConfig cfg = base;
        cfg.state.rasterizer.cull = CullMode(b % 3);
        std::vector<TestTriangle> batch;
        for (int k = 0; k < 32; ++k) batch.push_back(gen.random());
        ctx.reset_stats();
        draw_coverage_batch(ctx, target, cfg, batch, b % 2 ? BatchMode::LastWins : BatchMode::Bits);
        out.add(read_color(ctx, target));
        out.add_stats(ctx.stats());
      }
    }
}

void watertight_scene(Context& ctx, Output& out) {
  const ViewportMap map(Viewport{}, 128, 64);
  const ScreenRect r{7.30078125, 5.099609375, 120.7001953125, 60.900390625};
  std::mt19937 rng(9);
  for (int S : {1, 8}) {
    ColorTarget target(128, 64, S);
    glm::vec4 corners[4];
    for (const Mesh& m : {jittered_grid(map, r, 37, 19, rng), thin_fan(map, r, 1000, rng), random_strip(map, r, 50, 60, rng),
                          perspective_floor(100.0f, -4.0f, 60.0f, 0.25f, 30, 40, rng, corners)}) {
      clear_color(ctx, target, glm::vec4(0.0f));
      ctx.reset_stats();
      draw_counting(ctx, target, m);
      out.add(read_color(ctx, target));
      out.add_stats(ctx.stats());
    }
  }
}

void reference_scenes(Context& ctx, Output& out) {
  for (uint32_t seed = 0; seed < 24; ++seed) {
    ctx.reset_stats();
    const SceneOutput s = render_scene(ctx, random_scene(777 + seed, 1 << (seed % 4)));
    out.add(s.color);
    out.add(s.depth);
    out.add(s.stencil);
    out.add(&s.query, sizeof(s.query));
    out.add_stats(ctx.stats());
  }
}

/// Many overlapping triangles in one draw (several front-end chunks), blended with a
/// non-commutative equation, so any change of order changes bytes; depth tested against a
/// sloped plane, and an occlusion query.
void ordered_blend_scene(Context& ctx, Output& out) {
  const int W = 200, H = 130, S = 4;  // 4 x 3 tiles, partial
  const ViewportMap map(Viewport{0, 0, 256, 256}, W, H);
  std::mt19937 rng(31337);
  // Corners within 10 pixels of the center: small and large (beyond the small-triangle walk)
  // alike, each pixel still under hundreds of them, at a sixth of the shading of 25.
  std::uniform_real_distribution<double> ux(-10, W + 10), uy(-10, H + 10), d(-10, 10), z(0, 1);
  std::vector<glm::vec4> pos;
  std::vector<std::array<glm::vec4, 1>> col;
  const int n = kTrianglesPerChunk * 2 + 1234;
  for (int i = 0; i < n; ++i) {
    const double cx = ux(rng), cy = uy(rng);
    const glm::vec4 c{float(z(rng)), float(z(rng)), float(z(rng)), float(z(rng))};
    for (int k = 0; k < 3; ++k) {
      const glm::dvec2 p{cx + d(rng), cy + d(rng)};
      const float depth = float(z(rng));
      pos.push_back({float((p.x - map.x) / (map.w / 2) - 1), float(1 - (p.y - map.y) / (map.h / 2)), depth, 1.0f});
      col.push_back({c});
    }
  }
  ColorTarget target(W, H, S);
  DepthStencilTarget ds(W, H, S);
  clear_color(ctx, target, {0.1f, 0.2f, 0.3f, 0.4f});
  clear_depth_stencil(ctx, ds, 0.8f, 0);
  PipelineState st;
  st.viewport = {0, 0, 256, 256};
  st.rasterizer.cull = CullMode::None;
  st.depth_stencil.depth_func = CompareFunc::Less;
  st.depth_stencil.stencil_enable = true;
  st.depth_stencil.front.pass = StencilOp::Incr;
  st.depth_stencil.front.depth_fail = StencilOp::Decr;
  st.blend.enable = true;
  st.blend.src = BlendFactor::SrcAlpha;
  st.blend.dst = BlendFactor::InvSrcAlpha;
  OcclusionQuery q;
  ctx.reset_stats();
  ctx.begin_query(q);
  draw(ctx, Framebuffer{&target, &ds}, st, Geometry::non_indexed(uint32_t(pos.size())), ArrayVS<1>{pos.data(), col.data()},
       VaryingPS{});
  ctx.end_query();
  const uint64_t count = ctx.query_result(q);
  out.add(&count, sizeof(count));
  const Image img = resolve(ctx, target);
  out.add(img.rgba);
  out.add(read_color(ctx, target));
  std::vector<float> depth;
  std::vector<uint8_t> stencil;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      for (int s = 0; s < S; ++s) {
        depth.push_back(ds.depth(x, y, s));
        stencil.push_back(ds.stencil(x, y, s));
      }
  out.add(depth);
  out.add(stencil);
  out.add_stats(ctx.stats());
}

struct CheckerPS {
  static constexpr bool kCanDiscard = false, kWritesDepth = false;
  void operator()(const PixelInput<1>& in, PixelOutput& out) const {
    const auto u = lanes_of(in.varyings[0].x), v = lanes_of(in.varyings[0].y);
    std::array<float, simd::kLanes> c;
    for (int l = 0; l < simd::kLanes; ++l) c[l] = float((int(std::floor(u[l])) + int(std::floor(v[l]))) & 1);
    out.color = {from_lanes(c), from_lanes(u) * simd::Float(0.01f), from_lanes(v) * simd::Float(0.01f), simd::Float(1.0f)};
  }
};

/// A perspective checkerboard floor (perspective-correct varyings, near and guard-band clipping).
void perspective_scene(Context& ctx, Output& out) {
  std::mt19937 rng(4);
  glm::vec4 corners[4];
  const Mesh m = perspective_floor(100.0f, -4.0f, 60.0f, 0.25f, 20, 30, rng, corners);
  std::vector<std::array<glm::vec4, 1>> uv;
  for (const glm::vec4& c : m.clip) uv.push_back({glm::vec4(c.x, c.w, 0, 0)});
  for (int S : {1, 4}) {
    ColorTarget target(200, 100, S);
    clear_color(ctx, target, glm::vec4(0.0f));
    PipelineState st;
    st.rasterizer.cull = CullMode::None;
    ctx.reset_stats();
    draw(ctx, Framebuffer{&target, nullptr}, st, Geometry::indexed(std::span<const uint32_t>(m.indices), uint32_t(m.clip.size())),
         ArrayVS<1>{m.clip.data(), uv.data()}, CheckerPS{});
    out.add(resolve(ctx, target).rgba);
    out.add(read_color(ctx, target));
    out.add_stats(ctx.stats());
  }
}

/// Samples two mipmapped textures (a power-of-two RGBA8 one and an odd-sized RGBA16F one) with
/// four samplers: trilinear wrap, bilinear mirror with point mips, point clamp, and trilinear
/// border with a LOD bias. The coordinates repeat the textures many times and go negative, so
/// every address mode and several mip levels are used within one stamp row.
struct TexturedPS {
  static constexpr bool kCanDiscard = false, kWritesDepth = false;
  const Texture* a;
  const Texture* b;
  Sampler s[4];
  void operator()(const PixelInput<1>& in, PixelOutput& out) const {
    const TexCoord uv{in.varyings[0].x, in.varyings[0].y, simd::Float(0.0f)};
    const TexCoord uv2{in.varyings[0].z, in.varyings[0].w, simd::Float(0.0f)};
    const simd::Float4 t0 = sample(*a, s[0], uv), t1 = sample(*b, s[1], uv2);
    const simd::Float4 t2 = sample(*a, s[2], uv2), t3 = sample(*b, s[3], uv, simd::Float(0.5f));
    const simd::Float k(0.25f);
    out.color = {(t0.x + t1.x + t2.x + t3.x) * k, (t0.y + t1.y + t2.y + t3.y) * k, (t0.z + t1.z + t2.z + t3.z) * k,
                 (t0.w + t1.w) * simd::Float(0.5f)};
  }
};

/// A perspective floor and random depth-tested triangles, textured.
void textured_scene(Context& ctx, Output& out) {
  std::mt19937 rng(77);
  Texture a = Texture::create_2d(64, 64, TextureFormat::RGBA8);
  Texture b = Texture::create_2d(37, 23, TextureFormat::RGBA16F);
  {
    std::vector<glm::vec4> ta(64 * 64), tb(37 * 23);
    std::uniform_real_distribution<float> u(0, 1);
    for (auto& t : ta) t = {u(rng), u(rng), u(rng), u(rng)};
    for (auto& t : tb) t = {u(rng) * 2, u(rng), u(rng), u(rng)};
    a.upload(0, ta);
    b.upload(0, tb);
    a.generate_mips();
    b.generate_mips();
  }
  TexturedPS ps{&a, &b, {}};
  ps.s[1].mip = MipFilter::Point;
  ps.s[1].u = ps.s[1].v = Address::Mirror;
  ps.s[2].min = ps.s[2].mag = Filter::Point;
  ps.s[2].mip = MipFilter::Point;
  ps.s[2].u = ps.s[2].v = Address::Clamp;
  ps.s[3].u = Address::Border;
  ps.s[3].v = Address::Wrap;
  ps.s[3].border = {0.25f, 0.5f, 0.75f, 1.0f};
  ps.s[3].lod_bias = 0.75f;
  glm::vec4 corners[4];
  const Mesh floor = perspective_floor(60.0f, -4.0f, 50.0f, 0.25f, 16, 24, rng, corners);
  std::vector<glm::vec4> pos = floor.clip;
  std::vector<uint32_t> idx = floor.indices;
  std::vector<std::array<glm::vec4, 1>> uv;
  for (const glm::vec4& c : floor.clip) uv.push_back({glm::vec4(c.x * 0.7f, c.w * 0.9f, -c.x * 0.3f - 5.0f, c.w * 0.4f)});
  std::uniform_real_distribution<float> ndc(-1.2f, 1.2f), z(0.0f, 1.0f), t(-6.0f, 6.0f);
  for (int i = 0; i < 300; ++i) {
    const uint32_t base = uint32_t(pos.size());
    const float cx = ndc(rng), cy = ndc(rng), r = 0.05f + 0.3f * z(rng);
    for (int k = 0; k < 3; ++k) {
      pos.push_back({cx + r * ndc(rng), cy + r * ndc(rng), z(rng), 1.0f});
      uv.push_back({glm::vec4{t(rng), t(rng), t(rng) * 3, t(rng) * 0.1f}});
      idx.push_back(base + uint32_t(k));
    }
  }
  for (int S : {1, 4}) {
    ColorTarget target(160, 96, S);
    DepthStencilTarget ds(160, 96, S);
    clear_color(ctx, target, glm::vec4(0.0f));
    clear_depth_stencil(ctx, ds, 1.0f, 0);
    PipelineState st;
    st.rasterizer.cull = CullMode::None;
    ctx.reset_stats();
    draw(ctx, Framebuffer{&target, &ds}, st, Geometry::indexed(std::span<const uint32_t>(idx), uint32_t(pos.size())),
         ArrayVS<1>{pos.data(), uv.data()}, ps);
    const Image img = resolve(ctx, target);
    // Not a scene that compares equal because it drew nothing: texels show through everywhere.
    std::vector<uint32_t> colors(img.rgba.size() / 4);
    std::memcpy(colors.data(), img.rgba.data(), img.rgba.size());
    std::sort(colors.begin(), colors.end());
    EXPECT_GT(std::unique(colors.begin(), colors.end()) - colors.begin(), 2000);
    out.add(img.rgba);
    out.add(read_color(ctx, target));
    out.add_stats(ctx.stats());
  }
}

/// A functor that declares itself trivial (draw.hpp): early-rejected stamps are shaded with no
/// live lane instead of skipped, on every depth-only early path.
struct TrivialVaryingPS {
  static constexpr bool kCanDiscard = false, kWritesDepth = false, kTrivial = true;
  void operator()(const PixelInput<1>& in, PixelOutput& out) const { out.color = in.varyings[0]; }
};

/// Depth-mixed geometry (sloped triangles at random depths, overlapping many times) drawn by a
/// trivial functor with Less, LessEqual, Greater and (with stencil) LessEqual again.
void trivial_functor_scene(Context& ctx, Output& out) {
  const int W = 150, H = 110, S = 4;
  std::mt19937 rng(123);
  std::uniform_real_distribution<float> ndc(-1.1f, 1.1f), z(0.0f, 1.0f), d(-0.3f, 0.3f);
  std::vector<glm::vec4> pos;
  std::vector<std::array<glm::vec4, 1>> col;
  for (int i = 0; i < 3000; ++i) {
    const float cx = ndc(rng), cy = ndc(rng);
    const glm::vec4 c{z(rng), z(rng), z(rng), 1.0f};
    for (int k = 0; k < 3; ++k) {
      pos.push_back({cx + d(rng), cy + d(rng), z(rng), 1.0f});
      col.push_back({c * (0.5f + 0.5f * z(rng))});
    }
  }
  ColorTarget target(W, H, S);
  DepthStencilTarget ds(W, H, S);
  clear_color(ctx, target, glm::vec4(0.0f));
  clear_depth_stencil(ctx, ds, 1.0f, 0);
  ctx.reset_stats();
  OcclusionQuery q;
  ctx.begin_query(q);
  const uint32_t third = uint32_t(pos.size() / 9) * 3;
  for (CompareFunc f : {CompareFunc::Less, CompareFunc::LessEqual, CompareFunc::Greater}) {
    PipelineState st;
    st.rasterizer.cull = CullMode::None;
    st.depth_stencil.depth_func = f;
    st.rasterizer.slope_scaled_depth_bias = f == CompareFunc::Greater ? -1.0f : 0.0f;
    draw(ctx, Framebuffer{&target, &ds}, st, Geometry::non_indexed(third), ArrayVS<1>{pos.data(), col.data()},
         TrivialVaryingPS{});
  }
  PipelineState st;
  st.rasterizer.cull = CullMode::None;
  st.depth_stencil.stencil_enable = true;
  st.depth_stencil.front.pass = StencilOp::Incr;
  st.depth_stencil.front.depth_fail = StencilOp::Decr;
  draw(ctx, Framebuffer{&target, &ds}, st, Geometry::non_indexed(uint32_t(pos.size()) - third),
       ArrayVS<1>{pos.data() + third, col.data() + third}, TrivialVaryingPS{});
  ctx.end_query();
  const uint64_t count = ctx.query_result(q);
  // Depth-mixed: many samples pass and many fail.
  EXPECT_GT(count, uint64_t(W * H * S));
  EXPECT_LT(ctx.stats().stamps_shaded, ctx.stats().stamps_full + ctx.stats().stamps_partial);
  out.add(&count, sizeof(count));
  out.add(read_color(ctx, target));
  std::vector<float> depth;
  std::vector<uint8_t> stencil;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      for (int s = 0; s < S; ++s) {
        depth.push_back(ds.depth(x, y, s));
        stencil.push_back(ds.stencil(x, y, s));
      }
  out.add(depth);
  out.add(stencil);
  out.add_stats(ctx.stats());
}

void check_thread_counts(const char* name, const SceneFn& scene) {
  Output reference;
  {
    Context ctx(1);
    scene(ctx, reference);
  }
  ASSERT_FALSE(reference.bytes.empty());
  // LUXEL_DUMP_DIR=dir writes each scene's bytes but the stats to dir/<name>.bin: builds for
  // different ISAs (x86-64-v3, native, x86-64-v2) can then be compared byte by byte
  // (scripts/compare-isa), which one build alone cannot check.
  if (const char* dir = std::getenv("LUXEL_DUMP_DIR")) {
    std::string file = std::string(dir) + "/" + name + ".bin";
    std::replace(file.begin() + std::ptrdiff_t(std::strlen(dir)), file.end(), ' ', '_');
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(reference.samples.data()),
                                                 std::streamsize(reference.samples.size()));
  }
  for (int threads : {2, 3, 8}) {
    Context ctx(threads);
    ASSERT_EQ(ctx.thread_count(), threads);
    Output o;
    scene(ctx, o);
    // Twice on the same context too: no state may leak from one frame into the next.
    Output again;
    scene(ctx, again);
    EXPECT_TRUE(o.bytes == reference.bytes) << name << ": " << threads << " threads differ from 1 thread";
    EXPECT_TRUE(again.bytes == reference.bytes) << name << ": second run on " << threads << " threads differs";
  }
}

TEST(Determinism, CoverageBatches) { check_thread_counts("coverage", coverage_scene); }
TEST(Determinism, WatertightMeshes) { check_thread_counts("watertight", watertight_scene); }
TEST(Determinism, ReferenceScenes) { check_thread_counts("reference scenes", reference_scenes); }
TEST(Determinism, PerspectiveCheckerboard) { check_thread_counts("perspective", perspective_scene); }
TEST(Determinism, OrderedBlendingAcrossChunks) { check_thread_counts("ordered blending", ordered_blend_scene); }
TEST(Determinism, TexturedDraws) { check_thread_counts("textured", textured_scene); }
TEST(Determinism, TrivialFunctorOnDepthMixedGeometry) { check_thread_counts("trivial functor", trivial_functor_scene); }

}  // namespace
}  // namespace luxel::rasterizer::test
