#pragma once
// Per-vertex tangents for meshes that have normals and uv0 but no tangents, following
// MikkTSpace (the glTF specification's choice) as its reference implementation defines them:
//
//  1. Per triangle, the texture-space tangent dP/du (the first UV derivative of position) and the
//     orientation: whether the triangle's UV winding is preserved (signed UV area > 0).
//  2. Per corner, that tangent projected onto the plane of the corner's vertex normal and
//     normalized, weighted by the corner's angle (between its two edges, also projected onto
//     that plane).
//  3. Per vertex and orientation, the weighted sum normalized; handedness w = +1 for
//     orientation-preserving triangles, -1 for mirrored ones. A vertex used by triangles of both
//     orientations is split: the mirrored side gets a copy of the vertex (all attributes), so
//     each gets the tangent of its own side, as MikkTSpace's output vertices do.
//
// UVs are glTF's (v down the image); MikkTSpace is evaluated with v up (v' = 1 - v), as
// Blender's exporter and three.js's computeMikkTSpaceTangents(negateSign) do, so that the
// bitangent w * cross(n, t) points up the image (towards decreasing glTF v), the direction a
// glTF (OpenGL-convention, +Y up) normal map's green channel means.
//
// Departures from the reference, on purpose: vertices are the index buffer's vertices
// (MikkTSpace also welds distinct vertices with equal position, normal and uv; glTF exporters
// share those already), and a vertex whose triangles all have degenerate UVs gets an arbitrary
// unit tangent perpendicular to its normal (the reference copies one from a neighbour).

#include "luxel/scenes/scene.hpp"

namespace luxel::scenes {

/// Fills mesh.tangents (and may append vertices, see above). Requires normals and uv0 on every
/// vertex; throws std::invalid_argument otherwise.
void generate_tangents(Mesh& mesh);

}  // namespace luxel::scenes
