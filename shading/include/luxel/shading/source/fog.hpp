#pragma once
// Fog, step 3 of every DX9 pixel shader's epilogue (docs/fidelity.md#fog; common_ps_fxc.h
// CalcRangeFog, CalcWaterFogAlpha, BlendPixelFog, FinalOutput; common_vs_fxc.h RangeFog), done
// per shader model as the SDK does it:
//
//   Fog::range         ps_2_b / ps_3_0 (PIXEL_FOG_TYPE_RANGE): f = sat(min(maxDensity, projZ / range
//                      - start / range)) and rgb = lerp(rgb, fog, f²) (the SDK squares f "to get the
//                      middle range mixing closer to hardware fog").
//   Fog::vertex_range  ps_2_0: CalcRangeFog returns 0 there ("too many ran out of slots"), so the
//                      pixel shader leaves its color unfogged and D3D's fixed-function fog blends it
//                      with the vertex shader's FOG output v = max(1 - maxDensity, (end - projZ) /
//                      range) (vertex_fog, RangeFog): rgb = v rgb + (1 - v) fog (fixed_function_fog:
//                      the fog unit's work after the shader, so no pixel-shader slots).
//   Fog::height        every model (PIXEL_FOG_TYPE_HEIGHT, seen through water): t = sat((waterZ - P.z)
//                      / (eyeZ - P.z)), the part of the eye-to-point segment under the water plane;
//                      f = sat(t projZ / range); rgb = lerp(rgb, fog, f), linear, not squared.
//
// The blend comes after the tone-map multiply, with the fog color of c29. Both the pixel fog
// constants and c29 are written by the closed shaderapi (NOT IN SDK); fog_constants() writes them
// as follows, and says why:
//  - params.x = start / range: CalcRangeFog's own parameter name ("FogStartOverRange"); with it f
//    runs from 0 at `start` to 1 at `end`, as the vertex path's (end - z) / range does. (The
//    #define names it FogEndOverRange, the name of the vertex constant c16.x = end / range.)
//  - the fog color is linear x LINEAR_LIGHT_SCALE: the client clears an INTEGER-HDR frame to
//    the fog color x scale^(1/2.2) in gamma space (docs/fidelity.md#tone-mapping), i.e. linear
//    fog x scale, and fully fogged geometry should meet that clear color.
//  - the vertex path's floor c16.z is 1 - maxDensity (RangeFog's max() is on visibility, 1 = clear).
//
// Scenes describe fog with FogSettings (no fog by default: the SDK draws unfogged unless a fog
// controller is active); range_fog_for_model() names the combo that draws range fog on a model.

#include "luxel/shading/source/common.hpp"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace luxel::shading::source {

/// The pixel shader's fog static combo (PIXELFOGTYPE), per shader model.
enum class Fog {
  none,          ///< unfogged
  range,         ///< pixel range fog, f² (ps_2_b, ps_3_0)
  vertex_range,  ///< ps_2_0's range fog: fixed-function, by the vertex shader's fog factor
  height,        ///< under-water height fog, linear (every model)
};

/// Whether the SDK can draw fog type f on pixel-shader model m.
constexpr bool fog_valid(Fog f, ShaderModel m) {
  if (f == Fog::range) return m != ShaderModel::ps_2_0;
  if (f == Fog::vertex_range) return m == ShaderModel::ps_2_0;
  return true;
}

/// The combo that draws range fog on model m (the SDK's choice).
constexpr Fog range_fog_for_model(ShaderModel m) {
  return m == ShaderModel::ps_2_0 ? Fog::vertex_range : Fog::range;
}

constexpr const char* fog_name(Fog f) {
  switch (f) {
    case Fog::range: return "+fog";
    case Fog::vertex_range: return "+vertexfog";
    case Fog::height: return "+heightfog";
    default: return "";
  }
}

/// A scene's fog, as a fog controller (or the water the eye is under) describes it.
struct FogSettings {
  float start = 0.0f;        ///< projected depth where range fog starts
  float end = 1.0f;          ///< projected depth of full range fog (height fog: depth of full fog)
  float max_density = 0.0f;  ///< cap on the fog amount; 0 = no fog (the SDK default)
  glm::vec3 color{0.0f};     ///< linear
  float water_z = 0.0f;      ///< height fog: world z of the water plane
};

