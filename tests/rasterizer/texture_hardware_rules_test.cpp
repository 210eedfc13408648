// The hardware sampling rules (texture.hpp, "Sampling rules"), one test per rule, each on inputs
// where the ideal rules (float weights and filtering, a LOD per pixel) give another answer: the
// expected values are worked out by hand from the rule, and each test also checks that the ideal
// rules miss them, so that a float or per-pixel implementation cannot pass.

#include "luxel/rasterizer/srgb.hpp"
#include "luxel/rasterizer/texture.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

namespace luxel::rasterizer::hardware_rules_test {
namespace {

using simd::kLanes;

std::array<glm::vec4, kLanes> lanes_of(const simd::Float4& r) {
  std::array<float, kLanes> x, y, z, w;
  r.x.store_unaligned(x.data());
  r.y.store_unaligned(y.data());
  r.z.store_unaligned(z.data());
  r.w.store_unaligned(w.data());
  std::array<glm::vec4, kLanes> out;
  for (int l = 0; l < kLanes; ++l) out[l] = {x[l], y[l], z[l], w[l]};
  return out;
}

/// Lane 0 of the SIMD path and the scalar reference at one coordinate, under `rules`: both.
std::array<glm::vec4, 2> read(const Texture& t, Sampler s, SamplingRules rules, glm::vec3 c, float lod) {
  s.rules = rules;
  const TexCoord coord{simd::Float(c.x), simd::Float(c.y), simd::Float(c.z)};
  return {lanes_of(sample_level(t, s, coord, simd::Float(lod)))[0], sample_reference(t, s, c, lod)};
}

Sampler bilinear_clamped() {
  Sampler s;
  s.mip = MipFilter::None;
  s.u = s.v = s.w = Address::Clamp;
  return s;
}

/// A 2x1 RGBA16F texture (no fixed point: the weights alone decide) holding 0 and 1.
Texture zero_one_half_floats() {
  Texture t = Texture::create_2d(2, 1, TextureFormat::RGBA16F, 1);
  t.upload(0, std::vector<glm::vec4>{glm::vec4(0.0f), glm::vec4(1.0f)});
  return t;
}

TEST(TextureHardwareRules, BilinearWeightsHaveEightBits) {
  // u = 0.4 on 2 texels: position 0.3 past texel 0's center, 76.8 / 256 of the way to texel 1:
  // rounded to 77 / 256 (16.8 fixed point, to nearest).
  const Texture t = zero_one_half_floats();
  for (const glm::vec4 got : read(t, bilinear_clamped(), SamplingRules::hardware, {0.4f, 0.5f, 0}, 0)) EXPECT_EQ(got.x, 77.0f / 256.0f);
  for (const glm::vec4 got : read(t, bilinear_clamped(), SamplingRules::ideal, {0.4f, 0.5f, 0}, 0)) EXPECT_NEAR(got.x, 0.3f, 1e-6f);
}

TEST(TextureHardwareRules, TexelPositionsSnapToTheNearestEighthBit) {
  // Position 0.999 past texel 0's center rounds to 256 / 256: the footprint moves on to texels
  // 1 and 2 (clamped: 1) with weight 0, and reads texel 1 exactly.
  const Texture t = zero_one_half_floats();
  const float u = (0.999f + 0.5f) / 2.0f;
  for (const glm::vec4 got : read(t, bilinear_clamped(), SamplingRules::hardware, {u, 0.5f, 0}, 0)) EXPECT_EQ(got.x, 1.0f);
  for (const glm::vec4 got : read(t, bilinear_clamped(), SamplingRules::ideal, {u, 0.5f, 0}, 0)) EXPECT_LT(got.x, 0.9995f);
}

TEST(TextureHardwareRules, EightBitTexelsBlendInFixedPointRoundingEachStep) {
  // Texels 0 and 255 halfway: 0 + floor(128 x 255 / 256 + 1/2) = 128 (a truncating blend gives
  // 127, float 127.5).
  Texture t = Texture::create_2d(2, 1, TextureFormat::RGBA8, 1);
  t.upload(0, std::vector<uint8_t>{0, 0, 0, 255, 255, 255, 255, 255});
  for (const glm::vec4 got : read(t, bilinear_clamped(), SamplingRules::hardware, {0.5f, 0.5f, 0}, 0)) EXPECT_EQ(got.x, 128.0f / 255.0f);
  for (const glm::vec4 got : read(t, bilinear_clamped(), SamplingRules::ideal, {0.5f, 0.5f, 0}, 0)) EXPECT_NEAR(got.x, 0.5f, 1e-6f);
  // Each blend rounds to an integer before the next: a 2x2 footprint of 0, 1 / 1, 0 at its
  // center is the blend of rows 0 + floor(128 / 256 + 1/2) = 1 and 1 + floor(-128 / 256 + 1/2) = 1:
  // 1, where exact weights give 0.5.
  Texture checker = Texture::create_2d(2, 2, TextureFormat::RGBA8, 1);
  checker.upload(0, std::vector<uint8_t>{0, 0, 0, 255, 1, 1, 1, 255, 1, 1, 1, 255, 0, 0, 0, 255});
  for (const glm::vec4 got : read(checker, bilinear_clamped(), SamplingRules::hardware, {0.5f, 0.5f, 0}, 0)) EXPECT_EQ(got.x, 1.0f / 255.0f);
  for (const glm::vec4 got : read(checker, bilinear_clamped(), SamplingRules::ideal, {0.5f, 0.5f, 0}, 0)) EXPECT_NEAR(got.x, 0.5f / 255.0f, 1e-7f);
}

TEST(TextureHardwareRules, SrgbIsDecodedAfterFiltering) {
  // Codes 10 and 255 halfway: the filtered code 133 decoded (0.2346), not the mean of the decoded
  // values (0.5015).
  Texture t = Texture::create_2d(2, 1, TextureFormat::RGBA8_sRGB, 1);
  t.upload(0, std::vector<uint8_t>{10, 10, 10, 255, 255, 255, 255, 255});
  for (const glm::vec4 got : read(t, bilinear_clamped(), SamplingRules::hardware, {0.5f, 0.5f, 0}, 0)) EXPECT_EQ(got.x, kSrgbToLinear[133]);
  for (const glm::vec4 got : read(t, bilinear_clamped(), SamplingRules::ideal, {0.5f, 0.5f, 0}, 0)) EXPECT_NEAR(got.x, 0.5015176f, 1e-6f);
}

TEST(TextureHardwareRules, TheLodHasEightFractionalBits) {
  // Level 0 black, level 1 white, trilinear at LOD 0.3: 77 / 256 of the way (76.8 rounded).
  Texture t = Texture::create_2d(2, 2, TextureFormat::RGBA16F, 2);
  t.upload(0, std::vector<glm::vec4>(4, glm::vec4(0.0f)));
  t.upload(1, std::vector<glm::vec4>{glm::vec4(1.0f)});
  Sampler s;
  for (const glm::vec4 got : read(t, s, SamplingRules::hardware, {0.5f, 0.5f, 0}, 0.3f)) EXPECT_EQ(got.x, 77.0f / 256.0f);
  for (const glm::vec4 got : read(t, s, SamplingRules::ideal, {0.5f, 0.5f, 0}, 0.3f)) EXPECT_NEAR(got.x, 0.3f, 1e-6f);
}

TEST(TextureHardwareRules, OneLodPerQuadFromItsTopLeftPixel) {
  // A cube map whose levels are constant colors (level l holds l / 8), read along directions whose
  // major axis shrinks across each quad: the LOD of a cube read grows as |ma| shrinks, so each
  // pixel of a quad has its own. Under the hardware rules every pixel reads at its quad's
  // top-left pixel's LOD; under the ideal rules at its own.
  Texture t = Texture::create_cube(64, TextureFormat::RGBA16F);
  for (int level = 0; level < t.mip_levels(); ++level) {
    const int n = t.width(level);
    for (int face = 0; face < 6; ++face)
      t.upload(level, std::vector<glm::vec4>(size_t(n) * n, glm::vec4(float(level) / 8.0f)), face);
  }
  std::array<float, kLanes> x, y, z;
  for (int l = 0; l < kLanes; ++l) {
    const float px = float(simd::lane_x(l)), py = float(simd::lane_y(l));
    x[l] = 0.01f * px, y[l] = 0.01f * py, z[l] = 1.0f / (1.0f + 0.6f * (px + py));  // +Z face
  }
  const TexCoord c{simd::Float::load_unaligned(x.data()), simd::Float::load_unaligned(y.data()),
                   simd::Float::load_unaligned(z.data())};
  Sampler s;
  s.rules = SamplingRules::hardware;
  const auto hardware = lanes_of(sample(t, s, c));
  s.rules = SamplingRules::ideal;
  const auto ideal = lanes_of(sample(t, s, c));
  bool any_pixel_differs_from_its_quad = false;
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_EQ(hardware[l].x, hardware[l - l % 4].x) << "lane " << l;
    any_pixel_differs_from_its_quad |= ideal[l].x != ideal[l - l % 4].x;
  }
  EXPECT_TRUE(any_pixel_differs_from_its_quad) << "the test's directions no longer give a quad's pixels different LODs";
}

}  // namespace
}  // namespace luxel::rasterizer::hardware_rules_test
