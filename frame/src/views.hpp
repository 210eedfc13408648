#pragma once
// Private: a view of the scene as the frame draws it. The camera's view is one; the water's
// reflection and refraction views (water_passes.hpp) are others, drawn with the same shaders
// from another eye, through another projection, at another exposure or with another fog. Each
// view's draws are a PassList; renderer.cpp builds them (FrameBuilder) from a ViewSpec.

#include "source_draws.hpp"
#include "trivial_unlit.hpp"

#include "luxel/frame/renderer.hpp"
#include "luxel/rasterizer/context.hpp"
#include "luxel/rasterizer/draw.hpp"
#include "luxel/rasterizer/framebuffer.hpp"
#include "luxel/scenes/scene.hpp"
#include "luxel/shading/source/fog.hpp"

#include <glm/ext/matrix_double4x4.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace luxel::frame {

/// A camera's view and projection matrices, in double (renderer.hpp: rounded once, at the end).
struct ViewMatrices {
  glm::dmat4 view{1.0};
  glm::dmat4 projection{1.0};
};
ViewMatrices view_matrices(const scenes::Camera& camera, int width, int height);

/// One draw: the trivial functor of the peer workloads' materials, or a Source shader.
struct Pass {
  std::optional<UnlitVertex> trivial;
  std::optional<SourceDraw> source;
  rasterizer::PipelineState state;
  rasterizer::Geometry geometry;
};

/// A view's draws in the order renderer.hpp gives: opaque meshes in scene order, then the sky,
/// then translucent meshes back to front.
struct PassList {
  std::vector<Pass> opaque, sky, translucent;
};

/// How one view of the scene is drawn.
struct ViewSpec {
  glm::vec3 eye{0.0f};          ///< where the shaders see the eye (fog, env maps, specular, sorting)
  glm::mat4 view_projection{1.0f};
  /// Set when the projection's near plane is oblique (a clip plane, water_passes.hpp): the z row of
  /// the view's ordinary projection, so that fog still reads the distance along the view axis.
  std::optional<glm::vec4> proj_z_row;
  float far_plane = 1.0f;
  float exposure = 1.0f;        ///< the tone-map scale
  bool mirrored = false;        ///< the view mirrors the world: front faces turn clockwise on screen
  /// World plane (n, d), n·p + d >= 0 kept: meshes wholly on the other side are not drawn.
  std::optional<glm::vec4> keep;
  /// Set: the water's height fog instead of the scene's fog, and opaque materials write its
  /// factor to destination alpha (the refraction view, water_passes.hpp).
  std::optional<shading::source::FogSettings> water_fog;
  /// The pixels drawn (the water's views: only what the water can read): inside `scissor`, and
  /// with `masked`, only where the view's stencil holds kDrawnStencil (the water's footprint,
  /// which water_passes.cpp writes there before the view's draws).
  rasterizer::Scissor scissor;
  bool masked = false;
  bool sky = true;              ///< the sky cube
  bool water = true;            ///< water meshes (the water's own views never draw water)
};

/// The stencil value of the pixels a masked view draws (ViewSpec::masked).
inline constexpr uint8_t kDrawnStencil = 1;

/// Builds a view's draws.
using BuildView = std::function<void(const ViewSpec&, PassList&)>;

/// Times a frame's passes (FrameSettings::time_passes) into `times`: a timed pass runs to its end
/// (the context flushed) before its clock stops. Without `times`, passes just run.
class PassClock {
 public:
  PassClock(rasterizer::Context& ctx, std::vector<PassTime>* times) : ctx_(ctx), times_(times) {}

  template <class Run>
  void run(const char* pass, int draws, Run&& run) {
    if (!times_) return run();
    const auto start = std::chrono::steady_clock::now();
    run();
    ctx_.flush();
    times_->push_back({pass, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count(), draws});
  }

 private:
  rasterizer::Context& ctx_;
  std::vector<PassTime>* times_;
};

/// The draws of `passes`.
int draw_count(const PassList& passes);

/// Runs every draw of `passes` into `fb`, in order; with a clock, each non-empty list (opaque, sky,
/// translucent) is one timed pass.
void run_passes(rasterizer::Context& ctx, const rasterizer::Framebuffer& fb, PassList& passes, PassClock* clock = nullptr);

/// Adds what the Source draws of `passes` shaded to `uses`: one entry per combo, in order of
/// first use.
void add_shader_uses(const PassList& passes, std::vector<ShaderUse>& uses);

}  // namespace luxel::frame
