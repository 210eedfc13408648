#include "luxel/frame/builtin.hpp"

#include "luxel/rasterizer/msaa.hpp"
#include "workload_scenes.hpp"

#include <stdexcept>
#include <string>

namespace luxel::frame {

std::vector<std::string> builtin_scene_names() { return {"demo", "fill", "tris"}; }

std::unique_ptr<BuiltinScene> make_builtin_scene(std::string_view name, const FrameSettings& s) {
  if (s.width < 1 || s.height < 1 || s.width > rasterizer::kMaxTargetSize || s.height > rasterizer::kMaxTargetSize)
    throw std::invalid_argument("image size " + std::to_string(s.width) + "x" + std::to_string(s.height) +
                                " is outside 1.." + std::to_string(rasterizer::kMaxTargetSize));
  if (!rasterizer::is_valid_sample_count(s.samples))
    throw std::invalid_argument("msaa " + std::to_string(s.samples) + " is not 1, 2, 4 or 8");
  if (name == "demo") return make_demo_scene(s);
  if (name == "fill") return make_fill_scene(s);
  if (name == "tris") return make_tris_scene(s);
  std::string known;
  for (const std::string& n : builtin_scene_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown built-in scene '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace luxel::frame
