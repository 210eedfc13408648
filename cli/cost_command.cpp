// luxel cost [--shader all|lightmapped|vertexlit|unlit|sky|water|luminance] [--pixels N]: every
// Source shader variant on every pixel-shader model — counted DX9 slots, temps, constants, the
// model's limits, whether it fits — and measured ns/pixel on the SIMD and scalar lanes (a short
// timing loop: a report, not a benchmark; bench/shading_source_bench.cpp has the careful numbers).

#include "commands.hpp"

#include "luxel/shading/source/lightmapped_generic.hpp"
#include "luxel/shading/source/luminance_range.hpp"
#include "luxel/shading/source/sky.hpp"
#include "luxel/shading/source/spherical_harmonics.hpp"
#include "luxel/shading/source/unlit_generic.hpp"
#include "luxel/shading/source/vertexlit_generic.hpp"
#include "luxel/shading/source/water.hpp"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace luxel::cli {

namespace {

namespace src = shading::source;
using shading::Cost;
using shading::ShaderModel;
namespace simd = rasterizer::simd;

struct CostOptions {
  std::string shader = "all";
  int pixels = 1 << 15;
};

/// Random inputs for a shader body: K values per pixel.
struct Inputs {
  std::vector<float> v;
  int k, pixels;
  Inputs(int k_, int pixels_) : v(static_cast<size_t>(k_) * pixels_), k(k_), pixels(pixels_) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> d(0.05f, 1.0f);  // no NaN/denormal slow paths in a timing loop
    for (float& x : v) x = d(rng);
  }
};

/// ns per pixel of `shade` (a generic lambda over the lane taking get(i)) on the SIMD and scalar lanes.
template <class Shade>
std::pair<double, double> time_shader(Shade&& shade, int k, int pixels) {
  const Inputs in(k, pixels);
  using clock = std::chrono::steady_clock;
  volatile float sink = 0.0f;
  // SIMD: inputs stored per stamp, input-major within the stamp.
  auto t0 = clock::now();
  for (int p = 0; p + simd::kLanes <= pixels; p += simd::kLanes) {
    const float* base = in.v.data() + static_cast<size_t>(p) * k;
    auto get = [&](int i) { return simd::Float::load_unaligned(base + static_cast<size_t>(i) * simd::kLanes); };
    const auto c = shade.template operator()<simd::Float>(get);
    alignas(64) float lanes[simd::kLanes];
    (c.x + c.w).store_aligned(lanes);
    sink = sink + lanes[0];
  }
  auto t1 = clock::now();
  for (int p = 0; p < pixels; ++p) {
    const float* base = in.v.data() + static_cast<size_t>(p) * k;
    auto get = [&](int i) { return base[i]; };
    const auto c = shade.template operator()<float>(get);
    sink = sink + c.x + c.w;
  }
  auto t2 = clock::now();
  const double simd_ns = std::chrono::duration<double, std::nano>(t1 - t0).count() / pixels;
  const double scalar_ns = std::chrono::duration<double, std::nano>(t2 - t1).count() / pixels;
  return {simd_ns, scalar_ns};
}

void print_header() {
  std::printf("%-18s %-46s %-7s %5s %4s %5s %6s %5s  %-26s %-4s %8s %8s\n", "shader", "variant", "model", "arith", "tex",
              "temps", "consts", "indir", "limits (arith/tex/tmp/c)", "fits", "ns simd", "ns scal");
}

std::string limit(int v) { return v >= shading::kUnlimited ? "-" : std::to_string(v); }

void print_row(const char* shader, const std::string& variant, ShaderModel m, const Cost& c, double simd_ns,
               double scalar_ns) {
  const shading::ShaderModelCaps& k = shading::caps(m);
  const std::string limits = (k.arithmetic_slots >= shading::kUnlimited ? std::to_string(k.total_slots) + " total"
                                                                        : limit(k.arithmetic_slots) + "/" + limit(k.texture_slots)) +
                             "/" + std::to_string(k.temps) + "/" + std::to_string(k.constants);
  const bool ok = static_cast<bool>(shading::fits(c, k));
  std::printf("%-18s %-46s %-7s %5d %4d %5d %6d %5d  %-26s %-4s %8.1f %8.1f\n", shader, variant.c_str(),
              std::string(k.name).c_str(), c.arithmetic_slots, c.texture_slots, c.temps, c.constant_registers(),
              c.texture_indirections, limits.c_str(), ok ? "yes" : "NO", simd_ns, scalar_ns);
}

/// Times one static combo on both lanes and prints a row for every shader model it exists on.
template <class Combo, class Shade, class Measure>
void report_combo(const char* shader, const Combo& combo, Shade&& shade, int inputs, int pixels, Measure&& measure) {
  const auto [simd_ns, scalar_ns] = time_shader(shade, inputs, pixels);
  for (ShaderModel m : src::kPixelModels) {
    if constexpr (requires { combo.valid(m); }) {
      if (!combo.valid(m)) continue;
    }
    print_row(shader, combo.name(), m, measure(m), simd_ns, scalar_ns);
  }
}

