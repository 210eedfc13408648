// The frame draws VertexLitGeneric materials with the shader the SDK's helper picks
// (docs/fidelity.md#which-shader-a-model-gets), checked on the courtyard: its barrel and ball
// ask for $phong without a bump map, which the SDK draws with the ordinary shader, so turning
// their $phong off must not change a byte; its hero has a bump map and takes the skin shader, so
// turning its $phong off must change it. An env map on such a material is drawn by the ordinary
// shader on every card (docs/fidelity.md#env-maps-on-models): the same bytes on ps_2_0 and ps_2_b.

#include "frame/frame_support.hpp"

#include "luxel/frame/renderer.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace luxel::frame {
namespace {

/// The courtyard as `card` draws it, with $phong off on the materials named in `without_phong`.
rasterizer::Image courtyard_without_phong(shading::ShaderModel card, std::initializer_list<std::string> without_phong) {
  scenes::Scene scene = *builtin_scene("courtyard", 160, 90);
  for (scenes::Material& m : scene.materials)
    for (const std::string& name : without_phong)
      if (m.name == name) {
        EXPECT_TRUE(m.phong) << name;
        m.phong = false;
      }
  FrameSettings f{160, 90, 4};
  f.model = card;
  f.color_correction = false;
  return render_frame(scene, f);
}

TEST(VertexLitDispatchFrame, PhongWithoutBumpMapChangesNothing) {
  for (shading::ShaderModel card : {shading::ShaderModel::ps_2_b, shading::ShaderModel::ps_3_0}) {
    SCOPED_TRACE(std::string(shading::caps(card).name));
    const rasterizer::Image with = courtyard_without_phong(card, {});
    const rasterizer::Image without = courtyard_without_phong(card, {"courtyard/barrel", "courtyard/painted"});
    EXPECT_TRUE(with.rgba == without.rgba) << "a $phong material without a bump map got specular";
    const rasterizer::Image hero_without = courtyard_without_phong(card, {"courtyard/bronze"});
    EXPECT_FALSE(with.rgba == hero_without.rgba) << "the bumped hero's $phong changed nothing";
  }
}

/// The courtyard without fog (so that ps_2_0 fogs nothing differently), its barrels and painted
/// balls ($phong without a bump map) with an env map or not, as `card` draws it.
rasterizer::Image courtyard_painted_envmap(shading::ShaderModel card, bool envmap) {
  scenes::Scene scene = *builtin_scene("courtyard", 160, 90);
  scene.fog = scenes::Fog{};
  for (scenes::Material& m : scene.materials)
    if ((m.name == "courtyard/painted" || m.name == "courtyard/barrel") && envmap) {
      m.envmap = scenes::EnvmapSource::nearest_sample;
      m.envmap_tint = glm::vec3(0.6f);
    }
  FrameSettings f{160, 90, 4};
  f.model = card;
  f.color_correction = false;
  return render_frame(scene, f);
}

TEST(VertexLitDispatchFrame, PlainModelsDrawTheirEnvMapAlikeOnEveryCard) {
  const rasterizer::Image without_20 = courtyard_painted_envmap(shading::ShaderModel::ps_2_0, false);
  const rasterizer::Image with_20 = courtyard_painted_envmap(shading::ShaderModel::ps_2_0, true);
  const rasterizer::Image without_2b = courtyard_painted_envmap(shading::ShaderModel::ps_2_b, false);
  const rasterizer::Image with_2b = courtyard_painted_envmap(shading::ShaderModel::ps_2_b, true);
  int changed_20 = 0, changed_2b = 0, compared = 0, differ = 0;
  for (size_t px = 0; px + 3 < with_20.rgba.size(); px += 4) {
    auto same = [px](const rasterizer::Image& a, const rasterizer::Image& b) {
      for (size_t c = 0; c < 3; ++c)
        if (a.rgba[px + c] != b.rgba[px + c]) return false;
      return true;
    };
    const bool changed = !same(with_20, without_20);
    changed_20 += changed;
    changed_2b += !same(with_2b, without_2b);
    if (changed && same(without_20, without_2b)) {
      ++compared;
      differ += !same(with_20, with_2b);
    }
  }
  std::printf("env map on the barrels and balls: %d pixels change on ps_2_0, %d on ps_2_b; %d of %d compared differ\n",
              changed_20, changed_2b, differ, compared);
  EXPECT_GT(changed_20, 20) << "ps_2_0 drew no env map on the barrels and balls";
  EXPECT_EQ(changed_20, changed_2b);
  EXPECT_GT(compared, 20);
  EXPECT_EQ(differ, 0) << "the ordinary shader's env map differs between the cards";
}

}  // namespace
}  // namespace luxel::frame
