#pragma once
// A plain row-major RGBA8 image (top row first), the rasterizer's way out to files.

#include <cstdint>
#include <string>
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

/// Writes the image with OpenImageIO (format from the extension: .png, .tif, .exr...).
/// Throws std::runtime_error naming the file on failure.
void write_image(const Image& image, const std::string& path);

/// Reads an image file as RGBA8 (missing channels: alpha 255, grey replicated).
/// Throws std::runtime_error naming the file on failure.
Image read_image(const std::string& path);

}  // namespace luxel::rasterizer
