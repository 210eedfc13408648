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
// Lanes: each functor's `shade` computes a pixel's color from its attributes on any lane: the
// SIMD stamp (operator(), what draws run) or the float lane, one pixel at a time (ScalarReference
// below, the scalar reference that tests hold the stamps to).
//
// Counting: when `pixels` is set, each invocation adds its covered lanes to it (shader_use.hpp).
//
// Water fog to destination alpha: the world families' height-fog combos (the view through the
// water, the refraction view) write the fog factor to alpha when `water_fog_to_alpha` is set, as
// the SDK's WRITEWATERFOGTODESTALPHA (lightmappedgeneric_dx9_helper.cpp and vertexlitgeneric's:
// set with height fog for fully opaque materials; the others keep their alpha). The water shader
// reads it back as the water's depth (water.hpp).

#include "luxel/rasterizer/draw.hpp"
#include "luxel/shading/source/lightmapped_generic.hpp"
#include "luxel/shading/source/shader_use.hpp"
#include "luxel/shading/source/sky.hpp"
#include "luxel/shading/source/unlit_generic.hpp"
#include "luxel/shading/source/vertexlit_generic.hpp"
#include "luxel/shading/source/water.hpp"

#include <array>
#include <atomic>
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
  light_r, light_g, light_b,           ///< the vertex shader's lighting (VertexLitGeneric without a bump map)
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

/// A stamp's attributes (SIMD lanes), each read from the varyings at its place in L.
template <AttributeList L, int N>
struct StampAttributes {
  using Lane = simd::Float;
  const rasterizer::PixelInput<N>& in;

  /// The pixels' centers on the target (x + 0.5, y + 0.5).
  LUXEL_INLINE simd::Float pixel_x() const { return in.x; }
  LUXEL_INLINE simd::Float pixel_y() const { return in.y; }

  template <Attribute A>
  LUXEL_INLINE simd::Float get() const {
    constexpr int i = L.index_of(A);
    static_assert(i >= 0, "the combo's attribute list does not hold this attribute");
    const simd::Float4& v = in.varyings[i / 4];
    if constexpr (i % 4 == 0) return v.x;
    else if constexpr (i % 4 == 1) return v.y;
    else if constexpr (i % 4 == 2) return v.z;
    else return v.w;
  }
};

/// One pixel's attributes (the float lane), in L's order.
template <AttributeList L>
struct PixelAttributes {
  using Lane = float;
  std::array<float, kAttributeKinds> values{};
  float x = 0.0f, y = 0.0f;  ///< the pixel's center on the target

  float pixel_x() const { return x; }
  float pixel_y() const { return y; }

  template <Attribute A>
  float get() const {
    constexpr int i = L.index_of(A);
    static_assert(i >= 0, "the combo's attribute list does not hold this attribute");
    return values[static_cast<size_t>(i)];
  }
};

template <Attribute X, Attribute Y, Attribute Z, class A>
LUXEL_INLINE float3<typename A::Lane> get3(const A& a) {
  return float3<typename A::Lane>(a.template get<X>(), a.template get<Y>(), a.template get<Z>());
}

/// The shader's color after the fixed-function fog of ps_2_0.
template <Fog F, class A>
LUXEL_INLINE float4<typename A::Lane> fogged(const float4<typename A::Lane>& c, const A& a, const FogConstants& fog) {
  if constexpr (F == Fog::vertex_range) return fixed_function_fog(c, a.template get<Attribute::fog_visibility>(), fog);
  else return c;
}

/// WRITEWATERFOGTODESTALPHA: alpha = the height fog factor (Fog::height combos only).
template <Fog F, class A>
LUXEL_INLINE float4<typename A::Lane> with_water_fog_alpha(float4<typename A::Lane> c, bool enabled, const A& a,
                                                           const FogConstants& fog) {
  if constexpr (F == Fog::height) {
    using L = typename A::Lane;
    if (enabled)
      c.w = pixel_fog_factor<Fog::height>(FogInputs<L>{a.template get<Attribute::world_z>(), a.template get<Attribute::proj_z>()}, fog);
  }
  return c;
}

