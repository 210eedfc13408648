// Sky_HDR_DX9: the 16-bit decode (RGBA16 UNORM holds linear / 16) and the RGBS decode with its
// manual bilinear filter, closed forms through real textures on both lanes, SIMD vs scalar, and
// the DX9 budget of every combo.

#include "source_support.hpp"

#include "luxel/shading/source/sky.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

namespace luxel::shading::source {
namespace {

using testing::compare_lanes;
using testing::Draw;

constexpr SkyCombo kHdr16{SkyTexture::hdr16};
constexpr SkyCombo kRgbs{SkyTexture::rgbs_compressed};

rasterizer::Texture uniform_rgba16(uint16_t r, uint16_t g, uint16_t b, uint16_t a) {
  rasterizer::Texture t = rasterizer::Texture::create_2d(4, 4, rasterizer::TextureFormat::RGBA16, 1);
  std::vector<uint8_t> bytes(16 * 8);
  for (int i = 0; i < 16; ++i) {
    const uint16_t c[4] = {r, g, b, a};
    std::memcpy(&bytes[size_t(i) * 8], c, 8);
  }
  t.upload(0, bytes);
  return t;
}

template <Lane L>
SkyInputs<L> at(float u, float v) {
  SkyInputs<L> in;
  in.uv = float2<L>(L(u), L(v));
  return in;
}

TEST(SourceSky, Rgba16DecodesToSixteenTimesTheUnormValue) {
  const rasterizer::Texture tex = uniform_rgba16(8192, 65535, 0, 32768);
  SkyParams p;
  p.base.texture = &tex;
  p.input_scale = glm::vec4(sky_input_scale(SkyFormat::rgba16, glm::vec3(1.0f, 0.5f, 2.0f)), 1.0f);
  p.tonemap = ToneMapConstants::for_scale(0.75f);
  const float4<float> s = sky<kHdr16>(at<float>(0.3f, 0.6f), p);
  EXPECT_NEAR(s.x, 8192.0 / 65535.0 * 16.0 * 1.0 * 0.75, 1e-6);
  EXPECT_NEAR(s.y, 16.0 * 0.5 * 0.75, 1e-6) << "65535 is linear 16, the top of the range";
  EXPECT_EQ(s.z, 0.0f);
  EXPECT_NEAR(s.w, 32768.0 / 65535.0, 1e-7) << "alpha is the texel's, not scaled or tone-mapped";
  const float4<simd::Float> v = sky<kHdr16>(at<simd::Float>(0.3f, 0.6f), p);
  for (int l = 0; l < simd::kLanes; ++l) EXPECT_NEAR(testing::lane_of(v.x, l), s.x, 1e-6f);
  EXPECT_EQ(sky_input_scale(SkyFormat::rgba16f, glm::vec3(0.5f)), glm::vec3(0.5f)) << "half floats hold linear light";
}

TEST(SourceSky, Rgba16RoundTripKeepsSixteenBitsOfHeadroom) {
  double worst = 0.0;
  for (float linear : {0.001f, 0.25f, 1.0f, 3.7f, 9.99f, 15.9f}) {
    const uint16_t stored = static_cast<uint16_t>(std::lround(encode_sky_rgba16(linear) * 65535.0f));
    const double decoded = stored / 65535.0 * 16.0;
    worst = std::max(worst, std::abs(decoded - linear));
  }
  EXPECT_LE(worst, 0.5 * 16.0 / 65535.0 + 1e-7) << "half a step of 16/65535";
  EXPECT_EQ(encode_sky_rgba16(100.0f), 1.0f) << "above 16 clips";
}

TEST(SourceSky, RgbsDecodesEachTexelBeforeInterpolating) {
  SkyTexels<float> t;
  t.s00 = float4<float>(1.0f, 0.5f, 0.0f, 1.0f);
  t.s10 = float4<float>(0.0f, 0.5f, 1.0f, 0.25f);
  t.s01 = float4<float>(0.5f, 0.5f, 0.5f, 0.5f);
  t.s11 = float4<float>(1.0f, 1.0f, 1.0f, 0.0f);
  SkyParams p;
  p.input_scale = glm::vec4(sky_rgbs_input_scale(), 1.0f);
  SkyInputs<float> in;
  in.uv_in_texels = float2<float>(7.25f, -2.5f);  // fractions 0.25 and 0.5
  const float4<float> c = sky_combine<kRgbs>(t, in, p);
  // Decoded: s00 (1, .5, 0), s10 (0, .125, .25), s01 (.25, .25, .25), s11 0.
  const double top[3] = {0.75 * 1.0 + 0.25 * 0.0, 0.75 * 0.5 + 0.25 * 0.125, 0.75 * 0.0 + 0.25 * 0.25};
  const double bottom[3] = {0.75 * 0.25, 0.75 * 0.25, 0.75 * 0.25};
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k], 8.0 * (0.5 * top[k] + 0.5 * bottom[k]), 1e-6) << k;
  EXPECT_EQ(c.w, 1.0f);
  // Filtering rgb and alpha separately (what a bilinear fetch would do) is a different image.
  const double separate = 8.0 * (0.75 * 0.5 * 1.0 + 0.25 * 0.5 * 0.0 + 0.75 * 0.5 * 0.5 + 0.25 * 0.5 * 1.0) *
                          (0.75 * 0.5 * 1.0 + 0.25 * 0.5 * 0.25 + 0.75 * 0.5 * 0.5 + 0.25 * 0.5 * 0.0);
  EXPECT_GT(std::abs(separate - c.x), 0.1);
}

