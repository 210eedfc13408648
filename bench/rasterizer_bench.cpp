// Micro-benchmarks of the rasterizer's stages: front end (vertex functor, clip, setup, binning),
// coverage and early depth on large and thin triangles, and whole draws of small triangles.
// Items are triangles (front end) or pixels (coverage); Google Benchmark reports rates.

#include "machine.hpp"

#include "luxel/rasterizer/draw_definition.hpp"

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

namespace {

// The CPU and instruction set in the context block every run prints first.
const bool kMachineInContext = [] {
  benchmark::AddCustomContext("machine", luxel::bench::machine_line());
  return true;
}();

using namespace luxel::rasterizer;
using simd::Float;

/// Vertices already in clip space, one flat color varying.
struct ClipVertices {
  static constexpr int kVaryings = 1;
  const glm::vec4* positions;
  void operator()(uint32_t i, VertexOutput<1>& out) const {
    out.position = positions[i];
    out.varyings[0] = {0.5f, 0.25f, 0.75f, 1.0f};
  }
};

struct FlatColor {
  static constexpr bool kCanDiscard = false, kWritesDepth = false;
  void operator()(const PixelInput<1>& in, PixelOutput& out) const { out.color = in.varyings[0]; }
};

/// `count` random triangles of about `size` pixels on a side on a 1280x720 screen.
std::vector<glm::vec4> random_triangles(int count, float size, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<glm::vec4> v;
  for (int t = 0; t < count; ++t) {
    const float cx = unit(rng) * 2 - 1, cy = unit(rng) * 2 - 1, z = unit(rng);
    for (int k = 0; k < 3; ++k)
      v.push_back({cx + (unit(rng) - 0.5f) * size / 640.0f, cy + (unit(rng) - 0.5f) * size / 360.0f, z, 1.0f});
  }
  return v;
}

PipelineState no_cull() {
  PipelineState state;
  state.rasterizer.cull = CullMode::None;
  state.depth_stencil.depth_func = CompareFunc::Less;
  return state;
}

void BM_FrontEnd(benchmark::State& state) {
  const int count = 100000;
  const auto vertices = random_triangles(count, 3.0f, 1);
  Context ctx(1);
  ColorTarget color(1280, 720, 4);
  DepthStencilTarget depth(1280, 720, 4);
  const PipelineState ps = no_cull();
  for (auto _ : state) {
    draw(ctx, {&color, &depth}, ps, Geometry::non_indexed(3 * count), ClipVertices{vertices.data()}, FlatColor{});
    state.PauseTiming();
    ctx.flush();
    state.ResumeTiming();
  }
  state.SetItemsProcessed(state.iterations() * count);
}
BENCHMARK(BM_FrontEnd)->Unit(benchmark::kMillisecond);

/// The front end of a post pass's draw: a rectangle covering a 1280x720 target (two triangles,
/// one varying, binned into each of its 240 tiles), after a pass on a quarter-size target (another
/// tiling), as in a frame. Items are triangles.
void BM_FrontEndFullscreen(benchmark::State& state) {
  const std::vector<glm::vec4> quad = {{-1, -1, 0.5f, 1}, {1, -1, 0.5f, 1}, {1, 1, 0.5f, 1},
                                       {-1, -1, 0.5f, 1}, {1, 1, 0.5f, 1},  {-1, 1, 0.5f, 1}};
  Context ctx(1);
  ColorTarget frame(1280, 720, 1), quarter(320, 180, 1);
  const PipelineState ps = no_cull();
  for (auto _ : state) {
    state.PauseTiming();
    draw(ctx, {&quarter, nullptr}, ps, Geometry::non_indexed(6), ClipVertices{quad.data()}, FlatColor{});
    ctx.flush();
    state.ResumeTiming();
    draw(ctx, {&frame, nullptr}, ps, Geometry::non_indexed(6), ClipVertices{quad.data()}, FlatColor{});
    state.PauseTiming();
    ctx.flush();
    state.ResumeTiming();
  }
  state.SetItemsProcessed(state.iterations() * 2);
}
BENCHMARK(BM_FrontEndFullscreen)->Unit(benchmark::kMicrosecond)->Iterations(500);  // each flush ~1 ms, untimed

/// Whole draws (front end + rasterization) of small triangles, by sample count.
void BM_SmallTriangles(benchmark::State& state) {
  const int count = 100000, samples = static_cast<int>(state.range(0));
  const auto vertices = random_triangles(count, 3.0f, 2);
  Context ctx(1);
  ColorTarget color(1280, 720, samples);
  DepthStencilTarget depth(1280, 720, samples);
  const PipelineState ps = no_cull();
  for (auto _ : state) {
    clear_depth_stencil(ctx, depth, 1.0f, 0);
    draw(ctx, {&color, &depth}, ps, Geometry::non_indexed(3 * count), ClipVertices{vertices.data()}, FlatColor{});
    ctx.flush();
  }
  state.SetItemsProcessed(state.iterations() * count);
}
BENCHMARK(BM_SmallTriangles)->Arg(1)->Arg(4)->Unit(benchmark::kMillisecond);

/// Coverage + early depth + flat shading of big triangles: two covering the screen.
void BM_FullscreenCoverage(benchmark::State& state) {
  const int samples = static_cast<int>(state.range(0));
  const std::vector<glm::vec4> quad = {{-1, -1, 0.5f, 1}, {1, -1, 0.5f, 1}, {1, 1, 0.5f, 1},
                                       {-1, -1, 0.5f, 1}, {1, 1, 0.5f, 1},  {-1, 1, 0.5f, 1}};
  Context ctx(1);
  ColorTarget color(1280, 720, samples);
  DepthStencilTarget depth(1280, 720, samples);
  const PipelineState ps = no_cull();
  for (auto _ : state) {
    clear_depth_stencil(ctx, depth, 1.0f, 0);
    draw(ctx, {&color, &depth}, ps, Geometry::non_indexed(6), ClipVertices{quad.data()}, FlatColor{});
    ctx.flush();
  }
  state.SetItemsProcessed(state.iterations() * 1280 * 720);
}
BENCHMARK(BM_FullscreenCoverage)->Arg(1)->Arg(4)->Unit(benchmark::kMillisecond);

/// Thin slivers: almost every stamp is partly covered and needs per-sample edge tests.
void BM_SliverCoverage(benchmark::State& state) {
  std::vector<glm::vec4> v;
  for (int i = 0; i < 2000; ++i) {
    const float x = -1.0f + 2.0f * i / 2000.0f;
    v.insert(v.end(), {{x, -1, 0.5f, 1}, {x + 0.0015f, -1, 0.5f, 1}, {x + 0.0008f, 1, 0.5f, 1}});
  }
  Context ctx(1);
  ColorTarget color(1280, 720, 4);
  DepthStencilTarget depth(1280, 720, 4);
  const PipelineState ps = no_cull();
  for (auto _ : state) {
    clear_depth_stencil(ctx, depth, 1.0f, 0);
    draw(ctx, {&color, &depth}, ps, Geometry::non_indexed(static_cast<uint32_t>(v.size())), ClipVertices{v.data()},
         FlatColor{});
    ctx.flush();
  }
  state.SetItemsProcessed(state.iterations() * 2000);
}
BENCHMARK(BM_SliverCoverage)->Unit(benchmark::kMillisecond);

}  // namespace
