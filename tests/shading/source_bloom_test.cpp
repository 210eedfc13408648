// The bloom's shaders (docs/fidelity.md#bloom): the downsample's shaped taps against double math, the
// blur's 13 taps reproducing the 25 per-texel weights on a delta (both axes, with and without the
// vertical step quirk), bloomadd returning its texel, SIMD vs scalar, and the budgets.

#include "source_support.hpp"

#include "luxel/shading/source/bloom_add.hpp"
#include "luxel/shading/source/bloom_blur.hpp"
#include "luxel/shading/source/bloom_downsample.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <random>

namespace luxel::shading::source {
namespace {

using testing::compare_lanes;
using testing::Draw;
using testing::expect_bit_identical;

/// The downsample in double, from the formula.
glm::dvec3 downsample_reference(const std::array<glm::dvec3, 4>& taps, const glm::dvec4& tint) {
  glm::dvec3 sum(0.0);
  for (const glm::dvec3& p : taps) {
    const double lum = p.x * tint.x + p.y * tint.y + p.z * tint.z;
    sum += glm::dvec3(std::pow(p.x, tint.w), std::pow(p.y, tint.w), std::pow(p.z, tint.w)) * lum;
  }
  return sum / 4.0;
}

TEST(SourceBloomDownsample, ShapedTapsMatchDoubleMath) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> d(0.0, 1.0);
  for (bool tint : {true, false}) {
    DownsampleParams p;
    p.tint = downsample_constant(tint);
    double worst = 0.0;
    for (int i = 0; i < 2000; ++i) {
      std::array<glm::dvec3, 4> taps;
      std::array<float3<float>, 4> lanes;
      for (int t = 0; t < 4; ++t) {
        // Bytes, as the 8-bit frame holds them.
        taps[t] = glm::dvec3(std::floor(d(rng) * 256.0), std::floor(d(rng) * 256.0), std::floor(d(rng) * 256.0)) / 255.0;
        lanes[t] = float3<float>(float(taps[t].x), float(taps[t].y), float(taps[t].z));
      }
      const glm::dvec3 expected = downsample_reference(taps, glm::dvec4(p.tint));
      const float4<float> got = downsample_combine(lanes, p);
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(got[c] - expected[c]));
      EXPECT_EQ(got.w, 1.0f);
    }
    // The lanes' pow is exp2(y log2 x) with float polynomials; well inside one 8-bit step.
    EXPECT_LT(worst, 2e-6) << (tint ? "tint" : "no tint");
    std::printf("Downsample (%s) max |float - double| %.2e\n", tint ? "tint" : "no tint", worst);
  }
  // A worked value: grey 0.5 with the tint: 0.5^2.2 * 0.5 = 0.10881882.
  DownsampleParams p;
  const float3<float> grey(0.5f, 0.5f, 0.5f);
  EXPECT_NEAR(downsample_combine<float>({grey, grey, grey, grey}, p).x, std::pow(0.5, 2.2) * 0.5, 1e-6);
}

TEST(SourceBloomShaders, SimdAgreesWithScalarExactly) {
  for (int hard_every : {0, 3}) {
    const std::vector<Draw> draws = {Draw{0.0f, 1.0f, hard_every}};
    for (bool tint : {true, false}) {
      DownsampleParams p;
      p.tint = downsample_constant(tint);
      auto shade = [&]<class L>(const auto& get) {
        std::array<float3<L>, 4> taps;
        for (int i = 0; i < 4; ++i) taps[i] = float3<L>(get(3 * i), get(3 * i + 1), get(3 * i + 2));
        return downsample_combine(taps, p);
      };
      expect_bit_identical(compare_lanes<12>(shade, draws, 512, 3u + hard_every), "downsample");
    }
    const BlurParams blur_params = blur_constants(BlurAxis::vertical, 64, 36, BlurStep::sdk_width_quirk, 0.7f);
    auto blur_shade = [&]<class L>(const auto& get) {
      BlurTaps<L> t;
      t.centre = float3<L>(get(0), get(1), get(2));
      for (int k = 0; k < 6; ++k) {
        t.plus[k] = float3<L>(get(3 + 3 * k), get(4 + 3 * k), get(5 + 3 * k));
        t.minus[k] = float3<L>(get(21 + 3 * k), get(22 + 3 * k), get(23 + 3 * k));
      }
      return blur_combine(t, blur_params);
    };
    expect_bit_identical(compare_lanes<39>(blur_shade, draws, 512, 5u + hard_every), "blur");
    auto add_shade = [&]<class L>(const auto& get) { return bloom_add_combine(float3<L>(get(0), get(1), get(2))); };
    expect_bit_identical(compare_lanes<3>(add_shade, draws, 256, 7u + hard_every), "bloomadd");
  }
}

/// A width x height R32F texture, 0 everywhere but 1 at (cx, cy); reads (r, 1, 1, 1).
rasterizer::Texture delta_texture(int width, int height, int cx, int cy) {
  std::vector<glm::vec4> texels(size_t(width) * height, glm::vec4(0.0f));
  texels[size_t(cy) * width + cx] = glm::vec4(1.0f);
  rasterizer::Texture t = rasterizer::Texture::create_2d(width, height, rasterizer::TextureFormat::R32F, 1);
  t.upload(0, texels);
  return t;
}

/// The blur (scalar lane, through the texture) at texel centre (x, y).
float blur_at(const BlurParams& p, int width, int height, int x, int y) {
  return blur<float>(float2<float>((x + 0.5f) / width, (y + 0.5f) / height), p).x;
}

