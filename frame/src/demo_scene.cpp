// `demo`: a small depth-tested, textured, perspective scene that needs no files: a checkered
// ground plane running to the horizon (mip-mapped, trilinear: no shimmer in the distance) and a
// ring of lit, textured cubes, under a sky gradient.

#include "luxel/frame/builtin.hpp"
#include "workload_scenes.hpp"

#include "luxel/rasterizer/texture.hpp"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <cmath>
#include <numbers>
#include <vector>

namespace luxel::frame {

using namespace rasterizer;
using simd::Float;

namespace {

struct MeshVertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 uv;
};

struct Mesh {
  std::vector<MeshVertex> vertices;
  std::vector<uint32_t> indices;

  /// A quad from four corners listed counter-clockwise seen from the side the normal points to.
  void add_quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 n, float uv_scale) {
    const uint32_t base = static_cast<uint32_t>(vertices.size());
    vertices.push_back({a, n, {0, uv_scale}});
    vertices.push_back({b, n, {uv_scale, uv_scale}});
    vertices.push_back({c, n, {uv_scale, 0}});
    vertices.push_back({d, n, {0, 0}});
    indices.insert(indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }

  void add_cube(const glm::mat4& model) {
    static const glm::vec3 kNormals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const glm::vec3& n : kNormals) {
      // Two axes spanning the face, so that (u, v, n) is right-handed.
      const glm::vec3 u = std::abs(n.y) > 0.5f ? glm::vec3(1, 0, 0) : glm::normalize(glm::cross(glm::vec3(0, 1, 0), n));
      const glm::vec3 v = glm::cross(n, u);
      auto world = [&](glm::vec3 p) { return glm::vec3(model * glm::vec4(p, 1)); };
      const glm::vec3 wn = glm::normalize(glm::vec3(model * glm::vec4(n, 0)));
      add_quad(world(n - u - v), world(n + u - v), world(n + u + v), world(n - u + v), wn, 1.0f);
    }
  }
};

/// A procedural sRGB texture with its mip chain: `pattern(x, y)` gives the linear color.
template <class Pattern>
Texture make_texture(int size, Pattern pattern) {
  Texture texture = Texture::create_2d(size, size, TextureFormat::RGBA8_sRGB);
  std::vector<glm::vec4> texels(static_cast<size_t>(size) * size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) texels[static_cast<size_t>(y) * size + x] = pattern(x, y);
  texture.upload(0, texels);
  texture.generate_mips();
  return texture;
}

