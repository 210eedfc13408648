#pragma once
// UnlitGeneric, DX9 pixel shader: base texture x $color (x vertex color), an optional detail
// texture, an optional cube-map specular with mask, tint, contrast and saturation, ending in
// FinalOutput with LINEAR tone mapping and the fog of the combo (fog.hpp). The SDK builds it from
// vertexlit_and_unlit_generic_ps2x.fxc with DIFFUSELIGHTING = 0 (ps20, ps20b and ps30 builds),
// and VertexLitGeneric without a bump map from the same file with DIFFUSELIGHTING = 1: the
// lighting then comes per vertex from vertexlit_vertex_shader.hpp (two lights and the ambient
// cube, docs/fidelity.md#non-bumped-models) through the same i.color interpolant a vertex color
// uses, and only multiplies the albedo here. docs/fidelity.md#unlitgeneric-and-detail (envmap,
// detail modes), #gamma-and-colors (gamma of constants and detail), #tone-mapping (epilogue), #fog.
//
//   albedo   = detail_combine(base) x c1.rgb ($color, gamma -> linear on the CPU)
//   diffuse  = albedo x i.color.rgb (VERTEXCOLOR: the vertex color; DIFFUSELIGHTING: the vertex
//              shader's lighting) or albedo
//   spec     = c30.z x cube(R) x mask x c0.rgb ($envmaptint, gamma -> linear), R = 2(N·E)N - (N·N)E
//   spec     = lerp(spec, spec², contrast); spec = lerp(grey(spec), spec, saturation)
//   alpha    = c1.a x base.a (not with $basealphaenvmapmask), lerp(alpha, alpha x vertex.a, c12.w)
// Unlike LightmappedGeneric there is no fast path: contrast and saturation are always
// applied, and there is no Fresnel.
//
// Detail (TextureCombine): mode 0 mod2x, base.rgb x lerp(1, 2 detail.rgb, blend), with the
// detail read raw (sRGB off: 0.5 grey is neutral); mode 1 additive, base.rgb + blend x
// detail.rgb, with the detail sRGB-decoded (on for mode 1 on models). detail.rgb is multiplied by
// $detailtint (c10) first.
//
// Not implemented: detail modes 2-9, self-illum, $blendtintbybasealpha, seamless mapping,
// distance alpha, sphere-map envmaps, flashlight, depth to dest alpha; VERTEXCOLOR together with
// DIFFUSELIGHTING (the SDK's vertex shader then skips the lighting and the pixel shader multiplies
// by the vertex color twice), which valid() refuses.

#include "luxel/shading/source/binaries.hpp"
#include "luxel/shading/source/common.hpp"
#include "luxel/shading/source/fog.hpp"

#include <iterator>
#include <string>
#include <utility>

namespace luxel::shading::source {

enum class UnlitDetail { none, mod2x, additive };
enum class UnlitEnvmapMask { none, base_alpha_inverted, texture };

struct UnlitCombo {
  UnlitDetail detail = UnlitDetail::none;
  bool envmap = false;
  UnlitEnvmapMask mask = UnlitEnvmapMask::none;
  bool vertex_color = false;
  bool diffuse_lighting = false;  ///< DIFFUSELIGHTING: VertexLitGeneric lit per vertex
  Fog fog = Fog::none;

