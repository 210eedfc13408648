#pragma once
// Sky_HDR_DX9, the HDR skybox pixel shader: one texture read, times an input scale, tone-mapped
// with LINEAR scale and never fogged (docs/fidelity.md#sky; sky_ps2x.fxc,
// sky_hdr_compressed_rgbs_ps2x.fxc, sky_hdr_dx9.cpp).
//
// Static combos (SkyCombo::texture):
//   hdr16            sky_ps2x: color = tex.rgb x c0.rgb. The texture is 16 bits per channel,
//                    read with sRGB off: RGBA16 UNORM stores linear / 16, so c0 = $color x 16;
//                    RGBA16F stores linear light, c0 = $color (sky_input_scale()).
//   rgbs_compressed  sky_hdr_compressed_rgbs_ps2x: an 8-bit RGBA texture holding rgb x scale in
//                    alpha, decoded as rgb x a x 8 (c0 = $color x 8); the shader reads the four
//                    nearest texels with point sampling and interpolates by hand *after*
//                    decoding, since filtering rgb and a separately is not filtering rgb·a.
// Alpha: the texel's alpha (hdr16), 1 (rgbs). The same code is measured on ps_2_0, ps_2_b and
// ps_3_0 (the SDK builds ps20 and ps20b; ps_3_0 cards run ps20b).
//
// The 16-bit scale (MAX_HDR_OVERBRIGHT = 16 is only the legacy RGB·A·16 helpers'): sky_hdr_dx9.cpp
// multiplies c0 by 16 for IMAGE_FORMAT_RGBA16161616, so a 16-bit UNORM sky covers linear 0..16 in
// steps of 16 / 65535. It also multiplies by 16 for RGBA16161616F when the HDR type is INTEGER,
// which only makes sense if the closed texture loader re-encodes float skies as value / 16 in that
// mode; luxel keeps an RGBA16F texture as uploaded (linear), so its scale stays $color in every
// mode.
//
// The rgbs interpolants (four texel coordinates and the pixel-space coordinate) come from
// sky_vs20.fxc (lines 47-60) and the constants sky_hdr_dx9.cpp sends (c1 = (0.5/w - fudge,
// 0.5/h - fudge, w, h), fudge = 0.01 / max(w, h)): the four texels uv ± c1.xy, which is what
// bilinear filtering would read, and the pixel coordinate (uv - c1.xy) x c1.zw.
// sky_rgbs_coordinates() computes the same texels; its pixel coordinate is uv x size - 0.5,
// without the fudge (docs/fidelity.md#sky: at most 0.01 texel in the interpolation fraction).
//
// Not implemented: $hdrcompressedtexture0..2 (compression method B), WRITE_DEPTH_TO_DESTALPHA
// (ps_2_b: alpha = saturate(1e20 x c29.w) = 1), CONVERT_TO_SRGB (see common.hpp).

#include "luxel/shading/source/binaries.hpp"
#include "luxel/shading/source/common.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <iterator>
#include <string>
#include <utility>

namespace luxel::shading::source {

enum class SkyTexture {
  hdr16,            ///< RGBA16 or RGBA16F, one bilinear read
  rgbs_compressed,  ///< RGBA8 rgb x a x 8, four point reads, bilinear after decoding
};

struct SkyCombo {
  SkyTexture texture = SkyTexture::hdr16;

