#pragma once
// The per-tile stage of a draw: the tile rasterizer, which takes the triangles binned to one tile
// through coverage, depth and stencil, the pixel functor and the output merger, and the plan of
// the draw it reads (detail/draw_plan.hpp). A header because it is templated on the pixel functor,
// which the stamp loop inlines (or calls through a pointer: detail/called_shader.hpp); what does
// not depend on the functor is compiled once (plan_draw: rasterizer/src/draw.cpp).

#include "luxel/rasterizer/detail/called_shader.hpp"
#include "luxel/rasterizer/detail/draw_plan.hpp"
#include "luxel/rasterizer/detail/output_merger.hpp"
#include "luxel/rasterizer/detail/triangle_setup.hpp"
#include "luxel/rasterizer/draw.hpp"
#include "luxel/rasterizer/fast_paths.hpp"
#include "luxel/rasterizer/framebuffer.hpp"
#include "luxel/rasterizer/msaa.hpp"
#include "luxel/rasterizer/simd.hpp"
#include "luxel/rasterizer/state.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>

namespace luxel::rasterizer::detail {

/// Lane constants of a stamp, built once.
struct StampLanes {
  Float center_x, center_y;  ///< pixel-center offsets of the lanes from the stamp's corner
  Int x_sub, y_sub;          ///< pixel offsets of the lanes in subpixels
  Int bit;                   ///< 1 << lane
  StampLanes()
      : center_x(simd::lanes([](int l) { return simd::lane_x(l) + 0.5f; })),
        center_y(simd::lanes([](int l) { return simd::lane_y(l) + 0.5f; })),
        x_sub(simd::lanes<Int>([](int l) { return simd::lane_x(l) * kSubpixelsPerPixel; })),
        y_sub(simd::lanes<Int>([](int l) { return simd::lane_y(l) * kSubpixelsPerPixel; })),
        bit(simd::lanes<Int>([](int l) { return 1 << l; })) {}
};
inline const StampLanes& stamp_lanes() {
  static const StampLanes lanes;
  return lanes;
}

inline Float eval_plane(const Plane& p, const Float& dx, const Float& dy) {
  return simd::fma(Float(p.dqdx), dx, simd::fma(Float(p.dqdy), dy, Float(p.q0)));
}

/// Where a draw tests depth and stencil, fixed per draw. The common early cases have their own
/// paths, where the compare function is a constant: a switch and flag checks per stamp, and the
/// generic path's code in the loop, cost small triangles dearly (bench/README.md). Only trivial
/// pixel functors (draw.hpp) get them: beside any other shader those costs are small, and every
/// path is one more tile rasterizer to compile per functor and sample count.
enum class DepthPath {
  Late,            ///< after the pixel functor (it can discard or write depth, or alpha test is on)
  Early,           ///< before it: any depth/stencil state, or none
  EarlyLess,       ///< before it, depth test Less (OpenGL's default), no stencil
  EarlyLessEqual,  ///< the same with LessEqual (Direct3D's default)
};

/// Rasterizes the triangles binned to one tile, in submission order. S is the sample count.
///
/// Every depth and color write of a stamp stores whole vectors: the new values of the lanes that
/// pass, blended with the old values of the others. AVX2 masked stores (vmaskmovps, vpmaskmovd)
/// would not read the old values, but AMD Zen runs them as microcode and neither vendor forwards
/// a later load from them; a load, a blend and a store are simple instructions on both.
template <class PS, int N, DepthPath kPath, int S>
class TileRasterizer {
 public:
  TileRasterizer(const DrawPlan& plan, const PS& ps, int tile, bool count_samples)
      : plan_(plan), ps_(ps), state_(*plan.state), lanes_(stamp_lanes()), count_samples_(count_samples) {
    const int tx = tile % plan.layout.tiles_x, ty = tile / plan.layout.tiles_x;
    tile_x_ = tx * kTileSize;
    tile_y_ = ty * kTileSize;
    color_ = plan.color ? plan.color->tile(tile) : nullptr;
    depth_ = plan.depth_stencil ? plan.depth_stencil->depth_tile(tile) : nullptr;
    stencil_ = plan.depth_stencil ? plan.depth_stencil->stencil_tile(tile) : nullptr;
    const DrawConstants& dc = plan.constants;
    clip_x0_ = std::max(dc.clip_x0, tile_x_);
    clip_y0_ = std::max(dc.clip_y0, tile_y_);
    clip_x1_ = std::min(dc.clip_x1, tile_x_ + kTileSize);
    clip_y1_ = std::min(dc.clip_y1, tile_y_ + kTileSize);
    whole_tile_ = clip_x0_ == tile_x_ && clip_y0_ == tile_y_ && clip_x1_ == tile_x_ + kTileSize &&
                  clip_y1_ == tile_y_ + kTileSize;
    for (int s = 0; s < S; ++s) {
      sample_x_[s] = sample_subpixel(plan.sample_offsets[s].x);
      sample_y_[s] = sample_subpixel(plan.sample_offsets[s].y);
      sample_X_[s] = lanes_.x_sub + Int(sample_x_[s]);
      sample_Y_[s] = lanes_.y_sub + Int(sample_y_[s]);
      sample_XY_[s] = sample_X_[s] | (sample_Y_[s] << 16);
      for (int phase = 0; phase < kPlanePhases; ++phase)
        sample_dx_[phase][s] =
            simd::lanes([&](int l) { return phase * simd::kStampWidth + simd::lane_x(l) + sample_x_[s] / 256.0f; });
      sample_dy_[s] = simd::lanes([&](int l) { return simd::lane_y(l) + sample_y_[s] / 256.0f; });
    }
    for (int phase = 0; phase < kPlanePhases; ++phase)
      block_center_x_[phase] = Float(float(phase * simd::kStampWidth)) + lanes_.center_x;
    simple_depth_ = depth_ && !plan.stencil;
    if (!color_ || !plan.color_write_mask) {
      color_write_ = ColorWrite::None;
    } else if (plan.float_color) {
      color_write_ = ColorWrite::Float;
    } else if (state_.blend.enable || plan.color_write_mask != 0xffffffffu) {
      color_write_ = ColorWrite::Merged;
    } else {
      color_write_ = state_.blend.srgb_write ? ColorWrite::PlainSrgb : ColorWrite::Plain;
    }
    const FastPaths fast = plan.constants.fast_paths;
    full_coverage_ = fast.on(FastPath::FullCoverage);
    fixed_depth_ = fast.on(FastPath::FixedDepthPaths);
    constant_depth_path_ = fast.on(FastPath::ConstantDepth);
    trivial_ = kTrivialPixelFunctor<PS> && fast.on(FastPath::TrivialShaders);
    depth_test_ = plan.depth_test;
    depth_write_ = plan.depth_write;
    depth_func_ = state_.depth_stencil.depth_func;
    min_depth_ = plan.constants.min_depth;
    max_depth_ = plan.constants.max_depth;
  }

