// Whole-frame benchmark of the llvmpipe peer's workloads (bench/README.md), printing
// exactly its line format so both run side by side:
//   workload=<name> width=W height=H msaa=S threads=T frames=N median_ms=X min_ms=Y
// or `workload=sponza skipped reason="..."` when W3's glTF file is missing (exit 0, as the peer).
// A frame is what the peer calls a frame: clear, draw, resolve to a 1-sample image. The scenes are
// built (demo and courtyard: and baked, quickly) and the frame prepared (textures uploaded) before
// the clock starts, as the peer generates its vertex buffers first. W1 `fill` and W2 `tris` (and
// `demo`, `courtyard`) are built-in scenes drawn by frame::Renderer; W3 `sponza` is any glTF file
// drawn by workloads/sponza.hpp with the peer's arguments (--sponza PATH --eye X,Y,Z --target X,Y,Z).
// stderr gets the CPU, the instruction set and the fast paths turned off (LUXEL_NO_FASTPATH).
// The Source frames (demo, courtyard) run the passes on the finished image that their scene and
// the options ask for: auto exposure's histogram and color correction from the scene, bloom and
// film grain with --bloom and --film-grain; --passes times each. Their auto exposure starts settled
// on the view, as `luxel render` starts a still (untimed; stderr says where).

#include "machine.hpp"
#include "sponza.hpp"

#include "luxel/bake/bake.hpp"
#include "luxel/frame/cubemaps.hpp"
#include "luxel/frame/renderer.hpp"
#include "luxel/rasterizer/fast_paths.hpp"
#include "luxel/scenes/builtin.hpp"
#include "luxel/scenes/image_io.hpp"
#include "luxel/shading/shader_model.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace {

