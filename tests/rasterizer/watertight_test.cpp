// Watertightness: meshes that tile a region exactly, drawn with additive blending (each triangle
// adds 1/255 to red): every sample inside the region must hold exactly 1, every sample outside 0.
// Shared edges must be rasterized once (top-left rule on identical snapped vertices), also when
// the triangles sharing them are clipped against the near plane and the guard band.

#include "mesh_support.hpp"
#include "raster_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace luxel::rasterizer::test {
namespace {

/// Compares every sample's count with `expected(x, y, s)` (-1: either 0 or 1). Returns mismatches.
template <class Expected>
int check_counts(Context& ctx, const ColorTarget& target, const std::string& name, Expected expected, int* max_count = nullptr) {
  const int W = target.width(), H = target.height(), S = target.samples();
  const std::vector<uint32_t> v = read_color(ctx, target);
  int bad = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      for (int s = 0; s < S; ++s) {
        const uint32_t a = v[sample_index(W, S, x, y, s)];
        const int e = expected(x, y, s);
        if (max_count) *max_count = std::max(*max_count, int(a & 255));
        const bool ok = (a >> 8) == 0 && (e < 0 ? (a & 255) <= 1 : int(a & 255) == e);
        if (!ok && bad++ < 8)
          ADD_FAILURE() << name << ", " << S << " samples: pixel (" << x << ", " << y << ") sample " << s << " covered "
                        << (a & 255) << " times (raw 0x" << std::hex << a << std::dec << "), expected "
                        << (e < 0 ? "0 or 1" : std::to_string(e));
      }
  return bad;
}

TEST(Watertight, ScreenSpaceMeshesCoverEverySampleOnce) {
  const int W = 128, H = 64;
  const ViewportMap map(Viewport{}, W, H);
  // Corners on the 2^-10 grid, not on the 1/256 grid: they snap (exactly predictable).
  const ScreenRect r{7.30078125, 5.099609375, 120.7001953125, 60.900390625};
  std::mt19937 rng(2024);
  for (int S : {1, 2, 4, 8}) {
    std::vector<Mesh> meshes;
    meshes.push_back(jittered_grid(map, r, 8, 4, rng));
    meshes.push_back(jittered_grid(map, r, 37, 19, rng));
    meshes.push_back(jittered_grid(map, r, budget(150, 60), budget(70, 30), rng));  // sub-pixel cells
    meshes.push_back(random_fan(map, r, 12, rng));
    meshes.push_back(random_strip(map, r, 9, 14, rng));
    meshes.push_back(random_strip(map, r, 200, 150, rng));
    meshes.push_back(thin_fan(map, r, 1000, rng));
    Context ctx(2);
    ColorTarget target(W, H, S);
    const auto pattern = d3d_pattern(S);
    for (const Mesh& m : meshes) {
      clear_color(ctx, target, glm::vec4(0.0f));
      draw_counting(ctx, target, m);
      const int bad = check_counts(ctx, target, m.name, [&](int x, int y, int s) {
        return r.contains_sample(sample_sub_x(x, pattern[s]), sample_sub_y(y, pattern[s])) ? 1 : 0;
      });
      EXPECT_EQ(bad, 0) << m.name << ", " << S << " samples";
    }
  }
}

// The fan's 1000 triangles meet at one vertex and are thinner than a pixel near it.
TEST(Watertight, ThinFanAroundOneVertexWithViewportOffsetAndScissor) {
  const int W = 100, H = 90;
  PipelineState state;
  state.viewport = {-14, 3, 128, 128};
  state.scissor = {true, 5, 0, 97, 80};
  const ViewportMap map(state.viewport, W, H);
  const PixelRect rect = writable_rect(state, W, H);
  const ScreenRect r{-3.5, 1.25, 103.0009765625, 85.7490234375};  // partly outside the scissor
  std::mt19937 rng(77);
  for (int S : {1, 8}) {
    const Mesh m = thin_fan(map, r, 1000, rng);
    Context ctx(2);
    ColorTarget target(W, H, S);
    clear_color(ctx, target, glm::vec4(0.0f));
    draw_counting(ctx, target, m, state);
    const auto pattern = d3d_pattern(S);
    EXPECT_EQ(check_counts(ctx, target, m.name, [&](int x, int y, int s) {
                return rect.contains(x, y) && r.contains_sample(sample_sub_x(x, pattern[s]), sample_sub_y(y, pattern[s])) ? 1 : 0;
              }),
              0);
  }
}

// A jittered grid on a floor plane seen in perspective, from behind the eye to far away and
// far beyond the guard band on both sides: the clipped pieces of neighbouring triangles must
// still meet exactly. Samples farther than eps from the boundary of the (double-precision)
// clipped floor must be covered exactly once; none anywhere more than once.
TEST(Watertight, PerspectiveMeshAcrossNearPlaneAndGuardBand) {
  const int W = 128, H = 64;
  const ViewportMap map(Viewport{}, W, H);
  std::mt19937 rng(5);
  for (int S : {1, 4, 8}) {
    for (float half_x : {3.0f, 100.0f, 600.0f}) {  // 600: clipped points ~ 150000 px out
      glm::vec4 corners[4];
      const Mesh m = perspective_floor(half_x, -4.0f, 60.0f, 0.25f, budget(40, 16), budget(64, 24), rng, corners);
      const RefPrimitive floor = make_fuzzy_primitive(corners, map, CullMode::None, 1.0 / 32);
      ASSERT_FALSE(floor.empty);
      Context ctx(2);
      ColorTarget target(W, H, S);
      clear_color(ctx, target, glm::vec4(0.0f));
      draw_counting(ctx, target, m);
      const auto pattern = d3d_pattern(S);
      int inside = 0, max_count = 0;
      const int bad = check_counts(ctx, target, m.name, [&](int x, int y, int s) {
        const Cover c = floor.cover(x, y, pattern[s]);
        inside += c == Cover::In;
        return c == Cover::In ? 1 : c == Cover::Out ? 0 : -1;
      }, &max_count);
      EXPECT_EQ(bad, 0) << "half width " << half_x << ", " << S << " samples";
      EXPECT_GT(inside, W * H * S / 4) << "test setup: the floor should fill a good part of the view";
      EXPECT_LE(max_count, 1);
    }
  }
}

// The near plane cuts a dense mesh right through the target (w = 1 everywhere, so the mesh lies
// flat on screen and its depth z crosses 0 along wavy curves): thousands of shared edges are
// clipped, and both triangles of each must produce the same new vertex. The viewport is placed
// far from the screen origin (ndc ~ 1 with 4096-pixel half-width) so that float rounding of the
// clipped vertices is a sizeable fraction of the 1/256 snapping step. A sample whose depth on
// the (unclipped) mesh is clearly positive must be covered once, clearly negative not at all
// ("clearly": beyond |grad z| * 1/32 pixel, room for the float and snapping error of clipped
// vertices), and no sample ever twice.
TEST(Watertight, NearPlaneCutsThroughTheTarget) {
  const int W = 128, H = 128;
  PipelineState st;
  st.viewport = {-8064, -8064, 8192, 8192};
  const ViewportMap map(st.viewport, W, H);
  std::mt19937 rng(1234);
  const int n = budget(96, 40);
  const double lo = -2, cell = (W + 4.0) / n;
  for (int variant = 0; variant < 3; ++variant)
    for (int S : {1, 4, 8}) {
      Mesh m;
      m.name = "near-plane cut " + std::to_string(variant);
      std::vector<glm::dvec2> screen;
      std::vector<double> depth;
      std::uniform_real_distribution<double> u01(0, 1);
      const double f1 = 1 + variant, f2 = 2 + variant, phase = u01(rng) * 6.28;
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
          glm::dvec2 p(lo + cell * i, lo + cell * j);
          if (i > 0 && i < n) p.x += (u01(rng) - 0.5) * 0.3 * cell;
          if (j > 0 && j < n) p.y += (u01(rng) - 0.5) * 0.3 * cell;
          const double u = (p.x - lo) / (W + 4.0), v = (p.y - lo) / (H + 4.0);
          const float z = float(0.1 * std::sin(6.283 * f1 * u + phase) * std::cos(6.283 * f2 * v) + 0.01 * (u01(rng) - 0.5));
          const float nx = float((p.x - map.x) / (map.w / 2) - 1), ny = float(1 - (p.y - map.y) / (map.h / 2));
          m.clip.push_back({nx, ny, z, 1.0f});
          screen.push_back(map.screen_from_ndc(nx, ny));  // where the float vertex really is
          depth.push_back(z);
        }
      auto id = [&](int i, int j) { return uint32_t(j * (n + 1) + i); };
      // Per cell, its two triangles (for looking samples up), drawn with random windings.
      std::vector<std::array<uint32_t, 6>> cells;
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
          const std::array<uint32_t, 6> t = (rng() & 1) ? std::array<uint32_t, 6>{a, b, c, a, c, d}
                                                         : std::array<uint32_t, 6>{a, b, d, b, c, d};
          cells.push_back(t);
          for (int k = 0; k < 2; ++k) {
            uint32_t v0 = t[3 * k], v1 = t[3 * k + 1], v2 = t[3 * k + 2];
            if (rng() & 1) std::swap(v1, v2);
            m.indices.insert(m.indices.end(), {v0, v1, v2});
          }
        }
      Context ctx(2);
      ColorTarget target(W, H, S);
      clear_color(ctx, target, glm::vec4(0.0f));
      draw_counting(ctx, target, m, st);
      const auto pattern = d3d_pattern(S);
      int decided = 0;
      const int bad = check_counts(ctx, target, m.name, [&](int x, int y, int s) {
        const glm::dvec2 p(x + (128 + 16 * pattern[s].x) / 256.0, y + (128 + 16 * pattern[s].y) / 256.0);
        const int ci = std::clamp(int((p.x - lo) / cell), 0, n - 1), cj = std::clamp(int((p.y - lo) / cell), 0, n - 1);
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di) {
            const int i = ci + di, j = cj + dj;
            if (i < 0 || j < 0 || i >= n || j >= n) continue;
            for (int k = 0; k < 2; ++k) {
              const uint32_t* t = &cells[size_t(j) * n + i][3 * k];
              const glm::dvec2 a = screen[t[0]], b = screen[t[1]], c = screen[t[2]];
              const double det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
              const double l1 = ((p.x - a.x) * (c.y - a.y) - (c.x - a.x) * (p.y - a.y)) / det;
              const double l2 = ((b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y)) / det;
              if (l1 < -1e-9 || l2 < -1e-9 || l1 + l2 > 1 + 1e-9) continue;
              const double z = depth[t[0]] + l1 * (depth[t[1]] - depth[t[0]]) + l2 * (depth[t[2]] - depth[t[0]]);
              const double gx = ((depth[t[1]] - depth[t[0]]) * (c.y - a.y) - (depth[t[2]] - depth[t[0]]) * (b.y - a.y)) / det;
              const double gy = ((depth[t[2]] - depth[t[0]]) * (b.x - a.x) - (depth[t[1]] - depth[t[0]]) * (c.x - a.x)) / det;
              const double margin = std::sqrt(gx * gx + gy * gy) / 32 + 1e-7;
              if (std::abs(z) <= margin) return -1;
              ++decided;
              return z > 0 ? 1 : 0;
            }
          }
        return -1;
      });
      EXPECT_EQ(bad, 0) << m.name << ", " << S << " samples";
      EXPECT_GT(decided, W * H * S * 9 / 10) << "test setup: most samples should be decided";
    }
}

