#pragma once
// The engine's combine pass when color correction runs (docs/fidelity.md#bloom, #color-correction;
// Engine_Post_ps2x.fxc, Engine_Post_dx9.cpp): one full-screen pass that adds the bloom to the
// frame and color-corrects the sum, so the sum is never rounded to 8 bits in between:
//
//   c       = frame.rgb + bloom.rgb * bloomFactor        (gamma values; may exceed 1)
//   uvw     = c * 31/32 + 0.5/32
//   out.rgb = c * defaultWeight + sum_k tex3D(LUT_k, uvw).rgb * w_k
//   out.a   = frame.a
//
// A sum above 1 reads the volume's last texel (its sampler clamps) and its own share
// saturates when written. The frame and the bloom are read with sRGB decode off and the result is
// written with sRGB write off; the frame point-sampled at its own texel centers (which a
// bilinear read there returns exactly), the bloom bilinear and clamped, stretched over the frame as
// bloomadd stretches it (postfx/bloom.hpp). bloomFactor is 1 or 0 in the SDK (the bloom amount is
// already in the bloom texture). With bloom and no color correction the engine draws bloomadd
// instead (bloom_add.hpp); with color correction and no bloom luxel draws colorcorrection_ps2x
// (color_correction.hpp), which is this pass with bloomFactor 0 minus the bloom's fetch.
//
// Static combos (EnginePostCombo): the number of lookups, 1..4 (COL_CORRECT_NUM_LOOKUPS). The
// software AA (off on PC) is not modelled. Samplers: s0 the frame, s1 the bloom, s2..s5
// the LUTs, as in the SDK. Constants: c0 = (w0, w1, w2, w3), c1.x = defaultWeight,
// c1.y = bloomFactor (the SDK's packing is closed).

#include "luxel/shading/source/binaries.hpp"
#include "luxel/shading/source/color_correction.hpp"

namespace luxel::shading::source {

struct EnginePostCombo {
  int luts = 1;  ///< lookups blended, 1..kMaxColorCorrectionLuts

  constexpr bool valid() const { return luts >= 1 && luts <= kMaxColorCorrectionLuts; }
  friend constexpr bool operator==(const EnginePostCombo&, const EnginePostCombo&) = default;
  constexpr ColorCorrectionCombo correction() const { return {luts}; }
  std::string name() const { return correction().name(); }
};

/// How the bloom texture is read: bilinear, no mips, clamped (the LUTs' state, one axis less).
inline rasterizer::Sampler engine_post_bloom_sampler() { return color_correction_lut_sampler(); }

struct EnginePostParams {
  Sampler2D frame{0, nullptr, color_correction_frame_sampler()};  ///< _rt_FullFrameFB, sRGB read off
  Sampler2D bloom{1, nullptr, engine_post_bloom_sampler()};       ///< _rt_SmallFB0 after both blurs
  std::array<Sampler3D, kMaxColorCorrectionLuts> luts{
      Sampler3D{2, nullptr, color_correction_lut_sampler()}, Sampler3D{3, nullptr, color_correction_lut_sampler()},
      Sampler3D{4, nullptr, color_correction_lut_sampler()}, Sampler3D{5, nullptr, color_correction_lut_sampler()}};
  glm::vec4 lut_weights{0.0f};  ///< c0: w0..w3
  float default_weight = 1.0f;  ///< c1.x: the bloomed frame's own weight
  float bloom_factor = 1.0f;    ///< c1.y
  int lut_size = kColorCorrectionLutSize;  ///< the volumes' edge (ColorCorrectionParams::lut_size)
};

/// The bloom added to the frame: what the lookups read.
template <Lane L>
inline float3<L> engine_post_bloomed(const float3<L>& frame, const float3<L>& bloom, const EnginePostParams& p) {
  return bloom * constant<L>(p.bloom_factor) + frame;  // one mad
}

/// The pixel shader: frame_uv and bloom_uv are the two textures' coordinates.
template <EnginePostCombo C, Lane L>
inline float4<L> engine_post(const float2<L>& frame_uv, const float2<L>& bloom_uv, const EnginePostParams& p) {
  static_assert(C.valid());
  const float4<L> frame = tex2D(p.frame, frame_uv);
  const float3<L> bloomed = engine_post_bloomed(frame.rgb(), tex2D(p.bloom, bloom_uv).rgb(), p);
  const float3<L> uvw = color_correction_uvw(bloomed, p.lut_size);
  std::array<float3<L>, kMaxColorCorrectionLuts> lookups;
  for (int k = 0; k < C.luts; ++k) lookups[k] = tex3D(p.luts[k], uvw).rgb();
  return float4<L>(color_correction_combine<C.correction()>(bloomed, lookups, p.lut_weights, p.default_weight), frame.w);
}

template <EnginePostCombo C>
inline Cost measure_engine_post(ShaderModel model) {
  const EnginePostParams params{};
  return measure(model, [&](CountedInputs& in) {
    const float4<Counted> uvs = in.vector<4>();
    return engine_post<C>(uvs.xy(), uvs.zw(), params);
  });
}

/// The shader as a rasterizer pixel functor: varying 0 .xy is the frame's coordinate, .zw the
/// bloom's.
template <EnginePostCombo C>
struct EnginePostPixelShader {
  static constexpr const char* kFamily = "Engine_Post";  ///< its name in the shading catalog
  /// Engine_Post_ps2x.fxc: ps20 and ps20b only.
  static constexpr ShaderBuilds kBuilds = kPs2xBuilds;
  static constexpr bool kCanDiscard = false;
  static constexpr bool kWritesDepth = false;
  const EnginePostParams* params = nullptr;
  std::atomic<uint64_t>* pixels = nullptr;  ///< counts the pixels shaded when set (shader_use.hpp)

  void operator()(const rasterizer::PixelInput<1>& in, rasterizer::PixelOutput& out) const {
    count_pixels(pixels, in.live);
    const float2<simd::Float> frame_uv(in.varyings[0].x, in.varyings[0].y), bloom_uv(in.varyings[0].z, in.varyings[0].w);
    const float4<simd::Float> c = engine_post<C>(frame_uv, bloom_uv, *params);
    out.color = {c.x, c.y, c.z, c.w};
  }
};

}  // namespace luxel::shading::source
