// The front end of a draw: perspective divide, viewport transform, snapping to 1/256 pixel,
// culling, edge and plane setup, kLanes triangles at a time, each set-up triangle then binned
// (binning.cpp); a triangle not wholly inside the view volume goes through clipping.cpp first.

#include "luxel/rasterizer/detail/triangle_setup.hpp"

#include "binning.hpp"
#include "front_end.hpp"

#include "luxel/rasterizer/draw.hpp"
#include "luxel/rasterizer/msaa.hpp"
#include "luxel/rasterizer/simd.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <new>

namespace luxel::rasterizer::detail {

/// Snaps kLanes vertices (clip-space positions rows[l]) to 1/256 pixel. Every vertex is snapped
/// here, clipped or not, so a vertex shared by a clipped and an unclipped triangle lands on the
/// same subpixel. Returns the lanes that can be set up: w positive with a finite reciprocal, and
/// within twice the guard band. Clipping leaves every vertex inside the band up to rounding,
/// which is a few pixels when a near-plane intersection has w close to 0 (seen: 8 px), and
/// unbounded when an intersection parameter rounds to 1 between vertices whose w differ by 30
/// orders of magnitude (garbage input): the outside vertex itself comes back. Twice the band keeps
/// the former, whose 64-bit edge constants still fit with room to spare, and drops the latter,
/// whose subpixel coordinates would overflow. `in_view` gets the lanes inside the view volume
/// with finite coordinates: a triangle of three such vertices needs no clipping.
simd::LaneBits snap_vertices(const DrawConstants& dc, const float* const* rows, SnappedLanes& out,
                             simd::LaneBits& in_view) {
  using simd::Float;
  using simd::Int;
  Float px, py, pz, pw;
  simd::transpose_rows(rows, px, py, pz, pw);
  const Float one(1.0f), zero(0.0f);
  const Float rw = one / pw;
  const Float sx = simd::fma(simd::fma(px, rw, one), Float(dc.half_w), Float(dc.vp_x));
  const Float sy = simd::fma(simd::fma(-py, rw, one), Float(dc.half_h), Float(dc.vp_y));
  const Float band(2.0f * kGuardBand);
  const auto snappable = (pw > zero) & (rw - rw == zero) & (xsimd::abs(sx) <= band) & (xsimd::abs(sy) <= band);
  const auto view = (xsimd::abs(px) <= pw) & (xsimd::abs(py) <= pw) & (pz >= zero) & (pz <= pw) & (pw - pw == zero);
  const Int ix = simd::round_to_int(sx * Float(float(kSubpixelsPerPixel)));
  const Int iy = simd::round_to_int(sy * Float(float(kSubpixelsPerPixel)));
  ix.store_aligned(out.X);
  iy.store_aligned(out.Y);
  (xsimd::batch_cast<float>(ix) * Float(1.0f / kSubpixelsPerPixel)).store_aligned(out.x);
  (xsimd::batch_cast<float>(iy) * Float(1.0f / kSubpixelsPerPixel)).store_aligned(out.y);
  simd::fma(pz * rw, Float(dc.max_depth - dc.min_depth), Float(dc.min_depth)).store_aligned(out.z);
  rw.store_aligned(out.inv_w);
  in_view = simd::to_bits(view);
  return simd::to_bits(snappable);
}

namespace {

Edge make_edge(int32_t x0, int32_t y0, int32_t x1, int32_t y1) {
  const int32_t dx = x1 - x0, dy = y1 - y0;
  // Top-left rule (y down, interior on the positive side): left edges go up, top edges are
  // horizontal and go right. Samples exactly on other edges are outside. (Bitwise, not
  // short-circuit: the edge directions of a mesh are random, a branch here mispredicts.)
  const bool top_left = (dy < 0) | ((dy == 0) & (dx > 0));
  return {-dy, dx, int64_t(dy) * x0 - int64_t(dx) * y0 - int64_t(!top_left)};
}

}  // namespace

/// Edge k of triangle l, on its vertices in positive (clockwise) order.
Edge lane_edge(const TriangleLanes& tri, const SetupLanes& setup, int l, int k) {
  const bool clockwise = setup.clockwise >> l & 1;
  const int i1 = clockwise ? 1 : 2, i2 = clockwise ? 2 : 1;
  const int from = k == 0 ? 0 : k == 1 ? i1 : i2, to = k == 0 ? i1 : k == 1 ? i2 : 0;
  const SnappedLanes* v = tri.vertex;
  return make_edge(v[from].X[l], v[from].Y[l], v[to].X[l], v[to].Y[l]);
}

namespace {

/// Per-sample edge values of a stamp fit 32 bits (TriangleSetup::narrow_edges); triangle l is
/// not small (small triangles always are).
bool narrow_edges(const TriangleLanes& tri, const SetupLanes& setup, int l) {
  bool narrow = true;
  for (int k = 0; k < 3; ++k) {
    const Edge e = lane_edge(tri, setup, l, k);
    const int64_t span = std::abs(int64_t(e.a)) * (simd::kStampWidth * kSubpixelsPerPixel) +
                         std::abs(int64_t(e.b)) * (simd::kStampHeight * kSubpixelsPerPixel);
    narrow &= span <= kNarrowEdgeLimit;
  }
  return narrow;
}

/// Sets up the triangles of `tri` whose lanes are in `ready`. (Other lanes are computed too, from
/// whatever their vertices hold, and must be ignored.)
void setup_lanes(const DrawConstants& dc, const TriangleLanes& tri, simd::LaneBits ready, SetupLanes& out) {
  using simd::Double;
  using simd::Float;
  using simd::Int;
  constexpr int kHalf = static_cast<int>(Double::size);
  const SnappedLanes* v = tri.vertex;
  const Int X0 = Int::load_aligned(v[0].X), X1 = Int::load_aligned(v[1].X), X2 = Int::load_aligned(v[2].X);
  const Int Y0 = Int::load_aligned(v[0].Y), Y1 = Int::load_aligned(v[1].Y), Y2 = Int::load_aligned(v[2].Y);

  // Bounds: a sample lies in [0, 240] subpixels from its pixel's corner, so the pixels that
  // may hold a covered sample are those that meet the vertices' bounding box.
  const Int min_x = xsimd::min(X0, xsimd::min(X1, X2)), max_x = xsimd::max(X0, xsimd::max(X1, X2));
  const Int min_y = xsimd::min(Y0, xsimd::min(Y1, Y2)), max_y = xsimd::max(Y0, xsimd::max(Y1, Y2));
  const Int x0 = xsimd::max(Int(dc.clip_x0), min_x >> kSubpixelBits);
  const Int y0 = xsimd::max(Int(dc.clip_y0), min_y >> kSubpixelBits);
  const Int x1 = xsimd::min(Int(dc.clip_x1), (max_x >> kSubpixelBits) + Int(1));
  const Int y1 = xsimd::min(Int(dc.clip_y1), (max_y >> kSubpixelBits) + Int(1));
  x0.store_aligned(out.x0);
  y0.store_aligned(out.y0);
  x1.store_aligned(out.x1);
  y1.store_aligned(out.y1);
  out.empty = simd::to_bits((x0 >= x1) | (y0 >= y1));
  const Int tx0 = x0 >> kTileShift, ty0 = y0 >> kTileShift;
  (ty0 * Int(dc.tiles_x) + tx0).store_aligned(out.tile);
  out.one_tile = simd::to_bits((tx0 == ((x1 - Int(1)) >> kTileShift)) & (ty0 == ((y1 - Int(1)) >> kTileShift)));
  const Int small_span(kSmallTriangleSize * kSubpixelsPerPixel);
  const FastPaths fast = dc.fast_paths;
  if (fast.on(FastPath::SmallTriangleWalk) && fast.on(FastPath::NarrowEdges))
    out.small = simd::to_bits((max_x - min_x < small_span) & (max_y - min_y < small_span));
  const Float w0 = Float::load_aligned(v[0].inv_w);
  if (fast.on(FastPath::AffineRecords))
    out.affine = simd::to_bits((w0 == Float::load_aligned(v[1].inv_w)) & (w0 == Float::load_aligned(v[2].inv_w)));

  // The doubled signed area and the depth plane, in doubles, the low lanes then the high.
  Double dx1[2], dy1[2], dx2[2], dy2[2], z0[2], z1[2], z2[2];
  simd::to_doubles(X1 - X0, dx1[0], dx1[1]);
  simd::to_doubles(Y1 - Y0, dy1[0], dy1[1]);
  simd::to_doubles(X2 - X0, dx2[0], dx2[1]);
  simd::to_doubles(Y2 - Y0, dy2[0], dy2[1]);
  simd::to_doubles(Float::load_aligned(v[0].z), z0[0], z0[1]);
  simd::to_doubles(Float::load_aligned(v[1].z), z1[0], z1[1]);
  simd::to_doubles(Float::load_aligned(v[2].z), z2[0], z2[1]);
  xsimd::batch_bool<double, simd::Arch> zero[2], positive[2];
  Double dzdx[2], dzdy[2];
  const Double scale(1.0 / kSubpixelsPerPixel);
  for (int h = 0; h < 2; ++h) {
    const Double area2 = dx1[h] * dy2[h] - dx2[h] * dy1[h];
    zero[h] = area2 == Double(0.0);
    positive[h] = area2 > Double(0.0);
    const Double e1x = dx1[h] * scale, e1y = dy1[h] * scale, e2x = dx2[h] * scale, e2y = dy2[h] * scale;
    const Double inv_det = Double(double(kSubpixelsPerPixel) * kSubpixelsPerPixel) / area2;
    e1x.store_aligned(out.e1x + h * kHalf);
    e1y.store_aligned(out.e1y + h * kHalf);
    e2x.store_aligned(out.e2x + h * kHalf);
    e2y.store_aligned(out.e2y + h * kHalf);
    inv_det.store_aligned(out.inv_det + h * kHalf);
    const Double d1 = z1[h] - z0[h], d2 = z2[h] - z0[h];  // as PlaneBasis::plane
    dzdx[h] = (d1 * e2y - d2 * e1y) * inv_det;
    dzdy[h] = (d2 * e1x - d1 * e2x) * inv_det;
  }
  out.zero_area = simd::to_bits(zero[0], zero[1]);
  out.clockwise = simd::to_bits(positive[0], positive[1]);

  // SmallEdges, for every lane (only small ones keep them, where they are exact): the edges on
  // the vertices in positive (clockwise) order, from the record corner.
  const auto clockwise = simd::int_mask(out.clockwise);
  const Int Xa = xsimd::select(clockwise, X1, X2), Ya = xsimd::select(clockwise, Y1, Y2);
  const Int Xb = xsimd::select(clockwise, X2, X1), Yb = xsimd::select(clockwise, Y2, Y1);
  const Int corner_x = (x0 & Int(~(simd::kStampWidth - 1))) << kSubpixelBits;
  const Int corner_y = (y0 & Int(~(simd::kStampHeight - 1))) << kSubpixelBits;
  Int small_edges[8];  // SmallEdges: corner[0..3], ab[0..3]
  auto small_edge = [&](int k, const Int& Px, const Int& Py, const Int& Qx, const Int& Qy) {
    const Int a = Py - Qy, b = Qx - Px;  // as make_edge
    const auto top_left = (a > Int(0)) | ((a == Int(0)) & (b > Int(0)));
    const Int bias = xsimd::select(top_left, Int(0), Int(1));
    small_edges[k] = a * (corner_x - Px) + b * (corner_y - Py) - bias;
    small_edges[4 + k] = (a & Int(0xffff)) | (b << 16);
  };
  small_edge(0, X0, Y0, Xa, Ya);
  small_edge(1, Xa, Ya, Xb, Yb);
  small_edge(2, Xb, Yb, X0, Y0);
  small_edges[3] = small_edges[7] = Int(0);
  simd::transpose_to_rows(small_edges, out.small_edges);

  const CullMode cull = dc.rasterizer.cull;
  out.culled = cull == CullMode::CW    ? out.clockwise
               : cull == CullMode::CCW ? ~out.clockwise & ~out.zero_area & simd::kAllLanes
                                       : 0;
  const Float dqdx = simd::to_float(dzdx[0], dzdx[1]), dqdy = simd::to_float(dzdy[0], dzdy[1]);
  Float q0 = Float::load_aligned(v[0].z);
  if (dc.rasterizer.depth_bias != 0 || dc.rasterizer.slope_scaled_depth_bias != 0) {
    const Float slope = xsimd::max(xsimd::abs(dqdx), xsimd::abs(dqdy));
    q0 += Float(dc.rasterizer.depth_bias) + Float(dc.rasterizer.slope_scaled_depth_bias) * slope;
  }

  // The record's size and flags. Flat varyings: the same finite bits at the three vertices
  // (then they interpolate to their value at vertex 0, which the record stores alone).
  simd::LaneBits flat = fast.on(FastPath::FlatRecords) ? simd::kAllLanes : 0;
  for (int i = 0; i < dc.varyings && flat; ++i) {
    Float c[3][4];
    for (int k = 0; k < 3; ++k) simd::transpose_rows(tri.data[k], c[k][0], c[k][1], c[k][2], c[k][3], 4 * (1 + i));
    for (int j = 0; j < 4; ++j) {
      const Int v0 = xsimd::bitwise_cast<Int>(c[0][j]), exponent(0x7f800000);  // all ones: Inf or NaN
      flat &= simd::to_bits((v0 == xsimd::bitwise_cast<Int>(c[1][j])) & (v0 == xsimd::bitwise_cast<Int>(c[2][j])) &
                            ((v0 & exponent) != exponent));
    }
  }
  // Narrow edges: always for small triangles; for others (rare) a test in 64 bits.
  simd::LaneBits narrow = out.small;
  const simd::LaneBits others = fast.on(FastPath::NarrowEdges) ? ready & ~out.rejected() & ~out.small : 0;
  for (simd::LaneBits wide = others; wide; wide &= wide - 1)
    if (narrow_edges(tri, out, std::countr_zero(wide))) narrow |= wide & -wide;
  const simd::LaneBits front_facing = dc.rasterizer.front_counter_clockwise ? ~out.clockwise : out.clockwise;
  auto flag = [](simd::LaneBits lanes, int bit) { return xsimd::select(simd::int_mask(lanes), Int(bit), Int(0)); };
  const Int flags = flag(front_facing, TriangleSetup::kFrontFacing) | flag(narrow, TriangleSetup::kNarrowEdges) |
                    flag(out.small, TriangleSetup::kSmall) | flag(out.affine, TriangleSetup::kAffine) |
                    flag(flat, TriangleSetup::kFlat);
  auto blocks = [&](bool small) {
    const int n = dc.varyings;
    return xsimd::select(simd::int_mask(flat), Int(triangle_record_size(n, small, true, false) / 16),
                         xsimd::select(simd::int_mask(out.affine), Int(triangle_record_size(n, small, false, true) / 16),
                                       Int(triangle_record_size(n, small, false, false) / 16)));
  };
  const Int size_and_flags = xsimd::select(simd::int_mask(out.small), blocks(true), blocks(false)) | (flags << 8);
  // TriangleSetup, field by field (see the static_assert on its layout).
  const Int header[8] = {(x0 & Int(0xffff)) | (y0 << 16),
                         (x1 & Int(0xffff)) | (y1 << 16),
                         xsimd::bitwise_cast<Int>(Float::load_aligned(v[0].x)),
                         xsimd::bitwise_cast<Int>(Float::load_aligned(v[0].y)),
                         xsimd::bitwise_cast<Int>(q0),
                         xsimd::bitwise_cast<Int>(dqdx),
                         xsimd::bitwise_cast<Int>(dqdy),
                         size_and_flags};
  simd::transpose_to_rows(header, out.header);
}

/// Sets up and bins triangles 0..count-1 of `tri` (snapped) in order; `ready` are those to set
/// up, the others go to `other(l)` in their turn.
template <class Other>
void setup_and_bin(const DrawConstants& dc, const TriangleLanes& tri, int count, simd::LaneBits ready, ChunkBins& bins,
                   DrawStats& stats, Other&& other) {
  SetupLanes setup;
  if (ready) setup_lanes(dc, tri, ready, setup);
  const simd::LaneBits rejected = ready & setup.rejected(), binned = ready & ~rejected;
  stats.culled += std::popcount(rejected & setup.culled);
  stats.degenerate += std::popcount(rejected & ~setup.culled);
  stats.rasterized += std::popcount(binned);
  for (int l = 0; l < count; ++l) {
    if (binned >> l & 1) {
      if (setup.one_tile >> l & 1) {
        emit_record(dc, tri, setup, l, setup.tile[l], bins);
      } else {
        bin_to_tiles(dc, tri, setup, l, bins);
      }
    } else if (!(ready >> l & 1)) {
      other(l);
    }
  }
}

}  // namespace

/// Sets up and bins the fan of an n-gon (n - 2 triangles from its first vertex, which keeps the
/// winding); each vertex is a position followed by varyings. The fan of a fully clipped polygon
/// fits one set of 8 or 16 lanes; 4-lane targets (x86-64-v2) take it in two, in order.
void setup_fan(const DrawConstants& dc, const float* const* polygon, int n, ChunkBins& bins, DrawStats& stats) {
  for (int first = 0; first < n - 2; first += simd::kLanes) {
    TriangleLanes tri;
    const int count = std::min(n - 2 - first, simd::kLanes);
    for (int l = 0; l < count; ++l) {
      tri.data[0][l] = polygon[0];
      tri.data[1][l] = polygon[first + l + 1];
      tri.data[2][l] = polygon[first + l + 2];
    }
    tri.snap(dc, count);
    setup_and_bin(dc, tri, count, tri.snappable, bins, stats, [&](int) { ++stats.degenerate; });
  }
}

void process_triangles(const DrawConstants& dc, const glm::vec4* const* vertices, int count, ChunkBins& bins,
                       DrawStats& stats) {
  // kLanes triangles at a time: vertices snapped, and the triangles whose three vertices lie in
  // the view volume set up together; any other goes through clip_and_bin in its turn.
  for (int first = 0; first < count; first += simd::kLanes) {
    const int n = std::min(simd::kLanes, count - first);
    const glm::vec4* const* batch = vertices + 3 * first;
    TriangleLanes tri;
    for (int l = 0; l < n; ++l)
      for (int k = 0; k < 3; ++k) tri.data[k][l] = &batch[3 * l + k]->x;
    tri.snap(dc, n);
    setup_and_bin(dc, tri, n, tri.snappable & tri.in_view, bins, stats,
                  [&](int l) { clip_and_bin(dc, batch + 3 * l, bins, stats); });
  }
}

}  // namespace luxel::rasterizer::detail
