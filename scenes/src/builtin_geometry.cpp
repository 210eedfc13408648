#include "builtin_geometry.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace luxel::scenes::builtin {

namespace {


std::vector<uint16_t>& indices16(Mesh& m) {
  auto& idx = std::get<std::vector<uint16_t>>(m.indices);
  if (m.positions.size() > 65535) throw std::logic_error("built-in mesh '" + m.name + "' is too large for 16-bit indices");
  return idx;
}

/// Triangles of a (columns + 1) x (rows + 1) vertex grid from `first`, counter-clockwise when
/// columns run along +u and rows along +v of a right-handed (u, v, front) frame.
template <class Index>
void grid_triangles(std::vector<Index>& idx, uint32_t first, int columns, int rows) {
  const uint32_t row = static_cast<uint32_t>(columns + 1);
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const auto v00 = static_cast<Index>(first + j * row + i), v10 = static_cast<Index>(v00 + 1);
      const auto v01 = static_cast<Index>(v00 + row), v11 = static_cast<Index>(v01 + 1);
      idx.insert(idx.end(), {v00, v10, v11, v00, v11, v01});
    }
}

}  // namespace

void add_rectangle(Mesh& m, glm::vec3 origin, glm::vec3 edge_u, glm::vec3 edge_v, int nu, int nv, float uv_inches,
                   ChartPacker* charts, int mesh_index) {
  const auto first = static_cast<uint32_t>(m.positions.size());
  const glm::vec3 n = glm::normalize(glm::cross(edge_u, edge_v));
  const float lu = glm::length(edge_u), lv = glm::length(edge_v);
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      const float s = float(i) / nu, t = float(j) / nv;
      m.positions.push_back(origin + s * edge_u + t * edge_v);
      m.normals.push_back(n);
      m.uv0.push_back({s * lu / uv_inches, -t * lv / uv_inches});
    }
  if (std::holds_alternative<std::vector<uint16_t>>(m.indices)) grid_triangles(indices16(m), first, nu, nv);
  else grid_triangles(std::get<std::vector<uint32_t>>(m.indices), first, nu, nv);
  if (charts) charts->chart(mesh_index, first, nu, nv, lu, lv);
}

void add_box(Mesh& m, glm::vec3 lo, glm::vec3 hi, float uv_inches, ChartPacker* charts, int mesh_index, bool bottom) {
  const glm::vec3 d = hi - lo;
  // Each face seen from outside: (origin, edge_u, edge_v) right-handed toward the outward normal,
  // edge_v up (+Z) on the sides. Faces are split into quads of at most 128 inches.
  auto face = [&](glm::vec3 o, glm::vec3 eu, glm::vec3 ev) {
    const int nu = std::max(1, int(std::ceil(glm::length(eu) / 128.0f)));
    const int nv = std::max(1, int(std::ceil(glm::length(ev) / 128.0f)));
    add_rectangle(m, o, eu, ev, nu, nv, uv_inches, charts, mesh_index);
  };
  face({lo.x, lo.y, lo.z}, {d.x, 0, 0}, {0, 0, d.z});        // -Y
  face({hi.x, hi.y, lo.z}, {-d.x, 0, 0}, {0, 0, d.z});       // +Y
  face({hi.x, lo.y, lo.z}, {0, d.y, 0}, {0, 0, d.z});        // +X
  face({lo.x, hi.y, lo.z}, {0, -d.y, 0}, {0, 0, d.z});       // -X
  face({lo.x, lo.y, hi.z}, {d.x, 0, 0}, {0, d.y, 0});        // +Z
  if (bottom) face({lo.x, hi.y, lo.z}, {d.x, 0, 0}, {0, -d.y, 0});  // -Z
}

void add_sphere(Mesh& m, glm::vec3 c, float r, int slices, int stacks) {
  const auto first = static_cast<uint32_t>(m.positions.size());
  for (int j = 0; j <= stacks; ++j)
    for (int i = 0; i <= slices; ++i) {
      const float u = float(i) / slices, v = float(j) / stacks;
      const float phi = 2 * kPi * u, theta = kPi * v;  // theta from the top
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      m.positions.push_back(c + r * n);
      m.normals.push_back(n);
      m.uv0.push_back({u, v});
    }
  // Rows run down from the top: columns along +u (east), rows along -up, so flip the winding.
  std::vector<uint16_t>& idx = indices16(m);
  const uint32_t row = slices + 1;
  for (int j = 0; j < stacks; ++j)
    for (int i = 0; i < slices; ++i) {
      const auto v00 = uint16_t(first + j * row + i), v10 = uint16_t(v00 + 1);
      const auto v01 = uint16_t(v00 + row), v11 = uint16_t(v01 + 1);
      idx.insert(idx.end(), {v00, v11, v10, v00, v01, v11});
    }
}

