#pragma once
// VertexLitGeneric's vertex shader for models without a bump map, lit per vertex as the SDK does
// it (vertexlit_and_unlit_generic_vs20.fxc; common_vs_fxc.h DoLightingUnrolled, DoLightInternal,
// CosineTermInternal, VertexAttenInternal, AmbientLight, RangeFog; docs/fidelity.md#ambient-cube,
// #model-lights, #non-bumped-models, #fog). Written in the lane language like the pixel shaders and
// counted on the Counted lane against vs_2_0 and vs_3_0 (shader_model.hpp).
//
// Per vertex:
//   world     = cModel (4x3) x position; normal = normalize(cModel x normal)   (no skinning here)
//   proj      = cViewProj x world
//   lighting  = Σ_i color_i x cosine(N·L_i) x atten_i + ambient_cube(N)
//               cosine: squared Half-Lambert (0.5 N·L + 0.5)², *not* saturated first (the pixel
//               shader's DiffuseTerm saturates, the vertex CosineTermInternal does not; equal for
//               unit vectors), or Lambert max(0, N·L) (no upper clamp)
//   fog       = RangeFog: max(1 - maxDensity, (end - projZ) / range), ps_2_0's fixed-function fog
//               (fog.hpp); ps_2_b / ps_3_0 fog per pixel from worldPos_projPosZ
//   outputs   proj, uv, lighting (i.color, TEXCOORD2: not a clamped COLOR, so it can exceed 1),
//             worldVertToEyeVector and the world normal (cube maps), worldPos_projPosZ, fog
// The lighting is the pixel shader's code where the SDK shares it: light_attenuation() (the SDK's
// VertexAttenInternal, used by the bumped path's per-vertex attenuation too) and ambient_light()
// (VertexShaderAmbientLight has the pixel version's math). The pixel shader that reads i.color is
// unlit_generic.hpp's DIFFUSELIGHTING combo.
//
// Light counts (NUM_LIGHTS): 0..2 on vs_2_0 (DoLightingUnrolled); vs_3_0 loops over up to four
// (DoLighting with g_nLightCount), which luxel unrolls, so a vs_3_0 four-light count is that of the
// unrolled loop, an upper bound on the SDK's looped code. Light records use the pixel shader's
// LocalLight layout (vertexlit_generic.hpp): a directional light's position register holds the
// unit vector toward it (w = 0), so L = normalize(pos.xyz - world x pos.w) for every type, where the
// SDK lerps between that and -dir by color.w: the same vector.
//
// Not modelled: skinning and morphs, static (baked) vertex lighting (STATIC_LIGHT_VERTEX), vertex
// color, seamless and detail coordinates, tree sway, the flashlight, DOWATERFOG (on vs_2_0 the SDK's
// vertex shader writes 1 there and the pixel shader fogs: Fog::height).

#include "luxel/shading/source/binaries.hpp"
#include "luxel/shading/source/common.hpp"
#include "luxel/shading/source/fog.hpp"
#include "luxel/shading/source/vertexlit_generic.hpp"

#include <array>
#include <iterator>
#include <string>
#include <utility>

namespace luxel::shading::source {

/// The two vertex-shader models.
inline constexpr ShaderModel kVertexModels[] = {ShaderModel::vs_2_0, ShaderModel::vs_3_0};

struct VertexLitVsCombo {
  int lights = 2;            ///< local lights: 0..2 (vs_2_0), 0..4 (vs_3_0)
  bool half_lambert = true;  ///< $halflambert (squared Half-Lambert), else Lambert

