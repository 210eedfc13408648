#pragma once
// The registry of the Source shader combos: for each family, every static combo the SDK builds a
// binary of, over the switches luxel models, and each one's counted cost. Everything that lists,
// draws, counts or times a combo reads it: the frame draws a subset of a family's space (what its
// materials can ask for), `luxel cost` and the report list the catalog built from it
// (catalog.hpp), tests and benchmarks walk it. A combo appears here once.
//
// A space is generated, not written out: every combination of a family's switches that its
// valid() (the SKIP lines of the SDK's .fxc and the helper's choices, docs/fidelity.md) allows on
// some pixel model its source is built for. Fog is a switch like the others: unfogged, range fog
// per pixel (ps_2_b and up), per vertex (ps_2_0) and the height fog of the view through water.
//
// Counting runs a combo once on the Counted lane and keeps the answer (per combo and binary
// model); that code lives in registry_counts.cpp, compiled without optimization: it runs once per
// combo and model, and optimized it cost more build time than the draws.

#include "luxel/shading/cost.hpp"
#include "luxel/shading/shader_model.hpp"
#include "luxel/shading/source/color_correction.hpp"
#include "luxel/shading/source/engine_post.hpp"
#include "luxel/shading/source/lightmapped_generic.hpp"
#include "luxel/shading/source/luminance_range.hpp"
#include "luxel/shading/source/sky.hpp"
#include "luxel/shading/source/unlit_generic.hpp"
#include "luxel/shading/source/vertexlit_generic.hpp"
#include "luxel/shading/source/vertexlit_vertex_shader.hpp"
#include "luxel/shading/source/water.hpp"

#include <array>
#include <cstddef>
#include <utility>

