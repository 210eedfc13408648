// Bloom (docs/fidelity.md#bloom): black stays black; a bright spot blooms symmetrically across and,
// with the SDK's vertical step, height/width as far down (symmetric again with the step fixed);
// the whole pass against a reference written here in double from its formulas; 1 and 2 threads
// give the same bytes; any frame from 4x4 up; the bloom amount's smoothing.

#include "image_plane.hpp"

#include "luxel/postfx/bloom.hpp"
#include "luxel/postfx/bloom_amount.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace luxel::postfx {
namespace {

using shading::source::BlurStep;
using shading::source::HdrType;
using test::Plane;
using test::plane_of;

rasterizer::Image solid(int width, int height, uint8_t value) {
  rasterizer::Image image(width, height);
  for (size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = (i % 4 == 3) ? 200 : value;
  return image;
}

int channel(const rasterizer::Image& image, int x, int y, int c = 0) { return image.pixel(x, y)[c]; }

TEST(Bloom, OfABlackFrameIsBlackAndAlphaIsKept) {
  rasterizer::Context ctx(2);
  rasterizer::Image frame = solid(96, 64, 0);
  const rasterizer::Image before = frame;
  Bloom bloom;
  bloom.apply(ctx, frame, 1.0f);
  EXPECT_EQ(frame.rgba, before.rgba);
}

// ---- A bright spot ---------------------------------------------------------------------------

/// The first frame texel the downsample's taps read for small texel i along an axis of `frame`
/// texels (the rectangle 0..frame-2 over frame/4 texels, centre to centre; taps at +0.5 and
/// +2.5): small texel i reads frame texels first .. first + 3 and no other small texel does.
int first_texel_read(int i, int frame) {
  const int small = frame / 4;
  return static_cast<int>(std::floor(0.5 + i * double(frame - 2) / (small - 1)));
}

constexpr int kW = 256, kH = 144, kSpot = 10;  // 16:9; the small targets are 64 x 36
constexpr double kPerTexel[13] = {0.2013,  0.14495, 0.07355, 0.04684, 0.03526, 0.02644, 0.01966,
                                  0.01478, 0.01142, 0.00901, 0.00719, 0.00571, 0.00449};

/// White where the predicate says, black elsewhere.
template <class Inside>
rasterizer::Image spot_frame(Inside inside) {
  rasterizer::Image frame = solid(kW, kH, 0);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      if (inside(x, y)) std::fill_n(frame.pixel(x, y), 3, uint8_t(255));
  return frame;
}

bool covers_small_texel(int coordinate, int frame) {
  const int first = first_texel_read(kSpot, frame);
  return coordinate >= first && coordinate <= first + 3;
}

/// The bloom texture (after both blurs, amount 1) of a frame.
rasterizer::Image bloom_texture(const rasterizer::Image& frame, BlurStep step) {
  rasterizer::Context ctx(2);
  BloomOptions options;
  options.vertical_step = step;
  Bloom bloom(options);
  bloom.copy(frame);
  bloom.downsample(ctx);
  EXPECT_EQ(channel(bloom.small_image(), kSpot, kSpot), 255) << "the spot fills one small texel";
  EXPECT_EQ(channel(bloom.small_image(), kSpot + 1, kSpot + 1), 0) << "and only that one";
  bloom.blur_x(ctx);
  bloom.blur_y(ctx, 1.0f);
  return bloom.small_image();
}

/// sqrt(sum k^2 v_k / sum v_k) over a profile centred at kSpot.
double spread(const std::vector<int>& profile) {
  double m0 = 0.0, m2 = 0.0;
  for (size_t i = 0; i < profile.size(); ++i) {
    const double k = double(i) - kSpot;
    m0 += profile[i];
    m2 += k * k * profile[i];
  }
  return std::sqrt(m2 / m0);
}

TEST(Bloom, ASpotBloomsSymmetricallyAcross) {
  const rasterizer::Image spot = spot_frame(
      [](int x, int y) { return covers_small_texel(x, kW) && covers_small_texel(y, kH); });
  const rasterizer::Image t = bloom_texture(spot, BlurStep::sdk_width_quirk);
  int asymmetric = 0;
  for (int y = 0; y < t.height; ++y)
    for (int k = 1; k <= kSpot; ++k) asymmetric += channel(t, kSpot - k, y) != channel(t, kSpot + k, y);
  EXPECT_EQ(asymmetric, 0) << "left and right of the spot, every row";
  EXPECT_GT(channel(t, kSpot, kSpot), channel(t, kSpot + 1, kSpot));
}

TEST(Bloom, HorizontalProfileIsThePerTexelKernel) {
  // A vertical stripe one small texel wide: blur y leaves it, each row is blur x's profile.
  const rasterizer::Image stripe = spot_frame([](int x, int) { return covers_small_texel(x, kW); });
  const rasterizer::Image t = bloom_texture(stripe, BlurStep::sdk_width_quirk);
  for (int k = -kSpot; k <= 12; ++k) {
    const int expected = static_cast<int>(std::lround(255.0 * kPerTexel[std::abs(k)]));
    EXPECT_NEAR(channel(t, kSpot + k, 20), expected, 1) << "k = " << k << ": rounded twice, so within a step";
  }
}

/// The vertical profile (a horizontal stripe, so blur x leaves it) and the horizontal one.
struct Profiles {
  std::vector<int> across, down;
};
Profiles profiles(BlurStep step) {
  const rasterizer::Image vertical_stripe = spot_frame([](int x, int) { return covers_small_texel(x, kW); });
  const rasterizer::Image horizontal_stripe = spot_frame([](int, int y) { return covers_small_texel(y, kH); });
  const rasterizer::Image a = bloom_texture(vertical_stripe, step), d = bloom_texture(horizontal_stripe, step);
  Profiles p;
  for (int i = 0; i < 2 * kSpot + 1; ++i) {
    p.across.push_back(channel(a, i, 20));
    p.down.push_back(channel(d, 30, i));
  }
  return p;
}

TEST(Bloom, VerticalSpreadFollowsTheWidthStepQuirkAndIsSymmetricWithoutIt) {
  const Profiles quirk = profiles(BlurStep::sdk_width_quirk), fixed = profiles(BlurStep::true_height);
  const double ratio = spread(quirk.down) / spread(quirk.across), fixed_ratio = spread(fixed.down) / spread(fixed.across);
  std::printf("vertical/horizontal spread: quirk %.3f (height/width %.4f), fixed %.3f\n", ratio, double(kH) / kW,
              fixed_ratio);
  // Taps h/w as far apart, each spread by a one-texel bilinear tent: the spread shrinks by a
  // little less than h/w.
  EXPECT_GT(ratio, 0.5625);
  EXPECT_LT(ratio, 0.70);
  // The down profile with the quirk: the tents of the taps at o * h/w texels, in double.
  for (int k = -kSpot; k <= kSpot; ++k) {
    double expected = 0.2013 * std::max(0.0, 1.0 - std::abs(k));
    for (int t = 0; t < 6; ++t) {
      const double o = shading::source::kBlurPairOffsets[t] * kH / kW;
      expected += shading::source::kBlurPairWeights[t] *
                  (std::max(0.0, 1.0 - std::abs(k - o)) + std::max(0.0, 1.0 - std::abs(k + o)));
    }
    EXPECT_NEAR(quirk.down[kSpot + k], 255.0 * expected, 1.0) << "k = " << k;
  }
  for (int i = 0; i < 2 * kSpot + 1; ++i) {
    EXPECT_NEAR(fixed.down[i], fixed.across[i], 1) << "without the quirk down is across, i = " << i;
    EXPECT_EQ(quirk.across[i], fixed.across[i]) << "the quirk changes only the vertical pass";
  }
}

// ---- Against a reference in double -------------------------------------------------------------

/// The bloom from the formulas: downsample (shaped taps), blur x, blur y x amount, add; 8-bit between.
Plane reference_bloom(const rasterizer::Image& image, double amount, bool quirk) {
  const Plane frame = plane_of(image);
  const int W = frame.width, H = frame.height, w = W / 4, h = H / 4;
  Plane small{w, h, std::vector<glm::dvec3>(size_t(w) * h)};
  const double sx = double(W - 2) / (w - 1), sy = double(H - 2) / (h - 1);
  const double offsets[4][2] = {{0.5, 0.5}, {2.5, 0.5}, {0.5, 2.5}, {2.5, 2.5}};
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      glm::dvec3 sum(0.0);
      for (const auto& o : offsets) {
        const glm::dvec3 p = frame.sample((0.5 + i * sx + o[0]) / W, (0.5 + j * sy + o[1]) / H);
        const double lum = 0.3 * p.x + 0.59 * p.y + 0.11 * p.z;
        sum += glm::dvec3(std::pow(p.x, 2.2), std::pow(p.y, 2.2), std::pow(p.z, 2.2)) * lum;
      }
      small.texels[size_t(j) * w + i] = sum / 4.0;
    }
  small = small.rounded();
  const double centre = 0.2013, weights[6] = {0.2185, 0.0821, 0.0461, 0.0262, 0.0162, 0.0102};
  const double taps[6] = {1.3366, 3.4295, 5.4264, 7.4359, 9.4436, 11.4401};
  auto blur = [&](const Plane& src, double du, double dv, double scale) {
    Plane out = src;
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        const double u = (i + 0.5) / w, v = (j + 0.5) / h;
        glm::dvec3 sum = src.sample(u, v) * centre;
        for (int k = 0; k < 6; ++k)
          sum += (src.sample(u + taps[k] * du, v + taps[k] * dv) + src.sample(u - taps[k] * du, v - taps[k] * dv)) * weights[k];
        out.texels[size_t(j) * w + i] = sum * scale;
      }
    return out.rounded();
  };
  const Plane blurred = blur(blur(small, 1.0 / w, 0.0, 1.0), 0.0, quirk ? 1.0 / w : 1.0 / h, amount);
  Plane out = frame;
  // The add's rectangle: small texels (0, -0.5) to (w - 1, h - 1) over the frame.
  const double ax = double(w - 1) / (W - 1), ay = (h - 1 + 0.5) / (H - 1);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      out.texels[size_t(y) * W + x] += blurred.sample((0.5 + x * ax) / w, (-0.5 + 0.5 + y * ay) / h);
  return out.rounded();
}

