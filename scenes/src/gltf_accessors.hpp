#pragma once
// luxel's validation layer over tinygltf's model: buffer views and accessors checked in 64-bit
// arithmetic before a byte is read (tinygltf's own checks have had overflow bugs), per-attribute
// type rules of the glTF specification, and accessors read to floats or indices through it.

#include "tinygltf.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace luxel::scenes::gltf {

/// Bytes of one component of `type` (TINYGLTF_COMPONENT_TYPE_*); 0 for a type glTF does not have.
int component_size(int type);

/// What an attribute may be: its types (TINYGLTF_TYPE_*) and whether unsigned normalized bytes and
/// shorts are allowed beside floats (TEXCOORD, COLOR).
struct AttributeRule {
  const char* name;
  std::vector<int> types;
  bool normalized_integers = false;
  /// What KHR_mesh_quantization adds, in a file that uses it: none; any byte or short, normalized
  /// or not (POSITION, TEXCOORD); signed normalized bytes and shorts (NORMAL, TANGENT).
  enum class Quantized { none, integers, signed_normalized } quantized = Quantized::none;
};

/// An accessor's values as floats, `components` per element (sparse substitutions applied,
/// normalized integers mapped as the specification says).
struct Floats {
  size_t count = 0;
  int components = 0;
  std::vector<float> values;
  const float* at(size_t i) const { return values.data() + i * components; }
};

class Accessors {
 public:
  /// Checks every buffer view and accessor of `model`; throws GltfError("PATH: ...") on the first
  /// problem.
  Accessors(const tinygltf::Model& model, std::string path);

  [[noreturn]] void fail(const std::string& what) const;

  /// The accessor read for an attribute (`where` names it in messages) after checking its types.
  Floats attribute(int accessor, const AttributeRule& rule, const std::string& where) const;
  /// An index accessor (SCALAR, unsigned byte, short or int, not normalized); `component_type` out.
  std::vector<uint32_t> indices(int accessor, const std::string& where, int* component_type) const;
  /// The bytes of a buffer view (checked at construction).
  std::span<const uint8_t> view(int buffer_view, const std::string& where) const;
  /// The number of elements of an accessor (checked at construction).
  size_t count(int accessor, const std::string& where) const;

 private:
  void check_view(size_t index) const;
  /// Calls write(element, value bytes) for each of a sparse accessor's replaced elements.
  template <class Write>
  void for_each_sparse(const tinygltf::Accessor& a, const std::string& what, size_t value_size, Write write) const;
  void check_accessor(size_t index) const;
  const tinygltf::Accessor& accessor(int index, const std::string& where) const;

  /// Whether `a` has a component type `rule` allows.
  bool allowed_components(const tinygltf::Accessor& a, const AttributeRule& rule) const;

  const tinygltf::Model& model_;
  std::string path_;
  bool quantization_ = false;  ///< the file uses KHR_mesh_quantization
};

}  // namespace luxel::scenes::gltf
