// Numeric hard cases through the whole frame: coordinates near 1e6 and 1e-6, the camera inside
// geometry and on a light, lights on and inside surfaces, all-black and all-white frames through
// auto exposure, HDR values of 1e30 through tone mapping, bloom and color correction, denormal
// texels. Each test says what "sensible" means for its case; none may give a NaN (which the 8-bit
// target stores as 0) or throw.

#include "frame_support.hpp"

#include "luxel/rasterizer/texture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace luxel::frame {
namespace {

constexpr int kExtremesSize = 64;

FrameSettings small_frame(int samples = 1) {
  FrameSettings s;
  s.width = s.height = kExtremesSize;
  s.samples = samples;
  return s;
}

const uint8_t* pixel(const rasterizer::Image& image, int x, int y) { return &image.rgba[size_t(4 * (y * image.width + x))]; }

/// Pixels whose rgb differs between two frames.
int differing(const rasterizer::Image& a, const rasterizer::Image& b) {
  int n = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      n += pixel(a, x, y)[0] != pixel(b, x, y)[0] || pixel(a, x, y)[1] != pixel(b, x, y)[1] || pixel(a, x, y)[2] != pixel(b, x, y)[2];
  return n;
}

/// An unlit white square of half-width `scale / 2` centered at `offset`, seen from straight above
/// through an orthographic camera `scale` inches high: the square covers the middle half of the
/// frame (pixels 16 to 47 of 64 on each axis, its edges between pixel centers), black around it.
scenes::Scene square_at(glm::vec3 offset, float scale) {
  scenes::Scene s = top_down();
  s.cameras[0].position = offset + glm::vec3(0, 0, 10 * scale);
  s.cameras[0].target = offset;
  s.cameras[0].ortho_height = 2 * scale;
  s.cameras[0].near_plane = scale;
  s.cameras[0].far_plane = 20 * scale;
  scenes::Material m;
  m.family = scenes::ShaderFamily::unlit_generic;
  s.materials = {m};
  s.meshes = {square(offset.x - scale / 2, offset.y - scale / 2, offset.x + scale / 2, offset.y + scale / 2, offset.z, 0)};
  s.background = glm::vec3(0.0f);
  s.exposure.min_scale = s.exposure.max_scale = 1.0f;
  return s;
}

/// The square's expected frame: white inside pixels 16..47, black outside.
int misplaced(const rasterizer::Image& image) {
  int n = 0;
  for (int y = 0; y < kExtremesSize; ++y)
    for (int x = 0; x < kExtremesSize; ++x) {
      const uint8_t want = x >= 16 && x < 48 && y >= 16 && y < 48 ? 255 : 0;
      n += pixel(image, x, y)[0] != want || pixel(image, x, y)[1] != want || pixel(image, x, y)[2] != want;
    }
  return n;
}

// Sensible: the square far from the origin covers what it covers at the origin. At 1e6 inches a
// float's step is 1/16 inch; the square is 1000 inches across on 64 pixels (15.6 inches a pixel),
// so snapping moves its edges by far less than a pixel: every pixel as predicted. At 1e7 (one
// inch a step, a fifteenth of a pixel) the same.
TEST(NumericExtremes, CoordinatesNearAMillionInches) {
  for (float at : {1e6f, -1e6f, 1e7f}) {
    const scenes::Scene s = square_at(glm::vec3(at, -at, at / 2), 1000.0f);
    EXPECT_EQ(misplaced(render_frame(s, small_frame())), 0) << at;
  }
}

// Sensible: a square a millionth of an inch across, seen by a camera two millionths high (near
// plane 1e-6), covers what the unit square covers: projection in double (renderer.hpp) keeps its
// scale; no step underflows.
TEST(NumericExtremes, CoordinatesNearAMillionthOfAnInch) {
  for (float scale : {1e-6f, 1e-9f}) {
    const scenes::Scene s = square_at(glm::vec3(1e-6f, 0, 0), scale);
    EXPECT_EQ(misplaced(render_frame(s, small_frame(4))), 0) << scale;
  }
}

/// A closed cube of `half` inches around the origin, its faces counter-clockwise seen from outside,
/// unlit in `color`, and a perspective camera at `eye` looking along +X.
scenes::Scene closed_box(float half, glm::vec3 eye, bool double_sided) {
  scenes::Scene s;
  s.name = "box";
  scenes::Camera c;
  c.position = eye;
  c.target = eye + glm::vec3(1, 0, 0);
  c.vertical_fov = 1.2f;
  c.near_plane = 0.01f;
  c.far_plane = 100.0f;
  s.cameras = {c};
  scenes::Material m;
  m.family = scenes::ShaderFamily::unlit_generic;
  m.color = glm::vec4(0.25f, 0.5f, 0.75f, 1.0f);
  m.double_sided = double_sided;
  s.materials = {m};
  scenes::Mesh box;
  box.material = 0;
  const float h = half;
  box.positions = {{-h, -h, -h}, {h, -h, -h}, {h, h, -h}, {-h, h, -h}, {-h, -h, h}, {h, -h, h}, {h, h, h}, {-h, h, h}};
  box.indices = std::vector<uint16_t>{0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                      1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
  s.meshes = {box};
  s.background = glm::vec3(1.0f, 0.0f, 0.0f);
  s.exposure.min_scale = s.exposure.max_scale = 1.0f;
  return s;
}

// Sensible: from inside a closed box every pixel sees the box from behind. Single-sided, every
// face is culled and the frame is the background (red) everywhere; double-sided ($nocull), the box
// fills the frame in its one color. With the eye exactly on a face and on a corner, each pixel is
// the box or the background, nothing else (one sample a pixel: no edge blends).
TEST(NumericExtremes, CameraInsideGeometry) {
  const rasterizer::Image inside = render_frame(closed_box(10, glm::vec3(0.0f), true), small_frame(4));
  uint8_t box_color[3];
  std::memcpy(box_color, pixel(inside, 0, 0), 3);
  for (glm::vec3 eye : {glm::vec3(0.0f), glm::vec3(0, 0, 10), glm::vec3(-10, -10, -10)}) {
    const int samples = eye == glm::vec3(0.0f) ? 4 : 1;
    const rasterizer::Image culled = render_frame(closed_box(10, eye, false), small_frame(samples));
    const rasterizer::Image drawn = render_frame(closed_box(10, eye, true), small_frame(samples));
    int not_background = 0, not_box = 0;
    for (int y = 0; y < kExtremesSize; ++y)
      for (int x = 0; x < kExtremesSize; ++x) {
        not_background += pixel(culled, x, y)[0] != 255 || pixel(culled, x, y)[1] != 0 || pixel(culled, x, y)[2] != 0;
        not_box += std::memcmp(pixel(drawn, x, y), box_color, 3) != 0;
      }
    if (eye == glm::vec3(0.0f)) {  // inside: everything is the box
      EXPECT_EQ(not_background, 0);
      EXPECT_EQ(not_box, 0);
      EXPECT_EQ(box_color[2], 225) << "0.75 sRGB-encoded";
    } else {  // on a face or a corner: what lies outside the box is background; nothing else
      int other = 0;
      for (int y = 0; y < kExtremesSize; ++y)
        for (int x = 0; x < kExtremesSize; ++x) {
          const uint8_t* p = pixel(drawn, x, y);
          other += !(std::memcmp(p, box_color, 3) == 0 || (p[0] == 255 && p[1] == 0 && p[2] == 0));
        }
      EXPECT_EQ(other, 0) << "pixels neither box nor background, eye at " << eye.x << " " << eye.z;
    }
  }
}

/// A lit (VertexLitGeneric) floor 20 inches square at z = 0 seen from above, with a key light at
/// (0, 0, 10) and `extra` added.
scenes::Scene lit_floor(const std::vector<scenes::Light>& extra) {
  scenes::Scene s = top_down();
  s.cameras[0].ortho_height = 20;
  s.cameras[0].position = {0, 0, 15};
  s.cameras[0].far_plane = 40;
  scenes::Material m;
  m.family = scenes::ShaderFamily::vertexlit_generic;
  m.color = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
  s.materials = {m};
  s.meshes = {square(-10, -10, 10, 10, 0, 0)};
  scenes::Model model;
  model.name = "floor";
  model.meshes = {0};
  s.models = {model};
  scenes::Light key;
  key.name = "key";
  key.position = {0, 0, 10};
  key.color = glm::vec3(40.0f);
  key.quadratic = 1.0f;
  s.lights = {key};
  s.lights.insert(s.lights.end(), extra.begin(), extra.end());
  s.background = glm::vec3(0.1f);
  s.exposure.min_scale = s.exposure.max_scale = 1.0f;
  return s;
}

// Sensible: a point light exactly in the floor's plane (at its center and on a vertex, where the
// distance to the lit point reaches 0 and the direction to it is undefined) or just under it
// (inside the surface, behind its front) lights nothing: N.L is 0 or negative, so the frame is the
// one without it, the key light alone, byte for byte (the extra light is the model's second local
// light). Both where the attenuation is computed: per vertex (the SDK's, and on a vertex the
// distance is exactly 0) and per pixel.
TEST(NumericExtremes, LightsOnAndInsideASurface) {
  for (bool per_pixel : {false, true}) {
    FrameSettings f = small_frame();
    f.pixel_attenuation = per_pixel;
    const rasterizer::Image key_only = render_frame(lit_floor({}), f);
    ASSERT_GT(pixel(key_only, kExtremesSize / 2, kExtremesSize / 2)[0], 60) << "the key light lights the floor";
    for (glm::vec3 at : {glm::vec3(0, 0, 0), glm::vec3(-10, -10, 0), glm::vec3(0, 0, -0.01f), glm::vec3(3, 2, -1e-6f)}) {
      scenes::Light l;
      l.name = "in the floor";
      l.position = at;
      l.color = glm::vec3(1000.0f);
      EXPECT_EQ(differing(render_frame(lit_floor({l}), f), key_only), 0)
          << at.x << " " << at.y << " " << at.z << (per_pixel ? ", per pixel" : ", per vertex");
    }
  }
}

// Sensible: the eye exactly at the key light's position changes nothing (the eye is not lit);
// the floor is lit brightest under the light and symmetrically, no pixel of it black.
TEST(NumericExtremes, CameraOnALight) {
  scenes::Scene s = lit_floor({});
  s.cameras[0].position = s.lights[0].position;
  const rasterizer::Image image = render_frame(s, small_frame());
  const uint8_t center = pixel(image, kExtremesSize / 2, kExtremesSize / 2)[0];
  for (int y = 0; y < kExtremesSize; ++y)
    for (int x = 0; x < kExtremesSize; ++x) {
      ASSERT_GT(pixel(image, x, y)[0], 0) << x << " " << y;
      ASSERT_LE(pixel(image, x, y)[0], center) << x << " " << y;
      ASSERT_EQ(pixel(image, x, y)[0], pixel(image, kExtremesSize - 1 - x, y)[0]) << x << " " << y;
    }
}

/// Frames of an unlit square of `color` filling the frame, with auto exposure between 0.25 and 4,
/// adapting fast; returns the scales the frames were drawn with.
std::vector<float> exposures_over(glm::vec3 color, int frames) {
  scenes::Scene s = square_at(glm::vec3(0.0f), 1.0f);
  s.meshes = {square(-10, -10, 10, 10, 0, 0)};
  s.materials[0].color = glm::vec4(color, 1.0f);
  s.exposure.min_scale = 0.25f;
  s.exposure.max_scale = 4.0f;
  s.exposure.rate = 10.0f;
  FrameSettings settings = small_frame();
  Renderer renderer(s, settings);
  rasterizer::Context ctx(2);
  std::vector<float> scales;
  for (int n = 0; n < frames; ++n) {
    renderer.set_time(float(n) / 30.0f);
    scales.push_back(renderer.exposure());
    renderer.render(ctx);
  }
  return scales;
}

// Sensible: an all-black frame has no bright pixels to aim at: the scale only rises, stays finite
// and approaches the range's maximum; an all-white (1e6, far past saturation) frame only lowers it,
// towards the minimum. Neither overshoots the range nor becomes NaN from an empty or saturated histogram.
TEST(NumericExtremes, AllBlackAndAllWhiteFramesThroughAutoExposure) {
  const std::vector<float> black = exposures_over(glm::vec3(0.0f), 300);
  const std::vector<float> white = exposures_over(glm::vec3(1e6f), 300);
  for (size_t n = 0; n < black.size(); ++n) {
    ASSERT_TRUE(std::isfinite(black[n]) && black[n] >= 0.25f && black[n] <= 4.0f) << n << ": " << black[n];
    ASSERT_TRUE(std::isfinite(white[n]) && white[n] >= 0.25f && white[n] <= 4.0f) << n << ": " << white[n];
    if (n > 0) {
      ASSERT_GE(black[n], black[n - 1]) << n;
      ASSERT_LE(white[n], white[n - 1]) << n;
    }
  }
  EXPECT_NEAR(black.back(), 4.0f, 0.05f) << "approaching the maximum in 10 s";
  EXPECT_NEAR(white.back(), 0.25f, 0.025f) << "approaching the minimum in 10 s";
}

// Sensible: 1e30 (a float, 10^22 times past anything an 8-bit target shows) is white after the
// tone map, through the bloom (white plus bloom is white) and through a color correction whose
// LUT maps white to its own white; the dark half of the frame stays finite and dark-ish, nothing
// is NaN-black where it was lit.
TEST(NumericExtremes, HdrOf1e30ThroughToneMappingBloomAndColorCorrection) {
  scenes::Scene s = square_at(glm::vec3(0.0f), 1.0f);
  s.materials[0].color = glm::vec4(1e30f, 1e30f, 1e30f, 1.0f);
  s.background = glm::vec3(0.05f);
  FrameSettings plain = small_frame();
  const rasterizer::Image toned = render_frame(s, plain);
  EXPECT_EQ(misplaced(toned), kExtremesSize * kExtremesSize - 32 * 32) << "inside white, outside the background (not black)";
  for (int y = 16; y < 48; ++y)
    for (int x = 16; x < 48; ++x) ASSERT_EQ(pixel(toned, x, y)[0], 255);
  FrameSettings post = plain;
  post.bloom = postfx::BloomOptions{};
  scenes::ColorCorrection grade;  // a global node at full weight
  grade.lut = "builtin:warm";
  grade.min_falloff = grade.max_falloff = -1.0f;
  s.color_corrections = {grade};
  const rasterizer::Image graded = render_frame(s, post);
  const uint8_t* white = pixel(graded, kExtremesSize / 2, kExtremesSize / 2);
  for (int y = 16; y < 48; ++y)
    for (int x = 16; x < 48; ++x) ASSERT_EQ(std::memcmp(pixel(graded, x, y), white, 3), 0) << x << " " << y;
  EXPECT_GT(int(white[0]) + white[1] + white[2], 3 * 200) << "the grade's white";
  for (int y = 0; y < kExtremesSize; ++y)
    for (int x = 0; x < kExtremesSize; ++x) ASSERT_GT(int(pixel(graded, x, y)[0]) + pixel(graded, x, y)[1] + pixel(graded, x, y)[2], 0) << x << " " << y;
}

// Sensible: denormal texels are read as the small numbers they are, filtered between their
// neighbours, never NaN. Every texture format the rasterizer has, through both sampling paths, at
// LOD 0 and between mips: float (R32F: 1e-40, a float denormal), half (RGBA16F: 1e-6, a half
// subnormal, a normal float once decoded), and the 8- and 16-bit unorm formats' smallest step
// (they hold no denormals: their smallest nonzero code). In the mode the workers shade in
// (simd::ScopedFlushDenormals: D3D10 flushes float32 denormals) the R32F texel reads as 0, as on
// D3D10 hardware, and every other format as outside it. Then a scene's half-float texture of
// subnormal texels multiplied by a $color of 1e4 renders as the 0.1 it is (sRGB 89), not black.
TEST(NumericExtremes, DenormalTexelsInEveryFormat) {
  using rasterizer::TextureFormat;
  struct Case { TextureFormat format; float value; float tolerance; };
  for (const Case& c : {Case{TextureFormat::R32F, 1e-40f, 1e-41f}, Case{TextureFormat::RGBA16F, 1e-6f, 6e-8f},
                        Case{TextureFormat::RGBA16, 1.0f / 65535, 1e-9f}, Case{TextureFormat::RGBA8, 1.0f / 255, 1e-7f},
                        Case{TextureFormat::RGBA8_sRGB, 1.0f / 255 / 12.92f, 1e-7f}}) {
    rasterizer::Texture t = rasterizer::Texture::create_2d(4, 4, c.format);
    std::vector<glm::vec4> texels(16, glm::vec4(c.value, c.value, c.value, 1.0f));
    t.upload(0, texels);
    t.generate_mips();
    rasterizer::Sampler sampler;  // trilinear, wrap
    namespace simd = rasterizer::simd;
    for (float lod : {0.0f, 0.5f, 1.5f}) {
      const rasterizer::TexCoord coord{simd::Float(0.3f), simd::Float(0.6f), simd::Float(0.0f)};
      float lanes[simd::kLanes];
      sample_level(t, sampler, coord, simd::Float(lod)).x.store_unaligned(lanes);
      for (float got : {rasterizer::sample_reference(t, sampler, glm::vec3(0.3f, 0.6f, 0.0f), lod).x, lanes[0]}) {
        EXPECT_NEAR(got, c.value, c.tolerance) << int(c.format) << " lod " << lod;
        EXPECT_GT(got, 0.0f) << int(c.format) << " lod " << lod << ": flushed to zero";
      }
      const simd::ScopedFlushDenormals ftz;
      sample_level(t, sampler, coord, simd::Float(lod)).x.store_unaligned(lanes);
      EXPECT_NEAR(lanes[0], c.format == TextureFormat::R32F ? 0.0f : c.value, c.tolerance) << int(c.format) << " lod " << lod;
      EXPECT_TRUE(std::isfinite(lanes[0]));
    }
  }
  scenes::Scene s = square_at(glm::vec3(0.0f), 2.0f);
  scenes::Texture tiny;
  tiny.name = "subnormal";
  tiny.color_space = scenes::ColorSpace::linear;
  scenes::PixelImage image;
  image.width = image.height = 4;
  image.rgba32f.assign(64, 1e-5f);  // 2^-16.6: below half's smallest normal (6.1e-5)
  for (size_t i = 3; i < 64; i += 4) image.rgba32f[i] = 1.0f;
  tiny.faces = {image};
  s.textures = {tiny};
  s.materials[0].base.texture = 0;
  s.materials[0].color = glm::vec4(1e4f, 1e4f, 1e4f, 1.0f);
  const rasterizer::Image frame = render_frame(s, small_frame());
  EXPECT_NEAR(pixel(frame, kExtremesSize / 2, kExtremesSize / 2)[0], 89, 1) << "1e-5 x 1e4 = 0.1, sRGB-encoded";
}

}  // namespace
}  // namespace luxel::frame
