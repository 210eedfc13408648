#include "gltf_compression.hpp"

#include "gltf_accessors.hpp"
#include "gltf_values.hpp"
#include "luxel/scenes/gltf.hpp"

#include <draco/compression/decode.h>
#include <meshoptimizer.h>

#include <cstring>
#include <memory>
#include <optional>
#include <span>

namespace luxel::scenes::gltf {

namespace {

using tinygltf::Value;

// --- EXT_meshopt_compression -----------------------------------------------------------------------

/// A compressed view's extension object, its values checked for type.
struct MeshoptStream {
  int buffer = -1;
  uint64_t offset = 0, length = 0, stride = 0, count = 0;
  std::string mode, filter = "NONE";
};

/// A non-negative integer member of `o`, or nullopt when absent; anything else fails.
std::optional<uint64_t> unsigned_member(const Value& o, const char* key, const std::string& where, const DecodeReporting& r) {
  const Value& v = o.Get(key);
  if (v.Type() == tinygltf::NULL_TYPE) return std::nullopt;
  const std::optional<int> i = integer(v);
  if (!i || *i < 0) r.fail(where + "." + key + " is not a non-negative integer");
  return uint64_t(*i);
}

std::string string_member(const Value& o, const char* key, const std::string& fallback, const std::string& where,
                          const DecodeReporting& r) {
  const Value& v = o.Get(key);
  if (v.Type() == tinygltf::NULL_TYPE) return fallback;
  if (!v.IsString()) r.fail(where + "." + key + " is not a string");
  return v.Get<std::string>();
}

MeshoptStream meshopt_stream(const Value& e, const std::string& where, const DecodeReporting& r) {
  if (!e.IsObject()) r.fail(where + " is not an object");
  MeshoptStream s;
  const auto buffer = unsigned_member(e, "buffer", where, r);
  const auto length = unsigned_member(e, "byteLength", where, r);
  const auto stride = unsigned_member(e, "byteStride", where, r);
  const auto count = unsigned_member(e, "count", where, r);
  if (!buffer || !length || !stride || !count) r.fail(where + " lacks buffer, byteLength, byteStride or count");
  s.buffer = int(*buffer);
  s.offset = unsigned_member(e, "byteOffset", where, r).value_or(0);
  s.length = *length, s.stride = *stride, s.count = *count;
  s.mode = string_member(e, "mode", "", where, r);
  s.filter = string_member(e, "filter", "NONE", where, r);
  return s;
}

/// Why the decoder may not be given `s`, or "" (meshoptimizer asserts these rather than reports them).
std::string meshopt_refusal(const MeshoptStream& s) {
  if (s.count > kMaxGltfIndices) return "has " + std::to_string(s.count) + " elements, more than luxel reads";
  if (s.mode == "ATTRIBUTES") {
    if (s.stride == 0 || s.stride % 4 != 0 || s.stride > 256) return "ATTRIBUTES has byteStride " + std::to_string(s.stride) + " (4 to 256, a multiple of 4)";
  } else if (s.mode == "TRIANGLES" || s.mode == "INDICES") {
    if (s.stride != 2 && s.stride != 4) return s.mode + " has byteStride " + std::to_string(s.stride) + " (2 or 4)";
    if (s.mode == "TRIANGLES" && s.count % 3 != 0) return "TRIANGLES has " + std::to_string(s.count) + " indices, not a multiple of 3";
  } else {
    return "has mode '" + s.mode + "' (ATTRIBUTES, TRIANGLES or INDICES)";
  }
  if (s.filter != "NONE") {
    if (s.mode != "ATTRIBUTES") return "filters " + s.mode;
    if (s.filter == "OCTAHEDRAL" && s.stride != 4 && s.stride != 8) return "OCTAHEDRAL has byteStride " + std::to_string(s.stride) + " (4 or 8)";
    if (s.filter == "QUATERNION" && s.stride != 8) return "QUATERNION has byteStride " + std::to_string(s.stride) + " (8)";
    if (s.filter != "OCTAHEDRAL" && s.filter != "QUATERNION" && s.filter != "EXPONENTIAL") return "has unknown filter '" + s.filter + "'";
  }
  return "";
}

/// meshoptimizer's codecs spend at least 2 bits per 16 bytes of vertex data (a byte of each
/// vertex's attribute, its group of 16 all equal), a byte per triangle and one per index of a
/// sequence: a stream that claims to decode to more than 64 times its size (and a block's worth
/// more) is refused before the decoded bytes are allocated.
constexpr uint64_t kMeshoptMaxRatio = 64, kMeshoptSlack = 4096;

/// The decoded bytes of `s` (count x stride), its source bytes `src`.
std::vector<unsigned char> meshopt_decoded(const MeshoptStream& s, std::span<const unsigned char> src, const std::string& where,
                                           const DecodeReporting& r) {
  std::vector<unsigned char> out(size_t(s.count * s.stride));
  int status = 0;
  if (s.mode == "ATTRIBUTES") status = meshopt_decodeVertexBuffer(out.data(), size_t(s.count), size_t(s.stride), src.data(), src.size());
  else if (s.mode == "TRIANGLES") status = meshopt_decodeIndexBuffer(out.data(), size_t(s.count), size_t(s.stride), src.data(), src.size());
  else status = meshopt_decodeIndexSequence(out.data(), size_t(s.count), size_t(s.stride), src.data(), src.size());
  if (status != 0) r.fail(where + ": the " + s.mode + " stream does not decode (meshoptimizer error " + std::to_string(status) + ")");
  if (s.filter == "OCTAHEDRAL") meshopt_decodeFilterOct(out.data(), size_t(s.count), size_t(s.stride));
  else if (s.filter == "QUATERNION") meshopt_decodeFilterQuat(out.data(), size_t(s.count), size_t(s.stride));
  else if (s.filter == "EXPONENTIAL") meshopt_decodeFilterExp(out.data(), size_t(s.count), size_t(s.stride));
  return out;
}

/// [offset, offset + length) within [0, size), in 64 bits without overflow.
bool lies_within(uint64_t offset, uint64_t length, uint64_t size) { return offset <= size && length <= size - offset; }

// --- KHR_draco_mesh_compression --------------------------------------------------------------------

int type_components(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    default: return 0;
  }
}

/// A new buffer holding `bytes` and a view of all of it; returns the view's index.
int append_view(tinygltf::Model& model, std::vector<unsigned char> bytes) {
  tinygltf::Buffer buffer;
  buffer.data = std::move(bytes);
  tinygltf::BufferView view;
  view.buffer = int(model.buffers.size());
  view.byteLength = buffer.data.size();
  model.buffers.push_back(std::move(buffer));
  model.bufferViews.push_back(view);
  return int(model.bufferViews.size()) - 1;
}

/// Every point's value of `attribute` as components of type T, tightly packed.
template <class T>
bool draco_values(const draco::Mesh& mesh, const draco::PointAttribute& attribute, int components, std::vector<unsigned char>& out) {
  out.resize(mesh.num_points() * size_t(components) * sizeof(T));
  T value[4] = {};
  for (draco::PointIndex i(0); i < mesh.num_points(); ++i) {
    if (!attribute.ConvertValue<T>(attribute.mapped_index(i), int8_t(components), value)) return false;
    std::memcpy(out.data() + size_t(i.value()) * size_t(components) * sizeof(T), value, size_t(components) * sizeof(T));
  }
  return true;
}

bool draco_values(const draco::Mesh& mesh, const draco::PointAttribute& attribute, int component_type, int components,
                  std::vector<unsigned char>& out) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return draco_values<int8_t>(mesh, attribute, components, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return draco_values<uint8_t>(mesh, attribute, components, out);
    case TINYGLTF_COMPONENT_TYPE_SHORT: return draco_values<int16_t>(mesh, attribute, components, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return draco_values<uint16_t>(mesh, attribute, components, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return draco_values<uint32_t>(mesh, attribute, components, out);
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return draco_values<float>(mesh, attribute, components, out);
    default: return false;
  }
}

/// The mesh's triangle corners in the index type `component_type`.
std::vector<unsigned char> draco_indices(const draco::Mesh& mesh, int component_type) {
  const size_t size = size_t(component_size(component_type));
  std::vector<unsigned char> out(size_t(mesh.num_faces()) * 3 * size);
  size_t at = 0;
  for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k, at += size) {
      const uint32_t v = mesh.face(f)[k].value();
      if (size == 1) out[at] = uint8_t(v);
      else if (size == 2) { const uint16_t s = uint16_t(v); std::memcpy(out.data() + at, &s, 2); }
      else std::memcpy(out.data() + at, &v, 4);
    }
  return out;
}

class DracoPrimitive {
 public:
  DracoPrimitive(tinygltf::Model& model, tinygltf::Primitive& p, const std::string& where, const DecodeReporting& r)
      : model_(model), p_(p), where_(where), r_(r) {}

