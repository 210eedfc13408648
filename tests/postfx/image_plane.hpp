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
  /// Bilinear, clamped, D3D's texel centres.
  glm::dvec3 sample(double u, double v) const {
    const double x = u * width - 0.5, y = v * height - 0.5;
    const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
    const double fx = x - x0, fy = y - y0;
    return (at(x0, y0) * (1 - fx) + at(x0 + 1, y0) * fx) * (1 - fy) + (at(x0, y0 + 1) * (1 - fx) + at(x0 + 1, y0 + 1) * fx) * fy;
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
