#pragma once
// The scene-wide Source data glTF has no place for, in the glTF scene's extras.luxel (gltf.hpp
// lists the keys). Positions there are Source inches, +Z up, as the scene holds them.

#include "luxel/scenes/scene.hpp"
#include "tinygltf.hpp"

namespace luxel::scenes::gltf {

tinygltf::Value scene_extras(const Scene& scene);

/// Sets what `extras` (the glTF scene's extras) holds under "luxel"; ignores what it does not.
void read_scene_extras(const tinygltf::Value& extras, Scene& scene);

}  // namespace luxel::scenes::gltf
