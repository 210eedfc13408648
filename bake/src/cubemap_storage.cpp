// Baked cube maps on disk: half-float EXR faces through OpenImageIO, a JSON index (nlohmann).
#include "luxel/bake/cubemap_storage.hpp"

#include "luxel/scenes/image_io.hpp"

#include <OpenImageIO/imageio.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace luxel::bake {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kIndexFile = "cubemaps.json";
constexpr int kVersion = 1;

std::string hex(uint64_t h) {
  char b[17];
  std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(h));
  return b;
}

/// The cube's faces stacked top to bottom, rgb.
std::vector<float> stacked_rgb(const scenes::Texture& cube, const std::string& path) {
  if (cube.shape != scenes::TextureShape::cube || cube.faces.size() != 6)
    throw std::runtime_error(path + ": '" + cube.name + "' is not a cube of six faces");
  const int n = cube.faces[0].width;
  std::vector<float> rgb;
  rgb.reserve(size_t(n) * n * 6 * 3);
  for (const scenes::PixelImage& f : cube.faces) {
    if (f.width != n || f.height != n || f.rgba32f.size() != size_t(n) * n * 4)
      throw std::runtime_error(path + ": '" + cube.name + "' has a face that is not " + std::to_string(n) + "x" +
                               std::to_string(n) + " float texels");
    for (size_t i = 0; i < size_t(n) * n; ++i) rgb.insert(rgb.end(), {f.rgba32f[4 * i], f.rgba32f[4 * i + 1], f.rgba32f[4 * i + 2]});
  }
  return rgb;
}

void write_exr(const std::vector<float>& rgb, int width, int height, const std::string& path) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw std::runtime_error(path + ": cannot write EXR (" + OIIO::geterror() + ")");
  OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::HALF);
  spec.attribute("compression", "zip");
  spec.attribute("DateTime", "1970:01:01 00:00:00");  // the same cubes, the same bytes (storage.cpp)
  if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, rgb.data()) || !out->close())
    throw std::runtime_error(path + ": " + out->geterror());
}

}  // namespace

void save_cubemaps(const StoredCubemaps& stored, uint64_t hash, const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw std::runtime_error(dir + ": cannot create the bake folder (" + ec.message() + ")");
  json names = json::array(), files = json::array(), sizes = json::array();
  for (size_t i = 0; i < stored.cubes.size(); ++i) {
    const scenes::Texture& cube = stored.cubes[i];
    const std::string file = "cubemap_" + std::to_string(i) + ".exr";
    const std::string path = (fs::path(dir) / file).string();
    const std::vector<float> rgb = stacked_rgb(cube, path);
    write_exr(rgb, cube.faces[0].width, 6 * cube.faces[0].width, path);
    names.push_back(cube.name), files.push_back(file), sizes.push_back(cube.faces[0].width);
  }
  json index = {{"format", "luxel-cubemaps"},
                {"version", kVersion},
                {"hash", hex(hash)},
                {"unit", "linear radiance, as the shaders read an HDR env map; RGB half float"},
                {"layout", "six faces stacked top to bottom: +X, -X, +Y, -Y, +Z, -Z (D3D)"},
                {"names", names},
                {"files", files},
                {"face_sizes", sizes},
                {"exposures", stored.exposures}};
  const std::string path = (fs::path(dir) / kIndexFile).string(), tmp = path + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    f << index.dump(1) << "\n";
    if (!f) throw std::runtime_error(tmp + ": cannot write");
  }
  fs::rename(tmp, path, ec);
  if (ec) throw std::runtime_error(path + ": cannot write (" + ec.message() + ")");
}

std::optional<StoredCubemaps> load_cubemaps(const std::string& dir, uint64_t hash) {
  const std::string path = (fs::path(dir) / kIndexFile).string();
  std::ifstream f(path, std::ios::binary);
  if (!f) return std::nullopt;
  try {
    const json index = json::parse(f);
    if (index.value("format", "") != "luxel-cubemaps" || index.value("version", 0) != kVersion) return std::nullopt;
    if (index.value("hash", "") != hex(hash)) return std::nullopt;
    StoredCubemaps r;
    const json& files = index.at("files");
    const json& names = index.at("names");
    if (names.size() != files.size()) throw std::runtime_error("names and files differ in count");
    for (size_t i = 0; i < files.size(); ++i) {
      const std::string file = files[i].get<std::string>();
      if (fs::path(file).filename() != fs::path(file)) throw std::runtime_error("file '" + file + "' is not in the folder");
      const scenes::PixelImage stacked = scenes::read_image((fs::path(dir) / file).string());
      const int n = stacked.width;
      if (n < 1 || stacked.height != 6 * n || !stacked.is_hdr())
        throw std::runtime_error(file + " is not six square float faces stacked");
      scenes::Texture cube;
      cube.name = names[i].get<std::string>();
      cube.shape = scenes::TextureShape::cube;
      cube.color_space = scenes::ColorSpace::linear;
      const size_t face_floats = size_t(n) * n * 4;
      for (size_t k = 0; k < 6; ++k) {
        scenes::PixelImage face;
        face.width = face.height = n;
        face.rgba32f.assign(stacked.rgba32f.begin() + std::ptrdiff_t(k * face_floats),
                            stacked.rgba32f.begin() + std::ptrdiff_t((k + 1) * face_floats));
        for (size_t t = 3; t < face.rgba32f.size(); t += 4) face.rgba32f[t] = 1.0f;
        cube.faces.push_back(std::move(face));
      }
      r.cubes.push_back(std::move(cube));
    }
    r.exposures = index.value("exposures", std::vector<float>{});
    return r;
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": damaged cube maps (" + e.what() + ")");
  }
}

}  // namespace luxel::bake
