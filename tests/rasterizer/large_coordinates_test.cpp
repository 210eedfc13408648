// Exact coverage at large pixel coordinates: triangles with vertices near 8000 pixels on targets
// as large as kMaxTargetSize on one side (8192 x 64 and 64 x 8192, so that x and then y are
// large while memory stays small), and on a full 8192 x 8192 target scissored to its far corner,
// where both are. Small triangles, 1/16-pixel grid ones (the fill rule decides on sample
// positions), long thin ones reaching across the whole target (64-bit edge constants beyond
// 2^40, and edges too long for the 32-bit stamp path), axis-aligned slivers (top and left edges),
// at 1, 4 and 8 samples, compared sample by sample with the exact oracle of raster_support.hpp.
// (coverage_test.cpp's targets are at most 150 pixels wide.)

#include "coverage_support.hpp"
#include "raster_support.hpp"

#include "luxel/rasterizer/limits.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <sstream>

namespace luxel::rasterizer::test {
namespace {

constexpr int kFar = kMaxTargetSize;

/// Random triangles in (long, short) coordinates: `along` is the large axis (up to kFar), `across`
/// the target's small one (0 .. across_size); to_screen puts them on x or y.
class FarTriangles {
 public:
  FarTriangles(uint32_t seed, int across_size) : rng_(seed), across_(across_size) {}

  /// Vertices (along, across), pixels, on the 1/256 grid (or 1/16 for grid triangles).
  std::array<glm::dvec2, 3> make(int kind) {
    std::array<glm::dvec2, 3> v;
    auto far_along = [&] { return uniform(kFar - 300, kFar + 20); };
    auto across = [&] { return uniform(-4, across_ + 4); };
    switch (kind) {
      case 0: {  // small, near the far edge
        const glm::dvec2 c{far_along(), across()};
        const double r = std::exp(uniform(std::log(0.3), std::log(30.0)));
        for (auto& p : v) p = q8(c + glm::dvec2(uniform(-r, r), uniform(-r, r)));
        break;
      }
      case 1: {  // on the 1/16 grid that holds the sample positions: edges through samples
        const glm::dvec2 b{std::floor(far_along()), std::floor(across())};
        for (auto& p : v) p = b + glm::dvec2(uniform_int(-128, 128), uniform_int(-128, 128)) / 16.0;
        break;
      }
      case 2: {  // long, from near the origin to the far edge: thin, or as wide as the target
        // (then samples tens of pixels from a long edge give edge values beyond 2^32)
        const glm::dvec2 a{uniform(-20, 600), across()}, b{far_along(), across()};
        const double t = uniform(0.2, 0.8);
        glm::dvec2 m = a + t * (b - a) + glm::dvec2(0, uniform(-3, 3));
        if (uniform_int(0, 1)) m.y = across();
        v = {q8(a), q8(b), q8(m)};
        break;
      }
      case 3: {  // an axis-aligned sliver: one edge along the long axis, 1/16 to 2 pixels across
        const double a0 = uniform_int(0, 16 * 600) / 16.0, a1 = uniform_int(16 * (kFar - 300), 16 * kFar) / 16.0;
        const double c0 = uniform_int(-16, 16 * across_) / 16.0, h = uniform_int(1, 32) / 16.0;
        v = {glm::dvec2(a0, c0), glm::dvec2(a1, c0), glm::dvec2(uniform_int(0, 1) ? a0 : a1, c0 + (uniform_int(0, 1) ? h : -h))};
        break;
      }
      default: {  // medium, near the far edge: block-level accept and reject
        const glm::dvec2 c{far_along(), across()};
        const double r = uniform(30, 400);
        for (auto& p : v) p = q8(c + glm::dvec2(uniform(-r, r), uniform(-r, r)));
        break;
      }
    }
    if (uniform_int(0, 1)) std::swap(v[1], v[2]);  // either winding
    return v;
  }

 private:
  static double q8(double v) { return std::round(v * 256) / 256; }
  static glm::dvec2 q8(glm::dvec2 v) { return {q8(v.x), q8(v.y)}; }
  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }
  int uniform_int(int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng_); }
  std::mt19937 rng_;
  int across_;
};

glm::dvec2 to_screen(glm::dvec2 along_across, bool along_x) {
  return along_x ? along_across : glm::dvec2(along_across.y, along_across.x);
}

