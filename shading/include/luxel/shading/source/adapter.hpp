#pragma once
// The adapter: a Source shader family, one static combo and its bound constants and textures as a
// rasterizer pixel functor (rasterizer/draw.hpp). The frame draws with these, and so do the tests
// and benchmarks that want a Source shader on real geometry: nobody else writes the wiring.
//
// Interpolants. A combo reads only some per-vertex values (a flat lightmapped surface without an
// env map needs no tangent frame, a fogless one no projected z). Each functor's kAttributes lists
// what its combo reads, in a fixed order, packed four to a float4 varying; the vertex stage (the
// frame's) writes the same list for the same combo, so nothing unread is interpolated. Values
// the SDK's vertex shaders interpolate but that are affine in these (the eye vector, eye - world
// position; the three bump-lightmap coordinates, offsets of the lightmap coordinate into the
// lightmap page) are derived per pixel: the same values, and the counted DX9 cost of a combo is
// the shader's own (measure_*), independent of how luxel feeds it.
//
// Fixed-function work after the shader, as D3D9 does it: ps_2_0's range fog
// (Fog::vertex_range) blends with the vertex shader's fog visibility, interpolated
// (fixed_function_fog). The output is the linear FinalOutput color; the output merger encodes it
// (sRGB write on, BlendState::srgb_write).
//
// Counting: when `pixels` is set, each invocation adds its covered lanes to it (relaxed atomics:
// the sum is the same whatever the thread count; off by default, it costs a contended add per
// stamp).
//
// Water fog to destination alpha: the world families' height-fog combos (the view through the
// water, the refraction view) write the fog factor to alpha when `water_fog_to_alpha` is set, as
// the SDK's WRITEWATERFOGTODESTALPHA (lightmappedgeneric_dx9_helper.cpp and vertexlitgeneric's:
// set with height fog for fully opaque materials; the others keep their alpha). The water shader
// reads it back as the water's depth (water.hpp).

#include "luxel/rasterizer/draw.hpp"
#include "luxel/shading/source/lightmapped_generic.hpp"
#include "luxel/shading/source/sky.hpp"
#include "luxel/shading/source/unlit_generic.hpp"
#include "luxel/shading/source/vertexlit_generic.hpp"
#include "luxel/shading/source/water.hpp"

#include <array>
#include <atomic>
#include <bit>
#include <cstdint>

namespace luxel::shading::source {

/// One scalar a vertex stage can supply per vertex.
enum class Attribute : uint8_t {
  world_x, world_y, world_z,           ///< world position, inches
  proj_z,                              ///< clip-space z (the SDK's projPos.z: fog distance)
  normal_x, normal_y, normal_z,        ///< world normal (unit at the vertex)
  tangent_x, tangent_y, tangent_z,     ///< world tangent: the texture's +u direction
  binormal_x, binormal_y, binormal_z,  ///< w cross(n, t) (scene.hpp's handedness rule)
  base_u, base_v,                      ///< base-texture coordinate, after the material's transform
  lightmap_u, lightmap_v,              ///< uv1 in the lightmap atlas, [0, 1]
  color_r, color_g, color_b, color_a,  ///< vertex color, linear (white without one)
  attenuation_0, attenuation_1, attenuation_2, attenuation_3,  ///< per-vertex light attenuation (SDK combos)
  fog_visibility,                      ///< vertex range fog: 1 = clear (ps_2_0)
};
inline constexpr int kAttributeKinds = static_cast<int>(Attribute::fog_visibility) + 1;

/// The per-vertex values a combo reads, in varying order (four to a float4).
struct AttributeList {
  std::array<Attribute, kAttributeKinds> items{};
  int count = 0;

