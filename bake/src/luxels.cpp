// Luxel coverage by uv1 triangles, and the geometry of each luxel.
#include "luxels.hpp"

#include "luxel/bake/rnm_basis.hpp"

#include <algorithm>
#include <cmath>

namespace luxel::bake::detail {

namespace {

using namespace scenes;

struct Corners {
  uint32_t v[3];
};

Corners corners(const Mesh& m, size_t t) {
  return {{m.vertex_of_corner(3 * t), m.vertex_of_corner(3 * t + 1), m.vertex_of_corner(3 * t + 2)}};
}

/// Any unit vector perpendicular to n.
glm::vec3 perpendicular(glm::vec3 n) {
  const glm::vec3 a = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(a - n * glm::dot(a, n));
}

}  // namespace

int atlas_side_from_uv1(const Scene& scene, const Inputs& in, const MeshUvs& uvs, float luxel_size) {
  std::vector<double> density;
  for (size_t mi = 0; mi < scene.meshes.size(); ++mi) {
    if (!uvs[mi]) continue;
    const Mesh& m = scene.meshes[mi];
    const auto& uv = *uvs[mi];
    for (size_t t = 0; t < m.triangle_count(); ++t) {
      const Corners c = corners(m, t);
      const glm::dvec3 p0(m.positions[c.v[0]]), p1(m.positions[c.v[1]]), p2(m.positions[c.v[2]]);
      const double world = 0.5 * glm::length(glm::cross(p1 - p0, p2 - p0));
      const glm::dvec2 a(uv[c.v[1]] - uv[c.v[0]]), b(uv[c.v[2]] - uv[c.v[0]]);
      const double area = 0.5 * std::abs(a.x * b.y - a.y * b.x);
      if (world > 0 && area > 0 && std::isfinite(world / area)) density.push_back(std::sqrt(world / area));
    }
  }
  if (density.empty()) return 0;
  std::nth_element(density.begin(), density.begin() + density.size() / 2, density.end());
  const double side = density[density.size() / 2] / double(luxel_size);
  if (!std::isfinite(side)) return 0;
  return int(std::clamp(std::round(side), 1.0, double(1 << 30)));  // the caller refuses anything over its limit
}

LuxelGrid make_luxels(const Scene& scene, const Inputs& in, const MeshUvs& uvs, int width, int height,
                      std::vector<std::string>& warnings) {
  LuxelGrid g;
  g.width = width, g.height = height;
  const size_t texels = size_t(width) * size_t(height);
  g.at.assign(texels, -1);
  // Per texel: the claiming triangle, its barycentrics, and whether the center was strictly inside
  // (overlap is reported only between two strict claims: neighbours share edges exactly).
  struct Claim {
    int mesh = -1;
    uint32_t triangle = 0;
    float b1 = 0, b2 = 0;
    bool strict = false;
  };
  std::vector<Claim> claims(texels);
  uint64_t degenerate = 0, no_uv_area = 0, out_of_range = 0, overlapping = 0;
  for (size_t mi = 0; mi < scene.meshes.size(); ++mi) {
    if (!uvs[mi]) continue;
    const Mesh& m = scene.meshes[mi];
    const auto& uv = *uvs[mi];
    for (size_t t = 0; t < m.triangle_count(); ++t) {
      const Corners c = corners(m, t);
      const glm::vec3 p0 = m.positions[c.v[0]], p1 = m.positions[c.v[1]], p2 = m.positions[c.v[2]];
      if (!(glm::length(glm::cross(p1 - p0, p2 - p0)) > 0.0f)) {
        ++degenerate;
        continue;
      }
      glm::dvec2 q[3];
      bool outside = false, finite = true;
      for (int k = 0; k < 3; ++k) {
        const glm::vec2 u = uv[c.v[k]];
        if (!(u.x >= 0.0f && u.x <= 1.0f && u.y >= 0.0f && u.y <= 1.0f)) outside = true;
        finite = finite && std::isfinite(u.x) && std::isfinite(u.y);
        q[k] = glm::dvec2(double(u.x) * width, double(u.y) * height);
      }
      if (outside) ++out_of_range;
      if (!finite) continue;  // counted as outside; nothing of it can be drawn
      const double area2 = (q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[1].y - q[0].y) * (q[2].x - q[0].x);
      if (!(std::abs(area2) > 1e-12)) {
        ++no_uv_area;
        continue;
      }
      const double lo_x = std::min({q[0].x, q[1].x, q[2].x}), hi_x = std::max({q[0].x, q[1].x, q[2].x});
      const double lo_y = std::min({q[0].y, q[1].y, q[2].y}), hi_y = std::max({q[0].y, q[1].y, q[2].y});
      // Clamped in double first: uv far outside [0, 1] must not overflow an int.
      auto texel = [](double v, int size) { return int(std::clamp(v, -1.0, double(size))); };
      const int x0 = std::max(0, texel(std::floor(lo_x - 0.5), width)), x1 = std::min(width - 1, texel(std::ceil(hi_x - 0.5), width));
      const int y0 = std::max(0, texel(std::floor(lo_y - 0.5), height)), y1 = std::min(height - 1, texel(std::ceil(hi_y - 0.5), height));
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
          const glm::dvec2 p(x + 0.5, y + 0.5);
          // Barycentrics of p: b1 for corner 1, b2 for corner 2.
          const double b1 = ((p.x - q[0].x) * (q[2].y - q[0].y) - (p.y - q[0].y) * (q[2].x - q[0].x)) / area2;
          const double b2 = ((q[1].x - q[0].x) * (p.y - q[0].y) - (q[1].y - q[0].y) * (p.x - q[0].x)) / area2;
          const double b0 = 1.0 - b1 - b2;
          const double e = -1e-9;
          if (b0 < e || b1 < e || b2 < e) continue;
          const bool strict = b0 > 1e-4 && b1 > 1e-4 && b2 > 1e-4;
          Claim& cl = claims[size_t(y) * size_t(width) + size_t(x)];
          if (cl.mesh >= 0) {
            if (strict && cl.strict) ++overlapping;
            continue;
          }
          cl = {int(mi), uint32_t(t), float(b1), float(b2), strict};
        }
    }
  }
  const std::string& name = scene.name;
  if (degenerate) warnings.push_back(name + ": " + std::to_string(degenerate) + " lightmapped triangles have no area (skipped)");
  if (no_uv_area) warnings.push_back(name + ": " + std::to_string(no_uv_area) + " lightmapped triangles have no uv1 area (skipped)");
  if (out_of_range) warnings.push_back(name + ": " + std::to_string(out_of_range) + " lightmapped triangles have uv1 outside [0, 1] (clipped)");
  if (overlapping) warnings.push_back(name + ": " + std::to_string(overlapping) + " luxels are covered by overlapping uv1 triangles (the first one is kept)");