/// A frame with structure at every scale: a smooth gradient, noise, and bright discs.
rasterizer::Image test_frame(int width, int height, uint32_t seed) {
  rasterizer::Image image(width, height);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> noise(-40, 40);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      uint8_t* p = image.pixel(x, y);
      const double disc = std::hypot(x - width * 0.3, y - height * 0.4) < height * 0.12 ? 255.0 : 0.0;
      p[0] = static_cast<uint8_t>(std::clamp(disc + 120.0 * x / width + noise(rng), 0.0, 255.0));
      p[1] = static_cast<uint8_t>(std::clamp(disc * 0.8 + 90.0 * y / height + noise(rng), 0.0, 255.0));
      p[2] = static_cast<uint8_t>(std::clamp(60.0 + noise(rng), 0.0, 255.0));
      p[3] = 255;
    }
  for (int i = 0; i < 12; ++i) std::fill_n(image.pixel(rng() % width, rng() % height), 3, uint8_t(255));
  return image;
}

TEST(Bloom, MatchesADoubleReferenceWithinOneStep) {
  // 131 x 67 is no multiple of 4: the same formulas, other spacings (bloom.hpp).
  for (auto [width, height, quirk, amount] : {std::tuple{160, 90, true, 1.0f}, std::tuple{160, 90, true, 0.3f},
                                             std::tuple{160, 90, true, 2.5f}, std::tuple{160, 90, false, 1.0f},
                                             std::tuple{160, 90, false, 0.3f}, std::tuple{160, 90, false, 2.5f},
                                             std::tuple{131, 67, true, 1.0f}, std::tuple{131, 67, false, 1.0f}}) {
    const rasterizer::Image source = test_frame(width, height, 3u);
    rasterizer::Image frame = source;
    rasterizer::Context ctx(2);
    BloomOptions options;
    options.vertical_step = quirk ? BlurStep::sdk_width_quirk : BlurStep::true_height;
    Bloom(options).apply(ctx, frame, amount);
    const Plane expected = reference_bloom(source, amount, quirk);
    int worst = 0, off = 0, changed = 0;
    for (int y = 0; y < frame.height; ++y)
      for (int x = 0; x < frame.width; ++x)
        for (int c = 0; c < 3; ++c) {
          const int e = static_cast<int>(std::lround(expected.at(x, y)[c] * 255.0));
          const int d = std::abs(channel(frame, x, y, c) - e);
          worst = std::max(worst, d);
          off += d != 0;
          changed += channel(frame, x, y, c) != channel(source, x, y, c);
        }
    // Float vs double can round an intermediate 8-bit texel the other way; the add's
    // bilinear carries at most that one step.
    EXPECT_LE(worst, 1) << width << "x" << height << " amount " << amount << (quirk ? " quirk" : "");
    EXPECT_GT(changed, frame.width * frame.height) << "the bloom is visible";
    std::printf("bloom vs double (%dx%d, amount %.1f, %s): max %d step, %d of %d channels off\n", width, height,
                amount, quirk ? "quirk" : "fixed", worst, off, frame.width * frame.height * 3);
  }
}