namespace luxel::shading::source {

// ---- Spaces as compile-time arrays ------------------------------------------------------------

/// A space being built at compile time: room for Cap, `count` used.
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

/// The combos of kSpace that kKeep (a captureless predicate) keeps, in kSpace's order.
template <auto kSpace, auto kKeep>
constexpr auto subset() {
  constexpr size_t kCount = [] {
    size_t n = 0;
    for (const auto& c : kSpace) n += kKeep(c) ? 1 : 0;
    return n;
  }();
  std::array<typename decltype(kSpace)::value_type, kCount> out{};
  size_t i = 0;
  for (const auto& c : kSpace)
    if (kKeep(c)) out[i++] = c;
  return out;
}

/// Calls fn.template operator()<C>() for every C of kSpace, in order.
template <auto kSpace, class Fn>
void for_each_combo(Fn&& fn) {
  [&]<size_t... I>(std::index_sequence<I...>) {
    (fn.template operator()<kSpace[I]>(), ...);
  }(std::make_index_sequence<kSpace.size()>());
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

/// Whether combo c is allowed on some model its source is built for.
template <class Combo>
constexpr bool on_some_model(const Combo& c) {
  for (ShaderModel card : kPixelModels) {
    const std::optional<ShaderModel> binary = c.builds().binary_for(card);
    if (binary && c.valid(*binary)) return true;
  }
  return false;
}

inline constexpr Fog kFogs[] = {Fog::none, Fog::range, Fog::vertex_range, Fog::height};

// ---- The families' spaces ---------------------------------------------------------------------

/// LightmappedGeneric (lightmappedgeneric_ps2x.fxc): bump, env map, its mask and path, fog.
inline constexpr auto kLightmappedSpace = compact<[] {
  ComboList<LightmappedCombo, 256> l;
  for (bool bump : {false, true})
    for (bool envmap : {false, true})
      for (EnvmapMask mask : {EnvmapMask::none, EnvmapMask::base_alpha_inverted, EnvmapMask::normal_alpha, EnvmapMask::texture})
        for (EnvmapPath path : {EnvmapPath::fast, EnvmapPath::fast_contrast, EnvmapPath::full})
          for (Fog fog : kFogs) {
            const LightmappedCombo c{bump, envmap, mask, path, fog};
            if (on_some_model(c)) l.add(c);
          }
  return l;
}()>();

/// VertexLitGeneric lit per pixel: the bumped path (vertexlit_and_unlit_generic_bump_ps2x.fxc)
/// and the skin shader (skin_ps20b.fxc, Phong, with a bump map or FASTPATH_NOBUMP). Without a bump
/// map and without Phong the SDK lights a model per vertex: kUnlitSpace's DIFFUSELIGHTING combos.
/// Local lights: none, two (ps_2_0's most), four (ps_2_b and up); attenuation per vertex (the
/// SDK's) or per pixel (luxel's option, measured in the report); rim and Half-Lambert where the
/// rules allow; the normalization cube map exactly on ps_2_0; env map, masked by the normal map's
/// alpha or not. Without lights Half-Lambert and attenuation change nothing: one of each.
/// The SH9 ambient switch (VertexLitCombo::sh9_ambient) is luxel's measurement of another basis,
/// not a binary: it is counted in the report's lighting-bases table, not listed here.
inline constexpr auto kVertexLitSpace = compact<[] {
  ComboList<VertexLitCombo, 1024> l;
  for (int lights : {0, 2, 4})
    for (bool bump : {false, true})
      for (bool phong : {false, true})
        for (bool rim : {false, true})
          for (bool half_lambert : {false, true})
            for (bool pixel_attenuation : {false, true})
              for (Fog fog : kFogs)
                for (bool cube : {false, true})
                  for (auto [envmap, normal_alpha] : {std::pair{false, false}, std::pair{true, false}, std::pair{true, true}}) {
                    if (lights == 0 && !(half_lambert && pixel_attenuation)) continue;
                    if (!bump && !phong) continue;
                    const VertexLitCombo c{lights, bump, phong, rim, half_lambert, pixel_attenuation, false, fog, cube, envmap,
                                           normal_alpha};
                    if (on_some_model(c)) l.add(c);
                  }
  return l;
}()>();

/// The per-vertex VertexLitGeneric vertex shader (vertexlit_and_unlit_generic_vs20.fxc) on
/// vs_2_0 / vs_3_0: local lights 0..4, Half-Lambert or not.
inline constexpr auto kVertexLitVsSpace = compact<[] {
  ComboList<VertexLitVsCombo, 16> l;
  for (int lights = 0; lights <= 4; ++lights)
    for (bool half_lambert : {true, false}) {
      const VertexLitVsCombo c{lights, half_lambert};
      if (lights == 0 && !half_lambert) continue;  // nothing to light: Half-Lambert changes nothing
      if (c.valid(ShaderModel::vs_2_0) || c.valid(ShaderModel::vs_3_0)) l.add(c);
    }
  return l;
}()>();

/// UnlitGeneric and non-bumped VertexLitGeneric (vertexlit_and_unlit_generic_ps2x.fxc): detail
/// texture (mod2x, additive), env map and its mask, vertex color, DIFFUSELIGHTING, fog.
inline constexpr auto kUnlitSpace = compact<[] {
  ComboList<UnlitCombo, 256> l;
  for (UnlitDetail detail : {UnlitDetail::none, UnlitDetail::mod2x, UnlitDetail::additive})
    for (bool envmap : {false, true})
      for (UnlitEnvmapMask mask : {UnlitEnvmapMask::none, UnlitEnvmapMask::base_alpha_inverted, UnlitEnvmapMask::texture})
        for (bool vertex_color : {false, true})
          for (bool diffuse_lighting : {false, true})
            for (Fog fog : kFogs) {
              const UnlitCombo c{detail, envmap, mask, vertex_color, diffuse_lighting, fog};
              if (on_some_model(c)) l.add(c);
            }
  return l;
}()>();

/// Water seen from above (luxel draws no water from below): reflection, refraction or both,
/// MULTITEXTURE, BLURRY ($blurrefract, where it refracts), fog.
inline constexpr auto kWaterSpace = compact<[] {
  ComboList<WaterCombo, 64> l;
  for (auto [reflect, refract] : {std::pair{true, true}, std::pair{true, false}, std::pair{false, true}})
    for (bool multitexture : {false, true})
      for (bool blurry : {false, true})
        for (Fog fog : kFogs) {
          const WaterCombo c{reflect, refract, true, multitexture, blurry, fog};
          if (on_some_model(c)) l.add(c);
        }
  return l;
}()>();

/// Sky_HDR: the 16-bit sky and the compressed RGBS one.
inline constexpr std::array kSkySpace{SkyCombo{SkyTexture::hdr16}, SkyCombo{SkyTexture::rgbs_compressed}};

/// The luminance range test of the exposure histogram: alpha test or texkill.
inline constexpr std::array kLuminanceRangeSpace{LuminanceRangeCombo{LuminanceReject::alpha_test},
                                                 LuminanceRangeCombo{LuminanceReject::texkill}};

/// Color correction and the engine's post shader: 1 to 4 lookup tables blended.
inline constexpr auto kColorCorrectionSpace = [] {
  std::array<ColorCorrectionCombo, kMaxColorCorrectionLuts> s{};
  for (int i = 0; i < kMaxColorCorrectionLuts; ++i) s[size_t(i)] = {i + 1};
  return s;
}();
inline constexpr auto kEnginePostSpace = [] {
  std::array<EnginePostCombo, kMaxColorCorrectionLuts> s{};
  for (int i = 0; i < kMaxColorCorrectionLuts; ++i) s[size_t(i)] = {i + 1};
  return s;
}();

/// vertex_lighting_at (vertexlit_vertex_shader.hpp) of the combo of kVertexLitVsSpace equal to
/// `combo`; null when none is.
inline VertexLightingFn vertex_lighting_fn(const VertexLitVsCombo& combo) {
  VertexLightingFn fn = nullptr;
  with_combo<kVertexLitVsSpace>(combo, [&]<VertexLitVsCombo C>() { fn = &vertex_lighting_at<C>; });
  return fn;
}

// ---- Counted cost -----------------------------------------------------------------------------

/// The counted cost of a combo's binary of model `binary` (std::logic_error for a combo outside
/// its family's space). Which binary a card runs: binaries.hpp.
Cost counted_cost(const LightmappedCombo& combo, ShaderModel binary);
Cost counted_cost(const VertexLitCombo& combo, ShaderModel binary);
Cost counted_cost(const VertexLitVsCombo& combo, ShaderModel binary);
Cost counted_cost(const UnlitCombo& combo, ShaderModel binary);
Cost counted_cost(const WaterCombo& combo, ShaderModel binary);
Cost counted_cost(const SkyCombo& combo, ShaderModel binary);
Cost counted_cost(const LuminanceRangeCombo& combo, ShaderModel binary);
Cost counted_cost(const ColorCorrectionCombo& combo, ShaderModel binary);
Cost counted_cost(const EnginePostCombo& combo, ShaderModel binary);

/// Whether a VertexLitGeneric combo has a binary of model `binary`: allowed by the rules and
/// within the model's limits (vertexlit_compiles); false outside kVertexLitSpace.
bool vertexlit_fits(const VertexLitCombo& combo, ShaderModel binary);

}  // namespace luxel::shading::source
