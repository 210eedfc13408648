#pragma once
// The radiosity-normal-mapping basis (docs/fidelity.md#rnm-basis-and-lightmaps: common_fxc.h bumpBasis,
// bumpvects.h g_localBumpBasis): three orthonormal directions in tangent space (x = tangent, the
// texture's S direction; y = bitangent = w cross(n, t), up the image; z = normal), each 54.7356 degrees
// from the normal and 120 degrees apart around it.

#include <glm/vec3.hpp>

#include <array>
#include <cmath>

namespace luxel::bake {

/// The basis in tangent space, exact (sqrt(2/3), 1/sqrt(6), 1/sqrt(2), 1/sqrt(3)), not the
/// shader's float literals, which differ in the last digits.
inline const std::array<glm::vec3, 3>& rnm_basis() {
  static const std::array<glm::vec3, 3> basis = {
      glm::vec3(float(std::sqrt(2.0 / 3.0)), 0.0f, float(1.0 / std::sqrt(3.0))),
      glm::vec3(float(-1.0 / std::sqrt(6.0)), float(1.0 / std::sqrt(2.0)), float(1.0 / std::sqrt(3.0))),
      glm::vec3(float(-1.0 / std::sqrt(6.0)), float(-1.0 / std::sqrt(2.0)), float(1.0 / std::sqrt(3.0)))};
  return basis;
}

/// (1/pi) times the integral, over the hemisphere above the surface normal, of max(0, b . w) for a
/// basis direction b: the irradiance / pi a basis direction receives from a uniform radiance of 1
/// over that hemisphere, what the basis maps' self-normalized gather of bounced and emitted light
/// is scaled by (the sky follows vrad's own rule, lightmaps.hpp). It is the tilted-plane factor
/// (1 + cos beta) / 2 with cos beta = b.z = 1/sqrt(3).
inline constexpr double kBasisSkyFactor = 0.78867513459481288;  // (1 + 1/sqrt(3)) / 2

}  // namespace luxel::bake
