#pragma once
// glTF's meters and +Y up against the scene's inches and +Z up (gltf.hpp): the one matrix and
// its inverse that import and export share, in double precision.

#include "luxel/scenes/scene.hpp"

#include <glm/mat4x4.hpp>

namespace luxel::scenes::gltf {

inline constexpr double kInches = double(kInchesPerMeter);

/// glTF (x, y, z) meters -> scene (x, -z, y) inches.
inline glm::dmat4 gltf_to_source() {
  glm::dmat4 c(0.0);
  c[0] = glm::dvec4(kInches, 0, 0, 0);   // glTF +X -> +X
  c[1] = glm::dvec4(0, 0, kInches, 0);   // glTF +Y (up) -> +Z
  c[2] = glm::dvec4(0, -kInches, 0, 0);  // glTF +Z -> -Y
  c[3] = glm::dvec4(0, 0, 0, 1);
  return c;
}

/// The inverse: scene inches, +Z up -> glTF meters, +Y up (the export's root node).
inline glm::dmat4 source_to_gltf() {
  glm::dmat4 c(0.0);
  c[0] = glm::dvec4(1.0 / kInches, 0, 0, 0);
  c[1] = glm::dvec4(0, 0, -1.0 / kInches, 0);
  c[2] = glm::dvec4(0, 1.0 / kInches, 0, 0);
  c[3] = glm::dvec4(0, 0, 0, 1);
  return c;
}

/// glTF point lights fall off as I / d_m^2 = I k^2 / d_in^2: Source's quadratic term is 1 / k^2.
inline constexpr float kLightQuadratic = float(1.0 / (kInches * kInches));

/// The name of the export's root node.
inline constexpr const char* kRootNodeName = "luxel:source-to-gltf";

}  // namespace luxel::scenes::gltf
