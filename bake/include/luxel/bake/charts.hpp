#pragma once
// Lightmap charts for meshes without uv1 (vbsp's job in Source: a face per chart).
//
// Triangles join a chart when they share an edge (same vertex indices, or the same positions) and
// their normals differ by less than `angle_degrees` (coplanar within a tolerance). Each chart is
// projected onto its plane (axes: the first triangle's longest edge and the normal cross it),
// measured in luxels at `luxel_size` inches (rounded up, at least 1 x 1), and packed on shelves,
// tallest first, with one empty luxel of padding on every side so that the border rings of
// lightmaps.hpp never meet another chart. The atlas is square, the smallest multiple of 4 luxels
// that holds the shelves. Deterministic: a function of the meshes and the two numbers.

#include "luxel/scenes/scene.hpp"

#include <glm/vec2.hpp>

#include <vector>

namespace luxel::bake {

struct GeneratedCharts {
  int atlas_size = 0;                          ///< luxels on a side
  size_t charts = 0;
  std::vector<std::vector<glm::vec2>> uv1;     ///< per scene mesh; empty for meshes not asked for
};

/// Charts for the meshes `which[i] != 0`, all in one atlas. Meshes are read through their
/// indices; the uv1 returned has one entry per vertex, so vertices shared by two charts are not
/// possible: such meshes must be unwelded first (the baker does it, see bake.cpp). Throws
/// BakeError when the atlas would exceed `max_side` luxels.
GeneratedCharts make_charts(const scenes::Scene& scene, const std::vector<char>& which, float luxel_size,
                            float angle_degrees, int max_side);

}  // namespace luxel::bake
