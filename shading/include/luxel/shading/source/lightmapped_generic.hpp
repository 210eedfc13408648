#pragma once
// LightmappedGeneric (world surfaces), DX9 pixel shader: base texture x radiosity-normal-mapped
// diffuse from three directional lightmaps (or the flat lightmap without a bump map), plus optional
// cube-map specular with mask, tint, contrast, saturation and Fresnel, ending in FinalOutput.
// docs/fidelity.md#lightmappedgeneric (combine, envmap, alpha), #tone-mapping
// (lightmap scale, epilogue), #fog (fog.hpp: the SDK's PIXELFOGTYPE on every model).
//
// Written once over the lane L; the static combos are the template parameter LightmappedCombo,
// the dynamic state (constants, textures) is LightmappedGenericParams. The shader is split in
// two stages so tests can drive the arithmetic with arbitrary texel values on both lanes:
//   lightmapped_generic_fetch()    the independent texture reads (base, bump, lightmaps, mask)
//   lightmapped_generic_combine()  everything else, with the cube map read through `env(R)`
//   lightmapped_generic()          both, with texCUBE as env: the real shader
//
// Lightmaps: the diffuse is multiplied by c12.rgb = modulation color x lightmap scale
// factor. HDR: RGBA16F lightmaps hold linear light, factor 1. LDR: VRAD's encoding stores
// 0.5 L^(1/2.2) (gamma 2.2, overbright 2) in an sRGB-read RGBA8 texture, so the factor that
// recovers L is 2^2.2 (≈ 4.595): lightmap_scale_factor(). Exact only where the sRGB read curve
// equals the 2.2 power; see encode_ldr_lightmap() and its test for the measured difference.
//
// Fast-path quirk: Valve's helper uses the fast path (no contrast except exactly 1, no
// saturation, no Fresnel) unless (contrast ∉ {0,1} and saturation ≠ 1), or R0 ≠ 1, or a
// self-illum tint ≠ 1. choose_lightmapped_combo(material) reproduces that by default
// (faithful_fast_path = true); pass false to get the intended look (full path whenever any of the
// three parameters is not its default).
//
// Not implemented: ssbump (BUMPMAP == 2), detail textures, $basetexture2 blends, self-illum,
// vertex color, lightwarp, bicubic lightmaps.

#include "luxel/shading/source/binaries.hpp"
#include "luxel/shading/source/common.hpp"
#include "luxel/shading/source/fog.hpp"

#include <cmath>
#include <cstdint>
#include <iterator>
#include <string>
#include <utility>

namespace luxel::shading::source {

/// Where the cube-map specular mask comes from.
enum class EnvmapMask {
  none,                 ///< 1
  base_alpha_inverted,  ///< $basealphaenvmapmask: 1 - base alpha ("Reversing alpha blows!")
  normal_alpha,         ///< $normalmapalphaenvmapmask: bump map alpha (needs a bump map)
  texture,              ///< $envmapmask rgb (not allowed with a bump map)
};

/// The envmap combine.
enum class EnvmapPath {
  fast,           ///< tint and mask only
  fast_contrast,  ///< FASTPATHENVMAPCONTRAST: contrast exactly 1, i.e. spec²
  full,           ///< contrast, saturation, Fresnel
};

/// The static combos of LightmappedGeneric.
struct LightmappedCombo {
  bool bump = true;
  bool envmap = false;
  EnvmapMask mask = EnvmapMask::none;
  EnvmapPath path = EnvmapPath::fast;
  Fog fog = Fog::none;

