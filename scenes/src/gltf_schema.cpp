#include "gltf_schema.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace luxel::scenes::gltf {

namespace {

using json = nlohmann::json;

/// How a value's JSON type reads in a message ("a string").
std::string json_kind(const json& v) {
  switch (v.type()) {
    case json::value_t::null: return "null";
    case json::value_t::object: return "an object";
    case json::value_t::array: return "an array";
    case json::value_t::string: return "a string";
    case json::value_t::boolean: return "a boolean";
    case json::value_t::number_float: return "a fractional number";
    default: return "a number";
  }
}

/// The value as the file wrote it, cut short: messages stay one readable line.
std::string json_text(const json& v) {
  std::string s = v.dump();
  if (s.size() > 40) s = s.substr(0, 37) + "...";
  return s;
}

std::string number_text(double d) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", d);
  return text;
}

/// An integer that fits an int: what tinygltf keeps as an index (it skips 1.0 and "1").
bool is_index_value(const json& v) {
  return (v.is_number_integer() || v.is_number_unsigned()) && v.get<double>() >= 0.0 && v.get<double>() <= 2147483647.0;
}

class SchemaCheck {
 public:
  SchemaCheck(const json& doc, const Report& fail, const Report& warn) : doc_(doc), fail_(fail), warn_(warn) {}

  void run() {
    // The lists first: an index into a list that is not one names nothing.
    for (const char* key : {"scenes", "nodes", "meshes", "materials", "textures", "images", "samplers", "accessors",
                            "bufferViews", "buffers", "cameras", "animations", "skins"})
      objects(doc_, key, key);
    extension_lists();
    scene();
    each("scenes", [&](const json& s, const std::string& at) { indices(s, "nodes", at, "nodes"); });
    each("nodes", [&](const json& n, const std::string& at) { node(n, at); });
    each("meshes", [&](const json& m, const std::string& at) { mesh(m, at); });
    each("materials", [&](const json& m, const std::string& at) { material(m, at); });
    each("textures", [&](const json& t, const std::string& at) {
      index(t, "source", at, "images");
      index(t, "sampler", at, "samplers");
    });
    each("images", [&](const json& i, const std::string& at) {
      index(i, "bufferView", at, "bufferViews");
      string(i, "uri", at);
    });
    each("samplers", [&](const json& s, const std::string& at) {
      for (const char* key : {"magFilter", "minFilter"}) optional_integer(s, key, at, "linear filtering");
      for (const char* key : {"wrapS", "wrapT"}) optional_integer(s, key, at, "REPEAT (10497)");
    });
    each("accessors", [&](const json& a, const std::string& at) { accessor(a, at); });
    each("bufferViews", [&](const json& v, const std::string& at) {
      required_index(v, "buffer", at, "buffers");
      for (const char* key : {"byteOffset", "byteLength", "byteStride"}) integer(v, key, at);
    });
    each("buffers", [&](const json& b, const std::string& at) {
      integer(b, "byteLength", at);
      string(b, "uri", at);
    });
    each("animations", [&](const json& a, const std::string& at) { animation(a, at); });
    lights();
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    fail_(what);
    throw std::logic_error(what);  // fail_ throws; this keeps [[noreturn]] honest
  }
  void warn(const std::string& what) const { warn_(what); }

  /// The length of a top-level array (0 when the file has none).
  size_t count_of(const char* top) const {
    if (std::string(top) == "lights") return lights_count_;
    const auto it = doc_.find(top);
    return it != doc_.end() && it->is_array() ? it->size() : 0;
  }

  /// Calls fn(element, path) for each object of the top-level array `key`; anything else there is an error.
  template <class Fn>
  void each(const char* key, Fn fn) {
    if (const json* a = objects(doc_, key, key))
      for (size_t i = 0; i < a->size(); ++i) fn((*a)[i], std::string(key) + "[" + std::to_string(i) + "]");
  }

  /// parent[key] as an array of objects, or nullptr when absent.
  const json* objects(const json& parent, const char* key, const std::string& at) const {
    const auto it = parent.find(key);
    if (it == parent.end()) return nullptr;
    if (!it->is_array()) fail(at + " is " + json_kind(*it) + ", not an array");
    for (size_t i = 0; i < it->size(); ++i)
      if (!(*it)[i].is_object()) fail(at + "[" + std::to_string(i) + "] is " + json_kind((*it)[i]) + ", not an object");
    return &*it;
  }

