#pragma once
// Water (the expensive DX9 water, water_ps2x.fxc / water_ps2x_helper.h / water.cpp): a normal map
// bends the screen-space coordinates of the reflection and refraction render targets; the two
// are blended with a Fresnel term; the refraction fades toward the fog color with depth.
// docs/fidelity.md#water (Fresnel, fog, reflection exposure; epilogue: TONEMAP NONE, then the
// pixel fog of the combo, fog.hpp, as water_ps2x.fxc's FinalOutput does).
//
// Order of operations (per pixel):
//   n      = 2 tex(normal).xyz - 1, n.a kept (MULTITEXTURE: 0.33 x the sum of three reads first)
//   depth  = refraction alpha at the undistorted coordinate (ABOVEWATER; else 1): the water depth
//            the world shaders wrote to destination alpha
//   offset = (n.x, n.y) x n.a x c5 x depth  (c5 = ($reflectamount, $reflectamount,
//            $refractamount, $refractamount); BLURRY skips the x depth)
//   reflect = tex(reflection, reflect.xy / w + offset) x c4 (reflect tint)
//   refract = tex(refraction, refract.wz / w + offset); ABOVEWATER: depth = its alpha
//            BLURRY (ps_2_b+): the mean of 25 reads on a 5x5 grid 0.005 apart, x c1 (refract
//            tint), and reflect x c7.z (overbright) as well
//   F      = (1 - sat(normalize(eye_tangent) · n))^5 x sat((depth - 0.05) x 20)
//   refract = lerp(refract, fog x c30.x, ABOVEWATER ? sat(depth - 0.05)
//                                                   : sat((projZ - fogStart) / (fogEnd - fogStart)))
//   result = lerp(refract, reflect, F) (REFLECT and REFRACT), reflect alone, or refract alone;
//   alpha 1; FinalOutput with TONEMAP NONE (both render targets were already tone-mapped) and fog.
//
// Quirks kept from the SDK: without BLURRY the refract tint ($refracttint, c1) is never applied
// (water_ps2x_helper.h multiplies only the blurry result by it); with ABOVEWATER the depth comes
// from the refraction texture even in a REFLECT-only combo, so that texture must be bound.
//
// Reflection exposure in INTEGER HDR (WaterMaterial::exposure; water_reflection_scale() is the
// tone-map scale the reflection view renders with, water_constants() the matching tint). The
// reflection view renders into an 8-bit sRGB target, so whatever it stores above 1 is lost:
//  - reflectivity (luxel's default, the 2006 course notes' §8.5): the view renders with s x rho,
//    rho = the water's reflectivity, the largest channel of the linear reflect tint, and the
//    shader's tint is the linear tint / rho (largest channel 1). The target then holds what the
//    water will show in its brightest channel (rho s L), so that channel clips exactly where the
//    water's output clips anyway, and the target's 8 bits are spent on the displayed range. The
//    other channels clip with it (a grey radiance past the range shows tint / rho, the tint's hue)
//    where sdk_fixed keeps them up to s L = 4. rho <= 0 (no reflection) keeps s.
//  - sdk_fixed (water.cpp, viewrender.cpp; docs/fidelity.md#water: the SDK has no exposure that depends
//    on the reflectivity): the view renders with 0.25 s and the tint is GammaToLinear(tint) x 4, so
//    a reflected radiance L arrives as s L up to s L = 4 and clips there, whatever the tint; 2 bits
//    of the target's precision go to that headroom. The blurry variant multiplies by the
//    overbright constant c7.z = 4 *and* by the x4 tint, 16x in all: an SDK bug kept by default
//    (water_constants(..., faithful_blurry_overbright = false) turns it off).
// The tint clamp differs by HDR mode in the SDK: INTEGER converts $reflecttint with mathlib's
// GammaToLinear directly, which returns 1 for every value >= 0.95, so a tint above 1 is clamped to
// 1 (then x4); LDR and FLOAT go through the material conversion, which passes values above 1
// through as linear (material_color.hpp), so [2 2 2] reflects twice as bright there. The
// reflectivity mode converts like LDR (no clamp): rho = 2 exposes the view at 2 s.
//
// Not implemented: BASETEXTURE (lightmapped base on water), cheap water (WaterCheap, envmap
// only), flow maps, depth to dest alpha, NORMAL_DECODE_MODE != 0.

