// Texture fetches on each lane, through the texture module: how each lane gets its level of detail.

#include "lanes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace luxel::shading {
namespace {

using testing::lane_of;

/// A 256x256 texture whose mip level l is the constant color (l / 16, 0, 0, 1), read with point
/// filtering and point mips: the red channel tells which level a fetch chose.
rasterizer::Texture level_probe() {
  rasterizer::Texture t = rasterizer::Texture::create_2d(256, 256, rasterizer::TextureFormat::RGBA16);
  for (int l = 0; l < t.mip_levels(); ++l) {
    std::vector<glm::vec4> texels(static_cast<size_t>(t.width(l)) * t.height(l), glm::vec4(l / 16.0f, 0, 0, 1));
    t.upload(l, texels);
  }
  return t;
}
rasterizer::Sampler point_sampler() {
  rasterizer::Sampler s;
  s.min = s.mag = rasterizer::Filter::Point;
  s.mip = rasterizer::MipFilter::Point;
  return s;
}
int level_of(float red) { return static_cast<int>(std::lround(red * 16.0f)); }

TEST(Textures, SimdLaneTakesDerivativesPerQuad) {
  const rasterizer::Texture probe = level_probe();
  const Sampler2D s{0, &probe, point_sampler()};
  // uv = pixel position / 64: one pixel step is 4 texels of level 0: LOD 2.
  const simd::Float u = simd::lanes([](int l) { return (10.0f + simd::lane_x(l)) / 64.0f; });
  const simd::Float v = simd::lanes([](int l) { return (20.0f + simd::lane_y(l)) / 64.0f; });
  const float2<simd::Float> uv(u, v);
  for (int i = 0; i < simd::kLanes; ++i) {
    EXPECT_EQ(level_of(lane_of(tex2D(s, uv).x, i)), 2) << "lane " << i;
    // A dependent read: uv * 4 has four times the derivatives, two levels smaller.
    EXPECT_EQ(level_of(lane_of(tex2D(s, uv * 4.0f).x, i)), 4) << "lane " << i;
    EXPECT_EQ(level_of(lane_of(tex2Dbias(s, float4<simd::Float>(uv, 0.0f, 1.0f)).x, i)), 3) << "bias";
    EXPECT_EQ(level_of(lane_of(tex2Dlod(s, float4<simd::Float>(uv, 0.0f, 5.0f)).x, i)), 5) << "lod";
    const float2<simd::Float> d(1.0f / 8.0f, 0.0f);  // 32 texels a pixel: LOD 5
    EXPECT_EQ(level_of(lane_of(tex2Dgrad(s, uv, d, d.yx()).x, i)), 5) << "grad";
  }
}

TEST(Textures, FloatLaneUsesTheCallersQuadDerivatives) {
  const rasterizer::Texture probe = level_probe();
  Sampler2D s{0, &probe, point_sampler()};
  s.reference_ddx = glm::vec3(1.0f / 64.0f, 0.0f, 0.0f);  // what the SIMD lane measures above
  s.reference_ddy = glm::vec3(0.0f, 1.0f / 64.0f, 0.0f);
  const float2<float> uv(0.25f, 0.5f);
  EXPECT_EQ(level_of(tex2D(s, uv).x), 2);
  EXPECT_EQ(level_of(tex2Dbias(s, float4<float>(uv, 0.0f, 1.0f)).x), 3);
  EXPECT_EQ(level_of(tex2Dlod(s, float4<float>(uv, 0.0f, 5.0f)).x), 5);
  EXPECT_EQ(level_of(tex2Dgrad(s, uv, float2<float>(0.0f, 1.0f / 8.0f), float2<float>(0.0f)).x), 5);
}

TEST(Textures, CubeAndVolumeOnBothLanes) {
  rasterizer::Texture cube = rasterizer::Texture::create_cube(8, rasterizer::TextureFormat::RGBA16F, 1);
  for (int f = 0; f < 6; ++f) cube.upload(0, std::vector<glm::vec4>(64, glm::vec4(static_cast<float>(f))), f);
  const SamplerCube sc{1, &cube};
  EXPECT_EQ(texCUBE(sc, float3<float>(0.0f, -2.0f, 0.1f)).x, 3.0f) << "-Y is face 3";
  const float4<simd::Float> c = texCUBE(sc, float3<simd::Float>(simd::Float(0.0f), simd::Float(0.2f), simd::Float(-5.0f)));
  EXPECT_EQ(lane_of(c.x, 0), 5.0f) << "-Z is face 5";

  rasterizer::Texture volume = rasterizer::Texture::create_volume(4, 4, 4, rasterizer::TextureFormat::RGBA16F, 1);
  volume.upload(0, std::vector<glm::vec4>(64, glm::vec4(0.5f)));
  const Sampler3D s3{2, &volume};
  EXPECT_EQ(tex3D(s3, float3<float>(0.3f, 0.6f, 0.9f)).w, 0.5f);
  EXPECT_EQ(lane_of(tex3D(s3, float3<simd::Float>(simd::Float(0.3f))).y, 0), 0.5f);
}

TEST(Textures, NoTextureBoundIsAnError) {
  const Sampler2D unbound{3};
  EXPECT_THROW(tex2D(unbound, float2<float>(0.5f)), std::logic_error);
  const rasterizer::Texture probe = level_probe();
  const SamplerCube wrong_kind{0, &probe};
  EXPECT_THROW(texCUBE(wrong_kind, float3<float>(1.0f)), std::logic_error);
}

}  // namespace
}  // namespace luxel::shading