  const auto& basis = rnm_basis();
  for (size_t i = 0; i < texels; ++i) {
    const Claim& cl = claims[i];
    if (cl.mesh < 0) continue;
    const Mesh& m = scene.meshes[size_t(cl.mesh)];
    const auto& uv = *uvs[size_t(cl.mesh)];
    const Corners c = corners(m, cl.triangle);
    const float w1 = cl.b1, w2 = cl.b2, w0 = 1.0f - w1 - w2;
    Luxel l;
    l.texel = uint32_t(i);
    l.mesh = cl.mesh;
    l.triangle = cl.triangle;
    const glm::vec3 p0 = m.positions[c.v[0]], p1 = m.positions[c.v[1]], p2 = m.positions[c.v[2]];
    l.position = w0 * p0 + w1 * p1 + w2 * p2;
    l.geometric_normal = glm::normalize(glm::cross(p1 - p0, p2 - p0));
    glm::vec3 n = l.geometric_normal;
    if (m.normals.size() == m.positions.size()) {
      const glm::vec3 s = w0 * m.normals[c.v[0]] + w1 * m.normals[c.v[1]] + w2 * m.normals[c.v[2]];
      if (glm::length(s) > 1e-6f) n = glm::normalize(s);
    }
    l.normal = n;
    glm::vec3 t(0.0f);
    float handedness = 1.0f;
    if (m.tangents.size() == m.positions.size()) {
      const glm::vec4 s = w0 * m.tangents[c.v[0]] + w1 * m.tangents[c.v[1]] + w2 * m.tangents[c.v[2]];
      t = glm::vec3(s);
      handedness = m.tangents[c.v[0]].w < 0 ? -1.0f : 1.0f;
    }
    t -= n * glm::dot(n, t);
    t = glm::length(t) > 1e-6f ? glm::normalize(t) : perpendicular(n);
    l.tangent = t;
    l.bitangent = handedness * glm::cross(n, t);
    for (int k = 0; k < 3; ++k) l.basis[size_t(k)] = basis[size_t(k)].x * t + basis[size_t(k)].y * l.bitangent + basis[size_t(k)].z * n;
    // World step per texel: invert the triangle's (texel -> world) Jacobian.
    const glm::dvec2 a(double(uv[c.v[1]].x - uv[c.v[0]].x) * width, double(uv[c.v[1]].y - uv[c.v[0]].y) * height);
    const glm::dvec2 b(double(uv[c.v[2]].x - uv[c.v[0]].x) * width, double(uv[c.v[2]].y - uv[c.v[0]].y) * height);
    const double det = a.x * b.y - a.y * b.x;
    const glm::dvec3 e1(p1 - p0), e2(p2 - p0);
    l.dpdx = glm::vec3((e1 * b.y - e2 * a.y) / det);
    l.dpdy = glm::vec3((e2 * a.x - e1 * b.x) / det);
    l.area = glm::length(glm::cross(l.dpdx, l.dpdy));
    g.at[i] = int32_t(g.luxels.size());
    g.luxels.push_back(l);
  }
  return g;
}

}  // namespace luxel::bake::detail
