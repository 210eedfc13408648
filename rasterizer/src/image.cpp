#include "luxel/rasterizer/image.hpp"

#include <OpenImageIO/imageio.h>

#include <stdexcept>

namespace luxel::rasterizer {

void write_image(const Image& image, const std::string& path) {
  if (image.width <= 0 || image.height <= 0) throw std::runtime_error(path + ": cannot write an empty image");
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw std::runtime_error(path + ": cannot write this file type (" + OIIO::geterror() + ")");
  OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
  // The bytes are straight (unassociated) alpha, as PNG stores them: without this OIIO's PNG
  // writer divides color by alpha, as if it were premultiplied, and loses it where alpha is 0.
  spec.attribute("oiio:UnassociatedAlpha", 1);
  if (!out->open(path, spec)) throw std::runtime_error(path + ": " + out->geterror());
  if (!out->write_image(OIIO::TypeDesc::UINT8, image.rgba.data())) throw std::runtime_error(path + ": " + out->geterror());
  if (!out->close()) throw std::runtime_error(path + ": " + out->geterror());
}

Image read_image(const std::string& path) {
  // Straight alpha back (see write_image): otherwise OIIO's PNG reader premultiplies.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) throw std::runtime_error(path + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.width > 16384 || spec.height > 16384 || spec.nchannels <= 0)
    throw std::runtime_error(path + ": unsupported image size or channel count");
  std::vector<uint8_t> raw(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, raw.data()))
    throw std::runtime_error(path + ": " + in->geterror());
  Image image(spec.width, spec.height);
  const int n = spec.nchannels;
  for (size_t i = 0; i < static_cast<size_t>(spec.width) * spec.height; ++i) {
    const uint8_t* p = &raw[i * n];
    uint8_t* q = &image.rgba[i * 4];
    q[0] = p[0];
    q[1] = n >= 3 ? p[1] : p[0];
    q[2] = n >= 3 ? p[2] : p[0];
    q[3] = n == 4 ? p[3] : (n == 2 ? p[1] : 255);
  }
  return image;
}

}  // namespace luxel::rasterizer
