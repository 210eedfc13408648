#include "raster_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <glm/geometric.hpp>
#include <cstdio>
#include <limits>
#include <sstream>

namespace luxel::rasterizer::test {

std::span<const Offset16> d3d_pattern(int samples) {
  // D3D11_STANDARD_MULTISAMPLE_PATTERN (introduced by D3D10.1), 1/16 pixel.
  static constexpr Offset16 k1[] = {{0, 0}};
  static constexpr Offset16 k2[] = {{4, 4}, {-4, -4}};
  static constexpr Offset16 k4[] = {{-2, -6}, {6, -2}, {-6, 2}, {2, 6}};
  static constexpr Offset16 k8[] = {{1, -3}, {-1, 3}, {5, 1}, {-3, -5}, {-5, 5}, {-7, -1}, {3, 7}, {7, -7}};
  static constexpr Offset16 k16[] = {{1, 1},  {-1, -3}, {-3, 2}, {4, -1}, {-5, -2}, {2, 5},  {5, 3},  {3, -5},
                                     {-2, 6}, {0, -7},  {-4, -6}, {-6, 4}, {-8, 0}, {7, -4}, {6, 7}, {-7, -8}};
  switch (samples) {
    case 1: return k1;
    case 2: return k2;
    case 4: return k4;
    case 8: return k8;
    case 16: return k16;
    default: return {};
  }
}

int64_t round_half_even(double v) {
  const double f = std::floor(v);
  const double d = v - f;
  int64_t i = static_cast<int64_t>(f);
  if (d > 0.5 || (d == 0.5 && (i & 1))) ++i;
  return i;
}

int unorm8(double v) {
  if (std::isnan(v)) return 0;
  v = std::clamp(v, 0.0, 1.0);
  return static_cast<int>(round_half_even(v * 255.0));
}

double srgb_to_linear(double s) { return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4); }
double linear_to_srgb(double l) { return l <= 0.0031308 ? l * 12.92 : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055; }

ViewportMap::ViewportMap(const Viewport& vp, int target_w, int target_h)
    : x(vp.x), y(vp.y), w(vp.width > 0 ? vp.width : target_w), h(vp.height > 0 ? vp.height : target_h) {}

glm::vec4 ViewportMap::clip_from_screen(double sx, double sy, float z, float clip_w) const {
  const double nx = (sx - x) / (w / 2) - 1;
  const double ny = 1 - (sy - y) / (h / 2);
  const float fx = static_cast<float>(nx), fy = static_cast<float>(ny);
  // Precondition of the exact oracle (not the oracle itself): the float transform is exact.
  const float back_x = static_cast<float>(x) + (fx + 1.0f) * static_cast<float>(w / 2);
  const float back_y = static_cast<float>(y) + (1.0f - fy) * static_cast<float>(h / 2);
  EXPECT_TRUE(double(fx) == nx && double(fy) == ny && double(back_x) == sx && double(back_y) == sy)
      << "test setup: screen point (" << sx << ", " << sy << ") is not exactly representable";
  EXPECT_EQ(std::exp2(std::round(std::log2(clip_w))), double(clip_w)) << "test setup: clip w must be a power of two";
  return {fx * clip_w, fy * clip_w, z * clip_w, clip_w};
}

PixelRect writable_rect(const PipelineState& state, int target_w, int target_h) {
  const ViewportMap m(state.viewport, target_w, target_h);
  PixelRect r;
  r.x0 = std::max(0, static_cast<int>(std::floor(m.x)));
  r.y0 = std::max(0, static_cast<int>(std::floor(m.y)));
  r.x1 = std::min(target_w, static_cast<int>(std::ceil(m.x + m.w)));
  r.y1 = std::min(target_h, static_cast<int>(std::ceil(m.y + m.h)));
  if (state.scissor.enable) {
    r.x0 = std::max(r.x0, state.scissor.x0);
    r.y0 = std::max(r.y0, state.scissor.y0);
    r.x1 = std::min(r.x1, state.scissor.x1);
    r.y1 = std::min(r.y1, state.scissor.y1);
  }
  return r;
}

