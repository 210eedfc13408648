// Fast-path switches (fast_paths.hpp): every scene renders to the same color, depth, stencil and
// occlusion counts with every fast path on, all off, and each one off alone; with all off the
// output still matches the scalar oracles; and each switch really turns its path off (the
// DrawStats counter of the path it names).

#include "coverage_support.hpp"
#include "mesh_support.hpp"
#include "pipeline_support.hpp"
#include "raster_support.hpp"

#include "luxel/rasterizer/fast_paths.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <functional>
#include <random>

namespace luxel::rasterizer::test {
namespace {

Context make_context(FastPaths paths) {
  ContextOptions options;
  options.threads = 2;
  options.fast_paths = paths;
  return Context(options);
}

/// Bytes a scene produced, and the stats of its draws (compared only where a test says so).
struct PathOutput {
  std::vector<uint8_t> bytes;
  DrawStats stats;
  template <class T>
  void add(const std::vector<T>& v) {
    const auto* b = reinterpret_cast<const uint8_t*>(v.data());
    bytes.insert(bytes.end(), b, b + v.size() * sizeof(T));
  }
  void add(uint64_t v) { add(std::vector<uint64_t>{v}); }
};
using PathSceneFn = std::function<void(Context&, PathOutput&)>;

/// The pipeline oracle's random scenes: depth functions, stencil, blending, discard, shader
/// depth, queries, 1 to 8 samples.
void oracle_scenes(Context& ctx, PathOutput& out) {
  for (uint32_t seed = 0; seed < uint32_t(budget(24, 8)); ++seed) {
    const SceneOutput s = render_scene(ctx, random_scene(4242 + seed, 1 << (seed % 4)));
    out.add(s.color);
    out.add(s.depth);
    out.add(s.stencil);
    out.add(s.query);
  }
}

/// Random triangles of every kind (small, large, wide-edged, slivers, clipped), one draw each.
void path_coverage_scene(Context& ctx, PathOutput& out) {
  const CoverageConfig base = coverage_configs(false).front();
  for (int S : {1, 4, 8}) {
    TriangleGenerator gen(uint32_t(900 + S), base);
    ColorTarget target(base.width, base.height, S);
    for (int b = 0; b < budget(4, 2); ++b) {
      std::vector<TestTriangle> batch;
      for (int k = 0; k < 32; ++k) batch.push_back(gen.random());
      // Large kinds too: they exercise the 16x16 blocks.
      batch[0] = gen.make(TriKind::Large);
      batch[1] = gen.make(TriKind::Wide);
      draw_coverage_batch(ctx, target, base, batch, b % 2 ? BatchMode::LastWins : BatchMode::Bits);
      out.add(read_color(ctx, target));
    }
  }
}

/// Indexed meshes with shared vertices (the vertex cache), perspective and affine ones.
void mesh_scene(Context& ctx, PathOutput& out) {
  const ViewportMap map(Viewport{}, 128, 64);
  const ScreenRect r{3.30078125, 2.099609375, 124.7001953125, 61.900390625};
  std::mt19937 rng(12);
  glm::vec4 corners[4];
  ColorTarget target(128, 64, 4);
  for (const Mesh& m : {jittered_grid(map, r, 37, 19, rng), random_fan(map, r, 300, rng),
                        perspective_floor(100.0f, -4.0f, 60.0f, 0.25f, 30, 40, rng, corners)}) {
    clear_color(ctx, target, glm::vec4(0.0f));
    draw_counting(ctx, target, m);
    out.add(read_color(ctx, target));
  }
}

/// A W2-like draw: small flat-coloured triangles at random sloped depths, a trivial pixel
/// functor, each early depth function with and without depth writes, an occlusion query.
struct FlatVS {
  static constexpr int kVaryings = 1;
  const glm::vec4* positions;
  const glm::vec4* colors;
  void operator()(uint32_t i, VertexOutput<1>& out) const {
    out.position = positions[i];
    out.varyings[0] = colors[i / 3];
  }
};
struct TrivialPS {
  static constexpr bool kCanDiscard = false, kWritesDepth = false, kTrivial = true;
  void operator()(const PixelInput<1>& in, PixelOutput& out) const { out.color = in.varyings[0]; }
};
void trivial_depth_scene(Context& ctx, PathOutput& out) {
  const int W = 150, H = 90, S = 4;
  std::mt19937 rng(77);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<glm::vec4> pos, colors;
  for (int i = 0; i < 6000; ++i) {
    const float cx = u(rng) * 2.2f - 1.1f, cy = u(rng) * 2.2f - 1.1f;
    const float size = i % 50 == 0 ? 0.8f : 0.04f;  // a few larger ones
    colors.push_back({u(rng), u(rng), u(rng), 1.0f});
    // Every third triangle has constant depth (FastPath::ConstantDepth), some of them at 0, the
    // depth that path leaves to the general one.
    const float constant_z = i % 7 == 0 ? 0.0f : u(rng);
    for (int k = 0; k < 3; ++k)
      pos.push_back({cx + size * (u(rng) - 0.5f), cy + size * (u(rng) - 0.5f), i % 3 == 0 ? constant_z : u(rng), 1.0f});
  }
  ColorTarget target(W, H, S);
  DepthStencilTarget ds(W, H, S);
  for (CompareFunc f : {CompareFunc::Less, CompareFunc::LessEqual, CompareFunc::Greater, CompareFunc::GreaterEqual,
                        CompareFunc::Equal, CompareFunc::NotEqual}) {
    for (bool write : {true, false}) {
      clear_color(ctx, target, {0.1f, 0.1f, 0.1f, 1.0f});
      clear_depth_stencil(ctx, ds, f == CompareFunc::Greater || f == CompareFunc::GreaterEqual ? 0.0f : 1.0f, 0);
      PipelineState st;
      st.rasterizer.cull = CullMode::None;
      st.depth_stencil.depth_func = f;
      st.depth_stencil.depth_write = write;
      OcclusionQuery q;
      ctx.begin_query(q);
      // Twice: Equal and NotEqual then meet depths already written.
      for (int pass = 0; pass < 2; ++pass)
        draw(ctx, Framebuffer{&target, &ds}, st, Geometry::non_indexed(uint32_t(pos.size())), FlatVS{pos.data(), colors.data()},
             TrivialPS{});
      ctx.end_query();
      out.add(ctx.query_result(q));
      out.add(read_color(ctx, target));
      std::vector<float> depth;
      for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
          for (int s = 0; s < S; ++s) depth.push_back(ds.depth(x, y, s));
      out.add(depth);
    }
  }
}

PathOutput render(const PathSceneFn& scene, FastPaths paths) {
  Context ctx = make_context(paths);
  PathOutput out;
  ctx.reset_stats();
  scene(ctx, out);
  ctx.flush();
  out.stats = ctx.stats();
  return out;
}

void check_switches(const char* name, const PathSceneFn& scene) {
  const PathOutput all_on = render(scene, FastPaths());
  ASSERT_FALSE(all_on.bytes.empty());
  EXPECT_TRUE(render(scene, FastPaths::none()).bytes == all_on.bytes) << name << ": all fast paths off";
  for (const FastPathName& p : kFastPathNames)
    EXPECT_TRUE(render(scene, FastPaths::all_but(p.path)).bytes == all_on.bytes) << name << ": " << p.name << " off";
}

TEST(FastPaths, OracleScenesKeepTheirBytes) { check_switches("oracle scenes", oracle_scenes); }
TEST(FastPaths, CoverageKeepsItsBytes) { check_switches("coverage", path_coverage_scene); }
TEST(FastPaths, MeshesKeepTheirBytes) { check_switches("meshes", mesh_scene); }
TEST(FastPaths, TrivialShaderDepthPathsKeepTheirBytes) { check_switches("trivial depth", trivial_depth_scene); }

// With every fast path off the library still agrees with the oracles (the general paths are not
// merely equal to the fast ones, they are right).
TEST(FastPaths, AllOffMatchesTheOracles) {
  Context ctx = make_context(FastPaths::none());
  for (uint32_t seed = 0; seed < uint32_t(budget(24, 8)); ++seed) {
    const Scene scene = random_scene(4242 + seed, 1 << (seed % 4));
    std::vector<std::string> messages;
    EXPECT_EQ(compare_scene(scene, render_scene(ctx, scene), reference_scene(scene), messages, 4), 0)
        << scene.describe() << join(messages);
  }
  const CoverageConfig base = coverage_configs(false).front();
  for (int S : {1, 4}) {
    TriangleGenerator gen(uint32_t(700 + S), base);
    ColorTarget target(base.width, base.height, S);
    std::vector<TestTriangle> batch;
    for (int k = 0; k < 32; ++k) batch.push_back(gen.random());
    draw_coverage_batch(ctx, target, base, batch, BatchMode::Bits);
    std::vector<std::string> messages;
    EXPECT_EQ(check_coverage_batch(ctx, target, base, batch, BatchMode::Bits, messages, 4), 0) << join(messages);
  }
}

// Each switch turns off the path it names: the path's counter drops to zero (or the general
// path's rises).
TEST(FastPaths, EachSwitchTurnsItsPathOff) {
  auto stats = [](const PathSceneFn& scene, FastPaths paths) { return render(scene, paths).stats; };
  const DrawStats on = stats(path_coverage_scene, FastPaths());
  ASSERT_GT(on.small_walks, 0u);
  ASSERT_GT(on.blocks_full, 0u);
  ASSERT_GT(on.stamps_full, 0u);
  EXPECT_EQ(stats(path_coverage_scene, FastPaths::all_but(FastPath::SmallTriangleWalk)).small_walks, 0u);
  const DrawStats wide = stats(path_coverage_scene, FastPaths::all_but(FastPath::NarrowEdges));
  EXPECT_EQ(wide.small_walks, 0u);  // the small walk is a 32-bit path
  EXPECT_EQ(wide.stamps_wide_edges, wide.stamps_partial);
  EXPECT_LT(on.stamps_wide_edges, on.stamps_partial);
  const DrawStats no_full = stats(path_coverage_scene, FastPaths::all_but(FastPath::FullCoverage));
  EXPECT_EQ(no_full.blocks_full, 0u);
  EXPECT_EQ(no_full.stamps_full, 0u);
  EXPECT_EQ(no_full.stamps_shaded, on.stamps_shaded);
  // Trivial functors shade stamps that lost all their samples: off, fewer stamps are shaded.
  const DrawStats trivial_on = stats(trivial_depth_scene, FastPaths());
  const DrawStats trivial_off = stats(trivial_depth_scene, FastPaths::all_but(FastPath::TrivialShaders));
  EXPECT_LT(trivial_off.stamps_shaded, trivial_on.stamps_shaded);
  // Without the fixed depth paths, kTrivial has no path to take either (the general early test
  // branches around dead stamps).
  EXPECT_EQ(stats(trivial_depth_scene, FastPaths::all_but(FastPath::FixedDepthPaths)).stamps_shaded,
            trivial_off.stamps_shaded);
  EXPECT_GT(trivial_on.constant_depth, 0u);
  EXPECT_EQ(stats(trivial_depth_scene, FastPaths::all_but(FastPath::ConstantDepth)).constant_depth, 0u);
}

TEST(FastPaths, SwitchListsParse) {
  EXPECT_EQ(parse_fast_paths_off(""), FastPaths());
  EXPECT_EQ(parse_fast_paths_off("all"), FastPaths::none());
  EXPECT_EQ(parse_fast_paths_off("trivial"), FastPaths::all_but(FastPath::TrivialShaders));
  EXPECT_EQ(parse_fast_paths_off("flat,affine"),
            FastPaths::all_but(FastPath::FlatRecords).without(FastPath::AffineRecords));
  EXPECT_EQ(fast_paths_off_names(parse_fast_paths_off("vertex_cache,small_walk")), "small_walk,vertex_cache");
  EXPECT_EQ(fast_paths_off_names(FastPaths()), "none");
  for (const FastPathName& p : kFastPathNames) EXPECT_EQ(parse_fast_paths_off(p.name), FastPaths::all_but(p.path));
  try {
    parse_fast_paths_off("small_walk,fast");
    ADD_FAILURE() << "an unknown name must throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'fast'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace luxel::rasterizer::test