void report_lightmapped(int pixels) {
  src::LightmappedGenericParams p;
  p.fresnel = src::fresnel_constant(0.2f);
  src::for_each_lightmapped_combo([&]<src::LightmappedCombo C>() {
    auto shade = [&]<class L>(const auto& get) {
      src::LightmappedTexels<L> t;
      t.base = shading::float4<L>(get(0), get(1), get(2), get(3));
      t.bump = shading::float4<L>(get(4), get(5), get(6), get(7));
      t.mask = shading::float3<L>(get(8), get(9), get(10));
      for (int i = 0; i < 4; ++i) t.lightmap[i] = shading::float3<L>(get(11), get(12), get(13)) * float(i + 1);
      src::LightmappedInputs<L> in;
      in.tangent = shading::float3<L>(get(14), get(15), get(16));
      in.binormal = shading::float3<L>(get(17), get(18), get(19));
      in.normal = shading::float3<L>(get(20), get(21), get(22));
      in.eye_vector = shading::float3<L>(get(23), get(24), get(25));
      return src::lightmapped_generic_combine<C>(t, in, p, [](const shading::float3<L>& r) { return r * r; });
    };
    report_combo("LightmappedGeneric", C, shade, 26, pixels, [](ShaderModel m) { return src::measure_lightmapped_generic<C>(m); });
  });
}

void report_vertexlit(int pixels) {
  src::VertexLitParams p;
  for (auto& l : p.lights) {
    l.color = glm::vec4(1.0f, 0.8f, 0.6f, 0.0f);
    l.position = glm::vec4(2.0f, 1.0f, 3.0f, 1.0f);
  }
  src::for_each_vertexlit_combo([&]<src::VertexLitCombo C>() {
    auto shade = [&]<class L>(const auto& get) {
      src::VertexLitTexels<L> t;
      t.base = shading::float4<L>(get(0), get(1), get(2), get(3));
      t.bump = shading::float4<L>(get(4), get(5), get(6), get(7));
      t.exponent = shading::float4<L>(get(8), get(9), get(10), get(11));
      src::VertexLitInputs<L> in;
      in.world_pos = shading::float3<L>(get(12), get(13), get(14));
      in.normal = shading::float3<L>(get(15), get(16), get(17));
      in.tangent = shading::float3<L>(get(18), get(19), get(20));
      in.binormal = shading::float3<L>(get(21), get(22), get(23));
      in.attenuation = shading::float4<L>(get(24), get(25), get(26), get(27));
      return src::vertexlit_combine<C>(t, in, p);
    };
    report_combo("VertexLitGeneric", C, shade, 28, pixels, [](ShaderModel m) { return src::measure_vertexlit_generic<C>(m); });
  });
}

void report_unlit(int pixels) {
  src::UnlitGenericParams p;
  p.envmap_contrast = glm::vec4(0.5f);
  src::for_each_unlit_combo([&]<src::UnlitCombo C>() {
    auto shade = [&]<class L>(const auto& get) {
      src::UnlitTexels<L> t;
      t.base = shading::float4<L>(get(0), get(1), get(2), get(3));
      t.detail = shading::float4<L>(get(4), get(5), get(6), get(7));
      t.mask = shading::float3<L>(get(8), get(9), get(10));
      src::UnlitInputs<L> in;
      in.vertex_color = shading::float4<L>(get(11), get(12), get(13), get(14));
      in.eye_vector = shading::float3<L>(get(15), get(16), get(17));
      in.normal = shading::float3<L>(get(18), get(19), get(20));
      return src::unlit_generic_combine<C>(t, in, p, [](const shading::float3<L>& r) { return r * r; });
    };
    report_combo("UnlitGeneric", C, shade, 21, pixels, [](ShaderModel m) { return src::measure_unlit_generic<C>(m); });
  });
}

void report_sky(int pixels) {
  src::SkyParams p;
  p.input_scale = glm::vec4(src::sky_input_scale(src::SkyFormat::rgba16), 1.0f);
  src::for_each_sky_combo([&]<src::SkyCombo C>() {
    auto shade = [&]<class L>(const auto& get) {
      src::SkyTexels<L> t;
      t.base = shading::float4<L>(get(0), get(1), get(2), get(3));
      t.s00 = shading::float4<L>(get(4), get(5), get(6), get(7));
      t.s01 = shading::float4<L>(get(8), get(9), get(10), get(11));
      t.s10 = shading::float4<L>(get(12), get(13), get(14), get(15));
      t.s11 = shading::float4<L>(get(16), get(17), get(18), get(19));
      src::SkyInputs<L> in;
      in.uv_in_texels = shading::float2<L>(get(20), get(21));
      return src::sky_combine<C>(t, in, p);
    };
    report_combo("Sky_HDR", C, shade, 22, pixels, [](ShaderModel m) { return src::measure_sky<C>(m); });
  });
}