  void triangle(const TriangleSetup& t);

  uint64_t samples_passed = 0;
  DrawStats stats;

 private:
  /// Edge data of one triangle at stamp granularity.
  struct StampEdges {
    Int lane_offset[3][S];               ///< narrow edges: value at each lane and sample minus the stamp corner's
    int64_t min_offset[3], max_offset[3];  ///< bounds over a stamp, relative to its corner
  };
  static constexpr int kBlockSize = 16;  ///< pixels; a tile is 4 x 4 blocks
  static constexpr int kStampsPerRow = kTileSize / simd::kStampWidth;
  static_assert(kTileSize % kBlockSize == 0 && kBlockSize % simd::kStampWidth == 0);

  /// The path for other triangles. Out of line: the record loop, with the small-triangle walk
  /// inlined, stays small.
  [[gnu::noinline]] void rasterize(const TriangleSetup& t, int x0, int y0, int x1, int y1);
  /// The path for small triangles (TriangleSetup::small()): 32-bit edge values throughout.
  void rasterize_small(const TriangleSetup& t, int sx0, int sy0, int x1, int y1);
  void rasterize_stamps(const TriangleSetup& t, const StampEdges& edges, int x0, int y0, int x1, int y1);
  /// Per-sample coverage of a partly covered stamp of a triangle with wide edges.
  bool wide_coverage(const TriangleSetup& t, int px, int py, const Int& clip, Int* coverage);
  /// The lanes of the stamp at (px, py) inside the draw's clip rectangle.
  Int clip_mask(int px, int py) const {
    if (whole_tile_ ||
        (px >= clip_x0_ && px + simd::kStampWidth <= clip_x1_ && py >= clip_y0_ && py + simd::kStampHeight <= clip_y1_))
      return Int(-1);
    const Int x = Int(px) + lanes_.x_sub / Int(kSubpixelsPerPixel), y = Int(py) + lanes_.y_sub / Int(kSubpixelsPerPixel);
    return simd::mask_of(x >= Int(clip_x0_)) & simd::mask_of(x < Int(clip_x1_)) & simd::mask_of(y >= Int(clip_y0_)) &
           simd::mask_of(y < Int(clip_y1_));
  }
  /// Depth and the interpolants are planes evaluated at offsets from the corner of the stamp's
  /// block (kPlaneBlockWidth x 2 pixels), not from the stamp's own corner: the same terms,
  /// rounded the same way, for any stamp width, so that neither depends on the lane count (ISA)
  /// a build has.
  static constexpr int kPlaneBlockWidth = 8;
  static constexpr int kPlanePhases = kPlaneBlockWidth / simd::kStampWidth;  ///< stamps per block
  static_assert(kPlanePhases >= 1 && kPlaneBlockWidth % simd::kStampWidth == 0);
  struct StampDepth {
    float corner;  ///< the plane at the block's corner, relative to the reference vertex
    int phase;     ///< which stamp of its block
  };
  /// The triangle's depth at sample s of a stamp (see StampDepth, stamp_depth), clamped to the
  /// viewport's depth range; constant_z_ if the triangle has constant depth (the same value).
  /// Early and late depth tests take it from here alike, so that a pass with depth func Equal
  /// over the same triangles passes whichever test its shader allows. The hot callers pass
  /// copies of the members: a depth store could alias them.
  LUXEL_INLINE Float sample_depth(int s, StampDepth d, const Float& min_depth, const Float& max_depth,
                                  bool constant_depth, const Float& constant_z) const {
    if (constant_depth) return constant_z;
    return clamp_depth(sample_z_[d.phase][s] + Float(d.corner), min_depth, max_depth);
  }
  /// A depth clamped to the viewport's depth range, as every depth test sees it.
  static Float clamp_depth(const Float& z, const Float& min_depth, const Float& max_depth) {
    return xsimd::min(xsimd::max(z, min_depth), max_depth);
  }
  /// The block of the stamp whose corner is (px, py): its corner's x and the stamp's phase in it.
  struct StampBlock {
    int x, phase;
  };
  static StampBlock stamp_block(int px) {
    const int x = px & ~(kPlaneBlockWidth - 1);
    return {x, (px - x) / simd::kStampWidth};
  }
  StampDepth stamp_depth(const TriangleSetup& t, StampBlock block, int py) const {
    if (constant_depth_) return {0.0f, 0};
    return {std::fma(t.z.dqdx, float(block.x) - t.ref_x, t.z.dqdy * (float(py) - t.ref_y)), block.phase};
  }
  /// The pixel functor's interpolants at the pixel centers (cx, cy relative to vertex 0),
  /// perspective-correct.
  LUXEL_INLINE void interpolate(const TriangleSetup& t, const Float& cx, const Float& cy, PixelInput<N>& in);
  /// The index of the stamp whose corner is (px, py) in the tile's stamp order.
  int stamp_index(int px, int py) const {
    return static_cast<int>((unsigned(py - tile_y_) / simd::kStampHeight) * kStampsPerRow +
                            unsigned(px - tile_x_) / simd::kStampWidth);
  }
  /// Shades and writes the stamp at (px, py), index `stamp`. Coverage is carried as one mask per
  /// sample: all-ones lanes are covered.
  LUXEL_INLINE void shade_stamp(const TriangleSetup& t, int px, int py, int stamp, Int* coverage);
  Int depth_stencil_test(const TriangleSetup& t, StampDepth stamp_z, int stamp, int s, const Int& coverage,
                         const Float* shader_depth);
  /// Blending and write masks (plain writes are shade_stamp's).
  void write_color(int stamp, int s, const Int& coverage, const simd::Float4& color, const Int& packed);
  /// An rgba32f target's write: the color as the functor left it, into each written channel's
  /// plane (one sample: plan_draw refuses blending, the target more samples).
  void write_float(int stamp, const Int& coverage, const simd::Float4& color);
  template <CompareFunc kFunc>
  LUXEL_INLINE Int early_depth(StampDepth stamp_z, int stamp, Int* coverage);

