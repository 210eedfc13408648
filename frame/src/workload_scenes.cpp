// W1 `fill` and W2 `tris`, rendered as ../shared/peers/llvmpipe defines them.

#include "luxel/frame/builtin.hpp"
#include "workload_scenes.hpp"

#include "luxel/scenes/workloads.hpp"

namespace luxel::frame {

using namespace rasterizer;
using simd::Float;

namespace {

/// OpenGL NDC depth [-1, 1] to Direct3D [0, 1].
constexpr float d3d_depth(float gl_ndc_z) { return 0.5f * gl_ndc_z + 0.5f; }

class FillScene final : public BuiltinScene {
 public:
  explicit FillScene(const FrameSettings& s)
      : workload_(scenes::make_fill_workload()), color_(s.width, s.height, s.samples),
        depth_(s.width, s.height, s.samples) {
    state_.rasterizer.cull = CullMode::None;
    state_.depth_stencil.depth_func = CompareFunc::Less;
  }

  struct Vertex {
    static constexpr int kVaryings = 1;
    const scenes::FillWorkload::Vertex* vertices;
    float z;
    void operator()(uint32_t i, VertexOutput<1>& out) const {
      out.position = {vertices[i].ndc.x, vertices[i].ndc.y, z, 1.0f};
      out.varyings[0] = {vertices[i].uv.x, vertices[i].uv.y, 0.0f, 0.0f};
    }
  };
  struct Pixel {
    static constexpr bool kCanDiscard = false, kWritesDepth = false, kTrivial = true;
    glm::vec3 color;
    void operator()(const PixelInput<1>& in, PixelOutput& out) const {
      const Float ramp = Float(0.9f) + Float(0.1f) * in.varyings[0].x;
      out.color = {Float(color.r) * ramp, Float(color.g) * ramp, Float(color.b) * ramp, Float(1.0f)};
    }
  };

  void render(Context& ctx) override {
    ctx.reset_stats();
    clear_color(ctx, color_, {0, 0, 0, 1});
    clear_depth(ctx, depth_, 1.0f);  // as the peer: stencil neither cleared nor used
    const Framebuffer fb{&color_, &depth_};
    const Geometry geometry = Geometry::indexed(std::span<const uint16_t>(workload_.indices),
                                                static_cast<uint32_t>(workload_.vertices.size()));
    for (int k = 0; k < scenes::FillWorkload::kLayers; ++k) {
      draw(ctx, fb, state_, geometry, Vertex{workload_.vertices.data(), d3d_depth(workload_.layer_ndc_z[k])},
                     Pixel{workload_.layer_color[k]});
    }
    resolve_into(ctx, color_, image_);
    stats_ = ctx.stats();
  }

 private:
  scenes::FillWorkload workload_;
  ColorTarget color_;
  DepthStencilTarget depth_;
  PipelineState state_;
};

class TrisScene final : public BuiltinScene {
 public:
  explicit TrisScene(const FrameSettings& s)
      : workload_(scenes::make_tris_workload(s.width, s.height)), color_(s.width, s.height, s.samples),
        depth_(s.width, s.height, s.samples), width_(s.width), height_(s.height) {
    state_.rasterizer.cull = CullMode::None;
    state_.depth_stencil.depth_func = CompareFunc::Less;
  }

  struct Vertex {
    static constexpr int kVaryings = 1;
    const scenes::TrisWorkload::Vertex* vertices;
    float scale_x, scale_y;
    const void* input(uint32_t i) const { return &vertices[i]; }
    void operator()(uint32_t i, VertexOutput<1>& out) const {
      const scenes::TrisWorkload::Vertex& v = vertices[i];
      out.position = {v.x * scale_x - 1.0f, v.y * scale_y - 1.0f, d3d_depth(v.z), 1.0f};
      out.varyings[0] = unpack_rgba8(v.rgba);
    }
  };
  struct Pixel {
    static constexpr bool kCanDiscard = false, kWritesDepth = false, kTrivial = true;
    void operator()(const PixelInput<1>& in, PixelOutput& out) const { out.color = in.varyings[0]; }
  };

  void render(Context& ctx) override {
    ctx.reset_stats();
    clear_color(ctx, color_, {0.1f, 0.1f, 0.1f, 1.0f});
    clear_depth(ctx, depth_, 1.0f);  // as the peer: stencil neither cleared nor used
    const Framebuffer fb{&color_, &depth_};
    draw(ctx, fb, state_, Geometry::non_indexed(static_cast<uint32_t>(workload_.vertices.size())),
                  Vertex{workload_.vertices.data(), 2.0f / width_, 2.0f / height_}, Pixel{});
    resolve_into(ctx, color_, image_);
    stats_ = ctx.stats();
  }

 private:
  scenes::TrisWorkload workload_;
  ColorTarget color_;
  DepthStencilTarget depth_;
  PipelineState state_;
  int width_, height_;
};

}  // namespace

std::unique_ptr<BuiltinScene> make_fill_scene(const FrameSettings& s) { return std::make_unique<FillScene>(s); }
std::unique_ptr<BuiltinScene> make_tris_scene(const FrameSettings& s) { return std::make_unique<TrisScene>(s); }

}  // namespace luxel::frame
