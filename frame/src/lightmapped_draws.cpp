// LightmappedGeneric draws (source_draws.hpp): the frame's combo space of world surfaces.

#include "source_draws.hpp"

namespace luxel::frame {

namespace {

using namespace shading::source;

/// Every valid combination of bump, env map, mask and path, unfogged, with the range fog of each
/// model and with the height fog of the view through water (the refraction view).
constexpr auto kAll = [] {
  detail::ComboList<LightmappedCombo, 256> l;
  for (bool bump : {false, true})
    for (bool envmap : {false, true})
      for (EnvmapMask mask : {EnvmapMask::none, EnvmapMask::base_alpha_inverted, EnvmapMask::normal_alpha, EnvmapMask::texture})
        for (EnvmapPath path : {EnvmapPath::fast, EnvmapPath::fast_contrast, EnvmapPath::full})
          for (Fog fog : {Fog::none, Fog::range, Fog::vertex_range, Fog::height}) {
            const LightmappedCombo c{bump, envmap, mask, path, fog};
            if (c.valid()) l.add(c);
          }
  return l;
}();
constexpr auto kSpace = detail::compact<kAll>();

}  // namespace

SourceDraw lightmapped_draw(const LightmappedCombo& combo, shading::ShaderModel model, const DrawTarget& target,
                            const LightmappedGenericParams& params, const LightmapPage& page, const glm::vec3& eye) {
  SourceDraw d;
  const bool found = detail::with_combo<kSpace>(combo, [&]<LightmappedCombo C>() {
    LightmappedPixelShader<C> ps{params, page, eye};
    d = detail::make_source_draw(ps, target, "LightmappedGeneric", C.name(),
                                 measure_lightmapped_generic<C>(model).total_slots());
  });
  if (!found) detail::outside_space("LightmappedGeneric", combo.name());
  return d;
}

}  // namespace luxel::frame
