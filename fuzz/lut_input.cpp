#include "fuzz_support.hpp"
#include "inputs.hpp"

#include "luxel/postfx/lut_file.hpp"
#include "luxel/postfx/lut_source.hpp"
#include "luxel/postfx/raw_lut_file.hpp"

#include <glm/vec3.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <vector>

namespace luxel::fuzz {

void read_lut_input(std::span<const uint8_t> input) {
  if (input.empty()) return;
  const std::string path = scratch_path(std::string("lut.") + kLutExtensions[input[0] % std::size(kLutExtensions)]);
  write_file(path, input.data() + 1, input.size() - 1);
  postfx::ColorTransform transform;
  try {
    transform = postfx::color_transform_named(path);
  } catch (const std::runtime_error& e) {
    expect_one_line_naming(e, path);
    return;
  }
  (void)postfx::sample_lut(transform);
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<glm::vec3> colors = {{nan, 0.5f, 0.5f}, {inf, -inf, 0.0f}, {1e30f, -1e30f, 2.0f}, {-0.5f, 1.5f, 1e-40f}};
  transform.apply(colors);
}

namespace {

/// `file` with the index of its extension in kLutExtensions in front, as DIR/NAME.
void write_seed(const std::string& file, uint8_t extension, const std::string& dir, const std::string& name) {
  std::ifstream in(file, std::ios::binary);
  std::string bytes(1, char(extension));
  bytes.append(std::istreambuf_iterator<char>(in), {});
  std::ofstream(std::filesystem::path(dir) / name, std::ios::binary) << bytes;
}

}  // namespace

void write_lut_seeds(const std::string& dir) {
  const std::string cube = scratch_path("identity.cube"), raw = scratch_path("identity.raw");
  postfx::write_cube(postfx::Lut::identity(), cube, "identity");
  postfx::write_raw_lut(postfx::Lut::identity(), raw);
  write_seed(cube, 0, dir, "engine-identity.cube");
  write_seed(raw, 11, dir, "engine-identity.raw");
}

}  // namespace luxel::fuzz
