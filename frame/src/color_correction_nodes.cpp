// The color-correction pass's lookups at a time on the scene's clock (color_correction_nodes.hpp).

#include "color_correction_nodes.hpp"

#include "luxel/postfx/color_correction_weights.hpp"
#include "luxel/postfx/lut_source.hpp"

#include <glm/geometric.hpp>

#include <filesystem>
#include <span>
#include <stdexcept>
#include <utility>

namespace luxel::frame {
namespace {

/// A file name relative to the scene file's folder (built-ins and absolute names as they are).
std::string lut_path(const scenes::Scene& scene, const std::string& lut) {
  if (lut.rfind("builtin:", 0) == 0 || std::filesystem::path(lut).is_absolute() || scene.name.rfind("builtin:", 0) == 0)
    return lut;
  return (std::filesystem::path(scene.name).parent_path() / lut).string();
}

/// The LUT named `lut` of the node or volume `where` names, composed with the look's grade when
/// there is one.
postfx::Lut scene_lut(const scenes::Scene& scene, const std::string& lut, const std::string& where,
                      const std::optional<postfx::ColorTransform>& look) {
  try {
    const postfx::Lut resolved = postfx::resolve_lut(lut_path(scene, lut));
    return look ? postfx::compose(resolved, *look) : resolved;
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(where + ": " + e.what());
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(where + ": " + e.what());
  }
}

std::vector<Box> volume_boxes(const scenes::Scene& scene) {
  std::vector<Box> boxes;
  for (const scenes::ColorCorrectionVolume& v : scene.color_correction_volumes) boxes.push_back({v.min, v.max});
  return boxes;
}

/// A node's weight at `time` seen from `eye` (color_correction_nodes.hpp): its fade over
/// max_weight through the inputs sent so far, times max_weight, through its falloff.
float node_weight(const scenes::ColorCorrection& c, float time, glm::vec3 eye) {
  postfx::EntityFade fade({1.0f, c.fade_in, c.fade_out, c.start_disabled});
  for (const scenes::ColorCorrectionInput& input : c.inputs) {
    if (input.time > time) break;
    if (input.kind == scenes::ColorCorrectionInput::Kind::enable) fade.enable(input.time);
    else fade.disable(input.time);
  }
  return postfx::falloff_weight(c.max_weight * fade.weight(time), c.min_falloff, c.max_falloff, glm::distance(eye, c.position));
}

/// A volume's weight at `time` after the eye's crossings so far (an enter, a leave, ...).
float volume_weight(std::span<const double> crossings, float fade_duration, float time) {
  postfx::VolumeFade fade(fade_duration);
  for (size_t i = 0; i < crossings.size(); ++i) {
    if (i % 2 == 0) fade.enter(crossings[i]);
    else fade.leave(crossings[i]);
  }
  return fade.weight(time);
}

}  // namespace

ColorCorrectionNodes::ColorCorrectionNodes(const scenes::Scene& scene, EyePath eye, bool scene_nodes,
                                           const std::optional<std::string>& look)
    : scene_(&scene), eye_(eye), crossings_(scene_nodes ? volume_boxes(scene) : std::vector<Box>{}, std::move(eye)) {
  std::optional<postfx::ColorTransform> grade;
  if (look) {
    grade = postfx::color_transform_named(*look);
    look_ = postfx::sample_lut(*grade);
  }
  if (scene_nodes) {
    for (size_t i = 0; i < scene.color_corrections.size(); ++i)
      luts_.push_back(scene_lut(scene, scene.color_corrections[i].lut, "color correction " + std::to_string(i), grade));
    for (size_t i = 0; i < scene.color_correction_volumes.size(); ++i)
      luts_.push_back(scene_lut(scene, scene.color_correction_volumes[i].lut, "color correction volume " + std::to_string(i), grade));
  }
  for (const postfx::Lut& lut : luts_) volumes_.push_back(postfx::lut_volume(lut));
  if (look_) look_volume_ = postfx::lut_volume(*look_);
}

std::vector<float> ColorCorrectionNodes::scene_weights(float time) {
  std::vector<float> weights;
  if (luts_.empty()) return weights;  // the scene's nodes are not blended
  const glm::vec3 eye = eye_.at(time);
  for (const scenes::ColorCorrection& c : scene_->color_corrections) weights.push_back(node_weight(c, time, eye));
  for (size_t i = 0; i < scene_->color_correction_volumes.size(); ++i)
    weights.push_back(volume_weight(crossings_.crossings(i, time), scene_->color_correction_volumes[i].fade_duration, time));
  return weights;
}

std::vector<postfx::WeightedLut> ColorCorrectionNodes::weighted_at(float time) {
  const std::vector<float> weights = scene_weights(time);
  std::vector<int> chosen = postfx::heaviest_lookups(weights);
  if (look_ && chosen.size() == size_t(postfx::kMaxLuts)) {
    // The grade's own lookup takes the fourth unless the three heaviest weigh 1 together.
    float three = 0.0f;
    for (size_t k = 0; k + 1 < chosen.size(); ++k) three += weights[size_t(chosen[k])];
    if (three < 1.0f) chosen.pop_back();
  }
  std::vector<postfx::WeightedLut> out;
  std::vector<float> chosen_weights;
  for (int i : chosen) {
    out.push_back({&luts_[size_t(i)], weights[size_t(i)], &volumes_[size_t(i)]});
    chosen_weights.push_back(weights[size_t(i)]);
  }
  if (look_) {
    if (const float own = postfx::default_weight(chosen_weights); own > 0.0f) out.push_back({&*look_, own, &*look_volume_});
  }
  return out;
}

}  // namespace luxel::frame
