#pragma once
// CPU side of model lighting: light descriptions, their pixel-shader constants, and folding the
// lights beyond the shader's count into the ambient cube
// (docs/fidelity.md#irradiance-volume-and-lights: the SDK shows that DrawModelInfo_t's cube holds
// "ambient, and lights that aren't in locallight[]", but the folding code and the priority are closed —
// NOT IN SDK; what follows is luxel's).
//
// Significance metric: the luminance (0.2125, 0.7154, 0.0721 — the histogram's weights)
// of the light's color times its attenuation (distance and spot, the SDK formula) at the model's
// reference point (its bounding-box center). That is the irradiance scale the light delivers to
// the model; it ignores orientation, because a model has normals in every direction. Ties keep
// the input order (stable sort), so the choice is deterministic.
//
// Folding: a folded light of attenuated intensity I arriving from unit direction L adds, to each
// of the six cube sides with axis a_j, I · term(dot(a_j, L)), where term is the material's diffuse
// term (squared Half-Lambert or saturated Lambert). The shader's cube weights are n² per axis, so
// for a normal along an axis the cube returns exactly that side: a folded directional light is
// reproduced exactly for the six axis normals (and approximately in between; Lambert's cosine is
// not a sum of n² lobes).

#include "luxel/shading/source/common.hpp"
#include "luxel/shading/source/vertexlit_generic.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <span>
#include <vector>

namespace luxel::shading::source {

struct LightDesc {
  enum class Type { point, spot, directional };
  Type type = Type::point;
  glm::vec3 color{1.0f};                  ///< linear intensity
  glm::vec3 position{0.0f};               ///< point / spot
  glm::vec3 direction{0.0f, 0.0f, -1.0f}; ///< spot axis / the direction a directional light travels
  glm::vec3 attenuation{1.0f, 0.0f, 0.0f};  ///< constant, linear, quadratic
  float spot_exponent = 5.0f;             ///< LightDesc_t::InitSpot's default
  float cos_inner = 0.9848f, cos_outer = 0.9659f;
};

/// The pixel-shader registers of a light (LocalLight's conventions).
inline LocalLight to_local_light(const LightDesc& d) {
  LocalLight l;
  const bool directional = d.type == LightDesc::Type::directional;
  l.color = glm::vec4(d.color, directional ? 1.0f : 0.0f);
  l.position = directional ? glm::vec4(-glm::normalize(d.direction), 0.0f) : glm::vec4(d.position, 1.0f);
  l.spot_direction = glm::vec4(glm::normalize(d.direction), d.type == LightDesc::Type::spot ? 1.0f : 0.0f);
  const float range = d.cos_inner - d.cos_outer;
  l.spot_params = glm::vec4(d.spot_exponent, 0.0f, d.cos_outer, range <= 1e-10f ? 1.0f : 1.0f / range);
  l.attenuation = glm::vec4(d.attenuation, 0.0f);
  return l;
}

/// Attenuated intensity and direction toward the light at `point` (double, the SDK formula).
inline glm::dvec3 light_at(const LightDesc& d, const glm::vec3& point, glm::dvec3& to_light) {
  if (d.type == LightDesc::Type::directional) {
    to_light = -glm::normalize(glm::dvec3(d.direction));
    return glm::dvec3(d.color);
  }
  const glm::dvec3 v = glm::dvec3(d.position) - glm::dvec3(point);
  const double dist = glm::length(v);
  to_light = dist > 0.0 ? v / dist : glm::dvec3(0.0);
  double a = 1.0 / (d.attenuation.x + d.attenuation.y * dist + d.attenuation.z * dist * dist);
  if (d.type == LightDesc::Type::spot) {
    const double range = d.cos_inner - d.cos_outer;
    const double inv = range <= 1e-10 ? 1.0 : 1.0 / range;
    const double c = (glm::dot(glm::normalize(glm::dvec3(d.direction)), -to_light) - d.cos_outer) * inv;
    a *= std::clamp(std::pow(std::max(c, 0.0001), double(d.spot_exponent)), 0.0, 1.0);
  }
  return glm::dvec3(d.color) * a;
}

/// The significance metric (see the file comment).
inline double light_significance(const LightDesc& d, const glm::vec3& point) {
  glm::dvec3 l;
  const glm::dvec3 i = light_at(d, point, l);
  return 0.2125 * i.x + 0.7154 * i.y + 0.0721 * i.z;
}

struct FoldedLights {
  std::vector<LightDesc> kept;  ///< the most significant first, at most `keep`
  AmbientCube cube;             ///< the input cube plus the folded lights
};

/// The lights' indices, the most significant at `point` first (ties: input order).
inline std::vector<size_t> significance_order(std::span<const LightDesc> lights, const glm::vec3& point) {
  std::vector<size_t> order(lights.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::vector<double> sig(lights.size());
  for (size_t i = 0; i < lights.size(); ++i) sig[i] = light_significance(lights[i], point);
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return sig[a] > sig[b]; });
  return order;
}

