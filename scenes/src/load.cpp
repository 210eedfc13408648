#include "luxel/scenes/load.hpp"

#include <algorithm>
#include <cctype>

namespace luxel::scenes {

bool has_extension(const std::string& path, const std::string& extension) {
  if (path.size() < extension.size()) return false;
  return std::equal(extension.begin(), extension.end(), path.end() - long(extension.size()),
                    [](char a, char b) { return std::tolower(uint8_t(a)) == std::tolower(uint8_t(b)); });
}

Scene load_scene(const std::string& arg, const GltfImportOptions& gltf, const BuiltinOptions& builtin) {
  const std::string prefix = "builtin:";
  if (arg.rfind(prefix, 0) == 0) {
    try {
      return make_builtin_scene(std::string_view(arg).substr(prefix.size()), builtin);
    } catch (const std::invalid_argument& e) {
      throw SceneArgumentError(arg + ": " + e.what());
    }
  }
  if (has_extension(arg, ".gltf") || has_extension(arg, ".glb")) return load_gltf(arg, gltf);
  throw SceneArgumentError(arg + ": not a scene: name a .gltf or .glb file, or builtin:NAME");
}

}  // namespace luxel::scenes
