#include "fuzz_support.hpp"
#include "inputs.hpp"

#include "luxel/scenes/gltf.hpp"

namespace luxel::fuzz {

void read_gltf_input(std::span<const uint8_t> input) {
  static const std::string path = scratch_path("scene.gltf"), exported = scratch_path("exported.glb");
  write_file(path, input.data(), input.size());
  scenes::Scene scene;
  try {
    scene = scenes::load_gltf(path);
  } catch (const scenes::GltfError& e) {
    expect_one_line_naming(e, path);
    return;
  }
  // What luxel read, it writes, and reads back.
  std::string failure;
  try {
    scenes::save_gltf(scene, exported);
    (void)scenes::load_gltf(exported);
  } catch (const std::exception& e) {
    failure = e.what();
  }
  if (!failure.empty()) finding("a scene that loaded does not export and load again: " + failure);
}

}  // namespace luxel::fuzz
