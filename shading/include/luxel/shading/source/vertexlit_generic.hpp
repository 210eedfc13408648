#pragma once
// VertexLitGeneric (models), DX9 pixel shader with per-pixel lighting: albedo x (ambient cube +
// Σ local lights with squared Half-Lambert or Lambert), and on ps_2_b / ps_3_0 the Phong ("skin")
// terms: exponent and mask textures, Fresnel ranges, rim lighting; on ps_3_0 optionally SH9
// ambient instead of the cube (spherical_harmonics.hpp). docs/fidelity.md#ambient-cube,
// #model-lights (attenuation, diffuse, counts), #bumped-and-skin-paths, #phong, #phong-defaults,
// #tone-mapping.
//
// Static combos: the template parameter VertexLitCombo (light count, bump, Phong, rim,
// Half-Lambert, where the attenuation is computed); the shader model is a separate
// axis: VertexLitCombo::valid(model) says which combos the SDK's rules allow where (ps_2_0: at
// most two lights, no Phong, as Valve's helper forces $phong off there), and
// vertexlit_compiles<C>(model) adds the model's limits, counted from the shader's code as fxc
// would refuse it: that, not a rule written here, is what keeps the heavier per-pixel-attenuated
// combos off ps_2_0 (their arithmetic exceeds its 64 slots; two Lambert lights still fit).
//
// Lights: the SDK computes attenuation per vertex and N·L per pixel: the combos with
// pixel_attenuation = false (an interpolated float4, one component per light,
// vertex_light_attenuation() in the vertex stage), the frame's default. luxel's option computes
// the attenuation per pixel too (pixel_attenuation = true: a light close to a coarse mesh is not
// smeared across the triangle) where the combo fits. Four lights go per vertex only: their full
// records (5 float4 each) do not fit ps_2_b's 32 constant registers, the reason the SDK splits
// the work. The light type is dynamic as in the SDK: color.w = 1 directional, spot.w = 1 spot.
// A directional light's position register holds the unit vector toward the light with w = 0, so
// one mad gives L for every type: L = pos.xyz - worldPos * pos.w.
//
// Normalisation (docs/fidelity.md#bumped-and-skin-paths): ps_2_b and ps_3_0 normalize the interpolated
// normal and the light vectors with nrm; ps_2_0 reads them from the signed normalization cube map
// (NormalizeWithCubemap: one texture slot for nrm's three arithmetic slots, and a dependent
// read), as the SDK's bump shader does, so ps_2_0 lighting carries the cube map's filtering and
// 8-bit error (normalization_cube.hpp). The combo's normalization_cube flag is that choice, and
// valid() holds it to the model: on ps_2_0 and only there.
//
// Fog: every combo's fog type (fog.hpp), the SDK's PIXELFOGTYPE.
//
// The SDK's VertexLitGeneric without a bump map is lit per vertex, and so is the frame's:
// vertexlit_vertex_shader.hpp and the DIFFUSELIGHTING combos of unlit_generic.hpp. The combos here
// without a bump map or Phong are luxel's per-pixel lighting of smooth models, which the catalog
// and the report measure against it.
//
// The skin shader (phong) has the SDK's two forms (docs/fidelity.md#phong, #phong-defaults): with
// `bump`, skin_ps20b's full path, which always reads the normal map (a flat one when the material
// has none) and the exponent texture (white when it has none) and picks per pixel: the exponent
// c.x when c.x >= 0, else 1 + 149 r; the tint c.rgb when c.r >= 0, else lerp(1, base, g); and
// with $basemapalphaphongmask (c27.x = 1) the normal (0, 0, 1), the mask and the alpha from the
// base. Without `bump`, FASTPATH_NOBUMP: the interpolated normal, mask = base alpha, exponent
// max(c.x, 0), tint 1, no rim.
//
// Env maps (docs/fidelity.md#env-maps-on-models), the `envmap` combos: the skin shader's adds
// c30.z · lerp(1, Fresnel ranges, $envmapfresnel) · mask · cube(R) · $envmaptint, R = 2 N (N·V) - V,
// the mask the base alpha, or with $normalmapalphaenvmapmask (envmap_tint.w = 1) the Phong mask;
// no contrast or saturation. The bumped path's adds c30.z · cube(R) · mask · $envmaptint, R =
// 2 (N·E) N - (N·N) E, the mask the normal map's alpha on the envmap_normal_alpha combos (the SDK's
// static NORMALMAPALPHAENVMAPMASK) else 1, then contrast and saturation. Both are added after
// the lighting, unlit by it.
//
// Not implemented: lightwarp, phong warp, self-illum, detail, $phongexponentfactor,
// $blendtintbybasealpha, $invertphongmask.

