// frame::image_difference (image_difference.hpp) on constructed pairs whose numbers are computed
// by hand here, and the same pairs against OpenImageIO's `idiff` binary, whose meaning the header
// promises; heat_colour's ramp and the heat map.

#include "luxel/frame/image_difference.hpp"
#include "luxel/scenes/image_io.hpp"
#include "scenes/temp_dir.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <regex>
#include <stdexcept>
#include <string>
#include <utility>

namespace luxel::frame {
namespace {

/// An 8x4 image whose every value differs (a gradient), alpha 255.
rasterizer::Image gradient() {
  rasterizer::Image image(8, 4);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      uint8_t* p = image.pixel(x, y);
      p[0] = uint8_t(20 + 25 * x);
      p[1] = uint8_t(40 + 50 * y);
      p[2] = uint8_t(7 * (x + y));
      p[3] = 255;
    }
  return image;
}

/// 20 log10(1 / rms) with rms of `sum_squares` (in 8-bit steps squared) over `values` values.
double psnr(double sum_squares, double values) {
  return 20 * std::log10(1 / std::sqrt(sum_squares / (255.0 * 255.0) / values));
}

/// The gradient with red 3 steps up in 5 known pixels.
rasterizer::Image red_up_3(const rasterizer::Image& base) {
  rasterizer::Image b = base;
  constexpr std::pair<int, int> kPixels[] = {{0, 0}, {3, 1}, {7, 1}, {2, 3}, {5, 2}};
  for (auto [x, y] : kPixels) b.pixel(x, y)[0] += 3;
  return b;
}

TEST(ImageDifference, IdenticalImagesHaveInfinitePsnrAndNoError) {
  const rasterizer::Image a = gradient();
  const ImageDifference d = image_difference(a, a);
  EXPECT_TRUE(std::isinf(d.psnr_db) && d.psnr_db > 0);
  EXPECT_EQ(d.max_error, 0);
  EXPECT_EQ(d.mean_error, 0.0);
  EXPECT_EQ(d.rms_error, 0.0);
  EXPECT_EQ(d.differing_pixels, 0u);
  EXPECT_EQ(d.pixels, 32u);
  EXPECT_TRUE(d.identical());
}

TEST(ImageDifference, OneChannelThreeStepsOffInFivePixels) {
  const rasterizer::Image a = gradient();
  const ImageDifference d = image_difference(a, red_up_3(a));
  // 32 pixels x 4 channels = 128 values; five of them are 3 steps off.
  EXPECT_EQ(d.max_error, 3);
  EXPECT_NEAR(d.mean_error, 5 * 3 / 128.0, 1e-6);
  EXPECT_NEAR(d.rms_error, 3 / 255.0 * std::sqrt(5 / 128.0), 1e-8);  // OpenImageIO differences in float
  EXPECT_NEAR(d.psnr_db, psnr(5 * 9, 128), 1e-4);
  EXPECT_EQ(d.differing_pixels, 5u);
  EXPECT_DOUBLE_EQ(d.differing_share(), 5 / 32.0);
  EXPECT_FALSE(d.identical());
}

TEST(ImageDifference, AlphaCountsAndEveryChannelOfAPixelCountsOnce) {
  const rasterizer::Image a = gradient();
  rasterizer::Image b = a;
  b.pixel(1, 1)[3] = 245;                               // alpha 10 steps down
  b.pixel(6, 2)[1] += 2, b.pixel(6, 2)[2] += 7;         // two channels of one pixel
  const ImageDifference d = image_difference(a, b);
  EXPECT_EQ(d.max_error, 10);
  EXPECT_NEAR(d.mean_error, (10 + 2 + 7) / 128.0, 1e-6);
  EXPECT_NEAR(d.psnr_db, psnr(100 + 4 + 49, 128), 1e-4);
  EXPECT_EQ(d.differing_pixels, 2u);
}

TEST(ImageDifference, FullScaleDifferenceEverywhere) {
  rasterizer::Image black(4, 4), white(4, 4);
  std::fill(white.rgba.begin(), white.rgba.end(), uint8_t(255));
  const ImageDifference d = image_difference(black, white);
  EXPECT_EQ(d.max_error, 255);
  EXPECT_NEAR(d.mean_error, 255.0, 1e-4);
  EXPECT_NEAR(d.psnr_db, 0.0, 1e-6);
  EXPECT_EQ(d.differing_pixels, 16u);
}

TEST(ImageDifference, RefusesImagesOfDifferentSizes) {
  EXPECT_THROW(image_difference(rasterizer::Image(4, 4), rasterizer::Image(4, 5)), std::invalid_argument);
  EXPECT_THROW(image_difference(rasterizer::Image(), rasterizer::Image()), std::invalid_argument);
  EXPECT_THROW(difference_heat_map(rasterizer::Image(4, 4), rasterizer::Image(5, 4)), std::invalid_argument);
}

TEST(HeatColour, StopsAndStepsBetweenThem) {
  using C = std::array<uint8_t, 3>;
  EXPECT_EQ(heat_colour(0), (C{0, 0, 0}));
  EXPECT_EQ(heat_colour(1), (C{0, 0, 128}));
  EXPECT_EQ(heat_colour(3), (C{0, 132, 255}));  // halfway from blue (0,64,255) to cyan (0,200,255)
  EXPECT_EQ(heat_colour(8), (C{0, 255, 0}));
  EXPECT_EQ(heat_colour(24), (C{255, 192, 0}));  // halfway from yellow to orange (255,128,0)
  EXPECT_EQ(heat_colour(64), (C{255, 0, 0}));
  EXPECT_EQ(heat_colour(128), (C{255, 255, 255}));
  EXPECT_EQ(heat_colour(255), (C{255, 255, 255}));
  EXPECT_EQ(heat_colour(-4), (C{0, 0, 0}));
  for (int s = 1; s <= 128; ++s) EXPECT_NE(heat_colour(s), heat_colour(s - 1)) << s;  // every step its own shade
}

TEST(HeatMap, LargestChannelDifferencePerPixelOpaque) {
  const rasterizer::Image a = gradient();
  rasterizer::Image b = red_up_3(a);
  b.pixel(1, 1)[3] = 245;
  const rasterizer::Image heat = difference_heat_map(a, b);
  ASSERT_EQ(heat.width, 8);
  ASSERT_EQ(heat.height, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 8; ++x) {
      const uint8_t* a_px = a.pixel(x, y);
      const uint8_t* b_px = b.pixel(x, y);
      int largest = 0;
      for (int c = 0; c < 4; ++c) largest = std::max(largest, std::abs(a_px[c] - b_px[c]));
      const std::array<uint8_t, 3> want = heat_colour(largest);
      const uint8_t* h = heat.pixel(x, y);
      EXPECT_EQ((std::array<uint8_t, 3>{h[0], h[1], h[2]}), want) << x << "," << y;
      EXPECT_EQ(h[3], 255);
    }
  EXPECT_EQ(heat.pixel(0, 0)[2], heat_colour(3)[2]);
  EXPECT_EQ(heat.pixel(1, 1)[0], heat_colour(10)[0]);
}

// --- against the idiff binary ----------------------------------------------------------------

constexpr const char* kIdiff = "/usr/bin/idiff";

struct IdiffReport {
  bool pass = false;  ///< printed PASS: identical (no numbers then)
  double mean = 0, rms = 0, psnr = 0, max = 0;
  double differing = 0;  ///< pixels over the fail threshold
};

/// Runs idiff on the two images written as PNG, and parses what it prints.
IdiffReport run_idiff(const rasterizer::Image& a, const rasterizer::Image& b) {
  const scenes::test::TempDir dir;
  scenes::write_image(a.width, a.height, a.rgba, dir.file("a.png"));
  scenes::write_image(b.width, b.height, b.rgba, dir.file("b.png"));
  FILE* pipe = popen((std::string(kIdiff) + " " + dir.file("a.png") + " " + dir.file("b.png") + " 2>&1").c_str(), "r");
  if (!pipe) throw std::runtime_error("cannot run idiff");
  std::string out;
  std::array<char, 4096> buf;
  for (size_t n; (n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0;) out.append(buf.data(), n);
  pclose(pipe);
  IdiffReport r;
  auto number = [&](const char* pattern) -> double {
    std::smatch m;
    if (!std::regex_search(out, m, std::regex(pattern))) throw std::runtime_error("idiff printed no " + std::string(pattern) + ":\n" + out);
    return std::stod(m[1]);
  };
  if (out.find("PASS") != std::string::npos) {
    r.pass = true;
    return r;
  }
  r.mean = number(R"(Mean error = ([-0-9.e+]+))");
  r.rms = number(R"(RMS error = ([-0-9.e+]+))");
  r.psnr = number(R"(Peak SNR = ([-0-9.e+]+))");
  r.max = number(R"(Max error\s+= ([-0-9.e+]+))");
  r.differing = number(R"(\n\s+([0-9]+) pixels? \([0-9.e+-]+%\) over 1e-06\nFAILURE)");
  return r;
}

/// idiff prints six significant digits.
void expect_six_digits(double ours, double idiffs, const char* what) {
  EXPECT_NEAR(ours, idiffs, 6e-6 * std::abs(idiffs) + 1e-12) << what;
}

void expect_agrees_with_idiff(const rasterizer::Image& a, const rasterizer::Image& b) {
  const ImageDifference d = image_difference(a, b);
  const IdiffReport r = run_idiff(a, b);
  if (d.identical()) {
    EXPECT_TRUE(r.pass);
    return;
  }
  ASSERT_FALSE(r.pass);
  expect_six_digits(d.mean_error / 255.0, r.mean, "mean error");
  expect_six_digits(d.rms_error, r.rms, "RMS error");
  expect_six_digits(d.psnr_db, r.psnr, "PSNR");
  EXPECT_EQ(d.max_error, std::lround(r.max * 255.0)) << "max error";
  EXPECT_EQ(double(d.differing_pixels), r.differing) << "differing pixels";
}

class AgainstIdiff : public ::testing::Test {
 protected:
  void SetUp() override {
    if (access(kIdiff, X_OK) != 0) GTEST_SKIP() << kIdiff << " is absent (Debian package openimageio-tools)";
  }
};

TEST_F(AgainstIdiff, IdenticalPair) { expect_agrees_with_idiff(gradient(), gradient()); }

TEST_F(AgainstIdiff, OneChannelThreeStepsOffInFivePixels) {
  const rasterizer::Image a = gradient();
  expect_agrees_with_idiff(a, red_up_3(a));
}

TEST_F(AgainstIdiff, AlphaAndSeveralChannels) {
  // OpenImageIO reads a PNG pixel with alpha below 255 premultiplied, so the pixel whose alpha
  // differs is black: only its alpha differs in idiff's reading as in ours.
  rasterizer::Image a = gradient();
  std::fill_n(a.pixel(1, 1), 3, uint8_t(0));
  rasterizer::Image b = a;
  b.pixel(1, 1)[3] = 245;
  b.pixel(6, 2)[1] += 2, b.pixel(6, 2)[2] += 7;
  expect_agrees_with_idiff(a, b);
}

TEST_F(AgainstIdiff, ManyPseudoRandomDifferences) {
  // 61x37 (odd sizes), about a third of the colour values off by up to +-40 steps; opaque, as
  // OpenImageIO would read a PNG pixel with alpha below 255 premultiplied.
  rasterizer::Image a(61, 37), b(61, 37);
  uint32_t state = 12345;
  auto next = [&] { return state = state * 1664525u + 1013904223u, state >> 8; };
  for (size_t i = 0; i < a.rgba.size(); ++i) {
    if (i % 4 == 3) {
      a.rgba[i] = b.rgba[i] = 255;
      continue;
    }
    a.rgba[i] = uint8_t(next());
    const int delta = next() % 3 == 0 ? int(next() % 81) - 40 : 0;
    b.rgba[i] = uint8_t(std::clamp(int(a.rgba[i]) + delta, 0, 255));
  }
  expect_agrees_with_idiff(a, b);
}

}  // namespace
}  // namespace luxel::frame
