// Perspective-correct interpolation against the analytic answer: a planar quad (two triangles)
// seen in perspective carries uv (and more varyings, all affine on the plane); for every shaded
// pixel the interpolants at the pixel center must equal the ray-plane intersection through that
// center, computed in double. The quads are chosen so that their projected corners are exactly
// representable (view depth 1, 2 or 4; coordinates on a 1/64 grid): snapping moves nothing, and
// the only error left is the library's float arithmetic.
//
// Tolerance: |uv error| < 1e-4 for uv in about [-1, 9] (float planes evaluated over <= 128
// pixels, then a division: a few 1e-7 relative, ~1e-5 absolute at worst); derivatives 2e-4.
// The checkerboard written from uv must match the analytic checker on every covered sample,
// except on pixels whose analytic uv lies within 1e-3 of a cell border.

#include "raster_support.hpp"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <random>

namespace luxel::rasterizer::test {
namespace {

constexpr int kN = 10;  // varyings (kMaxVaryings)

struct Capture {
  int width = 0;
  std::vector<uint8_t> live;
  std::vector<float> x, y, dudx, dudy;
  std::vector<std::array<float, 4 * kN>> var;
  std::vector<uint8_t> front;
  explicit Capture(int w, int h)
      : width(w), live(size_t(w) * h), x(live.size()), y(live.size()), dudx(live.size()), dudy(live.size()),
        var(live.size()), front(live.size()) {}
};

/// Records what it receives per live pixel, outputs a checker from varying 0 (uv).
struct CapturePS {
  static constexpr bool kCanDiscard = false, kWritesDepth = false;
  Capture* cap;
  void operator()(const PixelInput<kN>& in, PixelOutput& out) const {
    const auto xs = lanes_of(in.x), ys = lanes_of(in.y);
    const auto dudx = lanes_of(simd::ddx(in.varyings[0].x)), dudy = lanes_of(simd::ddy(in.varyings[0].x));
    std::array<std::array<float, simd::kLanes>, 4 * kN> v;
    for (int i = 0; i < kN; ++i) {
      v[4 * i] = lanes_of(in.varyings[i].x);
      v[4 * i + 1] = lanes_of(in.varyings[i].y);
      v[4 * i + 2] = lanes_of(in.varyings[i].z);
      v[4 * i + 3] = lanes_of(in.varyings[i].w);
    }
    std::array<float, simd::kLanes> checker;
    for (int l = 0; l < simd::kLanes; ++l) {
      checker[l] = float((int(std::floor(v[0][l])) + int(std::floor(v[1][l]))) & 1);
      if (!((in.live >> l) & 1)) continue;
      const int px = int(std::floor(xs[l])), py = int(std::floor(ys[l]));
      const size_t i = size_t(py) * cap->width + px;
      cap->live[i] = 1;
      cap->x[i] = xs[l];
      cap->y[i] = ys[l];
      cap->dudx[i] = dudx[l];
      cap->dudy[i] = dudy[l];
      for (int k = 0; k < 4 * kN; ++k) cap->var[i][k] = v[k][l];
      cap->front[i] = in.front_facing;
    }
    const simd::Float c = from_lanes(checker);
    out.color = {c, c, c, simd::Float(1.0f)};
  }
};

/// A planar quad P(a, b) = P0 + a A + b B, a, b in [0, 1], in view space (x right, y up, z = depth).
struct Quad {
  glm::dvec3 p0, A, B;
  glm::dvec3 at(double a, double b) const { return p0 + a * A + b * B; }
};

/// Varying k of the quad's point (a, b): affine in (a, b), so exactly interpolable.
std::array<float, 4 * kN> varyings_at(double a, double b) {
  std::array<float, 4 * kN> v;
  const double u = 8 * a, w = 8 * b;
  for (int k = 0; k < kN; ++k) {
    v[4 * k] = float(k == 0 ? u : u * (k + 1) - w);
    v[4 * k + 1] = float(k == 0 ? w : w * 0.5 - k);
    v[4 * k + 2] = float(u + w + k);
    v[4 * k + 3] = float(k);  // constant: must come out exactly
  }
  return v;
}

/// Intersection of the ray through NDC (nx, ny) with the quad's plane, as (a, b).
glm::dvec2 intersect(const Quad& q, double nx, double ny) {
  // p0 + a A + b B = t (nx, ny, 1)  <=>  [A B -d] (a b t)^T = -p0
  const glm::dvec3 d(nx, ny, 1);
  const glm::dmat3 m(q.A, q.B, -d);
  const glm::dvec3 s = glm::inverse(m) * (-q.p0);
  return {s.x, s.y};
}

struct Result {
  double worst_uv = 0, worst_var = 0, worst_deriv = 0;
  double worst_clipped_ratio = 0;  ///< NearClipped: uv error / its tolerance
  int shaded = 0, checked_samples = 0;
};

enum class Mode {
  Perspective,  ///< corners exactly representable
  EqualW,       ///< the same quad flat at w = 2 (the library's affine path)
  NearClipped,  ///< the quad crosses the near plane (clip z = w - 0.25): new vertices in float
};

Result run_quad(Context& ctx, const Quad& q, int S, Mode mode) {
  const int W = 128, H = 128;
  const float kNear = 0.25f;
  const ViewportMap map(Viewport{}, W, H);
  const glm::dvec2 corner_ab[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::vector<glm::vec4> pos;
  std::vector<std::array<glm::vec4, kN>> vars;
  glm::dvec2 screen[4];
  for (int k = 0; k < 4; ++k) {
    const glm::dvec3 p = q.at(corner_ab[k].x, corner_ab[k].y);
    if (mode == Mode::NearClipped) {
      pos.push_back({float(p.x), float(p.y), float(p.z) - kNear, float(p.z)});
    } else {
      // EqualW: the "view depth" is only used for projection of a flat quad at w = 2.
      const double w = mode == Mode::EqualW ? 2.0 : p.z;
      screen[k] = map.screen_from_ndc(p.x / w, p.y / w);
      pos.push_back(map.clip_from_screen(screen[k].x, screen[k].y, 0.5f, float(w)));
    }
    const auto v = varyings_at(corner_ab[k].x, corner_ab[k].y);
    std::array<glm::vec4, kN> a;
    for (int i = 0; i < kN; ++i) a[i] = {v[4 * i], v[4 * i + 1], v[4 * i + 2], v[4 * i + 3]};
    vars.push_back(a);
  }
  const uint32_t idx[6] = {0, 1, 2, 0, 2, 3};
  ColorTarget target(W, H, S);
  Capture cap(W, H);
  clear_color(ctx, target, {0.5f, 0.5f, 0.5f, 0.0f});
  PipelineState st;
  st.rasterizer.cull = CullMode::None;
  draw(ctx, Framebuffer{&target, nullptr}, st, Geometry::indexed(std::span<const uint32_t>(idx), 4),
       ArrayVS<kN>{pos.data(), vars.data()}, CapturePS{&cap});
  ctx.flush();

  // The analytic quad: for EqualW, the plane is the screen-parallel plane z = 2.
  Quad analytic = q;
  if (mode == Mode::EqualW) {
    for (glm::dvec3* v : {&analytic.p0, &analytic.A, &analytic.B}) v->z = 0;
    analytic.p0.z = 2;
  }
  auto ab_at = [&](double px, double py) {
    const double nx = (px - map.x) / (map.w / 2) - 1, ny = 1 - (py - map.y) / (map.h / 2);
    return intersect(analytic, nx, ny);
  };
  // Coverage: exact triangles, or the double-precision clipped quad up to 1/64 pixel.
  RefPrimitive tri[2], clipped;
  bool clockwise = false;
  if (mode == Mode::NearClipped) {
    clipped = make_fuzzy_primitive(pos, map, CullMode::None, 1.0 / 64);
  } else {
    const glm::dvec2 tri_screen[2][3] = {{screen[0], screen[1], screen[2]}, {screen[0], screen[2], screen[3]}};
    tri[0] = make_exact_primitive(tri_screen[0], CullMode::None);
    tri[1] = make_exact_primitive(tri_screen[1], CullMode::None);
    clockwise = tri[0].tri.area2 > 0;
  }
  const auto pattern = d3d_pattern(S);
  Result r;
  int bad = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      bool any = false, unknown = false, covered[8];
      for (int s = 0; s < S; ++s) {
        if (mode == Mode::NearClipped) {
          const Cover c = clipped.cover(x, y, pattern[s]);
          covered[s] = c == Cover::In;
          unknown |= c == Cover::Unknown;
        } else {
          covered[s] = tri[0].cover(x, y, pattern[s]) == Cover::In || tri[1].cover(x, y, pattern[s]) == Cover::In;
        }
        any |= covered[s];
      }
      const size_t i = size_t(y) * W + x;
      if (unknown && !any) continue;
      if (!unknown && bool(cap.live[i]) != any) {
        if (bad++ < 5) ADD_FAILURE() << "pixel " << x << ", " << y << ": shaded " << int(cap.live[i]) << ", covered " << any;
        continue;
      }
      if (!any) {
        for (int s = 0; s < S; ++s) EXPECT_EQ(target.sample(x, y, s), rgba8(128, 128, 128, 0));
        continue;
      }
      ++r.shaded;
      EXPECT_EQ(cap.x[i], x + 0.5f);
      EXPECT_EQ(cap.y[i], y + 0.5f);
      if (mode != Mode::NearClipped) {
        EXPECT_EQ(bool(cap.front[i]), clockwise);
      }
      const glm::dvec2 ab = ab_at(x + 0.5, y + 0.5);
      const auto expect = varyings_at(ab.x, ab.y);
      const double u = 8 * ab.x, v = 8 * ab.y;
      const double eu = std::abs(cap.var[i][0] - u), ev = std::abs(cap.var[i][1] - v);
      for (int k = 3; k < 4 * kN; k += 4)
        EXPECT_EQ(cap.var[i][k], float(k / 4)) << "constant varying " << k / 4 << " at " << x << ", " << y;
      double tolerance = 1e-4;
      if (mode == Mode::NearClipped) {
        // Clipped vertices are computed in float and snapped: allow uv to move as much as a
        // 1/128 pixel displacement moves it (the snapping itself is at most 1/512).
        const glm::dvec2 ax = ab_at(x + 1.5, y + 0.5), ay = ab_at(x + 0.5, y + 1.5);
        const double grad = 8 * std::max(std::abs(ax.x - ab.x) + std::abs(ay.x - ab.x), std::abs(ax.y - ab.y) + std::abs(ay.y - ab.y));
        tolerance = 1e-4 + grad / 128;
        r.worst_clipped_ratio = std::max(r.worst_clipped_ratio, std::max(eu, ev) / tolerance);
      } else {
        r.worst_uv = std::max({r.worst_uv, eu, ev});
        for (int k = 0; k < 4 * kN; ++k)
          if (k % 4 != 3)
            r.worst_var = std::max(r.worst_var, std::abs(double(cap.var[i][k]) - double(expect[k])) / (1 + std::abs(expect[k])));
        // Coarse derivatives of u: the quad's top row and left column.
        const int qx = x & ~1, qy = y & ~1;
        const double u00 = 8 * ab_at(qx + 0.5, qy + 0.5).x;
        const double dudx = 8 * ab_at(qx + 1.5, qy + 0.5).x - u00, dudy = 8 * ab_at(qx + 0.5, qy + 1.5).x - u00;
        r.worst_deriv = std::max({r.worst_deriv, std::abs(cap.dudx[i] - dudx), std::abs(cap.dudy[i] - dudy)});
      }
      // Checker on every covered sample, away from cell borders.
      auto near_border = [&](double t) { return std::abs(t - std::round(t)) < 1e-3 + tolerance; };
      if (unknown || near_border(u) || near_border(v)) continue;
      const int checker = ((int(std::floor(u)) + int(std::floor(v))) & 1) ? 255 : 0;
      for (int s = 0; s < S; ++s) {
        const uint32_t expect_color = covered[s] ? rgba8(checker, checker, checker, 255) : rgba8(128, 128, 128, 0);
        if (target.sample(x, y, s) != expect_color && bad++ < 5)
          ADD_FAILURE() << "pixel " << x << ", " << y << " sample " << s << ": 0x" << std::hex << target.sample(x, y, s)
                        << " expected 0x" << expect_color << std::dec << " (u " << u << ", v " << v << ")";
        r.checked_samples += covered[s];
      }
    }
  EXPECT_EQ(bad, 0);
  return r;
}

TEST(Perspective, SlantedCheckerboardMatchesRayPlaneIntersection) {
  Context ctx(2);
  // A floor seen from above it, receding from depth 1 to 2 (corners exactly representable).
  const Quad floor{{-1.5, -0.75, 1}, {0, 0, 1}, {3, 0, 0}};
  std::mt19937 rng(8);
  std::vector<Quad> quads = {floor};
  auto grid = [&](double lo, double hi) {  // a multiple of 1/64 in [lo, hi]
    return std::uniform_int_distribution<int>(int(lo * 64), int(hi * 64))(rng) / 64.0;
  };
  while (int(quads.size()) < budget(24, 4)) {
    // P0 at depth z0, A doubles the depth, B keeps it: a slanted plane in any orientation.
    const double z0 = (rng() & 1) ? 1 : 2;
    Quad q{{grid(-1, 0.5) * z0, grid(-1, 0.5) * z0, z0}, {grid(-1, 1) * z0, grid(-1, 1) * z0, z0}, {grid(-1.5, 1.5) * z0, grid(-1.5, 1.5) * z0, 0}};
    const double cross = q.A.x * q.B.y - q.A.y * q.B.x;
    if (std::abs(cross) < 0.2 * z0 * z0) continue;  // too thin
    quads.push_back(q);
  }
  Result worst;
  for (const Quad& q : quads)
    for (int S : {1, 4})
      for (bool affine : {false, true}) {
        if (affine && std::abs(q.A.x * q.B.y - q.A.y * q.B.x) < 0.1) continue;  // flat on screen at equal w
        SCOPED_TRACE(testing::Message() << "quad p0 (" << q.p0.x << ", " << q.p0.y << ", " << q.p0.z << "), " << S
                                        << " samples" << (affine ? ", equal w" : ""));
        const Result r = run_quad(ctx, q, S, affine ? Mode::EqualW : Mode::Perspective);
        EXPECT_LT(r.worst_uv, 1e-4);
        EXPECT_LT(r.worst_var, 1e-4);
        EXPECT_LT(r.worst_deriv, 2e-4);
        worst.worst_uv = std::max(worst.worst_uv, r.worst_uv);
        worst.worst_var = std::max(worst.worst_var, r.worst_var);
        worst.worst_deriv = std::max(worst.worst_deriv, r.worst_deriv);
        worst.shaded += r.shaded;
        worst.checked_samples += r.checked_samples;
      }
  EXPECT_GT(worst.checked_samples, 10000);
  std::printf("[          ] worst |uv error| %.3g, varyings (relative) %.3g, derivatives %.3g over %d shaded pixels\n",
              worst.worst_uv, worst.worst_var, worst.worst_deriv, worst.shaded);
}

// The near plane cuts the quad: the clipper makes new vertices (and their varyings) in clip
// space, where everything is linear; what is left must still interpolate perspective-correctly.
TEST(Perspective, NearClippedQuadStaysPerspectiveCorrect) {
  Context ctx(2);
  const Quad quads[] = {
      {{-3, -1, -2}, {0, 0, 8}, {6, 0, 0}},       // a floor from behind the eye to depth 6
      {{-1, -3, -1}, {0.5, 0, 5}, {0, 6, 0.5}},  // a wall, slanted both ways
      {{2, -2, 3}, {-4, 0.5, -3.5}, {0.25, 4, 0.25}},
  };
  double worst = 0;
  int checked = 0;
  for (const Quad& q : quads)
    for (int S : {1, 4}) {
      const Result r = run_quad(ctx, q, S, Mode::NearClipped);
      EXPECT_LT(r.worst_clipped_ratio, 1.0) << "uv error beyond its tolerance";
      worst = std::max(worst, r.worst_clipped_ratio);
      checked += r.checked_samples;
    }
  EXPECT_GT(checked, 5000);
  std::printf("[          ] clipped quads: worst uv error %.3g of its tolerance\n", worst);
}

}  // namespace
}  // namespace luxel::rasterizer::test
