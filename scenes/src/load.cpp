#include "luxel/scenes/load.hpp"

#include <algorithm>
#include <cctype>

namespace luxel::scenes {

bool has_extension(const std::string& path, const std::string& extension) {
  if (path.size() < extension.size()) return false;
  return std::equal(extension.begin(), extension.end(), path.end() - long(extension.size()),
                    [](char a, char b) { return std::tolower(uint8_t(a)) == std::tolower(uint8_t(b)); });
}

Scene load_scene(const std::string& arg, const GltfImportOptions& options) {
  const std::string builtin = "builtin:";
  if (arg.rfind(builtin, 0) == 0) {
    // Built-in scenes (scenes/builtin.hpp, make_builtin_scene) plug in here.
    throw SceneArgumentError(arg + ": built-in scenes are not on this branch");
  }
  if (has_extension(arg, ".gltf") || has_extension(arg, ".glb")) return load_gltf(arg, options);
  throw SceneArgumentError(arg + ": not a scene: name a .gltf or .glb file, or builtin:NAME");
}

}  // namespace luxel::scenes
