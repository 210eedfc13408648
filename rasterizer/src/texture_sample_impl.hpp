#pragma once
// Private to the texture module: the SIMD sampling path, as templates over the sampling rules
// (texture.hpp). Each rule set is compiled in its own translation unit (texture_sample.cpp: the
// hardware rules and the public entry points; texture_sample_ideal.cpp: the ideal rules), so the
// two compile in parallel. One stamp of simd::kLanes pixels per call.
//
// Per call: project cube directions / reduce coordinates (once), turn the LOD into one or two
// levels per lane, then per level: texel positions and addressing in integer lanes, one gather per
// footprint texel (both words of an 8-byte one: simd::gather_pairs; or, in the one-level reads of
// the post passes, windows along the stamp's rows: simd::gather_stamp_rows), decode, blend.
//
// A header per stage, each including the one before: texture_formats.hpp (the formats, their
// decode, the lane helpers and the filters' arithmetic), texture_addressing.hpp (the per-call
// state, level geometry, addressing and footprints), texture_filters.hpp (the 2D, volume and cube
// filters). This one: the levels a sample reads (the LOD's bias and clamps, the mip filter, the
// mag / min choice) and the dispatch of a rule set's entry points on the format, kind and filter.

#include "texture_filters.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <tuple>
#include <utility>

