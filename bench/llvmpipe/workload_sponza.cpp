// W3 `sponza` drawn by OpenGL from the scene luxel's W3 draws: the file is read by luxel's
// importer (bench::load_sponza_scene), so the two sides cannot disagree on what a node, an
// accessor or a material means, and the camera, lights and ambient cube are luxel's W3 constants
// (bench::sponza_camera, bench::sponza_lighting) in the scene's space: Source's inches, +Z up.
// bench/workloads/sponza.hpp explains why that space draws the peer's picture.

#include "workload_sponza.hpp"

#include "clip_space.hpp"
#include "gl_context.hpp"
#include "mesh_indices.hpp"
#include "source_textures.hpp"

#include "luxel/frame/renderer.hpp"
#include "luxel/scenes/scene.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace luxel::llvmpipe {

namespace {

constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;  // world space (the scene's), inches
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;
uniform mat4 viewProjection;
out vec3 vWorld;
out vec3 vNormal;
out vec2 vUv;
void main() {
  vWorld = position;
  vNormal = normal;
  vUv = uv;
  gl_Position = viewProjection * vec4(position, 1.0);
}
)";

// The W3 shading in the definition's order. The ambient cube's faces are Source's +X, -X, +Y,
// -Y, +Z, -Z; its three terms are summed in glTF's axis order (x, y, z) = Source's (x, z, y), as
// the peer sums them and luxel's W3 does.
constexpr const char* kFragmentShader = R"(#version 330 core
in vec3 vWorld;
in vec3 vNormal;
in vec2 vUv;
uniform sampler2D baseTexture;
uniform vec4 baseColorFactor;
uniform vec3 ambientCube[6];
uniform vec3 lightPosition[2];
uniform vec3 lightColor[2];
out vec4 color;
void main() {
  vec3 n = normalize(vNormal);
  if (!gl_FrontFacing) n = -n;  // only double-sided draws show back faces
  vec3 w = n * n;
  vec3 ambient = w.x * (n.x >= 0.0 ? ambientCube[0] : ambientCube[1]);
  ambient += w.z * (n.z >= 0.0 ? ambientCube[4] : ambientCube[5]);
  ambient += w.y * (n.y >= 0.0 ? ambientCube[2] : ambientCube[3]);
  vec3 light = ambient;
  for (int i = 0; i < 2; ++i) {
    vec3 d = lightPosition[i] - vWorld;
    vec3 l = d / length(d);
    float halfLambert = 0.5 * dot(n, l) + 0.5;
    light += lightColor[i] * (halfLambert * halfLambert / dot(d, d));
  }
  vec4 albedo = texture(baseTexture, vUv) * baseColorFactor;
  color = vec4(clamp(albedo.rgb * light, 0.0, 1.0), 1.0);  // exposure 1
}
)";

/// W3's texture rules: RGBA8 without sRGB decode, premultiplied as the peer decodes
/// (bench::sponza_texture), full mip chain, always trilinear, the sampler's wrap modes.
GLuint upload_texture(const scenes::Texture& scene_texture) {
  const scenes::Texture texture = bench::sponza_texture(scene_texture);
  const scenes::PixelImage& image = texture.faces.at(0);
  GLuint name = 0;
  glGenTextures(1, &name);
  glBindTexture(GL_TEXTURE_2D, name);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  // Top row first, as glTF's v = 0 is the image's top: uv reads the texture as it is stored.
  if (image.is_hdr())
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, image.width, image.height, 0, GL_RGBA, GL_FLOAT, image.rgba32f.data());
  else
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba8.data());
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, gl_wrap(texture.wrap_u));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, gl_wrap(texture.wrap_v));
  return name;
}

GLuint white_texture() {
  const uint8_t white[4] = {255, 255, 255, 255};
  GLuint name = 0;
  glGenTextures(1, &name);
  glBindTexture(GL_TEXTURE_2D, name);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, white);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  return name;
}

template <class T>
GLuint array_buffer(const std::vector<T>& data) {
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(T)), data.data(), GL_STATIC_DRAW);
  return buffer;
}

/// One glTF primitive instance: its vertex array and what its draw call needs.
struct Draw {
  GLuint vertex_array = 0;
  std::vector<GLuint> buffers;
  MeshIndices indices;
  bool double_sided = false;
  GLuint texture = 0;
  glm::vec4 factor{1.0f};
};

