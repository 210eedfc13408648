#pragma once
// Source's own color-correction files (docs/fidelity.md#color-correction): .raw, the engine's 32^3
// lattice as 32,768 color24 entries, 98,304 bytes, nothing else. The engine's loader is closed, so the
// order is an inference: red fastest, then green, then blue (index r + 32 g + 1024 b, the
// RGBX5551 key's bit order), bytes R, G, B. OpenColorIO does not read the format; it is read and
// written here byte for byte, and its exact transform is that lattice interpolated trilinearly in
// float by OpenColorIO (a Lut3DTransform built from the entries), like any 32^3 LUT file.

#include "luxel/postfx/color_transform.hpp"
#include "luxel/postfx/lut.hpp"

#include <string>

namespace luxel::postfx {

/// Bytes of a .raw file.
inline constexpr size_t kRawLutBytes = size_t(kLutEntries) * 3;

/// The file's lattice. Throws std::runtime_error "PATH: problem" for a missing file or one of
/// another size.
Lut read_raw_lut(const std::string& path);

/// The lattice as a transform named `name`, described as "Source .raw 32^3, trilinear".
ColorTransform raw_lut_transform(const Lut& lut, const std::string& name);

/// Writes the lattice as a .raw. Throws std::runtime_error "PATH: cannot write it".
void write_raw_lut(const Lut& lut, const std::string& path);

}  // namespace luxel::postfx
