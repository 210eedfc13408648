#pragma once
// Looks: a style over the whole finished frame, chosen by whoever renders it (FrameSettings::look,
// `luxel render --look`), on top of what the scene's own post passes do.
//
// archival: old footage, the look Day of Defeat made with film grain and desaturation
// (docs/fidelity.md#film-grain: its effect code is not in the SDK, so how the parts combine is
// luxel's):
//  - the grade builtin:archival (postfx/grade.hpp: saturation 0.1, faded blacks and whites, a
//    slight sepia) at full weight, in the color-correction pass, on top of the scene's nodes and
//    volumes: each of their LUTs is composed with the grade (postfx::compose) and keeps its
//    weight, and the grade alone takes the frame's own weight (1 minus their sum), so every pixel
//    is graded whatever the scene's weights are. While the scene's weights sum to less than 1
//    that takes one of the pass's four lookups, and the scene keeps its three heaviest;
//  - film grain (postfx/film_grain.hpp) at kArchivalGrainScale, seeded by FrameSettings::film_grain's
//    seed when it is set, else seed 0.

#include "luxel/postfx/film_grain.hpp"

#include <glm/vec4.hpp>

#include <map>
#include <optional>
#include <string>

namespace luxel::frame {

/// (int, not uint8_t: CLI11 prints the values in its messages, and a byte would print as a character.)
enum class Look { none, archival };

/// Every look by its name ("none", "archival").
const std::map<std::string, Look>& look_names();

/// The grade a look blends at full weight (a name postfx::resolve_lut knows), or nullopt.
std::optional<std::string> look_lut(Look look);

/// The archival look's film grain (the shader's noise scale): up to 0.12 of noise added and 0.85
/// to 1 of the frame kept, which at mid grey spreads the pixels about 1.3 times as far as the
/// default grain (FilmGrainOptions: 0.1 and 0.9 to 1) does.
inline constexpr glm::vec4 kArchivalGrainScale{0.12f, 0.12f, 0.12f, 0.85f};

/// The film grain a frame blends: without a look, `asked` (FrameSettings::film_grain); with the
/// archival look, `asked` (or the default options) at kArchivalGrainScale.
std::optional<postfx::FilmGrainOptions> look_film_grain(Look look, const std::optional<postfx::FilmGrainOptions>& asked);

}  // namespace luxel::frame
