// The front end of a draw: trivial reject, clipping (near, far, guard band), perspective divide,
// viewport transform, snapping to 1/256 pixel, culling, edge and plane setup, and binning.

#include "luxel/rasterizer/detail/triangle_setup.hpp"

#include "luxel/rasterizer/draw.hpp"
#include "luxel/rasterizer/msaa.hpp"
#include "luxel/rasterizer/simd.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
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

void ChunkBins::reset(int tile_count) {
  if (static_cast<int>(tile_records.size()) != tile_count) {
    tile_records.clear();
    tile_records.resize(tile_count);
  } else {
    for (uint32_t t : touched_tiles) tile_records[t].clear();
  }
  touched_tiles.clear();
  staged.clear();
  staged_triangles.clear();
}

namespace {

constexpr int kMaxClipVertices = 3 + 6;  // each of the 6 clip planes adds at most one vertex
constexpr int kFloatsPerVertex = 4 * (1 + kMaxVaryings);

/// A vertex being clipped: position then varyings, all float4.
struct ClipVertex {
  float v[kFloatsPerVertex];
};

/// Clip planes: a vertex is inside when dot(plane, position) >= 0.
struct ClipPlanes {
  glm::vec4 plane[6];
};

ClipPlanes make_clip_planes(const DrawConstants& dc) {
  return {{
      {0, 0, 1, 0},                   // near: z >= 0
      {0, 0, -1, 1},                  // far: z <= w
      {1, 0, 0, -dc.guard_min_x},     // x >= guard_min_x * w
      {-1, 0, 0, dc.guard_max_x},     // x <= guard_max_x * w
      {0, 1, 0, -dc.guard_min_y},
      {0, -1, 0, dc.guard_max_y},
  }};
}

float plane_distance(const glm::vec4& plane, const float* p) {
  return plane.x * p[0] + plane.y * p[1] + plane.z * p[2] + plane.w * p[3];
}

/// Sutherland-Hodgman against one plane; returns the new vertex count.
int clip_polygon(const glm::vec4& plane, const ClipVertex* in, int n, ClipVertex* out, int floats) {
  int m = 0;
  for (int i = 0; i < n; ++i) {
    const ClipVertex& a = in[i];
    const ClipVertex& b = in[(i + 1) % n];
    const float da = plane_distance(plane, a.v);
    const float db = plane_distance(plane, b.v);
    if (da >= 0) out[m++] = a;
    if ((da >= 0) != (db >= 0)) {
      // Interpolate from the inside vertex so that a shared edge clips to the same point from
      // both of its triangles (watertight clipping).
      const bool a_inside = da >= 0;
      const ClipVertex& from = a_inside ? a : b;
      const ClipVertex& to = a_inside ? b : a;
      const float dfrom = a_inside ? da : db, dto = a_inside ? db : da;
      const float t = dfrom / (dfrom - dto);
      ClipVertex& v = out[m++];
      for (int k = 0; k < floats; ++k) v.v[k] = from.v[k] + t * (to.v[k] - from.v[k]);
    }
  }
  return m;
}

bool finite_position(const glm::vec4& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
}

struct ScreenVertex {
  int32_t X, Y;    // subpixels
  float x, y;      // pixels (snapped)
  float z, inv_w;
};

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

Edge make_edge(int32_t x0, int32_t y0, int32_t x1, int32_t y1) {
  const int32_t dx = x1 - x0, dy = y1 - y0;
  Edge e{-dy, dx, int64_t(dy) * x0 - int64_t(dx) * y0};
  // Top-left rule (y down, interior on the positive side): left edges go up, top edges are
  // horizontal and go right. Samples exactly on other edges are outside.
  const bool top_left = dy < 0 || (dy == 0 && dx > 0);
  if (!top_left) e.c -= 1;
  return e;
}

/// Snapped screen positions of kLanes vertices, lane l from rows[l].
struct SnappedLanes {
  alignas(64) int32_t X[simd::kLanes], Y[simd::kLanes];
  alignas(64) float x[simd::kLanes], y[simd::kLanes], z[simd::kLanes], inv_w[simd::kLanes];

