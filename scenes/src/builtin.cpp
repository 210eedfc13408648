#include "luxel/scenes/builtin.hpp"

#include "builtin_scenes.hpp"

#include <stdexcept>

namespace luxel::scenes {

std::vector<std::string> builtin_scene_names() { return {"courtyard", "demo", "fill", "tris"}; }

Scene make_builtin_scene(std::string_view name, const BuiltinOptions& options) {
  if (name == "courtyard") return builtin::make_courtyard();
  if (name == "demo") return builtin::make_demo();
  if (name == "fill") return builtin::make_fill();
  if (name == "tris") {
    // The limit of a render target (rasterizer/limits.hpp), which scenes does not include.
    constexpr int kMaxSize = 8192;
    if (options.width < 1 || options.height < 1 || options.width > kMaxSize || options.height > kMaxSize)
      throw std::invalid_argument("builtin:tris: image size " + std::to_string(options.width) + "x" +
                                  std::to_string(options.height) + " is outside 1.." + std::to_string(kMaxSize));
    return builtin::make_tris(options.width, options.height);
  }
  std::string known;
  for (const std::string& n : builtin_scene_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown built-in scene '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace luxel::scenes
