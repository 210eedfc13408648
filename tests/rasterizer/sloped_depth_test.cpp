// Sloped depth: triangles whose depth varies across them (random planes, steep slopes, slivers,
// planes across the whole target) with constant and slope-scaled depth bias, through each depth
// path a draw can take (DepthPath in detail/tile_rasterizer.hpp: Late, Early, EarlyLess,
// EarlyLessEqual), against a scalar oracle in double: every sample's depth, stencil and color and
// the occlusion count. (output_merger_test's random scenes have constant depth only.)
//
// The library evaluates the depth plane in float, so the oracle knows a triangle's depth at a
// sample only up to a bound on float rounding (plane_depth below). A depth test whose two sides
// lie within their bounds of each other cannot be decided: the sample is then "unsettled" and left
// out of every later comparison, and the occlusion count gets a range. Two depths of the same
// triangle (the same vertices, viewport and bias, drawn again by a later draw) are bit-identical
// by the library's promise (tile_rasterizer.hpp, sample_depth: early and late tests take depth from one
// place), so Equal / LessEqual redraws of earlier triangles are decided exactly; so are depths
// clamped to the viewport's depth range.

#include "pipeline_support.hpp"
#include "raster_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>
#include <random>
#include <sstream>

namespace luxel::rasterizer::test {
namespace {

enum class Path { Late, Early, EarlyLess, EarlyLessEqual };
const char* path_name(Path p) {
  switch (p) {
    case Path::Late: return "Late";
    case Path::Early: return "Early";
    case Path::EarlyLess: return "EarlyLess";
    case Path::EarlyLessEqual: return "EarlyLessEqual";
  }
  return "?";
}

struct SlopedTriangle {
  glm::dvec2 screen[3];  ///< on the 1/16 pixel grid (exact through the viewport transform)
  float z[3];            ///< NDC depth per vertex, multiples of 1/1024 in [0, 1] (no clipping)
};

struct SlopedDraw {
  PipelineState state;
  ShadeParams shade;     ///< discard / write_depth pick a functor that can (the late path)
  bool trivial = false;  ///< the functor declares kTrivial (draw.hpp)
  bool counted = false;  ///< inside the occlusion query
  int source = -1;       ///< repeats this earlier draw's triangles, viewport and bias
  std::vector<SlopedTriangle> triangles;
};

struct SlopedScene {
  Path path = Path::Early;
  int width = 80, height = 72, samples = 1;
  glm::vec4 clear_color{0.0f};
  float clear_depth = 1.0f;
  uint8_t clear_stencil = 0;
  std::vector<SlopedDraw> draws;