LUXEL_INLINE void write(const float4<simd::Float>& c, rasterizer::PixelOutput& out) { out.color = {c.x, c.y, c.z, c.w}; }

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

  template <class A>
  LUXEL_INLINE float4<typename A::Lane> shade(const A& a) const {
    using F = typename A::Lane;
    LightmappedInputs<F> i;
    i.base_uv = float2<F>(a.template get<Attribute::base_u>(), a.template get<Attribute::base_v>());
    const F lu = a.template get<Attribute::lightmap_u>() * page.scale;
    const F lv = a.template get<Attribute::lightmap_v>();
    i.lightmap_uv0 = float2<F>(lu + page.offset[0], lv);
    i.lightmap_uv12 = float4<F>(lu + page.offset[1], lv, lu + page.offset[2], lv);
    i.lightmap_uv3 = float2<F>(lu + page.offset[3], lv);
    if constexpr (C.envmap) {
      i.normal = detail::get3<Attribute::normal_x, Attribute::normal_y, Attribute::normal_z>(a);
      if constexpr (C.bump) {
        i.tangent = detail::get3<Attribute::tangent_x, Attribute::tangent_y, Attribute::tangent_z>(a);
        i.binormal = detail::get3<Attribute::binormal_x, Attribute::binormal_y, Attribute::binormal_z>(a);
      }
      i.eye_vector = constant<F>(eye) - detail::get3<Attribute::world_x, Attribute::world_y, Attribute::world_z>(a);
    }
    if constexpr (C.fog == Fog::range || C.fog == Fog::height)
      i.fog = FogInputs<F>{a.template get<Attribute::world_z>(), a.template get<Attribute::proj_z>()};
    return detail::with_water_fog_alpha<C.fog>(detail::fogged<C.fog>(lightmapped_generic<C>(i, params), a, params.fog),
                                               water_fog_to_alpha, a, params.fog);
  }

  void operator()(const rasterizer::PixelInput<kVaryings>& in, rasterizer::PixelOutput& out) const {
    count_pixels(pixels, in.live);
    detail::write(shade(detail::StampAttributes<kAttributes, kVaryings>{in}), out);
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

  template <class A>
  LUXEL_INLINE float4<typename A::Lane> shade(const A& a) const {
    using F = typename A::Lane;
    VertexLitInputs<F> i;
    i.uv = float2<F>(a.template get<Attribute::base_u>(), a.template get<Attribute::base_v>());
    i.world_pos = detail::get3<Attribute::world_x, Attribute::world_y, Attribute::world_z>(a);
    i.normal = detail::get3<Attribute::normal_x, Attribute::normal_y, Attribute::normal_z>(a);
    if constexpr (C.bump) {
      i.tangent = detail::get3<Attribute::tangent_x, Attribute::tangent_y, Attribute::tangent_z>(a);
      i.binormal = detail::get3<Attribute::binormal_x, Attribute::binormal_y, Attribute::binormal_z>(a);
    }
    if constexpr (!C.pixel_attenuation && C.lights > 0)
      i.attenuation = float4<F>(a.template get<Attribute::attenuation_0>(), a.template get<Attribute::attenuation_1>(),
                                a.template get<Attribute::attenuation_2>(), a.template get<Attribute::attenuation_3>());
    if constexpr (C.fog == Fog::range || C.fog == Fog::height) i.proj_z = a.template get<Attribute::proj_z>();
    return detail::with_water_fog_alpha<C.fog>(detail::fogged<C.fog>(vertexlit_generic<C>(i, params), a, params.fog),
                                               water_fog_to_alpha, a, params.fog);
  }

  void operator()(const rasterizer::PixelInput<kVaryings>& in, rasterizer::PixelOutput& out) const {
    count_pixels(pixels, in.live);
    detail::write(shade(detail::StampAttributes<kAttributes, kVaryings>{in}), out);
  }
};

// ---- UnlitGeneric -------------------------------------------------------------------------------

