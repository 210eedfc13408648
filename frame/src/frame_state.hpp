#pragma once
// What a prepared frame holds between its renders (Renderer::State is this): the scene and
// settings, the targets, the textures and per-mesh data the draws point at, the views' draws, the
// clock and what moves with it, the exposure and the post passes' state. renderer.cpp runs the
// frame over it; frame_builder.cpp fills its views' draws.

#include "color_correction_nodes.hpp"
#include "model_lighting.hpp"
#include "source_vertex.hpp"
#include "views.hpp"
#include "water_passes.hpp"

#include "luxel/frame/renderer.hpp"
#include "luxel/frame/textures.hpp"
#include "luxel/frame/world_envmaps.hpp"
#include "luxel/postfx/bloom_amount.hpp"
#include "luxel/postfx/full_frame.hpp"
#include "luxel/rasterizer/framebuffer.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace luxel::frame {

/// Everything a prepared frame holds (FrameState is this).
struct FrameState {
  const scenes::Scene* scene;
  FrameSettings settings;
  rasterizer::ColorTarget color;
  rasterizer::DepthStencilTarget depth;
  glm::vec4 clear;
  std::shared_ptr<const SceneTextures> prepared;  // possibly shared with other renderers of the scene
  const std::vector<GpuTexture>& textures = prepared->textures;
  GpuTexture white = white_texture();
  GpuTexture flat_normal = flat_normal_texture();
  const std::optional<GpuTexture>& lightmaps = prepared->lightmaps;
  const shading::source::LightmapPage& page = prepared->page;
  std::optional<GpuTexture> normalization_cube;
  std::vector<GpuTexture> sky_faces;
  std::vector<std::unique_ptr<scenes::Mesh>> completed_meshes;  // per mesh: given the tangents the frame needed
  std::vector<std::unique_ptr<std::vector<EnvmapFaceGroup>>> envmap_groups;  // per world mesh reflecting samples
  std::vector<std::unique_ptr<VertexSetup>> vertex_setups;
  struct SkyQuads {
    glm::vec3 positions[24];
    glm::vec2 uvs[24];
  };
  std::vector<std::unique_ptr<SkyQuads>> sky_quads;  // per view
  std::optional<WaterPasses> water;
  struct WaterTargets {
    explicit WaterTargets(int side) : color(side, side, 1), depth(side, side, 1) {}
    rasterizer::ColorTarget color;
    rasterizer::DepthStencilTarget depth;
  };
  std::optional<WaterTargets> water_targets;  ///< the water's views', made at the first frame with water
  std::optional<rasterizer::ColorTarget> float_color;     ///< render_float's (rgba32f), made at its first frame
  PassList passes;                                   // the camera's view
  rasterizer::Image image;
  rasterizer::DrawStats stats;
  std::vector<ShaderUse> shader_uses;
  std::vector<PassTime> pass_times;
  // The scene's clock (renderer.hpp) and what moves with it, per Scene::models entry.
  std::vector<glm::vec3> model_offsets;
  std::vector<AveragedLighting> model_lighting;
  std::vector<ModelLightingState> model_states;
  bool views_current = false;
  // The exposure (renderer.hpp): the scale the views are drawn with, the auto exposure that moves
  // it, and the clock at the last frame rendered (the next frame's duration).
  float exposure = 1.0f;
  std::optional<postfx::AutoExposure> auto_exposure;
  std::optional<float> start_exposure;  // where auto exposure starts when not at its initial scale
  std::optional<float> last_frame_time;
  std::optional<ColorCorrectionNodes> color_correction;  // when the frame blends the scene's nodes
  std::optional<postfx::Bloom> bloom;
  postfx::BloomAmount bloom_amount;                      // smoothed from frame to frame
  std::optional<postfx::FilmGrain> film_grain;
  postfx::FullFrameTexture full_frame;  // _rt_FullFrameFB: the frame's one copy for the post passes

  FrameState(const scenes::Scene& s, const FrameSettings& f, std::shared_ptr<const SceneTextures> t)
      : scene(&s), settings(f), color(f.width, f.height, f.samples), depth(f.width, f.height, f.samples), prepared(std::move(t)) {}
};

}  // namespace luxel::frame