#include "luxel/shading/source/binaries.hpp"
#include "luxel/shading/source/common.hpp"
#include "luxel/shading/source/fog.hpp"
#include "luxel/shading/source/normalization_cube.hpp"
#include "luxel/shading/source/spherical_harmonics.hpp"

#include <array>
#include <iterator>
#include <string>
#include <utility>

namespace luxel::shading::source {

/// The static combos of the per-pixel VertexLitGeneric / skin shader.
struct VertexLitCombo {
  int lights = 2;     ///< local lights evaluated per pixel: 0..2 (ps_2_0), 0..4
  /// A normal map (tangent frame interpolated). In the skin shader: its full path, which reads
  /// the normal and exponent maps; without it, FASTPATH_NOBUMP.
  bool bump = false;
  bool phong = false;  ///< the skin shader: Phong specular (ps_2_b / ps_3_0 only)
  bool rim = false;    ///< rim lighting (the skin shader's full path)
  bool half_lambert = true;       ///< squared Half-Lambert (the skin shader always uses it)
  bool pixel_attenuation = true;  ///< attenuation per pixel (luxel's option) or per vertex, interpolated (the SDK's)
  bool sh9_ambient = false;       ///< ambient from 9 SH coefficients instead of the cube (ps_3_0 only)
  Fog fog = Fog::none;
  bool normalization_cube = false;  ///< normalize through the normalization cube map (ps_2_0's way)
  bool envmap = false;              ///< CUBEMAP: env-map specular
  /// NORMALMAPALPHAENVMAPMASK: the bumped path's env map masked by the normal map's alpha (the
  /// skin shader takes that choice from a constant instead).
  bool envmap_normal_alpha = false;

