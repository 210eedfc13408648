#include "model_lighting.hpp"

#include <glm/common.hpp>

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

shading::source::AmbientCube ambient_cube(const scenes::Scene& scene, const glm::vec3& point, AmbientSampling sampling) {
  shading::source::AmbientCube cube;
  if (!scene.irradiance_volume || scene.irradiance_volume->cubes.empty()) {
    if (scene.lights.empty() && scene.sky_texture < 0) cube.color.fill(glm::vec3(1.0f));  // fullbright
    return cube;
  }
  const scenes::IrradianceVolume& v = *scene.irradiance_volume;
  const glm::ivec3 last = glm::max(v.counts - 1, 0);
  // The point in grid units, clamped to the grid (a model outside the volume takes its edge).
  glm::vec3 grid;
  for (int a = 0; a < 3; ++a) {
    const float t = v.spacing[a] > 0 ? (point[a] - v.min[a]) / v.spacing[a] : 0.0f;
    grid[a] = std::clamp(std::isfinite(t) ? t : 0.0f, 0.0f, static_cast<float>(last[a]));
  }
  const auto sample = [&](const glm::ivec3& c) -> const scenes::AmbientCube* {
    const size_t index = (static_cast<size_t>(c.z) * v.counts.y + c.y) * v.counts.x + c.x;
    return index < v.cubes.size() ? &v.cubes[index] : nullptr;
  };
  if (sampling == AmbientSampling::nearest) {
    glm::ivec3 nearest;
    for (int a = 0; a < 3; ++a) nearest[a] = static_cast<int>(std::lround(grid[a]));  // halves away from 0
    if (const scenes::AmbientCube* c = sample(nearest)) cube.color = *c;
    return cube;
  }
  const glm::ivec3 lo(glm::floor(grid));
  const glm::ivec3 hi = glm::min(lo + 1, last);
  const glm::vec3 f = grid - glm::vec3(lo);
  for (int corner = 0; corner < 8; ++corner) {
    glm::ivec3 c;
    float w = 1.0f;
    for (int a = 0; a < 3; ++a) {
      const bool upper = (corner >> a) & 1;
      c[a] = upper ? hi[a] : lo[a];
      w *= upper ? f[a] : 1.0f - f[a];
    }
    const scenes::AmbientCube* s = sample(c);
    if (!s || w == 0.0f) continue;
    for (size_t side = 0; side < 6; ++side) cube.color[side] += w * (*s)[side];
  }
  return cube;
}

ModelLighting light_model(const scenes::Scene& scene, std::span<const LightDesc> lights, const glm::vec3& centroid,
                          const scenes::Material& material, AmbientSampling sampling) {
  const bool half_lambert = material.half_lambert || material.phong;
  const shading::source::FoldedLights folded =
      shading::source::fold_lights(lights, 2, centroid, ambient_cube(scene, centroid, sampling), half_lambert);
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
