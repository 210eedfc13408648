// EGL surfaceless context creation and program building for the llvmpipe benchmark.

#include "gl_context.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <algorithm>
#include <cstdio>
#include <utility>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace luxel::llvmpipe {

namespace {

/// Whether a space-separated extension list names `name` exactly (not as a prefix of another).
bool has_extension(const char* list, std::string_view name) {
  if (!list) return false;
  std::string_view rest(list);
  while (!rest.empty()) {
    const size_t end = rest.find(' ');
    if (rest.substr(0, end) == name) return true;
    if (end == std::string_view::npos) break;
    rest.remove_prefix(end + 1);
  }
  return false;
}

[[noreturn]] void fail(const std::string& what) {
  throw std::runtime_error(what + " (EGL error 0x" + [] {
    char hex[16];
    std::snprintf(hex, sizeof hex, "%04x", unsigned(eglGetError()));
    return std::string(hex);
  }() + ")");
}

}  // namespace

GlContext::GlContext() {
  // The surfaceless platform is a client extension of Mesa's libEGL: without it there is no way
  // to reach llvmpipe without a display server.
  if (!has_extension(eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS), "EGL_MESA_platform_surfaceless"))
    throw std::runtime_error("EGL has no EGL_MESA_platform_surfaceless (is Mesa's libegl-mesa0 installed?)");
  EGLDisplay display = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY) fail("eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA) failed");
  if (!eglInitialize(display, nullptr, nullptr)) fail("eglInitialize failed");
  display_ = display;
  if (!has_extension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context"))
    throw std::runtime_error("the EGL display has no EGL_KHR_surfaceless_context");
  if (!eglBindAPI(EGL_OPENGL_API)) fail("eglBindAPI(EGL_OPENGL_API) failed");

  // Every target is a framebuffer object, so the config only has to allow desktop OpenGL; where
  // no config is offered, EGL_KHR_no_config_context lets the context go without one.
  const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  if (!eglChooseConfig(display, config_attributes, &config, 1, &configs) || configs < 1) config = nullptr;

  for (const auto& [major, minor] : {std::pair{4, 5}, std::pair{3, 3}}) {
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, major, EGL_CONTEXT_MINOR_VERSION, minor,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, attributes);
    if (context != EGL_NO_CONTEXT) {
      context_ = context;
      break;
    }
  }
  if (!context_) fail("eglCreateContext refused OpenGL 4.5 core and 3.3 core");
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, static_cast<EGLContext>(context_)))
    fail("eglMakeCurrent without a surface failed");
}

GlContext::~GlContext() {
  if (!display_) return;
  EGLDisplay display = static_cast<EGLDisplay>(display_);
  eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (context_) eglDestroyContext(display, static_cast<EGLContext>(context_));
  eglTerminate(display);
}

std::string GlContext::renderer() { return reinterpret_cast<const char*>(glGetString(GL_RENDERER)); }
std::string GlContext::version() { return reinterpret_cast<const char*>(glGetString(GL_VERSION)); }

namespace {

GLuint compile(GLenum stage, const std::string& source) {
  const GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(size_t(std::max(length, 1)));
    glGetShaderInfoLog(shader, GLsizei(log.size()), nullptr, log.data());
    glDeleteShader(shader);
    throw std::runtime_error(std::string(stage == GL_VERTEX_SHADER ? "vertex" : "fragment") + " shader: " + log.data());
  }
  return shader;
}

}  // namespace

GLuint build_program(const std::string& vertex_source, const std::string& fragment_source) {
  const GLuint vertex = compile(GL_VERTEX_SHADER, vertex_source);
  GLuint fragment = 0;
  try {
    fragment = compile(GL_FRAGMENT_SHADER, fragment_source);
  } catch (...) {
    glDeleteShader(vertex);
    throw;
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, vertex);
  glAttachShader(program, fragment);
  glLinkProgram(program);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(size_t(std::max(length, 1)));
    glGetProgramInfoLog(program, GLsizei(log.size()), nullptr, log.data());
    glDeleteProgram(program);
    throw std::runtime_error(std::string("program link: ") + log.data());
  }
  return program;
}

void check_gl(const char* what) {
  const GLenum error = glGetError();
  if (error == GL_NO_ERROR) return;
  while (glGetError() != GL_NO_ERROR) {
  }
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%04x", error);
  throw std::runtime_error(std::string(what) + ": OpenGL error " + hex);
}

}  // namespace luxel::llvmpipe
