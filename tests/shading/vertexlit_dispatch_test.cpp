// VertexLitGeneric's choice of shader against the SDK helper's rules (vertexlit_dispatch.hpp,
// docs/fidelity.md#which-shader-a-model-gets): every combination of the parameters that choose,
// on every pixel-shader model, against the rules written out here as the helper states them;
// then the combo: the lights each path takes per card, and the env map's mask as the helpers
// leave the flags (docs/fidelity.md#env-maps-on-models).

#include "luxel/shading/source/vertexlit_dispatch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <utility>

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

TEST(VertexLitDispatch, LightsPerPathAndCard) {
  for (int wanted : {1, 2, 3, 4}) {
    EXPECT_EQ(vertexlit_max_lights(VertexLitPath::plain, ShaderModel::ps_3_0, wanted), std::min(wanted, 2));
    EXPECT_EQ(vertexlit_max_lights(VertexLitPath::bumped, ShaderModel::ps_2_0, wanted), std::min(wanted, 2));
    EXPECT_EQ(vertexlit_max_lights(VertexLitPath::bumped, ShaderModel::ps_2_b, wanted), wanted);
    EXPECT_EQ(vertexlit_max_lights(VertexLitPath::skin, ShaderModel::ps_3_0, wanted), wanted);
  }
  const VertexLitMaterial bumped{.bump = true};
  for (auto [kept, lights] : {std::pair{0, 0}, std::pair{1, 2}, std::pair{2, 2}, std::pair{3, 4}, std::pair{4, 4}})
    EXPECT_EQ(vertexlit_combo(bumped, VertexLitPath::bumped, kept, ShaderModel::ps_2_b, {}).lights, lights) << kept;
  for (ShaderModel card : {ShaderModel::ps_2_0, ShaderModel::ps_2_b, ShaderModel::ps_3_0})
    EXPECT_EQ(vertexlit_combo(bumped, VertexLitPath::bumped, 2, card, {}).normalization_cube, card == ShaderModel::ps_2_0);
}

TEST(VertexLitDispatch, SkinFullPathUnlessItsFastPathApplies) {
  const VertexLitMaterial mask_only{.phong = true, .base_map_alpha_phong_mask = true};
  const VertexLitCombo fast = vertexlit_combo(mask_only, VertexLitPath::skin, 2, ShaderModel::ps_2_b, {});
  EXPECT_TRUE(fast.phong);
  EXPECT_FALSE(fast.bump) << "FASTPATH_NOBUMP";
  EXPECT_TRUE(fast.half_lambert) << "the skin shader always";
  for (VertexLitMaterial m : {VertexLitMaterial{.phong = true, .bump = true}, VertexLitMaterial{.phong = true, .base_map_alpha_phong_mask = true, .exponent_texture = true},
                              VertexLitMaterial{.phong = true, .base_map_alpha_phong_mask = true, .rim = true}}) {
    const VertexLitCombo full = vertexlit_combo(m, VertexLitPath::skin, 2, ShaderModel::ps_2_b, {});
    EXPECT_TRUE(full.bump) << "the full path reads a (flat) normal map";
    EXPECT_EQ(full.rim, m.rim);
  }
}

