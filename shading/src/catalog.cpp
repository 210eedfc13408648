// The shader catalog (catalog.hpp): each family's combos with their inputs for timing.

#include "luxel/shading/source/catalog.hpp"

#include "luxel/shading/source/bloom_add.hpp"
#include "luxel/shading/source/bloom_blur.hpp"
#include "luxel/shading/source/bloom_downsample.hpp"
#include "luxel/shading/source/color_correction.hpp"
#include "luxel/shading/source/engine_post.hpp"
#include "luxel/shading/source/film_grain.hpp"
#include "luxel/shading/source/lightmapped_generic.hpp"
#include "luxel/shading/source/luminance_range.hpp"
#include "luxel/shading/source/sky.hpp"
#include "luxel/shading/source/unlit_generic.hpp"
#include "luxel/shading/source/vertexlit_generic.hpp"
#include "luxel/shading/source/vertexlit_vertex_shader.hpp"
#include "luxel/shading/source/water.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <random>
#include <optional>
#include <span>

// Each family's constants are a static that the shade lambdas (generic, inside a template lambda)
// read; GCC 12 still calls those statics "set but not used".
#pragma GCC diagnostic ignored "-Wunused-but-set-variable"

namespace luxel::shading::source {

namespace {

/// K random inputs per pixel, in [0.05, 1]: no NaN or denormal slow paths in a timing loop.
struct TimingInputs {
  std::vector<float> v;
  TimingInputs(int k, int pixels) : v(static_cast<size_t>(k) * pixels) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> d(0.05f, 1.0f);
    for (float& x : v) x = d(rng);
  }
};

/// Median ns per pixel of `shade` (a generic lambda over the lane taking get(i)) on both lanes.
template <class Shade>
LaneTimes time_lanes(const Shade& shade, int k, int pixels, int repeats) {
  pixels = std::max(pixels, simd::kLanes) / simd::kLanes * simd::kLanes;
  const TimingInputs in(k, pixels);
  using clock = std::chrono::steady_clock;
  volatile float sink = 0.0f;
  std::vector<double> simd_ns, scalar_ns;
  for (int r = 0; r < std::max(repeats, 1); ++r) {
    // SIMD: inputs stored per stamp, input-major within the stamp.
    const auto t0 = clock::now();
    for (int p = 0; p < pixels; p += simd::kLanes) {
      const float* base = in.v.data() + static_cast<size_t>(p) * k;
      auto get = [&](int i) { return simd::Float::load_unaligned(base + static_cast<size_t>(i) * simd::kLanes); };
      const float4<simd::Float> c = shade.template operator()<simd::Float>(get);
      alignas(64) float lanes[simd::kLanes];
      (c.x + c.w).store_aligned(lanes);
      sink = sink + lanes[0];
    }
    const auto t1 = clock::now();
    for (int p = 0; p < pixels; ++p) {
      const float* base = in.v.data() + static_cast<size_t>(p) * k;
      auto get = [&](int i) { return base[i]; };
      const float4<float> c = shade.template operator()<float>(get);
      sink = sink + c.x + c.w;
    }
    const auto t2 = clock::now();
    simd_ns.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() / pixels);
    scalar_ns.push_back(std::chrono::duration<double, std::nano>(t2 - t1).count() / pixels);
  }
  auto median = [](std::vector<double>& v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  return {median(simd_ns), median(scalar_ns)};
}

/// `shade` on the SIMD lane and, pixel by pixel, on the scalar lane over the same inputs (the
/// timing's, each SIMD lane's values fed to the scalar pixel it stands for), compared.
template <class Shade>
LaneAgreement compare_lanes(const Shade& shade, int k, int pixels) {
  pixels = std::max(pixels, simd::kLanes) / simd::kLanes * simd::kLanes;
  const TimingInputs in(k, pixels);
  const auto to_steps = [](float v) { return int(std::lround(std::clamp(double(v), 0.0, 1.0) * 255.0)); };
  LaneAgreement r;
  for (int p = 0; p < pixels; p += simd::kLanes) {
    const float* base = in.v.data() + static_cast<size_t>(p) * k;
    auto get = [&](int i) { return simd::Float::load_unaligned(base + static_cast<size_t>(i) * simd::kLanes); };
    const float4<simd::Float> c = shade.template operator()<simd::Float>(get);
    alignas(64) float lanes[4][simd::kLanes];
    c.x.store_aligned(lanes[0]), c.y.store_aligned(lanes[1]), c.z.store_aligned(lanes[2]), c.w.store_aligned(lanes[3]);
    for (int j = 0; j < simd::kLanes; ++j) {
      auto get_scalar = [&](int i) { return base[static_cast<size_t>(i) * simd::kLanes + static_cast<size_t>(j)]; };
      const float4<float> s = shade.template operator()<float>(get_scalar);
      const float scalar[4] = {s.x, s.y, s.z, s.w};
      bool differs = false;
      for (int ch = 0; ch < 4; ++ch) {
        const float a = lanes[ch][j], b = scalar[ch];
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

/// The cards of `candidates` (the pixel-shader models unless told otherwise) that have a binary of
/// the combo (`builds`) which the combo's rules allow (its valid(model), where the family has one).
template <class Combo>
std::vector<ShaderModel> models_of(const Combo& combo, ShaderBuilds builds, std::span<const ShaderModel> candidates) {
  std::vector<ShaderModel> models;
  for (ShaderModel card : candidates) {
    const std::optional<ShaderModel> binary = builds.binary_for(card);
    if (!binary) continue;
    if constexpr (requires { combo.valid(*binary); }) {
      if (!combo.valid(*binary)) continue;
    }
    models.push_back(card);
  }
  return models;
}

template <class Combo, class Shade, class Measure>
ShaderVariant variant(const char* family, const char* option, const Combo& combo, ShaderBuilds builds, int inputs,
                      Shade shade, Measure measure, std::span<const ShaderModel> candidates = kPixelModels) {
  return {family, option, combo.name(), models_of(combo, builds, candidates), builds, measure,
          [shade, inputs](int pixels, int repeats) { return time_lanes(shade, inputs, pixels, repeats); },
          [shade, inputs](int pixels) { return compare_lanes(shade, inputs, pixels); }};
}

void add_lightmapped(std::vector<ShaderVariant>& out) {
  static LightmappedGenericParams p = [] {
    LightmappedGenericParams q;
    q.fresnel = fresnel_constant(0.2f);
    return q;
  }();
  for_each_lightmapped_combo([&]<LightmappedCombo C>() {
    auto shade = []<class L>(const auto& get) {
      LightmappedTexels<L> t;
      t.base = float4<L>(get(0), get(1), get(2), get(3));
      t.bump = float4<L>(get(4), get(5), get(6), get(7));
      t.mask = float3<L>(get(8), get(9), get(10));
      for (int i = 0; i < 4; ++i) t.lightmap[i] = float3<L>(get(11), get(12), get(13)) * float(i + 1);
      LightmappedInputs<L> in;
      in.tangent = float3<L>(get(14), get(15), get(16));
      in.binormal = float3<L>(get(17), get(18), get(19));
      in.normal = float3<L>(get(20), get(21), get(22));
      in.eye_vector = float3<L>(get(23), get(24), get(25));
      in.fog = FogInputs<L>{get(26), get(27)};
      return lightmapped_generic_combine<C>(t, in, p, [](const float3<L>& r) { return r * r; });
    };
    out.push_back(variant("LightmappedGeneric", "lightmapped", C, C.builds(), 28, shade,
                          [](ShaderModel m) { return measure_lightmapped_generic<C>(m); }));
  });
}

void add_vertexlit(std::vector<ShaderVariant>& out) {
  static const rasterizer::Texture normalization_cube = normalization_cube_map();  // the ps_2_0 combos
  static VertexLitParams p = [] {
    VertexLitParams q;
    for (auto& l : q.lights) {
      l.color = glm::vec4(1.0f, 0.8f, 0.6f, 0.0f);
      l.position = glm::vec4(2.0f, 1.0f, 3.0f, 1.0f);
    }
    q.normalization_cube.texture = &normalization_cube;
    return q;
  }();
  for_each_vertexlit_combo([&]<VertexLitCombo C>() {
    auto shade = []<class L>(const auto& get) {
      VertexLitTexels<L> t;
      t.base = float4<L>(get(0), get(1), get(2), get(3));
      t.bump = float4<L>(get(4), get(5), get(6), get(7));
      t.exponent = float4<L>(get(8), get(9), get(10), get(11));
      VertexLitInputs<L> in;
      in.world_pos = float3<L>(get(12), get(13), get(14));
      in.normal = float3<L>(get(15), get(16), get(17));
      in.tangent = float3<L>(get(18), get(19), get(20));
      in.binormal = float3<L>(get(21), get(22), get(23));
      in.attenuation = float4<L>(get(24), get(25), get(26), get(27));
      in.proj_z = get(28);
      return vertexlit_combine<C>(t, in, p, [](const float3<L>& r) { return r * r; });
    };
    out.push_back(variant("VertexLitGeneric", "vertexlit", C, C.builds(), 29, shade,
                          [](ShaderModel m) { return measure_vertexlit_generic<C>(m); }));
  });
}

/// The per-vertex VertexLitGeneric vertex shader on vs_2_0 / vs_3_0: timed per vertex.
void add_vertexlit_vs(std::vector<ShaderVariant>& out) {
  static VertexLitVsParams p = [] {
    VertexLitVsParams q;
    for (auto& l : q.lights) {
      l.color = glm::vec4(1.0f, 0.8f, 0.6f, 0.0f);
      l.position = glm::vec4(2.0f, 1.0f, 3.0f, 1.0f);
    }
    return q;
  }();
  for_each_vertexlit_vs_combo([&]<VertexLitVsCombo C>() {
    auto shade = []<class L>(const auto& get) {
      VertexLitVsInputs<L> v;
      v.position = float4<L>(get(0), get(1), get(2), L(1.0f));
      v.normal = float3<L>(get(3), get(4), get(5));
      v.uv = float2<L>(get(6), get(7));
      const VertexLitVsOutputs<L> o = vertexlit_vertex_shader<C>(v, p);
      return float4<L>(o.lighting + o.proj_pos.xyz(), o.fog);
    };
    out.push_back(variant("VertexLitGeneric_vs", "vertexlit_vs", C, C.builds(), 8, shade,
                          [](ShaderModel m) { return measure_vertexlit_vertex_shader<C>(m); }, kVertexModels));
  });
}

void add_unlit(std::vector<ShaderVariant>& out) {
  static UnlitGenericParams p = [] {
    UnlitGenericParams q;
    q.envmap_contrast = glm::vec4(0.5f);
    return q;
  }();
  for_each_unlit_combo([&]<UnlitCombo C>() {
    auto shade = []<class L>(const auto& get) {
      UnlitTexels<L> t;
      t.base = float4<L>(get(0), get(1), get(2), get(3));
      t.detail = float4<L>(get(4), get(5), get(6), get(7));
      t.mask = float3<L>(get(8), get(9), get(10));
      UnlitInputs<L> in;
      in.vertex_color = float4<L>(get(11), get(12), get(13), get(14));
      in.eye_vector = float3<L>(get(15), get(16), get(17));
      in.normal = float3<L>(get(18), get(19), get(20));
      in.fog = FogInputs<L>{get(21), get(22)};
      return unlit_generic_combine<C>(t, in, p, [](const float3<L>& r) { return r * r; });
    };
    // DIFFUSELIGHTING is VertexLitGeneric without a bump map: listed, and asked for, under it.
    out.push_back(variant(C.family(), C.diffuse_lighting ? "vertexlit" : "unlit", C, C.builds(), 23, shade,
                          [](ShaderModel m) { return measure_unlit_generic<C>(m); }));
  });
}

void add_sky(std::vector<ShaderVariant>& out) {
  static SkyParams p = [] {
    SkyParams q;
    q.input_scale = glm::vec4(sky_input_scale(SkyFormat::rgba16), 1.0f);
    return q;
  }();
  for_each_sky_combo([&]<SkyCombo C>() {
    auto shade = []<class L>(const auto& get) {
      SkyTexels<L> t;
      t.base = float4<L>(get(0), get(1), get(2), get(3));
      t.s00 = float4<L>(get(4), get(5), get(6), get(7));
      t.s01 = float4<L>(get(8), get(9), get(10), get(11));
      t.s10 = float4<L>(get(12), get(13), get(14), get(15));
      t.s11 = float4<L>(get(16), get(17), get(18), get(19));
      SkyInputs<L> in;
      in.uv_in_texels = float2<L>(get(20), get(21));
      return sky_combine<C>(t, in, p);
    };
    out.push_back(variant("Sky_HDR", "sky", C, C.builds(), 22, shade, [](ShaderModel m) { return measure_sky<C>(m); }));
  });
}

void add_water(std::vector<ShaderVariant>& out) {
  static const WaterParams p = water_constants(WaterMaterial{}, HdrType::integer, ToneMapConstants{});
  for_each_water_combo([&]<WaterCombo C>() {
    auto shade = []<class L>(const auto& get) {
      WaterNormalTexels<L> t;
      t.n0 = float4<L>(get(0), get(1), get(2), get(3));
      t.n1 = float4<L>(get(4), get(5), get(6), get(7));
      t.n2 = float4<L>(get(8), get(9), get(10), get(11));
      WaterInputs<L> in;
      in.tangent_eye = float3<L>(get(12), get(13), get(14));
      in.reflect_refract = float4<L>(get(15), get(16), get(17), get(18));
      in.w = get(19);
      in.proj_z = get(20);
      in.world_z = get(21);
      auto target = [](const float2<L>& uv) { return float4<L>(uv.x, uv.y, uv.x * uv.y, uv.y); };
      return water_combine<C>(t, in, p, target, target);
    };
    out.push_back(variant("Water", "water", C, C.builds(), 22, shade, [](ShaderModel m) { return measure_water<C>(m); }));
  });
}

void add_luminance_range(std::vector<ShaderVariant>& out) {
  static const LuminanceRangeParams p = [] {
    LuminanceRangeParams q;
    q.min_max_scale = luminance_range_constant(0.2f, 0.6f);
    return q;
  }();
  for_each_luminance_range_combo([&]<LuminanceRangeCombo C>() {
    auto shade = []<class L>(const auto& get) {
      return luminance_range_combine<C>(float3<L>(get(0), get(1), get(2)), p).color;
    };
    out.push_back(variant(LuminanceRangePixelShader<C>::kFamily, "luminance", C, LuminanceRangePixelShader<C>::kBuilds, 3, shade,
                          [](ShaderModel m) { return measure_luminance_range<C>(m); }));
  });
}

void add_color_correction(std::vector<ShaderVariant>& out) {
  static const ColorCorrectionParams p = [] {
    ColorCorrectionParams q;
    q.lut_weights = glm::vec4(0.2f, 0.15f, 0.1f, 0.05f);
    q.default_weight = 0.5f;
    return q;
  }();
  for_each_color_correction_combo([&]<ColorCorrectionCombo C>() {
    auto shade = []<class L>(const auto& get) {
      std::array<float3<L>, kMaxColorCorrectionLuts> lookups;
      for (int k = 0; k < kMaxColorCorrectionLuts; ++k) lookups[k] = float3<L>(get(3 + 3 * k), get(4 + 3 * k), get(5 + 3 * k));
      return float4<L>(color_correction_combine<C>(float3<L>(get(0), get(1), get(2)), lookups, p.lut_weights, p.default_weight),
                       L(1.0f));
    };
    out.push_back(variant(ColorCorrectionPixelShader<C>::kFamily, "colorcorrection", C, ColorCorrectionPixelShader<C>::kBuilds, 3 + 3 * kMaxColorCorrectionLuts, shade,
                          [](ShaderModel m) { return measure_color_correction<C>(m); }));
  });
}

void add_engine_post(std::vector<ShaderVariant>& out) {
  static const EnginePostParams p = [] {
    EnginePostParams q;
    q.lut_weights = glm::vec4(0.2f, 0.15f, 0.1f, 0.05f);
    q.default_weight = 0.5f;
    return q;
  }();
  for_each_engine_post_combo([&]<EnginePostCombo C>() {
    auto shade = []<class L>(const auto& get) {
      const float3<L> bloomed = engine_post_bloomed(float3<L>(get(0), get(1), get(2)), float3<L>(get(3), get(4), get(5)), p);
      std::array<float3<L>, kMaxColorCorrectionLuts> lookups;
      for (int k = 0; k < kMaxColorCorrectionLuts; ++k) lookups[k] = float3<L>(get(6 + 3 * k), get(7 + 3 * k), get(8 + 3 * k));
      return float4<L>(color_correction_combine<C.correction()>(bloomed, lookups, p.lut_weights, p.default_weight), L(1.0f));
    };
    out.push_back(variant(EnginePostPixelShader<C>::kFamily, "enginepost", C, EnginePostPixelShader<C>::kBuilds, 6 + 3 * kMaxColorCorrectionLuts, shade,
                          [](ShaderModel m) { return measure_engine_post<C>(m); }));
  });
}

/// The post-processing shaders have no static combos: one variant each.
struct SingleVariant {
  std::string name() const { return kSingleCombo; }
};

void add_bloom(std::vector<ShaderVariant>& out) {
  static const DownsampleParams downsample_params{};
  auto downsample_shade = []<class L>(const auto& get) {
    std::array<float3<L>, 4> taps;
    for (int i = 0; i < 4; ++i) taps[i] = float3<L>(get(3 * i), get(3 * i + 1), get(3 * i + 2));
    return downsample_combine(taps, downsample_params);
  };
  out.push_back(variant(DownsamplePixelShader::kFamily, "downsample", SingleVariant{}, DownsamplePixelShader::kBuilds, 12, downsample_shade, measure_downsample));

  static const BlurParams blur_params = blur_constants(BlurAxis::vertical, 320, 180, BlurStep::sdk_width_quirk, 0.3f);
  auto blur_shade = []<class L>(const auto& get) {
    auto texel = [&](int i) { return float3<L>(get(3 * i), get(3 * i + 1), get(3 * i + 2)); };
    BlurTaps<L> t;
    t.centre = texel(0);
    for (int k = 0; k < 6; ++k) {
      t.plus[k] = texel(1 + k);
      t.minus[k] = texel(7 + k);
    }
    return blur_combine(t, blur_params);
  };
  out.push_back(variant(BlurPixelShader::kFamily, "blur", SingleVariant{}, BlurPixelShader::kBuilds, 39, blur_shade, measure_blur));

  auto add_shade = []<class L>(const auto& get) { return bloom_add_combine(float3<L>(get(0), get(1), get(2))); };
  out.push_back(variant(BloomAddPixelShader::kFamily, "bloomadd", SingleVariant{}, BloomAddPixelShader::kBuilds, 3, add_shade, measure_bloom_add));
}

void add_film_grain(std::vector<ShaderVariant>& out) {
  static const FilmGrainParams p = [] {
    FilmGrainParams q;
    q.noise_scale = glm::vec4(0.1f, 0.1f, 0.1f, 0.9f);
    return q;
  }();
  auto shade = []<class L>(const auto& get) { return film_grain_combine(float4<L>(get(0), get(1), get(2), get(3)), p); };
  out.push_back(variant(FilmGrainPixelShader::kFamily, "filmgrain", SingleVariant{}, FilmGrainPixelShader::kBuilds, 4, shade, measure_film_grain));
}

}  // namespace

const std::vector<ShaderVariant>& shader_catalog() {
  static const std::vector<ShaderVariant> catalog = [] {
    std::vector<ShaderVariant> c;
    add_lightmapped(c);
    add_vertexlit(c);
    add_vertexlit_vs(c);
    add_unlit(c);
    add_sky(c);
    add_water(c);
    add_luminance_range(c);
    add_color_correction(c);
    add_bloom(c);
    add_engine_post(c);
    add_film_grain(c);
    return c;
  }();
  return catalog;
}

}  // namespace luxel::shading::source
