#include "pipeline_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <sstream>

namespace luxel::rasterizer::test {

namespace {

uint32_t mix(uint32_t a, uint32_t b) {
  uint32_t h = a * 0x9E3779B1u ^ (b + 0x7F4A7C15u + (a << 6) + (a >> 2));
  h ^= h >> 15;
  h *= 0x2C1B3C6Du;
  h ^= h >> 12;
  h *= 0x297A2D39u;
  h ^= h >> 15;
  return h;
}

}  // namespace

ShadeResult shade(const ShadeParams& p, int x, int y) {
  const uint32_t h = mix(mix(p.seed, uint32_t(x) * 7919u), uint32_t(y));
  ShadeResult r;
  for (int c = 0; c < 4; ++c) {
    const uint32_t k = mix(h, 100 + c);
    switch ((k >> 8) % 16) {
      case 11: {
        // Between multiples of 1/255, at least 0.05 steps from a rounding tie.
        const double f = 0.05 + 0.4 * ((k >> 16) % 1000) / 999.0;
        r.color[c] = float((double(k & 255) + ((k >> 12) & 1 ? 0.5 + f : f)) / 255.0);
        break;
      }
      case 12: r.color[c] = -0.5f; break;
      case 13: r.color[c] = 1.5f; break;
      case 14: r.color[c] = p.allow_nan ? std::numeric_limits<float>::quiet_NaN() : 0.25f; break;
      case 15: r.color[c] = 1.0f; break;
      default: r.color[c] = float(k & 255) / 255.0f; break;
    }
  }
  r.discard = p.discard && mix(h, 7) % 4 == 0;
  static constexpr float kDepths[] = {-0.25f, 0.0f, 0.25f, 0.5f, 0.625f, 0.75f, 1.0f, 1.25f};
  r.depth = kDepths[mix(h, 9) % 8];
  return r;
}

namespace {

template <bool kDiscard, bool kDepth, bool kTrivialPS = false>
struct ScenePS {
  static constexpr bool kCanDiscard = kDiscard, kWritesDepth = kDepth, kTrivial = kTrivialPS;
  ShadeParams params;
  void operator()(const PixelInput<1>& in, PixelOutput& out) const {
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

template <bool kDiscard, bool kDepth, bool kTrivialPS = false>
void draw_with(Context& ctx, const Framebuffer& fb, const SceneDraw& d, const std::vector<glm::vec4>& clip) {
  draw(ctx, fb, d.state, Geometry::non_indexed(uint32_t(clip.size())), PositionVS{clip.data()},
       ScenePS<kDiscard, kDepth, kTrivialPS>{d.shade});
}

double sat(double v) { return std::isnan(v) ? 0.0 : std::clamp(v, 0.0, 1.0); }

/// The 8-bit values a converted channel may take: round-half-even of v255, and its neighbour
/// when v255 lies within `band` of a rounding boundary.
void rounding_candidates(double v255, double band, int out[2], int& n) {
  const int r = int(round_half_even(v255));
  out[0] = std::clamp(r, 0, 255);
  n = 1;
  const double f = v255 - std::floor(v255);
  if (std::abs(f - 0.5) < band) {
    const int other = (r == int(std::floor(v255))) ? r + 1 : r - 1;
    if (other >= 0 && other <= 255) out[n++] = other;
  }
}

}  // namespace

bool ref_compare(CompareFunc f, double a, double b) {
  switch (f) {
    case CompareFunc::Never: return false;
    case CompareFunc::Less: return a < b;
    case CompareFunc::Equal: return a == b;
    case CompareFunc::LessEqual: return a <= b;
    case CompareFunc::Greater: return a > b;
    case CompareFunc::NotEqual: return a != b;
    case CompareFunc::GreaterEqual: return a >= b;
    case CompareFunc::Always: return true;
  }
  return true;
}

uint8_t ref_stencil_op(StencilOp op, uint8_t v, uint8_t ref) {
  switch (op) {
    case StencilOp::Keep: return v;
    case StencilOp::Zero: return 0;
    case StencilOp::Replace: return ref;
    case StencilOp::IncrSat: return v == 255 ? 255 : v + 1;
    case StencilOp::DecrSat: return v == 0 ? 0 : v - 1;
    case StencilOp::Invert: return uint8_t(~v);
    case StencilOp::Incr: return uint8_t(v + 1);
    case StencilOp::Decr: return uint8_t(v - 1);
  }
  return v;
}

std::vector<uint32_t> ref_output(const BlendState& b, const float src_in[4], uint32_t dst) {
  double src[4], d[4];
  for (int c = 0; c < 4; ++c) src[c] = sat(src_in[c]);
  for (int c = 0; c < 4; ++c) {
    const int v = channel(dst, c);
    d[c] = (b.srgb_write && c < 3) ? srgb_to_linear(v / 255.0) : v / 255.0;
  }
  int options[4][2], counts[4];
  for (int c = 0; c < 4; ++c) {
    if (!((b.write_mask >> c) & 1)) {
      options[c][0] = channel(dst, c);
      counts[c] = 1;
      continue;
    }
    double r = src[c];
    if (b.enable) {
      const bool alpha = c == 3 && b.separate_alpha;
      const BlendFactor fs = alpha ? b.src_alpha : b.src, fd = alpha ? b.dst_alpha : b.dst;
      const BlendOp op = alpha ? b.op_alpha : b.op;
      auto factor = [&](BlendFactor f) -> double {
        switch (f) {
          case BlendFactor::Zero: return 0;
          case BlendFactor::One: return 1;
          case BlendFactor::SrcColor: return src[c];
          case BlendFactor::InvSrcColor: return 1 - src[c];
          case BlendFactor::SrcAlpha: return src[3];
          case BlendFactor::InvSrcAlpha: return 1 - src[3];
          case BlendFactor::DestAlpha: return d[3];
          case BlendFactor::InvDestAlpha: return 1 - d[3];
          case BlendFactor::DestColor: return d[c];
          case BlendFactor::InvDestColor: return 1 - d[c];
          case BlendFactor::SrcAlphaSat: return c == 3 ? 1.0 : std::min(src[3], 1 - d[3]);
          case BlendFactor::BlendFactor: return b.blend_factor[c];
          case BlendFactor::InvBlendFactor: return 1 - double(b.blend_factor[c]);
        }
        return 1;
      };
      switch (op) {
        case BlendOp::Add: r = src[c] * factor(fs) + d[c] * factor(fd); break;
        case BlendOp::Subtract: r = src[c] * factor(fs) - d[c] * factor(fd); break;
        case BlendOp::RevSubtract: r = d[c] * factor(fd) - src[c] * factor(fs); break;
        case BlendOp::Min: r = std::min(src[c], d[c]); break;
        case BlendOp::Max: r = std::max(src[c], d[c]); break;
      }
      r = sat(r);
    }
    if (b.srgb_write && c < 3) {
      rounding_candidates(std::clamp(linear_to_srgb(r), 0.0, 1.0) * 255.0, 0.03, options[c], counts[c]);
    } else {
      rounding_candidates(r * 255.0, 1e-3, options[c], counts[c]);
    }
  }
  std::vector<uint32_t> out;
  for (int i0 = 0; i0 < counts[0]; ++i0)
    for (int i1 = 0; i1 < counts[1]; ++i1)
      for (int i2 = 0; i2 < counts[2]; ++i2)
        for (int i3 = 0; i3 < counts[3]; ++i3)
          out.push_back(rgba8(options[0][i0], options[1][i1], options[2][i2], options[3][i3]));
  return out;
}

// --- Scenes --------------------------------------------------------------------------------------

Scene random_scene(uint32_t seed, int samples) {
  std::mt19937 rng(seed);
  auto pick = [&](int n) { return int(rng() % uint32_t(n)); };
  auto chance = [&](int percent) { return pick(100) < percent; };
  auto byte = [&]() { return uint8_t(rng() & 255); };
  Scene s;
  s.samples = samples;
  Viewport vp;
  if (chance(50)) {
    s.width = 48, s.height = 40, vp = {-8, 0, 64, 64};
  } else {
    s.width = 80, s.height = 70, vp = {0, 0, 128, 128};
  }
  s.has_color = !chance(12);
  s.has_depth_stencil = !chance(15);
  if (!s.has_color && !s.has_depth_stencil) s.has_color = true;
  s.clear_color = {pick(256) / 255.0f, pick(256) / 255.0f, pick(256) / 255.0f, pick(256) / 255.0f};
  static constexpr float kClearDepths[] = {0.0f, 0.25f, 0.5f, 0.75f, 1.0f};
  s.clear_depth = kClearDepths[pick(5)];
  s.clear_stencil = chance(50) ? 0 : byte();
  static constexpr float kZ[] = {0.0f, 0.125f, 0.25f, 0.375f, 0.5f, 0.625f, 0.75f, 1.0f};
  static constexpr float kRanges[][2] = {{0, 1}, {0.25f, 0.75f}, {0, 0.5f}, {0.5f, 0.5f}, {0.5f, 1}};
  static constexpr uint8_t kRefs[] = {0, 1, 2, 0x7f, 0x80, 0xfe, 0xff};
  const int draws = 3 + pick(6);
  const int q0 = pick(draws + 1), q1 = q0 + pick(draws + 1 - q0);
  auto random_face = [&]() {
    StencilFace f;
    f.fail = StencilOp(pick(8));
    f.depth_fail = StencilOp(pick(8));
    f.pass = StencilOp(pick(8));
    f.func = CompareFunc(pick(8));
    return f;
  };
  for (int i = 0; i < draws; ++i) {
    SceneDraw d;
    d.counted = i >= q0 && i < q1;
    PipelineState& st = d.state;
    st.viewport = vp;
    const auto& range = kRanges[chance(50) ? 0 : pick(5)];
    st.viewport.min_depth = range[0];
    st.viewport.max_depth = range[1];
    st.rasterizer.cull = chance(60) ? CullMode::None : CullMode(1 + pick(2));
    st.rasterizer.front_counter_clockwise = chance(50);
    if (chance(20)) st.rasterizer.depth_bias = chance(50) ? 0.125f : -0.0625f;
    if (chance(20)) st.rasterizer.slope_scaled_depth_bias = 2.0f;  // constant depth: no slope
    DepthStencilState& ds = st.depth_stencil;
    ds.depth_enable = chance(85);
    ds.depth_write = chance(70);
    ds.depth_func = CompareFunc(pick(8));
    ds.stencil_enable = chance(50);
    ds.two_sided_stencil = chance(50);
    ds.stencil_ref = chance(70) ? kRefs[pick(7)] : byte();
    ds.stencil_read_mask = chance(60) ? 0xff : byte();
    ds.stencil_write_mask = chance(60) ? 0xff : byte();
    ds.front = random_face();
    ds.back = random_face();
    BlendState& b = st.blend;
    b.enable = chance(60);
    b.src = BlendFactor(pick(13));
    b.dst = BlendFactor(pick(13));
    b.op = BlendOp(pick(5));
    b.separate_alpha = chance(40);
    b.src_alpha = BlendFactor(pick(13));
    b.dst_alpha = BlendFactor(pick(13));
    b.op_alpha = BlendOp(pick(5));
    b.blend_factor = {pick(256) / 255.0f, pick(256) / 255.0f, pick(256) / 255.0f, pick(256) / 255.0f};
    b.write_mask = chance(60) ? uint8_t(kWriteAll) : uint8_t(pick(16));
    b.srgb_write = chance(25);
    st.alpha_test.enable = chance(30);
    st.alpha_test.func = CompareFunc(pick(8));
    st.alpha_test.ref = chance(50) ? byte() : kRefs[pick(7)];
    d.shade.seed = rng();
    d.shade.discard = chance(30);
    d.shade.write_depth = chance(20);
    d.shade.trivial = d.shade.seed & 1;  // (from a value drawn already: the scenes stay as they were)
    const int tris = 1 + pick(3);
    for (int t = 0; t < tris; ++t) {
      SceneTriangle tri;
      const double cx = pick(16 * (s.width + 8)) / 16.0 - 4, cy = pick(16 * (s.height + 8)) / 16.0 - 4;
      const int r = 16 * (2 + pick(chance(50) ? 12 : 40));
      for (auto& v : tri.screen) v = {cx + (pick(2 * r + 1) - r) / 16.0, cy + (pick(2 * r + 1) - r) / 16.0};
      tri.z = kZ[pick(8)];
      d.triangles.push_back(tri);
    }
    s.draws.push_back(d);
  }
  return s;
}

std::string Scene::describe() const {
  std::ostringstream o;
  o << width << "x" << height << ", " << samples << " samples, color " << has_color << ", depth-stencil "
    << has_depth_stencil << ", clear depth " << clear_depth << " stencil " << int(clear_stencil) << "\n";
  for (size_t i = 0; i < draws.size(); ++i) {
    const SceneDraw& d = draws[i];
    const PipelineState& st = d.state;
    const DepthStencilState& ds = st.depth_stencil;
    const BlendState& b = st.blend;
    o << " draw " << i << (d.counted ? " (counted)" : "") << ": cull " << int(st.rasterizer.cull) << " front_ccw "
      << st.rasterizer.front_counter_clockwise << " bias " << st.rasterizer.depth_bias << " range ["
      << st.viewport.min_depth << ", " << st.viewport.max_depth << "]; depth " << ds.depth_enable << "/"
      << ds.depth_write << " func " << int(ds.depth_func) << "; stencil " << ds.stencil_enable << " two-sided "
      << ds.two_sided_stencil << " ref " << int(ds.stencil_ref) << " masks " << int(ds.stencil_read_mask) << "/"
      << int(ds.stencil_write_mask) << " front {" << int(ds.front.fail) << int(ds.front.depth_fail)
      << int(ds.front.pass) << " f" << int(ds.front.func) << "} back {" << int(ds.back.fail) << int(ds.back.depth_fail)
      << int(ds.back.pass) << " f" << int(ds.back.func) << "}; blend " << b.enable << " " << int(b.src) << "/"
      << int(b.dst) << " op " << int(b.op) << " sep " << b.separate_alpha << " " << int(b.src_alpha) << "/"
      << int(b.dst_alpha) << " op " << int(b.op_alpha) << " mask " << int(b.write_mask) << " srgb " << b.srgb_write
      << "; alpha test " << st.alpha_test.enable << " func " << int(st.alpha_test.func) << " ref "
      << int(st.alpha_test.ref) << "; ps discard " << d.shade.discard << " depth " << d.shade.write_depth << "\n";
    for (const SceneTriangle& t : d.triangles) o << "   " << test::describe(t.screen) << " z " << t.z << "\n";
  }
  return o.str();
}

SceneOutput render_scene(Context& ctx, const Scene& scene, SceneEnd end) {
  std::unique_ptr<ColorTarget> color;
  std::unique_ptr<DepthStencilTarget> ds;
  if (scene.has_color) color = std::make_unique<ColorTarget>(scene.width, scene.height, scene.samples);
  if (scene.has_depth_stencil) ds = std::make_unique<DepthStencilTarget>(scene.width, scene.height, scene.samples);
  if (color) clear_color(ctx, *color, scene.clear_color);
  if (ds) clear_depth_stencil(ctx, *ds, scene.clear_depth, scene.clear_stencil);
  const Framebuffer fb{color.get(), ds.get()};
  OcclusionQuery query;
  bool active = false;
  for (const SceneDraw& d : scene.draws) {
    if (d.counted && !active) ctx.begin_query(query), active = true;
    if (!d.counted && active) ctx.end_query(), active = false;
    const ViewportMap map(d.state.viewport, scene.width, scene.height);
    std::vector<glm::vec4> clip;
    for (const SceneTriangle& t : d.triangles)
      for (const glm::dvec2& v : t.screen) clip.push_back(map.clip_from_screen(v.x, v.y, t.z));
    if (d.shade.discard) {
      d.shade.write_depth ? draw_with<true, true>(ctx, fb, d, clip) : draw_with<true, false>(ctx, fb, d, clip);
    } else {
      d.shade.write_depth ? draw_with<false, true>(ctx, fb, d, clip)
      : d.shade.trivial   ? draw_with<false, false, true>(ctx, fb, d, clip)
                          : draw_with<false, false>(ctx, fb, d, clip);
    }
  }
  if (active) ctx.end_query();
  SceneOutput out;
  if (end == SceneEnd::discard) {
    if (ds) discard(ctx, *ds);
    if (color) discard(ctx, *color), out.resolved = resolve(ctx, *color).rgba;
    out.query = ctx.query_result(query);  // ends the frame (already ended by the resolve, if any)
    return out;
  }
  out.query = ctx.query_result(query);
  ctx.flush();
  if (color) out.color = read_color(ctx, *color), out.resolved = resolve(ctx, *color).rgba;
  if (ds) {
    for (int y = 0; y < scene.height; ++y)
      for (int x = 0; x < scene.width; ++x)
        for (int s = 0; s < scene.samples; ++s) {
          out.depth.push_back(ds->depth(x, y, s));
          out.stencil.push_back(ds->stencil(x, y, s));
        }
  }
  return out;
}

SceneReference reference_scene(const Scene& scene) {
  const int W = scene.width, H = scene.height, S = scene.samples;
  const size_t n = size_t(W) * H * S;
  SceneReference ref;
  if (scene.has_color) {
    uint32_t clear = 0;
    for (int c = 0; c < 4; ++c) clear |= uint32_t(unorm8(scene.clear_color[c])) << (8 * c);
    ref.color.assign(n, {clear});
  }
  if (scene.has_depth_stencil) {
    ref.depth.assign(n, scene.clear_depth);
    ref.stencil.assign(n, scene.clear_stencil);
  }
  const auto pattern = d3d_pattern(S);
  for (const SceneDraw& d : scene.draws) {
    const PipelineState& st = d.state;
    const DepthStencilState& ds = st.depth_stencil;
    const PixelRect rect = writable_rect(st, W, H);
    const float lo = st.viewport.min_depth, hi = st.viewport.max_depth;
    for (const SceneTriangle& t : d.triangles) {
      const RefPrimitive p = make_exact_primitive(t.screen, st.rasterizer.cull);
      if (p.culled) continue;
      const bool clockwise = p.tri.area2 > 0;
      const bool front = st.rasterizer.front_counter_clockwise ? !clockwise : clockwise;
      const StencilFace& face = (ds.two_sided_stencil && !front) ? ds.back : ds.front;
      // Depth of the triangle: viewport mapping, then bias, then clamp to the viewport range.
      const float z_tri = std::clamp(lo + t.z * (hi - lo) + st.rasterizer.depth_bias, lo, hi);
      for (int y = std::max(rect.y0, p.by0); y < std::min(rect.y1, p.by1); ++y)
        for (int x = std::max(rect.x0, p.bx0); x < std::min(rect.x1, p.bx1); ++x) {
          bool any = false;
          bool covered[8];
          for (int s = 0; s < S; ++s) any |= covered[s] = p.cover(x, y, pattern[s]) == Cover::In;
          if (!any) continue;
          const ShadeResult sh = shade(d.shade, x, y);
          // Texkill and alpha test kill the whole pixel before stencil and depth.
          if (d.shade.discard && sh.discard) continue;
          if (st.alpha_test.enable && !ref_compare(st.alpha_test.func, unorm8(sh.color[3]), st.alpha_test.ref)) continue;
          const float z = d.shade.write_depth ? std::clamp(sh.depth, lo, hi) : z_tri;
          for (int s = 0; s < S; ++s) {
            if (!covered[s]) continue;
            const size_t i = sample_index(W, S, x, y, s);
            bool pass = true;
            if (scene.has_depth_stencil) {
              const bool depth_pass = !ds.depth_enable || ref_compare(ds.depth_func, z, ref.depth[i]);
              pass = depth_pass;
              if (ds.stencil_enable) {
                const uint8_t v = ref.stencil[i];
                const bool stencil_pass =
                    ref_compare(face.func, ds.stencil_ref & ds.stencil_read_mask, v & ds.stencil_read_mask);
                const StencilOp op = !stencil_pass ? face.fail : !depth_pass ? face.depth_fail : face.pass;
                const uint8_t updated = ref_stencil_op(op, v, ds.stencil_ref);
                ref.stencil[i] = uint8_t((v & ~ds.stencil_write_mask) | (updated & ds.stencil_write_mask));
                pass = stencil_pass && depth_pass;
              }
              if (pass && ds.depth_enable && ds.depth_write) ref.depth[i] = z;
            }
            if (!pass) continue;
            if (d.counted) ++ref.query;
            if (!scene.has_color) continue;
            std::vector<uint32_t> next;
            for (uint32_t dst : ref.color[i])
              for (uint32_t v : ref_output(st.blend, sh.color, dst))
                if (std::find(next.begin(), next.end(), v) == next.end()) next.push_back(v);
            ref.color[i] = std::move(next);
          }
        }
    }
  }
  for (const auto& c : ref.color) ref.ambiguous_samples += c.size() > 1;
  return ref;
}

int compare_scene(const Scene& scene, const SceneOutput& out, const SceneReference& ref, std::vector<std::string>& messages,
                  int max_messages) {
  const int W = scene.width, S = scene.samples;
  int bad = 0;
  auto where = [&](size_t i) {
    std::ostringstream o;
    const int s = int(i % S), x = int((i / S) % W), y = int(i / S / W);
    o << "pixel (" << x << ", " << y << ") sample " << s;
    return o.str();
  };
  if (out.query != ref.query) {
    ++bad;
    messages.push_back("occlusion query: " + std::to_string(out.query) + ", reference " + std::to_string(ref.query));
  }
  for (size_t i = 0; i < ref.color.size(); ++i) {
    const auto& c = ref.color[i];
    if (std::find(c.begin(), c.end(), out.color[i]) != c.end()) continue;
    if (bad++ >= max_messages) continue;
    std::ostringstream o;
    o << where(i) << ": color 0x" << std::hex << out.color[i] << ", reference";
    for (uint32_t v : c) o << " 0x" << v;
    messages.push_back(o.str());
  }
  for (size_t i = 0; i < ref.depth.size(); ++i) {
    if (out.depth[i] == ref.depth[i] && out.stencil[i] == ref.stencil[i]) continue;
    if (bad++ >= max_messages) continue;
    std::ostringstream o;
    o << where(i) << ": depth " << out.depth[i] << " stencil " << int(out.stencil[i]) << ", reference depth "
      << ref.depth[i] << " stencil " << int(ref.stencil[i]);
    messages.push_back(o.str());
  }
  return bad;
}

}  // namespace luxel::rasterizer::test
