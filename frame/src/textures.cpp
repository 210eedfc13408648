#include "luxel/frame/textures.hpp"

#include <glm/vec4.hpp>

#include <vector>

namespace luxel::frame {

namespace {

rasterizer::Address address(scenes::Wrap w) {
  switch (w) {
    case scenes::Wrap::mirror: return rasterizer::Address::Mirror;
    case scenes::Wrap::clamp: return rasterizer::Address::Clamp;
    default: return rasterizer::Address::Wrap;
  }
}

rasterizer::Filter filter(scenes::Filter f) {
  return f == scenes::Filter::nearest ? rasterizer::Filter::Point : rasterizer::Filter::Linear;
}

}  // namespace

GpuTexture upload(const scenes::Texture& t) {
  const scenes::PixelImage& first = t.faces.at(0);
  const bool hdr = first.is_hdr();
  const rasterizer::TextureFormat format = hdr ? rasterizer::TextureFormat::RGBA16F
                                           : t.color_space == scenes::ColorSpace::srgb ? rasterizer::TextureFormat::RGBA8_sRGB
                                                                                        : rasterizer::TextureFormat::RGBA8;
  const int levels = t.mipmaps ? rasterizer::Texture::kFullMipChain : 1;
  GpuTexture g{t.shape == scenes::TextureShape::cube ? rasterizer::Texture::create_cube(first.width, format, levels)
                                                     : rasterizer::Texture::create_2d(first.width, first.height, format, levels),
               {}};
  for (size_t f = 0; f < t.faces.size(); ++f) {
    const scenes::PixelImage& image = t.faces[f];
    if (hdr) {
      std::vector<glm::vec4> texels(image.rgba32f.size() / 4);
      for (size_t i = 0; i < texels.size(); ++i)
        texels[i] = {image.rgba32f[4 * i], image.rgba32f[4 * i + 1], image.rgba32f[4 * i + 2], image.rgba32f[4 * i + 3]};
      g.texture.upload(0, std::span<const glm::vec4>(texels), static_cast<int>(f));
    } else {
      g.texture.upload(0, std::span<const uint8_t>(image.rgba8), static_cast<int>(f));
    }
  }
  if (t.mipmaps) g.texture.generate_mips();
  g.sampler.u = address(t.wrap_u);
  g.sampler.v = address(t.wrap_v);
  g.sampler.mag = filter(t.mag);
  g.sampler.min = filter(t.min);
  g.sampler.mip = t.mipmaps ? rasterizer::MipFilter::Linear : rasterizer::MipFilter::None;
  return g;
}

GpuTexture white_texture() {
  GpuTexture g{rasterizer::Texture::create_2d(1, 1, rasterizer::TextureFormat::RGBA8, 1), {}};
  const uint8_t white[4] = {255, 255, 255, 255};
  g.texture.upload(0, std::span<const uint8_t>(white));
  return g;
}

}  // namespace luxel::frame
