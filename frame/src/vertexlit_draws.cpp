// VertexLitGeneric draws (source_draws.hpp): the frame's combo space of models, per pixel.

#include "combo_slots.hpp"
#include "combo_spaces.hpp"
#include "source_draws.hpp"

namespace luxel::frame {

using namespace shading::source;

std::optional<VertexLitCombo> fitting_vertexlit_combo(VertexLitCombo wanted, shading::ShaderModel model) {
  if (wanted.lights == 0) wanted.half_lambert = wanted.pixel_attenuation = true;
  const std::optional<shading::ShaderModel> binary = wanted.builds().binary_for(model);
  if (!binary) return std::nullopt;
  if (detail::vertexlit_fits(wanted, *binary)) return wanted;
  wanted.pixel_attenuation = false;
  if (wanted.lights > 0 && detail::vertexlit_fits(wanted, *binary)) return wanted;
  return std::nullopt;
}

SourceDraw vertexlit_draw(const VertexLitCombo& combo, shading::ShaderModel model, const DrawTarget& target,
                          const VertexLitParams& params) {
  SourceDraw d;
  const bool found = detail::with_combo<detail::kVertexLitSpace>(combo, [&]<VertexLitCombo C>() {
    VertexLitPixelShader<C> ps{params};
    const shading::ShaderModel binary = detail::binary_for(C, model);
    d = detail::make_source_draw(ps, target, "VertexLitGeneric", C.name(), binary, detail::vertexlit_slots(C, binary));
  });
  if (!found) detail::outside_space("VertexLitGeneric", combo.name());
  return d;
}

}  // namespace luxel::frame
