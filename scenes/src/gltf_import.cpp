// load_gltf: tinygltf parses, luxel's layer (gltf_accessors.hpp) checks and reads, this file
// turns the node hierarchy into a flat Scene in Source units (gltf.hpp documents every mapping).

#include "gltf_accessors.hpp"
#include "gltf_axes.hpp"
#include "gltf_compression.hpp"
#include "gltf_materials.hpp"
#include "gltf_scene_extras.hpp"
#include "gltf_schema.hpp"
#include "gltf_values.hpp"
#include "one_line.hpp"
#include "luxel/scenes/framing.hpp"
#include "luxel/scenes/gltf.hpp"
#include "luxel/scenes/image_io.hpp"
#include "luxel/scenes/memory_limit.hpp"
#include "luxel/scenes/tangents.hpp"
#include "tinygltf.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <optional>

namespace luxel::scenes {

GltfError::GltfError(const std::string& what) : std::runtime_error(one_line(what)) {}

namespace {

namespace fs = std::filesystem;
using gltf::Accessors;
using gltf::AttributeRule;

/// Files larger than this are refused before they are read.
constexpr uint64_t kMaxFileBytes = uint64_t{1} << 31;

/// The extensions luxel reads (docs/gltf.md lists them with those it ignores and refuses).
const std::vector<std::string> kReadExtensions = {"KHR_texture_transform",   "KHR_lights_punctual",
                                                  "KHR_materials_emissive_strength", "KHR_materials_unlit",
                                                  "KHR_mesh_quantization",   "EXT_meshopt_compression",
                                                  "KHR_draco_mesh_compression"};

bool reads_extension(const std::string& name) {
  return std::find(kReadExtensions.begin(), kReadExtensions.end(), name) != kReadExtensions.end();
}

std::string first_line(const std::string& s) {
  size_t begin = 0;
  while (begin < s.size()) {
    size_t end = s.find('\n', begin);
    if (end == std::string::npos) end = s.size();
    std::string line = s.substr(begin, end - begin);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (!line.empty()) return line;
    begin = end + 1;
  }
  return "tinygltf could not read it";
}

std::string percent_decode(const std::string& s) {
  std::string out;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '%' && i + 2 < s.size() && std::isxdigit(uint8_t(s[i + 1])) && std::isxdigit(uint8_t(s[i + 2]))) {
      out += char(std::stoi(s.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += s[i];
    }
  }
  return out;
}

/// Why a (decoded) URI does not name a file inside the glTF's folder, or "" if it does.
std::string unconfined(const std::string& uri) {
  const fs::path p(uri);
  if (uri.empty()) return "is empty";
  if (p.is_absolute() || p.has_root_name() || p.has_root_directory()) return "is an absolute path";
  if (uri.find(':') != std::string::npos) return "is not a relative file reference";
  const fs::path normal = p.lexically_normal();
  if (!normal.empty() && *normal.begin() == "..") return "leaves the folder of the file";
  return "";
}

bool finite(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

/// Within 1e-9 of the identity: what luxel's own exports compose to (their root node undoes the
/// import's unit and axis conversion), so values are copied bit for bit.
bool is_identity(const glm::dmat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (std::abs(m[c][r] - (c == r ? 1.0 : 0.0)) > 1e-9) return false;
  return true;
}

class Importer {
 public:
  Importer(const std::string& path, const GltfImportOptions& options) : path_(path), options_(options) {
    dir_ = fs::path(path).parent_path().string();
    if (dir_.empty()) dir_ = ".";
  }

  Scene run() {
    parse();
    decode_compressed();
    Accessors accessors(model_, path_);
    accessors_ = &accessors;
    scene_.name = path_;
    images_.resize(model_.images.size());
    for (size_t i = 0; i < model_.materials.size(); ++i)
      scene_.materials.push_back(gltf::material_from_gltf(
          model_.materials[i], i, [this](int t, ColorSpace cs, const std::string& where) { return texture(t, cs, where); },
          [this](const std::string& what) { fail(what); }));
    walk_nodes();
    order_cameras();
    add_defaults();
    try {
      validate(scene_);
    } catch (const std::invalid_argument& e) {
      throw GltfError(e.what());  // validate names the scene, which is the file
    }
    return std::move(scene_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw GltfError(path_ + ": " + what); }

  void warn(const std::string& what) const {
    const std::string line = one_line(path_ + ": " + what);
    if (options_.warn) options_.warn(line);
    else std::cerr << "luxel: warning: " << line << "\n";
  }

  /// The memory limit's check (memory_limit.hpp), its refusal a GltfError like every problem here.
  void check_memory(uint64_t needed, const std::string& what) const {
    try {
      scenes::check_memory(path_, needed, what, options_.memory_limit);
    } catch (const MemoryLimitError& e) {
      throw GltfError(e.what());
    }
  }

  // --- Parsing -----------------------------------------------------------------------------------

  std::vector<uint8_t> read_whole(const std::string& file, const std::string& what) {
    std::error_code ec;
    const auto size = fs::file_size(file, ec);
    if (ec) fail(what + ": " + ec.message());
    if (size > kMaxFileBytes) fail(what + " has " + std::to_string(size) + " bytes, more than luxel reads");
    // The file's bytes and tinygltf's copy of the buffers in them are held together.
    file_bytes_ += size;
    check_memory(2 * file_bytes_, "its " + format_bytes(file_bytes_) + " of files, read and parsed");
    std::ifstream in(file, std::ios::binary);
    std::vector<uint8_t> bytes(size);
    if (!in || !in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size))) fail(what + ": cannot read it");
    return bytes;
  }

  /// The GLB container's header and chunks, checked before tinygltf sees them.
  void check_glb(const std::vector<uint8_t>& b) const {
    auto u32 = [&](size_t at) {
      uint32_t v;
      std::memcpy(&v, b.data() + at, 4);
      return v;
    };
    if (b.size() < 20) fail("truncated .glb: " + std::to_string(b.size()) + " bytes, less than a header");
    if (u32(4) != 2) fail(".glb version " + std::to_string(u32(4)) + ", not 2");
    if (u32(8) != b.size())
      fail((u32(8) > b.size() ? "truncated .glb: its header says " : ".glb header says ") + std::to_string(u32(8)) +
           " bytes, the file has " + std::to_string(b.size()));
    const uint64_t json = u32(12);
    if (u32(16) != 0x4E4F534Au) fail(".glb's first chunk is not JSON");
    if (20 + json > b.size()) fail("truncated .glb: its JSON chunk runs past the end of the file");
    uint64_t at = 20 + json;
    if (at < b.size()) {
      if (at + 8 > b.size()) fail("truncated .glb: a chunk header runs past the end of the file");
      if (at + 8 + u32(size_t(at)) > b.size()) fail("truncated .glb: its binary chunk runs past the end of the file");
    }
  }

  void parse() {
    std::vector<uint8_t> bytes = read_whole(path_, "cannot open it");
    const bool glb = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    if (glb) check_glb(bytes);
    if (bytes.empty()) fail("the file is empty");
    if (const std::optional<std::string> json =
            check_json(glb ? glb_json(bytes) : std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), glb))
      bytes = glb ? with_glb_json(bytes, *json) : std::vector<uint8_t>(json->begin(), json->end());
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&Importer::collect_image, this);
    tinygltf::FsCallbacks callbacks{&Importer::file_exists, &Importer::expand_path, &Importer::read_file,
                                    &Importer::write_file, this};
    loader.SetFsCallbacks(callbacks);
    std::string err, warn;
    bool ok = false;
    try {
      ok = glb ? loader.LoadBinaryFromMemory(&model_, &err, &warn, bytes.data(), unsigned(bytes.size()), dir_)
               : loader.LoadASCIIFromString(&model_, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                            unsigned(bytes.size()), dir_);
    } catch (const std::exception& e) {
      // tinygltf indexes with at() where it does not check (a .glb buffer of byteLength 0 is
      // data.at(0) of an empty vector): its exception becomes this file's error.
      fail(std::string("tinygltf could not read it (") + e.what() + ")");
    }
    if (!fs_error_.empty()) fail(fs_error_);
    if (!ok) {
      std::string why = first_line(err.empty() ? warn : err);
      // nlohmann's parse errors start with "[json.exception.parse_error.101] ".
      if (const size_t tag = why.find("[json.exception."); tag != std::string::npos) {
        const size_t end = why.find("] ", tag);
        why = "malformed JSON: " + (end == std::string::npos ? why : why.substr(end + 2));
      }
      fail(why);
    }
  }

