#pragma once
// Random triangles with their coverage oracle, and batches of them drawn so that one read-back
// answers for up to 32 triangles: each triangle adds its own bit (additive blending ONE/ONE of
// (1 << bit) / 255 in one channel), or, in "last wins" mode, writes its index (no blending), so
// the sample must hold the last covering triangle in submission order.

#include "raster_support.hpp"

#include <random>
#include <string>
#include <vector>

namespace luxel::rasterizer::test {

enum class TriKind {
  Small, Grid, Axis, Sliver, Subpixel, Degenerate, Offscreen, Large, Wide, Ties,  // exact oracle
  GuardBand, NearPlane, Perspective,                                              // fuzzy oracle
  kCount
};
const char* kind_name(TriKind k);

struct TestTriangle {
  TriKind kind;
  glm::vec4 clip[3];
  glm::dvec2 screen[3];  ///< exact kinds: the screen positions the clip positions map to
  RefPrimitive ref;
  bool wide = false;     ///< exact kinds: an edge is too long for the 32-bit stamp path
};

/// A render-target and pipeline configuration for coverage tests (no depth, no blending set).
struct CoverageConfig {
  std::string name;
  int width = 128, height = 64;
  PipelineState state;  ///< viewport (power-of-two size), scissor, cull mode, winding
};
/// The configurations the coverage tests sweep: whole-target, smaller, offset, partly off the
/// target, scissored, and fractional viewports (the D3D9 half-pixel mapping among them).
std::vector<CoverageConfig> coverage_configs(bool fractional_viewports);

class TriangleGenerator {
 public:
  TriangleGenerator(uint32_t seed, const CoverageConfig& config);
  TestTriangle make(TriKind kind);
  TestTriangle random();  ///< a kind drawn with fixed weights
  TestTriangle from_screen(TriKind kind, const glm::dvec2 s[3]);
  TestTriangle from_clip(TriKind kind, const glm::vec4 c[3], double eps);
  std::mt19937& rng() { return rng_; }
  const ViewportMap& map() const { return map_; }

 private:
  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }
  int uniform_int(int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng_); }
  /// m or -m, at random. (Draws that make one value are sequenced by calls like this one and by
  /// braces: the order in which a function's arguments or an operator's operands are evaluated is
  /// unspecified, and GCC and Clang differ, so `dvec2(uniform(), uniform())` would make different
  /// scenes with each compiler.)
  double with_random_sign(double m) { return uniform_int(0, 1) ? m : -m; }
  glm::dvec2 in_region(double margin);
  const CoverageConfig& config_;
  ViewportMap map_;
  std::mt19937 rng_;
};

/// True when an edge of the snapped triangle exceeds the 32-bit stamp path's bound
/// (|dy| * stamp width + |dx| * stamp height, in subpixels, > 2^29; kNarrowEdgeLimit in detail/triangle_setup.hpp).
bool needs_wide_edges(const ExactTriangle& t);

enum class BatchMode { Bits, LastWins };

/// Clears `target` and draws the batch (one draw per triangle). At most 32 triangles in Bits mode.
void draw_coverage_batch(Context& ctx, ColorTarget& target, const CoverageConfig& config,
                         const std::vector<TestTriangle>& batch, BatchMode mode);

/// Compares every sample of `target` with the oracle; returns the number of mismatching samples
/// and appends up to `max_messages` descriptions. `unknown` counts samples left to Unknown.
int check_coverage_batch(Context& ctx, const ColorTarget& target, const CoverageConfig& config,
                         const std::vector<TestTriangle>& batch, BatchMode mode, std::vector<std::string>& messages,
                         int max_messages, uint64_t* unknown = nullptr, uint64_t* covered = nullptr);

}  // namespace luxel::rasterizer::test