  constexpr int index_of(Attribute a) const {
    for (int i = 0; i < count; ++i)
      if (items[static_cast<size_t>(i)] == a) return i;
    return -1;
  }
  constexpr void add(Attribute a) {
    if (index_of(a) < 0) items[static_cast<size_t>(count++)] = a;
  }
  constexpr void add(std::initializer_list<Attribute> as) {
    for (Attribute a : as) add(a);
  }
  constexpr int varyings() const { return (count + 3) / 4; }
};

namespace detail {

inline constexpr void add_world(AttributeList& l) { l.add({Attribute::world_x, Attribute::world_y, Attribute::world_z}); }
inline constexpr void add_normal(AttributeList& l) { l.add({Attribute::normal_x, Attribute::normal_y, Attribute::normal_z}); }
inline constexpr void add_tangent_frame(AttributeList& l) {
  l.add({Attribute::tangent_x, Attribute::tangent_y, Attribute::tangent_z});
  l.add({Attribute::binormal_x, Attribute::binormal_y, Attribute::binormal_z});
}
inline constexpr void add_fog(AttributeList& l, Fog fog) {
  if (fog == Fog::range || fog == Fog::height) l.add({Attribute::world_z, Attribute::proj_z});
  if (fog == Fog::vertex_range) l.add(Attribute::fog_visibility);
}

/// Attribute A of a stamp, read from the varyings at its place in L.
template <AttributeList L, Attribute A, int N>
LUXEL_INLINE simd::Float read(const rasterizer::PixelInput<N>& in) {
  constexpr int i = L.index_of(A);
  static_assert(i >= 0, "the combo's attribute list does not hold this attribute");
  const simd::Float4& v = in.varyings[i / 4];
  if constexpr (i % 4 == 0) return v.x;
  else if constexpr (i % 4 == 1) return v.y;
  else if constexpr (i % 4 == 2) return v.z;
  else return v.w;
}

template <AttributeList L, Attribute X, Attribute Y, Attribute Z, int N>
LUXEL_INLINE float3<simd::Float> read3(const rasterizer::PixelInput<N>& in) {
  return float3<simd::Float>(read<L, X>(in), read<L, Y>(in), read<L, Z>(in));
}

/// The shader's color as the rasterizer's output, after the fixed-function fog of ps_2_0.
template <Fog F, AttributeList L, int N>
LUXEL_INLINE void write(const float4<simd::Float>& c, const rasterizer::PixelInput<N>& in, const FogConstants& fog,
                        rasterizer::PixelOutput& out) {
  if constexpr (F == Fog::vertex_range) {
    const float4<simd::Float> f = fixed_function_fog(c, read<L, Attribute::fog_visibility>(in), fog);
    out.color = {f.x, f.y, f.z, f.w};
  } else {
    out.color = {c.x, c.y, c.z, c.w};
  }
}

/// WRITEWATERFOGTODESTALPHA: alpha = the height fog factor (Fog::height combos only).
template <Fog F, AttributeList L, int N>
LUXEL_INLINE void write_water_fog_alpha(bool enabled, const rasterizer::PixelInput<N>& in, const FogConstants& fog,
                                        rasterizer::PixelOutput& out) {
  if constexpr (F == Fog::height) {
    if (enabled)
      out.color.w = pixel_fog_factor<Fog::height>(
          FogInputs<simd::Float>{read<L, Attribute::world_z>(in), read<L, Attribute::proj_z>(in)}, fog);
  }
}

LUXEL_INLINE void count(std::atomic<uint64_t>* pixels, simd::LaneBits live) {
  if (pixels) pixels->fetch_add(static_cast<uint64_t>(std::popcount(live)), std::memory_order_relaxed);
}

}  // namespace detail

// ---- LightmappedGeneric -----------------------------------------------------------------------

/// Where the four lightmaps sit in the one lightmap texture the shader samples (its s1, as
/// Source's lightmap page holds a face's flat and bump lightmaps side by side): map k (0 flat,
/// 1..3 the RNM basis) at u = offset[k] + scale x lightmap_u, v = lightmap_v.
struct LightmapPage {
  float scale = 0.25f;
  std::array<float, 4> offset{0.0f, 0.25f, 0.5f, 0.75f};
};

constexpr AttributeList lightmapped_attributes(const LightmappedCombo& c) {
  AttributeList l;
  l.add({Attribute::base_u, Attribute::base_v, Attribute::lightmap_u, Attribute::lightmap_v});
  if (c.envmap) {
    detail::add_normal(l);
    if (c.bump) detail::add_tangent_frame(l);
    detail::add_world(l);
  }
  detail::add_fog(l, c.fog);
  return l;
}

template <LightmappedCombo C>
struct LightmappedPixelShader {
  static constexpr AttributeList kAttributes = lightmapped_attributes(C);
  static constexpr int kVaryings = kAttributes.varyings();
  static constexpr bool kCanDiscard = false, kWritesDepth = false;

