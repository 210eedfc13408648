#include "model_lighting.hpp"

#include <algorithm>
#include <cmath>

namespace luxel::frame {

using shading::source::LightDesc;

std::vector<LightDesc> light_descriptions(const scenes::Scene& scene) {
  std::vector<LightDesc> out;
  for (const scenes::Light& l : scene.lights) {
    LightDesc d;
    d.type = l.type == scenes::LightType::directional ? LightDesc::Type::directional
             : l.type == scenes::LightType::spot      ? LightDesc::Type::spot
                                                      : LightDesc::Type::point;
    d.color = l.color;
    d.position = l.position;
    d.direction = l.direction;
    d.attenuation = {l.constant, l.linear, l.quadratic};
    d.spot_exponent = l.spot_exponent;
    d.cos_inner = std::cos(l.inner_cone);
    d.cos_outer = std::cos(l.outer_cone);
    out.push_back(d);
  }
  return out;
}

shading::source::AmbientCube nearest_ambient_cube(const scenes::Scene& scene, const glm::vec3& point) {
  shading::source::AmbientCube cube;
  if (!scene.irradiance_volume || scene.irradiance_volume->cubes.empty()) {
    if (scene.lights.empty() && scene.sky_texture < 0) cube.color.fill(glm::vec3(1.0f));  // fullbright
    return cube;
  }
  const scenes::IrradianceVolume& v = *scene.irradiance_volume;
  glm::ivec3 cell;
  for (int a = 0; a < 3; ++a) {
    const float t = v.spacing[a] > 0 ? (point[a] - v.min[a]) / v.spacing[a] : 0.0f;
    cell[a] = std::clamp(static_cast<int>(std::lround(std::isfinite(t) ? t : 0.0f)), 0, std::max(v.counts[a] - 1, 0));
  }
  const size_t index = (static_cast<size_t>(cell.z) * v.counts.y + cell.y) * v.counts.x + cell.x;
  if (index < v.cubes.size()) cube.color = v.cubes[index];
  return cube;
}

ModelLighting light_model(const scenes::Scene& scene, std::span<const LightDesc> lights, const glm::vec3& centroid,
                          const scenes::Material& material) {
  const bool half_lambert = material.half_lambert || material.phong;
  const shading::source::FoldedLights folded =
      shading::source::fold_lights(lights, 2, centroid, nearest_ambient_cube(scene, centroid), half_lambert);
  ModelLighting m;
  m.kept = static_cast<int>(folded.kept.size());
  shading::source::AmbientBoost boost;
  boost.enabled = material.hero_boost > 1.0f;
  boost.min_ambient_fraction *= material.hero_boost;
  m.cube = shading::source::boost_ambient_cube(folded.cube, folded.kept, centroid, boost);
  for (int i = 0; i < m.kept; ++i) m.lights[static_cast<size_t>(i)] = shading::source::to_local_light(folded.kept[static_cast<size_t>(i)]);
  return m;
}

}  // namespace luxel::frame
