#include "luxel/frame/exposure_merge.hpp"

#include "luxel/rasterizer/srgb.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace luxel::frame {

float exposure_weight(int code) { return code > kDarkCode && code < 255 ? float(code - kDarkCode) : 0.0f; }

std::vector<glm::vec4> merge_exposures(std::span<const rasterizer::Image> images, std::span<const float> exposures) {
  if (images.empty() || images.size() != exposures.size())
    throw std::invalid_argument("exposure merge: " + std::to_string(images.size()) + " images for " +
                                std::to_string(exposures.size()) + " exposures");
  for (size_t k = 0; k < images.size(); ++k) {
    if (images[k].width != images[0].width || images[k].height != images[0].height)
      throw std::invalid_argument("exposure merge: image " + std::to_string(k) + " is not the size of image 0");
    if (!(std::isfinite(exposures[k]) && exposures[k] > 0.0f))
      throw std::invalid_argument("exposure merge: exposure " + std::to_string(exposures[k]) + " is not positive and finite");
  }
  const size_t texels = size_t(images[0].width) * size_t(images[0].height);
  std::vector<glm::vec4> out(texels, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  for (size_t i = 0; i < texels; ++i)
    for (int c = 0; c < 3; ++c) {
      double sum = 0.0, weights = 0.0;
      size_t fallback = 0;
      for (size_t k = 0; k < images.size(); ++k) {
        const int code = images[k].rgba[4 * i + size_t(c)];
        const double value = double(rasterizer::kSrgbToLinear[size_t(code)]) / exposures[k];
        const double w = exposure_weight(code);
        sum += w * value;
        weights += w;
        if (std::abs(code - 128) < std::abs(int(images[fallback].rgba[4 * i + size_t(c)]) - 128)) fallback = k;
      }
      out[i][c] = weights > 0.0 ? float(sum / weights)
                                : rasterizer::kSrgbToLinear[images[fallback].rgba[4 * i + size_t(c)]] / exposures[fallback];
    }
  return out;
}

}  // namespace luxel::frame
