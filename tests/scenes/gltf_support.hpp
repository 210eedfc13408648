#pragma once
// Helpers for the glTF tests: a temporary folder, and glTF files built from JSON with their
// buffers as base64 data URIs or side files, so each test states its whole input.

#include "test_paths.hpp"
#include "luxel/scenes/gltf.hpp"
#include "temp_dir.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace luxel::scenes::test {

namespace fs = std::filesystem;

using json = nlohmann::json;

/// Source inches per glTF meter.
inline constexpr double kInches = double(kInchesPerMeter);

/// glTF meters (x, y, z) -> Source inches (x, -z, y) * kInches, each component rounded once from
/// double.
inline glm::vec3 source_inches(double x, double y, double z) {
  return glm::vec3(float(x * kInches), float(-z * kInches), float(y * kInches));
}

/// Import options that add no camera and no lights of their own.
inline GltfImportOptions no_defaults() {
  GltfImportOptions o;
  o.default_camera = o.default_lights = false;
  return o;
}

/// The copied-in assets (tests/data/gltf, see its SOURCES.md).
inline std::string asset(const std::string& relative) { return luxel::test::data_dir() + "/gltf/" + relative; }


inline void write_bytes(const std::string& path, const std::vector<uint8_t>& bytes) {
  fs::create_directories(fs::path(path).parent_path());
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}
inline void write_text(const std::string& path, const std::string& text) {
  fs::create_directories(fs::path(path).parent_path());
  std::ofstream(path, std::ios::binary) << text;
}
inline std::vector<uint8_t> read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), {});
}

inline std::string base64(const std::vector<uint8_t>& b) {
  static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < b.size(); i += 3) {
    const uint32_t v = uint32_t(b[i]) << 16 | (i + 1 < b.size() ? uint32_t(b[i + 1]) << 8 : 0) | (i + 2 < b.size() ? b[i + 2] : 0);
    out += t[v >> 18 & 63];
    out += t[v >> 12 & 63];
    out += i + 1 < b.size() ? t[v >> 6 & 63] : '=';
    out += i + 2 < b.size() ? t[v & 63] : '=';
  }
  return out;
}

/// Bytes of a glTF buffer, appended to with views that the glTF JSON then describes.
struct BufferBuilder {
  std::vector<uint8_t> bytes;
  template <class T>
  size_t add(const std::vector<T>& values) {
    while (bytes.size() % 4) bytes.push_back(0);
    const size_t at = bytes.size();
    bytes.resize(at + values.size() * sizeof(T));
    std::memcpy(bytes.data() + at, values.data(), values.size() * sizeof(T));
    return at;
  }
};

/// A glTF document with one buffer (a data URI), a view per add_accessor call.
struct GltfBuilder {
  json doc = {{"asset", {{"version", "2.0"}}}, {"scene", 0}, {"scenes", json::array({{{"nodes", json::array()}}})},
              {"nodes", json::array()}, {"meshes", json::array()}, {"accessors", json::array()},
              {"bufferViews", json::array()}, {"buffers", json::array()}};
  BufferBuilder buffer;

  /// An accessor over `values` (tightly packed); returns its index.
  template <class T>
  int add_accessor(const std::vector<T>& values, int component_type, const char* type, int components, bool normalized = false) {
    const size_t at = buffer.add(values);
    doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", at}, {"byteLength", values.size() * sizeof(T)}});
    json a = {{"bufferView", doc["bufferViews"].size() - 1}, {"componentType", component_type},
              {"count", values.size() / size_t(components)}, {"type", type}};
    if (normalized) a["normalized"] = true;
    doc["accessors"].push_back(a);
    return int(doc["accessors"].size()) - 1;
  }
  int add_positions(const std::vector<float>& xyz) { return add_accessor(xyz, 5126, "VEC3", 3); }
  int add_floats(const std::vector<float>& v, const char* type, int n) { return add_accessor(v, 5126, type, n); }

  /// A mesh of one primitive; returns the mesh index.
  int add_mesh(json attributes, int indices = -1, int mode = -1, int material = -1) {
    json p = {{"attributes", attributes}};
    if (indices >= 0) p["indices"] = indices;
    if (mode >= 0) p["mode"] = mode;
    if (material >= 0) p["material"] = material;
    doc["meshes"].push_back({{"primitives", json::array({p})}});
    return int(doc["meshes"].size()) - 1;
  }
  /// A node (a root of the scene unless `root` is false); returns its index.
  int add_node(json node, bool root = true) {
    doc["nodes"].push_back(node);
    const int index = int(doc["nodes"].size()) - 1;
    if (root) doc["scenes"][0]["nodes"].push_back(index);
    return index;
  }
  std::string text() {
    json d = doc;
    for (const char* key : {"nodes", "meshes", "accessors", "bufferViews", "buffers"})
      if (d[key].empty()) d.erase(key);
    if (!buffer.bytes.empty())
      d["buffers"] = json::array({{{"byteLength", buffer.bytes.size()},
                                 {"uri", "data:application/octet-stream;base64," + base64(buffer.bytes)}}});
    return d.dump(1);
  }
  std::string write(const TempDir& dir, const std::string& name = "scene.gltf") {
    const std::string path = dir.file(name);
    write_text(path, text());
    return path;
  }
};

/// Runs fn, expecting a GltfError whose message is one line starting with "PATH: " and containing
/// `part`; returns the message.
template <class Fn>
std::string expect_gltf_error(const std::string& path, const std::string& part, Fn fn) {
  try {
    fn();
  } catch (const GltfError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind(path + ": ", 0), 0u) << m;
    EXPECT_NE(m.find(part), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    return m;
  }
  ADD_FAILURE() << path << ": no GltfError (expected '" << part << "')";
  return "";
}

}  // namespace luxel::scenes::test
