#include "sponza.hpp"

#include "luxel/frame/renderer.hpp"
#include "luxel/frame/textures.hpp"
#include "luxel/rasterizer/draw_definition.hpp"
#include "luxel/rasterizer/framebuffer.hpp"
#include "luxel/rasterizer/msaa.hpp"
#include "luxel/rasterizer/texture.hpp"
#include "luxel/scenes/gltf.hpp"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace luxel::bench {

using rasterizer::simd::Float;

std::optional<glm::vec3> parse_vec3(const std::string& text) {
  float v[3];
  char tail = 0;
  if (std::sscanf(text.c_str(), "%f,%f,%f%c", &v[0], &v[1], &v[2], &tail) != 3) return std::nullopt;
  return glm::vec3(v[0], v[1], v[2]);
}

scenes::Scene load_sponza_scene(const std::string& path) {
  scenes::GltfImportOptions options;
  options.default_camera = false;
  options.default_lights = false;
  options.generate_tangents = false;  // W3 does no normal mapping
  options.missing_normal = glm::vec3(0.0f, 1.0f, 0.0f);
  return scenes::load_gltf(path, options);
}

namespace {

// --- The workload's constants, in glTF space as the peer defines them -------------------------
constexpr float kFovYDegrees = 60.0f;
constexpr float kNear = 0.1f, kFar = 100.0f;  // meters
/// Faces +X, -X, +Y, -Y, +Z, -Z of glTF's axes.
constexpr std::array<glm::vec3, 6> kAmbientCube = {
    glm::vec3(0.30f, 0.28f, 0.25f), glm::vec3(0.20f, 0.20f, 0.22f), glm::vec3(0.45f, 0.45f, 0.50f),
    glm::vec3(0.10f, 0.09f, 0.08f), glm::vec3(0.25f, 0.25f, 0.25f), glm::vec3(0.22f, 0.22f, 0.24f)};
constexpr std::array<glm::vec3, 2> kLightPosition = {glm::vec3(0.0f, 8.0f, 0.0f), glm::vec3(8.0f, 3.0f, 1.0f)};
constexpr std::array<glm::vec3, 2> kLightColor = {glm::vec3(6.0f, 5.5f, 5.0f), glm::vec3(2.0f, 2.5f, 4.0f)};
// ----------------------------------------------------------------------------------------------

constexpr double kInches = double(scenes::kInchesPerMeter);

/// A glTF point (meters, +Y up) in the scene's space (inches, +Z up), as the importer maps it.
glm::vec3 to_source(glm::vec3 g) { return glm::vec3(glm::dvec3(g.x, -g.z, g.y) * kInches); }

}  // namespace

SponzaLighting sponza_lighting() {
  SponzaLighting l;
  l.cube = {kAmbientCube[0], kAmbientCube[1], kAmbientCube[5], kAmbientCube[4], kAmbientCube[2], kAmbientCube[3]};
  for (int i = 0; i < 2; ++i) {
    l.position[i] = to_source(kLightPosition[i]);
    l.color[i] = glm::vec3(glm::dvec3(kLightColor[i]) * (kInches * kInches));
  }
  return l;
}

scenes::Camera sponza_camera(const SponzaView& view) {
  scenes::Camera camera;
  camera.position = to_source(view.eye);
  camera.target = to_source(view.target);
  camera.up = {0.0f, 0.0f, 1.0f};  // glTF's +Y
  camera.vertical_fov = kFovYDegrees * std::numbers::pi_v<float> / 180.0f;
  camera.near_plane = float(kNear * kInches);
  camera.far_plane = float(kFar * kInches);
  return camera;
}

/// The peer decodes with OpenImageIO's defaults, under which its PNG reader premultiplies color
/// by alpha, truncating (c a / 255; the same bytes as OpenImageIO's on every courtyard texture),
/// where luxel's importer keeps unassociated alpha: W3 premultiplies the same way.
scenes::Texture sponza_texture(const scenes::Texture& texture) {
  scenes::Texture w3 = texture;
  for (scenes::PixelImage& face : w3.faces)
    for (size_t i = 0; i + 3 < face.rgba8.size(); i += 4)
      for (size_t c = 0; c < 3; ++c) face.rgba8[i + c] = uint8_t(unsigned(face.rgba8[i + c]) * face.rgba8[i + 3] / 255u);
  w3.color_space = scenes::ColorSpace::linear;
  w3.mipmaps = true;
  w3.min = w3.mag = scenes::Filter::linear;
  return w3;
}