  /// parent[key] as an object, or nullptr when absent.
  const json* object(const json& parent, const char* key, const std::string& at) const {
    const auto it = parent.find(key);
    if (it == parent.end()) return nullptr;
    if (!it->is_object()) fail(at + "." + key + " is " + json_kind(*it) + ", not an object");
    return &*it;
  }

  void check_index(const json& v, const std::string& at, const char* target) const {
    if (!is_index_value(v)) fail(at + " is " + json_kind(v) + " (" + json_text(v) + "), not an index");
    const size_t n = count_of(target), i = v.get<size_t>();
    if (i >= n) fail(at + " names " + target + "[" + std::to_string(i) + "], which does not exist (the file has " + std::to_string(n) + ")");
  }
  void index(const json& o, const char* key, const std::string& at, const char* target) const {
    if (const auto it = o.find(key); it != o.end()) check_index(*it, at + "." + key, target);
  }
  void required_index(const json& o, const char* key, const std::string& at, const char* target) const {
    if (!o.contains(key)) fail(at + " has no " + key);
    index(o, key, at, target);
  }
  void indices(const json& o, const char* key, const std::string& at, const char* target) const {
    const auto it = o.find(key);
    if (it == o.end()) return;
    if (!it->is_array()) fail(at + "." + key + " is " + json_kind(*it) + ", not an array");
    for (size_t i = 0; i < it->size(); ++i) check_index((*it)[i], at + "." + key + "[" + std::to_string(i) + "]", target);
  }
  /// A count, size or offset luxel needs to read the data right: anything but an integer is an error.
  void integer(const json& o, const char* key, const std::string& at) const {
    const auto it = o.find(key);
    if (it != o.end() && !(it->is_number_integer() || it->is_number_unsigned()))
      fail(at + "." + key + " is " + json_kind(*it) + " (" + json_text(*it) + "), not an integer");
  }
  void string(const json& o, const char* key, const std::string& at) const {
    const auto it = o.find(key);
    if (it != o.end() && !it->is_string()) fail(at + "." + key + " is " + json_kind(*it) + ", not a string");
  }

  // --- Optional values: a warning and the default ----------------------------------------------

  void optional_integer(const json& o, const char* key, const std::string& at, const std::string& fallback) const {
    const auto it = o.find(key);
    if (it != o.end() && !(it->is_number_integer() || it->is_number_unsigned()))
      warn(at + "." + key + " is " + json_kind(*it) + " (" + json_text(*it) + "), not an integer; " + fallback + " is used");
  }
  void optional_boolean(const json& o, const char* key, const std::string& at, bool fallback) const {
    const auto it = o.find(key);
    if (it != o.end() && !it->is_boolean())
      warn(at + "." + key + " is " + json_kind(*it) + " (" + json_text(*it) + "), not a boolean; " + (fallback ? "true" : "false") + " is used");
  }
  /// A number: of the wrong type, `fallback` is used (tinygltf keeps its default); outside
  /// [lo, hi], the nearest end (the importer clamps it) when `clamped`, else only named.
  void optional_number(const json& o, const char* key, const std::string& at, double fallback, double lo = -INFINITY,
                       double hi = INFINITY) const {
    const auto it = o.find(key);
    if (it == o.end()) return;
    if (!it->is_number()) {
      warn(at + "." + key + " is " + json_kind(*it) + " (" + json_text(*it) + "), not a number; " + number_text(fallback) + " is used");
      return;
    }
    const double v = it->get<double>();
    if (v < lo || v > hi)
      warn(at + "." + key + " is " + number_text(v) + ", outside [" + number_text(lo) + ", " + number_text(hi) + "]; " +
           number_text(std::clamp(v, lo, hi)) + " is used");
  }
  void optional_numbers(const json& o, const char* key, const std::string& at, size_t n, const char* fallback) const {
    const auto it = o.find(key);
    if (it == o.end()) return;
    const bool ok = it->is_array() && std::all_of(it->begin(), it->end(), [](const json& v) { return v.is_number(); });
    if (!ok) warn(at + "." + key + " is " + json_kind(*it) + " (" + json_text(*it) + "), not " + std::to_string(n) + " numbers; " + fallback + " is used");
  }
  void optional_string(const json& o, const char* key, const std::string& at, const char* fallback) const {
    const auto it = o.find(key);
    if (it != o.end() && !it->is_string())
      warn(at + "." + key + " is " + json_kind(*it) + " (" + json_text(*it) + "), not a string; " + fallback + " is used");
  }

