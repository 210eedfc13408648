#pragma once
// Which VertexLitGeneric shader a model material gets, as the SDK's helper chooses it
// (docs/fidelity.md#which-shader-a-model-gets): the Phong ("skin") shader only for a `$phong`
// material that has a bump map, `$basemapalphaphongmask 1` or a lightwarp texture
// (WantsSkinShader), and only on hardware with ps_2_b or more; every other material takes the
// ordinary path, bumped or not, without specular, on every model. Half-Lambert is the material's
// `$halflambert` on the ordinary paths; the skin shader always uses it. The skin shader has two
// forms: its full path, and FASTPATH_NOBUMP for a material with nothing but a base texture.
//
// Then the static combo of the chosen shader (vertexlit_combo, vertexlit_plain_combo): the light
// count the shader model allows, the env map and its mask as the helpers leave them
// (docs/fidelity.md#env-maps-on-models), the frame's fog and attenuation choices.
//
// Plain values in, plain values out: the frame reads a scene's material into VertexLitMaterial.

#include "luxel/shading/shader_model.hpp"
#include "luxel/shading/source/fog.hpp"
#include "luxel/shading/source/unlit_generic.hpp"
#include "luxel/shading/source/vertexlit_generic.hpp"

#include <algorithm>

namespace luxel::shading::source {

/// What masks a model's env map (the .vmt flags): nothing, $envmapmask, $basealphaenvmapmask,
/// $normalmapalphaenvmapmask.
enum class ModelEnvmapMask { none, texture, base_alpha, normal_alpha };

/// The parameters of a VertexLitGeneric (or UnlitGeneric) material that choose its shader.
struct VertexLitMaterial {
  bool phong = false;                      ///< $phong
  bool bump = false;                       ///< a $bumpmap texture
  bool base_map_alpha_phong_mask = false;  ///< $basemapalphaphongmask 1
  bool lightwarp = false;                  ///< a $lightwarptexture
  bool half_lambert = false;               ///< $halflambert
  bool exponent_texture = false;           ///< a $phongexponenttexture
  bool rim = false;                        ///< $rimlight
  bool envmap = false;                     ///< an env map to reflect
  ModelEnvmapMask envmap_mask = ModelEnvmapMask::none;
  bool base_translucent = false;           ///< the base texture has texels with alpha below 1 (ITexture::IsTranslucent)
  bool vertex_color = false;               ///< the mesh's vertex colors ($vertexcolor; UnlitGeneric)
};

/// The three ways VertexLitGeneric draws a model.
enum class VertexLitPath {
  skin,    ///< skin_ps20b / skin_ps30: Phong, rim, Half-Lambert always
  bumped,  ///< vertexlit_and_unlit_generic_bump_ps2x: a normal map, no specular
  plain,   ///< vertexlit_and_unlit_generic_ps2x: no normal map, no specular
};

/// WantsSkinShader: `$phong` with a lightwarp texture, `$basemapalphaphongmask 1` or a bump map.
constexpr bool wants_skin_shader(const VertexLitMaterial& m) {
  return m.phong && (m.lightwarp || m.base_map_alpha_phong_mask || m.bump);
}

/// The path a card of pixel-shader model `card` draws the material with: the skin shader needs
/// ps_2_b (the SDK builds it as ps20b and ps30 only); a lightwarp texture takes the bumped path.
constexpr VertexLitPath vertexlit_path(const VertexLitMaterial& m, ShaderModel card) {
  if (wants_skin_shader(m) && card != ShaderModel::ps_2_0) return VertexLitPath::skin;
  return m.bump || m.lightwarp ? VertexLitPath::bumped : VertexLitPath::plain;
}

/// Whether the skin shader draws the material with FASTPATH_NOBUMP (skin_dx9_helper.cpp): no
/// normal map, exponent texture or rim light. The SDK also asks that the base alpha be a Phong
/// mask or the base opaque, and that there be no tint map, phong warp, detail, self-illum or
/// $blendtintbybasealpha, none of which luxel models: a skin material without a normal map has
/// $basemapalphaphongmask here, since luxel draws no lightwarp.
constexpr bool skin_fast_path(const VertexLitMaterial& m) { return !m.bump && !m.exponent_texture && !m.rim; }

/// Whether the path lights with squared Half-Lambert: always in the skin shader, else as the
/// material's `$halflambert` asks.
constexpr bool vertexlit_half_lambert(const VertexLitMaterial& m, VertexLitPath path) {
  return path == VertexLitPath::skin || m.half_lambert;
}

/// The most local lights the path takes on card `card` when the frame asks for `wanted` (1..4):
/// the bumped and skin shaders take four from ps_2_b up, two on ps_2_0; the plain path's vertex
/// shader two.
constexpr int vertexlit_max_lights(VertexLitPath path, ShaderModel card, int wanted) {
  return path != VertexLitPath::plain && card != ShaderModel::ps_2_0 ? wanted : std::min(wanted, 2);
}

/// What the frame decides beside the material.
struct VertexLitFrameChoices {
  bool pixel_attenuation = false;  ///< luxel's option (FrameSettings::pixel_attenuation)
  Fog fog = Fog::none;
};

/// The combo of the bumped or skin path (`path`) for a model with `lights` local lights kept
/// (0..4) on card `card`, before fitting it to the card's limits: the skin shader's full path
/// unless its fast path applies, the normalization cube exactly on ps_2_0, the bumped path's
/// env map masked by the normal map's alpha only with $normalmapalphaenvmapmask (a static combo;
/// the skin shader reads that choice from skin_envmap_mask_control). A bumped material's env map
/// masked otherwise is deleted by the helper (scenes::validate refuses it).
constexpr VertexLitCombo vertexlit_combo(const VertexLitMaterial& m, VertexLitPath path, int lights, ShaderModel card,
                                         const VertexLitFrameChoices& frame) {
  const bool skin = path == VertexLitPath::skin;
  VertexLitCombo c;
  c.lights = lights == 0 ? 0 : lights <= 2 ? 2 : 4;
  c.bump = skin ? !skin_fast_path(m) : m.bump;
  c.phong = skin;
  c.rim = skin && m.rim;
  c.half_lambert = vertexlit_half_lambert(m, path);
  c.pixel_attenuation = frame.pixel_attenuation;
  c.fog = frame.fog;
  c.normalization_cube = card == ShaderModel::ps_2_0;
  c.envmap = m.envmap;
  c.envmap_normal_alpha = m.envmap && !skin && m.bump && m.envmap_mask == ModelEnvmapMask::normal_alpha;
  return c;
}

/// The skin shader's env-map mask control (c.w of its tint register): 1 with
/// $normalmapalphaenvmapmask and a bump map (the Phong mask masks the env map), else 0 (the base
/// alpha does).
constexpr float skin_envmap_mask_control(const VertexLitMaterial& m) {
  return m.bump && m.envmap_mask == ModelEnvmapMask::normal_alpha ? 1.0f : 0.0f;
}

/// vertexlit_and_unlit_generic_ps2x's combo: the plain VertexLitGeneric path (`diffuse_lighting`)
/// or UnlitGeneric (with the mesh's vertex colors), with the env map masked as the helper leaves
/// the flags: $basealphaenvmapmask only over a translucent base, no $normalmapalphaenvmapmask
/// (no tangent space).
constexpr UnlitCombo generic_combo(const VertexLitMaterial& m, bool diffuse_lighting, Fog fog) {
  UnlitCombo c;
  c.diffuse_lighting = diffuse_lighting;
  c.vertex_color = !diffuse_lighting && m.vertex_color;
  c.envmap = m.envmap;
  if (m.envmap && m.envmap_mask == ModelEnvmapMask::texture) c.mask = UnlitEnvmapMask::texture;
  if (m.envmap && m.envmap_mask == ModelEnvmapMask::base_alpha && m.base_translucent) c.mask = UnlitEnvmapMask::base_alpha_inverted;
  c.fog = fog;
  return c;
}

}  // namespace luxel::shading::source
