#pragma once
// ns per pixel of a function of the normal written in the lane language (float3<L> n -> float3<L>),
// on the SIMD lane and the scalar lane: what a report section times when its approximation is a
// per-pixel function of a direction (the lighting bases). The median of `repeats` runs, each over
// kTimingNormals Fibonacci normals (structure of arrays: they stay in L1) evaluated again and
// again; each result is stored and read, as catalog.cpp's timing does, so that nothing is
// optimised away. The function alone: no interpolation, no texture, no output merger.

#include "luxel/rasterizer/simd.hpp"
#include "luxel/shading/hlsl.hpp"
#include "luxel/shading/source/sphere_quadrature.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <utility>
#include <vector>

namespace luxel::cli {

inline constexpr int kTimingNormals = 4096;

/// {SIMD ns, scalar ns} per pixel of `eval`, a generic lambda taking a float3 of either lane.
template <class Eval>
std::pair<double, double> time_normal_function(const Eval& eval, int repeats) {
  namespace simd = rasterizer::simd;
  using shading::float3;
  constexpr int kSimdPasses = 256, kScalarPasses = 32;  // ~1 ms per lane and run
  static const std::array<std::vector<float>, 3> soa = [] {
    std::array<std::vector<float>, 3> r;
    for (const glm::dvec3& n : shading::source::fibonacci_normals(kTimingNormals))
      for (int c = 0; c < 3; ++c) r[size_t(c)].push_back(float(n[c]));
    return r;
  }();
  using clock = std::chrono::steady_clock;
  volatile float sink = 0.0f;
  std::vector<double> simd_ns, scalar_ns;
  for (int r = 0; r < std::max(repeats, 1); ++r) {
    const auto t0 = clock::now();
    for (int pass = 0; pass < kSimdPasses; ++pass) {
      for (int p = 0; p < kTimingNormals; p += simd::kLanes) {
        const float3<simd::Float> n(simd::Float::load_unaligned(soa[0].data() + p), simd::Float::load_unaligned(soa[1].data() + p),
                                    simd::Float::load_unaligned(soa[2].data() + p));
        const float3<simd::Float> c = eval(n);
        alignas(64) float lanes[simd::kLanes];
        (c.x + c.y + c.z).store_aligned(lanes);
        sink = sink + lanes[0];
      }
    }
    const auto t1 = clock::now();
    for (int pass = 0; pass < kScalarPasses; ++pass) {
      for (size_t p = 0; p < size_t(kTimingNormals); ++p) {
        const float3<float> c = eval(float3<float>(soa[0][p], soa[1][p], soa[2][p]));
        sink = sink + c.x + c.y + c.z;
      }
    }
    const auto t2 = clock::now();
    simd_ns.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() / (double(kTimingNormals) * kSimdPasses));
    scalar_ns.push_back(std::chrono::duration<double, std::nano>(t2 - t1).count() / (double(kTimingNormals) * kScalarPasses));
  }
  const auto median = [](std::vector<double>& v) {
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  return {median(simd_ns), median(scalar_ns)};
}

}  // namespace luxel::cli
