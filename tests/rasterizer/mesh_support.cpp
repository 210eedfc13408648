#include "mesh_support.hpp"

#include <algorithm>
#include <cmath>

namespace luxel::rasterizer::test {

namespace {

double q10(double v) { return std::round(v * 1024.0) / 1024.0; }

glm::vec4 approx_clip(const ViewportMap& map, glm::dvec2 s) {
  return {static_cast<float>((s.x - map.x) / (map.w / 2) - 1), static_cast<float>(1 - (s.y - map.y) / (map.h / 2)), 0.5f,
          1.0f};
}

void add_triangle(Mesh& m, uint32_t a, uint32_t b, uint32_t c, std::mt19937& rng) {
  if (rng() & 1) std::swap(b, c);  // random winding
  m.indices.insert(m.indices.end(), {a, b, c});
}

/// Two triangles per cell of an (nx + 1) x (ny + 1) vertex grid (row-major), each
/// cell split along a random diagonal.
void triangulate_grid(Mesh& m, int nx, int ny, std::mt19937& rng) {
  auto id = [&](int i, int j) { return uint32_t(j * (nx + 1) + i); };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (rng() & 1) {
        add_triangle(m, a, b, c, rng);
        add_triangle(m, a, c, d, rng);
      } else {
        add_triangle(m, a, b, d, rng);
        add_triangle(m, b, c, d, rng);
      }
    }
}

/// Point at perimeter parameter t (clockwise from the top-left corner), along-edge coordinate
/// on the 2^-10 grid so the point is exact.
glm::dvec2 perimeter_point(const ScreenRect& r, double t) {
  const double w = r.x1 - r.x0, h = r.y1 - r.y0;
  if (t < w) return {q10(r.x0 + t), r.y0};
  t -= w;
  if (t < h) return {r.x1, q10(r.y0 + t)};
  t -= h;
  if (t < w) return {q10(r.x1 - t), r.y1};
  t -= w;
  return {r.x0, q10(r.y1 - t)};
}

std::vector<glm::dvec2> boundary_points(const ScreenRect& r, int extra, std::mt19937& rng) {
  const double w = r.x1 - r.x0, h = r.y1 - r.y0, p = 2 * (w + h);
  std::vector<double> t = {0, w, w + h, 2 * w + h};
  std::uniform_real_distribution<double> u(0, p);
  for (int i = 0; i < extra; ++i) t.push_back(u(rng));
  std::sort(t.begin(), t.end());
  std::vector<glm::dvec2> pts;
  for (double x : t) {
    const glm::dvec2 q = perimeter_point(r, x);
    if (pts.empty() || q != pts.back()) pts.push_back(q);
  }
  while (pts.size() > 1 && pts.back() == pts.front()) pts.pop_back();
  return pts;
}

}  // namespace

bool ScreenRect::contains_sample(int64_t sx, int64_t sy) const {
  return sx >= round_half_even(x0 * 256) && sx < round_half_even(x1 * 256) && sy >= round_half_even(y0 * 256) &&
         sy < round_half_even(y1 * 256);
}

Mesh jittered_grid(const ViewportMap& map, const ScreenRect& r, int nx, int ny, std::mt19937& rng) {
  Mesh m;
  m.name = "jittered grid " + std::to_string(nx) + "x" + std::to_string(ny);
  m.format = Mesh::Format::U32;
  const double cw = (r.x1 - r.x0) / nx, ch = (r.y1 - r.y0) / ny;
  std::uniform_real_distribution<double> jitter(-0.15, 0.15);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const bool bx = i == 0 || i == nx, by = j == 0 || j == ny;
      double x = i == nx ? r.x1 : r.x0 + cw * i, y = j == ny ? r.y1 : r.y0 + ch * j;
      if (!bx) x += jitter(rng) * cw;
      if (!by) y += jitter(rng) * ch;
      if (bx || by) {
        m.clip.push_back(map.clip_from_screen(q10(x), q10(y)));
      } else {
        m.clip.push_back(approx_clip(map, {x, y}));
      }
    }
  triangulate_grid(m, nx, ny, rng);
  return m;
}

Mesh random_fan(const ViewportMap& map, const ScreenRect& r, int boundary, std::mt19937& rng) {
  Mesh m;
  m.name = "random fan of " + std::to_string(boundary);
  m.format = Mesh::Format::U16;
  std::uniform_real_distribution<double> u(0.25, 0.75);
  m.clip.push_back(approx_clip(map, {r.x0 + u(rng) * (r.x1 - r.x0), r.y0 + u(rng) * (r.y1 - r.y0)}));
  const std::vector<glm::dvec2> pts = boundary_points(r, boundary - 4, rng);
  for (const glm::dvec2& p : pts) m.clip.push_back(map.clip_from_screen(p.x, p.y));
  const uint32_t n = uint32_t(pts.size());
  for (uint32_t k = 0; k < n; ++k) add_triangle(m, 0, 1 + k, 1 + (k + 1) % n, rng);
  return m;
}

