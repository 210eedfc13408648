// The engine's LUT (lut.hpp): sampling a transform on the lattice, and the volume texture.

#include "luxel/postfx/lut.hpp"

#include <cmath>
#include <utility>

namespace luxel::postfx {

uint8_t to_unorm8(float x) {
  if (!(x > 0.0f)) return 0;  // NaN and <= 0
  if (x >= 1.0f) return 255;
  return static_cast<uint8_t>(std::lround(x * 255.0f));
}

Lut Lut::identity() {
  Lut lut;
  for (int b = 0; b < kLutSize; ++b)
    for (int g = 0; g < kLutSize; ++g)
      for (int r = 0; r < kLutSize; ++r)
        lut.at(r, g, b) = {to_unorm8(lattice_color(r)), to_unorm8(lattice_color(g)), to_unorm8(lattice_color(b))};
  return lut;
}

namespace {

/// `colors` (one per entry) transformed and rounded into a LUT.
Lut transformed(std::vector<glm::vec3> colors, const ColorTransform& transform) {
  transform.apply(colors);
  Lut lut;
  for (size_t i = 0; i < colors.size(); ++i)
    lut.entries[i] = {to_unorm8(colors[i].x), to_unorm8(colors[i].y), to_unorm8(colors[i].z)};
  return lut;
}

}  // namespace

Lut sample_lut(const ColorTransform& transform) {
  std::vector<glm::vec3> colors(kLutEntries);
  for (int b = 0; b < kLutSize; ++b)
    for (int g = 0; g < kLutSize; ++g)
      for (int r = 0; r < kLutSize; ++r)
        colors[static_cast<size_t>((b * kLutSize + g) * kLutSize + r)] =
            glm::vec3(lattice_color(r), lattice_color(g), lattice_color(b));
  return transformed(std::move(colors), transform);
}

Lut compose(const Lut& lut, const ColorTransform& then) {
  std::vector<glm::vec3> colors(kLutEntries);
  for (size_t i = 0; i < colors.size(); ++i)
    colors[i] = glm::vec3(lut.entries[i][0], lut.entries[i][1], lut.entries[i][2]) / 255.0f;
  return transformed(std::move(colors), then);
}

rasterizer::Texture lut_volume(const Lut& lut) {
  rasterizer::Texture volume =
      rasterizer::Texture::create_volume(kLutSize, kLutSize, kLutSize, rasterizer::TextureFormat::RGBA8, 1);
  std::vector<uint8_t> bytes(static_cast<size_t>(kLutEntries) * 4);
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
