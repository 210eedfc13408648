#include "luxel/frame/renderer.hpp"

#include "color_correction_nodes.hpp"
#include "frame_builder.hpp"
#include "frame_state.hpp"
#include "model_lighting.hpp"
#include "source_draws.hpp"
#include "views.hpp"
#include "water_passes.hpp"

#include "luxel/frame/look.hpp"
#include "luxel/frame/textures.hpp"
#include "luxel/frame/world_envmaps.hpp"
#include "luxel/postfx/bloom_amount.hpp"
#include "luxel/postfx/full_frame.hpp"
#include "luxel/rasterizer/framebuffer.hpp"
#include "luxel/rasterizer/msaa.hpp"
#include "luxel/rasterizer/srgb.hpp"
#include "luxel/scenes/memory_limit.hpp"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_double4x4.hpp>
#include <glm/ext/vector_double3.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace luxel::frame {

using namespace rasterizer;

scenes::Camera frame_camera(const scenes::Scene& scene, const FrameSettings& settings) {
  if (settings.view) return *settings.view;
  if (settings.camera_path) {
    if (scene.camera_path.empty())
      throw std::invalid_argument((scene.name.empty() ? std::string("scene") : scene.name) + " has no camera path");
    return scenes::camera_at(scene.camera_path, settings.time);
  }
  if (settings.camera < 0 || settings.camera >= static_cast<int>(scene.cameras.size()))
    throw std::invalid_argument((scene.name.empty() ? std::string("scene") : scene.name) + " has no camera " +
                                std::to_string(settings.camera) + " (it has " + std::to_string(scene.cameras.size()) +
                                ")");
  return scene.cameras[settings.camera];
}

glm::mat4 view_projection(const scenes::Camera& c, int width, int height) {
  const ViewMatrices m = view_matrices(c, width, height);
  return glm::mat4(m.projection * m.view);
}

namespace {

/// The exposure controls where the frame's camera is (renderer.hpp).
const scenes::Exposure& frame_controls(const scenes::Scene& scene, const FrameSettings& settings) {
  return scenes::exposure_at(scene, frame_camera(scene, settings).position);
}

/// The tone-map scale of the first frame (renderer.hpp).
float frame_exposure(const scenes::Scene& scene, const FrameSettings& settings) {
  if (settings.exposure) return *settings.exposure;
  const scenes::Exposure& e = frame_controls(scene, settings);
  return std::clamp(1.0f, e.min_scale, std::max(e.min_scale, e.max_scale));
}

/// Where the frame's camera is at each time on the clock, and from when it stands still (the
/// camera path's end; a camera of its own never moves).
EyePath eye_path(const scenes::Scene& scene, const FrameSettings& settings) {
  const bool moves = settings.camera_path && !settings.view;
  return {[&scene, at = settings](float time) mutable {
            at.time = time;
            return frame_camera(scene, at).position;
          },
          moves && !scene.camera_path.empty() ? scene.camera_path.back().time : 0.0f};
}

/// Whether the frames run auto exposure: no fixed scale, and a range somewhere in the scene.
bool uses_auto_exposure(const scenes::Scene& scene, const FrameSettings& settings) {
  if (settings.exposure || settings.cubemap_capture) return false;
  const auto ranged = [](const scenes::Exposure& e) { return e.min_scale < e.max_scale; };
  return ranged(scene.exposure) ||
         std::any_of(scene.exposure_zones.begin(), scene.exposure_zones.end(), [&](const auto& z) { return ranged(z.exposure); });
}

/// Auto exposure's settings under the controls `e`.
postfx::AutoExposureSettings auto_exposure_settings(const scenes::Exposure& e, const FrameSettings& settings) {
  postfx::AutoExposureSettings a;
  a.histogram = settings.histogram;
  a.min_scale = e.min_scale;
  a.max_scale = e.max_scale;
  a.rate = e.rate;
  a.percent_target = e.percent_target;
  a.percent_bright = e.percent_bright;
  a.initial_scale = std::clamp(1.0f, e.min_scale, std::max(e.min_scale, e.max_scale));
  return a;
}

}  // namespace

