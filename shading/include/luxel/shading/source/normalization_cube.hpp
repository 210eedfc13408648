#pragma once
// The normalization cube map ps_2_0 normalizes vectors with (docs/fidelity.md#bumped-and-skin-paths;
// NormalizeWithCubemap in common_ps_fxc.h returns the texel as is, and the DX9 helpers bind
// TEXTURE_NORMALIZATION_CUBEMAP_SIGNED): each texel holds the unit vector through its center in a
// signed 8-bit format, so texCUBE(cube, v) is v / |v| up to the texel's quantization and the
// bilinear blend of four neighbouring directions (whose result is a little shorter than 1 and
// points between texel centers). ps_2_b and ps_3_0 use nrm instead.
//
// The texture is built by the closed materialsystem (NOT IN SDK): its size, format and filtering
// are luxel's choice, stated here. Size kNormalizationCubeSize texels a side; format signed 8-bit
// (D3DFMT_Q8W8V8U8: component c stored as round(127 c) / 127), held in RGBA16F because the
// rasterizer has no signed 8-bit format (half floats keep 11 significant bits of each k / 127, a
// further rounding below 2^-12); bilinear filtering, one mip level, read at level 0.

#include "luxel/rasterizer/texture.hpp"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <vector>

namespace luxel::shading::source {

inline constexpr int kNormalizationCubeSize = 32;

/// Bilinear, no mips (what the ps_2_0 combos read the cube map with).
inline rasterizer::Sampler normalization_cube_sampler() {
  rasterizer::Sampler s;
  s.min = rasterizer::Filter::Linear;
  s.mag = rasterizer::Filter::Linear;
  s.mip = rasterizer::MipFilter::None;
  return s;
}

/// One component of a unit vector as the signed 8-bit texel stores it.
inline float snorm8(float c) { return std::round(c * 127.0f) / 127.0f; }

/// The signed normalization cube map, `size` texels a side.
inline rasterizer::Texture normalization_cube_map(int size = kNormalizationCubeSize) {
  rasterizer::Texture cube = rasterizer::Texture::create_cube(size, rasterizer::TextureFormat::RGBA16F, 1);
  std::vector<glm::vec4> texels(static_cast<size_t>(size) * size);
  for (int f = 0; f < 6; ++f) {
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        const glm::vec3 d = glm::normalize(rasterizer::cube_direction(static_cast<rasterizer::CubeFace>(f),
                                                                      (x + 0.5f) / size, (y + 0.5f) / size));
        texels[static_cast<size_t>(y) * size + x] = glm::vec4(snorm8(d.x), snorm8(d.y), snorm8(d.z), 1.0f);
      }
    }
    cube.upload(0, texels, f);
  }
  return cube;
}

}  // namespace luxel::shading::source
