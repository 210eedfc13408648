#pragma once
// An 8-bit image as doubles, for references written in double: a texel at (x, y) clamped to the
// edges, and the bilinear read D3D makes between texel centres.

#include "luxel/rasterizer/image.hpp"

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace luxel::postfx::test {

/// An RGB image in double, values in [0, 1].
struct Plane {
  int width = 0, height = 0;
  std::vector<glm::dvec3> texels;
  glm::dvec3 at(int x, int y) const {
    x = std::clamp(x, 0, width - 1);
    y = std::clamp(y, 0, height - 1);
    return texels[size_t(y) * width + x];
  }
  /// Bilinear, clamped, D3D's texel centres, as the hardware rules filter an 8-bit texture
  /// (rasterizer/texture.hpp, "Sampling rules"): the position in 16.8 fixed point, rounded to
  /// nearest; each blend of two 8-bit values, along x and then y, rounded to a step. The plane's
  /// texels are 8-bit values (k / 255).
  glm::dvec3 sample(double u, double v) const {
    const long fx = std::lround(std::nearbyint((u * width - 0.5) * 256.0));
    const long fy = std::lround(std::nearbyint((v * height - 0.5) * 256.0));
    const int x0 = static_cast<int>(fx >> 8), y0 = static_cast<int>(fy >> 8);
    const long wx = fx & 255, wy = fy & 255;
    auto blend = [](double a, double b, long w) { return a + std::floor(double(w) * (b - a) / 256.0 + 0.5); };
    glm::dvec3 out;
    for (int c = 0; c < 3; ++c) {
      auto byte = [&](int x, int y) { return std::round(at(x, y)[c] * 255.0); };
      out[c] = blend(blend(byte(x0, y0), byte(x0 + 1, y0), wx), blend(byte(x0, y0 + 1), byte(x0 + 1, y0 + 1), wx), wy) / 255.0;
    }
    return out;
  }
  /// Stored as an 8-bit target stores it.
  Plane rounded() const {
    Plane r = *this;
    for (glm::dvec3& t : r.texels)
      for (int c = 0; c < 3; ++c) t[c] = std::round(std::clamp(t[c], 0.0, 1.0) * 255.0) / 255.0;
    return r;
  }
};

inline Plane plane_of(const rasterizer::Image& image) {
  Plane p{image.width, image.height, {}};
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const uint8_t* b = image.pixel(x, y);
      p.texels.push_back(glm::dvec3(b[0], b[1], b[2]) / 255.0);
    }
  return p;
}

}  // namespace luxel::postfx::test
