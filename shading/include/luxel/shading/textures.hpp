#pragma once
// Texture fetches: HLSL's tex2D, tex2Dbias, tex2Dlod, tex2Dgrad, texCUBE, texCUBEbias, texCUBElod,
// tex3D; and tex2D_taps, several tex2D of one sampler (not HLSL: what a shader's N texld of one
// sampler cost, read in one call on the SIMD lane).
//
// A shader names a sampler by a handle it receives with its parameters, as HLSL names
// `sampler2D BaseTextureSampler : register(s0)`:
//
//   float4<L> base = tex2D(params.base_texture, uv);
//
// The handle carries the sampler register (s#, counted against the model's 16), the texture bound
// there and the sampler state (rasterizer/texture.hpp: filtering, addressing, LOD bias and clamps).
//
// Level of detail:
//  - SIMD lane: rasterizer::sample() takes the coordinate's screen-space derivatives per 2x2 quad
//    (simd::ddx/ddy, coarse, as DX9 hardware), so dependent reads get the derivatives of the
//    computed coordinate.
//  - float lane: one pixel has no neighbours, so the caller supplies the quad's derivatives of the
//    coordinate this sampler is fetched with (reference_ddx/ddy), computed from the interpolants'
//    screen-space gradients. That is exact for coordinates that are affine in the interpolants (how
//    Source fetches its base, bump, detail and lightmap textures); for a dependent read the caller
//    must pass the derivatives of the computed coordinate (e.g. the SIMD lane's). The float lane
//    samples with the texture module's scalar reference (sample_reference / lod_reference), so
//    textured results agree with the SIMD lane to the texture module's tolerance, not bit for bit.
//  - tex2Dbias adds .w to the LOD (texldb, ps_2_0 and up; DX9 allows a bias in [-3, 3] on ps_2_x);
//    tex2Dlod takes the LOD from .w (texldl: ps_3_0 and vs_3_0 only); tex2Dgrad takes explicit
//    derivatives (texldd: ps_2_a and ps_3_0, not ps_2_b).
//
// Counted: a fetch is one texture slot (texld/texldb), two (texldl) or three (texldd); its result has
// the texture-indirection level of its coordinates plus one, where coordinates that are not an
// unmodified input register count at least level 1 ("texld - ps_2_0 and up": a texld whose
// coordinates are in a temporary register is a first-order dependent read). Coordinates that are
// not one register read in order (a swizzle on ps_2_x, or parts of several registers, or a
// negation) cost the mov that assembles them.

#include "luxel/rasterizer/texture.hpp"
#include "luxel/shading/counted.hpp"
#include "luxel/shading/vector.hpp"

#include <glm/vec3.hpp>

#include <array>
#include <stdexcept>
#include <string>

