// A LightmappedGeneric material with $bumpmap and $basealphaenvmapmask over a base texture with
// alpha asks for a combo the SDK never compiles (lightmappedgeneric_ps2_3_x.h: SKIP
// $BASEALPHAENVMAPMASK && $BUMPMAP; docs/fidelity.md#lightmappedgeneric): validate() refuses it,
// naming the material. Over an opaque base the helper drops the flag, so the scene is drawn.
// A bumped VertexLitGeneric material whose env map is masked by the base alpha or an $envmapmask
// loses the env map in the helper's InitParams (docs/fidelity.md#env-maps-on-models): refused too.

#include "luxel/scenes/scene.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace luxel::scenes {
namespace {

Texture one_texel(uint8_t alpha) {
  Texture t;
  t.name = "base";
  PixelImage image;
  image.width = image.height = 1;
  image.rgba8 = {200, 180, 160, alpha};
  t.faces = {image};
  return t;
}

Scene floor_asking(uint8_t base_alpha, bool bump, EnvmapMask mask) {
  Scene s;
  s.name = "floor";
  s.textures = {one_texel(base_alpha), one_texel(255)};
  Material m;
  m.name = "paving";
  m.family = ShaderFamily::lightmapped_generic;
  m.base.texture = 0;
  if (bump) m.bump.texture = 1;
  m.envmap = EnvmapSource::nearest_sample;
  m.envmap_mask = mask;
  s.materials = {m};
  return s;
}

TEST(SkippedCombo, BumpWithBaseAlphaEnvmapMaskOverAlphaIsRefused) {
  try {
    validate(floor_asking(128, true, EnvmapMask::base_alpha));
    FAIL() << "accepted a combo the SDK never compiles";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'paving'"), std::string::npos) << what;
    EXPECT_NE(what.find("$basealphaenvmapmask"), std::string::npos) << what;
  }
  EXPECT_NO_THROW(validate(floor_asking(255, true, EnvmapMask::base_alpha))) << "an opaque base: the helper drops the flag";
  EXPECT_NO_THROW(validate(floor_asking(128, false, EnvmapMask::base_alpha))) << "no bump map: a compiled combo";
  EXPECT_NO_THROW(validate(floor_asking(128, true, EnvmapMask::normal_alpha)));
}

TEST(SkippedCombo, BumpedModelEnvMapMaskedByBaseAlphaOrTextureIsRefused) {
  for (EnvmapMask mask : {EnvmapMask::base_alpha, EnvmapMask::texture}) {
    Scene s = floor_asking(128, true, mask);
    s.materials[0].family = ShaderFamily::vertexlit_generic;
    try {
      validate(s);
      FAIL() << "accepted an env map the SDK deletes";
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("'paving'"), std::string::npos) << what;
      EXPECT_NE(what.find(mask == EnvmapMask::base_alpha ? "$basealphaenvmapmask" : "$envmapmask"), std::string::npos) << what;
    }
    s.materials[0].bump = TextureRef{};
    EXPECT_NO_THROW(validate(s)) << "without a bump map the ordinary path masks the env map";
  }
  for (EnvmapMask mask : {EnvmapMask::none, EnvmapMask::normal_alpha}) {
    Scene s = floor_asking(128, true, mask);
    s.materials[0].family = ShaderFamily::vertexlit_generic;
    EXPECT_NO_THROW(validate(s));
  }
}

TEST(SkippedCombo, TranslucentTexelsAreThoseBelowFullAlpha) {
  EXPECT_FALSE(has_translucent_texels(one_texel(255)));
  EXPECT_TRUE(has_translucent_texels(one_texel(254)));
  Texture hdr;
  PixelImage image;
  image.width = image.height = 1;
  image.rgba32f = {4.0f, 2.0f, 1.0f, 1.0f};
  hdr.faces = {image};
  EXPECT_FALSE(has_translucent_texels(hdr));
  hdr.faces[0].rgba32f[3] = 0.5f;
  EXPECT_TRUE(has_translucent_texels(hdr));
}

}  // namespace
}  // namespace luxel::scenes