  ScreenVertex vertex(int l) const { return {X[l], Y[l], x[l], y[l], z[l], inv_w[l]}; }
};

/// Snaps kLanes vertices (clip-space positions rows[l]) to 1/256 pixel. Every vertex is snapped
/// here, clipped or not, so a vertex shared by a clipped and an unclipped triangle lands on the
/// same subpixel. Returns the lanes that can be set up: w positive with a finite reciprocal, and
/// within twice the guard band. Clipping leaves every vertex inside the band up to rounding,
/// which is a few pixels when a near-plane intersection has w close to 0 (seen: 8 px), and
/// unbounded when an intersection parameter rounds to 1 between vertices whose w differ by 30
/// orders of magnitude (garbage input): the outside vertex itself comes back. Twice the band keeps
/// the former, whose 64-bit edge constants still fit with room to spare, and drops the latter,
/// whose subpixel coordinates would overflow. `in_view` gets the lanes inside the view volume
/// with finite coordinates (process_triangle's inside_view): a triangle of three such vertices
/// needs no clipping.
simd::LaneBits snap_vertices(const DrawConstants& dc, const float* const* rows, SnappedLanes& out,
                             simd::LaneBits& in_view) {
  using simd::Float;
  using simd::Int;
  Float px, py, pz, pw;
  simd::transpose_rows(rows, px, py, pz, pw);
  const Float one(1.0f), zero(0.0f);
  const Float rw = one / pw;
  const Float sx = xsimd::fma(xsimd::fma(px, rw, one), Float(dc.half_w), Float(dc.vp_x));
  const Float sy = xsimd::fma(xsimd::fma(-py, rw, one), Float(dc.half_h), Float(dc.vp_y));
  const Float band(2.0f * kGuardBand);
  const auto snappable = (pw > zero) & (rw - rw == zero) & (xsimd::abs(sx) <= band) & (xsimd::abs(sy) <= band);
  const auto view = (xsimd::abs(px) <= pw) & (xsimd::abs(py) <= pw) & (pz >= zero) & (pz <= pw) & (pw - pw == zero);
  const Int ix = simd::round_to_int(sx * Float(float(kSubpixelsPerPixel)));
  const Int iy = simd::round_to_int(sy * Float(float(kSubpixelsPerPixel)));
  ix.store_aligned(out.X);
  iy.store_aligned(out.Y);
  (xsimd::batch_cast<float>(ix) * Float(1.0f / kSubpixelsPerPixel)).store_aligned(out.x);
  (xsimd::batch_cast<float>(iy) * Float(1.0f / kSubpixelsPerPixel)).store_aligned(out.y);
  xsimd::fma(pz * rw, Float(dc.max_depth - dc.min_depth), Float(dc.min_depth)).store_aligned(out.z);
  rw.store_aligned(out.inv_w);
  in_view = simd::to_bits(view);
  return simd::to_bits(snappable);
}

/// Sets up and bins one triangle from its snapped vertices; `v[k]` points at vertex k's position,
/// followed by its varyings.
void setup_snapped(const DrawConstants& dc, const float* const v[3], const ScreenVertex s[3], ChunkBins& bins,
                   DrawStats& stats) {
  const int64_t area2 = int64_t(s[1].X - s[0].X) * (s[2].Y - s[0].Y) - int64_t(s[2].X - s[0].X) * (s[1].Y - s[0].Y);
  if (area2 == 0) {
    ++stats.degenerate;
    return;
  }
  const bool clockwise = area2 > 0;  // on screen, y down
  const CullMode cull = dc.rasterizer.cull;
  if ((cull == CullMode::CW && clockwise) || (cull == CullMode::CCW && !clockwise)) {
    ++stats.culled;
    return;
  }

  // Bounds: a sample lies in [0, 240] subpixels from its pixel's corner, so the pixels that
  // may hold a covered sample are those that meet the vertices' bounding box.
  const int32_t min_x = std::min({s[0].X, s[1].X, s[2].X}), max_x = std::max({s[0].X, s[1].X, s[2].X});
  const int32_t min_y = std::min({s[0].Y, s[1].Y, s[2].Y}), max_y = std::max({s[0].Y, s[1].Y, s[2].Y});
  const int x0 = std::max(dc.clip_x0, min_x >> kSubpixelBits);
  const int y0 = std::max(dc.clip_y0, min_y >> kSubpixelBits);
  const int x1 = std::min(dc.clip_x1, (max_x >> kSubpixelBits) + 1);
  const int y1 = std::min(dc.clip_y1, (max_y >> kSubpixelBits) + 1);
  if (x0 >= x1 || y0 >= y1) {
    ++stats.degenerate;
    return;
  }

  // Flat varyings (the same finite bits at the three vertices) interpolate to their value at
  // vertex 0: the record stores that alone and no barycentrics.
  const glm::vec4* a[3] = {reinterpret_cast<const glm::vec4*>(v[0]) + 1, reinterpret_cast<const glm::vec4*>(v[1]) + 1,
                           reinterpret_cast<const glm::vec4*>(v[2]) + 1};
  bool flat = true;
  for (int i = 0; i < dc.varyings && flat; ++i) {
    const glm::vec4& a0 = a[0][i];
    const float zero = a0.x * 0.0f + a0.y * 0.0f + a0.z * 0.0f + a0.w * 0.0f;  // NaN unless all finite
    flat = std::memcmp(&a[1][i], &a0, sizeof(glm::vec4)) == 0 && std::memcmp(&a[2][i], &a0, sizeof(glm::vec4)) == 0 &&
           zero == 0.0f;
  }
  const bool affine = s[0].inv_w == s[1].inv_w && s[0].inv_w == s[2].inv_w;
  const size_t size = triangle_record_size(dc.varyings, flat, affine);

  // The record is written in place, in the stage (see ChunkBins).
  static_assert(std::has_single_bit(unsigned(kTileSize)));
  constexpr int kTileShift = std::countr_zero(unsigned(kTileSize));
  bins.staged_triangles.push_back({static_cast<uint32_t>(bins.staged.size()), static_cast<uint16_t>(x0 >> kTileShift),
                                   static_cast<uint16_t>(y0 >> kTileShift), static_cast<uint16_t>((x1 - 1) >> kTileShift),
                                   static_cast<uint16_t>((y1 - 1) >> kTileShift)});
  std::byte* record = bins.staged.append(size);
  TriangleSetup& t = *::new (record) TriangleSetup;
  t.x0 = static_cast<int16_t>(x0);
  t.y0 = static_cast<int16_t>(y0);
  t.x1 = static_cast<int16_t>(x1);
  t.y1 = static_cast<int16_t>(y1);
  t.record_blocks = static_cast<uint8_t>(size / 16);
  t.flat = flat;

  // Edges on the vertices in positive (clockwise) order.
  const int i1 = clockwise ? 1 : 2, i2 = clockwise ? 2 : 1;
  t.edge[0] = make_edge(s[0].X, s[0].Y, s[i1].X, s[i1].Y);
  t.edge[1] = make_edge(s[i1].X, s[i1].Y, s[i2].X, s[i2].Y);
  t.edge[2] = make_edge(s[i2].X, s[i2].Y, s[0].X, s[0].Y);
  const bool small = max_x - min_x < kSmallTriangleSize * kSubpixelsPerPixel &&
                     max_y - min_y < kSmallTriangleSize * kSubpixelsPerPixel;
  bool narrow_edges = true;  // always for small triangles
  if (!small) {
    for (const Edge& e : t.edge) {
      const int64_t span = std::abs(int64_t(e.a)) * (simd::kStampWidth * kSubpixelsPerPixel) +
                           std::abs(int64_t(e.b)) * (simd::kStampHeight * kSubpixelsPerPixel);
      if (span > kNarrowEdgeLimit) narrow_edges = false;
    }
  }
  t.small = small;
  t.narrow_edges = narrow_edges;

  // Planes, in the vertices' own order.
  const double scale = 1.0 / kSubpixelsPerPixel;
  const PlaneBasis basis{(s[1].X - s[0].X) * scale, (s[1].Y - s[0].Y) * scale, (s[2].X - s[0].X) * scale,
                         (s[2].Y - s[0].Y) * scale, double(kSubpixelsPerPixel) * kSubpixelsPerPixel / double(area2)};
  t.ref_x = s[0].x;
  t.ref_y = s[0].y;
  Plane z = basis.plane(s[0].z, s[1].z, s[2].z);
  if (dc.rasterizer.depth_bias != 0 || dc.rasterizer.slope_scaled_depth_bias != 0) {
    const float slope = std::max(std::abs(z.dqdx), std::abs(z.dqdy));
    z.q0 += dc.rasterizer.depth_bias + dc.rasterizer.slope_scaled_depth_bias * slope;
  }
  t.z = z;
  t.front_facing = dc.rasterizer.front_counter_clockwise ? !clockwise : clockwise;
  t.affine = affine;

  std::byte* tail = record + sizeof(TriangleSetup);
  if (flat) {
    for (int i = 0; i < dc.varyings; ++i) std::memcpy(tail + 16 * i, &a[0][i], 16);
  } else if (affine) {
    // Equal w: varyings are linear on screen, a plane per component (a constant one exactly).
    Plane* planes = reinterpret_cast<Plane*>(tail);
    for (int i = 0; i < dc.varyings; ++i)
      for (int c = 0; c < 4; ++c) planes[4 * i + c] = basis.plane(a[0][i][c], a[1][i][c], a[2][i][c]);
  } else {
    // Perspective-correct barycentrics: b_k = (b_k / w) / (1 / w).
    Barycentrics& bary = *::new (tail) Barycentrics;
    bary.inv_w = basis.plane(s[0].inv_w, s[1].inv_w, s[2].inv_w);
    bary.b1_w = basis.plane(0.0, s[1].inv_w, 0.0);
    bary.b2_w = basis.plane(0.0, 0.0, s[2].inv_w);
    float* d = reinterpret_cast<float*>(tail + sizeof(Barycentrics));
    for (int i = 0; i < dc.varyings; ++i, d += 12) {
      for (int c = 0; c < 4; ++c) {
        d[c] = a[0][i][c];
        d[4 + c] = a[1][i][c] - a[0][i][c];
        d[8 + c] = a[2][i][c] - a[0][i][c];
      }
    }
  }
  ++stats.rasterized;
}

/// Sets up and bins one triangle whose vertices are inside the clip volume (w > 0, within the
/// guard band). `v[k]` points at a position followed by varyings.
void setup_and_bin(const DrawConstants& dc, const float* const v[3], ChunkBins& bins, DrawStats& stats) {
  const float* rows[simd::kLanes];
  for (int l = 0; l < simd::kLanes; ++l) rows[l] = v[std::min(l, 2)];
  SnappedLanes snapped;
  simd::LaneBits in_view;
  if ((snap_vertices(dc, rows, snapped, in_view) & 7) != 7) {
    ++stats.degenerate;
    return;
  }
  const ScreenVertex s[3] = {snapped.vertex(0), snapped.vertex(1), snapped.vertex(2)};
  setup_snapped(dc, v, s, bins, stats);
}

/// Which clip-space half-spaces a position lies outside of: bits 0-3 the writable pixel
/// rectangle (-x, +x, -y, +y), bits 4-5 near and far, bits 6-9 the guard band (-x, +x, -y, +y).
unsigned outcode(const DrawConstants& dc, const glm::vec4& p) {
  return unsigned(p.x < dc.reject_min_x * p.w) | unsigned(p.x > dc.reject_max_x * p.w) << 1 |
         unsigned(p.y < dc.reject_min_y * p.w) << 2 | unsigned(p.y > dc.reject_max_y * p.w) << 3 |
         unsigned(p.z < 0) << 4 | unsigned(p.z > p.w) << 5 | unsigned(p.x < dc.guard_min_x * p.w) << 6 |
         unsigned(p.x > dc.guard_max_x * p.w) << 7 | unsigned(p.y < dc.guard_min_y * p.w) << 8 |
         unsigned(p.y > dc.guard_max_y * p.w) << 9;
}

/// The scalar path of one triangle: non-finite and trivial rejects, clipping, then setup.
void process_triangle(const DrawConstants& dc, const glm::vec4* const vertices[3], ChunkBins& bins, DrawStats& stats) {
  const glm::vec4& p0 = vertices[0][0];
  const glm::vec4& p1 = vertices[1][0];
  const glm::vec4& p2 = vertices[2][0];
  // x * 0 is 0 for finite x and NaN for NaN or Inf.
  const float zero = (p0.x + p0.y + p0.z + p0.w) * 0.0f + (p1.x + p1.y + p1.z + p1.w) * 0.0f +
                     (p2.x + p2.y + p2.z + p2.w) * 0.0f;
  if (zero != 0.0f && !(finite_position(p0) && finite_position(p1) && finite_position(p2))) {
    ++stats.non_finite;
    return;
  }
  // Common case first: all three vertices inside the view volume, hence inside the guard band.
  auto inside_view = [](const glm::vec4& p) {
    return (std::abs(p.x) <= p.w) & (std::abs(p.y) <= p.w) & (p.z >= 0.0f) & (p.z <= p.w);
  };
  const float* v[3] = {&vertices[0][0].x, &vertices[1][0].x, &vertices[2][0].x};
  if (inside_view(p0) & inside_view(p1) & inside_view(p2)) {
    setup_and_bin(dc, v, bins, stats);
    return;
  }
  const unsigned c0 = outcode(dc, p0), c1 = outcode(dc, p1), c2 = outcode(dc, p2);
  if (c0 & c1 & c2 & 0x3f) {  // all three beyond one side of the writable rectangle, near or far
    ++stats.outside;
    return;
  }
  // Bits 4-9: some vertex lies beyond the near, far or a guard-band plane.
  if (((c0 | c1 | c2) & 0x3f0) == 0) {
    setup_and_bin(dc, v, bins, stats);
    return;
  }

  ++stats.clipped;
  const ClipPlanes planes = make_clip_planes(dc);
  const int floats = 4 * (1 + dc.varyings);
  ClipVertex buffer[2][kMaxClipVertices];
  for (int k = 0; k < 3; ++k) std::copy(v[k], v[k] + floats, buffer[0][k].v);
  int n = 3, current = 0;
  for (int i = 0; i < 6 && n >= 3; ++i) {
    // Each plane tests the polygon as it is now, not the original vertices: a vertex an earlier
    // plane made (a near-plane intersection has w close to 0) can lie beyond a guard-band plane
    // that all three original vertices respected.
    const ClipVertex* polygon = buffer[current];
    if (std::all_of(polygon, polygon + n, [&](const ClipVertex& c) { return plane_distance(planes.plane[i], c.v) >= 0; }))
      continue;
    n = clip_polygon(planes.plane[i], buffer[current], n, buffer[1 - current], floats);
    current = 1 - current;
  }
  // Fan from the first vertex keeps the original winding.
  for (int k = 1; k + 1 < n; ++k) {
    const float* tri[3] = {buffer[current][0].v, buffer[current][k].v, buffer[current][k + 1].v};
    setup_and_bin(dc, tri, bins, stats);
  }
}


}  // namespace

