// The Counted lane: DX9 slot counts of small known snippets, macro costs, free modifiers,
// dependent-read depth, constant and temp counting, and caps checks that reject what fxc would.

#include "luxel/shading/hlsl.hpp"

#include <gtest/gtest.h>

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace luxel::shading {
namespace {

using C = Counted;

/// Arithmetic slots of a one-output snippet, without the `mov oC0` shader model 2 adds.
template <class Body>
int slots(ShaderModel model, Body&& body) {
  const Cost cost = measure(model, body);
  return cost.arithmetic_slots - (caps(model).output_by_mov_only ? 1 : 0);
}

// ---- The ambient cube (docs/fidelity.md#ambient-cube), in our words -------------------------

struct AmbientCube {
  glm::vec3 color[6];  ///< +X, -X, +Y, -Y, +Z, -Z
};

/// n^2-weighted blend of the cube side each normal component faces.
template <class L>
float3<L> ambient_cube_light(const float3<L>& n, const AmbientCube& cube) {
  const float3<L> n2 = n * n;
  const bool3<L> facing_plus = n >= 0.0f;
  const float3<L> plus = select(facing_plus, n2, 0.0f);
  const float3<L> minus = select(facing_plus, 0.0f, n2);
  return plus.x * constant<L>(cube.color[0]) + minus.x * constant<L>(cube.color[1]) +
         plus.y * constant<L>(cube.color[2]) + minus.y * constant<L>(cube.color[3]) +
         plus.z * constant<L>(cube.color[4]) + minus.z * constant<L>(cube.color[5]);
}

TEST(Counted, AmbientCubeCountsNinePixelInstructions) {
  const AmbientCube cube{};
  // mul (n^2), cmp, cmp (the comparisons with 0 are cmp's own test), then six products summed:
  // the first product is a mul, the other five ride on the adds as mads. 1 + 2 + 1 + 5 = 9, the
  // count Valve's comment gives ("now only 9": mul, cmp, cmp, mul, mad x5). ps_2_0 adds the
  // mov to oC0.
  const Cost ps20 = measure(ShaderModel::ps_2_0, [&](CountedInputs& in) {
    return ambient_cube_light<C>(in.vector<3>(), cube);
  });
  EXPECT_EQ(ps20.arithmetic_slots, 10) << describe(ps20);
  EXPECT_EQ(ps20.texture_slots, 0);
  EXPECT_EQ(ps20.uniform_registers, 6);
  EXPECT_EQ(ps20.literal_registers, 1) << "the 0 the selects write";
  EXPECT_EQ(ps20.inputs, 1);
  EXPECT_GE(ps20.temps, 2);
  EXPECT_LE(ps20.temps, 4) << describe(ps20);
  EXPECT_TRUE(fits(ps20, caps(ShaderModel::ps_2_0))) << fits(ps20, caps(ShaderModel::ps_2_0)).reason;

  const Cost ps30 = measure(ShaderModel::ps_3_0, [&](CountedInputs& in) {
    return ambient_cube_light<C>(in.vector<3>(), cube);
  });
  EXPECT_EQ(ps30.arithmetic_slots, 9) << describe(ps30);
}

// ---- Macro costs ---------------------------------------------------------------------------

TEST(Counted, MacroCostsAsTheDx9TablesGiveThem) {
  const auto m = ShaderModel::ps_2_0;
  glm::mat3 m3(1.0f);
  glm::mat4 m4(1.0f);
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return normalize(in.vector<3>()); }), 3) << "nrm";
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return normalize(in.vector<4>()); }), 3) << "dp4 + rsq + mul";
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return pow(in.scalar(), in.scalar()); }), 3) << "pow";
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return pow(in.vector<3>(), in.scalar()); }), 7)
      << "3 log + mul + 3 exp: log/exp are scalar instructions";
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return lerp(in.vector<3>(), in.vector<3>(), in.scalar()); }), 2)
      << "lrp (as add + mad)";
  EXPECT_EQ(slots(m, [&](CountedInputs& in) { return mul(constant<C>(m3), in.vector<3>()); }), 3) << "m3x3";
  EXPECT_EQ(slots(m, [&](CountedInputs& in) { return mul(constant<C>(m4), in.vector<4>()); }), 4) << "m4x4";
  EXPECT_EQ(slots(m, [&](CountedInputs& in) { return mul(in.vector<3>(), constant<C>(m3)); }), 3)
      << "row vector: mul + 2 mad";
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return cross(in.vector<3>(), in.vector<3>()); }), 2) << "crs";
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return dot(in.vector<3>(), in.vector<3>()); }), 1) << "dp3";
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return dot(in.vector<4>(), in.vector<4>()); }), 1) << "dp4";
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return dot(in.vector<2>(), in.vector<2>()); }), 2) << "dp2add";
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return length(in.vector<3>()); }), 3) << "dp3 + rsq + rcp";
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return sqrt(in.scalar()); }), 2) << "rsq + rcp";
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return exp2(in.vector<3>()); }), 3) << "exp per component";
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return rcp(in.vector<2>()); }), 2) << "rcp per component";
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return in.vector<3>() / in.scalar(); }), 2) << "rcp + mul";
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return in.vector<3>() / in.vector<3>(); }), 4) << "3 rcp + mul";
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return in.vector<3>() / 2.0f; }), 1) << "mul by 1/2";
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return frac(in.vector<4>()); }), 1) << "frc";
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return floor(in.vector<4>()); }), 2) << "frc + add";
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return min(in.vector<3>(), in.vector<3>()); }), 1) << "min";
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return reflect(in.vector<3>(), in.vector<3>()); }), 3)
      << "dp3, mul by 2, mad";
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return step(0.0f, in.scalar()); }), 1) << "cmp against 0";
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return step(0.5f, in.scalar()); }), 2) << "add + cmp";
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return smoothstep(0.0f, 1.0f, in.scalar()); }), 4)
      << "(x - 0) / 1 is x: mov_sat t; then mul t*t, mad 3 - 2t, mul";
}

