// The frame draws VertexLitGeneric materials with the shader the SDK's helper picks
// (docs/fidelity.md#which-shader-a-model-gets), checked on the courtyard: its barrel and ball
// ask for $phong without a bump map, which the SDK draws with the ordinary shader, so turning
// their $phong off must not change a byte; its hero has a bump map and takes the skin shader, so
// turning its $phong off must change it.

#include "frame/frame_support.hpp"

#include "luxel/frame/renderer.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace luxel::frame