  /// A combination Valve's helper can produce (on some model).
  constexpr bool valid() const {
    if (!envmap) return mask == EnvmapMask::none && path == EnvmapPath::fast;
    if (mask == EnvmapMask::normal_alpha && !bump) return false;
    if (mask == EnvmapMask::texture && bump) return false;
    // lightmappedgeneric_ps2_3_x.h: SKIP $BASEALPHAENVMAPMASK && $BUMPMAP. The helper does not
    // resolve it; a scene that asks for it is refused (scenes::validate).
    if (mask == EnvmapMask::base_alpha_inverted && bump) return false;
    return true;
  }
  /// ... on model m: the fog type decides (fog.hpp).
  constexpr bool valid(ShaderModel m) const { return valid() && fog_valid(fog, m); }
  /// lightmappedgeneric_ps2x.fxc: ps20 and ps20b only.
  static constexpr ShaderBuilds builds() { return kPs2xBuilds; }
  friend constexpr bool operator==(const LightmappedCombo&, const LightmappedCombo&) = default;
  std::string name() const {
    static const char* masks[] = {"", "+basealphamask", "+normalalphamask", "+envmapmask"};
    static const char* paths[] = {"", "+contrast1", "+full"};
    return std::string(bump ? "bump" : "flat") + (envmap ? "+envmap" : "") + masks[static_cast<int>(mask)] +
           paths[static_cast<int>(path)] + fog_name(fog);
  }
};

/// The dynamic state: samplers and constant registers.
struct LightmappedGenericParams {
  Sampler2D base{0};
  Sampler2D lightmap{1};
  SamplerCube envmap{2};
  Sampler2D bump{4};
  Sampler2D envmap_mask{5};
  /// c12: rgb = modulation color x lightmap scale factor, w = $alpha x $alpha2 (luxel has no $alpha2: 1).
  glm::vec4 tint_lightmap_scale{1.0f};
  /// x: i.vertexColor.a, which the vertex shader sets to cModulationColor.a ($alpha) on a surface
  /// without $vertexcolor: the same at every vertex, so luxel reads it as a constant.
  glm::vec4 vertex_alpha{1.0f};
  /// $envmaptint, raw (no gamma conversion for brushes).
  glm::vec4 envmap_tint{1.0f, 1.0f, 1.0f, 0.0f};
  /// x = $envmapcontrast, y = $envmapsaturation.
  glm::vec4 envmap_contrast_saturation{0.0f, 1.0f, 0.0f, 0.0f};
  /// c4 = (0, 0, 1 - R0, R0), R0 = $fresnelreflection.
  glm::vec4 fresnel{0.0f, 0.0f, 0.0f, 1.0f};
  ToneMapConstants tonemap{};
  FogConstants fog{};
};

/// The interpolants (SDK: lightmappedgeneric_vs20 outputs).
template <Lane L>
struct LightmappedInputs {
  float2<L> base_uv;       ///< base, bump and envmap-mask coordinates
  float2<L> lightmap_uv0;  ///< flat lightmap
  float4<L> lightmap_uv12; ///< bump lightmaps 1 (xy) and 2 (zw)
  float2<L> lightmap_uv3;  ///< bump lightmap 3
  float3<L> tangent, binormal, normal;  ///< tangentSpaceTranspose rows: the world-space frame
  float3<L> eye_vector;    ///< worldVertToEyeVector, unnormalised
  FogInputs<L> fog{};      ///< world z and projected z (pixel fog combos)
};

/// The independent texture reads.
template <Lane L>
struct LightmappedTexels {
  float4<L> base{1.0f};
  float4<L> bump{0.5f, 0.5f, 1.0f, 1.0f};
  float3<L> mask{1.0f};
  float3<L> lightmap[4];  ///< flat, bump 1, 2, 3
};

template <LightmappedCombo C, Lane L>
inline LightmappedTexels<L> lightmapped_generic_fetch(const LightmappedInputs<L>& in, const LightmappedGenericParams& p) {
  static_assert(C.valid(), "not a combo Valve's helper can select");
  LightmappedTexels<L> t;
  t.base = tex2D(p.base, in.base_uv);
  if constexpr (C.bump) {
    t.bump = tex2D(p.bump, in.base_uv);
    const auto bumped = tex2D_taps(p.lightmap, std::array{float2<L>(in.lightmap_uv12.xy()), float2<L>(in.lightmap_uv12.zw()), in.lightmap_uv3});
    for (int k = 0; k < 3; ++k) t.lightmap[k + 1] = bumped[size_t(k)].rgb();
  } else {
    t.lightmap[0] = tex2D(p.lightmap, in.lightmap_uv0).rgb();
  }
  if constexpr (C.envmap && C.mask == EnvmapMask::texture) t.mask = tex2D(p.envmap_mask, in.base_uv).rgb();
  return t;
}

/// Everything after the independent reads; env(R) returns the cube map's rgb in direction R.
template <LightmappedCombo C, Lane L, class EnvFn>
inline float4<L> lightmapped_generic_combine(const LightmappedTexels<L>& t, const LightmappedInputs<L>& in,
                                             const LightmappedGenericParams& p, EnvFn&& env) {
  static_assert(C.valid(), "not a combo Valve's helper can select");
  const float4<L> c12 = constant<L>(p.tint_lightmap_scale);
  const float3<L> albedo = t.base.rgb();

  // RNM: n = 2 tex - 1 (no renormalisation), d_i = sat(dot(n, basis_i))², weighted sum / Σd_i.
  float3<L> n(0.0f, 0.0f, 1.0f);
  float3<L> diffuse;
  if constexpr (C.bump) {
    n = t.bump.xyz() * 2.0f - 1.0f;
    const float3<L> d = rnm_weights(n);
    diffuse = d.x * t.lightmap[1] + d.y * t.lightmap[2] + d.z * t.lightmap[3];
    const L sum = dot(d, float3<L>(1.0f));
    diffuse = diffuse * (c12.rgb() / sum);
  } else {
    diffuse = t.lightmap[0] * c12.rgb();
  }
  float3<L> color = albedo * diffuse;

  // alpha = base.a x i.vertexColor.a x c12.w, which applies $alpha twice (docs/fidelity.md#lightmappedgeneric).
  const L modulation_alpha = L(constant<L>(p.vertex_alpha).x) * c12.w;
  L alpha = t.base.w * modulation_alpha;
  if constexpr (C.envmap) {
    // Env map: R = 2(N·E)N − (N·N)E, N the tangent-space normal rotated to world, not renormalised.
    float3<L> world_normal;
    if constexpr (C.bump) {
      world_normal = n.x * in.tangent + n.y * in.binormal + n.z * in.normal;
    } else {
      world_normal = in.normal;
    }
    const float3<L>& e = in.eye_vector;
    const float3<L> r = (2.0f * dot(world_normal, e)) * world_normal - dot(world_normal, world_normal) * e;
    const float4<L> c30 = constant<L>(p.tonemap.c30);
    float3<L> spec = env(r) * c30.z;
    if constexpr (C.mask == EnvmapMask::base_alpha_inverted) {
      spec = spec * (1.0f - t.base.w);
      alpha = modulation_alpha;  // the base alpha is a mask, not opacity
    } else if constexpr (C.mask == EnvmapMask::normal_alpha) {
      spec = spec * t.bump.w;
    } else if constexpr (C.mask == EnvmapMask::texture) {
      spec = spec * t.mask;
    }
    spec = spec * constant<L>(p.envmap_tint).rgb();
    if constexpr (C.path == EnvmapPath::fast_contrast) {
      spec = spec * spec;
    } else if constexpr (C.path == EnvmapPath::full) {
      const float4<L> cs = constant<L>(p.envmap_contrast_saturation);
      spec = lerp(spec, spec * spec, cs.x);
      const L grey = dot(spec, float3<L>(0.299f, 0.587f, 0.114f));
      spec = lerp(float3<L>(grey), spec, cs.y);
      const float4<L> c4 = constant<L>(p.fresnel);
      const L f = 1.0f - dot(world_normal, normalize(e));
      const L fresnel = pow(f, L(5.0f)) * c4.z + c4.w;
      spec = spec * fresnel;
    }
    color = color + spec;
  }
  return fogged_output<ToneMap::linear, C.fog>(float4<L>(color, alpha), p.tonemap, in.fog, p.fog);
}

/// The pixel shader: fetch, combine with the cube map read at R.
template <LightmappedCombo C, Lane L>
inline float4<L> lightmapped_generic(const LightmappedInputs<L>& in, const LightmappedGenericParams& p) {
  const LightmappedTexels<L> t = lightmapped_generic_fetch<C>(in, p);
  return lightmapped_generic_combine<C>(t, in, p, [&](const float3<L>& r) { return texCUBE(p.envmap, r).rgb(); });
}

/// The interpolants as Counted input registers (one register each, in SDK order).
template <LightmappedCombo C>
inline LightmappedInputs<Counted> lightmapped_counted_inputs(CountedInputs& in) {
  LightmappedInputs<Counted> r;
  r.base_uv = in.vector<2>();
  if constexpr (C.bump) {
    r.lightmap_uv12 = in.vector<4>();
    r.lightmap_uv3 = in.vector<2>();
  } else {
    r.lightmap_uv0 = in.vector<2>();
  }
  if constexpr (C.envmap) {
    if constexpr (C.bump) {
      r.tangent = in.vector<3>();
      r.binormal = in.vector<3>();
    }
    r.normal = in.vector<3>();
    r.eye_vector = in.vector<3>();
  }
  r.fog = fog_counted_inputs<C.fog>(in);
  return r;
}

/// The cost of combo C on `model`, measured from the shader's code.
template <LightmappedCombo C>
inline Cost measure_lightmapped_generic(ShaderModel model) {
  const LightmappedGenericParams params{};
  return measure(model, [&](CountedInputs& in) {
    return lightmapped_generic<C>(lightmapped_counted_inputs<C>(in), params);
  });
}

// ---- CPU side: combo choice and lightmap encodings --------------------------------------------

/// The material parameters that pick the combo.
struct LightmappedMaterial {
  bool bump = true;
  bool envmap = false;
  EnvmapMask mask = EnvmapMask::none;
  bool base_translucent = true;  ///< the base texture has alpha (a missing base has none)
  float envmap_contrast = 0.0f;
  float envmap_saturation = 1.0f;
  float fresnel_reflection = 1.0f;
  bool selfillum_tint_not_one = false;
};

/// Valve's combo choice. faithful_fast_path = false: the full path whenever a parameter
/// differs from its default (contrast 1 still takes the exact FASTPATHENVMAPCONTRAST shortcut).
inline LightmappedCombo choose_lightmapped_combo(const LightmappedMaterial& m, bool faithful_fast_path = true) {
  LightmappedCombo c;
  c.bump = m.bump;
  c.envmap = m.envmap;
  if (!m.envmap) return c;
  c.mask = m.mask;
  if (c.mask == EnvmapMask::texture && c.bump) c.mask = EnvmapMask::none;  // the helper drops $envmapmask
  // ... and $basealphaenvmapmask over a base without alpha (lightmappedgeneric_dx9_helper.cpp:143-147, 214-218)
  if (c.mask == EnvmapMask::base_alpha_inverted && !m.base_translucent) c.mask = EnvmapMask::none;
  const bool contrast_special = m.envmap_contrast == 0.0f || m.envmap_contrast == 1.0f;
  bool full;
  if (faithful_fast_path) {
    full = (!contrast_special && m.envmap_saturation != 1.0f) || m.fresnel_reflection != 1.0f || m.selfillum_tint_not_one;
  } else {
    full = !contrast_special || m.envmap_saturation != 1.0f || m.fresnel_reflection != 1.0f;
  }
  c.path = full ? EnvmapPath::full : m.envmap_contrast == 1.0f ? EnvmapPath::fast_contrast : EnvmapPath::fast;
  return c;
}

/// c4 for $fresnelreflection R0.
inline glm::vec4 fresnel_constant(float r0) { return glm::vec4(0.0f, 0.0f, 1.0f - r0, r0); }

enum class LightmapFormat {
  hdr_float16,  ///< RGBA16F, linear, sRGB read off: factor 1
  ldr_srgb8,    ///< RGBA8_sRGB holding 0.5 L^(1/2.2): factor 2^2.2
};

/// The lightmap scale factor that goes into c12 with the modulation color (its value is
/// NOT IN SDK, this is the derivation from VRAD's encoding).
inline float lightmap_scale_factor(LightmapFormat f) {
  return f == LightmapFormat::ldr_srgb8 ? std::pow(2.0f, 2.2f) : 1.0f;
}

/// VRAD's 8-bit lightmap texel (ConvertLinearToRGBA8888): linear -> lineartovertex table
/// ((i/1024)^(1/2.2) x 0.5, 4096 entries covering 0..4) -> hue-preserving clamp -> x255 round.
inline std::array<uint8_t, 3> encode_ldr_lightmap(const glm::vec3& linear) {
  float v[3];
  float largest = 0.0f;
  for (int i = 0; i < 3; ++i) {
    const float x = std::isnan(linear[i]) ? 0.0f : linear[i];
    const int index = static_cast<int>(std::fmin(std::fmax(x * 1024.0f, 0.0f), 4095.0f));
    v[i] = std::pow(index / 1024.0f, 1.0f / 2.2f) * 0.5f;
    largest = std::fmax(largest, v[i]);
  }
  std::array<uint8_t, 3> out{};
  for (int i = 0; i < 3; ++i) {
    const float c = largest > 1.0f ? v[i] / largest : v[i];
    out[i] = static_cast<uint8_t>(std::lround(c * 255.0f));
  }
  return out;
}

/// The linear value to upload to an RGBA8_sRGB lightmap page for VRAD's 8-bit texel `bytes`:
/// (b/255)^2.2, the curve the engine assumes. Reading VRAD's bytes directly through the exact sRGB
/// decode instead is up to ~40 % too bright at the dark end (sRGB's linear toe vs the 2.2 power;
/// see the test), so the page is re-encoded at upload and the shader stays as the SDK's.
inline glm::vec3 ldr_lightmap_upload_value(const std::array<uint8_t, 3>& bytes) {
  glm::vec3 v;
  for (int i = 0; i < 3; ++i) v[i] = std::pow(bytes[i] / 255.0f, 2.2f);
  return v;
}

}  // namespace luxel::shading::source
