#pragma once
// How Source's C++ turns a material's gamma-space color parameter ($color, $envmaptint,
// $reflecttint, $refracttint, $fogcolor) into the linear value of a pixel-shader constant
// (docs/fidelity.md#gamma-and-colors): mathlib's GammaToLinear, a 256-entry table of (i / 255)^2.2
// indexed by round(x * 255), which returns 0 below 0 and exactly 1.0 from 0.95 up (so 0.96 and 1.0 give
// the same constant). BaseVSShader converts only values <= 1; larger ones are taken as linear already
// (material_gamma_to_linear). CPU code, double-checked by the tests; not shader code.

#include <glm/vec3.hpp>

#include <cmath>

namespace luxel::shading::source {

/// mathlib GammaToLinear (color_conversion.cpp): the table with its 0.95 cut.
inline float mathlib_gamma_to_linear(float gamma) {
  if (!(gamma >= 0.0f)) return 0.0f;  // below 0 (and NaN)
  if (gamma >= 0.95f) return 1.0f;
  const long index = std::lround(gamma * 255.0f);
  return static_cast<float>(std::pow(index / 255.0, 2.2));
}

/// A material color constant, per channel: GammaToLinear when <= 1, else passed through.
inline glm::vec3 material_gamma_to_linear(const glm::vec3& gamma) {
  glm::vec3 r;
  for (int i = 0; i < 3; ++i) r[i] = gamma[i] > 1.0f ? gamma[i] : mathlib_gamma_to_linear(gamma[i]);
  return r;
}

}  // namespace luxel::shading::source
