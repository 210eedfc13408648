// Clipping: the front end's path for a triangle not wholly inside the view volume (or with a
// vertex that would not snap): non-finite and trivial rejects, Sutherland-Hodgman against the near,
// far and guard-band planes, then the polygon's fan to setup (triangle_setup.cpp).

#include "front_end.hpp"

#include "luxel/rasterizer/detail/triangle_setup.hpp"
#include "luxel/rasterizer/draw.hpp"

#include <algorithm>
#include <cmath>

namespace luxel::rasterizer::detail {

namespace {

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

}  // namespace

int clip_polygon(const glm::vec4& plane, const ClipVertex* in, int n, ClipVertex* out, int floats) {
  int m = 0;
  for (int i = 0; i < n; ++i) {
    const ClipVertex& a = in[i];
    const ClipVertex& b = in[(i + 1) % n];
    const float da = plane_distance(plane, a.v);
    const float db = plane_distance(plane, b.v);
    // Each input vertex emits itself if inside and a crossing if its edge changes side.
    if (m + (da >= 0) + ((da >= 0) != (db >= 0)) > kMaxClipVertices) return -1;
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

namespace {

bool finite_position(const glm::vec4& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
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

}  // namespace

/// The path of a triangle not wholly inside the view volume, or with a vertex that would not
/// snap: non-finite and trivial rejects, clipping, then setup.
void clip_and_bin(const DrawConstants& dc, const glm::vec4* const vertices[3], ChunkBins& bins, DrawStats& stats) {
  const glm::vec4& p0 = vertices[0][0];
  const glm::vec4& p1 = vertices[1][0];
  const glm::vec4& p2 = vertices[2][0];
  if (!(finite_position(p0) && finite_position(p1) && finite_position(p2))) {
    ++stats.non_finite;
    return;
  }
  const float* v[3] = {&p0.x, &p1.x, &p2.x};
  const unsigned c0 = outcode(dc, p0), c1 = outcode(dc, p1), c2 = outcode(dc, p2);
  if (c0 & c1 & c2 & 0x3f) {  // all three beyond one side of the writable rectangle, near or far
    ++stats.outside;
    return;
  }
  // Bits 4-9: some vertex lies beyond the near, far or a guard-band plane.
  if (((c0 | c1 | c2) & 0x3f0) == 0) {
    setup_fan(dc, v, 3, bins, stats);
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
    if (n < 0) {
      ++stats.clip_overflow;
      return;
    }
    current = 1 - current;
  }
  if (n < 3) return;
  const float* polygon[kMaxClipVertices];
  for (int k = 0; k < n; ++k) polygon[k] = buffer[current][k].v;
  setup_fan(dc, polygon, n, bins, stats);
}

}  // namespace luxel::rasterizer::detail