  void decode(const Value& e) {
    if (!e.IsObject() || !e.Get("attributes").IsObject()) r_.fail(where_ + " has no attributes object");
    const std::optional<int> view = integer(e.Get("bufferView"));
    if (!view || *view < 0 || size_t(*view) >= model_.bufferViews.size()) r_.fail(where_ + " names no buffer view");
    const std::unique_ptr<draco::Mesh> mesh = decoded(source(*view));
    if (mesh->num_faces() == 0) r_.fail(where_ + ": the Draco stream holds no triangles");
    for (const std::string& name : e.Get("attributes").Keys()) attribute(*mesh, name, e.Get("attributes").Get(name));
    indices(*mesh);
  }

 private:
  std::span<const unsigned char> source(int index) const {
    const tinygltf::BufferView& v = model_.bufferViews[size_t(index)];
    if (v.buffer < 0 || size_t(v.buffer) >= model_.buffers.size()) r_.fail(where_ + ": buffer view " + std::to_string(index) + " names no buffer");
    const std::vector<unsigned char>& data = model_.buffers[size_t(v.buffer)].data;
    if (!lies_within(v.byteOffset, v.byteLength, data.size()))
      r_.fail(where_ + ": buffer view " + std::to_string(index) + " runs past the end of its buffer");
    return std::span<const unsigned char>(data).subspan(v.byteOffset, v.byteLength);
  }

