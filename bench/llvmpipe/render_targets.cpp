// Framebuffers A (drawn, multisampled) and B (resolved) of the llvmpipe benchmark's frame.

#include "render_targets.hpp"

#include "gl_context.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace luxel::llvmpipe {

namespace {

/// For one sample, plain storage: Mesa rounds a multisample request for 1 sample up to its
/// smallest multisample count (4 on llvmpipe), which would silently turn msaa=1 into 4x.
void allocate(GLenum format, int width, int height, int samples) {
  if (samples > 1)
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
  else
    glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
}

GLuint make_renderbuffer(GLenum format, int width, int height, int samples) {
  GLuint renderbuffer = 0;
  glGenRenderbuffers(1, &renderbuffer);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer);
  allocate(format, width, height, samples);
  return renderbuffer;
}

void require_complete(const char* which) {
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error(std::string("framebuffer ") + which + " is incomplete (status " + std::to_string(status) + ")");
}

}  // namespace

RenderTargets::RenderTargets(int width, int height, int samples) : width_(width), height_(height) {
  GLint max_samples = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  if (samples > max_samples)
    throw std::runtime_error("msaa " + std::to_string(samples) + " is more than the driver's GL_MAX_SAMPLES " +
                             std::to_string(max_samples));
  draw_color_ = make_renderbuffer(GL_RGBA8, width, height, samples);
  draw_depth_ = make_renderbuffer(GL_DEPTH24_STENCIL8, width, height, samples);
  glGenFramebuffers(1, &draw_framebuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, draw_framebuffer_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, draw_color_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, draw_depth_);
  require_complete("A");
  GLint granted = 0;
  glGetIntegerv(GL_SAMPLES, &granted);
  samples_ = std::max(1, int(granted));

  image_color_ = make_renderbuffer(GL_RGBA8, width, height, 1);
  glGenFramebuffers(1, &image_framebuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, image_framebuffer_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, image_color_);
  require_complete("B");
  check_gl("creating the framebuffers");
}

RenderTargets::~RenderTargets() {
  const GLuint framebuffers[] = {draw_framebuffer_, image_framebuffer_};
  const GLuint renderbuffers[] = {draw_color_, draw_depth_, image_color_};
  glDeleteFramebuffers(2, framebuffers);
  glDeleteRenderbuffers(3, renderbuffers);
}

void RenderTargets::bind_for_drawing() const {
  glBindFramebuffer(GL_FRAMEBUFFER, draw_framebuffer_);
  glViewport(0, 0, width_, height_);
}

void RenderTargets::resolve() const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, draw_framebuffer_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, image_framebuffer_);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

std::vector<uint8_t> RenderTargets::read_image() const {
  const size_t row = size_t(width_) * 4;
  std::vector<uint8_t> bottom_first(row * size_t(height_));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, image_framebuffer_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, bottom_first.data());
  std::vector<uint8_t> top_first(bottom_first.size());
  for (int y = 0; y < height_; ++y)
    std::copy_n(bottom_first.data() + size_t(height_ - 1 - y) * row, row, top_first.data() + size_t(y) * row);
  return top_first;
}

}  // namespace luxel::llvmpipe
