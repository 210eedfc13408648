// VertexLitGeneric draws (source_draws.hpp): the frame's combo space of models, per pixel.

#include "combo_slots.hpp"
#include "combo_spaces.hpp"
#include "source_draws.hpp"

namespace luxel::frame {

using namespace shading::source;

std::optional<VertexLitCombo> fitting_vertexlit_combo(VertexLitCombo wanted, shading::ShaderModel model) {
  if (wanted.lights == 0) wanted.half_lambert = wanted.pixel_attenuation = true;
  if (detail::vertexlit_fits(wanted, model)) return wanted;
  wanted.pixel_attenuation = false;
  if (wanted.lights > 0 && detail::vertexlit_fits(wanted, model)) return wanted;
  return std::nullopt;
}

SourceDraw vertexlit_draw(const VertexLitCombo& combo, shading::ShaderModel model, const DrawTarget& target,
                          const VertexLitParams& params) {
  SourceDraw d;
  const bool found = detail::with_combo<detail::kVertexLitSpace>(combo, [&]<VertexLitCombo C>() {
    VertexLitPixelShader<C> ps{params};
    d = detail::make_source_draw(ps, target, "VertexLitGeneric", C.name(), detail::vertexlit_slots(C, model));
  });
  if (!found) detail::outside_space("VertexLitGeneric", combo.name());
  return d;
}

}  // namespace luxel::frame