void bin_staged(const DrawConstants& dc, ChunkBins& bins) {
  const std::byte* stage = bins.staged.data();
  for (const ChunkBins::StagedTriangle& st : bins.staged_triangles) {
    const auto& t = *reinterpret_cast<const TriangleSetup*>(stage + st.offset);
    const size_t blocks = t.record_blocks;
    auto emit = [&](int tile) {
      RecordStream& records = bins.tile_records[tile];
      if (records.empty()) bins.touched_tiles.push_back(static_cast<uint32_t>(tile));
      std::byte* out = records.append(16 * blocks);
      const std::byte* in = stage + st.offset;
      for (size_t b = 0; b < blocks; ++b) std::memcpy(out + 16 * b, in + 16 * b, 16);
    };
    if (st.tx0 == st.tx1 && st.ty0 == st.ty1) {
      emit(st.ty0 * dc.tiles_x + st.tx0);
      continue;
    }
    for (int ty = st.ty0; ty <= st.ty1; ++ty) {
      for (int tx = st.tx0; tx <= st.tx1; ++tx) {
        const int64_t X0 = int64_t(tx) * kTileSize * kSubpixelsPerPixel, X1 = X0 + kTileSize * kSubpixelsPerPixel - 1;
        const int64_t Y0 = int64_t(ty) * kTileSize * kSubpixelsPerPixel, Y1 = Y0 + kTileSize * kSubpixelsPerPixel - 1;
        bool outside = false;
        for (const Edge& e : t.edge) {
          const int64_t emax = e.c + std::max(e.a * X0, e.a * X1) + std::max(e.b * Y0, e.b * Y1);
          outside |= emax < 0;
        }
        if (!outside) emit(ty * dc.tiles_x + tx);
      }
    }
  }
  bins.staged.clear();
  bins.staged_triangles.clear();
}

