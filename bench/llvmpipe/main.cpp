// luxel_llvmpipe_bench: the peer's side of luxel's frame benchmark. Mesa's llvmpipe draws the
// workloads luxel_frame_bench draws (W1 fill, W2 tris, W3 sponza, W4 source; bench/README.md),
// through OpenGL on EGL's surfaceless platform, and prints luxel_frame_bench's line per workload:
//   workload=<name> width=W height=H msaa=S threads=T frames=N median_ms=X min_ms=Y
// or `workload=<name> skipped reason="..."` when its input is missing (exit 0). Diagnostics (the
// renderer string, the samples obtained) go to stderr. scripts/bench runs it beside luxel.

#include "frame_loop.hpp"
#include "gl_context.hpp"
#include "render_targets.hpp"
#include "workload_fill.hpp"
#include "workload_source.hpp"
#include "workload_sponza.hpp"
#include "workload_tris.hpp"

#include "luxel/scenes/image_io.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace {

using namespace luxel::llvmpipe;

struct Options {
  int width = 1280, height = 720, samples = 4, frames = 30, warmup = 5;
  std::optional<int> threads;
  std::string out, sponza, eye, target, source;
  int camera = 0;
  float exposure = 1.0f;
  bool print_frames = false;
  std::vector<std::string> workloads;
};

/// llvmpipe reads LP_NUM_THREADS when the context is created: --threads wins, then the
/// environment, then 2 (the measuring machines' core count).
int set_thread_count(const Options& options) {
  if (options.threads) {
    setenv("LP_NUM_THREADS", std::to_string(*options.threads).c_str(), 1);
    return *options.threads;
  }
  if (const char* set = std::getenv("LP_NUM_THREADS")) return std::atoi(set);
  setenv("LP_NUM_THREADS", "2", 1);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"llvmpipe's side of luxel's frame benchmark: W1 fill, W2 tris, W3 sponza, W4 source (bench/README.md)"};
  Options o;
  app.add_option("--width", o.width)->check(CLI::Range(1, 8192));
  app.add_option("--height", o.height)->check(CLI::Range(1, 8192));
  app.add_option("--msaa", o.samples, "Samples of framebuffer A (llvmpipe has 1 and 4; 2 gets 4)")->check(CLI::Range(1, 64));
  app.add_option("--threads", o.threads, "LP_NUM_THREADS (default: the environment's, else 2)")->check(CLI::Range(1, 256));
  app.add_option("--frames", o.frames)->check(CLI::Range(1, 100000));
  app.add_option("--warmup", o.warmup)->check(CLI::Range(0, 100000));
  app.add_option("--out", o.out, "Directory for the final frame of each workload as PNG");
  app.add_flag("--print-frames", o.print_frames, "Print every frame time to stderr");
  app.add_option("--sponza", o.sponza, "glTF file for W3 (without it W3 is skipped)");
  app.add_option("--eye", o.eye, "W3 camera position X,Y,Z in glTF space (with --target)");
  app.add_option("--target", o.target, "W3 camera target X,Y,Z in glTF space (with --eye)");
  app.add_option("--source", o.source, "W4's glTF file, written by luxel export and baked by luxel bake (without it W4 is skipped)");
  app.add_option("--camera", o.camera, "W4: the glTF camera to draw from")->check(CLI::Range(0, 1 << 20));
  app.add_option("--exposure", o.exposure, "W4: the tone-map scale S")->check(CLI::PositiveNumber);
  app.add_option("workloads", o.workloads, "fill, tris, sponza, source or all (default: all four)")
      ->check(CLI::IsMember({"fill", "tris", "sponza", "source", "all"}));
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "luxel_llvmpipe_bench: %s\n", e.what());
    return 2;
  }
  luxel::bench::SponzaView view;
  for (auto [text, name, value] : {std::tuple{&o.eye, "--eye", &view.eye}, std::tuple{&o.target, "--target", &view.target}}) {
    if (text->empty()) continue;
    const std::optional<glm::vec3> v = luxel::bench::parse_vec3(*text);
    if (!v) {
      std::fprintf(stderr, "luxel_llvmpipe_bench: %s expects X,Y,Z, got '%s'\n", name, text->c_str());
      return 2;
    }
    *value = *v;
  }
  if (o.eye.empty() != o.target.empty()) {
    std::fprintf(stderr, "luxel_llvmpipe_bench: --eye and --target must be given together\n");
    return 2;
  }
  std::vector<std::string> names;
  for (const std::string& w : o.workloads.empty() ? std::vector<std::string>{"all"} : o.workloads) {
    if (w == "all")
      names.insert(names.end(), {"fill", "tris", "sponza", "source"});
    else
      names.push_back(w);
  }

  const int threads = set_thread_count(o);
  try {
    GlContext context;
    std::fprintf(stderr, "renderer=\"%s\" version=\"%s\" LP_NUM_THREADS=%d\n", GlContext::renderer().c_str(),
                 GlContext::version().c_str(), threads);
    const RenderTargets targets(o.width, o.height, o.samples);
    if (targets.samples() != o.samples)
      std::fprintf(stderr, "luxel_llvmpipe_bench: asked for msaa %d, the driver gave %d\n", o.samples, targets.samples());
    if (!o.out.empty()) std::filesystem::create_directories(o.out);

    for (const std::string& name : names) {
      std::unique_ptr<Workload> workload;
      try {
        if (name == "fill") workload = make_fill();
        else if (name == "tris") workload = make_tris(o.width, o.height);
        else if (name == "sponza") workload = make_sponza(o.sponza, view, o.width, o.height);
        else workload = make_source(SourceOptions{o.source, o.camera, o.exposure}, o.width, o.height);
      } catch (const Skipped& e) {
        std::printf("workload=%s skipped reason=\"%s\"\n", name.c_str(), e.what());
        std::fflush(stdout);
        continue;
      }
      const std::vector<double> times = time_frames(*workload, targets, o.warmup, o.frames);
      check_gl(name.c_str());
      if (o.print_frames)
        for (size_t i = 0; i < times.size(); ++i) std::fprintf(stderr, "%s frame %zu: %.3f ms\n", name.c_str(), i, times[i]);
      const FrameStats stats = stats_of(times);
      std::printf("workload=%s width=%d height=%d msaa=%d threads=%d frames=%d median_ms=%.3f min_ms=%.3f\n", name.c_str(),
                  o.width, o.height, targets.samples(), threads, o.frames, stats.median_ms, stats.min_ms);
      std::fflush(stdout);
      if (!o.out.empty()) {
        const std::string path = o.out + "/" + name + "_" + std::to_string(o.width) + "x" + std::to_string(o.height) + "_msaa" +
                                 std::to_string(targets.samples()) + "_t" + std::to_string(threads) + ".png";
        luxel::scenes::write_image(o.width, o.height, targets.read_image(), path);
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "luxel_llvmpipe_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
