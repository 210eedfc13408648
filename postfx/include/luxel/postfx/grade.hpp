#pragma once
// Grades: color transforms built from layered operators, the way a colorist builds a look in an
// image editor, then sampled on the engine's lattice (lut.hpp) as Source's color-correction
// authoring did (docs/fidelity.md#color-correction: gamma-space 8-bit colors in and out).
//
// Operators act on gamma-space RGB in [0, 1], in the grade's order, and each clamps its result to
// [0, 1] (as an 8-bit editor's layers do), so the next sees what a frame could hold:
//   Curves        a tone curve per channel after a master curve on all three; each a monotone
//                 cubic through control points (Fritsch-Carlson: no overshoot between points),
//                 flat beyond the first and last;
//   Levels        y = out_black + (out_white - out_black) * sat((x - in_black) / (in_white - in_black))^(1 / gamma);
//   ColorBalance  c + shadows (1 - L)^2 + midtones 2 L (1 - L) + highlights L^2: offsets weighted by
//                 the Bernstein basis of the luma L (the three weights sum to 1 for every L);
//   Saturation    L + amount (c - L): 0 grey, 1 unchanged, above 1 more saturated.
// L is the gamma-space luma with the weights (0.299, 0.587, 0.114), the grey Source's shaders use
// for saturation (docs/fidelity.md#gamma-and-colors).
//
// Presets (grade_preset): "day-for-night" (night shot by day: desaturated, blue, dark),
// "archival" (desaturated archival-footage look: faded blacks and whites, a slight sepia),
// "warm" and "cool" (the built-in courtyard's two color-correction nodes).

#include "luxel/postfx/color_transform.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace luxel::postfx {

/// A curve through control points (x, y), x strictly increasing, all in [0, 1]; no points is the
/// identity. At least two points otherwise.
struct Curve {
  std::vector<glm::vec2> points;
  float operator()(float x) const;
};

struct Curves {
  Curve master, red, green, blue;
};

struct Levels {
  float in_black = 0.0f, in_white = 1.0f;  ///< in_black < in_white
  float gamma = 1.0f;                      ///< > 0; above 1 brightens the midtones
  float out_black = 0.0f, out_white = 1.0f;
};

struct ColorBalance {
  glm::vec3 shadows{0.0f}, midtones{0.0f}, highlights{0.0f};
};

struct Saturation {
  float amount = 1.0f;  ///< >= 0
};

using GradeOperator = std::variant<Curves, Levels, ColorBalance, Saturation>;

struct Grade {
  std::vector<GradeOperator> operators;  ///< applied first to last
};

/// The gamma-space luma (0.299, 0.587, 0.114).
float grade_luma(glm::vec3 c);

/// One color through the grade (one that grade_transform accepts).
glm::vec3 apply_grade(const Grade& grade, glm::vec3 color);

/// The grade as a transform named `name`. Throws std::invalid_argument, naming the operator and
/// the problem, for parameters outside the ranges above or not finite.
ColorTransform grade_transform(Grade grade, std::string name);

/// The preset's grade, or nullopt for an unknown name.
std::optional<Grade> grade_preset(std::string_view name);
/// The preset names, in a fixed order.
const std::vector<std::string>& grade_preset_names();

}  // namespace luxel::postfx