  std::string describe() const {
    std::ostringstream o;
    o << path_name(path) << " path, " << width << "x" << height << ", " << samples << " samples, clear depth "
      << clear_depth << " stencil " << int(clear_stencil) << "\n";
    for (size_t i = 0; i < draws.size(); ++i) {
      const SlopedDraw& d = draws[i];
      const PipelineState& st = d.state;
      const DepthStencilState& ds = st.depth_stencil;
      o << " draw " << i << (d.counted ? " (counted)" : "") << " source " << d.source << ": viewport (" << st.viewport.x
        << ", " << st.viewport.y << ", " << st.viewport.width << ") range [" << st.viewport.min_depth << ", "
        << st.viewport.max_depth << "] bias " << st.rasterizer.depth_bias << " slope bias "
        << st.rasterizer.slope_scaled_depth_bias << " cull " << int(st.rasterizer.cull) << "; depth "
        << ds.depth_enable << "/" << ds.depth_write << " func " << int(ds.depth_func) << "; stencil "
        << ds.stencil_enable << " ref " << int(ds.stencil_ref) << " front {" << int(ds.front.fail)
        << int(ds.front.depth_fail) << int(ds.front.pass) << " f" << int(ds.front.func) << "}; blend "
        << st.blend.enable << " srgb " << st.blend.srgb_write << "; alpha test " << st.alpha_test.enable << " func "
        << int(st.alpha_test.func) << " ref " << int(st.alpha_test.ref) << "; ps discard " << d.shade.discard
        << " depth " << d.shade.write_depth << " trivial " << d.trivial << "\n";
      for (const SlopedTriangle& t : d.triangles)
        o << "   " << test::describe(t.screen) << " z " << t.z[0] << " " << t.z[1] << " " << t.z[2] << "\n";
    }
    return o.str();
  }
};

// --- Scenes ---------------------------------------------------------------------------------------

SlopedTriangle random_triangle(std::mt19937& rng, int W, int H) {
  auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  auto grid = [](double v) { return std::floor(v * 16) / 16; };
  auto z_any = [&] { return float(rng() % 1025) / 1024.0f; };
  SlopedTriangle t;
  for (float& z : t.z) z = z_any();
  switch (rng() % 8) {
    case 0:
    case 1: {  // steep: depth 0 to 1 across a few pixels
      const glm::dvec2 c{grid(uniform(-2, W + 2)), grid(uniform(-2, H + 2))};
      const double r = uniform(1, 5);
      for (auto& v : t.screen) v = {grid(c.x + uniform(-r, r)), grid(c.y + uniform(-r, r))};
      t.z[0] = 0.0f;
      t.z[1] = 1.0f;
      break;
    }
    case 2: {  // a sliver: long, up to half a pixel thick, depth changing fast across it
      const glm::dvec2 a{grid(uniform(-4, W + 4)), grid(uniform(-4, H + 4))};
      const glm::dvec2 b{grid(a.x + uniform(-45, 45)), grid(a.y + uniform(-45, 45))};
      const glm::dvec2 m{grid((a.x + b.x) / 2 + uniform(-0.5, 0.5)), grid((a.y + b.y) / 2 + uniform(-0.5, 0.5))};
      t.screen[0] = a, t.screen[1] = b, t.screen[2] = m;
      t.z[2] = rng() % 2 ? 1.0f : 0.0f;
      break;
    }
    case 3: {  // a plane across the whole target
      t.screen[0] = {grid(uniform(-40, -10)), grid(uniform(-40, -10))};
      t.screen[1] = {grid(uniform(2 * W + 10, 2 * W + 40)), grid(uniform(-40, H))};
      t.screen[2] = {grid(uniform(-40, W)), grid(uniform(2 * H + 10, 2 * H + 40))};
      if (rng() % 2) std::swap(t.screen[1], t.screen[2]);
      break;
    }
    default: {  // any size, random plane
      const glm::dvec2 c{grid(uniform(-4, W + 4)), grid(uniform(-4, H + 4))};
      const double r = uniform(2, 40);
      for (auto& v : t.screen) v = {grid(c.x + uniform(-r, r)), grid(c.y + uniform(-r, r))};
      break;
    }
  }
  return t;
}

SlopedScene random_sloped_scene(uint32_t seed, Path path, int samples) {
  std::mt19937 rng(seed);
  auto pick = [&](int n) { return int(rng() % uint32_t(n)); };
  auto chance = [&](int percent) { return pick(100) < percent; };
  SlopedScene s;
  s.path = path;
  s.samples = samples;
  Viewport vp{0, 0, 128, 128};
  if (chance(40)) s.width = 48, s.height = 40, vp = {-8, 0, 64, 64};
  s.clear_color = {pick(256) / 255.0f, pick(256) / 255.0f, pick(256) / 255.0f, 1.0f};
  static constexpr float kClearDepths[] = {0.0f, 0.25f, 0.5f, 0.75f, 1.0f};
  // Less / LessEqual against a cleared 0 never pass: keep those scenes interesting.
  s.clear_depth = (path == Path::EarlyLess || path == Path::EarlyLessEqual) ? kClearDepths[2 + pick(3)]
                                                                             : kClearDepths[pick(5)];
  s.clear_stencil = uint8_t(pick(4));
  static constexpr float kRanges[][2] = {{0, 1}, {0.25f, 0.75f}, {0, 0.5f}, {0.5f, 1}};
  static constexpr float kBias[] = {0.0f, 0.0f, 1.0f / 64, -1.0f / 128, 1.0f / 4096};
  static constexpr float kSlopeBias[] = {0.0f, 0.0f, 0.5f, 1.0f, 2.0f, -1.0f};
  const int draws = 3 + pick(5);
  const int q0 = pick(draws), q1 = q0 + 1 + pick(draws - q0);
  for (int i = 0; i < draws; ++i) {
    SlopedDraw d;
    d.counted = i >= q0 && i < q1;
    PipelineState& st = d.state;
    st.rasterizer.cull = chance(70) ? CullMode::None : CullMode(1 + pick(2));
    if (i > 0 && chance(35)) {
      // An earlier draw's triangles again, as a depth pre-pass's second pass draws them.
      d.source = pick(i);
      while (s.draws[d.source].source >= 0) d.source = s.draws[d.source].source;
      st.viewport = s.draws[d.source].state.viewport;
      st.rasterizer.depth_bias = s.draws[d.source].state.rasterizer.depth_bias;
      st.rasterizer.slope_scaled_depth_bias = s.draws[d.source].state.rasterizer.slope_scaled_depth_bias;
      d.triangles = s.draws[d.source].triangles;
    } else {
      st.viewport = vp;
      const auto& range = kRanges[chance(50) ? 0 : pick(4)];
      st.viewport.min_depth = range[0];
      st.viewport.max_depth = range[1];
      st.rasterizer.depth_bias = kBias[pick(5)];
      st.rasterizer.slope_scaled_depth_bias = kSlopeBias[pick(6)];
      const int tris = 1 + pick(4);
      for (int t = 0; t < tris; ++t) d.triangles.push_back(random_triangle(rng, s.width, s.height));
    }
    DepthStencilState& ds = st.depth_stencil;
    ds.depth_enable = true;
    ds.depth_write = chance(85);
    auto random_face = [&] {
      StencilFace f;
      f.fail = StencilOp(pick(8));
      f.depth_fail = StencilOp(pick(8));
      f.pass = StencilOp(pick(8));
      f.func = CompareFunc(pick(8));
      return f;
    };
    switch (path) {
      case Path::EarlyLess: ds.depth_func = CompareFunc::Less; break;
      case Path::EarlyLessEqual: ds.depth_func = CompareFunc::LessEqual; break;
      case Path::Early: {
        static constexpr CompareFunc kDepthOnly[] = {CompareFunc::Greater, CompareFunc::GreaterEqual, CompareFunc::Equal,
                                                     CompareFunc::NotEqual, CompareFunc::Always, CompareFunc::Never};
        if (chance(55)) {
          ds.depth_func = d.source >= 0 && chance(60) ? CompareFunc::Equal : kDepthOnly[pick(6)];
        } else {  // depth + stencil: any compare function, Less and LessEqual included
          ds.depth_func = d.source >= 0 && chance(50) ? CompareFunc::Equal : CompareFunc(pick(8));
          ds.stencil_enable = true;
        }
        break;
      }
      case Path::Late: {
        ds.depth_func = d.source >= 0 && chance(50) ? CompareFunc::Equal : CompareFunc(pick(8));
        ds.stencil_enable = chance(40);
        const int kind = pick(4);
        d.shade.discard = kind == 0 || kind == 3;
        d.shade.write_depth = kind == 1 || (kind == 3 && chance(50));
        st.alpha_test.enable = kind == 2 || chance(20);
        st.alpha_test.func = CompareFunc(pick(8));
        st.alpha_test.ref = uint8_t(rng());
        break;
      }
    }
    if (ds.stencil_enable) {
      ds.stencil_ref = uint8_t(pick(4));
      ds.two_sided_stencil = chance(50);
      ds.front = random_face();
      ds.back = random_face();
    }
    // The fixed paths are a trivial functor's (DepthPath): their tests draw with one always.
    const bool maybe_trivial = chance(40);
    d.trivial = path == Path::EarlyLess || path == Path::EarlyLessEqual || (path != Path::Late && maybe_trivial);
    st.blend.enable = chance(30);
    st.blend.src = BlendFactor::SrcAlpha;
    st.blend.dst = BlendFactor::InvSrcAlpha;
    st.blend.srgb_write = chance(10);
    d.shade.seed = rng();
    s.draws.push_back(std::move(d));
  }
  return s;
}

// --- The library's side ---------------------------------------------------------------------------

/// What the pixel functors saw, to tell which depth path ran.
struct FunctorCounts {
  std::atomic<uint64_t> without_live{0};  ///< invocations with no live lane
};

template <bool kDiscard, bool kDepth, bool kIsTrivial>
struct SlopedPS {
  static constexpr bool kCanDiscard = kDiscard, kWritesDepth = kDepth, kTrivial = kIsTrivial;
  ShadeParams params;
  FunctorCounts* counts;
  void operator()(const PixelInput<1>& in, PixelOutput& out) const {
    if (in.live == 0) counts->without_live.fetch_add(1, std::memory_order_relaxed);
    const auto xs = lanes_of(in.x), ys = lanes_of(in.y);
    std::array<float, simd::kLanes> c[4], depth;
    simd::LaneBits discard = 0;
    for (int l = 0; l < simd::kLanes; ++l) {
      const ShadeResult r = shade(params, int(std::floor(xs[l])), int(std::floor(ys[l])));
      for (int k = 0; k < 4; ++k) c[k][l] = r.color[k];
      depth[l] = r.depth;
      if (r.discard) discard |= 1u << l;
    }
    out.color = {from_lanes(c[0]), from_lanes(c[1]), from_lanes(c[2]), from_lanes(c[3])};
    if constexpr (kDepth) out.depth = from_lanes(depth);
    if constexpr (kDiscard) out.discard = discard;
  }
};

struct DrawRecord {
  DrawStats stats;
  uint64_t without_live = 0;
};

struct SlopedOutput {
  std::vector<uint32_t> color;
  std::vector<float> depth;
  std::vector<uint8_t> stencil;
  uint64_t query = 0;
  std::vector<DrawRecord> draws;
};

SlopedOutput render(Context& ctx, const SlopedScene& scene) {
  ColorTarget color(scene.width, scene.height, scene.samples);
  DepthStencilTarget ds(scene.width, scene.height, scene.samples);
  clear_color(ctx, color, scene.clear_color);
  clear_depth_stencil(ctx, ds, scene.clear_depth, scene.clear_stencil);
  const Framebuffer fb{&color, &ds};
  SlopedOutput out;
  OcclusionQuery query;
  bool active = false;
  for (const SlopedDraw& d : scene.draws) {
    if (d.counted && !active) ctx.begin_query(query), active = true;
    if (!d.counted && active) ctx.end_query(), active = false;
    const ViewportMap map(d.state.viewport, scene.width, scene.height);
    std::vector<glm::vec4> clip;
    for (const SlopedTriangle& t : d.triangles)
      for (int k = 0; k < 3; ++k) clip.push_back(map.clip_from_screen(t.screen[k].x, t.screen[k].y, t.z[k]));
    FunctorCounts counts;
    const Geometry g = Geometry::non_indexed(uint32_t(clip.size()));
    const PositionVS vs{clip.data()};
    ctx.flush();
    ctx.reset_stats();
    const ShadeParams& p = d.shade;
    if (p.discard && p.write_depth) {
      draw(ctx, fb, d.state, g, vs, SlopedPS<true, true, false>{p, &counts});
    } else if (p.discard) {
      draw(ctx, fb, d.state, g, vs, SlopedPS<true, false, false>{p, &counts});
    } else if (p.write_depth) {
      draw(ctx, fb, d.state, g, vs, SlopedPS<false, true, false>{p, &counts});
    } else if (d.trivial) {
      draw(ctx, fb, d.state, g, vs, SlopedPS<false, false, true>{p, &counts});
    } else {
      draw(ctx, fb, d.state, g, vs, SlopedPS<false, false, false>{p, &counts});
    }
    ctx.flush();
    out.draws.push_back({ctx.stats(), counts.without_live.load()});
  }
  if (active) ctx.end_query();
  out.query = ctx.query_result(query);
  out.color = read_color(ctx, color);
  for (int y = 0; y < scene.height; ++y)
    for (int x = 0; x < scene.width; ++x)
      for (int s = 0; s < scene.samples; ++s) {
        out.depth.push_back(ds.depth(x, y, s));
        out.stencil.push_back(ds.stencil(x, y, s));
      }
  return out;
}

// --- The oracle --------------------------------------------------------------------------------

/// A depth as the oracle knows it: within `tol` of `v`; `id` >= 0 names the triangle it comes
/// from (equal ids: bit-identical values), -1 for values known exactly.
struct RefDepth {
  double v = 0, tol = 0;
  int64_t id = -1;
};

/// The depth plane of a triangle on its snapped vertices, in double.
struct RefPlane {
  double x0 = 0, y0 = 0, z0 = 0, dzdx = 0, dzdy = 0, bias = 0, bias_terms = 0;
  double lo = 0, hi = 1;
  int64_t id = -1;

