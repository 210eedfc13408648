// The engine's LUT (lut.hpp): sampling a transform on the lattice, and the volume texture.

#include "luxel/postfx/lut.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace luxel::postfx {

uint8_t to_unorm8(float x) {
  if (!(x > 0.0f)) return 0;  // NaN and <= 0
  if (x >= 1.0f) return 255;
  return static_cast<uint8_t>(std::lround(x * 255.0f));
}

Lut Lut::of_size(int size) {
  if (size < kMinLutSize || size > kMaxLutSize)
    throw std::invalid_argument("a LUT of " + std::to_string(size) + " points per axis: luxel's are " +
                                std::to_string(kMinLutSize) + " to " + std::to_string(kMaxLutSize));
  Lut lut;
  lut.size = size;
  lut.entries.assign(static_cast<size_t>(size) * size * size, Color24{0, 0, 0});
  return lut;
}

Lut Lut::identity(int size) {
  Lut lut = of_size(size);
  for (int b = 0; b < size; ++b)
    for (int g = 0; g < size; ++g)
      for (int r = 0; r < size; ++r)
        lut.at(r, g, b) = {to_unorm8(lattice_color(r, size)), to_unorm8(lattice_color(g, size)),
                           to_unorm8(lattice_color(b, size))};
  return lut;
}

namespace {

/// `colors` (one per entry of a `size`^3 lattice) transformed and rounded into a LUT.
Lut transformed(std::vector<glm::vec3> colors, const ColorTransform& transform, int size) {
  transform.apply(colors);
  Lut lut = Lut::of_size(size);
  for (size_t i = 0; i < colors.size(); ++i)
    lut.entries[i] = {to_unorm8(colors[i].x), to_unorm8(colors[i].y), to_unorm8(colors[i].z)};
  return lut;
}

}  // namespace

Lut sample_lut(const ColorTransform& transform, int size) {
  (void)Lut::of_size(size);  // the size checked before the colors are made
  std::vector<glm::vec3> colors(static_cast<size_t>(size) * size * size);
  for (int b = 0; b < size; ++b)
    for (int g = 0; g < size; ++g)
      for (int r = 0; r < size; ++r)
        colors[static_cast<size_t>((b * size + g) * size + r)] =
            glm::vec3(lattice_color(r, size), lattice_color(g, size), lattice_color(b, size));
  return transformed(std::move(colors), transform, size);
}

Lut compose(const Lut& lut, const ColorTransform& then) {
  std::vector<glm::vec3> colors(lut.entries.size());
  for (size_t i = 0; i < colors.size(); ++i)
    colors[i] = glm::vec3(lut.entries[i][0], lut.entries[i][1], lut.entries[i][2]) / 255.0f;
  return transformed(std::move(colors), then, lut.size);
}

rasterizer::Texture lut_volume(const Lut& lut) {
  rasterizer::Texture volume =
      rasterizer::Texture::create_volume(lut.size, lut.size, lut.size, rasterizer::TextureFormat::RGBA8, 1);
  std::vector<uint8_t> bytes(lut.entries.size() * 4);
  for (size_t i = 0; i < lut.entries.size(); ++i) {
    bytes[4 * i + 0] = lut.entries[i][0];
    bytes[4 * i + 1] = lut.entries[i][1];
    bytes[4 * i + 2] = lut.entries[i][2];
    bytes[4 * i + 3] = 255;
  }
  volume.upload(0, bytes);
  return volume;
}

}  // namespace luxel::postfx
