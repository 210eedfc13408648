#pragma once
// Private: one factory per built-in scene (one .cpp each), and the small helpers they share.

#include "luxel/scenes/scene.hpp"

#include <glm/ext/vector_uint4_sized.hpp>

#include <cstdint>
#include <string>

namespace luxel::scenes::builtin {

Scene make_demo();
Scene make_fill();
Scene make_tris(int width, int height);
Scene make_courtyard();

/// A flat rgba8 texture of `size` x `size` texels from pattern(x, y) -> glm::u8vec4 (already in
/// the texture's color space: sRGB bytes for base textures, linear for normal maps and masks).
template <class Pattern>
Texture make_flat_texture(std::string name, int size, ColorSpace space, Pattern pattern) {
  Texture t;
  t.name = std::move(name);
  t.color_space = space;
  PixelImage image;
  image.width = image.height = size;
  image.rgba8.resize(static_cast<size_t>(size) * size * 4);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const auto c = pattern(x, y);
      uint8_t* texel = &image.rgba8[(static_cast<size_t>(y) * size + x) * 4];
      texel[0] = c.r, texel[1] = c.g, texel[2] = c.b, texel[3] = c.a;
    }
  t.faces.push_back(std::move(image));
  return t;
}

}  // namespace luxel::scenes::builtin