  /// The JSON chunk of a .glb that check_glb accepted.
  static std::string_view glb_json(const std::vector<uint8_t>& b) {
    uint32_t length;
    std::memcpy(&length, b.data() + 12, 4);
    return std::string_view(reinterpret_cast<const char*>(b.data()) + 20, length);
  }

  /// The schema's structure (gltf_schema.hpp) and the extensions, on JSON that parses; what does
  /// not parse, tinygltf reports.
  /// Returns the JSON tinygltf is to read instead of the file's, if any (take_out_draco_indices,
  /// stub_fallback_buffers).
  std::optional<std::string> check_json(std::string_view text, bool glb) {
    const nlohmann::json doc = nlohmann::json::parse(text.begin(), text.end(), nullptr, false);
    if (doc.is_discarded() || !doc.is_object()) return std::nullopt;
    gltf::check_schema(doc, [this](const std::string& what) { fail(what); }, [this](const std::string& what) { warn(what); });
    check_extensions(doc);
    nlohmann::json copy;  // made when something is to change
    take_out_draco_indices(doc, copy);
    if (!glb) stub_fallback_buffers(doc, copy);
    if (copy.is_null()) return std::nullopt;
    return copy.dump();
  }

  /// A required extension luxel does not read refuses the file: drawn without it, it would be
  /// drawn wrong. One that is only used is drawn without, with a warning.
  void check_extensions(const nlohmann::json& doc) {
    if (const auto it = doc.find("extensionsRequired"); it != doc.end())
      for (const auto& e : *it)
        if (!reads_extension(e.get<std::string>()))
          fail("requires extension " + e.get<std::string>() + ", which luxel does not read");
    if (const auto it = doc.find("extensionsUsed"); it != doc.end())
      for (const auto& e : *it)
        if (!reads_extension(e.get<std::string>()))
          warn("uses extension " + e.get<std::string>() + ", which luxel does not read; drawn without it");
  }

  /// Compressed geometry decoded into plain buffers (gltf_compression.hpp), counted by the memory
  /// limit with the buffers and images before each decoder allocates.
  void decode_compressed() {
    for (const auto& [mesh, primitive, accessor] : draco_indices_)
      if (mesh < model_.meshes.size() && primitive < model_.meshes[mesh].primitives.size())
        model_.meshes[mesh].primitives[primitive].indices = accessor;
    gltf::DecodeReporting report;
    report.fail = [this](const std::string& what) { fail(what); };
    report.reserve = [this](uint64_t bytes, const std::string& what) {
      check_memory(buffer_bytes() + image_bytes_ + bytes, "decoding " + what);
    };
    gltf::decode_meshopt_views(model_, report);
    gltf::decode_draco_primitives(model_, report);
  }

  /// tinygltf 2.7 refuses an index accessor without a buffer view, which is how a Draco primitive's
  /// indices are written (they are in the Draco stream): those primitives' `indices` are taken out
  /// of the JSON tinygltf reads (`copy`, made from `doc` when null), kept in draco_indices_, and put
  /// back after it.
  void take_out_draco_indices(const nlohmann::json& doc, nlohmann::json& copy) {
    // check_schema has checked the types and indices; this checks them again rather than rely on it.
    const auto meshes = doc.find("meshes");
    const auto accessors = doc.find("accessors");
    if (meshes == doc.end() || accessors == doc.end() || !meshes->is_array() || !accessors->is_array()) return;
    for (size_t m = 0; m < meshes->size(); ++m) {
      const auto primitives = (*meshes)[m].find("primitives");
      if (primitives == (*meshes)[m].end() || !primitives->is_array()) continue;
      for (size_t k = 0; k < primitives->size(); ++k) {
        const nlohmann::json& p = (*primitives)[k];
        const auto ext = p.find("extensions");
        const auto indices = p.find("indices");
        if (ext == p.end() || !ext->is_object() || !ext->contains("KHR_draco_mesh_compression") || indices == p.end() ||
            !indices->is_number_unsigned() || indices->get<size_t>() >= accessors->size())
          continue;
        const size_t a = indices->get<size_t>();
        if (!(*accessors)[a].is_object() || (*accessors)[a].contains("bufferView")) continue;
        if (copy.is_null()) copy = doc;
        copy["meshes"][m]["primitives"][k].erase("indices");
        draco_indices_.push_back({m, k, int(a)});
      }
    }
  }

