// Binning: the per-tile record streams, and each set-up triangle's record written into every
// 64x64 tile it touches (less those wholly outside an edge). The one-tile fast path, inlined into
// setup, is binning.hpp.

#include "binning.hpp"

#include "front_end.hpp"
#include "luxel/rasterizer/detail/triangle_setup.hpp"

#include <glm/vec4.hpp>

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <new>

namespace luxel::rasterizer::detail {

void RecordStream::grow(size_t needed) {
  const size_t capacity = std::max<size_t>({needed, 2 * capacity_, 4096});
  std::unique_ptr<std::byte[]> data(new std::byte[capacity]);  // uninitialized: records are written whole
  if (size_) std::memcpy(data.get(), data_.get(), size_);
  data_ = std::move(data);
  capacity_ = capacity;
}

size_t ChunkBins::bytes() const {
  size_t bytes = size_t(tile_count) * sizeof(RecordStream);
  for (uint32_t t : touched_tiles) bytes += tile_records[t].size();
  return bytes;
}

void ChunkBins::reset(int tiles) {
  for (uint32_t t : touched_tiles) tile_records[t].clear();
  touched_tiles.clear();
  if (tile_records.size() < size_t(tiles)) tile_records.resize(size_t(tiles));
  tile_count = tiles;
}

/// The parts of a record after its header, for any triangle but a small flat-shaded one (out of
/// line: rare in the workloads where setup is the bottleneck): wide edges, interpolated varyings.
[[gnu::noinline]] void write_record_rest(const DrawConstants& dc, const TriangleLanes& tri, const SetupLanes& setup,
                                         int l, std::byte* record) {
  const int flags = setup.header[l][7] >> 8;
  const bool small = flags & TriangleSetup::kSmall;
  if (small) {
    std::memcpy(record + sizeof(TriangleSetup), setup.small_edges[l], sizeof(SmallEdges));
  } else {
    Edge* e = ::new (record + sizeof(TriangleSetup)) Edge[3];
    for (int k = 0; k < 3; ++k) e[k] = lane_edge(tri, setup, l, k);
  }
  const glm::vec4* a[3];  // the varyings of the three vertices
  for (int k = 0; k < 3; ++k) a[k] = reinterpret_cast<const glm::vec4*>(tri.data[k][l]) + 1;
  std::byte* tail = record + TriangleSetup::varyings_offset(small);
  if (flags & TriangleSetup::kFlat) {
    for (int i = 0; i < dc.varyings; ++i) std::memcpy(tail + 16 * i, &a[0][i], 16);
    return;
  }
  // Planes in the vertices' own order.
  const PlaneBasis basis = setup.basis(l);
  if (flags & TriangleSetup::kAffine) {
    // Equal w: varyings are linear on screen, a plane per component (a constant one exactly).
    Plane* planes = reinterpret_cast<Plane*>(tail);
    for (int i = 0; i < dc.varyings; ++i)
      for (int c = 0; c < 4; ++c) planes[4 * i + c] = basis.plane(a[0][i][c], a[1][i][c], a[2][i][c]);
    return;
  }
  // Perspective-correct barycentrics: b_k = (b_k / w) / (1 / w).
  const SnappedLanes* v = tri.vertex;
  Barycentrics& bary = *::new (tail) Barycentrics;
  bary.inv_w = basis.plane(v[0].inv_w[l], v[1].inv_w[l], v[2].inv_w[l]);
  bary.b1_w = basis.plane(0.0, v[1].inv_w[l], 0.0);
  bary.b2_w = basis.plane(0.0, 0.0, v[2].inv_w[l]);
  float* d = reinterpret_cast<float*>(tail + sizeof(Barycentrics));
  for (int i = 0; i < dc.varyings; ++i, d += 12) {
    for (int c = 0; c < 4; ++c) {
      d[c] = a[0][i][c];
      d[4 + c] = a[1][i][c] - a[0][i][c];
      d[8 + c] = a[2][i][c] - a[0][i][c];
    }
  }
}

/// Writes triangle l's record (set up and not rejected) into every tile it touches (less those
/// wholly outside an edge).
[[gnu::noinline]] void bin_to_tiles(const DrawConstants& dc, const TriangleLanes& tri, const SetupLanes& setup, int l,
                                    ChunkBins& bins) {
  const int tx0 = setup.x0[l] >> kTileShift, ty0 = setup.y0[l] >> kTileShift;
  const int tx1 = (setup.x1[l] - 1) >> kTileShift, ty1 = (setup.y1[l] - 1) >> kTileShift;
  const Edge edges[3] = {lane_edge(tri, setup, l, 0), lane_edge(tri, setup, l, 1), lane_edge(tri, setup, l, 2)};
  const size_t bytes = record_bytes(setup, l);
  // The record is the same in every tile: written from setup's rows once (its planes are computed
  // in double), copied after.
  const std::byte* first = nullptr;
  for (int ty = ty0; ty <= ty1; ++ty) {
    for (int tx = tx0; tx <= tx1; ++tx) {
      const int64_t X0 = int64_t(tx) * kTileSize * kSubpixelsPerPixel, X1 = X0 + kTileSize * kSubpixelsPerPixel - 1;
      const int64_t Y0 = int64_t(ty) * kTileSize * kSubpixelsPerPixel, Y1 = Y0 + kTileSize * kSubpixelsPerPixel - 1;
      bool outside = false;
      for (const Edge& e : edges) {
        const int64_t emax = e.c + std::max(e.a * X0, e.a * X1) + std::max(e.b * Y0, e.b * Y1);
        outside |= emax < 0;
      }
      if (outside) continue;
      std::byte* record = append_to_tile(bins, ty * dc.tiles_x + tx, bytes);  // another stream than `first`'s
      if (first) {
        std::memcpy(record, first, bytes);
      } else {
        write_record(dc, tri, setup, l, record);
        first = record;
      }
    }
  }
}

}  // namespace luxel::rasterizer::detail
