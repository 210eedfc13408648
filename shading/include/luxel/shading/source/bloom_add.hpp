#pragma once
// The bloom's combine when neither software AA nor color correction runs (docs/fidelity.md#bloom;
// bloomadd_ps2x.fxc, material dev/bloomadd): the shader returns the bloom texel, and the draw adds
// it onto the frame with ONE/ONE blending. The frame is the 8-bit back buffer without sRGB write,
// so the add happens on gamma values, as on DX9-class hardware:
//
//   frame' = saturate(frame + bloom)          per channel, 8-bit, rounded
//
// bloom_add_pipeline_state() is that draw's state. The dev/bloomadd material is NOT IN SDK;
// we write rgb only, so the frame's alpha (whatever the scene stored there) survives the add.
// Alpha out of the shader: 1 (the SDK's), unused with that mask.

#include "luxel/shading/source/binaries.hpp"
#include "luxel/rasterizer/draw.hpp"
#include "luxel/shading/source/common.hpp"
#include "luxel/shading/source/shader_use.hpp"

namespace luxel::shading::source {

struct BloomAddParams {
  Sampler2D bloom{0};  ///< _rt_SmallFB0 after both blurs: RGBA8, bilinear, clamped
};

/// The shader after its fetch.
template <Lane L>
inline float4<L> bloom_add_combine(const float3<L>& bloom) {
  return float4<L>(bloom, L(1.0f));
}

/// The pixel shader.
template <Lane L>
inline float4<L> bloom_add(const float2<L>& uv, const BloomAddParams& p) {
  return bloom_add_combine(tex2D(p.bloom, uv).rgb());
}

inline Cost measure_bloom_add(ShaderModel model) {
  const BloomAddParams params{};
  return measure(model, [&](CountedInputs& in) { return bloom_add(in.vector<2>(), params); });
}

/// The additive draw: ONE/ONE on rgb, no depth, no culling, alpha kept.
inline rasterizer::PipelineState bloom_add_pipeline_state() {
  using namespace rasterizer;
  PipelineState s;
  s.rasterizer.cull = CullMode::None;
  s.depth_stencil.depth_enable = false;
  s.blend.enable = true;
  s.blend.src = BlendFactor::One;
  s.blend.dst = BlendFactor::One;
  s.blend.write_mask = kWriteRed | kWriteGreen | kWriteBlue;
  return s;
}

/// The shader as a rasterizer pixel functor: varying 0 .xy is the bloom texture's coordinate.
struct BloomAddPixelShader {
  static constexpr const char* kFamily = "bloomadd";  ///< its name in the shading catalog
  /// bloomadd_ps2x.fxc: ps20 and ps20b only.
  static constexpr ShaderBuilds kBuilds = kPs2xBuilds;
  static constexpr bool kCanDiscard = false;
  static constexpr bool kWritesDepth = false;
  const BloomAddParams* params = nullptr;
  std::atomic<uint64_t>* pixels = nullptr;  ///< counts the pixels shaded when set (shader_use.hpp)

  void operator()(const rasterizer::PixelInput<1>& in, rasterizer::PixelOutput& out) const {
    count_pixels(pixels, in.live);
    const float4<simd::Float> c = bloom_add(float2<simd::Float>(in.varyings[0].x, in.varyings[0].y), *params);
    out.color = {c.x, c.y, c.z, c.w};
  }
};

}  // namespace luxel::shading::source
