#pragma once
// HLSL's intrinsic functions over any lane, scalar or vector:
//   saturate lerp dot cross normalize length distance pow exp2 log2 rsqrt rcp sqrt
//   min max abs frac floor clamp step smoothstep reflect select sin cos sincos clip
// (mul is in matrix.hpp, the tex* functions in textures.hpp).
//
// Numerics are DX9's, identical on the float and SIMD lanes (same IEEE operations in the same
// order, no FMA contraction, no approximate instructions), so the fast path agrees with the
// scalar reference bit for bit. The definitions, with the DX9 instruction pages they follow:
//   min(a, b)     a < b ? a : b           min - ps; min(NaN, 1) = 1, min(1, NaN) = NaN
//   max(a, b)     a > b ? a : b           max - ps writes >=: the two differ only in the sign of
//                                         a zero result; > is what minps/maxps compute, so the
//                                         compiler may pick them in either lane without a change
//   saturate(x)   min(max(x, 0), 1)       saturate(NaN) = 0
//                 (min, max and saturate never return -0, nor a denormal under flush-to-zero)
//   rcp(x)        1 / x                   IEEE: rcp(0) = +inf; `/` is exact IEEE division
//   rsqrt(x)      1 / sqrt(|x|)           rsq - ps takes |x|; rsqrt(0) = +inf, rsqrt(1) = 1
//   sqrt(x)       sqrt(|x|)               fxc's rsq + rcp
//   log2(x)       log2(|x|)               log - ps: log2(0) = -FLT_MAX, not -inf
//   exp2(x)       2^x                     +inf from 128, 0 below -150, NaN stays NaN
//   pow(x, y)     exp2(y * log2(x))       pow - ps: |x|^y, expanded as fxc does; pow(0, 0) =
//                                         exp2(0 * -FLT_MAX) = 1, pow(0, y > 0) = 0
//   normalize(v)  v * (d == 0 ? FLT_MAX : 1 / sqrt(d)), d = dot(v, v)
//                                         nrm - ps: normalize(0) = 0
//   frac(x)       x - floor(x)            frc; frac(-1e-9) rounds to 1.0
//   sin, cos      reduced as fxc does, r = frac(x / 2 pi + 1/2), then a polynomial; absolute
//                 error < (|x| + 1) 2^-22, growing with |x| like the reduction's rounding
// exp2 and log2 are polynomials written once over the lane; measured against double precision
// (tests/shading/accuracy_test.cpp): exp2 within 1 ulp, log2 within 2 ulp (2^-23 absolute for
// results under 1), pow within (|y log2 x| + 4) * 2^-22 relative. DX9 promised 21 bits for exp and
// log, 15 for pow.
//
// The functions are function objects, not functions: an unqualified call finds them and no
// argument-dependent lookup happens, so pow(a, b) on simd::Float never silently becomes xsimd::pow.
//
// On the Counted lane each intrinsic records what fxc emits for it; the ones composed of others
// here (lerp, pow, length, smoothstep, reflect, cross, step, clamp) are simply recorded as their
// parts, which cost what the DX9 macros cost (lrp 2 = add + mad; crs 2 = mul + mad; pow 3 =
// log + mul + exp; length 3 = dp3 + rsq + rcp).

#include "luxel/shading/counted.hpp"
#include "luxel/shading/vector.hpp"

#include <array>
#include <cfloat>
#include <limits>

