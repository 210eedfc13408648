// Looks over the whole frame (look.hpp).

#include "luxel/frame/look.hpp"

namespace luxel::frame {

const std::map<std::string, Look>& look_names() {
  static const std::map<std::string, Look> names{{"none", Look::none}, {"archival", Look::archival}};
  return names;
}

std::optional<std::string> look_lut(Look look) {
  if (look == Look::archival) return "builtin:archival";
  return std::nullopt;
}

std::optional<postfx::FilmGrainOptions> look_film_grain(Look look, const std::optional<postfx::FilmGrainOptions>& asked) {
  if (look != Look::archival) return asked;
  postfx::FilmGrainOptions grain = asked.value_or(postfx::FilmGrainOptions{});
  grain.noise_scale = kArchivalGrainScale;
  return grain;
}

}  // namespace luxel::frame