// A fan of thin triangles around a vertex far behind the eye (w = -917): every shared edge runs
// from an on-screen vertex (w = 1) through the near plane (clip z = 1.001 (w - 0.25)), and
// clipping it from its far end would cancel catastrophically (w ~ -917 + 917.5): the two
// triangles of the edge would disagree by several subpixels. The clipped fan is an annulus
// between the on-screen polygon P and its image C at the near plane (~4x larger): samples
// farther than 1/64 pixel from both must be covered exactly once inside the annulus, never
// elsewhere.
TEST(Watertight, FanFromBehindTheEye) {
  const int W = 128, H = 128;
  const ViewportMap map(Viewport{}, W, H);
  std::mt19937 rng(99);
  for (float far_w : {-917.3f, -3.1f})
    for (int S : {1, 8}) {
      const float near = 0.25f, zscale = 1.001f;
      Mesh m;
      m.name = "fan from behind the eye, w = " + std::to_string(far_w);
      // Far behind, V may lie anywhere (its image at the near plane moves by ~ V.xy / 1200);
      // close behind, it must project near the center for C to surround P.
      const float vx = far_w < -100 ? 37.3f : 0.05f, vy = far_w < -100 ? -21.7f : -0.03f;
      m.clip.push_back({vx, vy, zscale * (far_w - near), far_w});
      const int count = budget(500, 200);
      std::vector<double> angles;
      std::uniform_real_distribution<double> u(0, 6.283185307179586);
      for (int i = 0; i < count; ++i) angles.push_back(u(rng));
      std::sort(angles.begin(), angles.end());
      std::vector<glm::dvec2> inner, outer;
      for (double a : angles) {
        const float w = 1.0f;  // P and C (an affine image of P) stay convex
        const glm::vec4 p{float(0.2 * std::cos(a) + 0.03) * w, float(0.17 * std::sin(a)) * w, zscale * (w - near), w};
        m.clip.push_back(p);
        inner.push_back(map.screen_from_ndc(double(p.x) / p.w, double(p.y) / p.w));
        // The edge to the far vertex meets the near plane (z = 0) here, in double.
        const glm::dvec4 P(p), V(m.clip[0]);
        const glm::dvec4 c = P + (V - P) * (P.z / (P.z - V.z));
        outer.push_back(map.screen_from_ndc(c.x / c.w, c.y / c.w));
      }
      for (int i = 0; i < count; ++i) {
        uint32_t a = 1 + i, b = 1 + (i + 1) % count;
        if (rng() & 1) std::swap(a, b);
        m.indices.insert(m.indices.end(), {0u, a, b});
      }
      auto polygon = [](std::vector<glm::dvec2> v) {
        FuzzyPolygon f;
        f.v = std::move(v);
        for (size_t i = 0; i < f.v.size(); ++i) {
          const glm::dvec2 a = f.v[i], b = f.v[(i + 1) % f.v.size()];
          f.area2 += a.x * b.y - b.x * a.y;
        }
        f.eps = 1.0 / 64;
        return f;
      };
      const FuzzyPolygon in = polygon(inner), out = polygon(outer);
      Context ctx(2);
      ColorTarget target(W, H, S);
      clear_color(ctx, target, glm::vec4(0.0f));
      draw_counting(ctx, target, m);
      const auto pattern = d3d_pattern(S);
      int annulus = 0;
      const int bad = check_counts(ctx, target, m.name, [&](int x, int y, int s) {
        const double px = x + (128 + 16 * pattern[s].x) / 256.0, py = y + (128 + 16 * pattern[s].y) / 256.0;
        const Cover ci = in.classify(px, py), co = out.classify(px, py);
        if (ci == Cover::Unknown || co == Cover::Unknown) return -1;
        const bool inside = co == Cover::In && ci == Cover::Out;
        annulus += inside;
        return inside ? 1 : 0;
      });
      EXPECT_EQ(bad, 0) << m.name << ", " << S << " samples";
      EXPECT_GT(annulus, 3000 * S) << "test setup";
    }
}

}  // namespace
}  // namespace luxel::rasterizer::test