namespace {

void check_settings(const FrameSettings& s) {
  if (s.width < 1 || s.height < 1 || s.width > kMaxTargetSize || s.height > kMaxTargetSize)
    throw std::invalid_argument("image size " + std::to_string(s.width) + "x" + std::to_string(s.height) +
                                " is outside 1.." + std::to_string(kMaxTargetSize));
  if (!is_valid_sample_count(s.samples))
    throw std::invalid_argument("msaa " + std::to_string(s.samples) + " is not 1, 2, 4 or 8");
  if (!shading::caps(s.model).pixel)
    throw std::invalid_argument("shader model " + std::string(shading::caps(s.model).name) + " is not a pixel-shader model");
  if (s.water_texture_size < 0 || s.water_texture_size > kMaxTargetSize)
    throw std::invalid_argument("water texture size " + std::to_string(s.water_texture_size) + " is outside 1.." +
                                std::to_string(kMaxTargetSize) + " (or 0: the default)");
  if (s.exposure && !(std::isfinite(*s.exposure) && *s.exposure > 0.0f))
    throw std::invalid_argument("exposure " + std::to_string(*s.exposure) + " is not a positive finite number");
  if (s.local_lights < 1 || s.local_lights > kMaxLocalLights)
    throw std::invalid_argument("local lights " + std::to_string(s.local_lights) + " is outside 1.." +
                                std::to_string(kMaxLocalLights));
}

const FrameSettings& checked(const scenes::Scene& scene, const FrameSettings& s) {
  check_settings(s);
  scenes::validate(scene);
  return s;
}

}  // namespace

int water_texture_side(const FrameSettings& settings) {
  if (settings.water_texture_size > 0) return settings.water_texture_size;
  constexpr int kSdkSide = 1024;
  return std::min(kSdkSide, static_cast<int>(std::bit_ceil(static_cast<unsigned>(std::max(settings.width, settings.height)))));
}

void check_memory(const scenes::Scene& scene, const FrameSettings& s) {
  uint64_t uploads = 0;  // RGBA8 or RGBA16F, each with its mips (a third more)
  for (const scenes::Texture& t : scene.textures)
    for (const scenes::PixelImage& face : t.faces) uploads += uint64_t(face.width) * uint64_t(face.height) * (face.is_hdr() ? 8 : 4) * 4 / 3;
  // The targets are allocated in whole tiles: color (4 bytes), depth (4) and stencil (1) per sample.
  auto tiles = [](int pixels) { return uint64_t(pixels + kTileSize - 1) / kTileSize * kTileSize; };
  const int side = water_texture_side(s);
  const uint64_t water = uint64_t(side) * uint64_t(side);
  const uint64_t targets = tiles(s.width) * tiles(s.height) * uint64_t(s.samples) * 9 + tiles(side) * tiles(side) * 9;
  // The resolved image and a post pass's target; the water's resolved view and its two textures.
  const uint64_t images = 2 * 4 * uint64_t(s.width) * uint64_t(s.height) + 3 * 4 * water;
  const uint64_t scene_bytes = scenes::scene_bytes(scene);
  scenes::check_memory(scene.name, scene_bytes + uploads + targets + images,
                       "a " + std::to_string(s.width) + "x" + std::to_string(s.height) + " frame at " + std::to_string(s.samples) +
                           " samples: " + scenes::format_bytes(targets + images) + "; the scene's meshes and textures: " +
                           scenes::format_bytes(scene_bytes + uploads),
                       s.memory_limit);
}

namespace {

/// The scene's textures, checked to be its own or prepared here, once the scene and settings passed.
std::shared_ptr<const SceneTextures> prepared(const scenes::Scene& scene, const FrameSettings& s,
                                              std::shared_ptr<const SceneTextures> textures) {
  checked(scene, s);
  check_memory(scene, s);
  if (!textures) return std::make_shared<const SceneTextures>(scene);
  if (textures->textures.size() != scene.textures.size())
    throw std::invalid_argument(scene.name + ": the prepared textures are not the scene's (" +
                                std::to_string(textures->textures.size()) + " for " + std::to_string(scene.textures.size()) + ")");
  return textures;
}

}  // namespace