bool inside_viewport(const ViewportMap& m, int px, int py, Offset16 o) {
  const double x = px + (128 + 16 * o.x) / 256.0, y = py + (128 + 16 * o.y) / 256.0;
  return x >= m.x && x < m.x + m.w && y >= m.y && y < m.y + m.h;
}

// --- ExactTriangle ------------------------------------------------------------------------------

ExactTriangle::ExactTriangle(const int64_t X_[3], const int64_t Y_[3]) {
  for (int k = 0; k < 3; ++k) {
    X[k] = X_[k];
    Y[k] = Y_[k];
  }
  area2 = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
}

ExactTriangle ExactTriangle::from_screen(const glm::dvec2 v[3]) {
  int64_t X[3], Y[3];
  for (int k = 0; k < 3; ++k) {
    X[k] = round_half_even(v[k].x * 256.0);
    Y[k] = round_half_even(v[k].y * 256.0);
  }
  return ExactTriangle(X, Y);
}

bool ExactTriangle::edge_is_top_left(int i) const {
  const int j = (i + 1) % 3, k = (i + 2) % 3;
  // Top edge: exactly horizontal, the third vertex below it (y grows downwards).
  if (Y[i] == Y[j]) return Y[k] > Y[i];
  // Left edge: the interior is to the right of it. At the height of the third vertex R, R lies
  // right of the edge's line: (R.x - P.x) (Q.y - P.y) - (R.y - P.y) (Q.x - P.x) has the sign of
  // (Q.y - P.y).
  const int64_t t = (X[k] - X[i]) * (Y[j] - Y[i]) - (Y[k] - Y[i]) * (X[j] - X[i]);
  return (t > 0) == (Y[j] - Y[i] > 0);
}

bool ExactTriangle::covers(int64_t sx, int64_t sy) const {
  if (area2 == 0) return false;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const int64_t ex = X[j] - X[i], ey = Y[j] - Y[i];
    const int64_t side_s = ex * (sy - Y[i]) - ey * (sx - X[i]);
    const int64_t side_r = ex * (Y[k] - Y[i]) - ey * (X[k] - X[i]);
    if (side_s == 0) {
      if (!edge_is_top_left(i)) return false;
    } else if ((side_s > 0) != (side_r > 0)) {
      return false;
    }
  }
  return true;
}

// --- FuzzyPolygon -------------------------------------------------------------------------------

Cover FuzzyPolygon::classify(double x, double y) const {
  const size_t n = v.size();
  if (n < 3) return Cover::Out;
  const double orient = area2 >= 0 ? 1.0 : -1.0;
  // Signed distances to the edge lines (positive inside): beyond eps outside any line, the
  // point is Out; eps inside all of them, In; otherwise measure the distance to the segments.
  double min_line = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < n; ++i) {
    const glm::dvec2 a = v[i], b = v[(i + 1) % n];
    const glm::dvec2 ab = b - a;
    const double len = std::sqrt(ab.x * ab.x + ab.y * ab.y);
    if (len == 0) continue;
    const double d = orient * (ab.x * (y - a.y) - ab.y * (x - a.x)) / len;
    if (d <= -eps) return Cover::Out;
    min_line = std::min(min_line, d);
  }
  if (min_line >= eps) return Cover::In;
  double dist = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < n; ++i) {
    const glm::dvec2 a = v[i], b = v[(i + 1) % n];
    const glm::dvec2 ab = b - a, ap = glm::dvec2(x, y) - a;
    const double len2 = ab.x * ab.x + ab.y * ab.y;
    const double t = len2 > 0 ? std::clamp((ap.x * ab.x + ap.y * ab.y) / len2, 0.0, 1.0) : 0.0;
    const glm::dvec2 d = ap - t * ab;
    dist = std::min(dist, std::sqrt(d.x * d.x + d.y * d.y));
  }
  if (dist < eps) return Cover::Unknown;
  return min_line >= 0 ? Cover::In : Cover::Out;
}

