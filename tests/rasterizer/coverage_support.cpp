#include "coverage_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <numbers>
#include <sstream>

namespace luxel::rasterizer::test {

const char* kind_name(TriKind k) {
  switch (k) {
    case TriKind::Small: return "small";
    case TriKind::Grid: return "grid";
    case TriKind::Axis: return "axis";
    case TriKind::Sliver: return "sliver";
    case TriKind::Subpixel: return "subpixel";
    case TriKind::Degenerate: return "degenerate";
    case TriKind::Offscreen: return "offscreen";
    case TriKind::Large: return "large";
    case TriKind::Wide: return "wide";
    case TriKind::Ties: return "ties";
    case TriKind::GuardBand: return "guard-band";
    case TriKind::NearPlane: return "near-plane";
    case TriKind::Perspective: return "perspective";
    default: return "?";
  }
}

std::vector<CoverageConfig> coverage_configs(bool fractional_viewports) {
  std::vector<CoverageConfig> c;
  auto add = [&](std::string name, int w, int h, Viewport vp, Scissor sc = {}) {
    CoverageConfig k;
    k.name = std::move(name);
    k.width = w;
    k.height = h;
    k.state.viewport = vp;
    k.state.scissor = sc;
    c.push_back(k);
  };
  add("whole-target 128x64", 128, 64, {});
  add("viewport smaller than target", 150, 90, {0, 0, 128, 64});
  add("viewport partly off the target", 100, 80, {-40, 11, 256, 64});
  add("scissor", 96, 72, {8, -16, 64, 128}, {true, 3, 10, 60, 50});
  add("one odd tile", 37, 23, {-3, -5, 64, 32});
  if (fractional_viewports) {
    add("half-pixel viewport offset", 64, 64, {0.5f, 0.5f, 64, 64});
    add("negative half-pixel viewport offset", 64, 64, {-0.5f, -0.5f, 64, 64});
    add("fractional viewport", 70, 40, {0.25f, -0.75f, 64, 32});
  }
  return c;
}

TriangleGenerator::TriangleGenerator(uint32_t seed, const CoverageConfig& config)
    : config_(config), map_(config.state.viewport, config.width, config.height), rng_(seed) {}

namespace {
double q10(double v) { return std::round(v * 1024.0) / 1024.0; }
glm::dvec2 q10(glm::dvec2 v) { return {q10(v.x), q10(v.y)}; }
}  // namespace

glm::dvec2 TriangleGenerator::in_region(double margin) {
  return {uniform(-margin, config_.width + margin), uniform(-margin, config_.height + margin)};
}

TestTriangle TriangleGenerator::from_screen(TriKind kind, const glm::dvec2 s[3]) {
  TestTriangle t;
  t.kind = kind;
  for (int k = 0; k < 3; ++k) {
    t.screen[k] = s[k];
    t.clip[k] = map_.clip_from_screen(s[k].x, s[k].y);
  }
  t.ref = make_exact_primitive(s, CullMode::None);
  t.wide = needs_wide_edges(t.ref.tri);
  return t;
}

TestTriangle TriangleGenerator::from_clip(TriKind kind, const glm::vec4 c[3], double eps) {
  TestTriangle t;
  t.kind = kind;
  for (int k = 0; k < 3; ++k) t.clip[k] = c[k];
  t.ref = make_fuzzy_primitive(std::span<const glm::vec4>(c, 3), map_, CullMode::None, eps);
  return t;
}

TestTriangle TriangleGenerator::random() {
  static constexpr int kWeights[] = {3, 3, 2, 2, 2, 1, 1, 1, 2, 2, 1, 2, 1};
  static_assert(std::size(kWeights) == size_t(TriKind::kCount));
  std::discrete_distribution<int> d(std::begin(kWeights), std::end(kWeights));
  return make(static_cast<TriKind>(d(rng_)));
}

TestTriangle TriangleGenerator::make(TriKind kind) {
  glm::dvec2 s[3];
  const double two_pi = 2 * std::numbers::pi;
  auto ndc = [&](glm::dvec2 p) { return glm::dvec2((p.x - map_.x) / (map_.w / 2) - 1, 1 - (p.y - map_.y) / (map_.h / 2)); };
  switch (kind) {
    case TriKind::Small: {
      const glm::dvec2 c = in_region(8);
      const double r = std::exp(uniform(std::log(0.5), std::log(60.0)));
      for (auto& v : s) {
        const double a = uniform(0, two_pi), d = r * std::sqrt(uniform(0, 1));
        v = q10(c + d * glm::dvec2(std::cos(a), std::sin(a)));
      }
      break;
    }
    case TriKind::Grid: {
      // On the 1/16 pixel grid that holds every standard sample position: edges run through
      // samples, so the fill rule decides.
      const glm::dvec2 b = glm::floor(in_region(4));
      for (auto& v : s) v = b + glm::dvec2{uniform_int(-128, 128), uniform_int(-128, 128)} / 16.0;
      break;
    }
    case TriKind::Axis: {
      // A right triangle with one horizontal and one vertical edge (top, bottom, left or right).
      const glm::dvec2 b = glm::floor(in_region(4) * 16.0) / 16.0;
      const double lx = with_random_sign(uniform_int(1, 200) / 16.0);
      const double ly = with_random_sign(uniform_int(1, 200) / 16.0);
      s[0] = b;
      s[1] = b + glm::dvec2(lx, 0);
      s[2] = b + glm::dvec2(0, ly);
      std::shuffle(s, s + 3, rng_);
      break;
    }
    case TriKind::Sliver: {
      const glm::dvec2 p0 = in_region(8);
      double a = uniform(0, two_pi);
      if (uniform_int(0, 2) == 0) a = uniform_int(0, 3) * std::numbers::pi / 2;  // axis-aligned
      const glm::dvec2 dir(std::cos(a), std::sin(a)), normal(-dir.y, dir.x);
      const glm::dvec2 p1 = p0 + uniform(20, 200) * dir;
      const double t = uniform(0.05, 0.95);
      const double off = with_random_sign(std::exp(uniform(std::log(1.0 / 512), std::log(2.0))));
      s[0] = q10(p0);
      s[1] = q10(p1);
      s[2] = q10(p0 + t * (p1 - p0) + off * normal);
      break;
    }
    case TriKind::Subpixel: {
      const glm::dvec2 b = in_region(2);
      for (auto& v : s) v = q10(b + glm::dvec2{uniform(0, 1.5), uniform(0, 1.5)});
      break;
    }
    case TriKind::Degenerate: {
      const glm::dvec2 p0 = glm::floor(in_region(4) * 256.0) / 256.0;
      const glm::dvec2 d = glm::dvec2{uniform_int(-4000, 4000), uniform_int(-4000, 4000)} / 256.0;
      switch (uniform_int(0, 3)) {
        case 0: s[0] = p0; s[1] = p0 + d; s[2] = p0 + (uniform_int(0, 1) ? 2.0 : -1.0) * d; break;  // collinear
        case 1: s[0] = p0; s[1] = p0 + d; s[2] = p0 + d; break;                                       // repeated vertex
        case 2: s[0] = s[1] = s[2] = p0; break;                                                       // a point
        default:
          // Not collinear in float, collinear after snapping (moved by 1/1024 pixel).
          s[0] = p0;
          s[1] = p0 + d;
          s[2] = p0 + 2.0 * d + glm::dvec2{uniform_int(-1, 1), uniform_int(-1, 1)} / 1024.0;
          break;
      }
      std::shuffle(s, s + 3, rng_);
      break;
    }
    case TriKind::Offscreen: {
      const double W = config_.width, H = config_.height;
      const int side = uniform_int(0, 3);
      for (auto& v : s) {
        glm::dvec2 p = in_region(100);
        if (side == 0) p.x = uniform(-150, -1.0 / 16);
        if (side == 1) p.x = uniform(W, W + 150);
        if (side == 2) p.y = uniform(-150, -1.0 / 16);
        if (side == 3) p.y = uniform(H, H + 150);
        v = q10(p);
      }
      break;
    }
    case TriKind::Large: {
      for (auto& v : s) v = q10(in_region(900));
      break;
    }
    case TriKind::Wide: {
      const int variant = uniform_int(0, 5);
      if (variant == 0) {
        // A right triangle with a vertical and a horizontal edge on the 1/16 grid (through sample
        // positions) and legs of thousands of pixels: the fill rule on the 64-bit path.
        const glm::dvec2 b = glm::floor(in_region(2) * 16.0) / 16.0;
        const double lx = with_random_sign(uniform_int(4200, 15000));
        const double ly = with_random_sign(uniform_int(4200, 15000));
        s[0] = b;
        s[1] = glm::clamp(b + glm::dvec2(lx, 0), glm::dvec2(-16000), glm::dvec2(16000));
        s[2] = glm::clamp(b + glm::dvec2(0, ly), glm::dvec2(-16000), glm::dvec2(16000));
        std::shuffle(s, s + 3, rng_);
      } else if (variant == 1) {
        for (auto& v : s) v = q10(glm::dvec2{uniform(-16000, 16000), uniform(-16000, 16000)});
      } else {
        // A long triangle through the target: two far vertices on opposite sides, one near.
        const glm::dvec2 c = in_region(4);
        const double a = uniform(0, two_pi);
        const glm::dvec2 dir(std::cos(a), std::sin(a));
        auto clamp16k = [](glm::dvec2 p) { return glm::clamp(p, glm::dvec2(-16000), glm::dvec2(16000)); };
        s[0] = q10(clamp16k(c + uniform(3000, 15000) * dir));
        s[1] = q10(clamp16k(c - uniform(3000, 15000) * dir));
        s[2] = q10(in_region(40));
        std::shuffle(s, s + 3, rng_);
      }
      break;
    }
    case TriKind::Ties: {
      // Odd multiples of 1/512 pixel: every coordinate is a rounding tie at 1/256.
      const glm::dvec2 b = glm::floor(in_region(4));
      for (auto& v : s) v = b + glm::dvec2{2 * uniform_int(-2048, 2048) + 1, 2 * uniform_int(-2048, 2048) + 1} / 512.0;
      break;
    }
    case TriKind::GuardBand: {
      glm::vec4 c[3];
      const glm::dvec2 center(config_.width / 2.0, config_.height / 2.0);
      double m = 0;
      const bool surround = uniform_int(0, 3) == 0;
      const int far = surround ? 3 : uniform_int(1, 3);
      const double a0 = uniform(0, two_pi);
      for (int k = 0; k < 3; ++k) {
        glm::dvec2 p;
        if (surround) {
          p = center + uniform(20000, 131072) * glm::dvec2(std::cos(a0 + k * two_pi / 3), std::sin(a0 + k * two_pi / 3));
        } else if (k < far) {
          const double a = uniform(0, two_pi);
          p = center + uniform(17000, 131072) * glm::dvec2(std::cos(a), std::sin(a));
        } else {
          p = in_region(8);
        }
        m = std::max({m, std::abs(p.x), std::abs(p.y)});
        const glm::dvec2 n = ndc(p);
        const float w = uniform_int(0, 1) ? 1.0f : static_cast<float>(uniform(0.5, 2.0));
        c[k] = {static_cast<float>(n.x) * w, static_cast<float>(n.y) * w, 0.5f * w, w};
      }
      // Float clipping against the guard band (at ~2^14 pixels) of vertices up to M pixels away
      // moves the clipped vertices by a few float ulps of M; bound them by M * 2^-21.
      return from_clip(kind, c, std::max(1.0 / 64, m * std::exp2(-21)));
    }
    case TriKind::NearPlane: {
      glm::vec4 c[3];
      for (;;) {
        int behind = 0;
        for (auto& v : c) {
          // In front of the eye: z = w - 0.3 (near plane at w = 0.3). Behind it (w <= 0.05): any
          // z, so that the far plane (z <= w) clips some of them too.
          const float w = static_cast<float>(uniform(-1, 3));
          if (w > 0.05f) {
            const glm::dvec2 n = ndc(in_region(8));
            v = {static_cast<float>(n.x) * w, static_cast<float>(n.y) * w, w - 0.3f, w};
          } else {
            v = {static_cast<float>(uniform(-3, 3)), static_cast<float>(uniform(-3, 3)), static_cast<float>(uniform(-2, 2)), w};
          }
          behind += v.z < 0 || v.z > v.w;
        }
        if (behind > 0 && behind < 3) break;
      }
      return from_clip(kind, c, 1.0 / 64);
    }
    case TriKind::Perspective: {
      glm::vec4 c[3];
      const glm::dvec2 center = in_region(8);
      const double r = std::exp(uniform(std::log(1.0), std::log(60.0)));
      for (auto& v : c) {
        const float w = static_cast<float>(uniform(0.25, 4));
        const double a = uniform(0, two_pi);
        const glm::dvec2 n = ndc(center + r * glm::dvec2(std::cos(a), std::sin(a)));
        v = {static_cast<float>(n.x) * w, static_cast<float>(n.y) * w, 0.5f * w, w};
      }
      return from_clip(kind, c, 1.0 / 64);
    }
    default: break;
  }
  return from_screen(kind, s);
}

bool needs_wide_edges(const ExactTriangle& t) {
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const int64_t dx = std::abs(t.X[j] - t.X[i]), dy = std::abs(t.Y[j] - t.Y[i]);
    if (dy * simd::kStampWidth * 256 + dx * simd::kStampHeight * 256 > (int64_t(1) << 29)) return true;
  }
  return false;
}

