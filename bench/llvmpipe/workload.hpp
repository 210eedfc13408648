#pragma once
// What a workload is to the benchmark's frame loop: the GL objects it made up front, a clear color,
// and the draws of one frame. The frame itself (bind A, clear, draw, resolve into B) is the
// harness's, so every workload is timed the same way (bench/README.md, "llvmpipe").

#include <GL/glcorearb.h>
#include <glm/vec4.hpp>

#include <stdexcept>
#include <string>

namespace luxel::llvmpipe {

class Workload {
 public:
  virtual ~Workload() = default;
  /// The color framebuffer A is cleared to before the draws (depth is cleared to 1).
  virtual glm::vec4 clear_color() const = 0;
  /// Issues the frame's draws into the bound framebuffer A, setting all the state they need.
  virtual void draw() const = 0;
};

/// The state every workload draws with: depth test LESS with depth writes, no blending (culling
/// is each workload's own).
inline void depth_tested_without_blending() {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

/// Thrown while preparing a workload whose input is missing: the benchmark prints
/// `workload=<name> skipped reason="..."` and goes on, as the peer does.
class Skipped : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace luxel::llvmpipe