TEST(Counted, SinCosIsTheEightSlotMacroPlusFxcsRangeReduction) {
  // mad (x / 2 pi + 1/2), frc, mad (back to [-pi, pi)), sincos 8: 11.
  EXPECT_EQ(slots(ShaderModel::ps_2_0, [](CountedInputs& in) { return sin(in.scalar()); }), 11);
  EXPECT_EQ(slots(ShaderModel::ps_2_0,
                  [](CountedInputs& in) {
                    C s, c;
                    sincos(in.scalar(), s, c);
                    return s * c;
                  }),
            12)
      << "one sincos gives both";
  EXPECT_EQ(slots(ShaderModel::ps_2_0, [](CountedInputs& in) { return sin(in.vector<3>()); }), 3 + 3 * 8)
      << "sincos is scalar: the reduction is 3 vector slots, then 8 per component";
  EXPECT_EQ(measure(ShaderModel::ps_2_0, [](CountedInputs& in) { return sin(in.scalar()); }).literal_registers, 3)
      << "two registers of sincos series constants (D3DSINCOSCONST1/2) + the reduction's 4";
  EXPECT_EQ(measure(ShaderModel::ps_3_0, [](CountedInputs& in) { return sin(in.scalar()); }).literal_registers, 1)
      << "ps_3_0's sincos needs no constants";
}

TEST(Counted, ClipIsATexkillKeptForItsEffect) {
  const Cost cost = measure(ShaderModel::ps_2_0, [](CountedInputs& in) {
    const float4<C> color = in.vector<4>();
    clip(color.a() - 0.5f);  // the mask goes to PixelOutput::discard; nothing reads it here
    return color;
  });
  EXPECT_EQ(cost.texture_slots, 1) << "texkill";
  EXPECT_EQ(cost.arithmetic_slots, 2) << "add, mov oC0";
  EXPECT_FALSE(fits(measure(ShaderModel::vs_3_0, [](CountedInputs& in) {
                      clip(in.scalar());
                      return in.scalar();
                    }),
                    caps(ShaderModel::vs_3_0)));
}

