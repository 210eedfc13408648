// Coplanar charts, projected and shelf-packed (charts.hpp states the rules).
#include "luxel/bake/charts.hpp"

#include "luxel/bake/bake.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <deque>
#include <map>
#include <numeric>

namespace luxel::bake {

namespace {

using namespace scenes;

/// Every triangle gets three vertices of its own.
Mesh unweld(const Mesh& m) {
  Mesh out;
  out.name = m.name;
  out.material = m.material;
  const size_t corners = 3 * m.triangle_count();
  std::vector<uint32_t> idx(corners);
  for (size_t i = 0; i < corners; ++i) {
    const uint32_t v = m.vertex_of_corner(i);
    out.positions.push_back(m.positions[v]);
    if (!m.normals.empty()) out.normals.push_back(m.normals[v]);
    if (!m.tangents.empty()) out.tangents.push_back(m.tangents[v]);
    if (!m.uv0.empty()) out.uv0.push_back(m.uv0[v]);
    if (!m.colors.empty()) out.colors.push_back(m.colors[v]);
    idx[i] = uint32_t(i);
  }
  out.indices = std::move(idx);
  return out;
}

struct Chart {
  size_t mesh;
  std::vector<uint32_t> triangles;
  glm::vec3 u{0.0f}, v{0.0f};
  glm::vec2 lo{0.0f};
  int w = 1, h = 1;
  int x = 0, y = 0;  // placement, padding excluded
};

/// A position as a key: its bits (equal floats, equal keys).
std::array<uint32_t, 3> key(glm::vec3 p) {
  std::array<uint32_t, 3> k;
  std::memcpy(k.data(), &p, sizeof k);
  return k;
}

}  // namespace

GeneratedCharts make_charts(const Scene& scene, const std::vector<char>& which, float luxel_size, float angle_degrees,
                            int max_side) {
  GeneratedCharts g;
  g.meshes.resize(scene.meshes.size());
  std::vector<Chart> charts;
  const float cos_limit = std::cos(angle_degrees * 3.14159265f / 180.0f);
  for (size_t mi = 0; mi < scene.meshes.size(); ++mi) {
    if (mi >= which.size() || !which[mi]) continue;
    Mesh m = unweld(scene.meshes[mi]);
    const size_t tris = m.triangle_count();
    std::vector<glm::vec3> normal(tris);
    for (size_t t = 0; t < tris; ++t) {
      const glm::vec3 n = glm::cross(m.positions[3 * t + 1] - m.positions[3 * t], m.positions[3 * t + 2] - m.positions[3 * t]);
      const float len = glm::length(n);
      normal[t] = len > 0 ? n / len : glm::vec3(0.0f);
    }
    // Edges by end positions (unordered) -> triangles.
    std::map<std::array<uint32_t, 6>, std::vector<uint32_t>> edges;
    auto edge_key = [&](size_t t, int e) {
      auto a = key(m.positions[3 * t + size_t(e)]), b = key(m.positions[3 * t + size_t((e + 1) % 3)]);
      if (b < a) std::swap(a, b);
      return std::array<uint32_t, 6>{a[0], a[1], a[2], b[0], b[1], b[2]};
    };
    for (size_t t = 0; t < tris; ++t)
      for (int e = 0; e < 3; ++e) edges[edge_key(t, e)].push_back(uint32_t(t));
    std::vector<char> taken(tris, 0);
    for (size_t seed = 0; seed < tris; ++seed) {
      if (taken[seed]) continue;
      Chart c;
      c.mesh = mi;
      taken[seed] = 1;
      std::deque<uint32_t> queue{uint32_t(seed)};
      const glm::vec3 n = normal[seed];
      while (!queue.empty()) {
        const uint32_t t = queue.front();
        queue.pop_front();
        c.triangles.push_back(t);
        for (int e = 0; e < 3; ++e)
          for (uint32_t o : edges[edge_key(t, e)])
            if (!taken[o] && glm::dot(normal[o], n) >= cos_limit && glm::length(n) > 0) {
              taken[o] = 1;
              queue.push_back(o);
            }
      }
      // Axes: of the seed's three edges, the one whose direction gives the chart the smallest
      // bounding box (a rectangle split in two is then measured along its sides, not its diagonal).
      const glm::vec3 nn = glm::length(n) > 0 ? n : glm::vec3(0, 0, 1);
      double best = INFINITY;
      glm::vec2 lo(0.0f), hi(0.0f);
      for (int e = 0; e < 3; ++e) {
        const glm::vec3 d = m.positions[3 * seed + size_t((e + 1) % 3)] - m.positions[3 * seed + size_t(e)];
        glm::vec3 u = d - nn * glm::dot(nn, d);
        if (!(glm::length(u) > 0))
          u = std::abs(nn.x) < 0.9f ? glm::cross(nn, glm::vec3(1, 0, 0)) : glm::cross(nn, glm::vec3(0, 1, 0));
        u = glm::normalize(u);
        const glm::vec3 cu = u / luxel_size, cv = glm::cross(nn, u) / luxel_size;
        glm::vec2 l(INFINITY), h(-INFINITY);
        for (uint32_t t : c.triangles)
          for (int k = 0; k < 3; ++k) {
            const glm::vec3 p = m.positions[3 * t + size_t(k)];
            const glm::vec2 q(glm::dot(p, cu), glm::dot(p, cv));
            l = glm::min(l, q), h = glm::max(h, q);
          }
        const double area = double(h.x - l.x) * double(h.y - l.y);
        if (area < best) best = area, c.u = cu, c.v = cv, lo = l, hi = h;
      }
      c.lo = lo;
      // A chart exactly 8 luxels wide may measure 8.0000005 in float: not a ninth column.
      const double w = std::ceil(double(hi.x - lo.x) - 1e-3), h = std::ceil(double(hi.y - lo.y) - 1e-3);
      if (!(w <= double(max_side)) || !(h <= double(max_side)))
        throw BakeError(scene.name + ": mesh " + std::to_string(mi) + " '" + m.name + "' has a chart " + std::to_string(w) +
                        " x " + std::to_string(h) + " luxels at " + std::to_string(luxel_size) +
                        " inches a luxel, more than " + std::to_string(max_side) + " a side");
      c.w = std::max(1, int(w)), c.h = std::max(1, int(h));
      charts.push_back(std::move(c));
    }
    g.meshes[mi] = std::move(m);
  }
  g.charts = charts.size();
  if (charts.empty()) return g;

  // Shelves, tallest first (stable: ties keep chart order).
  std::vector<size_t> order(charts.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return charts[a].h > charts[b].h; });
  double area = 0;
  int widest = 0;
  for (const Chart& c : charts) area += double(c.w + 2) * double(c.h + 2), widest = std::max(widest, c.w + 2);
  int64_t side = std::max<int64_t>(int64_t(std::ceil(std::sqrt(area))), widest);
  for (;;) {
    side = (side + 3) / 4 * 4;
    if (side > max_side)
      throw BakeError(scene.name + ": the generated charts need a lightmap atlas over " + std::to_string(max_side) +
                      " luxels a side at " + std::to_string(luxel_size) + " inches a luxel");
    int64_t x = 0, y = 0, shelf = 0;
    for (size_t i : order) {
      Chart& c = charts[i];
      if (x + c.w + 2 > side) x = 0, y += shelf, shelf = 0;
      c.x = int(x) + 1, c.y = int(y) + 1;
      x += c.w + 2;
      shelf = std::max<int64_t>(shelf, c.h + 2);
    }
    if (y + shelf <= side) break;
    side += std::max<int64_t>(4, side / 8);
  }
  g.atlas_size = int(side);
  const float s = float(side);
  for (const Chart& c : charts) {
    Mesh& m = *g.meshes[c.mesh];
    m.uv1.resize(m.positions.size());
    for (uint32_t t : c.triangles)
      for (int k = 0; k < 3; ++k) {
        const glm::vec3 p = m.positions[3 * t + size_t(k)];
        const glm::vec2 q(glm::dot(p, c.u) - c.lo.x, glm::dot(p, c.v) - c.lo.y);
        m.uv1[3 * t + size_t(k)] = {(float(c.x) + q.x) / s, (float(c.y) + q.y) / s};
      }
  }
  return g;
}

}  // namespace luxel::bake
