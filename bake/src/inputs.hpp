#pragma once
// What the bake reads from a scene, prepared once: each mesh's role and reflectivity, the sky,
// the lights' falloff, the ray offset.

#include "luxel/bake/settings.hpp"
#include "luxel/scenes/scene.hpp"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace luxel::bake::detail {

/// How a mesh takes part in the bake.
enum class MeshRole : uint8_t {
  ignored,      ///< water, sky, blended or translucent: lets light through, is not lit
  lightmapped,  ///< world LightmappedGeneric: gets luxels, reflects its lightmap
  diffuse,      ///< models and other opaque surfaces: block light, reflect direct light only
  emitter,      ///< UnlitGeneric with an emissive color: glows, does not block lights
};

struct Inputs {
  const scenes::Scene* scene = nullptr;
  std::vector<MeshRole> roles;
  std::vector<glm::vec3> albedo, emissive;  ///< per mesh: vrad's reflectivity, emitted radiance
  float epsilon = 0.01f;                    ///< ray origin offset along the normal, inches
  float sky_max = 16.0f;

  bool visible(size_t mesh) const { return roles[mesh] != MeshRole::ignored; }
  bool occluding(size_t mesh) const { return roles[mesh] == MeshRole::lightmapped || roles[mesh] == MeshRole::diffuse; }
  /// The radiance of the sky in direction `dir` (unit, world): the sky cube's nearest texel
  /// (clamped to sky_max), else the background.
  glm::vec3 sky(glm::vec3 dir) const;
};

Inputs prepare_inputs(const scenes::Scene& scene, const BakeSettings& settings);

/// A light as seen from a point: unit direction to it, distance (infinity for directional) and
/// the color after falloff and cone (lightmaps.hpp). False when it does not reach the point.
struct LightSample {
  glm::vec3 to_light{0.0f};
  float distance = 0;
  glm::vec3 intensity{0.0f};
};
bool light_at(const scenes::Light& light, glm::vec3 point, LightSample& out);

inline float luminance(glm::vec3 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

}  // namespace luxel::bake::detail
