#pragma once
// Private: the trivial draw of the peer workloads' materials (renderer.cpp: is_trivial_unlit):
// unlit, untextured, vertex color x material color, as UnlitGeneric computes it, through the
// rasterizer's fastest paths.

#include "luxel/rasterizer/draw.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace luxel::frame {

/// Position and vertex color x material color: for unlit, untextured materials.
struct UnlitVertex {
  static constexpr int kVaryings = 1;
  const glm::vec3* positions;
  const glm::vec4* colors;  ///< or null: white
  glm::vec4 color;          ///< the material's
  glm::mat4 view_projection;
  /// The front end prefetches the positions (draw.hpp); the colors, a second stream as large
  /// (W2's 48 MB), are prefetched here, as far ahead: without it W2 ran ~1.5% slower.
  static constexpr uint32_t kColorsAhead = 64;
  const void* input(uint32_t i) const { return positions + i; }
  void operator()(uint32_t i, rasterizer::VertexOutput<1>& out) const {
    out.position = view_projection * glm::vec4(positions[i], 1.0f);
    if (colors) rasterizer::simd::prefetch(colors + i + kColorsAhead);  // never faults, even past the end
    out.varyings[0] = colors ? colors[i] * color : color;
  }
};

/// The interpolated color, as it is: trivial (rasterizer/draw.hpp), so the workloads' draws take
/// the rasterizer's fastest paths.
struct UnlitPixel {
  static constexpr bool kCanDiscard = false, kWritesDepth = false, kTrivial = true;
  void operator()(const rasterizer::PixelInput<1>& in, rasterizer::PixelOutput& out) const {
    out.color = in.varyings[0];
  }
};

}  // namespace luxel::frame