Mesh thin_fan(const ViewportMap& map, const ScreenRect& r, int triangles, std::mt19937& rng) {
  Mesh m = random_fan(map, r, triangles, rng);
  m.name = "fan of " + std::to_string(m.triangle_count()) + " thin triangles";
  return m;
}

Mesh random_strip(const ViewportMap& map, const ScreenRect& r, int top, int bottom, std::mt19937& rng) {
  Mesh m;
  m.name = "random strip " + std::to_string(top) + "/" + std::to_string(bottom);
  m.format = Mesh::Format::None;
  std::uniform_real_distribution<double> u(r.x0, r.x1);
  auto row = [&](int n, double y) {
    std::vector<double> xs = {r.x0, r.x1};
    for (int i = 0; i < n; ++i) xs.push_back(q10(u(rng)));
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    std::vector<uint32_t> ids;
    for (double x : xs) {
      ids.push_back(uint32_t(m.clip.size()));
      m.clip.push_back(map.clip_from_screen(x, y));
    }
    return std::make_pair(xs, ids);
  };
  const auto [tx, ti] = row(top, r.y0);
  const auto [bx, bi] = row(bottom, r.y1);
  size_t i = 0, j = 0;
  while (i + 1 < tx.size() || j + 1 < bx.size()) {
    if (j + 1 == bx.size() || (i + 1 < tx.size() && tx[i + 1] < bx[j + 1])) {
      add_triangle(m, ti[i], ti[i + 1], bi[j], rng);
      ++i;
    } else {
      add_triangle(m, ti[i], bi[j], bi[j + 1], rng);
      ++j;
    }
  }
  return m;
}

Mesh perspective_floor(float half_x, float w0, float w1, float near, int nx, int nz, std::mt19937& rng,
                       glm::vec4 corners[4]) {
  Mesh m;
  m.name = "perspective floor";
  m.format = Mesh::Format::U32;
  const float y = -1.5f;
  auto vertex = [&](float x, float w) { return glm::vec4(x, y, w - near, w); };
  std::uniform_real_distribution<float> jitter(-0.15f, 0.15f);
  const float cx = 2 * half_x / nx, cz = (w1 - w0) / nz;
  for (int k = 0; k <= nz; ++k)
    for (int i = 0; i <= nx; ++i) {
      float x = i == nx ? half_x : -half_x + cx * i, w = k == nz ? w1 : w0 + cz * k;
      if (i > 0 && i < nx) x += jitter(rng) * cx;
      if (k > 0 && k < nz) w += jitter(rng) * cz;
      m.clip.push_back(vertex(x, w));
    }
  corners[0] = vertex(-half_x, w0);
  corners[1] = vertex(half_x, w0);
  corners[2] = vertex(half_x, w1);
  corners[3] = vertex(-half_x, w1);
  triangulate_grid(m, nx, nz, rng);
  return m;
}

void draw_counting(Context& ctx, ColorTarget& target, const Mesh& mesh, PipelineState state) {
  state.blend.enable = true;
  state.blend.src = BlendFactor::One;
  state.blend.dst = BlendFactor::One;
  state.blend.op = BlendOp::Add;
  state.rasterizer.cull = CullMode::None;
  const ConstantPS ps{{1.0f / 255, 0, 0, 0}};
  const Framebuffer fb{&target, nullptr};
  const uint32_t n = uint32_t(mesh.clip.size());
  switch (mesh.format) {
    case Mesh::Format::U32:
      draw(ctx, fb, state, Geometry::indexed(std::span<const uint32_t>(mesh.indices), n), PositionVS{mesh.clip.data()}, ps);
      break;
    case Mesh::Format::U16: {
      const std::vector<uint16_t> idx(mesh.indices.begin(), mesh.indices.end());
      draw(ctx, fb, state, Geometry::indexed(std::span<const uint16_t>(idx), n), PositionVS{mesh.clip.data()}, ps);
      break;
    }
    case Mesh::Format::None: {
      std::vector<glm::vec4> expanded;
      for (uint32_t i : mesh.indices) expanded.push_back(mesh.clip[i]);
      draw(ctx, fb, state, Geometry::non_indexed(uint32_t(expanded.size())), PositionVS{expanded.data()}, ps);
      break;
    }
  }
}

}  // namespace luxel::rasterizer::test