namespace {

/// World position and u, then the normal and v: (px, py, pz, u), (nx, ny, nz, v).
struct W3Vertex {
  static constexpr int kVaryings = 2;
  const glm::vec3* positions;
  const glm::vec3* normals;  ///< or null: +Z, glTF's +Y (load_sponza_scene fills missing ones)
  const glm::vec2* uvs;      ///< or null: (0, 0)
  glm::mat4 view_projection;
  const void* input(uint32_t i) const { return positions + i; }
  void operator()(uint32_t i, rasterizer::VertexOutput<2>& out) const {
    const glm::vec3 p = positions[i];
    const glm::vec3 n = normals ? normals[i] : glm::vec3(0.0f, 0.0f, 1.0f);
    const glm::vec2 uv = uvs ? uvs[i] : glm::vec2(0.0f);
    out.position = view_projection * glm::vec4(p, 1.0f);
    out.varyings[0] = {p.x, p.y, p.z, uv.x};
    out.varyings[1] = {n.x, n.y, n.z, uv.y};
  }
};

/// The peer's fragment shader, in its order of operations, over one stamp.
struct W3Pixel {
  static constexpr bool kCanDiscard = false, kWritesDepth = false;
  const rasterizer::Texture* texture;
  const rasterizer::Sampler* sampler;
  glm::vec4 factor;  ///< baseColorFactor
  SponzaLighting light;

  void operator()(const rasterizer::PixelInput<2>& in, rasterizer::PixelOutput& out) const {
    const rasterizer::simd::Float4& a = in.varyings[0];
    const rasterizer::simd::Float4& b = in.varyings[1];
    const rasterizer::simd::Float4 albedo = rasterizer::sample(*texture, *sampler, {a.w, b.w, Float(0.0f)});
    // normalize(), negated on back faces (only double-sided draws have any).
    Float scale = Float(1.0f) / xsimd::sqrt(b.x * b.x + b.y * b.y + b.z * b.z);
    if (!in.front_facing) scale = -scale;
    const Float n[3] = {b.x * scale, b.y * scale, b.z * scale};
    const Float pos[3] = {a.x, a.y, a.z};
    // The cube's three terms summed in glTF's axis order (x, y, z) = Source's (x, z, y), as the
    // peer sums them.
    constexpr int kGltfOrder[3] = {0, 2, 1};
    Float rgb[3];
    for (int c = 0; c < 3; ++c) {
      rgb[c] = Float(0.0f);
      for (int axis : kGltfOrder) {
        const Float face = xsimd::select(n[axis] >= Float(0.0f), Float(light.cube[2 * axis][c]), Float(light.cube[2 * axis + 1][c]));
        rgb[c] = rgb[c] + n[axis] * n[axis] * face;
      }
    }
    for (int i = 0; i < 2; ++i) {
      const Float d[3] = {Float(light.position[i].x) - pos[0], Float(light.position[i].y) - pos[1],
                          Float(light.position[i].z) - pos[2]};
      const Float dist2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      const Float inv_dist = Float(1.0f) / xsimd::sqrt(dist2);
      Float half_lambert = Float(0.5f) * ((n[0] * d[0] + n[1] * d[1] + n[2] * d[2]) * inv_dist) + Float(0.5f);
      half_lambert = half_lambert * half_lambert;
      const Float falloff = half_lambert / dist2;
      for (int c = 0; c < 3; ++c) rgb[c] = rgb[c] + Float(light.color[i][c]) * falloff;
    }
    out.color = {albedo.x * Float(factor.r) * rgb[0], albedo.y * Float(factor.g) * rgb[1],
                 albedo.z * Float(factor.b) * rgb[2], Float(1.0f)};
  }
};

struct Draw {
  rasterizer::Geometry geometry;
  rasterizer::PipelineState state;
  W3Vertex vertex;
  W3Pixel pixel;
};

rasterizer::Geometry geometry_of(const scenes::Mesh& m) {
  const auto vertices = static_cast<uint32_t>(m.vertex_count());
  if (!m.indexed()) return rasterizer::Geometry::non_indexed(vertices);
  if (const auto* i16 = std::get_if<std::vector<uint16_t>>(&m.indices))
    return rasterizer::Geometry::indexed(std::span(*i16), vertices);
  return rasterizer::Geometry::indexed(std::span(std::get<std::vector<uint32_t>>(m.indices)), vertices);
}

/// The texture as the peer uploads it: RGBA8 without sRGB decoding, a full mip chain, always
/// trilinear; only the wrap modes come from the glTF sampler.
frame::GpuTexture upload_as_w3(const scenes::Texture& t) { return frame::upload(sponza_texture(t)); }

}  // namespace

