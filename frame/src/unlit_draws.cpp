// UnlitGeneric and Sky_HDR draws (source_draws.hpp).

#include "source_draws.hpp"

namespace luxel::frame {

namespace {

using namespace shading::source;

/// Base texture x $color, with or without vertex color and an env map (each mask); unfogged, each
/// model's range fog or the height fog of the view through water. No detail texture yet (the
/// adapter does not feed its coordinate).
constexpr auto kAll = [] {
  detail::ComboList<UnlitCombo, 64> l;
  for (bool envmap : {false, true})
    for (UnlitEnvmapMask mask : {UnlitEnvmapMask::none, UnlitEnvmapMask::base_alpha_inverted, UnlitEnvmapMask::texture})
      for (bool vertex_color : {false, true})
        for (Fog fog : {Fog::none, Fog::range, Fog::vertex_range, Fog::height}) {
          const UnlitCombo c{UnlitDetail::none, envmap, mask, vertex_color, false, fog};
          if (c.valid()) l.add(c);
        }
  return l;
}();
constexpr auto kSpace = detail::compact<kAll>();

}  // namespace

SourceDraw unlit_draw(const UnlitCombo& combo, shading::ShaderModel model, const DrawTarget& target,
                      const UnlitGenericParams& params, const glm::vec3& eye) {
  SourceDraw d;
  const bool found = detail::with_combo<kSpace>(combo, [&]<UnlitCombo C>() {
    UnlitPixelShader<C> ps{params, eye};
    d = detail::make_source_draw(ps, target, "UnlitGeneric", C.name(), measure_unlit_generic<C>(model).total_slots());
  });
  if (!found) detail::outside_space("UnlitGeneric", combo.name());
  return d;
}

SourceDraw sky_draw(shading::ShaderModel model, const DrawTarget& target, const SkyParams& params) {
  SkyPixelShader ps{params};
  return detail::make_source_draw(ps, target, "Sky_HDR", SkyPixelShader::kCombo.name(),
                                  measure_sky<SkyPixelShader::kCombo>(model).total_slots());
}

}  // namespace luxel::frame
