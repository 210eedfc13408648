#pragma once
// `--scene SCENE [--camera N]`, shared by the commands that read a scene (render and compare take
// theirs from frame_options.hpp), and how they all report a scene that cannot be read: one line,
// exit 2 for an argument that names no scene, 1 for a file that cannot be read.

#include "luxel/scenes/load.hpp"
#include "memory_limit_option.hpp"

#include <CLI/CLI.hpp>

#include <iostream>
#include <optional>
#include <string>

namespace luxel::cli {

/// Whether any mesh of the scene has a triangle: a file that places none would be an empty frame.
inline bool draws_something(const scenes::Scene& scene) {
  for (const scenes::Mesh& m : scene.meshes)
    if (m.triangle_count() > 0) return true;
  return false;
}

/// scenes::load_scene(arg, gltf, builtin), or nullopt after printing one line and setting `code`:
/// a file that cannot be read, or that has nothing to draw. Warnings go to standard error, one line
/// each after "luxel COMMAND: warning: ".
inline std::optional<scenes::Scene> load_scene_or_report(const std::string& command, const std::string& arg,
                                                         scenes::GltfImportOptions gltf,
                                                         const scenes::BuiltinOptions& builtin, int& code) {
  if (!gltf.warn) gltf.warn = [command](const std::string& line) { std::cerr << "luxel " << command << ": warning: " << line << "\n"; };
  try {
    scenes::Scene scene = scenes::load_scene(arg, gltf, builtin);
    if (draws_something(scene)) return scene;
    std::cerr << "luxel " << command << ": " << arg << ": nothing to draw: its scene places no triangles\n";
    code = 1;
  } catch (const scenes::SceneArgumentError& e) {
    std::cerr << "luxel " << command << ": --scene " << e.what() << "\n";
    code = 2;
  } catch (const std::exception& e) {
    std::cerr << "luxel " << command << ": " << e.what() << "\n";
    code = 1;
  }
  return std::nullopt;
}

struct SceneArgument {
  std::string scene;
  int camera = 0;
  MemoryLimitOption memory;

  void add_to(CLI::App& cmd) {
    cmd.add_option("--scene", scene, "Scene: FILE.gltf, FILE.glb or builtin:NAME")->required();
    cmd.add_option("--camera", camera, "The file's camera to use first (index into its cameras)")
        ->check(CLI::Range(0, 1 << 20))
        ->capture_default_str();
    memory.add_to(cmd);
  }

  /// The scene, or nullopt after printing one line and setting `code`.
  std::optional<scenes::Scene> load(const std::string& command, int& code) const {
    scenes::GltfImportOptions options;
    options.camera = camera;
    const std::optional<uint64_t> limit = memory.bytes(command, code);
    if (!limit) return std::nullopt;
    options.memory_limit = *limit;
    return load_scene_or_report(command, scene, options, {}, code);
  }
};

}  // namespace luxel::cli
