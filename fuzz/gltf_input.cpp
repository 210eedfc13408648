#include "fuzz_support.hpp"
#include "inputs.hpp"

#include "luxel/scenes/gltf.hpp"

#include <stdexcept>
#include <string>

namespace luxel::fuzz {

void read_gltf_input(std::span<const uint8_t> input) {
  static const std::string path = scratch_path("scene.gltf"), exported = scratch_path("exported.glb");
  write_file(path, input.data(), input.size());
  // Warnings are one line naming the file, like errors: checked instead of printed, so that a run
  // is not spent writing them.
  scenes::GltfImportOptions options;
  options.warn = [](const std::string& line) {
    if (line.rfind(path + ": ", 0) != 0 || line.find('\n') != std::string::npos)
      finding("a warning that is not one line naming the file: " + line);
  };
  scenes::Scene scene;
  try {
    scene = scenes::load_gltf(path, options);
  } catch (const scenes::GltfError& e) {
    expect_one_line_naming(e, path);
    return;
  }
  // What luxel read, it writes, and reads back.
  std::string failure;
  try {
    scenes::save_gltf(scene, exported);
    scenes::GltfImportOptions quiet;  // what luxel writes, its import reads without a warning
    quiet.warn = [](const std::string& line) { throw std::runtime_error("a warning on reading it back: " + line); };
    (void)scenes::load_gltf(exported, quiet);
  } catch (const std::exception& e) {
    failure = e.what();
  }
  if (!failure.empty()) finding("a scene that loaded does not export and load again: " + failure);
}

}  // namespace luxel::fuzz