class DemoScene final : public BuiltinScene {
 public:
  explicit DemoScene(const FrameSettings& s)
      : color_(s.width, s.height, s.samples), depth_(s.width, s.height, s.samples), aspect_(float(s.width) / s.height) {
    // Ground: 200 x 200 units, the checker repeating every 2 units.
    ground_.add_quad({-100, 0, 100}, {100, 0, 100}, {100, 0, -100}, {-100, 0, -100}, {0, 1, 0}, 100.0f);
    for (int i = 0; i < 7; ++i) {
      const float a = 2.0f * std::numbers::pi_v<float> * i / 7;
      glm::mat4 m = glm::translate(glm::mat4(1), {5.0f * std::cos(a), 0.9f + 0.25f * (i % 3), 5.0f * std::sin(a) - 2.0f});
      m = glm::rotate(m, 0.7f * i + 0.3f, glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f * i)));
      cubes_.add_cube(glm::scale(m, glm::vec3(0.8f)));
    }
    checker_ = make_texture(256, [](int x, int y) {
      const bool dark = ((x / 128) + (y / 128)) % 2;
      return dark ? glm::vec4(0.08f, 0.09f, 0.11f, 1) : glm::vec4(0.75f, 0.72f, 0.66f, 1);
    });
    bricks_ = make_texture(128, [](int x, int y) {
      const int row = y / 16, offset = (row % 2) * 16;
      const bool mortar = y % 16 < 2 || (x + offset) % 32 < 2;
      const float shade = 0.8f + 0.2f * float((x * 7 + y * 13) % 17) / 16.0f;
      return mortar ? glm::vec4(0.55f, 0.55f, 0.5f, 1) : glm::vec4(0.45f * shade, 0.12f * shade, 0.07f * shade, 1);
    });
    sampler_.u = sampler_.v = Address::Wrap;
    // OpenGL-style content: front faces are counter-clockwise on screen, so cull clockwise ones.
    state_.rasterizer.front_counter_clockwise = true;
    state_.rasterizer.cull = CullMode::CW;
    state_.blend.srgb_write = true;
  }

  struct Vertex {
    static constexpr int kVaryings = 2;  // uv, world normal
    const MeshVertex* vertices;
    glm::mat4 view_projection;
    void operator()(uint32_t i, VertexOutput<2>& out) const {
      const MeshVertex& v = vertices[i];
      out.position = view_projection * glm::vec4(v.position, 1);
      out.varyings[0] = {v.uv, 0, 0};
      out.varyings[1] = {v.normal, 0};
    }
  };

  struct Pixel {
    static constexpr bool kCanDiscard = false, kWritesDepth = false;
    const Texture* texture;
    const Sampler* sampler;
    void operator()(const PixelInput<2>& in, PixelOutput& out) const {
      const simd::Float4 albedo = sample(*texture, *sampler, {in.varyings[0].x, in.varyings[0].y, Float(0.0f)});
      const simd::Float4& n = in.varyings[1];
      const Float inv_len = Float(1.0f) / xsimd::sqrt(n.x * n.x + n.y * n.y + n.z * n.z + Float(1e-20f));
      // Sun from the upper left, plus a sky-blue ambient that is brighter facing up.
      const Float ndotl = xsimd::max(Float(0.0f), (n.x * Float(-0.45f) + n.y * Float(0.8f) + n.z * Float(0.4f)) * inv_len);
      const Float up = Float(0.5f) + Float(0.5f) * n.y * inv_len;
      const Float r = Float(0.12f) + Float(0.10f) * up + Float(1.1f) * ndotl;
      const Float g = Float(0.14f) + Float(0.13f) * up + Float(1.0f) * ndotl;
      const Float b = Float(0.18f) + Float(0.20f) * up + Float(0.85f) * ndotl;
      out.color = {albedo.x * r, albedo.y * g, albedo.z * b, Float(1.0f)};
    }
  };

  void render(Context& ctx) override {
    ctx.reset_stats();
    clear_color(ctx, color_, {0.42f, 0.55f, 0.75f, 1.0f});
    clear_depth_stencil(ctx, depth_, 1.0f, 0);
    const glm::mat4 view = glm::lookAtRH(glm::vec3(0, 3.2f, 9), glm::vec3(0, 0.6f, -2), glm::vec3(0, 1, 0));
    const glm::mat4 projection = glm::perspectiveRH_ZO(glm::radians(55.0f), aspect_, 0.1f, 300.0f);
    const glm::mat4 vp = projection * view;
    const Framebuffer fb{&color_, &depth_};
    for (const auto& [mesh, texture] : {std::pair{&ground_, &checker_}, std::pair{&cubes_, &bricks_}}) {
      draw(ctx, fb, state_,
           Geometry::indexed(std::span<const uint32_t>(mesh->indices), static_cast<uint32_t>(mesh->vertices.size())),
           Vertex{mesh->vertices.data(), vp}, Pixel{texture, &sampler_});
    }
    resolve_into(ctx, color_, image_);
    stats_ = ctx.stats();
  }

 private:
  ColorTarget color_;
  DepthStencilTarget depth_;
  float aspect_;
  Mesh ground_, cubes_;
  Texture checker_ = Texture::create_2d(1, 1, TextureFormat::RGBA8);
  Texture bricks_ = Texture::create_2d(1, 1, TextureFormat::RGBA8);
  Sampler sampler_;
  PipelineState state_;
};

}  // namespace

std::unique_ptr<BuiltinScene> make_demo_scene(const FrameSettings& s) { return std::make_unique<DemoScene>(s); }

}  // namespace luxel::frame