struct Renderer::State : FrameState {
  using FrameState::FrameState;
};

namespace {

/// Moves the models and their lighting to the clock's time, `dt` after the last frame (negative:
/// restart the averaging).
void move_models(FrameState& st, float dt) {
  const scenes::Scene& scene = *st.scene;
  const std::vector<LightDesc> lights = light_descriptions(scene);
  const size_t count = scene.models.size();
  st.model_offsets.resize(count);
  st.model_lighting.resize(count);
  st.model_states.resize(count);
  for (size_t i = 0; i < count; ++i) {
    const scenes::Model& model = scene.models[i];
    st.model_offsets[i] = scenes::model_offset(model, st.settings.time);
    const glm::vec3 centroid = model.centroid + st.model_offsets[i];
    const AveragedLighting target = lighting_at(scene, lights, centroid, st.settings.ambient, st.settings.local_lights);
    step_towards(st.model_lighting[i], target, dt, st.settings.lighting_time_constant);
    ModelLightingState& state = st.model_states[i];
    state.model = model.name;
    state.centroid = centroid;
    state.volume = st.model_lighting[i].volume.color;
    state.light_shares = st.model_lighting[i].shares;
    state.local_lights.clear();
    for (int l : local_light_slots(shading::source::significance_order(lights, centroid), st.model_lighting[i].shares,
                                   st.settings.local_lights))
      if (l >= 0) state.local_lights.push_back(l);
  }
  st.views_current = false;
}

/// The camera's view and the water's views at the clock's time, drawn from scratch.
void build_views(FrameState& st) {
  const scenes::Scene& scene = *st.scene;
  const FrameSettings& settings = st.settings;
  st.passes = PassList{};
  st.water.reset();
  st.vertex_setups.clear();
  st.sky_quads.clear();
  const scenes::Camera camera = frame_camera(scene, settings);
  const ViewMatrices matrices = view_matrices(camera, settings.width, settings.height);
  ViewSpec view;
  view.eye = camera.position;
  view.view_projection = glm::mat4(matrices.projection * matrices.view);
  view.far_plane = camera.far_plane;
  view.exposure = st.exposure;
  // A capture's background is exposed as its surfaces are (renderer.hpp).
  const glm::vec3 background = scene.background * (settings.cubemap_capture ? view.exposure : 1.0f);
  st.clear = glm::vec4(float(linear_to_srgb(std::clamp(background.r, 0.0f, 1.0f))),
                       float(linear_to_srgb(std::clamp(background.g, 0.0f, 1.0f))),
                       float(linear_to_srgb(std::clamp(background.b, 0.0f, 1.0f))), 1.0f);
  const BuildView build = [&st](const ViewSpec& v, PassList& out) { build_view(st, v, out); };
  // Before the camera's view: its water draws read them. A capture draws no water.
  if (!settings.cubemap_capture) st.water.emplace(scene, settings, matrices, view, build);
  build(view, st.passes);
  st.views_current = true;
}

}  // namespace

