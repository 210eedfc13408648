// The film-grain shader (docs/fidelity.md#film-grain): its source color and alpha against the formula,
// its blend state, SIMD vs scalar, and its budget. The blend itself is checked on whole frames in
// tests/postfx/film_grain_test.cpp.

#include "source_support.hpp"

#include "luxel/shading/source/film_grain.hpp"

#include <gtest/gtest.h>

namespace luxel::shading::source {
namespace {

TEST(SourceFilmGrain, SourceColorAndAlphaFollowTheFormula) {
  FilmGrainParams p;
  p.noise_scale = glm::vec4(0.5f, 0.25f, 0.125f, 0.75f);
  const float4<float> out = film_grain_combine(float4<float>(0.5f, 0.25f, 1.0f, 0.0f), p);
  EXPECT_EQ(out.x, 0.25f);
  EXPECT_EQ(out.y, 0.0625f);
  EXPECT_EQ(out.z, 0.125f);
  EXPECT_EQ(out.w, 0.5f * 0.25f + 0.75f) << "n.r * (1 - w) + w";
  const rasterizer::PipelineState s = film_grain_pipeline_state();
  EXPECT_TRUE(s.blend.enable);
  EXPECT_EQ(s.blend.src, rasterizer::BlendFactor::One);
  EXPECT_EQ(s.blend.dst, rasterizer::BlendFactor::SrcAlpha);
  EXPECT_EQ(s.blend.op, rasterizer::BlendOp::Add);
  EXPECT_FALSE(s.blend.srgb_write);
}

TEST(SourceFilmGrain, SimdAgreesWithScalarExactly) {
  FilmGrainParams p;
  p.noise_scale = glm::vec4(0.1f, 0.2f, 0.3f, 0.6f);
  for (int hard_every : {0, 3}) {
    auto shade = [&]<class L>(const auto& get) {
      return film_grain_combine(float4<L>(get(0), get(1), get(2), get(3)), p);
    };
    testing::expect_bit_identical(testing::compare_lanes<4>(shade, {testing::Draw{0.0f, 1.0f, hard_every}}, 256, 9u),
                                  "filmgrain");
  }
}

TEST(SourceFilmGrain, FitsEveryPixelShaderModel) {
  for (ShaderModel m : kPixelModels) {
    const Cost cost = measure_film_grain(m);
    const Verdict v = fits(cost, caps(m));
    EXPECT_TRUE(v) << describe(cost) << ": " << v.reason;
    EXPECT_EQ(cost.texture_slots, 1) << describe(cost);
    EXPECT_LE(cost.arithmetic_slots, 4) << "a mul and a mad or two: " << describe(cost);
  }
}

}  // namespace
}  // namespace luxel::shading::source