struct SponzaFrame::State {
  rasterizer::ColorTarget color;
  rasterizer::DepthStencilTarget depth;
  std::vector<frame::GpuTexture> textures;
  frame::GpuTexture white = frame::white_texture();
  std::vector<Draw> draws;
  rasterizer::Image image;
  uint64_t triangles = 0;

  State(int width, int height, int samples) : color(width, height, samples), depth(width, height, samples) {}
};

namespace {

int checked_samples(int width, int height, int samples) {
  if (width < 1 || height < 1 || width > rasterizer::kMaxTargetSize || height > rasterizer::kMaxTargetSize)
    throw std::invalid_argument("image size " + std::to_string(width) + "x" + std::to_string(height) + " is outside 1.." +
                                std::to_string(rasterizer::kMaxTargetSize));
  if (!rasterizer::is_valid_sample_count(samples))
    throw std::invalid_argument("msaa " + std::to_string(samples) + " is not 1, 2, 4 or 8");
  return samples;
}

}  // namespace

SponzaFrame::SponzaFrame(const scenes::Scene& scene, const SponzaView& view, int width, int height, int samples)
    : state_(std::make_unique<State>(width, height, checked_samples(width, height, samples))) {
  scenes::validate(scene);
  State& st = *state_;
  const glm::mat4 view_projection = frame::view_projection(sponza_camera(view), width, height);

  st.textures.reserve(scene.textures.size());
  for (const scenes::Texture& t : scene.textures) st.textures.push_back(upload_as_w3(t));
  const SponzaLighting lighting = sponza_lighting();
  const scenes::Material untextured;  // white, factor 1, single-sided: the peer's default material
  for (const scenes::Mesh& mesh : scene.meshes) {
    const scenes::Material& m = mesh.material >= 0 ? scene.materials[mesh.material] : untextured;
    Draw d;
    d.geometry = geometry_of(mesh);
    d.state.depth_stencil.depth_func = rasterizer::CompareFunc::Less;
    d.state.rasterizer.front_counter_clockwise = true;
    d.state.rasterizer.cull = m.double_sided ? rasterizer::CullMode::None : rasterizer::CullMode::CW;
    const std::vector<glm::vec2>& uvs = m.base.uv_set == 1 ? mesh.uv1 : mesh.uv0;
    d.vertex = W3Vertex{mesh.positions.data(), mesh.normals.empty() ? nullptr : mesh.normals.data(),
                        uvs.empty() ? nullptr : uvs.data(), view_projection};
    const frame::GpuTexture& t = m.base.bound() ? st.textures[m.base.texture] : st.white;
    d.pixel = W3Pixel{&t.texture, &t.sampler, m.color, lighting};
    st.triangles += d.geometry.triangle_count();
    st.draws.push_back(d);
  }
}

SponzaFrame::~SponzaFrame() = default;
SponzaFrame::SponzaFrame(SponzaFrame&&) noexcept = default;
SponzaFrame& SponzaFrame::operator=(SponzaFrame&&) noexcept = default;

void SponzaFrame::render(rasterizer::Context& ctx) {
  State& st = *state_;
  // Cleared whole and discarded once resolved, as the peer's frame may (its depth is never read):
  // the samples live in tile memory (rasterizer/framebuffer.hpp).
  clear_color(ctx, st.color, kSponzaClear);
  clear_depth_stencil(ctx, st.depth, 1.0f, 0);
  const rasterizer::Framebuffer fb{&st.color, &st.depth};
  for (const Draw& d : st.draws) rasterizer::draw(ctx, fb, d.state, d.geometry, d.vertex, d.pixel);
  discard(ctx, st.color);
  discard(ctx, st.depth);
  resolve_into(ctx, st.color, st.image);
}

const rasterizer::Image& SponzaFrame::image() const { return state_->image; }
uint64_t SponzaFrame::triangles() const { return state_->triangles; }

}  // namespace luxel::bench