/// The pixel shader's fog registers.
struct FogConstants {
  glm::vec4 params{0.0f};        ///< g_FogParams: x start / range, y water z, z max density, w 1 / range
  glm::vec4 color{0.0f};         ///< c29.rgb: linear fog color x LINEAR_LIGHT_SCALE
  glm::vec4 eye_position{0.0f};  ///< g_EyePos: height fog reads .z
};

inline FogConstants fog_constants(const FogSettings& s, const glm::vec3& eye, float tonemap_scale = 1.0f) {
  const float range = s.end - s.start;
  FogConstants c;
  c.params = glm::vec4(s.start / range, s.water_z, s.max_density, 1.0f / range);
  c.color = glm::vec4(s.color * tonemap_scale, 1.0f);
  c.eye_position = glm::vec4(eye, 1.0f);
  return c;
}

/// The vertex shader's fog register c16: (end / range, 1, 1 - maxDensity, 1 / range).
inline glm::vec4 vertex_fog_constant(const FogSettings& s) {
  const float range = s.end - s.start;
  return glm::vec4(s.end / range, 1.0f, 1.0f - s.max_density, 1.0f / range);
}

/// What fog reads per pixel: world z (height fog) and projected z (both), the SDK's
/// worldPos_projPosZ interpolant.
template <Lane L>
struct FogInputs {
  L world_z = L(0.0f);
  L proj_z = L(0.0f);
};

/// The fog interpolant as a Counted input register (worldPos_projPosZ: one float4) for the pixel
/// fog types; none and vertex_range read nothing.
template <Fog F>
inline FogInputs<Counted> fog_counted_inputs(CountedInputs& in) {
  FogInputs<Counted> r;
  if constexpr (F == Fog::range || F == Fog::height) {
    const float4<Counted> world_pos_proj_z = in.vector<4>();
    r.world_z = world_pos_proj_z.z;
    r.proj_z = world_pos_proj_z.w;
  }
  return r;
}

/// The fog amount f of the pixel fog types (0 = unfogged), before the blend.
template <Fog F, Lane L>
inline L pixel_fog_factor(const FogInputs<L>& in, const FogConstants& fog) {
  const float4<L> p = constant<L>(fog.params);
  if constexpr (F == Fog::range) {
    return saturate(min(p.z, in.proj_z * p.w - p.x));
  } else if constexpr (F == Fog::height) {
    const L below_water = p.y - in.world_z;
    const L below_eye = constant<L>(fog.eye_position).z - in.world_z;
    const L through_water = saturate(below_water * (1.0f / below_eye));
    return saturate(through_water * in.proj_z * p.w);
  } else {
    return L(0.0f);
  }
}

/// FinalOutput with fog: the tone map (final_output), then the blend of fog type F.
template <ToneMap T, Fog F, Lane L>
inline float4<L> fogged_output(const float4<L>& color, const ToneMapConstants& tm, const FogInputs<L>& in,
                               const FogConstants& fog) {
  const float4<L> c = final_output<T>(color, tm);
  if constexpr (F == Fog::range || F == Fog::height) {
    const L f = pixel_fog_factor<F>(in, fog);
    const L amount = F == Fog::range ? L(f * f) : f;
    return float4<L>(lerp(c.rgb(), constant<L>(fog.color).rgb(), amount), c.w);
  } else {
    return c;  // none; vertex_range is blended after the shader (fixed_function_fog)
  }
}

/// The vertex shader's FOG output for range fog (RangeFog): visibility, 1 = clear.
template <Lane L>
inline L vertex_fog(const L& proj_z, const glm::vec4& c16) {
  const float4<L> p = constant<L>(c16);
  return max(p.z, p.x - proj_z * p.w);
}

/// D3D9's fixed-function fog blend of a ps_2_0 pixel (Fog::vertex_range): the interpolated vertex
/// visibility v, clamped to [0, 1], mixes the shader's color with the fog color: v rgb + (1 - v)
/// fog. The fog unit's work, not the shader's: call it on the shader's output, never measure it.
template <Lane L>
inline float4<L> fixed_function_fog(const float4<L>& color, const L& visibility, const FogConstants& fog) {
  const L v = saturate(visibility);
  return float4<L>(lerp(constant<L>(fog.color).rgb(), color.rgb(), v), color.w);
}

}  // namespace luxel::shading::source
