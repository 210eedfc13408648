// Bakes on disk: half-float EXR maps through OpenImageIO, a JSON index (nlohmann), the input hash.
#include "luxel/bake/storage.hpp"

#include "luxel/scenes/content_hash.hpp"

#include "luxel/scenes/image_io.hpp"

#include <OpenImageIO/imageio.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <type_traits>

namespace luxel::bake {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const char* const kMapFiles[4] = {"lightmap_flat.exr", "lightmap_basis0.exr", "lightmap_basis1.exr", "lightmap_basis2.exr"};
constexpr const char* kIndexFile = "bake.json";

/// Texture `index` of the scene as the bake reads it (its index, then its texels), or the index
/// alone when there is no such texture.
void hash_texture(scenes::ContentHash& h, const scenes::Scene& s, int index) {
  h.value(index);
  if (index < 0 || index >= int(s.textures.size())) return;
  const scenes::Texture& t = s.textures[size_t(index)];
  h.values(t.shape, t.color_space);
  for (const auto& f : t.faces) h.image(f);
}

std::string hex(uint64_t h) {
  char b[17];
  std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(h));
  return b;
}

json settings_json(const BakeSettings& s) {
  return {{"samples", s.samples},
          {"stop_fraction", s.stop_fraction},
          {"max_bounces", s.max_bounces},
          {"supersample", s.supersample},
          {"supersample_threshold", s.supersample_threshold},
          {"sky_max_radiance", s.sky_max_radiance},
          {"cube_samples", s.cube_samples},
          {"cubes_all_light", s.cubes_all_light},
          {"default_volume_spacing", {s.default_volume_spacing.x, s.default_volume_spacing.y, s.default_volume_spacing.z}},
          {"luxel_size", s.luxel_size},
          {"chart_angle_degrees", s.chart_angle_degrees},
          {"seed", s.seed}};
}

json vec3(glm::vec3 v) { return json::array({v.x, v.y, v.z}); }
// The index's numbers, checked: nlohmann's get<int>() and get<float>() cast whatever number they
// find, and a cast out of range is undefined behavior.
int int_field(const json& j) {
  if (!j.is_number_integer()) throw std::runtime_error("a count that is not an integer: " + j.dump());
  const bool fits = j.is_number_unsigned() ? j.get<uint64_t>() <= uint64_t(std::numeric_limits<int>::max())
                                           : j.get<int64_t>() >= std::numeric_limits<int>::min() &&
                                                 j.get<int64_t>() <= std::numeric_limits<int>::max();
  if (!fits) throw std::runtime_error("a count out of range: " + j.dump());
  return int(j.get<int64_t>());
}

uint64_t uint64_field(const json& j) {
  if (!j.is_number_unsigned()) throw std::runtime_error("a count that is not a natural number: " + j.dump());
  return j.get<uint64_t>();
}

float float_field(const json& j) {
  if (!j.is_number()) throw std::runtime_error("not a number: " + j.dump());
  const double d = j.get<double>();
  if (!(std::abs(d) <= double(std::numeric_limits<float>::max()))) throw std::runtime_error("a number out of range: " + j.dump());
  return float(d);
}

glm::vec3 vec3(const json& j) { return {float_field(j.at(0)), float_field(j.at(1)), float_field(j.at(2))}; }

void write_map(const std::vector<glm::vec3>& map, int width, int height, const std::string& path) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw std::runtime_error(path + ": cannot write EXR (" + OIIO::geterror() + ")");
  OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::HALF);
  spec.attribute("compression", "zip");
  // OpenImageIO stamps the time of writing into the header unless told a time: a fixed one keeps
  // the same bake the same bytes on disk too.
  spec.attribute("DateTime", "1970:01:01 00:00:00");
  if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, map.data()) || !out->close())
    throw std::runtime_error(path + ": " + out->geterror());
}

}  // namespace

