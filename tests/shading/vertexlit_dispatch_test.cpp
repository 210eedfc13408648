// VertexLitGeneric's choice of shader against the SDK helper's rules (vertexlit_dispatch.hpp,
// docs/fidelity.md#which-shader-a-model-gets): every combination of the parameters that choose,
// on every pixel-shader model, against the rules written out here as the helper states them.

#include "luxel/shading/source/vertexlit_dispatch.hpp"

#include <gtest/gtest.h>

namespace luxel::shading::source {
namespace {

TEST(VertexLitDispatch, FollowsWantsSkinShaderOnEveryModel) {
  for (int bits = 0; bits < 32; ++bits) {
    const VertexLitMaterial m{bool(bits & 1), bool(bits & 2), bool(bits & 4), bool(bits & 8), bool(bits & 16)};
    for (ShaderModel card : {ShaderModel::ps_2_0, ShaderModel::ps_2_b, ShaderModel::ps_3_0}) {
      SCOPED_TRACE(bits);
      SCOPED_TRACE(std::string(caps(card).name));
      // WantsSkinShader: $phong and (lightwarp, or $basemapalphaphongmask 1, or a bump map); the
      // draw needs ps_2_b. Otherwise the bumped path for a bump map or a lightwarp, else the plain one.
      const bool skin = m.phong && (m.lightwarp || m.base_map_alpha_phong_mask || m.bump) && card != ShaderModel::ps_2_0;
      const VertexLitPath expected = skin ? VertexLitPath::skin : (m.bump || m.lightwarp) ? VertexLitPath::bumped : VertexLitPath::plain;
      EXPECT_EQ(vertexlit_path(m, card), expected);
      // The skin shader always lights with Half-Lambert; the ordinary paths as $halflambert says.
      EXPECT_EQ(vertexlit_half_lambert(m, vertexlit_path(m, card)), skin || m.half_lambert);
    }
  }
}

TEST(VertexLitDispatch, PhongWithoutBumpIsTheOrdinaryPath) {
  const VertexLitMaterial phong_only{.phong = true};
  EXPECT_FALSE(wants_skin_shader(phong_only));
  EXPECT_EQ(vertexlit_path(phong_only, ShaderModel::ps_3_0), VertexLitPath::plain);
  EXPECT_FALSE(vertexlit_half_lambert(phong_only, VertexLitPath::plain));
  const VertexLitMaterial bumped{.phong = true, .bump = true};
  EXPECT_EQ(vertexlit_path(bumped, ShaderModel::ps_2_b), VertexLitPath::skin);
  EXPECT_EQ(vertexlit_path(bumped, ShaderModel::ps_2_0), VertexLitPath::bumped);
}

}  // namespace
}  // namespace luxel::shading::source
