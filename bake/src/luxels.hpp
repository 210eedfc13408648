#pragma once
// uv1 triangles -> luxels: which atlas texels are covered, and each one's sample point, normal,
// RNM basis in world space and footprint (lightmaps.hpp states the rules).

#include "inputs.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace luxel::bake::detail {

struct Luxel {
  uint32_t texel = 0;  ///< y * width + x
  int mesh = -1;
  uint32_t triangle = 0;
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f, 0.0f, 1.0f};            ///< interpolated, unit
  glm::vec3 geometric_normal{0.0f, 0.0f, 1.0f};  ///< the triangle's, unit
  glm::vec3 tangent{1.0f, 0.0f, 0.0f}, bitangent{0.0f, 1.0f, 0.0f};
  std::array<glm::vec3, 3> basis{};              ///< RNM basis in world space
  glm::vec3 dpdx{0.0f}, dpdy{0.0f};              ///< world step per texel in x and y
  float area = 0;                                ///< world inches^2 of the luxel
};

struct LuxelGrid {
  int width = 0, height = 0;
  std::vector<Luxel> luxels;  ///< in texel order
  std::vector<int32_t> at;    ///< per texel: index into luxels, or -1
};

/// The uv1 of each mesh the bake uses: its own, or generated; empty for meshes without luxels.
using MeshUvs = std::vector<const std::vector<glm::vec2>*>;

/// The square atlas side implied by uv1 density: the median over triangles of
/// sqrt(world area / uv area) / luxel_size, rounded; 0 when no triangle has area.
int atlas_side_from_uv1(const scenes::Scene& scene, const Inputs& in, const MeshUvs& uvs, float luxel_size);

LuxelGrid make_luxels(const scenes::Scene& scene, const Inputs& in, const MeshUvs& uvs, int width, int height,
                      std::vector<std::string>& warnings);

}  // namespace luxel::bake::detail
