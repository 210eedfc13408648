#include "baking.hpp"

#include "luxel/bake/cubemap_storage.hpp"
#include "luxel/bake/folder_lock.hpp"
#include "luxel/bake/storage.hpp"

#include <unistd.h>

#include <algorithm>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>

namespace luxel::cli {

std::string default_bake_folder(const std::string& scene) {
  namespace fs = std::filesystem;
  if (scene.rfind("builtin:", 0) == 0) {
    std::string base;
    if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) base = x;
    else if (const char* h = std::getenv("HOME"); h && *h) base = std::string(h) + "/.cache";
    else return {};
    return (fs::path(base) / "luxel" / "bake" / scene.substr(8)).string();
  }
  fs::path p(scene);
  p.replace_extension(".bake");
  return p.string();
}

std::string ray_rate(double rays, double seconds) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f Mrays/s", seconds > 0 ? rays / seconds * 1e-6 : 0.0);
  return b;
}

bake::ProgressFn bake_progress_printer() {
  const bool tty = isatty(STDERR_FILENO) != 0;
  return [tty](const bake::Progress& p) {
    char line[256];
    if (tty) {
      const double left = p.done > 0 && p.done < p.total ? p.seconds * double(p.total - p.done) / double(p.done) : 0.0;
      std::snprintf(line, sizeof line, "\r\033[Kluxel bake: %.*s: %llu/%llu, %s, %.1f s, %.0f s left", int(p.phase.size()),
                    p.phase.data(), static_cast<unsigned long long>(p.done), static_cast<unsigned long long>(p.total),
                    ray_rate(double(p.rays), p.seconds).c_str(), p.seconds, left);
      std::cerr << line << (p.finished ? "\n" : "") << std::flush;
    } else if (p.finished) {
      std::snprintf(line, sizeof line, "luxel bake: %.*s: %llu done, %llu rays in %.2f s (%s)\n", int(p.phase.size()),
                    p.phase.data(), static_cast<unsigned long long>(p.total), static_cast<unsigned long long>(p.rays),
                    p.seconds, ray_rate(double(p.rays), p.seconds).c_str());
      std::cerr << line << std::flush;
    }
  };
}

bool needs_bake(const scenes::Scene& scene) {
  bool lightmapped = false, vertexlit = false;
  for (const scenes::Mesh& m : scene.meshes) {
    if (m.material < 0) {
      vertexlit = true;  // the default material is VertexLitGeneric
      continue;
    }
    const scenes::ShaderFamily f = scene.materials[static_cast<size_t>(m.material)].family;
    lightmapped = lightmapped || f == scenes::ShaderFamily::lightmapped_generic;
    vertexlit = vertexlit || f == scenes::ShaderFamily::vertexlit_generic;
  }
  const bool volume_empty = scene.irradiance_volume && scene.irradiance_volume->cubes.empty();
  const bool cube_missing = std::any_of(scene.cubemap_samples.begin(), scene.cubemap_samples.end(),
                                        [](const scenes::CubemapSample& s) { return s.texture < 0; });
  return (lightmapped && !scene.lightmaps) || (vertexlit && volume_empty) || cube_missing;
}

bake::FolderLock lock_bake_folder(const std::string& folder, const char* command) {
  return bake::FolderLock(folder, [&] {
    std::cerr << command << ": another luxel is baking into " << folder << "; waiting for it\n" << std::flush;
  });
}

void bake_and_attach(scenes::Scene& scene, const std::string& folder, const bake::BakeSettings& settings,
                     const frame::CubemapSettings& cube_settings, const char* command) {
  const bake::FolderLock lock = lock_bake_folder(folder, command);
  std::optional<bake::BakeResult> result;
  try {
    result = bake::load_bake(folder, scene, settings);
  } catch (const std::exception& e) {
    std::cerr << command << ": warning: " << e.what() << "; baking again\n";  // a damaged bake is replaced
  }
  if (!result) {
    std::cerr << command << ": " << scene.name << " needs a bake; baking into " << folder << "\n";
    result = bake::bake(scene, settings, bake_progress_printer());
    for (const std::string& w : result->warnings) std::cerr << command << ": bake warning: " << w << "\n";
    bake::save_bake(*result, scene, settings, folder);
  }
  bake::attach(scene, *result);
  bake_and_attach_cubemaps(scene, folder, cube_settings, settings.threads, command);
}

bool bake_and_attach_cubemaps(scenes::Scene& scene, const std::string& folder, const frame::CubemapSettings& settings,
                              int threads, const char* command, bool force) {
  if (scene.cubemap_samples.empty()) return false;
  const uint64_t hash = frame::cubemap_input_hash(scene, settings);
  std::optional<bake::StoredCubemaps> stored;
  if (!force) {
    try {
      stored = bake::load_cubemaps(folder, hash);
    } catch (const std::exception& e) {
      std::cerr << command << ": warning: " << e.what() << "; baking them again\n";  // damaged cubes are replaced
    }
  }
  const bool render = !stored;
  if (render) {
    const bool tty = isatty(STDERR_FILENO) != 0;
    const auto start = std::chrono::steady_clock::now();
    auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    stored.emplace();
    stored->exposures = frame::exposure_bracket(scene, settings.stops_apart);
    rasterizer::Context ctx(threads);
    stored->cubes = frame::bake_cubemaps(scene, settings, ctx, [&](int done, int total) {
      if (tty) std::fprintf(stderr, "\r\033[Kluxel bake: cube maps: %d/%d, %.1f s", done, total, seconds());
    });
    std::fprintf(stderr, "%sluxel bake: cube maps: %zu done (%d exposures, %s faces) in %.2f s\n", tty ? "\r\033[K" : "", stored->cubes.size(),
                 int(stored->exposures.size()),
                 settings.face_size > 0 ? (std::to_string(settings.face_size) + "-texel").c_str() : "sample-size", seconds());
    bake::save_cubemaps(*stored, hash, folder);
  }
  frame::attach_cubemaps(scene, std::move(stored->cubes));
  return render;
}

}  // namespace luxel::cli