void report_water(int pixels) {
  const src::WaterParams p = src::water_constants(src::WaterMaterial{}, src::HdrType::integer, src::ToneMapConstants{});
  src::for_each_water_combo([&]<src::WaterCombo C>() {
    auto shade = [&]<class L>(const auto& get) {
      src::WaterNormalTexels<L> t;
      t.n0 = shading::float4<L>(get(0), get(1), get(2), get(3));
      t.n1 = shading::float4<L>(get(4), get(5), get(6), get(7));
      t.n2 = shading::float4<L>(get(8), get(9), get(10), get(11));
      src::WaterInputs<L> in;
      in.tangent_eye = shading::float3<L>(get(12), get(13), get(14));
      in.reflect_refract = shading::float4<L>(get(15), get(16), get(17), get(18));
      in.w = get(19);
      in.proj_z = get(20);
      auto target = [](const shading::float2<L>& uv) { return shading::float4<L>(uv.x, uv.y, uv.x * uv.y, uv.y); };
      return src::water_combine<C>(t, in, p, target, target);
    };
    report_combo("Water", C, shade, 21, pixels, [](ShaderModel m) { return src::measure_water<C>(m); });
  });
}

void report_luminance(int pixels) {
  src::LuminanceRangeParams p;
  p.min_max_scale = src::luminance_range_constant(0.2f, 0.6f);
  src::for_each_luminance_range_combo([&]<src::LuminanceRangeCombo C>() {
    auto shade = [&]<class L>(const auto& get) {
      return src::luminance_range_combine<C>(shading::float3<L>(get(0), get(1), get(2)), p).color;
    };
    report_combo("LuminanceRange", C, shade, 3, pixels, [](ShaderModel m) { return src::measure_luminance_range<C>(m); });
  });
}

void report_ambient_cube() {
  src::AmbientCube cube;
  auto body = [&](shading::CountedInputs& in) { return src::ambient_light<shading::Counted>(in.vector<3>(), cube); };
  const int ps30 = shading::measure(ShaderModel::ps_3_0, body).arithmetic_slots;
  const int ps20 = shading::measure(ShaderModel::ps_2_0, body).arithmetic_slots;
  const int vs20 = shading::measure(ShaderModel::vs_2_0, body).arithmetic_slots;
  std::printf("\nambient cube: ps_3_0 %d, ps_2_0 %d (+mov oC0), vs_2_0 %d slots | published: 11 PS / 6 VS (2006 notes), "
              "9 PS (SDK comment)\n",
              ps30, ps20, vs20);
  std::printf("  PS = the SDK's 9 (mul, cmp, cmp, mul, mad x5; the notes' 11 predate it); VS 6 needs relative "
              "addressing (mova), we select with slt/sge + lrp instead.\n");
  const src::Sh9Ambient sh9;
  const shading::Cost sh = shading::measure(ShaderModel::ps_3_0, [&](shading::CountedInputs& in) {
    return src::sh9_ambient_light<shading::Counted>(in.vector<3>(), sh9);
  });
  std::printf("SH9 ambient (ps_3_0 option): %d slots, %d constant registers (cube: %d slots, 6 registers); "
              "error vs ground truth: tests/shading/sh9_test.cpp, bench/README.md\n",
              sh.arithmetic_slots, sh.uniform_registers, ps30);
}

}  // namespace

Runner add_cost_command(CLI::App& app) {
  auto options = std::make_shared<CostOptions>();
  CLI::App* cmd = app.add_subcommand("cost", "Print DX9 slot counts, limits and ns/pixel of every Source shader variant");
  cmd->add_option("--shader", options->shader, "all, lightmapped, vertexlit, unlit, sky, water or luminance")
      ->check(CLI::IsMember({"all", "lightmapped", "vertexlit", "unlit", "sky", "water", "luminance"}))
      ->capture_default_str();
  cmd->add_option("--pixels", options->pixels, "Pixels per timing loop")->check(CLI::Range(64, 1 << 24))->capture_default_str();
  return [cmd, options]() -> int {
    if (!cmd->parsed()) return -1;
    print_header();
    if (options->shader == "all" || options->shader == "lightmapped") report_lightmapped(options->pixels);
    if (options->shader == "all" || options->shader == "vertexlit") report_vertexlit(options->pixels);
    if (options->shader == "all" || options->shader == "unlit") report_unlit(options->pixels);
    if (options->shader == "all" || options->shader == "sky") report_sky(options->pixels);
    if (options->shader == "all" || options->shader == "water") report_water(options->pixels);
    if (options->shader == "all" || options->shader == "luminance") report_luminance(options->pixels);
    report_ambient_cube();
    return 0;
  };
}

}  // namespace luxel::cli