constexpr AttributeList unlit_attributes(const UnlitCombo& c) {
  AttributeList l;
  l.add({Attribute::base_u, Attribute::base_v});
  if (c.vertex_color) l.add({Attribute::color_r, Attribute::color_g, Attribute::color_b, Attribute::color_a});
  if (c.diffuse_lighting) l.add({Attribute::light_r, Attribute::light_g, Attribute::light_b});
  if (c.envmap) {
    detail::add_normal(l);
    detail::add_world(l);
  }
  detail::add_fog(l, c.fog);
  return l;
}

/// UnlitGeneric without detail texture (the frame's unlit materials), and with DIFFUSELIGHTING
/// VertexLitGeneric without a bump map, its lighting from the vertex stage (light_r/g/b: the
/// vertex shader's, vertexlit_vertex_shader.hpp).
template <UnlitCombo C>
struct UnlitPixelShader {
  static_assert(C.detail == UnlitDetail::none, "detail needs a coordinate the adapter does not feed");
  static constexpr AttributeList kAttributes = unlit_attributes(C);
  static constexpr int kVaryings = kAttributes.varyings();
  static constexpr bool kCanDiscard = false, kWritesDepth = false;

  UnlitGenericParams params;
  glm::vec3 eye{0.0f};
  std::atomic<uint64_t>* pixels = nullptr;
  bool water_fog_to_alpha = false;

  template <class A>
  LUXEL_INLINE float4<typename A::Lane> shade(const A& a) const {
    using F = typename A::Lane;
    UnlitInputs<F> i;
    i.base_uv = float2<F>(a.template get<Attribute::base_u>(), a.template get<Attribute::base_v>());
    if constexpr (C.vertex_color)
      i.vertex_color = float4<F>(a.template get<Attribute::color_r>(), a.template get<Attribute::color_g>(),
                                 a.template get<Attribute::color_b>(), a.template get<Attribute::color_a>());
    if constexpr (C.diffuse_lighting)
      i.vertex_color = float4<F>(a.template get<Attribute::light_r>(), a.template get<Attribute::light_g>(),
                                 a.template get<Attribute::light_b>(), F(1.0f));
    if constexpr (C.envmap) {
      i.normal = detail::get3<Attribute::normal_x, Attribute::normal_y, Attribute::normal_z>(a);
      i.eye_vector = constant<F>(eye) - detail::get3<Attribute::world_x, Attribute::world_y, Attribute::world_z>(a);
    }
    if constexpr (C.fog == Fog::range || C.fog == Fog::height)
      i.fog = FogInputs<F>{a.template get<Attribute::world_z>(), a.template get<Attribute::proj_z>()};
    return detail::with_water_fog_alpha<C.fog>(detail::fogged<C.fog>(unlit_generic<C>(i, params), a, params.fog),
                                               water_fog_to_alpha, a, params.fog);
  }

  void operator()(const rasterizer::PixelInput<kVaryings>& in, rasterizer::PixelOutput& out) const {
    count_pixels(pixels, in.live);
    detail::write(shade(detail::StampAttributes<kAttributes, kVaryings>{in}), out);
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

  template <class A>
  LUXEL_INLINE float4<typename A::Lane> shade(const A& a) const {
    using F = typename A::Lane;
    SkyInputs<F> i;
    i.uv = float2<F>(a.template get<Attribute::base_u>(), a.template get<Attribute::base_v>());
    return sky<kCombo>(i, params);
  }

  void operator()(const rasterizer::PixelInput<kVaryings>& in, rasterizer::PixelOutput& out) const {
    count_pixels(pixels, in.live);
    detail::write(shade(detail::StampAttributes<kAttributes, kVaryings>{in}), out);
  }
};

// ---- The scalar reference -----------------------------------------------------------------------

/// Any functor above computed one covered pixel at a time on the float lane: the scalar reference
/// of the same draw, which tests hold the SIMD stamps to. Each live lane's attributes are read out
/// of the stamp and shaded alone; helper lanes output 0. Textures are sampled with the texture
/// module's scalar reference at level 0 (the float lane has no neighbours for derivatives, and
/// this functor supplies none): exact only for textures without mips.
template <class PS>
struct ScalarReference {
  static constexpr AttributeList kAttributes = PS::kAttributes;
  static constexpr int kVaryings = PS::kVaryings;
  static constexpr bool kCanDiscard = false, kWritesDepth = false;