  const DrawPlan& plan_;
  const PS& ps_;
  const PipelineState& state_;
  const StampLanes& lanes_;
  bool count_samples_;
  bool whole_tile_;
  bool simple_depth_;   ///< depth buffer without stencil
  bool full_coverage_;  ///< FastPath::FullCoverage
  bool fixed_depth_;    ///< FastPath::FixedDepthPaths
  bool constant_depth_path_;  ///< FastPath::ConstantDepth
  bool trivial_;        ///< a kTrivial functor, FastPath::TrivialShaders on
  bool depth_test_, depth_write_;
  CompareFunc depth_func_;
  float min_depth_, max_depth_;
  /// The 8-bit writes first: shade_stamp tells them from the other two with the one test that
  /// None needs, so that float targets add nothing to an 8-bit draw's stamps.
  enum class ColorWrite {
    Plain,      ///< no blending, all channels
    PlainSrgb,  ///< the same, sRGB-encoded
    Merged,     ///< blending or a partial write mask (write_color)
    None,       ///< no color target or nothing written
    Float,      ///< an rgba32f target (write_float)
  };
  ColorWrite color_write_;
  int tile_x_, tile_y_;
  int clip_x0_, clip_y0_, clip_x1_, clip_y1_;
  uint32_t* color_;
  float* depth_;
  uint8_t* stencil_;
  int sample_x_[S], sample_y_[S];
  Int sample_X_[S], sample_Y_[S];      ///< subpixels from the stamp's corner to each lane's sample
  Int sample_XY_[S];                   ///< the same, X in the low 16 bits and Y in the high (dot_halves)
  Float sample_dx_[kPlanePhases][S];  ///< the same in pixels, from the corner of the stamp's block
  Float block_center_x_[kPlanePhases];  ///< pixel centers' x from the corner of the stamp's block
  Float sample_dy_[S];
  /// The current triangle's depth at each sample of each stamp of a depth block whose corner is
  /// on the reference vertex.
  Float sample_z_[kPlanePhases][S];
  /// The current triangle has the same depth at every sample (FastPath::ConstantDepth):
  /// constant_z_, clamped, and sample_z_ is not set.
  bool constant_depth_ = false;
  Float constant_z_;
};

template <class PS, int N, DepthPath kPath, int S>
void TileRasterizer<PS, N, kPath, S>::triangle(const TriangleSetup& t) {
  // The triangle's pixels in this tile, widened to whole stamps.
  const int x0 = std::max<int>(t.x0, clip_x0_), y0 = std::max<int>(t.y0, clip_y0_);
  const int x1 = std::min<int>(t.x1, clip_x1_), y1 = std::min<int>(t.y1, clip_y1_);
  if (x0 >= x1 || y0 >= y1) return;
  // No slope: the per-sample path would add only zeros to q0 (exactly, but for the sign of a zero
  // q0, which is why it is left out) and clamp the same value at every sample.
  constant_depth_ = constant_depth_path_ && t.z.dqdx == 0.0f && t.z.dqdy == 0.0f && t.z.q0 != 0.0f;
  if (constant_depth_) {
    ++stats.constant_depth;
    constant_z_ = clamp_depth(Float(t.z.q0), Float(min_depth_), Float(max_depth_));
  } else if (depth_test_) {
    const Float z0(t.z.q0), dzdx(t.z.dqdx), dzdy(t.z.dqdy);
    for (int phase = 0; phase < kPlanePhases; ++phase)
      for (int s = 0; s < S; ++s)
        sample_z_[phase][s] = simd::fma(dzdx, sample_dx_[phase][s], simd::fma(dzdy, sample_dy_[s], z0));
  }
  const int sx0 = x0 & ~(simd::kStampWidth - 1), sy0 = y0 & ~(simd::kStampHeight - 1);
  if (t.small()) {
    rasterize_small(t, sx0, sy0, x1, y1);
  } else {
    rasterize(t, sx0, sy0, x1, y1);
  }
}

/// Edge bounds over a w x h subpixel rectangle from its corner: [min, max] added to the corner's value.
inline void edge_bounds(const Edge& e, int64_t w, int64_t h, int64_t& lo, int64_t& hi) {
  const int64_t ax = int64_t(e.a) * (w - 1), by = int64_t(e.b) * (h - 1);
  lo = std::min<int64_t>(0, ax) + std::min<int64_t>(0, by);
  hi = std::max<int64_t>(0, ax) + std::max<int64_t>(0, by);
}

template <class PS, int N, DepthPath kPath, int S>
void TileRasterizer<PS, N, kPath, S>::rasterize(const TriangleSetup& t, int sx0, int sy0, int x1, int y1) {
  StampEdges edges;
  for (int e = 0; e < 3; ++e) {
    const Edge& E = t.edges()[e];
    if (t.narrow_edges()) {
      const Int a(E.a), b(E.b);
      for (int s = 0; s < S; ++s) edges.lane_offset[e][s] = a * sample_X_[s] + b * sample_Y_[s];
    }
    edge_bounds(E, simd::kStampWidth * kSubpixelsPerPixel, simd::kStampHeight * kSubpixelsPerPixel,
                edges.min_offset[e], edges.max_offset[e]);
    if (!full_coverage_) edges.min_offset[e] = -(int64_t(1) << 62);  // no stamp is wholly inside
  }
  // Small triangles: straight to stamps. Larger ones: 16x16 blocks first, each rejected,
  // accepted whole (no edge tests for its stamps), or walked stamp by stamp.
  if (x1 - sx0 <= kBlockSize || y1 - sy0 <= kBlockSize || !full_coverage_) {
    rasterize_stamps(t, edges, sx0, sy0, x1, y1);
    return;
  }
  int64_t block_min[3], block_max[3];
  for (int e = 0; e < 3; ++e)
    edge_bounds(t.edges()[e], kBlockSize * kSubpixelsPerPixel, kBlockSize * kSubpixelsPerPixel, block_min[e], block_max[e]);
  for (int by = sy0 & ~(kBlockSize - 1); by < y1; by += kBlockSize) {
    for (int bx = sx0 & ~(kBlockSize - 1); bx < x1; bx += kBlockSize) {
      bool outside = false, inside = true;
      for (int e = 0; e < 3; ++e) {
        const Edge& E = t.edges()[e];
        const int64_t v = E.c + int64_t(E.a) * bx * kSubpixelsPerPixel + int64_t(E.b) * by * kSubpixelsPerPixel;
        outside |= v + block_max[e] < 0;
        inside &= v + block_min[e] >= 0;
      }
      if (outside) continue;
      const int x0 = std::max(bx, sx0), y0 = std::max(by, sy0);
      const int xe = std::min(bx + kBlockSize, x1), ye = std::min(by + kBlockSize, y1);
      if (!inside) {
        rasterize_stamps(t, edges, x0, y0, xe, ye);
        continue;
      }
      ++stats.blocks_full;
      Int coverage[S];
      for (int py = y0; py < ye; py += simd::kStampHeight) {
        int stamp = stamp_index(x0, py);
        for (int px = x0; px < xe; px += simd::kStampWidth, ++stamp) {
          const Int clip = clip_mask(px, py);
          for (int s = 0; s < S; ++s) coverage[s] = clip;
          ++stats.stamps_full;
          shade_stamp(t, px, py, stamp, coverage);
        }
      }
    }
  }
}

template <class PS, int N, DepthPath kPath, int S>
void TileRasterizer<PS, N, kPath, S>::rasterize_small(const TriangleSetup& t, int sx0, int sy0, int x1, int y1) {
  ++stats.small_walks;
  // The three edges side by side in the lanes of one Int4 (lane 3 is all zero): their values
  // at a stamp's corner, their steps to the next stamp in x and y, and their bounds over a
  // stamp (for reject and accept); 32-bit throughout (see kSmallTriangleSize).
  using simd::Int4;
  constexpr int kStampW = simd::kStampWidth * kSubpixelsPerPixel, kStampH = simd::kStampHeight * kSubpixelsPerPixel;
  const SmallEdges& edges = t.small_edges();
  const Int4 ab = Int4::load_aligned(edges.ab);
  const Int4 a = (ab << 16) >> 16, b = ab >> 16;
  // The record's corner moved to this walk's first stamp (a later tile of the triangle's).
  const int dx = sx0 - (t.x0 & ~(simd::kStampWidth - 1)), dy = sy0 - (t.y0 & ~(simd::kStampHeight - 1));
  Int4 row = Int4::load_aligned(edges.corner) + a * Int4(dx * kSubpixelsPerPixel) + b * Int4(dy * kSubpixelsPerPixel);
  const Int4 step_x = a * Int4(kStampW), step_y = b * Int4(kStampH);
  const Int4 a_span = step_x - a, b_span = step_y - b;  // (stamp size - 1) subpixels
  const Int4 zero(0);
  // Without FastPath::FullCoverage no stamp counts as wholly inside: |v| < 2^30 (above).
  const Int4 lo = full_coverage_ ? xsimd::min(a_span, zero) + xsimd::min(b_span, zero) : Int4(-(1 << 30));
  const Int4 hi = xsimd::max(a_span, zero) + xsimd::max(b_span, zero);
  // Per edge, the offsets of every lane's sample s from the stamp's corner: a X + b Y, one
  // 16-bit dot product per lane (|a|, |b| < 2^13, offsets < 2^11).
  static_assert(kSmallTriangleSize * kSubpixelsPerPixel <= INT16_MAX &&
                simd::kStampWidth * kSubpixelsPerPixel <= INT16_MAX);
  Int offset[3][S];
  const Int ab0 = simd::broadcast_lane<0>(ab), ab1 = simd::broadcast_lane<1>(ab), ab2 = simd::broadcast_lane<2>(ab);
  for (int s = 0; s < S; ++s) {
    offset[0][s] = simd::dot_halves(ab0, sample_XY_[s]);
    offset[1][s] = simd::dot_halves(ab1, sample_XY_[s]);
    offset[2][s] = simd::dot_halves(ab2, sample_XY_[s]);
  }
  Int coverage[S];
  for (int py = sy0; py < y1; py += simd::kStampHeight, row += step_y) {
    Int4 v = row;
    int stamp = stamp_index(sx0, py);
    bool entered = false;
    for (int px = sx0; px < x1; px += simd::kStampWidth, ++stamp, v += step_x) {
      // Wholly outside some edge: its bound is negative.
      if (simd::sign_bits(v + hi) & 7) {
        // The stamps of a row that no edge rejects are contiguous (each edge keeps an interval of
        // them): once past them, the row is done.
        if (entered) break;
        continue;
      }
      entered = true;
      const Int clip = clip_mask(px, py);
      if (!(simd::sign_bits(v + lo) & 7)) {
        for (int s = 0; s < S; ++s) coverage[s] = clip;
        ++stats.stamps_full;
      } else {
        const Int c0 = simd::broadcast_lane<0>(v), c1 = simd::broadcast_lane<1>(v), c2 = simd::broadcast_lane<2>(v);
        Int any(0);
        for (int s = 0; s < S; ++s) {
          // Negative in any edge: the sign bit marks the lanes outside.
          const Int outside = (c0 + offset[0][s]) | (c1 + offset[1][s]) | (c2 + offset[2][s]);
          coverage[s] = clip & ~(outside >> 31);
          any |= coverage[s];
        }
        if (!simd::sign_bits(any)) continue;
        ++stats.stamps_partial;
      }
      shade_stamp(t, px, py, stamp, coverage);
    }
  }
}

template <class PS, int N, DepthPath kPath, int S>
void TileRasterizer<PS, N, kPath, S>::rasterize_stamps(const TriangleSetup& t, const StampEdges& edges, int sx0,
                                                        int sy0, int x1, int y1) {
  constexpr int kStampW = simd::kStampWidth * kSubpixelsPerPixel;
  constexpr int64_t kClamp = int64_t(1) << 30;
  Int coverage[S];
  for (int py = sy0; py < y1; py += simd::kStampHeight) {
    int64_t row[3];
    for (int e = 0; e < 3; ++e)
      row[e] = t.edges()[e].c + int64_t(t.edges()[e].a) * sx0 * kSubpixelsPerPixel +
               int64_t(t.edges()[e].b) * py * kSubpixelsPerPixel;
    int stamp = stamp_index(sx0, py);
    bool entered = false;
    for (int px = sx0; px < x1; px += simd::kStampWidth, ++stamp) {
      const int64_t e0 = row[0], e1 = row[1], e2 = row[2];
      for (int e = 0; e < 3; ++e) row[e] += int64_t(t.edges()[e].a) * kStampW;
      if (((e0 + edges.max_offset[0]) | (e1 + edges.max_offset[1]) | (e2 + edges.max_offset[2])) < 0) {
        if (entered) break;  // see rasterize_small
        continue;
      }
      entered = true;
      const Int clip = clip_mask(px, py);
      if (((e0 + edges.min_offset[0]) | (e1 + edges.min_offset[1]) | (e2 + edges.min_offset[2])) >= 0) {
        for (int s = 0; s < S; ++s) coverage[s] = clip;
        ++stats.stamps_full;
      } else if (t.narrow_edges()) {
        // Per sample: the three edges at every lane, 32-bit. An edge value beyond +-2^30 at the
        // stamp corner keeps its sign over the whole stamp, so clamping it changes nothing.
        const Int c0(static_cast<int32_t>(std::clamp(e0, -kClamp, kClamp)));
        const Int c1(static_cast<int32_t>(std::clamp(e1, -kClamp, kClamp)));
        const Int c2(static_cast<int32_t>(std::clamp(e2, -kClamp, kClamp)));
        Int any(0);
        for (int s = 0; s < S; ++s) {
          // Negative in any edge: the sign bit marks the lanes outside.
          const Int outside = (c0 + edges.lane_offset[0][s]) | (c1 + edges.lane_offset[1][s]) |
                              (c2 + edges.lane_offset[2][s]);
          coverage[s] = clip & ~(outside >> 31);
          any |= coverage[s];
        }
        if (!simd::sign_bits(any)) continue;
        ++stats.stamps_partial;
      } else if (!wide_coverage(t, px, py, clip, coverage)) {
        continue;
      }
      shade_stamp(t, px, py, stamp, coverage);
    }
  }
}

template <class PS, int N, DepthPath kPath, int S>
bool TileRasterizer<PS, N, kPath, S>::wide_coverage(const TriangleSetup& t, int px, int py, const Int& clip,
                                                      Int* coverage) {
  // Edges too long for 32-bit per-sample steps: exact 64-bit evaluation, one sample at a time.
  const Edge* edges = t.edges();
  Int any(0);
  for (int s = 0; s < S; ++s) {
    alignas(64) int32_t inside[simd::kLanes];
    for (int l = 0; l < simd::kLanes; ++l) {
      const int64_t X = int64_t(px + simd::lane_x(l)) * kSubpixelsPerPixel + sample_x_[s];
      const int64_t Y = int64_t(py + simd::lane_y(l)) * kSubpixelsPerPixel + sample_y_[s];
      bool in = true;
      for (int e = 0; e < 3; ++e) in &= edges[e].a * X + edges[e].b * Y + edges[e].c >= 0;
      inside[l] = in ? -1 : 0;
    }
    coverage[s] = clip & Int::load_aligned(inside);
    any |= coverage[s];
  }
  if (!simd::sign_bits(any)) return false;
  ++stats.stamps_partial;
  ++stats.stamps_wide_edges;
  return true;
}

template <class PS, int N, DepthPath kPath, int S>
Int TileRasterizer<PS, N, kPath, S>::depth_stencil_test(const TriangleSetup& t, StampDepth stamp_z, int stamp, int s,
                                                         const Int& coverage, const Float* shader_depth) {
  float* depth = depth_ + s * kTilePixels + stamp * simd::kLanes;
  const Float dst_depth = Float::load_aligned(depth);
  Int depth_pass = coverage;
  Float z;
  if (depth_test_) {
    const Float min_depth(min_depth_), max_depth(max_depth_);
    z = shader_depth ? clamp_depth(*shader_depth, min_depth, max_depth)
                     : sample_depth(s, stamp_z, min_depth, max_depth, constant_depth_, constant_z_);
    depth_pass &= simd::mask_of(compare(depth_func_, z, dst_depth));
  }
  Int pass = depth_pass;
  if (!simple_depth_) {
    const DepthStencilState& ds = state_.depth_stencil;
    uint8_t* stencil = stencil_ + s * kTilePixels + stamp * simd::kLanes;
    const StencilFace& face = (ds.two_sided_stencil && !t.front_facing()) ? ds.back : ds.front;
    const Int value = simd::load_bytes(stencil);
    const Int read_mask(ds.stencil_read_mask);
    const Int stencil_pass =
        coverage & simd::mask_of(compare(face.func, Int(ds.stencil_ref) & read_mask, value & read_mask));
    pass = depth_pass & stencil_pass;
    const Int fail = coverage & ~stencil_pass;
    const Int depth_fail = stencil_pass & ~depth_pass;
    Int updated = simd::select(fail, stencil_op(face.fail, value, ds.stencil_ref), value);
    updated = simd::select(depth_fail, stencil_op(face.depth_fail, value, ds.stencil_ref), updated);
    updated = simd::select(pass, stencil_op(face.pass, value, ds.stencil_ref), updated);
    const Int write_mask(ds.stencil_write_mask);
    updated = (value & ~write_mask) | (updated & write_mask);
    simd::store_bytes(stencil, updated);
  }
  if (depth_write_) simd::select(pass, z, dst_depth).store_aligned(depth);
  return pass;
}

template <class PS, int N, DepthPath kPath, int S>
template <CompareFunc kFunc>
Int TileRasterizer<PS, N, kPath, S>::early_depth(StampDepth stamp_z, int stamp, Int* coverage) {
  // The common case, kept tight: depth test without stencil, compare function fixed.
  // Members copied before the first store: a float store could alias them, so the compiler
  // would otherwise load them again for every sample.
  float* depth = depth_ + stamp * simd::kLanes;
  const Float min_depth(min_depth_), max_depth(max_depth_);
  const bool depth_write = depth_write_, constant_depth = constant_depth_;
  const Float constant_z = constant_z_;
  Int live(0);
  for (int s = 0; s < S; ++s, depth += kTilePixels) {
    const Float d = Float::load_aligned(depth);
    const Float z = sample_depth(s, stamp_z, min_depth, max_depth, constant_depth, constant_z);
    const Int pass = coverage[s] & simd::mask_of(compare(kFunc, z, d));
    if (depth_write) simd::select(pass, z, d).store_aligned(depth);
    coverage[s] = pass;
    live |= pass;
  }
  return live;
}

template <class PS, int N, DepthPath kPath, int S>
void TileRasterizer<PS, N, kPath, S>::write_color(int stamp, int s, const Int& coverage, const simd::Float4& color,
                                                   const Int& packed) {
  int32_t* dst = reinterpret_cast<int32_t*>(color_ + s * kTilePixels + stamp * simd::kLanes);
  const Int old = Int::load_aligned(dst);
  Int value = packed;
  const BlendState& b = state_.blend;
  if (b.enable) {
    const simd::Float4 dst_color = b.srgb_write ? unpack_srgb8(old) : unpack_unorm8(old);
    const simd::Float4 blended = saturate(blend(b, color, dst_color));
    value = b.srgb_write ? pack_srgb8(blended) : pack_unorm8(blended);
  }
  const Int write(static_cast<int32_t>(plan_.color_write_mask));
  value = (value & write) | (old & ~write);
  simd::select(coverage, value, old).store_aligned(dst);
}

template <class PS, int N, DepthPath kPath, int S>
void TileRasterizer<PS, N, kPath, S>::write_float(int stamp, const Int& coverage, const simd::Float4& color) {
  float* dst = reinterpret_cast<float*>(color_) + stamp * simd::kLanes;
  const Float* channels[4] = {&color.x, &color.y, &color.z, &color.w};
  for (int c = 0; c < 4; ++c, dst += kTilePixels)
    if ((plan_.color_write_mask >> (8 * c)) & 0xffu)
      simd::select(coverage, *channels[c], Float::load_aligned(dst)).store_aligned(dst);
}

template <class PS, int N, DepthPath kPath, int S>
void TileRasterizer<PS, N, kPath, S>::interpolate(const TriangleSetup& t, const Float& cx, const Float& cy,
                                                   PixelInput<N>& in) {
  if (t.flat()) {
    const float* a = t.flat_varyings();
    for (int i = 0; i < N; ++i, a += 4) in.varyings[i] = {Float(a[0]), Float(a[1]), Float(a[2]), Float(a[3])};
    return;
  }
  if (t.affine()) {
    const Plane* p = t.varying_planes();
    for (int i = 0; i < N; ++i, p += 4)
      in.varyings[i] = {eval_plane(p[0], cx, cy), eval_plane(p[1], cx, cy), eval_plane(p[2], cx, cy),
                        eval_plane(p[3], cx, cy)};
    return;
  }
  const Barycentrics& bary = t.barycentrics();
  const Float w = Float(1.0f) / eval_plane(bary.inv_w, cx, cy);
  const Float b1 = eval_plane(bary.b1_w, cx, cy) * w, b2 = eval_plane(bary.b2_w, cx, cy) * w;
  const float* a = t.varying_deltas();
  for (int i = 0; i < N; ++i, a += 12) {  // a0 (4 floats), a1 - a0, a2 - a0
    in.varyings[i].x = simd::fma(b2, Float(a[8]), simd::fma(b1, Float(a[4]), Float(a[0])));
    in.varyings[i].y = simd::fma(b2, Float(a[9]), simd::fma(b1, Float(a[5]), Float(a[1])));
    in.varyings[i].z = simd::fma(b2, Float(a[10]), simd::fma(b1, Float(a[6]), Float(a[2])));
    in.varyings[i].w = simd::fma(b2, Float(a[11]), simd::fma(b1, Float(a[7]), Float(a[3])));
  }
}

template <class PS, int N, DepthPath kPath, int S>
void TileRasterizer<PS, N, kPath, S>::shade_stamp(const TriangleSetup& t, int px, int py, int stamp,
                                                   Int* coverage) {
  // The fixed paths test depth by construction: no flag to read.
  constexpr bool kFixedDepthPath = kPath == DepthPath::EarlyLess || kPath == DepthPath::EarlyLessEqual;
  const StampBlock block = stamp_block(px);
  const StampDepth stamp_z = kFixedDepthPath || depth_test_ ? stamp_depth(t, block, py) : StampDepth{0.0f, 0};
  Int live(0);
  if constexpr (kFixedDepthPath) {
    constexpr CompareFunc kFunc = kPath == DepthPath::EarlyLess ? CompareFunc::Less : CompareFunc::LessEqual;
    live = early_depth<kFunc>(stamp_z, stamp, coverage);
    if ((!kTrivialPixelFunctor<PS> || !trivial_) && !simd::sign_bits(live)) return;  // kTrivial: see draw.hpp
  } else if constexpr (kPath == DepthPath::Early) {
    if (kTrivialPixelFunctor<PS> && simple_depth_ && depth_test_ && fixed_depth_) {
      switch (depth_func_) {  // Less and LessEqual have their own paths
        case CompareFunc::Greater: live = early_depth<CompareFunc::Greater>(stamp_z, stamp, coverage); break;
        case CompareFunc::GreaterEqual: live = early_depth<CompareFunc::GreaterEqual>(stamp_z, stamp, coverage); break;
        default:
          for (int s = 0; s < S; ++s) {
            coverage[s] = depth_stencil_test(t, stamp_z, stamp, s, coverage[s], nullptr);
            live |= coverage[s];
          }
      }
      if ((!kTrivialPixelFunctor<PS> || !trivial_) && !simd::sign_bits(live)) return;  // kTrivial: see draw.hpp
    } else if (depth_) {
      for (int s = 0; s < S; ++s) {
        coverage[s] = depth_stencil_test(t, stamp_z, stamp, s, coverage[s], nullptr);
        live |= coverage[s];
      }
      if (!simd::sign_bits(live)) return;
    } else {
      for (int s = 0; s < S; ++s) live |= coverage[s];
    }
  } else {
    for (int s = 0; s < S; ++s) live |= coverage[s];
  }

  PixelInput<N> in;
  in.x = Float(float(px)) + lanes_.center_x;
  in.y = Float(float(py)) + lanes_.center_y;
  if constexpr (N > 0) {
    // Offsets of the pixel centers from the triangle's reference vertex, from the block's corner
    // (kPlaneBlockWidth: the same rounding for any stamp width).
    const Float cx = Float(float(block.x) - t.ref_x) + block_center_x_[block.phase];
    const Float cy = Float(float(py) - t.ref_y) + lanes_.center_y;
    interpolate(t, cx, cy, in);
  }
  in.live = simd::sign_bits(live);
  in.front_facing = t.front_facing();
  PixelOutput out;
  ps_(in, out);
  ++stats.stamps_shaded;

  if constexpr (kPath == DepthPath::Late) {
    Int keep(-1);
    if constexpr (PS::kCanDiscard) keep = ~simd::mask_of(simd::int_mask(out.discard));
    if (plan_.alpha_test) {
      const Int alpha8 = simd::round_to_int(xsimd::min(xsimd::max(out.color.w, Float(0.0f)), Float(1.0f)) * Float(255.0f));
      keep &= simd::mask_of(compare(state_.alpha_test.func, alpha8, Int(state_.alpha_test.ref)));
    }
    live = Int(0);
    for (int s = 0; s < S; ++s) {
      coverage[s] &= keep;
      if (depth_ && simd::sign_bits(coverage[s]))
        coverage[s] = depth_stencil_test(t, stamp_z, stamp, s, coverage[s], writes_depth(ps_) ? &out.depth : nullptr);
      live |= coverage[s];
    }
    if (!simd::sign_bits(live)) return;
  }

  if (count_samples_)
    for (int s = 0; s < S; ++s) samples_passed += std::popcount(simd::sign_bits(coverage[s]));
  if (color_write_ >= ColorWrite::None) {  // see ColorWrite
    if (color_write_ == ColorWrite::Float) write_float(stamp, coverage[0], out.color);
    return;
  }
  if (color_write_ != ColorWrite::Merged) {
    // No blending, all channels: packing clamps by itself.
    const Int packed = color_write_ == ColorWrite::PlainSrgb ? pack_srgb8(out.color) : pack_unorm8(out.color);
    int32_t* dst = reinterpret_cast<int32_t*>(color_ + stamp * simd::kLanes);
    for (int s = 0; s < S; ++s, dst += kTilePixels)
      simd::select(coverage[s], packed, Int::load_aligned(dst)).store_aligned(dst);
    return;
  }
  const simd::Float4 color = saturate(out.color);
  const Int packed = state_.blend.enable ? Int(0) : (state_.blend.srgb_write ? pack_srgb8(color) : pack_unorm8(color));
  for (int s = 0; s < S; ++s) write_color(stamp, s, coverage[s], color, packed);
}

}  // namespace luxel::rasterizer::detail
