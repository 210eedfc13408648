// luxel bake --scene SCENE [--out DIR] [--threads N] [--quick] [--force] [--cubes-all-light]: bakes the scene's RNM
// lightmaps and ambient cubes (bake/bake.hpp) into a folder (bake/storage.hpp), then the HDR cube
// maps at its cube-map samples, rendered with that bake (frame/cubemaps.hpp,
// bake/cubemap_storage.hpp), or reuses what is already there when what it read is unchanged. Default folder: beside a scene file
// (scene.gltf -> scene.bake/), for built-in scenes $XDG_CACHE_HOME/luxel/bake/NAME (or
// ~/.cache/...). Progress on stderr: a live line on a terminal, one plain line per phase otherwise.

#include "baking.hpp"
#include "commands.hpp"
#include "memory_limit_option.hpp"
#include "scene_argument.hpp"

#include "luxel/bake/bake.hpp"
#include "luxel/bake/storage.hpp"
#include "luxel/frame/cubemaps.hpp"
#include "luxel/scenes/load.hpp"

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

namespace luxel::cli {

namespace {

struct BakeOptions {
  std::string scene, out;
  int threads = 0;
  bool quick = false, force = false, cubes_all_light = false;
  MemoryLimitOption memory;
};

}  // namespace

Runner add_bake_command(CLI::App& app) {
  auto o = std::make_shared<BakeOptions>();
  CLI::App* cmd = app.add_subcommand("bake", "Bake RNM lightmaps and ambient cubes (luxel's vrad), then HDR cube maps");
  cmd->add_option("--scene", o->scene, "Scene: FILE.gltf, FILE.glb or builtin:NAME")->required();
  cmd->add_option("--out", o->out, "Bake folder (default: beside the scene file; built-in scenes: ~/.cache/luxel/bake/NAME)");
  cmd->add_option("--threads", o->threads, "Worker threads (default: all cores); never changes the result")
      ->check(CLI::Range(1, 256));
  cmd->add_flag("--quick", o->quick, "Fewer rays, an earlier stop, 16-texel cube maps from fewer exposures: a preview in seconds");
  cmd->add_flag("--force", o->force, "Bake even when the folder holds a bake of the same inputs");
  cmd->add_flag("--cubes-all-light", o->cubes_all_light,
                "Ambient cubes with the lights' direct light too (for comparisons; the engine adds it itself)");
  o->memory.add_to(*cmd);
  return [cmd, o]() -> int {
    if (!cmd->parsed()) return -1;
    int code = 0;
    const std::optional<uint64_t> memory_limit = o->memory.bytes("bake", code);
    if (!memory_limit) return code;
    scenes::GltfImportOptions gltf;
    gltf.memory_limit = *memory_limit;
    std::optional<scenes::Scene> scene = load_scene_or_report("bake", o->scene, gltf, {}, code);
    if (!scene) return code;
    const std::string folder = o->out.empty() ? default_bake_folder(o->scene) : o->out;
    if (folder.empty()) {
      std::cerr << "luxel bake: " << o->scene << ": no HOME or XDG_CACHE_HOME to keep the bake in; give --out DIR\n";
      return 2;
    }
    bake::BakeSettings settings = o->quick ? bake::BakeSettings::quick() : bake::BakeSettings{};
    settings.threads = o->threads;
    settings.cubes_all_light = o->cubes_all_light;
    settings.max_memory_bytes = *memory_limit;
    const frame::CubemapSettings cube_settings = o->quick ? frame::CubemapSettings::quick() : frame::CubemapSettings{};
    try {
      // The folder and its lock first: a bake that cannot be kept is not started.
      const bake::FolderLock lock = lock_bake_folder(folder, "luxel bake");
      std::optional<bake::BakeResult> r;
      if (!o->force) {
        try {
          r = bake::load_bake(folder, *scene, settings);
        } catch (const std::exception& e) {
          std::cerr << "luxel bake: warning: " << e.what() << "; baking again\n";  // a damaged bake is replaced
        }
      }
      const bool lightmaps_baked = !r;
      if (!r) {
        r = bake::bake(*scene, settings, bake_progress_printer());
        for (const std::string& w : r->warnings) std::cerr << "luxel bake: warning: " << w << "\n";
        bake::save_bake(*r, *scene, settings, folder);
        std::printf("%s: baked in %.2f s: lightmaps %dx%d (%llu luxels, %d bounces), %llu ambient cubes, %llu rays (%s) -> %s\n",
                    scene->name.c_str(), r->stats.seconds, r->stats.width, r->stats.height,
                    static_cast<unsigned long long>(r->stats.luxels), r->stats.bounces,
                    static_cast<unsigned long long>(r->stats.cube_samples), static_cast<unsigned long long>(r->stats.rays),
                    ray_rate(double(r->stats.rays), r->stats.seconds).c_str(), folder.c_str());
      }
      // The cube maps render the scene with its bake attached.
      bake::attach(*scene, *r);
      const bool cubes_baked = bake_and_attach_cubemaps(*scene, folder, cube_settings, o->threads, "luxel bake", o->force);
      if (cubes_baked) std::printf("%s: %zu cube maps -> %s\n", scene->name.c_str(), scene->cubemap_samples.size(), folder.c_str());
      if (!lightmaps_baked && !cubes_baked)
        std::printf("%s: up to date in %s (inputs unchanged; --force rebakes)\n", scene->name.c_str(), folder.c_str());
    } catch (const bake::BakeError& e) {
      std::cerr << "luxel bake: " << e.what() << "\n";
      return 1;
    } catch (const std::exception& e) {
      std::cerr << "luxel bake: " << e.what() << "\n";
      return 1;
    }
    return 0;
  };
}

}  // namespace luxel::cli
