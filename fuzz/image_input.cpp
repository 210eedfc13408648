#include "fuzz_support.hpp"
#include "inputs.hpp"

#include "luxel/scenes/image_io.hpp"

#include <filesystem>

namespace luxel::fuzz {

void read_image_input(std::span<const uint8_t> input) {
  static const std::string name = "fuzz-image";
  scenes::PixelImage image;
  try {
    image = scenes::read_image(input, name);
  } catch (const std::runtime_error& e) {
    expect_one_line_naming(e, name);
    return;
  }
  if (image.width < 1 || image.height < 1 || image.width > scenes::kMaxImageSide || image.height > scenes::kMaxImageSide)
    finding("an image of " + std::to_string(image.width) + "x" + std::to_string(image.height) + " was accepted");
  const size_t values = size_t(image.width) * size_t(image.height) * 4;
  if (image.rgba8.empty() == image.rgba32f.empty() || (image.is_hdr() ? image.rgba32f.size() : image.rgba8.size()) != values)
    finding("an image's pixels do not match its size");
}

void write_image_seeds(const std::string& dir) {
  scenes::PixelImage ldr, hdr;
  ldr.width = hdr.width = 5;
  ldr.height = hdr.height = 3;
  for (int i = 0; i < 15 * 4; ++i) {
    ldr.rgba8.push_back(uint8_t(i * 17));
    hdr.rgba32f.push_back(i % 4 == 3 ? 1.0f : float(i) * 0.37f);
  }
  for (const std::string ext : {"png", "jpg", "tif", "tga", "ppm", "bmp", "exr", "hdr"}) {
    try {
      scenes::write_image(ext == "exr" || ext == "hdr" ? hdr : ldr, (std::filesystem::path(dir) / ("seed." + ext)).string());
    } catch (const std::runtime_error&) {
      // Not every OpenImageIO build writes every format: the seeds are what this one does.
    }
  }
}

}  // namespace luxel::fuzz