  RefPlane(const ExactTriangle& t, const SlopedTriangle& st, const PipelineState& s, int64_t id_)
      : lo(s.viewport.min_depth), hi(s.viewport.max_depth), id(id_) {
    double x[3], y[3], z[3];
    for (int k = 0; k < 3; ++k) {
      x[k] = t.X[k] / 256.0;
      y[k] = t.Y[k] / 256.0;
      z[k] = lo + double(st.z[k]) * (hi - lo);  // the viewport's depth mapping
    }
    const double area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
    dzdx = ((z[1] - z[0]) * (y[2] - y[0]) - (z[2] - z[0]) * (y[1] - y[0])) / area;
    dzdy = ((z[2] - z[0]) * (x[1] - x[0]) - (z[1] - z[0]) * (x[2] - x[0])) / area;
    x0 = x[0], y0 = y[0], z0 = z[0];
    // D3D9 (state.hpp): depth_bias + slope_scaled_depth_bias * max(|dz/dx|, |dz/dy|), before the
    // clamp to the viewport's range.
    const double slope_term = double(s.rasterizer.slope_scaled_depth_bias) * std::max(std::abs(dzdx), std::abs(dzdy));
    bias = s.rasterizer.depth_bias + slope_term;
    bias_terms = std::abs(s.rasterizer.depth_bias) + std::abs(slope_term);
  }

