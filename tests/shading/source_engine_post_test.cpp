// Engine_Post's combine (docs/fidelity.md#bloom): the bloom is added before the lookups read the sum,
// the blend is the formula's at colors where a missing term or the wrong order shows, SIMD and
// scalar lanes agree in bits, and every combo fits every pixel-shader model with the frame's and
// the bloom's fetches before the lookups' dependent reads.

#include "source_support.hpp"

#include "luxel/shading/source/engine_post.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>

namespace luxel::shading::source {
namespace {

using testing::compare_lanes;
using testing::Draw;
using testing::expect_bit_identical;

TEST(SourceEnginePost, BloomIsAddedBeforeTheLookupsAndUnclamped) {
  EnginePostParams p;
  p.bloom_factor = 1.0f;
  const float3<float> frame(0.8f, 0.3f, 0.55f), bloom(0.35f, 0.125f, 0.0625f);
  const float3<float> bloomed = engine_post_bloomed(frame, bloom, p);
  EXPECT_FLOAT_EQ(bloomed.x, 1.15f) << "a sum above 1 is kept: the volume's sampler clamps it, the write saturates it";
  EXPECT_FLOAT_EQ(bloomed.y, 0.425f);
  p.bloom_factor = 0.0f;
  EXPECT_EQ(engine_post_bloomed(frame, bloom, p).z, 0.55f) << "bloomFactor 0 leaves the frame";
}

TEST(SourceEnginePost, BlendIsTheBloomedFrameTimesDefaultPlusWeightedLookups) {
  EnginePostParams p;
  p.lut_weights = glm::vec4(0.25f, 0.5f, 0.125f, 0.0625f);
  p.default_weight = 0.0625f;
  const float3<float> frame(0.6f, 0.3f, 0.55f), bloom(0.2f, 0.05f, 0.4f);
  const std::array<float3<float>, 4> lookups = {float3<float>(0.1f, 0.9f, 0.4f), float3<float>(0.7f, 0.2f, 0.35f),
                                                float3<float>(0.05f, 0.6f, 1.0f), float3<float>(0.95f, 0.45f, 0.15f)};
  for_each_combo<kEnginePostSpace>([&]<EnginePostCombo C>() {
    const float3<float> out = color_correction_combine<C.correction()>(engine_post_bloomed(frame, bloom, p), lookups,
                                                                       p.lut_weights, p.default_weight);
    for (int c = 0; c < 3; ++c) {
      double expect = (double(frame[c]) + bloom[c]) * p.default_weight;
      for (int k = 0; k < C.luts; ++k) expect += double(lookups[k][c]) * p.lut_weights[k];
      EXPECT_NEAR(out[c], expect, 1e-6) << C.name() << " channel " << c;
    }
  });
}

TEST(SourceEnginePost, SimdAgreesWithScalarInBits) {
  EnginePostParams p;
  p.lut_weights = glm::vec4(0.3f, 0.2f, 0.15f, 0.1f);
  p.default_weight = 0.25f;
  for_each_combo<kEnginePostSpace>([&]<EnginePostCombo C>() {
    for (int hard_every : {0, 4}) {
      auto shade = [&]<class L>(const auto& get) -> float4<L> {
        const float3<L> bloomed = engine_post_bloomed(float3<L>(get(0), get(1), get(2)), float3<L>(get(3), get(4), get(5)), p);
        std::array<float3<L>, 4> lookups;
        for (int k = 0; k < 4; ++k) lookups[k] = float3<L>(get(6 + 3 * k), get(7 + 3 * k), get(8 + 3 * k));
        return float4<L>(color_correction_combine<C.correction()>(bloomed, lookups, p.lut_weights, p.default_weight), get(0));
      };
      const auto r = compare_lanes<18>(shade, {Draw{0.0f, 1.0f, hard_every}}, 512, 11u + C.luts);
      expect_bit_identical(r, C.name());
    }
  });
}

TEST(SourceEnginePost, EveryComboFitsEveryPixelShaderModel) {
  for_each_combo<kEnginePostSpace>([&]<EnginePostCombo C>() {
    for (ShaderModel m : kPixelModels) {
      const Cost cost = measure_engine_post<C>(m);
      const Verdict v = fits(cost, caps(m));
      EXPECT_TRUE(v) << C.name() << ": " << v.reason;
      EXPECT_EQ(cost.texture_slots, 2 + C.luts) << C.name() << " " << describe(cost);
      EXPECT_EQ(cost.samplers, 2 + C.luts) << C.name();
      // The frame's read, the bloom's (its coordinate is the varying's .zw, which ps_2_x cannot
      // read a texture at without first moving it to a temp), then the lookups.
      EXPECT_EQ(cost.texture_indirections, 3) << C.name();
      // colorcorrection_ps2x's slots (color_correction_test) plus one mad for the bloom; ps_2_x
      // also moves the output to oC0 and the bloom's coordinate to a temp.
      const int ps2x_moves = m == ShaderModel::ps_3_0 ? 0 : 2;
      EXPECT_EQ(cost.arithmetic_slots, 3 + C.luts + ps2x_moves) << C.name() << " " << describe(cost);
      std::printf("Engine_Post %s %s\n", C.name().c_str(), describe(cost).c_str());
    }
  });
}

}  // namespace
}  // namespace luxel::shading::source
