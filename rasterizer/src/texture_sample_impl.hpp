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
// Filtering happens in each format's "raw" domain (UNORM channels as 0..2^n-1 integers in float;
// sRGB decoded to linear under the ideal rules, the encoded bytes under the hardware rules) and
// the UNORM scale (or the hardware rules' sRGB decode) is applied once at the end, the scale
// rounded like a division so that a point sample of c is exactly c / (2^n - 1).
//
// A texture whose alpha is at its maximum everywhere (Texture::opaque) is read as Opaque<Format>:
// the color channels alone are filtered, and alpha is 1 (the same result, a quarter less work).
//
// Level geometry is taken per lane (levels differ between quads in trilinear stamps), with a fast
// case when the whole stamp reads one level. Cube maps are read from their bordered copy
// (Texture), where a footprint straddling a face's edge finds the texels across it in the border;
// only texels past a corner are computed here.

#include "luxel/rasterizer/texture.hpp"
#include "texture_internal.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>

namespace luxel::rasterizer::texture_sampling {

using simd::Float;
using simd::Float4;
using simd::Int;
using simd::kLanes;
using FloatMask = simd::FloatMask;
using IntMask = simd::IntMask;

// --- Small lane helpers -----------------------------------------------------------------------

LUXEL_INLINE Int to_int(const Float& x) { return xsimd::to_int(x); }  // truncates: floor for x >= 0
LUXEL_INLINE Float to_float(const Int& i) { return xsimd::to_float(i); }
LUXEL_INLINE FloatMask float_mask(const IntMask& m) { return xsimd::bool_cast(m); }
LUXEL_INLINE IntMask int_mask(const FloatMask& m) { return xsimd::bool_cast(m); }
LUXEL_INLINE Float lerp(const Float& a, const Float& b, const Float& t) {
  return simd::fma(t, b - a, a);
}
LUXEL_INLINE Float4 lerp(const Float4& a, const Float4& b, const Float& t) {
  return {lerp(a.x, b.x, t), lerp(a.y, b.y, t), lerp(a.z, b.z, t), lerp(a.w, b.w, t)};
}
LUXEL_INLINE Float4 select(const FloatMask& m, const Float4& a, const Float4& b) {
  return {xsimd::select(m, a.x, b.x), xsimd::select(m, a.y, b.y), xsimd::select(m, a.z, b.z),
          xsimd::select(m, a.w, b.w)};
}
/// The texels of an opaque texture as filtered: alpha is left out (see Opaque below).
struct Float3 {
  Float x, y, z;
};
LUXEL_INLINE Float3 lerp(const Float3& a, const Float3& b, const Float& t) {
  return {lerp(a.x, b.x, t), lerp(a.y, b.y, t), lerp(a.z, b.z, t)};
}
LUXEL_INLINE Float3 select(const FloatMask& m, const Float3& a, const Float3& b) {
  return {xsimd::select(m, a.x, b.x), xsimd::select(m, a.y, b.y), xsimd::select(m, a.z, b.z)};
}
/// The mean of three texels: a texel past a cube corner.
LUXEL_INLINE Float4 mean(const Float4& a, const Float4& b, const Float4& d) {
  const Float third(3.0f);
  return {(a.x + b.x + d.x) / third, (a.y + b.y + d.y) / third, (a.z + b.z + d.z) / third, (a.w + b.w + d.w) / third};
}
LUXEL_INLINE Float3 mean(const Float3& a, const Float3& b, const Float3& d) {
  const Float third(3.0f);
  return {(a.x + b.x + d.x) / third, (a.y + b.y + d.y) / third, (a.z + b.z + d.z) / third};
}
LUXEL_INLINE Float4 broadcast(const glm::vec4& v) {
  return {Float(v.x), Float(v.y), Float(v.z), Float(v.w)};
}

/// x / d, correctly rounded like a division, for the UNORM scales d = 255 and 65535: a product by
/// the rounded reciprocal and one Markstein correction step (e = x - q d is exact with an FMA).
/// Checked equal to x / d for every integer and 10^7 random x in [0, d]; a third of a divide's cost.
template <int kDivisor>
LUXEL_INLINE Float divide_by(const Float& x) {
  const Float d(static_cast<float>(kDivisor)), r(1.0f / static_cast<float>(kDivisor));
  const Float q = x * r;
  return simd::fma(simd::fnma(q, d, x), r, q);
}

/// 32-bit words at base[index[l]].
LUXEL_INLINE Int gather(const int32_t* base, const Int& index) {
#if defined(__SANITIZE_ADDRESS__)
  // Hardware gathers are invisible to AddressSanitizer; scalar loads let it check every read.
  alignas(64) int32_t i[kLanes], out[kLanes];
  index.store_aligned(i);
  for (int l = 0; l < kLanes; ++l) out[l] = base[i[l]];
  return Int::load_aligned(out);
#else
  return simd::gather(base, index);
#endif
}

/// base[index[l]], read as windows along the stamp's rows where the indices allow it
/// (simd::gather_stamp_rows), gathered where they do not.
LUXEL_INLINE Int gather_stamp_rows(const int32_t* base, const Int& index) {
  Int words;
  if (simd::gather_stamp_rows(base, index, words)) return words;
  return gather(base, index);
}

/// The 8-byte texels at base[index[l]] and base[index[l] + 1]: the low words into `low`, the high
/// ones into `high`.
LUXEL_INLINE void gather_pairs(const int32_t* base, const Int& index, Int& low, Int& high) {
#if defined(__SANITIZE_ADDRESS__)
  low = gather(base, index);
  high = gather(base, index + Int(1));
#else
  simd::gather_pairs(base, index, low, high);
#endif
}

/// log2(x) for the LOD: for normal x > 0 within 1e-7 plus the float rounding of the result
/// (exponent plus a degree-8 polynomial in the mantissa around 1, interpolating at Chebyshev
/// nodes), -inf for 0, x itself for +inf and NaN. No division and no branch, unlike xsimd::log2;
/// D3D11 asks for only 8 bits of LOD fraction (D3D11_MIP_LOD_FRACTIONAL_BIT_COUNT).
LUXEL_INLINE Float lod_log2(const Float& x) {
  const Int bits = xsimd::bitwise_cast<Int>(x);
  Float m = xsimd::bitwise_cast<Float>((bits & Int(0x007fffff)) | Int(0x3f800000));  // [1, 2)
  const FloatMask high = m > Float(1.41421356f);  // -> [sqrt(1/2), sqrt(2)), where p is fitted
  m = xsimd::select(high, m * Float(0.5f), m);
  const Float e = to_float((bits >> 23) - Int(127) + xsimd::select(int_mask(high), Int(1), Int(0)));
  const Float t = m - Float(1.0f);
  // log2(1 + t) = t q(t), q evaluated by Estrin's scheme: four independent pairs, then two
  // levels of combination, so the LOD, which every later step of a sample waits for, is ready
  // after 4 dependent FMAs instead of 8.
  const Float t2 = t * t;
  const Float p01 = simd::fma(Float(-0.7213529313629768f), t, Float(1.4426949948930465f));
  const Float p23 = simd::fma(Float(-0.3602251824607909f), t, Float(0.4809167080001651f));
  const Float p45 = simd::fma(Float(-0.2492718220796073f), t, Float(0.2872888823759086f));
  const Float p67 = simd::fma(Float(-0.14275973432660397f), t, Float(0.232652578806726f));
  const Float t4 = t2 * t2;
  const Float q = simd::fma(simd::fma(p67, t2, p45), t4, simd::fma(p23, t2, p01));
  Float r = simd::fma(q, t, e);
  const Float infinity(std::numeric_limits<float>::infinity());
  r = xsimd::select(x == Float(0.0f), -infinity, r);
  return xsimd::select(x < infinity, r, x);  // +inf and NaN pass through
}

// --- Formats ----------------------------------------------------------------------------------
// Each format: kWords per texel, fetch() to the raw domain, the border color in that domain, and
// finish() from raw to the returned linear RGBA. A one-word format's fetch is decode() of the
// gathered word. kNonNegative: every texel decodes to a finite value >= +0 in the raw domain.
// The formats below follow the ideal rules (SamplingRules::ideal); Hardware<Format> and
// Rgba8SrgbAfterFiltering read them by the hardware rules. kHardware: weights and the LOD
// fraction are quantized; kFixedPoint: the raw values are 8-bit integers and every filtering
// step truncates to an integer (texture.hpp, "Sampling rules").

/// What every format of the ideal rules shares.
struct IdealFormat {
  static constexpr bool kHardware = false;
  static constexpr bool kFixedPoint = false;
};

struct Rgba8 : IdealFormat {
  static constexpr bool kNonNegative = true;
  static constexpr int kWords = 1;
  LUXEL_INLINE static Float4 fetch(const int32_t* words, const Int& index) { return decode(gather(words, index)); }
  LUXEL_INLINE static Float4 decode(const Int& w) {
    return {to_float(simd::byte_of<0>(w)), to_float(simd::byte_of<1>(w)), to_float(simd::byte_of<2>(w)),
            to_float(simd::byte_of<3>(w))};
  }
  static Float4 raw_border(const glm::vec4& b) { return broadcast(b * 255.0f); }
  LUXEL_INLINE static Float4 finish(const Float4& raw) {
    return {divide_by<255>(raw.x), divide_by<255>(raw.y), divide_by<255>(raw.z), divide_by<255>(raw.w)};
  }
};

/// kSrgbToLinear as lookup_bytes3 reads it.
inline constexpr simd::ByteTable kSrgbBytes = simd::byte_table(kSrgbToLinear);

struct Rgba8Srgb : IdealFormat {
  static constexpr bool kNonNegative = true;
  static constexpr int kWords = 1;
  LUXEL_INLINE static Float4 fetch(const int32_t* words, const Int& index) { return decode(gather(words, index)); }
  LUXEL_INLINE static Float4 decode(const Int& w) {
    Float4 t;
    simd::lookup_bytes3(kSrgbBytes, w, t.x, t.y, t.z);
    t.w = to_float(simd::byte_of<3>(w));
    return t;
  }
  static Float4 raw_border(const glm::vec4& b) { return broadcast({b.x, b.y, b.z, b.w * 255.0f}); }
  LUXEL_INLINE static Float4 finish(const Float4& raw) { return {raw.x, raw.y, raw.z, divide_by<255>(raw.w)}; }
};

struct Rgba16f : IdealFormat {
  static constexpr bool kNonNegative = false;
  static constexpr int kWords = 2;
  LUXEL_INLINE static Float4 fetch(const int32_t* words, const Int& index) {
    Int rg, ba;
    gather_pairs(words, index, rg, ba);
    Float4 t;
    simd::unpack_halves(rg, t.x, t.y);
    simd::unpack_halves(ba, t.z, t.w);
    return t;
  }
  static Float4 raw_border(const glm::vec4& b) { return broadcast(b); }
  LUXEL_INLINE static Float4 finish(const Float4& raw) { return raw; }
};

struct Rgba16 : IdealFormat {
  static constexpr bool kNonNegative = true;
  static constexpr int kWords = 2;
  LUXEL_INLINE static Float4 fetch(const int32_t* words, const Int& index) {
    Int rg, ba;
    gather_pairs(words, index, rg, ba);
    const Int low(0xffff);
    return {to_float(rg & low), to_float((rg >> 16) & low), to_float(ba & low), to_float((ba >> 16) & low)};
  }
  static Float4 raw_border(const glm::vec4& b) { return broadcast(b * 65535.0f); }
  LUXEL_INLINE static Float4 finish(const Float4& raw) {
    return {divide_by<65535>(raw.x), divide_by<65535>(raw.y), divide_by<65535>(raw.z),
            divide_by<65535>(raw.w)};
  }
};

struct R32f : IdealFormat {
  static constexpr bool kNonNegative = false;
  static constexpr int kWords = 1;
  LUXEL_INLINE static Float4 fetch(const int32_t* words, const Int& index) { return decode(gather(words, index)); }
  LUXEL_INLINE static Float4 decode(const Int& w) {
    const Float one(1.0f);
    return {xsimd::bitwise_cast<Float>(w), one, one, one};
  }
  static Float4 raw_border(const glm::vec4& b) { return broadcast(b); }
  LUXEL_INLINE static Float4 finish(const Float4& raw) { return raw; }
};

/// `Format` read by the hardware rules: quantized weights and LOD fraction; an 8-bit UNORM format
/// filtered in fixed point, its border color rounded to the format's steps (the filter blends
/// integers).
template <class Format>
struct Hardware : Format {
  static constexpr bool kHardware = true;
  static constexpr bool kFixedPoint = std::is_same_v<Format, Rgba8>;
  static auto raw_border(const glm::vec4& b) {
    if constexpr (kFixedPoint) {
      auto step = [](float c) { return std::round(std::clamp(c, 0.0f, 1.0f) * 255.0f); };
      return broadcast({step(b.x), step(b.y), step(b.z), step(b.w)});
    } else {
      return Format::raw_border(b);
    }
  }
};

/// An sRGB read by the hardware rules: the encoded bytes are filtered in fixed point, as RGBA8's,
/// and the filtered byte is decoded (DX9-era texture units converted after filtering).
struct Rgba8SrgbAfterFiltering : Hardware<Rgba8> {
  static Float4 raw_border(const glm::vec4& b) {
    auto encode = [](float c) { return std::round(float(linear_to_srgb(std::clamp(c, 0.0f, 1.0f))) * 255.0f); };
    return broadcast({encode(b.x), encode(b.y), encode(b.z), std::round(std::clamp(b.w, 0.0f, 1.0f) * 255.0f)});
  }
  LUXEL_INLINE static Float4 finish(const Float4& raw) {
    const Int bytes = to_int(raw.x) | (to_int(raw.y) << 8) | (to_int(raw.z) << 16);
    Float4 t;
    simd::lookup_bytes3(kSrgbBytes, bytes, t.x, t.y, t.z);
    t.w = divide_by<255>(raw.w);
    return t;
  }
};

/// A texture of `Format` whose alpha is at its maximum everywhere (Texture::opaque), read with no
/// border color: the color channels are filtered alone and alpha is 1, which is what filtering the
/// constant alpha gives exactly (lerps of equal values, the mean of three equal values, max / max).
/// The format's own fetch and finish are used; inlined, the work on the alpha they drop goes.
template <class Format>
struct Opaque {
  static constexpr bool kNonNegative = Format::kNonNegative;
  static constexpr int kWords = Format::kWords;
  static constexpr bool kHardware = Format::kHardware;
  static constexpr bool kFixedPoint = Format::kFixedPoint;
  LUXEL_INLINE static Float3 fetch(const int32_t* words, const Int& index) {
    const Float4 t = Format::fetch(words, index);
    return {t.x, t.y, t.z};
  }
  LUXEL_INLINE static Float3 decode(const Int& w)
    requires(kWords == 1)
  {
    const Float4 t = Format::decode(w);
    return {t.x, t.y, t.z};
  }
  static Float3 raw_border(const glm::vec4& b) {
    const Float4 raw = Format::raw_border(b);
    return {raw.x, raw.y, raw.z};
  }
  LUXEL_INLINE static Float4 finish(const Float3& raw) {
    const Float4 done = Format::finish({raw.x, raw.y, raw.z, Float(0.0f)});
    return {done.x, done.y, done.z, Float(1.0f)};
  }
};

/// What the filters carry for `Format`: Float4, or Float3 for an Opaque one.
template <class Format>
struct TexelType {
  using type = Float4;
};
template <class Format>
struct TexelType<Opaque<Format>> {
  using type = Float3;
};
template <class Format>
using TexelOf = typename TexelType<Format>::type;

// --- Filter arithmetic ------------------------------------------------------------------------

/// x rounded to 8 fractional bits (to nearest, ties to even): a float converted to fixed point.
LUXEL_INLINE Float to_eight_fraction_bits(const Float& x) {
  return xsimd::nearbyint(x * Float(256.0f)) * Float(1.0f / 256.0f);
}

/// a + t (b - a): in fixed point, rounded to an integer (a + floor(w (b - a) / 256 + 1/2) for the
/// 8-bit weight w = 256 t: exact in float, a's and b's integers and w (b - a) / 256 needing at
/// most 16 bits), or in float.
template <class Format>
LUXEL_INLINE Float blend(const Float& a, const Float& b, const Float& t) {
  if constexpr (Format::kFixedPoint) return xsimd::floor(simd::fma(t, b - a, a + Float(0.5f)));
  return lerp(a, b, t);
}
template <class Format>
LUXEL_INLINE Float4 blend(const Float4& a, const Float4& b, const Float& t) {
  return {blend<Format>(a.x, b.x, t), blend<Format>(a.y, b.y, t), blend<Format>(a.z, b.z, t), blend<Format>(a.w, b.w, t)};
}
template <class Format>
LUXEL_INLINE Float3 blend(const Float3& a, const Float3& b, const Float& t) {
  return {blend<Format>(a.x, b.x, t), blend<Format>(a.y, b.y, t), blend<Format>(a.z, b.z, t)};
}

/// A texel past a cube corner: the mean of the footprint's other three (in fixed point, rounded
/// to an integer, halves up).
template <class Format, class Texel>
LUXEL_INLINE Texel corner_mean(const Texel& a, const Texel& b, const Texel& d) {
  Texel m = mean(a, b, d);
  if constexpr (Format::kFixedPoint) {
    const Float half(0.5f);
    m.x = xsimd::floor(m.x + half), m.y = xsimd::floor(m.y + half), m.z = xsimd::floor(m.z + half);
    if constexpr (std::is_same_v<Texel, Float4>) m.w = xsimd::floor(m.w + half);
  }
  return m;
}

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

// --- 2D and volume ----------------------------------------------------------------------------

template <class Format>
LUXEL_INLINE TexelOf<Format> filter_2d(const Context<Format>& ctx, const Level& g, Filter filter, const Float& u, const Float& v) {
  const Sampler& s = ctx.sampler;
  if (filter == Filter::Point) {
    IntMask out_x = simd::no_lanes(), out_y = simd::no_lanes();
    const Int i = point_axis(u, g.width, g.fwidth, s.u, out_x);
    const Int j = point_axis(v, g.height, g.fheight, s.v, out_y);
    const Int index = word_index<Format>(g.offset, row_start(j, g.width) + i);
    if (ctx.prefetch_words_below != 0) prefetch_below(ctx.storage.words, index, ctx.prefetch_words_below);
    TexelOf<Format> t = fetch(ctx, index);
    if (ctx.any_border) apply_border(ctx, out_x | out_y, t);
    return t;
  }
  const LinearAxis x = linear_axis<Format>(u, g.width, g.fwidth, s.u);
  const LinearAxis y = linear_axis<Format>(v, g.height, g.fheight, s.v);
  const Int row0 = row_start(y.i0, g.width), row1 = row_start(y.i1, g.width);
  if (ctx.prefetch_words_below != 0) {
    prefetch_windows_below(ctx.storage.words, word_index<Format>(g.offset, row0 + x.i0), word_index<Format>(g.offset, row1 + x.i0),
                           ctx.prefetch_words_below);
  }
  const auto texel = [&](const Int& row, const Int& column) LUXEL_INLINE_LAMBDA {
    return fetch(ctx, word_index<Format>(g.offset, row + column));
  };
  TexelOf<Format> t00 = texel(row0, x.i0);
  if constexpr (Format::kNonNegative) {
    // A post pass's blur taps along one axis and samples the other at texel centers, where the
    // weight is 0 wherever the coordinate's float rounding is exact: then the lerp along that axis
    // returns its first texel to the bit (fma(0, b - a, a) = a for finite b - a and a >= +0, and
    // the first lerps' results lie between their texels), so its second texels need not be read.
    if (ctx.skips_zero_weights && !ctx.any_border) {
      if (xsimd::all(y.weight == Float(0.0f))) return blend<Format>(t00, texel(row0, x.i1), x.weight);
      if (xsimd::all(x.weight == Float(0.0f))) return blend<Format>(t00, texel(row1, x.i0), y.weight);
    }
  }
  TexelOf<Format> t10 = texel(row0, x.i1);
  TexelOf<Format> t01 = texel(row1, x.i0);
  TexelOf<Format> t11 = texel(row1, x.i1);
  if (ctx.any_border) {
    apply_border(ctx, x.outside0 | y.outside0, t00);
    apply_border(ctx, x.outside1 | y.outside0, t10);
    apply_border(ctx, x.outside0 | y.outside1, t01);
    apply_border(ctx, x.outside1 | y.outside1, t11);
  }
  return blend<Format>(blend<Format>(t00, t10, x.weight), blend<Format>(t01, t11, x.weight), y.weight);
}

/// A trilinear footprint under Clamp read from the volume's cells (Texture::cell_words_): the
/// texels and weights filter_volume's own footprint reads, and its lerps in its order, so the same
/// result to the bit, from two loads per lane instead of eight gathers.
template <class Format>
LUXEL_INLINE TexelOf<Format> filter_volume_cells(const Context<Format>& ctx, const Level& g, const Float& u, const Float& v,
                                                 const Float& w) {
  // A footprint's start clamped to [-1, n - 1] names the cell of the two texels Clamp reads, plus
  // one: cells start at -1.
  const auto cell_axis = [](const Float& c, const Int& n, const Float& fn, Float& weight) {
    return xsimd::min(xsimd::max(footprint_start<Format>(c, fn, weight), Int(-1)), n - Int(1)) + Int(1);
  };
  Float wx, wy, wz;
  const Int i = cell_axis(u, g.width, g.fwidth, wx), j = cell_axis(v, g.height, g.fheight, wy);
  const Int k = cell_axis(w, g.depth, g.fdepth, wz);
  const Int one(1);
  const Int square = (k * (g.height + one) + j) * (g.width + one) + i;
  Int words[8];
  const int32_t first = square.get(0);
  if (xsimd::all(square == Int(first))) {
    // Every lane's footprint in one cell (a flat patch of the frame, where neighbouring pixels'
    // colors differ by less than a LUT texel): its eight words read once for all lanes, the
    // same words the gathers would bring each.
    const int32_t* cell = ctx.cells + 4 * first;
    for (int c = 0; c < 4; ++c) {
      words[c] = Int(cell[c]);
      words[c + 4] = Int(cell[ctx.cell_slice_words + c]);
    }
  } else {
    simd::gather_two_fours(ctx.cells, square << 2, ctx.cell_slice_words, words);
  }
  TexelOf<Format> t[8];
  for (int c = 0; c < 8; ++c) t[c] = Format::decode(words[c]);
  return blend<Format>(blend<Format>(blend<Format>(t[0], t[1], wx), blend<Format>(t[2], t[3], wx), wy), blend<Format>(blend<Format>(t[4], t[5], wx), blend<Format>(t[6], t[7], wx), wy), wz);
}

template <class Format>
LUXEL_INLINE TexelOf<Format> filter_volume(const Context<Format>& ctx, const Level& g, Filter filter, const Float& u,
                                           const Float& v, const Float& w) {
  const Sampler& s = ctx.sampler;
  const Int slice = g.width * g.height;
  if (filter == Filter::Point) {
    IntMask out_x = simd::no_lanes(), out_y = simd::no_lanes(), out_z = simd::no_lanes();
    const Int i = point_axis(u, g.width, g.fwidth, s.u, out_x);
    const Int j = point_axis(v, g.height, g.fheight, s.v, out_y);
    const Int k = point_axis(w, g.depth, g.fdepth, s.w, out_z);
    TexelOf<Format> t = fetch(ctx, word_index<Format>(g.offset, k * slice + row_start(j, g.width) + i));
    if (ctx.any_border) apply_border(ctx, out_x | out_y | out_z, t);
    return t;
  }
  if constexpr (Format::kWords == 1) {
    if (ctx.cells) return filter_volume_cells<Format>(ctx, g, u, v, w);
  }
  const LinearAxis x = linear_axis<Format>(u, g.width, g.fwidth, s.u);
  const LinearAxis y = linear_axis<Format>(v, g.height, g.fheight, s.v);
  const LinearAxis z = linear_axis<Format>(w, g.depth, g.fdepth, s.w);
  auto filter_slice = [&](const Int& k, const IntMask& out_z) LUXEL_INLINE_LAMBDA {
    const Int plane = k * slice;
    const Int row0 = plane + row_start(y.i0, g.width), row1 = plane + row_start(y.i1, g.width);
    TexelOf<Format> t00 = fetch(ctx, word_index<Format>(g.offset, row0 + x.i0));
    TexelOf<Format> t10 = fetch(ctx, word_index<Format>(g.offset, row0 + x.i1));
    TexelOf<Format> t01 = fetch(ctx, word_index<Format>(g.offset, row1 + x.i0));
    TexelOf<Format> t11 = fetch(ctx, word_index<Format>(g.offset, row1 + x.i1));
    if (ctx.any_border) {
      apply_border(ctx, x.outside0 | y.outside0 | out_z, t00);
      apply_border(ctx, x.outside1 | y.outside0 | out_z, t10);
      apply_border(ctx, x.outside0 | y.outside1 | out_z, t01);
      apply_border(ctx, x.outside1 | y.outside1 | out_z, t11);
    }
    return blend<Format>(blend<Format>(t00, t10, x.weight), blend<Format>(t01, t11, x.weight), y.weight);
  };
  return blend<Format>(filter_slice(z.i0, z.outside0), filter_slice(z.i1, z.outside1), z.weight);
}

// --- Cube maps --------------------------------------------------------------------------------

/// Per-lane face, u, v of cube directions (see texture.hpp for the rules).
struct CubeCoords {
  Int face;
  Float u, v;
};

LUXEL_INLINE CubeCoords project_to_faces(const TexCoord& d) {
  const Float ax = xsimd::abs(d.x), ay = xsimd::abs(d.y), az = xsimd::abs(d.z);
  const FloatMask on_z = (az >= ax) & (az >= ay);
  const FloatMask on_y = (!on_z) & (ay >= ax);
  const Float ma = xsimd::select(on_z, d.z, xsimd::select(on_y, d.y, d.x));
  const FloatMask negative = ma < Float(0.0f);
  // (sc, tc): +X (-z, -y), -X (z, -y), +Y (x, z), -Y (x, -z), +Z (x, -y), -Z (-x, -y).
  const Float sign = xsimd::select(negative, Float(-1.0f), Float(1.0f));
  const Float sc = xsimd::select(on_z, sign * d.x, xsimd::select(on_y, d.x, -(sign * d.z)));
  const Float tc = xsimd::select(on_y, sign * d.z, -d.y);
  const Float m = xsimd::abs(ma);
  Float s = sc / m, t = tc / m;
  const Float zero(0.0f), one(1.0f), half(0.5f);
  // NaN -> the face's center; clamped, as a NaN component can make |ma| not the largest.
  s = xsimd::min(xsimd::max(xsimd::select(xsimd::isnan(s), zero, s), -one), one);
  t = xsimd::min(xsimd::max(xsimd::select(xsimd::isnan(t), zero, t), -one), one);
  CubeCoords c;
  const Int axis = xsimd::select(int_mask(on_z), Int(2), xsimd::select(int_mask(on_y), Int(1), Int(0)));
  c.face = axis + axis + xsimd::select(int_mask(negative), Int(1), Int(0));
  c.u = (s + one) * half;
  c.v = (t + one) * half;
  return c;
}

template <class Format>
LUXEL_INLINE TexelOf<Format> filter_cube(const Context<Format>& ctx, const Level& g, Filter filter, const CubeCoords& c) {
  // The sampling copy (Texture): face levels n texels wide are stored n + 2 wide, texel (i, j) of
  // the face at (i + 1, j + 1), bordered by the texels across its edges. g.offset is the level's
  // offset in that copy.
  const Int face_offset = c.face * Int(ctx.storage.face_words) + g.offset;
  const Int one(1), stride = g.width + Int(2), last = g.width - one;
  if (filter == Filter::Point) {
    const Int i = xsimd::min(to_int(xsimd::floor(c.u * g.fwidth)), last) + one;
    const Int j = xsimd::min(to_int(xsimd::floor(c.v * g.fwidth)), last) + one;
    return Format::fetch(ctx.storage.words, word_index<Format>(face_offset, row_start(j, stride) + i));
  }
  // u and v lie in [0, 1] (project_to_faces), so i0 and j0 lie in [-1, n - 1]: within the border.
  Float wx, wy;
  const Int i0 = footprint_start<Format>(c.u, g.fwidth, wx), j0 = footprint_start<Format>(c.v, g.fwidth, wy);
  // Slots 0..3: texels (i0, j0), (i1, j0), (i0, j1), (i1, j1).
  const Int row0 = row_start(j0 + one, stride) + i0 + one, row1 = row0 + stride;
  const Int index[4] = {word_index<Format>(face_offset, row0), word_index<Format>(face_offset, row0 + one),
                        word_index<Format>(face_offset, row1), word_index<Format>(face_offset, row1 + one)};
  TexelOf<Format> t[4];
  for (int k = 0; k < 4; ++k) t[k] = Format::fetch(ctx.storage.words, index[k]);
  // A texel past a cube corner (past two edges) is the mean of the footprint's other three.
  const Int zero(0);
  const IntMask before_i = i0 < zero, after_i = i0 >= last, before_j = j0 < zero, after_j = j0 >= last;
  const IntMask corner[4] = {before_i & before_j, after_i & before_j, before_i & after_j, after_i & after_j};
  if (xsimd::any(corner[0] | corner[1] | corner[2] | corner[3])) {
    TexelOf<Format> fixed[4];
    for (int k = 0; k < 4; ++k) fixed[k] = corner_mean<Format>(t[k ^ 1], t[k ^ 2], t[k ^ 3]);
    for (int k = 0; k < 4; ++k) t[k] = select(float_mask(corner[k]), fixed[k], t[k]);
  }
  return blend<Format>(blend<Format>(t[0], t[1], wx), blend<Format>(t[2], t[3], wx), wy);
}

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