TEST(SourceSky, RgbsCoordinatesReadTheFourTexelsBilinearFilteringWould) {
  // A 4x4 RGBA8 texture with distinct texels, point sampled: the shader through the reconstructed
  // interpolants must equal the double-precision bilinear of the decoded texels.
  const int N = 4;
  rasterizer::Texture tex = rasterizer::Texture::create_2d(N, N, rasterizer::TextureFormat::RGBA8, 1);
  std::vector<uint8_t> bytes(N * N * 4);
  for (int i = 0; i < N * N; ++i) {
    bytes[size_t(i) * 4 + 0] = static_cast<uint8_t>(17 * i);
    bytes[size_t(i) * 4 + 1] = static_cast<uint8_t>(255 - 9 * i);
    bytes[size_t(i) * 4 + 2] = static_cast<uint8_t>((i * 37) % 256);
    bytes[size_t(i) * 4 + 3] = static_cast<uint8_t>(32 + 13 * i);
  }
  tex.upload(0, bytes);
  SkyParams p;
  p.base.texture = &tex;
  p.base.state.min = p.base.state.mag = rasterizer::Filter::Point;
  p.base.state.mip = rasterizer::MipFilter::None;
  p.base.state.u = p.base.state.v = rasterizer::Address::Clamp;
  p.input_scale = glm::vec4(sky_rgbs_input_scale(), 1.0f);
  auto decoded = [&](int x, int y, int c) {
    x = std::clamp(x, 0, N - 1);
    y = std::clamp(y, 0, N - 1);
    const uint8_t* t = &bytes[(size_t(y) * N + x) * 4];
    return t[c] / 255.0 * (t[3] / 255.0) * 8.0;
  };
  // Positions at least 0.01 texel from a texel center: closer, the SDK's fudge (0.01 / size off
  // the half-texel offsets, "per ATI") makes both taps of a row read the same texel.
  for (float u : {0.3f, 0.55f, 0.2f, 0.8f})
    for (float v : {0.2f, 0.5f, 0.71f}) {
      SkyInputs<float> in;
      sky_rgbs_coordinates(float2<float>(u, v), float(N), float(N), in);
      const float4<float> c = sky<kRgbs>(in, p);
      SkyInputs<simd::Float> vin;
      sky_rgbs_coordinates(float2<simd::Float>(simd::Float(u), simd::Float(v)), float(N), float(N), vin);
      const float4<simd::Float> vc = sky<kRgbs>(vin, p);
      const double px = u * N - 0.5, py = v * N - 0.5;
      const int x = int(std::floor(px)), y = int(std::floor(py));
      const double fx = px - x, fy = py - y;
      for (int k = 0; k < 3; ++k) {
        const double top = decoded(x, y, k) * (1 - fx) + decoded(x + 1, y, k) * fx;
        const double bottom = decoded(x, y + 1, k) * (1 - fx) + decoded(x + 1, y + 1, k) * fx;
        EXPECT_NEAR(c[k], top * (1 - fy) + bottom * fy, 2e-5) << "u " << u << " v " << v << " channel " << k;
        EXPECT_EQ(testing::lane_of(vc[k], 0), c[k]) << "SIMD lane";
      }
    }
}

template <SkyCombo C>
testing::LaneComparison compare_sky(int hard_every, uint32_t seed) {
  SkyParams p;
  p.input_scale = glm::vec4(C.texture == SkyTexture::hdr16 ? sky_input_scale(SkyFormat::rgba16) : sky_rgbs_input_scale(), 1.0f);
  p.tonemap = ToneMapConstants::for_scale(0.6f);
  auto shade = [&]<class L>(const auto& get) -> float4<L> {
    SkyTexels<L> t;
    t.base = float4<L>(get(0), get(1), get(2), get(3));
    t.s00 = float4<L>(get(4), get(5), get(6), get(7));
    t.s01 = float4<L>(get(8), get(9), get(10), get(11));
    t.s10 = float4<L>(get(12), get(13), get(14), get(15));
    t.s11 = float4<L>(get(16), get(17), get(18), get(19));
    SkyInputs<L> in;
    in.uv_in_texels = float2<L>(get(20), get(21));
    return sky_combine<C>(t, in, p);
  };
  std::vector<Draw> draws(22, Draw{0.0f, 1.0f, hard_every});
  draws[20] = draws[21] = Draw{-100.0f, 100.0f, hard_every};
  return compare_lanes<22>(shade, draws, 512, seed);
}

TEST(SourceSky, SimdAgreesWithScalarBitForBitForEveryCombo) {
  uint32_t seed = 71;
  for_each_combo<kSkySpace>([&]<SkyCombo C>() {
    const auto random = compare_sky<C>(0, seed++);
    const auto hard = compare_sky<C>(3, seed++);
    testing::expect_bit_identical(random, C.name());
    testing::expect_bit_identical(hard, C.name() + " (hard inputs)");
    std::printf("Sky %-8s simd-vs-scalar max %d step(s) (hard: %d)\n", C.name().c_str(), random.max_step, hard.max_step);
  });
}

TEST(SourceSky, EveryComboFitsEveryPixelShaderModel) {
  for_each_combo<kSkySpace>([&]<SkyCombo C>() {
    for (ShaderModel m : kPixelModels) {
      const Cost cost = measure_sky<C>(m);
      const Verdict v = fits(cost, caps(m));
      EXPECT_TRUE(v) << C.name() << ": " << v.reason;
      EXPECT_EQ(cost.texture_slots, C.texture == SkyTexture::hdr16 ? 1 : 4) << C.name();
    }
  });
}

}  // namespace
}  // namespace luxel::shading::source
