// Water draws (source_draws.hpp): every Water combo (drawn_combos.hpp).

#include "drawn_combos.hpp"
#include "make_source_draw.hpp"

namespace luxel::frame {

using namespace shading::source;

SourceDraw water_draw(const WaterCombo& combo, shading::ShaderModel model, const DrawTarget& target,
                      const WaterParams& params, const WaterVertexConstants& constants, const glm::vec3& eye) {
  SourceDraw d;
  const bool found = detail::with_combo<detail::kWaterDrawn>(combo, [&]<WaterCombo C>() {
    WaterPixelShader<C> ps{params, constants, eye};
    const shading::ShaderModel binary = detail::binary_for(C, model);
    d = detail::make_source_draw(ps, target, "Water", C.name(), binary, counted_cost(C, binary).total_slots());
  });
  if (!found) detail::outside_space("Water", combo.name());
  return d;
}

}  // namespace luxel::frame
