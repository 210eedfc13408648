#include "luxel/scenes/tangents.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace luxel::scenes {

namespace {

using dvec3 = glm::dvec3;

/// v projected onto the plane perpendicular to the unit n.
dvec3 project(dvec3 v, dvec3 n) { return v - n * glm::dot(n, v); }

dvec3 normalized_or_zero(dvec3 v) {
  const double len = glm::length(v);
  return len > 0.0 ? v / len : dvec3(0.0);
}

/// Any unit vector perpendicular to n.
dvec3 perpendicular(dvec3 n) {
  const dvec3 axis = std::abs(n.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
  const dvec3 t = normalized_or_zero(project(axis, n));
  return glm::length(t) > 0.0 ? t : dvec3(1, 0, 0);
}

void generate(Mesh& mesh, std::vector<uint32_t>& indices) {
  const size_t n = mesh.vertex_count();
  // Accumulated tangents per vertex and orientation (0: preserving, 1: mirrored).
  std::vector<dvec3> sum[2] = {std::vector<dvec3>(n, dvec3(0.0)), std::vector<dvec3>(n, dvec3(0.0))};
  std::vector<char> used[2] = {std::vector<char>(n, 0), std::vector<char>(n, 0)};
  const size_t triangles = indices.size() / 3;
  std::vector<uint8_t> orientation(triangles, 2);  // 2: degenerate UVs, neither side
  for (size_t t = 0; t < triangles; ++t) {
    const uint32_t v[3] = {indices[3 * t], indices[3 * t + 1], indices[3 * t + 2]};
    dvec3 p[3];
    glm::dvec2 uv[3];
    for (int k = 0; k < 3; ++k) {
      p[k] = dvec3(mesh.positions[v[k]]);
      uv[k] = glm::dvec2(mesh.uv0[v[k]].x, 1.0 - double(mesh.uv0[v[k]].y));  // v up
    }
    const dvec3 d1 = p[1] - p[0], d2 = p[2] - p[0];
    const glm::dvec2 t21 = uv[1] - uv[0], t31 = uv[2] - uv[0];
    const double area = t21.x * t31.y - t21.y * t31.x;  // MikkTSpace's fSignedAreaSTx2
    const int side = area > 0.0 ? 0 : 1;
    // dP/du * area; the sign of the area turns it into dP/du's direction.
    const dvec3 os = (area > 0.0 ? 1.0 : -1.0) * (t31.y * d1 - t21.y * d2);
    if (area == 0.0 || glm::length(os) == 0.0) continue;  // degenerate UVs: no tangent to give
    orientation[t] = uint8_t(side);
    for (int k = 0; k < 3; ++k) {
      const dvec3 normal = normalized_or_zero(dvec3(mesh.normals[v[k]]));
      const dvec3 tangent = normalized_or_zero(project(os, normal));
      const dvec3 e1 = normalized_or_zero(project(p[(k + 1) % 3] - p[k], normal));
      const dvec3 e2 = normalized_or_zero(project(p[(k + 2) % 3] - p[k], normal));
      const double angle = std::acos(std::clamp(glm::dot(e1, e2), -1.0, 1.0));
      sum[side][v[k]] += angle * tangent;
      used[side][v[k]] = 1;
    }
  }
  // A vertex used from both sides: the mirrored side gets its own copy.
  std::vector<uint32_t> mirrored_copy(n, UINT32_MAX);
  std::vector<uint32_t> copy_of;  // per appended vertex, the vertex it copies
  for (size_t t = 0; t < triangles; ++t) {
    if (orientation[t] != 1) continue;
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = indices[3 * t + k];
      if (v >= n || !used[0][v]) continue;  // only this side uses it (or an appended copy)
      if (mirrored_copy[v] == UINT32_MAX) {
        mirrored_copy[v] = static_cast<uint32_t>(mesh.positions.size());
        copy_of.push_back(v);
        mesh.positions.push_back(mesh.positions[v]);
        mesh.normals.push_back(mesh.normals[v]);
        mesh.uv0.push_back(mesh.uv0[v]);
        if (!mesh.uv1.empty()) mesh.uv1.push_back(mesh.uv1[v]);
        if (!mesh.colors.empty()) mesh.colors.push_back(mesh.colors[v]);
      }
      indices[3 * t + k] = mirrored_copy[v];
    }
  }
  mesh.tangents.assign(mesh.positions.size(), glm::vec4(1, 0, 0, 1));
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    // An original vertex takes the side that uses it (preserving if both: its mirrored triangles
    // now use the copy); an appended copy takes the mirrored sum of the vertex it copies.
    const int side = v >= n ? 1 : (used[0][v] || !used[1][v] ? 0 : 1);
    const dvec3 s = v >= n ? sum[1][copy_of[v - n]] : sum[side][v];
    dvec3 t = normalized_or_zero(s);
    if (glm::length(t) == 0.0) t = perpendicular(normalized_or_zero(dvec3(mesh.normals[v])));
    mesh.tangents[v] = glm::vec4(glm::vec3(t), side == 0 ? 1.0f : -1.0f);
  }
}

}  // namespace

void generate_tangents(Mesh& mesh) {
  if (mesh.normals.size() != mesh.vertex_count() || mesh.uv0.size() != mesh.vertex_count())
    throw std::invalid_argument("mesh '" + mesh.name + "': tangents need a normal and a uv0 per vertex");
  std::vector<uint32_t> indices(3 * mesh.triangle_count());
  for (size_t k = 0; k < indices.size(); ++k) {
    indices[k] = mesh.vertex_of_corner(k);
    if (indices[k] >= mesh.vertex_count())
      throw std::invalid_argument("mesh '" + mesh.name + "': index " + std::to_string(k) + " is beyond its vertices");
  }
  generate(mesh, indices);
  // Split vertices may need wider indices than the mesh had.
  if (std::holds_alternative<std::vector<uint16_t>>(mesh.indices) && mesh.vertex_count() <= 65536)
    mesh.indices = std::vector<uint16_t>(indices.begin(), indices.end());
  else
    mesh.indices = std::move(indices);
}

}  // namespace luxel::scenes
