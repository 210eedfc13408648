#pragma once
// The scene-wide Source data glTF has no place for, in the glTF scene's extras.luxel (gltf.hpp
// lists the keys). Positions there are Source inches, +Z up, as the scene holds them.

#include "luxel/scenes/scene.hpp"
#include "tinygltf.hpp"

#include <functional>
#include <string>

namespace luxel::scenes::gltf {

tinygltf::Value scene_extras(const Scene& scene);

/// Sets what `extras` (the glTF scene's extras) holds under "luxel"; ignores keys it does not
/// know. `fail` throws with the message given (a color-correction input that is neither enable
/// nor disable).
void read_scene_extras(const tinygltf::Value& extras, Scene& scene, const std::function<void(const std::string&)>& fail);

}  // namespace luxel::scenes::gltf
