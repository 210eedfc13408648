#pragma once
// Pieces the lightmap and ambient-cube stages share: the bake's context, direct light at a point,
// where a ray hit lands in the atlas, stratified directions.

#include "inputs.hpp"
#include "luxels.hpp"
#include "parallel.hpp"

#include "luxel/bake/rays.hpp"
#include "luxel/bake/random.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace luxel::bake::detail {

struct Context {
  const scenes::Scene& scene;
  const Inputs& in;
  const RayScene& rays;
  const LuxelGrid& grid;
  const MeshUvs& uvs;
  const BakeSettings& settings;
  int threads = 1;
  const ProgressFn& progress;
};

/// Flat map then the three basis maps.
struct Rgb4 {
  std::array<glm::vec3, 4> v{};
};

/// The lights' direct contribution at `p` (shadow rays from p + epsilon n_geo): flat about
/// `normal`, and about each world basis vector; nothing from below n_geo. Counts its rays.
Rgb4 direct_light(const Context& c, glm::vec3 p, glm::vec3 normal, glm::vec3 n_geo, const std::array<glm::vec3, 3>& basis,
                  uint64_t& rays);
/// The flat part only (for surfaces without luxels, and for ambient-cube faces in all-light mode
/// with `normal` an axis and no geometric normal test when n_geo is zero).
glm::vec3 direct_flat(const Context& c, glm::vec3 p, glm::vec3 normal, glm::vec3 n_geo, uint64_t& rays);

/// The point and geometric normal (unit, front side) of a hit.
void hit_geometry(const scenes::Scene& scene, const Hit& h, glm::vec3& point, glm::vec3& n_geo);
/// The atlas texel a hit on a lightmapped mesh lands in (nearest), or -1.
int64_t texel_of_hit(const Context& c, const Hit& h);

/// The radiance a ray in direction `dir` brings back once the lightmaps are final (the rule of
/// ambient_cubes.hpp, which irradiance_at shares): the sky on a miss; on the front of a surface
/// its emissive plus albedo x the final flat map `flat` (lightmapped, nearest texel; nothing
/// when `flat` is empty) or albedo x the lights' direct light there (other diffuse surfaces);
/// black on a back face, which sets `back`. Counts the shadow rays it traces.
glm::vec3 final_radiance(const Context& c, const std::vector<glm::vec3>& flat, const std::optional<Hit>& hit, glm::vec3 dir,
                         uint64_t& rays, bool& back);

/// Stratum j of n x n over [0, 1)^2, jittered by key.
inline glm::vec2 stratified(const RandomKey& key, int j, int n) {
  const float r1 = random01(key, 0), r2 = random01(key, 1);
  return {(float(j % n) + r1) / float(n), (float(j / n) + r2) / float(n)};
}

/// The direction uniform over the hemisphere about +z for a point `xi` of [0, 1)^2 (z = xi.x).
inline glm::vec3 uniform_hemisphere(glm::vec2 xi) {
  const float z = xi.x, r = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = 6.2831853f * xi.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

/// The number of strata per side for a requested ray count (at least 1).
int strata_side(int samples);

}  // namespace luxel::bake::detail
