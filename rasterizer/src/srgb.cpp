// The sRGB encode table (srgb.hpp), built once from the exact curve.

#include "luxel/rasterizer/srgb.hpp"

#include <algorithm>

namespace luxel::rasterizer {

const std::array<uint8_t, 65536>& srgb_encode_table() {
  static const std::array<uint8_t, 65536> table = [] {
    std::array<uint8_t, 65536> t{};
    for (int i = 0; i < 65536; ++i)
      t[i] = static_cast<uint8_t>(std::lround(std::clamp(linear_to_srgb(i / 65535.0), 0.0, 1.0) * 255.0));
    return t;
  }();
  return table;
}

}  // namespace luxel::rasterizer
