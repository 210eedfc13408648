// The shader catalog (catalog.hpp): the families' variants (catalog_*.cpp) and their timing.

#include "luxel/shading/source/catalog.hpp"

#include "catalog_entries.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cfloat>
#include <cmath>
#include <iterator>
#include <limits>
#include <random>

namespace luxel::shading::source {

namespace {

/// K random inputs per pixel, in [0.05, 1]: no NaN or denormal slow paths in a timing loop; with
/// LaneInputs::hard one in four replaced by a hard value.
struct TimingInputs {
  std::vector<float> v;
  TimingInputs(int k, int pixels, LaneInputs kind = LaneInputs::timing) : v(static_cast<size_t>(k) * pixels) {
    static constexpr float kHard[] = {0.0f, -0.0f, 1.0f, -1.0f, 1e-40f, -1e-42f, FLT_MIN, 1e30f, -1e30f, 65504.0f,
                                      std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                                      -std::numeric_limits<float>::infinity()};
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> d(0.05f, 1.0f);
    std::uniform_int_distribution<int> quarter(0, 3);
    std::uniform_int_distribution<size_t> pick(0, std::size(kHard) - 1);
    for (float& x : v) x = kind == LaneInputs::hard && quarter(rng) == 0 ? kHard[pick(rng)] : d(rng);
  }
};

}  // namespace

LaneTimes time_lanes(const ShaderVariant& v, int pixels, int repeats) {
  const int k = v.inputs;
  pixels = std::max(pixels, simd::kLanes) / simd::kLanes * simd::kLanes;
  const TimingInputs in(k, pixels);
  using clock = std::chrono::steady_clock;
  volatile float sink = 0.0f;
  alignas(64) float out[4 * simd::kLanes];
  std::vector<double> simd_ns, scalar_ns;
  for (int r = 0; r < std::max(repeats, 1); ++r) {
    // SIMD: inputs stored per stamp, input-major within the stamp.
    const auto t0 = clock::now();
    for (int p = 0; p < pixels; p += simd::kLanes) {
      v.shade_simd(in.v.data() + static_cast<size_t>(p) * k, out);
      sink = sink + out[0];
    }
    const auto t1 = clock::now();
    for (int p = 0; p < pixels; ++p) {
      v.shade_scalar(in.v.data() + static_cast<size_t>(p) * k, out);
      sink = sink + out[0];
    }
    const auto t2 = clock::now();
    simd_ns.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() / pixels);
    scalar_ns.push_back(std::chrono::duration<double, std::nano>(t2 - t1).count() / pixels);
  }
  auto median = [](std::vector<double>& x) {
    std::nth_element(x.begin(), x.begin() + x.size() / 2, x.end());
    return x[x.size() / 2];
  };
  return {median(simd_ns), median(scalar_ns)};
}

LaneAgreement compare_lanes(const ShaderVariant& v, int pixels, LaneInputs inputs) {
  const int k = v.inputs;
  pixels = std::max(pixels, simd::kLanes) / simd::kLanes * simd::kLanes;
  const TimingInputs in(k, pixels, inputs);
  const auto to_steps = [](float x) { return int(std::lround(std::clamp(double(x), 0.0, 1.0) * 255.0)); };
  LaneAgreement r;
  alignas(64) float lanes[4 * simd::kLanes];
  std::vector<float> one(static_cast<size_t>(k));
  for (int p = 0; p < pixels; p += simd::kLanes) {
    const float* base = in.v.data() + static_cast<size_t>(p) * k;
    v.shade_simd(base, lanes);
    for (int j = 0; j < simd::kLanes; ++j) {
      // The scalar pixel that SIMD lane j stands for: its values of each input.
      for (int i = 0; i < k; ++i) one[size_t(i)] = base[static_cast<size_t>(i) * simd::kLanes + static_cast<size_t>(j)];
      float scalar[4];
      v.shade_scalar(one.data(), scalar);
      bool differs = false;
      for (int ch = 0; ch < 4; ++ch) {
        const float a = lanes[ch * simd::kLanes + j], b = scalar[ch];
        if (std::bit_cast<uint32_t>(a) == std::bit_cast<uint32_t>(b) || (std::isnan(a) && std::isnan(b))) continue;
        differs = true;
        const double d = std::isnan(a) || std::isnan(b) ? HUGE_VAL : std::fabs(double(a) - double(b));
        r.max_abs = std::max(r.max_abs, d);
        r.max_steps = std::max(r.max_steps, std::abs(to_steps(a) - to_steps(b)));
      }
      r.differing += differs;
      ++r.pixels;
    }
  }
  return r;
}

const std::vector<ShaderVariant>& shader_catalog() {
  static const std::vector<ShaderVariant> catalog = [] {
    std::vector<ShaderVariant> c;
    detail::add_lightmapped(c);
    detail::add_vertexlit_plain(c);
    detail::add_vertexlit_envmap(c);
    detail::add_unlit(c);
    detail::add_water(c);
    detail::add_small_families(c);
    return c;
  }();
  return catalog;
}

}  // namespace luxel::shading::source