class Sponza final : public Workload {
 public:
  Sponza(const scenes::Scene& scene, const bench::SponzaView& view, int width, int height) {
    program_ = build_program(kVertexShader, kFragmentShader);
    glUseProgram(program_);
    const glm::mat4 view_projection = opengl_clip(frame::view_projection(bench::sponza_camera(view), width, height));
    glUniformMatrix4fv(glGetUniformLocation(program_, "viewProjection"), 1, GL_FALSE, glm::value_ptr(view_projection));
    const bench::SponzaLighting lighting = bench::sponza_lighting();
    glUniform3fv(glGetUniformLocation(program_, "ambientCube"), 6, glm::value_ptr(lighting.cube[0]));
    glUniform3fv(glGetUniformLocation(program_, "lightPosition"), 2, glm::value_ptr(lighting.position[0]));
    glUniform3fv(glGetUniformLocation(program_, "lightColor"), 2, glm::value_ptr(lighting.color[0]));
    glUniform1i(glGetUniformLocation(program_, "baseTexture"), 0);
    factor_location_ = glGetUniformLocation(program_, "baseColorFactor");

    for (const scenes::Texture& t : scene.textures) textures_.push_back(upload_texture(t));
    white_ = white_texture();
    const scenes::Material untextured;  // white, factor 1, single-sided
    for (const scenes::Mesh& mesh : scene.meshes) {
      const scenes::Material& material = mesh.material >= 0 ? scene.materials[mesh.material] : untextured;
      draws_.push_back(make_draw(mesh, material));
    }
    check_gl("preparing sponza");
  }

  ~Sponza() override {
    for (const Draw& d : draws_) {
      glDeleteBuffers(GLsizei(d.buffers.size()), d.buffers.data());
      glDeleteVertexArrays(1, &d.vertex_array);
    }
    glDeleteTextures(GLsizei(textures_.size()), textures_.data());
    glDeleteTextures(1, &white_);
    glDeleteProgram(program_);
  }

  glm::vec4 clear_color() const override { return bench::kSponzaClear; }

  void draw() const override {
    depth_tested_without_blending();
    glFrontFace(GL_CCW);
    glCullFace(GL_BACK);
    glUseProgram(program_);
    glActiveTexture(GL_TEXTURE0);
    for (const Draw& d : draws_) {
      if (d.double_sided)
        glDisable(GL_CULL_FACE);
      else
        glEnable(GL_CULL_FACE);
      glBindTexture(GL_TEXTURE_2D, d.texture);
      glUniform4f(factor_location_, d.factor.r, d.factor.g, d.factor.b, d.factor.a);
      glBindVertexArray(d.vertex_array);
      draw_triangles(d.indices);
    }
  }

 private:
  Draw make_draw(const scenes::Mesh& mesh, const scenes::Material& material) {
    Draw d;
    d.double_sided = material.double_sided;
    d.texture = material.base.bound() ? textures_.at(size_t(material.base.texture)) : white_;
    d.factor = material.color;
    glGenVertexArrays(1, &d.vertex_array);
    glBindVertexArray(d.vertex_array);
    const auto attribute = [&](GLuint location, GLint components, GLuint buffer) {
      d.buffers.push_back(buffer);
      glEnableVertexAttribArray(location);
      glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, 0, nullptr);
    };
    attribute(0, 3, array_buffer(mesh.positions));
    // load_sponza_scene fills a missing NORMAL; a missing uv set reads (0, 0), a constant attribute.
    if (!mesh.normals.empty()) attribute(1, 3, array_buffer(mesh.normals));
    else glVertexAttrib3f(1, 0.0f, 0.0f, 1.0f);
    const std::vector<glm::vec2>& uvs = material.base.uv_set == 1 ? mesh.uv1 : mesh.uv0;
    if (!uvs.empty()) attribute(2, 2, array_buffer(uvs));
    else glVertexAttrib2f(2, 0.0f, 0.0f);

    const MeshIndices indices = upload_indices(mesh);
    if (indices.buffer) d.buffers.push_back(indices.buffer);
    d.indices = indices;
    glBindVertexArray(0);
    return d;
  }

  GLuint program_ = 0, white_ = 0;
  GLint factor_location_ = -1;
  std::vector<GLuint> textures_;
  std::vector<Draw> draws_;
};

}  // namespace

std::unique_ptr<Workload> make_sponza(const std::string& path, const bench::SponzaView& view, int width, int height) {
  // The same reasons as luxel_frame_bench's, so that the two sides' skip lines read alike.
  if (path.empty()) throw Skipped("no glTF file given (--sponza PATH)");
  if (!std::filesystem::is_regular_file(path)) throw Skipped("glTF file not found: " + path);
  const scenes::Scene scene = bench::load_sponza_scene(path);
  return std::make_unique<Sponza>(scene, view, width, height);
}

}  // namespace luxel::llvmpipe