  constexpr bool valid(ShaderModel m) const {
    if (m != ShaderModel::vs_2_0 && m != ShaderModel::vs_3_0) return false;
    return lights >= 0 && lights <= (m == ShaderModel::vs_2_0 ? 2 : 4);
  }
  /// vertexlit_and_unlit_generic_vs20.fxc: vs20 and vs30.
  static constexpr ShaderBuilds builds() { return {true, false, true}; }
  friend constexpr bool operator==(const VertexLitVsCombo&, const VertexLitVsCombo&) = default;
  std::string name() const {
    return std::to_string(lights) + (lights == 1 ? " light" : " lights") + (half_lambert ? "" : "+lambert");
  }
};

/// The vertex shader's constant registers.
struct VertexLitVsParams {
  glm::mat4 view_proj{1.0f};                      ///< cViewProj
  std::array<glm::vec4, 3> model{glm::vec4(1, 0, 0, 0), glm::vec4(0, 1, 0, 0), glm::vec4(0, 0, 1, 0)};  ///< cModel[0]: 4x3 rows
  glm::vec4 eye_position{0.0f};                   ///< cEyePos
  AmbientCube ambient{};                          ///< cAmbientCube
  std::array<LocalLight, 4> lights{};             ///< cLightInfo
  glm::vec4 fog = vertex_fog_constant(FogSettings{});  ///< c16 (no fog by default)
};

template <Lane L>
struct VertexLitVsInputs {
  float4<L> position{0.0f, 0.0f, 0.0f, 1.0f};  ///< object space, w = 1
  float3<L> normal{0.0f, 0.0f, 1.0f};          ///< object space
  float2<L> uv{0.0f};
};

template <Lane L>
struct VertexLitVsOutputs {
  float4<L> proj_pos;           ///< POSITION
  float2<L> uv;                 ///< TEXCOORD0
  float3<L> lighting;           ///< TEXCOORD2 (i.color.rgb of the pixel shader)
  float3<L> eye_vector;         ///< TEXCOORD3: world vertex to eye, unnormalised
  float3<L> world_normal;       ///< TEXCOORD4
  float4<L> world_pos_proj_z;   ///< TEXCOORD7: world position, projected z
  L fog;                        ///< FOG: range-fog visibility (1 = clear)
};

/// CosineTermInternal (vertex version): squared Half-Lambert without saturate, or max(0, N·L).
template <Lane L>
inline L vertex_cosine_term(const L& n_dot_l, bool half_lambert) {
  if (half_lambert) {
    const L h = n_dot_l * 0.5f + 0.5f;
    return h * h;
  }
  return max(n_dot_l, L(0.0f));
}

/// DoLightingUnrolled's dynamic part: the local lights and the ambient cube at a world point.
/// kFiniteAttenuation: hold each attenuation below kMaxVertexAttenuation (vertexlit_generic.hpp),
/// as the frame's vertex stage does, so that a light exactly on a vertex does not make the
/// interpolated lighting NaN; the counted shader, the SDK's, has no such guard.
template <VertexLitVsCombo C, Lane L, bool kFiniteAttenuation = false>
inline float3<L> vertex_lighting(const float3<L>& world_pos, const float3<L>& world_normal, const VertexLitVsParams& p) {
  float3<L> linear(0.0f);
  for (int i = 0; i < C.lights; ++i) {
    const LocalLight& light = p.lights[static_cast<size_t>(i)];
    float3<L> to_light;
    L atten = light_attenuation(world_pos, light, to_light);
    if constexpr (kFiniteAttenuation) atten = min(atten, L(kMaxVertexAttenuation));  // NaN too: min keeps the bound
    linear = linear + constant<L>(light.color).rgb() * (vertex_cosine_term(dot(world_normal, to_light), C.half_lambert) * atten);
  }
  return linear + ambient_light(world_normal, p.ambient);
}

template <VertexLitVsCombo C, Lane L>
inline VertexLitVsOutputs<L> vertexlit_vertex_shader(const VertexLitVsInputs<L>& in, const VertexLitVsParams& p) {
  const float4<L> m0 = constant<L>(p.model[0]);
  const float4<L> m1 = constant<L>(p.model[1]);
  const float4<L> m2 = constant<L>(p.model[2]);
  const float3<L> world(dot(m0, in.position), dot(m1, in.position), dot(m2, in.position));
  const float3<L> normal = normalize(float3<L>(dot(m0.xyz(), in.normal), dot(m1.xyz(), in.normal), dot(m2.xyz(), in.normal)));
  VertexLitVsOutputs<L> out;
  out.proj_pos = mul(constant<L>(p.view_proj), float4<L>(world, L(1.0f)));
  out.uv = in.uv;
  out.lighting = vertex_lighting<C>(world, normal, p);
  out.eye_vector = constant<L>(p.eye_position).xyz() - world;
  out.world_normal = normal;
  out.world_pos_proj_z = float4<L>(world, out.proj_pos.z);
  out.fog = vertex_fog(out.proj_pos.z, p.fog);
  return out;
}

/// The vertex shader's lighting (TEXCOORD2) of one vertex given in world space, its normal
/// normalized as the shader does, on the float lane with the frame's finite attenuation: what the
/// frame's vertex stage hands the DIFFUSELIGHTING pixel shader (unlit_generic.hpp).
template <VertexLitVsCombo C>
inline glm::vec3 vertex_lighting_at(const glm::vec3& world, const glm::vec3& normal, const VertexLitVsParams& p) {
  const float3<float> n = normalize(float3<float>(normal.x, normal.y, normal.z));
  const float3<float> l = vertex_lighting<C, float, true>(float3<float>(world.x, world.y, world.z), n, p);
  return {l.x, l.y, l.z};
}

using VertexLightingFn = glm::vec3 (*)(const glm::vec3& world, const glm::vec3& normal, const VertexLitVsParams& p);

template <VertexLitVsCombo C>
inline Cost measure_vertexlit_vertex_shader(ShaderModel model) {
  const VertexLitVsParams params{};
  return measure(model, [&](CountedInputs& in) {
    VertexLitVsInputs<Counted> v;
    v.position = in.vector<4>();
    v.normal = in.vector<3>();
    v.uv = in.vector<2>();
    const VertexLitVsOutputs<Counted> o = vertexlit_vertex_shader<C>(v, params);
    return std::make_tuple(o.proj_pos, o.uv, o.lighting, o.eye_vector, o.world_normal, o.world_pos_proj_z, o.fog);
  });
}

}  // namespace luxel::shading::source
