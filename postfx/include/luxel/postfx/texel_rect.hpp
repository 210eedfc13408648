#pragma once
// The source texels a post pass's screen rectangle shows, as Source's DrawScreenSpaceRectangle
// takes them: a header of its own because passes' interfaces name it (Bloom::bloom_rectangle),
// while the rectangle's drawing (postfx/src/screen_rectangle.hpp) includes the draw
// implementation, which only the files that draw a pass parse.

namespace luxel::postfx {

/// Which source texels appear on the first and the last destination pixel, and the source
/// texture's size (DrawScreenSpaceRectangle's src_texture_x0..y1, width, height).
struct TexelRect {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int texture_width = 1, texture_height = 1;
};

/// A texel rectangle covering the whole of a width x height texture: texel (0, 0) to the last.
inline TexelRect whole_texture(int width, int height) {
  return {0.0f, 0.0f, static_cast<float>(width - 1), static_cast<float>(height - 1), width, height};
}

}  // namespace luxel::postfx
