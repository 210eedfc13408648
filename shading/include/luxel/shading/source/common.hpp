#pragma once
// What every Source DX9 shader shares: the tone-map epilogue (FinalOutput), the 8-bit encoding,
// the radiosity-normal-mapping basis, the ambient cube, the Fresnel forms.
// Written once over the lane L (float, simd::Float, Counted); docs/fidelity.md's sections
// cite where each formula comes from.
//
// Output convention (docs/fidelity.md#tone-mapping, #gamma-and-colors):
//   FinalOutput multiplies rgb by LINEAR_LIGHT_SCALE (c30.x) and hands a *linear* color to the
//   output merger, which encodes it with D3D9's SRGBWRITEENABLE: the exact IEC 61966-2-1 sRGB
//   curve, then 8 bits (rasterizer: BlendState::srgb_write). World and model shaders write with
//   sRGB write on in the SDK, and the hardware sRGB write is defined by D3D as the sRGB curve, not
//   the pure 2.2 power the shaders use for *material colors* (GammaToLinear). ps_2_b's
//   CONVERT_TO_SRGB path uses a gamma table at s15 whose contents are closed (NOT IN SDK); we take
//   it to be the same sRGB curve, so both paths give the same bytes. encode_srgb8() below is that
//   encoding written over the lane, for tests and for callers that write bytes themselves; it is
//   not part of the measured pixel-shader cost (on the hardware it is the ROP's work).
//   NaN: saturate(NaN) = 0 (intrinsics.hpp), so a NaN channel encodes to byte 0, as the
//   rasterizer's output merger also writes NaN as 0. +inf encodes to 255, -inf to 0.

#include "luxel/rasterizer/srgb.hpp"
#include "luxel/shading/hlsl.hpp"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cmath>
#include <cstdint>

