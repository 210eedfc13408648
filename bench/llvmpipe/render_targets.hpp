#pragma once
// The two framebuffers of every frame: A, where the workload draws (RGBA8 color and
// DEPTH24_STENCIL8, S samples), and B, the single-sample RGBA8 image A is resolved into.

#include <GL/glcorearb.h>

#include <cstdint>
#include <vector>

namespace luxel::llvmpipe {

class RenderTargets {
 public:
  /// Throws std::runtime_error when the framebuffers are incomplete or the sample count refused.
  RenderTargets(int width, int height, int samples);
  ~RenderTargets();
  RenderTargets(const RenderTargets&) = delete;
  RenderTargets& operator=(const RenderTargets&) = delete;

  /// Binds A and sets the viewport to all of it.
  void bind_for_drawing() const;
  /// Copies A's color into B (GL_NEAREST): the MSAA resolve when A has samples.
  void resolve() const;
  /// B as RGBA8, top row first (OpenGL's rows are bottom first).
  std::vector<uint8_t> read_image() const;

  int width() const { return width_; }
  int height() const { return height_; }
  /// max(1, GL_SAMPLES) of A: what the driver gave, which may be more than asked.
  int samples() const { return samples_; }

 private:
  int width_, height_, samples_ = 1;
  GLuint draw_framebuffer_ = 0, draw_color_ = 0, draw_depth_ = 0;
  GLuint image_framebuffer_ = 0, image_color_ = 0;
};

}  // namespace luxel::llvmpipe
