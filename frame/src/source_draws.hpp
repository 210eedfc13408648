#pragma once
// Private: one draw of a Source shader, ready to run: the family's combo chosen, its pixel
// functor built through the shading adapter (shading/source/adapter.hpp), its vertex stage
// (source_vertex.hpp) told which attributes to write.
//
// Each family compiles the combos the frame can choose (drawn_combos.hpp, a part of the
// registry's space) in its own source file (with make_source_draw.hpp), so the families compile in
// parallel; their slots are the registry's counts. A combo outside them is a frame bug
// (std::logic_error), never a silent substitute. This header declares the draws and parses none
// of the draw implementation, so the files that only choose, hold and run draws stay light.

#include "source_vertex.hpp"

#include "luxel/rasterizer/context.hpp"
#include "luxel/rasterizer/draw.hpp"
#include "luxel/rasterizer/framebuffer.hpp"
#include "luxel/rasterizer/state.hpp"
#include "luxel/shading/shader_model.hpp"
#include "luxel/shading/source/adapter.hpp"

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace luxel::frame {

/// A draw with its shader, and what it reports (Renderer::shader_uses).
struct SourceDraw {
  std::string family;  ///< the catalog's family name
  std::string combo;   ///< the combo's name
  shading::ShaderModel binary = shading::ShaderModel::ps_2_0;  ///< the SDK binary the frame's card runs (binaries.hpp)
  int slots = 0;       ///< that binary's counted DX9 slots per pixel
  std::unique_ptr<std::atomic<uint64_t>> pixels = std::make_unique<std::atomic<uint64_t>>(0);
  rasterizer::PipelineState state;  ///< the draw's own (DrawTarget::state)
  /// Draws with `state`, or with another: Renderer::render_float's, unblended and linear, into a
  /// float target.
  std::function<void(rasterizer::Context&, const rasterizer::Framebuffer&, const rasterizer::PipelineState&)> draw;

  void run(rasterizer::Context& ctx, const rasterizer::Framebuffer& fb) const { draw(ctx, fb, state); }
};

/// Where a draw goes: its state, its triangles, its vertex stage (whose attribute list the
/// family functions fill in for the combo).
struct DrawTarget {
  rasterizer::PipelineState state;
  rasterizer::Geometry geometry;
  VertexSetup* vertex = nullptr;
  bool count_pixels = false;
  /// The world families' height-fog combos write the fog factor to alpha (adapter.hpp): the
  /// refraction view's opaque draws (water_passes.hpp).
  bool water_fog_to_alpha = false;
};

SourceDraw lightmapped_draw(const shading::source::LightmappedCombo& combo, shading::ShaderModel model,
                            const DrawTarget& target, const shading::source::LightmappedGenericParams& params,
                            const shading::source::LightmapPage& page, const glm::vec3& eye);

/// `wanted` if it exists on `model`, else the same with the SDK's per-vertex attenuation (what
/// ps_2_0's budget forces), else nothing.
std::optional<shading::source::VertexLitCombo> fitting_vertexlit_combo(shading::source::VertexLitCombo wanted,
                                                                       shading::ShaderModel model);
SourceDraw vertexlit_draw(const shading::source::VertexLitCombo& combo, shading::ShaderModel model,
                          const DrawTarget& target, const shading::source::VertexLitParams& params);

SourceDraw unlit_draw(const shading::source::UnlitCombo& combo, shading::ShaderModel model, const DrawTarget& target,
                      const shading::source::UnlitGenericParams& params, const glm::vec3& eye);

SourceDraw sky_draw(shading::ShaderModel model, const DrawTarget& target, const shading::source::SkyParams& params);

SourceDraw water_draw(const shading::source::WaterCombo& combo, shading::ShaderModel model, const DrawTarget& target,
                      const shading::source::WaterParams& params,
                      const shading::source::WaterVertexConstants& constants, const glm::vec3& eye);

}  // namespace luxel::frame
