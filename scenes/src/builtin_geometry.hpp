#pragma once
// Private: the shapes built-in scenes are made of (boxes, spheres, tori, cylinders), their
// tangent frames, lightmap charts, and the procedural noise their textures are made with.

#include "luxel/scenes/scene.hpp"

#include <cstdint>
#include <numbers>
#include <vector>

namespace luxel::scenes::builtin {

inline constexpr float kPi = std::numbers::pi_v<float>;

class ChartPacker;

/// Appends a planar rectangle `origin + s edge_u + t edge_v` (s, t in [0, 1]), front face toward
/// cross(edge_u, edge_v), split into nu x nv quads. uv0 is planar: `uv_inches` world inches per
/// texture repeat, u along edge_u, v down the image against edge_v (so edge_v is "up" on the
/// texture). With `charts`, the rectangle becomes one lightmap chart of mesh `mesh_index`.
/// Indices go to whichever list (16 or 32 bits) the mesh holds.
void add_rectangle(Mesh& mesh, glm::vec3 origin, glm::vec3 edge_u, glm::vec3 edge_v, int nu, int nv,
                   float uv_inches, ChartPacker* charts = nullptr, int mesh_index = -1);

/// An axis-aligned box, each face a rectangle (and a chart, with `charts`); without its bottom
/// face unless `bottom` (a box resting on the floor never shows it).
void add_box(Mesh& mesh, glm::vec3 min, glm::vec3 max, float uv_inches, ChartPacker* charts = nullptr,
             int mesh_index = -1, bool bottom = false);

/// A UV sphere (uv0: u around, v from the top), 16-bit indices.
void add_sphere(Mesh& mesh, glm::vec3 center, float radius, int slices, int stacks);
/// A torus around the +Z axis through `center`, 16-bit indices.
void add_torus(Mesh& mesh, glm::vec3 center, float major, float minor, int segments, int sides);
/// A closed cylinder standing on `base`, 16-bit indices.
void add_cylinder(Mesh& mesh, glm::vec3 base, float radius, float height, int slices);

/// Tangents from the uv0 derivatives of each triangle (summed per vertex, made orthogonal to the
/// normal), with handedness w = +-1 such that w cross(n, t) points up the image (-v), the glTF
/// convention scene.hpp states.
void compute_tangents(Mesh& mesh);

/// Lightmap charts: each rectangle given to it becomes one chart, sized by its world size at
/// `inches_per_luxel`; pack() lays all charts out on shelves, one luxel of padding around each,
/// without overlap inside [0, 1]^2, and writes the meshes' uv1.
class ChartPacker {
 public:
  explicit ChartPacker(float inches_per_luxel) : inches_per_luxel_(inches_per_luxel) {}
  /// The (nu + 1) x (nv + 1) grid of vertices from `first` (row by row) of mesh `mesh` spans a
  /// rectangle of width x height inches.
  void chart(int mesh, uint32_t first, int nu, int nv, float width, float height);
  /// Writes uv1 of every charted vertex (each charted mesh's uv1 sized to its positions first).
  void pack(std::vector<Mesh>& meshes) const;

 private:
  struct Chart {
    int mesh;
    uint32_t first;
    int nu, nv;
    int w, h;  // luxels, padding excluded
  };
  float inches_per_luxel_;
  std::vector<Chart> charts_;
};

/// Value noise on a grid of `period` cells that tiles over [0, 1)^2, smooth (cubic Hermite), in
/// [0, 1]. Deterministic: a function of its arguments only.
float tiled_noise(float u, float v, int period, uint32_t seed);
/// A few octaves of tiled_noise, each twice the frequency and half the weight, in [0, 1].
float tiled_fbm(float u, float v, int period, int octaves, uint32_t seed);
/// A hash of three integers to [0, 1).
float hash01(int x, int y, uint32_t seed);

}  // namespace luxel::scenes::builtin
