#include "report/environment_image.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace luxel::cli {

namespace {

constexpr double kPi = std::numbers::pi;

glm::dvec3 rgb_at(const scenes::PixelImage& image, int i, int j) {
  const float* p = image.rgba32f.data() + (static_cast<size_t>(i) * image.width + j) * 4;
  return {p[0], p[1], p[2]};
}

void add_angular(const scenes::PixelImage& image, shading::source::SampledRadiance& out) {
  const int w = image.width;
  const double half = 0.5 * w, d_omega_scale = (2.0 * kPi / w) * (2.0 * kPi / w);
  for (int i = 0; i < w; ++i) {
    for (int j = 0; j < w; ++j) {
      const double u = (j + 0.5 - half) / half, v = (half - i - 0.5) / half;
      const double r = std::sqrt(u * u + v * v);
      if (r >= 1.0) continue;
      const double theta = kPi * r;
      const double sin_over_r = r > 0.0 ? std::sin(theta) / r : kPi;  // sin θ / r -> π at the centre
      const double sinc = r > 0.0 ? std::sin(theta) / theta : 1.0;
      out.push_back({glm::dvec3(sin_over_r * u, sin_over_r * v, std::cos(theta)), rgb_at(image, i, j), d_omega_scale * sinc});
    }
  }
}

void add_latlong(const scenes::PixelImage& image, shading::source::SampledRadiance& out) {
  const int w = image.width, h = image.height;
  for (int i = 0; i < h; ++i) {
    const double polar = kPi * (i + 0.5) / h;
    const double d_omega = (2.0 * kPi / w) * (std::cos(kPi * i / h) - std::cos(kPi * (i + 1) / h));
    for (int j = 0; j < w; ++j) {
      const double azimuth = 2.0 * kPi * ((j + 0.5) / w - 0.5);
      const glm::dvec3 d(std::sin(polar) * std::sin(azimuth), std::cos(polar), std::sin(polar) * std::cos(azimuth));
      out.push_back({d, rgb_at(image, i, j), d_omega});
    }
  }
}

}  // namespace

EnvironmentMapping mapping_of(const scenes::PixelImage& image, const std::string& name) {
  if (image.width == image.height) return EnvironmentMapping::angular;
  if (image.width == 2 * image.height) return EnvironmentMapping::latlong;
  throw std::runtime_error(name + ": " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                           " is neither an angular map (square) nor a lat-long map (2:1)");
}

const char* mapping_name(EnvironmentMapping mapping) {
  return mapping == EnvironmentMapping::angular ? "angular map" : "lat-long";
}

shading::source::SampledRadiance environment_samples(const scenes::PixelImage& image, EnvironmentMapping mapping,
                                                     const std::string& name) {
  if (!image.is_hdr()) throw std::runtime_error(name + ": an 8-bit image; a light probe is a float image (.hdr, .exr)");
  shading::source::SampledRadiance out;
  out.reserve(static_cast<size_t>(image.width) * image.height);
  if (mapping == EnvironmentMapping::angular) add_angular(image, out);
  else add_latlong(image, out);
  return out;
}

}  // namespace luxel::cli
