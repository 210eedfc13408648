#pragma once
// The one place a scene argument (`--scene` of `luxel render`, `export`, `info`) becomes a Scene.

#include "luxel/scenes/builtin.hpp"
#include "luxel/scenes/gltf.hpp"
#include "luxel/scenes/scene.hpp"

#include <stdexcept>
#include <string>

namespace luxel::scenes {

/// A scene argument that names no scene (an unknown built-in, a file that is not glTF by its
/// name): one line naming the argument. Problems inside a file are GltfError.
struct SceneArgumentError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// Whether `path` ends in `extension` (".glb"), in any letter case.
bool has_extension(const std::string& path, const std::string& extension);

/// `arg` is a .gltf or .glb path (case-insensitive extension), read with `gltf`, or builtin:NAME,
/// built with `builtin`. Throws SceneArgumentError or GltfError.
Scene load_scene(const std::string& arg, const GltfImportOptions& gltf = {}, const BuiltinOptions& builtin = {});

}  // namespace luxel::scenes
