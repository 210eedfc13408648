#pragma once
// The bloom's downsample (docs/fidelity.md#bloom; Downsample_nohdr_ps2x.fxc, downsample_nohdr.cpp):
// the tone-mapped 8-bit frame, read as gamma values (sRGB read off), to a quarter-size
// target. Four bilinear taps at source-texel offsets (0.5, 0.5), (2.5, 0.5), (0.5, 2.5), (2.5, 2.5)
// from the pixel's base coordinate, each landing between two texels on both axes, so the four
// cover a 4x4 block. Each tap is shaped before the average, so that bright texels survive and
// dark ones vanish:
//
//   lum = dot(p, tint.rgb);   p <- pow(p, tint.w) * lum;   out = average of the 4 shaped taps
//
// tint = c0 = (r_bloomtintr, g, b, r_bloomtintexponent) = (0.3, 0.59, 0.11, 2.2); with
// $bloomtintenable 0 the weights are 0.333 and the exponent 1 (downsample_constant()). The SDK
// switches this with constants, not a static combo, so there is one shader.
//
// Alpha: 1. What the SDK writes there is not read by any later pass (the blur reads rgb, bloomadd
// does not write alpha), so it is our choice.
// No FinalOutput tone map (post passes use TONEMAP NONE); the 8-bit target stores gamma
// values as they are (no sRGB write).
//
// Where the taps are: the SDK's vertex shader adds the four offsets (in source texels) to the
// interpolated coordinate, so the pixel shader receives four coordinates and its four texld are
// not dependent reads. The pixel functor below takes them as varyings 0.xy, 0.zw, 1.xy, 1.zw
// (postfx's screen rectangle writes them).

#include "luxel/shading/source/binaries.hpp"
#include "luxel/rasterizer/draw.hpp"
#include "luxel/shading/source/common.hpp"
#include "luxel/shading/source/shader_use.hpp"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <tuple>

namespace luxel::shading::source {

/// The tap offsets in source texels.
inline constexpr glm::vec2 kDownsampleTapOffsets[4] = {{0.5f, 0.5f}, {2.5f, 0.5f}, {0.5f, 2.5f}, {2.5f, 2.5f}};

/// c0 of the downsample: the tint weights and exponent, or the neutral ones with the tint off.
inline glm::vec4 downsample_constant(bool tint_enable) {
  return tint_enable ? glm::vec4(0.3f, 0.59f, 0.11f, 2.2f) : glm::vec4(0.333f, 0.333f, 0.333f, 1.0f);
}

struct DownsampleParams {
  Sampler2D frame{0};  ///< _rt_FullFrameFB: RGBA8 gamma values, bilinear, clamped
  glm::vec4 tint = downsample_constant(true);  ///< c0
};

/// One tap shaped: pow(p, tint.w) * dot(p, tint.rgb).
template <Lane L>
inline float3<L> bloom_shape(const float3<L>& p, const float4<L>& tint) {
  return pow(p, tint.w) * dot(p, tint.xyz());
}

/// The shader after its four fetches (tests drive it with arbitrary texels).
template <Lane L>
inline float4<L> downsample_combine(const std::array<float3<L>, 4>& taps, const DownsampleParams& p) {
  const float4<L> tint = constant<L>(p.tint);
  const float3<L> sum = bloom_shape(taps[0], tint) + bloom_shape(taps[1], tint) + bloom_shape(taps[2], tint) +
                        bloom_shape(taps[3], tint);
  return float4<L>(sum * 0.25f, L(1.0f));
}

/// The pixel shader: four coordinates in, the shaped average out.
template <Lane L>
inline float4<L> downsample(const std::array<float2<L>, 4>& coords, const DownsampleParams& p) {
  const std::array<float4<L>, 4> texels = tex2D_taps(p.frame, coords);
  std::array<float3<L>, 4> taps;
  for (size_t i = 0; i < 4; ++i) taps[i] = texels[i].rgb();
  return downsample_combine(taps, p);
}

inline Cost measure_downsample(ShaderModel model) {
  const DownsampleParams params{};
  return measure(model, [&](CountedInputs& in) {
    std::array<float2<Counted>, 4> coords;
    for (auto& c : coords) c = in.vector<2>();
    return downsample(coords, params);
  });
}

/// The shader as a rasterizer pixel functor: taps in varyings 0.xy, 0.zw, 1.xy, 1.zw.
struct DownsamplePixelShader {
  static constexpr const char* kFamily = "Downsample_nohdr";  ///< its name in the shading catalog
  /// Downsample_nohdr_ps2x.fxc: ps20 and ps20b only.
  static constexpr ShaderBuilds kBuilds = kPs2xBuilds;
  static constexpr bool kCanDiscard = false;
  static constexpr bool kWritesDepth = false;
  const DownsampleParams* params = nullptr;
  std::atomic<uint64_t>* pixels = nullptr;  ///< counts the pixels shaded when set (shader_use.hpp)

  void operator()(const rasterizer::PixelInput<2>& in, rasterizer::PixelOutput& out) const {
    count_pixels(pixels, in.live);
    const std::array<float2<simd::Float>, 4> coords = {
        float2<simd::Float>(in.varyings[0].x, in.varyings[0].y), float2<simd::Float>(in.varyings[0].z, in.varyings[0].w),
        float2<simd::Float>(in.varyings[1].x, in.varyings[1].y), float2<simd::Float>(in.varyings[1].z, in.varyings[1].w)};
    const float4<simd::Float> c = downsample(coords, *params);
    out.color = {c.x, c.y, c.z, c.w};
  }
};

}  // namespace luxel::shading::source