// ---- Threads, sizes, amount --------------------------------------------------------------------

TEST(Bloom, SameBytesForOneAndTwoThreadsAtAnySize) {
  for (auto [w, h] : {std::pair{300, 170}, std::pair{131, 67}, std::pair{4, 4}, std::pair{7, 5}}) {
    const rasterizer::Image source = test_frame(w, h, 11u);
    rasterizer::Image one = source, two = source;
    rasterizer::Context ctx1(1), ctx2(2);
    Bloom(BloomOptions{}).apply(ctx1, one, 1.0f);
    Bloom(BloomOptions{}).apply(ctx2, two, 1.0f);
    EXPECT_EQ(one.rgba, two.rgba) << w << "x" << h;
    EXPECT_EQ(bloom_size(w, h).width, w / 4);
  }
}

TEST(Bloom, TheTargetPathAndTheImagePathAgreeAndMultisampledFramesWork) {
  const rasterizer::Image source = test_frame(128, 72, 5u);
  rasterizer::Context ctx(2);
  rasterizer::Image via_image = source;
  Bloom bloom;
  bloom.apply(ctx, via_image, 0.8f);
  for (int samples : {1, 4}) {
    rasterizer::ColorTarget target(source.width, source.height, samples);
    rasterizer::load_image(ctx, source, target);
    bloom.apply(ctx, target, 0.8f);
    EXPECT_EQ(rasterizer::resolve(ctx, target).rgba, via_image.rgba) << samples << " samples";
  }
}

