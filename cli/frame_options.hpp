#pragma once
// The options of the commands that render frames (`luxel render`, `luxel compare`): the scene, its
// camera, the frame of its sequence, the image size, MSAA, worker threads and the bake made on
// demand, the memory limit, the LUXEL_NO_FASTPATH
// switches, and how each of them is reported when it is bad: one line on stderr naming the
// argument, exit 2 for an argument (an unknown built-in, a camera the scene lacks, a bad switch),
// 1 for a file that cannot be read or written.

#include "luxel/frame/renderer.hpp"
#include "luxel/rasterizer/context.hpp"
#include "luxel/scenes/scene.hpp"
#include "luxel/shading/shader_model.hpp"
#include "memory_limit_option.hpp"

#include <CLI/CLI.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace luxel::cli {

/// The pixel-shader models named in `list` ("ps_2_0,ps_3_0", the --models or --model of a
/// command), in order, at least `at_least` of them; nullopt after one line on stderr naming
/// `command` and `option` (exit 2).
std::optional<std::vector<shading::ShaderModel>> parse_models(const std::string& command, const std::string& option,
                                                              const std::string& list, size_t at_least);

/// What the renderers of one command's scene share (compare's and cost's models, each measured by
/// a counted and a timed renderer): the scene's textures, which the first prepares (most of what
/// constructing a renderer costs, frame/textures.hpp), and the scale auto exposure starts at.
struct SharedRendering {
  std::shared_ptr<const frame::SceneTextures> textures;
  /// The first renderer's settled scale: every later one starts there, so that they differ by
  /// their settings alone.
  std::optional<float> exposure_start;
};

struct FrameOptions {
  std::string scene = "builtin:demo";
  frame::FrameSettings settings;  ///< size, samples, camera, ambient (the model is each command's own)
  int threads = 0;
  std::string bake = "full";      ///< the bake made on demand: full or quick
  int frame = 0;                  ///< the frame of the scene's sequence, at time frame / fps
  float fps = 30.0f;
  std::optional<float> exposure;  ///< --exposure: a fixed tone-map scale
  bool unsettled = false;         ///< --unsettled: auto exposure starts at the engine's 1, not settled
  bool no_bloom = false, bloom_true_height = false;
  std::optional<uint64_t> film_grain_seed;  ///< --film-grain SEED
  MemoryLimitOption memory;                 ///< --memory-limit: the scene's import, the bake, the renderer

  /// Registers --scene --width --height --msaa --camera --camera-path --frame --fps --threads
  /// --bake --ambient --exposure --unsettled --tonemap-algorithm --histogram --query-latency
  /// --no-color-correction --no-bloom --bloom-true-height --film-grain --look --memory-limit on `cmd`.
  void add_to(CLI::App& cmd);

  /// The rasterizer context's options: the threads and LUXEL_NO_FASTPATH; nullopt after printing
  /// one line (exit code 2 in `code`).
  std::optional<rasterizer::ContextOptions> context_options(const std::string& command, int& code) const;

  /// The scene, ready to render with `settings` (a copy of this->settings with the command's own
  /// fields set; its memory limit is set here). What can fail quickly is checked first: the memory
  /// limit, and that each of `outs` (the files the command will write) has a folder and is not
  /// one. Then the scene is loaded (a file's camera N
  /// is made its first on import, as `luxel info` and `export` do, and `settings` then looks
  /// through camera 0; a built-in is built for the settings' size), its camera checked, and the
  /// bake it needs and lacks loaded or made (cli/baking.hpp). nullopt after printing one line,
  /// with `code` set.
  std::optional<scenes::Scene> prepare_scene(const std::string& command, frame::FrameSettings& settings,
                                             const std::vector<std::string>& outs, int& code) const;

  /// A renderer of `scene` (which must outlive it) with `settings`, its clock at `frame`: started
  /// at frame 0 and moved through every frame before, so that the models' lighting is averaged
  /// as in the sequence (frame/renderer.hpp); with auto exposure those frames are rendered on
  /// `ctx`, since each one's exposure comes from the frames before it (progress on a terminal).
  /// Auto exposure starts at frame 0 settled unless --unsettled: at `shared->exposure_start` when
  /// it holds a scale, else at the scale it comes to rest at on frame 0's view
  /// (Renderer::settle_exposure, one line on stderr saying which), kept there when `shared` is
  /// given. The renderer reads `shared->textures`, prepared by the first call, when given.
  /// nullptr after printing one line for settings the renderer refuses, exit code 2 in `code`.
  std::unique_ptr<frame::Renderer> make_renderer(const std::string& command, const scenes::Scene& scene,
                                                 const frame::FrameSettings& settings, rasterizer::Context& ctx,
                                                 int& code, SharedRendering* shared = nullptr) const;
};

}  // namespace luxel::cli
