#pragma once
// Film grain (docs/fidelity.md#film-grain; filmgrain_ps20.fxc, filmgrain_dx8_dx9.cpp): a noise texel n
// and a constant noiseScale (c0) give a source color and a source alpha,
//
//   src.rgb = n.rgb * noiseScale.rgb,   src.a = n.r * (1 - noiseScale.w) + noiseScale.w
//
// and the draw blends them onto the 8-bit frame with src * ONE + dst * SRCALPHA:
//
//   frame' = saturate(n.rgb * noiseScale.rgb + frame * (n.r * (1 - noiseScale.w) + noiseScale.w))
//
// so noiseScale.w = 1 adds the scaled noise, noiseScale.w = 0 also darkens the frame by n.r, and
// values between mix the two. The frame is read and written as gamma values (no sRGB write, as
// every post pass). film_grain_pipeline_state() is that draw's state; the material that
// sets it (and the screen-space effect class that drives it) is not in the SDK, so two choices
// are ours: rgb is written and alpha kept (the blend would otherwise fold src.a into the frame's
// alpha), and the grain texture itself (postfx/film_grain.hpp says how it is made).
// No FinalOutput tone map (TONEMAP NONE).

#include "luxel/shading/source/binaries.hpp"
#include "luxel/rasterizer/draw.hpp"
#include "luxel/shading/source/common.hpp"
#include "luxel/shading/source/shader_use.hpp"

#include <glm/vec4.hpp>

namespace luxel::shading::source {

struct FilmGrainParams {
  Sampler2D grain{0};             ///< the noise: RGBA8, point-sampled, wrapped
  glm::vec4 noise_scale{1.0f};    ///< c0: rgb scales the noise, w blends between add and modulate
};

/// The shader after its fetch.
template <Lane L>
inline float4<L> film_grain_combine(const float4<L>& n, const FilmGrainParams& p) {
  const float4<L> scale = constant<L>(p.noise_scale);
  return float4<L>(n.rgb() * scale.xyz(), n.x * (1.0f - scale.w) + scale.w);
}

/// The pixel shader.
template <Lane L>
inline float4<L> film_grain(const float2<L>& uv, const FilmGrainParams& p) {
  return film_grain_combine(tex2D(p.grain, uv), p);
}

inline Cost measure_film_grain(ShaderModel model) {
  const FilmGrainParams params{};
  return measure(model, [&](CountedInputs& in) { return film_grain(in.vector<2>(), params); });
}

/// The blended draw: src * ONE + dst * SRCALPHA on rgb, no depth, no culling, alpha kept.
inline rasterizer::PipelineState film_grain_pipeline_state() {
  using namespace rasterizer;
  PipelineState s;
  s.rasterizer.cull = CullMode::None;
  s.depth_stencil.depth_enable = false;
  s.blend.enable = true;
  s.blend.src = BlendFactor::One;
  s.blend.dst = BlendFactor::SrcAlpha;
  s.blend.write_mask = kWriteRed | kWriteGreen | kWriteBlue;
  return s;
}

/// The shader as a rasterizer pixel functor: varying 0 .xy is the grain texture's coordinate.
struct FilmGrainPixelShader {
  static constexpr const char* kFamily = "filmgrain";  ///< its name in the shading catalog
  /// filmgrain_ps20.fxc: ps20 only, so every card runs the ps20 binary.
  static constexpr ShaderBuilds kBuilds = ShaderBuilds{true, false, false};
  static constexpr bool kCanDiscard = false;
  static constexpr bool kWritesDepth = false;
  const FilmGrainParams* params = nullptr;
  std::atomic<uint64_t>* pixels = nullptr;  ///< counts the pixels shaded when set (shader_use.hpp)

  void operator()(const rasterizer::PixelInput<1>& in, rasterizer::PixelOutput& out) const {
    count_pixels(pixels, in.live);
    const float4<simd::Float> c = film_grain(float2<simd::Float>(in.varyings[0].x, in.varyings[0].y), *params);
    out.color = {c.x, c.y, c.z, c.w};
  }
};

}  // namespace luxel::shading::source
