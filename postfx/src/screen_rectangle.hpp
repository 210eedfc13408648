#pragma once
// Private: the full-target rectangle every post pass draws: Source's DrawScreenSpaceRectangle
// (IMatRenderContext), which maps a rectangle of source texels onto a rectangle of destination
// pixels centre to centre: the centre of source texel (x0, y0) lands on the centre of the first
// destination pixel and the centre of (x1, y1) on the centre of the last. With a destination
// w pixels wide, one pixel steps s = (x1 - x0) / (w - 1) texels (0 when w is 1), so u runs from
// (x0 + 0.5 - s/2) / texture_width at the quad's left edge to (x1 + 0.5 + s/2) / texture_width at
// its right edge, and pixel i reads u = (x0 + 0.5 + i s) / texture_width (likewise v).
//
// The SDK's quad sits at D3D9 screen position -0.5 (its half-pixel offset), which is luxel's pixel
// edge 0 (rasterizer/state.hpp), so the rectangle here covers the whole target [0, w) x [0, h).
//
// Some shaders take several tap coordinates from their vertex shader (the bloom's downsample takes
// four): tap i is the interpolated coordinate plus a fixed offset in source texels, packed two to
// a varying (.xy, .zw).

#include "luxel/postfx/texel_rect.hpp"
#include "luxel/rasterizer/draw_definition.hpp"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstdint>

namespace luxel::postfx {

/// The vertex functor of the rectangle: two triangles, six vertices, `Taps` texture coordinates.
template <int Taps>
struct ScreenRectangle {
  static constexpr int kVaryings = (Taps + 1) / 2;
  glm::vec2 uv_min{0.0f}, uv_max{0.0f};      ///< texture coordinates at the rectangle's corners
  std::array<glm::vec2, Taps> tap_offsets{}; ///< per tap, in texture coordinates

  void operator()(uint32_t vertex, rasterizer::VertexOutput<kVaryings>& out) const {
    static constexpr int kCorner[6][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 0}, {1, 1}, {0, 1}};
    const int cx = kCorner[vertex][0], cy = kCorner[vertex][1];
    out.position = glm::vec4(cx ? 1.0f : -1.0f, cy ? -1.0f : 1.0f, 0.5f, 1.0f);
    const glm::vec2 uv(cx ? uv_max.x : uv_min.x, cy ? uv_max.y : uv_min.y);
    for (int i = 0; i < Taps; ++i) {
      const glm::vec2 tap = uv + tap_offsets[i];
      out.varyings[i / 2][2 * (i % 2)] = tap.x;
      out.varyings[i / 2][2 * (i % 2) + 1] = tap.y;
    }
  }
};

/// The rectangle over a target_width x target_height target showing `src`, with tap offsets given
/// in source texels.
template <int Taps>
ScreenRectangle<Taps> screen_rectangle(int target_width, int target_height, const TexelRect& src,
                                       const std::array<glm::vec2, Taps>& tap_offsets_in_texels) {
  ScreenRectangle<Taps> r;
  const float step_x = target_width > 1 ? (src.x1 - src.x0) / static_cast<float>(target_width - 1) : 0.0f;
  const float step_y = target_height > 1 ? (src.y1 - src.y0) / static_cast<float>(target_height - 1) : 0.0f;
  const glm::vec2 texel(1.0f / static_cast<float>(src.texture_width), 1.0f / static_cast<float>(src.texture_height));
  r.uv_min = glm::vec2(src.x0 + 0.5f - 0.5f * step_x, src.y0 + 0.5f - 0.5f * step_y) * texel;
  r.uv_max = glm::vec2(src.x1 + 0.5f + 0.5f * step_x, src.y1 + 0.5f + 0.5f * step_y) * texel;
  for (int i = 0; i < Taps; ++i) r.tap_offsets[i] = tap_offsets_in_texels[i] * texel;
  return r;
}

/// The same with one tap at the interpolated coordinate.
inline ScreenRectangle<1> screen_rectangle(int target_width, int target_height, const TexelRect& src) {
  return screen_rectangle<1>(target_width, target_height, src, {glm::vec2(0.0f)});
}

/// Two rectangles over the same target drawn as one, for a pass that reads two textures of
/// different sizes (Engine_Post reads the frame and the bloom): varying 0 .xy runs over the first's
/// coordinates, .zw over the second's.
struct ScreenRectanglePair {
  static constexpr int kVaryings = 1;
  ScreenRectangle<1> first, second;

  void operator()(uint32_t vertex, rasterizer::VertexOutput<1>& out) const {
    rasterizer::VertexOutput<1> a, b;
    first(vertex, a);
    second(vertex, b);
    out.position = a.position;
    out.varyings[0] = glm::vec4(a.varyings[0].x, a.varyings[0].y, b.varyings[0].x, b.varyings[0].y);
  }
};

/// Draws a rectangle (ScreenRectangle or ScreenRectanglePair) with `state` (its viewport covers
/// the target) and pixel functor `ps`.
template <class Rectangle, class PixelShader>
void draw_screen_rectangle(rasterizer::Context& ctx, rasterizer::ColorTarget& target,
                           const rasterizer::PipelineState& state, const Rectangle& rectangle,
                           const PixelShader& ps) {
  rasterizer::draw(ctx, rasterizer::Framebuffer{&target, nullptr}, state, rasterizer::Geometry::non_indexed(6),
                   rectangle, ps);
}

/// The state of a post pass that replaces the target's pixels: no depth, no culling, no blending.
inline rasterizer::PipelineState post_pass_state() {
  rasterizer::PipelineState s;
  s.rasterizer.cull = rasterizer::CullMode::None;
  s.depth_stencil.depth_enable = false;
  return s;
}

}  // namespace luxel::postfx
