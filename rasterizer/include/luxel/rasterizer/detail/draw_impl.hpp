#pragma once
// Private: the body of draw(). Templated on the shader functors so that the per-stamp loop
// inlines them; everything that does not depend on them lives in .cpp files.

#include "luxel/rasterizer/detail/command_queue.hpp"
#include "luxel/rasterizer/detail/output_merger.hpp"
#include "luxel/rasterizer/detail/triangle_setup.hpp"
#include "luxel/rasterizer/msaa.hpp"

#include <bit>
#include <stdexcept>
#include <vector>

namespace luxel::rasterizer::detail {

/// Everything about a draw the tile rasterizer needs, decided once per draw.
struct DrawPlan {
  DrawConstants constants;
  const PipelineState* state = nullptr;
  ColorTarget* color = nullptr;
  DepthStencilTarget* depth_stencil = nullptr;
  SurfaceLayout layout;
  SampleOffset sample_offsets[kMaxSamples];
  bool depth_test = false, depth_write = false, stencil = false, alpha_test = false;
  uint32_t color_write_mask = 0;  ///< RGBA8 bits to write
};

DrawPlan plan_draw(const Framebuffer& fb, const PipelineState& state, int varyings);

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
  return xsimd::fma(Float(p.dqdx), dx, xsimd::fma(Float(p.dqdy), dy, Float(p.q0)));
}

/// Rasterizes the triangles binned to one tile, in submission order. S is the sample count.
template <class PS, int N, bool kEarlyZ, int S>
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
      sample_dx_[s] = simd::lanes([&](int l) { return simd::lane_x(l) + sample_x_[s] / 256.0f; });
      sample_dy_[s] = simd::lanes([&](int l) { return simd::lane_y(l) + sample_y_[s] / 256.0f; });
    }
    simple_depth_ = depth_ && !plan.stencil;
    plain_color_ = color_ && !state_.blend.enable && plan.color_write_mask == 0xffffffffu;
  }

  void triangle(const TriangleSetup& t);

  uint64_t samples_passed = 0;
  DrawStats stats;

 private:
  void rasterize_narrow(const TriangleSetup& t, int x0, int y0, int x1, int y1);
  void rasterize_wide(const TriangleSetup& t, int x0, int y0, int x1, int y1);
  LaneBits clip_lanes(int px, int py) const {
    if (whole_tile_) return simd::kAllLanes;
    if (px >= clip_x0_ && px + simd::kStampWidth <= clip_x1_ && py >= clip_y0_ && py + simd::kStampHeight <= clip_y1_)
      return simd::kAllLanes;
    LaneBits bits = 0;
    for (int l = 0; l < simd::kLanes; ++l) {
      const int x = px + simd::lane_x(l), y = py + simd::lane_y(l);
      if (x >= clip_x0_ && x < clip_x1_ && y >= clip_y0_ && y < clip_y1_) bits |= 1u << l;
    }
    return bits;
  }
  IntMask lane_mask(LaneBits bits) const { return (Int(static_cast<int32_t>(bits)) & lanes_.bit) != Int(0); }
  void shade_stamp(const TriangleSetup& t, int px, int py, LaneBits* coverage);
  LaneBits depth_stencil_test(const TriangleSetup& t, const Float& dx, const Float& dy, int stamp, int s,
                              LaneBits coverage, const Float* shader_depth);
  void write_color(int stamp, int s, LaneBits coverage, const simd::Float4& color, const Int& packed);

  const DrawPlan& plan_;
  const PS& ps_;
  const PipelineState& state_;
  const StampLanes& lanes_;
  bool count_samples_;
  bool whole_tile_;
  bool simple_depth_;   ///< depth buffer without stencil
  bool plain_color_;    ///< no blending, all channels written
  int tile_x_, tile_y_;
  int clip_x0_, clip_y0_, clip_x1_, clip_y1_;
  uint32_t* color_;
  float* depth_;
  uint8_t* stencil_;
  int sample_x_[S], sample_y_[S];
  Float sample_dx_[S], sample_dy_[S];
};

