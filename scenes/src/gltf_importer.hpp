#pragma once
// The glTF importer (load_gltf) shared by the files of its stages: the driver (gltf_import.cpp),
// parsing (gltf_parse.cpp), images and textures (gltf_textures.cpp), nodes and animation
// (gltf_nodes.cpp), meshes and primitives (gltf_primitives.cpp), cameras and lights
// (gltf_cameras_lights.cpp).

#include "gltf_accessors.hpp"
#include "luxel/scenes/gltf.hpp"
#include "luxel/scenes/image_io.hpp"
#include "luxel/scenes/scene.hpp"
#include "tinygltf.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace luxel::scenes::gltf {

/// Why a (decoded) URI does not name a file inside the glTF's folder, or "" if it does
/// (gltf_parse.cpp).
std::string unconfined(const std::string& uri);

inline bool finite(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

/// Within 1e-9 of the identity: what luxel's own exports compose to (their root node undoes the
/// import's unit and axis conversion), so values are copied bit for bit.
inline bool is_identity(const glm::dmat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (std::abs(m[c][r] - (c == r ? 1.0 : 0.0)) > 1e-9) return false;
  return true;
}

class Importer {
 public:
  Importer(const std::string& path, const GltfImportOptions& options);
  Scene run();

 private:
  // The driver (gltf_import.cpp): errors, warnings, the memory limit.
  [[noreturn]] void fail(const std::string& what) const;
  void warn(const std::string& what) const;
  void check_memory(uint64_t needed, const std::string& what) const;
  uint64_t buffer_bytes() const;

  // Parsing (gltf_parse.cpp): the file, its JSON, tinygltf on a confined file system.
  std::vector<uint8_t> read_whole(const std::string& file, const std::string& what);
  void check_glb(const std::vector<uint8_t>& b) const;
  void parse();
  static std::string_view glb_json(const std::vector<uint8_t>& b);
  std::optional<std::string> check_json(std::string_view text, bool glb);
  void check_extensions(const nlohmann::json& doc);
  void decode_compressed();
  void take_out_draco_indices(const nlohmann::json& doc, nlohmann::json& copy);
  static void stub_fallback_buffers(const nlohmann::json& doc, nlohmann::json& copy);
  static std::vector<uint8_t> with_glb_json(const std::vector<uint8_t>& bytes, const std::string& json);
  static bool file_exists(const std::string& abs, void* user);
  static std::string expand_path(const std::string& path, void*);
  static bool read_file(std::vector<unsigned char>* out, std::string* err, const std::string& abs, void* user);
  static bool write_file(std::string*, const std::string&, const std::vector<unsigned char>&, void*);
  std::string folder_prefix() const;
  void record(const std::string& what);
  static bool collect_image(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                            const unsigned char* bytes, int size, void* user);

  // Images and textures (gltf_textures.cpp).
  const PixelImage& image(int index, const std::string& where);
  int texture(int index, ColorSpace color_space, const std::string& where);

  // Nodes and animation (gltf_nodes.cpp).
  /// A translation animation moving a node and everything under it: the channel, the world
  /// matrix of the animated node's parent, the node's own translation at rest.
  struct Motion {
    int channel = -1;
    glm::dmat4 parent{1.0};
    glm::dvec3 rest{0.0};
  };

  glm::dmat4 local_matrix(const tinygltf::Node& n, const std::string& where) const;
  std::vector<int> translation_channels() const;
  std::vector<ModelKey> animated_path(const Motion& motion, const std::string& node) const;
  void walk_nodes();
  std::string node_name(int index) const;

  // Meshes and primitives (gltf_primitives.cpp).
  /// The vertices and triangle corners a mesh will have once read, and the bytes they take as read
  /// and as kept (each attribute read as floats, then copied into the Mesh; the corners as 32-bit
  /// indices, then kept in up to 32 bits).
  struct Flattened { uint64_t vertices = 0, indices = 0, bytes = 0; };

  Flattened flattened(int mesh) const;
  void add_mesh(int index, const glm::dmat4& world, const std::string& node, const tinygltf::Value& luxel, const Motion& motion);
  Mesh primitive(const tinygltf::Primitive& p, const glm::dmat4& world, const std::string& where);

  // Cameras and lights (gltf_cameras_lights.cpp).
  static glm::vec3 point(const glm::dmat4& m, glm::dvec3 p);
  static glm::vec3 direction(const glm::dmat4& m, glm::dvec3 d);
  void add_camera(int index, const glm::dmat4& world, const std::string& node);
  void add_light(int index, const glm::dmat4& world, const std::string& node);
  void order_cameras();
  void add_defaults();

  std::string path_, dir_;
  const GltfImportOptions& options_;
  tinygltf::Model model_;
  const Accessors* accessors_ = nullptr;
  std::map<int, std::vector<uint8_t>> data_uri_images_;
  struct DracoIndices { size_t mesh, primitive; int accessor; };
  std::vector<DracoIndices> draco_indices_;
  std::string fs_error_;
  std::vector<std::optional<PixelImage>> images_;
  // What the memory limit counts as the file is read: its files' bytes, its images' pixels.
  uint64_t file_bytes_ = 0, image_bytes_ = 0;
  int images_read_ = 0;
  std::map<std::pair<int, ColorSpace>, int> textures_;
  std::vector<std::pair<int, Camera>> cameras_;
  Scene scene_;
};

}  // namespace luxel::scenes::gltf
