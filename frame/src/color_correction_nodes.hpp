#pragma once
// The scene's color-correction nodes (scenes::ColorCorrection, Source's color_correction entity)
// as the frame's last pass blends them (postfx/color_correction.hpp): each node's LUT resolved
// once (postfx/lut_source.hpp: a built-in grade, a Source .raw file or any file OpenColorIO reads,
// a relative file name taken from the scene file's folder), and per frame the weight the eye sees
// at its distance (postfx/color_correction_weights.hpp: max_weight through the node's falloff;
// nodes hold their weight, the scene model has no enable or disable inputs), the four heaviest
// blended. A camera moving along its path crosses the falloffs smoothly.

#include "luxel/postfx/color_correction.hpp"
#include "luxel/scenes/scene.hpp"

#include <glm/vec3.hpp>

#include <vector>

namespace luxel::frame {

class ColorCorrectionNodes {
 public:
  /// Throws what postfx::resolve_lut throws for a node whose LUT cannot be had, prefixed with the
  /// node's index.
  explicit ColorCorrectionNodes(const scenes::Scene& scene);
  bool empty() const { return luts_.empty(); }
  /// The LUTs and weights the eye at `eye` sees, at most four, none when every weight is 0.
  std::vector<postfx::WeightedLut> weighted_at(glm::vec3 eye) const;

 private:
  const scenes::Scene* scene_;
  std::vector<postfx::Lut> luts_;  ///< per node
};

}  // namespace luxel::frame
