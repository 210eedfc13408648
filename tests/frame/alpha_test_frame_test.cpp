// The alpha test in the frame (D3DRS_ALPHAFUNC GREATEREQUAL against $alphatestreference x 255,
// rounded): a square whose base texture's left texel has alpha 127 and right texel 128, under a
// reference of 0.5 (128): the left half is discarded, the background shows; the right half is
// drawn, its texel through the sRGB read and write. A test that kept 127 (a rounding or a
// comparison off by one) or dropped 128 (GREATER) fails.

#include "frame/frame_support.hpp"

#include "luxel/frame/renderer.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace luxel::frame {
namespace {

TEST(AlphaTestFrame, GreaterEqualTheRoundedReference) {
  scenes::Scene s = top_down();
  s.background = glm::vec3(0.05f, 0.1f, 0.2f);
  scenes::Texture t;
  t.name = "two alphas";
  t.color_space = scenes::ColorSpace::srgb;
  t.mag = t.min = scenes::Filter::nearest;
  t.mipmaps = false;
  scenes::PixelImage image;
  image.width = 2, image.height = 1;
  image.rgba8 = {200, 100, 50, 127, 200, 100, 50, 128};
  t.faces = {image};
  s.textures = {t};
  scenes::Material m;
  m.family = scenes::ShaderFamily::unlit_generic;
  m.base.texture = 0;
  m.alpha = scenes::AlphaMode::alpha_test;
  m.alpha_cutoff = 0.5f;
  s.materials = {m};
  s.meshes = {square(-1, -1, 1, 1, 0, 0)};
  FrameSettings f{64, 64, 1};
  f.exposure = 1.0f;
  f.color_correction = false;
  const std::array<double, 3> background = {255 * srgb_encode(0.05), 255 * srgb_encode(0.1), 255 * srgb_encode(0.2)};
  const std::array<double, 3> texel = {200, 100, 50};
  for (shading::ShaderModel card : {shading::ShaderModel::ps_2_0, shading::ShaderModel::ps_3_0}) {
    f.model = card;
    const rasterizer::Image frame = render_frame(s, f);
    EXPECT_EQ(channels_off(frame, 0, 31, background), 0) << shading::caps(card).name << ": alpha 127 is discarded";
    EXPECT_EQ(channels_off(frame, 33, 64, texel), 0) << shading::caps(card).name << ": alpha 128 passes";
  }
}

}  // namespace
}  // namespace luxel::frame