TEST(LargeCoordinates, CoverageMatchesTheOracleNearTheTargetLimit) {
  const int batches = budget(12, 2);
  Context ctx(2);
  uint64_t covered = 0, wide = 0, wide_stamps = 0;
  int failures = 0;
  for (bool along_x : {true, false}) {
    CoverageConfig cfg;
    cfg.name = along_x ? "8192x64" : "64x8192";
    cfg.width = along_x ? kFar : 64;
    cfg.height = along_x ? 64 : kFar;
    cfg.state.viewport = {0, 0, float(kFar), float(kFar)};  // a power of two: screen points exact in NDC
    cfg.state.rasterizer.cull = CullMode::None;
    TriangleGenerator gen(7, cfg);
    for (int S : {1, 4, 8}) {
      ColorTarget target(cfg.width, cfg.height, S);
      FarTriangles far(uint32_t(100 * S + along_x), 64);
      for (int b = 0; b < batches && failures < 3; ++b) {
        std::vector<TestTriangle> batch;
        for (int k = 0; k < 32; ++k) {
          const auto v = far.make(k % 5);
          const glm::dvec2 s[3] = {to_screen(v[0], along_x), to_screen(v[1], along_x), to_screen(v[2], along_x)};
          batch.push_back(gen.from_screen(TriKind::Large, s));
          wide += batch.back().wide;
        }
        const BatchMode mode = b % 3 == 2 ? BatchMode::LastWins : BatchMode::Bits;
        ctx.reset_stats();
        draw_coverage_batch(ctx, target, cfg, batch, mode);
        std::vector<std::string> messages;
        const int bad = check_coverage_batch(ctx, target, cfg, batch, mode, messages, 6, nullptr, &covered);
        wide_stamps += ctx.stats().stamps_wide_edges;
        if (bad) {
          ++failures;
          ADD_FAILURE() << cfg.name << ", " << S << " samples, batch " << b << ": " << bad << " mismatches\n"
                        << join(messages);
        }
      }
    }
  }
  EXPECT_GT(covered, 100000u);
  // Long edges took the 64-bit per-sample path too.
  EXPECT_GT(wide, 0u);
  EXPECT_GT(wide_stamps, 0u);
}

// Both coordinates large: a full-size target, drawn only in its far 192 x 192 corner (scissor),
// compared there and on a band around it (which must stay clear). One sample: 256 MB of color.
TEST(LargeCoordinates, CoverageMatchesTheOracleInTheFarCornerOfAFullSizeTarget) {
  if (kReducedRun) GTEST_SKIP() << "a 256 MB target: optimized builds only";
  Context ctx(2);
  ColorTarget target(kFar, kFar, 1);
  CoverageConfig cfg;
  cfg.name = "8192x8192, far corner";
  cfg.width = cfg.height = kFar;
  cfg.state.viewport = {0, 0, float(kFar), float(kFar)};
  cfg.state.rasterizer.cull = CullMode::None;
  const int x0 = kFar - 192;
  cfg.state.scissor = {true, x0, x0, kFar, kFar};
  TriangleGenerator gen(11, cfg);
  std::mt19937 rng(5);
  auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  uint64_t covered = 0;
  for (int b = 0; b < 4; ++b) {
    std::vector<TestTriangle> batch;
    for (int k = 0; k < 32; ++k) {
      glm::dvec2 s[3];
      if (k % 4 == 3) {  // long: from far away across the corner
        s[0] = {std::round(uniform(0, 4000) * 256) / 256, std::round(uniform(0, 4000) * 256) / 256};
        for (int j = 1; j < 3; ++j) s[j] = {std::round(uniform(x0, kFar + 40) * 256) / 256, std::round(uniform(x0, kFar + 40) * 256) / 256};
      } else {
        const glm::dvec2 c{uniform(x0 - 8, kFar + 8), uniform(x0 - 8, kFar + 8)};
        const double r = std::exp(uniform(std::log(0.3), std::log(60.0)));
        for (auto& v : s) v = {std::round((c.x + uniform(-r, r)) * 16) / 16, std::round((c.y + uniform(-r, r)) * 16) / 16};
      }
      batch.push_back(gen.from_screen(TriKind::Large, s));
    }
    draw_coverage_batch(ctx, target, cfg, batch, BatchMode::Bits);
    ctx.flush();
    // The oracle over the corner and a 64-pixel band before it.
    int bad = 0;
    std::vector<std::string> messages;
    for (int y = x0 - 64; y < kFar; ++y)
      for (int x = x0 - 64; x < kFar; ++x) {
        uint32_t expect = 0;
        if (x >= x0 && y >= x0)
          for (size_t k = 0; k < batch.size(); ++k)
            if (batch[k].ref.cover(x, y, Offset16{0, 0}) == Cover::In) expect |= 1u << k;
        covered += expect != 0;
        const uint32_t got = target.sample(x, y, 0);
        if (got == expect) continue;
        if (bad++ < 6) {
          std::ostringstream o;
          o << "pixel (" << x << ", " << y << "): 0x" << std::hex << got << ", oracle 0x" << expect;
          messages.push_back(o.str());
        }
      }
    EXPECT_EQ(bad, 0) << "batch " << b << "\n" << join(messages);
  }
  EXPECT_GT(covered, 10000u);
}

}  // namespace
}  // namespace luxel::rasterizer::test
