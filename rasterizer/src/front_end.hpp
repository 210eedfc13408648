#pragma once
// What the front end's stages share: triangles in lanes, snapped and set up (triangle_setup.cpp)
// as binning.cpp reads them, and the calls from one stage's file into another's.

#include "luxel/rasterizer/detail/triangle_setup.hpp"

#include "luxel/rasterizer/simd.hpp"

#include <glm/vec4.hpp>

#include <bit>
#include <cstddef>
#include <cstdint>

namespace luxel::rasterizer {
struct DrawStats;
}

namespace luxel::rasterizer::detail {

static_assert(std::has_single_bit(unsigned(kTileSize)));
inline constexpr int kTileShift = std::countr_zero(unsigned(kTileSize));

/// Screen-space gradients of values at the snapped vertices: the two edge vectors from vertex
/// 0 (pixels) and one over their cross product (the signed doubled area).
struct PlaneBasis {
  double e1x, e1y, e2x, e2y, inv_det;

  Plane plane(double q0, double q1, double q2) const {
    const double d1 = q1 - q0, d2 = q2 - q0;
    return {static_cast<float>(q0), static_cast<float>((d1 * e2y - d2 * e1y) * inv_det),
            static_cast<float>((d2 * e1x - d1 * e2x) * inv_det)};
  }
};

/// Snapped screen positions of kLanes vertices, lane l from rows[l].
struct SnappedLanes {
  alignas(64) int32_t X[simd::kLanes], Y[simd::kLanes];
  alignas(64) float x[simd::kLanes], y[simd::kLanes], z[simd::kLanes], inv_w[simd::kLanes];
};

/// Snaps kLanes vertices to 1/256 pixel (triangle_setup.cpp).
simd::LaneBits snap_vertices(const DrawConstants& dc, const float* const* rows, SnappedLanes& out,
                             simd::LaneBits& in_view);

/// kLanes triangles, lane l triangle l: where each vertex's data is (position, then varyings),
/// and the vertices snapped.
struct TriangleLanes {
  const float* data[3][simd::kLanes];
  SnappedLanes vertex[3];
  simd::LaneBits snappable = 0;  ///< lanes whose three vertices snapped
  simd::LaneBits in_view = 0;    ///< lanes whose three vertices lie inside the view volume

  /// Snaps the vertices of triangles 0..count-1; the lanes above become copies of the last
  /// triangle (so that every lane reads valid data) and are left out of both masks.
  void snap(const DrawConstants& dc, int count) {
    const simd::LaneBits lanes = simd::kAllLanes >> (simd::kLanes - count);
    snappable = in_view = lanes;
    for (int k = 0; k < 3; ++k) {
      for (int l = count; l < simd::kLanes; ++l) data[k][l] = data[k][count - 1];
      simd::LaneBits view;
      snappable &= snap_vertices(dc, data[k], vertex[k], view);
      in_view &= view;
    }
  }
};

/// What setup computes for kLanes triangles at once, lane l for triangle l. The products of
/// subpixel coordinates (the doubled area, up to 2^48) are exact in doubles, as the planes were
/// computed in doubles one triangle at a time: the results are the same bits.
struct SetupLanes {
  alignas(64) int32_t x0[simd::kLanes], y0[simd::kLanes], x1[simd::kLanes], y1[simd::kLanes];
  alignas(64) int32_t tile[simd::kLanes];  ///< the tile of pixel (x0, y0)
  alignas(64) double e1x[simd::kLanes], e1y[simd::kLanes], e2x[simd::kLanes], e2y[simd::kLanes];
  alignas(64) double inv_det[simd::kLanes];
  /// Lane l's record as write_record writes it: the TriangleSetup header, and SmallEdges (small
  /// lanes). Built in lanes and transposed: writing a record is two 32-byte copies.
  alignas(32) int32_t header[simd::kLanes][8];
  alignas(32) int32_t small_edges[simd::kLanes][8];
  simd::LaneBits zero_area = 0;  ///< degenerate after snapping
  simd::LaneBits culled = 0;     ///< facing away by the cull mode (zero-area lanes excluded)
  simd::LaneBits empty = 0;      ///< no pixel inside the clip rectangle
  simd::LaneBits clockwise = 0;  ///< on screen, y down
  simd::LaneBits small = 0;      ///< TriangleSetup::small
  simd::LaneBits affine = 0;     ///< equal 1/w at the three vertices
  simd::LaneBits one_tile = 0;   ///< all pixels in `tile`

  PlaneBasis basis(int l) const { return {e1x[l], e1y[l], e2x[l], e2y[l], inv_det[l]}; }
  /// Lanes that are set up but will not be binned.
  simd::LaneBits rejected() const { return zero_area | culled | empty; }
};

// The header as setup_lanes lays it out: eight 32-bit fields.
static_assert(sizeof(TriangleSetup) == 32 && offsetof(TriangleSetup, x0) == 0 && offsetof(TriangleSetup, y0) == 2 &&
              offsetof(TriangleSetup, x1) == 4 && offsetof(TriangleSetup, y1) == 6 &&
              offsetof(TriangleSetup, ref_x) == 8 && offsetof(TriangleSetup, ref_y) == 12 &&
              offsetof(TriangleSetup, z) == 16 && sizeof(Plane) == 12 &&
              offsetof(TriangleSetup, record_blocks) == 28 && offsetof(TriangleSetup, flags) == 29);
static_assert(sizeof(SmallEdges) == 32);

/// Edge k of triangle l, on its vertices in positive (clockwise) order (triangle_setup.cpp).
Edge lane_edge(const TriangleLanes& tri, const SetupLanes& setup, int l, int k);

/// Sets up and bins the fan of an n-gon (triangle_setup.cpp).
void setup_fan(const DrawConstants& dc, const float* const* polygon, int n, ChunkBins& bins, DrawStats& stats);

/// The path of a triangle not wholly inside the view volume (clipping.cpp).
void clip_and_bin(const DrawConstants& dc, const glm::vec4* const vertices[3], ChunkBins& bins, DrawStats& stats);

}  // namespace luxel::rasterizer::detail
