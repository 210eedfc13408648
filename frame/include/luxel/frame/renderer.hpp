#pragma once
// The frame: renders a scenes::Scene, whatever it holds, into an 8-bit image, as Source's DX9
// frame would.
//
// A Renderer prepares a scene once (each scenes::Texture uploaded as a rasterizer::Texture with
// its mips, the camera's view-projection, one draw per mesh) and then renders any number of
// frames, each what the llvmpipe peer calls a frame: clear, draw, resolve. Every mesh is drawn
// with its material's Source shader family and static combo, as the frame's shader model
// (FrameSettings::model) would run it; the passes on the finished frame (histogram, bloom, color
// correction, film grain) follow. The output bytes do not depend on the context's thread count.
//
// docs/architecture.md ("The frame's passes") states the contract in full: the passes in order,
// what each shader family draws, the tone-map scale and auto exposure, the post passes, what a
// cube-map capture draws, the scene's clock and the models' time-averaged lighting, and what is
// not drawn yet. docs/fidelity.md gives the Source rule behind each.
//
// Conventions: the view is Source's (+Z up, right-handed), projections are Direct3D's (depth in
// [0, 1]). The view-projection matrix is computed in double and rounded once.

#include "luxel/frame/look.hpp"
#include "luxel/postfx/auto_exposure.hpp"
#include "luxel/postfx/bloom.hpp"
#include "luxel/postfx/film_grain.hpp"
#include "luxel/rasterizer/context.hpp"
#include "luxel/rasterizer/draw.hpp"
#include "luxel/rasterizer/image.hpp"
#include "luxel/scenes/memory_limit.hpp"
#include "luxel/scenes/scene.hpp"
#include "luxel/shading/shader_model.hpp"
#include "luxel/shading/source/shader_use.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <memory>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace luxel::frame {

/// How a model's ambient cube is read from the irradiance volume at its centroid. (An int: CLI11
/// prints a uint8_t enum's values as characters in its help and errors.)
enum class AmbientSampling : int {
  nearest,    ///< the nearest sample's cube (a model's light changes in steps as it moves)
  trilinear,  ///< the eight samples around the centroid, blended trilinearly per cube side
};

struct SceneTextures;  // textures.hpp

struct FrameSettings {
  int width = 1280;
  int height = 720;
  int samples = 4;
  int camera = 0;                   ///< index into Scene::cameras
  /// The scene's clock at the first frame, seconds (Renderer::set_time moves it).
  float time = 0.0f;
  /// Look through Scene::camera_path at the clock's time instead of Scene::cameras[camera].
  bool camera_path = false;
  /// tau of the models' lighting averaging across frames (docs/architecture.md), seconds; 0: no averaging.
  float lighting_time_constant = 0.2f;
  /// The pixel-shader model the Source shaders are drawn as: ps_2_0, ps_2_b or ps_3_0.
  shading::ShaderModel model = shading::ShaderModel::ps_3_0;
  /// The cards whose dispatch rules the frame follows instead of `model`'s, rule by rule (unset:
  /// `model`'s; `luxel compare --explain` draws a card with another's rule to find which rule a
  /// difference comes from). Each rule is the SDK helpers' choice for a card, not a shader the
  /// card lacks: the binary drawn stays `model`'s.
  struct DispatchCards {
    /// Which shader a model material gets: the skin shader needs ps_2_b (vertexlit_dispatch.hpp).
    std::optional<shading::ShaderModel> model_shader;
    /// How many local lights a bumped or skin model takes: two at most on ps_2_0.
    std::optional<shading::ShaderModel> light_count;
    /// Whether water blurs its refraction ($blurrefract): ps_2_b and up.
    std::optional<shading::ShaderModel> water_blur;
  };
  DispatchCards dispatch_cards;
  AmbientSampling ambient = AmbientSampling::nearest;
  /// Attenuate the models' local lights per pixel where the combo fits the model, instead of per
  /// vertex as the SDK's bumped and skin shaders do on every model (luxel's option: a light close
  /// to a coarse mesh is not smeared across its triangles; `luxel report`, vertex_lighting).
  bool pixel_attenuation = false;
  /// The most significant lights a model takes as local lights, 1 to 4, the others folded into its
  /// ambient cube: 2 (the seed's rule) by default; up to 4 where the SDK's shaders take them (the
  /// bumped and skin shaders on ps_2_b and ps_3_0; elsewhere two at most).
  int local_lights = 2;
  /// Added to the mip LOD of every texture a material, the sky, a reflection or a water normal reads
  /// (D3DSAMP_MIPMAPLODBIAS): log2(k) draws a frame k times larger with the textures at the mips
  /// of the frame k times smaller (`luxel report`'s MSAA references).
  float texture_lod_bias = 0.0f;
  /// How the 3D passes' texture reads filter (rasterizer/texture.hpp, "Sampling rules"): as the
  /// DX9-era cards did (the default), or ideally, in float at a LOD per pixel (the reference that
  /// luxel report speed-error measures the hardware rules against).
  rasterizer::SamplingRules sampling = rasterizer::SamplingRules::hardware;
  /// A fixed tone-map scale (LINEAR_LIGHT_SCALE); unset: the scene's Exposure decides (docs/architecture.md).
  std::optional<float> exposure = std::nullopt;
  /// How auto exposure counts its histogram: target algorithm, counting method, query latency,
  /// region (the scene's Exposure gives the range, rate and percentages).
  postfx::HistogramSettings histogram{};
  /// Bloom after the histogram (docs/architecture.md); nullopt: none (mat_disable_bloom). Off
  /// unless asked, so that a frame's pixels are its shaders' (`luxel render` asks for it unless
  /// --no-bloom).
  std::optional<postfx::BloomOptions> bloom = std::nullopt;
  /// Blend the scene's color-correction nodes into the finished frame (mat_colorcorrection).
  bool color_correction = true;
  /// Film grain last; nullopt (the default, as Source without -filmgrain): none.
  std::optional<postfx::FilmGrainOptions> film_grain = std::nullopt;
  /// A look over the whole frame (look.hpp): archival grades every frame at full weight over the
  /// scene's color-correction nodes and blends a stronger grain (film_grain's seed, or 0).
  Look look = Look::none;
  /// Count the pixels each shader combo shades, the post passes' included (Renderer::shader_uses);
  /// off, a frame counts nothing.
  bool count_shading = false;
  /// Time each pass (Renderer::pass_times). The rasterizer then runs each pass over all tiles
  /// before the next instead of all passes tile by tile, and the frame's samples travel through
  /// the targets' memory between them instead of staying in tile memory, so a timed frame is
  /// slower.
  bool time_passes = false;
  /// Set: the frame looks through this camera, not `camera` nor the camera path (a cube-map face).
  std::optional<scenes::Camera> view = std::nullopt;
  /// Draw what a cube-map capture draws (docs/architecture.md): the world and the sky, unfogged.
  bool cubemap_capture = false;
  /// The side of the water's reflection and refraction targets, square whatever the frame's size:
  /// each view is drawn over the whole target with the camera's aspect, without multisampling
  /// (render targets, unlike the back buffer, have none), as viewrender.cpp's AdjustView draws
  /// them. 1 to kMaxTargetSize, or 0: water_texture_side's choice.
  int water_texture_size = 0;
  /// Draw of the water's views only what the water can read of them (water_passes.hpp: its
  /// footprint on screen, inside the rectangle around it); off, they draw the whole target:
  /// slower, and the same bytes (tested), like the rasterizer's fast paths.
  bool limit_water_views = true;
  /// The most bytes a renderer may ask for (Renderer's constructor, scenes/memory_limit.hpp).
  uint64_t memory_limit = scenes::kDefaultMemoryLimit;
};

