// A ps_3_0 card runs the ps20b binary of every family the SDK builds only as ps20 / ps20b
// (LightmappedGeneric, Water, Sky_HDR, the post passes: docs/fidelity.md#shader-models): on the
// courtyard with bloom and color correction, its frame is ps_2_b's bytes, and each of those
// families' shader uses names the ps20b binary with ps_2_b's pixels and slots. The model shaders
// (VertexLitGeneric, its skin shader, UnlitGeneric) have ps30 builds of their own: there the
// ps_3_0 card names ps30, with the same pixels.

#include "frame/frame_support.hpp"

#include "luxel/frame/renderer.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

namespace luxel::frame {
namespace {

struct Frame {
  rasterizer::Image image;
  std::vector<ShaderUse> uses;
};

Frame courtyard_as(shading::ShaderModel card) {
  FrameSettings f{160, 90, 4};
  f.model = card;
  f.count_shading = true;
  f.bloom = postfx::BloomOptions{};
  const std::shared_ptr<const scenes::Scene> scene = builtin_scene("courtyard", 160, 90);
  Renderer r(*scene, f);
  rasterizer::Context ctx(2);
  r.render(ctx);
  return {r.image(), r.shader_uses()};
}

TEST(SdkBinariesFrame, APs30CardRunsThePs20bBinaryOfTheFamiliesBuiltOnlyAsPs2x) {
  const Frame b = courtyard_as(shading::ShaderModel::ps_2_b);
  const Frame c = courtyard_as(shading::ShaderModel::ps_3_0);
  EXPECT_TRUE(b.image.rgba == c.image.rgba) << "the courtyard draws the same combos on both cards";
  const std::set<std::string> ps30_built = {"VertexLitGeneric", "UnlitGeneric"};
  std::set<std::string> ps20b_families;
  ASSERT_EQ(b.uses.size(), c.uses.size());
  for (size_t i = 0; i < c.uses.size(); ++i) {
    const ShaderUse &u2b = b.uses[i], &u30 = c.uses[i];
    SCOPED_TRACE(u30.family + " " + u30.combo);
    EXPECT_EQ(u30.family, u2b.family);
    EXPECT_EQ(u30.combo, u2b.combo);
    EXPECT_EQ(u30.pixels, u2b.pixels);
    EXPECT_EQ(u2b.binary, shading::ShaderModel::ps_2_b);
    if (ps30_built.count(u30.family)) {
      EXPECT_EQ(u30.binary, shading::ShaderModel::ps_3_0);
    } else {
      EXPECT_EQ(u30.binary, shading::ShaderModel::ps_2_b) << "the SDK builds no ps30 binary of it";
      EXPECT_EQ(u30.slots, u2b.slots);
      ps20b_families.insert(u30.family);
    }
  }
  for (const char* family : {"LightmappedGeneric", "Water", "Sky_HDR", "LuminanceRange", "Engine_Post"})
    EXPECT_TRUE(ps20b_families.count(family)) << family << " is not drawn: the test checks less than it says";
}

}  // namespace
}  // namespace luxel::frame
