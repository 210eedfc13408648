#pragma once
// Which DX9 binaries the Source SDK 2013 builds of a shader, and which of them a card runs
// (docs/fidelity.md#shader-models). The SDK compiles each .fxc only for the profiles its
// build lists name: stdshader_dx9_20b.txt builds "ps2x" sources as ps20 and ps20b (filmgrain_ps20
// as ps20 alone), and stdshader_dx9_30.txt adds ps30 / vs30 for a few model shaders only
// (VertexLitGeneric's two paths, UnlitGeneric through the same helper, skin). A card runs the
// newest binary it can: a ps_3_0 card runs LightmappedGeneric, Water, Sky and the post-processing
// shaders as their ps20b binaries, and film grain everywhere as ps20. So what luxel counts and
// checks against a model's limits is the binary's model, not the card's.
//
// Each family says what it builds: a combo's builds() (LightmappedCombo, VertexLitCombo, ...),
// or, for a post shader without static combos, its pixel functor's kBuilds.

#include "luxel/shading/shader_model.hpp"

#include <optional>
#include <string_view>

namespace luxel::shading::source {

/// The binaries of one shader source. For a pixel shader: ps20, ps20b, ps30; for a vertex
/// shader: vs20 (`v2_0`) and vs30 (`v3_0`; `v2_b` unused).
struct ShaderBuilds {
  bool v2_0 = true;   ///< ps20 / vs20
  bool v2_b = true;   ///< ps20b
  bool v3_0 = false;  ///< ps30 / vs30

  /// The model of the binary a card of model `card` runs: the newest built one not above the
  /// card (nothing if none is, e.g. the skin shader on a ps_2_0 card).
  constexpr std::optional<ShaderModel> binary_for(ShaderModel card) const {
    switch (card) {
      case ShaderModel::ps_3_0:
        if (v3_0) return ShaderModel::ps_3_0;
        [[fallthrough]];
      case ShaderModel::ps_2_b:
        if (v2_b) return ShaderModel::ps_2_b;
        [[fallthrough]];
      case ShaderModel::ps_2_0:
        if (v2_0) return ShaderModel::ps_2_0;
        return std::nullopt;
      case ShaderModel::vs_3_0:
        if (v3_0) return ShaderModel::vs_3_0;
        [[fallthrough]];
      case ShaderModel::vs_2_0:
        if (v2_0) return ShaderModel::vs_2_0;
        return std::nullopt;
    }
    return std::nullopt;
  }
};

/// ps20 + ps20b: what stdshader_dx9_20b.txt makes of a "ps2x" source that stdshader_dx9_30.txt
/// does not list (LightmappedGeneric, Water, Sky, bloom, color correction, Engine_Post, ...).
inline constexpr ShaderBuilds kPs2xBuilds{true, true, false};
/// ps20 + ps20b + ps30: the sources both lists name (VertexLitGeneric and UnlitGeneric).
inline constexpr ShaderBuilds kPs2x30Builds{true, true, true};

/// The SDK's name of a binary's profile: "ps20", "ps20b", "ps30", "vs20", "vs30".
constexpr std::string_view binary_name(ShaderModel binary) {
  switch (binary) {
    case ShaderModel::ps_2_0: return "ps20";
    case ShaderModel::ps_2_b: return "ps20b";
    case ShaderModel::ps_3_0: return "ps30";
    case ShaderModel::vs_2_0: return "vs20";
    case ShaderModel::vs_3_0: return "vs30";
  }
  return "?";
}

}  // namespace luxel::shading::source