TEST(Bloom, RefusesFramesSmallerThanFourByFour) {
  rasterizer::Context ctx(1);
  rasterizer::Image tiny = solid(3, 8, 10);
  EXPECT_THROW(Bloom().apply(ctx, tiny, 1.0f), std::invalid_argument);
  EXPECT_THROW(Bloom().downsample(ctx), std::logic_error) << "a pass before any copy";
  rasterizer::Image small_but_unbloomed = tiny;
  EXPECT_NO_THROW(Bloom().apply(ctx, small_but_unbloomed, 0.0f)) << "amount 0: nothing runs, as in the SDK";
}

TEST(BloomAmount, SmoothsTowardTheScaleAndScalesLdr) {
  BloomAmount a;
  EXPECT_FLOAT_EQ(a.advance(1.0f, HdrType::integer), 1.0f) << "starts at 1";
  EXPECT_FLOAT_EQ(a.advance(0.0f, HdrType::integer), 0.95f);
  EXPECT_FLOAT_EQ(a.advance(0.0f, HdrType::integer), 0.95f * 0.95f);
  BloomAmount ldr;
  EXPECT_FLOAT_EQ(ldr.advance(2.0f, HdrType::none), (2.0f * 0.05f + 0.95f) * 0.3f);
  EXPECT_FLOAT_EQ(ldr.smoothed, 1.05f) << "the LDR factor scales the output, not the carried state";
  EXPECT_FLOAT_EQ(ldr.advance(2.0f, HdrType::floating, 0.5f), (2.0f * 0.05f + 0.95f * 1.05f) * 0.5f);
  BloomAmount converging;
  for (int i = 0; i < 400; ++i) converging.advance(3.0f, HdrType::integer);
  EXPECT_NEAR(converging.smoothed, 3.0f, 1e-4f);
}

}  // namespace
}  // namespace luxel::postfx