// --- RefPrimitive -------------------------------------------------------------------------------

namespace {
int64_t floor_div(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
int clamp_int(double v) { return static_cast<int>(std::clamp(v, -1e7, 1e7)); }
}  // namespace

Cover RefPrimitive::cover(int px, int py, Offset16 o) const {
  if (culled) return Cover::Out;
  if (exact) return tri.covers(sample_sub_x(px, o), sample_sub_y(py, o)) ? Cover::In : Cover::Out;
  const Cover c = poly.classify(px + (128 + 16 * o.x) / 256.0, py + (128 + 16 * o.y) / 256.0);
  if (winding_unknown && c == Cover::In) return Cover::Unknown;
  return c;
}

RefPrimitive make_exact_primitive(const glm::dvec2 screen[3], CullMode cull) {
  RefPrimitive p;
  p.exact = true;
  p.tri = ExactTriangle::from_screen(screen);
  const int64_t a = p.tri.area2;
  p.culled = a == 0 || (cull == CullMode::CW && a > 0) || (cull == CullMode::CCW && a < 0);
  const int64_t min_x = std::min({p.tri.X[0], p.tri.X[1], p.tri.X[2]});
  const int64_t max_x = std::max({p.tri.X[0], p.tri.X[1], p.tri.X[2]});
  const int64_t min_y = std::min({p.tri.Y[0], p.tri.Y[1], p.tri.Y[2]});
  const int64_t max_y = std::max({p.tri.Y[0], p.tri.Y[1], p.tri.Y[2]});
  // Pixel px holds samples at px * 256 + [0, 240].
  p.bx0 = static_cast<int>(std::max<int64_t>(floor_div(min_x - 240, 256), -10'000'000));
  p.by0 = static_cast<int>(std::max<int64_t>(floor_div(min_y - 240, 256), -10'000'000));
  p.bx1 = static_cast<int>(std::min<int64_t>(floor_div(max_x, 256) + 1, 10'000'000));
  p.by1 = static_cast<int>(std::min<int64_t>(floor_div(max_y, 256) + 1, 10'000'000));
  return p;
}

std::vector<glm::dvec4> clip_polygon(const std::vector<glm::dvec4>& in, const glm::dvec4& plane) {
  std::vector<glm::dvec4> out;
  const size_t n = in.size();
  if (n < 3) return out;
  for (size_t i = 0; i < n; ++i) {
    const glm::dvec4 a = in[i], b = in[(i + 1) % n];
    const double da = glm::dot(plane, a), db = glm::dot(plane, b);
    if (da >= 0) out.push_back(a);
    if ((da >= 0) != (db >= 0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

std::vector<glm::dvec4> clip_near_far(const std::vector<glm::dvec4>& poly) {
  return clip_polygon(clip_polygon(poly, {0, 0, 1, 0}), {0, 0, -1, 1});
}

RefPrimitive make_fuzzy_primitive(std::span<const glm::vec4> clip, const ViewportMap& map, CullMode cull, double eps) {
  RefPrimitive p;
  p.exact = false;
  p.poly.eps = eps;
  std::vector<glm::dvec4> in;
  for (const glm::vec4& v : clip) in.push_back(glm::dvec4(v));
  // Near and far, then a band of +-2^15 pixels around the screen origin: the polygon may reach
  // w = 0 (where the near and far planes meet), and project to infinity; what lies beyond the
  // band never reaches a target (<= 8192 pixels), so clipping there changes no sample.
  std::vector<glm::dvec4> c = clip_near_far(in);
  const double G = 32768;
  const double x0 = (-G - map.x) / (map.w / 2) - 1, x1 = (G - map.x) / (map.w / 2) - 1;
  const double y0 = 1 - (G - map.y) / (map.h / 2), y1 = 1 - (-G - map.y) / (map.h / 2);
  c = clip_polygon(c, {1, 0, 0, -x0});
  c = clip_polygon(c, {-1, 0, 0, x1});
  c = clip_polygon(c, {0, 1, 0, -y0});
  c = clip_polygon(c, {0, -1, 0, y1});
  std::erase_if(c, [](const glm::dvec4& v) { return !(v.w > 1e-300); });
  if (c.size() < 3) {
    p.empty = p.culled = true;
    return p;
  }
  double min_x = 1e300, min_y = 1e300, max_x = -1e300, max_y = -1e300;
  for (const glm::dvec4& q : c) {
    const glm::dvec2 s = map.screen_from_ndc(q.x / q.w, q.y / q.w);
    p.poly.v.push_back(s);
    min_x = std::min(min_x, s.x);
    max_x = std::max(max_x, s.x);
    min_y = std::min(min_y, s.y);
    max_y = std::max(max_y, s.y);
  }
  double a = 0;
  for (size_t i = 0; i < p.poly.v.size(); ++i) {
    const glm::dvec2 u = p.poly.v[i], w = p.poly.v[(i + 1) % p.poly.v.size()];
    a += u.x * w.y - w.x * u.y;
  }
  p.poly.area2 = a;
  if (std::abs(a) < 1e-6) {
    p.winding_unknown = true;
  } else {
    p.culled = (cull == CullMode::CW && a > 0) || (cull == CullMode::CCW && a < 0);
  }
  p.bx0 = clamp_int(std::floor(min_x - eps) - 1);
  p.by0 = clamp_int(std::floor(min_y - eps) - 1);
  p.bx1 = clamp_int(std::ceil(max_x + eps) + 1);
  p.by1 = clamp_int(std::ceil(max_y + eps) + 1);
  return p;
}

RefPrimitive with_cull(RefPrimitive p, CullMode cull) {
  if (p.exact) {
    const int64_t a = p.tri.area2;
    p.culled = a == 0 || (cull == CullMode::CW && a > 0) || (cull == CullMode::CCW && a < 0);
  } else if (!p.empty && !p.winding_unknown) {
    const double a = p.poly.area2;
    p.culled = (cull == CullMode::CW && a > 0) || (cull == CullMode::CCW && a < 0);
  }
  return p;
}

void for_each_sample(const RefPrimitive& p, const PixelRect& rect, int samples,
                     const std::function<void(int, int, int, Cover)>& fn) {
  if (p.culled) return;
  const std::span<const Offset16> pattern = d3d_pattern(samples);
  const int x0 = std::max(rect.x0, p.bx0), x1 = std::min(rect.x1, p.bx1);
  const int y0 = std::max(rect.y0, p.by0), y1 = std::min(rect.y1, p.by1);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      for (int s = 0; s < samples; ++s) {
        const Cover c = p.cover(x, y, pattern[s]);
        if (c != Cover::Out) fn(x, y, s, c);
      }
}

// --- Read-back ----------------------------------------------------------------------------------

std::vector<uint32_t> read_color(Context& ctx, const ColorTarget& t) {
  ctx.flush();
  std::vector<uint32_t> out(size_t(t.width()) * t.height() * t.samples());
  for (int y = 0; y < t.height(); ++y)
    for (int x = 0; x < t.width(); ++x)
      for (int s = 0; s < t.samples(); ++s) out[sample_index(t.width(), t.samples(), x, y, s)] = t.sample(x, y, s);
  return out;
}

std::string describe(const glm::vec4 clip[3]) {
  std::ostringstream o;
  o.precision(9);
  for (int k = 0; k < 3; ++k)
    o << (k ? " " : "") << "(" << clip[k].x << ", " << clip[k].y << ", " << clip[k].z << ", " << clip[k].w << ")";
  return o.str();
}

std::string describe(const glm::dvec2 screen[3]) {
  std::ostringstream o;
  o.precision(12);
  for (int k = 0; k < 3; ++k) o << (k ? " " : "") << "(" << screen[k].x << ", " << screen[k].y << ")";
  return o.str();
}

std::string join(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& l : lines) s += l + "\n";
  return s;
}

}  // namespace luxel::rasterizer::test
