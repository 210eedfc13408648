// luxel export --scene SCENE --out FILE.gltf|FILE.glb [--camera N]: writes the scene as glTF 2.0
// (scenes/gltf.hpp: geometry re-imports bit for bit, Source materials in extras).

#include "commands.hpp"
#include "scene_argument.hpp"

#include "luxel/scenes/gltf.hpp"

#include <iostream>
#include <memory>

namespace luxel::cli {

namespace {
struct ExportOptions {
  SceneArgument scene;
  std::string out;
};

}  // namespace

Runner add_export_command(CLI::App& app) {
  auto options = std::make_shared<ExportOptions>();
  CLI::App* cmd = app.add_subcommand("export", "Write a scene as glTF 2.0 (.gltf with embedded data, or .glb)");
  options->scene.add_to(*cmd);
  cmd->add_option("--out", options->out, "Output file: FILE.gltf or FILE.glb")->required();
  return [cmd, options]() -> int {
    if (!cmd->parsed()) return -1;
    if (!scenes::has_extension(options->out, ".gltf") && !scenes::has_extension(options->out, ".glb")) {
      std::cerr << "luxel export: --out " << options->out << ": the name must end in .gltf or .glb\n";
      return 2;
    }
    int code = 0;
    const std::optional<scenes::Scene> scene = options->scene.load("export", code);
    if (!scene) return code;
    try {
      scenes::save_gltf(*scene, options->out);
    } catch (const std::exception& e) {
      std::cerr << "luxel export: " << e.what() << "\n";
      return 1;
    }
    return 0;
  };
}

}  // namespace luxel::cli
