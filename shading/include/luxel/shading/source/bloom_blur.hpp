#pragma once
// The bloom's blur (docs/fidelity.md#bloom; BlurFilter_ps2x.fxc, BlurFilterX.cpp, BlurFilterY.cpp):
// 13 bilinear taps along one axis, a centre and six symmetric pairs. Each pair's tap sits between
// two texels at the offset where bilinear filtering gives the two texels the weights of a wider
// kernel, so 13 fetches make a 25-texel kernel (per-texel weights 0.2013, 0.14495, 0.07355, ...;
// heavy-tailed, not a Gaussian):
//
//   out.rgb = scale.rgb * (0.2013 t(0) + sum_k w_k (t(+o_k) + t(-o_k)))
//   w = 0.2185, 0.0821, 0.0461, 0.0262, 0.0162, 0.0102   at o = 1.3366, 3.4295, 5.4264, 7.4359,
//   9.4436, 11.4401 texels along the pass's axis.
//
// One shader for both passes; blur_constants() sets the axis and the scale:
//  - horizontal (dev/blurfilterx): step 1/width along u, scale 1;
//  - vertical (dev/blurfiltery): step along v, scale = the bloom amount. The SDK computes
//    this step from the texture's *width* (BlurFilterY.cpp reads GetActualWidth() into its height),
//    so a vertical tap lands at o_k * height/width texels: 0.5625 of a texel at 16:9. That quirk is
//    the default (BlurStep::sdk_width_quirk); BlurStep::true_height steps whole texels.
// Alpha: 1 (nothing reads it; see bloom_downsample.hpp).
//
// The SDK's vertex shader computes some tap coordinates and the pixel shader the rest; here the
// pixel shader adds all twelve offsets (constants c0-c2, two offsets per register) to the one
// interpolated coordinate. The taps are the same; on the Counted lane this costs twelve adds and
// makes the twelve fetches first-order dependent reads, which every model allows.

#include "luxel/shading/source/binaries.hpp"
#include "luxel/rasterizer/draw.hpp"
#include "luxel/shading/source/common.hpp"
#include "luxel/shading/source/shader_use.hpp"

#include <glm/vec4.hpp>

#include <array>

