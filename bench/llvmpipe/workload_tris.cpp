// W2 `tris`: 1,000,000 equilateral triangles of 2 to 4 px^2 at random places, depths and
// orientations, one glDrawArrays of 3,000,000 non-indexed vertices. The generator draws only raw
// std::mt19937 outputs, which the C++ standard fixes, so luxel's copy of it yields the same
// triangles bit for bit.

#include "workload_tris.hpp"

#include "gl_context.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

namespace luxel::llvmpipe {

namespace {

constexpr int kTriangles = 1'000'000;

/// 16 bytes: position in pixels (origin bottom-left), NDC depth, color.
struct Vertex {
  float x, y, z;
  uint8_t rgba[4];
};
static_assert(sizeof(Vertex) == 16);

std::vector<Vertex> generate(int width, int height) {
  std::mt19937 rng(1);
  // 24 bits of one output, in [0, 1): exact in a double, whatever the standard library.
  const auto unit = [&rng] { return double(rng() >> 8) / double(1u << 24); };
  const auto channel = [&rng] { return uint8_t(64 + rng() % 192); };
  std::vector<Vertex> vertices;
  vertices.reserve(size_t(kTriangles) * 3);
  for (int t = 0; t < kTriangles; ++t) {
    // The draws are in the definition's order: the order is what makes them reproducible.
    const double cx = width * unit();
    const double cy = height * unit();
    const double z = 2.0 * unit() - 1.0;
    const double area = 2.0 + 2.0 * unit();
    const double theta = 2.0 * std::numbers::pi * unit();
    const uint8_t r = channel();
    const uint8_t g = channel();
    const uint8_t b = channel();
    // Circumradius of the equilateral triangle of that area.
    const double radius = std::sqrt(4.0 * area / (3.0 * std::sqrt(3.0)));
    for (int k = 0; k < 3; ++k) {
      // k * (2 pi / 3), not 2 pi k / 3: the two round differently in the last bit, and this is
      // the expression the peer and luxel's built-in scene evaluate.
      const double angle = theta + k * (2.0 * std::numbers::pi / 3.0);
      vertices.push_back({float(cx + radius * std::cos(angle)), float(cy + radius * std::sin(angle)), float(z), {r, g, b, 255}});
    }
  }
  return vertices;
}

constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;  // x, y in pixels, z in NDC
layout(location = 1) in vec4 color;
uniform vec2 pixelsToNdc;                // (2 / W, 2 / H)
flat out vec4 vColor;
void main() {
  vColor = color;
  gl_Position = vec4(position.xy * pixelsToNdc - 1.0, position.z, 1.0);
}
)";

constexpr const char* kFragmentShader = R"(#version 330 core
flat in vec4 vColor;
out vec4 color;
void main() { color = vColor; }
)";

class Tris final : public Workload {
 public:
  Tris(int width, int height) {
    const std::vector<Vertex> vertices = generate(width, height);
    vertex_count_ = GLsizei(vertices.size());
    glGenVertexArrays(1, &vertex_array_);
    glBindVertexArray(vertex_array_);
    glGenBuffers(1, &vertex_buffer_);
    glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, x)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, rgba)));
    glBindVertexArray(0);
    program_ = build_program(kVertexShader, kFragmentShader);
    glUseProgram(program_);
    glUniform2f(glGetUniformLocation(program_, "pixelsToNdc"), 2.0f / float(width), 2.0f / float(height));
    check_gl("preparing tris");
  }

  ~Tris() override {
    glDeleteProgram(program_);
    glDeleteBuffers(1, &vertex_buffer_);
    glDeleteVertexArrays(1, &vertex_array_);
  }

  glm::vec4 clear_color() const override { return {0.1f, 0.1f, 0.1f, 1.0f}; }

  void draw() const override {
    depth_tested_without_blending();
    glDisable(GL_CULL_FACE);
    glUseProgram(program_);
    glBindVertexArray(vertex_array_);
    glDrawArrays(GL_TRIANGLES, 0, vertex_count_);
  }

 private:
  GLuint vertex_array_ = 0, vertex_buffer_ = 0, program_ = 0;
  GLsizei vertex_count_ = 0;
};

}  // namespace

std::unique_ptr<Workload> make_tris(int width, int height) { return std::make_unique<Tris>(width, height); }

}  // namespace luxel::llvmpipe