BlurParams delta_blur(const rasterizer::Texture& t, BlurAxis axis, BlurStep step) {
  BlurParams p = blur_constants(axis, t.width(), t.height(), step, 1.0f);
  p.source.texture = &t;
  p.source.state.mip = rasterizer::MipFilter::None;
  p.source.state.u = p.source.state.v = rasterizer::Address::Clamp;
  // The kernel's own weights: the ideal rules' exact bilinear weights (the hardware rules round
  // each tap's to 8 bits: rasterizer/texture.hpp, tested there).
  p.source.state.rules = rasterizer::SamplingRules::ideal;
  return p;
}

// The blur's equivalent per-texel weights for |k| = 0..12.
constexpr double kPerTexel[13] = {0.2013,  0.14495, 0.07355, 0.04684, 0.03526, 0.02644, 0.01966,
                                  0.01478, 0.01142, 0.00901, 0.00719, 0.00571, 0.00449};

TEST(SourceBloomBlur, TapsReproduceThePerTexelWeightsOnADelta) {
  const int W = 64, H = 64, c = 32;
  const rasterizer::Texture delta = delta_texture(W, H, c, c);
  for (BlurAxis axis : {BlurAxis::horizontal, BlurAxis::vertical}) {
    // Square texture: the quirk's 1/width is 1/height, so both axes step whole texels.
    const BlurParams p = delta_blur(delta, axis, BlurStep::sdk_width_quirk);
    double total = 0.0;
    for (int k = -14; k <= 14; ++k) {
      const int x = axis == BlurAxis::horizontal ? c + k : c, y = axis == BlurAxis::vertical ? c + k : c;
      const double w = blur_at(p, W, H, x, y);
      const double expected = std::abs(k) <= 12 ? kPerTexel[std::abs(k)] : 0.0;
      EXPECT_NEAR(w, expected, 6e-6) << "k = " << k << (axis == BlurAxis::horizontal ? " (x)" : " (y)");
      total += w;
    }
    EXPECT_NEAR(total, 0.9999, 1e-5) << "the weights' sum (§8.2)";
  }
}

TEST(SourceBloomBlur, VerticalQuirkStepsHeightOverWidthOfATexel) {
  // 64 x 36 (16:9): a vertical tap at offset o lands o * 36/64 texels away; with the fix, o texels.
  const int W = 64, H = 36, cx = 20, cy = 18;
  const rasterizer::Texture delta = delta_texture(W, H, cx, cy);
  for (BlurStep step : {BlurStep::sdk_width_quirk, BlurStep::true_height}) {
    const double r = step == BlurStep::sdk_width_quirk ? double(H) / W : 1.0;
    // The expected column: each tap's bilinear tent around the delta, in double.
    auto tent = [](double d) { return std::max(0.0, 1.0 - std::abs(d)); };
    const BlurParams p = delta_blur(delta, BlurAxis::vertical, step);
    for (int k = -14; k <= 14; ++k) {
      if (cy + k < 0 || cy + k >= H) continue;
      double expected = kBlurCentreWeight * tent(k);
      for (int t = 0; t < 6; ++t) {
        expected += kBlurPairWeights[t] * (tent(k - kBlurPairOffsets[t] * r) + tent(k + kBlurPairOffsets[t] * r));
      }
      EXPECT_NEAR(blur_at(p, W, H, cx, cy + k), expected, 2e-6) << "k = " << k << " r = " << r;
      EXPECT_EQ(blur_at(p, W, H, cx + 1, cy + k), 0.0f) << "a vertical pass stays in its column";
    }
  }
}

TEST(SourceBloomShaders, FitEveryPixelShaderModel) {
  for (ShaderModel m : kPixelModels) {
    const Cost down = measure_downsample(m), blur_cost = measure_blur(m), add = measure_bloom_add(m);
    for (const Cost* c : {&down, &blur_cost, &add}) {
      const Verdict v = fits(*c, caps(m));
      EXPECT_TRUE(v) << describe(*c) << ": " << v.reason;
    }
    EXPECT_EQ(down.texture_slots, 4) << describe(down);
    EXPECT_EQ(down.texture_indirections, 1) << "the taps come from the vertex shader: " << describe(down);
    EXPECT_EQ(blur_cost.texture_slots, 13) << describe(blur_cost);
    EXPECT_GE(blur_cost.arithmetic_slots, 12 + 13) << "twelve coordinates and thirteen weighted taps";
    EXPECT_EQ(add.texture_slots, 1) << describe(add);
    std::printf("downsample %s\nblur %s\nbloomadd %s\n", describe(down).c_str(), describe(blur_cost).c_str(),
                describe(add).c_str());
  }
}

TEST(SourceBloomAdd, ReturnsTheBloomTexelWithOneOneBlending) {
  const float4<float> c = bloom_add_combine(float3<float>(0.25f, 0.5f, 1.0f));
  EXPECT_EQ(c.x, 0.25f);
  EXPECT_EQ(c.y, 0.5f);
  EXPECT_EQ(c.z, 1.0f);
  EXPECT_EQ(c.w, 1.0f);
  const rasterizer::PipelineState s = bloom_add_pipeline_state();
  EXPECT_TRUE(s.blend.enable);
  EXPECT_EQ(s.blend.src, rasterizer::BlendFactor::One);
  EXPECT_EQ(s.blend.dst, rasterizer::BlendFactor::One);
  EXPECT_FALSE(s.blend.srgb_write) << "the add happens on gamma values (§8.2)";
  EXPECT_EQ(s.blend.write_mask, rasterizer::kWriteRed | rasterizer::kWriteGreen | rasterizer::kWriteBlue);
}

}  // namespace
}  // namespace luxel::shading::source