TEST(Counted, ReadingAnUnassignedValueThrows) {
  EXPECT_THROW(measure(ShaderModel::ps_2_0,
                       [](CountedInputs& in) {
                         C never_set;
                         return in.scalar() + never_set;
                       }),
               std::logic_error);
}

TEST(Counted, ScalarInstructionsCountPerDistinctComponent) {
  EXPECT_EQ(slots(ShaderModel::ps_2_0, [](CountedInputs& in) { return rsqrt(float3<C>(in.scalar())); }), 1)
      << "a broadcast scalar needs one rsq";
}

// ---- Modifiers ----------------------------------------------------------------------------

TEST(Counted, NegationIsAFreeSourceModifier) {
  const auto m = ShaderModel::ps_2_0;
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return in.vector<3>() - in.vector<3>(); }), 1) << "add with -src";
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return -in.vector<3>() * in.scalar(); }), 1);
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return in.vector<3>() - in.vector<3>() * in.vector<3>(); }), 1)
      << "mad with a negated source";
}

TEST(Counted, AbsIsAnInstructionBeforeShaderModel3) {
  auto body = [](CountedInputs& in) { return abs(in.vector<3>()) * in.scalar(); };
  EXPECT_EQ(slots(ShaderModel::ps_2_0, body), 2) << "ps_2_0 has no _abs modifier: abs + mul";
  EXPECT_EQ(slots(ShaderModel::ps_2_b, body), 2);
  EXPECT_EQ(slots(ShaderModel::ps_3_0, body), 1) << "ps_3_0: mul r, |v|, s";
}

TEST(Counted, SaturateIsTheFreeSatModifierOfAFreshResult) {
  const auto ps = ShaderModel::ps_2_0;
  EXPECT_EQ(slots(ps, [](CountedInputs& in) { return saturate(in.vector<3>() * in.scalar()); }), 1) << "mul_sat";
  EXPECT_EQ(slots(ps, [](CountedInputs& in) { return saturate(dot(in.vector<3>(), in.vector<3>())); }), 1)
      << "dp3_sat";
  EXPECT_EQ(slots(ps, [](CountedInputs& in) { return saturate(in.vector<3>() * in.scalar() + in.vector<3>()); }), 1)
      << "mad_sat";
  EXPECT_EQ(slots(ps, [](CountedInputs& in) { return saturate(in.vector<3>()); }), 1)
      << "an input is nobody's result: mov_sat";
  EXPECT_EQ(slots(ps,
                  [](CountedInputs& in) {
                    const float3<C> x = in.vector<3>() * in.scalar();
                    return saturate(x) + x;  // x is needed unsaturated too
                  }),
            3)
      << "mul, mov_sat, add";
  EXPECT_EQ(slots(ps, [](CountedInputs& in) { return saturate(frac(in.vector<3>())); }), 2)
      << "frc cannot take _sat";
  EXPECT_EQ(slots(ShaderModel::vs_2_0, [](CountedInputs& in) { return saturate(in.vector<3>() * in.scalar()); }), 3)
      << "vs_2_0 has no _sat: mul, max, min";
  EXPECT_EQ(slots(ShaderModel::vs_3_0, [](CountedInputs& in) { return saturate(in.vector<3>() * in.scalar()); }), 1)
      << "vs_3_0 has _sat";
}

TEST(Counted, ShaderModel2WritesOutputsWithMov) {
  auto body = [](CountedInputs& in) { return in.vector<4>() * in.scalar(); };
  EXPECT_EQ(measure(ShaderModel::ps_2_0, body).arithmetic_slots, 2) << "mul r0, mov oC0, r0";
  EXPECT_EQ(measure(ShaderModel::ps_3_0, body).arithmetic_slots, 1) << "mul oC0";
}

// ---- What fxc drops or merges -------------------------------------------------------------

