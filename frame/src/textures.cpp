#include "luxel/frame/textures.hpp"

#include <glm/vec4.hpp>

#include <stdexcept>
#include <string>
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
               {},
               scenes::has_translucent_texels(t)};
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

namespace {

GpuTexture one_texel(const uint8_t (&rgba)[4]) {
  GpuTexture g{rasterizer::Texture::create_2d(1, 1, rasterizer::TextureFormat::RGBA8, 1), {}};
  g.texture.upload(0, std::span<const uint8_t>(rgba));
  return g;
}

}  // namespace

GpuTexture white_texture() { return one_texel({255, 255, 255, 255}); }

GpuTexture flat_normal_texture() { return one_texel({128, 128, 255, 255}); }

namespace {

/// Texel (x, y) of an image as linear rgba (8-bit images are read as stored: lightmaps and skies
/// are linear or HDR).
glm::vec4 texel(const scenes::PixelImage& image, int x, int y) {
  const size_t i = (static_cast<size_t>(y) * image.width + x) * 4;
  if (image.is_hdr()) return {image.rgba32f[i], image.rgba32f[i + 1], image.rgba32f[i + 2], image.rgba32f[i + 3]};
  return glm::vec4(image.rgba8[i], image.rgba8[i + 1], image.rgba8[i + 2], image.rgba8[i + 3]) / 255.0f;
}

}  // namespace

LightmapPageTexels lightmap_page_texels(const scenes::Scene& scene, shading::source::LightmapPage& page) {
  const scenes::Lightmaps& maps = scene.lightmaps.value();
  const int ids[4] = {maps.flat, maps.textures[0], maps.textures[1], maps.textures[2]};
  const int w = maps.width, h = maps.height;
  constexpr int kGap = 2;
  const int page_width = 4 * w + 3 * kGap;
  LightmapPageTexels out{page_width, h, std::vector<glm::vec4>(static_cast<size_t>(page_width) * h, glm::vec4(0.0f))};
  for (int k = 0; k < 4; ++k) {
    if (ids[k] < 0 || ids[k] >= static_cast<int>(scene.textures.size()))
      throw std::invalid_argument(scene.name + ": lightmap " + std::to_string(k) + " is missing");
    const scenes::PixelImage& image = scene.textures[static_cast<size_t>(ids[k])].faces.at(0);
    if (image.width != w || image.height != h)
      throw std::invalid_argument(scene.name + ": lightmap " + std::to_string(k) + " is " + std::to_string(image.width) +
                                  "x" + std::to_string(image.height) + ", not the atlas's " + std::to_string(w) + "x" +
                                  std::to_string(h));
    const int x0 = k * (w + kGap);
    for (int y = 0; y < h; ++y) {
      glm::vec4* row = out.texels.data() + static_cast<size_t>(y) * page_width;
      for (int x = 0; x < w; ++x) row[x0 + x] = texel(image, x, y);
      if (k > 0) row[x0 - 1] = row[x0];
      if (k < 3) row[x0 + w] = row[x0 + w - 1];
    }
    page.offset[static_cast<size_t>(k)] = static_cast<float>(x0) / page_width;
  }
  page.scale = static_cast<float>(w) / page_width;
  return out;
}

GpuTexture lightmap_page(const scenes::Scene& scene, shading::source::LightmapPage& page) {
  const LightmapPageTexels page_texels = lightmap_page_texels(scene, page);
  GpuTexture g{rasterizer::Texture::create_2d(page_texels.width, page_texels.height, rasterizer::TextureFormat::RGBA16F, 1), {}};
  g.texture.upload(0, std::span<const glm::vec4>(page_texels.texels));
  g.sampler.u = g.sampler.v = rasterizer::Address::Clamp;
  g.sampler.mag = g.sampler.min = rasterizer::Filter::Linear;
  g.sampler.mip = rasterizer::MipFilter::None;
  return g;
}

SceneTextures::SceneTextures(const scenes::Scene& scene) {
  textures.reserve(scene.textures.size());
  for (const scenes::Texture& t : scene.textures) textures.push_back(upload(t));
  if (scene.lightmaps) lightmaps = lightmap_page(scene, page);
}

std::vector<GpuTexture> cube_faces(const scenes::Texture& cube) {
  std::vector<GpuTexture> faces;
  for (int f = 0; f < 6; ++f) {
    scenes::Texture face = cube;
    face.shape = scenes::TextureShape::flat;
    face.faces = {cube.faces.at(static_cast<size_t>(f))};
    face.wrap_u = face.wrap_v = scenes::Wrap::clamp;
    faces.push_back(upload(face));
  }
  return faces;
}

}  // namespace luxel::frame
