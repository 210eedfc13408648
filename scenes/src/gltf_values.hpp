#pragma once
// glm vectors and numbers to and from tinygltf Values (the extras luxel reads and writes).

#include "tinygltf.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <climits>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

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
/// The integer `v` holds, if it holds one that fits an int. tinygltf's GetNumberAsInt converts any
/// number, and converting 1e300 or NaN to int is undefined: an index of 2.5 or 1e300 names nothing.
inline std::optional<int> integer(const tinygltf::Value& v) {
  if (v.IsInt()) return v.Get<int>();
  if (!v.IsReal()) return std::nullopt;
  const double d = v.Get<double>();
  if (!(d >= double(INT_MIN) && d <= double(INT_MAX)) || d != std::floor(d)) return std::nullopt;
  return int(d);
}
inline void read(const tinygltf::Value& v, int& out) {
  if (const std::optional<int> i = integer(v)) out = *i;
}
/// A number as the file wrote it (to double's precision), for an error that names it.
inline std::string number_text(const tinygltf::Value& v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v.GetNumberAsDouble());
  return text;
}
inline void read(const tinygltf::Value& v, bool& out) {
  if (v.IsBool()) out = v.Get<bool>();
}

}  // namespace luxel::scenes::gltf
