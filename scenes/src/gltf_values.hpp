#pragma once
// glm vectors and numbers to and from tinygltf Values (the extras luxel reads and writes).

#include "tinygltf.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace luxel::scenes::gltf {

template <int N>
tinygltf::Value floats(const glm::vec<N, float>& v) {
  tinygltf::Value::Array a;
  for (int i = 0; i < N; ++i) a.emplace_back(double(v[i]));
  return tinygltf::Value(std::move(a));
}

/// Sets `out` when `v` is an array of N numbers (a number, a boolean: below); leaves it alone otherwise.
template <int N>
void read(const tinygltf::Value& v, glm::vec<N, float>& out) {
  if (!v.IsArray() || int(v.ArrayLen()) != N) return;
  glm::vec<N, float> r;
  for (int i = 0; i < N; ++i) {
    if (!v.Get(i).IsNumber()) return;
    r[i] = float(v.Get(i).GetNumberAsDouble());
  }
  out = r;
}
inline void read(const tinygltf::Value& v, float& out) {
  if (v.IsNumber()) out = float(v.GetNumberAsDouble());
}
inline void read(const tinygltf::Value& v, int& out) {
  if (v.IsNumber()) out = v.GetNumberAsInt();
}
inline void read(const tinygltf::Value& v, bool& out) {
  if (v.IsBool()) out = v.Get<bool>();
}

}  // namespace luxel::scenes::gltf
