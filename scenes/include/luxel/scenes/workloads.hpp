#pragma once
// The benchmark workloads shared with the llvmpipe peer (../shared/peers/llvmpipe/README.md),
// rebuilt exactly as that harness defines them, as plain data. They are stated in OpenGL terms
// (NDC depth in [-1, 1], window y up); the renderer maps them to Direct3D conventions.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace luxel::scenes {

/// W1 `fill`: a 64 x 36 grid of quads covering the viewport, drawn as 8 layers, each nearer
/// than the last, with a per-layer color ramped by 0.9 + 0.1 u.
struct FillWorkload {
  static constexpr int kQuadsX = 64, kQuadsY = 36, kLayers = 8;
  struct Vertex {
    glm::vec2 ndc;  ///< x, y in [-1, 1]
    glm::vec2 uv;
  };
  std::vector<Vertex> vertices;     ///< 65 x 37, row-major from the bottom-left
  std::vector<uint16_t> indices;    ///< 4,608 counter-clockwise triangles
  std::array<float, kLayers> layer_ndc_z;       ///< 0.875 - 0.25 k
  std::array<glm::vec3, kLayers> layer_color;
};
FillWorkload make_fill_workload();

/// W2 `tris`: one million small equilateral triangles (2 to 4 pixel^2) with random position,
/// depth, orientation and flat color, from std::mt19937(1).
struct TrisWorkload {
  struct Vertex {
    float x, y;     ///< pixels, origin bottom-left
    float z;        ///< NDC depth in [-1, 1]
    uint32_t rgba;  ///< r | g << 8 | b << 16 | a << 24
  };
  std::vector<Vertex> vertices;  ///< 3 per triangle, counter-clockwise
};
TrisWorkload make_tris_workload(int width, int height, int triangles = 1'000'000);

}  // namespace luxel::scenes
