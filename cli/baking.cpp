#include "baking.hpp"

#include "luxel/bake/storage.hpp"

#include <unistd.h>

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
  return (lightmapped && !scene.lightmaps) || (vertexlit && volume_empty);
}

void bake_and_attach(scenes::Scene& scene, const std::string& folder, const bake::BakeSettings& settings,
                     const char* command) {
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
}

}  // namespace luxel::cli
