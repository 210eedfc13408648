#pragma once
// Private: the lookups the frame's color-correction pass blends (postfx/color_correction.hpp) at
// a time on the scene's clock: the scene's nodes (scenes::ColorCorrection, Source's
// color_correction), its volumes (scenes::ColorCorrectionVolume, color_correction_volume) and a
// look on top (look.hpp).
//
// Each LUT is resolved once (postfx/lut_source.hpp: a built-in grade, a Source .raw file or any
// file OpenColorIO reads, a relative file name taken from the scene file's folder). The weights at
// time t are a function of t and the eye's path alone, never of the frames rendered before
// (postfx/color_correction_weights.hpp has the SDK's rules, docs/fidelity.md#color-correction):
//  - a node: its inputs up to t replayed through a postfx::EntityFade, then its falloff at the
//    eye's distance at t. The fade runs on the node's weight over max_weight (the SDK's fades
//    exactly, their durations shortened by that ratio), times max_weight, with one difference:
//    the SDK spawns an enabled entity at 1 whatever its maxweight, a luxel node at max_weight,
//    the weight its designer gave it (the built-in courtyard's nodes hold 0.8);
//  - a volume: the eye's crossings of its box up to t (volume_crossings.hpp: tested every 0.01 s
//    from 0) replayed through a postfx::VolumeFade.
// Nodes first, then volumes; the four heaviest are blended (postfx::heaviest_lookups: the earlier
// first on a tie). With a look, every LUT is composed with the look's grade and the grade alone
// takes the frame's own weight, 1 minus the scene's (look.hpp): then the scene keeps its three
// heaviest while they weigh less than 1 together, its four heaviest once they weigh 1 or more
// (the frame's own weight is then 0 and the grade needs no lookup of its own).

#include "volume_crossings.hpp"

#include "luxel/postfx/color_correction.hpp"
#include "luxel/scenes/scene.hpp"

#include <optional>
#include <string>
#include <vector>

namespace luxel::frame {

class ColorCorrectionNodes {
 public:
  /// `scene_nodes`: blend the scene's nodes and volumes (FrameSettings::color_correction); `look`:
  /// the look's grade (look_lut), or none. Throws what postfx::resolve_lut throws for a LUT that
  /// cannot be had, prefixed with the node or volume it belongs to.
  ColorCorrectionNodes(const scenes::Scene& scene, EyePath eye, bool scene_nodes, const std::optional<std::string>& look);
  bool empty() const { return luts_.empty() && !look_; }
  /// The LUTs and weights at `time`, at most four, none when every weight is 0.
  std::vector<postfx::WeightedLut> weighted_at(float time);

 private:
  /// Per node, then per volume: its weight at `time`.
  std::vector<float> scene_weights(float time);

  const scenes::Scene* scene_;
  EyePath eye_;
  std::vector<postfx::Lut> luts_;   ///< per node, then per volume (composed with the look's grade)
  std::optional<postfx::Lut> look_;  ///< the look's grade alone
  /// postfx::lut_volume of each of luts_ and of look_: made once, not per frame.
  std::vector<rasterizer::Texture> volumes_;
  std::optional<rasterizer::Texture> look_volume_;
  VolumeCrossings crossings_;
};

}  // namespace luxel::frame
