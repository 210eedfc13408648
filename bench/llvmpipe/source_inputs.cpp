// Reading W4's scene and its bake through luxel's libraries, as `luxel render` reads them.

#include "source_inputs.hpp"

#include "workload.hpp"

#include "luxel/bake/bake.hpp"
#include "luxel/bake/cubemap_storage.hpp"
#include "luxel/bake/storage.hpp"
#include "luxel/frame/cubemaps.hpp"
#include "luxel/scenes/gltf.hpp"
#include "luxel/scenes/load.hpp"

#include <filesystem>
#include <optional>

namespace luxel::llvmpipe {

scenes::Scene load_baked_scene(const std::string& path, int camera) {
  if (path.empty()) throw Skipped("no glTF file given (--source PATH)");
  if (!std::filesystem::is_regular_file(path)) throw Skipped("glTF file not found: " + path);
  scenes::GltfImportOptions gltf;
  gltf.camera = camera;
  scenes::Scene scene = scenes::load_scene(path, gltf);

  const std::string folder = std::filesystem::path(path).replace_extension(".bake").string();
  if (!std::filesystem::is_regular_file(folder + "/bake.json"))
    throw Skipped("no bake: " + folder + "/bake.json is missing (luxel bake --scene " + path + ")");
  // The default settings are `luxel bake`'s: the stored bake is found by the hash of the scene and
  // them, so a bake of other inputs is never read as this one's.
  const std::optional<bake::BakeResult> result = bake::load_bake(folder, scene, bake::BakeSettings{});
  if (!result) throw Skipped("the bake in " + folder + " is of other inputs (luxel bake --scene " + path + ")");
  bake::attach(scene, *result);
  if (!scene.cubemap_samples.empty()) {
    std::optional<bake::StoredCubemaps> cubes =
        bake::load_cubemaps(folder, frame::cubemap_input_hash(scene, frame::CubemapSettings{}));
    if (!cubes) throw Skipped("no cube maps of these inputs in " + folder + " (luxel bake --scene " + path + ")");
    frame::attach_cubemaps(scene, std::move(cubes->cubes));
  }
  return scene;
}

}  // namespace luxel::llvmpipe
