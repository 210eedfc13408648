#include "frame_options.hpp"

#include "baking.hpp"
#include "scene_argument.hpp"

#include "luxel/frame/look.hpp"
#include "luxel/frame/textures.hpp"
#include "luxel/rasterizer/fast_paths.hpp"
#include "luxel/scenes/builtin.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <algorithm>
#include <map>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <unistd.h>

namespace luxel::cli {

std::optional<std::vector<shading::ShaderModel>> parse_models(const std::string& command, const std::string& option,
                                                              const std::string& list, size_t at_least) {
  std::vector<shading::ShaderModel> models;
  std::istringstream names(list);
  std::string name;
  try {
    while (std::getline(names, name, ',')) {
      const shading::ShaderModel m = shading::parse_pixel_model(name);
      if (std::find(models.begin(), models.end(), m) != models.end())
        throw std::invalid_argument(name + " is named twice");
      models.push_back(m);
    }
    if (models.size() < at_least)
      throw std::invalid_argument(at_least == 2 ? "name at least two models, comma-separated" : "name a model");
  } catch (const std::invalid_argument& e) {
    std::cerr << "luxel " << command << ": " << option << " " << list << ": " << e.what() << "\n";
    return std::nullopt;
  }
  return models;
}

void FrameOptions::add_to(CLI::App& cmd) {
  std::string names;
  for (const std::string& n : scenes::builtin_scene_names()) names += (names.empty() ? "" : ", ") + n;
  cmd.add_option("--scene", scene, "Scene to render: FILE.gltf, FILE.glb or builtin:NAME (" + names + ")")->capture_default_str();
  cmd.add_option("--width", settings.width, "Image width in pixels")->check(CLI::Range(1, 8192))->capture_default_str();
  cmd.add_option("--height", settings.height, "Image height in pixels")->check(CLI::Range(1, 8192))->capture_default_str();
  cmd.add_option("--msaa", settings.samples, "Samples per pixel: 1, 2, 4 or 8")
      ->check(CLI::IsMember({1, 2, 4, 8}))
      ->capture_default_str();
  cmd.add_option("--camera", settings.camera, "Which of the scene's cameras to look through (0 = the first)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd.add_flag("--camera-path", settings.camera_path,
               "Look through the scene's camera path at the frame's time instead of a camera");
  cmd.add_option("--frame", frame,
                 "Which frame of the scene's sequence (its camera path, moving models, water scroll): time = frame / fps; "
                 "the models' lighting is averaged over the frames before it")
      ->check(CLI::Range(0, 1000000))
      ->capture_default_str();
  cmd.add_option("--fps", fps, "Frames per second of the sequence")->check(CLI::Range(1.0f, 1000.0f))->capture_default_str();
  cmd.add_option("--threads", threads, "Worker threads (0 = one per core)")->check(CLI::Range(0, 256))->capture_default_str();
  cmd.add_option("--bake", bake,
                 "When the scene needs a bake it lacks (kept as `luxel bake` keeps it): full, or quick (a preview in seconds)")
      ->check(CLI::IsMember({"full", "quick"}))
      ->capture_default_str();
  const std::map<std::string, frame::AmbientSampling> ambient{{"nearest", frame::AmbientSampling::nearest},
                                                               {"trilinear", frame::AmbientSampling::trilinear}};
  cmd.add_option("--ambient", settings.ambient,
                 "A model's ambient cube from the irradiance volume: nearest (the nearest sample's, the default) or "
                 "trilinear (blended from the eight samples around it)")
      ->transform(CLI::CheckedTransformer(ambient, CLI::ignore_case));
  cmd.add_option("--lights", settings.local_lights,
                 "Local lights a model takes, the others folded into its ambient cube: 2 (the default), up to 4 for "
                 "bumped and skin models on ps_2_b and ps_3_0, as the SDK's later shaders take")
      ->check(CLI::Range(1, 4))
      ->capture_default_str();
  const std::map<std::string, rasterizer::SamplingRules> sampling{{"hardware", rasterizer::SamplingRules::hardware},
                                                                   {"ideal", rasterizer::SamplingRules::ideal}};
  cmd.add_option("--sampling", settings.sampling,
                 "How the 3D passes filter textures: hardware (as DX9-era cards did: a LOD per 2x2 quad, 8-bit weights "
                 "and LOD fraction, 8-bit texels in fixed point, sRGB decoded after filtering; the default) or ideal "
                 "(float, a LOD per pixel, sRGB decoded first: docs/fidelity.md#texture-sampling)")
      ->transform(CLI::CheckedTransformer(sampling, CLI::ignore_case));
  cmd.add_flag("--pixel-attenuation", settings.pixel_attenuation,
               "Attenuate the models' local lights per pixel where the combo fits the model, instead of per vertex as "
               "the SDK does");
  cmd.add_option("--exposure", exposure,
                 "A fixed tone-map scale; without it the scene's exposure range decides (auto exposure from the "
                 "luminance histogram, starting where it settles on the first frame's view, or the range's one value)")
      ->check(CLI::PositiveNumber);
  cmd.add_flag("--unsettled", unsettled,
               "Start auto exposure at the engine's first-frame scale (1, clamped to the scene's range) instead of "
               "the scale it comes to rest at on the first frame's view (found by drawing that frame a few times)")
      ->excludes("--exposure");
  const std::map<std::string, postfx::ExposureAlgorithm> algorithms{{"percentile", postfx::ExposureAlgorithm::percentile},
                                                                     {"mean", postfx::ExposureAlgorithm::mean}};
  cmd.add_option("--tonemap-algorithm", settings.histogram.algorithm,
                 "Auto exposure's rule (mat_tonemap_algorithm): percentile (17 buckets, the 98th percentile and the "
                 "median term, the default) or mean (31 log-spaced buckets; Day of Defeat, Counter-Strike, Lost Coast)")
      ->transform(CLI::CheckedTransformer(algorithms, CLI::ignore_case));
  const std::map<std::string, postfx::HistogramCount> counts{{"direct", postfx::HistogramCount::direct_query},
                                                             {"stencil", postfx::HistogramCount::stencil}};
  cmd.add_option("--histogram", settings.histogram.count,
                 "How the histogram counts a bucket: direct (the range test inside the occlusion query, the default) "
                 "or stencil (the test marks the stencil, a second draw counts it; mat_tonemapping_occlusion_use_stencil)")
      ->transform(CLI::CheckedTransformer(counts, CLI::ignore_case));
  cmd.add_option("--query-latency", settings.histogram.query_latency,
                 "Frames before a histogram query is read back (the engine waited 3)")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  cmd.add_option("--water-size", settings.water_texture_size,
                 "Side of the water's square reflection and refraction targets, drawn without MSAA; 0 (the default): "
                 "the SDK's 1024 (iWaterTextureSize), or the frame's larger side rounded up to a power of two where "
                 "that is less")
      ->check(CLI::Range(0, 8192))
      ->capture_default_str();
  cmd.add_flag("!--no-color-correction", settings.color_correction,
               "Leave out the scene's color-correction nodes (Source's mat_colorcorrection 0)");
  cmd.add_flag("--no-bloom", no_bloom, "Leave out the bloom (Source's mat_disable_bloom 1)");
  cmd.add_flag("--bloom-true-height", bloom_true_height,
               "Step the vertical bloom blur by 1/height; by default it steps by 1/width, as the SDK's BlurFilterY "
               "does (a quirk: at 16:9 its taps are 0.5625 texels apart vertically)");
  cmd.add_option("--film-grain", film_grain_seed,
                 "Blend film grain seeded by SEED (different each frame of a sequence, the same bytes for any thread count)");
  cmd.add_option("--look", settings.look,
                 "A look over the whole frame: none (the default) or archival (old footage: the builtin:archival grade "
                 "at full weight over the scene's color-correction nodes, and film grain about 1.3 times as strong as "
                 "--film-grain's, seeded by --film-grain's SEED or 0)")
      ->transform(CLI::CheckedTransformer(frame::look_names(), CLI::ignore_case));
  memory.add_to(cmd);
}

std::optional<rasterizer::ContextOptions> FrameOptions::context_options(const std::string& command, int& code) const {
  rasterizer::ContextOptions options;
  options.threads = threads;
  if (const char* off = std::getenv("LUXEL_NO_FASTPATH")) {
    try {
      options.fast_paths = rasterizer::parse_fast_paths_off(off);
    } catch (const std::invalid_argument& e) {
      std::cerr << "luxel " << command << ": LUXEL_NO_FASTPATH: " << e.what() << "\n";
      code = 2;
      return std::nullopt;
    }
  }
  return options;
}

std::optional<scenes::Scene> FrameOptions::prepare_scene(const std::string& command, frame::FrameSettings& frame_settings,
                                                         const std::vector<std::string>& outs, int& code) const {
  const std::optional<uint64_t> memory_limit = memory.bytes(command, code);
  if (!memory_limit) return std::nullopt;
  frame_settings.memory_limit = *memory_limit;
  // The outputs first: a user should not wait for a render to learn it cannot be written.
  for (const std::string& out : outs) {
    const std::filesystem::path path(out), dir = path.parent_path();
    const char* problem = !dir.empty() && !std::filesystem::is_directory(dir) ? "no such folder to write into"
                          : std::filesystem::is_directory(path)              ? "is a folder, not a file to write"
                                                                             : nullptr;
    if (problem) {
      std::cerr << "luxel " << command << ": " << out << ": " << problem << "\n";
      code = 1;
      return std::nullopt;
    }
  }
  scenes::GltfImportOptions gltf;
  gltf.memory_limit = *memory_limit;
  gltf.framing_aspect = float(frame_settings.width) / float(frame_settings.height);
  if (scene.rfind("builtin:", 0) != 0) gltf.camera = std::exchange(frame_settings.camera, 0);
  std::optional<scenes::Scene> loaded =
      load_scene_or_report(command, scene, gltf, {frame_settings.width, frame_settings.height}, code);
  if (!loaded) return std::nullopt;
  frame_settings.time = static_cast<float>(double(frame) / fps);
  try {
    frame::frame_camera(*loaded, frame_settings);
  } catch (const std::invalid_argument& e) {
    std::cerr << "luxel " << command << ": " << e.what() << "\n";
    code = 2;
    return std::nullopt;
  }
  // Before a bake: a frame beyond the memory limit is known from its sizes (the renderer checks
  // again with the bake's maps).
  try {
    frame::check_memory(*loaded, frame_settings);
  } catch (const scenes::MemoryLimitError& e) {
    std::cerr << "luxel " << command << ": " << e.what() << "\n";
    code = 1;
    return std::nullopt;
  }
  if (needs_bake(*loaded)) {
    const std::string folder = default_bake_folder(scene);
    if (folder.empty()) {
      std::cerr << "luxel " << command << ": " << scene
                << " needs a bake and there is no HOME or XDG_CACHE_HOME to keep it in; run luxel bake --out DIR\n";
      code = 2;
      return std::nullopt;
    }
    bake::BakeSettings bake_settings = bake == "quick" ? bake::BakeSettings::quick() : bake::BakeSettings{};
    bake_settings.threads = threads;
    bake_settings.max_memory_bytes = *memory_limit;
    try {
      const frame::CubemapSettings cube_settings = bake == "quick" ? frame::CubemapSettings::quick() : frame::CubemapSettings{};
      bake_and_attach(*loaded, folder, bake_settings, cube_settings, ("luxel " + command).c_str());
    } catch (const std::exception& e) {
      std::cerr << "luxel " << command << ": " << e.what() << "\n";
      code = 1;
      return std::nullopt;
    }
  }
  return loaded;
}

std::unique_ptr<frame::Renderer> FrameOptions::make_renderer(const std::string& command, const scenes::Scene& scene,
                                                             const frame::FrameSettings& settings, rasterizer::Context& ctx,
                                                             int& code, SharedRendering* shared) const {
  try {
    frame::FrameSettings first = settings;
    first.time = 0.0f;
    first.exposure = exposure;
    if (!no_bloom) {
      first.bloom = postfx::BloomOptions{};
      if (bloom_true_height) first.bloom->vertical_step = shading::source::BlurStep::true_height;
    }
    if (film_grain_seed) first.film_grain = postfx::FilmGrainOptions{*film_grain_seed};
    if (shared && !shared->textures) shared->textures = std::make_shared<const frame::SceneTextures>(scene);
    auto renderer = std::make_unique<frame::Renderer>(scene, first, shared ? shared->textures : nullptr);
    const bool carried = renderer->auto_exposure() != nullptr;
    const bool terminal = isatty(STDERR_FILENO);
    if (carried && !unsettled) {
      if (shared && shared->exposure_start) {
        renderer->start_exposure_at(*shared->exposure_start);
      } else {
        const frame::SettledExposure settled = renderer->settle_exposure(ctx);
        std::fprintf(stderr, "luxel %s: auto exposure %s at %.4g after %d draws of the first frame\n", command.c_str(),
                     settled.settled ? "starts settled" : "starts (not settled within its draws)", settled.scale,
                     settled.draws);
        if (shared) shared->exposure_start = settled.scale;
      }
    }
    for (int n = 0; n < frame; ++n) {
      if (carried) {
        renderer->render(ctx);
        if (terminal) std::fprintf(stderr, "\rluxel %s: frames before %d for the exposure: %d/%d", command.c_str(), frame, n + 1, frame);
      }
      renderer->set_time(static_cast<float>(double(n + 1) / fps));
    }
    if (carried && terminal && frame > 0) std::fprintf(stderr, "\n");
    return renderer;
  } catch (const std::invalid_argument& e) {
    std::cerr << "luxel " << command << ": " << e.what() << "\n";
    code = 2;
    return nullptr;
  } catch (const std::runtime_error& e) {  // a file the frame reads (a color-correction LUT)
    std::cerr << "luxel " << command << ": " << e.what() << "\n";
    code = 1;
    return nullptr;
  }
}

}  // namespace luxel::cli