  // --- The parts --------------------------------------------------------------------------------

  void extension_lists() const {
    for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
      const auto it = doc_.find(key);
      if (it == doc_.end()) continue;
      if (!it->is_array()) fail(std::string(key) + " is " + json_kind(*it) + ", not an array");
      for (size_t i = 0; i < it->size(); ++i)
        if (!(*it)[i].is_string())
          fail(std::string(key) + "[" + std::to_string(i) + "] is " + json_kind((*it)[i]) + ", not an extension name");
    }
  }

  void scene() {
    if (const json* ext = object(doc_, "extensions", "")) {
      if (const json* lights = object(*ext, "KHR_lights_punctual", "extensions"))
        if (const json* list = objects(*lights, "lights", "extensions.KHR_lights_punctual.lights")) lights_count_ = list->size();
    }
    if (const auto it = doc_.find("scene"); it != doc_.end()) check_index(*it, "scene", "scenes");
  }

  void lights() const {
    const json* list = nullptr;
    if (const auto ext = doc_.find("extensions"); ext != doc_.end())
      if (const auto l = ext->find("KHR_lights_punctual"); l != ext->end())
        if (const auto a = l->find("lights"); a != l->end()) list = &*a;
    if (!list) return;
    for (size_t i = 0; i < list->size(); ++i) {
      const json& l = (*list)[i];
      const std::string at = "extensions.KHR_lights_punctual.lights[" + std::to_string(i) + "]";
      optional_numbers(l, "color", at, 3, "[1, 1, 1]");
      optional_number(l, "intensity", at, 1.0);
      optional_number(l, "range", at, 0.0);
      if (const json* spot = object(l, "spot", at)) {
        optional_number(*spot, "innerConeAngle", at + ".spot", 0.0);
        optional_number(*spot, "outerConeAngle", at + ".spot", 0.7853981634);
      }
    }
  }

  void node(const json& n, const std::string& at) const {
    indices(n, "children", at, "nodes");
    index(n, "mesh", at, "meshes");
    index(n, "camera", at, "cameras");
    optional_numbers(n, "matrix", at, 16, "the identity");
    optional_numbers(n, "translation", at, 3, "[0, 0, 0]");
    optional_numbers(n, "rotation", at, 4, "[0, 0, 0, 1]");
    optional_numbers(n, "scale", at, 3, "[1, 1, 1]");
    if (const json* ext = object(n, "extensions", at))
      if (const json* light = object(*ext, "KHR_lights_punctual", at + ".extensions"))
        required_index(*light, "light", at + ".extensions.KHR_lights_punctual", "lights");
  }

  void mesh(const json& m, const std::string& at) const {
    if (!m.contains("primitives")) fail(at + " has no primitives");
    const json* primitives = objects(m, "primitives", at + ".primitives");
    for (size_t i = 0; i < primitives->size(); ++i) {
      const json& p = (*primitives)[i];
      const std::string where = at + ".primitives[" + std::to_string(i) + "]";
      const auto attributes = p.find("attributes");
      if (attributes == p.end()) fail(where + " has no attributes");
      if (!attributes->is_object()) fail(where + ".attributes is " + json_kind(*attributes) + ", not an object");
      for (const auto& [name, value] : attributes->items()) check_index(value, where + ".attributes." + name, "accessors");
      index(p, "indices", where, "accessors");
      index(p, "material", where, "materials");
      integer(p, "mode", where);
    }
  }

  void texture_info(const json& m, const char* key, const std::string& at) const {
    const json* t = object(m, key, at);
    if (!t) return;
    const std::string where = at + "." + key;
    required_index(*t, "index", where, "textures");
    optional_integer(*t, "texCoord", where, "0");
    if (std::string(key) == "normalTexture") optional_number(*t, "scale", where, 1.0);
    if (std::string(key) == "occlusionTexture") optional_number(*t, "strength", where, 1.0, 0.0, 1.0);
    if (const json* ext = object(*t, "extensions", where))
      if (const json* tt = object(*ext, "KHR_texture_transform", where + ".extensions")) {
        const std::string tat = where + ".extensions.KHR_texture_transform";
        optional_numbers(*tt, "offset", tat, 2, "[0, 0]");
        optional_numbers(*tt, "scale", tat, 2, "[1, 1]");
        optional_number(*tt, "rotation", tat, 0.0);
        optional_integer(*tt, "texCoord", tat, "the texture's texCoord");
      }
  }

  void material(const json& m, const std::string& at) const {
    if (const json* pbr = object(m, "pbrMetallicRoughness", at)) {
      const std::string where = at + ".pbrMetallicRoughness";
      texture_info(*pbr, "baseColorTexture", where);
      texture_info(*pbr, "metallicRoughnessTexture", where);
      optional_numbers(*pbr, "baseColorFactor", where, 4, "[1, 1, 1, 1]");
      optional_number(*pbr, "metallicFactor", where, 1.0, 0.0, 1.0);
      optional_number(*pbr, "roughnessFactor", where, 1.0, 0.0, 1.0);
    }
    for (const char* key : {"normalTexture", "occlusionTexture", "emissiveTexture"}) texture_info(m, key, at);
    optional_numbers(m, "emissiveFactor", at, 3, "[0, 0, 0]");
    optional_string(m, "alphaMode", at, "OPAQUE");
    if (const auto it = m.find("alphaMode"); it != m.end() && it->is_string() && *it != "OPAQUE" && *it != "MASK" && *it != "BLEND")
      warn(at + ".alphaMode is " + json_text(*it) + ", not OPAQUE, MASK or BLEND; OPAQUE is used");
    optional_number(m, "alphaCutoff", at, 0.5);
    optional_boolean(m, "doubleSided", at, false);
    if (const json* ext = object(m, "extensions", at))
      if (const json* es = object(*ext, "KHR_materials_emissive_strength", at + ".extensions"))
        optional_number(*es, "emissiveStrength", at + ".extensions.KHR_materials_emissive_strength", 1.0);
  }

  void accessor(const json& a, const std::string& at) const {
    index(a, "bufferView", at, "bufferViews");
    for (const char* key : {"byteOffset", "componentType", "count"}) integer(a, key, at);
    string(a, "type", at);
    optional_boolean(a, "normalized", at, false);
    if (const json* sparse = object(a, "sparse", at)) {
      integer(*sparse, "count", at + ".sparse");
      for (const char* part : {"indices", "values"})
        if (const json* p = object(*sparse, part, at + ".sparse")) {
          index(*p, "bufferView", at + ".sparse." + part, "bufferViews");
          integer(*p, "byteOffset", at + ".sparse." + part);
        }
    }
  }

  void animation(const json& a, const std::string& at) const {
    const json* samplers = objects(a, "samplers", at + ".samplers");
    const size_t sampler_count = samplers ? samplers->size() : 0;
    for (size_t i = 0; i < sampler_count; ++i) {
      const std::string where = at + ".samplers[" + std::to_string(i) + "]";
      index((*samplers)[i], "input", where, "accessors");
      index((*samplers)[i], "output", where, "accessors");
    }
    const json* channels = objects(a, "channels", at + ".channels");
    for (size_t i = 0; channels && i < channels->size(); ++i) {
      const json& c = (*channels)[i];
      const std::string where = at + ".channels[" + std::to_string(i) + "]";
      if (const auto s = c.find("sampler"); s != c.end()) {
        if (!is_index_value(*s)) fail(where + ".sampler is " + json_kind(*s) + " (" + json_text(*s) + "), not an index");
        if (s->get<size_t>() >= sampler_count)
          fail(where + ".sampler names " + at + ".samplers[" + std::to_string(s->get<size_t>()) + "], which does not exist");
      }
      if (const json* target = object(c, "target", where)) index(*target, "node", where + ".target", "nodes");
    }
  }

  const json& doc_;
  const Report& fail_;
  const Report& warn_;
  size_t lights_count_ = 0;
};

}  // namespace

void check_schema(const nlohmann::json& doc, const Report& fail, const Report& warn) {
  if (!doc.is_object()) return;  // tinygltf says what the root is
  SchemaCheck(doc, fail, warn).run();
}

}  // namespace luxel::scenes::gltf
