// Parsing a glTF: the file read within the memory limit, a .glb's container checked, the JSON
// checked against the schema and the extensions luxel reads, tinygltf run on a file system
// confined to the file's folder, compressed geometry decoded.

#include "gltf_compression.hpp"
#include "gltf_importer.hpp"
#include "gltf_schema.hpp"
#include "luxel/scenes/memory_limit.hpp"
#include "tinygltf.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace luxel::scenes::gltf {

namespace fs = std::filesystem;

namespace {

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

}  // namespace

std::string unconfined(const std::string& uri) {
  const fs::path p(uri);
  if (uri.empty()) return "is empty";
  if (p.is_absolute() || p.has_root_name() || p.has_root_directory()) return "is an absolute path";
  if (uri.find(':') != std::string::npos) return "is not a relative file reference";
  const fs::path normal = p.lexically_normal();
  if (!normal.empty() && *normal.begin() == "..") return "leaves the folder of the file";
  return "";
}

std::vector<uint8_t> Importer::read_whole(const std::string& file, const std::string& what) {
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
void Importer::check_glb(const std::vector<uint8_t>& b) const {
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

void Importer::parse() {
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
std::string_view Importer::glb_json(const std::vector<uint8_t>& b) {
  uint32_t length;
  std::memcpy(&length, b.data() + 12, 4);
  return std::string_view(reinterpret_cast<const char*>(b.data()) + 20, length);
}

/// The schema's structure (gltf_schema.hpp) and the extensions, on JSON that parses; what does
/// not parse, tinygltf reports.
/// Returns the JSON tinygltf is to read instead of the file's, if any (take_out_draco_indices,
/// stub_fallback_buffers).
std::optional<std::string> Importer::check_json(std::string_view text, bool glb) {
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
void Importer::check_extensions(const nlohmann::json& doc) {
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
void Importer::decode_compressed() {
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
void Importer::take_out_draco_indices(const nlohmann::json& doc, nlohmann::json& copy) {
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
void Importer::stub_fallback_buffers(const nlohmann::json& doc, nlohmann::json& copy) {
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
std::vector<uint8_t> Importer::with_glb_json(const std::vector<uint8_t>& bytes, const std::string& json) {
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
bool Importer::file_exists(const std::string& abs, void* user) {
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

std::string Importer::expand_path(const std::string& path, void*) { return path; }

bool Importer::read_file(std::vector<unsigned char>* out, std::string* err, const std::string& abs, void* user) {
  auto* self = static_cast<Importer*>(user);
  try {
    *out = self->read_whole(abs, "buffer file '" + abs + "'");
  } catch (const GltfError& e) {
    self->record(std::string(e.what()).substr(self->path_.size() + 2));
    return false;
  }
  return true;
}

bool Importer::write_file(std::string*, const std::string&, const std::vector<unsigned char>&, void*) { return false; }

/// How tinygltf's JoinPath puts the folder before a URI.
std::string Importer::folder_prefix() const { return dir_.back() == '/' ? dir_ : dir_ + "/"; }

void Importer::record(const std::string& what) {
  if (fs_error_.empty()) fs_error_ = what;
}

/// tinygltf hands data-URI and buffer-view images here while parsing. Buffer views are not
/// checked yet, so their bytes are read later, through the validation layer.
bool Importer::collect_image(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                          const unsigned char* bytes, int size, void* user) {
  auto* self = static_cast<Importer*>(user);
  if (image->bufferView < 0 && size > 0) self->data_uri_images_[index].assign(bytes, bytes + size);
  return true;
}

}  // namespace luxel::scenes::gltf
