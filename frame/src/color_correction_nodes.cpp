#include "color_correction_nodes.hpp"

#include "luxel/postfx/color_correction_weights.hpp"
#include "luxel/postfx/lut_source.hpp"

#include <glm/geometric.hpp>

#include <filesystem>
#include <stdexcept>
#include <string>

namespace luxel::frame {
namespace {

/// A file name relative to the scene file's folder (built-ins and absolute names as they are).
std::string lut_path(const scenes::Scene& scene, const std::string& lut) {
  if (lut.rfind("builtin:", 0) == 0 || std::filesystem::path(lut).is_absolute() || scene.name.rfind("builtin:", 0) == 0)
    return lut;
  return (std::filesystem::path(scene.name).parent_path() / lut).string();
}

}  // namespace

ColorCorrectionNodes::ColorCorrectionNodes(const scenes::Scene& scene) : scene_(&scene) {
  for (size_t i = 0; i < scene.color_corrections.size(); ++i) {
    const std::string where = "color correction " + std::to_string(i) + ": ";
    try {
      luts_.push_back(postfx::resolve_lut(lut_path(scene, scene.color_corrections[i].lut)));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(where + e.what());
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(where + e.what());
    }
  }
}

std::vector<postfx::WeightedLut> ColorCorrectionNodes::weighted_at(glm::vec3 eye) const {
  std::vector<float> weights;
  for (const scenes::ColorCorrection& c : scene_->color_corrections)
    weights.push_back(postfx::falloff_weight(c.max_weight, c.min_falloff, c.max_falloff, glm::distance(eye, c.position)));
  std::vector<postfx::WeightedLut> out;
  for (int i : postfx::heaviest_lookups(weights)) out.push_back({&luts_[size_t(i)], weights[size_t(i)]});
  return out;
}

}  // namespace luxel::frame