template <class PS, int N, bool kEarlyZ, int S>
void TileRasterizer<PS, N, kEarlyZ, S>::triangle(const TriangleSetup& t) {
  // The triangle's pixels in this tile, widened to whole stamps.
  const int x0 = std::max<int>(t.x0, clip_x0_), y0 = std::max<int>(t.y0, clip_y0_);
  const int x1 = std::min<int>(t.x1, clip_x1_), y1 = std::min<int>(t.y1, clip_y1_);
  if (x0 >= x1 || y0 >= y1) return;
  const int sx0 = x0 & ~(simd::kStampWidth - 1), sy0 = y0 & ~(simd::kStampHeight - 1);
  if (t.narrow_edges) {
    rasterize_narrow(t, sx0, sy0, x1, y1);
  } else {
    rasterize_wide(t, sx0, sy0, x1, y1);
  }
}

template <class PS, int N, bool kEarlyZ, int S>
void TileRasterizer<PS, N, kEarlyZ, S>::rasterize_narrow(const TriangleSetup& t, int sx0, int sy0, int x1, int y1) {
  constexpr int kStampW = simd::kStampWidth * kSubpixelsPerPixel;
  constexpr int kStampH = simd::kStampHeight * kSubpixelsPerPixel;
  constexpr int64_t kClamp = int64_t(1) << 30;

  Int pixel_offset[3];
  int32_t sample_offset[3][S];
  int64_t min_offset[3], max_offset[3];
  for (int e = 0; e < 3; ++e) {
    const Edge& E = t.edge[e];
    pixel_offset[e] = Int(E.a) * lanes_.x_sub + Int(E.b) * lanes_.y_sub;
    for (int s = 0; s < S; ++s) sample_offset[e][s] = E.a * sample_x_[s] + E.b * sample_y_[s];
    // Bounds of the edge over the stamp's area (conservative: the whole rectangle).
    const int64_t ax = int64_t(E.a) * (kStampW - 1), by = int64_t(E.b) * (kStampH - 1);
    min_offset[e] = std::min<int64_t>(0, ax) + std::min<int64_t>(0, by);
    max_offset[e] = std::max<int64_t>(0, ax) + std::max<int64_t>(0, by);
  }

  LaneBits coverage[S];
  for (int py = sy0; py < y1; py += simd::kStampHeight) {
    int64_t row[3];
    for (int e = 0; e < 3; ++e)
      row[e] = t.edge[e].c + int64_t(t.edge[e].a) * sx0 * kSubpixelsPerPixel +
               int64_t(t.edge[e].b) * py * kSubpixelsPerPixel;
    for (int px = sx0; px < x1; px += simd::kStampWidth) {
      const int64_t e0 = row[0], e1 = row[1], e2 = row[2];
      for (int e = 0; e < 3; ++e) row[e] += int64_t(t.edge[e].a) * kStampW;
      if (e0 + max_offset[0] < 0 || e1 + max_offset[1] < 0 || e2 + max_offset[2] < 0) continue;
      const LaneBits clip = clip_lanes(px, py);
      if (e0 + min_offset[0] >= 0 && e1 + min_offset[1] >= 0 && e2 + min_offset[2] >= 0) {
        for (int s = 0; s < S; ++s) coverage[s] = clip;
        ++stats.stamps_full;
      } else {
        // Per sample: the three edges at every lane, 32-bit. An edge value beyond +-2^30 at the
        // stamp corner keeps its sign over the whole stamp, so clamping it changes nothing.
        const Int c0(static_cast<int32_t>(std::clamp(e0, -kClamp, kClamp)));
        const Int c1(static_cast<int32_t>(std::clamp(e1, -kClamp, kClamp)));
        const Int c2(static_cast<int32_t>(std::clamp(e2, -kClamp, kClamp)));
        const Int p0 = c0 + pixel_offset[0], p1 = c1 + pixel_offset[1], p2 = c2 + pixel_offset[2];
        LaneBits any = 0;
        for (int s = 0; s < S; ++s) {
          const Int inside = (p0 + Int(sample_offset[0][s])) | (p1 + Int(sample_offset[1][s])) |
                             (p2 + Int(sample_offset[2][s]));
          coverage[s] = ~simd::sign_bits(inside) & clip;
          any |= coverage[s];
        }
        if (!any) continue;
        ++stats.stamps_partial;
      }
      shade_stamp(t, px, py, coverage);
    }
  }
}