  /// An EXT_meshopt_compression fallback buffer of a .gltf may have no URI (its bytes are never
  /// read: the compressed views it stands behind are decoded), which tinygltf refuses: tinygltf reads
  /// three zero bytes in its place. (In a .glb tinygltf takes such a buffer from the binary chunk.)
  static void stub_fallback_buffers(const nlohmann::json& doc, nlohmann::json& copy) {
    const auto buffers = doc.find("buffers");
    if (buffers == doc.end() || !buffers->is_array()) return;
    for (size_t i = 0; i < buffers->size(); ++i) {
      const nlohmann::json& b = (*buffers)[i];
      if (!b.is_object() || b.contains("uri")) continue;
      const auto ext = b.find("extensions");
      if (ext == b.end() || !ext->is_object()) continue;
      const auto meshopt = ext->find("EXT_meshopt_compression");
      if (meshopt == ext->end() || !meshopt->is_object()) continue;
      const auto fallback = meshopt->find("fallback");
      if (fallback == meshopt->end() || *fallback != true) continue;
      if (copy.is_null()) copy = doc;
      copy["buffers"][i]["uri"] = "data:application/octet-stream;base64,AAAA";
      copy["buffers"][i]["byteLength"] = 3;
    }
  }

  /// `bytes` (a .glb that check_glb accepted) with `json` as its JSON chunk.
  static std::vector<uint8_t> with_glb_json(const std::vector<uint8_t>& bytes, const std::string& json) {
    uint32_t old_length;
    std::memcpy(&old_length, bytes.data() + 12, 4);
    std::string chunk = json;
    while (chunk.size() % 4) chunk += ' ';
    std::vector<uint8_t> out(bytes.begin(), bytes.begin() + 12);
    const uint32_t length = uint32_t(chunk.size()), type = 0x4E4F534Au;
    out.insert(out.end(), reinterpret_cast<const uint8_t*>(&length), reinterpret_cast<const uint8_t*>(&length) + 4);
    out.insert(out.end(), reinterpret_cast<const uint8_t*>(&type), reinterpret_cast<const uint8_t*>(&type) + 4);
    out.insert(out.end(), chunk.begin(), chunk.end());
    out.insert(out.end(), bytes.begin() + 20 + old_length, bytes.end());
    const uint32_t total = uint32_t(out.size());
    std::memcpy(out.data() + 8, &total, 4);
    return out;
  }

  // tinygltf's file system, confined: it joins the folder and a (decoded) buffer URI, then asks.
  static bool file_exists(const std::string& abs, void* user) {
    auto* self = static_cast<Importer*>(user);
    const std::string prefix = self->folder_prefix();
    if (abs.rfind(prefix, 0) != 0) return false;  // tinygltf's second try, relative to the working directory
    const std::string uri = abs.substr(prefix.size());
    if (const std::string why = unconfined(uri); !why.empty()) {
      self->record("buffer URI '" + uri + "' " + why);
      return false;
    }
    std::error_code ec;
    if (!fs::is_regular_file(abs, ec)) {
      self->record("buffer file '" + uri + "' is missing");
      return false;
    }
    return true;
  }
  static std::string expand_path(const std::string& path, void*) { return path; }
  static bool read_file(std::vector<unsigned char>* out, std::string* err, const std::string& abs, void* user) {
    auto* self = static_cast<Importer*>(user);
    try {
      *out = self->read_whole(abs, "buffer file '" + abs + "'");
    } catch (const GltfError& e) {
      self->record(std::string(e.what()).substr(self->path_.size() + 2));
      return false;
    }
    return true;
  }
  static bool write_file(std::string*, const std::string&, const std::vector<unsigned char>&, void*) { return false; }
  /// How tinygltf's JoinPath puts the folder before a URI.
  std::string folder_prefix() const { return dir_.back() == '/' ? dir_ : dir_ + "/"; }
  void record(const std::string& what) {
    if (fs_error_.empty()) fs_error_ = what;
  }

  /// tinygltf hands data-URI and buffer-view images here while parsing. Buffer views are not
  /// checked yet, so their bytes are read later, through the validation layer.
  static bool collect_image(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                            const unsigned char* bytes, int size, void* user) {
    auto* self = static_cast<Importer*>(user);
    if (image->bufferView < 0 && size > 0) self->data_uri_images_[index].assign(bytes, bytes + size);
    return true;
  }

  // --- Images and textures -----------------------------------------------------------------------

  const PixelImage& image(int index, const std::string& where) {
    if (index < 0 || size_t(index) >= model_.images.size())
      fail(where + " refers to image " + std::to_string(index) + " of " + std::to_string(model_.images.size()));
    std::optional<PixelImage>& cached = images_[size_t(index)];
    if (cached) return *cached;
    const tinygltf::Image& im = model_.images[size_t(index)];
    const std::string name = where + ": image " + std::to_string(index) + (im.name.empty() ? "" : " '" + im.name + "'");
    try {
      if (im.bufferView >= 0) {
        cached = read_image(accessors_->view(im.bufferView, name), name, options_.memory_limit);
      } else if (auto it = data_uri_images_.find(index); it != data_uri_images_.end()) {
        cached = read_image(it->second, name, options_.memory_limit);
      } else if (im.uri.rfind("data:", 0) == 0) {
        fail(name + " has a data URI that is not base64 PNG or JPEG");
      } else if (!im.uri.empty()) {
        const std::string uri = percent_decode(im.uri);
        if (const std::string why = unconfined(uri); !why.empty()) fail(name + " URI '" + uri + "' " + why);
        const std::string file = folder_prefix() + uri;
        std::error_code ec;
        if (!fs::is_regular_file(file, ec)) fail(name + " file '" + uri + "' is missing");
        cached = read_image(file, options_.memory_limit);
      } else {
        fail(name + " has neither a URI nor a buffer view");
      }
    } catch (const GltfError&) {
      throw;
    } catch (const std::exception& e) {
      fail(name + ": " + e.what());
    }
    image_bytes_ += image_bytes(uint64_t(cached->width), uint64_t(cached->height), cached->is_hdr());
    ++images_read_;
    check_memory(buffer_bytes() + image_bytes_, std::to_string(images_read_) + " images and " + format_bytes(buffer_bytes()) + " of buffers");
    return *cached;
  }

