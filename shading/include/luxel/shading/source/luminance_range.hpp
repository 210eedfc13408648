#pragma once
// The luminance-range test of auto exposure (docs/fidelity.md#auto-exposure;
// luminance_compare_ps2x.fxc): one full-screen pass per histogram bucket over the copied, tone-mapped
// 8-bit frame, inside an occlusion query. The pixel shader outputs 1 where min <= luminance <= max
// (both inclusive) and 0 elsewhere, in all four channels, and depth 0; screenspace_general's alpha test
// (alpha > 0) discards the zeros, so the query counts only the samples in range.
//
//   luminance = dot(texel.rgb * c0.z, (0.2125, 0.7154, 0.0721))
//   c0 = (min, max, scale): scale is the tone-map scale in FLOAT HDR, else 1 (the measured image
//   already carries the scale); a bucket whose max is exactly 1.0 tests against 10000 so the top
//   bucket also collects everything brighter — luminance_range_constant().
//
// No FinalOutput: the SDK compiles this shader with HDRTYPE NONE and returns its result directly.
// NaN luminance fails both comparisons (DX9's cmp takes NaN >= 0 as false) and is never counted.
//
// Static combos (LuminanceRangeCombo): how out-of-range pixels are rejected, so that the
// rasterizer's occlusion query and stencil see only passing samples:
//   alpha_test  the SDK's way: alpha 0/1 and the fixed-function alpha test, func Greater, ref 0
//               (luminance_range_pipeline_state() sets it);
//   texkill     clip() in the shader (texkill), for a pipeline without alpha test; costs one
//               texture slot and keeps the same counts.
// The same code is measured on ps_2_0, ps_2_b and ps_3_0 (the SDK builds ps20 and ps20b; ps_3_0
// cards run ps20b).
//
// Counting with the stencil (mat_tonemapping_occlusion_use_stencil 1): pass 1 draws this
// shader with the stencil writing 1 (REPLACE, ALWAYS) where a sample survives; pass 2 draws any
// shader with stencil EQUAL 1 inside the query. luminance_range_pipeline_state(kind) returns the
// state of either pass; what else the SDK's dev/lumcompare material sets (blending, color writes)
// is NOT IN SDK: we turn color writes off, which changes no count.

#include "luxel/shading/source/binaries.hpp"
#include "luxel/rasterizer/draw.hpp"
#include "luxel/shading/source/common.hpp"
#include "luxel/shading/source/shader_use.hpp"
#include "luxel/shading/source/hdr_type.hpp"

#include <glm/vec3.hpp>

#include <iterator>
#include <string>
#include <utility>

namespace luxel::shading::source {

/// How out-of-range pixels disappear.
enum class LuminanceReject {
  alpha_test,  ///< the SDK: alpha 0/1 + fixed-function alpha test (Greater, 0)
  texkill,     ///< clip() in the shader
};

struct LuminanceRangeCombo {
  LuminanceReject reject = LuminanceReject::alpha_test;

