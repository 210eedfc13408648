#pragma once
// luxel's view-projection (frame::view_projection) is Direct3D's: depth 0..w in clip space.
// OpenGL clips depth to -w..w; this maps one to the other, so the GL side draws from luxel's own
// camera matrices (the same x and y, so the same pixels) rather than from a second copy of them.

#include <glm/mat4x4.hpp>

namespace luxel::llvmpipe {

/// z' = 2 z - w: Direct3D's clip space to OpenGL's.
inline glm::mat4 opengl_clip(const glm::mat4& direct3d_view_projection) {
  glm::mat4 depth_to_opengl(1.0f);
  depth_to_opengl[2][2] = 2.0f;
  depth_to_opengl[3][2] = -1.0f;
  return depth_to_opengl * direct3d_view_projection;
}

}  // namespace luxel::llvmpipe
