#pragma once
// HLSL's matrices over a lane: float3x3<L>, float4x4<L>, stored as rows, and mul().
//
//   mul(M, v)   column vector: component r is dot(row r, v)      (m3x3 / m4x4: one dp per row)
//   mul(v, M)   row vector: v.x * row 0 + v.y * row 1 + ...      (mul + mads: one slot per row)
//
// Both cost one slot per row on the Counted lane, as the DX9 macros m3x3 (3) and m4x4 (4) do,
// because they are written here as the dot products and the mul/mad chain fxc expands them into.

#include "luxel/shading/intrinsics.hpp"
#include "luxel/shading/vector.hpp"

#include <array>

namespace luxel::shading {

template <Lane L, int R, int C>
struct Mat {
  std::array<Vec<L, C>, R> rows;

  Mat() = default;
  /// From rows, as HLSL's float3x3(r0, r1, r2).
  template <class... Rows>
    requires(sizeof...(Rows) == R)
  explicit Mat(const Rows&... r) : rows{r...} {}

  Vec<L, C>& operator[](int r) { return rows[r]; }
  const Vec<L, C>& operator[](int r) const { return rows[r]; }
};

template <Lane L>
using float3x3 = Mat<L, 3, 3>;
template <Lane L>
using float4x4 = Mat<L, 4, 4>;

template <Lane L, int R, int C>
LUXEL_INLINE Mat<L, C, R> transpose(const Mat<L, R, C>& m) {
  Mat<L, C, R> t;
  for (int r = 0; r < R; ++r)
    for (int c = 0; c < C; ++c) t[c][r] = m[r][c];
  return t;
}

namespace detail {
struct MulFn {
  /// Matrix times column vector: one dot product per row.
  template <Lane L, int R, int C>
  LUXEL_INLINE Vec<L, R> operator()(const Mat<L, R, C>& m, const Vec<L, C>& v) const {
    Vec<L, R> r;
    for (int i = 0; i < R; ++i) r[i] = shading::dot(m[i], v);
    return r;
  }
  /// Row vector times matrix: a mul then one mad per further row.
  template <Lane L, int R, int C>
  LUXEL_INLINE Vec<L, C> operator()(const Vec<L, R>& v, const Mat<L, R, C>& m) const {
    Vec<L, C> r = v[0] * m[0];
    for (int i = 1; i < R; ++i) r = r + v[i] * m[i];
    return r;
  }
};
}  // namespace detail

inline constexpr detail::MulFn mul{};

}  // namespace luxel::shading