void add_torus(Mesh& m, glm::vec3 c, float major, float minor, int segments, int sides) {
  const auto first = static_cast<uint32_t>(m.positions.size());
  for (int j = 0; j <= sides; ++j)
    for (int i = 0; i <= segments; ++i) {
      const float u = float(i) / segments, v = float(j) / sides;
      const float phi = 2 * kPi * u, psi = 2 * kPi * v;
      const glm::vec3 radial(std::cos(phi), std::sin(phi), 0);
      const glm::vec3 n = std::cos(psi) * radial + std::sin(psi) * glm::vec3(0, 0, 1);
      m.positions.push_back(c + major * radial + minor * n);
      m.normals.push_back(n);
      m.uv0.push_back({u * 4, v});
    }
  // Columns along +phi (east), rows along +psi (from outside over the top: up on the outside).
  grid_triangles(indices16(m), first, segments, sides);
}

void add_cylinder(Mesh& m, glm::vec3 base, float r, float height, int slices) {
  auto& idx = indices16(m);
  const auto first = static_cast<uint32_t>(m.positions.size());
  for (int j = 0; j <= 1; ++j)
    for (int i = 0; i <= slices; ++i) {
      const float u = float(i) / slices, phi = 2 * kPi * u;
      const glm::vec3 n(std::cos(phi), std::sin(phi), 0);
      m.positions.push_back(base + r * n + glm::vec3(0, 0, j * height));
      m.normals.push_back(n);
      m.uv0.push_back({u * 3, 1.0f - j});
    }
  grid_triangles(idx, first, slices, 1);
  for (int cap = 0; cap <= 1; ++cap) {
    const glm::vec3 n(0, 0, cap ? 1.0f : -1.0f);
    const auto center = uint16_t(m.positions.size());
    m.positions.push_back(base + glm::vec3(0, 0, cap * height));
    m.normals.push_back(n);
    m.uv0.push_back({0.5f, 0.5f});
    for (int i = 0; i <= slices; ++i) {
      const float phi = 2 * kPi * float(i) / slices;
      m.positions.push_back(base + glm::vec3(r * std::cos(phi), r * std::sin(phi), cap * height));
      m.normals.push_back(n);
      m.uv0.push_back({0.5f + 0.5f * std::cos(phi), 0.5f - 0.5f * std::sin(phi)});
    }
    for (int i = 0; i < slices; ++i) {
      const auto a = uint16_t(center + 1 + i), b = uint16_t(a + 1);
      if (cap) idx.insert(idx.end(), {center, a, b});
      else idx.insert(idx.end(), {center, b, a});
    }
  }
}

void compute_tangents(Mesh& m) {
  const size_t n = m.vertex_count();
  std::vector<glm::dvec3> tan(n, glm::dvec3(0)), up(n, glm::dvec3(0));
  for (size_t k = 0; k + 2 < m.index_count(); k += 3) {
    const uint32_t i0 = m.vertex_of_corner(k), i1 = m.vertex_of_corner(k + 1), i2 = m.vertex_of_corner(k + 2);
    const glm::dvec3 e1 = glm::dvec3(m.positions[i1] - m.positions[i0]), e2 = glm::dvec3(m.positions[i2] - m.positions[i0]);
    const glm::dvec2 d1 = glm::dvec2(m.uv0[i1] - m.uv0[i0]), d2 = glm::dvec2(m.uv0[i2] - m.uv0[i0]);
    const double det = d1.x * d2.y - d2.x * d1.y;
    if (std::abs(det) < 1e-12) continue;
    const glm::dvec3 dpdu = (e1 * d2.y - e2 * d1.y) / det, dpdv = (e2 * d1.x - e1 * d2.x) / det;
    for (uint32_t i : {i0, i1, i2}) {
      tan[i] += dpdu;
      up[i] -= dpdv;  // up the image is -v
    }
  }
  m.tangents.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const glm::dvec3 nn = glm::dvec3(m.normals[i]);
    glm::dvec3 t = tan[i] - nn * glm::dot(nn, tan[i]);
    if (glm::length(t) < 1e-9) {  // no u gradient (a pole): across the v gradient, else any
      t = glm::cross(up[i], nn);
      if (glm::length(t) < 1e-9) t = std::abs(nn.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
      t -= nn * glm::dot(nn, t);
    }
    t = glm::normalize(t);
    const float w = glm::dot(glm::cross(nn, t), up[i]) < 0 ? -1.0f : 1.0f;
    m.tangents[i] = glm::vec4(glm::vec3(t), w);
  }
}

