// A glTF's images and textures: each image read once (from a buffer view, a data URI or a file
// in the glTF's folder), counted by the memory limit; each texture a Scene texture per color space.

#include "gltf_importer.hpp"
#include "luxel/scenes/image_io.hpp"
#include "luxel/scenes/memory_limit.hpp"
#include "tinygltf.hpp"

#include <cctype>
#include <filesystem>

namespace luxel::scenes::gltf {

namespace fs = std::filesystem;

namespace {

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

}  // namespace

const PixelImage& Importer::image(int index, const std::string& where) {
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

int Importer::texture(int index, ColorSpace color_space, const std::string& where) {
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

}  // namespace luxel::scenes::gltf