TEST(Counted, DeadCodeIsNotCounted) {
  const Cost cost = measure(ShaderModel::ps_2_0, [](CountedInputs& in) {
    const float3<C> n = in.vector<3>();
    const float3<C> unused = normalize(n) * pow(n.x, 8.0f);  // never reaches the output
    (void)unused;
    return n * 2.0f;
  });
  EXPECT_EQ(cost.arithmetic_slots, 2) << describe(cost);
  EXPECT_EQ(cost.literal_registers, 1) << "only the 2 is live; the 8 died with its pow";
}

TEST(Counted, MulFeedingOneAddIsAMad) {
  const auto m = ShaderModel::ps_3_0;
  EXPECT_EQ(slots(m, [](CountedInputs& in) { return in.vector<3>() * in.vector<3>() + in.vector<3>(); }), 1);
  EXPECT_EQ(slots(m,
                  [](CountedInputs& in) {
                    const float3<C> p = in.vector<3>() * in.vector<3>();
                    return p + in.vector<3>() + p;  // p read twice: no fusion
                  }),
            3);
}

TEST(Counted, LiteralsFoldAndCountFourToARegister) {
  const Cost cost = measure(ShaderModel::ps_2_0, [](CountedInputs& in) {
    const C folded = C(2.0f) * C(3.0f);  // no instruction: fxc folds it
    const C x = in.scalar();
    return x * folded + x * 0.5f + x * 0.25f + x * 0.125f + x * 0.0625f;
  });
  EXPECT_EQ(cost.arithmetic_slots, 5 + 1) << describe(cost);
  EXPECT_EQ(cost.literal_registers, 2) << "six, 0.5, 0.25, 0.125, 0.0625: five literals, two def registers";
}

TEST(Counted, CountedOutsideMeasureThrows) { EXPECT_THROW(Counted(1.0f), std::logic_error); }

// ---- Dependent reads ----------------------------------------------------------------------

TEST(Counted, DependentReadLevels) {
  const Sampler2D s0{0}, s1{1}, s2{2}, s3{3}, s4{4};
  auto chain = [&](int depth) {
    return [&, depth](CountedInputs& in) {
      float4<C> c = tex2D(s0, in.vector<2>());  // level 1: an unmodified input register
      const Sampler2D* next[] = {&s1, &s2, &s3, &s4};
      for (int i = 1; i < depth; ++i) c = tex2D(*next[i - 1], c.xy());  // each read one level deeper
      return c;
    };
  };
  for (int depth = 1; depth <= 5; ++depth) {
    const Cost cost = measure(ShaderModel::ps_2_0, chain(depth));
    EXPECT_EQ(cost.texture_indirections, depth);
    EXPECT_EQ(cost.texture_slots, depth);
    EXPECT_EQ(cost.samplers, depth);
  }
  const Cost five = measure(ShaderModel::ps_2_0, chain(5));
  const Verdict v20 = fits(five, caps(ShaderModel::ps_2_0));
  EXPECT_FALSE(v20);
  EXPECT_NE(v20.reason.find("5 levels of texture indirection > 4"), std::string::npos) << v20.reason;
  EXPECT_FALSE(fits(measure(ShaderModel::ps_2_b, chain(5)), caps(ShaderModel::ps_2_b))) << "ps_2_b keeps the 4";
  EXPECT_TRUE(fits(measure(ShaderModel::ps_3_0, chain(5)), caps(ShaderModel::ps_3_0)));
  EXPECT_TRUE(fits(measure(ShaderModel::ps_2_0, chain(4)), caps(ShaderModel::ps_2_0)));
}