template <class PS, int N, bool kEarlyZ, int S>
void TileRasterizer<PS, N, kEarlyZ, S>::rasterize_wide(const TriangleSetup& t, int sx0, int sy0, int x1, int y1) {
  // Edges too long for 32-bit per-sample steps: exact 64-bit evaluation, one sample at a time.
  LaneBits coverage[S];
  for (int py = sy0; py < y1; py += simd::kStampHeight) {
    for (int px = sx0; px < x1; px += simd::kStampWidth) {
      const LaneBits clip = clip_lanes(px, py);
      LaneBits any = 0;
      for (int s = 0; s < S; ++s) {
        LaneBits bits = 0;
        for (int l = 0; l < simd::kLanes; ++l) {
          const int64_t X = int64_t(px + simd::lane_x(l)) * kSubpixelsPerPixel + sample_x_[s];
          const int64_t Y = int64_t(py + simd::lane_y(l)) * kSubpixelsPerPixel + sample_y_[s];
          bool inside = true;
          for (const Edge& e : t.edge) inside &= e.a * X + e.b * Y + e.c >= 0;
          bits |= LaneBits(inside) << l;
        }
        coverage[s] = bits & clip;
        any |= coverage[s];
      }
      if (!any) continue;
      ++stats.stamps_partial;
      ++stats.stamps_wide_edges;
      shade_stamp(t, px, py, coverage);
    }
  }
}

template <class PS, int N, bool kEarlyZ, int S>
LaneBits TileRasterizer<PS, N, kEarlyZ, S>::depth_stencil_test(const TriangleSetup& t, const Float& dx,
                                                              const Float& dy, int stamp, int s, LaneBits coverage,
                                                              const Float* shader_depth) {
  const DepthStencilState& ds = state_.depth_stencil;
  float* depth = depth_ + s * kTilePixels + stamp * simd::kLanes;
  const Float dst_depth = Float::load_aligned(depth);
  LaneBits depth_pass = coverage;
  Float z;
  if (plan_.depth_test) {
    z = shader_depth ? *shader_depth : eval_plane(t.z, dx + sample_dx_[s], dy + sample_dy_[s]);
    z = xsimd::min(xsimd::max(z, Float(plan_.constants.min_depth)), Float(plan_.constants.max_depth));
    depth_pass &= simd::to_bits(compare(ds.depth_func, z, dst_depth));
  }
  LaneBits pass = depth_pass;
  if (!simple_depth_) {
    uint8_t* stencil = stencil_ + s * kTilePixels + stamp * simd::kLanes;
    const StencilFace& face = (ds.two_sided_stencil && !t.front_facing) ? ds.back : ds.front;
    const Int value = simd::load_bytes(stencil);
    const Int read_mask(ds.stencil_read_mask);
    const LaneBits stencil_pass =
        coverage & simd::to_bits(compare(face.func, Int(ds.stencil_ref) & read_mask, value & read_mask));
    pass = depth_pass & stencil_pass;
    const LaneBits fail = coverage & ~stencil_pass;
    const LaneBits depth_fail = stencil_pass & ~depth_pass;
    Int updated = value;
    if (fail) updated = xsimd::select(lane_mask(fail), stencil_op(face.fail, value, ds.stencil_ref), updated);
    if (depth_fail)
      updated = xsimd::select(lane_mask(depth_fail), stencil_op(face.depth_fail, value, ds.stencil_ref), updated);
    if (pass) updated = xsimd::select(lane_mask(pass), stencil_op(face.pass, value, ds.stencil_ref), updated);
    const Int write_mask(ds.stencil_write_mask);
    updated = (value & ~write_mask) | (updated & write_mask);
    simd::store_bytes(stencil, updated);
  }
  if (plan_.depth_write && pass) {
    const FloatMask m = xsimd::bitwise_cast<Float>(Int(lane_mask(pass))) != Float(0.0f);
    xsimd::select(m, z, dst_depth).store_aligned(depth);
  }
  return pass;
}

