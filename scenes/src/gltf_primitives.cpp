// A glTF mesh's primitives as Scene meshes in world space: attributes and indices read, strips and
// fans as triangle lists, flat normals where none are given, tangents generated; the Model the
// VertexLitGeneric ones make.

#include "gltf_importer.hpp"
#include "gltf_values.hpp"
#include "luxel/scenes/tangents.hpp"
#include "tinygltf.hpp"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <limits>

namespace luxel::scenes::gltf {

/// A mesh's Flattened: its POSITION counts (or a vertex per corner where flat normals unweld it)
/// and its triangle list's length. (Materials are read before the nodes.)
Importer::Flattened Importer::flattened(int mesh) const {
  Flattened total;
  if (mesh < 0 || size_t(mesh) >= model_.meshes.size()) return total;
  for (const tinygltf::Primitive& p : model_.meshes[size_t(mesh)].primitives) {
    auto count = [&](int accessor) -> uint64_t {
      return accessor >= 0 && size_t(accessor) < model_.accessors.size() ? model_.accessors[size_t(accessor)].count : 0;
    };
    auto position = p.attributes.find("POSITION");
    const uint64_t n = position == p.attributes.end() ? 0 : count(position->second);
    const uint64_t m = p.indices >= 0 ? count(p.indices) : n;
    const uint64_t corners = p.mode == TINYGLTF_MODE_TRIANGLES || p.mode < 0 ? m : 3 * (m > 2 ? m - 2 : 0);
    // Flat normals unweld: a primitive without NORMAL, unless it gets a constant normal or is
    // unlit (primitive() below).
    const bool unlit = p.material >= 0 && size_t(p.material) < scene_.materials.size() &&
                       scene_.materials[size_t(p.material)].family == ShaderFamily::unlit_generic;
    const bool welded = p.attributes.count("NORMAL") || options_.missing_normal || unlit;
    const uint64_t vertices = welded ? n : corners;
    const bool uv0 = p.attributes.count("TEXCOORD_0") != 0;
    const uint64_t vertex_bytes = sizeof(glm::vec3) * 2 +  // position, normal
                                  (p.attributes.count("TANGENT") || (uv0 && options_.generate_tangents) ? sizeof(glm::vec4) : 0) +
                                  (uv0 ? sizeof(glm::vec2) : 0) + (p.attributes.count("TEXCOORD_1") ? sizeof(glm::vec2) : 0) +
                                  (p.attributes.count("COLOR_0") ? sizeof(glm::vec4) : 0);
    total.vertices += vertices;
    total.indices += corners;
    total.bytes += 2 * (vertices * vertex_bytes + corners * sizeof(uint32_t));
  }
  return total;
}

/// The node's mesh; its VertexLitGeneric primitives become one Model, whose centroid is
/// `luxel.centroid` (the node's extras, as luxel exports it) or else the mean of their vertices,
/// and whose path is `luxel.path` ([{"time": s, "offset": [x, y, z]}...], offsets in the node's
/// parent's units, as luxel exports it).
void Importer::add_mesh(int index, const glm::dmat4& world, const std::string& node, const tinygltf::Value& luxel, const Motion& motion) {
  if (size_t(index) >= model_.meshes.size()) fail(node + " refers to mesh " + std::to_string(index));
  const tinygltf::Mesh& m = model_.meshes[size_t(index)];
  Model model;
  model.name = m.name.empty() ? "mesh " + std::to_string(index) : m.name;
  glm::dvec3 sum(0.0);
  size_t count = 0;
  for (size_t p = 0; p < m.primitives.size(); ++p) {
    const std::string where = "mesh " + std::to_string(index) + (m.name.empty() ? "" : " '" + m.name + "'") +
                              " primitive " + std::to_string(p);
    Mesh mesh = primitive(m.primitives[p], world, where);
    mesh.name = m.primitives.size() == 1 ? model.name : model.name + " " + std::to_string(p);
    const bool vertexlit = mesh.material < 0 || scene_.materials[size_t(mesh.material)].family == ShaderFamily::vertexlit_generic;
    if (vertexlit) {
      for (const glm::vec3& v : mesh.positions) sum += glm::dvec3(v);
      count += mesh.positions.size();
      model.meshes.push_back(int(scene_.meshes.size()));
    }
    scene_.meshes.push_back(std::move(mesh));
  }
  if (!model.meshes.empty()) {
    model.centroid = glm::vec3(count ? sum / double(count) : glm::dvec3(0.0));
    glm::vec3 given(std::numeric_limits<float>::quiet_NaN());
    gltf::read(luxel.Get("centroid"), given);
    if (finite(glm::dvec3(given))) model.centroid = is_identity(world) ? given : glm::vec3(world * glm::dvec4(given, 1.0));
    const tinygltf::Value& path = luxel.Get("path");
    for (size_t k = 0; path.IsArray() && k < path.ArrayLen(); ++k) {
      ModelKey key;
      key.time = std::numeric_limits<float>::quiet_NaN();
      key.offset = glm::vec3(std::numeric_limits<float>::quiet_NaN());
      gltf::read(path.Get(int(k)).Get("time"), key.time);
      gltf::read(path.Get(int(k)).Get("offset"), key.offset);
      if (!std::isfinite(key.time) || !finite(glm::dvec3(key.offset)) || (k > 0 && !(key.time > model.path.back().time)))
        fail(node + ": extras.luxel.path key " + std::to_string(k) + " is not a finite time and offset later than the key before");
      if (!is_identity(world)) key.offset = glm::vec3(world * glm::dvec4(key.offset, 0.0));
      model.path.push_back(key);
    }
    if (!path.IsArray() && motion.channel >= 0) model.path = animated_path(motion, node);
    scene_.models.push_back(std::move(model));
  }
}

Mesh Importer::primitive(const tinygltf::Primitive& p, const glm::dmat4& world, const std::string& where) {
  static const char* kModes[] = {"POINTS", "LINES", "LINE_LOOP", "LINE_STRIP"};
  if (p.mode >= 0 && p.mode <= 3) fail(where + " is " + kModes[p.mode] + "; luxel draws triangles only");
  if (p.mode > 6) fail(where + " has unknown mode " + std::to_string(p.mode));
  if (p.material >= int(model_.materials.size())) fail(where + " refers to material " + std::to_string(p.material));
  Mesh mesh;
  mesh.material = p.material;
  auto attr = [&](const char* name) { auto it = p.attributes.find(name); return it == p.attributes.end() ? -1 : it->second; };
  const int position = attr("POSITION");
  if (position < 0) fail(where + " has no POSITION");
  const size_t n = accessors_->count(position, where);
  if (n > kMaxGltfVertices) fail(where + " has " + std::to_string(n) + " vertices, more than luxel reads");
  auto read = [&](const char* name, const AttributeRule& rule) -> std::optional<gltf::Floats> {
    const int a = attr(name);
    if (a < 0) return std::nullopt;
    gltf::Floats f = accessors_->attribute(a, rule, where);
    if (f.count != n) fail(where + " " + name + " has " + std::to_string(f.count) + " elements for " + std::to_string(n) + " positions");
    return f;
  };
  using Q = AttributeRule::Quantized;
  const auto pos = read("POSITION", {"POSITION", {TINYGLTF_TYPE_VEC3}, false, Q::integers});
  const auto nrm = read("NORMAL", {"NORMAL", {TINYGLTF_TYPE_VEC3}, false, Q::signed_normalized});
  const auto tan = read("TANGENT", {"TANGENT", {TINYGLTF_TYPE_VEC4}, false, Q::signed_normalized});
  const auto uv0 = read("TEXCOORD_0", {"TEXCOORD_0", {TINYGLTF_TYPE_VEC2}, true, Q::integers});
  const auto uv1 = read("TEXCOORD_1", {"TEXCOORD_1", {TINYGLTF_TYPE_VEC2}, true, Q::integers});
  const auto col = read("COLOR_0", {"COLOR_0", {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4}, true});

  // Indices as the mode defines triangles (glTF 2.0 section 3.7.2.1).
  std::vector<uint32_t> raw;
  int index_type = 0;
  if (p.indices >= 0) {
    raw = accessors_->indices(p.indices, where, &index_type);
    for (size_t k = 0; k < raw.size(); ++k)
      if (raw[k] >= n)
        fail(where + " index " + std::to_string(k) + " = " + std::to_string(raw[k]) + " is beyond its " + std::to_string(n) + " vertices");
  } else {
    raw.resize(n);
    for (size_t k = 0; k < n; ++k) raw[k] = uint32_t(k);
  }
  std::vector<uint32_t> tri;
  const int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    if (raw.size() % 3 != 0) fail(where + " has " + std::to_string(raw.size()) + " indices, not a multiple of 3");
    tri = std::move(raw);
  } else {
    for (size_t i = 0; i + 2 < raw.size(); ++i) {
      if (mode == TINYGLTF_MODE_TRIANGLE_STRIP)
        tri.insert(tri.end(), {raw[i], raw[i + 1 + i % 2], raw[i + 2 - i % 2]});
      else  // TRIANGLE_FAN
        tri.insert(tri.end(), {raw[i + 1], raw[i + 2], raw[0]});
    }
  }

