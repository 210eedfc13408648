#include "luxel/frame/renderer.hpp"

#include "plain_shaders.hpp"

#include "luxel/frame/textures.hpp"
#include "luxel/rasterizer/framebuffer.hpp"
#include "luxel/rasterizer/msaa.hpp"
#include "luxel/rasterizer/srgb.hpp"
#include "luxel/scenes/camera_path.hpp"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_double4x4.hpp>
#include <glm/ext/vector_double3.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace luxel::frame {

using namespace rasterizer;

scenes::Camera frame_camera(const scenes::Scene& scene, const FrameSettings& settings) {
  if (settings.path_time) return scenes::camera_at(scene.camera_path, *settings.path_time);
  if (settings.camera < 0 || settings.camera >= static_cast<int>(scene.cameras.size()))
    throw std::invalid_argument((scene.name.empty() ? std::string("scene") : scene.name) + " has no camera " +
                                std::to_string(settings.camera) + " (it has " + std::to_string(scene.cameras.size()) +
                                ")");
  return scene.cameras[settings.camera];
}

namespace {

/// The view-projection matrix in double (renderer.hpp: rounded once, at the end).
glm::dmat4 view_projection_d(const scenes::Camera& c, int width, int height) {
  const glm::dvec3 eye(c.position), target(c.target);
  glm::dvec3 up(c.up);
  // An up along the line of sight (looking straight down with +Z up) has no screen direction:
  // screen up is then +Y.
  const glm::dvec3 forward = glm::normalize(target - eye);
  if (glm::length(glm::cross(forward, glm::normalize(up))) < 1e-6) up = glm::dvec3(0, 1, 0);
  const glm::dmat4 view = glm::lookAtRH(eye, target, up);
  const double n = c.near_plane, f = c.far_plane;
  glm::dmat4 projection;
  if (c.projection == scenes::Projection::orthographic) {
    const double half_h = 0.5 * c.ortho_height;
    // (h W) / H is exact for integer h, W, H whose quotient is: the workloads' cameras.
    const double half_w = 0.5 * (c.aspect > 0 ? double(c.ortho_height) * c.aspect : double(c.ortho_height) * width / height);
    projection = glm::orthoRH_ZO(-half_w, half_w, -half_h, half_h, n, f);
  } else {
    const double aspect = c.aspect > 0 ? double(c.aspect) : double(width) / height;
    projection = glm::perspectiveRH_ZO(double(c.vertical_fov), aspect, n, f);
  }
  return projection * view;
}

}  // namespace

glm::mat4 view_projection(const scenes::Camera& c, int width, int height) {
  return glm::mat4(view_projection_d(c, width, height));
}

namespace {

/// One mesh, ready to draw: its geometry, its shader's constants and its state.
struct Draw {
  Geometry geometry;
  PipelineState state;
  std::variant<UnlitVertex, PlainVertex> vertex;
  PlainPixel pixel{};  // PlainVertex draws only
};

Geometry geometry_of(const scenes::Mesh& m) {
  const auto vertices = static_cast<uint32_t>(m.vertex_count());
  if (!m.indexed()) return Geometry::non_indexed(vertices);
  if (const auto* i16 = std::get_if<std::vector<uint16_t>>(&m.indices)) return Geometry::indexed(std::span(*i16), vertices);
  return Geometry::indexed(std::span(std::get<std::vector<uint32_t>>(m.indices)), vertices);
}

template <class T>
const T* data_or_null(const std::vector<T>& v) {
  return v.empty() ? nullptr : v.data();
}

bool lit(scenes::ShaderFamily f) { return f != scenes::ShaderFamily::unlit_generic && f != scenes::ShaderFamily::sky; }

/// The demo's light, with Source's axes: a sun from the upper left, plus a sky-blue ambient that
/// is brighter facing up.
PlainLight plain_sun() {
  PlainLight l;
  l.ambient = {0.12f, 0.14f, 0.18f};
  l.ambient_up = {0.10f, 0.13f, 0.20f};
  l.sun = {1.1f, 1.0f, 0.85f};
  l.to_sun = {-0.45f, -0.4f, 0.8f};
  return l;
}

}  // namespace

struct Renderer::State {
  const scenes::Scene* scene;
  ColorTarget color;
  DepthStencilTarget depth;
  glm::vec4 clear;
  std::vector<GpuTexture> textures;
  GpuTexture white = white_texture();
  std::vector<Draw> draws;
  std::optional<SkyVertex> sky;  // when the scene has a sky cube
  Image image;
  DrawStats stats;
  std::vector<ShaderUse> shader_uses;

  State(const scenes::Scene& s, const FrameSettings& f)
      : scene(&s), color(f.width, f.height, f.samples), depth(f.width, f.height, f.samples) {}
};

