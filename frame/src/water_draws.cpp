// Water draws (source_draws.hpp): the frame's combo space of water surfaces.

#include "source_draws.hpp"

namespace luxel::frame {

namespace {

using namespace shading::source;

/// Seen from above (the frame draws no water from below, water_passes.hpp): reflection,
/// refraction or both, with or without MULTITEXTURE, with or without BLURRY ($blurrefract, where
/// it refracts); unfogged, each model's range fog or height fog.
constexpr auto kAll = [] {
  detail::ComboList<WaterCombo, 64> l;
  for (auto [reflect, refract] : {std::pair{true, true}, std::pair{true, false}, std::pair{false, true}})
    for (bool multitexture : {false, true})
      for (bool blurry : {false, true})
        for (Fog fog : {Fog::none, Fog::range, Fog::vertex_range, Fog::height}) {
          const WaterCombo c{reflect, refract, true, multitexture, blurry, fog};
          bool on_some_model = false;
          for (shading::ShaderModel m : kPixelModels) on_some_model = on_some_model || c.valid(m);
          if (on_some_model) l.add(c);
        }
  return l;
}();
constexpr auto kSpace = detail::compact<kAll>();

}  // namespace

SourceDraw water_draw(const WaterCombo& combo, shading::ShaderModel model, const DrawTarget& target,
                      const WaterParams& params, const WaterVertexConstants& constants, const glm::vec3& eye) {
  SourceDraw d;
  const bool found = detail::with_combo<kSpace>(combo, [&]<WaterCombo C>() {
    WaterPixelShader<C> ps{params, constants, eye};
    d = detail::make_source_draw(ps, target, "Water", C.name(), measure_water<C>(model).total_slots());
  });
  if (!found) detail::outside_space("Water", combo.name());
  return d;
}

}  // namespace luxel::frame
