#pragma once
// Private: what each family's source file (lightmapped_draws.cpp, vertexlit_draw_in.hpp,
// unlit_draws.cpp, water_draws.cpp) builds its draws (source_draws.hpp) with. A SourceDraw's
// function instantiates rasterizer::draw for the family's pixel functor, so this header includes
// the draw implementation (draw_definition.hpp): only those files include it.

#include "source_draws.hpp"
#include "source_vertex.hpp"

#include "luxel/rasterizer/draw_definition.hpp"
#include "luxel/shading/shader_model.hpp"

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace luxel::frame {
namespace detail {

/// The model of the binary a card of model `card` runs for `combo` (binaries.hpp). The frame
/// chooses only combos the card has a binary for: none is a frame bug.
template <class Combo>
shading::ShaderModel binary_for(const Combo& combo, shading::ShaderModel card) {
  const std::optional<shading::ShaderModel> b = combo.builds().binary_for(card);
  if (!b) throw std::logic_error(combo.name() + ": the SDK builds no binary of it for " + std::string(shading::caps(card).name));
  return *b;
}

/// The draw of pixel functor `ps` (its counter wired when counting), running the SDK binary of
/// model `binary`, which counts `slots`.
template <class PS>
SourceDraw make_source_draw(PS ps, const DrawTarget& target, std::string family, std::string combo,
                            shading::ShaderModel binary, int slots) {
  SourceDraw d;
  d.family = std::move(family);
  d.combo = std::move(combo);
  d.binary = binary;
  d.slots = slots;
  if (target.count_pixels) ps.pixels = d.pixels.get();
  if constexpr (requires { ps.water_fog_to_alpha; }) ps.water_fog_to_alpha = target.water_fog_to_alpha;
  target.vertex->attributes = PS::kAttributes;
  const SourceVertex<PS::kVaryings> vs{target.vertex};
  d.state = target.state;
  d.draw = [ps, vs, geometry = target.geometry](rasterizer::Context& ctx, const rasterizer::Framebuffer& fb,
                                                const rasterizer::PipelineState& state) {
    rasterizer::draw(ctx, fb, state, geometry, vs, ps);
  };
  return d;
}

[[noreturn]] inline void outside_space(const char* family, const std::string& combo) {
  throw std::logic_error(std::string(family) + " combo " + combo + " is outside the combos the frame draws");
}

}  // namespace detail
}  // namespace luxel::frame