void ChartPacker::chart(int mesh, uint32_t first, int nu, int nv, float width, float height) {
  charts_.push_back({mesh, first, nu, nv, std::max(1, int(std::ceil(width / inches_per_luxel_))),
                     std::max(1, int(std::ceil(height / inches_per_luxel_)))});
}

void ChartPacker::pack(std::vector<Mesh>& meshes) const {
  // Shelves: charts from tallest to shortest (stable, so the layout is a function of the order
  // given), left to right, a new shelf when a row is full.
  std::vector<size_t> order(charts_.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return charts_[a].h > charts_[b].h; });
  int area = 0;
  for (const Chart& c : charts_) area += (c.w + 2) * (c.h + 2);
  int atlas = 64;
  for (const Chart& c : charts_) atlas = std::max(atlas, c.w + 2);
  while (atlas * atlas < area * 2) atlas *= 2;  // room for the shelves' waste
  struct Place { int x, y; };
  std::vector<Place> place(charts_.size());
  int x = 0, y = 0, shelf = 0;
  for (size_t i : order) {
    const Chart& c = charts_[i];
    if (x + c.w + 2 > atlas) x = 0, y += shelf, shelf = 0;
    place[i] = {x + 1, y + 1};
    x += c.w + 2;
    shelf = std::max(shelf, c.h + 2);
  }
  const int size = std::max(atlas, y + shelf);
  for (Mesh& m : meshes)
    if (m.uv1.size() != m.positions.size()) m.uv1.assign(m.positions.size(), glm::vec2(0.0f));
  for (size_t i = 0; i < charts_.size(); ++i) {
    const Chart& c = charts_[i];
    Mesh& m = meshes[c.mesh];
    for (int j = 0; j <= c.nv; ++j)
      for (int k = 0; k <= c.nu; ++k) {
        const float s = float(k) / c.nu, t = float(j) / c.nv;
        // t runs up the chart: v = 0 is the atlas's top row.
        m.uv1[c.first + j * (c.nu + 1) + k] = {(place[i].x + s * c.w) / size, (place[i].y + (1.0f - t) * c.h) / size};
      }
  }
}

float hash01(int x, int y, uint32_t seed) {
  uint32_t h = seed * 0x9E3779B9u ^ static_cast<uint32_t>(x) * 0x85EBCA6Bu ^ static_cast<uint32_t>(y) * 0xC2B2AE35u;
  h ^= h >> 16;
  h *= 0x7FEB352Du;
  h ^= h >> 15;
  h *= 0x846CA68Bu;
  h ^= h >> 16;
  return float(h >> 8) / float(1u << 24);
}

float tiled_noise(float u, float v, int period, uint32_t seed) {
  const float x = (u - std::floor(u)) * period, y = (v - std::floor(v)) * period;
  const int x0 = int(x) % period, y0 = int(y) % period;
  const int x1 = (x0 + 1) % period, y1 = (y0 + 1) % period;
  const float fx = x - std::floor(x), fy = y - std::floor(y);
  const float sx = fx * fx * (3 - 2 * fx), sy = fy * fy * (3 - 2 * fy);
  const float a = hash01(x0, y0, seed), b = hash01(x1, y0, seed), c = hash01(x0, y1, seed), d = hash01(x1, y1, seed);
  return (a + (b - a) * sx) + ((c + (d - c) * sx) - (a + (b - a) * sx)) * sy;
}

float tiled_fbm(float u, float v, int period, int octaves, uint32_t seed) {
  float sum = 0, weight = 0.5f, total = 0;
  for (int o = 0; o < octaves; ++o, period *= 2, weight *= 0.5f) {
    sum += weight * tiled_noise(u, v, period, seed + o);
    total += weight;
  }
  return sum / total;
}

}  // namespace luxel::scenes::builtin
