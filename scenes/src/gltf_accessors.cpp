#include "gltf_accessors.hpp"

#include "luxel/scenes/gltf.hpp"

#include <algorithm>
#include <cstring>

namespace luxel::scenes::gltf {

int component_size(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

namespace {

int components(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
  }
}

std::string type_name(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return "type " + std::to_string(type);
  }
}

std::string component_name(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
    default: return "component type " + std::to_string(type);
  }
}

/// [offset, offset + length) within [0, size), in 64 bits without overflow.
bool within(uint64_t offset, uint64_t length, uint64_t size) { return offset <= size && length <= size - offset; }

/// One component as the specification maps it: normalized integers to [0, 1] or [-1, 1].
float component(const uint8_t* p, int type, bool normalized) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      float f;
      std::memcpy(&f, p, 4);
      return f;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? p[0] / 255.0f : float(p[0]);
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const int8_t v = int8_t(p[0]);
      return normalized ? std::max(v / 127.0f, -1.0f) : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? v / 65535.0f : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      int16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? std::max(v / 32767.0f, -1.0f) : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      uint32_t v;
      std::memcpy(&v, p, 4);
      return normalized ? float(v / 4294967295.0) : float(v);
    }
    default: return 0.0f;
  }
}

uint32_t unsigned_value(const uint8_t* p, int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return p[0];
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t v;
      std::memcpy(&v, p, 2);
      return v;
    }
    default: {
      uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
  }
}

bool unsigned_index_type(int type) {
  return type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
         type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

}  // namespace

Accessors::Accessors(const tinygltf::Model& model, std::string path) : model_(model), path_(std::move(path)) {
  quantization_ = std::find(model_.extensionsUsed.begin(), model_.extensionsUsed.end(), "KHR_mesh_quantization") !=
                  model_.extensionsUsed.end();
  for (size_t i = 0; i < model_.bufferViews.size(); ++i) check_view(i);
  for (size_t i = 0; i < model_.accessors.size(); ++i) check_accessor(i);
}

void Accessors::fail(const std::string& what) const { throw GltfError(path_ + ": " + what); }

void Accessors::check_view(size_t i) const {
  const tinygltf::BufferView& v = model_.bufferViews[i];
  const std::string where = "buffer view " + std::to_string(i);
  if (v.buffer < 0 || size_t(v.buffer) >= model_.buffers.size())
    fail(where + " refers to buffer " + std::to_string(v.buffer) + " of " + std::to_string(model_.buffers.size()));
  const size_t size = model_.buffers[size_t(v.buffer)].data.size();
  if (!within(v.byteOffset, v.byteLength, size))
    fail(where + " spans bytes " + std::to_string(v.byteOffset) + " + " + std::to_string(v.byteLength) +
         " of buffer " + std::to_string(v.buffer) + ", which holds " + std::to_string(size));
  if (v.byteStride != 0 && (v.byteStride < 4 || v.byteStride > 252 || v.byteStride % 4 != 0))
    fail(where + " has byteStride " + std::to_string(v.byteStride) + " (4 to 252, a multiple of 4)");
}