template <class PS, int N, bool kEarlyZ, int S>
void TileRasterizer<PS, N, kEarlyZ, S>::write_color(int stamp, int s, LaneBits coverage, const simd::Float4& color,
                                                   const Int& packed) {
  int32_t* dst = reinterpret_cast<int32_t*>(color_ + s * kTilePixels + stamp * simd::kLanes);
  if (plain_color_) {
    if (coverage == simd::kAllLanes) {
      packed.store_aligned(dst);
    } else {
      xsimd::select(lane_mask(coverage), packed, Int::load_aligned(dst)).store_aligned(dst);
    }
    return;
  }
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
  xsimd::select(lane_mask(coverage), value, old).store_aligned(dst);
}

template <class PS, int N, bool kEarlyZ, int S>
void TileRasterizer<PS, N, kEarlyZ, S>::shade_stamp(const TriangleSetup& t, int px, int py, LaneBits* coverage) {
  const int stamp = ((py - tile_y_) / simd::kStampHeight) * (kTileSize / simd::kStampWidth) +
                    (px - tile_x_) / simd::kStampWidth;
  // Offsets of the stamp's corner from the triangle's reference vertex: exact in float.
  const Float dx(float(px) - t.ref_x), dy(float(py) - t.ref_y);
  LaneBits live = 0;
  if constexpr (kEarlyZ) {
    if (depth_) {
      for (int s = 0; s < S; ++s) {
        coverage[s] = depth_stencil_test(t, dx, dy, stamp, s, coverage[s], nullptr);
        live |= coverage[s];
      }
      if (!live) return;
    } else {
      for (int s = 0; s < S; ++s) live |= coverage[s];
    }
  } else {
    for (int s = 0; s < S; ++s) live |= coverage[s];
  }

  // Interpolants at the pixel centers, perspective-correct.
  PixelInput<N> in;
  const Float cx = dx + lanes_.center_x, cy = dy + lanes_.center_y;
  in.x = Float(float(px)) + lanes_.center_x;
  in.y = Float(float(py)) + lanes_.center_y;
  if constexpr (N > 0) {
    const Float w = Float(1.0f) / eval_plane(t.inv_w, cx, cy);
    const Float b1 = eval_plane(t.b1_w, cx, cy) * w;
    const Float b2 = eval_plane(t.b2_w, cx, cy) * w;
    const float* a = t.varyings();
    for (int i = 0; i < N; ++i, a += 12) {
      in.varyings[i].x = xsimd::fma(b2, Float(a[2]), xsimd::fma(b1, Float(a[1]), Float(a[0])));
      in.varyings[i].y = xsimd::fma(b2, Float(a[5]), xsimd::fma(b1, Float(a[4]), Float(a[3])));
      in.varyings[i].z = xsimd::fma(b2, Float(a[8]), xsimd::fma(b1, Float(a[7]), Float(a[6])));
      in.varyings[i].w = xsimd::fma(b2, Float(a[11]), xsimd::fma(b1, Float(a[10]), Float(a[9])));
    }
  }
  in.live = live;
  in.front_facing = t.front_facing;
  PixelOutput out;
  ps_(in, out);

  if constexpr (!kEarlyZ) {
    LaneBits kill = 0;
    if constexpr (PS::kCanDiscard) kill |= out.discard;
    if (plan_.alpha_test) {
      const Int alpha8 = simd::round_to_int(xsimd::min(xsimd::max(out.color.w, Float(0.0f)), Float(1.0f)) * Float(255.0f));
      kill |= ~simd::to_bits(compare(state_.alpha_test.func, alpha8, Int(state_.alpha_test.ref)));
    }
    live = 0;
    for (int s = 0; s < S; ++s) {
      coverage[s] &= ~kill;
      if (coverage[s] && depth_)
        coverage[s] = depth_stencil_test(t, dx, dy, stamp, s, coverage[s], PS::kWritesDepth ? &out.depth : nullptr);
      live |= coverage[s];
    }
    if (!live) return;
  }

  if (count_samples_)
    for (int s = 0; s < S; ++s) samples_passed += std::popcount(coverage[s]);
  if (!color_ || !plan_.color_write_mask) return;
  const simd::Float4 color = saturate(out.color);
  const Int packed = state_.blend.enable ? Int(0) : (state_.blend.srgb_write ? pack_srgb8(color) : pack_unorm8(color));
  for (int s = 0; s < S; ++s) {
    if (coverage[s]) write_color(stamp, s, coverage[s], color, packed);
  }
}