TEST(Counted, ComputedCoordinatesAreAFirstOrderDependentRead) {
  const Sampler2D base{0};
  // uv * scale lives in a temporary register: "texld - ps_2_0 and up" calls that first-order
  // dependent, like a read whose coordinates come from another texture.
  const Cost scaled = measure(ShaderModel::ps_2_0, [&](CountedInputs& in) { return tex2D(base, in.vector<2>() * 4.0f); });
  EXPECT_EQ(scaled.texture_indirections, 2);
  EXPECT_EQ(scaled.arithmetic_slots, 1 + 1) << "mul + mov oC0";
  // Source packs two uv sets in one texcoord; the .zw pair must be moved to a temp first.
  const Cost packed = measure(ShaderModel::ps_2_0, [&](CountedInputs& in) { return tex2D(base, in.vector<4>().zw()); });
  EXPECT_EQ(packed.texture_indirections, 2);
  EXPECT_EQ(packed.arithmetic_slots, 1 + 1) << "mov r0.xy, t0.wz... + mov oC0";
  const Cost direct = measure(ShaderModel::ps_2_0, [&](CountedInputs& in) { return tex2D(base, in.vector<4>().xy()); });
  EXPECT_EQ(direct.texture_indirections, 1) << "texld r0, t0 reads .xy in place";
  EXPECT_EQ(direct.arithmetic_slots, 1) << "only mov oC0";
  const Cost swizzled30 = measure(ShaderModel::ps_3_0, [&](CountedInputs& in) { return tex2D(base, in.vector<4>().zw()); });
  EXPECT_EQ(swizzled30.arithmetic_slots, 0) << "ps_3_0 swizzles texture coordinates freely";
}

TEST(Counted, TextureOpsTheModelLacks) {
  const Sampler2D s{0};
  auto lod = [&](CountedInputs& in) { return tex2Dlod(s, in.vector<4>()); };
  const Verdict v = fits(measure(ShaderModel::ps_2_0, lod), caps(ShaderModel::ps_2_0));
  EXPECT_FALSE(v);
  EXPECT_NE(v.reason.find("texldl"), std::string::npos) << v.reason;
  const Cost ps30 = measure(ShaderModel::ps_3_0, lod);
  EXPECT_TRUE(fits(ps30, caps(ShaderModel::ps_3_0)));
  EXPECT_EQ(ps30.texture_slots, 2) << "texldl";
  EXPECT_TRUE(fits(measure(ShaderModel::ps_2_0, [&](CountedInputs& in) { return tex2Dbias(s, in.vector<4>()); }),
                   caps(ShaderModel::ps_2_0)))
      << "texldb is ps_2_0";
  EXPECT_FALSE(fits(measure(ShaderModel::vs_2_0, lod), caps(ShaderModel::vs_2_0))) << "vs_2_0 samples nothing";
  auto grad = [&](CountedInputs& in) { return tex2Dgrad(s, in.vector<2>(), in.vector<2>(), in.vector<2>()); };
  EXPECT_FALSE(fits(measure(ShaderModel::ps_2_b, grad), caps(ShaderModel::ps_2_b))) << "no texldd on ps_2_b";
  EXPECT_EQ(measure(ShaderModel::ps_3_0, grad).texture_slots, 3) << "texldd";
  EXPECT_TRUE(fits(measure(ShaderModel::vs_3_0, lod), caps(ShaderModel::vs_3_0)));
  EXPECT_FALSE(fits(measure(ShaderModel::vs_3_0, [&](CountedInputs& in) { return tex2D(s, in.vector<2>()); }),
                    caps(ShaderModel::vs_3_0)))
      << "vertex textures need tex2Dlod";
}

// ---- Limits -------------------------------------------------------------------------------

TEST(Counted, OverBudgetArithmeticIsRejectedReadably) {
  const glm::vec4 k(0.5f);
  auto long_chain = [&](CountedInputs& in) {
    float4<C> x = in.vector<4>();
    for (int i = 0; i < 70; ++i) x = x * constant<C>(k) + x;  // one mad each
    return x;
  };
  const Cost cost = measure(ShaderModel::ps_2_0, long_chain);
  EXPECT_EQ(cost.arithmetic_slots, 70 + 1);
  const Verdict v = fits(cost, caps(ShaderModel::ps_2_0));
  EXPECT_FALSE(v);
  EXPECT_EQ(v.reason, "ps_2_0: 71 arithmetic slots > 64");
  EXPECT_TRUE(fits(measure(ShaderModel::ps_2_b, long_chain), caps(ShaderModel::ps_2_b)));
}

