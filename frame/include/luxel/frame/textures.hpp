#pragma once
// A scenes::Texture as the rasterizer samples it: uploaded once, mips generated. Public so that
// draws outside the renderer (the benchmark workloads) upload textures the same way.

#include "luxel/rasterizer/texture.hpp"
#include "luxel/scenes/scene.hpp"

namespace luxel::frame {

struct GpuTexture {
  rasterizer::Texture texture;
  rasterizer::Sampler sampler;
};

/// 8-bit sRGB images become RGBA8_sRGB, other 8-bit ones RGBA8, float images RGBA16F (HDR); a
/// full mip chain when the texture asks for mipmaps, the base level alone otherwise.
GpuTexture upload(const scenes::Texture& texture);

/// A 1x1 opaque white texture: what an untextured material samples.
GpuTexture white_texture();

}  // namespace luxel::frame
