// The post passes in Renderer::shader_uses, after the 3D draws: the histogram's range test, the
// bloom's downsample and two blurs, its add and the color correction in one Engine_Post draw, and
// the film grain, each with the pixels its rectangles cover (worked out here), the SDK binary the
// frame's card runs and the slots the shading catalog counts for that binary.

#include "frame/frame_support.hpp"

#include "luxel/frame/renderer.hpp"
#include "luxel/shading/source/catalog.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace luxel::frame {
namespace {

// Not multiples of 4: the bloom's small targets are floor(64 / 4) x floor(44 / 4) = 16 x 11.
constexpr int kPostWidth = 64, kPostHeight = 44;
constexpr uint64_t kFrame = uint64_t(kPostWidth) * kPostHeight, kSmall = 16 * 11;
// The histogram's region: the SDK skips int(W x 0.5 x (1 - 0.9)) = int(3.2) = 3 columns and
// int(H x 0.5 x (1 - 0.85)) = int(3.3) = 3 rows on each side.
constexpr uint64_t kRegion = (kPostWidth - 6) * (kPostHeight - 6);

/// The color ramp with an exposure range (so the histogram runs; from 1.25, so that the square is
/// drawn by UnlitGeneric, not by the trivial functor of exposure 1) and two global nodes.
scenes::Scene post_processed() {
  scenes::Scene s = color_ramp();
  s.exposure.min_scale = 1.25f, s.exposure.max_scale = 2.0f;
  for (const char* lut : {"builtin:warm", "builtin:cool"}) {
    scenes::ColorCorrection c;
    c.lut = lut;
    c.max_weight = 0.3f;
    s.color_corrections.push_back(c);
  }
  return s;
}

FrameSettings every_pass() {
  FrameSettings f{kPostWidth, kPostHeight, 1};
  f.model = shading::ShaderModel::ps_2_b;
  f.count_shading = true;
  f.bloom = postfx::BloomOptions{};
  f.film_grain = postfx::FilmGrainOptions{5};
  return f;
}

std::vector<ShaderUse> uses_of(const scenes::Scene& s, const FrameSettings& f) {
  Renderer r(s, f);
  rasterizer::Context ctx(2);
  r.render(ctx);
  return r.shader_uses();
}

/// The catalog's binary of the combo for a card of model `card`, and its slots.
std::pair<shading::ShaderModel, int> catalog_binary(const std::string& family, const std::string& combo, shading::ShaderModel card) {
  for (const shading::source::ShaderVariant& v : shading::source::shader_catalog())
    if (v.family == family && v.variant == combo) {
      const shading::ShaderModel binary = *v.builds.binary_for(card);
      return {binary, v.measure(binary).total_slots()};
    }
  ADD_FAILURE() << family << " " << combo << " is not in the catalog";
  return {card, -1};
}

/// `region_pixels`: what the range test shaded, which a multisampled frame's diagonal changes.
void expect_post_passes(const std::vector<ShaderUse>& uses, const std::string& range_test, uint64_t region_pixels,
                        shading::ShaderModel model) {
  struct Expected {
    std::string family, combo;
    uint64_t pixels;
  };
  const std::vector<Expected> expected = {{"LuminanceRange", range_test, region_pixels},
                                          {"Downsample_nohdr", "default", kSmall},
                                          {"BlurFilter", "default", 2 * kSmall},  // the x and the y blur
                                          {"Engine_Post", "2luts", kFrame},  // the bloom's add and the correction
                                          {"filmgrain", "default", kFrame}};
  std::string listed;
  for (const ShaderUse& u : uses) listed += " " + u.family + "/" + u.combo;
  ASSERT_EQ(uses.size(), 1 + expected.size()) << listed;
  EXPECT_EQ(uses[0].family, "UnlitGeneric") << "the 3D draws first";
  for (size_t i = 0; i < expected.size(); ++i) {
    const ShaderUse& u = uses[i + 1];
    EXPECT_EQ(u.family, expected[i].family);
    EXPECT_EQ(u.combo, expected[i].combo) << u.family;
    EXPECT_EQ(u.pixels, expected[i].pixels) << u.family;
    EXPECT_EQ(std::pair(u.binary, u.slots), catalog_binary(u.family, u.combo, model)) << u.family;
    // The SDK builds these as ps20 and ps20b only, film grain as ps20 only: no card runs a ps30.
    const shading::ShaderModel built = u.family == "filmgrain" || model == shading::ShaderModel::ps_2_0
                                           ? shading::ShaderModel::ps_2_0
                                           : shading::ShaderModel::ps_2_b;
    EXPECT_EQ(u.binary, built) << u.family;
    EXPECT_GT(u.slots, 0) << u.family;
  }
}

TEST(FramePostPassShaders, EveryPostPassListsItsShaderWithThePixelsItShaded) {
  const scenes::Scene s = post_processed();
  expect_post_passes(uses_of(s, every_pass()), "alphatest", kRegion, shading::ShaderModel::ps_2_b);
  // The stencil method counts its mark (the range test); its counting draw is no catalog shader.
  // With 4 samples the range test draws into the frame's multisampled target, where a pixel on
  // the rectangle's diagonal with samples in both triangles is shaded once for each: at most one
  // more per row and column of the region. The other passes draw on the resolved image.
  FrameSettings stencil = every_pass();
  stencil.samples = 4;
  stencil.model = shading::ShaderModel::ps_3_0;
  stencil.histogram.count = postfx::HistogramCount::stencil;
  stencil.histogram.reject = shading::source::LuminanceReject::texkill;
  const std::vector<ShaderUse> uses = uses_of(s, stencil);
  ASSERT_GE(uses.size(), 2u);
  EXPECT_GE(uses[1].pixels, kRegion);
  EXPECT_LE(uses[1].pixels, kRegion + (kPostWidth - 6) + (kPostHeight - 6));
  expect_post_passes(uses, "texkill", uses[1].pixels, shading::ShaderModel::ps_3_0);
}

TEST(FramePostPassShaders, NothingIsCountedUnlessAsked) {
  FrameSettings f = every_pass();
  f.count_shading = false;
  EXPECT_TRUE(uses_of(post_processed(), f).empty());
}

}  // namespace
}  // namespace luxel::frame