namespace luxel::shading::source {

using namespace luxel::shading;

/// The three pixel-shader models the Source DX9 shaders are built for.
inline constexpr ShaderModel kPixelModels[] = {ShaderModel::ps_2_0, ShaderModel::ps_2_b, ShaderModel::ps_3_0};

/// FinalOutput's TONEMAP_SCALE_* (common_ps_fxc.h).
enum class ToneMap { none, linear, gamma };

/// Constant register c30 (docs/fidelity.md#tone-mapping): x = LINEAR_LIGHT_SCALE, y = LIGHT_MAP_SCALE,
/// z = ENV_MAP_SCALE, w = GAMMA_LIGHT_SCALE (= x^(1/2.2), the client's own convention).
struct ToneMapConstants {
  glm::vec4 c30{1.0f, 1.0f, 1.0f, 1.0f};
  /// c30 for a linear tone-map scale s (INTEGER HDR: the auto-exposure scale; LDR: 1).
  static ToneMapConstants for_scale(float s, float lightmap_scale = 1.0f, float envmap_scale = 1.0f);
};

inline ToneMapConstants ToneMapConstants::for_scale(float s, float lightmap_scale, float envmap_scale) {
  ToneMapConstants t;
  t.c30 = glm::vec4(s, lightmap_scale, envmap_scale, std::pow(s, 1.0f / 2.2f));
  return t;
}

// Per-model differences of FinalOutput (common_ps_fxc.h) and where they are:
//  - fog: ps_2_0 has no pixel range fog (fog.hpp models both paths);
//  - CONVERT_TO_SRGB (ps_2_b / ps_3_0, SRGBOutput through the gamma table at s15): not modelled;
//    the table is closed and luxel encodes with the hardware sRGB write on every model (above);
//  - WRITE_DEPTH_TO_DESTALPHA (ps_2_b / ps_3_0: alpha = projZ x c29.w; ps_2_0's DepthToDestAlpha
//    returns 1 and the ps_2_0 builds pass false): not modelled. Its reader is the water's
//    refraction alpha (water.hpp takes that depth as given) and soft particles; which passes write
//    it is the frame's decision, so the shaders' alpha stays the shader's alpha here.

/// FinalOutput (docs/fidelity.md#tone-mapping, before fog): rgb x the tone-map scale of type T; alpha
/// passes. Returns the linear color the output merger encodes; fogged_output() (fog.hpp) adds step 3.
template <ToneMap T, Lane L>
inline float4<L> final_output(const float4<L>& color, const ToneMapConstants& tm) {
  if constexpr (T == ToneMap::none) {
    return color;
  } else {
    const float4<L> c30 = constant<L>(tm.c30);
    const L scale = T == ToneMap::linear ? c30.x : c30.w;
    return float4<L>(color.rgb() * scale, color.w);
  }
}

/// Exact sRGB encode (IEC 61966-2-1) of a linear value, after saturate (NaN -> 0).
template <Lane L>
inline L linear_to_srgb(const L& x) {
  const L c = saturate(x);
  const L lo = c * 12.92f;
  const L hi = pow(c, L(1.0f / 2.4f)) * 1.055f - 0.055f;
  return select(c <= L(0.0031308f), lo, hi);
}

/// The 8-bit value (0..255, as a float lane) of a [0,1] encoded value: round(sat(x) * 255).
template <Lane L>
inline L unorm8(const L& x) {
  return floor(saturate(x) * 255.0f + 0.5f);
}

/// What the output merger stores for a FinalOutput color with sRGB write on: rgb sRGB-encoded,
/// alpha linear, each 0..255.
template <Lane L>
inline float4<L> encode_srgb8(const float4<L>& linear) {
  return float4<L>(unorm8(linear_to_srgb(linear.x)), unorm8(linear_to_srgb(linear.y)),
                   unorm8(linear_to_srgb(linear.z)), unorm8(linear.w));
}

/// Same on the CPU in double precision: the reference the lanes are measured against.
inline uint8_t srgb8_reference(double x) {
  if (!(x > 0.0)) return 0;  // NaN and <= 0
  if (x >= 1.0) return 255;
  return static_cast<uint8_t>(std::floor(rasterizer::linear_to_srgb(x) * 255.0 + 0.5));
}

/// The RNM basis (docs/fidelity.md#rnm-basis-and-lightmaps, common_fxc.h bumpBasis), the shader's
/// literals exactly.
inline constexpr float kBumpBasis[3][3] = {
    {0.81649661064147949f, 0.0f, 0.57735025882720947f},
    {-0.40824833512306213f, 0.70710676908493042f, 0.57735025882720947f},
    {-0.40824821591377258f, -0.7071068286895752f, 0.57735025882720947f},
};

/// The RNM weights of a tangent-space normal (docs/fidelity.md#lightmappedgeneric):
/// d_i = sat(dot(n, basis_i))^2. LightmappedGeneric lights with sum d_i LM_i / sum d_i.
template <Lane L>
inline float3<L> rnm_weights(const float3<L>& n) {
  const float3<L> d(saturate(dot(n, float3<L>(kBumpBasis[0][0], kBumpBasis[0][1], kBumpBasis[0][2]))),
                    saturate(dot(n, float3<L>(kBumpBasis[1][0], kBumpBasis[1][1], kBumpBasis[1][2]))),
                    saturate(dot(n, float3<L>(kBumpBasis[2][0], kBumpBasis[2][1], kBumpBasis[2][2]))));
  return d * d;
}

/// Six ambient-cube colors, order +X, -X, +Y, -Y, +Z, -Z (docs/fidelity.md#ambient-cube), linear.
struct AmbientCube {
  std::array<glm::vec3, 6> color{};
};

/// PixelShaderAmbientLight (docs/fidelity.md#ambient-cube): n^2 weights, + entry where n >= 0. Nine
/// ps_3_0 slots (mul, cmp, cmp, mul, mad x5), the count in Valve's comment.
template <Lane L>
inline float3<L> ambient_light(const float3<L>& n, const AmbientCube& cube) {
  const float3<L> n2 = n * n;
  const bool3<L> plus = n >= 0.0f;
  const float3<L> p = select(plus, n2, 0.0f);
  const float3<L> m = select(plus, 0.0f, n2);
  return p.x * constant<L>(cube.color[0]) + m.x * constant<L>(cube.color[1]) + p.y * constant<L>(cube.color[2]) +
         m.y * constant<L>(cube.color[3]) + p.z * constant<L>(cube.color[4]) + m.z * constant<L>(cube.color[5]);
}

/// CPU reference of the ambient cube (double), for tests and light folding.
inline glm::dvec3 ambient_light_reference(const glm::dvec3& n, const AmbientCube& cube) {
  glm::dvec3 r(0.0);
  for (int a = 0; a < 3; ++a) r += n[a] * n[a] * glm::dvec3(cube.color[2 * a + (n[a] >= 0.0 ? 0 : 1)]);
  return r;
}

/// Squared Half-Lambert, saturated before squaring (docs/fidelity.md#model-lights, DiffuseTerm).
template <Lane L>
inline L half_lambert(const L& n_dot_l) {
  const L h = saturate(n_dot_l * 0.5f + 0.5f);
  return h * h;
}

}  // namespace luxel::shading::source
