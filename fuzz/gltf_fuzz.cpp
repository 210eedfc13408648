// libFuzzer target: glTF import (inputs.hpp, read_gltf_input). Three mutations in four edit the
// JSON (of a .gltf, or of a .glb's JSON chunk, its lengths then set to match) as JSON.

#include "inputs.hpp"
#include "json_mutator.hpp"

#include <cstring>
#include <vector>

extern "C" size_t LLVMFuzzerMutate(uint8_t* data, size_t size, size_t max_size);

namespace {

constexpr uint32_t kGlbMagic = 0x46546C67, kJsonChunk = 0x4E4F534A;

uint32_t le32(const uint8_t* p) { return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24; }
void put_le32(uint8_t* p, uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = uint8_t(v >> (8 * i));
}

/// A .glb whose JSON chunk is mutated as JSON; 0 if the bytes are no .glb with a JSON chunk.
size_t mutate_glb(uint8_t* data, size_t size, size_t max_size, unsigned seed) {
  if (size < 20 || le32(data) != kGlbMagic || le32(data + 16) != kJsonChunk) return 0;
  const size_t json_size = le32(data + 12);
  if (json_size > size - 20) return 0;
  std::vector<uint8_t> json(data + 20, data + 20 + json_size), rest(data + 20 + json_size, data + size);
  json.resize(json_size + 4096);
  const size_t mutated = luxel::fuzz::mutate_json(json.data(), json_size, json.size(), seed);
  if (mutated == 0) return 0;
  json.resize(mutated);
  while (json.size() % 4) json.push_back(' ');  // chunks are 4-byte aligned
  const size_t total = 20 + json.size() + rest.size();
  if (total > max_size) return 0;
  put_le32(data + 8, uint32_t(total));
  put_le32(data + 12, uint32_t(json.size()));
  std::memcpy(data + 20, json.data(), json.size());
  std::memcpy(data + 20 + json.size(), rest.data(), rest.size());
  return total;
}

}  // namespace

extern "C" size_t LLVMFuzzerCustomMutator(uint8_t* data, size_t size, size_t max_size, unsigned seed) {
  if (seed % 4 != 0) {
    if (size_t n = mutate_glb(data, size, max_size, seed)) return n;
    if (size_t n = luxel::fuzz::mutate_json(data, size, max_size, seed)) return n;
  }
  return LLVMFuzzerMutate(data, size, max_size);
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  luxel::fuzz::read_gltf_input({data, size});
  return 0;
}
