#pragma once
// Scenes built in code for the bake tests: quads with uv1 charts on a grid of atlas cells, a
// closed box, materials of a given albedo.

#include "luxel/bake/bake.hpp"
#include "luxel/scenes/scene.hpp"

#include <glm/geometric.hpp>

#include <string>

namespace luxel::bake::test {

/// A bake of `samples` rays per luxel and per ambient-cube sample, on two threads: enough for the
/// tests' small scenes.
inline BakeSettings quick_bake(int samples) {
  BakeSettings b;
  b.samples = samples;
  b.cube_samples = samples;
  b.threads = 2;
  return b;
}

/// A material that bakes with albedo `albedo` (LightmappedGeneric, no texture) and emits `emissive`.
inline scenes::Material lightmapped(glm::vec3 albedo, glm::vec3 emissive = glm::vec3(0.0f)) {
  scenes::Material m;
  m.name = "test/lightmapped";
  m.family = scenes::ShaderFamily::lightmapped_generic;
  m.color = glm::vec4(albedo, 1.0f);
  m.emissive = emissive;
  return m;
}

/// Appends the quad origin + s edge_u + t edge_v (s, t in [0, 1], two triangles, front toward
/// cross(edge_u, edge_v)) to `mesh`: normal, tangent = edge_u (w = +1, so the bitangent is
/// edge_v's direction when the edges are orthogonal), and uv1 mapping the quad onto the cell
/// (cell_x, cell_y) of a cells x cells grid over the atlas, each cell `pad` luxels of padding
/// around `chart` luxels (atlas side = cells * (chart + 2 pad)).
inline void add_quad(scenes::Mesh& mesh, glm::vec3 origin, glm::vec3 edge_u, glm::vec3 edge_v, int cell_x, int cell_y,
                     int cells, int chart, int pad = 1) {
  const float side = float(cells * (chart + 2 * pad));
  const glm::vec2 lo((cell_x * (chart + 2 * pad) + pad) / side, (cell_y * (chart + 2 * pad) + pad) / side);
  const float size = chart / side;
  const glm::vec3 n = glm::normalize(glm::cross(edge_u, edge_v));
  const uint32_t base = uint32_t(mesh.positions.size());
  const glm::vec2 st[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (const glm::vec2& p : st) {
    mesh.positions.push_back(origin + p.x * edge_u + p.y * edge_v);
    mesh.normals.push_back(n);
    mesh.tangents.push_back(glm::vec4(glm::normalize(edge_u), 1.0f));
    mesh.uv0.push_back(p);
    mesh.uv1.push_back(lo + glm::vec2(p.x, 1.0f - p.y) * size);  // t up the chart: v = 0 is the top row
  }
  auto& idx = std::get<std::vector<uint32_t>>(mesh.indices);
  for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) idx.push_back(base + i);
}

inline scenes::Mesh empty_mesh(std::string name, int material) {
  scenes::Mesh m;
  m.name = std::move(name);
  m.material = material;
  m.indices = std::vector<uint32_t>{};
  return m;
}

/// A closed cube of side `size` inches centered at the origin, its six faces looking inward, each
/// a chart of `chart` luxels in a 3 x 3 cell atlas (luxel size = size / chart). Face 0 (the
/// floor, -Z) uses material 1, the others material 0.
inline scenes::Scene closed_box(float size, int chart, scenes::Material walls, scenes::Material floor) {
  scenes::Scene s;
  s.name = "test:closed-box";
  s.materials = {walls, floor};
  s.lightmap_luxel_size = size / chart;
  const float h = size / 2;
  scenes::Mesh floor_mesh = empty_mesh("floor", 1), walls_mesh = empty_mesh("walls", 0);
  // Inward-facing: edges ordered so cross(edge_u, edge_v) points into the box.
  add_quad(floor_mesh, {-h, -h, -h}, {size, 0, 0}, {0, size, 0}, 0, 0, 3, chart);     // floor, normal +Z
  add_quad(walls_mesh, {-h, -h, h}, {0, size, 0}, {size, 0, 0}, 1, 0, 3, chart);      // ceiling, -Z
  add_quad(walls_mesh, {-h, -h, -h}, {0, size, 0}, {0, 0, size}, 2, 0, 3, chart);     // x = -h, +X
  add_quad(walls_mesh, {h, -h, -h}, {0, 0, size}, {0, size, 0}, 0, 1, 3, chart);      // x = +h, -X
  add_quad(walls_mesh, {-h, -h, -h}, {0, 0, size}, {size, 0, 0}, 1, 1, 3, chart);     // y = -h, +Y
  add_quad(walls_mesh, {-h, h, -h}, {size, 0, 0}, {0, 0, size}, 2, 1, 3, chart);      // y = +h, -Y
  s.meshes = {floor_mesh, walls_mesh};
  return s;
}

/// Luxels (covered texels) of an atlas, for averaging.
inline std::vector<size_t> covered(const LightmapAtlas& a) {
  std::vector<size_t> out;
  for (size_t i = 0; i < a.coverage.size(); ++i)
    if (a.coverage[i] == LuxelCoverage::covered) out.push_back(i);
  return out;
}

}  // namespace luxel::bake::test
