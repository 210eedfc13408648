// The color-correction shader: the volume coordinate lands on texel centers, the blend is
// the formula's at colors where a wrong weight or a missing term shows, SIMD and scalar lanes agree
// in bits, every combo fits every pixel-shader model with one fetch per LUT behind one dependent
// read, and a lookup between lattice points is the trilinear mix of its eight neighbours.

#include "source_support.hpp"

#include "luxel/shading/source/color_correction.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

namespace luxel::shading::source {
namespace {

using testing::compare_lanes;
using testing::Draw;
using testing::expect_bit_identical;

TEST(SourceColorCorrection, CoordinatesHitTheFirstAndLastTexelCentersAndEveryLatticePoint) {
  const float3<float> black = color_correction_uvw(float3<float>(0.0f));
  const float3<float> white = color_correction_uvw(float3<float>(1.0f));
  EXPECT_EQ(black.x, 0.5f / 32.0f);
  EXPECT_EQ(white.y, 31.5f / 32.0f);
  for (int i = 0; i < 32; ++i) {
    const float texel = color_correction_uvw(float3<float>(i / 31.0f)).z * 32.0f - 0.5f;
    EXPECT_NEAR(texel, float(i), 2e-5f) << "lattice point " << i << "/31 reads texel " << i;
  }
}

TEST(SourceColorCorrection, BlendIsFrameTimesDefaultPlusWeightedLookups) {
  ColorCorrectionParams p;
  p.lut_weights = glm::vec4(0.25f, 0.5f, 0.125f, 0.0625f);
  p.default_weight = 0.0625f;
  const float3<float> frame(0.8f, 0.3f, 0.55f);
  const std::array<float3<float>, 4> lookups = {float3<float>(0.1f, 0.9f, 0.4f), float3<float>(0.7f, 0.2f, 0.35f),
                                                float3<float>(0.05f, 0.6f, 1.0f), float3<float>(0.95f, 0.45f, 0.15f)};
  for_each_combo<kColorCorrectionSpace>([&]<ColorCorrectionCombo C>() {
    const float3<float> out = color_correction_combine<C>(frame, lookups, p.lut_weights, p.default_weight);
    for (int c = 0; c < 3; ++c) {
      double expect = double(frame[c]) * p.default_weight;
      for (int k = 0; k < C.luts; ++k) expect += double(lookups[k][c]) * p.lut_weights[k];
      EXPECT_NEAR(out[c], expect, 1e-6) << C.name() << " channel " << c;
    }
  });
}

TEST(SourceColorCorrection, SimdAgreesWithScalarInBits) {
  ColorCorrectionParams p;
  p.lut_weights = glm::vec4(0.3f, 0.2f, 0.15f, 0.1f);
  p.default_weight = 0.25f;
  for_each_combo<kColorCorrectionSpace>([&]<ColorCorrectionCombo C>() {
    for (int hard_every : {0, 4}) {
      auto shade = [&]<class L>(const auto& get) -> float4<L> {
        std::array<float3<L>, 4> lookups;
        for (int k = 0; k < 4; ++k) lookups[k] = float3<L>(get(3 + 3 * k), get(4 + 3 * k), get(5 + 3 * k));
        return float4<L>(color_correction_combine<C>(float3<L>(get(0), get(1), get(2)), lookups, p.lut_weights, p.default_weight), get(0));
      };
      const auto r = compare_lanes<15>(shade, {Draw{0.0f, 1.0f, hard_every}}, 512, 7u + C.luts);
      expect_bit_identical(r, C.name());
    }
  });
}

TEST(SourceColorCorrection, EveryComboFitsEveryPixelShaderModel) {
  for_each_combo<kColorCorrectionSpace>([&]<ColorCorrectionCombo C>() {
    for (ShaderModel m : kPixelModels) {
      const Cost cost = measure_color_correction<C>(m);
      const Verdict v = fits(cost, caps(m));
      EXPECT_TRUE(v) << C.name() << ": " << v.reason;
      EXPECT_EQ(cost.texture_slots, 1 + C.luts) << C.name() << " " << describe(cost);
      EXPECT_EQ(cost.samplers, 1 + C.luts) << C.name();
      EXPECT_EQ(cost.texture_indirections, 2) << "the lookups read at coordinates computed from the frame's texel";
      // One mad for the coordinates, one mul for the default weight, one mad per lookup; ps_2_x
      // assembles the output in a temp and moves it to oC0.
      const int mov_to_output = m == ShaderModel::ps_3_0 ? 0 : 1;
      EXPECT_EQ(cost.arithmetic_slots, 2 + C.luts + mov_to_output) << C.name() << " " << describe(cost);
      std::printf("ColorCorrection %s %s\n", C.name().c_str(), describe(cost).c_str());
    }
  });
}

/// A 32^3 RGBA8 volume whose texel (i, j, k) holds (f(i), g(j), h(k)) bytes of simple distinct
/// functions, so a trilinear read at a point between lattice points is known in closed form.
TEST(SourceColorCorrection, LookupIsTrilinearBetweenLatticePoints) {
  rasterizer::Texture volume = rasterizer::Texture::create_volume(32, 32, 32, rasterizer::TextureFormat::RGBA8, 1);
  auto f = [](int i) { return (i * 7) % 256; };
  auto g = [](int j) { return 255 - 8 * j; };
  auto h = [](int k) { return (k * k) % 256; };
  std::vector<uint8_t> bytes(32 * 32 * 32 * 4);
  for (int k = 0; k < 32; ++k)
    for (int j = 0; j < 32; ++j)
      for (int i = 0; i < 32; ++i) {
        uint8_t* t = &bytes[((size_t(k) * 32 + j) * 32 + i) * 4];
        t[0] = uint8_t(f(i)), t[1] = uint8_t(g(j)), t[2] = uint8_t(h(k)), t[3] = 255;
      }
  volume.upload(0, bytes);
  ColorCorrectionParams p;
  p.luts[0].texture = &volume;
  p.lut_weights = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
  p.default_weight = 0.0f;
  for (const glm::vec3 color : {glm::vec3(0.3f, 0.61f, 0.95f), glm::vec3(0.02f, 0.5f, 0.77f), glm::vec3(1.0f, 0.0f, 0.4f)}) {
    const float3<float> uvw = color_correction_uvw(float3<float>(color.x, color.y, color.z));
    const float4<float> read = tex3D(p.luts[0], uvw);
    // Separable texels: the trilinear mix of (f, g, h) is the mix of each along its axis (the
    // blends along the other two axes are of equal values). The hardware rules: the position in
    // 16.8 fixed point, rounded; the blend of two 8-bit values rounded to a step.
    auto linear = [](auto fn, float c) {
      const long fixed = std::lround(std::nearbyint(std::clamp(double(c) * 31.0, 0.0, 31.0) * 256.0));
      const int i0 = int(fixed >> 8), w = int(fixed & 255);
      const double a = fn(i0), b = fn(std::min(i0 + 1, 31));
      return (a + std::floor(w * (b - a) / 256.0 + 0.5)) / 255.0;
    };
    EXPECT_NEAR(read.x, linear(f, color.x), 2e-5) << color.x;
    EXPECT_NEAR(read.y, linear(g, color.y), 2e-5) << color.y;
    EXPECT_NEAR(read.z, linear(h, color.z), 2e-5) << color.z;
  }
}

}  // namespace
}  // namespace luxel::shading::source
