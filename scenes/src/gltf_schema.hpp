#pragma once
// The structural fields luxel reads, checked against the glTF schema on the parsed JSON before
// tinygltf builds its model. tinygltf skips a value of the wrong JSON type and keeps its default,
// so a mesh whose `primitives` is an object would load with no geometry and a node whose `mesh`
// is "0" with no mesh: here such a file is refused, naming the JSON path. A wrong-typed or
// out-of-range optional value (a factor, a scale) is a warning naming the path and the value used.

#include <nlohmann/json.hpp>

#include <functional>
#include <string>

namespace luxel::scenes::gltf {

using Report = std::function<void(const std::string&)>;

/// Checks `doc` (the glTF JSON, an object): `fail` (which throws) on the first structural error,
/// "JSON.PATH problem"; `warn` once per optional value that is ignored or clamped.
void check_schema(const nlohmann::json& doc, const Report& fail, const Report& warn);

}  // namespace luxel::scenes::gltf
