#pragma once
// Constant registers: how a shader declares its uniforms.
//
// A shader keeps its parameters as plain glm values (in its parameter struct) and reads each one
// through constant<L>():
//
//   const float3<L> tint = constant<L>(params.envmap_tint);     // one c# register
//   const float3x3<L> basis = constant<L>(params.bump_basis);   // three registers, one per row
//
// On the numeric lanes this is the value itself (broadcast to every SIMD lane). On Counted it is a
// constant-register leaf keyed by the parameter's address, so each distinct object used by live
// code counts one float4 register (a matrix one per row) against the model's limit (32 on ps_2_0
// and ps_2_b, 224 on ps_3_0), as fxc allocates them. Scalars and float2/float3 are not packed
// together: Source's shaders pack by hand into float4s, and so should ours.

#include "luxel/shading/matrix.hpp"
#include "luxel/shading/vector.hpp"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace luxel::shading {

namespace detail {
template <Lane L, int N, class G>
inline Vec<L, N> constant_vec(const G& value, const void* key, int row) {
  if constexpr (kIsCounted<L>) {
    return counted_result<N, true>(counted::constant(key, row, N));
  } else {
    Vec<L, N> v;
    for (int i = 0; i < N; ++i) v[i] = L(value[i]);
    return v;
  }
}
}  // namespace detail

template <Lane L>
inline L constant(const float& value) {
  if constexpr (kIsCounted<L>) {
    return Counted(counted::Ref{counted::constant(&value, 0, 1), 0, 0});
  } else {
    return L(value);
  }
}
template <Lane L>
inline float2<L> constant(const glm::vec2& value) {
  return detail::constant_vec<L, 2>(value, &value, 0);
}
template <Lane L>
inline float3<L> constant(const glm::vec3& value) {
  return detail::constant_vec<L, 3>(value, &value, 0);
}
template <Lane L>
inline float4<L> constant(const glm::vec4& value) {
  return detail::constant_vec<L, 4>(value, &value, 0);
}
/// A matrix, rows as registers; entries keep their mathematical meaning (glm stores columns), so
/// mul(M, v) on the shader side is glm's M * v.
template <Lane L>
inline float3x3<L> constant(const glm::mat3& m) {
  float3x3<L> r;
  for (int row = 0; row < 3; ++row)
    r[row] = detail::constant_vec<L, 3>(glm::vec3(m[0][row], m[1][row], m[2][row]), &m, row);
  return r;
}
template <Lane L>
inline float4x4<L> constant(const glm::mat4& m) {
  float4x4<L> r;
  for (int row = 0; row < 4; ++row)
    r[row] = detail::constant_vec<L, 4>(glm::vec4(m[0][row], m[1][row], m[2][row], m[3][row]), &m, row);
  return r;
}

}  // namespace luxel::shading
