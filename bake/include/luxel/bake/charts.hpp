#pragma once
// Lightmap charts for world meshes without uv1 (vbsp's job in Source: a chart per face).
//
// A mesh that gets charts is first unwelded (three vertices of its own per triangle, every
// attribute copied), so that a vertex on a chart's edge can have a uv1 per chart. Charts grow
// breadth-first from the lowest-numbered triangle not yet in a chart, over shared edges (equal
// end positions), taking a neighbour whose normal is within `angle_degrees` of the seed
// triangle's (so a chart stays within that angle of one plane, never creeping around a curve).
// Each chart is projected onto the seed's plane (u: the seed's edge, of its three, that gives the
// smallest bounding box; v: normal x u),
// measured in luxels at `luxel_size` inches (rounded up, at least 1 x 1), and packed on shelves,
// tallest first, with one empty luxel of padding on every side (so the border rings of
// lightmaps.hpp never reach another chart). The atlas is square, a multiple of 4 luxels, the
// smallest such that the shelves fit (grown by 1/8 at a time). Deterministic: a function of the
// meshes and the two numbers.

#include "luxel/scenes/scene.hpp"

#include <optional>
#include <vector>

namespace luxel::bake {

struct GeneratedCharts {
  int atlas_size = 0;  ///< luxels on a side
  size_t charts = 0;
  /// Per scene mesh: the unwelded mesh with its uv1, for the meshes asked for; nullopt otherwise.
  std::vector<std::optional<scenes::Mesh>> meshes;
};

/// Charts for the meshes with `which[i] != 0`, all in one atlas. Throws BakeError (bake.hpp)
/// when the atlas would exceed `max_side` luxels a side.
GeneratedCharts make_charts(const scenes::Scene& scene, const std::vector<char>& which, float luxel_size,
                            float angle_degrees, int max_side);

}  // namespace luxel::bake
