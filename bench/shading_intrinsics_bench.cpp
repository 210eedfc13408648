// ns per pixel of intrinsics-heavy shader snippets, on the scalar reference lane and the SIMD lane.
// The same template code runs in both; "ns_per_pixel" is the number to compare.

#include "luxel/shading/hlsl.hpp"

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

namespace luxel::shading {
namespace {

constexpr int kPixels = 4096;  // one 64x64 tile

/// Six float inputs per pixel, structure of arrays (what the rasterizer's varyings look like).
struct Inputs {
  std::vector<float> v[6];
  Inputs() {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> d(-1.0f, 1.0f);
    for (auto& a : v) {
      a.resize(kPixels);
      for (float& x : a) x = d(rng);
    }
  }
};
const Inputs& inputs() {
  static const Inputs in;
  return in;
}

struct AmbientCube {
  glm::vec3 color[6] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}};
};

/// Phong specular with exponent 150, half-Lambert diffuse, three normalizes, a lerp.
template <class L>
float3<L> phong(const L* a) {
  const float3<L> n = normalize(float3<L>(a[0], a[1], a[2]));
  const float3<L> l = normalize(float3<L>(a[3], a[4], a[5]));
  const float3<L> v = normalize(float3<L>(a[1], a[5], L(1.0f)));
  const float3<L> r = reflect(-v, n);
  const L spec = pow(saturate(dot(r, l)), L(150.0f));
  const L half_lambert = saturate(dot(n, l) * 0.5f + 0.5f);
  return lerp(float3<L>(0.2f, 0.3f, 0.4f), float3<L>(half_lambert * half_lambert), L(0.75f)) + spec;
}

/// The ambient cube (docs/fidelity.md#ambient-cube).
template <class L>
float3<L> ambient(const L* a, const AmbientCube& cube) {
  const float3<L> n(a[0], a[1], a[2]);
  const float3<L> n2 = n * n;
  const bool3<L> plus = n >= 0.0f;
  const float3<L> p = select(plus, n2, 0.0f);
  const float3<L> m = select(plus, 0.0f, n2);
  return p.x * constant<L>(cube.color[0]) + m.x * constant<L>(cube.color[1]) + p.y * constant<L>(cube.color[2]) +
         m.y * constant<L>(cube.color[3]) + p.z * constant<L>(cube.color[4]) + m.z * constant<L>(cube.color[5]);
}

/// Gamma encode and decode: pow-heavy color math (the tone-map epilogue's kind).
template <class L>
float3<L> gamma(const L* a) {
  const float3<L> c = abs(float3<L>(a[0], a[1], a[2])) * 4.0f;
  const float3<L> linear = pow(c, 2.2f);
  return pow(saturate(linear * 0.7f), 1.0f / 2.2f);
}

template <class Snippet>
void run_scalar(benchmark::State& state, Snippet snippet) {
  const Inputs& in = inputs();
  std::vector<float> out(kPixels);
  for (auto _ : state) {
    for (int p = 0; p < kPixels; ++p) {
      const float a[6] = {in.v[0][p], in.v[1][p], in.v[2][p], in.v[3][p], in.v[4][p], in.v[5][p]};
      const float3<float> c = snippet(a);
      out[p] = c.x + c.y + c.z;
    }
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * kPixels);
  state.counters["ns_per_pixel"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * kPixels * 1e-9,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

template <class Snippet>
void run_simd(benchmark::State& state, Snippet snippet) {
  const Inputs& in = inputs();
  std::vector<float> out(kPixels);
  for (auto _ : state) {
    for (int p = 0; p < kPixels; p += simd::kLanes) {
      simd::Float a[6];
      for (int i = 0; i < 6; ++i) a[i] = simd::Float::load_unaligned(in.v[i].data() + p);
      const float3<simd::Float> c = snippet(a);
      (c.x + c.y + c.z).store_unaligned(out.data() + p);
    }
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * kPixels);
  state.counters["ns_per_pixel"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * kPixels * 1e-9,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

const AmbientCube kCube;

void BM_ShadingPhongScalar(benchmark::State& s) { run_scalar(s, [](const float* a) { return phong(a); }); }
void BM_ShadingPhongSimd(benchmark::State& s) { run_simd(s, [](const simd::Float* a) { return phong(a); }); }
void BM_ShadingAmbientCubeScalar(benchmark::State& s) {
  run_scalar(s, [](const float* a) { return ambient(a, kCube); });
}
void BM_ShadingAmbientCubeSimd(benchmark::State& s) {
  run_simd(s, [](const simd::Float* a) { return ambient(a, kCube); });
}
void BM_ShadingGammaScalar(benchmark::State& s) { run_scalar(s, [](const float* a) { return gamma(a); }); }
void BM_ShadingGammaSimd(benchmark::State& s) { run_simd(s, [](const simd::Float* a) { return gamma(a); }); }

BENCHMARK(BM_ShadingPhongScalar);
BENCHMARK(BM_ShadingPhongSimd);
BENCHMARK(BM_ShadingAmbientCubeScalar);
BENCHMARK(BM_ShadingAmbientCubeSimd);
BENCHMARK(BM_ShadingGammaScalar);
BENCHMARK(BM_ShadingGammaSimd);

}  // namespace
}  // namespace luxel::shading