  std::unique_ptr<draco::Mesh> decoded(std::span<const unsigned char> bytes) const {
    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    draco::Decoder decoder;
    auto result = decoder.DecodeMeshFromBuffer(&buffer);
    if (!result.ok()) r_.fail(where_ + ": the Draco stream does not decode (" + result.status().error_msg_string() + ")");
    std::unique_ptr<draco::Mesh> mesh = std::move(result).value();
    if (!mesh) r_.fail(where_ + ": the Draco stream holds no mesh");
    return mesh;
  }

  void attribute(const draco::Mesh& mesh, const std::string& name, const Value& id) {
    const std::string what = where_ + " Draco attribute " + name;
    const auto it = p_.attributes.find(name);
    if (it == p_.attributes.end()) r_.fail(what + " is not an attribute of the primitive");
    if (it->second < 0 || size_t(it->second) >= model_.accessors.size()) r_.fail(what + " names no accessor");
    const std::optional<int> unique_id = integer(id);
    const draco::PointAttribute* a = unique_id && *unique_id >= 0 ? mesh.GetAttributeByUniqueId(uint32_t(*unique_id)) : nullptr;
    if (!a) r_.fail(what + " names no attribute of the Draco stream");
    tinygltf::Accessor& accessor = model_.accessors[size_t(it->second)];
    const int components = type_components(accessor.type);
    if (components == 0 || components != a->num_components())
      r_.fail(what + " has " + std::to_string(a->num_components()) + " components; its accessor has " + std::to_string(components));
    if (accessor.count != mesh.num_points())
      r_.fail(what + " has " + std::to_string(mesh.num_points()) + " values; its accessor has " + std::to_string(accessor.count));
    std::vector<unsigned char> bytes;
    r_.reserve(uint64_t(mesh.num_points()) * uint64_t(components) * size_t(component_size(accessor.componentType)), what);
    if (!draco_values(mesh, *a, accessor.componentType, components, bytes))
      r_.fail(what + " does not convert to its accessor's component type");
    accessor.bufferView = append_view(model_, std::move(bytes));
    accessor.byteOffset = 0;
  }