double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"luxel frame benchmark (same workloads and output format as the llvmpipe peer)"};
  luxel::frame::FrameSettings settings;
  int threads = 2, frames = 30, warmup = 5;
  bool print_frames = false, passes = false;
  std::string out, model = "ps_3_0";
  std::vector<std::string> workloads;
  std::string sponza_path, eye_text, target_text;
  app.add_option("--width", settings.width)->check(CLI::Range(1, 8192));
  app.add_option("--height", settings.height)->check(CLI::Range(1, 8192));
  app.add_option("--msaa", settings.samples)->check(CLI::IsMember({1, 2, 4, 8}));
  app.add_option("--threads", threads)->check(CLI::Range(1, 256));
  app.add_option("--frames", frames)->check(CLI::Range(1, 100000));
  app.add_option("--warmup", warmup)->check(CLI::Range(0, 100000));
  app.add_option("--out", out, "Directory for the final frame of each workload as PNG");
  app.add_flag("--print-frames", print_frames, "Print every frame time to stderr");
  app.add_option("--model", model, "Shader model of the Source frame (demo, courtyard): ps_2_0, ps_2_b or ps_3_0")
      ->check(CLI::IsMember({"ps_2_0", "ps_2_b", "ps_3_0"}));
  const std::map<std::string, luxel::rasterizer::SamplingRules> sampling{{"hardware", luxel::rasterizer::SamplingRules::hardware},
                                                                        {"ideal", luxel::rasterizer::SamplingRules::ideal}};
  app.add_option("--sampling", settings.sampling,
                 "How the Source frames' 3D passes filter textures: hardware (the default) or ideal (rasterizer/texture.hpp)")
      ->transform(CLI::CheckedTransformer(sampling, CLI::ignore_case));
  app.add_flag("--passes", passes,
               "Then time each pass of the built-in scenes' frames (stderr: median ms per pass, each pass run to its end "
               "before the next and without tile memory, so their sum exceeds the frame's time)");
  bool bloom = false;
  std::optional<uint64_t> film_grain_seed;
  app.add_flag("--bloom", bloom, "Add the bloom to the Source frames (as luxel render does; off in the library's FrameSettings)");
  app.add_option("--film-grain", film_grain_seed, "Blend film grain seeded by SEED onto the Source frames");
  app.add_option("--sponza", sponza_path, "glTF file for the sponza workload (without it the workload is skipped, as the "
                                             "peer skips it without its asset)");
  app.add_option("--eye", eye_text, "Sponza camera position X,Y,Z in glTF space (with --target)");
  app.add_option("--target", target_text, "Sponza camera target X,Y,Z in glTF space (with --eye)");
  app.add_option("workloads", workloads,
                 "fill, tris, sponza (default: the three, as the peer), or a built-in scene: demo, courtyard");
  CLI11_PARSE(app, argc, argv);
  if (workloads.empty()) workloads = {"fill", "tris", "sponza"};
  settings.model = luxel::shading::parse_pixel_model(model);
  if (bloom) settings.bloom = luxel::postfx::BloomOptions{};
  if (film_grain_seed) settings.film_grain = luxel::postfx::FilmGrainOptions{*film_grain_seed};
  luxel::bench::SponzaView view;
  for (auto [text, name, value] : {std::tuple{&eye_text, "--eye", &view.eye}, std::tuple{&target_text, "--target", &view.target}}) {
    if (text->empty()) continue;
    const std::optional<glm::vec3> v = luxel::bench::parse_vec3(*text);
    if (!v) {
      std::fprintf(stderr, "luxel_frame_bench: %s expects X,Y,Z, got '%s'\n", name, text->c_str());
      return 2;
    }
    *value = *v;
  }
  if (eye_text.empty() != target_text.empty()) {
    std::fprintf(stderr, "luxel_frame_bench: --eye and --target must be given together\n");
    return 2;
  }
  luxel::rasterizer::ContextOptions options;
  options.threads = threads;
  if (const char* off = std::getenv("LUXEL_NO_FASTPATH")) {
    try {
      options.fast_paths = luxel::rasterizer::parse_fast_paths_off(off);
    } catch (const std::invalid_argument& e) {
      std::fprintf(stderr, "luxel_frame_bench: LUXEL_NO_FASTPATH: %s\n", e.what());
      return 2;
    }
  }
  std::fprintf(stderr, "%s fast_paths_off=%s\n", luxel::bench::machine_line().c_str(),
               luxel::rasterizer::fast_paths_off_names(options.fast_paths).c_str());
  luxel::rasterizer::Context ctx(options);
  int status = 0;
  for (const std::string& name : workloads) {
    luxel::scenes::Scene scene;
    std::unique_ptr<luxel::frame::Renderer> renderer;
    std::unique_ptr<luxel::bench::SponzaFrame> sponza;
    if (name == "sponza") {
      if (sponza_path.empty()) {
        std::printf("workload=sponza skipped reason=\"no glTF file given (--sponza PATH)\"\n");
        std::fflush(stdout);
        continue;
      }
      if (!std::filesystem::is_regular_file(sponza_path)) {
        std::printf("workload=sponza skipped reason=\"glTF file not found: %s\"\n", sponza_path.c_str());
        std::fflush(stdout);
        continue;
      }
      try {
        const auto t0 = std::chrono::steady_clock::now();
        scene = luxel::bench::load_sponza_scene(sponza_path);
        const auto t1 = std::chrono::steady_clock::now();
        sponza = std::make_unique<luxel::bench::SponzaFrame>(scene, view, settings.width, settings.height, settings.samples);
        const auto t2 = std::chrono::steady_clock::now();
        std::fprintf(stderr, "sponza: %zu draws, %llu triangles, %zu textures; load %.2f s, prepare %.2f s\n",
                     scene.meshes.size(), static_cast<unsigned long long>(sponza->triangles()), scene.textures.size(),
                     std::chrono::duration<double>(t1 - t0).count(), std::chrono::duration<double>(t2 - t1).count());
        std::fprintf(stderr, "sponza: camera eye (%.4f, %.4f, %.4f) target (%.4f, %.4f, %.4f) in glTF space\n", view.eye.x,
                     view.eye.y, view.eye.z, view.target.x, view.target.y, view.target.z);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "luxel_frame_bench: sponza: %s\n", e.what());
        status = 1;
        continue;
      }
    } else {
      try {
        scene = luxel::scenes::make_builtin_scene(name, {settings.width, settings.height});
        // Scenes that need baked data get what `luxel render --bake quick` bakes (the lightmaps,
        // the irradiance volume and the cube maps), before the clock and not timed.
        if (name == "demo" || name == "courtyard") {
          luxel::bake::attach(scene, luxel::bake::bake(scene, luxel::bake::BakeSettings::quick()));
          luxel::frame::attach_cubemaps(scene, luxel::frame::bake_cubemaps(scene, luxel::frame::CubemapSettings::quick(), ctx));
        }
        renderer = std::make_unique<luxel::frame::Renderer>(scene, settings);
        // As luxel render starts a still: auto exposure settled on the view (untimed).
        if (const luxel::frame::SettledExposure s = renderer->settle_exposure(ctx); s.draws > 0)
          std::fprintf(stderr, "%s: auto exposure starts settled at %.4g after %d draws\n", name.c_str(), s.scale, s.draws);
      } catch (const std::exception& e) {
        std::printf("workload=%s skipped reason=\"%s\"\n", name.c_str(), e.what());
        continue;
      }
    }
    const std::function<void()> render = [&] { renderer ? renderer->render(ctx) : sponza->render(ctx); };
    for (int i = 0; i < warmup; ++i) render();
    std::vector<double> ms;
    for (int i = 0; i < frames; ++i) {
      const auto t0 = std::chrono::steady_clock::now();
      render();
      const auto t1 = std::chrono::steady_clock::now();
      ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
      if (print_frames) std::fprintf(stderr, "%s frame %d: %.3f ms\n", name.c_str(), i, ms.back());
    }
    std::vector<double> sorted = ms;
    std::sort(sorted.begin(), sorted.end());
    std::printf("workload=%s width=%d height=%d msaa=%d threads=%d frames=%d median_ms=%.3f min_ms=%.3f\n",
                name.c_str(), settings.width, settings.height, settings.samples, threads, frames, median_of(ms), sorted[0]);
    std::fflush(stdout);
    if (passes && renderer) {
      luxel::frame::FrameSettings timed = settings;
      timed.time_passes = true;
      luxel::frame::Renderer per_pass(scene, timed);
      per_pass.settle_exposure(ctx);
      std::vector<std::pair<std::string, std::vector<double>>> pass_ms;
      for (int i = 0; i < warmup + frames; ++i) {
        per_pass.render(ctx);
        if (i < warmup) continue;
        for (const luxel::frame::PassTime& p : per_pass.pass_times()) {
          auto it = std::find_if(pass_ms.begin(), pass_ms.end(), [&](const auto& e) { return e.first == p.pass; });
          if (it == pass_ms.end()) it = pass_ms.insert(pass_ms.end(), {p.pass, {}});
          it->second.push_back(p.ms);
        }
      }
      std::fprintf(stderr, "%s %s passes median_ms:", name.c_str(), model.c_str());
      for (const auto& [pass, times] : pass_ms) std::fprintf(stderr, " %s=%.3f", pass.c_str(), median_of(times));
      std::fprintf(stderr, "\n");
    }
    if (!out.empty()) {
      const std::string path = out + "/" + name + "_" + std::to_string(settings.width) + "x" +
                               std::to_string(settings.height) + "_msaa" + std::to_string(settings.samples) + "_t" +
                               std::to_string(threads) + ".png";
      try {
        std::filesystem::create_directories(out);  // as the peer harness does
        const luxel::rasterizer::Image& image = renderer ? renderer->image() : sponza->image();
        luxel::scenes::write_image(image.width, image.height, image.rgba, path);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "luxel_frame_bench: %s: %s\n", path.c_str(), e.what());
        return 1;
      }
    }
  }
  return status;
}
