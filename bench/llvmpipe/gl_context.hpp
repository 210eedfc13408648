#pragma once
// The OpenGL context llvmpipe draws in: EGL's surfaceless platform (no window system, no
// pbuffer), an OpenGL 4.5 core context with 3.3 core as the fallback, made current with no
// surface. Also the one helper every workload needs: compiling a program.

#include <GL/glcorearb.h>

#include <string>

namespace luxel::llvmpipe {

class GlContext {
 public:
  /// Creates the context and makes it current. Throws std::runtime_error (one line) when EGL or
  /// Mesa is missing or refuses both versions. LP_NUM_THREADS must be set before this.
  GlContext();
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  /// GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  static std::string renderer();
  /// GL_VERSION, e.g. "4.5 (Core Profile) Mesa 22.3.6".
  static std::string version();

 private:
  void* display_ = nullptr;  // EGLDisplay: EGL's types stay out of this header
  void* context_ = nullptr;  // EGLContext
};

/// Compiles and links a vertex and a fragment shader. Throws std::runtime_error with the
/// compiler's log.
GLuint build_program(const std::string& vertex_source, const std::string& fragment_source);

/// Throws std::runtime_error naming `what` when glGetError has anything to report.
void check_gl(const char* what);

}  // namespace luxel::llvmpipe