Renderer::Renderer(const scenes::Scene& scene, const FrameSettings& settings, std::shared_ptr<const SceneTextures> textures)
    : state_(std::make_unique<State>(scene, settings, prepared(scene, settings, std::move(textures)))) {
  State& st = *state_;
  if (!std::isfinite(settings.time)) throw std::invalid_argument("frame time " + std::to_string(settings.time) + " is not finite");
  if (!(settings.lighting_time_constant >= 0.0f && std::isfinite(settings.lighting_time_constant)))
    throw std::invalid_argument("lighting time constant " + std::to_string(settings.lighting_time_constant) +
                                " is not a finite number >= 0");
  st.completed_meshes.resize(scene.meshes.size());
  st.envmap_groups.resize(scene.meshes.size());
  st.exposure = frame_exposure(scene, settings);
  if (uses_auto_exposure(scene, settings)) st.auto_exposure.emplace(auto_exposure_settings(frame_controls(scene, settings), settings));
  if (!settings.cubemap_capture) {
    const bool scene_nodes =
        settings.color_correction && !(scene.color_corrections.empty() && scene.color_correction_volumes.empty());
    const std::optional<std::string> look = look_lut(settings.look);
    if (scene_nodes || look) st.color_correction.emplace(scene, eye_path(scene, settings), scene_nodes, look);
  }
  // The bloom's quarter-size targets need a frame of 4 x 4 or more.
  if (settings.bloom && !settings.cubemap_capture && settings.width >= 4 && settings.height >= 4) st.bloom.emplace(*settings.bloom);
  // The SDK's smoothed amount is a static that starts at 1 when the game starts; a renderer starts
  // it at the scene's own scale, so that a first frame shows the bloom the designer set.
  st.bloom_amount.smoothed = frame_controls(scene, settings).bloom_scale;
  if (const auto grain = look_film_grain(settings.look, settings.film_grain); grain && !settings.cubemap_capture)
    st.film_grain.emplace(*grain);
  move_models(st, -1.0f);
  build_views(st);
}

void Renderer::set_time(float seconds) {
  State& st = *state_;
  if (!std::isfinite(seconds)) throw std::invalid_argument("frame time " + std::to_string(seconds) + " is not finite");
  const float dt = seconds - st.settings.time;
  st.settings.time = seconds;
  move_models(st, dt);
}

float Renderer::time() const { return state_->settings.time; }

Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

namespace {

/// The 3D frame at st.exposure, resolved into st.image (its draws' stats in st.stats): what
/// the post passes start from.
/// The water's views and the frame's 3D passes, resolved into the image, or into `copy` (the
/// post passes' copy of the frame) when given.
void draw_3d(FrameState& st, Context& ctx, PassClock& clock, postfx::FullFrameTexture* copy = nullptr) {
  ctx.reset_stats();
  // After the clock or the exposure moved: the views' draws made anew on the CPU (a sequence pays
  // it per frame).
  if (!st.views_current) clock.run("views", 0, [&] { build_views(st); });
  if (st.water && st.water->has_views()) {  // the water's views first: its draws read them
    if (!st.water_targets) st.water_targets.emplace(water_texture_side(st.settings));
    st.water->render(ctx, st.water_targets->color, st.water_targets->depth, clock);
  }
  // Cleared whole and discarded once resolved: the frame's samples live in tile memory
  // (rasterizer/framebuffer.hpp) and never travel to the targets' memory.
  clear_color(ctx, st.color, st.clear);
  clear_depth_stencil(ctx, st.depth, 1.0f, 0);
  run_passes(ctx, Framebuffer{&st.color, &st.depth}, st.passes, &clock);
  discard(ctx, st.color);
  discard(ctx, st.depth);
  // The target's alpha holds what the shaders wrote there (base alpha, blend results, the water's
  // fog factor), which a screen never shows: the image is what is shown, opaque.
  clock.run("resolve", 0, [&] {
    if (copy) copy->resolve(ctx, st.color, rasterizer::ResolveAlpha::opaque);
    else resolve_into(ctx, st.color, st.image, rasterizer::ResolveAlpha::opaque);
  });
  st.stats = ctx.stats();  // the 3D frame's draws, not the passes on the finished image
}

/// Auto exposure's controls where the camera is, starting from the renderer's start scale.
postfx::AutoExposureSettings exposure_controls(const FrameState& st) {
  postfx::AutoExposureSettings controls = auto_exposure_settings(frame_controls(*st.scene, st.settings), st.settings);
  if (st.start_exposure) controls.initial_scale = *st.start_exposure;
  return controls;
}

}  // namespace