/// The side of the water's view targets: FrameSettings::water_texture_size when set, else the
/// SDK's 1024 (iWaterTextureSize, CBaseClientRenderTargets; tf_water_resolution's default), or
/// the smallest power of two holding the frame's larger side where that is less: every frame of
/// 640 x 480 or more (all the engine drew) gets the engine's targets, a thumbnail does not pay
/// for a million texels a view.
int water_texture_side(const FrameSettings& settings);

/// A model's lighting in the last frame, after the time averaging (docs/architecture.md), before
/// a material's folding and hero boost.
struct ModelLightingState {
  std::string model;                   ///< Scene::models[i].name
  glm::vec3 centroid{0.0f};            ///< where its lighting was sampled: its centroid moved along its path
  std::array<glm::vec3, 6> volume{};   ///< the averaged irradiance-volume cube, +X, -X, +Y, -Y, +Z, -Z
  std::vector<float> light_shares;     ///< per scene light: its averaged share of being a local light
  std::vector<int> local_lights;       ///< the scene lights ranked as its local lights (FrameSettings::local_lights), in slot order
};

/// One pass of the last frame and its wall time (FrameSettings::time_passes).
struct PassTime {
  std::string pass;  ///< "views" (the draws made anew after the clock or the exposure moved), "water
                     ///< reflection", "water refraction", "opaque", "sky", "translucent", "resolve",
                     ///< "frame copy", "histogram", "bloom", "color correction", "film grain"
  double ms = 0.0;
  int draws = 0;
};

/// One shader combo the last frame ran (FrameSettings::count_shading): its family and combo, the
/// pixels it shaded, its counted DX9 slots per pixel on the frame's model.
using ShaderUse = shading::source::ShaderUse;

/// The camera a frame with these settings looks through (FrameSettings::view when set). Throws
/// std::invalid_argument when the scene has no such camera (an index out of range, a camera path
/// asked of a scene without one).
scenes::Camera frame_camera(const scenes::Scene& scene, const FrameSettings& settings);

/// Throws scenes::MemoryLimitError naming the scene when a renderer of `scene` with `settings`
/// would need more than settings.memory_limit: the estimate Renderer's constructor checks first.
void check_memory(const scenes::Scene& scene, const FrameSettings& settings);

/// World (inches, +Z up) to Direct3D clip space for `camera` drawn into a width x height image
/// (its aspect, when the camera gives none).
glm::mat4 view_projection(const scenes::Camera& camera, int width, int height);

