// VertexLitGeneric draws (source_draws.hpp): the frame's combo space of models, per pixel.

#include "source_draws.hpp"

namespace luxel::frame {

namespace {

using namespace shading::source;

/// Two local lights or none (a model gets the two most significant, the rest folded into its
/// cube); every valid choice of bump, Phong, exponent texture, rim and Half-Lambert; attenuation
/// per pixel (luxel's default) or per vertex (what ps_2_0's budget forces); the ambient cube (SH9
/// is a ps_3_0 option the frame does not take); unfogged, each model's range fog or the height fog
/// of the view through water; the normalization cube map exactly on ps_2_0. Without lights, Half-Lambert and attenuation change
/// nothing, so only one of each is compiled.
constexpr auto kAll = [] {
  detail::ComboList<VertexLitCombo, 1024> l;
  for (int lights : {0, 2})
    for (bool bump : {false, true})
      for (bool phong : {false, true})
        for (bool exponent_texture : {false, true})
          for (bool rim : {false, true})
            for (bool half_lambert : {false, true})
              for (bool pixel_attenuation : {false, true})
                for (Fog fog : {Fog::none, Fog::range, Fog::vertex_range, Fog::height})
                  for (bool cube : {false, true}) {
                    if (lights == 0 && !(half_lambert && pixel_attenuation)) continue;
                    const VertexLitCombo c{lights, bump, phong, exponent_texture, rim, half_lambert, pixel_attenuation,
                                           false, fog, cube};
                    bool on_some_model = false;
                    for (shading::ShaderModel m : kPixelModels) on_some_model = on_some_model || c.valid(m);
                    if (on_some_model) l.add(c);
                  }
  return l;
}();
constexpr auto kSpace = detail::compact<kAll>();

bool compiles(const VertexLitCombo& combo, shading::ShaderModel model) {
  bool fits = false;
  detail::with_combo<kSpace>(combo, [&]<VertexLitCombo C>() { fits = vertexlit_compiles<C>(model); });
  return fits;
}

}  // namespace

std::optional<VertexLitCombo> fitting_vertexlit_combo(VertexLitCombo wanted, shading::ShaderModel model) {
  if (wanted.lights == 0) wanted.half_lambert = wanted.pixel_attenuation = true;
  if (compiles(wanted, model)) return wanted;
  wanted.pixel_attenuation = false;
  if (wanted.lights > 0 && compiles(wanted, model)) return wanted;
  return std::nullopt;
}

SourceDraw vertexlit_draw(const VertexLitCombo& combo, shading::ShaderModel model, const DrawTarget& target,
                          const VertexLitParams& params) {
  SourceDraw d;
  const bool found = detail::with_combo<kSpace>(combo, [&]<VertexLitCombo C>() {
    VertexLitPixelShader<C> ps{params};
    d = detail::make_source_draw(ps, target, "VertexLitGeneric", C.name(),
                                 measure_vertexlit_generic<C>(model).total_slots());
  });
  if (!found) detail::outside_space("VertexLitGeneric", combo.name());
  return d;
}

}  // namespace luxel::frame
