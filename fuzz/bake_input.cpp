#include "fuzz_support.hpp"
#include "inputs.hpp"

#include "luxel/bake/bake.hpp"
#include "luxel/bake/storage.hpp"
#include "luxel/scenes/builtin.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

namespace luxel::fuzz {

namespace {

struct Baked {
  scenes::Scene scene;
  bake::BakeSettings settings;
  std::string folder, index, hash;
};

/// builtin:demo baked cheaply into the scratch folder, once per process, at a coarse luxel size:
/// the index spells out the atlas's coverage a character a texel, and a small atlas keeps every
/// input (and so every run) small.
const Baked& baked() {
  static const Baked b = [] {
    Baked b;
    b.scene = scenes::make_builtin_scene("demo", {64, 64});
    b.settings = bake::BakeSettings::quick();
    b.settings.samples = 16;
    b.settings.cube_samples = 16;
    b.settings.threads = 1;
    b.settings.luxel_size = 256.0f;
    b.folder = scratch_path("bake");
    bake::save_bake(bake::bake(b.scene, b.settings), b.scene, b.settings, b.folder);
    b.index = (std::filesystem::path(b.folder) / "bake.json").string();
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(bake::bake_input_hash(b.scene, b.settings)));
    b.hash = hex;
    return b;
  }();
  return b;
}

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) text.replace(at, from.size(), to);
  return text;
}

}  // namespace

void read_bake_input(std::span<const uint8_t> input) {
  const Baked& b = baked();
  const std::string index = replace_all(replace_all(std::string(input.begin(), input.end()), "@HASH@", b.hash), "@VERSION@",
                                        std::to_string(bake::kBakeFormatVersion));
  write_file(b.index, reinterpret_cast<const uint8_t*>(index.data()), index.size());
  std::optional<bake::BakeResult> result;
  try {
    result = bake::load_bake(b.folder, b.scene, b.settings);
  } catch (const std::runtime_error& e) {
    expect_one_line_naming(e, b.index);
    return;
  }
  if (!result) return;
  scenes::Scene scene = b.scene;
  bake::attach(scene, *result);
  std::string failure;
  try {
    scenes::validate(scene);
  } catch (const std::exception& e) {
    failure = e.what();
  }
  if (!failure.empty()) finding("a bake that loaded leaves the scene invalid: " + failure);
}

void write_bake_seed(const std::string& dir) {
  const Baked& b = baked();
  std::stringstream index;
  index << std::ifstream(b.index).rdbuf();
  const std::string version = "\"version\": " + std::to_string(bake::kBakeFormatVersion);
  std::ofstream(std::filesystem::path(dir) / "bake.json") << replace_all(replace_all(index.str(), b.hash, "@HASH@"), version, "\"version\": @VERSION@");
}

}  // namespace luxel::fuzz
