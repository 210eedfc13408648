#pragma once
// Color correction through 3D lookup tables (docs/fidelity.md#color-correction;
// colorcorrection_ps2x.fxc, the same lookups Engine_Post_ps2x.fxc makes after the bloom add): one
// full-screen pass over the gamma-space 8-bit frame that blends up to four 32x32x32 volume lookups with
// the frame itself.
//
//   uvw     = frame.rgb * 31/32 + 0.5/32                              (texel centers 0..31)
//   out.rgb = frame.rgb * defaultWeight + sum_k tex3D(LUT_k, uvw).rgb * w_k,   k < number of LUTs
//   out.a   = frame.a
//
// The frame and the volumes are read with sRGB decode off and the output is written with sRGB
// write off (post passes run in gamma space), so the bytes in are the bytes the LUT
// was authored for. The volume is filtered trilinearly (the SDK's filter state is closed:
// trilinear presumed); the frame is read with point filtering, which at the pixel centers this
// pass samples gives the texel itself, exactly.
//
// Static combos (ColorCorrectionCombo): the number of lookups, 1..4 (the SDK's NUM_LOOKUPS; with 0
// the pass does not run). The samplers are s0 (frame) and s1..s4 (LUTs), as in the standalone
// shader. Constants: c0 = (w0, w1, w2, w3), c1.x = defaultWeight; how the SDK packs them and how it
// normalizes the weights are closed: postfx/color_correction.hpp states luxel's rule.
// The frame's alpha passes through, as colorcorrection_ps2x.fxc keeps baseColor.a.
// The same code is measured on ps_2_0, ps_2_b and ps_3_0 (the SDK builds ps20 and ps20b;
// docs/fidelity.md#shader-models).

#include "luxel/shading/source/binaries.hpp"
#include "luxel/rasterizer/draw.hpp"
#include "luxel/shading/source/common.hpp"
#include "luxel/shading/source/shader_use.hpp"

#include <glm/vec4.hpp>

#include <array>
#include <iterator>
#include <string>
#include <utility>

namespace luxel::shading::source {

/// The edge of the engine's LUT volume (RGBX5551 keys, 5 bits per channel). Other edges
/// are luxel's, to measure what the engine's choice costs (`luxel report`, color_correction).
inline constexpr int kColorCorrectionLutSize = 32;
/// Most lookups one pass blends.
inline constexpr int kMaxColorCorrectionLuts = 4;

struct ColorCorrectionCombo {
  int luts = 1;  ///< lookups blended, 1..kMaxColorCorrectionLuts

  constexpr bool valid() const { return luts >= 1 && luts <= kMaxColorCorrectionLuts; }
  friend constexpr bool operator==(const ColorCorrectionCombo&, const ColorCorrectionCombo&) = default;
  std::string name() const { return std::to_string(luts) + (luts == 1 ? "lut" : "luts"); }
};

/// How the frame is read: point, no mips (see above); clamped, so nothing wraps at the edges.
inline rasterizer::Sampler color_correction_frame_sampler() {
  rasterizer::Sampler s;
  s.min = s.mag = rasterizer::Filter::Point;
  s.mip = rasterizer::MipFilter::None;
  s.u = s.v = s.w = rasterizer::Address::Clamp;
  return s;
}

/// How a LUT volume is read: trilinear within its one level, clamped (luxel's: the SDK's is closed).
inline rasterizer::Sampler color_correction_lut_sampler() {
  rasterizer::Sampler s;
  s.min = s.mag = rasterizer::Filter::Linear;
  s.mip = rasterizer::MipFilter::None;
  s.u = s.v = s.w = rasterizer::Address::Clamp;
  return s;
}

struct ColorCorrectionParams {
  Sampler2D frame{0, nullptr, color_correction_frame_sampler()};  ///< the 8-bit frame, sRGB read off
  std::array<Sampler3D, kMaxColorCorrectionLuts> luts{
      Sampler3D{1, nullptr, color_correction_lut_sampler()}, Sampler3D{2, nullptr, color_correction_lut_sampler()},
      Sampler3D{3, nullptr, color_correction_lut_sampler()}, Sampler3D{4, nullptr, color_correction_lut_sampler()}};
  glm::vec4 lut_weights{0.0f};  ///< c0: w0..w3
  float default_weight = 1.0f;  ///< c1.x: the frame's own weight
  int lut_size = kColorCorrectionLutSize;  ///< the volumes' edge: the literals of the uvw's mad
};

/// The volume coordinate of a color (for the engine's size 32: uvw = c * 31/32 + 0.5/32):
/// 0 and 1 land on the first and last texel centers of a volume `size` texels on a side.
template <Lane L>
inline float3<L> color_correction_uvw(const float3<L>& color, int size = kColorCorrectionLutSize) {
  const float n = float(size);
  return color * ((n - 1.0f) / n) + 0.5f / n;
}

/// The blend of the frame's color with the lookups already fetched (lookups[k] for k < C.luts):
/// c0 = lut_weights, c1.x = default_weight.
template <ColorCorrectionCombo C, Lane L>
inline float3<L> color_correction_combine(const float3<L>& frame,
                                          const std::array<float3<L>, kMaxColorCorrectionLuts>& lookups,
                                          const glm::vec4& lut_weights, float default_weight) {
  static_assert(C.valid());
  const float4<L> weights = constant<L>(lut_weights);
  float3<L> out = frame * constant<L>(default_weight);
  for (int k = 0; k < C.luts; ++k) out = out + lookups[k] * weights[k];
  return out;
}

/// The pixel shader: uv is the frame's texture coordinate.
template <ColorCorrectionCombo C, Lane L>
inline float4<L> color_correction(const float2<L>& uv, const ColorCorrectionParams& p) {
  const float4<L> frame = tex2D(p.frame, uv);
  const float3<L> uvw = color_correction_uvw(frame.rgb(), p.lut_size);
  std::array<float3<L>, kMaxColorCorrectionLuts> lookups;
  for (int k = 0; k < C.luts; ++k) lookups[k] = tex3D(p.luts[k], uvw).rgb();
  return float4<L>(color_correction_combine<C>(frame.rgb(), lookups, p.lut_weights, p.default_weight), frame.w);
}

template <ColorCorrectionCombo C>
inline Cost measure_color_correction(ShaderModel model) {
  const ColorCorrectionParams params{};
  return measure(model, [&](CountedInputs& in) { return color_correction<C>(in.vector<2>(), params); });
}

/// The shader as a rasterizer pixel functor: varying 0 .xy is the frame's texture coordinate.
template <ColorCorrectionCombo C>
struct ColorCorrectionPixelShader {
  static constexpr const char* kFamily = "ColorCorrection";  ///< its name in the shading catalog
  /// colorcorrection_ps2x.fxc: ps20 and ps20b only.
  static constexpr ShaderBuilds kBuilds = kPs2xBuilds;
  static constexpr bool kCanDiscard = false;
  static constexpr bool kWritesDepth = false;
  const ColorCorrectionParams* params = nullptr;
  std::atomic<uint64_t>* pixels = nullptr;  ///< counts the pixels shaded when set (shader_use.hpp)

  void operator()(const rasterizer::PixelInput<1>& in, rasterizer::PixelOutput& out) const {
    count_pixels(pixels, in.live);
    const float2<simd::Float> uv(in.varyings[0].x, in.varyings[0].y);
    const float4<simd::Float> c = color_correction<C>(uv, *params);
    out.color = {c.x, c.y, c.z, c.w};
  }
};

}  // namespace luxel::shading::source
