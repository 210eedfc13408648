#pragma once
// Private to the texture module: where the SIMD sampling path (texture_sample_impl.hpp) finds
// each lane's texels: the state one call's reads share, the geometry of the level each lane
// reads, addressing (wrap, mirror, clamp, border), linear and point footprints, the word of a
// texel in the storage, and the prefetch hints.
//
// Level geometry is taken per lane (levels differ between quads in trilinear stamps), with a fast
// case when the whole stamp reads one level.

#include "texture_formats.hpp"

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace luxel::rasterizer::texture_sampling {

// --- Per-call state ---------------------------------------------------------------------------

template <class Format>
struct Context {
  const Texture& texture;
  const Sampler& sampler;
  SampledStorage storage;
  TexelOf<Format> border;  ///< in the format's raw domain
  bool any_border;
  /// One-level 2D reads: ask for the texels this many words below the stamp's (0: none).
  int32_t prefetch_words_below = 0;
  /// One-word formats: read each footprint texel's words as windows along the stamp's rows where
  /// they lie close enough (gather_stamp_rows).
  bool reads_stamp_rows = false;
  /// Bilinear reads of a 2D level: where every lane's weight along an axis is 0, read only the
  /// first texel along it (filter_2d).
  bool skips_zero_weights = false;
  /// Trilinear reads of a volume under Clamp on every axis: its cells (Texture::cell_words_), or
  /// null to read its texels one by one.
  const int32_t* cells = nullptr;
  int32_t cell_slice_words = 0;  ///< words from a square of the cells to the one above it
};

/// The texel at `index` of each lane, in the format's raw domain.
template <class Format>
LUXEL_INLINE TexelOf<Format> fetch(const Context<Format>& ctx, const Int& index) {
  if constexpr (Format::kWords == 1) {
    if (ctx.reads_stamp_rows) return Format::decode(gather_stamp_rows(ctx.storage.words, index));
  }
  return Format::fetch(ctx.storage.words, index);
}

/// Geometry of the level each lane reads.
struct Level {
  Int width, height, depth;
  Float fwidth, fheight, fdepth;
  Int offset;  ///< first word of the level within a face
};

/// Geometry of level `level`, the same for every lane.
LUXEL_INLINE Level level_geometry(const Texture& t, const std::array<int32_t, kMaxMipLevels>& offsets, int level) {
  Level g;
  g.width = Int(t.width(level));
  g.height = Int(t.height(level));
  g.depth = Int(t.depth(level));
  g.offset = Int(offsets[level]);
  g.fwidth = to_float(g.width);
  g.fheight = to_float(g.height);
  g.fdepth = to_float(g.depth);
  return g;
}

/// Geometry of the level each lane reads.
LUXEL_INLINE Level level_geometry(const Texture& t, const std::array<int32_t, kMaxMipLevels>& offsets, const Int& level) {
#if defined(__SANITIZE_ADDRESS__)
  // The level table is an array inside the Texture: AddressSanitizer cannot see a read past its
  // end (it lands on the next member or padding), so sanitizer builds check the levels here.
  if (!xsimd::all((level >= Int(0)) & (level < Int(t.mip_levels())))) {
    std::fputs("luxel: texture sampling read a mip level outside the texture\n", stderr);
    std::abort();
  }
#endif
  alignas(64) int32_t l[kLanes];
  level.store_aligned(l);
  if (xsimd::all(level == Int(l[0]))) return level_geometry(t, offsets, l[0]);
  Level g;
  const Int one(1);
  g.width = xsimd::max(Int(t.width()) >> level, one);
  g.height = xsimd::max(Int(t.height()) >> level, one);
  g.depth = xsimd::max(Int(t.depth()) >> level, one);
  g.offset = simd::gather(offsets.data(), level);
  g.fwidth = to_float(g.width);
  g.fheight = to_float(g.height);
  g.fdepth = to_float(g.depth);
  return g;
}

// --- Addressing -------------------------------------------------------------------------------

/// One period of the coordinate (see texture.hpp); NaN -> 0.
LUXEL_INLINE Float reduce(const Float& c, Address mode) {
  const Float zero(0.0f);
  Float x = xsimd::select(xsimd::isnan(c), zero, c);
  switch (mode) {
    case Address::Wrap: x = x - xsimd::floor(x); return xsimd::select(xsimd::isnan(x), zero, x);
    case Address::Mirror:
      x = x - Float(2.0f) * xsimd::floor(x * Float(0.5f));
      return xsimd::select(xsimd::isnan(x), zero, x);
    case Address::Clamp:
    case Address::Border: return xsimd::min(xsimd::max(x, Float(-1.0f)), Float(2.0f));
  }
  return x;
}

/// Texel index along an axis of n texels. The reduced coordinate bounds i to [-1, n] under Wrap,
/// [-1, 2n] under Mirror; Border sets `outside` and clamps (so every read stays in the level).
LUXEL_INLINE Int address(Int i, const Int& n, Address mode, IntMask& outside) {
  const Int zero(0), one(1);
  switch (mode) {
    case Address::Wrap: {
      // -1 -> n-1 and n -> 0 as unsigned minima: of i, i + n and i - n, the out-of-range
      // candidates are negative, i.e. huge unsigned.
      const simd::UInt u = xsimd::bitwise_cast<simd::UInt>(i);
      const simd::UInt wrapped = xsimd::min(xsimd::min(u, u + xsimd::bitwise_cast<simd::UInt>(n)),
                                            u - xsimd::bitwise_cast<simd::UInt>(n));
      return xsimd::bitwise_cast<Int>(wrapped);
    }
    case Address::Mirror: {
      const Int period = n + n;
      i = xsimd::select(i < zero, Int(-1) - i, i);
      i = xsimd::select(i >= period, i - period, i);
      return xsimd::select(i >= n, period - one - i, i);
    }
    case Address::Clamp: return xsimd::min(xsimd::max(i, zero), n - one);
    case Address::Border: outside = (i < zero) | (i >= n); return xsimd::min(xsimd::max(i, zero), n - one);
  }
  return i;
}

/// The two texels and the weight of the second along one axis of a linear footprint.
struct LinearAxis {
  Int i0, i1;
  Float weight;
  IntMask outside0 = simd::no_lanes(), outside1 = simd::no_lanes();  ///< set by Border only
};

/// Where a linear footprint starts along an axis of n texels (fn = n): the first of its two texels
/// before addressing, and the weight of the second.
/// The hardware rules first convert the texel position to 16.8 fixed point (rounded to nearest,
/// ties to even): its integer part names the first texel, its 8 fractional bits the weight.
template <class Format>
LUXEL_INLINE Int footprint_start(const Float& c, const Float& fn, Float& weight) {
  const Float x = c * fn - Float(0.5f);
  if constexpr (Format::kHardware) {
    const Int fixed = simd::round_to_int(x * Float(256.0f));
    weight = to_float(fixed & Int(255)) * Float(1.0f / 256.0f);
    return fixed >> 8;  // arithmetic: the floor
  }
  const Float first = xsimd::floor(x);
  weight = x - first;
  return to_int(first);
}

template <class Format>
LUXEL_INLINE LinearAxis linear_axis(const Float& c, const Int& n, const Float& fn, Address mode) {
  LinearAxis a;
  const Int i0 = footprint_start<Format>(c, fn, a.weight);
  a.i0 = address(i0, n, mode, a.outside0);
  a.i1 = address(i0 + Int(1), n, mode, a.outside1);
  return a;
}

LUXEL_INLINE Int point_axis(const Float& c, const Int& n, const Float& fn, Address mode,
                                    IntMask& outside) {
  return address(to_int(xsimd::floor(c * fn)), n, mode, outside);
}

/// The first texel of row j of a level `width` texels wide: j * width, as one 16-bit multiply-add
/// (rows and widths are below 2^15, kMaxTextureSize): the texel address waits for this product,
/// and a 32-bit multiply takes twice the latency on Intel cores (the same on AMD's).
LUXEL_INLINE Int row_start(const Int& j, const Int& width) { return simd::dot_halves(j, width); }

template <class Format>
LUXEL_INLINE Int word_index(const Int& offset, const Int& texel) {
  return Format::kWords == 1 ? offset + texel : offset + (texel << 1);
}

/// Asks for the cache lines `words_below` words past the texels of lanes 0 and 2: the left end of
/// the stamp's two rows (simd.hpp's lane order).
LUXEL_INLINE void prefetch_below(const int32_t* words, const Int& index, int32_t words_below) {
  // In integers: the lines asked for may lie past the texture, which a hint may name but a
  // pointer may not.
  const auto at = [&](int lane) {
    return reinterpret_cast<const void*>(reinterpret_cast<uintptr_t>(words) +
                                         sizeof(int32_t) * static_cast<uintptr_t>(int64_t{index.get(lane)} + words_below));
  };
  simd::prefetch(at(0));
  simd::prefetch(at(2));
}

/// prefetch_below for a linear footprint's rows: the first two lines of each row's window, for its
/// first and second rows. A stamp row's window spans up to 32 words; where it starts mid-line its
/// third line is the first line of the next stamp's window, which that stamp's hint asks for.
LUXEL_INLINE void prefetch_windows_below(const int32_t* words, const Int& row0_first, const Int& row1_first,
                                         int32_t words_below) {
  for (const Int* first : {&row0_first, &row1_first}) {
    prefetch_below(words, *first, words_below);
    prefetch_below(words, *first, words_below + 16);
  }
}

/// Replaces the lanes of `t` outside the level with the border color.
template <class Format>
LUXEL_INLINE void apply_border(const Context<Format>& ctx, const IntMask& outside, TexelOf<Format>& t) {
  if (xsimd::any(outside)) t = select(float_mask(outside), ctx.border, t);
}

}  // namespace luxel::rasterizer::texture_sampling
