#pragma once
// The rasterizer's fast paths, each of which can be turned off on its own (as llvmpipe's
// LP_DEBUG=no_fastpath and LP_PERF=no_*): to find which one a wrong image comes from, and to
// measure what each one is worth. Every fast path produces the same bytes as the general path it
// short-cuts (color, depth, stencil, query counts: tests/rasterizer/fast_paths_test.cpp and
// tests/frame/fast_paths_test.cpp); turning one off changes only the time and the DrawStats.
//
// The library never reads the environment: the `luxel` command and the benchmarks read
// LUXEL_NO_FASTPATH (a list as parse_fast_paths_off takes it) and pass it in ContextOptions.

#include <cstdint>
#include <string>
#include <string_view>

namespace luxel::rasterizer {

enum class FastPath : uint32_t {
  /// Triangles under kSmallTriangleSize pixels on a side walk from their record's corner with
  /// 32-bit edges and no 64-bit row setup (DrawStats::small_walks). Needs NarrowEdges.
  SmallTriangleWalk = 1u << 0,
  /// Per-sample edge values in 32-bit lanes where they fit; off, every partly covered stamp is
  /// evaluated exactly in 64 bits one sample at a time (DrawStats::stamps_wide_edges).
  NarrowEdges = 1u << 1,
  /// 16x16 blocks and stamps wholly inside a triangle skip per-sample edge tests
  /// (DrawStats::blocks_full, stamps_full).
  FullCoverage = 1u << 2,
  /// Early depth tests whose compare function is a compile-time constant (Less, LessEqual,
  /// Greater, GreaterEqual without stencil), for trivial pixel functors (draw.hpp); off, the
  /// general depth/stencil test runs.
  FixedDepthPaths = 1u << 3,
  /// Pixel functors that declare kTrivial are run on stamps whose samples all failed early
  /// depth, with no live lane, instead of being branched around (see draw.hpp).
  TrivialShaders = 1u << 4,
  /// Records of triangles whose varyings are the same at the three vertices hold one value
  /// per varying instead of interpolation data.
  FlatRecords = 1u << 5,
  /// Records of triangles with equal w at the three vertices interpolate with one plane per
  /// component instead of perspective-correct barycentrics.
  AffineRecords = 1u << 6,
  /// Indexed draws shade a vertex once for the triangles that share it while it is in a small
  /// post-transform cache; off, every index is shaded anew.
  VertexCache = 1u << 7,
  /// Triangles whose depth is the same at every sample (no slope: screen-aligned quads, full-
  /// screen passes) test and write one depth, clamped once per triangle, instead of evaluating
  /// and clamping the plane per sample.
  ConstantDepth = 1u << 8,
  /// A target that a frame (the commands between two flushes) clears whole first and discards
  /// (discard()) lives in each thread's own tile memory while that frame runs: its samples stay
  /// in the core's cache from the clear to the resolve and never travel to the target's memory
  /// (DrawStats::tile_memory_targets). Off, they are kept in the target's memory as any other.
  TileMemory = 1u << 9,
};

/// A set of fast paths (all of them by default).
class FastPaths {
 public:
  static constexpr uint32_t kAll = (1u << 10) - 1;
  constexpr FastPaths() = default;
  static constexpr FastPaths none() { return FastPaths(0); }
  static constexpr FastPaths all_but(FastPath p) { return FastPaths(kAll & ~uint32_t(p)); }

  constexpr bool on(FastPath p) const { return bits_ & uint32_t(p); }
  constexpr FastPaths without(FastPath p) const { return FastPaths(bits_ & ~uint32_t(p)); }
  constexpr uint32_t bits() const { return bits_; }
  constexpr bool operator==(const FastPaths&) const = default;

 private:
  explicit constexpr FastPaths(uint32_t bits) : bits_(bits) {}
  uint32_t bits_ = kAll;
};

/// Every fast path with its switch name, in declaration order.
struct FastPathName {
  FastPath path;
  const char* name;
};
inline constexpr FastPathName kFastPathNames[] = {
    {FastPath::SmallTriangleWalk, "small_walk"}, {FastPath::NarrowEdges, "narrow_edges"},
    {FastPath::FullCoverage, "full_coverage"},   {FastPath::FixedDepthPaths, "fixed_depth"},
    {FastPath::TrivialShaders, "trivial"},       {FastPath::FlatRecords, "flat"},
    {FastPath::AffineRecords, "affine"},         {FastPath::VertexCache, "vertex_cache"},
    {FastPath::ConstantDepth, "constant_depth"}, {FastPath::TileMemory, "tile_memory"},
};

/// The fast paths left on when those named in `list` are turned off: comma-separated switch
/// names (kFastPathNames), or `all`; empty turns nothing off. Throws std::invalid_argument
/// naming the first word it does not know.
FastPaths parse_fast_paths_off(std::string_view list);

/// The names of the fast paths that are off, comma-separated ("none" when all are on).
std::string fast_paths_off_names(FastPaths paths);

}  // namespace luxel::rasterizer
