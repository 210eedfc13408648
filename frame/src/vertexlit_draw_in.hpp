#pragma once
// Private: the VertexLitGeneric draw of a combo from one half of the drawn combos
// (drawn_combos.hpp). The combos without an env map compile in vertexlit_draws.cpp, those with
// one in vertexlit_envmap_draws.cpp, so that the two build in parallel.

#include "drawn_combos.hpp"
#include "make_source_draw.hpp"

namespace luxel::frame::detail {

template <auto kSpace>
SourceDraw vertexlit_draw_in(const shading::source::VertexLitCombo& combo, shading::ShaderModel model,
                             const DrawTarget& target, const shading::source::VertexLitParams& params) {
  using shading::source::VertexLitCombo;
  SourceDraw d;
  const bool found = with_combo<kSpace>(combo, [&]<VertexLitCombo C>() {
    shading::source::VertexLitPixelShader<C> ps{params};
    const shading::ShaderModel binary = binary_for(C, model);
    d = make_source_draw(ps, target, "VertexLitGeneric", C.name(), binary, shading::source::counted_cost(C, binary).total_slots());
  });
  if (!found) outside_space("VertexLitGeneric", combo.name());
  return d;
}

/// vertexlit_draw_in over the combos with an env map.
SourceDraw vertexlit_envmap_draw(const shading::source::VertexLitCombo& combo, shading::ShaderModel model,
                                 const DrawTarget& target, const shading::source::VertexLitParams& params);

}  // namespace luxel::frame::detail