  /// A combination the SDK can produce (on some model).
  constexpr bool valid() const { return (envmap || mask == UnlitEnvmapMask::none) && !(vertex_color && diffuse_lighting); }
  /// ... on model m: the fog type decides (fog.hpp).
  constexpr bool valid(ShaderModel m) const { return valid() && fog_valid(fog, m); }
  /// vertexlit_and_unlit_generic_ps2x.fxc: ps20, ps20b and ps30.
  static constexpr ShaderBuilds builds() { return kPs2x30Builds; }
  /// The material family that draws with it: DIFFUSELIGHTING is VertexLitGeneric without a bump map.
  constexpr const char* family() const { return diffuse_lighting ? "VertexLitGeneric" : "UnlitGeneric"; }
  friend constexpr bool operator==(const UnlitCombo&, const UnlitCombo&) = default;
  std::string name() const {
    static const char* details[] = {"", "+detail_mod2x", "+detail_additive"};
    static const char* masks[] = {"", "+basealphamask", "+envmapmask"};
    std::string n = std::string(diffuse_lighting ? "vertexlit" : "base") + details[static_cast<int>(detail)] +
                    (envmap ? "+envmap" : "") + masks[static_cast<int>(mask)];
    return (vertex_color ? n + "+vertexcolor" : n) + fog_name(fog);
  }
};

/// Samplers and constants (registers as in the SDK shader).
struct UnlitGenericParams {
  Sampler2D base{0};
  SamplerCube envmap{1};
  Sampler2D detail{2};
  Sampler2D envmap_mask{4};
  glm::vec4 envmap_tint{1.0f, 1.0f, 1.0f, 0.0f};      ///< c0.rgb: $envmaptint, linear
  glm::vec4 modulation{1.0f};                         ///< c1: $color (linear) and alpha
  glm::vec4 envmap_contrast{0.0f};                    ///< c2.xyz: $envmapcontrast
  glm::vec4 envmap_saturation{1.0f};                  ///< c3.xyz: $envmapsaturation
  glm::vec4 detail_blend{0.0f, 0.0f, 0.0f, 1.0f};     ///< c4.w: $detailblendfactor
  glm::vec4 detail_tint{1.0f};                        ///< c10.rgb: $detailtint
  glm::vec4 shader_controls{0.0f};                    ///< c12.w: 1 with $vertexalpha
  ToneMapConstants tonemap{};
  FogConstants fog{};
};

template <Lane L>
struct UnlitInputs {
  float2<L> base_uv;
  float2<L> detail_uv;
  float4<L> vertex_color{1.0f};  ///< i.color: vertex color, or the vertex shader's lighting
  float3<L> eye_vector;  ///< world vertex -> eye, unnormalised
  float3<L> normal;      ///< world normal, interpolated
  FogInputs<L> fog{};
};

template <Lane L>
struct UnlitTexels {
  float4<L> base{1.0f};
  float4<L> detail{0.5f};
  float3<L> mask{1.0f};
};

template <UnlitCombo C, Lane L>
inline UnlitTexels<L> unlit_generic_fetch(const UnlitInputs<L>& in, const UnlitGenericParams& p) {
  static_assert(C.valid(), "an envmap mask needs an envmap");
  UnlitTexels<L> t;
  t.base = tex2D(p.base, in.base_uv);
  if constexpr (C.detail != UnlitDetail::none) t.detail = tex2D(p.detail, in.detail_uv);
  if constexpr (C.mask == UnlitEnvmapMask::texture) t.mask = tex2D(p.envmap_mask, in.base_uv).rgb();
  return t;
}

/// Everything after the independent reads; env(R) returns the cube map's rgb in direction R.
template <UnlitCombo C, Lane L, class EnvFn>
inline float4<L> unlit_generic_combine(const UnlitTexels<L>& t, const UnlitInputs<L>& in, const UnlitGenericParams& p,
                                       EnvFn&& env) {
  static_assert(C.valid(), "an envmap mask needs an envmap");
  float3<L> base = t.base.rgb();
  if constexpr (C.detail != UnlitDetail::none) {
    const float3<L> detail = t.detail.rgb() * constant<L>(p.detail_tint).rgb();
    const L blend = constant<L>(p.detail_blend).w;
    if constexpr (C.detail == UnlitDetail::mod2x) {
      base = base * lerp(float3<L>(1.0f), detail * 2.0f, blend);
    } else {
      base = base + detail * blend;
    }
  }
  const float4<L> modulation = constant<L>(p.modulation);
  float3<L> color = base * modulation.rgb();
  L alpha = modulation.w;
  if constexpr (C.mask != UnlitEnvmapMask::base_alpha_inverted) alpha = alpha * t.base.w;
  if constexpr (C.diffuse_lighting) color = color * in.vertex_color.rgb();
  if constexpr (C.vertex_color) {
    color = color * in.vertex_color.rgb();
    alpha = lerp(alpha, alpha * in.vertex_color.w, constant<L>(p.shader_controls).w);
  }
  if constexpr (C.envmap) {
    const float3<L>& n = in.normal;
    const float3<L>& e = in.eye_vector;
    const float3<L> r = (2.0f * dot(n, e)) * n - dot(n, n) * e;
    float3<L> spec = env(r) * constant<L>(p.tonemap.c30).z;
    if constexpr (C.mask == UnlitEnvmapMask::texture) spec = spec * t.mask;
    if constexpr (C.mask == UnlitEnvmapMask::base_alpha_inverted) spec = spec * (1.0f - t.base.w);
    spec = spec * constant<L>(p.envmap_tint).rgb();
    spec = lerp(spec, spec * spec, constant<L>(p.envmap_contrast).xyz());
    const L grey = dot(spec, float3<L>(0.299f, 0.587f, 0.114f));
    spec = lerp(float3<L>(grey), spec, constant<L>(p.envmap_saturation).xyz());
    color = color + spec;
  }
  return fogged_output<ToneMap::linear, C.fog>(float4<L>(color, alpha), p.tonemap, in.fog, p.fog);
}

template <UnlitCombo C, Lane L>
inline float4<L> unlit_generic(const UnlitInputs<L>& in, const UnlitGenericParams& p) {
  return unlit_generic_combine<C>(unlit_generic_fetch<C>(in, p), in, p,
                                  [&](const float3<L>& r) { return texCUBE(p.envmap, r).rgb(); });
}

template <UnlitCombo C>
inline UnlitInputs<Counted> unlit_counted_inputs(CountedInputs& in) {
  UnlitInputs<Counted> r;
  r.base_uv = in.vector<2>();
  if constexpr (C.detail != UnlitDetail::none) r.detail_uv = in.vector<2>();
  if constexpr (C.vertex_color || C.diffuse_lighting) r.vertex_color = in.vector<4>();
  if constexpr (C.envmap) {
    r.eye_vector = in.vector<3>();
    r.normal = in.vector<3>();
  }
  r.fog = fog_counted_inputs<C.fog>(in);
  return r;
}

template <UnlitCombo C>
inline Cost measure_unlit_generic(ShaderModel model) {
  const UnlitGenericParams params{};
  return measure(model, [&](CountedInputs& in) { return unlit_generic<C>(unlit_counted_inputs<C>(in), params); });
}

}  // namespace luxel::shading::source