TEST(Counted, OverFiveHundredTwelveSlotsIsRefusedOnPs2bAndPs30) {
  const glm::vec4 k(0.5f);
  auto chain = [&](int n) {
    return [&, n](CountedInputs& in) {
      float4<C> x = in.vector<4>();
      for (int i = 0; i < n; ++i) x = x * constant<C>(k) + x;  // one mad each
      return x;
    };
  };
  for (ShaderModel m : {ShaderModel::ps_2_b, ShaderModel::ps_3_0}) {
    const int out = m == ShaderModel::ps_2_b ? 1 : 0;  // shader model 2 writes oC0 with a mov
    const Cost at_limit = measure(m, chain(512 - out));
    EXPECT_EQ(at_limit.total_slots(), 512);
    EXPECT_TRUE(fits(at_limit, caps(m))) << caps(m).name;
    const Cost over = measure(m, chain(513 - out));
    const Verdict v = fits(over, caps(m));
    EXPECT_FALSE(v) << caps(m).name;
    EXPECT_EQ(v.reason, std::string(caps(m).name) + ": 513 instruction slots > 512");
  }
}

TEST(Counted, OverThirtyTwoTempsIsRefusedOnPs2bAndPs30) {
  auto live = [](int n) {
    return [n](CountedInputs& in) {
      const float4<C> x = in.vector<4>();
      std::vector<float4<C>> p(static_cast<size_t>(n));
      for (int i = 0; i < n; ++i) p[i] = x * float(i + 2);  // n float4 values, all alive...
      float4<C> m = p[0];
      for (int i = 1; i < n; ++i) m = max(m, p[i]);  // ...until they are folded together here
      return m;
    };
  };
  for (ShaderModel m : {ShaderModel::ps_2_b, ShaderModel::ps_3_0}) {
    const Cost at_limit = measure(m, live(32));
    EXPECT_EQ(at_limit.temps, 32) << describe(at_limit);
    EXPECT_TRUE(fits(at_limit, caps(m))) << caps(m).name << ": " << fits(at_limit, caps(m)).reason;
    const Cost over = measure(m, live(33));
    EXPECT_EQ(over.temps, 33) << describe(over);
    const Verdict v = fits(over, caps(m));
    EXPECT_FALSE(v) << caps(m).name;
    EXPECT_EQ(v.reason, std::string(caps(m).name) + ": 33 temporaries alive at once (estimate) > 32");
  }
}

TEST(Counted, TooManyTextureSlotsOnPs20) {
  // 33 different fetches (no two alike: fxc would merge identical ones): 5 uv sets x 8 samplers.
  std::array<Sampler2D, 8> samplers;
  for (int i = 0; i < 8; ++i) samplers[i].slot = i;
  auto fetches = [&](CountedInputs& in) {
    std::array<float2<C>, 5> uv;
    for (auto& u : uv) u = in.vector<2>();
    float4<C> sum = tex2D(samplers[0], uv[0]);
    for (int i = 1; i < 33; ++i) sum = sum + tex2D(samplers[i % 8], uv[i / 8]);
    return sum;
  };
  const Verdict v = fits(measure(ShaderModel::ps_2_0, fetches), caps(ShaderModel::ps_2_0));
  EXPECT_FALSE(v);
  EXPECT_NE(v.reason.find("33 texture slots > 32"), std::string::npos) << v.reason;
  EXPECT_TRUE(fits(measure(ShaderModel::ps_2_b, fetches), caps(ShaderModel::ps_2_b)));
}