TEST(VertexLitDispatch, EnvMapMasksAsTheHelpersLeaveThem) {
  using M = ModelEnvmapMask;
  // The bumped path: the normal map's alpha is a static combo.
  VertexLitMaterial bumped{.bump = true, .envmap = true, .envmap_mask = M::normal_alpha};
  EXPECT_TRUE(vertexlit_combo(bumped, VertexLitPath::bumped, 2, ShaderModel::ps_2_0, {}).envmap_normal_alpha);
  bumped.envmap_mask = M::none;
  EXPECT_TRUE(vertexlit_combo(bumped, VertexLitPath::bumped, 2, ShaderModel::ps_2_0, {}).envmap);
  EXPECT_FALSE(vertexlit_combo(bumped, VertexLitPath::bumped, 2, ShaderModel::ps_2_0, {}).envmap_normal_alpha);
  // The skin shader: a constant, 1 only with the flag and a bump map; the combo has no mask axis.
  VertexLitMaterial skin{.phong = true, .bump = true, .envmap = true, .envmap_mask = M::normal_alpha};
  EXPECT_FALSE(vertexlit_combo(skin, VertexLitPath::skin, 2, ShaderModel::ps_2_b, {}).envmap_normal_alpha);
  EXPECT_EQ(skin_envmap_mask_control(skin), 1.0f);
  skin.envmap_mask = M::none;
  EXPECT_EQ(skin_envmap_mask_control(skin), 0.0f) << "the base alpha masks the skin shader's env map by default";
  const VertexLitMaterial skin_no_bump{.phong = true, .base_map_alpha_phong_mask = true, .envmap = true, .envmap_mask = M::normal_alpha};
  EXPECT_EQ(skin_envmap_mask_control(skin_no_bump), 0.0f) << "no tangent space: the flag is cleared";
  // The plain path and UnlitGeneric: $basealphaenvmapmask only over a translucent base, no
  // $normalmapalphaenvmapmask.
  for (bool diffuse_lighting : {false, true}) {
    VertexLitMaterial plain{.envmap = true, .envmap_mask = M::base_alpha};
    EXPECT_EQ(generic_combo(plain, diffuse_lighting, Fog::none).mask, UnlitEnvmapMask::none) << "an opaque base";
    plain.base_translucent = true;
    EXPECT_EQ(generic_combo(plain, diffuse_lighting, Fog::none).mask, UnlitEnvmapMask::base_alpha_inverted);
    plain.envmap_mask = M::texture;
    EXPECT_EQ(generic_combo(plain, diffuse_lighting, Fog::none).mask, UnlitEnvmapMask::texture);
    plain.envmap_mask = M::normal_alpha;
    EXPECT_EQ(generic_combo(plain, diffuse_lighting, Fog::none).mask, UnlitEnvmapMask::none);
    plain.envmap = false;
    plain.envmap_mask = M::texture;
    EXPECT_FALSE(generic_combo(plain, diffuse_lighting, Fog::none).envmap);
    EXPECT_EQ(generic_combo(plain, diffuse_lighting, Fog::none).mask, UnlitEnvmapMask::none);
    EXPECT_EQ(generic_combo(plain, diffuse_lighting, Fog::range).fog, Fog::range);
  }
  const VertexLitMaterial colored{.vertex_color = true};
  EXPECT_TRUE(generic_combo(colored, false, Fog::none).vertex_color);
  EXPECT_FALSE(generic_combo(colored, true, Fog::none).vertex_color) << "VertexLitGeneric's lighting takes i.color";
}

TEST(VertexLitDispatch, SkinExponentConstantsAsTheHelperSetsThem) {
  // skin_dx9_helper.cpp: c.w = $phongexponentfactor when not 0 (the PHONG_USE_EXPONENT_FACTOR
  // binary: 1 + factor r), else $phongexponent when above 0, else -1 (1 + 149 r from the texture).
  // luxel's one binary: the texture path with the factor as its scale; the fast path reads c.w.
  const SkinExponentConstants unset = skin_exponent_constants(0.0f, 0.0f, false);
  EXPECT_EQ(unset.exponent, -1.0f);
  EXPECT_EQ(unset.texture_scale, 149.0f);
  EXPECT_EQ(skin_exponent_constants(-3.0f, 0.0f, false).exponent, -1.0f) << "not above 0: unset";
  const SkinExponentConstants constant = skin_exponent_constants(12.0f, 0.0f, false);
  EXPECT_EQ(constant.exponent, 12.0f);
  EXPECT_EQ(constant.texture_scale, 149.0f);
  const SkinExponentConstants factor = skin_exponent_constants(12.0f, 20.0f, false);
  EXPECT_EQ(factor.exponent, -1.0f) << "the factor wins over $phongexponent";
  EXPECT_EQ(factor.texture_scale, 20.0f);
  EXPECT_EQ(skin_exponent_constants(12.0f, 20.0f, true).exponent, 20.0f) << "FASTPATH_NOBUMP: max(c.w, 0), c.w the factor";
  EXPECT_EQ(skin_exponent_constants(12.0f, 0.0f, true).exponent, 12.0f);
}

TEST(VertexLitDispatch, SkinSpecularTintAsTheHelperSetsIt) {
  // skin_dx9_helper.cpp: $phongtint as given; all zero: -1 (the albedo tint) with $phongalbedotint
  // and an exponent texture, else white.
  const glm::vec3 tint(0.5f, 0.25f, 1.0f), zero(0.0f);
  EXPECT_EQ(skin_specular_tint(tint, true, true), tint) << "a tint wins over $phongalbedotint";
  EXPECT_EQ(skin_specular_tint(zero, true, true), glm::vec3(-1.0f, 0.0f, 0.0f));
  EXPECT_EQ(skin_specular_tint(zero, true, false), glm::vec3(1.0f)) << "no exponent texture: no tint map";
  EXPECT_EQ(skin_specular_tint(zero, false, true), glm::vec3(1.0f)) << "zero means unset: white, not black";
  EXPECT_EQ(skin_specular_tint(glm::vec3(0.0f, 0.0f, 0.5f), true, true), glm::vec3(0.0f, 0.0f, 0.5f));
}

}  // namespace
}  // namespace luxel::shading::source
