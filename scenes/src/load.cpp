#include "luxel/scenes/load.hpp"

#include <algorithm>

namespace luxel::scenes {

namespace {

bool ends_with(std::string s, const std::string& suffix) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

Scene load_scene(const std::string& arg, const GltfImportOptions& options) {
  const std::string builtin = "builtin:";
  if (arg.rfind(builtin, 0) == 0) {
    // Built-in scenes (scenes/builtin.hpp, make_builtin_scene) plug in here.
    throw SceneArgumentError(arg + ": built-in scenes are not on this branch");
  }
  if (ends_with(arg, ".gltf") || ends_with(arg, ".glb")) return load_gltf(arg, options);
  throw SceneArgumentError(arg + ": not a scene: name a .gltf or .glb file, or builtin:NAME");
}

}  // namespace luxel::scenes