void Accessors::check_accessor(size_t i) const {
  const tinygltf::Accessor& a = model_.accessors[i];
  const std::string where = "accessor " + std::to_string(i);
  const int csize = component_size(a.componentType), n = components(a.type);
  if (csize == 0) fail(where + " has unknown " + component_name(a.componentType));
  if (n == 0) fail(where + " has unknown " + type_name(a.type));
  if (a.count < 1) fail(where + " has no elements");
  if (a.count > kMaxGltfIndices)
    fail(where + " has " + std::to_string(a.count) + " elements, more than luxel reads (" +
         std::to_string(kMaxGltfIndices) + ")");
  const uint64_t element = uint64_t(csize) * uint64_t(n);
  if (a.bufferView >= 0) {
    if (size_t(a.bufferView) >= model_.bufferViews.size())
      fail(where + " refers to buffer view " + std::to_string(a.bufferView) + " of " +
           std::to_string(model_.bufferViews.size()));
    const tinygltf::BufferView& v = model_.bufferViews[size_t(a.bufferView)];
    const uint64_t stride = v.byteStride ? v.byteStride : element;
    if (stride < element)
      fail(where + " elements of " + std::to_string(element) + " bytes do not fit buffer view " +
           std::to_string(a.bufferView) + "'s byteStride " + std::to_string(stride));
    // count <= 2^26 and stride <= 252: the span fits 64 bits; the offset is checked against it.
    const uint64_t span = (uint64_t(a.count) - 1) * stride + element;
    if (!within(a.byteOffset, span, v.byteLength))
      fail(where + " reads bytes " + std::to_string(a.byteOffset) + " + " + std::to_string(span) +
           " of buffer view " + std::to_string(a.bufferView) + ", which holds " + std::to_string(v.byteLength));
  } else if (a.bufferView != -1) {
    fail(where + " refers to buffer view " + std::to_string(a.bufferView));
  }
  if (a.sparse.isSparse) {
    const auto& s = a.sparse;
    if (s.count < 1 || uint64_t(s.count) > a.count)
      fail(where + " has " + std::to_string(s.count) + " sparse values for " + std::to_string(a.count) + " elements");
    auto check_part = [&](int view, int offset, uint64_t bytes, const char* part) {
      if (view < 0 || size_t(view) >= model_.bufferViews.size())
        fail(where + " sparse " + part + " refer to buffer view " + std::to_string(view));
      if (offset < 0) fail(where + " sparse " + part + " have byteOffset " + std::to_string(offset));
      const uint64_t length = model_.bufferViews[size_t(view)].byteLength;
      if (!within(uint64_t(offset), bytes, length))
        fail(where + " sparse " + part + " read bytes " + std::to_string(offset) + " + " + std::to_string(bytes) +
             " of buffer view " + std::to_string(view) + ", which holds " + std::to_string(length));
    };
    if (!unsigned_index_type(s.indices.componentType))
      fail(where + " sparse indices are " + component_name(s.indices.componentType));
    check_part(s.indices.bufferView, s.indices.byteOffset,
               uint64_t(s.count) * uint64_t(component_size(s.indices.componentType)), "indices");
    check_part(s.values.bufferView, s.values.byteOffset, uint64_t(s.count) * element, "values");
  }
}

const tinygltf::Accessor& Accessors::accessor(int index, const std::string& where) const {
  if (index < 0 || size_t(index) >= model_.accessors.size())
    fail(where + " refers to accessor " + std::to_string(index) + " of " + std::to_string(model_.accessors.size()));
  return model_.accessors[size_t(index)];
}

size_t Accessors::count(int index, const std::string& where) const { return accessor(index, where).count; }

std::span<const uint8_t> Accessors::view(int index, const std::string& where) const {
  if (index < 0 || size_t(index) >= model_.bufferViews.size())
    fail(where + " refers to buffer view " + std::to_string(index) + " of " + std::to_string(model_.bufferViews.size()));
  const tinygltf::BufferView& v = model_.bufferViews[size_t(index)];
  return std::span<const uint8_t>(model_.buffers[size_t(v.buffer)].data).subspan(v.byteOffset, v.byteLength);
}

template <class Write>
void Accessors::for_each_sparse(const tinygltf::Accessor& a, const std::string& what, size_t value_size, Write write) const {
  const auto& s = a.sparse;
  const std::span<const uint8_t> ind = view(s.indices.bufferView, what).subspan(size_t(s.indices.byteOffset));
  const std::span<const uint8_t> val = view(s.values.bufferView, what).subspan(size_t(s.values.byteOffset));
  const size_t isize = size_t(component_size(s.indices.componentType));
  for (size_t k = 0; k < size_t(s.count); ++k) {
    const uint32_t target = unsigned_value(ind.data() + k * isize, s.indices.componentType);
    if (target >= a.count)
      fail(what + " sparse index " + std::to_string(k) + " = " + std::to_string(target) + " is beyond its " +
           std::to_string(a.count) + " elements");
    write(target, val.data() + k * value_size);
  }
}

