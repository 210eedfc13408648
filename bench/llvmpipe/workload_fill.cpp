// W1 `fill`: a grid of 64 x 36 quads covering the viewport, drawn as 8 layers each nearer than the
// one before, so that every layer passes the depth test at every sample: 8 full screens of pixels
// shaded with a one-line fragment shader. The grid (rather than two big triangles) keeps the
// triangle count, 4,608 a layer, the same as luxel's.

#include "workload_fill.hpp"

#include "gl_context.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace luxel::llvmpipe {

namespace {

constexpr int kColumns = 64, kRows = 36, kLayers = 8;

/// Layer k's color, drawn k-th; the last one (orange) is the final image.
constexpr std::array<glm::vec3, kLayers> kLayerColors = {
    glm::vec3(.90f, .20f, .20f), glm::vec3(.20f, .90f, .20f), glm::vec3(.20f, .20f, .90f), glm::vec3(.90f, .90f, .20f),
    glm::vec3(.90f, .20f, .90f), glm::vec3(.20f, .90f, .90f), glm::vec3(.60f, .60f, .60f), glm::vec3(.95f, .55f, .15f)};

/// NDC depth of layer k: each nearer than all before it, so LESS passes everywhere.
float layer_depth(int k) { return 0.875f - 0.25f * float(k); }

constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec2 position;  // NDC
layout(location = 1) in vec2 uv;
uniform float depth;
out vec2 vUv;
void main() {
  vUv = uv;
  gl_Position = vec4(position, depth, 1.0);
}
)";

constexpr const char* kFragmentShader = R"(#version 330 core
in vec2 vUv;
uniform vec3 layerColor;
out vec4 color;
void main() { color = vec4(layerColor * (0.9 + 0.1 * vUv.x), 1.0); }
)";

class Fill final : public Workload {
 public:
  Fill() {
    // (65 x 37) vertices: NDC position, then uv, interleaved.
    std::vector<glm::vec2> vertices;
    for (int j = 0; j <= kRows; ++j)
      for (int i = 0; i <= kColumns; ++i) {
        const glm::vec2 uv(float(i) / kColumns, float(j) / kRows);
        vertices.push_back(glm::vec2(-1.0f + 2.0f * float(i) / kColumns, -1.0f + 2.0f * float(j) / kRows));
        vertices.push_back(uv);
      }
    std::vector<uint16_t> indices;
    const auto at = [](int i, int j) { return uint16_t(j * (kColumns + 1) + i); };
    for (int j = 0; j < kRows; ++j)
      for (int i = 0; i < kColumns; ++i) {
        // Two counter-clockwise triangles (v00, v10, v11) and (v00, v11, v01).
        for (uint16_t v : {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)}) indices.push_back(v);
      }
    index_count_ = GLsizei(indices.size());

    glGenVertexArrays(1, &vertex_array_);
    glBindVertexArray(vertex_array_);
    glGenBuffers(1, &vertex_buffer_);
    glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(glm::vec2)), vertices.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(glm::vec2), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(glm::vec2), reinterpret_cast<void*>(sizeof(glm::vec2)));
    glGenBuffers(1, &index_buffer_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_buffer_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(uint16_t)), indices.data(), GL_STATIC_DRAW);
    glBindVertexArray(0);

    program_ = build_program(kVertexShader, kFragmentShader);
    depth_location_ = glGetUniformLocation(program_, "depth");
    color_location_ = glGetUniformLocation(program_, "layerColor");
    check_gl("preparing fill");
  }

  ~Fill() override {
    glDeleteProgram(program_);
    glDeleteBuffers(1, &vertex_buffer_);
    glDeleteBuffers(1, &index_buffer_);
    glDeleteVertexArrays(1, &vertex_array_);
  }

  glm::vec4 clear_color() const override { return {0.0f, 0.0f, 0.0f, 1.0f}; }

  void draw() const override {
    depth_tested_without_blending();
    glDisable(GL_CULL_FACE);
    glUseProgram(program_);
    glBindVertexArray(vertex_array_);
    for (int k = 0; k < kLayers; ++k) {
      glUniform1f(depth_location_, layer_depth(k));
      glUniform3f(color_location_, kLayerColors[k].r, kLayerColors[k].g, kLayerColors[k].b);
      glDrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_SHORT, nullptr);
    }
  }

 private:
  GLuint vertex_array_ = 0, vertex_buffer_ = 0, index_buffer_ = 0, program_ = 0;
  GLint depth_location_ = -1, color_location_ = -1;
  GLsizei index_count_ = 0;
};

}  // namespace

std::unique_ptr<Workload> make_fill() { return std::make_unique<Fill>(); }

}  // namespace luxel::llvmpipe