namespace luxel::shading::source {

inline constexpr float kBlurCentreWeight = 0.2013f;
inline constexpr float kBlurPairWeights[6] = {0.2185f, 0.0821f, 0.0461f, 0.0262f, 0.0162f, 0.0102f};
inline constexpr float kBlurPairOffsets[6] = {1.3366f, 3.4295f, 5.4264f, 7.4359f, 9.4436f, 11.4401f};

enum class BlurAxis { horizontal, vertical };

/// How the vertical pass steps one texel.
enum class BlurStep {
  sdk_width_quirk,  ///< 1/width, as BlurFilterY.cpp does (the default)
  true_height,      ///< 1/height
};

struct BlurParams {
  Sampler2D source{0};  ///< _rt_SmallFB0 or 1: RGBA8, bilinear, clamped
  /// c0-c2: the uv offsets of pairs (0, 1), (2, 3), (4, 5), as (u_a, v_a, u_b, v_b).
  std::array<glm::vec4, 3> offsets{};
  glm::vec4 scale{1.0f};  ///< c3: rgb multiplier (the bloom amount in the vertical pass)
};

/// The constants of one pass over a width x height source: the axis, the vertical step's rule,
/// and the scale (1 for the horizontal pass, the bloom amount for the vertical one).
inline BlurParams blur_constants(BlurAxis axis, int width, int height, BlurStep step, float scale) {
  BlurParams p;
  glm::vec2 texel(0.0f);
  if (axis == BlurAxis::horizontal) {
    texel.x = 1.0f / static_cast<float>(width);
  } else {
    texel.y = 1.0f / static_cast<float>(step == BlurStep::sdk_width_quirk ? width : height);
  }
  for (int k = 0; k < 6; ++k) {
    const glm::vec2 o = texel * kBlurPairOffsets[k];
    p.offsets[k / 2][2 * (k % 2)] = o.x;
    p.offsets[k / 2][2 * (k % 2) + 1] = o.y;
  }
  p.scale = glm::vec4(scale, scale, scale, 1.0f);
  return p;
}

/// The 13 fetched texels: the centre, then the pairs (+o_k, -o_k) for k = 0..5.
template <Lane L>
struct BlurTaps {
  float3<L> centre;
  std::array<float3<L>, 6> plus, minus;
};

/// The weighted sum over taps that `fetch(k, side)` returns (k = -1: the centre; else pair k, side
/// +1 or -1), accumulated in tap order, so that few fetched texels are alive at once (ps_2_0 has
/// 12 temporaries for 13 taps).
template <Lane L, class Fetch>
inline float4<L> blur_sum(const Fetch& fetch, const BlurParams& p) {
  float3<L> sum = fetch(-1, 0) * kBlurCentreWeight;
  for (int k = 0; k < 6; ++k) sum = sum + (fetch(k, +1) + fetch(k, -1)) * kBlurPairWeights[k];
  return float4<L>(sum * constant<L>(p.scale).xyz(), L(1.0f));
}

/// The shader after its fetches (tests drive it with arbitrary texels).
template <Lane L>
inline float4<L> blur_combine(const BlurTaps<L>& t, const BlurParams& p) {
  return blur_sum<L>([&](int k, int side) -> float3<L> { return k < 0 ? t.centre : side > 0 ? t.plus[k] : t.minus[k]; }, p);
}

/// The coordinate of tap (k, side), as blur_sum names taps: the pixel's own, or offset by pair k.
template <Lane L>
inline float2<L> blur_tap(const float2<L>& uv, int k, int side, const BlurParams& p) {
  if (k < 0) return uv;
  const float4<L> o = constant<L>(p.offsets[k / 2]);
  const float2<L> offset = k % 2 == 0 ? float2<L>(o.xy()) : float2<L>(o.zw());
  return side > 0 ? uv + offset : uv - offset;
}

/// The pixel shader.
template <Lane L>
inline float4<L> blur(const float2<L>& uv, const BlurParams& p) {
  return blur_sum<L>([&](int k, int side) -> float3<L> { return tex2D(p.source, blur_tap(uv, k, side, p)).rgb(); }, p);
}

inline Cost measure_blur(ShaderModel model) {
  const BlurParams params = blur_constants(BlurAxis::vertical, 320, 180, BlurStep::sdk_width_quirk, 0.3f);
  return measure(model, [&](CountedInputs& in) { return blur(in.vector<2>(), params); });
}

/// The shader as a rasterizer pixel functor: varying 0 .xy is the source coordinate.
struct BlurPixelShader {
  static constexpr const char* kFamily = "BlurFilter";  ///< its name in the shading catalog
  /// BlurFilter_ps2x.fxc: ps20 and ps20b only.
  static constexpr ShaderBuilds kBuilds = kPs2xBuilds;
  static constexpr bool kCanDiscard = false;
  static constexpr bool kWritesDepth = false;
  const BlurParams* params = nullptr;
  std::atomic<uint64_t>* pixels = nullptr;  ///< counts the pixels shaded when set (shader_use.hpp)

  /// blur(): its thirteen reads in one call (tex2D_taps), the same values. (blur() itself fetches
  /// tap by tap, which is what the Counted lane measures: few texels alive at once.)
  void operator()(const rasterizer::PixelInput<1>& in, rasterizer::PixelOutput& out) const {
    using F = simd::Float;
    count_pixels(pixels, in.live);
    const float2<F> uv(in.varyings[0].x, in.varyings[0].y);
    // Tap (k, side) at index 0 for the centre, 1 + 2k + (side < 0) for pair k.
    const auto index = [](int k, int side) { return k < 0 ? 0 : 1 + 2 * k + (side < 0 ? 1 : 0); };
    std::array<float2<F>, 13> coords;
    coords[0] = uv;
    for (int k = 0; k < 6; ++k) {
      coords[size_t(index(k, +1))] = blur_tap(uv, k, +1, *params);
      coords[size_t(index(k, -1))] = blur_tap(uv, k, -1, *params);
    }
    const std::array<float4<F>, 13> texels = tex2D_taps(params->source, coords);
    const float4<F> c = blur_sum<F>([&](int k, int side) { return texels[size_t(index(k, side))].rgb(); }, *params);
    out.color = {c.x, c.y, c.z, c.w};
  }
};

}  // namespace luxel::shading::source