  LightmappedGenericParams params;
  LightmapPage page;
  glm::vec3 eye{0.0f};
  std::atomic<uint64_t>* pixels = nullptr;
  bool water_fog_to_alpha = false;

  void operator()(const rasterizer::PixelInput<kVaryings>& in, rasterizer::PixelOutput& out) const {
    using F = simd::Float;
    constexpr AttributeList L = kAttributes;
    detail::count(pixels, in.live);
    LightmappedInputs<F> i;
    i.base_uv = float2<F>(detail::read<L, Attribute::base_u>(in), detail::read<L, Attribute::base_v>(in));
    const F lu = detail::read<L, Attribute::lightmap_u>(in) * page.scale;
    const F lv = detail::read<L, Attribute::lightmap_v>(in);
    i.lightmap_uv0 = float2<F>(lu + page.offset[0], lv);
    i.lightmap_uv12 = float4<F>(lu + page.offset[1], lv, lu + page.offset[2], lv);
    i.lightmap_uv3 = float2<F>(lu + page.offset[3], lv);
    if constexpr (C.envmap) {
      i.normal = detail::read3<L, Attribute::normal_x, Attribute::normal_y, Attribute::normal_z>(in);
      if constexpr (C.bump) {
        i.tangent = detail::read3<L, Attribute::tangent_x, Attribute::tangent_y, Attribute::tangent_z>(in);
        i.binormal = detail::read3<L, Attribute::binormal_x, Attribute::binormal_y, Attribute::binormal_z>(in);
      }
      i.eye_vector = constant<F>(eye) - detail::read3<L, Attribute::world_x, Attribute::world_y, Attribute::world_z>(in);
    }
    if constexpr (C.fog == Fog::range || C.fog == Fog::height)
      i.fog = FogInputs<F>{detail::read<L, Attribute::world_z>(in), detail::read<L, Attribute::proj_z>(in)};
    detail::write<C.fog, L>(lightmapped_generic<C>(i, params), in, params.fog, out);
    detail::write_water_fog_alpha<C.fog, L>(water_fog_to_alpha, in, params.fog, out);
  }
};

// ---- VertexLitGeneric ---------------------------------------------------------------------------

constexpr AttributeList vertexlit_attributes(const VertexLitCombo& c) {
  AttributeList l;
  l.add({Attribute::base_u, Attribute::base_v});
  detail::add_world(l);
  detail::add_normal(l);
  if (c.bump) detail::add_tangent_frame(l);
  if (!c.pixel_attenuation && c.lights > 0)
    l.add({Attribute::attenuation_0, Attribute::attenuation_1, Attribute::attenuation_2, Attribute::attenuation_3});
  detail::add_fog(l, c.fog);
  return l;
}

template <VertexLitCombo C>
struct VertexLitPixelShader {
  static constexpr AttributeList kAttributes = vertexlit_attributes(C);
  static constexpr int kVaryings = kAttributes.varyings();
  static constexpr bool kCanDiscard = false, kWritesDepth = false;

  VertexLitParams params;
  std::atomic<uint64_t>* pixels = nullptr;
  bool water_fog_to_alpha = false;