namespace {
glm::vec4 bit_color(int k) {
  glm::vec4 c(0.0f);
  c[k / 8] = static_cast<float>(1 << (k % 8)) / 255.0f;
  return c;
}
glm::vec4 index_color(int k) { return {static_cast<float>(k + 1) / 255.0f, 0.0f, 0.0f, 1.0f}; }
}  // namespace

void draw_coverage_batch(Context& ctx, ColorTarget& target, const CoverageConfig& config,
                         const std::vector<TestTriangle>& batch, BatchMode mode) {
  clear_color(ctx, target, glm::vec4(0.0f));
  PipelineState state = config.state;
  if (mode == BatchMode::Bits) {
    state.blend.enable = true;
    state.blend.src = BlendFactor::One;
    state.blend.dst = BlendFactor::One;
    state.blend.op = BlendOp::Add;
  }
  for (size_t k = 0; k < batch.size(); ++k) {
    const PositionVS vs{batch[k].clip, nullptr};
    const ConstantPS ps{mode == BatchMode::Bits ? bit_color(int(k)) : index_color(int(k))};
    draw(ctx, Framebuffer{&target, nullptr}, state, Geometry::non_indexed(3), vs, ps);
  }
}

int check_coverage_batch(Context& ctx, const ColorTarget& target, const CoverageConfig& config,
                         const std::vector<TestTriangle>& batch, BatchMode mode, std::vector<std::string>& messages,
                         int max_messages, uint64_t* unknown_count, uint64_t* covered_count) {
  const int W = target.width(), H = target.height(), S = target.samples();
  const std::vector<uint32_t> actual = read_color(ctx, target);
  const PixelRect rect = writable_rect(config.state, W, H);
  const CullMode cull = config.state.rasterizer.cull;
  const size_t n = actual.size();
  std::vector<uint32_t> in_bits, unknown_bits;
  std::vector<uint64_t> allowed;  // LastWins: bit v = value v may be there (0 = background)
  if (mode == BatchMode::Bits) {
    in_bits.assign(n, 0);
    unknown_bits.assign(n, 0);
  } else {
    allowed.assign(n, 1);
  }
  // Samples outside a fractional viewport but in a pixel it overlaps may be written (state.hpp)
  // by a triangle that reaches into the viewport, and are not by one that is trivially rejected
  // (see viewport_test.cpp): the oracle leaves them open.
  const ViewportMap map(config.state.viewport, W, H);
  const auto pattern = d3d_pattern(S);
  for (size_t k = 0; k < batch.size(); ++k) {
    const RefPrimitive p = with_cull(batch[k].ref, cull);
    for_each_sample(p, rect, S, [&](int x, int y, int s, Cover c) {
      if (c == Cover::In && !inside_viewport(map, x, y, pattern[s])) c = Cover::Unknown;
      const size_t i = sample_index(W, S, x, y, s);
      if (unknown_count && c == Cover::Unknown) ++*unknown_count;
      if (covered_count && c == Cover::In) ++*covered_count;
      if (mode == BatchMode::Bits) {
        (c == Cover::In ? in_bits : unknown_bits)[i] |= 1u << k;
      } else {
        allowed[i] = (c == Cover::In ? 0 : allowed[i]) | uint64_t(1) << (k + 1);
      }
    });
  }
  int mismatches = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      for (int s = 0; s < S; ++s) {
        const size_t i = sample_index(W, S, x, y, s);
        const uint32_t a = actual[i];
        if (mode == BatchMode::Bits) {
          const uint32_t wrong = (a ^ in_bits[i]) & ~unknown_bits[i];
          if (!wrong) continue;
          ++mismatches;
          if (int(messages.size()) >= max_messages) continue;
          std::ostringstream msg;
          const int k = std::countr_zero(wrong);
          const TestTriangle& t = batch[k];
          msg << config.name << ", " << S << " samples, cull " << int(cull) << ": pixel (" << x << ", " << y
              << ") sample " << s << ": triangle #" << k << " (" << kind_name(t.kind) << ") "
              << ((a >> k) & 1 ? "covers it, the oracle says not" : "does not cover it, the oracle says it does")
              << "; clip " << describe(t.clip);
          if (t.ref.exact) msg << "; screen " << describe(t.screen);
          messages.push_back(msg.str());
        } else {
          const uint32_t v = a & 255;
          const bool ok = (v == 0 ? a == 0 : a == (v | 0xff000000u)) && v <= batch.size() && ((allowed[i] >> v) & 1);
          if (ok) continue;
          ++mismatches;
          if (int(messages.size()) >= max_messages) continue;
          std::ostringstream msg;
          msg << config.name << ", " << S << " samples, cull " << int(cull) << ": pixel (" << x << ", " << y
              << ") sample " << s << ": holds 0x" << std::hex << a << std::dec
              << " (last-wins index " << int(v) - 1 << "); allowed indices:";
          for (int b = 0; b <= int(batch.size()); ++b)
            if ((allowed[i] >> b) & 1) msg << " " << b - 1;
          if (v >= 1 && v <= batch.size()) msg << "; triangle " << v - 1 << " clip " << describe(batch[v - 1].clip);
          const int last_allowed = 63 - std::countl_zero(allowed[i]);
          if (last_allowed >= 1 && uint32_t(last_allowed) != v)
            msg << "; triangle " << last_allowed - 1 << " (" << kind_name(batch[last_allowed - 1].kind) << ") clip "
                << describe(batch[last_allowed - 1].clip);
          messages.push_back(msg.str());
        }
      }
  return mismatches;
}

}  // namespace luxel::rasterizer::test