namespace luxel::rasterizer::texture_sampling {

// --- Levels and filters -----------------------------------------------------------------------

/// The coordinates after projection (cubes) or reduction (2D, volumes): what every level reads.
struct Prepared {
  Float u, v, w;
  CubeCoords cube;
};

template <class Format, TextureKind Kind>
LUXEL_INLINE TexelOf<Format> filter_level(const Context<Format>& ctx, const Level& g, Filter filter, const Prepared& p) {
  if constexpr (Kind == TextureKind::Cube) {
    return filter_cube<Format>(ctx, g, filter, p.cube);
  } else if constexpr (Kind == TextureKind::Volume) {
    return filter_volume<Format>(ctx, g, filter, p.u, p.v, p.w);
  } else {
    return filter_2d<Format>(ctx, g, filter, p.u, p.v);
  }
}

/// One level (`level`: an int for all lanes, or an Int per lane), with the mag filter on the
/// lanes `magnified` picks and the min filter on the others.
template <class Format, TextureKind Kind, class LevelIndex, class Magnified>
TexelOf<Format> filter_mip_level(const Context<Format>& ctx, const LevelIndex& level, const Magnified& magnified, const Prepared& p) {
  const Sampler& s = ctx.sampler;
  const Level g = level_geometry(ctx.texture, *ctx.storage.level_offsets, level);
  if (s.mag == s.min) return filter_level<Format, Kind>(ctx, g, s.mag, p);
  const FloatMask mask = magnified();
  const simd::LaneBits bits = simd::to_bits(mask);
  if (bits == simd::kAllLanes) return filter_level<Format, Kind>(ctx, g, s.mag, p);
  if (bits == 0) return filter_level<Format, Kind>(ctx, g, s.min, p);
  return select(mask, filter_level<Format, Kind>(ctx, g, s.mag, p), filter_level<Format, Kind>(ctx, g, s.min, p));
}

/// What every footprint of one call reads: the texture's storage and the border color.
template <class Format, TextureKind Kind>
LUXEL_INLINE Context<Format> context_of(const Texture& texture, const Sampler& s) {
  return {texture, s, TextureAccess::sampled(texture), Format::raw_border(s.border),
          Kind != TextureKind::Cube &&
              (s.u == Address::Border || s.v == Address::Border || (Kind == TextureKind::Volume && s.w == Address::Border))};
}

/// The coordinates projected onto cube faces or reduced to one period.
template <TextureKind Kind>
LUXEL_INLINE Prepared prepare(const Sampler& s, const TexCoord& coord) {
  Prepared p;
  if constexpr (Kind == TextureKind::Cube) {
    p.cube = project_to_faces(coord);
  } else {
    p.u = reduce(coord.x, s.u);
    p.v = reduce(coord.y, s.v);
    if constexpr (Kind == TextureKind::Volume) p.w = reduce(coord.z, s.w);
  }
  return p;
}

template <class Format, TextureKind Kind>
Float4 sample_level_impl(const Texture& texture, const Sampler& s, const TexCoord& coord,
                         const Float& lod_in) {
  const Context<Format> ctx = context_of<Format, Kind>(texture, s);
  const Prepared p = prepare<Kind>(s, coord);

  const Float zero(0.0f);
  Float lod = lod_in + Float(s.lod_bias);
  lod = xsimd::select(xsimd::isnan(lod), zero, lod);
  if constexpr (Format::kHardware) lod = to_eight_fraction_bits(lod);
  // Which lanes are magnified matters only to a sampler whose two filters differ.
  const auto magnified = [&] { return xsimd::min(xsimd::max(lod, Float(s.min_lod)), Float(s.max_lod)) <= zero; };
  // The level position: the LOD clamped to [min_lod, max_lod] and then to the texture's levels,
  // as one clamp to the clamped bounds (every later step waits for it). Non-negative, so the
  // conversions below truncate where they would floor.
  const float last = static_cast<float>(texture.mip_levels() - 1);
  const auto level_position = [&] {
    return xsimd::min(xsimd::max(lod, Float(std::clamp(s.min_lod, 0.0f, last))), Float(std::clamp(s.max_lod, 0.0f, last)));
  };

  TexelOf<Format> raw;
  switch (s.mip) {
    case MipFilter::None: raw = filter_mip_level<Format, Kind>(ctx, 0, magnified, p); break;
    case MipFilter::Point: raw = filter_mip_level<Format, Kind>(ctx, to_int(level_position() + Float(0.5f)), magnified, p); break;
    case MipFilter::Linear: {
      const Float l = level_position();
      const Int level = to_int(l);
      raw = filter_mip_level<Format, Kind>(ctx, level, magnified, p);
      const Float t = l - to_float(level);
      const FloatMask blended = t > zero;
      if (xsimd::any(blended)) {
        // The coarser level is fetched for every lane, blended or not: a lane on the last level
        // (t = 0) reads the last level again, not the one after it, which does not exist (for a
        // full chain of kMaxMipLevels not even as an entry of the level table).
        const Int coarser_level = xsimd::min(level + Int(1), Int(texture.mip_levels() - 1));
        const TexelOf<Format> coarser = filter_mip_level<Format, Kind>(ctx, coarser_level, magnified, p);
        raw = select(blended, blend<Format>(raw, coarser, t), raw);
      }
      break;
    }
  }
  return Format::finish(raw);
}

/// The context of a sampler with MipFilter::None and filter F on both sides of the crossover (the
/// post-processing passes', the color-correction volumes'): level 0 with one footprint at any LOD.
template <class Format, TextureKind Kind, Filter F>
LUXEL_INLINE Context<Format> one_level_context(const Texture& texture, const Sampler& s) {
  Context<Format> ctx = context_of<Format, Kind>(texture, s);
  // Within a tile, a read of a screen-aligned copy reads lower texel rows stamp row by stamp row.
  // A tile reads only a few lines of each texel row, each row in another page: too short a run for
  // the hardware prefetchers to follow, so without the hint every line is a miss the shader waits
  // for. Asked for four or eight texel rows below, the lines still came late (bench/README.md).
  constexpr int32_t kPrefetchRowsBelow = 16;
  if constexpr (Kind == TextureKind::Texture2D && F == Filter::Point) {
    // The post passes' point reads of the frame, a texel per pixel.
    ctx.prefetch_words_below = kPrefetchRowsBelow * Format::kWords * texture.width();
  }
  if constexpr (Kind == TextureKind::Texture2D && F == Filter::Linear && Format::kWords == 1) {
    // Bilinear reads of a level too large to stay in a core's cache from one pass to the next: the
    // bloom's downsample of the frame, four texels per pixel along each axis, each read once. The
    // quarter-size textures the blurs read thirteen times over stay cached, and the hints only cost
    // them (bench/README.md).
    constexpr int64_t kStreamedLevelBytes = int64_t(1) << 20;
    if (int64_t(texture.width()) * texture.height() * int64_t(sizeof(int32_t)) > kStreamedLevelBytes)
      ctx.prefetch_words_below = kPrefetchRowsBelow * texture.width();
  }
  // The same reads, and the color-correction volumes' (neighbouring pixels, neighbouring colors),
  // find a stamp row's texels within a few words of each other. The mip-mapped path does not try
  // the windows: its footprints turn with the surface and its stamps straddle levels, and the
  // check cost the 3D passes as much as the windows saved (bench/README.md). Cube maps
  // are read from their bordered copy, which keeps no padding for a window.
  if constexpr (Kind != TextureKind::Cube) ctx.reads_stamp_rows = true;
  if constexpr (Kind == TextureKind::Texture2D) ctx.skips_zero_weights = true;
  if constexpr (Kind == TextureKind::Volume && F == Filter::Linear) {
    if (s.u == Address::Clamp && s.v == Address::Clamp && s.w == Address::Clamp) {
      ctx.cells = ctx.storage.cells;
      ctx.cell_slice_words = 4 * (texture.width() + 1) * (texture.height() + 1);
    }
  }
  return ctx;
}

/// A read of such a sampler: the same texels and weights as sample_level_impl, in one function
/// with the filter known at compile time: none of the general path's per-call branches and calls.
template <class Format, TextureKind Kind, Filter F>
Float4 sample_one_level_impl(const Texture& texture, const Sampler& s, const TexCoord& coord) {
  const Context<Format> ctx = one_level_context<Format, Kind, F>(texture, s);
  const Level g = level_geometry(texture, *ctx.storage.level_offsets, 0);
  return Format::finish(filter_level<Format, Kind>(ctx, g, F, prepare<Kind>(s, coord)));
}

/// Several reads of such a sampler, each what sample_one_level_impl returns.
template <class Format, Filter F>
void sample_taps_impl(const Texture& texture, const Sampler& s, std::span<const TexCoord> coords, std::span<Float4> out) {
  constexpr TextureKind kKind = TextureKind::Texture2D;
  const Context<Format> ctx = one_level_context<Format, kKind, F>(texture, s);
  const Level g = level_geometry(texture, *ctx.storage.level_offsets, 0);
  for (size_t k = 0; k < coords.size(); ++k) out[k] = Format::finish(filter_level<Format, kKind>(ctx, g, F, prepare<kKind>(s, coords[k])));
}

// --- Entry points of one rule set -------------------------------------------------------------

/// The formats (TextureFormat order) as the ideal rules read them.
struct IdealRules {
  using Formats = std::tuple<Rgba8, Rgba8Srgb, Rgba16f, Rgba16, R32f>;
};
/// The formats as the hardware rules read them.
struct HardwareRules {
  using Formats = std::tuple<Hardware<Rgba8>, Rgba8SrgbAfterFiltering, Hardware<Rgba16f>, Hardware<Rgba16>, Hardware<R32f>>;
};

using SampleFn = Float4 (*)(const Texture&, const Sampler&, const TexCoord&, const Float&);
using OneLevelFn = Float4 (*)(const Texture&, const Sampler&, const TexCoord&);
using TapsFn = void (*)(const Texture&, const Sampler&, std::span<const TexCoord>, std::span<Float4>);

/// Whether a footprint of `sampler` on `texture` can read the border color: Address::Border on an
/// axis the texture has (cube maps ignore address modes).
inline bool reads_border(const Texture& texture, const Sampler& sampler) {
  if (texture.kind() == TextureKind::Cube) return false;
  return sampler.u == Address::Border || sampler.v == Address::Border ||
         (texture.kind() == TextureKind::Volume && sampler.w == Address::Border);
}

/// Whether `sampler` reads `texture` as Opaque: no border color can enter a footprint.
inline bool reads_opaque(const Texture& texture, const Sampler& sampler) {
  return texture.opaque() && !reads_border(texture, sampler);
}

/// The sampling functions of one rule set, dispatched on the texture and sampler.
template <class Rules>
struct Sampling {
  /// sample_level of a sampler that needs a LOD.
  static Float4 at_level(const Texture& texture, const Sampler& sampler, const TexCoord& coord, const Float& lod);
  /// sample of a sampler that reads one level with one filter (reads_one_level).
  static Float4 one_level(const Texture& texture, const Sampler& sampler, const TexCoord& coord);
  /// sample_taps of such a sampler, on a 2D texture.
  static void taps(const Texture& texture, const Sampler& sampler, std::span<const TexCoord> coords, std::span<Float4> out);
};

template <class Format>
constexpr std::array<SampleFn, 3> kinds_of() {
  return {&sample_level_impl<Format, TextureKind::Texture2D>, &sample_level_impl<Format, TextureKind::Cube>,
          &sample_level_impl<Format, TextureKind::Volume>};
}

// [filter][kind], in enum order.
template <class Format>
constexpr std::array<std::array<OneLevelFn, 3>, 2> one_level_of() {
  return {{{&sample_one_level_impl<Format, TextureKind::Texture2D, Filter::Point>,
            &sample_one_level_impl<Format, TextureKind::Cube, Filter::Point>,
            &sample_one_level_impl<Format, TextureKind::Volume, Filter::Point>},
           {&sample_one_level_impl<Format, TextureKind::Texture2D, Filter::Linear>,
            &sample_one_level_impl<Format, TextureKind::Cube, Filter::Linear>,
            &sample_one_level_impl<Format, TextureKind::Volume, Filter::Linear>}}};
}

// [filter], in enum order.
template <class Format>
constexpr std::array<TapsFn, 2> taps_of() {
  return {&sample_taps_impl<Format, Filter::Point>, &sample_taps_impl<Format, Filter::Linear>};
}

/// table_of(format) for every format of `Formats`, plain and Opaque: [opaque][format].
template <class Formats, template <class> class Of, size_t... I>
constexpr auto format_table(std::index_sequence<I...>) {
  using Entry = decltype(Of<std::tuple_element_t<0, Formats>>::value());
  return std::array<std::array<Entry, sizeof...(I)>, 2>{
      {{Of<std::tuple_element_t<I, Formats>>::value()...}, {Of<Opaque<std::tuple_element_t<I, Formats>>>::value()...}}};
}
template <class Format>
struct KindsOf {
  static constexpr auto value() { return kinds_of<Format>(); }
};
template <class Format>
struct OneLevelOf {
  static constexpr auto value() { return one_level_of<Format>(); }
};
template <class Format>
struct TapsOf {
  static constexpr auto value() { return taps_of<Format>(); }
};

template <class Rules>
Float4 Sampling<Rules>::at_level(const Texture& texture, const Sampler& sampler, const TexCoord& coord, const Float& lod) {
  // [opaque][format][kind]
  static constexpr auto kFns = format_table<typename Rules::Formats, KindsOf>(std::make_index_sequence<5>());
  const bool opaque = reads_opaque(texture, sampler);
  const int format = static_cast<int>(texture_detail::read_format(texture, sampler)), kind = static_cast<int>(texture.kind());
  return kFns[opaque][format][kind](texture, sampler, coord, lod);
}

template <class Rules>
Float4 Sampling<Rules>::one_level(const Texture& texture, const Sampler& sampler, const TexCoord& coord) {
  // [opaque][format][filter][kind]
  static constexpr auto kFns = format_table<typename Rules::Formats, OneLevelOf>(std::make_index_sequence<5>());
  const bool opaque = reads_opaque(texture, sampler);
  const int format = static_cast<int>(texture_detail::read_format(texture, sampler)), kind = static_cast<int>(texture.kind());
  return kFns[opaque][format][static_cast<int>(sampler.mag)][kind](texture, sampler, coord);
}

template <class Rules>
void Sampling<Rules>::taps(const Texture& texture, const Sampler& sampler, std::span<const TexCoord> coords,
                           std::span<Float4> out) {
  // [opaque][format][filter]
  static constexpr auto kFns = format_table<typename Rules::Formats, TapsOf>(std::make_index_sequence<5>());
  const bool opaque = reads_opaque(texture, sampler);
  const int format = static_cast<int>(texture_detail::read_format(texture, sampler));
  kFns[opaque][format][static_cast<int>(sampler.mag)](texture, sampler, coords, out);
}

extern template struct Sampling<IdealRules>;
extern template struct Sampling<HardwareRules>;

}  // namespace luxel::rasterizer::texture_sampling