  void operator()(const rasterizer::PixelInput<kVaryings>& in, rasterizer::PixelOutput& out) const {
    using F = simd::Float;
    constexpr AttributeList L = kAttributes;
    detail::count(pixels, in.live);
    VertexLitInputs<F> i;
    i.uv = float2<F>(detail::read<L, Attribute::base_u>(in), detail::read<L, Attribute::base_v>(in));
    i.world_pos = detail::read3<L, Attribute::world_x, Attribute::world_y, Attribute::world_z>(in);
    i.normal = detail::read3<L, Attribute::normal_x, Attribute::normal_y, Attribute::normal_z>(in);
    if constexpr (C.bump) {
      i.tangent = detail::read3<L, Attribute::tangent_x, Attribute::tangent_y, Attribute::tangent_z>(in);
      i.binormal = detail::read3<L, Attribute::binormal_x, Attribute::binormal_y, Attribute::binormal_z>(in);
    }
    if constexpr (!C.pixel_attenuation && C.lights > 0)
      i.attenuation = float4<F>(detail::read<L, Attribute::attenuation_0>(in), detail::read<L, Attribute::attenuation_1>(in),
                                detail::read<L, Attribute::attenuation_2>(in), detail::read<L, Attribute::attenuation_3>(in));
    if constexpr (C.fog == Fog::range || C.fog == Fog::height) i.proj_z = detail::read<L, Attribute::proj_z>(in);
    detail::write<C.fog, L>(vertexlit_generic<C>(i, params), in, params.fog, out);
    detail::write_water_fog_alpha<C.fog, L>(water_fog_to_alpha, in, params.fog, out);
  }
};

// ---- UnlitGeneric -------------------------------------------------------------------------------

constexpr AttributeList unlit_attributes(const UnlitCombo& c) {
  AttributeList l;
  l.add({Attribute::base_u, Attribute::base_v});
  if (c.vertex_color) l.add({Attribute::color_r, Attribute::color_g, Attribute::color_b, Attribute::color_a});
  if (c.envmap) {
    detail::add_normal(l);
    detail::add_world(l);
  }
  detail::add_fog(l, c.fog);
  return l;
}

/// UnlitGeneric without detail texture or per-vertex lighting (the frame's unlit materials).
template <UnlitCombo C>
struct UnlitPixelShader {
  static_assert(C.detail == UnlitDetail::none && !C.diffuse_lighting, "detail and DIFFUSELIGHTING need inputs the adapter does not feed");
  static constexpr AttributeList kAttributes = unlit_attributes(C);
  static constexpr int kVaryings = kAttributes.varyings();
  static constexpr bool kCanDiscard = false, kWritesDepth = false;

  UnlitGenericParams params;
  glm::vec3 eye{0.0f};
  std::atomic<uint64_t>* pixels = nullptr;
  bool water_fog_to_alpha = false;

  void operator()(const rasterizer::PixelInput<kVaryings>& in, rasterizer::PixelOutput& out) const {
    using F = simd::Float;
    constexpr AttributeList L = kAttributes;
    detail::count(pixels, in.live);
    UnlitInputs<F> i;
    i.base_uv = float2<F>(detail::read<L, Attribute::base_u>(in), detail::read<L, Attribute::base_v>(in));
    if constexpr (C.vertex_color)
      i.vertex_color = float4<F>(detail::read<L, Attribute::color_r>(in), detail::read<L, Attribute::color_g>(in),
                                 detail::read<L, Attribute::color_b>(in), detail::read<L, Attribute::color_a>(in));
    if constexpr (C.envmap) {
      i.normal = detail::read3<L, Attribute::normal_x, Attribute::normal_y, Attribute::normal_z>(in);
      i.eye_vector = constant<F>(eye) - detail::read3<L, Attribute::world_x, Attribute::world_y, Attribute::world_z>(in);
    }
    if constexpr (C.fog == Fog::range || C.fog == Fog::height)
      i.fog = FogInputs<F>{detail::read<L, Attribute::world_z>(in), detail::read<L, Attribute::proj_z>(in)};
    detail::write<C.fog, L>(unlit_generic<C>(i, params), in, params.fog, out);
    detail::write_water_fog_alpha<C.fog, L>(water_fog_to_alpha, in, params.fog, out);
  }
};

// ---- Sky_HDR ------------------------------------------------------------------------------------

constexpr AttributeList sky_attributes() {
  AttributeList l;
  l.add({Attribute::base_u, Attribute::base_v});
  return l;
}

/// One skybox face (Source draws the sky as six textured quads), the hdr16 combo.
struct SkyPixelShader {
  static constexpr SkyCombo kCombo{SkyTexture::hdr16};
  static constexpr AttributeList kAttributes = sky_attributes();
  static constexpr int kVaryings = kAttributes.varyings();
  static constexpr bool kCanDiscard = false, kWritesDepth = false;

  SkyParams params;
  std::atomic<uint64_t>* pixels = nullptr;

