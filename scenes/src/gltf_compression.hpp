#pragma once
// Compressed glTF geometry decoded into plain buffers of tinygltf's model, before luxel's
// validation layer (gltf_accessors.hpp) checks and reads it like any other:
// - EXT_meshopt_compression: each compressed buffer view decoded (meshoptimizer) into a buffer of
//   its own, the view pointed at it; the fallback buffer is never read.
// - KHR_draco_mesh_compression: each compressed primitive's Draco stream decoded (Draco) into one
//   buffer view per attribute it names and one for its indices, in the component types its
//   accessors declare, those accessors pointed at them.
// Every size a decoder is given is checked first: a stream that does not decode, or that decodes to
// other counts than its accessors declare, is one error naming the view or the primitive.

#include "tinygltf.hpp"

#include <cstdint>
#include <functional>
#include <string>

namespace luxel::scenes::gltf {

struct DecodeReporting {
  std::function<void(const std::string&)> fail;                       ///< throws
  std::function<void(uint64_t bytes, const std::string& what)> reserve;  ///< the memory limit's check, before decoding
};

void decode_meshopt_views(tinygltf::Model& model, const DecodeReporting& report);
void decode_draco_primitives(tinygltf::Model& model, const DecodeReporting& report);

}  // namespace luxel::scenes::gltf
