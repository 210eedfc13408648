// The framing camera of a scene without cameras (framing.hpp).

#include "luxel/scenes/framing.hpp"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace luxel::scenes {

Camera framing_camera(const Scene& scene, float aspect) {
  Bounds b = bounds_of(scene);
  if (b.empty) b.min = glm::vec3(-32.0f), b.max = glm::vec3(32.0f), b.empty = false;
  const glm::dvec3 center = 0.5 * (glm::dvec3(b.min) + glm::dvec3(b.max));
  const glm::dvec3 half = 0.5 * (glm::dvec3(b.max) - glm::dvec3(b.min));
  // In view terms (looking along the scene's +Y, glTF's -Z): across is X, up is Z, depth is Y.
  // A box with no extent across or up (a point, a line towards the camera) is given some, so the
  // distance stays finite and positive: a hundredth of its largest extent, at least an inch.
  const double floor = std::max(0.01 * std::max({half.x, half.y, half.z}), 1.0);
  const double across = std::max(half.x, floor), up = std::max(half.z, floor), depth = half.y;
  const double tan_y = std::tan(0.5 * double(kFramingVerticalFov));
  const double tan_x = tan_y * double(aspect > 0.0f ? aspect : 1.0f);
  // The front face, `front` away, subtends across / front and up / front (in tangent units).
  const double front = std::max(across / (kFramingFill * tan_x), up / (kFramingFill * tan_y));
  const double distance = front + depth;
  Camera c;
  c.name = "luxel:framing";
  c.vertical_fov = kFramingVerticalFov;
  c.position = glm::vec3(center - glm::dvec3(0.0, distance, 0.0));
  c.target = glm::vec3(center);
  c.up = glm::vec3(0.0f, 0.0f, 1.0f);
  c.aspect = 0.0f;
  c.near_plane = float(0.5 * front);
  c.far_plane = float(2.0 * (distance + depth));
  return c;
}

}  // namespace luxel::scenes
