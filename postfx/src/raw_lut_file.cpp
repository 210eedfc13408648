// Source .raw color-correction files (raw_lut_file.hpp).

#include "luxel/postfx/raw_lut_file.hpp"

#include <OpenColorIO/OpenColorIO.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace luxel::postfx {

namespace OCIO = OCIO_NAMESPACE;

Lut read_raw_lut(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) throw std::runtime_error(path + ": cannot open it");
  const auto size = std::filesystem::file_size(path, error);
  if (error || size != kRawLutBytes) {
    throw std::runtime_error(path + ": " + std::to_string(size) + " bytes; a Source .raw LUT has " +
                             std::to_string(kRawLutBytes) + " (32^3 RGB)");
  }
  std::ifstream in(path, std::ios::binary);
  Lut lut;
  if (!in.read(reinterpret_cast<char*>(lut.entries.data()), std::streamsize(kRawLutBytes))) {
    throw std::runtime_error(path + ": cannot read it");
  }
  return lut;
}

ColorTransform raw_lut_transform(const Lut& lut, const std::string& name) {
  const OCIO::Lut3DTransformRcPtr lattice = OCIO::Lut3DTransform::Create(unsigned(lut.size));
  lattice->setInterpolation(OCIO::INTERP_LINEAR);
  for (int b = 0; b < lut.size; ++b)
    for (int g = 0; g < lut.size; ++g)
      for (int r = 0; r < lut.size; ++r) {
        const Lut::Color24& e = lut.at(r, g, b);
        lattice->setValue(r, g, b, e[0] / 255.0f, e[1] / 255.0f, e[2] / 255.0f);
      }
  const OCIO::ConstCPUProcessorRcPtr cpu = OCIO::Config::CreateRaw()->getProcessor(lattice)->getOptimizedCPUProcessor(
      OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32, OCIO::OPTIMIZATION_LOSSLESS);
  return {name, "Source .raw 32^3, trilinear", [cpu](std::span<glm::vec3> colors) {
            if (colors.empty()) return;
            OCIO::PackedImageDesc image(&colors[0].x, static_cast<long>(colors.size()), 1, 3);
            cpu->apply(image);
          }};
}

void write_raw_lut(const Lut& lut, const std::string& path) {
  static_assert(sizeof(Lut::Color24) == 3, "entries are the file's bytes");
  if (lut.size != kLutSize) throw std::invalid_argument(path + ": a .raw holds the engine's 32^3 LUT, not " + std::to_string(lut.size) + "^3");
  std::ofstream out(path, std::ios::binary);
  if (!out.write(reinterpret_cast<const char*>(lut.entries.data()), std::streamsize(kRawLutBytes)) || !out.flush()) {
    throw std::runtime_error(path + ": cannot write it");
  }
}

}  // namespace luxel::postfx