void Renderer::start_exposure_at(float scale) {
  State& st = *state_;
  if (!st.auto_exposure) return;
  if (!(std::isfinite(scale) && scale > 0.0f))
    throw std::invalid_argument("start exposure " + std::to_string(scale) + " is not positive and finite");
  st.start_exposure = scale;
  st.auto_exposure.emplace(exposure_controls(st));
  if (st.exposure != st.auto_exposure->scale()) st.views_current = false;
  st.exposure = st.auto_exposure->scale();
}

SettledExposure Renderer::settle_exposure(Context& ctx, int max_draws) {
  State& st = *state_;
  SettledExposure result{st.exposure, 0, false};
  if (!st.auto_exposure) return result;
  const postfx::AutoExposureSettings controls = exposure_controls(st);
  // Step 3's clamp, which the scale cannot leave.
  const float low = std::max(controls.min_scale, 0.001f), high = std::max(low, controls.max_scale);
  // The target of the frame drawn at e, over e, does not grow with e: a brighter frame puts its
  // bright pixels higher, and the percentile rule asks for less (the mean rule too). So the scale
  // at rest is where the target crosses e (or a bound of the range); each draw narrows the bracket
  // [lo, hi] around it, and the next scale is the target itself (the engine's own step) while it
  // stays inside the bracket, else the bracket's geometric middle.
  float lo = low, hi = high, e = std::clamp(st.exposure, low, high);
  for (int draw = 0; draw < max_draws; ++draw) {
    st.exposure = e;
    st.views_current = false;  // the draws carry the scale in their constants
    PassClock clock(ctx, nullptr);
    draw_3d(st, ctx, clock);
    ++result.draws;
    const float target = std::clamp(postfx::exact_target(st.image, controls, e), low, high);
    if (std::fabs(target - e) <= kSettledTolerance * e) {
      result.settled = true;
      break;
    }
    (target > e ? lo : hi) = e;
    // (A target on the range's bound is tried as it is: the scale may rest there.)
    const bool inside = (target > lo || (target == low && lo == low)) && (target < hi || (target == high && hi == high));
    e = inside ? target : std::sqrt(lo * hi);
  }
  result.scale = e;
  start_exposure_at(e);
  return result;
}

