#pragma once
// HLSL's vector types over a lane: float2<L>, float3<L>, float4<L> (float1<L> is L itself) and
// their masks bool1<L>..bool4<L>.
//
//   template <class L> float3<L> tint(const float3<L>& albedo, const L& k) {
//     return albedo * k + float3<L>(0.1f);                       // one mad on the hardware
//   }
//
// Arithmetic is component-wise and broadcasts scalars (lane values or float literals) as HLSL
// does. Common swizzles are member functions (v.xyz(), v.zw(), v.rgb()), any other is
// swizzle<2, 1, 0>(v); components are the members x, y, z, w (r(), g(), b(), a() read them by
// their color names).
//
// Every component-wise operation goes through one function, lanewise(): on the numeric lanes it
// applies the scalar operation per component; on Counted it records one instruction of the
// vector's width (a float3 add is one slot, as on the hardware).

#include "luxel/shading/counted.hpp"
#include "luxel/shading/lane.hpp"

#include <algorithm>
#include <array>
#include <type_traits>

namespace luxel::shading {

template <Lane L, int N>
struct Vec;

template <Lane L>
using float1 = L;
template <Lane L>
using float2 = Vec<L, 2>;
template <Lane L>
using float3 = Vec<L, 3>;
template <Lane L>
using float4 = Vec<L, 4>;

/// N per-lane booleans: the result of comparing two vectors.
template <Lane L, int N>
struct BoolVec {
  std::array<Mask<L>, N> v;
  Mask<L>& operator[](int i) { return v[i]; }
  const Mask<L>& operator[](int i) const { return v[i]; }
};

template <Lane L>
using bool1 = Mask<L>;
template <Lane L>
using bool2 = BoolVec<L, 2>;
template <Lane L>
using bool3 = BoolVec<L, 3>;
template <Lane L>
using bool4 = BoolVec<L, 4>;

namespace detail {

/// Shape of an operand of a component-wise operation: a vector, a lane value, or a literal.
template <class T>
struct Shape {
  static constexpr bool vec = false;
  static constexpr bool boolvec = false;
  static constexpr int width = 1;
  using lane = std::conditional_t<std::is_arithmetic_v<T>, void, T>;
};
template <class L, int N>
struct Shape<Vec<L, N>> {
  static constexpr bool vec = true;
  static constexpr bool boolvec = false;
  static constexpr int width = N;
  using lane = L;
};
template <class L, int N>
struct Shape<BoolVec<L, N>> {
  static constexpr bool vec = false;
  static constexpr bool boolvec = true;
  static constexpr int width = N;
  using lane = L;
};
template <>
struct Shape<CountedMask> {
  static constexpr bool vec = false;
  static constexpr bool boolvec = false;
  static constexpr int width = 1;
  using lane = Counted;
};
template <>
struct Shape<simd::FloatMask> {
  static constexpr bool vec = false;
  static constexpr bool boolvec = false;
  static constexpr int width = 1;
  using lane = simd::Float;
};
template <>
struct Shape<bool> {
  static constexpr bool vec = false;
  static constexpr bool boolvec = false;
  static constexpr int width = 1;
  using lane = float;
};

/// The lane of an argument list: the first argument that is not a literal (float if all are).
template <class... Args>
struct LaneOf {
  using type = float;
};
template <class First, class... Rest>
struct LaneOf<First, Rest...> {
  using type = std::conditional_t<std::is_void_v<typename Shape<First>::lane>, typename LaneOf<Rest...>::type,
                                  typename Shape<First>::lane>;
};
template <class... Args>
using lane_of = typename LaneOf<std::remove_cvref_t<Args>...>::type;

template <class... Args>
inline constexpr int kWidth = std::max({1, Shape<std::remove_cvref_t<Args>>::width...});
template <class... Args>
inline constexpr bool kAnyVec = (Shape<std::remove_cvref_t<Args>>::vec || ...);

/// An operand that fits a component-wise operation on lane L and width N.
template <class T, class L, int N>
concept Operand = std::is_arithmetic_v<T> || std::is_same_v<T, L> || std::is_same_v<T, Vec<L, N>>;

/// Component i of an operand, as a lane value (literals converted, scalars broadcast).
template <class L, class T>
LUXEL_INLINE L component(const T& t, int i) {
  if constexpr (Shape<T>::vec) {
    return t[i];
  } else if constexpr (std::is_arithmetic_v<T>) {
    return L(static_cast<float>(t));
  } else {
    return t;
  }
}
template <class L, class T>
LUXEL_INLINE Mask<L> mask_component(const T& t, int i) {
  if constexpr (Shape<T>::boolvec) {
    return t[i];
  } else {
    return t;
  }
}

/// The N references an operand contributes to a Counted instruction.
template <int N, class T>
LUXEL_INLINE void counted_refs(const T& t, counted::Ref* out) {
  if constexpr (Shape<T>::vec || Shape<T>::boolvec) {
    for (int i = 0; i < N; ++i) out[i] = t[i].ref;
  } else if constexpr (std::is_arithmetic_v<T>) {
    const counted::Ref r = counted::literal(static_cast<float>(t));
    for (int i = 0; i < N; ++i) out[i] = r;
  } else {
    for (int i = 0; i < N; ++i) out[i] = t.ref;
  }
}

/// A Counted vector from N references (no literal nodes made on the way, unlike Vec's default
/// constructor). L is a parameter only so that Vec, defined below, is looked up when this is
/// instantiated (Clang checks a non-dependent Vec<Counted, 2> where it reads it).
template <int N, class L = Counted>
LUXEL_INLINE Vec<L, N> counted_vec(const counted::Ref* r) {
  if constexpr (N == 2) {
    return Vec<L, 2>(L(r[0]), L(r[1]));
  } else if constexpr (N == 3) {
    return Vec<L, 3>(L(r[0]), L(r[1]), L(r[2]));
  } else {
    return Vec<L, 4>(L(r[0]), L(r[1]), L(r[2]), L(r[3]));
  }
}

/// The value (a vector of width N, or a scalar) made of the components of Counted node `node`.
template <int N, bool kVec>
LUXEL_INLINE auto counted_result(uint32_t node) {
  std::array<counted::Ref, N> refs;
  for (int i = 0; i < N; ++i) refs[i] = counted::Ref{node, static_cast<uint8_t>(i), 0};
  if constexpr (kVec) {
    return counted_vec<N>(refs.data());
  } else {
    return Counted(refs[0]);
  }
}

/// One component-wise operation. On the numeric lanes: f applied per component. On Counted: one
/// instruction `op` of the operation's width.
template <counted::Op op, class F, class... Args>
LUXEL_INLINE auto lanewise(F&& f, const Args&... args) {
  using L = lane_of<Args...>;
  constexpr int N = kWidth<Args...>;
  constexpr bool kVec = kAnyVec<Args...>;
  static_assert((Operand<std::remove_cvref_t<Args>, L, N> && ...),
                "operands must share one lane type and one width (or be scalars)");
  if constexpr (kIsCounted<L>) {
    std::array<counted::Ref, N * sizeof...(Args)> refs;
    int group = 0;
    ((counted_refs<N>(args, refs.data() + N * group++)), ...);
    std::array<counted::Ref, N> out;
    counted::emit_lanewise(op, N, refs, out.data());
    if constexpr (kVec) {
      return counted_vec<N>(out.data());
    } else {
      return Counted(out[0]);
    }
  } else if constexpr (kVec) {
    Vec<L, N> r;
    for (int i = 0; i < N; ++i) r[i] = f(component<L>(args, i)...);
    return r;
  } else {
    return L(f(component<L>(args, 0)...));
  }
}

/// Component-wise comparison, giving masks.
template <counted::Comparison c, class F, class A, class B>
LUXEL_INLINE auto compare(F&& f, const A& a, const B& b) {
  using L = lane_of<A, B>;
  constexpr int N = kWidth<A, B>;
  static_assert(Operand<A, L, N> && Operand<B, L, N>, "operands must share one lane type and width");
  if constexpr (kIsCounted<L>) {
    std::array<counted::Ref, 2 * N> refs;
    counted_refs<N>(a, refs.data());
    counted_refs<N>(b, refs.data() + N);
    counted::Extra extra;
    extra.comparison = c;
    const uint32_t node = counted::emit(counted::Op::compare, N, N, refs, extra);
    BoolVec<Counted, N> r{};
    for (int i = 0; i < N; ++i) r[i] = CountedMask(counted::Ref{node, static_cast<uint8_t>(i), 0});
    return r;
  } else {
    BoolVec<L, N> r;
    for (int i = 0; i < N; ++i) r[i] = f(component<L>(a, i), component<L>(b, i));
    return r;
  }
}

struct Plus {
  template <class T>
  LUXEL_INLINE T operator()(const T& a, const T& b) const { return a + b; }
};
struct Minus {
  template <class T>
  LUXEL_INLINE T operator()(const T& a, const T& b) const { return a - b; }
};
struct Times {
  template <class T>
  LUXEL_INLINE T operator()(const T& a, const T& b) const { return a * b; }
};
struct Divide {
  template <class T>
  LUXEL_INLINE T operator()(const T& a, const T& b) const { return a / b; }
};

/// Shared members of float2..float4: swizzles and color-name accessors.
template <Lane L, int N>
struct VecCommon {
  template <int... I>
  auto swizzle() const {
    static_assert(((I >= 0 && I < N) && ...), "swizzle component out of range");
    const auto& self = static_cast<const Vec<L, N>&>(*this);
    if constexpr (sizeof...(I) == 1) {
      constexpr int kIndex[] = {I...};
      return L(self[kIndex[0]]);
    } else {
      return Vec<L, sizeof...(I)>(self[I]...);
    }
  }
  auto xy() const { return swizzle<0, 1>(); }
  auto yx() const { return swizzle<1, 0>(); }
  auto xz() const requires(N >= 3) { return swizzle<0, 2>(); }
  auto yz() const requires(N >= 3) { return swizzle<1, 2>(); }
  auto zw() const requires(N >= 4) { return swizzle<2, 3>(); }
  auto xyz() const requires(N >= 3) { return swizzle<0, 1, 2>(); }
  auto rgb() const requires(N >= 3) { return swizzle<0, 1, 2>(); }
  auto yzx() const requires(N >= 3) { return swizzle<1, 2, 0>(); }
  auto zxy() const requires(N >= 3) { return swizzle<2, 0, 1>(); }
  const L& r() const { return static_cast<const Vec<L, N>&>(*this)[0]; }
  const L& g() const { return static_cast<const Vec<L, N>&>(*this)[1]; }
  const L& b() const requires(N >= 3) { return static_cast<const Vec<L, N>&>(*this)[2]; }
  const L& a() const requires(N >= 4) { return static_cast<const Vec<L, N>&>(*this)[3]; }
};

template <class T, class L>
concept Literal = std::is_arithmetic_v<T> && !std::is_same_v<T, L>;

}  // namespace detail

template <Lane L>
struct Vec<L, 2> : detail::VecCommon<L, 2> {
  L x, y;
  Vec() : x(0.0f), y(0.0f) {}
  Vec(const L& s) : x(s), y(s) {}  // NOLINT: scalars broadcast, as in HLSL
  template <detail::Literal<L> T>
  Vec(T s) : Vec(L(static_cast<float>(s))) {}  // NOLINT
  Vec(const L& x_, const L& y_) : x(x_), y(y_) {}
  L& operator[](int i) { return i == 0 ? x : y; }
  const L& operator[](int i) const { return i == 0 ? x : y; }
};

template <Lane L>
struct Vec<L, 3> : detail::VecCommon<L, 3> {
  L x, y, z;
  Vec() : x(0.0f), y(0.0f), z(0.0f) {}
  Vec(const L& s) : x(s), y(s), z(s) {}  // NOLINT
  template <detail::Literal<L> T>
  Vec(T s) : Vec(L(static_cast<float>(s))) {}  // NOLINT
  Vec(const L& x_, const L& y_, const L& z_) : x(x_), y(y_), z(z_) {}
  Vec(const Vec<L, 2>& xy_, const L& z_) : x(xy_.x), y(xy_.y), z(z_) {}
  Vec(const L& x_, const Vec<L, 2>& yz_) : x(x_), y(yz_.x), z(yz_.y) {}
  L& operator[](int i) { return i == 0 ? x : i == 1 ? y : z; }
  const L& operator[](int i) const { return i == 0 ? x : i == 1 ? y : z; }
};

template <Lane L>
struct Vec<L, 4> : detail::VecCommon<L, 4> {
  L x, y, z, w;
  Vec() : x(0.0f), y(0.0f), z(0.0f), w(0.0f) {}
  Vec(const L& s) : x(s), y(s), z(s), w(s) {}  // NOLINT
  template <detail::Literal<L> T>
  Vec(T s) : Vec(L(static_cast<float>(s))) {}  // NOLINT
  Vec(const L& x_, const L& y_, const L& z_, const L& w_) : x(x_), y(y_), z(z_), w(w_) {}
  Vec(const Vec<L, 3>& xyz_, const L& w_) : x(xyz_.x), y(xyz_.y), z(xyz_.z), w(w_) {}
  Vec(const Vec<L, 2>& xy_, const Vec<L, 2>& zw_) : x(xy_.x), y(xy_.y), z(zw_.x), w(zw_.y) {}
  Vec(const Vec<L, 2>& xy_, const L& z_, const L& w_) : x(xy_.x), y(xy_.y), z(z_), w(w_) {}
  L& operator[](int i) { return i == 0 ? x : i == 1 ? y : i == 2 ? z : w; }
  const L& operator[](int i) const { return i == 0 ? x : i == 1 ? y : i == 2 ? z : w; }
};

namespace detail {
/// At least one operand is a vector, and all fit one lane type and width.
template <class A, class B>
concept VecOperands = (Shape<A>::vec || Shape<B>::vec) &&
                      Operand<A, lane_of<A, B>, kWidth<A, B>> && Operand<B, lane_of<A, B>, kWidth<A, B>>;
}  // namespace detail

template <class A, class B>
  requires detail::VecOperands<A, B>
LUXEL_INLINE auto operator+(const A& a, const B& b) {
  return detail::lanewise<counted::Op::add>(detail::Plus{}, a, b);
}
template <Lane L, int N>
LUXEL_INLINE Vec<L, N> operator-(const Vec<L, N>& a) {
  Vec<L, N> r = a;
  for (int i = 0; i < N; ++i) r[i] = -a[i];  // Counted: a free negate modifier per component
  return r;
}
template <class A, class B>
  requires detail::VecOperands<A, B>
LUXEL_INLINE auto operator-(const A& a, const B& b) {
  using L = detail::lane_of<A, B>;
  if constexpr (kIsCounted<L>) {
    if constexpr (std::is_arithmetic_v<B>) {
      return a + static_cast<float>(-b);
    } else {
      return a + (-b);  // add with a negated source
    }
  } else {
    return detail::lanewise<counted::Op::add>(detail::Minus{}, a, b);
  }
}
template <class A, class B>
  requires detail::VecOperands<A, B>
LUXEL_INLINE auto operator*(const A& a, const B& b) {
  return detail::lanewise<counted::Op::mul>(detail::Times{}, a, b);
}
template <class A, class B>
  requires detail::VecOperands<A, B>
LUXEL_INLINE auto operator/(const A& a, const B& b) {
  return detail::lanewise<counted::Op::div>(detail::Divide{}, a, b);
}

/// v.swizzle<I...>() as a free function, which template code can call without `template`:
/// swizzle<2, 1, 0>(v) is HLSL's v.zyx.
template <int... I, Lane L, int N>
LUXEL_INLINE auto swizzle(const Vec<L, N>& v) {
  return v.template swizzle<I...>();
}

template <Lane L, int N, class B>
LUXEL_INLINE Vec<L, N>& operator+=(Vec<L, N>& a, const B& b) { return a = a + b; }
template <Lane L, int N, class B>
LUXEL_INLINE Vec<L, N>& operator-=(Vec<L, N>& a, const B& b) { return a = a - b; }
template <Lane L, int N, class B>
LUXEL_INLINE Vec<L, N>& operator*=(Vec<L, N>& a, const B& b) { return a = a * b; }
template <Lane L, int N, class B>
LUXEL_INLINE Vec<L, N>& operator/=(Vec<L, N>& a, const B& b) { return a = a / b; }

// `!=` is !(==) per component: IEEE's unordered not-equal on both lanes (see lane.hpp).
#define LUXEL_SHADING_COMPARISON(OP, KIND, EXPR)                                                     \
  template <class A, class B>                                                                        \
    requires detail::VecOperands<A, B>                                                               \
  LUXEL_INLINE auto operator OP(const A& a, const B& b) {                                                  \
    return detail::compare<counted::Comparison::KIND>([](const auto& x, const auto& y) { return EXPR; }, a, b); \
  }
LUXEL_SHADING_COMPARISON(>=, ge, x >= y)
LUXEL_SHADING_COMPARISON(<, lt, x < y)
LUXEL_SHADING_COMPARISON(>, gt, x > y)
LUXEL_SHADING_COMPARISON(<=, le, x <= y)
LUXEL_SHADING_COMPARISON(==, eq, x == y)
LUXEL_SHADING_COMPARISON(!=, ne, !(x == y))
#undef LUXEL_SHADING_COMPARISON

template <Lane L, int N>
LUXEL_INLINE BoolVec<L, N> operator!(const BoolVec<L, N>& m) {
  BoolVec<L, N> r = m;
  for (int i = 0; i < N; ++i) r[i] = !m[i];
  return r;
}
template <Lane L, int N>
LUXEL_INLINE BoolVec<L, N> operator&&(const BoolVec<L, N>& a, const BoolVec<L, N>& b) {
  BoolVec<L, N> r = a;
  for (int i = 0; i < N; ++i) r[i] = a[i] && b[i];
  return r;
}
template <Lane L, int N>
LUXEL_INLINE BoolVec<L, N> operator||(const BoolVec<L, N>& a, const BoolVec<L, N>& b) {
  BoolVec<L, N> r = a;
  for (int i = 0; i < N; ++i) r[i] = a[i] || b[i];
  return r;
}

}  // namespace luxel::shading