  PS shader;

  void operator()(const rasterizer::PixelInput<kVaryings>& in, rasterizer::PixelOutput& out) const {
    alignas(64) float attributes[4 * (kVaryings > 0 ? kVaryings : 1)][simd::kLanes];
    for (int v = 0; v < kVaryings; ++v) {
      in.varyings[v].x.store_aligned(attributes[4 * v]);
      in.varyings[v].y.store_aligned(attributes[4 * v + 1]);
      in.varyings[v].z.store_aligned(attributes[4 * v + 2]);
      in.varyings[v].w.store_aligned(attributes[4 * v + 3]);
    }
    alignas(64) float xs[simd::kLanes], ys[simd::kLanes];
    in.x.store_aligned(xs);
    in.y.store_aligned(ys);
    alignas(64) float color[4][simd::kLanes] = {};
    for (int lane = 0; lane < simd::kLanes; ++lane) {
      if (!((in.live >> lane) & 1u)) continue;
      detail::PixelAttributes<kAttributes> a;
      for (int i = 0; i < kAttributes.count; ++i) a.values[static_cast<size_t>(i)] = attributes[i][lane];
      a.x = xs[lane];
      a.y = ys[lane];
      const float4<float> c = shader.shade(a);
      color[0][lane] = c.x;
      color[1][lane] = c.y;
      color[2][lane] = c.z;
      color[3][lane] = c.w;
    }
    out.color = {simd::Float::load_aligned(color[0]), simd::Float::load_aligned(color[1]),
                 simd::Float::load_aligned(color[2]), simd::Float::load_aligned(color[3])};
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

  template <class A>
  LUXEL_INLINE float4<typename A::Lane> shade(const A& a) const {
    using F = typename A::Lane;
    const F u = a.template get<Attribute::base_u>(), v = a.template get<Attribute::base_v>();
    WaterInputs<F> i;
    const float3<F> uv1(u, v, F(1.0f));
    i.bump_uv = float2<F>(dot(uv1, constant<F>(constants.bump_u)), dot(uv1, constant<F>(constants.bump_v)));
    if constexpr (C.multitexture) {
      const glm::vec4& o = constants.scroll_offsets;
      i.extra_bump_uv = float4<F>((u + v) * 0.1f + o.x, (v - u) * 0.1f + o.y, v * 0.45f + o.z, u * 0.45f + o.w);
    }
    const float3<F> eye_vector = constant<F>(eye) - detail::get3<Attribute::world_x, Attribute::world_y, Attribute::world_z>(a);
    const float3<F> t = detail::get3<Attribute::tangent_x, Attribute::tangent_y, Attribute::tangent_z>(a);
    const float3<F> b = detail::get3<Attribute::binormal_x, Attribute::binormal_y, Attribute::binormal_z>(a);
    const float3<F> n = detail::get3<Attribute::normal_x, Attribute::normal_y, Attribute::normal_z>(a);
    i.tangent_eye = float3<F>(dot(eye_vector, t), dot(eye_vector, b), dot(eye_vector, n));
    const F sx = a.pixel_x() * constants.inverse_size.x, sy = a.pixel_y() * constants.inverse_size.y;
    i.reflect_refract = float4<F>(sx, sy, sy, sx);
    i.w = F(1.0f);
    if constexpr (!C.above_water || C.fog == Fog::range || C.fog == Fog::height) i.proj_z = a.template get<Attribute::proj_z>();
    if constexpr (C.fog == Fog::height) i.world_z = a.template get<Attribute::world_z>();
    return detail::fogged<C.fog>(water<C>(i, params), a, params.pixel_fog);
  }

  void operator()(const rasterizer::PixelInput<kVaryings>& in, rasterizer::PixelOutput& out) const {
    count_pixels(pixels, in.live);
    detail::write(shade(detail::StampAttributes<kAttributes, kVaryings>{in}), out);
  }
};

}  // namespace luxel::shading::source
