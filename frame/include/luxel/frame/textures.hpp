#pragma once
// A scenes::Texture as the rasterizer samples it: uploaded once, mips generated. Public so that
// draws outside the renderer (the benchmark workloads) upload textures the same way.

#include "luxel/rasterizer/texture.hpp"
#include "luxel/scenes/scene.hpp"
#include "luxel/shading/source/adapter.hpp"

#include <optional>
#include <vector>

namespace luxel::frame {

struct GpuTexture {
  rasterizer::Texture texture;
  rasterizer::Sampler sampler;
  bool translucent = false;  ///< a texel with alpha below 1 (scenes::has_translucent_texels)
};

/// `s` as a frame's draws read with it: `lod_bias` added to its mip LOD bias
/// (FrameSettings::texture_lod_bias), filtering by `rules` (FrameSettings::sampling).
inline rasterizer::Sampler as_drawn(rasterizer::Sampler s, float lod_bias, rasterizer::SamplingRules rules) {
  s.lod_bias += lod_bias;
  s.rules = rules;
  return s;
}

/// 8-bit sRGB images become RGBA8_sRGB, other 8-bit ones RGBA8, float images RGBA16F (HDR); a
/// full mip chain when the texture asks for mipmaps, the base level alone otherwise.
GpuTexture upload(const scenes::Texture& texture);

/// A 1x1 opaque white texture: what an untextured material samples.
GpuTexture white_texture();

/// A 1x1 flat normal map (0.5, 0.5, 1, alpha 1 in 8 bits): what the skin shader's full path
/// reads for a material without one (the SDK's TEXTURE_NORMALMAP_FLAT; its alpha is not in the
/// SDK, and the Phong mask then comes from the base, $basemapalphaphongmask).
GpuTexture flat_normal_texture();

/// The lightmap page LightmappedGeneric samples: the scene's flat and three RNM lightmaps side by
/// side (RGBA16F, bilinear, no mips, as Source's lightmap pages), each followed by a copy of its
/// last column and preceded by a copy of its first, so that bilinear reads near a map's edge
/// never reach its neighbour. `page` receives where each map sits. Throws std::invalid_argument
/// when the scene's Lightmaps are incomplete or of different sizes.
GpuTexture lightmap_page(const scenes::Scene& scene, shading::source::LightmapPage& page);

/// The texels lightmap_page uploads (rows top first, linear RGBA), for a renderer that uploads them
/// itself: the llvmpipe benchmark's W4 reads the page luxel reads. Throws as lightmap_page does.
struct LightmapPageTexels {
  int width = 0, height = 0;
  std::vector<glm::vec4> texels;
};
LightmapPageTexels lightmap_page_texels(const scenes::Scene& scene, shading::source::LightmapPage& page);

/// A scene's textures as every frame of it samples them: each scenes::Texture uploaded (upload,
/// in scene order) and, when the scene has lightmaps, its lightmap page. Preparing them is most
/// of what constructing a Renderer costs: renderers of one scene with different settings (the
/// faces and exposures of a cube-map capture) share one. Throws as lightmap_page does.
struct SceneTextures {
  std::vector<GpuTexture> textures;
  std::optional<GpuTexture> lightmaps;
  shading::source::LightmapPage page;

  explicit SceneTextures(const scenes::Scene& scene);
};

/// The six faces of a cube texture as 2D textures (D3D face order), for the skybox's six quads:
/// face f's texel (s, t) is the cube's texel (s, t) of face f. Clamped at the edges.
std::vector<GpuTexture> cube_faces(const scenes::Texture& cube);

}  // namespace luxel::frame