void Renderer::render(Context& ctx) {
  State& st = *state_;
  // The frame's duration moves the exposure; a clock that went back starts it again.
  const float dt = st.last_frame_time ? st.settings.time - *st.last_frame_time : 0.0f;
  if (st.auto_exposure) {
    const postfx::AutoExposureSettings controls = exposure_controls(st);
    if (dt < 0.0f) {
      st.auto_exposure.emplace(controls);
      if (st.exposure != st.auto_exposure->scale()) st.views_current = false;
      st.exposure = st.auto_exposure->scale();
    } else {
      st.auto_exposure->set_controls(controls);  // the zone the camera is in
    }
  }
  st.last_frame_time = st.settings.time;
  st.pass_times.clear();
  PassClock clock(ctx, st.settings.time_passes ? &st.pass_times : nullptr);
  const glm::vec3 eye = frame_camera(*st.scene, st.settings).position;
  const std::vector<postfx::WeightedLut> luts =
      st.color_correction ? st.color_correction->weighted_at(st.settings.time) : std::vector<postfx::WeightedLut>{};
  // INTEGER HDR: no LDR factor (bloom_amount.hpp). At 0 the bloom's passes do not run (Bloom).
  const float bloom_amount =
      st.bloom ? st.bloom_amount.advance(scenes::exposure_at(*st.scene, eye).bloom_scale, shading::source::HdrType::integer) : 0.0f;
  const bool blooms = st.bloom && bloom_amount > 0.0f;
  // UpdateScreenEffectTexture: the post passes read one copy of the frame (_rt_FullFrameFB),
  // which the frame resolves into. The image is then the color correction's output, or the
  // copy's pixels where no correction runs.
  const bool post = st.auto_exposure || blooms || !luts.empty();
  draw_3d(st, ctx, clock, post ? &st.full_frame : nullptr);
  st.shader_uses.clear();
  if (st.settings.count_shading) {  // the 3D draws have run (the resolve flushed them)
    if (st.water) st.water->add_shader_uses(st.shader_uses);
    add_shader_uses(st.passes, st.shader_uses);
  }
  // The post passes add their shaders after the 3D draws'.
  const postfx::ShaderTally tally{st.settings.count_shading ? &st.shader_uses : nullptr, st.settings.model};
  if (post && luts.empty()) clock.run("frame copy", 0, [&] { postfx::read_into(st.full_frame.texture(), st.image); });
  if (st.auto_exposure) {
    clock.run("histogram", 1, [&] {
      st.auto_exposure->measure(ctx, st.full_frame.texture(), st.depth, std::max(dt, 0.0f), tally);
    });
    if (st.auto_exposure->scale() != st.exposure) {
      st.exposure = st.auto_exposure->scale();
      st.views_current = false;  // the draws carry the scale in their constants
    }
  }
  if (blooms) {
    if (luts.empty()) {
      clock.run("bloom", 5, [&] {
        st.bloom->blur(ctx, st.full_frame.texture(), bloom_amount, tally);
        st.bloom->add(ctx, st.image, tally);
      });
    } else {
      // Blurred only: the color correction adds it (Engine_Post, docs/fidelity.md#bloom).
      clock.run("bloom", 3, [&] { st.bloom->blur(ctx, st.full_frame.texture(), bloom_amount, tally); });
    }
  }
  if (!luts.empty()) {
    clock.run("color correction", 1, [&] {
      if (blooms) {
        postfx::color_correct_into(ctx, *st.bloom, luts, st.image, tally);
      } else {
        postfx::color_correct_into(ctx, st.full_frame.texture(), luts, st.image, tally);
      }
    });
  }
  if (st.film_grain) {
    clock.run("film grain", 1, [&] { st.film_grain->apply(ctx, st.image, std::bit_cast<uint32_t>(st.settings.time), tally); });
  }
}

std::vector<glm::vec4> Renderer::render_float(Context& ctx) {
  State& st = *state_;
  if (!st.settings.cubemap_capture || st.settings.samples != 1 || !st.passes.translucent.empty())
    throw std::invalid_argument("a float frame is rendered only for a cube-map capture without MSAA");
  if (!st.views_current) build_views(st);
  if (!st.float_color) st.float_color.emplace(st.settings.width, st.settings.height, 1, ColorFormat::rgba32f);
  ColorTarget& color = *st.float_color;
  const Framebuffer fb{&color, &st.depth};
  ctx.reset_stats();
  clear_color(ctx, color, glm::vec4(st.scene->background, 1.0f));
  clear_depth_stencil(ctx, st.depth, 1.0f, 0);
  for (auto* passes : {&st.passes.opaque, &st.passes.sky}) {
    for (Pass& p : *passes) {
      PipelineState linear = p.source->state;  // what a float target takes
      linear.blend.enable = false;
      linear.blend.srgb_write = false;
      p.source->draw(ctx, fb, linear);
    }
  }
  discard(ctx, color);
  discard(ctx, st.depth);
  std::vector<glm::vec4> out;
  resolve_into(ctx, color, out);
  st.stats = ctx.stats();
  for (glm::vec4& pixel : out) pixel.a = 1.0f;
  return out;
}

const Image& Renderer::image() const { return state_->image; }
const DrawStats& Renderer::stats() const { return state_->stats; }
const std::vector<ShaderUse>& Renderer::shader_uses() const { return state_->shader_uses; }
const std::vector<PassTime>& Renderer::pass_times() const { return state_->pass_times; }
const std::vector<ModelLightingState>& Renderer::model_lighting() const { return state_->model_states; }
float Renderer::exposure() const { return state_->exposure; }
const postfx::AutoExposure* Renderer::auto_exposure() const { return state_->auto_exposure ? &*state_->auto_exposure : nullptr; }

}  // namespace luxel::frame
