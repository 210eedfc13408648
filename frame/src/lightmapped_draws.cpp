// LightmappedGeneric draws (source_draws.hpp): every LightmappedGeneric combo (drawn_combos.hpp).

#include "drawn_combos.hpp"
#include "make_source_draw.hpp"

namespace luxel::frame {

using namespace shading::source;

SourceDraw lightmapped_draw(const LightmappedCombo& combo, shading::ShaderModel model, const DrawTarget& target,
                            const LightmappedGenericParams& params, const LightmapPage& page, const glm::vec3& eye) {
  SourceDraw d;
  const bool found = detail::with_combo<detail::kLightmappedDrawn>(combo, [&]<LightmappedCombo C>() {
    LightmappedPixelShader<C> ps{params, page, eye};
    const shading::ShaderModel binary = detail::binary_for(C, model);
    d = detail::make_source_draw(ps, target, "LightmappedGeneric", C.name(), binary, counted_cost(C, binary).total_slots());
  });
  if (!found) detail::outside_space("LightmappedGeneric", combo.name());
  return d;
}

}  // namespace luxel::frame
