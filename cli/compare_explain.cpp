// luxel compare --explain (compare_explain.hpp).

#include "compare_explain.hpp"

#include <cstring>
#include <iterator>
#include <vector>

namespace luxel::cli {

namespace {

constexpr Cause kDispatchRules[] = {Cause::skin_shader, Cause::light_count, Cause::water_blur};

bool same_rgb(const rasterizer::Image& a, const rasterizer::Image& b, size_t pixel) {
  return std::memcmp(&a.rgba[4 * pixel], &b.rgba[4 * pixel], 3) == 0;
}

/// `settings` drawn as card `card` with the dispatch rules `taken` (a set of kDispatchRules
/// indices, bit i for kDispatchRules[i]) taken from card `rules`.
frame::FrameSettings with_rules_of(frame::FrameSettings settings, shading::ShaderModel card, shading::ShaderModel rules,
                                   unsigned taken) {
  settings.model = card;
  frame::FrameSettings::DispatchCards& d = settings.dispatch_cards;
  if (taken & 1u) d.model_shader = rules;
  if (taken & 2u) d.light_count = rules;
  if (taken & 4u) d.water_blur = rules;
  return settings;
}

/// Whether dispatch rule kDispatchRules[r] can change anything in `scene` with `settings`: a
/// $phong model material, more than two local lights, water that blurs.
bool can_matter(size_t r, const scenes::Scene& scene, const frame::FrameSettings& settings) {
  for (const scenes::Material& m : scene.materials) {
    if (r == 0 && m.family == scenes::ShaderFamily::vertexlit_generic && m.phong) return true;
    if (r == 2 && m.family == scenes::ShaderFamily::water && m.water_blur_refract) return true;
  }
  return r == 1 && settings.local_lights > 2;
}

}  // namespace

std::string_view cause_name(Cause c) {
  switch (c) {
    case Cause::fog_per_vertex: return "fog_per_vertex";
    case Cause::skin_shader: return "skin_shader";
    case Cause::light_count: return "light_count";
    case Cause::water_blur: return "water_blur";
    case Cause::card_binary: return "card_binary";
    case Cause::several: return "several";
    case Cause::unexplained: return "unexplained";
  }
  return "?";
}

std::array<uint8_t, 3> cause_colour(Cause c) {
  switch (c) {
    case Cause::fog_per_vertex: return {70, 130, 255};
    case Cause::skin_shader: return {255, 60, 60};
    case Cause::light_count: return {255, 200, 0};
    case Cause::water_blur: return {0, 220, 220};
    case Cause::card_binary: return {60, 210, 60};
    case Cause::several: return {220, 0, 220};
    case Cause::unexplained: return {255, 255, 255};
  }
  return {0, 0, 0};
}

std::optional<Explanation> explain_pair(const rasterizer::Image& image_lo, const rasterizer::Image& image_hi,
                                        shading::ShaderModel lo, shading::ShaderModel hi, const scenes::Scene& scene,
                                        const frame::FrameSettings& settings, const FrameDrawer& draw) {
  Explanation e;
  e.map = rasterizer::Image(image_lo.width, image_lo.height);
  const size_t pixels = size_t(image_lo.width) * size_t(image_lo.height);
  for (size_t p = 0; p < pixels; ++p) {
    e.map.rgba[4 * p + 3] = 255;
    if (!same_rgb(image_lo, image_hi, p)) ++e.differing;
  }
  if (e.differing == 0) return e;

  // The pair without fog: the fog's rule made equal.
  scenes::Scene fogless = scene;
  fogless.fog = scenes::Fog{};
  frame::FrameSettings lo_settings = settings, hi_settings = settings;
  lo_settings.model = lo;
  hi_settings.model = hi;
  const std::optional<rasterizer::Image> lo0 = draw(fogless, lo_settings);
  if (!lo0) return std::nullopt;
  const std::optional<rasterizer::Image> hi0 = draw(fogless, hi_settings);
  if (!hi0) return std::nullopt;
  // `hi`'s card with `lo`'s dispatch: what is left against lo0 is the binary's own.
  constexpr unsigned kAll = 7;
  const std::optional<rasterizer::Image> base = draw(fogless, with_rules_of(settings, hi, lo, kAll));
  if (!base) return std::nullopt;
  // Per dispatch rule that can matter: `hi`'s choice for it alone on `base` (only it differs),
  // and `lo`'s choice for it alone on hi0 (it alone made equal). A rule is involved where either
  // changes the pixel: the second shows what the rule does only together with another (Phong
  // from the third and fourth light needs both the skin shader and the light count).
  std::vector<std::optional<rasterizer::Image>> only(std::size(kDispatchRules)), all_but(std::size(kDispatchRules));
  for (size_t r = 0; r < std::size(kDispatchRules); ++r) {
    if (!can_matter(r, scene, settings)) continue;
    only[r] = draw(fogless, with_rules_of(settings, hi, lo, kAll & ~(1u << r)));
    if (!only[r]) return std::nullopt;
    all_but[r] = draw(fogless, with_rules_of(settings, hi, lo, 1u << r));
    if (!all_but[r]) return std::nullopt;
  }

  for (size_t p = 0; p < pixels; ++p) {
    if (same_rgb(image_lo, image_hi, p)) continue;
    std::vector<Cause> causes;
    if (same_rgb(*lo0, *hi0, p)) {
      causes.push_back(Cause::fog_per_vertex);
    } else {
      if (!same_rgb(*lo0, *base, p)) causes.push_back(Cause::card_binary);
      bool dispatch_shown = false;
      for (size_t r = 0; r < only.size(); ++r)
        if (only[r] && (!same_rgb(*base, *only[r], p) || !same_rgb(*hi0, *all_but[r], p)))
          causes.push_back(kDispatchRules[r]), dispatch_shown = true;
      // What the dispatch changes there that no rule shows is left unexplained.
      if (!dispatch_shown && !same_rgb(*base, *hi0, p)) causes.clear();
    }
    const Cause cause = causes.empty() ? Cause::unexplained : causes.size() == 1 ? causes[0] : Cause::several;
    ++e.pixels[size_t(cause)];
    for (Cause c : causes) ++e.involved[size_t(c)];
    std::memcpy(&e.map.rgba[4 * p], cause_colour(cause).data(), 3);
  }
  return e;
}

}  // namespace luxel::cli
