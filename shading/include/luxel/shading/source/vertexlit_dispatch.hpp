#pragma once
// Which VertexLitGeneric shader a model material gets, as the SDK's helper chooses it
// (docs/fidelity.md#which-shader-a-model-gets): the Phong ("skin") shader only for a `$phong`
// material that has a bump map, `$basemapalphaphongmask 1` or a lightwarp texture
// (WantsSkinShader), and only on hardware with ps_2_b or more; every other material takes the
// ordinary path, bumped or not, without specular, on every model. Half-Lambert is the material's
// `$halflambert` on the ordinary paths; the skin shader always uses it. The skin shader has two
// forms: its full path, and FASTPATH_NOBUMP for a material with nothing but a base texture.
//
// Plain values in, plain values out: the frame reads a scene's material into VertexLitMaterial.

#include "luxel/shading/shader_model.hpp"

namespace luxel::shading::source {

/// The parameters of a VertexLitGeneric material that choose its shader.
struct VertexLitMaterial {
  bool phong = false;                      ///< $phong
  bool bump = false;                       ///< a $bumpmap texture
  bool base_map_alpha_phong_mask = false;  ///< $basemapalphaphongmask 1
  bool lightwarp = false;                  ///< a $lightwarptexture
  bool half_lambert = false;               ///< $halflambert
  bool exponent_texture = false;           ///< a $phongexponenttexture
  bool rim = false;                        ///< $rimlight
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

}  // namespace luxel::shading::source