  /// At a sample position (pixels), clamped to the depth range. The bound covers float rounding
  /// of the vertex depths, the gradients and the plane's evaluation relative to vertex 0 (a few
  /// ulps of the terms' magnitudes), with a margin of 16.
  RefDepth at(double sx, double sy) const {
    const double dx = sx - x0, dy = sy - y0;
    const double z = z0 + dzdx * dx + dzdy * dy + bias;
    const double tol =
        std::ldexp(1.0 + std::abs(z0) + std::abs(dzdx) * (std::abs(dx) + 16) + std::abs(dzdy) * (std::abs(dy) + 16) +
                       bias_terms,
                   -20);
    if (z - tol >= hi) return {hi, 0, -1};
    if (z + tol <= lo) return {lo, 0, -1};
    return {std::clamp(z, lo, hi), tol, id};
  }
};

/// The outcome of a depth compare: 0 fails, 1 passes, nullopt undecidable.
std::optional<bool> ref_depth_compare(CompareFunc f, const RefDepth& z, const RefDepth& stored) {
  if (f == CompareFunc::Never) return false;
  if (f == CompareFunc::Always) return true;
  if (z.id >= 0 && z.id == stored.id) return ref_compare(f, 0.0, 0.0);
  if ((z.tol == 0 && stored.tol == 0) || std::abs(z.v - stored.v) > z.tol + stored.tol)
    return ref_compare(f, z.v, stored.v);
  return std::nullopt;
}

struct SlopedReference {
  std::vector<std::vector<uint32_t>> color;  ///< possible values per sample
  std::vector<RefDepth> depth;
  std::vector<uint8_t> stencil;
  std::vector<uint8_t> settled;
  uint64_t query = 0, query_unknown = 0;
  // What the depth tests did, over settled samples (a scene that never passes or never fails
  // says little).
  uint64_t depth_passed = 0, depth_failed = 0, unsettled = 0, tested = 0;
  uint64_t equal_redraw_passed = 0;  ///< passes of Equal decided by identity
};

SlopedReference reference(const SlopedScene& scene) {
  const int W = scene.width, H = scene.height, S = scene.samples;
  const size_t n = size_t(W) * H * S;
  SlopedReference ref;
  uint32_t clear = 0;
  for (int c = 0; c < 4; ++c) clear |= uint32_t(unorm8(scene.clear_color[c])) << (8 * c);
  ref.color.assign(n, {clear});
  ref.depth.assign(n, RefDepth{scene.clear_depth, 0, -1});
  ref.stencil.assign(n, scene.clear_stencil);
  ref.settled.assign(n, 1);
  const auto pattern = d3d_pattern(S);
  for (size_t di = 0; di < scene.draws.size(); ++di) {
    const SlopedDraw& d = scene.draws[di];
    const PipelineState& st = d.state;
    const DepthStencilState& ds = st.depth_stencil;
    const PixelRect rect = writable_rect(st, W, H);
    const double lo = st.viewport.min_depth, hi = st.viewport.max_depth;
    const int64_t root = d.source >= 0 ? d.source : int64_t(di);
    for (size_t ti = 0; ti < d.triangles.size(); ++ti) {
      const SlopedTriangle& t = d.triangles[ti];
      const RefPrimitive p = make_exact_primitive(t.screen, st.rasterizer.cull);
      if (p.culled) continue;
      const RefPlane plane(p.tri, t, st, root * 64 + int64_t(ti));
      const bool clockwise = p.tri.area2 > 0;
      const bool front = st.rasterizer.front_counter_clockwise ? !clockwise : clockwise;
      const StencilFace& face = (ds.two_sided_stencil && !front) ? ds.back : ds.front;
      for (int y = std::max(rect.y0, p.by0); y < std::min(rect.y1, p.by1); ++y)
        for (int x = std::max(rect.x0, p.bx0); x < std::min(rect.x1, p.bx1); ++x) {
          bool covered[8], any = false;
          for (int s = 0; s < S; ++s) any |= covered[s] = p.cover(x, y, pattern[s]) == Cover::In;
          if (!any) continue;
          const ShadeResult sh = shade(d.shade, x, y);
          if (d.shade.discard && sh.discard) continue;
          if (st.alpha_test.enable && !ref_compare(st.alpha_test.func, unorm8(sh.color[3]), st.alpha_test.ref)) continue;
          for (int s = 0; s < S; ++s) {
            if (!covered[s]) continue;
            const size_t i = sample_index(W, S, x, y, s);
            if (!ref.settled[i]) {
              ref.query_unknown += d.counted;
              continue;
            }
            const RefDepth z = d.shade.write_depth
                                   ? RefDepth{std::clamp(double(sh.depth), lo, hi), 0, -1}
                                   : plane.at(x + (128 + 16 * pattern[s].x) / 256.0, y + (128 + 16 * pattern[s].y) / 256.0);
            const std::optional<bool> depth_pass = ref_depth_compare(ds.depth_func, z, ref.depth[i]);
            ++ref.tested;
            if (!depth_pass) {
              ref.settled[i] = 0;
              ++ref.unsettled;
              ref.query_unknown += d.counted;
              continue;
            }
            *depth_pass ? ++ref.depth_passed : ++ref.depth_failed;
            if (*depth_pass && ds.depth_func == CompareFunc::Equal && z.id >= 0) ++ref.equal_redraw_passed;
            bool pass = *depth_pass;
            if (ds.stencil_enable) {
              const uint8_t v = ref.stencil[i];
              const bool stencil_pass =
                  ref_compare(face.func, ds.stencil_ref & ds.stencil_read_mask, v & ds.stencil_read_mask);
              const StencilOp op = !stencil_pass ? face.fail : !*depth_pass ? face.depth_fail : face.pass;
              const uint8_t updated = ref_stencil_op(op, v, ds.stencil_ref);
              ref.stencil[i] = uint8_t((v & ~ds.stencil_write_mask) | (updated & ds.stencil_write_mask));
              pass = pass && stencil_pass;
            }
            if (!pass) continue;
            if (ds.depth_write) ref.depth[i] = z;
            ref.query += d.counted;
            std::vector<uint32_t> next;
            for (uint32_t dst : ref.color[i])
              for (uint32_t v : ref_output(st.blend, sh.color, dst))
                if (std::find(next.begin(), next.end(), v) == next.end()) next.push_back(v);
            ref.color[i] = std::move(next);
          }
        }
    }
  }
  return ref;
}

int compare(const SlopedScene& scene, const SlopedOutput& out, const SlopedReference& ref,
            std::vector<std::string>& messages, int max_messages) {
  const int W = scene.width, S = scene.samples;
  int bad = 0;
  auto where = [&](size_t i) {
    std::ostringstream o;
    o << "pixel (" << int((i / S) % W) << ", " << int(i / S / W) << ") sample " << int(i % S);
    return o.str();
  };
  if (out.query < ref.query || out.query > ref.query + ref.query_unknown) {
    ++bad;
    messages.push_back("occlusion query " + std::to_string(out.query) + ", reference " + std::to_string(ref.query) +
                       " + up to " + std::to_string(ref.query_unknown));
  }
  for (size_t i = 0; i < ref.color.size(); ++i) {
    if (!ref.settled[i]) continue;
    const RefDepth& z = ref.depth[i];
    const bool depth_ok = z.tol == 0 ? double(out.depth[i]) == z.v : std::abs(double(out.depth[i]) - z.v) <= z.tol;
    const auto& c = ref.color[i];
    const bool color_ok = std::find(c.begin(), c.end(), out.color[i]) != c.end();
    if (depth_ok && color_ok && out.stencil[i] == ref.stencil[i]) continue;
    if (bad++ >= max_messages) continue;
    std::ostringstream o;
    o.precision(9);
    o << where(i) << ": depth " << out.depth[i] << " stencil " << int(out.stencil[i]) << " color 0x" << std::hex
      << out.color[i] << std::dec << "; reference depth " << z.v << " +- " << z.tol << " stencil " << int(ref.stencil[i])
      << " color";
    for (uint32_t v : c) o << " 0x" << std::hex << v;
    messages.push_back(o.str());
  }
  return bad;
}

// --- The tests ---------------------------------------------------------------------------------

void run_path(Path path, uint32_t seed0) {
  const int scenes = budget(120, 12);
  Context ctx(2);
  int failures = 0;
  uint64_t tested = 0, passed = 0, failed = 0, unsettled = 0, equal_redraws = 0, counted = 0, query_slack = 0;
  // Stamps with coverage that the pixel functor never saw (rejected by an early depth test), and
  // invocations with no live lane (early-rejected stamps of a trivial functor, draw.hpp), split
  // by functor kind and by stencil.
  uint64_t skipped[2][2] = {}, without_live[2][2] = {};
  for (int i = 0; i < scenes && failures < 3; ++i) {
    const int S = 1 << (i % 4);
    const SlopedScene scene = random_sloped_scene(seed0 + uint32_t(i), path, S);
    const SlopedOutput out = render(ctx, scene);
    const SlopedReference ref = reference(scene);
    std::vector<std::string> messages;
    const int bad = compare(scene, out, ref, messages, 8);
    tested += ref.tested, passed += ref.depth_passed, failed += ref.depth_failed, unsettled += ref.unsettled;
    equal_redraws += ref.equal_redraw_passed, counted += ref.query, query_slack += ref.query_unknown;
    for (size_t k = 0; k < scene.draws.size(); ++k) {
      const DrawStats& st = out.draws[k].stats;
      const int trivial = scene.draws[k].trivial, stencil = scene.draws[k].state.depth_stencil.stencil_enable;
      skipped[trivial][stencil] += st.stamps_full + st.stamps_partial - st.stamps_shaded;
      without_live[trivial][stencil] += out.draws[k].without_live;
    }
    if (bad) {
      ++failures;
      ADD_FAILURE() << path_name(path) << " scene " << i << " (seed " << seed0 + i << "): " << bad << " mismatches\n"
                    << join(messages) << scene.describe();
    }
  }
  // The comparison must have said something: real depth tests both ways, few undecidable samples.
  EXPECT_GT(passed, tested / 20) << "depth passes";
  EXPECT_GT(failed, tested / 20) << "depth failures";
  EXPECT_LT(unsettled, tested / 100) << unsettled << " of " << tested << " depth tests undecidable";
  EXPECT_GT(counted, 0u);
  if ((path == Path::Early || path == Path::Late) && !kReducedRun) {  // 12 scenes may have none
    EXPECT_GT(equal_redraws, 0u) << "Equal redraws of earlier triangles";
  }
  // Which path ran, as far as a functor can tell: the late path shades every covered stamp with
  // live lanes; the early paths leave depth-rejected stamps unshaded, except that a trivial
  // functor is run on them with no live lane -- on the depth-only paths, not with stencil.
  // (EarlyLess and EarlyLessEqual are taken by trivial functors only: DepthPath.)
  if (path == Path::Late) {
    EXPECT_EQ(skipped[0][0] + skipped[0][1], 0u);
    EXPECT_EQ(without_live[0][0] + without_live[0][1], 0u);
  } else {
    if (path == Path::Early) {  // the fixed paths' scenes draw with trivial functors only
      EXPECT_GT(skipped[0][0], 0u) << "no stamp was rejected before shading";
    }
    EXPECT_GT(without_live[1][0], 0u) << "a trivial functor never ran on a rejected stamp";
    EXPECT_EQ(skipped[1][0], 0u) << "the depth-only paths run a trivial functor on every covered stamp";
    EXPECT_EQ(without_live[0][0] + without_live[0][1], 0u);
    if (path == Path::Early) {
      EXPECT_GT(skipped[1][1], 0u) << "with stencil, rejected stamps are skipped even for a trivial functor";
      EXPECT_EQ(without_live[1][1], 0u);
    }
  }
  std::cout << "[          ] " << path_name(path) << ": " << tested << " depth tests (" << passed << " passed, " << failed
            << " failed, " << unsettled << " undecidable), " << equal_redraws << " Equal passes of redrawn triangles, "
            << "query " << counted << " + up to " << query_slack << "\n";
}

TEST(SlopedDepth, LatePathMatchesTheOracle) { run_path(Path::Late, 41000); }
TEST(SlopedDepth, EarlyPathMatchesTheOracle) { run_path(Path::Early, 42000); }
TEST(SlopedDepth, EarlyLessPathMatchesTheOracle) { run_path(Path::EarlyLess, 43000); }
TEST(SlopedDepth, EarlyLessEqualPathMatchesTheOracle) { run_path(Path::EarlyLessEqual, 44000); }

// Slope-scaled bias alone, on a plane whose x and y slopes differ by 8x: every stored depth is the
// plane plus 2 max(|dz/dx|, |dz/dy|) (state.hpp). The smaller slope, the sum of both, or no bias
// would be off by at least 1/1024.
TEST(SlopedDepth, SlopeScaledBiasUsesTheSteeperAxis) {
  const int W = 64, H = 64;
  for (int S : {1, 4}) {
    Context ctx(1);
    ColorTarget color(W, H, S);
    DepthStencilTarget ds(W, H, S);
    clear_color(ctx, color, glm::vec4(0.0f));
    clear_depth_stencil(ctx, ds, 1.0f, 0);
    const ViewportMap map(Viewport{0, 0, 64, 64}, W, H);
    // z = 1/64 + x/256 + y/2048 over the target: dz/dx = 1/256, dz/dy = 1/2048 per pixel.
    auto z_at = [](double x, double y) { return float(1.0 / 64 + x / 256 + y / 2048); };
    const glm::dvec2 v[3] = {{0, 0}, {128, 0}, {0, 128}};
    std::vector<glm::vec4> clip;
    for (const auto& p : v) clip.push_back(map.clip_from_screen(p.x, p.y, z_at(p.x, p.y)));
    PipelineState st;
    st.viewport = {0, 0, 64, 64};
    st.rasterizer.cull = CullMode::None;
    st.rasterizer.slope_scaled_depth_bias = 2.0f;
    draw(ctx, Framebuffer{&color, &ds}, st, Geometry::non_indexed(3), PositionVS{clip.data()}, ConstantPS{});
    ctx.flush();
    const auto pattern = d3d_pattern(S);
    int bad = 0;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x)
        for (int s = 0; s < S; ++s) {
          const double sx = x + (128 + 16 * pattern[s].x) / 256.0, sy = y + (128 + 16 * pattern[s].y) / 256.0;
          const double expect = 1.0 / 64 + sx / 256 + sy / 2048 + 2.0 / 256;
          if (std::abs(ds.depth(x, y, s) - expect) > 1e-6 && bad++ < 5)
            ADD_FAILURE() << S << " samples, pixel (" << x << ", " << y << ") sample " << s << ": depth "
                          << ds.depth(x, y, s) << ", expected " << expect;
        }
    EXPECT_EQ(bad, 0) << S << " samples";
  }
}

}  // namespace
}  // namespace luxel::rasterizer::test