/// Adds `weight` x light `d`, as seen at `point`, to the six sides of `cube` (the file comment).
inline void fold_light(AmbientCube& cube, const LightDesc& d, const glm::vec3& point, bool half_lambert_term,
                       double weight = 1.0) {
  static const glm::dvec3 kAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  glm::dvec3 l;
  const glm::dvec3 intensity = light_at(d, point, l);
  for (int j = 0; j < 6; ++j) {
    const double c = glm::dot(kAxes[j], l);
    const double h = std::clamp(0.5 * c + 0.5, 0.0, 1.0);
    const double term = half_lambert_term ? h * h : std::clamp(c, 0.0, 1.0);
    cube.color[static_cast<size_t>(j)] += glm::vec3(intensity * term * weight);
  }
}

/// Keeps the `keep` most significant lights and folds the others into `cube`.
inline FoldedLights fold_lights(std::span<const LightDesc> lights, int keep, const glm::vec3& point,
                                const AmbientCube& cube, bool half_lambert_term) {
  const std::vector<size_t> order = significance_order(lights, point);
  FoldedLights r;
  r.cube = cube;
  for (size_t k = 0; k < order.size(); ++k) {
    const LightDesc& d = lights[order[k]];
    if (static_cast<int>(k) < keep) {
      r.kept.push_back(d);
      continue;
    }
    fold_light(r.cube, d, point, half_lambert_term);
  }
  return r;
}

// ---- The hero ambient boost ----------------------------------------------------------------------
//
// $ambientboost (the QC flag STUDIOHDR_FLAGS_AMBIENT_BOOST in studio.h, "first used on Alyx in
// Episode One" per the Valve Developer Community; the 2006 course notes §8.4.2: the directional
// ambient is boosted as a function of the direct lights, so that a hero character is not lost in
// darkness on the side the direct lights miss). The flag is all the SDK holds: the heuristic runs
// in the closed studiorender (NOT IN SDK), so what follows is luxel's, stated as a rule:
//   A = the ambient cube's mean luminance (the mean of its six sides: the cube's response averaged
//       over all directions, each axis weight n_a² averaging 1/3), D = the summed significance
//       (light_significance: delivered luminance at the model's reference point) of the direct
//       lights the shader evaluates; the cube is scaled by max(1, min_ambient_fraction x D / A),
//       i.e. raised until its luminance is at least that fraction of the direct light's. No direct
//       light, or an ambient already bright enough: unchanged. A black cube stays black (a boost
//       scales the cube's colors, it invents none).
// A CPU step before the constants are written, like the folding: the shaders are unchanged.

/// The material option (off by default, as the QC flag is).
struct AmbientBoost {
  bool enabled = false;               ///< $ambientboost
  float min_ambient_fraction = 0.25f; ///< luxel's: the ambient's luminance floor, x the direct lights'
};

inline double ambient_cube_luminance(const AmbientCube& cube) {
  double sum = 0.0;
  for (const glm::vec3& c : cube.color) sum += 0.2125 * c.x + 0.7154 * c.y + 0.0721 * c.z;
  return sum / 6.0;
}

/// The factor the boost scales the cube by, for the direct lights at `point`.
inline double ambient_boost_factor(const AmbientCube& cube, std::span<const LightDesc> direct, const glm::vec3& point,
                                   const AmbientBoost& boost) {
  if (!boost.enabled) return 1.0;
  const double ambient = ambient_cube_luminance(cube);
  if (!(ambient > 0.0)) return 1.0;
  double direct_luminance = 0.0;
  for (const LightDesc& d : direct) direct_luminance += light_significance(d, point);
  return std::max(1.0, boost.min_ambient_fraction * direct_luminance / ambient);
}

/// The cube with the boost applied (after folding: `direct` are the lights kept as real lights).
inline AmbientCube boost_ambient_cube(const AmbientCube& cube, std::span<const LightDesc> direct, const glm::vec3& point,
                                      const AmbientBoost& boost) {
  const double k = ambient_boost_factor(cube, direct, point, boost);
  AmbientCube r = cube;
  for (glm::vec3& c : r.color) c = glm::vec3(glm::dvec3(c) * k);
  return r;
}

}  // namespace luxel::shading::source
