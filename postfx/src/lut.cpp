// The engine's LUT (lut.hpp): sampling a transform on the lattice, and the volume texture.

#include "luxel/postfx/lut.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

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

namespace {

/// The color of every entry of a `size`^3 lattice, in entry order (checked by Lut::of_size first,
/// so that an absurd size is refused before it is allocated).
std::vector<glm::vec3> lattice_colors(int size) {
  (void)Lut::of_size(size);
  std::vector<glm::vec3> colors(static_cast<size_t>(size) * size * size);
  for (int b = 0; b < size; ++b)
    for (int g = 0; g < size; ++g)
      for (int r = 0; r < size; ++r)
        colors[static_cast<size_t>((b * size + g) * size + r)] =
            glm::vec3(lattice_color(r, size), lattice_color(g, size), lattice_color(b, size));
  return colors;
}

/// Each color rounded into the LUT's entry of the same index.
Lut rounded(const std::vector<glm::vec3>& colors, int size) {
  Lut lut = Lut::of_size(size);
  for (size_t i = 0; i < colors.size(); ++i)
    lut.entries[i] = {to_unorm8(colors[i].x), to_unorm8(colors[i].y), to_unorm8(colors[i].z)};
  return lut;
}

}  // namespace

Lut Lut::identity(int size) { return rounded(lattice_colors(size), size); }

Lut sample_lut(const ColorTransform& transform, int size) {
  std::vector<glm::vec3> colors = lattice_colors(size);
  transform.apply(colors);
  return rounded(colors, size);
}

Lut compose(const Lut& lut, const ColorTransform& then) {
  std::vector<glm::vec3> colors(lut.entries.size());
  for (size_t i = 0; i < colors.size(); ++i)
    colors[i] = glm::vec3(lut.entries[i][0], lut.entries[i][1], lut.entries[i][2]) / 255.0f;
  then.apply(colors);
  return rounded(colors, lut.size);
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
