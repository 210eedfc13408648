// Environment images as radiance samples (cli/report/environment_image.hpp): the solid angles
// and the frame, checked against closed forms on images made here. A uniform image gives
// E = πL; an image bright over one half gives the hemisphere's E = π (1 + n·a) / 2 with a the
// half's axis, which fixes the frame (+x right, +y up, +z at the centre) for both mappings.

#include "report/environment_image.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>

namespace luxel::cli {
namespace {

constexpr double kPi = std::numbers::pi;

/// A float image whose pixel (i, j) has radiance f(i, j) in every channel.
scenes::PixelImage image_of(int width, int height, const std::function<float(int, int)>& f) {
  scenes::PixelImage image;
  image.width = width, image.height = height;
  image.rgba32f.resize(size_t(width) * height * 4);
  for (int i = 0; i < height; ++i)
    for (int j = 0; j < width; ++j)
      for (int c = 0; c < 4; ++c) image.rgba32f[(size_t(i) * width + j) * 4 + size_t(c)] = c < 3 ? f(i, j) : 1.0f;
  return image;
}

double total_solid_angle(const shading::source::SampledRadiance& samples) {
  double sum = 0.0;
  for (const shading::source::RadianceSample& s : samples) sum += s.solid_angle;
  return sum;
}

/// Max |E(n) − expected(n)| over a set of normals.
double worst(const shading::source::SampledRadiance& samples, const std::function<double(const glm::dvec3&)>& expected) {
  double w = 0.0;
  for (const glm::dvec3& n : shading::source::fibonacci_normals(100))
    w = std::max(w, std::abs(shading::source::irradiance(samples, n).x - expected(n)));
  return w;
}

TEST(EnvironmentImage, ShapeGivesTheMapping) {
  EXPECT_EQ(mapping_of(image_of(8, 8, [](int, int) { return 1.0f; }), "a.hdr"), EnvironmentMapping::angular);
  EXPECT_EQ(mapping_of(image_of(16, 8, [](int, int) { return 1.0f; }), "a.hdr"), EnvironmentMapping::latlong);
  try {
    mapping_of(image_of(5, 3, [](int, int) { return 1.0f; }), "odd.hdr");
    FAIL() << "a 5x3 image was taken for a probe";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "odd.hdr: 5x3 is neither an angular map (square) nor a lat-long map (2:1)");
  }
}

TEST(EnvironmentImage, LatLongSolidAnglesAndFrame) {
  constexpr int w = 256, h = 128;
  const auto uniform = environment_samples(image_of(w, h, [](int, int) { return 2.0f; }), EnvironmentMapping::latlong, "u");
  EXPECT_NEAR(total_solid_angle(uniform), 4.0 * kPi, 1e-9);
  EXPECT_LT(worst(uniform, [](const glm::dvec3&) { return 2.0 * kPi; }), 1e-3);
  // Top half: y > 0. Right half: x > 0. The middle half of the columns: z > 0.
  const auto up = environment_samples(image_of(w, h, [](int i, int) { return i < h / 2 ? 1.0f : 0.0f; }), EnvironmentMapping::latlong, "up");
  EXPECT_LT(worst(up, [](const glm::dvec3& n) { return kPi * (1.0 + n.y) / 2.0; }), 2e-3);
  const auto right = environment_samples(image_of(w, h, [](int, int j) { return j >= w / 2 ? 1.0f : 0.0f; }), EnvironmentMapping::latlong, "r");
  EXPECT_LT(worst(right, [](const glm::dvec3& n) { return kPi * (1.0 + n.x) / 2.0; }), 2e-3);
  const auto front = environment_samples(image_of(w, h, [](int, int j) { return j >= w / 4 && j < 3 * w / 4 ? 1.0f : 0.0f; }),
                                         EnvironmentMapping::latlong, "f");
  EXPECT_LT(worst(front, [](const glm::dvec3& n) { return kPi * (1.0 + n.z) / 2.0; }), 2e-3);
}

TEST(EnvironmentImage, AngularMapSolidAnglesAndFrame) {
  constexpr int w = 256;
  const auto uniform = environment_samples(image_of(w, w, [](int, int) { return 2.0f; }), EnvironmentMapping::angular, "u");
  EXPECT_NEAR(total_solid_angle(uniform), 4.0 * kPi, 2e-3);
  EXPECT_LT(worst(uniform, [](const glm::dvec3&) { return 2.0 * kPi; }), 4e-3);
  // Top half: y > 0. Right half: x > 0. The disc of half the radius (θ < π/2): z > 0.
  const auto up = environment_samples(image_of(w, w, [](int i, int) { return i < w / 2 ? 1.0f : 0.0f; }), EnvironmentMapping::angular, "up");
  EXPECT_LT(worst(up, [](const glm::dvec3& n) { return kPi * (1.0 + n.y) / 2.0; }), 4e-3);
  const auto right = environment_samples(image_of(w, w, [](int, int j) { return j >= w / 2 ? 1.0f : 0.0f; }), EnvironmentMapping::angular, "r");
  EXPECT_LT(worst(right, [](const glm::dvec3& n) { return kPi * (1.0 + n.x) / 2.0; }), 4e-3);
  const auto front = environment_samples(image_of(w, w,
                                                  [](int i, int j) {
                                                    const double u = (j + 0.5 - w / 2.0) / (w / 2.0), v = (w / 2.0 - i - 0.5) / (w / 2.0);
                                                    return u * u + v * v < 0.25 ? 1.0f : 0.0f;
                                                  }),
                                         EnvironmentMapping::angular, "f");
  EXPECT_LT(worst(front, [](const glm::dvec3& n) { return kPi * (1.0 + n.z) / 2.0; }), 2e-2);  // a staircase circle
}

TEST(EnvironmentImage, EightBitImagesAreRefused) {
  scenes::PixelImage image;
  image.width = 4, image.height = 2;
  image.rgba8.assign(32, 255);
  EXPECT_THROW(environment_samples(image, EnvironmentMapping::latlong, "ldr.png"), std::runtime_error);
}

}  // namespace
}  // namespace luxel::cli