/// How close the target of a settled exposure's frame is to the scale (relative).
inline constexpr float kSettledTolerance = 0.005f;

/// What Renderer::settle_exposure found.
struct SettledExposure {
  float scale = 1.0f;    ///< the scale the frames start at
  int draws = 0;         ///< frames drawn to find it
  bool settled = false;  ///< the last draw's target was within kSettledTolerance (else: the draws ran out)
};

class Renderer {
 public:
  /// Prepares `scene`, which must outlive the renderer (it reads the meshes in place). Throws
  /// std::invalid_argument naming the problem for an invalid scene (scenes::validate), bad
  /// settings (size outside 1..kMaxTargetSize, samples not 1, 2, 4 or 8, a model that is
  /// not a pixel-shader model, an exposure that is not positive and finite), a missing camera,
  /// or what the scene lacks for its materials (lightmaps, uv1, normals for tangents, a water
  /// normal map, water that is not a horizontal plane or neither reflects nor refracts, an
  /// unknown built-in LUT); std::runtime_error naming the file for a color-correction LUT file
  /// that cannot be read. `textures`: the scene's textures prepared before (textures.hpp: renderers of one scene
  /// share them); null: prepared here.
  /// Before anything is allocated, what the renderer will hold is estimated and refused beyond
  /// FrameSettings::memory_limit with scenes::MemoryLimitError naming the scene: the scene's
  /// meshes and textures, the textures' uploaded copies with their mips, the color, depth and
  /// stencil targets in whole tiles at the frame's samples (9 bytes a sample), two 8-bit images
  /// the size of the frame (the resolved image, a post pass), and the water's one-sample targets
  /// with their resolved image and two textures (water_texture_side on a side).
  Renderer(const scenes::Scene& scene, const FrameSettings& settings, std::shared_ptr<const SceneTextures> textures = nullptr);
  /// A temporary scene would be gone before the first frame reads it.
  Renderer(scenes::Scene&& scene, const FrameSettings& settings, std::shared_ptr<const SceneTextures> textures = nullptr) = delete;
  ~Renderer();
  Renderer(Renderer&&) noexcept;
  Renderer& operator=(Renderer&&) noexcept;

  /// Moves the scene's clock to `seconds` (finite; else std::invalid_argument): the next frame
  /// is drawn at that time, and the models' lighting averaging steps to it (docs/architecture.md).
  void set_time(float seconds);
  float time() const;
  /// Renders one frame at the clock's time and resolves it into image().
  void render(rasterizer::Context& ctx);
  const rasterizer::Image& image() const;
  /// Renders the frame as HDR_TYPE_FLOAT's float target holds it: per pixel, the linear color the
  /// pixel shader wrote (after the tone-map scale, before any clamp or sRGB encode), alpha 1;
  /// where nothing was drawn, Scene::background. Row-major, top row first. One frame into an
  /// rgba32f target (rasterizer/framebuffer.hpp), each draw linear and unblended, read back bit
  /// for bit. Only a cube-map capture without MSAA can be rendered so (no blended draws, no
  /// samples averaged); otherwise throws std::invalid_argument.
  std::vector<glm::vec4> render_float(rasterizer::Context& ctx);
  /// What the draws of the last frame did, summed (the water's views included).
  const rasterizer::DrawStats& stats() const;
  /// What each shader combo did in the last frame, the water's views and the post passes
  /// (histogram, bloom, color correction, film grain) included, in a fixed order (first draw
  /// first); empty unless FrameSettings::count_shading.
  const std::vector<ShaderUse>& shader_uses() const;
  /// The last frame's passes in the order they ran, the ones the scene has; empty unless
  /// FrameSettings::time_passes.
  const std::vector<PassTime>& pass_times() const;
  /// Per Scene::models entry, its lighting at the clock's time.
  const std::vector<ModelLightingState>& model_lighting() const;
  /// Auto exposure only (otherwise nothing happens): the frames' exposure starts at `scale` (for
  /// the next frame, and again where a clock that went back restarts it), with its goal there,
  /// instead of at the first frame's 1. Throws std::invalid_argument for a scale that is not
  /// positive and finite.
  void start_exposure_at(float scale);
  /// Auto exposure only: finds the scale the exposure comes to rest at for the current view, and
  /// starts the frames there (start_exposure_at), as a still's viewer sees the scene once the eye
  /// has adapted rather than on its first frame. The scale at rest is the one whose frame's exact
  /// histogram targets that scale (postfx::exact_target, within kSettledTolerance; within the
  /// controls' range): what the engine's loop settles at on a view that does not move, once every
  /// bucket has been counted. Found by drawing the 3D frame (no post-processing) at most
  /// `max_draws` times; the image then holds the last draw.
  SettledExposure settle_exposure(rasterizer::Context& ctx, int max_draws = 8);
  /// The tone-map scale the next frame is drawn with.
  float exposure() const;
  /// The auto exposure (histogram, goal, last target), or null when the exposure is fixed.
  const postfx::AutoExposure* auto_exposure() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace luxel::frame