  constexpr bool valid() const { return true; }
  /// sky_ps2x.fxc, sky_hdr_compressed_rgbs_ps2x.fxc: ps20 and ps20b only.
  static constexpr ShaderBuilds builds() { return kPs2xBuilds; }
  std::string name() const { return texture == SkyTexture::hdr16 ? "hdr16" : "rgbs"; }
  constexpr bool operator==(const SkyCombo&) const = default;
};

/// The texture formats the hdr16 combo reads.
enum class SkyFormat {
  rgba16,   ///< 16-bit UNORM holding linear / 16
  rgba16f,  ///< half float holding linear
};

/// c0.rgb for the hdr16 combo: $color x 16 for RGBA16 UNORM, $color for RGBA16F (see above).
inline glm::vec3 sky_input_scale(SkyFormat format, const glm::vec3& color = glm::vec3(1.0f)) {
  return format == SkyFormat::rgba16 ? color * 16.0f : color;
}
/// c0.rgb for the rgbs combo: $color x 8.
inline glm::vec3 sky_rgbs_input_scale(const glm::vec3& color = glm::vec3(1.0f)) { return color * 8.0f; }

/// The 16-bit UNORM texel that stores linear value x (what a sky texture's converter writes).
inline float encode_sky_rgba16(float linear) { return std::clamp(linear / 16.0f, 0.0f, 1.0f); }

struct SkyParams {
  Sampler2D base{0};        ///< hdr16: bilinear, sRGB off; rgbs: point sampling
  glm::vec4 input_scale{1.0f};  ///< c0: rgb from sky_input_scale() / sky_rgbs_input_scale()
  ToneMapConstants tonemap{};
};

template <Lane L>
struct SkyInputs {
  float2<L> uv;                               ///< hdr16
  float2<L> uv00, uv01, uv10, uv11;           ///< rgbs: the four texels (x right, y down)
  float2<L> uv_in_texels;                     ///< rgbs: its fraction weighs them
};

/// The rgbs interpolants for texture coordinate uv on a w x h texture (our reconstruction of
/// sky_vs20, see above), on any lane (the vertex stage uses float).
template <Lane L>
inline void sky_rgbs_coordinates(const float2<L>& uv, float w, float h, SkyInputs<L>& in) {
  const float fudge = 0.01f / std::max(w, h);
  const float2<L> half(L(0.5f / w - fudge), L(0.5f / h - fudge));
  in.uv00 = uv - half;
  in.uv10 = float2<L>(uv.x + half.x, uv.y - half.y);
  in.uv01 = float2<L>(uv.x - half.x, uv.y + half.y);
  in.uv11 = uv + half;
  in.uv_in_texels = float2<L>(uv.x * w - 0.5f, uv.y * h - 0.5f);
}

template <Lane L>
struct SkyTexels {
  float4<L> base{1.0f};  ///< hdr16
  float4<L> s00{1.0f}, s01{1.0f}, s10{1.0f}, s11{1.0f};  ///< rgbs
};

template <SkyCombo C, Lane L>
inline SkyTexels<L> sky_fetch(const SkyInputs<L>& in, const SkyParams& p) {
  SkyTexels<L> t;
  if constexpr (C.texture == SkyTexture::hdr16) {
    t.base = tex2D(p.base, in.uv);
  } else {
    t.s00 = tex2D(p.base, in.uv00);
    t.s10 = tex2D(p.base, in.uv10);
    t.s01 = tex2D(p.base, in.uv01);
    t.s11 = tex2D(p.base, in.uv11);
  }
  return t;
}

template <SkyCombo C, Lane L>
inline float4<L> sky_combine(const SkyTexels<L>& t, const SkyInputs<L>& in, const SkyParams& p) {
  const float3<L> scale = constant<L>(p.input_scale).rgb();
  if constexpr (C.texture == SkyTexture::hdr16) {
    return final_output<ToneMap::linear>(float4<L>(t.base.rgb() * scale, t.base.w), p.tonemap);
  } else {
    // Decode each texel (rgb x a), then interpolate: x within the rows, then y.
    const float2<L> f = frac(in.uv_in_texels);
    const float3<L> top = lerp(t.s00.rgb() * t.s00.w, t.s10.rgb() * t.s10.w, f.x);
    const float3<L> bottom = lerp(t.s01.rgb() * t.s01.w, t.s11.rgb() * t.s11.w, f.x);
    return final_output<ToneMap::linear>(float4<L>(lerp(top, bottom, f.y) * scale, L(1.0f)), p.tonemap);
  }
}

template <SkyCombo C, Lane L>
inline float4<L> sky(const SkyInputs<L>& in, const SkyParams& p) {
  return sky_combine<C>(sky_fetch<C>(in, p), in, p);
}

template <SkyCombo C>
inline SkyInputs<Counted> sky_counted_inputs(CountedInputs& in) {
  SkyInputs<Counted> r;
  if constexpr (C.texture == SkyTexture::hdr16) {
    r.uv = in.vector<2>();
  } else {
    r.uv00 = in.vector<2>();
    r.uv01 = in.vector<2>();
    r.uv10 = in.vector<2>();
    r.uv11 = in.vector<2>();
    r.uv_in_texels = in.vector<2>();
  }
  return r;
}

template <SkyCombo C>
inline Cost measure_sky(ShaderModel model) {
  const SkyParams params{};
  return measure(model, [&](CountedInputs& in) { return sky<C>(sky_counted_inputs<C>(in), params); });
}

}  // namespace luxel::shading::source