TEST(Counted, ConstantRegistersAreCountedPerDeclaredObject) {
  std::array<glm::vec4, 33> params{};
  auto uses = [&](int n) {
    return [&, n](CountedInputs& in) {
      const float4<C> x = in.vector<4>();
      float4<C> sum = x * constant<C>(params[0]);
      for (int i = 1; i < n; ++i) sum = sum + x * constant<C>(params[i]);
      sum = sum + constant<C>(params[0]);  // the same register again: still one
      return sum;
    };
  };
  EXPECT_EQ(measure(ShaderModel::ps_2_0, uses(32)).uniform_registers, 32);
  EXPECT_TRUE(fits(measure(ShaderModel::ps_2_b, uses(32)), caps(ShaderModel::ps_2_b)));
  const Verdict v = fits(measure(ShaderModel::ps_2_b, uses(33)), caps(ShaderModel::ps_2_b));
  EXPECT_FALSE(v);
  EXPECT_NE(v.reason.find("33 constant registers > 32"), std::string::npos) << v.reason;
  EXPECT_TRUE(fits(measure(ShaderModel::ps_3_0, uses(33)), caps(ShaderModel::ps_3_0))) << "224 on ps_3_0";
}

TEST(Counted, TemporariesAliveAtOnce) {
  std::array<glm::vec4, 13> params{};
  auto live = [&](int n) {
    return [&, n](CountedInputs& in) {
      const float4<C> x = in.vector<4>();
      std::array<float4<C>, 13> p;
      for (int i = 0; i < n; ++i) p[i] = x * constant<C>(params[i]);  // n float4 values, all alive...
      float4<C> m = p[0];
      for (int i = 1; i < n; ++i) m = max(m, p[i]);  // ...until they are folded together here
      return m;
    };
  };
  EXPECT_EQ(measure(ShaderModel::ps_2_0, live(12)).temps, 12);
  const Cost thirteen = measure(ShaderModel::ps_2_0, live(13));
  EXPECT_EQ(thirteen.temps, 13);
  const Verdict v = fits(thirteen, caps(ShaderModel::ps_2_0));
  EXPECT_FALSE(v);
  EXPECT_NE(v.reason.find("13 temporaries alive at once"), std::string::npos) << v.reason;
  EXPECT_TRUE(fits(measure(ShaderModel::ps_2_b, live(13)), caps(ShaderModel::ps_2_b))) << "32 temps on ps_2_b";

  // Scalars share registers (write masks): eight live dp3 results fit in two.
  std::array<glm::vec3, 8> axes{};
  const Cost scalars = measure(ShaderModel::ps_2_0, [&](CountedInputs& in) {
    const float3<C> n = in.vector<3>();
    std::array<C, 8> d;
    for (int i = 0; i < 8; ++i) d[i] = dot(n, constant<C>(axes[i]));
    C sum = d[0];
    for (int i = 1; i < 8; ++i) sum = max(sum, d[i]);
    return sum;
  });
  EXPECT_EQ(scalars.temps_unpacked, 8);
  EXPECT_EQ(scalars.temps, 2);
}

TEST(Counted, CapsTableMatchesTheDocumentation) {
  EXPECT_EQ(caps(ShaderModel::ps_2_0).arithmetic_slots, 64);
  EXPECT_EQ(caps(ShaderModel::ps_2_0).texture_slots, 32);
  EXPECT_EQ(caps(ShaderModel::ps_2_0).temps, 12);
  EXPECT_EQ(caps(ShaderModel::ps_2_0).constants, 32);
  EXPECT_EQ(caps(ShaderModel::ps_2_0).texture_indirections, 4);
  EXPECT_EQ(caps(ShaderModel::ps_2_b).total_slots, 512);
  EXPECT_EQ(caps(ShaderModel::ps_2_b).temps, 32);
  EXPECT_EQ(caps(ShaderModel::ps_3_0).total_slots, 512);
  EXPECT_EQ(caps(ShaderModel::ps_3_0).constants, 224);
  EXPECT_EQ(caps(ShaderModel::vs_2_0).total_slots, 256);
  EXPECT_EQ(caps(ShaderModel::vs_3_0).temps, 32);
}

}  // namespace
}  // namespace luxel::shading
