#include "report/box_filter.hpp"

#include <stdexcept>
#include <string>

namespace luxel::cli {

rasterizer::Image box_filter_down(const rasterizer::Image& image, int factor) {
  if (factor < 1 || image.width % factor || image.height % factor)
    throw std::invalid_argument("box filter: a " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                                " image does not shrink by " + std::to_string(factor));
  rasterizer::Image out(image.width / factor, image.height / factor);
  const unsigned n = unsigned(factor * factor);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < 4; ++c) {
        unsigned sum = 0;
        for (int j = 0; j < factor; ++j)
          for (int i = 0; i < factor; ++i) sum += image.pixel(x * factor + i, y * factor + j)[c];
        out.pixel(x, y)[c] = uint8_t((sum + n / 2) / n);
      }
  return out;
}

}  // namespace luxel::cli
