// W4's textures uploaded to OpenGL by luxel's rules (source_textures.hpp).

#include "source_textures.hpp"

#include "luxel/frame/textures.hpp"

#include <cstdint>
#include <stdexcept>
#include <string>

namespace luxel::llvmpipe {

GLint gl_wrap(scenes::Wrap wrap) {
  switch (wrap) {
    case scenes::Wrap::repeat: return GL_REPEAT;
    case scenes::Wrap::mirror: return GL_MIRRORED_REPEAT;
    case scenes::Wrap::clamp: return GL_CLAMP_TO_EDGE;
  }
  return GL_REPEAT;
}


SourceTextures::SourceTextures(const scenes::Scene& scene) : scene_(scene) {
  const uint8_t white[4] = {255, 255, 255, 255};
  glGenTextures(1, &white_);
  glBindTexture(GL_TEXTURE_2D, white_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, white);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glGenTextures(1, &white_cube_);
  glBindTexture(GL_TEXTURE_CUBE_MAP, white_cube_);
  for (int f = 0; f < 6; ++f)
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, white);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
}

SourceTextures::~SourceTextures() {
  for (const auto& [key, name] : flat_) glDeleteTextures(1, &name);
  for (const auto& [key, name] : cubes_) glDeleteTextures(1, &name);
  glDeleteTextures(1, &white_);
  glDeleteTextures(1, &white_cube_);
  if (page_) glDeleteTextures(1, &page_);
}

/// The texture `ref` names, white when none: 8-bit sRGB textures decoded by the sampler (the
/// base texture: luxel's import marks it so), filters and wrap from the glTF sampler, linear
/// between mips whenever there are mips (luxel's rule).
GLuint SourceTextures::flat(const scenes::TextureRef& ref) {
  if (!ref.bound()) return white_;
  auto [it, added] = flat_.try_emplace(ref.texture, 0);
  if (!added) return it->second;
  const scenes::Texture& t = scene_.textures.at(size_t(ref.texture));
  const scenes::PixelImage& image = t.faces.at(0);
  glGenTextures(1, &it->second);
  glBindTexture(GL_TEXTURE_2D, it->second);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  if (image.is_hdr()) {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, image.width, image.height, 0, GL_RGBA, GL_FLOAT, image.rgba32f.data());
  } else {
    const GLint format = t.color_space == scenes::ColorSpace::srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8;
    glTexImage2D(GL_TEXTURE_2D, 0, format, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba8.data());
  }
  GLint min = t.min == scenes::Filter::linear ? GL_LINEAR : GL_NEAREST;
  if (t.mipmaps) {
    glGenerateMipmap(GL_TEXTURE_2D);
    min = t.min == scenes::Filter::linear ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_LINEAR;
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, t.mag == scenes::Filter::linear ? GL_LINEAR : GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, gl_wrap(t.wrap_u));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, gl_wrap(t.wrap_v));
  return it->second;
}

GLuint SourceTextures::cube(int index) {
  if (index < 0) return white_cube_;
  auto [it, added] = cubes_.try_emplace(index, 0);
  if (!added) return it->second;
  const scenes::Texture& t = scene_.textures.at(size_t(index));
  if (t.faces.size() != 6) throw std::runtime_error("texture " + t.name + " is not a cube map");
  glGenTextures(1, &it->second);
  glBindTexture(GL_TEXTURE_CUBE_MAP, it->second);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int f = 0; f < 6; ++f) {
    const scenes::PixelImage& face = t.faces[size_t(f)];
    if (face.is_hdr())
      glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGBA16F, face.width, face.height, 0, GL_RGBA, GL_FLOAT,
                   face.rgba32f.data());
    else
      glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGBA16F, face.width, face.height, 0, GL_RGBA,
                   GL_UNSIGNED_BYTE, face.rgba8.data());
  }
  glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
    glTexParameteri(GL_TEXTURE_CUBE_MAP, wrap, GL_CLAMP_TO_EDGE);
  return it->second;
}

GLuint SourceTextures::lightmap_page(shading::source::LightmapPage& page) {
  if (page_) {
    page = page_layout_;
    return page_;
  }
  const frame::LightmapPageTexels texels = frame::lightmap_page_texels(scene_, page_layout_);
  glGenTextures(1, &page_);
  glBindTexture(GL_TEXTURE_2D, page_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, texels.width, texels.height, 0, GL_RGBA, GL_FLOAT, texels.texels.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  page = page_layout_;
  return page_;
}

}  // namespace luxel::llvmpipe
