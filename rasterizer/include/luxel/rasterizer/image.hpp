#pragma once
// A plain row-major RGBA8 image (top row first): the rasterizer's resolve target. Writing it to a
// file is for scenes/image_io.hpp (the rasterizer knows nothing about files).

#include <cstddef>
#include <cstdint>
#include <vector>

namespace luxel::rasterizer {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgba;  ///< width * height * 4 bytes, row-major, top row first

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<size_t>(w) * h * 4, 0) {}

  uint8_t* pixel(int x, int y) { return rgba.data() + (static_cast<size_t>(y) * width + x) * 4; }
  const uint8_t* pixel(int x, int y) const {
    return rgba.data() + (static_cast<size_t>(y) * width + x) * 4;
  }
};

}  // namespace luxel::rasterizer