  void operator()(const rasterizer::PixelInput<kVaryings>& in, rasterizer::PixelOutput& out) const {
    using F = simd::Float;
    constexpr AttributeList L = kAttributes;
    detail::count(pixels, in.live);
    SkyInputs<F> i;
    i.uv = float2<F>(detail::read<L, Attribute::base_u>(in), detail::read<L, Attribute::base_v>(in));
    detail::write<Fog::none, L>(sky<kCombo>(i, params), in, FogConstants{}, out);
  }
};

// ---- Water --------------------------------------------------------------------------------------

constexpr AttributeList water_attributes(const WaterCombo& c) {
  AttributeList l;
  l.add({Attribute::base_u, Attribute::base_v});
  detail::add_world(l);
  detail::add_normal(l);
  detail::add_tangent_frame(l);
  if (!c.above_water) l.add(Attribute::proj_z);
  detail::add_fog(l, c.fog);
  return l;
}

/// What water_vs20 computes from constants, per pixel here (affine in the interpolants, or the
/// pixel's place on screen).
struct WaterVertexConstants {
  /// cBumpTexCoordTransform ($bumptransform): bump u = dot((u, v, 1), bump_u), v likewise, of
  /// the mesh's uv0.
  glm::vec3 bump_u{1.0f, 0.0f, 0.0f}, bump_v{0.0f, 1.0f, 0.0f};
  /// TexOffsets: time x ($scroll1.xy, $scroll2.xy), the MULTITEXTURE reads' offsets.
  glm::vec4 scroll_offsets{0.0f};
  /// 1 / the frame's width and height. The vertex shader's projective coordinate of a target
  /// ((x, -y) + w) / 2 divided by w is the pixel's place on screen, which the rasterizer gives:
  /// the shader is fed that, with w = 1. The reflection view is mirrored (water_passes.hpp), so
  /// both targets are read at the pixel's own place.
  glm::vec2 inverse_size{1.0f};
};

/// Water_ps2x on a water surface, its reflection and refraction bound as textures.
template <WaterCombo C>
struct WaterPixelShader {
  static constexpr AttributeList kAttributes = water_attributes(C);
  static constexpr int kVaryings = kAttributes.varyings();
  static constexpr bool kCanDiscard = false, kWritesDepth = false;

  WaterParams params;
  WaterVertexConstants constants;
  glm::vec3 eye{0.0f};
  std::atomic<uint64_t>* pixels = nullptr;

  void operator()(const rasterizer::PixelInput<kVaryings>& in, rasterizer::PixelOutput& out) const {
    using F = simd::Float;
    constexpr AttributeList L = kAttributes;
    detail::count(pixels, in.live);
    const F u = detail::read<L, Attribute::base_u>(in), v = detail::read<L, Attribute::base_v>(in);
    WaterInputs<F> i;
    const float3<F> uv1(u, v, F(1.0f));
    i.bump_uv = float2<F>(dot(uv1, constant<F>(constants.bump_u)), dot(uv1, constant<F>(constants.bump_v)));
    if constexpr (C.multitexture) {
      const glm::vec4& o = constants.scroll_offsets;
      i.extra_bump_uv = float4<F>((u + v) * 0.1f + o.x, (v - u) * 0.1f + o.y, v * 0.45f + o.z, u * 0.45f + o.w);
    }
    const float3<F> eye_vector =
        constant<F>(eye) - detail::read3<L, Attribute::world_x, Attribute::world_y, Attribute::world_z>(in);
    const float3<F> t = detail::read3<L, Attribute::tangent_x, Attribute::tangent_y, Attribute::tangent_z>(in);
    const float3<F> b = detail::read3<L, Attribute::binormal_x, Attribute::binormal_y, Attribute::binormal_z>(in);
    const float3<F> n = detail::read3<L, Attribute::normal_x, Attribute::normal_y, Attribute::normal_z>(in);
    i.tangent_eye = float3<F>(dot(eye_vector, t), dot(eye_vector, b), dot(eye_vector, n));
    const F sx = in.x * constants.inverse_size.x, sy = in.y * constants.inverse_size.y;
    i.reflect_refract = float4<F>(sx, sy, sy, sx);
    i.w = F(1.0f);
    if constexpr (!C.above_water || C.fog == Fog::range || C.fog == Fog::height)
      i.proj_z = detail::read<L, Attribute::proj_z>(in);
    if constexpr (C.fog == Fog::height) i.world_z = detail::read<L, Attribute::world_z>(in);
    detail::write<C.fog, L>(water<C>(i, params), in, params.pixel_fog, out);
  }
};

}  // namespace luxel::shading::source