uint64_t bake_input_hash(const scenes::Scene& scene, const BakeSettings& settings) {
  scenes::ContentHash h;
  h.value(kBakeFormatVersion);
  h.value(scene.meshes.size());
  const std::vector<char> in_model = scenes::meshes_in_models(scene);
  for (size_t i = 0; i < scene.meshes.size(); ++i) {
    const scenes::Mesh& m = scene.meshes[i];
    h.value(m.material), h.value(in_model[i]);
    h.vector(m.positions), h.vector(m.normals), h.vector(m.tangents), h.vector(m.uv1);
    std::visit([&](const auto& v) { h.vector(v); }, m.indices);
  }
  h.value(scene.materials.size());
  for (const scenes::Material& m : scene.materials) {
    h.value(m.family), h.value(m.color), h.value(m.emissive), h.value(m.alpha), h.value(m.translucent);
    hash_texture(h, scene, m.base.texture);
  }
  h.value(scene.lights.size());
  for (const scenes::Light& l : scene.lights) {
    h.value(l.type), h.value(l.position), h.value(l.direction), h.value(l.color), h.value(l.constant), h.value(l.linear),
        h.value(l.quadratic), h.value(l.inner_cone), h.value(l.outer_cone), h.value(l.spot_exponent), h.value(l.range);
  }
  hash_texture(h, scene, scene.sky_texture);
  h.value(scene.background);
  h.value(scene.lightmap_luxel_size);
  h.value(bool(scene.irradiance_volume));
  if (const auto& v = scene.irradiance_volume) h.value(v->min), h.value(v->max), h.value(v->spacing), h.value(v->counts);
  h.string(settings_json(settings).dump());
  return h.h;
}

void save_bake(const BakeResult& r, const scenes::Scene& scene, const BakeSettings& settings, const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw std::runtime_error(dir + ": cannot create the bake folder (" + ec.message() + ")");
  json index;
  index["format"] = "luxel-bake";
  index["version"] = kBakeFormatVersion;
  index["scene"] = scene.name;
  index["hash"] = hex(bake_input_hash(scene, settings));
  index["settings"] = settings_json(settings);
  const LightmapAtlas& a = r.lightmaps;
  if (a.width > 0) {
    json files = json::array();
    for (int k = 0; k < 4; ++k) {
      write_map(a.maps[size_t(k)], a.width, a.height, (fs::path(dir) / kMapFiles[k]).string());
      files.push_back(kMapFiles[k]);
    }
    json generated = json::array();
    for (size_t i = 0; i < r.charted_meshes.size(); ++i)
      if (r.charted_meshes[i]) generated.push_back(i);
    std::string coverage(a.coverage.size(), '0');
    for (size_t i = 0; i < a.coverage.size(); ++i) coverage[i] = char('0' + int(a.coverage[i]));
    index["lightmaps"] = {{"width", a.width},
                          {"height", a.height},
                          {"files", files},
                          {"unit", "linear irradiance / pi (diffuse = albedo x lightmap), RGB half float, top row = uv1 v 0"},
                          {"order", "flat, basis 0, basis 1, basis 2 (docs/fidelity.md#rnm-basis-and-lightmaps, tangent space)"},
                          {"luxels", r.stats.luxels},
                          {"coverage", coverage},
                          {"generated_uv1_meshes", generated}};
  }
  if (r.cubes) {
    const scenes::IrradianceVolume& v = r.cubes->volume;
    json cubes = json::array();
    for (const auto& c : v.cubes) {
      json faces = json::array();
      for (const glm::vec3& f : c) faces.push_back(vec3(f));
      cubes.push_back(faces);
    }
    index["volume"] = {{"min", vec3(v.min)},
                       {"max", vec3(v.max)},
                       {"spacing", vec3(v.spacing)},
                       {"counts", {v.counts.x, v.counts.y, v.counts.z}},
                       {"face_order", "+X, -X, +Y, -Y, +Z, -Z"},
                       {"cubes", cubes},
                       {"valid", r.cubes->valid}};
  }
  index["stats"] = {{"luxels", r.stats.luxels},     {"bounces", r.stats.bounces},
                    {"bounce_energy", r.stats.bounce_energy}, {"rays", r.stats.rays},
                    {"supersampled", r.stats.supersampled},   {"cube_samples", r.stats.cube_samples},
                    {"cube_samples_inside", r.stats.cube_samples_inside}, {"seconds", r.stats.seconds}};
  index["warnings"] = r.warnings;
  const std::string path = (fs::path(dir) / kIndexFile).string();
  // Written last and whole: a bake cut short leaves no index, so it is never reused.
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    f << index.dump(1) << "\n";
    if (!f) throw std::runtime_error(tmp + ": cannot write");
  }
  fs::rename(tmp, path, ec);
  if (ec) throw std::runtime_error(path + ": cannot write (" + ec.message() + ")");
}