  int texture(int index, ColorSpace color_space, const std::string& where) {
    if (index < 0 || size_t(index) >= model_.textures.size())
      fail(where + " refers to texture " + std::to_string(index) + " of " + std::to_string(model_.textures.size()));
    const auto key = std::make_pair(index, color_space);
    if (auto it = textures_.find(key); it != textures_.end()) return it->second;
    const tinygltf::Texture& t = model_.textures[size_t(index)];
    if (t.source < 0) fail(where + ": texture " + std::to_string(index) + " has no image luxel can read");
    Texture out;
    out.faces.push_back(image(t.source, where + " (texture " + std::to_string(index) + ")"));  // checks t.source
    const tinygltf::Image& im = model_.images[size_t(t.source)];
    out.name = !im.name.empty() ? im.name : !im.uri.empty() && im.uri.rfind("data:", 0) != 0 ? im.uri : "texture " + std::to_string(index);
    out.color_space = color_space;
    if (t.sampler >= 0) {
      if (size_t(t.sampler) >= model_.samplers.size()) fail(where + ": texture " + std::to_string(index) + " refers to sampler " + std::to_string(t.sampler));
      const tinygltf::Sampler& s = model_.samplers[size_t(t.sampler)];
      auto wrap = [](int w) {
        return w == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE ? Wrap::clamp : w == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT ? Wrap::mirror : Wrap::repeat;
      };
      out.wrap_u = wrap(s.wrapS);
      out.wrap_v = wrap(s.wrapT);
      out.mag = s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST ? Filter::nearest : Filter::linear;
      out.min = s.minFilter == TINYGLTF_TEXTURE_FILTER_NEAREST || s.minFilter == TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST ||
                        s.minFilter == TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR
                    ? Filter::nearest
                    : Filter::linear;
      out.mipmaps = s.minFilter != TINYGLTF_TEXTURE_FILTER_NEAREST && s.minFilter != TINYGLTF_TEXTURE_FILTER_LINEAR;
    }
    scene_.textures.push_back(std::move(out));
    return textures_[key] = int(scene_.textures.size()) - 1;
  }

  // --- Nodes -------------------------------------------------------------------------------------

