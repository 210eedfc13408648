#pragma once
// Private to the texture module: the texel formats the SIMD sampling path reads
// (texture_sample_impl.hpp), with the small lane helpers every stage of it shares and the
// filters' arithmetic (the blend of two texels, in float or in fixed point).
//
// Filtering happens in each format's "raw" domain (UNORM channels as 0..2^n-1 integers in float;
// sRGB decoded to linear under the ideal rules, the encoded bytes under the hardware rules) and
// the UNORM scale (or the hardware rules' sRGB decode) is applied once at the end, the scale
// rounded like a division so that a point sample of c is exactly c / (2^n - 1).
//
// A texture whose alpha is at its maximum everywhere (Texture::opaque) is read as Opaque<Format>:
// the color channels alone are filtered, and alpha is 1 (the same result, a quarter less work).

#include "luxel/rasterizer/texture.hpp"
#include "texture_internal.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
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

}  // namespace luxel::rasterizer::texture_sampling
