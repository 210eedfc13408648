// frame::Renderer's contract (renderer.hpp) on small scenes whose every pixel is known: sRGB
// decode of base textures and encode on write, the plain lighting formula, $linearwrite, the
// background, culling and depth order.

#include "luxel/frame/renderer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <cstdint>

namespace luxel::frame {
namespace {

constexpr int kSize = 32;

/// The sRGB encode (IEC 61966-2-1), written out here.
double encode(double linear) {
  linear = std::clamp(linear, 0.0, 1.0);
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
}

/// A camera looking straight down at [-1, 1]^2 (screen right +X, up +Y).
scenes::Scene top_down() {
  scenes::Scene s;
  s.name = "test";
  scenes::Camera c;
  c.projection = scenes::Projection::orthographic;
  c.position = {0, 0, 10};
  c.target = {0, 0, 0};
  c.up = {0, 1, 0};
  c.ortho_height = 2;
  c.aspect = 1;
  c.near_plane = 1;
  c.far_plane = 20;
  s.cameras.push_back(c);
  return s;
}

/// The square [x0, x1] x [y0, y1] at height z, facing +Z (counter-clockwise seen from above)
/// unless `flip`.
scenes::Mesh square(float x0, float y0, float x1, float y1, float z, int material, bool flip = false) {
  scenes::Mesh m;
  m.material = material;
  m.positions = {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
  m.normals.assign(4, {0, 0, 1});
  m.uv0 = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  m.indices = flip ? std::vector<uint16_t>{0, 2, 1, 0, 3, 2} : std::vector<uint16_t>{0, 1, 2, 0, 2, 3};
  return m;
}

rasterizer::Image render(const scenes::Scene& s) {
  Renderer r(s, {kSize, kSize, 4});
  rasterizer::Context ctx(2);
  r.render(ctx);
  return r.image();
}

void expect_everywhere(const rasterizer::Image& image, int x0, int x1, const double (&expected)[3], const char* what) {
  int off = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = x0; x < x1; ++x)
      for (int c = 0; c < 3; ++c) off += std::abs(image.pixel(x, y)[c] - expected[c]) > 1.0;
  EXPECT_EQ(off, 0) << what;
}

TEST(Renderer, UnlitBaseTextureRoundTripsThroughSrgb) {
  scenes::Scene s = top_down();
  scenes::Texture t;
  t.name = "solid";
  scenes::PixelImage image;
  image.width = image.height = 4;
  for (int i = 0; i < 16; ++i) image.rgba8.insert(image.rgba8.end(), {200, 100, 50, 255});
  t.faces = {image};
  s.textures = {t};
  scenes::Material m;
  m.family = scenes::ShaderFamily::unlit_generic;
  m.base.texture = 0;
  s.materials = {m};
  s.meshes = {square(-1, -1, 1, 1, 0, 0)};
  expect_everywhere(render(s), 0, kSize, {200, 100, 50}, "decoded on read, encoded on write");
}

TEST(Renderer, LitMaterialsTakeThePlainSunAndSky) {
  scenes::Scene s = top_down();
  scenes::Material m;  // VertexLitGeneric, untextured: white
  m.color = {0.4f, 0.3f, 0.2f, 1.0f};
  s.materials = {m};
  s.meshes = {square(-1, -1, 1, 1, 0, 0)};
  s.meshes[0].colors.assign(4, {0.5f, 1.0f, 1.0f, 1.0f});
  // renderer.hpp's formula for a normal facing up: ambient + ambient_up + sun * (n . to_sun), with
  // the demo's constants and to_sun = (-0.45, -0.4, 0.8).
  const double light[3] = {0.12 + 0.10 + 1.1 * 0.8, 0.14 + 0.13 + 1.0 * 0.8, 0.18 + 0.20 + 0.85 * 0.8};
  const double albedo[3] = {0.4 * 0.5, 0.3, 0.2};
  double expected[3];
  for (int c = 0; c < 3; ++c) expected[c] = 255 * encode(albedo[c] * light[c]);
  expect_everywhere(render(s), 0, kSize, expected, "lit");
}

TEST(Renderer, LinearWriteAndTheBackground) {
  scenes::Scene s = top_down();
  s.background = {0.2f, 0.05f, 0.6f};
  scenes::Material m;
  m.family = scenes::ShaderFamily::unlit_generic;
  m.linear_write = true;
  m.color = {0.5f, 1.0f, 1.0f, 1.0f};
  s.materials = {m};
  s.meshes = {square(-1, -1, 0, 1, 0, 0)};  // the left half
  s.meshes[0].colors.assign(4, {0.6f, 0.3f, 0.1f, 1.0f});
  const rasterizer::Image image = render(s);
  expect_everywhere(image, 0, kSize / 2, {255 * 0.3, 255 * 0.3, 255 * 0.1}, "written as it is");
  expect_everywhere(image, kSize / 2, kSize, {255 * encode(0.2), 255 * encode(0.05), 255 * encode(0.6)},
                    "the background, encoded");
}

TEST(Renderer, SingleSidedMaterialsCullTheirBackFaces) {
  scenes::Scene s = top_down();
  s.background = {0, 0, 0};
  scenes::Material one_sided;
  one_sided.family = scenes::ShaderFamily::unlit_generic;
  scenes::Material two_sided = one_sided;
  two_sided.double_sided = true;
  s.materials = {one_sided, two_sided};
  s.meshes = {square(-1, -1, 0, 1, 0, 0, true), square(0, -1, 1, 1, 0, 1, true)};  // both seen from behind
  const rasterizer::Image image = render(s);
  expect_everywhere(image, 0, kSize / 2, {0, 0, 0}, "culled");
  expect_everywhere(image, kSize / 2, kSize, {255, 255, 255}, "double-sided");
}

TEST(Renderer, TheNearerSurfaceWinsWhateverTheOrder) {
  scenes::Scene s = top_down();
  scenes::Material red, blue;
  red.family = blue.family = scenes::ShaderFamily::unlit_generic;
  red.color = {1, 0, 0, 1};
  blue.color = {0, 0, 1, 1};
  s.materials = {red, blue};
  s.meshes = {square(-1, -1, 1, 1, 5, 0), square(-1, -1, 1, 1, 2, 1)};  // red nearer, drawn first
  expect_everywhere(render(s), 0, kSize, {255, 0, 0}, "nearer first");
  std::swap(s.meshes[0], s.meshes[1]);
  expect_everywhere(render(s), 0, kSize, {255, 0, 0}, "nearer last");
}

}  // namespace
}  // namespace luxel::frame