/// Runs the vertex functor for a chunk of triangles and sets them up into `bins`.
template <class VS>
void front_end_chunk(const DrawConstants& dc, const Geometry& geometry, const VS& vs, uint32_t first, uint32_t last,
                     ChunkBins& bins, DrawStats& stats) {
  constexpr int N = VS::kVaryings;
  using Vertex = VertexOutput<N>;
  static_assert(sizeof(Vertex) == sizeof(glm::vec4) * (1 + N), "position and varyings must be contiguous");
  if (geometry.index_format == Geometry::IndexFormat::None) {
    Vertex v[3];
    const glm::vec4* p[3] = {&v[0].position, &v[1].position, &v[2].position};
    for (uint32_t tri = first; tri < last; ++tri) {
      for (int k = 0; k < 3; ++k) vs(3 * tri + k, v[k]);
      process_triangle(dc, p, bins, stats);
    }
    return;
  }
  // A small direct-mapped post-transform cache: shared vertices are shaded once most of the time.
  constexpr uint32_t kCacheSize = 64;
  struct Entry {
    uint32_t index = ~0u;
    Vertex out;
  };
  std::vector<Entry> cache(kCacheSize);
  Vertex spill[3];
  for (uint32_t tri = first; tri < last; ++tri) {
    uint32_t idx[3];
    bool bad = false;
    for (int k = 0; k < 3; ++k) {
      idx[k] = geometry.index(3 * tri + k);
      bad |= idx[k] >= geometry.vertex_count;
    }
    if (bad) {
      ++stats.bad_index;
      continue;
    }
    const glm::vec4* p[3];
    for (int k = 0; k < 3; ++k) {
      const uint32_t slot = idx[k] % kCacheSize;
      bool collides = false;  // an earlier vertex of this triangle lives in the same slot
      for (int j = 0; j < k; ++j) collides |= (idx[j] % kCacheSize == slot) && idx[j] != idx[k];
      if (collides) {
        vs(idx[k], spill[k]);
        p[k] = &spill[k].position;
        continue;
      }
      Entry& e = cache[slot];
      if (e.index != idx[k]) {
        vs(idx[k], e.out);
        e.index = idx[k];
      }
      p[k] = &e.out.position;
    }
    process_triangle(dc, p, bins, stats);
  }
}

/// A recorded draw: its binned triangles and a copy of everything its pixels need.
template <class PS, int N>
class DrawCommand final : public Command {
 public:
  DrawCommand(const DrawPlan& plan, const PipelineState& state, const PS& ps, std::vector<ChunkBins*> chunks,
              int query_slot)
      : plan_(plan), state_(state), ps_(ps), chunks_(std::move(chunks)), query_slot_(query_slot) {
    plan_.state = &state_;
    early_z_ = !PS::kCanDiscard && !PS::kWritesDepth && !plan_.alpha_test;
    tile_active_.assign(plan_.layout.tile_count(), 0);
    for (const ChunkBins* c : chunks_)
      for (uint32_t t : c->touched_tiles) tile_active_[t] = 1;
  }

