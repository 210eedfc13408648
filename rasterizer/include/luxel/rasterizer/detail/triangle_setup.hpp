#pragma once
// Private to the rasterizer: what the front end (clip, snap, setup, bin) hands the tile
// rasterizers, and process_triangles, where a draw's vertex stage (detail/vertex_front_end.hpp)
// hands its triangles to the front end. Not templated on shaders, so the front end is compiled
// once, in rasterizer/src: clipping.cpp, triangle_setup.cpp and binning.cpp, with what their
// stages share in front_end.hpp and binning's fast path in binning.hpp.

#include "luxel/rasterizer/fast_paths.hpp"
#include "luxel/rasterizer/limits.hpp"
#include "luxel/rasterizer/simd.hpp"
#include "luxel/rasterizer/state.hpp"

#include <glm/vec4.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace luxel::rasterizer {
struct DrawStats;
}

namespace luxel::rasterizer::detail {

/// Per-draw constants of the front end.
struct DrawConstants {
  // Viewport transform: x_s = vp_x + (ndc_x + 1) * half_w, y_s = vp_y + (1 - ndc_y) * half_h.
  float vp_x = 0, vp_y = 0, half_w = 0, half_h = 0;
  float min_depth = 0, max_depth = 1;
  // The guard band in NDC: outside it triangles are clipped.
  float guard_min_x = -1, guard_max_x = 1, guard_min_y = -1, guard_max_y = 1;
  // The writable pixel rectangle (clip_*) in NDC: a triangle wholly beyond one of its sides is
  // rejected. It, not the viewport, bounds the samples a draw can reach, so a triangle outside a
  // fractional viewport but inside a pixel the viewport overlaps is drawn, as its neighbours are.
  float reject_min_x = -1, reject_max_x = 1, reject_min_y = -1, reject_max_y = 1;
  // Pixels that may be written: scissor, viewport and target intersected; half-open.
  int clip_x0 = 0, clip_y0 = 0, clip_x1 = 0, clip_y1 = 0;
  int tiles_x = 0, tiles_y = 0;
  int samples = 1;
  int varyings = 0;
  RasterizerState rasterizer;
  FastPaths fast_paths;
};

/// E(X, Y) = a X + b Y + c over subpixel coordinates; a sample is inside when E >= 0 for all
/// three edges. c already carries the top-left bias (-1 on edges that are not top or left).
struct Edge {
  int32_t a, b;
  int64_t c;
};

/// A screen-space plane q(x, y) = q0 + dqdx (x - ref_x) + dqdy (y - ref_y), x and y in pixels.
struct Plane {
  float q0, dqdx, dqdy;
};

/// Perspective-correct barycentrics of vertices 1 and 2: b_k = b_k_w / inv_w.
struct Barycentrics {
  Plane inv_w;       ///< 1/w
  Plane b1_w, b2_w;  ///< barycentrics of vertices 1 and 2, divided by w
};

/// A small triangle's three edges side by side, as the tile rasterizer steps them (one 4-lane
/// vector), relative to its record's corner: the corner of pixel (x0, y0) rounded down to a
/// stamp column and row. Exact in 32 bits (see kSmallTriangleSize).
struct alignas(16) SmallEdges {
  int32_t corner[4];  ///< E at the record corner (subpixels), top-left bias included; [3] is 0
  int32_t ab[4];      ///< a in the low 16 bits, b in the high 16 bits (simd::dot_halves); [3] is 0
};

/// A binned triangle. Records differ in size: this header, then the edges (SmallEdges for small
/// triangles, else three Edges), then the varyings, one of
///  - flat: every varying is flat (the same at the three vertices, as in flat-shaded or
///    per-primitive data): one float4 per varying, its value;
///  - affine: equal w at the three vertices (2D and orthographic draws, full-screen passes): per
///    varying four Planes, one per component;
///  - otherwise: Barycentrics and per varying three float4 (the value at vertex 0 and the
///    differences a1 - a0, a2 - a0).
struct alignas(16) TriangleSetup {
  int16_t x0, y0, x1, y1;  ///< pixel bounds (half-open), inside the draw's clip rectangle
  float ref_x, ref_y;      ///< pixels: vertex 0, snapped
  Plane z;                 ///< screen-linear depth, bias included
  uint8_t record_blocks;   ///< size of this record in 16-byte blocks
  /// Flags below, in one byte that setup writes whole: assigning bitfields would read the byte
  /// first, from a record line just allocated and not yet in the cache.
  uint8_t flags;
  static constexpr uint8_t kFrontFacing = 1, kNarrowEdges = 2, kSmall = 4, kAffine = 8, kFlat = 16;