bool Accessors::allowed_components(const tinygltf::Accessor& a, const AttributeRule& rule) const {
  const int t = a.componentType;
  if (t == TINYGLTF_COMPONENT_TYPE_FLOAT) return !a.normalized;
  const bool small = t == TINYGLTF_COMPONENT_TYPE_BYTE || t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                     t == TINYGLTF_COMPONENT_TYPE_SHORT || t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  const bool unsigned_small = t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  if (rule.normalized_integers && a.normalized && unsigned_small) return true;
  if (!quantization_) return false;
  switch (rule.quantized) {
    case AttributeRule::Quantized::integers: return small;
    case AttributeRule::Quantized::signed_normalized:
      return a.normalized && (t == TINYGLTF_COMPONENT_TYPE_BYTE || t == TINYGLTF_COMPONENT_TYPE_SHORT);
    default: return false;
  }
}

Floats Accessors::attribute(int index, const AttributeRule& rule, const std::string& where) const {
  const tinygltf::Accessor& a = accessor(index, where);
  const std::string what = where + " " + rule.name + " (accessor " + std::to_string(index) + ")";
  if (std::find(rule.types.begin(), rule.types.end(), a.type) == rule.types.end())
    fail(what + " may not be " + type_name(a.type));
  if (!allowed_components(a, rule))
    fail(what + " may not be " + std::string(a.normalized ? "normalized " : "") + component_name(a.componentType) +
         (quantization_ || rule.quantized == AttributeRule::Quantized::none ? "" : " (without KHR_mesh_quantization)"));
  if (a.count > kMaxGltfVertices)
    fail(what + " has " + std::to_string(a.count) + " vertices, more than luxel reads (" +
         std::to_string(kMaxGltfVertices) + ")");
  Floats out;
  out.count = a.count;
  out.components = components(a.type);
  out.values.assign(a.count * size_t(out.components), 0.0f);  // no buffer view: zeros (sparse may fill)
  const int csize = component_size(a.componentType);
  const size_t element = size_t(csize) * size_t(out.components);
  auto read_element = [&](const uint8_t* p, size_t i) {
    for (int c = 0; c < out.components; ++c)
      out.values[i * size_t(out.components) + size_t(c)] = component(p + size_t(c) * size_t(csize), a.componentType, a.normalized);
  };
  if (a.bufferView >= 0) {
    const std::span<const uint8_t> bytes = view(a.bufferView, what);
    const size_t stride = model_.bufferViews[size_t(a.bufferView)].byteStride ? model_.bufferViews[size_t(a.bufferView)].byteStride : element;
    for (size_t i = 0; i < a.count; ++i) read_element(bytes.data() + a.byteOffset + i * stride, i);
  }
  if (a.sparse.isSparse)
    for_each_sparse(a, what, element, [&](uint32_t target, const uint8_t* value) { read_element(value, target); });
  return out;
}

std::vector<uint32_t> Accessors::indices(int index, const std::string& where, int* component_type) const {
  const tinygltf::Accessor& a = accessor(index, where);
  const std::string what = where + " indices (accessor " + std::to_string(index) + ")";
  if (a.type != TINYGLTF_TYPE_SCALAR) fail(what + " may not be " + type_name(a.type));
  if (a.normalized || !unsigned_index_type(a.componentType))
    fail(what + " may not be " + std::string(a.normalized ? "normalized " : "") + component_name(a.componentType));
  *component_type = a.componentType;
  std::vector<uint32_t> out(a.count, 0);
  const size_t csize = size_t(component_size(a.componentType));
  if (a.bufferView >= 0) {
    const std::span<const uint8_t> bytes = view(a.bufferView, what);
    const size_t stride = model_.bufferViews[size_t(a.bufferView)].byteStride ? model_.bufferViews[size_t(a.bufferView)].byteStride : csize;
    for (size_t i = 0; i < a.count; ++i) out[i] = unsigned_value(bytes.data() + a.byteOffset + i * stride, a.componentType);
  }
  if (a.sparse.isSparse)
    for_each_sparse(a, what, csize,
                    [&](uint32_t target, const uint8_t* value) { out[target] = unsigned_value(value, a.componentType); });
  return out;
}

}  // namespace luxel::scenes::gltf
