// ps_2_0's normalization cube map (normalization_cube.hpp): a lookup is the bilinear blend of the
// four nearest texels' quantized unit vectors, computed here in double from the texel layout of
// texture.hpp, and it differs from ps_2_b's exact normalize by what a 32-texel signed 8-bit cube
// map gives; VertexLitGeneric's ps_2_0 combos light with it, the ps_2_b ones with nrm.

#include "source_support.hpp"

#include "luxel/shading/source/normalization_cube.hpp"
#include "luxel/shading/source/vertexlit_generic.hpp"

#include <glm/gtc/packing.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace luxel::shading::source {
namespace {

using DVec = glm::dvec3;

/// The stored texel of face +Z at (x, y): the unit vector through its center, snorm8, then half.
DVec texel_pos_z(int x, int y, int size) {
  const double u = (x + 0.5) / size, v = (y + 0.5) / size;
  const DVec d = glm::normalize(DVec(2.0 * u - 1.0, -(2.0 * v - 1.0), 1.0));  // +Z: sc = x, tc = -y
  DVec r;
  for (int i = 0; i < 3; ++i) {
    const float q = static_cast<float>(std::round(d[i] * 127.0) / 127.0);
    r[i] = glm::unpackHalf1x16(glm::packHalf1x16(q));
  }
  return r;
}

/// Bilinear lookup of a direction on face +Z (|z| the major axis, away from the edges).
DVec lookup_pos_z(const DVec& dir, int size) {
  const double u = (dir.x / dir.z + 1.0) / 2.0, v = (-dir.y / dir.z + 1.0) / 2.0;
  const double tu = u * size - 0.5, tv = v * size - 0.5;
  const int x0 = static_cast<int>(std::floor(tu)), y0 = static_cast<int>(std::floor(tv));
  const double fx = tu - x0, fy = tv - y0;
  return (1 - fx) * (1 - fy) * texel_pos_z(x0, y0, size) + fx * (1 - fy) * texel_pos_z(x0 + 1, y0, size) +
         (1 - fx) * fy * texel_pos_z(x0, y0 + 1, size) + fx * fy * texel_pos_z(x0 + 1, y0 + 1, size);
}

const DVec kDirection = DVec(0.3, -0.2, 1.0) * 2.5;  // not unit; between texel centers of +Z

TEST(SourceNormalizationCube, LookupIsTheBilinearBlendOfQuantizedTexelDirections) {
  const rasterizer::Texture cube = normalization_cube_map();
  EXPECT_EQ(cube.width(), kNormalizationCubeSize);
  // The cube's contents and where a direction reads it, with the ideal rules' exact bilinear
  // weights (the hardware rules' are tested with the rasterizer's textures).
  rasterizer::Sampler ideal = normalization_cube_sampler();
  ideal.rules = rasterizer::SamplingRules::ideal;
  const SamplerCube s{5, &cube, ideal};
  const float4<float> got = texCUBE(s, float3<float>(float(kDirection.x), float(kDirection.y), float(kDirection.z)));
  const DVec expect = lookup_pos_z(kDirection, kNormalizationCubeSize);
  const DVec exact = glm::normalize(kDirection);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expect[c], 2e-6) << c;
  // What the cube map's resolution and 8 bits cost against nrm: measurable, and small.
  const double error = glm::length(expect - exact);
  std::printf("normalization cube %d: |cube - normalize| = %.2e at (%.2f, %.2f, %.2f)\n", kNormalizationCubeSize, error,
              exact.x, exact.y, exact.z);
  EXPECT_GT(error, 1e-3);
  EXPECT_LT(error, 0.02);
  EXPECT_NEAR(glm::length(DVec(got.x, got.y, got.z) - exact), error, 2e-6);
}

TEST(SourceNormalizationCube, Ps20LightsWithTheCubeAndPs2bWithNrm) {
  const rasterizer::Texture cube = normalization_cube_map();
  VertexLitParams p;
  p.normalization_cube.texture = &cube;
  p.normalization_cube.state.rules = rasterizer::SamplingRules::ideal;  // as lookup_pos_z weighs
  p.ambient.color = {glm::vec3(0.9f, 0.1f, 0.1f), glm::vec3(0.1f, 0.8f, 0.1f), glm::vec3(0.1f, 0.1f, 0.7f),
                     glm::vec3(0.6f, 0.6f, 0.1f), glm::vec3(0.1f, 0.5f, 0.5f), glm::vec3(0.4f, 0.1f, 0.4f)};
  constexpr VertexLitCombo kPs20{0, false, false, false, true, true, false, Fog::none, true};
  constexpr VertexLitCombo kPs2b{0, false, false, false, true, true};
  static_assert(kPs20.valid(ShaderModel::ps_2_0) && !kPs20.valid(ShaderModel::ps_2_b));
  static_assert(!kPs2b.valid(ShaderModel::ps_2_0) && kPs2b.valid(ShaderModel::ps_2_b));
  VertexLitInputs<float> in;
  in.normal = float3<float>(float(kDirection.x), float(kDirection.y), float(kDirection.z));
  const float4<float> ps20 = vertexlit_combine<kPs20>(VertexLitTexels<float>{}, in, p);
  const float4<float> ps2b = vertexlit_combine<kPs2b>(VertexLitTexels<float>{}, in, p);
  const glm::dvec3 via_cube = ambient_light_reference(lookup_pos_z(kDirection, kNormalizationCubeSize), p.ambient);
  const glm::dvec3 via_nrm = ambient_light_reference(glm::normalize(kDirection), p.ambient);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(ps20[c], via_cube[c], 4e-6) << c;
    EXPECT_NEAR(ps2b[c], via_nrm[c], 2e-6) << c;
  }
  EXPECT_GT(glm::length(via_cube - via_nrm), 1e-3) << "the two models differ visibly here";
  // Counted: one texture slot per normalization on ps_2_0, none on ps_2_b.
  EXPECT_EQ(measure_vertexlit_generic<kPs20>(ShaderModel::ps_2_0).texture_slots, 2);
  EXPECT_EQ(measure_vertexlit_generic<kPs2b>(ShaderModel::ps_2_b).texture_slots, 1);
}

}  // namespace
}  // namespace luxel::shading::source
