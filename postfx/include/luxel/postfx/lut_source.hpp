#pragma once
// Where a color-correction LUT comes from, by the name a scene gives it (scenes::ColorCorrection::lut)
// or `luxel grade --lut` takes: "builtin:NAME" is a grade preset (grade.hpp: builtin:warm,
// builtin:cool, builtin:day-for-night, builtin:archival); a name ending in .raw is Source's own
// format (raw_lut_file.hpp); anything else is a LUT file read through OpenColorIO (lut_file.hpp).

#include "luxel/postfx/color_transform.hpp"
#include "luxel/postfx/lut.hpp"

#include <string>

namespace luxel::postfx {

/// The transform the name stands for. Throws std::invalid_argument "builtin:NAME: unknown
/// built-in LUT 'NAME' (known: ...)" for an unknown preset, and the readers' one-line
/// std::runtime_error for a bad file.
ColorTransform color_transform_named(const std::string& name);

/// The engine's LUT of that name: the transform sampled on the 32^3 lattice.
Lut resolve_lut(const std::string& name);

}  // namespace luxel::postfx