  constexpr bool valid(ShaderModel m) const {
    if (lights < 0 || lights > 4) return false;
    // vertexlit_and_unlit_generic_bump_ps2x.fxc: SKIP $NORMALMAPALPHAENVMAPMASK && !$CUBEMAP.
    if (envmap_normal_alpha && !(envmap && bump && !phong)) return false;
    if (!fog_valid(fog, m)) return false;
    if (normalization_cube != (m == ShaderModel::ps_2_0)) return false;
    if (m == ShaderModel::ps_2_0 && (lights > 2 || phong)) return false;
    if (rim && !(phong && bump)) return false;  // skin_ps20b.fxc: SKIP $FASTPATH_NOBUMP && $RIMLIGHT
    if (phong && !half_lambert) return false;
    if (lights > 2 && pixel_attenuation) return false;
    // SH9 ambient is luxel's ps_3_0 option, where the SDK's separate VertexLitGeneric
    // ps_3_0 builds live (docs/fidelity.md#shader-models). A product choice, not a budget: it costs 2
    // slots and 3 constant registers more than the cube, and even the largest combo would fit ps_2_b
    // with it (25 of 32 constants, measured in sh9_test.cpp).
    if (sh9_ambient && m != ShaderModel::ps_3_0) return false;
    return true;
  }
  /// skin_ps20b.fxc (Phong) is built as ps20b and ps30; the VertexLitGeneric sources as ps20,
  /// ps20b and ps30.
  constexpr ShaderBuilds builds() const { return phong ? ShaderBuilds{false, true, true} : kPs2x30Builds; }
  friend constexpr bool operator==(const VertexLitCombo&, const VertexLitCombo&) = default;
  std::string name() const {
    std::string n = std::to_string(lights) + (lights == 1 ? " light" : " lights");
    if (bump) n += "+bump";
    if (phong) n += "+phong";
    if (rim) n += "+rim";
    if (!half_lambert) n += "+lambert";
    if (lights > 0 && !pixel_attenuation) n += "+vertexatten";
    if (sh9_ambient) n += "+sh9";
    if (normalization_cube) n += "+normcube";
    if (envmap) n += "+envmap";
    if (envmap_normal_alpha) n += "+normalalphamask";
    return n + fog_name(fog);
  }
};

/// One local light as the pixel shader's constant registers hold it.
struct LocalLight {
  glm::vec4 color{0.0f};           ///< rgb linear; w = 1 directional
  glm::vec4 position{0.0f};        ///< xyz world position, w = 1; directional: unit vector toward the light, w = 0
  glm::vec4 spot_direction{0.0f};  ///< xyz the spot's axis (direction it shines), w = 1 spot
  glm::vec4 spot_params{0.0f};     ///< x falloff exponent, z cos(outer), w 1 / (cos(inner) - cos(outer))
  glm::vec4 attenuation{1.0f, 0.0f, 0.0f, 0.0f};  ///< (constant, linear, quadratic)
};

struct VertexLitParams {
  Sampler2D base{0};
  Sampler2D bump{3};
  Sampler2D phong_exponent{7};  ///< white when the material has no $phongexponenttexture
  SamplerCube envmap{8};        ///< read by the envmap combos
  AmbientCube ambient{};
  Sh9Ambient ambient_sh9{};  ///< read instead of `ambient` by the sh9_ambient combos
  std::array<LocalLight, 4> lights{};
  glm::vec4 eye_position{0.0f};
  glm::vec4 modulation{1.0f};                          ///< $color (linear) and alpha
  /// rgb $phongtint (r < 0: the albedo tint lerp(1, base, exponent texel g)), w $phongboost
  glm::vec4 phong_tint_boost{1.0f, 1.0f, 1.0f, 1.0f};
  /// x the exponent (skin_exponent_constants()), y $rimlightexponent, z $rimlightboost, w $rimmask (0/1)
  glm::vec4 phong_params{-1.0f, 4.0f, 1.0f, 0.0f};
  /// The skin shader's controls (its g_ShaderControls, and the exponent texture's scale):
  /// x $basemapalphaphongmask (0/1): the normal (0, 0, 1), mask and alpha from the base;
  /// y what the full path multiplies the exponent texture's r by (1 + y r): 149, or
  /// $phongexponentfactor (skin_exponent_constants()); w $invertphongmask (0/1): the env map's
  /// mask inverted.
  glm::vec4 shader_controls{0.0f, 149.0f, 0.0f, 0.0f};
  /// $phongfresnelranges re-encoded (2(mid-min), mid, 2(max-mid)); (1, 0.5, 1) = plain (1-N·V)²
  glm::vec4 fresnel_ranges{1.0f, 0.5f, 1.0f, 0.0f};
  /// rgb $envmaptint; w (the skin shader) 1 with $normalmapalphaenvmapmask: the Phong mask masks
  /// the env map instead of the base alpha
  glm::vec4 envmap_tint{1.0f, 1.0f, 1.0f, 0.0f};
  glm::vec4 envmap_fresnel{0.0f};     ///< x $envmapfresnel (the skin shader)
  glm::vec4 envmap_contrast{0.0f};    ///< xyz $envmapcontrast (the bumped path)
  glm::vec4 envmap_saturation{1.0f};  ///< xyz $envmapsaturation (the bumped path)
  ToneMapConstants tonemap{};
  FogConstants fog{};
  /// s5: the signed normalization cube map (normalization_cube.hpp), read by the ps_2_0 combos.
  SamplerCube normalization_cube{5, nullptr, normalization_cube_sampler()};
};

/// The skin shader's exponent constants as skin_dx9_helper.cpp sets them: c.w is
/// $phongexponentfactor when it is not 0, else $phongexponent when it is above 0, else -1. The full
/// path reads c.w >= 0 as the exponent and otherwise takes it from the exponent texture (a white
/// one when there is none), 1 + 149 r; with a factor the SDK runs the PHONG_USE_EXPONENT_FACTOR
/// binary, 1 + factor r, which luxel's one binary computes as the texture path with the factor as
/// the scale (exponent -1, scale factor). FASTPATH_NOBUMP reads max(c.w, 0).
struct SkinExponentConstants {
  float exponent = -1.0f;         ///< VertexLitParams::phong_params.x
  float texture_scale = 149.0f;   ///< VertexLitParams::shader_controls.y
};
inline SkinExponentConstants skin_exponent_constants(float phong_exponent, float phong_exponent_factor, bool fast_path) {
  if (phong_exponent_factor != 0.0f) return fast_path ? SkinExponentConstants{phong_exponent_factor} : SkinExponentConstants{-1.0f, phong_exponent_factor};
  return {phong_exponent > 0.0f ? phong_exponent : -1.0f};
}

/// The skin shader's specular tint constant (skin_dx9_helper.cpp): $phongtint; all zero (no tint)
/// sends -1 in r, the albedo tint lerp(1, base, exponent texel g), with $phongalbedotint and an
/// exponent texture, else white.
inline glm::vec3 skin_specular_tint(const glm::vec3& phong_tint, bool albedo_tint, bool exponent_texture) {
  if (phong_tint != glm::vec3(0.0f)) return phong_tint;
  return albedo_tint && exponent_texture ? glm::vec3(-1.0f, 0.0f, 0.0f) : glm::vec3(1.0f);
}

/// The CPU re-encoding of $phongfresnelranges (docs/fidelity.md#phong).
inline glm::vec4 encode_fresnel_ranges(float min, float mid, float max) {
  return glm::vec4((mid - min) * 2.0f, mid, (max - mid) * 2.0f, 0.0f);
}

template <Lane L>
struct VertexLitInputs {
  float2<L> uv;
  float3<L> world_pos;
  float3<L> normal;             ///< world space, interpolated (not unit)
  float3<L> tangent, binormal;  ///< bump only
  float4<L> attenuation{1.0f};  ///< per-vertex attenuation of lights 0..3 (pixel_attenuation = false)
  L proj_z = L(0.0f);           ///< projected z, the .w beside world_pos (pixel fog combos)
};

/// The SDK's attenuation (VertexAttenInternal) of one light at a point, over any lane:
/// 1 / (a0 + a1 d + a2 d²), × spot sat(max(1e-4, (dot(axis, -L) - cosOuter) invRange)^exponent),
/// selected per light type by color.w / spot.w. Also returns the unit vector toward the light
/// (0 for a light exactly at the point: normalize(0) = 0, distance factor 1 / a0).
template <Lane L>
inline L light_attenuation(const float3<L>& world_pos, const LocalLight& light, float3<L>& to_light) {
  const float4<L> pos = constant<L>(light.position);
  const float4<L> color = constant<L>(light.color);
  const float4<L> axis = constant<L>(light.spot_direction);
  const float4<L> sp = constant<L>(light.spot_params);
  const float4<L> att = constant<L>(light.attenuation);
  const float3<L> v = pos.xyz() - world_pos * pos.w;
  const L d2 = dot(v, v);
  const L d = sqrt(d2);
  to_light = normalize(v);
  const L distance = 1.0f / dot(float3<L>(L(1.0f), d, d2), att.xyz());
  L spot = (dot(axis.xyz(), -to_light) - sp.z) * sp.w;
  spot = saturate(pow(max(spot, L(0.0001f)), sp.x));
  const L a = lerp(distance, distance * spot, axis.w);
  return lerp(a, L(1.0f), color.w);
}

/// The largest attenuation the vertex stage hands on (vertex_light_attenuation).
inline constexpr float kMaxVertexAttenuation = 1e8f;

/// The vertex stage's version (the SDK's): float lane, returns the attenuation only. A light
/// exactly on a vertex, without constant attenuation, is infinitely bright there (and the type
/// selects turn that infinity into NaN); interpolated, it would make the whole triangle NaN, so
/// anything not below kMaxVertexAttenuation is held at it (with quadratic attenuation 1: a light
/// within 1e-4 of the vertex).
inline float vertex_light_attenuation(const glm::vec3& world_pos, const LocalLight& light) {
  float3<float> l;
  const float a = light_attenuation<float>(float3<float>(world_pos.x, world_pos.y, world_pos.z), light, l);
  return a < kMaxVertexAttenuation ? a : kMaxVertexAttenuation;
}

/// The Phong-side textures.
template <Lane L>
struct VertexLitTexels {
  float4<L> base{1.0f};
  float4<L> bump{0.5f, 0.5f, 1.0f, 1.0f};
  float4<L> exponent{1.0f};
};

template <VertexLitCombo C, Lane L>
inline VertexLitTexels<L> vertexlit_fetch(const VertexLitInputs<L>& in, const VertexLitParams& p) {
  VertexLitTexels<L> t;
  t.base = tex2D(p.base, in.uv);
  if constexpr (C.bump) t.bump = tex2D(p.bump, in.uv);
  if constexpr (C.phong && C.bump) t.exponent = tex2D(p.phong_exponent, in.uv);
  return t;
}

/// The ambient term along a unit direction: the cube, or SH9 on the sh9_ambient combos (E/π both).
template <VertexLitCombo C, Lane L>
inline float3<L> vertexlit_ambient(const float3<L>& n, const VertexLitParams& p) {
  if constexpr (C.sh9_ambient) {
    return sh9_ambient_light(n, p.ambient_sh9);
  } else {
    return ambient_light(n, p.ambient);
  }
}

/// A unit vector along v: nrm, or on the normalization_cube combos the cube map's texel.
template <VertexLitCombo C, Lane L>
inline float3<L> vertexlit_normalize(const float3<L>& v, const VertexLitParams& p) {
  if constexpr (C.normalization_cube) {
    return texCUBE(p.normalization_cube, v).xyz();
  } else {
    return normalize(v);
  }
}

/// Everything after the 2D reads; env(R) returns the cube map's rgb in direction R.
template <VertexLitCombo C, Lane L, class EnvFn>
inline float4<L> vertexlit_combine(const VertexLitTexels<L>& t, const VertexLitInputs<L>& in, const VertexLitParams& p,
                                   EnvFn&& env) {
  float3<L> n;
  if constexpr (C.bump) {
    float3<L> tn = t.bump.xyz() * 2.0f - 1.0f;
    if constexpr (C.phong) tn = lerp(tn, float3<L>(0.0f, 0.0f, 1.0f), L(constant<L>(p.shader_controls).x));
    n = vertexlit_normalize<C>(tn.x * in.tangent + tn.y * in.binormal + tn.z * in.normal, p);
  } else {
    n = vertexlit_normalize<C>(in.normal, p);
  }
  float3<L> diffuse = vertexlit_ambient<C>(n, p);
  float3<L> spec(0.0f), rim(0.0f);
  float3<L> view;
  L exponent, fresnel;
  if constexpr (C.phong) {
    view = normalize(constant<L>(p.eye_position).xyz() - in.world_pos);
    const L c = constant<L>(p.phong_params).x;
    if constexpr (C.bump) {
      exponent = select(c >= L(0.0f), c, L(t.exponent.x * L(constant<L>(p.shader_controls).y) + 1.0f));
    } else {
      exponent = max(c, L(0.0f));
    }
  }
  for (int i = 0; i < C.lights; ++i) {
    const LocalLight& light = p.lights[static_cast<size_t>(i)];
    float3<L> to_light;
    L atten;
    if constexpr (C.pixel_attenuation) {
      atten = light_attenuation(in.world_pos, light, to_light);
    } else {
      const float4<L> pos = constant<L>(light.position);
      to_light = vertexlit_normalize<C>(pos.xyz() - in.world_pos * pos.w, p);
      atten = in.attenuation[i];
    }
    const float3<L> color = constant<L>(light.color).rgb() * atten;
    const L n_dot_l = dot(n, to_light);
    const L term = C.half_lambert ? half_lambert(n_dot_l) : saturate(n_dot_l);
    diffuse = diffuse + color * term;
    if constexpr (C.phong) {
      // Phong: R = 2 N (N·V) - V; s = sat(R·L)^exp · sat(N·L) · color · atten.
      const float3<L> r = (2.0f * dot(n, view)) * n - view;
      const L r_dot_l = saturate(dot(r, to_light));
      const float3<L> lit = color * saturate(n_dot_l);
      spec = spec + lit * pow(r_dot_l, exponent);
      if constexpr (C.rim) rim = rim + lit * pow(r_dot_l, L(constant<L>(p.phong_params).y));
    }
  }
  const float4<L> modulation = constant<L>(p.modulation);
  const float3<L> albedo = t.base.rgb() * modulation.rgb();
  float3<L> color = albedo * diffuse;
  if constexpr (C.phong) {
    // Fresnel ranges: f = sat(1 - N·V)²; ranges piecewise linear around 0.5.
    const L one_minus = saturate(1.0f - dot(n, view));
    const L f = one_minus * one_minus;
    const float4<L> ranges = constant<L>(p.fresnel_ranges);
    const L g = f - 0.5f;
    fresnel = ranges.y + g * select(g >= L(0.0f), ranges.z, ranges.x);
    const float4<L> tint_boost = constant<L>(p.phong_tint_boost);
    L mask = t.base.w;
    float3<L> tint(1.0f);
    if constexpr (C.bump) {
      mask = lerp(t.bump.w, t.base.w, L(constant<L>(p.shader_controls).x));
      tint = select(tint_boost.x >= L(0.0f), tint_boost.rgb(), lerp(float3<L>(1.0f), t.base.rgb(), t.exponent.y));
    }
    float3<L> env_color(0.0f);
    if constexpr (C.envmap) {
      // The base alpha masks the env map, or with $normalmapalphaenvmapmask the Phong mask.
      const float4<L> env_tint = constant<L>(p.envmap_tint);
      const L env_mask = lerp(t.base.w, mask, env_tint.w);
      const L invert = constant<L>(p.shader_controls).w;  // $invertphongmask
      const L scale = constant<L>(p.tonemap.c30).z * lerp(L(1.0f), fresnel, L(constant<L>(p.envmap_fresnel).x)) *
                      lerp(env_mask, 1.0f - env_mask, invert);
      env_color = env((2.0f * dot(n, view)) * n - view) * scale * env_tint.rgb();
    }
    spec = spec * (mask * fresnel * tint_boost.w);
    if constexpr (C.rim) {
      // Rim: fresnel (1 - N·V)^4, mask, max with the specular, then ambient along V gated by N.z.
      const float4<L> pp = constant<L>(p.phong_params);
      const L rim_fresnel = f * f;
      const L rim_mask = lerp(L(1.0f), t.exponent.w, pp.w);
      const L m = rim_mask * rim_fresnel;
      spec = max(spec, rim * m);
      spec = spec + vertexlit_ambient<C>(view, p) * (pp.z * saturate(m * n.z));
    }
    if constexpr (C.envmap) {
      color = spec * tint + env_color + color;
    } else {
      color = color + spec * tint;
    }
  } else if constexpr (C.envmap) {
    const float3<L> e = constant<L>(p.eye_position).xyz() - in.world_pos;
    const float3<L> r = (2.0f * dot(n, e)) * n - dot(n, n) * e;
    float3<L> s = env(r) * constant<L>(p.tonemap.c30).z;
    if constexpr (C.envmap_normal_alpha) s = s * t.bump.w;
    s = s * constant<L>(p.envmap_tint).rgb();
    s = lerp(s, s * s, constant<L>(p.envmap_contrast).xyz());
    const L grey = dot(s, float3<L>(0.299f, 0.587f, 0.114f));
    color = color + lerp(float3<L>(grey), s, constant<L>(p.envmap_saturation).xyz());
  }
  L alpha = t.base.w * modulation.w;
  if constexpr (C.phong) alpha = lerp(alpha, modulation.w, L(constant<L>(p.shader_controls).x));
  const FogInputs<L> fog{in.world_pos.z, in.proj_z};
  return fogged_output<ToneMap::linear, C.fog>(float4<L>(color, alpha), p.tonemap, fog, p.fog);
}

/// vertexlit_combine with the cube map of p.envmap.
template <VertexLitCombo C, Lane L>
inline float4<L> vertexlit_combine(const VertexLitTexels<L>& t, const VertexLitInputs<L>& in, const VertexLitParams& p) {
  return vertexlit_combine<C>(t, in, p, [&](const float3<L>& r) { return texCUBE(p.envmap, r).rgb(); });
}

template <VertexLitCombo C, Lane L>
inline float4<L> vertexlit_generic(const VertexLitInputs<L>& in, const VertexLitParams& p) {
  return vertexlit_combine<C>(vertexlit_fetch<C>(in, p), in, p);
}

template <VertexLitCombo C>
inline VertexLitInputs<Counted> vertexlit_counted_inputs(CountedInputs& in) {
  VertexLitInputs<Counted> r;
  r.uv = in.vector<2>();
  const float4<Counted> world_pos_proj_z = in.vector<4>();  // one register, as the SDK packs it
  r.world_pos = world_pos_proj_z.xyz();
  r.normal = in.vector<3>();
  if constexpr (C.bump) {
    r.tangent = in.vector<3>();
    r.binormal = in.vector<3>();
  }
  if constexpr (!C.pixel_attenuation && C.lights > 0) r.attenuation = in.vector<4>();
  r.proj_z = world_pos_proj_z.w;
  return r;
}

template <VertexLitCombo C>
inline Cost measure_vertexlit_generic(ShaderModel model) {
  const VertexLitParams params{};
  return measure(model, [&](CountedInputs& in) { return vertexlit_generic<C>(vertexlit_counted_inputs<C>(in), params); });
}

/// Whether combo C exists on `model`: allowed by the SDK's rules and within the model's limits.
template <VertexLitCombo C>
inline bool vertexlit_compiles(ShaderModel model) {
  return C.valid(model) && static_cast<bool>(fits(measure_vertexlit_generic<C>(model), caps(model)));
}

}  // namespace luxel::shading::source
