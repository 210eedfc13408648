// UnlitGeneric and Sky_HDR draws (source_draws.hpp).

#include "drawn_combos.hpp"
#include "make_source_draw.hpp"

namespace luxel::frame {

using namespace shading::source;

SourceDraw unlit_draw(const UnlitCombo& combo, shading::ShaderModel model, const DrawTarget& target,
                      const UnlitGenericParams& params, const glm::vec3& eye) {
  SourceDraw d;
  const bool found = detail::with_combo<detail::kUnlitDrawn>(combo, [&]<UnlitCombo C>() {
    UnlitPixelShader<C> ps{params, eye};
    const shading::ShaderModel binary = detail::binary_for(C, model);
    d = detail::make_source_draw(ps, target, C.family(), C.name(), binary, counted_cost(C, binary).total_slots());
  });
  if (!found) detail::outside_space(combo.family(), combo.name());
  return d;
}

SourceDraw sky_draw(shading::ShaderModel model, const DrawTarget& target, const SkyParams& params) {
  SkyPixelShader ps{params};
  const shading::ShaderModel binary = detail::binary_for(SkyPixelShader::kCombo, model);
  return detail::make_source_draw(ps, target, "Sky_HDR", SkyPixelShader::kCombo.name(), binary, counted_cost(SkyPixelShader::kCombo, binary).total_slots());
}

}  // namespace luxel::frame
