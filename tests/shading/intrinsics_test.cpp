// Every intrinsic against closed-form values, on the scalar and the SIMD lane.

#include "lanes.hpp"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>

namespace luxel::shading {
namespace {

using testing::lane_of;
using testing::make_lanes;

template <class L>
class Intrinsics : public ::testing::Test {};
using NumericLanes = ::testing::Types<float, simd::Float>;
TYPED_TEST_SUITE(Intrinsics, NumericLanes);

using testing::kInf;
using testing::kNaN;

/// Every lane of `v` equals `expected` exactly (NaN matches NaN).
template <class L>
void expect_all(const L& v, float expected, const char* what) {
  for (int i = 0; i < testing::kWidth<L>; ++i) {
    EXPECT_TRUE(testing::same_float(lane_of(v, i), expected))
        << what << ": lane " << i << " is " << lane_of(v, i) << ", expected " << expected;
  }
}
/// Every lane of `v` within `tolerance` of `expected`.
template <class L>
void expect_near_all(const L& v, float expected, float tolerance, const char* what) {
  for (int i = 0; i < testing::kWidth<L>; ++i) EXPECT_NEAR(lane_of(v, i), expected, tolerance) << what << ", lane " << i;
}

TYPED_TEST(Intrinsics, SaturateClampsAndMapsNaNToZero) {
  using L = TypeParam;
  expect_all(saturate(L(-2.0f)), 0.0f, "saturate(-2)");
  expect_all(saturate(L(0.25f)), 0.25f, "saturate(0.25)");
  expect_all(saturate(L(7.0f)), 1.0f, "saturate(7)");
  expect_all(saturate(L(kNaN)), 0.0f, "saturate(NaN)");
  expect_all(saturate(L(kInf)), 1.0f, "saturate(inf)");
  expect_all(saturate(L(-0.0f)), 0.0f, "saturate(-0): max(-0, 0) is 0 (-0 > 0 is false)");
}

TYPED_TEST(Intrinsics, MinMaxFollowTheDx9Definitions) {
  using L = TypeParam;
  expect_all(min(L(1.0f), L(2.0f)), 1.0f, "min");
  expect_all(max(L(1.0f), L(2.0f)), 2.0f, "max");
  // min(a, b) = a < b ? a : b, max(a, b) = a >= b ? a : b.
  expect_all(min(L(kNaN), L(1.0f)), 1.0f, "min(NaN, 1)");
  expect_all(min(L(1.0f), L(kNaN)), kNaN, "min(1, NaN)");
  expect_all(max(L(kNaN), L(1.0f)), 1.0f, "max(NaN, 1)");
  expect_all(max(L(1.0f), L(kNaN)), kNaN, "max(1, NaN)");
  expect_all(clamp(L(5.0f), 1.0f, 3.0f), 3.0f, "clamp high");
  expect_all(clamp(L(-5.0f), 1.0f, 3.0f), 1.0f, "clamp low");
  expect_all(clamp(L(2.5f), 0.0f, 1.0f), 1.0f, "clamp(x, 0, 1)");
}

TYPED_TEST(Intrinsics, LerpStepSmoothstep) {
  using L = TypeParam;
  expect_all(lerp(L(2.0f), L(6.0f), L(0.25f)), 3.0f, "lerp");
  expect_all(lerp(L(2.0f), L(6.0f), L(1.0f)), 6.0f, "lerp at 1");
  expect_all(step(L(0.5f), L(0.5f)), 1.0f, "step at the edge");
  expect_all(step(L(0.5f), L(0.4f)), 0.0f, "step below");
  expect_all(smoothstep(L(0.0f), L(1.0f), L(0.5f)), 0.5f, "smoothstep middle");
  expect_all(smoothstep(L(1.0f), L(3.0f), L(1.5f)), 0.15625f, "smoothstep 1/4: 3/16 - 2/64");
  expect_all(smoothstep(L(0.0f), L(1.0f), L(-1.0f)), 0.0f, "smoothstep below");
  expect_all(smoothstep(L(0.0f), L(1.0f), L(9.0f)), 1.0f, "smoothstep above");
}

TYPED_TEST(Intrinsics, AbsFracFloor) {
  using L = TypeParam;
  expect_all(abs(L(-3.5f)), 3.5f, "abs");
  expect_all(frac(L(2.75f)), 0.75f, "frac");
  expect_all(frac(L(-0.25f)), 0.75f, "frac of a negative: x - floor(x)");
  expect_all(frac(L(-1e-9f)), 1.0f, "frac(-1e-9) rounds to 1 (x - floor(x) in float)");
  expect_all(floor(L(-0.5f)), -1.0f, "floor");
  expect_all(frac(L(kInf)), kNaN, "frac(inf)");
}

TYPED_TEST(Intrinsics, ReciprocalsAndRoots) {
  using L = TypeParam;
  expect_all(rcp(L(4.0f)), 0.25f, "rcp");
  expect_all(rcp(L(0.0f)), kInf, "rcp(0)");
  expect_all(rcp(L(-0.0f)), -kInf, "rcp(-0)");
  expect_all(rsqrt(L(16.0f)), 0.25f, "rsqrt");
  expect_all(rsqrt(L(-16.0f)), 0.25f, "rsqrt takes |x| (rsq)");
  expect_all(rsqrt(L(1.0f)), 1.0f, "rsqrt(1) is exactly 1 (rsq)");
  expect_all(rsqrt(L(0.0f)), kInf, "rsqrt(0)");
  expect_all(sqrt(L(9.0f)), 3.0f, "sqrt");
  expect_all(sqrt(L(-9.0f)), 3.0f, "sqrt takes |x| (rsq + rcp)");
  expect_all(L(1.0f) / L(3.0f), 1.0f / 3.0f, "division is exact IEEE division");
}

TYPED_TEST(Intrinsics, Exp2Log2Pow) {
  using L = TypeParam;
  expect_all(exp2(L(0.0f)), 1.0f, "exp2(0)");
  expect_all(exp2(L(10.0f)), 1024.0f, "exp2(10)");
  expect_all(exp2(L(-1.0f)), 0.5f, "exp2(-1)");
  expect_near_all(exp2(L(0.5f)), 1.41421356f, 2e-7f, "exp2(1/2)");
  expect_all(exp2(L(128.0f)), kInf, "exp2(128)");
  expect_all(exp2(L(-200.0f)), 0.0f, "exp2(-200)");
  expect_all(exp2(L(-kInf)), 0.0f, "exp2(-inf)");
  expect_all(exp2(L(kInf)), kInf, "exp2(inf)");
  expect_all(exp2(L(kNaN)), kNaN, "exp2(NaN)");
  expect_all(log2(L(1.0f)), 0.0f, "log2(1)");
  expect_all(log2(L(8.0f)), 3.0f, "log2(8)");
  expect_all(log2(L(0.125f)), -3.0f, "log2(1/8)");
  expect_all(log2(L(-8.0f)), 3.0f, "log2 takes |x| (log)");
  expect_all(log2(L(0.0f)), -FLT_MAX, "log2(0) = -FLT_MAX (log)");
  expect_all(log2(L(kInf)), kInf, "log2(inf)");
  expect_all(log2(L(kNaN)), kNaN, "log2(NaN)");
  expect_near_all(log2(L(10.0f)), 3.32192809f, 3e-7f, "log2(10)");
  expect_all(pow(L(2.0f), L(10.0f)), 1024.0f, "pow(2, 10)");
  expect_all(pow(L(0.0f), L(0.0f)), 1.0f, "pow(0, 0) = exp2(0 * -FLT_MAX) = 1");
  expect_all(pow(L(0.0f), L(150.0f)), 0.0f, "pow(0, 150)");
  expect_all(pow(L(0.0f), L(-1.0f)), kInf, "pow(0, -1)");
  expect_all(pow(L(-2.0f), L(2.0f)), 4.0f, "pow takes |x|");
  expect_all(pow(L(1.0f), L(150.0f)), 1.0f, "pow(1, y) is exactly 1");
  expect_all(pow(L(0.5f), L(140.0f)), std::ldexp(1.0f, -140), "pow(0.5, 140) is the denormal 2^-140");
  expect_near_all(pow(L(0.9f), L(150.0f)), 1.3689147e-7f, 1.3689147e-7f * 2e-5f, "pow(0.9, 150)");
}

TYPED_TEST(Intrinsics, SinCosAndClip) {
  using L = TypeParam;
  expect_all(sin(L(0.0f)), 0.0f, "sin(0)");
  expect_near_all(cos(L(0.0f)), 1.0f, 1e-7f, "cos(0)");
  expect_near_all(sin(L(1.5707963f)), 1.0f, 1e-7f, "sin(pi/2)");
  expect_near_all(sin(L(-0.5f)), -0.47942554f, 2e-7f, "sin(-1/2)");
  expect_near_all(cos(L(3.14159265f)), -1.0f, 1e-7f, "cos(pi)");
  expect_near_all(sin(L(100.0f)), -0.50636564f, 1e-5f, "sin(100): the reduction's error grows with |x|");
  expect_all(sin(L(kNaN)), kNaN, "sin(NaN)");
  expect_all(sin(L(kInf)), kNaN, "sin(inf)");
  L s, c;
  sincos(L(0.5f), s, c);
  expect_near_all(s, 0.47942554f, 2e-7f, "sincos: sin");
  expect_near_all(c, 0.87758256f, 2e-7f, "sincos: cos");
  const float3<L> v = sin(float3<L>(L(0.0f), L(0.5f), L(1.0f)));
  expect_near_all(v.z, 0.84147098f, 2e-7f, "sin float3");

  const auto kill = clip(float3<L>(L(1.0f), L(-0.5f), L(2.0f)));
  for (int i = 0; i < testing::kWidth<L>; ++i) EXPECT_TRUE(lane_of(kill, i)) << "any component < 0 kills";
  const auto keep = clip(L(0.0f));
  for (int i = 0; i < testing::kWidth<L>; ++i) EXPECT_FALSE(lane_of(keep, i)) << "0 is kept";
}

TYPED_TEST(Intrinsics, VectorFunctions) {
  using L = TypeParam;
  const float3<L> a(L(1.0f), L(2.0f), L(3.0f));
  const float3<L> b(L(4.0f), L(-5.0f), L(6.0f));
  expect_all(dot(a, b), 12.0f, "dot");
  const float3<L> c = cross(a, b);
  expect_all(c.x, 27.0f, "cross.x");
  expect_all(c.y, 6.0f, "cross.y");
  expect_all(c.z, -13.0f, "cross.z");
  expect_all(length(float3<L>(L(3.0f), L(4.0f), L(12.0f))), 13.0f, "length");
  expect_all(distance(a, a + float3<L>(L(0.0f), L(3.0f), L(4.0f))), 5.0f, "distance");

  const float3<L> n = normalize(float3<L>(L(0.0f), L(3.0f), L(4.0f)));
  expect_all(n.y, 3.0f * (1.0f / std::sqrt(25.0f)), "normalize.y (v * (1 / sqrt(d)))");
  expect_all(n.z, 4.0f * (1.0f / std::sqrt(25.0f)), "normalize.z");
  const float3<L> zero = normalize(float3<L>(L(0.0f)));
  expect_all(zero.x, 0.0f, "normalize(0) = 0 * FLT_MAX = 0 (nrm)");
  const float4<L> n4 = normalize(float4<L>(L(1.0f), L(1.0f), L(1.0f), L(1.0f)));
  expect_all(n4.w, 0.5f, "normalize float4");

  // reflect(i, n) = i - 2 dot(n, i) n: a ray going down on a floor comes back up.
  const float3<L> r = reflect(float3<L>(L(1.0f), L(-1.0f), L(0.0f)), float3<L>(L(0.0f), L(1.0f), L(0.0f)));
  expect_all(r.x, 1.0f, "reflect.x");
  expect_all(r.y, 1.0f, "reflect.y");

  const float4<L> s = saturate(float4<L>(L(-1.0f), L(0.5f), L(2.0f), L(kNaN)));
  expect_all(s.x, 0.0f, "saturate float4 x");
  expect_all(s.y, 0.5f, "saturate float4 y");
  expect_all(s.z, 1.0f, "saturate float4 z");
  expect_all(s.w, 0.0f, "saturate float4 w");
  const float3<L> l = lerp(a, b, L(0.5f));
  expect_all(l.y, -1.5f, "lerp float3 by a scalar");
  const float2<L> p = pow(float2<L>(L(4.0f), L(9.0f)), 0.5f);
  expect_all(p.x, 2.0f, "pow float2 x");
  expect_near_all(p.y, 3.0f, 4e-7f, "pow float2 y");
}

TYPED_TEST(Intrinsics, MatrixMul) {
  using L = TypeParam;
  const float3x3<L> m(float3<L>(L(1.0f), L(2.0f), L(3.0f)), float3<L>(L(4.0f), L(5.0f), L(6.0f)),
                      float3<L>(L(7.0f), L(8.0f), L(9.0f)));
  const float3<L> v(L(1.0f), L(0.0f), L(-1.0f));
  const float3<L> mv = mul(m, v);  // rows . v
  expect_all(mv.x, -2.0f, "mul(M, v).x");
  expect_all(mv.y, -2.0f, "mul(M, v).y");
  expect_all(mv.z, -2.0f, "mul(M, v).z");
  const float3<L> vm = mul(v, m);  // v . columns
  expect_all(vm.x, -6.0f, "mul(v, M).x");
  expect_all(vm.y, -6.0f, "mul(v, M).y");
  expect_all(vm.z, -6.0f, "mul(v, M).z");
  const float3<L> tv = mul(transpose(m), v);
  expect_all(tv.x, -6.0f, "mul(transpose(M), v) = mul(v, M)");

  const glm::mat4 g(glm::vec4(1, 0, 0, 0), glm::vec4(0, 2, 0, 0), glm::vec4(0, 0, 3, 0), glm::vec4(5, 6, 7, 1));
  const float4x4<L> gm = constant<L>(g);
  const float4<L> moved = mul(gm, float4<L>(L(1.0f), L(1.0f), L(1.0f), L(1.0f)));
  expect_all(moved.x, 6.0f, "constant mat4 keeps glm's meaning: (M v).x");
  expect_all(moved.z, 10.0f, "(M v).z");
}

TYPED_TEST(Intrinsics, SelectIsThePerLaneIf) {
  using L = TypeParam;
  const L x = make_lanes<L>([](int i) { return i % 2 ? -1.0f - i : 1.0f + i; });
  const L y = select(x >= 0.0f, x, L(0.0f));  // if (x >= 0) y = x; else y = 0;
  for (int i = 0; i < testing::kWidth<L>; ++i) EXPECT_EQ(lane_of(y, i), i % 2 ? 0.0f : 1.0f + i);

  const float3<L> v(L(-1.0f), L(2.0f), L(-3.0f));
  const float3<L> pos = select(v >= 0.0f, v, 0.0f);
  expect_all(pos.x, 0.0f, "per-component select x");
  expect_all(pos.y, 2.0f, "per-component select y");
  const float3<L> either = select(x >= 0.0f && x < 100.0f, v, -v);
  for (int i = 0; i < testing::kWidth<L>; ++i) EXPECT_EQ(lane_of(either.y, i), i % 2 ? -2.0f : 2.0f);
}

TYPED_TEST(Intrinsics, ArithmeticBroadcastsLikeHlsl) {
  using L = TypeParam;
  float3<L> v(L(1.0f), L(2.0f), L(3.0f));
  const float3<L> w = 2.0f * v + 1.0f;
  expect_all(w.z, 7.0f, "2 v + 1");
  v *= L(0.5f);
  expect_all(v.y, 1.0f, "v *= s");
  const float4<L> c(v, 1.0f);
  expect_all(c.w, 1.0f, "float4(float3, 1)");
  expect_all(c.rgb().y, 1.0f, ".rgb");
  expect_all(swizzle<3, 0>(c).x, 1.0f, "swizzle<3, 0>");
  expect_all((-v).x, -0.5f, "negate");
  expect_all((v / 2.0f).z, 0.75f, "divide by a literal");
}

TEST(Constants, NumericLanesReadTheValue) {
  const glm::vec3 tint(0.25f, 0.5f, 1.0f);
  const float3<float> s = constant<float>(tint);
  EXPECT_EQ(s.y, 0.5f);
  const float3<simd::Float> v = constant<simd::Float>(tint);
  for (int i = 0; i < simd::kLanes; ++i) EXPECT_EQ(lane_of(v.z, i), 1.0f);
}

}  // namespace
}  // namespace luxel::shading
