// The VertexLitGeneric vertex shader, Sky_HDR and the post-processing shaders in the catalog
// (catalog_entries.hpp): every combo of the registry, and the post shaders without static combos.

#include "catalog_entries.hpp"

#include "luxel/shading/source/bloom_add.hpp"
#include "luxel/shading/source/bloom_blur.hpp"
#include "luxel/shading/source/bloom_downsample.hpp"
#include "luxel/shading/source/film_grain.hpp"

namespace luxel::shading::source::detail {

namespace {

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
  for_each_combo<kVertexLitVsSpace>([&]<VertexLitVsCombo C>() {
    auto shade = []<class L>(const auto& get) {
      VertexLitVsInputs<L> v;
      v.position = float4<L>(get(0), get(1), get(2), L(1.0f));
      v.normal = float3<L>(get(3), get(4), get(5));
      v.uv = float2<L>(get(6), get(7));
      const VertexLitVsOutputs<L> o = vertexlit_vertex_shader<C>(v, p);
      return float4<L>(o.lighting + o.proj_pos.xyz(), o.fog);
    };
    out.push_back(variant("VertexLitGeneric_vs", "vertexlit_vs", C, C.builds(), 8, shade,
                          registry_cost<C>, kVertexModels));
  });
}

void add_sky(std::vector<ShaderVariant>& out) {
  static SkyParams p = [] {
    SkyParams q;
    q.input_scale = glm::vec4(sky_input_scale(SkyFormat::rgba16), 1.0f);
    return q;
  }();
  for_each_combo<kSkySpace>([&]<SkyCombo C>() {
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
    out.push_back(variant("Sky_HDR", "sky", C, C.builds(), 22, shade, registry_cost<C>));
  });
}

void add_luminance_range(std::vector<ShaderVariant>& out) {
  static const LuminanceRangeParams p = [] {
    LuminanceRangeParams q;
    q.min_max_scale = luminance_range_constant(0.2f, 0.6f);
    return q;
  }();
  for_each_combo<kLuminanceRangeSpace>([&]<LuminanceRangeCombo C>() {
    auto shade = []<class L>(const auto& get) {
      return luminance_range_combine<C>(float3<L>(get(0), get(1), get(2)), p).color;
    };
    out.push_back(variant(LuminanceRangePixelShader<C>::kFamily, "luminance", C, LuminanceRangePixelShader<C>::kBuilds, 3, shade,
                          registry_cost<C>));
  });
}

void add_color_correction(std::vector<ShaderVariant>& out) {
  static const ColorCorrectionParams p = [] {
    ColorCorrectionParams q;
    q.lut_weights = glm::vec4(0.2f, 0.15f, 0.1f, 0.05f);
    q.default_weight = 0.5f;
    return q;
  }();
  for_each_combo<kColorCorrectionSpace>([&]<ColorCorrectionCombo C>() {
    auto shade = []<class L>(const auto& get) {
      std::array<float3<L>, kMaxColorCorrectionLuts> lookups;
      for (int k = 0; k < kMaxColorCorrectionLuts; ++k) lookups[k] = float3<L>(get(3 + 3 * k), get(4 + 3 * k), get(5 + 3 * k));
      return float4<L>(color_correction_combine<C>(float3<L>(get(0), get(1), get(2)), lookups, p.lut_weights, p.default_weight),
                       L(1.0f));
    };
    out.push_back(variant(ColorCorrectionPixelShader<C>::kFamily, "colorcorrection", C, ColorCorrectionPixelShader<C>::kBuilds, 3 + 3 * kMaxColorCorrectionLuts, shade,
                          registry_cost<C>));
  });
}

void add_engine_post(std::vector<ShaderVariant>& out) {
  static const EnginePostParams p = [] {
    EnginePostParams q;
    q.lut_weights = glm::vec4(0.2f, 0.15f, 0.1f, 0.05f);
    q.default_weight = 0.5f;
    return q;
  }();
  for_each_combo<kEnginePostSpace>([&]<EnginePostCombo C>() {
    auto shade = []<class L>(const auto& get) {
      const float3<L> bloomed = engine_post_bloomed(float3<L>(get(0), get(1), get(2)), float3<L>(get(3), get(4), get(5)), p);
      std::array<float3<L>, kMaxColorCorrectionLuts> lookups;
      for (int k = 0; k < kMaxColorCorrectionLuts; ++k) lookups[k] = float3<L>(get(6 + 3 * k), get(7 + 3 * k), get(8 + 3 * k));
      return float4<L>(color_correction_combine<C.correction()>(bloomed, lookups, p.lut_weights, p.default_weight), L(1.0f));
    };
    out.push_back(variant(EnginePostPixelShader<C>::kFamily, "enginepost", C, EnginePostPixelShader<C>::kBuilds, 6 + 3 * kMaxColorCorrectionLuts, shade,
                          registry_cost<C>));
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

void add_small_families(std::vector<ShaderVariant>& out) {
  add_vertexlit_vs(out);
  add_sky(out);
  add_luminance_range(out);
  add_color_correction(out);
  add_bloom(out);
  add_engine_post(out);
  add_film_grain(out);
}

}  // namespace luxel::shading::source::detail
