// ns per pixel of the Source shaders (shading/source/*.hpp), per static combo, on the SIMD lane and
// the scalar reference lane. The shader model changes only what is counted (the same C++ runs for
// ps_2_0, ps_2_b and ps_3_0), so one timing per combo stands for every model it is valid on; the
// benchmark name lists those models. Texture fetches are replaced by random texel values and the
// cube map by an analytic function: this measures the shading arithmetic (luxel cost prints the
// counted DX9 slots beside it).

#include "luxel/shading/source/lightmapped_generic.hpp"
#include "luxel/shading/source/luminance_range.hpp"
#include "luxel/shading/source/sky.hpp"
#include "luxel/shading/source/unlit_generic.hpp"
#include "luxel/shading/source/vertexlit_generic.hpp"
#include "luxel/shading/source/water.hpp"

#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

namespace luxel::shading::source {
namespace {

constexpr int kPixels = 4096;  // one 64x64 tile
constexpr int kInputs = 28;

/// kInputs floats per pixel, stamp-major (inputs of one stamp together, input-major inside).
const std::vector<float>& inputs() {
  static const std::vector<float> v = [] {
    std::vector<float> r(static_cast<size_t>(kPixels) * kInputs);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> d(0.05f, 1.0f);
    for (float& x : r) x = d(rng);
    return r;
  }();
  return v;
}

template <class L, class Shade>
void run(benchmark::State& state, Shade&& shade) {
  const std::vector<float>& in = inputs();
  constexpr int kStep = std::is_same_v<L, float> ? 1 : simd::kLanes;
  for (auto _ : state) {
    for (int p = 0; p + kStep <= kPixels; p += kStep) {
      const float* base = in.data() + static_cast<size_t>(p) * kInputs;
      auto get = [&](int i) {
        if constexpr (std::is_same_v<L, float>) {
          return base[i];
        } else {
          return simd::Float::load_unaligned(base + static_cast<size_t>(i) * simd::kLanes);
        }
      };
      const float4<L> c = shade.template operator()<L>(get);
      benchmark::DoNotOptimize(c);
    }
  }
  state.counters["ns_per_pixel"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * kPixels, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

template <class L, LightmappedCombo C>
void BM_Lightmapped(benchmark::State& state) {
  LightmappedGenericParams p;
  p.fresnel = fresnel_constant(0.2f);
  run<L>(state, [&]<class M>(const auto& get) {
    LightmappedTexels<M> t;
    t.base = float4<M>(get(0), get(1), get(2), get(3));
    t.bump = float4<M>(get(4), get(5), get(6), get(7));
    t.mask = float3<M>(get(8), get(9), get(10));
    for (int i = 0; i < 4; ++i) t.lightmap[i] = float3<M>(get(11 + i), get(12 + i), get(13 + i));
    LightmappedInputs<M> in;
    in.tangent = float3<M>(get(14), get(15), get(16));
    in.binormal = float3<M>(get(17), get(18), get(19));
    in.normal = float3<M>(get(20), get(21), get(22));
    in.eye_vector = float3<M>(get(23), get(24), get(25));
    return lightmapped_generic_combine<C>(t, in, p, [](const float3<M>& r) { return r * r; });
  });
}

template <class L, VertexLitCombo C>
void BM_VertexLit(benchmark::State& state) {
  VertexLitParams p;
  for (auto& l : p.lights) {
    l.color = glm::vec4(1.0f, 0.8f, 0.6f, 0.0f);
    l.position = glm::vec4(2.0f, 1.0f, 3.0f, 1.0f);
  }
  p.phong_params.x = 40.0f;
  const rasterizer::Texture normalization_cube = normalization_cube_map();  // the ps_2_0 combos
  p.normalization_cube.texture = &normalization_cube;
  run<L>(state, [&]<class M>(const auto& get) {
    VertexLitTexels<M> t;
    t.base = float4<M>(get(0), get(1), get(2), get(3));
    t.bump = float4<M>(get(4), get(5), get(6), get(7));
    t.exponent = float4<M>(get(8), get(9), get(10), get(11));
    VertexLitInputs<M> in;
    in.world_pos = float3<M>(get(12), get(13), get(14));
    in.normal = float3<M>(get(15), get(16), get(17));
    in.tangent = float3<M>(get(18), get(19), get(20));
    in.binormal = float3<M>(get(21), get(22), get(23));
    in.attenuation = float4<M>(get(24), get(25), get(26), get(27));
    return vertexlit_combine<C>(t, in, p);
  });
}

template <class L, UnlitCombo C>
void BM_Unlit(benchmark::State& state) {
  UnlitGenericParams p;
  p.envmap_contrast = glm::vec4(0.5f);
  run<L>(state, [&]<class M>(const auto& get) {
    UnlitTexels<M> t;
    t.base = float4<M>(get(0), get(1), get(2), get(3));
    t.detail = float4<M>(get(4), get(5), get(6), get(7));
    t.mask = float3<M>(get(8), get(9), get(10));
    UnlitInputs<M> in;
    in.vertex_color = float4<M>(get(11), get(12), get(13), get(14));
    in.eye_vector = float3<M>(get(15), get(16), get(17));
    in.normal = float3<M>(get(18), get(19), get(20));
    return unlit_generic_combine<C>(t, in, p, [](const float3<M>& r) { return r * r; });
  });
}

template <class L, SkyCombo C>
void BM_Sky(benchmark::State& state) {
  SkyParams p;
  p.input_scale = glm::vec4(sky_input_scale(SkyFormat::rgba16), 1.0f);
  run<L>(state, [&]<class M>(const auto& get) {
    SkyTexels<M> t;
    t.base = float4<M>(get(0), get(1), get(2), get(3));
    t.s00 = float4<M>(get(4), get(5), get(6), get(7));
    t.s01 = float4<M>(get(8), get(9), get(10), get(11));
    t.s10 = float4<M>(get(12), get(13), get(14), get(15));
    t.s11 = float4<M>(get(16), get(17), get(18), get(19));
    SkyInputs<M> in;
    in.uv_in_texels = float2<M>(get(20), get(21));
    return sky_combine<C>(t, in, p);
  });
}

template <class L, WaterCombo C>
void BM_Water(benchmark::State& state) {
  const WaterParams p = water_constants(WaterMaterial{}, HdrType::integer, ToneMapConstants{});
  run<L>(state, [&]<class M>(const auto& get) {
    WaterNormalTexels<M> t;
    t.n0 = float4<M>(get(0), get(1), get(2), get(3));
    t.n1 = float4<M>(get(4), get(5), get(6), get(7));
    t.n2 = float4<M>(get(8), get(9), get(10), get(11));
    WaterInputs<M> in;
    in.tangent_eye = float3<M>(get(12), get(13), get(14));
    in.reflect_refract = float4<M>(get(15), get(16), get(17), get(18));
    in.w = get(19);
    in.proj_z = get(20);
    // Analytic render targets: the reads' texture cost is not part of this benchmark.
    auto target = [](const float2<M>& uv) { return float4<M>(uv.x, uv.y, uv.x * uv.y, uv.y); };
    return water_combine<C>(t, in, p, target, target);
  });
}

template <class L, LuminanceRangeCombo C>
void BM_LuminanceRange(benchmark::State& state) {
  LuminanceRangeParams p;
  p.min_max_scale = luminance_range_constant(0.2f, 0.6f);
  run<L>(state, [&]<class M>(const auto& get) {
    return luminance_range_combine<C>(float3<M>(get(0), get(1), get(2)), p).color;
  });
}

/// The models the SDK's rules allow combo c on (LightmappedGeneric, UnlitGeneric).
template <class Combo>
std::string models_of(const Combo& c) {
  std::string r;
  for (ShaderModel m : kPixelModels)
    if (c.valid(m)) r += std::string(r.empty() ? "" : ",") + std::string(caps(m).name);
  return r;
}

/// VertexLitGeneric: the models combo C compiles on (the rules and the counted limits).
template <VertexLitCombo C>
std::string models_of() {
  std::string r;
  for (ShaderModel m : kPixelModels)
    if (vertexlit_compiles<C>(m)) r += std::string(r.empty() ? "" : ",") + std::string(caps(m).name);
  return r;
}

const bool registered = [] {
  for_each_lightmapped_combo([]<LightmappedCombo C>() {
    const std::string name = "LightmappedGeneric/" + C.name() + "/" + models_of(C);
    benchmark::RegisterBenchmark((name + "/simd").c_str(), BM_Lightmapped<simd::Float, C>);
    benchmark::RegisterBenchmark((name + "/scalar").c_str(), BM_Lightmapped<float, C>);
  });
  for_each_vertexlit_combo([]<VertexLitCombo C>() {
    const std::string models = models_of<C>();
    if (models.empty()) return;  // allowed by the rules but over every model's limits (luxel cost shows why)
    std::string name = "VertexLitGeneric/" + C.name() + "/" + models;
    for (char& ch : name)
      if (ch == ' ') ch = '_';
    benchmark::RegisterBenchmark((name + "/simd").c_str(), BM_VertexLit<simd::Float, C>);
    benchmark::RegisterBenchmark((name + "/scalar").c_str(), BM_VertexLit<float, C>);
  });
  for_each_unlit_combo([]<UnlitCombo C>() {
    const std::string name = "UnlitGeneric/" + C.name() + "/" + models_of(C);
    benchmark::RegisterBenchmark((name + "/simd").c_str(), BM_Unlit<simd::Float, C>);
    benchmark::RegisterBenchmark((name + "/scalar").c_str(), BM_Unlit<float, C>);
  });
  for_each_sky_combo([]<SkyCombo C>() {
    const std::string name = "Sky_HDR/" + C.name() + "/ps_2_0,ps_2_b,ps_3_0";
    benchmark::RegisterBenchmark((name + "/simd").c_str(), BM_Sky<simd::Float, C>);
    benchmark::RegisterBenchmark((name + "/scalar").c_str(), BM_Sky<float, C>);
  });
  for_each_water_combo([]<WaterCombo C>() {
    std::string models;
    for (ShaderModel m : kPixelModels)
      if (C.valid(m)) models += std::string(models.empty() ? "" : ",") + std::string(caps(m).name);
    const std::string name = "Water/" + C.name() + "/" + models;
    benchmark::RegisterBenchmark((name + "/simd").c_str(), BM_Water<simd::Float, C>);
    benchmark::RegisterBenchmark((name + "/scalar").c_str(), BM_Water<float, C>);
  });
  for_each_luminance_range_combo([]<LuminanceRangeCombo C>() {
    const std::string name = "LuminanceRange/" + C.name() + "/ps_2_0,ps_2_b,ps_3_0";
    benchmark::RegisterBenchmark((name + "/simd").c_str(), BM_LuminanceRange<simd::Float, C>);
    benchmark::RegisterBenchmark((name + "/scalar").c_str(), BM_LuminanceRange<float, C>);
  });
  return true;
}();

}  // namespace
}  // namespace luxel::shading::source