#include "luxel/shading/source/binaries.hpp"
#include "luxel/shading/source/common.hpp"
#include "luxel/shading/source/fog.hpp"
#include "luxel/shading/source/hdr_type.hpp"
#include "luxel/shading/source/material_color.hpp"

#include <algorithm>
#include <iterator>
#include <string>
#include <utility>

namespace luxel::shading::source {

struct WaterCombo {
  bool reflect = true;
  bool refract = true;
  bool above_water = true;
  bool multitexture = false;  ///< three normal-map reads ($scroll1 set)
  bool blurry_refract = false;  ///< $blurrefract: ps_2_b and up
  Fog fog = Fog::none;

  friend constexpr bool operator==(const WaterCombo&, const WaterCombo&) = default;
  /// water_ps2x.fxc: ps20 and ps20b only.
  static constexpr ShaderBuilds builds() { return kPs2xBuilds; }
  constexpr bool valid(ShaderModel m) const {
    if (!reflect && !refract) return false;  // the SDK returns black; never drawn
    if (blurry_refract && (m == ShaderModel::ps_2_0 || !refract)) return false;
    return fog_valid(fog, m);
  }
  std::string name() const {
    std::string n = reflect && refract ? "reflect+refract" : reflect ? "reflect" : "refract";
    n += above_water ? "+above" : "+below";
    if (multitexture) n += "+multitexture";
    if (blurry_refract) n += "+blurry";
    return n + fog_name(fog);
  }
};

/// Samplers and constants (registers as in water_ps2x.fxc).
struct WaterParams {
  Sampler2D refraction{0};  ///< _rt_WaterRefraction: sRGB read; alpha = water depth
  Sampler2D reflection{2};  ///< _rt_WaterReflection: sRGB read
  Sampler2D normal{4};
  glm::vec4 refract_tint{1.0f};     ///< c1: linear (blurry only)
  glm::vec4 reflect_tint{1.0f};     ///< c4: linear, x4 in INTEGER HDR
  glm::vec4 reflect_refract_scale{0.8f, 0.8f, 0.0f, 0.0f};  ///< c5: $reflectamount in xy, $refractamount in zw
  glm::vec4 fog_color{0.0f};        ///< c6: $fogcolor, linear
  glm::vec4 fog_params{0.0f, 1.0f, 1.0f, 0.0f};  ///< c7: fog start, end - start, reflect overbright
  ToneMapConstants tonemap{};
  FogConstants pixel_fog{};  ///< c8 (g_PixelFogParams), fog color, c9 eye position: the epilogue's fog
};

/// How the reflection view is exposed in INTEGER HDR (see the file comment).
enum class WaterReflectionExposure {
  reflectivity,  ///< s x rho, tint / rho (luxel's default, the 2006 notes)
  sdk_fixed,     ///< 0.25 s, tint x 4 (water.cpp)
};

/// The material parameters (gamma-space colors, as in the .vmt).
struct WaterMaterial {
  glm::vec3 reflect_tint{1.0f};
  glm::vec3 refract_tint{1.0f};
  glm::vec3 fog_color{0.0f};
  float reflect_amount = 0.8f;
  float refract_amount = 0.0f;
  float fog_start = 0.0f, fog_end = 1.0f;
  WaterReflectionExposure exposure = WaterReflectionExposure::reflectivity;
};

/// rho: the largest channel of the linear reflect tint (values above 1 pass, as in LDR); 1 when
/// the water reflects nothing, so that the view keeps the frame's exposure.
inline float water_reflectivity(const WaterMaterial& m) {
  const glm::vec3 linear = material_gamma_to_linear(m.reflect_tint);
  const float rho = std::max({linear.x, linear.y, linear.z});
  return rho > 0.0f ? rho : 1.0f;
}

/// The tone-map scale to render the reflection view with: in INTEGER HDR s x rho (reflectivity)
/// or 0.25 s (sdk_fixed); s in the other modes.
inline float water_reflection_scale(float tonemap_scale, HdrType hdr, const WaterMaterial& m) {
  if (hdr != HdrType::integer) return tonemap_scale;
  return m.exposure == WaterReflectionExposure::reflectivity ? tonemap_scale * water_reflectivity(m)
                                                             : 0.25f * tonemap_scale;
}

/// water.cpp's constants for a material, matching water_reflection_scale().
/// `faithful_blurry_overbright = false` leaves c7.z at 1, so the blurry variant of sdk_fixed does
/// not apply the x4 twice.
inline WaterParams water_constants(const WaterMaterial& m, HdrType hdr, const ToneMapConstants& tonemap,
                                   bool faithful_blurry_overbright = true) {
  WaterParams p;
  const bool fixed_quarter = hdr == HdrType::integer && m.exposure == WaterReflectionExposure::sdk_fixed;
  glm::vec3 reflect;
  if (fixed_quarter) {
    for (int i = 0; i < 3; ++i) reflect[i] = mathlib_gamma_to_linear(m.reflect_tint[i]) * 4.0f;
  } else if (hdr == HdrType::integer) {
    reflect = material_gamma_to_linear(m.reflect_tint) / water_reflectivity(m);
  } else {
    reflect = material_gamma_to_linear(m.reflect_tint);
  }
  p.reflect_tint = glm::vec4(reflect, 1.0f);
  p.refract_tint = glm::vec4(material_gamma_to_linear(m.refract_tint), 1.0f);
  p.fog_color = glm::vec4(material_gamma_to_linear(m.fog_color), 1.0f);
  p.reflect_refract_scale = glm::vec4(m.reflect_amount, m.reflect_amount, m.refract_amount, m.refract_amount);
  const float overbright = fixed_quarter && faithful_blurry_overbright ? 4.0f : 1.0f;
  p.fog_params = glm::vec4(m.fog_start, m.fog_end - m.fog_start, overbright, 0.0f);
  p.tonemap = tonemap;
  return p;
}

template <Lane L>
struct WaterInputs {
  float2<L> bump_uv;
  float4<L> extra_bump_uv;   ///< MULTITEXTURE: two more normal-map coordinates
  float3<L> tangent_eye;     ///< eye vector in tangent space, unnormalised
  float4<L> reflect_refract; ///< projective: reflection .xy, refraction .wz (times w)
  L w;                       ///< projection w
  L proj_z;                  ///< projection z (below-water fog, and the epilogue's pixel fog)
  L world_z = L(0.0f);       ///< world z (the epilogue's height fog)
};

/// The normal map read (texels only: the rest depends on it).
template <Lane L>
struct WaterNormalTexels {
  float4<L> n0{0.5f, 0.5f, 1.0f, 1.0f}, n1{0.5f, 0.5f, 1.0f, 1.0f}, n2{0.5f, 0.5f, 1.0f, 1.0f};
};

/// The shader with its render-target reads behind `read_refraction(uv)` / `read_reflection(uv)`,
/// so tests can drive the arithmetic with analytic images; water() binds them to tex2D.
template <WaterCombo C, Lane L, class RefractFn, class ReflectFn>
inline float4<L> water_combine(const WaterNormalTexels<L>& t, const WaterInputs<L>& in, const WaterParams& p,
                               RefractFn&& read_refraction, ReflectFn&& read_reflection) {
  float4<L> n = t.n0;
  if constexpr (C.multitexture) n = (t.n0 + t.n1 + t.n2) * 0.33f;
  n = float4<L>(n.xyz() * 2.0f - 1.0f, n.w);

  const L oo_w = 1.0f / in.w;
  const float4<L> projected = in.reflect_refract * oo_w;
  L depth = L(1.0f);
  float4<L> scale = constant<L>(p.reflect_refract_scale);
  if constexpr (!C.blurry_refract) {
    if constexpr (C.above_water) depth = read_refraction(float2<L>(projected.w, projected.z)).w;
    scale = scale * depth;
  }
  // reflect = .xy, refract = .wz: one mad for both.
  const float4<L> coords = float4<L>(n.x, n.y, n.y, n.x) * n.w * scale + projected;
  const float2<L> reflect_uv = coords.xy();
  const float2<L> refract_uv(coords.w, coords.z);

  const float4<L> fog = constant<L>(p.fog_color) * constant<L>(p.tonemap.c30).x;
  float3<L> reflect(0.0f), refract(0.0f);
  if constexpr (C.reflect) reflect = read_reflection(reflect_uv).rgb() * constant<L>(p.reflect_tint).rgb();
  if constexpr (C.blurry_refract) {
    float4<L> sum(0.0f);
    for (int i = -2; i <= 2; ++i)
      for (int j = -2; j <= 2; ++j) sum = sum + read_refraction(refract_uv + float2<L>(L(0.005f * i), L(0.005f * j)));
    const float4<L> blurred = sum * (1.0f / 25.0f);
    refract = blurred.rgb() * constant<L>(p.refract_tint).rgb();
    reflect = reflect * constant<L>(p.fog_params).z;
    if constexpr (C.above_water) depth = blurred.w;
  } else if constexpr (C.refract || C.above_water) {
    const float4<L> r = read_refraction(refract_uv);
    refract = r.rgb();
    if constexpr (C.above_water) depth = r.w;
  }

  // Fresnel (1 - sat(V·N))^5, faded to 0 where the water is shallow.
  const L n_dot_v = saturate(dot(normalize(in.tangent_eye), n.xyz()));
  const L fresnel = pow(1.0f - n_dot_v, L(5.0f)) * saturate((depth - 0.05f) * 20.0f);
  L fog_amount;
  if constexpr (C.above_water) {
    fog_amount = saturate(depth - 0.05f);
  } else {
    const float4<L> fp = constant<L>(p.fog_params);
    fog_amount = saturate((in.proj_z - fp.x) / fp.y);
  }
  refract = lerp(refract, fog.rgb(), fog_amount);

  float3<L> result;
  if constexpr (C.reflect && C.refract) {
    result = lerp(refract, reflect, fresnel);
  } else if constexpr (C.reflect) {
    result = reflect;
  } else {
    result = refract;
  }
  const FogInputs<L> pixel_fog{in.world_z, in.proj_z};
  return fogged_output<ToneMap::none, C.fog>(float4<L>(result, L(1.0f)), p.tonemap, pixel_fog, p.pixel_fog);
}

template <WaterCombo C, Lane L>
inline WaterNormalTexels<L> water_fetch_normals(const WaterInputs<L>& in, const WaterParams& p) {
  WaterNormalTexels<L> t;
  t.n0 = tex2D(p.normal, in.bump_uv);
  if constexpr (C.multitexture) {
    t.n1 = tex2D(p.normal, in.extra_bump_uv.xy());
    t.n2 = tex2D(p.normal, in.extra_bump_uv.zw());
  }
  return t;
}

template <WaterCombo C, Lane L>
inline float4<L> water(const WaterInputs<L>& in, const WaterParams& p) {
  return water_combine<C>(
      water_fetch_normals<C>(in, p), in, p, [&](const float2<L>& uv) { return tex2D(p.refraction, uv); },
      [&](const float2<L>& uv) { return tex2D(p.reflection, uv); });
}

template <WaterCombo C>
inline WaterInputs<Counted> water_counted_inputs(CountedInputs& in) {
  WaterInputs<Counted> r;
  r.bump_uv = in.vector<2>();
  r.tangent_eye = in.vector<3>();
  r.reflect_refract = in.vector<4>();
  r.w = in.scalar();
  r.proj_z = in.scalar();
  if constexpr (C.multitexture) r.extra_bump_uv = in.vector<4>();
  if constexpr (C.fog == Fog::height) r.world_z = in.scalar();
  return r;
}

template <WaterCombo C>
inline Cost measure_water(ShaderModel model) {
  const WaterParams params{};
  return measure(model, [&](CountedInputs& in) { return water<C>(water_counted_inputs<C>(in), params); });
}

}  // namespace luxel::shading::source