  // World transform (the unit conversion included); the identity copies values bit for bit.
  const bool identity = is_identity(world);
  const glm::dmat3 linear(world);
  const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(linear));
  const bool mirrored = glm::determinant(linear) < 0.0;
  mesh.positions.resize(n);
  for (size_t v = 0; v < n; ++v) {
    const glm::dvec3 local(pos->at(v)[0], pos->at(v)[1], pos->at(v)[2]);
    if (!finite(local)) fail(where + " position " + std::to_string(v) + " is not finite");
    mesh.positions[v] = identity ? glm::vec3(pos->at(v)[0], pos->at(v)[1], pos->at(v)[2])
                                 : glm::vec3(glm::dvec3(world * glm::dvec4(local, 1.0)));
    if (!finite(glm::dvec3(mesh.positions[v]))) fail(where + " position " + std::to_string(v) + " is not finite in world space");
  }
  if (nrm || options_.missing_normal) {
    mesh.normals.resize(n);
    for (size_t v = 0; v < n; ++v) {
      const glm::vec3 local = nrm ? glm::vec3(nrm->at(v)[0], nrm->at(v)[1], nrm->at(v)[2]) : *options_.missing_normal;
      if (identity) {
        mesh.normals[v] = local;
      } else {
        const glm::dvec3 w = normal_matrix * glm::dvec3(local);
        const double len = glm::length(w);
        mesh.normals[v] = len > 0.0 ? glm::vec3(w / len) : glm::vec3(0.0f);
      }
    }
  }
  if (tan) {
    mesh.tangents.resize(n);
    for (size_t v = 0; v < n; ++v) {
      const glm::vec3 local(tan->at(v)[0], tan->at(v)[1], tan->at(v)[2]);
      const float w = (tan->at(v)[3] < 0.0f) != mirrored ? -1.0f : 1.0f;
      if (identity) {
        mesh.tangents[v] = glm::vec4(local, w);
      } else {
        const glm::dvec3 t = linear * glm::dvec3(local);
        const double len = glm::length(t);
        mesh.tangents[v] = glm::vec4(len > 0.0 ? glm::vec3(t / len) : glm::vec3(0.0f), w);
      }
    }
  }
  auto vec2s = [&](const std::optional<gltf::Floats>& f, std::vector<glm::vec2>& out) {
    if (!f) return;
    out.resize(n);
    for (size_t v = 0; v < n; ++v) out[v] = glm::vec2(f->at(v)[0], f->at(v)[1]);
  };
  vec2s(uv0, mesh.uv0);
  vec2s(uv1, mesh.uv1);
  if (col) {
    mesh.colors.resize(n);
    for (size_t v = 0; v < n; ++v)
      mesh.colors[v] = glm::vec4(col->at(v)[0], col->at(v)[1], col->at(v)[2], col->components == 4 ? col->at(v)[3] : 1.0f);
  }
  if (mirrored)
    for (size_t t = 0; t + 2 < tri.size(); t += 3) std::swap(tri[t + 1], tri[t + 2]);

  // An unlit material (KHR_materials_unlit) reads no normal, so it gets none.
  const bool unlit = mesh.material >= 0 && scene_.materials[size_t(mesh.material)].family == ShaderFamily::unlit_generic;
  if (mesh.normals.empty() && !unlit) {
    // Flat normals: every triangle gets vertices of its own.
    Mesh flat;
    flat.material = mesh.material;
    for (size_t k = 0; k < tri.size(); ++k) {
      const uint32_t v = tri[k];
      flat.positions.push_back(mesh.positions[v]);
      if (!mesh.tangents.empty()) flat.tangents.push_back(mesh.tangents[v]);
      if (!mesh.uv0.empty()) flat.uv0.push_back(mesh.uv0[v]);
      if (!mesh.uv1.empty()) flat.uv1.push_back(mesh.uv1[v]);
      if (!mesh.colors.empty()) flat.colors.push_back(mesh.colors[v]);
    }
    flat.normals.resize(flat.positions.size());
    for (size_t t = 0; t + 2 < tri.size(); t += 3) {
      const glm::dvec3 a(flat.positions[t]), b(flat.positions[t + 1]), c(flat.positions[t + 2]);
      const glm::dvec3 f = glm::cross(b - a, c - a);
      const double len = glm::length(f);
      const glm::vec3 normal = len > 0.0 ? glm::vec3(f / len) : glm::vec3(0, 0, 1);
      flat.normals[t] = flat.normals[t + 1] = flat.normals[t + 2] = normal;
    }
    for (size_t k = 0; k < tri.size(); ++k) tri[k] = uint32_t(k);
    mesh = std::move(flat);
  }
  // 8-bit indices widen to 16, 32-bit ones stay; 16 bits widen where the vertices need it. A
  // triangle list without indices whose vertices stay in order (not mirrored, not a strip) stays one:
  // the scene's non-indexed mesh.
  const bool wide = index_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT || mesh.positions.size() > 65536;
  bool in_order = p.indices < 0 && tri.size() == mesh.positions.size();
  for (size_t k = 0; in_order && k < tri.size(); ++k) in_order = tri[k] == k;
  if (in_order) mesh.indices = std::vector<uint16_t>{};
  else if (wide) mesh.indices = std::move(tri);
  else mesh.indices = std::vector<uint16_t>(tri.begin(), tri.end());
  if (mesh.tangents.empty() && !mesh.normals.empty() && !mesh.uv0.empty() && options_.generate_tangents) generate_tangents(mesh);
  return mesh;
}

}  // namespace luxel::scenes::gltf
