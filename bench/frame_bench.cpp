// Whole-frame benchmark of the built-in workloads, printing exactly the line format of the
// llvmpipe peer (../shared/peers/llvmpipe) so both run side by side:
//   workload=<name> width=W height=H msaa=S threads=T frames=N median_ms=X min_ms=Y
// A frame is what the peer calls a frame: clear, draw, resolve to a 1-sample image. The scenes are
// built (demo and courtyard: and baked, quickly) and the renderer prepared (textures uploaded)
// before the clock starts, as the peer generates its vertex buffers first.
// stderr gets the CPU, the instruction set and the fast paths turned off (LUXEL_NO_FASTPATH).

#include "machine.hpp"

#include "luxel/bake/bake.hpp"
#include "luxel/frame/renderer.hpp"
#include "luxel/rasterizer/fast_paths.hpp"
#include "luxel/scenes/builtin.hpp"
#include "luxel/scenes/image_io.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  CLI::App app{"luxel frame benchmark (same workloads and output format as the llvmpipe peer)"};
  luxel::frame::FrameSettings settings;
  int threads = 2, frames = 30, warmup = 5;
  bool print_frames = false;
  std::string out;
  std::vector<std::string> workloads;
  app.add_option("--width", settings.width)->check(CLI::Range(1, 8192));
  app.add_option("--height", settings.height)->check(CLI::Range(1, 8192));
  app.add_option("--msaa", settings.samples)->check(CLI::IsMember({1, 2, 4, 8}));
  app.add_option("--threads", threads)->check(CLI::Range(1, 256));
  app.add_option("--frames", frames)->check(CLI::Range(1, 100000));
  app.add_option("--warmup", warmup)->check(CLI::Range(0, 100000));
  app.add_option("--out", out, "Directory for the final frame of each workload as PNG");
  app.add_flag("--print-frames", print_frames, "Print every frame time to stderr");
  app.add_option("workloads", workloads, "Built-in scenes: fill, tris (default: both), demo, courtyard");
  CLI11_PARSE(app, argc, argv);
  if (workloads.empty()) workloads = {"fill", "tris"};

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
  for (const std::string& name : workloads) {
    luxel::scenes::Scene scene;
    std::unique_ptr<luxel::frame::Renderer> renderer;
    try {
      scene = luxel::scenes::make_builtin_scene(name, {settings.width, settings.height});
      // Scenes that need baked data get a quick bake, before the clock and not timed.
      if (name == "demo" || name == "courtyard")
        luxel::bake::attach(scene, luxel::bake::bake(scene, luxel::bake::BakeSettings::quick()));
      renderer = std::make_unique<luxel::frame::Renderer>(scene, settings);
    } catch (const std::exception& e) {
      std::printf("workload=%s skipped reason=\"%s\"\n", name.c_str(), e.what());
      continue;
    }
    for (int i = 0; i < warmup; ++i) renderer->render(ctx);
    std::vector<double> ms;
    for (int i = 0; i < frames; ++i) {
      const auto t0 = std::chrono::steady_clock::now();
      renderer->render(ctx);
      const auto t1 = std::chrono::steady_clock::now();
      ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
      if (print_frames) std::fprintf(stderr, "%s frame %d: %.3f ms\n", name.c_str(), i, ms.back());
    }
    std::vector<double> sorted = ms;
    std::sort(sorted.begin(), sorted.end());
    const size_t n = sorted.size();
    const double median = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
    std::printf("workload=%s width=%d height=%d msaa=%d threads=%d frames=%d median_ms=%.3f min_ms=%.3f\n",
                name.c_str(), settings.width, settings.height, settings.samples, threads, frames, median, sorted[0]);
    std::fflush(stdout);
    if (!out.empty()) {
      const std::string path = out + "/" + name + "_" + std::to_string(settings.width) + "x" +
                               std::to_string(settings.height) + "_msaa" + std::to_string(settings.samples) + "_t" +
                               std::to_string(threads) + ".png";
      try {
        std::filesystem::create_directories(out);  // as the peer harness does
        const luxel::rasterizer::Image& image = renderer->image();
        luxel::scenes::write_image(image.width, image.height, image.rgba, path);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "luxel_frame_bench: %s: %s\n", path.c_str(), e.what());
        return 1;
      }
    }
  }
  return 0;
}