  constexpr bool valid() const { return true; }
  friend constexpr bool operator==(const LuminanceRangeCombo&, const LuminanceRangeCombo&) = default;
  std::string name() const { return reject == LuminanceReject::alpha_test ? "alphatest" : "texkill"; }
};

/// The luminance weights of the histogram.
inline constexpr float kHistogramLuminance[3] = {0.2125f, 0.7154f, 0.0721f};

/// c0 for the bucket [min, max]: max 1.0 exactly becomes 10000; the scale is the
/// tone-map scale in FLOAT mode only.
inline glm::vec3 luminance_range_constant(float min, float max, HdrType hdr = HdrType::integer,
                                          float tonemap_scale = 1.0f) {
  return glm::vec3(min, max == 1.0f ? 10000.0f : max, hdr == HdrType::floating ? tonemap_scale : 1.0f);
}

struct LuminanceRangeParams {
  Sampler2D frame{0};           ///< _rt_FullFrameFB, 8-bit, read with sRGB decode
  glm::vec3 min_max_scale{0.0f, 10000.0f, 1.0f};  ///< c0, from luminance_range_constant()
};

/// What the shader writes.
template <Lane L>
struct LuminanceRangeOutput {
  float4<L> color;  ///< 1 in range, else 0, all channels
  L depth;          ///< oDepth = 0
  Mask<L> discard{};  ///< texkill combo: the lanes clip() kills (else none)
};

/// The test on a texel already fetched (tests drive it with arbitrary colors).
template <LuminanceRangeCombo C, Lane L>
inline LuminanceRangeOutput<L> luminance_range_combine(const float3<L>& texel, const LuminanceRangeParams& p) {
  const float3<L> c0 = constant<L>(p.min_max_scale);
  const float3<L> weights(kHistogramLuminance[0], kHistogramLuminance[1], kHistogramLuminance[2]);
  const L luminance = dot(texel * c0.z, weights);
  const L in_range = step(c0.x, luminance) * step(luminance, c0.y);
  LuminanceRangeOutput<L> out;
  out.color = float4<L>(in_range);
  out.depth = L(0.0f);
  if constexpr (C.reject == LuminanceReject::texkill) out.discard = clip(in_range - 0.5f);
  return out;
}

/// The pixel shader.
template <LuminanceRangeCombo C, Lane L>
inline LuminanceRangeOutput<L> luminance_range(const float2<L>& uv, const LuminanceRangeParams& p) {
  return luminance_range_combine<C>(tex2D(p.frame, uv).rgb(), p);
}

template <LuminanceRangeCombo C>
inline Cost measure_luminance_range(ShaderModel model) {
  const LuminanceRangeParams params{};
  return measure(model, [&](CountedInputs& in) {
    const LuminanceRangeOutput<Counted> out = luminance_range<C>(in.vector<2>(), params);
    return std::make_tuple(out.color, out.depth);
  });
}

/// The shader as a rasterizer pixel functor: varying 0 .xy is the frame's texture coordinate.
template <LuminanceRangeCombo C>
struct LuminanceRangePixelShader {
  static constexpr const char* kFamily = "LuminanceRange";  ///< its name in the shading catalog
  /// luminance_compare_ps2x.fxc: ps20 and ps20b only.
  static constexpr ShaderBuilds kBuilds = kPs2xBuilds;
  static constexpr bool kCanDiscard = C.reject == LuminanceReject::texkill;
  static constexpr bool kWritesDepth = true;
  const LuminanceRangeParams* params = nullptr;
  std::atomic<uint64_t>* pixels = nullptr;  ///< counts the pixels shaded when set (shader_use.hpp)

  void operator()(const rasterizer::PixelInput<1>& in, rasterizer::PixelOutput& out) const {
    count_pixels(pixels, in.live);
    const float2<simd::Float> uv(in.varyings[0].x, in.varyings[0].y);
    const LuminanceRangeOutput<simd::Float> r = luminance_range<C>(uv, *params);
    out.color = {r.color.x, r.color.y, r.color.z, r.color.w};
    out.depth = r.depth;
    if constexpr (kCanDiscard) out.discard = simd::to_bits(r.discard);
  }
};

/// Which draw of the count.
enum class LuminancePass {
  query,         ///< the shader inside the query (mat_tonemapping_occlusion_use_stencil 0)
  stencil_mark,  ///< stencil pass 1: the shader writes stencil 1 where it passes
  stencil_count, ///< stencil pass 2: counted where the stencil is 1 (any shader; no pixel writes)
};

/// The fixed-function state of one draw of the count. No depth test (the pass is
/// screen-space), no color writes (our choice, see above).
inline rasterizer::PipelineState luminance_range_pipeline_state(LuminanceReject reject, LuminancePass pass) {
  using namespace rasterizer;
  PipelineState s;
  s.rasterizer.cull = CullMode::None;
  s.depth_stencil.depth_enable = false;
  s.blend.write_mask = 0;
  if (pass != LuminancePass::stencil_count && reject == LuminanceReject::alpha_test) {
    s.alpha_test = AlphaTestState{true, CompareFunc::Greater, 0};
  }
  if (pass == LuminancePass::stencil_mark) {
    s.depth_stencil.stencil_enable = true;
    s.depth_stencil.stencil_ref = 1;
    s.depth_stencil.front.func = CompareFunc::Always;
    s.depth_stencil.front.pass = StencilOp::Replace;
    s.depth_stencil.back = s.depth_stencil.front;
  } else if (pass == LuminancePass::stencil_count) {
    s.depth_stencil.stencil_enable = true;
    s.depth_stencil.stencil_ref = 1;
    s.depth_stencil.front.func = CompareFunc::Equal;
    s.depth_stencil.back = s.depth_stencil.front;
  }
  return s;
}

}  // namespace luxel::shading::source