namespace luxel::shading {

template <class T>
concept ShaderValue = Lane<T> || detail::Shape<T>::vec;

namespace detail::math {

// The numeric kernels, per lane value. Written once; the float and SIMD lanes run the same code.

// min and max pass their result through `+ 0`: the compiler may implement the select as
// minps/maxps in one lane and as a blend (or minss) in the other, and under flush-to-zero those
// differ on a denormal operand (minps flushes it, a blend passes its bits). Adding +0 flushes it
// in both (and turns -0 into +0 in both), so the lanes agree whatever instructions were chosen.
template <NumericLane L>
LUXEL_INLINE L min(const L& a, const L& b) {
  return lane::select(a < b, a, b) + L(0.0f);
}
template <NumericLane L>
LUXEL_INLINE L max(const L& a, const L& b) {
  return lane::select(a > b, a, b) + L(0.0f);
}
template <NumericLane L>
LUXEL_INLINE L saturate(const L& x) {
  return min(max(x, L(0.0f)), L(1.0f));
}
template <NumericLane L>
LUXEL_INLINE L frac(const L& x) {
  return x - lane::floor(x);
}
template <NumericLane L>
LUXEL_INLINE L rcp(const L& x) {
  return L(1.0f) / x;
}
template <NumericLane L>
LUXEL_INLINE L rsqrt(const L& x) {
  return L(1.0f) / lane::sqrt(lane::abs(x));
}
template <NumericLane L>
LUXEL_INLINE L sqrt(const L& x) {
  return lane::sqrt(lane::abs(x));
}

/// 2^x: x = n + f with n integral and |f| <= 1/2; 2^f by a degree-6 polynomial (interpolating 2^f
/// at the Chebyshev nodes of [-1/2, 1/2], relative error 2.5e-9 before rounding), 2^n by building
/// the exponent bits in two halves so that 2^n for n in [-151, 129] never leaves the normal range
/// before the final product, which rounds once (to a denormal, 0 or +inf where it must).
template <NumericLane L>
LUXEL_INLINE L exp2(const L& x) {
  using I = typename LaneTraits<L>::Int;
  const L clamped = min(max(x, L(-151.0f)), L(129.0f));
  const L n = lane::round_even(clamped);
  const L f = clamped - n;
  L p = L(1.546144469646172e-4f);
  p = p * f + L(1.3400428177419153e-3f);
  p = p * f + L(9.61805667852609e-3f);
  p = p * f + L(5.550327226670944e-2f);
  p = p * f + L(0.24022650922288827f);
  p = p * f + L(0.6931472067028321f);
  p = p * f + L(1.0f);
  const L n1 = lane::floor(n * L(0.5f));
  const L n2 = n - n1;
  const L scale1 = lane::from_bits((lane::to_int_exact(n1) + I(127)) << 23);
  const L scale2 = lane::from_bits((lane::to_int_exact(n2) + I(127)) << 23);
  const L r = (p * scale1) * scale2;
  return lane::select(lane::is_nan(x), x, r);
}

/// log2|x| = e + log2(m) with m in [sqrt(1/2), sqrt(2)); log2(m) = (2 / ln 2) atanh(t),
/// t = (m - 1) / (m + 1), |t| <= 0.1716, by its series up to t^9 (truncation error 2e-9 relative).
/// Denormal inputs are scaled by 2^23 first. log2(0) = -FLT_MAX as the DX9 log instruction.
template <NumericLane L>
LUXEL_INLINE L log2(const L& x) {
  using I = typename LaneTraits<L>::Int;
  const L ax = lane::abs(x);
  const auto tiny = ax < L(FLT_MIN);
  const L scaled = lane::select(tiny, ax * L(8388608.0f), ax);
  const I b = lane::bits(scaled);
  L e = lane::to_float((b >> 23) - I(127)) + lane::select(tiny, L(-23.0f), L(0.0f));
  L m = lane::from_bits((b & I(0x007fffff)) | I(0x3f800000));
  const auto high = m > L(1.41421356f);
  m = lane::select(high, m * L(0.5f), m);
  e = e + lane::select(high, L(1.0f), L(0.0f));
  const L t = (m - L(1.0f)) / (m + L(1.0f));
  const L t2 = t * t;
  L p = L(0.3205988979753252f);
  p = p * t2 + L(0.41219858311113243f);
  p = p * t2 + L(0.5770780163555854f);
  p = p * t2 + L(0.9617966939259756f);
  p = p * t2 + L(2.8853900817779268f);
  L r = e + t * p;
  r = lane::select(ax == L(0.0f), L(-FLT_MAX), r);
  r = lane::select(ax == L(std::numeric_limits<float>::infinity()), ax, r);
  return lane::select(lane::is_nan(x), x, r);
}

/// sin(2 pi u) for |u| <= 1/4: u P(u^2), P of degree 5 interpolating at the Chebyshev nodes
/// (error 3e-11 before rounding).
template <NumericLane L>
LUXEL_INLINE L sin_turns(const L& u) {
  const L w = u * u;
  L p = L(-14.393966340619201f);
  p = p * w + L(42.009779310595135f);
  p = p * w + L(-76.70427987650572f);
  p = p * w + L(81.60522617404322f);
  p = p * w + L(-41.34170211674418f);
  p = p * w + L(6.283185307072265f);
  return u * p;
}

/// sin and cos of the angle 2 pi (r - 1/2), r in [0, 1) being fxc's reduced argument
/// frac(x / 2 pi + 1/2); both from one polynomial by symmetry (sin(pi - a) = sin(a),
/// cos(a) = sin(pi / 2 - |a|)).
template <NumericLane L>
LUXEL_INLINE void sincos_reduced(const L& r, L& s, L& c) {
  const L t = r - L(0.5f);
  const L at = lane::abs(t);
  const L folded = lane::select(t < L(0.0f), L(-0.5f), L(0.5f)) - t;
  s = sin_turns(lane::select(at > L(0.25f), folded, t));
  c = sin_turns(L(0.25f) - at);
}

}  // namespace detail::math

namespace detail {

template <counted::Op op, class Kernel>
struct LanewiseIntrinsic {
  template <ShaderValue T>
  LUXEL_INLINE auto operator()(const T& x) const {
    return lanewise<op>([](const auto& v) { return Kernel{}(v); }, x);
  }
};

struct SaturateKernel {
  template <class L>
  LUXEL_INLINE L operator()(const L& x) const { return math::saturate(x); }
};
struct FracKernel {
  template <class L>
  LUXEL_INLINE L operator()(const L& x) const { return math::frac(x); }
};
struct FloorKernel {
  template <class L>
  LUXEL_INLINE L operator()(const L& x) const { return lane::floor(x); }
};
struct RcpKernel {
  template <class L>
  LUXEL_INLINE L operator()(const L& x) const { return math::rcp(x); }
};
struct RsqrtKernel {
  template <class L>
  LUXEL_INLINE L operator()(const L& x) const { return math::rsqrt(x); }
};
struct SqrtKernel {
  template <class L>
  LUXEL_INLINE L operator()(const L& x) const { return math::sqrt(x); }
};
struct Exp2Kernel {
  template <class L>
  LUXEL_INLINE L operator()(const L& x) const { return math::exp2(x); }
};
struct Log2Kernel {
  template <class L>
  LUXEL_INLINE L operator()(const L& x) const { return math::log2(x); }
};

struct MinFn {
  template <class A, class B>
  LUXEL_INLINE auto operator()(const A& a, const B& b) const {
    return lanewise<counted::Op::min>([](const auto& x, const auto& y) { return math::min(x, y); }, a, b);
  }
};
struct MaxFn {
  template <class A, class B>
  LUXEL_INLINE auto operator()(const A& a, const B& b) const {
    return lanewise<counted::Op::max>([](const auto& x, const auto& y) { return math::max(x, y); }, a, b);
  }
};

struct AbsFn {
  template <ShaderValue T>
  LUXEL_INLINE T operator()(const T& x) const {
    using L = lane_of<T>;
    if constexpr (kIsCounted<L>) {
      if (counted::active_model().abs_modifier) {  // the free _abs source modifier
        T r = x;
        if constexpr (Shape<T>::vec) {
          for (int i = 0; i < Shape<T>::width; ++i) r[i].ref = counted::absolute(x[i].ref);
        } else {
          r.ref = counted::absolute(x.ref);
        }
        return r;
      }
      return lanewise<counted::Op::abs>([](const auto& v) { return v; }, x);  // the abs instruction
    } else {
      return lanewise<counted::Op::abs>([](const auto& v) { return lane::abs(v); }, x);
    }
  }
};

struct DotFn {
  template <Lane L, int N>
  LUXEL_INLINE L operator()(const Vec<L, N>& a, const Vec<L, N>& b) const {
    if constexpr (kIsCounted<L>) {
      std::array<counted::Ref, 2 * N> refs;
      counted_refs<N>(a, refs.data());
      counted_refs<N>(b, refs.data() + N);
      return Counted(counted::Ref{counted::emit(counted::Op::dot, 1, N, refs), 0, 0});
    } else {
      L r = a[0] * b[0];
      for (int i = 1; i < N; ++i) r = r + a[i] * b[i];
      return r;
    }
  }
};

struct NormalizeFn {
  template <Lane L, int N>
  LUXEL_INLINE Vec<L, N> operator()(const Vec<L, N>& v) const {
    if constexpr (kIsCounted<L>) {
      std::array<counted::Ref, N> refs;
      counted_refs<N>(v, refs.data());
      return counted_result<N, true>(counted::emit(counted::Op::normalize, N, N, refs));
    } else {
      const L d = DotFn{}(v, v);
      const L inv = lane::select(d == L(0.0f), L(FLT_MAX), L(1.0f) / lane::sqrt(d));
      return v * inv;
    }
  }
};

struct SelectFn {
  /// mask ? a : b per lane (and per component for vector masks).
  template <class M, class A, class B>
  LUXEL_INLINE auto operator()(const M& m, const A& a, const B& b) const {
    using L = lane_of<M, A, B>;
    constexpr int N = kWidth<M, A, B>;
    constexpr bool kVec = kAnyVec<A, B> || Shape<M>::boolvec;
    if constexpr (kIsCounted<L>) {
      std::array<counted::Ref, 3 * N> refs;
      counted_refs<N>(m, refs.data());
      counted_refs<N>(a, refs.data() + N);
      counted_refs<N>(b, refs.data() + 2 * N);
      return counted_result<N, kVec>(counted::emit(counted::Op::select, N, N, refs));
    } else if constexpr (kVec) {
      Vec<L, N> r;
      for (int i = 0; i < N; ++i) r[i] = lane::select(mask_component<L>(m, i), component<L>(a, i), component<L>(b, i));
      return r;
    } else {
      return L(lane::select(m, component<L>(a, 0), component<L>(b, 0)));
    }
  }
};

}  // namespace detail

/// clamp(x, 0, 1); free on a fresh result (the _sat modifier).
inline constexpr detail::LanewiseIntrinsic<counted::Op::saturate, detail::SaturateKernel> saturate{};
/// x - floor(x) (frc).
inline constexpr detail::LanewiseIntrinsic<counted::Op::frac, detail::FracKernel> frac{};
/// Round down (x - frc(x): two slots).
inline constexpr detail::LanewiseIntrinsic<counted::Op::floor, detail::FloorKernel> floor{};
/// 1 / x (rcp, one slot per component: rcp is a scalar instruction).
inline constexpr detail::LanewiseIntrinsic<counted::Op::rcp, detail::RcpKernel> rcp{};
/// 1 / sqrt(|x|) (rsq, one slot per component).
inline constexpr detail::LanewiseIntrinsic<counted::Op::rsqrt, detail::RsqrtKernel> rsqrt{};
/// sqrt(|x|) (rsq + rcp per component).
inline constexpr detail::LanewiseIntrinsic<counted::Op::sqrt, detail::SqrtKernel> sqrt{};
/// 2^x (exp, one slot per component).
inline constexpr detail::LanewiseIntrinsic<counted::Op::exp2, detail::Exp2Kernel> exp2{};
/// log2|x| (log, one slot per component).
inline constexpr detail::LanewiseIntrinsic<counted::Op::log2, detail::Log2Kernel> log2{};
inline constexpr detail::MinFn min{};
inline constexpr detail::MaxFn max{};
/// |x|: the abs instruction, or the free _abs modifier on *_3_0.
inline constexpr detail::AbsFn abs{};
/// dp2add (2 slots), dp3, dp4 (1 slot).
inline constexpr detail::DotFn dot{};
/// nrm (3 slots; float4: dp4 + rsq + mul, also 3).
inline constexpr detail::NormalizeFn normalize{};
/// Per-lane `mask ? a : b`: cmp on pixel shaders.
inline constexpr detail::SelectFn select{};

namespace detail {

struct PowFn {
  template <class A, class B>
  LUXEL_INLINE auto operator()(const A& x, const B& y) const {
    return shading::exp2(y * shading::log2(x));
  }
};
struct LerpFn {
  /// a + (b - a) * t (HLSL's definition; lrp's 2 slots on Counted as add + mad).
  template <class A, class B, class T>
  LUXEL_INLINE auto operator()(const A& a, const B& b, const T& t) const {
    return a + (b - a) * t;
  }
};
struct LengthFn {
  template <Lane L, int N>
  LUXEL_INLINE L operator()(const Vec<L, N>& v) const {
    return shading::sqrt(shading::dot(v, v));
  }
};
struct DistanceFn {
  template <Lane L, int N>
  LUXEL_INLINE L operator()(const Vec<L, N>& a, const Vec<L, N>& b) const {
    return LengthFn{}(a - b);
  }
};
struct CrossFn {
  template <Lane L>
  LUXEL_INLINE Vec<L, 3> operator()(const Vec<L, 3>& a, const Vec<L, 3>& b) const {
    return a.yzx() * b.zxy() - a.zxy() * b.yzx();
  }
};
struct StepFn {
  /// x >= edge ? 1 : 0.
  template <class E, class X>
  LUXEL_INLINE auto operator()(const E& edge, const X& x) const {
    using L = lane_of<E, X>;
    if constexpr (Shape<X>::vec || Shape<E>::vec) {
      return shading::select(x >= edge, 1.0f, 0.0f);
    } else {
      return shading::select(L(x) >= L(edge), 1.0f, 0.0f);
    }
  }
};
struct ClampFn {
  template <class X, class A, class B>
  LUXEL_INLINE auto operator()(const X& x, const A& lo, const B& hi) const {
    if constexpr (std::is_arithmetic_v<A> && std::is_arithmetic_v<B>) {
      if (lo == 0 && hi == 1) return shading::saturate(x);
    }
    return shading::min(shading::max(x, lo), hi);
  }
};
struct SmoothstepFn {
  /// t = saturate((x - a) / (b - a)); t * t * (3 - 2 t).
  template <class A, class B, class X>
  LUXEL_INLINE auto operator()(const A& a, const B& b, const X& x) const {
    const auto t = shading::saturate((x - a) / (b - a));
    return t * t * (3.0f - 2.0f * t);
  }
};
struct ReflectFn {
  /// i - 2 dot(n, i) n.
  template <Lane L, int N>
  LUXEL_INLINE Vec<L, N> operator()(const Vec<L, N>& i, const Vec<L, N>& n) const {
    return i - (L(2.0f) * shading::dot(n, i)) * n;
  }
};

struct SinCosFn {
  /// HLSL's sincos(x, out s, out c). The argument is reduced as fxc does for the sincos
  /// instruction (which wants [-pi, pi]): r = frac(x / 2 pi + 1/2), a mad and a frc; then
  /// sincos (8 slots per component) with the mad back to radians.
  template <ShaderValue T>
  LUXEL_INLINE void operator()(const T& x, T& s, T& c) const {
    using L = lane_of<T>;
    constexpr int N = Shape<T>::width;
    const T reduced = shading::frac(x * 0.159154943f + 0.5f);
    if constexpr (kIsCounted<L>) {
      std::array<counted::Ref, N> refs;
      counted_refs<N>(reduced, refs.data());
      const uint32_t node = counted::emit(counted::Op::sincos, 2 * N, N, refs);
      if constexpr (N == 1) {
        s = Counted(counted::Ref{node, 0, 0});
        c = Counted(counted::Ref{node, 1, 0});
      } else {
        for (int i = 0; i < N; ++i) {
          s[i] = Counted(counted::Ref{node, static_cast<uint8_t>(i), 0});
          c[i] = Counted(counted::Ref{node, static_cast<uint8_t>(N + i), 0});
        }
      }
    } else if constexpr (N == 1) {
      math::sincos_reduced(L(reduced), s, c);
    } else {
      for (int i = 0; i < N; ++i) math::sincos_reduced(reduced[i], s[i], c[i]);
    }
  }
};

struct SinFn {
  template <ShaderValue T>
  LUXEL_INLINE T operator()(const T& x) const {
    T s, c;
    SinCosFn{}(x, s, c);
    return s;
  }
};
struct CosFn {
  template <ShaderValue T>
  LUXEL_INLINE T operator()(const T& x) const {
    T s, c;
    SinCosFn{}(x, s, c);
    return c;
  }
};

struct ClipFn {
  /// HLSL's clip(x): the lanes to discard (any component < 0), for PixelOutput::discard. On
  /// Counted a texkill (one texture slot), kept although no output reads it.
  template <ShaderValue T>
  LUXEL_INLINE Mask<lane_of<T>> operator()(const T& x) const {
    using L = lane_of<T>;
    constexpr int N = Shape<T>::width;
    if constexpr (kIsCounted<L>) {
      if (!counted::active_model().pixel) counted::unsupported("clip (texkill) exists only in pixel shaders");
      std::array<counted::Ref, N> refs;
      counted_refs<N>(x, refs.data());
      const uint32_t node = counted::emit(counted::Op::texkill, 1, N, refs);
      counted::side_effect(node);
      return CountedMask(counted::Ref{node, 0, 0});
    } else if constexpr (N == 1) {
      return L(x) < L(0.0f);
    } else {
      Mask<L> kill = x[0] < L(0.0f);
      for (int i = 1; i < N; ++i) kill = kill || x[i] < L(0.0f);
      return kill;
    }
  }
};

}  // namespace detail

/// sin and cos of x (radians) at once: one sincos instruction.
inline constexpr detail::SinCosFn sincos{};
/// sin(x): mad, frc, mad, sincos: 11 slots per component (sincos is scalar).
inline constexpr detail::SinFn sin{};
inline constexpr detail::CosFn cos{};
/// The discard mask of HLSL's clip(x).
inline constexpr detail::ClipFn clip{};

/// |x|^y as exp2(y log2 x): 3 slots for a scalar, 2N + 1 for a vector (log and exp are scalar
/// instructions, the mul is one vector slot).
inline constexpr detail::PowFn pow{};
inline constexpr detail::LerpFn lerp{};
inline constexpr detail::LengthFn length{};
inline constexpr detail::DistanceFn distance{};
/// crs (2 slots).
inline constexpr detail::CrossFn cross{};
inline constexpr detail::StepFn step{};
/// min(max(x, lo), hi); clamp(x, 0, 1) with literal bounds is saturate, as fxc compiles it.
inline constexpr detail::ClampFn clamp{};
inline constexpr detail::SmoothstepFn smoothstep{};
inline constexpr detail::ReflectFn reflect{};

}  // namespace luxel::shading