std::optional<BakeResult> load_bake(const std::string& dir, const scenes::Scene& scene, const BakeSettings& settings) {
  const std::string path = (fs::path(dir) / kIndexFile).string();
  std::ifstream f(path, std::ios::binary);
  if (!f) return std::nullopt;
  json index;
  try {
    index = json::parse(f);
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": not a bake index (" + e.what() + ")");
  }
  try {
    if (index.value("format", "") != "luxel-bake" || index.value("version", json()) != json(kBakeFormatVersion)) return std::nullopt;
    if (index.value("hash", "") != hex(bake_input_hash(scene, settings))) return std::nullopt;
    BakeResult r;
    r.charted_meshes.resize(scene.meshes.size());
    if (index.contains("lightmaps")) {
      const json& l = index["lightmaps"];
      LightmapAtlas& a = r.lightmaps;
      a.width = int_field(l.at("width")), a.height = int_field(l.at("height"));
      if (a.width <= 0 || a.height <= 0 || a.width > kMaxAtlasSide || a.height > kMaxAtlasSide)
        throw std::runtime_error("bad atlas size");
      const size_t texels = size_t(a.width) * size_t(a.height);
      for (int k = 0; k < 4; ++k) {
        const scenes::PixelImage img = scenes::read_image((fs::path(dir) / kMapFiles[k]).string());
        if (img.width != a.width || img.height != a.height || !img.is_hdr())
          throw std::runtime_error(std::string(kMapFiles[k]) + " is not the index's size or not float");
        a.maps[size_t(k)].resize(texels);
        for (size_t i = 0; i < texels; ++i)
          a.maps[size_t(k)][i] = {img.rgba32f[4 * i], img.rgba32f[4 * i + 1], img.rgba32f[4 * i + 2]};
      }
      const std::string coverage = l.at("coverage").get<std::string>();
      if (coverage.size() != texels) throw std::runtime_error("coverage is not the atlas's size");
      a.coverage.resize(texels);
      for (size_t i = 0; i < texels; ++i) a.coverage[i] = LuxelCoverage(std::clamp(coverage[i] - '0', 0, 2));
      r.stats.luxels = l.contains("luxels") ? uint64_field(l["luxels"]) : 0;
      // Charts the baker made are made again (a function of what the hash covers).
      if (!l.value("generated_uv1_meshes", json::array()).empty()) {
        GeneratedCharts charts = plan_charts(scene, settings);
        if (charts.atlas_size != a.width) throw std::runtime_error("the charts made again do not fit the stored atlas");
        r.charted_meshes = std::move(charts.meshes);
      }
    }
    if (index.contains("volume")) {
      const json& v = index["volume"];
      AmbientCubes cubes;
      cubes.volume.min = vec3(v.at("min")), cubes.volume.max = vec3(v.at("max")), cubes.volume.spacing = vec3(v.at("spacing"));
      cubes.volume.counts = {int_field(v.at("counts").at(0)), int_field(v.at("counts").at(1)), int_field(v.at("counts").at(2))};
      for (const json& c : v.at("cubes")) {
        scenes::AmbientCube cube;
        for (size_t k = 0; k < 6; ++k) cube[k] = vec3(c.at(k));
        cubes.volume.cubes.push_back(cube);
      }
      for (const json& valid : v.at("valid")) {
        if (valid != 0 && valid != 1) throw std::runtime_error("a cube's validity that is not 0 or 1: " + valid.dump());
        cubes.valid.push_back(char(valid == 1));
      }
      const uint64_t n = uint64_t(std::max(cubes.volume.counts.x, 0)) * uint64_t(std::max(cubes.volume.counts.y, 0)) *
                         uint64_t(std::max(cubes.volume.counts.z, 0));
      if (cubes.volume.cubes.size() != n || cubes.valid.size() != n) throw std::runtime_error("the volume's cube count is wrong");
      r.cubes = std::move(cubes);
    }
    const json& s = index.at("stats");
    r.stats.bounces = s.contains("bounces") ? int_field(s["bounces"]) : 0;
    r.stats.rays = s.contains("rays") ? uint64_field(s["rays"]) : 0;
    r.stats.seconds = s.value("seconds", 0.0);
    r.stats.width = r.lightmaps.width, r.stats.height = r.lightmaps.height;
    r.warnings = index.value("warnings", std::vector<std::string>{});
    return r;
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path + ": damaged bake (" + e.what() + ")");
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": damaged bake (" + e.what() + ")");
  }
}

}  // namespace luxel::bake
