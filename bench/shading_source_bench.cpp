// ns per pixel of the Source shaders, per catalog variant (shading/source/catalog.hpp: every static
// combo of the registry and the post shaders), on the SIMD lane and the scalar reference lane,
// through the catalog's entry points: the combine stage, fed random texel values and
// interpolants (texture reads excluded), one call per stamp or per scalar pixel. The shader model
// changes only what is counted (the same C++ runs for ps_2_0, ps_2_b and ps_3_0), so one timing
// per variant stands for every card it runs on; the benchmark name lists them. `luxel cost`
// prints the counted DX9 slots beside the same numbers.

#include "luxel/shading/source/catalog.hpp"

#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

namespace luxel::shading::source {
namespace {

constexpr int kPixels = 4096;  // one 64x64 tile

/// `inputs` random floats per pixel in [0.05, 1] (no NaN or denormal slow paths), stamp-major.
std::vector<float> random_inputs(int inputs) {
  std::vector<float> r(static_cast<size_t>(kPixels) * inputs);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> d(0.05f, 1.0f);
  for (float& x : r) x = d(rng);
  return r;
}

void run(benchmark::State& state, const ShaderVariant& v, bool simd_lane) {
  const std::vector<float> in = random_inputs(v.inputs);
  const int step = simd_lane ? simd::kLanes : 1;
  alignas(64) float out[4 * simd::kLanes];
  for (auto _ : state) {
    for (int p = 0; p + step <= kPixels; p += step) {
      (simd_lane ? v.shade_simd : v.shade_scalar)(in.data() + static_cast<size_t>(p) * v.inputs, out);
      benchmark::DoNotOptimize(out);
    }
  }
  state.counters["ns_per_pixel"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * kPixels, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

const bool registered = [] {
  for (const ShaderVariant& v : shader_catalog()) {
    if (v.models.empty()) continue;  // allowed by the rules but over every model's limits (luxel cost shows why)
    std::string cards;
    for (ShaderModel m : v.models) cards += std::string(cards.empty() ? "" : ",") + std::string(caps(m).name);
    std::string name = v.family + "/" + v.variant + "/" + cards;
    for (char& ch : name)
      if (ch == ' ') ch = '_';
    benchmark::RegisterBenchmark((name + "/simd").c_str(), [&v](benchmark::State& s) { run(s, v, true); });
    benchmark::RegisterBenchmark((name + "/scalar").c_str(), [&v](benchmark::State& s) { run(s, v, false); });
  }
  return true;
}();

}  // namespace
}  // namespace luxel::shading::source
