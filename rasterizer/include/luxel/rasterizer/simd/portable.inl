#pragma once
// The lane operations of simd.hpp written with xsimd's portable operations and plain loops: what
// an x86-64-v2 build (SSE4.2, 4 lanes, a stamp of 2x2 pixels) and any target without AVX2 run.
// Included by simd.hpp alone. Each operation gives the bits the AVX2 and AVX-512 files give.

namespace luxel::rasterizer::simd {

inline constexpr const char* kIsaName =
#if defined(__SSE4_2__)
    "sse4.2";
#else
    "portable";
#endif
inline constexpr int kStampRowWindowWords = 0;

inline void store_stamp_rows(const Int& row_major, void* top, void* bottom) {
  alignas(64) int32_t v[kLanes];
  row_major.store_aligned(v);
  __builtin_memcpy(top, v, sizeof(int32_t) * kStampWidth);
  __builtin_memcpy(bottom, v + kStampWidth, sizeof(int32_t) * kStampWidth);
}

template <class T>
inline LaneBits to_bits(const xsimd::batch_bool<T, Arch>& m) {
  alignas(64) bool b[xsimd::batch_bool<T, Arch>::size];
  m.store_aligned(b);
  LaneBits bits = 0;
  for (std::size_t i = 0; i < xsimd::batch_bool<T, Arch>::size; ++i) bits |= LaneBits(b[i]) << i;
  return bits;
}
inline LaneBits to_bits(const xsimd::batch_bool<double, Arch>& low, const xsimd::batch_bool<double, Arch>& high) {
  alignas(64) bool lo[Double::size], hi[Double::size];
  low.store_aligned(lo);
  high.store_aligned(hi);
  LaneBits bits = 0;
  for (std::size_t i = 0; i < Double::size; ++i) bits |= LaneBits(lo[i]) << i | LaneBits(hi[i]) << (i + Double::size);
  return bits;
}

inline IntMask no_lanes() { return IntMask(false); }

inline LaneBits sign_bits(const Int& v) { return to_bits(v < Int(0)); }
template <class V>
  requires(std::is_same_v<V, Int4> && !std::is_same_v<Int4, Int>)
inline LaneBits sign_bits(const V& v) {
  LaneBits bits = 0;
  for (int i = 0; i < 4; ++i) bits |= LaneBits(v.get(i) < 0) << i;
  return bits;
}

template <int Lane>
inline Int broadcast_lane(const Int4& v) {
  static_assert(Lane >= 0 && Lane < 4);
  return Int(v.get(Lane));
}

inline Int mask_of(const FloatMask& m) {
  return xsimd::bitwise_cast<Int>(xsimd::select(m, xsimd::bitwise_cast<Float>(Int(-1)), Float(0.0f)));
}
inline Int mask_of(const IntMask& m) { return xsimd::select(m, Int(-1), Int(0)); }
inline Float select(const Int& mask, const Float& a, const Float& b) {
  // xsimd selects floats by a float mask: the integer lanes go through as bits.
  return xsimd::bitwise_cast<Float>(xsimd::select(mask != Int(0), xsimd::bitwise_cast<Int>(a), xsimd::bitwise_cast<Int>(b)));
}
inline Int select(const Int& mask, const Int& a, const Int& b) { return xsimd::select(mask != Int(0), a, b); }

inline Int load_bytes(const uint8_t* p) {
  alignas(64) int32_t v[kLanes];
  for (int i = 0; i < kLanes; ++i) v[i] = p[i];
  return Int::load_aligned(v);
}
inline void store_bytes(uint8_t* p, const Int& v) {
  alignas(64) int32_t v2[kLanes];
  v.store_aligned(v2);
  for (int i = 0; i < kLanes; ++i) p[i] = static_cast<uint8_t>(v2[i]);
}

template <int kByte>
inline Int byte_of(const Int& v) {
  static_assert(kByte >= 0 && kByte < 4);
  if constexpr (kByte == 0) return v & Int(0xff);
  else return (v >> (8 * kByte)) & Int(0xff);
}

inline Int gather(const int32_t* base, const Int& index) { return Int::gather(base, index); }
inline Float gather(const float* base, const Int& index) { return Float::gather(base, index); }

inline void gather_pairs(const int32_t* base, const Int& index, Int& low, Int& high) {
  detail::gather_pairs_by_words(base, index, low, high);
}

inline Float lookup_byte(const float* table, const Int& index) { return gather(table, index); }

inline void lookup_bytes3(const ByteTable& table, const Int& words, Float& b0, Float& b1, Float& b2) {
  detail::lookup_bytes3_by_byte(table, words, b0, b1, b2);
}

/// No windows: every read is a gather.
inline bool gather_stamp_rows(const int32_t* base, const Int& index, Int& out) {
  (void)base, (void)index, (void)out;
  return false;
}

inline void gather_two_fours(const int32_t* base, const Int& index, int32_t second, Int (&words)[8]) {
  for (int k = 0; k < 4; ++k) {
    words[k] = gather(base, index + Int(k));
    words[k + 4] = gather(base, index + Int(second + k));
  }
}

inline void unpack_halves(const Int& packed, Float& low, Float& high) {
  alignas(64) int32_t p[kLanes];
  alignas(64) float lo[kLanes], hi[kLanes];
  packed.store_aligned(p);
  auto decode = [](uint32_t h) {
    const uint32_t sign = (h & 0x8000u) << 16, em = h & 0x7fffu;
    uint32_t bits;
    if (em >= 0x7c00u) {
      bits = 0x7f800000u | ((em & 0x3ffu) << 13);  // inf / NaN
    } else if (em >= 0x400u) {
      bits = (em << 13) + 0x38000000u;  // normal: rebias the exponent
    } else {
      const float denormal = static_cast<float>(em) * 5.9604644775390625e-8f;  // em * 2^-24, a normal float
      bits = __builtin_bit_cast(uint32_t, denormal);
    }
    return __builtin_bit_cast(float, bits | sign);
  };
  for (int i = 0; i < kLanes; ++i) {
    lo[i] = decode(static_cast<uint32_t>(p[i]) & 0xffffu);
    hi[i] = decode(static_cast<uint32_t>(p[i]) >> 16);
  }
  low = Float::load_aligned(lo);
  high = Float::load_aligned(hi);
}

inline Int dot_halves(const Int& a, const Int& b) {
  return ((a << 16) >> 16) * ((b << 16) >> 16) + (a >> 16) * (b >> 16);
}

inline Float fma(const Float& a, const Float& b, const Float& c) {
  alignas(64) float x[kLanes], y[kLanes], z[kLanes];
  a.store_aligned(x);
  b.store_aligned(y);
  c.store_aligned(z);
  for (int l = 0; l < kLanes; ++l) x[l] = std::fma(x[l], y[l], z[l]);
  return Float::load_aligned(x);
}

inline Int pack_unorm8(const Float4& c) {
  auto q = [](const Float& x) { return round_to_int(xsimd::min(xsimd::max(x, Float(0.0f)), Float(1.0f)) * Float(255.0f)); };
  return q(c.x) | (q(c.y) << 8) | (q(c.z) << 16) | (q(c.w) << 24);
}

inline void transpose_rows(const float* const* rows, Float& x, Float& y, Float& z, Float& w, int offset) {
  x = lanes([&](int l) { return rows[l][offset]; });
  y = lanes([&](int l) { return rows[l][offset + 1]; });
  z = lanes([&](int l) { return rows[l][offset + 2]; });
  w = lanes([&](int l) { return rows[l][offset + 3]; });
}

inline void transpose_to_rows(const Int (&fields)[8], int32_t (*rows)[8]) {
  for (int f = 0; f < 8; ++f) {
    alignas(64) int32_t lanes_of_field[kLanes];
    fields[f].store_aligned(lanes_of_field);
    for (int l = 0; l < kLanes; ++l) rows[l][f] = lanes_of_field[l];
  }
}

namespace detail {
template <class Batch>
inline void to_doubles_by_lane(const Batch& v, Double& low, Double& high) {
  alignas(64) typename Batch::value_type lanes_of_v[kLanes];
  v.store_aligned(lanes_of_v);
  low = lanes<Double>([&](int l) { return double(lanes_of_v[l]); });
  high = lanes<Double>([&](int l) { return double(lanes_of_v[l + Double::size]); });
}
}  // namespace detail

inline void to_doubles(const Int& v, Double& low, Double& high) { detail::to_doubles_by_lane(v, low, high); }
inline void to_doubles(const Float& v, Double& low, Double& high) { detail::to_doubles_by_lane(v, low, high); }
inline Float to_float(const Double& low, const Double& high) {
  alignas(64) double lo[Double::size], hi[Double::size];
  low.store_aligned(lo);
  high.store_aligned(hi);
  return lanes([&](int l) { return float(l < int(Double::size) ? lo[l] : hi[l - Double::size]); });
}

}  // namespace luxel::rasterizer::simd
