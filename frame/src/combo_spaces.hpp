#pragma once
// Private: the combos the frame can choose per Source family (its "combo space"): every
// combination of the material switches the frame reads, for the fog types a scene can ask, that
// the SDK's rules allow on some pixel model. The family's draws (source_draws.hpp) compile a
// pixel shader for each; its slot counts (combo_slots.hpp) count each apart.

#include "luxel/shading/shader_model.hpp"
#include "luxel/shading/source/lightmapped_generic.hpp"
#include "luxel/shading/source/unlit_generic.hpp"
#include "luxel/shading/source/vertexlit_generic.hpp"
#include "luxel/shading/source/water.hpp"

#include <array>
#include <cstddef>
#include <utility>

namespace luxel::frame::detail {

/// A combo space being built at compile time: room for Cap, `count` used.
template <class Combo, size_t Cap>
struct ComboList {
  std::array<Combo, Cap> items{};
  size_t count = 0;
  constexpr void add(const Combo& c) { items[count++] = c; }
};

/// The used part of a ComboList, as an array of exactly that size.
template <auto kList>
constexpr auto compact() {
  std::array<typename decltype(kList.items)::value_type, kList.count> out{};
  for (size_t i = 0; i < kList.count; ++i) out[i] = kList.items[i];
  return out;
}

/// Calls fn.template operator()<C>() for the C of kSpace equal to `combo`; false when none is.
template <auto kSpace, class Combo, class Fn>
bool with_combo(const Combo& combo, Fn&& fn) {
  return [&]<size_t... I>(std::index_sequence<I...>) {
    return ((kSpace[I] == combo ? (fn.template operator()<kSpace[I]>(), true) : false) || ...);
  }(std::make_index_sequence<kSpace.size()>());
}

/// The index of `combo` in kSpace, or -1.
template <auto kSpace, class Combo>
constexpr int index_in(const Combo& combo) {
  for (size_t i = 0; i < kSpace.size(); ++i)
    if (kSpace[i] == combo) return int(i);
  return -1;
}

using namespace shading::source;

/// Every valid combination of bump, env map, mask and path, unfogged, with the range fog of each
/// model and with the height fog of the view through water (the refraction view).
inline constexpr auto kLightmappedAll = [] {
  ComboList<LightmappedCombo, 256> l;
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
inline constexpr auto kLightmappedSpace = compact<kLightmappedAll>();

/// The models drawn lit per pixel: the bumped path and the skin shader (without a bump map or
/// Phong a model is lit per vertex, kUnlitSpace's DIFFUSELIGHTING combos). Two local lights or
/// none (a model gets its most significant lights, the rest folded into its cube), or four
/// (FrameSettings::local_lights on ps_2_b and ps_3_0, attenuated per vertex); every valid choice
/// of bump, Phong (with bump: the skin shader's full path; without: FASTPATH_NOBUMP), rim and
/// Half-Lambert; attenuation per vertex (the SDK's, the default) or per pixel (luxel's option);
/// the ambient cube (SH9 is a ps_3_0 option the frame does not take); unfogged, each model's range
/// fog or the height fog of the view through water; the normalization cube map exactly on ps_2_0.
/// Without lights, Half-Lambert and attenuation change nothing, so only one of each is compiled.
/// Each with and without an env map (the bumped path's masked by the normal map's alpha or not).
/// `envmap` selects the half: the draws of each compile in their own file.
template <class Keep>
constexpr auto vertexlit_combos(Keep keep) {
  ComboList<VertexLitCombo, 1024> l;
  for (int lights : {0, 2, 4})
    for (bool bump : {false, true})
      for (bool phong : {false, true})
        for (bool rim : {false, true})
          for (bool half_lambert : {false, true})
            for (bool pixel_attenuation : {false, true})
              for (Fog fog : {Fog::none, Fog::range, Fog::vertex_range, Fog::height})
                for (bool cube : {false, true})
                  for (auto [envmap, normal_alpha] : {std::pair{false, false}, std::pair{true, false}, std::pair{true, true}}) {
                    if (lights == 0 && !(half_lambert && pixel_attenuation)) continue;
                    if (!bump && !phong) continue;
                    const VertexLitCombo c{lights, bump, phong, rim, half_lambert, pixel_attenuation, false, fog, cube, envmap,
                                           normal_alpha};
                    bool on_some_model = false;
                    for (shading::ShaderModel m : kPixelModels) on_some_model = on_some_model || c.valid(m);
                    if (on_some_model && keep(c)) l.add(c);
                  }
  return l;
}
inline constexpr auto kVertexLitAll = vertexlit_combos([](const VertexLitCombo&) { return true; });
inline constexpr auto kVertexLitSpace = compact<kVertexLitAll>();
inline constexpr auto kVertexLitPlainAll = vertexlit_combos([](const VertexLitCombo& c) { return !c.envmap; });
inline constexpr auto kVertexLitPlainSpace = compact<kVertexLitPlainAll>();
inline constexpr auto kVertexLitEnvmapAll = vertexlit_combos([](const VertexLitCombo& c) { return c.envmap; });
inline constexpr auto kVertexLitEnvmapSpace = compact<kVertexLitEnvmapAll>();

/// Base texture x $color, with or without vertex color and an env map (each mask), and
/// VertexLitGeneric without a bump map (DIFFUSELIGHTING: x the vertex shader's lighting), with or
/// without an env map; unfogged, each model's range fog or the height fog of the view through
/// water. No detail texture yet (the adapter does not feed its coordinate).
inline constexpr auto kUnlitAll = [] {
  ComboList<UnlitCombo, 64> l;
  for (bool envmap : {false, true})
    for (UnlitEnvmapMask mask : {UnlitEnvmapMask::none, UnlitEnvmapMask::base_alpha_inverted, UnlitEnvmapMask::texture})
      for (bool vertex_color : {false, true})
        for (bool diffuse_lighting : {false, true})
          for (Fog fog : {Fog::none, Fog::range, Fog::vertex_range, Fog::height}) {
            const UnlitCombo c{UnlitDetail::none, envmap, mask, vertex_color, diffuse_lighting, fog};
            if (c.valid()) l.add(c);
          }
  return l;
}();
inline constexpr auto kUnlitSpace = compact<kUnlitAll>();

/// Seen from above (the frame draws no water from below, water_passes.hpp): reflection,
/// refraction or both, with or without MULTITEXTURE, with or without BLURRY ($blurrefract, where
/// it refracts); unfogged, each model's range fog or height fog.
inline constexpr auto kWaterAll = [] {
  ComboList<WaterCombo, 64> l;
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
inline constexpr auto kWaterSpace = compact<kWaterAll>();

}  // namespace luxel::frame::detail
