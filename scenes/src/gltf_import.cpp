// load_gltf: tinygltf parses, luxel's layer (gltf_accessors.hpp) checks and reads, the importer
// (gltf_importer.hpp, a file per stage) turns the node hierarchy into a flat Scene in Source units
// (gltf.hpp documents every mapping). This file runs the stages in order and reports their errors.

#include "gltf_importer.hpp"
#include "gltf_materials.hpp"
#include "one_line.hpp"
#include "luxel/scenes/gltf.hpp"
#include "luxel/scenes/memory_limit.hpp"

#include <filesystem>
#include <iostream>

namespace luxel::scenes {

GltfError::GltfError(const std::string& what) : std::runtime_error(one_line(what)) {}

namespace gltf {

namespace fs = std::filesystem;

Importer::Importer(const std::string& path, const GltfImportOptions& options) : path_(path), options_(options) {
  dir_ = fs::path(path).parent_path().string();
  if (dir_.empty()) dir_ = ".";
}

Scene Importer::run() {
  parse();
  decode_compressed();
  Accessors accessors(model_, path_);
  accessors_ = &accessors;
  scene_.name = path_;
  images_.resize(model_.images.size());
  for (size_t i = 0; i < model_.materials.size(); ++i)
    scene_.materials.push_back(gltf::material_from_gltf(
        model_.materials[i], i, [this](int t, ColorSpace cs, const std::string& where) { return texture(t, cs, where); },
        [this](const std::string& what) { fail(what); }));
  walk_nodes();
  order_cameras();
  add_defaults();
  try {
    validate(scene_);
  } catch (const std::invalid_argument& e) {
    throw GltfError(e.what());  // validate names the scene, which is the file
  }
  return std::move(scene_);
}

[[noreturn]] void Importer::fail(const std::string& what) const { throw GltfError(path_ + ": " + what); }

void Importer::warn(const std::string& what) const {
  const std::string line = one_line(path_ + ": " + what);
  if (options_.warn) options_.warn(line);
  else std::cerr << "luxel: warning: " << line << "\n";
}

/// The memory limit's check (memory_limit.hpp), its refusal a GltfError like every problem here.
void Importer::check_memory(uint64_t needed, const std::string& what) const {
  try {
    scenes::check_memory(path_, needed, what, options_.memory_limit);
  } catch (const MemoryLimitError& e) {
    throw GltfError(e.what());
  }
}

uint64_t Importer::buffer_bytes() const {
  uint64_t bytes = 0;
  for (const tinygltf::Buffer& b : model_.buffers) bytes += b.data.size();
  return bytes;
}

}  // namespace gltf

Scene load_gltf(const std::string& path, const GltfImportOptions& options) { return gltf::Importer(path, options).run(); }

}  // namespace luxel::scenes
