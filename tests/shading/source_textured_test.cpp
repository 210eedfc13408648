// The real shaders, texture fetches included, on both numeric lanes: uniform textures (so the
// LOD does not matter), SIMD and scalar bytes must agree within one step and match the closed form.

#include "source_support.hpp"

#include "luxel/shading/source/lightmapped_generic.hpp"
#include "luxel/shading/source/vertexlit_generic.hpp"

#include <gtest/gtest.h>

namespace luxel::shading::source {
namespace {

TEST(SourceTextured, LightmappedGenericBumpEnvmapOnBothLanes) {
  using rasterizer::TextureFormat;
  const rasterizer::Texture base = testing::uniform_2d(TextureFormat::RGBA8_sRGB, glm::vec4(0.5f, 0.25f, 1.0f, 0.0f));
  const rasterizer::Texture bump = testing::uniform_2d(TextureFormat::RGBA8, glm::vec4(0.5f, 0.5f, 1.0f, 1.0f));
  const rasterizer::Texture lightmap = testing::uniform_2d(TextureFormat::RGBA16F, glm::vec4(3.0f, 2.0f, 1.0f, 1.0f));
  const rasterizer::Texture cube = testing::face_colored_cube();
  LightmappedGenericParams p;
  p.base.texture = &base;
  p.bump.texture = &bump;
  p.lightmap.texture = &lightmap;
  p.envmap.texture = &cube;
  constexpr LightmappedCombo C{true, true, EnvmapMask::base_alpha_inverted, EnvmapPath::fast};
  auto make = [](auto zero) {
    using L = decltype(zero);
    LightmappedInputs<L> in;
    in.base_uv = float2<L>(zero + 0.3f, zero + 0.6f);
    in.lightmap_uv12 = float4<L>(zero + 0.1f, zero + 0.2f, zero + 0.3f, zero + 0.4f);
    in.lightmap_uv3 = float2<L>(zero + 0.5f, zero + 0.5f);
    in.tangent = float3<L>(L(1.0f), L(0.0f), L(0.0f));
    in.binormal = float3<L>(L(0.0f), L(1.0f), L(0.0f));
    in.normal = float3<L>(L(0.0f), L(0.0f), L(1.0f));
    in.eye_vector = float3<L>(L(0.0f), L(0.0f), L(5.0f));
    return in;
  };
  const float4<float> s = lightmapped_generic<C>(make(0.0f), p);
  const float4<simd::Float> v = lightmapped_generic<C>(make(simd::Float(0.0f)), p);
  const float4<float> sb = encode_srgb8(s);
  const float4<simd::Float> vb = encode_srgb8(v);
  for (int c = 0; c < 4; ++c)
    for (int l = 0; l < simd::kLanes; ++l) EXPECT_LE(std::abs(testing::lane_of(vb[c], l) - sb[c]), 1.0f);
  // Flat normal: average lightmap (3,2,1) x base (uploaded linear 0.5, stored sRGB, decoded on
  // read) + envmap +Z face (0.4,0.2,0.3) x (1 - base alpha 0). 8-bit bump/base quantisation: 0.02.
  const double base_r = 0.5;
  EXPECT_NEAR(s.x, 3.0 * base_r + 0.4, 0.02);
  EXPECT_NEAR(s.z, 1.0 * 1.0 + 0.3, 0.02);
}

TEST(SourceTextured, VertexLitGenericPhongOnBothLanes) {
  using rasterizer::TextureFormat;
  const rasterizer::Texture base = testing::uniform_2d(TextureFormat::RGBA8_sRGB, glm::vec4(0.8f, 0.6f, 0.4f, 1.0f));
  const rasterizer::Texture bump = testing::uniform_2d(TextureFormat::RGBA8, glm::vec4(0.5f, 0.5f, 1.0f, 1.0f));
  const rasterizer::Texture expo = testing::uniform_2d(TextureFormat::RGBA8, glm::vec4(0.2f, 0.0f, 0.0f, 1.0f));
  VertexLitParams p;
  p.base.texture = &base;
  p.bump.texture = &bump;
  p.phong_exponent.texture = &expo;
  p.lights[0].color = glm::vec4(2.0f, 2.0f, 2.0f, 0.0f);
  p.lights[0].position = glm::vec4(0.0f, 0.0f, 3.0f, 1.0f);
  p.eye_position = glm::vec4(0.0f, 1.0f, 4.0f, 1.0f);
  constexpr VertexLitCombo C{2, true, true, true, true, true, true};
  auto make = [](auto zero) {
    using L = decltype(zero);
    VertexLitInputs<L> in;
    in.uv = float2<L>(zero + 0.5f, zero + 0.5f);
    in.world_pos = float3<L>(zero + 0.1f, zero, zero);
    in.normal = float3<L>(L(0.0f), L(0.0f), L(1.0f));
    in.tangent = float3<L>(L(1.0f), L(0.0f), L(0.0f));
    in.binormal = float3<L>(L(0.0f), L(1.0f), L(0.0f));
    return in;
  };
  const float4<float> sb = encode_srgb8(vertexlit_generic<C>(make(0.0f), p));
  const float4<simd::Float> vb = encode_srgb8(vertexlit_generic<C>(make(simd::Float(0.0f)), p));
  for (int c = 0; c < 4; ++c)
    for (int l = 0; l < simd::kLanes; ++l) EXPECT_LE(std::abs(testing::lane_of(vb[c], l) - sb[c]), 1.0f);
  EXPECT_GT(sb.x, 0.0f);
}

}  // namespace
}  // namespace luxel::shading::source