  bool front_facing() const { return flags & kFrontFacing; }
  /// Per-sample edge values of a stamp fit 32-bit integers.
  bool narrow_edges() const { return flags & kNarrowEdges; }
  /// Spans less than kSmallTriangleSize pixels in x and in y: its edges are SmallEdges.
  bool small() const { return flags & kSmall; }
  /// Equal w at the vertices.
  bool affine() const { return flags & kAffine; }
  /// Every varying is flat.
  bool flat() const { return flags & kFlat; }

  /// Small triangles: the edges relative to the record corner.
  const SmallEdges& small_edges() const { return *reinterpret_cast<const SmallEdges*>(this + 1); }
  /// Other triangles: the three edges.
  const Edge* edges() const { return reinterpret_cast<const Edge*>(this + 1); }

  /// Flat: the varyings' values, float4 each.
  const float* flat_varyings() const { return reinterpret_cast<const float*>(varying_data()); }
  /// Affine, not flat: four planes per varying.
  const Plane* varying_planes() const { return reinterpret_cast<const Plane*>(varying_data()); }
  /// Neither flat nor affine: the barycentrics, then three float4 per varying.
  const Barycentrics& barycentrics() const { return *reinterpret_cast<const Barycentrics*>(varying_data()); }
  const float* varying_deltas() const {
    return reinterpret_cast<const float*>(varying_data() + sizeof(Barycentrics));
  }
  const TriangleSetup* next() const {
    return reinterpret_cast<const TriangleSetup*>(reinterpret_cast<const std::byte*>(this) + 16 * record_blocks);
  }

  /// Bytes from the start of a record to its varyings.
  static constexpr size_t varyings_offset(bool small) {
    return sizeof(TriangleSetup) + (small ? sizeof(SmallEdges) : 3 * sizeof(Edge));
  }

 private:
  const std::byte* varying_data() const { return reinterpret_cast<const std::byte*>(this) + varyings_offset(small()); }
};
static_assert(kMaxTargetSize <= INT16_MAX, "pixel bounds are stored in 16 bits");
static_assert(TriangleSetup::varyings_offset(true) == 64, "a small flat-shaded triangle takes 80 bytes with one varying");

/// Bound on |a| * stamp width + |b| * stamp height (subpixels) for the 32-bit per-sample path.
inline constexpr int64_t kNarrowEdgeLimit = int64_t(1) << 29;

/// Triangles narrower and shorter than this (pixels) are "small": their edge values anywhere
/// within kTileSize pixels of their vertices fit comfortably in 32 bits (|a|, |b| < 2^13
/// subpixels, distances < 2^15 subpixels: |E| < 2^29), so the tile rasterizer evaluates them
/// in 32-bit lanes from the first stamp on, without 64-bit row setup or per-stamp bounds.
inline constexpr int kSmallTriangleSize = 32;
static_assert(int64_t(kSmallTriangleSize) * kSubpixelsPerPixel * (kTileSize + kSmallTriangleSize) *
                      kSubpixelsPerPixel * 2 < (int64_t(1) << 30));

/// Bytes of one binned triangle with `varyings` float4 interpolants.
constexpr size_t triangle_record_size(int varyings, bool small, bool flat, bool affine) {
  const size_t bytes = TriangleSetup::varyings_offset(small) +
                       (flat     ? sizeof(float) * 4 * varyings
                        : affine ? sizeof(Plane) * 4 * varyings
                                 : sizeof(Barycentrics) + sizeof(float) * 12 * varyings);
  return (bytes + 15) / 16 * 16;
}
static_assert(triangle_record_size(kMaxVaryings, false, false, false) / 16 <= UINT8_MAX);

/// A growable byte stream that, unlike std::vector, does not zero what it appends.
class RecordStream {
 public:
  std::byte* append(size_t bytes) {
    if (size_ + bytes > capacity_) grow(size_ + bytes);
    std::byte* p = data_.get() + size_;
    size_ += bytes;
    // A draw appends to many streams in turn (one per tile), too many for the CPU's stream
    // prefetchers: without this, every new line's first store waited for the line to arrive.
    simd::prefetch_for_write(p + bytes);
    simd::prefetch_for_write(p + bytes + 64);
    return p;
  }
  const std::byte* data() const { return data_.get(); }
  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  void clear() { size_ = 0; }

