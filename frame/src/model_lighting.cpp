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

AveragedLighting lighting_at(const scenes::Scene& scene, std::span<const LightDesc> lights, const glm::vec3& centroid,
                             AmbientSampling sampling, int local_lights) {
  AveragedLighting a;
  a.volume = ambient_cube(scene, centroid, sampling);
  a.shares.assign(lights.size(), 0.0f);
  const std::vector<size_t> order = shading::source::significance_order(lights, centroid);
  for (size_t k = 0; k < order.size() && k < static_cast<size_t>(local_lights); ++k) a.shares[order[k]] = 1.0f;
  return a;
}

void step_towards(AveragedLighting& averaged, const AveragedLighting& target, float dt, float tau) {
  if (!(tau > 0.0f) || dt < 0.0f || averaged.shares.size() != target.shares.size()) {
    averaged = target;
    return;
  }
  const float a = static_cast<float>(1.0 - std::exp(-double(dt) / double(tau)));
  for (size_t side = 0; side < 6; ++side) averaged.volume.color[side] += (target.volume.color[side] - averaged.volume.color[side]) * a;
  for (size_t i = 0; i < target.shares.size(); ++i) averaged.shares[i] += (target.shares[i] - averaged.shares[i]) * a;
}

std::array<int, kMaxLocalLights> local_light_slots(std::span<const size_t> significance, std::span<const float> shares,
                                                   int count) {
  std::vector<size_t> by_share;
  for (size_t i : significance)
    if (i < shares.size() && shares[i] > 0.0f) by_share.push_back(i);
  std::stable_sort(by_share.begin(), by_share.end(), [&](size_t a, size_t b) { return shares[a] > shares[b]; });
  std::array<int, kMaxLocalLights> slots{-1, -1, -1, -1};
  const size_t n = static_cast<size_t>(std::clamp(count, 0, kMaxLocalLights));
  for (size_t k = 0; k < by_share.size() && k < n; ++k) slots[k] = static_cast<int>(by_share[k]);
  return slots;
}

shading::source::VertexLitMaterial vertexlit_material(const scenes::Material& material) {
  shading::source::VertexLitMaterial m;
  m.phong = material.phong;
  m.bump = material.bump.bound();
  m.base_map_alpha_phong_mask = material.base_map_alpha_phong_mask;
  m.half_lambert = material.half_lambert;
  m.exponent_texture = material.phong_exponent_texture.bound();
  m.rim = material.rim;
  switch (material.envmap_mask) {
    case scenes::EnvmapMask::none: m.envmap_mask = shading::source::ModelEnvmapMask::none; break;
    case scenes::EnvmapMask::texture: m.envmap_mask = shading::source::ModelEnvmapMask::texture; break;
    case scenes::EnvmapMask::base_alpha: m.envmap_mask = shading::source::ModelEnvmapMask::base_alpha; break;
    case scenes::EnvmapMask::normal_alpha: m.envmap_mask = shading::source::ModelEnvmapMask::normal_alpha; break;
  }
  return m;
}

ModelLighting light_model(std::span<const LightDesc> lights, const glm::vec3& centroid, const scenes::Material& material,
                          bool half_lambert, const AveragedLighting& averaged, int local_lights) {
  ModelLighting m;
  const std::vector<size_t> significance = shading::source::significance_order(lights, centroid);
  m.local = local_light_slots(significance, averaged.shares, local_lights);
  // A local light at s x its color folds (1 - s) of itself; every other light folds wholly, in
  // the order of significance (the order fold_lights adds them in).
  shading::source::AmbientCube cube = averaged.volume;
  for (size_t i : significance) {
    const bool local = std::find(m.local.begin(), m.local.end(), static_cast<int>(i)) != m.local.end();
    const double weight = local ? 1.0 - double(averaged.shares[i]) : 1.0;
    if (weight > 0.0) shading::source::fold_light(cube, lights[i], centroid, half_lambert, weight);
  }
  std::vector<LightDesc> direct;
  for (int i : m.local) {
    if (i < 0) continue;
    LightDesc d = lights[static_cast<size_t>(i)];
    d.color *= averaged.shares[static_cast<size_t>(i)];
    direct.push_back(d);
  }
  m.kept = static_cast<int>(direct.size());
  shading::source::AmbientBoost boost;
  boost.enabled = material.hero_boost > 1.0f;
  boost.min_ambient_fraction *= material.hero_boost;
  m.cube = shading::source::boost_ambient_cube(cube, direct, centroid, boost);
  for (size_t i = 0; i < direct.size(); ++i) m.lights[i] = shading::source::to_local_light(direct[i]);
  return m;
}

}  // namespace luxel::frame