void process_triangles(const DrawConstants& dc, const glm::vec4* const* vertices, int count, ChunkBins& bins,
                       DrawStats& stats) {
  // Vertices are snapped kLanes at a time; a triangle whose three vertices snapped inside the
  // view volume goes straight to setup, any other to process_triangle (checks, clipping).
  constexpr int kMaxVertices = 3 * kFrontEndBatch;
  static_assert(kMaxVertices % simd::kLanes == 0 && kMaxVertices <= 64);
  SnappedLanes snapped[kMaxVertices / simd::kLanes];
  const int n = 3 * count;
  uint64_t ready = 0;  // bit i: vertex i snapped and inside the view volume
  for (int base = 0; base < n; base += simd::kLanes) {
    const float* rows[simd::kLanes];
    for (int l = 0; l < simd::kLanes; ++l) rows[l] = &vertices[std::min(base + l, n - 1)]->x;
    simd::LaneBits in_view;
    const simd::LaneBits bits = snap_vertices(dc, rows, snapped[base / simd::kLanes], in_view);
    ready |= uint64_t(bits & in_view) << base;
  }
  for (int t = 0; t < count; ++t) {
    if ((ready >> (3 * t) & 7) != 7) {
      process_triangle(dc, vertices + 3 * t, bins, stats);
      continue;
    }
    ScreenVertex s[3];
    const float* v[3];
    for (int k = 0; k < 3; ++k) {
      const int i = 3 * t + k;
      s[k] = snapped[i / simd::kLanes].vertex(i % simd::kLanes);
      v[k] = &vertices[i]->x;
    }
    setup_snapped(dc, v, s, bins, stats);
  }
}

}  // namespace luxel::rasterizer::detail
