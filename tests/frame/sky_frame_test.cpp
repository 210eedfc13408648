// The sky's orientation in the frame: a sky cube whose six faces are six colours, seen along each
// world axis (+Z up, D3D's face order +X, -X, +Y, -Y, +Z, -Z: docs/fidelity.md#sky), shows that
// axis's face, whose 8-bit sRGB texel comes back through Sky_HDR (LINEAR tone map at exposure 1,
// input scale 1 for an 8-bit sky) and the sRGB write within a step; a wide view along +X with +Z
// up sees +Z above, -Z below, +Y on its left and -Y on its right (a right-handed world). A frame
// that swapped two faces, turned the sky upside down or mirrored it fails.

#include "frame/frame_support.hpp"

#include "luxel/frame/renderer.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace luxel::frame {
namespace {

constexpr int kSkySide = 17;  // odd: a centre pixel
constexpr std::array<std::array<uint8_t, 3>, 6> kFaceColors = {
    {{200, 40, 40}, {40, 200, 40}, {40, 40, 200}, {200, 200, 40}, {40, 200, 200}, {200, 40, 200}}};

scenes::Scene sky_only(const glm::vec3& look, const glm::vec3& up, float vertical_fov = 1.5707963f) {
  scenes::Scene s;
  s.name = "sky";
  scenes::Texture cube;
  cube.name = "six colours";
  cube.shape = scenes::TextureShape::cube;
  cube.color_space = scenes::ColorSpace::srgb;
  for (const auto& c : kFaceColors) {
    scenes::PixelImage face;
    face.width = face.height = 4;
    for (int i = 0; i < 16; ++i) face.rgba8.insert(face.rgba8.end(), {c[0], c[1], c[2], 255});
    cube.faces.push_back(face);
  }
  s.textures = {cube};
  s.sky_texture = 0;
  scenes::Camera c;
  c.position = {0, 0, 0};
  c.target = look;
  c.up = up;
  c.vertical_fov = vertical_fov;
  c.aspect = 1;
  c.near_plane = 1;
  c.far_plane = 1000;
  s.cameras.push_back(c);
  return s;
}

TEST(SkyFrame, EachAxisSeesItsFace) {
  const struct {
    glm::vec3 look, up;
  } axes[6] = {{{1, 0, 0}, {0, 0, 1}}, {{-1, 0, 0}, {0, 0, 1}}, {{0, 1, 0}, {0, 0, 1}},
               {{0, -1, 0}, {0, 0, 1}}, {{0, 0, 1}, {0, 1, 0}}, {{0, 0, -1}, {0, 1, 0}}};
  FrameSettings f{kSkySide, kSkySide, 1};
  f.exposure = 1.0f;
  f.color_correction = false;
  for (size_t face = 0; face < 6; ++face) {
    SCOPED_TRACE("face " + std::to_string(face));
    const rasterizer::Image image = render_frame(sky_only(axes[face].look, axes[face].up), f);
    // The centre and its 3x3 neighbourhood (a quarter of the face's angle around the axis).
    for (int y = kSkySide / 2 - 1; y <= kSkySide / 2 + 1; ++y)
      for (int x = kSkySide / 2 - 1; x <= kSkySide / 2 + 1; ++x)
        for (int c = 0; c < 3; ++c)
          EXPECT_LE(std::abs(int(image.pixel(x, y)[c]) - int(kFaceColors[face][size_t(c)])), 1)
              << "pixel (" << x << ", " << y << "), channel " << c;
  }
}

TEST(SkyFrame, AWideViewSeesUpAboveAndTheRightHandedSides) {
  FrameSettings f{kSkySide, kSkySide, 1};
  f.exposure = 1.0f;
  f.color_correction = false;
  // 120 degrees: the edges' directions leave the +X face (tan 60 x 16/17 > 1).
  const rasterizer::Image image = render_frame(sky_only({1, 0, 0}, {0, 0, 1}, 2.0943951f), f);
  const struct {
    int x, y;
    size_t face;
    const char* where;
  } probes[] = {{kSkySide / 2, 0, 4, "top: +Z"},     {kSkySide / 2, kSkySide - 1, 5, "bottom: -Z"},
                {0, kSkySide / 2, 2, "left: +Y"},    {kSkySide - 1, kSkySide / 2, 3, "right: -Y"},
                {kSkySide / 2, kSkySide / 2, 0, "centre: +X"}};
  for (const auto& p : probes)
    for (int c = 0; c < 3; ++c)
      EXPECT_LE(std::abs(int(image.pixel(p.x, p.y)[c]) - int(kFaceColors[p.face][size_t(c)])), 1) << p.where << ", channel " << c;
}

}  // namespace
}  // namespace luxel::frame