  void indices(const draco::Mesh& mesh) {
    const uint64_t corners = uint64_t(mesh.num_faces()) * 3;
    if (p_.indices < 0) {
      // A Draco primitive is indexed whether or not its JSON says so.
      tinygltf::Accessor a;
      a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
      a.type = TINYGLTF_TYPE_SCALAR;
      a.count = corners;
      model_.accessors.push_back(a);
      p_.indices = int(model_.accessors.size()) - 1;
    }
    if (size_t(p_.indices) >= model_.accessors.size()) r_.fail(where_ + " indices name no accessor");
    tinygltf::Accessor& accessor = model_.accessors[size_t(p_.indices)];
    if (accessor.count != corners)
      r_.fail(where_ + ": the Draco stream has " + std::to_string(corners) + " triangle corners; the indices accessor has " +
              std::to_string(accessor.count));
    const size_t size = size_t(component_size(accessor.componentType));
    if (size == 0 || accessor.componentType == TINYGLTF_COMPONENT_TYPE_BYTE || accessor.componentType == TINYGLTF_COMPONENT_TYPE_SHORT ||
        accessor.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT)
      r_.fail(where_ + " indices are not unsigned integers");
    if (size < 4 && mesh.num_points() > (uint64_t{1} << (8 * size)))
      r_.fail(where_ + ": the Draco stream's " + std::to_string(mesh.num_points()) + " points do not fit its indices' type");
    r_.reserve(corners * size, where_ + " indices");
    accessor.bufferView = append_view(model_, draco_indices(mesh, accessor.componentType));
    accessor.byteOffset = 0;
  }

  tinygltf::Model& model_;
  tinygltf::Primitive& p_;
  const std::string& where_;
  const DecodeReporting& r_;
};

}  // namespace

void decode_meshopt_views(tinygltf::Model& model, const DecodeReporting& report) {
  for (size_t i = 0; i < model.bufferViews.size(); ++i) {
    const auto ext = model.bufferViews[i].extensions.find("EXT_meshopt_compression");
    if (ext == model.bufferViews[i].extensions.end()) continue;
    const std::string where = "bufferViews[" + std::to_string(i) + "].extensions.EXT_meshopt_compression";
    const MeshoptStream s = meshopt_stream(ext->second, where, report);
    if (const std::string why = meshopt_refusal(s); !why.empty()) report.fail(where + " " + why);
    if (s.buffer < 0 || size_t(s.buffer) >= model.buffers.size()) report.fail(where + " names buffer " + std::to_string(s.buffer) + ", which does not exist");
    const std::vector<unsigned char>& data = model.buffers[size_t(s.buffer)].data;
    if (!lies_within(s.offset, s.length, data.size()))
      report.fail(where + " reads bytes " + std::to_string(s.offset) + " + " + std::to_string(s.length) + " of buffer " +
                  std::to_string(s.buffer) + ", which holds " + std::to_string(data.size()));
    if (model.bufferViews[i].byteLength != s.count * s.stride)
      report.fail(where + " decodes " + std::to_string(s.count * s.stride) + " bytes for a view of " +
                  std::to_string(model.bufferViews[i].byteLength));
    if (s.count * s.stride > kMeshoptMaxRatio * s.length + kMeshoptSlack)
      report.fail(where + " claims " + std::to_string(s.count * s.stride) + " bytes from " + std::to_string(s.length) +
                  ", more than meshoptimizer's encoding holds");
    report.reserve(s.count * s.stride, where);
    std::vector<unsigned char> bytes =
        meshopt_decoded(s, std::span<const unsigned char>(data).subspan(size_t(s.offset), size_t(s.length)), where, report);
    tinygltf::Buffer buffer;
    buffer.data = std::move(bytes);
    model.buffers.push_back(std::move(buffer));
    model.bufferViews[i].buffer = int(model.buffers.size()) - 1;
    model.bufferViews[i].byteOffset = 0;
  }
}

void decode_draco_primitives(tinygltf::Model& model, const DecodeReporting& report) {
  for (size_t m = 0; m < model.meshes.size(); ++m)
    for (size_t k = 0; k < model.meshes[m].primitives.size(); ++k) {
      tinygltf::Primitive& p = model.meshes[m].primitives[k];
      const auto ext = p.extensions.find("KHR_draco_mesh_compression");
      if (ext == p.extensions.end()) continue;
      const std::string where = "meshes[" + std::to_string(m) + "].primitives[" + std::to_string(k) + "]";
      const Value e = ext->second;  // the primitive may gain an indices accessor below
      DracoPrimitive(model, p, where, report).decode(e);
    }
}

}  // namespace luxel::scenes::gltf