  glm::dmat4 local_matrix(const tinygltf::Node& n, const std::string& where) const {
    auto all_finite = [](const std::vector<double>& v) {
      return std::all_of(v.begin(), v.end(), [](double d) { return std::isfinite(d); });
    };
    if (!n.matrix.empty()) {
      if (n.matrix.size() != 16 || !all_finite(n.matrix)) fail(where + " has a matrix that is not 16 finite numbers");
      glm::dmat4 m;
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) m[c][r] = n.matrix[size_t(c * 4 + r)];
      return m;
    }
    glm::dmat4 m(1.0);
    if (!n.translation.empty()) {
      if (n.translation.size() != 3 || !all_finite(n.translation)) fail(where + " has a bad translation");
      m[3] = glm::dvec4(n.translation[0], n.translation[1], n.translation[2], 1.0);
    }
    if (!n.rotation.empty()) {
      if (n.rotation.size() != 4 || !all_finite(n.rotation)) fail(where + " has a bad rotation");
      glm::dquat q(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);
      const double len = glm::length(q);
      if (!(len > 0.0)) fail(where + " has a zero rotation quaternion");
      m = m * glm::mat4_cast(q / len);
    }
    if (!n.scale.empty()) {
      if (n.scale.size() != 3 || !all_finite(n.scale)) fail(where + " has a bad scale");
      m = m * glm::dmat4(glm::dvec4(n.scale[0], 0, 0, 0), glm::dvec4(0, n.scale[1], 0, 0), glm::dvec4(0, 0, n.scale[2], 0),
                         glm::dvec4(0, 0, 0, 1));
    }
    return m;
  }

  /// A translation animation moving a node and everything under it: the channel, the world
  /// matrix of the animated node's parent, the node's own translation at rest.
  struct Motion {
    int channel = -1;
    glm::dmat4 parent{1.0};
    glm::dvec3 rest{0.0};
  };

  /// Per node, the channel of the first animation that animates its translation, or -1. Only
  /// the first animation plays (a file's other clips are not read); rotation, scale and morph
  /// weights are not read.
  std::vector<int> translation_channels() const {
    std::vector<int> of(model_.nodes.size(), -1);
    if (model_.animations.empty()) return of;
    const tinygltf::Animation& a = model_.animations[0];
    for (size_t c = 0; c < a.channels.size(); ++c) {
      const tinygltf::AnimationChannel& ch = a.channels[c];
      if (ch.target_path != "translation") continue;
      if (ch.target_node < 0 || size_t(ch.target_node) >= model_.nodes.size())
        fail("animation 0 channel " + std::to_string(c) + " targets node " + std::to_string(ch.target_node));
      if (of[size_t(ch.target_node)] < 0) of[size_t(ch.target_node)] = int(c);
    }
    return of;
  }

  /// The model path of a translation channel: its keys' times, each offset the animated
  /// translation's change from rest, in world space. LINEAR is read exactly; STEP and CUBICSPLINE
  /// as linear between their keys' values.
  std::vector<ModelKey> animated_path(const Motion& motion, const std::string& node) const {
    const tinygltf::Animation& a = model_.animations[0];
    const tinygltf::AnimationChannel& ch = a.channels[size_t(motion.channel)];
    const std::string where = node + ": animation 0 channel " + std::to_string(motion.channel);
    if (ch.sampler < 0 || size_t(ch.sampler) >= a.samplers.size()) fail(where + " refers to sampler " + std::to_string(ch.sampler));
    const tinygltf::AnimationSampler& sampler = a.samplers[size_t(ch.sampler)];
    const gltf::Floats times = accessors_->attribute(sampler.input, {"input", {TINYGLTF_TYPE_SCALAR}}, where + " input");
    const gltf::Floats values = accessors_->attribute(sampler.output, {"output", {TINYGLTF_TYPE_VEC3}}, where + " output");
    const bool cubic = sampler.interpolation == "CUBICSPLINE";
    if (values.count != times.count * (cubic ? 3 : 1))
      fail(where + " has " + std::to_string(values.count) + " translations for " + std::to_string(times.count) + " times");
    std::vector<ModelKey> keys;
    for (size_t k = 0; k < times.count; ++k) {
      const float t = *times.at(k);
      if (!std::isfinite(t) || (k > 0 && !(t > keys.back().time))) fail(where + " key " + std::to_string(k) + " is not finite or not later than the one before");
      const float* v = values.at(cubic ? 3 * k + 1 : k);  // a cubic key is (in-tangent, value, out-tangent)
      const glm::dvec3 change = glm::dvec3(v[0], v[1], v[2]) - motion.rest;
      keys.push_back({t, glm::vec3(motion.parent * glm::dvec4(change, 0.0))});
      if (!finite(glm::dvec3(keys.back().offset))) fail(where + " key " + std::to_string(k) + " is not finite");
    }
    return keys;
  }

  void walk_nodes() {
    std::vector<int> roots;
    if (!model_.scenes.empty()) {
      const int s = model_.defaultScene >= 0 ? model_.defaultScene : 0;
      if (size_t(s) >= model_.scenes.size()) fail("scene " + std::to_string(s) + " does not exist");
      roots = model_.scenes[size_t(s)].nodes;
      gltf::read_scene_extras(model_.scenes[size_t(s)].extras, scene_, [this](const std::string& what) { fail(what); });
    } else {
      // No scenes: every node without a parent is drawn.
      std::vector<char> child(model_.nodes.size(), 0);
      for (const auto& n : model_.nodes)
        for (int c : n.children)
          if (c >= 0 && size_t(c) < model_.nodes.size()) child[size_t(c)] = 1;
      for (size_t i = 0; i < model_.nodes.size(); ++i)
        if (!child[i]) roots.push_back(int(i));
    }
    // Depth first, without recursion, each node at most once (a cycle or a shared child is an error).
    // placed: `parent` is the node's world matrix; `motion` the translation animation that moves it.
    struct Item { int node; glm::dmat4 parent; int depth; Motion motion; };
    const std::vector<int> channel_of = translation_channels();
    std::vector<char> seen(model_.nodes.size(), 0);
    std::vector<Item> stack, placed;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, gltf::gltf_to_source(), 1, {}});
    while (!stack.empty()) {
      const Item item = stack.back();
      stack.pop_back();
      if (item.node < 0 || size_t(item.node) >= model_.nodes.size())
        fail("refers to node " + std::to_string(item.node) + " of " + std::to_string(model_.nodes.size()));
      if (seen[size_t(item.node)]) fail("node " + std::to_string(item.node) + " is reached twice (a cycle, or two parents)");
      if (item.depth > kMaxGltfNodeDepth) fail("nodes nest deeper than " + std::to_string(kMaxGltfNodeDepth) + " levels");
      seen[size_t(item.node)] = 1;
      const tinygltf::Node& n = model_.nodes[size_t(item.node)];
      const glm::dmat4 world = item.parent * local_matrix(n, node_name(item.node));
      Motion motion = item.motion;  // the nearest animated node's, itself included
      if (const int c = channel_of[size_t(item.node)]; c >= 0) {
        motion.channel = c;
        motion.parent = item.parent;
        motion.rest = n.translation.size() == 3 ? glm::dvec3(n.translation[0], n.translation[1], n.translation[2]) : glm::dvec3(0.0);
      }
      placed.push_back({item.node, world, item.depth, motion});
      for (auto c = n.children.rbegin(); c != n.children.rend(); ++c) stack.push_back({*c, world, item.depth + 1, motion});
    }
    // Instancing multiplies vertices and triangles: the flattened totals are known, and refused,
    // before any is read.
    Flattened total;
    for (const Item& item : placed) {
      const Flattened f = flattened(model_.nodes[size_t(item.node)].mesh);
      total.vertices += f.vertices, total.indices += f.indices, total.bytes += f.bytes;
    }
    if (total.vertices > kMaxGltfSceneVertices)
      fail("the flattened scene has " + std::to_string(total.vertices) + " vertices, more than luxel reads (" +
           std::to_string(kMaxGltfSceneVertices) + ")");
    if (total.indices > kMaxGltfSceneIndices)
      fail("the flattened scene has " + std::to_string(total.indices) + " triangle corners, more than luxel reads (" +
           std::to_string(kMaxGltfSceneIndices) + ")");
    check_memory(buffer_bytes() + image_bytes_ + total.bytes,
                 std::to_string(total.indices / 3) + " triangles, " + std::to_string(total.vertices) + " vertices, " +
                     std::to_string(images_read_) + " images, " + format_bytes(buffer_bytes()) + " of buffers");
    for (const Item& item : placed) {
      const tinygltf::Node& n = model_.nodes[size_t(item.node)];
      const std::string where = node_name(item.node);
      if (n.mesh >= 0) add_mesh(n.mesh, item.parent, where, n.extras.Get("luxel"), item.motion);
      if (n.camera >= 0) add_camera(n.camera, item.parent, where);
      if (auto it = n.extensions.find("KHR_lights_punctual"); it != n.extensions.end() && it->second.Get("light").IsNumber()) {
        const tinygltf::Value& light = it->second.Get("light");
        const std::optional<int> index = gltf::integer(light);
        if (!index) fail(where + " refers to light " + gltf::number_text(light) + ", which is not an index");
        add_light(*index, item.parent, where);
      }
    }
  }

  uint64_t buffer_bytes() const {
    uint64_t bytes = 0;
    for (const tinygltf::Buffer& b : model_.buffers) bytes += b.data.size();
    return bytes;
  }

  std::string node_name(int index) const {
    const tinygltf::Node& n = model_.nodes[size_t(index)];
    return "node " + std::to_string(index) + (n.name.empty() ? "" : " '" + n.name + "'");
  }

  /// The vertices and triangle corners a mesh will have once read, and the bytes they take as read
  /// and as kept (each attribute read as floats, then copied into the Mesh; the corners as 32-bit
  /// indices, then kept in up to 32 bits).
  struct Flattened { uint64_t vertices = 0, indices = 0, bytes = 0; };

  /// A mesh's Flattened: its POSITION counts (or a vertex per corner where flat normals unweld it)
  /// and its triangle list's length. (Materials are read before the nodes.)
  Flattened flattened(int mesh) const {
    Flattened total;
    if (mesh < 0 || size_t(mesh) >= model_.meshes.size()) return total;
    for (const tinygltf::Primitive& p : model_.meshes[size_t(mesh)].primitives) {
      auto count = [&](int accessor) -> uint64_t {
        return accessor >= 0 && size_t(accessor) < model_.accessors.size() ? model_.accessors[size_t(accessor)].count : 0;
      };
      auto position = p.attributes.find("POSITION");
      const uint64_t n = position == p.attributes.end() ? 0 : count(position->second);
      const uint64_t m = p.indices >= 0 ? count(p.indices) : n;
      const uint64_t corners = p.mode == TINYGLTF_MODE_TRIANGLES || p.mode < 0 ? m : 3 * (m > 2 ? m - 2 : 0);
      // Flat normals unweld: a primitive without NORMAL, unless it gets a constant normal or is
      // unlit (primitive() below).
      const bool unlit = p.material >= 0 && size_t(p.material) < scene_.materials.size() &&
                         scene_.materials[size_t(p.material)].family == ShaderFamily::unlit_generic;
      const bool welded = p.attributes.count("NORMAL") || options_.missing_normal || unlit;
      const uint64_t vertices = welded ? n : corners;
      const bool uv0 = p.attributes.count("TEXCOORD_0") != 0;
      const uint64_t vertex_bytes = sizeof(glm::vec3) * 2 +  // position, normal
                                    (p.attributes.count("TANGENT") || (uv0 && options_.generate_tangents) ? sizeof(glm::vec4) : 0) +
                                    (uv0 ? sizeof(glm::vec2) : 0) + (p.attributes.count("TEXCOORD_1") ? sizeof(glm::vec2) : 0) +
                                    (p.attributes.count("COLOR_0") ? sizeof(glm::vec4) : 0);
      total.vertices += vertices;
      total.indices += corners;
      total.bytes += 2 * (vertices * vertex_bytes + corners * sizeof(uint32_t));
    }
    return total;
  }

  // --- Meshes ------------------------------------------------------------------------------------

  /// The node's mesh; its VertexLitGeneric primitives become one Model, whose centroid is
  /// `luxel.centroid` (the node's extras, as luxel exports it) or else the mean of their vertices,
  /// and whose path is `luxel.path` ([{"time": s, "offset": [x, y, z]}...], offsets in the node's
  /// parent's units, as luxel exports it).
  void add_mesh(int index, const glm::dmat4& world, const std::string& node, const tinygltf::Value& luxel, const Motion& motion) {
    if (size_t(index) >= model_.meshes.size()) fail(node + " refers to mesh " + std::to_string(index));
    const tinygltf::Mesh& m = model_.meshes[size_t(index)];
    Model model;
    model.name = m.name.empty() ? "mesh " + std::to_string(index) : m.name;
    glm::dvec3 sum(0.0);
    size_t count = 0;
    for (size_t p = 0; p < m.primitives.size(); ++p) {
      const std::string where = "mesh " + std::to_string(index) + (m.name.empty() ? "" : " '" + m.name + "'") +
                                " primitive " + std::to_string(p);
      Mesh mesh = primitive(m.primitives[p], world, where);
      mesh.name = m.primitives.size() == 1 ? model.name : model.name + " " + std::to_string(p);
      const bool vertexlit = mesh.material < 0 || scene_.materials[size_t(mesh.material)].family == ShaderFamily::vertexlit_generic;
      if (vertexlit) {
        for (const glm::vec3& v : mesh.positions) sum += glm::dvec3(v);
        count += mesh.positions.size();
        model.meshes.push_back(int(scene_.meshes.size()));
      }
      scene_.meshes.push_back(std::move(mesh));
    }
    if (!model.meshes.empty()) {
      model.centroid = glm::vec3(count ? sum / double(count) : glm::dvec3(0.0));
      glm::vec3 given(std::numeric_limits<float>::quiet_NaN());
      gltf::read(luxel.Get("centroid"), given);
      if (finite(glm::dvec3(given))) model.centroid = is_identity(world) ? given : glm::vec3(world * glm::dvec4(given, 1.0));
      const tinygltf::Value& path = luxel.Get("path");
      for (size_t k = 0; path.IsArray() && k < path.ArrayLen(); ++k) {
        ModelKey key;
        key.time = std::numeric_limits<float>::quiet_NaN();
        key.offset = glm::vec3(std::numeric_limits<float>::quiet_NaN());
        gltf::read(path.Get(int(k)).Get("time"), key.time);
        gltf::read(path.Get(int(k)).Get("offset"), key.offset);
        if (!std::isfinite(key.time) || !finite(glm::dvec3(key.offset)) || (k > 0 && !(key.time > model.path.back().time)))
          fail(node + ": extras.luxel.path key " + std::to_string(k) + " is not a finite time and offset later than the key before");
        if (!is_identity(world)) key.offset = glm::vec3(world * glm::dvec4(key.offset, 0.0));
        model.path.push_back(key);
      }
      if (!path.IsArray() && motion.channel >= 0) model.path = animated_path(motion, node);
      scene_.models.push_back(std::move(model));
    }
  }

  Mesh primitive(const tinygltf::Primitive& p, const glm::dmat4& world, const std::string& where) {
    static const char* kModes[] = {"POINTS", "LINES", "LINE_LOOP", "LINE_STRIP"};
    if (p.mode >= 0 && p.mode <= 3) fail(where + " is " + kModes[p.mode] + "; luxel draws triangles only");
    if (p.mode > 6) fail(where + " has unknown mode " + std::to_string(p.mode));
    if (p.material >= int(model_.materials.size())) fail(where + " refers to material " + std::to_string(p.material));
    Mesh mesh;
    mesh.material = p.material;
    auto attr = [&](const char* name) { auto it = p.attributes.find(name); return it == p.attributes.end() ? -1 : it->second; };
    const int position = attr("POSITION");
    if (position < 0) fail(where + " has no POSITION");
    const size_t n = accessors_->count(position, where);
    if (n > kMaxGltfVertices) fail(where + " has " + std::to_string(n) + " vertices, more than luxel reads");
    auto read = [&](const char* name, const AttributeRule& rule) -> std::optional<gltf::Floats> {
      const int a = attr(name);
      if (a < 0) return std::nullopt;
      gltf::Floats f = accessors_->attribute(a, rule, where);
      if (f.count != n) fail(where + " " + name + " has " + std::to_string(f.count) + " elements for " + std::to_string(n) + " positions");
      return f;
    };
    using Q = AttributeRule::Quantized;
    const auto pos = read("POSITION", {"POSITION", {TINYGLTF_TYPE_VEC3}, false, Q::integers});
    const auto nrm = read("NORMAL", {"NORMAL", {TINYGLTF_TYPE_VEC3}, false, Q::signed_normalized});
    const auto tan = read("TANGENT", {"TANGENT", {TINYGLTF_TYPE_VEC4}, false, Q::signed_normalized});
    const auto uv0 = read("TEXCOORD_0", {"TEXCOORD_0", {TINYGLTF_TYPE_VEC2}, true, Q::integers});
    const auto uv1 = read("TEXCOORD_1", {"TEXCOORD_1", {TINYGLTF_TYPE_VEC2}, true, Q::integers});
    const auto col = read("COLOR_0", {"COLOR_0", {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4}, true});

    // Indices as the mode defines triangles (glTF 2.0 section 3.7.2.1).
    std::vector<uint32_t> raw;
    int index_type = 0;
    if (p.indices >= 0) {
      raw = accessors_->indices(p.indices, where, &index_type);
      for (size_t k = 0; k < raw.size(); ++k)
        if (raw[k] >= n)
          fail(where + " index " + std::to_string(k) + " = " + std::to_string(raw[k]) + " is beyond its " + std::to_string(n) + " vertices");
    } else {
      raw.resize(n);
      for (size_t k = 0; k < n; ++k) raw[k] = uint32_t(k);
    }
    std::vector<uint32_t> tri;
    const int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
      if (raw.size() % 3 != 0) fail(where + " has " + std::to_string(raw.size()) + " indices, not a multiple of 3");
      tri = std::move(raw);
    } else {
      for (size_t i = 0; i + 2 < raw.size(); ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_STRIP)
          tri.insert(tri.end(), {raw[i], raw[i + 1 + i % 2], raw[i + 2 - i % 2]});
        else  // TRIANGLE_FAN
          tri.insert(tri.end(), {raw[i + 1], raw[i + 2], raw[0]});
      }
    }

    // World transform (the unit conversion included); the identity copies values bit for bit.
    const bool identity = is_identity(world);
    const glm::dmat3 linear(world);
    const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(linear));
    const bool mirrored = glm::determinant(linear) < 0.0;
    mesh.positions.resize(n);
    for (size_t v = 0; v < n; ++v) {
      const glm::dvec3 local(pos->at(v)[0], pos->at(v)[1], pos->at(v)[2]);
      if (!finite(local)) fail(where + " position " + std::to_string(v) + " is not finite");
      mesh.positions[v] = identity ? glm::vec3(pos->at(v)[0], pos->at(v)[1], pos->at(v)[2])
                                   : glm::vec3(glm::dvec3(world * glm::dvec4(local, 1.0)));
      if (!finite(glm::dvec3(mesh.positions[v]))) fail(where + " position " + std::to_string(v) + " is not finite in world space");
    }
    if (nrm || options_.missing_normal) {
      mesh.normals.resize(n);
      for (size_t v = 0; v < n; ++v) {
        const glm::vec3 local = nrm ? glm::vec3(nrm->at(v)[0], nrm->at(v)[1], nrm->at(v)[2]) : *options_.missing_normal;
        if (identity) {
          mesh.normals[v] = local;
        } else {
          const glm::dvec3 w = normal_matrix * glm::dvec3(local);
          const double len = glm::length(w);
          mesh.normals[v] = len > 0.0 ? glm::vec3(w / len) : glm::vec3(0.0f);
        }
      }
    }
    if (tan) {
      mesh.tangents.resize(n);
      for (size_t v = 0; v < n; ++v) {
        const glm::vec3 local(tan->at(v)[0], tan->at(v)[1], tan->at(v)[2]);
        const float w = (tan->at(v)[3] < 0.0f) != mirrored ? -1.0f : 1.0f;
        if (identity) {
          mesh.tangents[v] = glm::vec4(local, w);
        } else {
          const glm::dvec3 t = linear * glm::dvec3(local);
          const double len = glm::length(t);
          mesh.tangents[v] = glm::vec4(len > 0.0 ? glm::vec3(t / len) : glm::vec3(0.0f), w);
        }
      }
    }
    auto vec2s = [&](const std::optional<gltf::Floats>& f, std::vector<glm::vec2>& out) {
      if (!f) return;
      out.resize(n);
      for (size_t v = 0; v < n; ++v) out[v] = glm::vec2(f->at(v)[0], f->at(v)[1]);
    };
    vec2s(uv0, mesh.uv0);
    vec2s(uv1, mesh.uv1);
    if (col) {
      mesh.colors.resize(n);
      for (size_t v = 0; v < n; ++v)
        mesh.colors[v] = glm::vec4(col->at(v)[0], col->at(v)[1], col->at(v)[2], col->components == 4 ? col->at(v)[3] : 1.0f);
    }
    if (mirrored)
      for (size_t t = 0; t + 2 < tri.size(); t += 3) std::swap(tri[t + 1], tri[t + 2]);

    // An unlit material (KHR_materials_unlit) reads no normal, so it gets none.
    const bool unlit = mesh.material >= 0 && scene_.materials[size_t(mesh.material)].family == ShaderFamily::unlit_generic;
    if (mesh.normals.empty() && !unlit) {
      // Flat normals: every triangle gets vertices of its own.
      Mesh flat;
      flat.material = mesh.material;
      for (size_t k = 0; k < tri.size(); ++k) {
        const uint32_t v = tri[k];
        flat.positions.push_back(mesh.positions[v]);
        if (!mesh.tangents.empty()) flat.tangents.push_back(mesh.tangents[v]);
        if (!mesh.uv0.empty()) flat.uv0.push_back(mesh.uv0[v]);
        if (!mesh.uv1.empty()) flat.uv1.push_back(mesh.uv1[v]);
        if (!mesh.colors.empty()) flat.colors.push_back(mesh.colors[v]);
      }
      flat.normals.resize(flat.positions.size());
      for (size_t t = 0; t + 2 < tri.size(); t += 3) {
        const glm::dvec3 a(flat.positions[t]), b(flat.positions[t + 1]), c(flat.positions[t + 2]);
        const glm::dvec3 f = glm::cross(b - a, c - a);
        const double len = glm::length(f);
        const glm::vec3 normal = len > 0.0 ? glm::vec3(f / len) : glm::vec3(0, 0, 1);
        flat.normals[t] = flat.normals[t + 1] = flat.normals[t + 2] = normal;
      }
      for (size_t k = 0; k < tri.size(); ++k) tri[k] = uint32_t(k);
      mesh = std::move(flat);
    }
    // 8-bit indices widen to 16, 32-bit ones stay; 16 bits widen where the vertices need it. A
    // triangle list without indices whose vertices stay in order (not mirrored, not a strip) stays one:
    // the scene's non-indexed mesh.
    const bool wide = index_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT || mesh.positions.size() > 65536;
    bool in_order = p.indices < 0 && tri.size() == mesh.positions.size();
    for (size_t k = 0; in_order && k < tri.size(); ++k) in_order = tri[k] == k;
    if (in_order) mesh.indices = std::vector<uint16_t>{};
    else if (wide) mesh.indices = std::move(tri);
    else mesh.indices = std::vector<uint16_t>(tri.begin(), tri.end());
    if (mesh.tangents.empty() && !mesh.normals.empty() && !mesh.uv0.empty() && options_.generate_tangents) generate_tangents(mesh);
    return mesh;
  }

  // --- Cameras and lights ------------------------------------------------------------------------

  static glm::vec3 point(const glm::dmat4& m, glm::dvec3 p) { return glm::vec3(glm::dvec3(m * glm::dvec4(p, 1.0))); }
  static glm::vec3 direction(const glm::dmat4& m, glm::dvec3 d) {
    const glm::dvec3 w = glm::dmat3(m) * d;
    const double len = glm::length(w);
    return len > 0.0 ? glm::vec3(w / len) : glm::vec3(0, 0, -1);
  }

  void add_camera(int index, const glm::dmat4& world, const std::string& node) {
    if (size_t(index) >= model_.cameras.size()) fail(node + " refers to camera " + std::to_string(index));
    const tinygltf::Camera& g = model_.cameras[size_t(index)];
    const std::string where = "camera " + std::to_string(index);
    Camera c;
    c.name = g.name.empty() ? where : g.name;
    c.position = point(world, glm::dvec3(0.0));
    double distance = 100.0;  // inches to the target (the direction is what glTF gives)
    if (const auto& d = g.extras.Get("luxel").Get("target_distance"); d.IsNumber()) distance = d.GetNumberAsDouble();
    c.target = c.position + direction(world, glm::dvec3(0, 0, -1)) * float(distance);
    c.up = direction(world, glm::dvec3(0, 1, 0));
    const double k = gltf::kInches;
    if (g.type == "orthographic") {
      c.projection = Projection::orthographic;
      c.ortho_height = float(2.0 * g.orthographic.ymag * k);
      c.aspect = g.orthographic.ymag > 0.0 ? float(g.orthographic.xmag / g.orthographic.ymag) : 0.0f;
      c.near_plane = float(std::max(g.orthographic.znear * k, 1e-3));
      c.far_plane = float(g.orthographic.zfar * k);
    } else {
      c.vertical_fov = float(g.perspective.yfov);
      c.aspect = float(g.perspective.aspectRatio);
      c.near_plane = float(g.perspective.znear * k);
      c.far_plane = g.perspective.zfar > 0.0 ? float(g.perspective.zfar * k) : std::max(16384.0f, c.near_plane * 65536.0f);
    }
    cameras_.push_back({index, std::move(c)});
  }

  void add_light(int index, const glm::dmat4& world, const std::string& node) {
    if (index < 0 || size_t(index) >= model_.lights.size()) fail(node + " refers to light " + std::to_string(index));
    const tinygltf::Light& g = model_.lights[size_t(index)];
    Light l;
    l.name = g.name.empty() ? "light " + std::to_string(index) : g.name;
    glm::vec3 color(1.0f);
    if (g.color.size() == 3) color = glm::vec3(float(g.color[0]), float(g.color[1]), float(g.color[2]));
    l.color = color * float(g.intensity);
    l.position = point(world, glm::dvec3(0.0));
    l.direction = direction(world, glm::dvec3(0, 0, -1));
    l.constant = 0.0f, l.linear = 0.0f, l.quadratic = gltf::kLightQuadratic;
    l.range = float(g.range * gltf::kInches);
    if (g.type == "directional") l.type = LightType::directional;
    else if (g.type == "spot") {
      l.type = LightType::spot;
      l.inner_cone = float(g.spot.innerConeAngle);
      l.outer_cone = float(g.spot.outerConeAngle);
    } else if (g.type == "point") l.type = LightType::point;
    else fail("light " + std::to_string(index) + " has unknown type '" + g.type + "'");
    scene_.lights.push_back(std::move(l));
  }

  /// The camera asked for first, the others after it in the order the nodes placed them.
  void order_cameras() {
    if (model_.cameras.empty() && options_.camera == 0) return;
    if (options_.camera < 0 || size_t(options_.camera) >= model_.cameras.size())
      fail("camera " + std::to_string(options_.camera) + " asked for; the file has " + std::to_string(model_.cameras.size()));
    auto chosen = std::find_if(cameras_.begin(), cameras_.end(), [&](const auto& c) { return c.first == options_.camera; });
    if (chosen == cameras_.end()) fail("camera " + std::to_string(options_.camera) + " is not placed by any node of the scene");
    scene_.cameras.push_back(chosen->second);
    for (auto it = cameras_.begin(); it != cameras_.end(); ++it)
      if (it != chosen) scene_.cameras.push_back(it->second);
  }

  void add_defaults() {
    if (scene_.cameras.empty() && options_.default_camera)
      scene_.cameras.push_back(framing_camera(scene_, options_.framing_aspect));
    if (scene_.lights.empty() && options_.default_lights) {
      // A key light over the camera's shoulder and a dimmer fill from the other side.
      Light key;
      key.name = "luxel:key";
      key.type = LightType::directional;
      key.direction = -glm::normalize(glm::vec3(-0.8f, -0.6f, 1.0f));
      key.color = glm::vec3(1.0f);
      Light fill = key;
      fill.name = "luxel:fill";
      fill.direction = -glm::normalize(glm::vec3(1.0f, -0.3f, 0.2f));
      fill.color = glm::vec3(0.35f);
      scene_.lights.push_back(key);
      scene_.lights.push_back(fill);
    }
  }

  std::string path_, dir_;
  const GltfImportOptions& options_;
  tinygltf::Model model_;
  const Accessors* accessors_ = nullptr;
  std::map<int, std::vector<uint8_t>> data_uri_images_;
  struct DracoIndices { size_t mesh, primitive; int accessor; };
  std::vector<DracoIndices> draco_indices_;
  std::string fs_error_;
  std::vector<std::optional<PixelImage>> images_;
  // What the memory limit counts as the file is read: its files' bytes, its images' pixels.
  uint64_t file_bytes_ = 0, image_bytes_ = 0;
  int images_read_ = 0;
  std::map<std::pair<int, ColorSpace>, int> textures_;
  std::vector<std::pair<int, Camera>> cameras_;
  Scene scene_;
};

}  // namespace

Scene load_gltf(const std::string& path, const GltfImportOptions& options) { return Importer(path, options).run(); }

}  // namespace luxel::scenes
