// VertexLitGeneric draws (source_draws.hpp): the models lit per pixel;
// here those without an env map (vertexlit_draw_in.hpp).

#include "vertexlit_draw_in.hpp"

namespace luxel::frame {

using namespace shading::source;

std::optional<VertexLitCombo> fitting_vertexlit_combo(VertexLitCombo wanted, shading::ShaderModel model) {
  if (wanted.lights == 0) wanted.half_lambert = wanted.pixel_attenuation = true;
  const std::optional<shading::ShaderModel> binary = wanted.builds().binary_for(model);
  if (!binary) return std::nullopt;
  if (vertexlit_fits(wanted, *binary)) return wanted;
  wanted.pixel_attenuation = false;
  if (wanted.lights > 0 && vertexlit_fits(wanted, *binary)) return wanted;
  return std::nullopt;
}

SourceDraw vertexlit_draw(const VertexLitCombo& combo, shading::ShaderModel model, const DrawTarget& target,
                          const VertexLitParams& params) {
  if (combo.envmap) return detail::vertexlit_envmap_draw(combo, model, target, params);
  return detail::vertexlit_draw_in<detail::kVertexLitPlainDrawn>(combo, model, target, params);
}

}  // namespace luxel::frame