  void execute(int tile, TileCounters& counters) override {
    if (!tile_active_[tile]) return;
    switch (plan_.layout.samples) {
      case 1: return execute_with<1>(tile, counters);
      case 2: return execute_with<2>(tile, counters);
      case 4: return execute_with<4>(tile, counters);
      default: return execute_with<8>(tile, counters);
    }
  }

 private:
  template <int S>
  void execute_with(int tile, TileCounters& counters) {
    if (early_z_) {
      run(TileRasterizer<PS, N, true, S>(plan_, ps_, tile, query_slot_ >= 0), tile, counters);
    } else {
      run(TileRasterizer<PS, N, false, S>(plan_, ps_, tile, query_slot_ >= 0), tile, counters);
    }
  }

  template <class Rasterizer>
  void run(Rasterizer rasterizer, int tile, TileCounters& counters) {
    const size_t size = triangle_record_size(N);
    for (const ChunkBins* bins : chunks_) {
      const std::vector<std::byte>& records = bins->tile_records[tile];
      for (size_t offset = 0; offset < records.size(); offset += size)
        rasterizer.triangle(*reinterpret_cast<const TriangleSetup*>(records.data() + offset));
    }
    if (query_slot_ >= 0) counters.query_samples[query_slot_] += rasterizer.samples_passed;
    *counters.stats += rasterizer.stats;
  }

  DrawPlan plan_;
  PipelineState state_;
  PS ps_;
  std::vector<ChunkBins*> chunks_;
  std::vector<uint8_t> tile_active_;
  int query_slot_;
  bool early_z_;
};

}  // namespace luxel::rasterizer::detail

namespace luxel::rasterizer {

template <VertexFunctor VS, PixelFunctor<VS::kVaryings> PS>
void draw(Context& ctx, const Framebuffer& fb, const PipelineState& state, const Geometry& geometry,
          const VS& vertex_shader, const PS& pixel_shader) {
  using namespace detail;
  constexpr int N = VS::kVaryings;
  const DrawPlan plan = plan_draw(fb, state, N);
  const uint32_t triangles = geometry.triangle_count();
  CommandQueue& queue = ctx.queue();
  if (!queue.accepts(plan.layout) || queue.pending_triangles() + triangles > kMaxPendingTriangles) ctx.flush();
  queue.set_layout(plan.layout);
  queue.front_end_stats().triangles += triangles;
  if (triangles == 0 || plan.constants.clip_x0 >= plan.constants.clip_x1 ||
      plan.constants.clip_y0 >= plan.constants.clip_y1)
    return;

  // Front end now, in parallel over chunks of triangles; each chunk bins into its own lists.
  const int chunk_count = static_cast<int>((triangles + kTrianglesPerChunk - 1) / kTrianglesPerChunk);
  std::vector<ChunkBins*> chunks = queue.allocate_chunks(chunk_count);
  std::vector<DrawStats> chunk_stats(chunk_count);
  ctx.parallel_for(chunk_count, [&](int c, int) {
    const uint32_t first = static_cast<uint32_t>(c) * kTrianglesPerChunk;
    const uint32_t last = std::min<uint32_t>(triangles, first + kTrianglesPerChunk);
    front_end_chunk(plan.constants, geometry, vertex_shader, first, last, *chunks[c], chunk_stats[c]);
  });
  for (const DrawStats& s : chunk_stats) queue.front_end_stats() += s;
  queue.add_pending_triangles(triangles);
  const int slot = queue.query_slot(ctx.active_query());
  queue.push(std::make_unique<DrawCommand<PS, N>>(plan, state, pixel_shader, std::move(chunks), slot));
}

}  // namespace luxel::rasterizer