namespace luxel::shading {

enum class SamplerKind { texture_2d, cube, volume };

template <SamplerKind K>
inline constexpr int kCoordinates = K == SamplerKind::texture_2d ? 2 : 3;

/// A sampler as a shader names it: register s#, the texture bound there and how it is read.
template <SamplerKind K>
struct TextureBinding {
  int slot = 0;                                  ///< s#
  const rasterizer::Texture* texture = nullptr;  ///< not read on the Counted lane
  rasterizer::Sampler state{};                   ///< filtering, addressing, LOD bias and clamps
  /// float lane only: d(coordinate)/dx and d/dy over this pixel's quad (see above).
  glm::vec3 reference_ddx{0.0f};
  glm::vec3 reference_ddy{0.0f};
};

using Sampler2D = TextureBinding<SamplerKind::texture_2d>;
using SamplerCube = TextureBinding<SamplerKind::cube>;
using Sampler3D = TextureBinding<SamplerKind::volume>;

namespace detail {

enum class LodMode { derivatives, bias, level };

/// bound_texture's failure, out of line so that the fetches it guards inline.
[[noreturn, gnu::cold, gnu::noinline]] inline void throw_unbound(int slot) {
  throw std::logic_error("sampler s" + std::to_string(slot) + ": no texture of the sampler's kind bound");
}

/// The texture a numeric lane samples; throws std::logic_error when none (or one of the wrong
/// kind) is bound, where a GPU would read black.
template <SamplerKind K>
LUXEL_INLINE const rasterizer::Texture& bound_texture(const TextureBinding<K>& s) {
  constexpr rasterizer::TextureKind kKind = K == SamplerKind::texture_2d ? rasterizer::TextureKind::Texture2D
                                            : K == SamplerKind::cube     ? rasterizer::TextureKind::Cube
                                                                         : rasterizer::TextureKind::Volume;
  if (s.texture == nullptr || s.texture->kind() != kKind) [[unlikely]] throw_unbound(s.slot);
  return *s.texture;
}

/// The SIMD lane's fetch.
template <SamplerKind K, int N>
LUXEL_INLINE float4<simd::Float> fetch_lanes(const TextureBinding<K>& s, const Vec<simd::Float, N>& coords, LodMode mode) {
  constexpr int D = kCoordinates<K>;
  const rasterizer::Texture& texture = bound_texture(s);
  rasterizer::TexCoord p{coords[0], coords[1], simd::Float(0.0f)};
  if constexpr (D == 3) p.z = coords[2];
  const simd::Float4 c = mode == LodMode::level ? rasterizer::sample_level(texture, s.state, p, coords[N - 1])
                         : mode == LodMode::bias ? rasterizer::sample(texture, s.state, p, coords[N - 1])
                                                 : rasterizer::sample(texture, s.state, p);
  return float4<simd::Float>(c.x, c.y, c.z, c.w);
}

/// The Counted and scalar lanes' fetch.
template <SamplerKind K, Lane L, int N>
inline float4<L> fetch_other(const TextureBinding<K>& s, const Vec<L, N>& coords, LodMode mode) {
  constexpr int D = kCoordinates<K>;
  if constexpr (kIsCounted<L>) {
    const ShaderModelCaps& model = counted::active_model();
    if (!model.texture_fetch) counted::unsupported(std::string(model.name) + " cannot sample textures");
    if (mode == LodMode::level && !model.texldl) {
      counted::unsupported("tex*lod (texldl) needs ps_3_0 or vs_3_0, not " + std::string(model.name));
    }
    if (mode != LodMode::level && !model.pixel) {
      counted::unsupported("vertex shaders can only sample with tex*lod (texldl)");
    }
    std::array<counted::Ref, N> refs;
    counted_refs<N>(coords, refs.data());
    counted::Extra extra;
    extra.sampler = s.slot;
    const counted::Op op = mode == LodMode::derivatives ? counted::Op::tex
                           : mode == LodMode::bias      ? counted::Op::tex_bias
                                                        : counted::Op::tex_lod;
    return counted_result<4, true>(counted::emit(op, 4, N, refs, extra));
  } else {
    static_assert(std::is_same_v<L, float>);
    const rasterizer::Texture& texture = bound_texture(s);
    glm::vec3 p(0.0f);
    for (int i = 0; i < D; ++i) p[i] = coords[i];
    const float lod = mode == LodMode::level
                          ? coords[N - 1]
                          : rasterizer::lod_reference(texture, p, s.reference_ddx, s.reference_ddy) +
                                (mode == LodMode::bias ? coords[N - 1] : 0.0f);
    const glm::vec4 c = rasterizer::sample_reference(texture, s.state, p, lod);
    return float4<float>(c.x, c.y, c.z, c.w);
  }
}

/// A fetch of `mode`. The SIMD lane's is inlined into the shader: out of line it cost a 64-byte
/// aligned frame of its own and a copy of the four result registers per read, several reads a
/// pixel in the post passes (bench/README.md).
template <SamplerKind K, Lane L, int N>
LUXEL_INLINE float4<L> fetch(const TextureBinding<K>& s, const Vec<L, N>& coords, LodMode mode) {
  static_assert(N == kCoordinates<K> || N == 4, "coordinates: the texture's dimension, or float4 with bias/LOD in .w");
  if constexpr (std::is_same_v<L, simd::Float>) return fetch_lanes(s, coords, mode);
  else return fetch_other(s, coords, mode);
}

template <Lane L>
inline float4<L> fetch_grad(const Sampler2D& s, const float2<L>& uv, const float2<L>& ddx, const float2<L>& ddy) {
  if constexpr (kIsCounted<L>) {
    const ShaderModelCaps& model = counted::active_model();
    if (!model.texldd) counted::unsupported("tex2Dgrad (texldd) needs ps_3_0, not " + std::string(model.name));
    std::array<counted::Ref, 6> refs;
    counted_refs<2>(uv, refs.data());
    counted_refs<2>(ddx, refs.data() + 2);
    counted_refs<2>(ddy, refs.data() + 4);
    counted::Extra extra;
    extra.sampler = s.slot;
    return counted_result<4, true>(counted::emit(counted::Op::tex_grad, 4, 2, refs, extra));
  } else {
    const rasterizer::Texture& texture = bound_texture(s);
    if constexpr (std::is_same_v<L, float>) {
      const glm::vec3 p(uv.x, uv.y, 0.0f);
      const float lod = rasterizer::lod_reference(texture, p, glm::vec3(ddx.x, ddx.y, 0.0f), glm::vec3(ddy.x, ddy.y, 0.0f));
      const glm::vec4 c = rasterizer::sample_reference(texture, s.state, p, lod);
      return float4<float>(c.x, c.y, c.z, c.w);
    } else {
      const simd::Float zero(0.0f);
      const simd::Float4 c = rasterizer::sample_grad(texture, s.state, {uv.x, uv.y, zero}, {ddx.x, ddx.y, zero},
                                                     {ddy.x, ddy.y, zero});
      return float4<simd::Float>(c.x, c.y, c.z, c.w);
    }
  }
}

}  // namespace detail

/// texld: LOD from the quad's derivatives.
template <Lane L>
inline float4<L> tex2D(const Sampler2D& s, const float2<L>& uv) {
  return detail::fetch(s, uv, detail::LodMode::derivatives);
}
/// N texld of one sampler: tex2D at each of `uvs`, in order. It is N fetches in the shader and
/// on the Counted lane (the same slots and order as N tex2D calls); the SIMD lane reads them in
/// one call (rasterizer::sample_taps: a blur's taps, the bumped lightmaps), the same values.
template <Lane L, size_t N>
inline std::array<float4<L>, N> tex2D_taps(const Sampler2D& s, const std::array<float2<L>, N>& uvs) {
  std::array<float4<L>, N> texels;
  if constexpr (std::is_same_v<L, simd::Float>) {
    const rasterizer::Texture& texture = detail::bound_texture(s);
    std::array<rasterizer::TexCoord, N> coords;
    for (size_t i = 0; i < N; ++i) coords[i] = {uvs[i].x, uvs[i].y, simd::Float(0.0f)};
    std::array<simd::Float4, N> read;
    rasterizer::sample_taps(texture, s.state, coords, read);
    for (size_t i = 0; i < N; ++i) texels[i] = float4<L>(read[i].x, read[i].y, read[i].z, read[i].w);
  } else {
    for (size_t i = 0; i < N; ++i) texels[i] = tex2D(s, uvs[i]);
  }
  return texels;
}
/// texldb: LOD from derivatives plus uvwb.w.
template <Lane L>
inline float4<L> tex2Dbias(const Sampler2D& s, const float4<L>& uvwb) {
  return detail::fetch(s, uvwb, detail::LodMode::bias);
}
/// texldl: LOD uvwl.w (ps_3_0, vs_3_0).
template <Lane L>
inline float4<L> tex2Dlod(const Sampler2D& s, const float4<L>& uvwl) {
  return detail::fetch(s, uvwl, detail::LodMode::level);
}
/// texldd: LOD from explicit derivatives of uv along screen x and y (ps_3_0).
template <Lane L>
inline float4<L> tex2Dgrad(const Sampler2D& s, const float2<L>& uv, const float2<L>& ddx, const float2<L>& ddy) {
  return detail::fetch_grad(s, uv, ddx, ddy);
}
template <Lane L>
inline float4<L> texCUBE(const SamplerCube& s, const float3<L>& direction) {
  return detail::fetch(s, direction, detail::LodMode::derivatives);
}
template <Lane L>
inline float4<L> texCUBEbias(const SamplerCube& s, const float4<L>& direction_bias) {
  return detail::fetch(s, direction_bias, detail::LodMode::bias);
}
template <Lane L>
inline float4<L> texCUBElod(const SamplerCube& s, const float4<L>& direction_lod) {
  return detail::fetch(s, direction_lod, detail::LodMode::level);
}
template <Lane L>
inline float4<L> tex3D(const Sampler3D& s, const float3<L>& uvw) {
  return detail::fetch(s, uvw, detail::LodMode::derivatives);
}

}  // namespace luxel::shading