namespace {

void check_settings(const FrameSettings& s) {
  if (s.width < 1 || s.height < 1 || s.width > kMaxTargetSize || s.height > kMaxTargetSize)
    throw std::invalid_argument("image size " + std::to_string(s.width) + "x" + std::to_string(s.height) +
                                " is outside 1.." + std::to_string(kMaxTargetSize));
  if (!is_valid_sample_count(s.samples))
    throw std::invalid_argument("msaa " + std::to_string(s.samples) + " is not 1, 2, 4 or 8");
  if (!shading::caps(s.model).pixel)
    throw std::invalid_argument("shader model " + std::string(shading::caps(s.model).name) + " is not a pixel-shader model");
}

const FrameSettings& checked(const scenes::Scene& scene, const FrameSettings& s) {
  check_settings(s);
  scenes::validate(scene);
  return s;
}

}  // namespace

Renderer::Renderer(const scenes::Scene& scene, const FrameSettings& settings)
    : state_(std::make_unique<State>(scene, checked(scene, settings))) {
  State& st = *state_;
  const scenes::Camera camera = frame_camera(scene, settings);
  const glm::dmat4 vp_d = view_projection_d(camera, settings.width, settings.height);
  const glm::mat4 vp(vp_d);
  st.clear = glm::vec4(float(linear_to_srgb(std::clamp(scene.background.r, 0.0f, 1.0f))),
                       float(linear_to_srgb(std::clamp(scene.background.g, 0.0f, 1.0f))),
                       float(linear_to_srgb(std::clamp(scene.background.b, 0.0f, 1.0f))), 1.0f);
  st.textures.reserve(scene.textures.size());
  for (const scenes::Texture& t : scene.textures) st.textures.push_back(upload(t));

  const scenes::Material default_material;
  for (const scenes::Mesh& mesh : scene.meshes) {
    const scenes::Material& m = mesh.material >= 0 ? scene.materials[mesh.material] : default_material;
    Draw d;
    d.geometry = geometry_of(mesh);
    d.state.depth_stencil.depth_func = CompareFunc::Less;
    d.state.rasterizer.front_counter_clockwise = true;
    d.state.rasterizer.cull = m.double_sided ? CullMode::None : CullMode::CW;
    d.state.blend.srgb_write = !m.linear_write;
    if (!lit(m.family) && !m.base.bound()) {
      d.vertex = UnlitVertex{mesh.positions.data(), data_or_null(mesh.colors), m.color, vp};
    } else {
      PlainVertex v{};
      v.positions = mesh.positions.data();
      v.normals = data_or_null(mesh.normals);
      v.uvs = data_or_null(m.base.uv_set == 1 ? mesh.uv1 : mesh.uv0);
      v.colors = data_or_null(mesh.colors);
      v.color = m.color;
      v.uv_transform = scenes::UvTransform::of(m.base);
      v.view_projection = vp;
      d.vertex = v;
      const GpuTexture& t = m.base.bound() ? st.textures[m.base.texture] : st.white;
      d.pixel = PlainPixel{&t.texture, &t.sampler, lit(m.family) ? plain_sun() : PlainLight{}};
    }
    st.draws.push_back(d);
  }
  if (scene.sky_texture >= 0 && scene.textures[scene.sky_texture].shape == scenes::TextureShape::cube) {
    const glm::dmat4 inverse = glm::inverse(vp_d);
    SkyVertex sky{};
    const glm::vec2 corners[3] = {{-1, -1}, {3, -1}, {-1, 3}};
    for (int i = 0; i < 3; ++i) {
      const glm::dvec4 near_point = inverse * glm::dvec4(corners[i].x, corners[i].y, 0, 1);
      const glm::dvec4 far_point = inverse * glm::dvec4(corners[i].x, corners[i].y, 1, 1);
      sky.clip[i] = glm::vec4(corners[i], 1, 1);
      sky.direction[i] = glm::vec4(glm::vec3(glm::dvec3(far_point) / far_point.w - glm::dvec3(near_point) / near_point.w), 0);
    }
    st.sky = sky;
  }
}

Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

void Renderer::render(Context& ctx) {
  State& st = *state_;
  ctx.reset_stats();
  clear_color(ctx, st.color, st.clear);
  clear_depth(ctx, st.depth, 1.0f);  // as the peer: stencil neither cleared nor used
  const Framebuffer fb{&st.color, &st.depth};
  for (const Draw& d : st.draws) {
    if (const auto* unlit = std::get_if<UnlitVertex>(&d.vertex))
      draw(ctx, fb, d.state, d.geometry, *unlit, UnlitPixel{});
    else
      draw(ctx, fb, d.state, d.geometry, std::get<PlainVertex>(d.vertex), d.pixel);
  }
  if (st.sky) {
    // Last, where nothing else was drawn: depth is still the clear's 1, the sky's too.
    PipelineState state;
    state.rasterizer.cull = CullMode::None;
    state.depth_stencil.depth_func = CompareFunc::LessEqual;
    state.depth_stencil.depth_write = false;
    state.blend.srgb_write = true;
    const GpuTexture& cube = st.textures[st.scene->sky_texture];
    draw(ctx, fb, state, Geometry::non_indexed(3), *st.sky, SkyPixel{&cube.texture, &cube.sampler});
  }
  resolve_into(ctx, st.color, st.image);
  st.stats = ctx.stats();
}

const Image& Renderer::image() const { return state_->image; }
const DrawStats& Renderer::stats() const { return state_->stats; }
const std::vector<ShaderUse>& Renderer::shader_uses() const { return state_->shader_uses; }

}  // namespace luxel::frame
