#pragma once
// A color transform on gamma-space RGB, evaluated in float: what the engine's 32^3 LUT is sampled
// from (lut.hpp) and what `luxel grade --exact` applies at full precision: a grade built from
// layered operators (grade.hpp), a LUT file read through OpenColorIO (lut_file.hpp) or a Source
// .raw (raw_lut_file.hpp); lut_source.hpp picks one by name.
//
// Colors are the gamma-space values of the 8-bit frame over 255 (LUTs are authored on gamma-space
// 8-bit colors, docs/fidelity.md#color-correction), so a file's transform applies to them as is.

#include <glm/vec3.hpp>

#include <functional>
#include <span>
#include <string>

namespace luxel::postfx {

struct ColorTransform {
  std::string name;         ///< "builtin:warm", or the LUT file's path
  std::string description;  ///< one line on what it is: "3D LUT 33^3, tetrahedral", "grade: levels, saturation"
  /// Transforms the colors in place. Pure and safe to call from several threads at once.
  std::function<void(std::span<glm::vec3> colors)> apply;
};

}  // namespace luxel::postfx