 private:
  void grow(size_t needed);
  std::unique_ptr<std::byte[]> data_;
  size_t size_ = 0, capacity_ = 0;
};

/// One chunk of a draw's triangles, binned: per tile, the records of the triangles that touch it
/// back to back in submission order, so that a tile reads its triangles as one stream.
struct ChunkBins {
  std::vector<RecordStream> tile_records;  ///< at least one per tile; the first tile_count in use
  std::vector<uint32_t> touched_tiles;
  int tile_count = 0;

  /// Empties the chunk for a draw over `tile_count` tiles. The streams keep their buffers whatever
  /// the tiling: a frame changes tilings from pass to pass, and streams freed at each change made
  /// the next draws allocate and fault in a buffer per tile again.
  void reset(int tile_count);
  /// The records' bytes and the per-tile streams' own: what the chunk costs until the flush.
  size_t bytes() const;
};

/// The front end takes triangles in batches of at most this many: the vertex functor runs for a
/// whole batch, then setup (kLanes triangles at a time), then binning. Setup reads vertex
/// outputs in other widths than a functor writes them (a float4 compared or copied whole after
/// four float stores), which the CPU cannot forward from its store buffer; read right after the
/// functor, each such load waited until every older store, the binned records' included, had
/// reached the cache. A batch later, the vertices are in the cache.
inline constexpr int kFrontEndBatch = 16;

/// Clips, sets up and bins `count` (at most kFrontEndBatch) triangles, in order.
/// `vertices[3 t + k]` points at the clip-space position of vertex k of triangle t, followed by
/// dc.varyings float4 interpolants.
void process_triangles(const DrawConstants& dc, const glm::vec4* const* vertices, int count, ChunkBins& bins,
                       DrawStats& stats);

/// Most vertices of a clipped polygon: a triangle plus one per clip plane (near, far, the four of
/// the guard band), as a plane adds at most one vertex to a convex polygon. Rounding in the
/// intersections can leave a near-degenerate polygon slightly non-convex, and one plane can then
/// add more; the clipper drops such a triangle (DrawStats::clip_overflow) instead.
inline constexpr int kMaxClipVertices = 3 + 6;

/// A vertex being clipped: position then varyings, all float4.
struct ClipVertex {
  float v[4 * (1 + kMaxVaryings)];
};

/// Sutherland-Hodgman: the polygon in[0, n) cut to dot(plane, position) >= 0 into `out` (room for
/// kMaxClipVertices), interpolating the first `floats` floats of each vertex. Returns the new
/// vertex count, or -1 when that would exceed kMaxClipVertices (out is then partly written).
int clip_polygon(const glm::vec4& plane, const ClipVertex* in, int n, ClipVertex* out, int floats);

}  // namespace luxel::rasterizer::detail
