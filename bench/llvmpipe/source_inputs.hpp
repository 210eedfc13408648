#pragma once
// W4's input: a glTF file luxel exported, read by luxel's importer, with the bake `luxel bake`
// wrote beside it (PATH without its extension + .bake) attached by luxel's own bake storage: the
// lightmaps, the irradiance volume and the cube maps luxel's renderer would read.

#include "luxel/scenes/scene.hpp"

#include <string>

namespace luxel::llvmpipe {

/// Throws Skipped when the file or its bake is missing, or the bake is for other inputs.
scenes::Scene load_baked_scene(const std::string& path, int camera);

}  // namespace luxel::llvmpipe
