// ps_2_0 differs from ps_2_b and ps_3_0 exactly where their combos differ, on the courtyard: the
// frame drops Phong and normalizes with the normalization cube on ps_2_0 for
// VertexLitGeneric (the models), and fogs per vertex there. Without fog, every other surface (the
// lightmapped world, the unlit flames, the sky) must be the same bytes on all three models; the
// water reflects and refracts the models, so its pixels may differ too. ps_2_b and ps_3_0 run the
// same combos: the same bytes everywhere.
//
// Where each kind of surface lies on screen comes from a second render of the same geometry with
// every material replaced by an unlit color naming its kind (same depth test, culling, alpha test
// and blending), so the masks are exactly the pixels the surfaces cover.

#include "frame/frame_support.hpp"

#include "luxel/frame/renderer.hpp"
#include "luxel/frame/textures.hpp"
#include "luxel/scenes/builtin.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <memory>
#include <set>
#include <string>

namespace luxel::frame {
namespace {

constexpr int kDiffWidth = 192, kDiffHeight = 108;

/// `textures`: the scene's (frame/textures.hpp), shared by its renders.
rasterizer::Image render(const scenes::Scene& scene, const std::shared_ptr<const SceneTextures>& textures,
                         shading::ShaderModel model, int camera) {
  FrameSettings f{kDiffWidth, kDiffHeight, 4, camera};
  f.color_correction = false;  // a pass over the finished image would tint the masks' kind colors
  f.model = model;
  Renderer r(scene, f, textures);
  rasterizer::Context ctx(2);
  r.render(ctx);
  return r.image();
}

/// Red: the hero model (Phong: ps_2_0 drops it); green: the other models; blue: water; black:
/// everything else.
scenes::Scene kind_masks(const scenes::Scene& scene) {
  scenes::Scene masks = scene;
  std::set<int> hero, model;
  for (const scenes::Model& m : scene.models)
    for (int mesh : m.meshes) (m.name == "hero" ? hero : model).insert(mesh);
  // One unlit material per kind (the same material may be both a model's and the world's).
  scenes::Material base;
  base.family = scenes::ShaderFamily::unlit_generic;
  base.linear_write = true;
  const size_t first = masks.materials.size();
  for (glm::vec4 color : {glm::vec4(0, 0, 0, 1), glm::vec4(1, 0, 0, 1), glm::vec4(0, 1, 0, 1), glm::vec4(0, 0, 1, 1)}) {
    scenes::Material m = base;
    m.name = "mask";
    m.color = color;
    masks.materials.push_back(m);
  }
  for (size_t i = 0; i < masks.meshes.size(); ++i) {
    scenes::Mesh& mesh = masks.meshes[i];
    const scenes::Material& was = mesh.material >= 0 ? scene.materials[size_t(mesh.material)] : scenes::Material{};
    EXPECT_EQ(was.alpha, scenes::AlphaMode::opaque) << mesh.name << ": the masks assume no alpha test nor blending";
    EXPECT_FALSE(was.translucent) << mesh.name;
    const int kind = hero.count(int(i))                              ? 1
                     : model.count(int(i))                           ? 2
                     : was.family == scenes::ShaderFamily::water     ? 3
                                                                     : 0;
    mesh.material = int(first) + kind;
    mesh.colors.clear();
  }
  masks.sky_texture = -1;
  masks.background = glm::vec3(0.0f);
  return masks;
}

struct Counts {
  int elsewhere = 0, elsewhere_differ = 0, hero = 0, hero_differ = 0, models = 0, models_differ = 0, water = 0;
};

/// The courtyard through `camera` on the three models: which pixels of each kind differ between
/// ps_2_0 and ps_2_b.
Counts compare_models(const scenes::Scene& scene, int camera) {
  const auto textures = std::make_shared<const SceneTextures>(scene);
  const rasterizer::Image ps20 = render(scene, textures, shading::ShaderModel::ps_2_0, camera);
  const rasterizer::Image ps2b = render(scene, textures, shading::ShaderModel::ps_2_b, camera);
  const rasterizer::Image ps30 = render(scene, textures, shading::ShaderModel::ps_3_0, camera);
  EXPECT_TRUE(ps2b.rgba == ps30.rgba) << "ps_2_b and ps_3_0 run the same combos; camera " << camera;
  const scenes::Scene masks_scene = kind_masks(scene);
  const rasterizer::Image masks =
      render(masks_scene, std::make_shared<const SceneTextures>(masks_scene), shading::ShaderModel::ps_3_0, camera);
  Counts c;
  for (int y = 0; y < kDiffHeight; ++y)
    for (int x = 0; x < kDiffWidth; ++x) {
      const uint8_t* m = masks.pixel(x, y);
      const uint8_t* a = ps20.pixel(x, y);
      const uint8_t* b = ps2b.pixel(x, y);
      const bool differ = a[0] != b[0] || a[1] != b[1] || a[2] != b[2];
      if (m[0] == 0 && m[1] == 0 && m[2] == 0) {
        ++c.elsewhere;
        c.elsewhere_differ += differ;
      } else if (m[1] == 0 && m[2] == 0) {  // the hero alone (an edge shared with another kind counts as that kind)
        ++c.hero;
        c.hero_differ += differ;
      } else if (m[1] != 0 && m[2] == 0) {
        ++c.models;
        c.models_differ += differ;
      } else {
        ++c.water;
      }
    }
  return c;
}

TEST(ModelDifferences, Ps20DiffersOnlyOnTheModelsAndWhatReflectsThem) {
  scenes::Scene scene = scenes::make_builtin_scene("courtyard", {kDiffWidth, kDiffHeight});
  attach_test_bake(scene);
  scene.fog.mode = scenes::FogMode::none;  // ps_2_0 fogs per vertex: every fogged surface would differ
  // The overview (every kind in view), then the hero's camera (the hero large).
  const Counts overview = compare_models(scene, 0);
  EXPECT_EQ(overview.elsewhere_differ, 0) << "of " << overview.elsewhere << " pixels of the world, flames and sky";
  EXPECT_GT(overview.elsewhere, kDiffWidth * kDiffHeight / 2) << "the world fills most of the view";
  EXPECT_GT(overview.hero, 20) << "the hero is in view";
  EXPECT_GT(overview.models, 50) << "the other models are in view";
  EXPECT_GT(overview.water, 50) << "the water is in view";
  const Counts close = compare_models(scene, 1);
  EXPECT_EQ(close.elsewhere_differ, 0) << "of " << close.elsewhere << " pixels of the world, flames and sky";
  ASSERT_GT(close.hero, 500) << "the hero is large in view";
  EXPECT_GT(close.hero_differ, close.hero / 2) << "without Phong, most of the hero's pixels change";
  for (const Counts* c : {&overview, &close})
    std::printf("hero: %d of %d pixels differ; other models: %d of %d; world, flames, sky: %d of %d\n", c->hero_differ,
                c->hero, c->models_differ, c->models, c->elsewhere_differ, c->elsewhere);
}

}  // namespace
}  // namespace luxel::frame
