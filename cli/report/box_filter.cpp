#include "report/box_filter.hpp"

#include "luxel/rasterizer/srgb.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace luxel::cli {

rasterizer::Image box_filter_down(const rasterizer::Image& image, int factor, BoxSpace space) {
  if (factor < 1 || image.width % factor || image.height % factor)
    throw std::invalid_argument("box filter: a " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                                " image does not shrink by " + std::to_string(factor));
  rasterizer::Image out(image.width / factor, image.height / factor);
  const unsigned n = unsigned(factor * factor);
  static const std::array<double, 256> decode = [] {
    std::array<double, 256> t{};
    for (size_t v = 0; v < t.size(); ++v) t[v] = rasterizer::srgb_to_linear(double(v) / 255.0);
    return t;
  }();
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < 4; ++c) {
        unsigned sum = 0;
        double linear = 0.0;
        for (int j = 0; j < factor; ++j)
          for (int i = 0; i < factor; ++i) {
            const uint8_t v = image.pixel(x * factor + i, y * factor + j)[c];
            sum += v;
            linear += decode[v];
          }
        out.pixel(x, y)[c] = space == BoxSpace::linear_light && c < 3
                                 ? uint8_t(std::floor(rasterizer::linear_to_srgb(linear / n) * 255.0 + 0.5))
                                 : uint8_t((sum + n / 2) / n);
      }
  return out;
}

}  // namespace luxel::cli
