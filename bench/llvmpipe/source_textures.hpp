#pragma once
// W4's textures as OpenGL objects, each uploaded once: the scene's 2D textures by luxel's rules
// (sRGB decode where the import marks a texture sRGB, the glTF sampler's filters and wrap, linear
// between mips whenever there are mips), the baked cube maps, and luxel's lightmap page.

#include "luxel/scenes/scene.hpp"
#include "luxel/shading/source/adapter.hpp"

#include <GL/glcorearb.h>

#include <map>

namespace luxel::llvmpipe {

/// The OpenGL wrap mode of a glTF sampler's (W3's and W4's textures).
GLint gl_wrap(scenes::Wrap wrap);

class SourceTextures {
 public:
  explicit SourceTextures(const scenes::Scene& scene);
  ~SourceTextures();
  SourceTextures(const SourceTextures&) = delete;
  SourceTextures& operator=(const SourceTextures&) = delete;

  /// The texture `ref` names; white when none.
  GLuint flat(const scenes::TextureRef& ref);
  /// Cube texture `index` (a baked cube map: six faces +X, -X, +Y, -Y, +Z, -Z, D3D's order and
  /// OpenGL's, each top row first), RGBA16F with mips, trilinear, clamped; white for -1.
  GLuint cube(int index);
  /// luxel's lightmap page (frame::lightmap_page_texels): RGBA16F, bilinear, clamped, no mips;
  /// `page` receives where each of its four maps lies.
  GLuint lightmap_page(shading::source::LightmapPage& page);

  GLuint white() const { return white_; }
  GLuint white_cube() const { return white_cube_; }

 private:
  const scenes::Scene& scene_;
  std::map<int, GLuint> flat_, cubes_;
  GLuint white_ = 0, white_cube_ = 0, page_ = 0;
  shading::source::LightmapPage page_layout_;
};

}  // namespace luxel::llvmpipe
