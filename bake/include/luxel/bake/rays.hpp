#pragma once
// Rays through Embree 3: closest hits for gathering, any hits for shadows.
//
// Determinism. Embree's documentation makes no promise that a BVH built by several threads is the
// same each time (rtcNewDevice(3): `threads=N` sets the build threads, the default is all of
// them). The device is therefore created with "threads=1": the build is one thread's sequential
// algorithm over the same input, so the same BVH every time, and it costs milliseconds for the
// scenes luxel bakes. Queries are made from any number of our own threads (rtcIntersect1 and
// rtcOccluded1 do not use Embree's task scheduler). Closest-hit answers do not depend on the
// BVH's shape anyway except at exact ties (a ray through a shared edge); robust mode
// (RTC_SCENE_FLAG_ROBUST, rtcore_scene.h) makes those watertight, and a single build makes even
// the tie-break fixed. BVH quality is RTC_BUILD_QUALITY_HIGH (spatial splits; a one-off cost).
//
// Two Embree scenes are built from one luxel scene: `visible` (everything gather rays can see:
// diffuse surfaces and emitters) and `occluding` (what blocks a light: the same minus pure
// emitters, so that a light placed inside its own glowing flame mesh is not shadowed by it).
// Which meshes go where is the caller's choice (MeshRole in bake_inputs).

#include "luxel/scenes/scene.hpp"

#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <span>

namespace luxel::bake {

/// A closest hit: which triangle, where on it (Embree's barycentrics: point = (1-u-v) p0 + u p1
/// + v p2), how far, and whether the ray met its front face (counter-clockwise, scene.hpp).
struct Hit {
  int mesh = -1;
  uint32_t triangle = 0;
  float u = 0, v = 0, t = 0;
  bool front = true;
};

class RayScene {
 public:
  /// `visible[i]` / `occluding[i]`: whether scene.meshes[i] is in each Embree scene. Throws
  /// std::runtime_error with Embree's error when the device or a scene cannot be made.
  RayScene(const scenes::Scene& scene, std::span<const char> visible, std::span<const char> occluding);
  ~RayScene();
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  /// The closest visible surface along origin + t dir, tmin < t < tmax (dir need not be unit).
  std::optional<Hit> intersect(glm::vec3 origin, glm::vec3 dir, float tmin, float tmax) const;
  /// Whether any occluding surface lies along origin + t dir, tmin < t < tmax.
  bool occluded(glm::vec3 origin, glm::vec3 dir, float tmin, float tmax) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace luxel::bake
