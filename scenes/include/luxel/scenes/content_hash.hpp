#pragma once
// A 64-bit FNV-1a hash of plain values, for keys that say "the inputs are the same": the bake's
// and the cube maps' stored results are reused while the hash of what they read is unchanged
// (bake/storage.hpp, bake/cubemap_storage.hpp). Values are hashed by their bytes, so a hash
// holds for one build's layout of the types, which is all a cache on one machine needs.

#include "luxel/scenes/scene.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

namespace luxel::scenes {

struct ContentHash {
  uint64_t h = 0xcbf29ce484222325ull;

  void bytes(const void* p, size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 0x100000001b3ull;
  }
  template <class T>
  void value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes(&v, sizeof v);
  }
  template <class... T>
  void values(const T&... v) {
    (value(v), ...);
  }
  /// Its size, then its elements' bytes.
  template <class T>
  void vector(const std::vector<T>& v) {
    value(v.size());
    if (!v.empty()) bytes(v.data(), v.size() * sizeof(T));
  }
  void string(const std::string& s) {
    value(s.size());
    bytes(s.data(), s.size());
  }
  void image(const PixelImage& img) {
    values(img.width, img.height);
    vector(img.rgba8);
    vector(img.rgba32f);
  }
};

}  // namespace luxel::scenes
