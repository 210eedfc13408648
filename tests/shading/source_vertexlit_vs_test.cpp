// VertexLitGeneric lit per vertex (vertexlit_vertex_shader.hpp): two lights of different colors
// and types at an off-axis normal through a rotated and translated model, Half-Lambert and Lambert,
// the ambient cube, projection and vertex fog, against the SDK's formulas written out in double;
// the per-pixel path agrees with it where both are defined; every combo's vs_2_0 / vs_3_0 budget.
// The hero ambient boost (light_folding.hpp) with lights of several strengths.

#include "source_support.hpp"

#include "luxel/shading/source/light_folding.hpp"
#include "luxel/shading/source/unlit_generic.hpp"
#include "luxel/shading/source/vertexlit_vertex_shader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace luxel::shading::source {
namespace {
// Named apart: the unity batches put this file beside source_vertexlit_test.cpp.
namespace vertex_shader {

using DVec = glm::dvec3;

constexpr VertexLitVsCombo kTwoHL{2, true};
constexpr VertexLitVsCombo kTwoLambert{2, false};

AmbientCube test_cube() {
  AmbientCube c;
  c.color = {glm::vec3(0.30f, 0.10f, 0.05f), glm::vec3(0.02f, 0.20f, 0.04f), glm::vec3(0.05f, 0.06f, 0.40f),
             glm::vec3(0.25f, 0.25f, 0.01f), glm::vec3(0.01f, 0.15f, 0.35f), glm::vec3(0.20f, 0.02f, 0.22f)};
  return c;
}

LightDesc point_light() {
  LightDesc d;
  d.position = glm::vec3(3.0f, -1.0f, 4.0f);
  d.color = glm::vec3(2.0f, 0.5f, 0.25f);
  d.attenuation = glm::vec3(1.0f, 0.1f, 0.01f);
  return d;
}
LightDesc directional_light() {
  LightDesc d;
  d.type = LightDesc::Type::directional;
  d.direction = glm::vec3(-0.3f, 0.9f, 0.4f);  // travels up and back: lights the model from below
  d.color = glm::vec3(0.1f, 0.6f, 1.2f);
  return d;
}

// Model: rotation by 30 degrees about z, then translation (1, 2, 0.5).
constexpr double kAngle = 0.52359877559829887;
DVec model_apply(const DVec& v, double w) {
  const double c = std::cos(kAngle), s = std::sin(kAngle);
  return DVec(c * v.x - s * v.y + w * 1.0, s * v.x + c * v.y + w * 2.0, v.z + w * 0.5);
}

VertexLitVsParams test_params() {
  VertexLitVsParams p;
  const float c = static_cast<float>(std::cos(kAngle)), s = static_cast<float>(std::sin(kAngle));
  p.model = {glm::vec4(c, -s, 0.0f, 1.0f), glm::vec4(s, c, 0.0f, 2.0f), glm::vec4(0.0f, 0.0f, 1.0f, 0.5f)};
  p.view_proj = glm::mat4(1.0f);
  p.view_proj[2][2] = 2.0f;   // z' = 2 z + 100 (column-major glm: [column][row])
  p.view_proj[3][2] = 100.0f;
  p.ambient = test_cube();
  p.lights[0] = to_local_light(point_light());
  p.lights[1] = to_local_light(directional_light());
  p.eye_position = glm::vec4(0.0f, -5.0f, 3.0f, 1.0f);
  FogSettings fog;
  fog.start = 50.0f;
  fog.end = 250.0f;
  fog.max_density = 0.7f;
  p.fog = vertex_fog_constant(fog);
  return p;
}

const DVec kObjectPos(0.5, 0.25, 1.0);
const DVec kObjectNormal(0.3, 0.5, 0.8);  // not unit, off every axis

/// The SDK's DoLightingUnrolled for the two lights and the cube, in double.
DVec expected_lighting(bool half_lambert) {
  const DVec world = model_apply(kObjectPos, 1.0);
  const DVec n = glm::normalize(model_apply(kObjectNormal, 0.0));
  auto cosine = [&](double n_dot_l) {
    return half_lambert ? (0.5 * n_dot_l + 0.5) * (0.5 * n_dot_l + 0.5) : std::max(0.0, n_dot_l);
  };
  DVec sum(0.0);
  {  // point light: 1 / (a0 + a1 d + a2 d²)
    const LightDesc d = point_light();
    const DVec v = DVec(d.position) - world;
    const double dist = glm::length(v);
    const double atten = 1.0 / (1.0 + 0.1 * dist + 0.01 * dist * dist);
    sum += DVec(d.color) * cosine(glm::dot(n, v / dist)) * atten;
  }
  {  // directional: L = -direction, no attenuation
    const LightDesc d = directional_light();
    const DVec l = -glm::normalize(DVec(d.direction));
    sum += DVec(d.color) * cosine(glm::dot(n, l));
  }
  const AmbientCube cube = test_cube();
  for (int a = 0; a < 3; ++a) sum += n[a] * n[a] * DVec(cube.color[2 * a + (n[a] >= 0.0 ? 0 : 1)]);
  return sum;
}

template <VertexLitVsCombo C>
VertexLitVsOutputs<float> run(const VertexLitVsParams& p) {
  VertexLitVsInputs<float> in;
  in.position = float4<float>(float(kObjectPos.x), float(kObjectPos.y), float(kObjectPos.z), 1.0f);
  in.normal = float3<float>(float(kObjectNormal.x), float(kObjectNormal.y), float(kObjectNormal.z));
  in.uv = float2<float>(0.25f, 0.75f);
  return vertexlit_vertex_shader<C>(in, p);
}

TEST(SourceVertexLitVs, TwoColoredLightsAndTheCubeAtAnOffAxisNormal) {
  const VertexLitVsParams p = test_params();
  {
    const DVec n = glm::normalize(model_apply(kObjectNormal, 0.0));
    ASSERT_LT(glm::dot(n, -glm::normalize(DVec(directional_light().direction))), -0.1)
        << "the directional light is behind the surface: Lambert and Half-Lambert differ there";
  }
  for (bool hl : {true, false}) {
    const VertexLitVsOutputs<float> o = hl ? run<kTwoHL>(p) : run<kTwoLambert>(p);
    const DVec e = expected_lighting(hl);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(o.lighting[c], e[c], 2e-6 * (1.0 + e[c])) << (hl ? "HL " : "Lambert ") << c;
  }
}

TEST(SourceVertexLitVs, PositionNormalEyeVectorAndVertexFog) {
  const VertexLitVsParams p = test_params();
  const VertexLitVsOutputs<float> o = run<kTwoHL>(p);
  const DVec world = model_apply(kObjectPos, 1.0);
  const DVec n = glm::normalize(model_apply(kObjectNormal, 0.0));
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(o.world_pos_proj_z[c], world[c], 1e-6);
    EXPECT_NEAR(o.world_normal[c], n[c], 1e-6);
  }
  const double proj_z = 2.0 * world.z + 100.0;
  EXPECT_NEAR(o.proj_pos.x, world.x, 1e-6);
  EXPECT_NEAR(o.proj_pos.z, proj_z, 1e-5);
  EXPECT_NEAR(o.world_pos_proj_z.w, proj_z, 1e-5);
  EXPECT_NEAR(o.eye_vector.y, -5.0 - world.y, 1e-6);
  // Fog visibility max(1 - 0.7, (250 - z) / 200) at an intermediate z (~105).
  EXPECT_NEAR(o.fog, std::max(0.3, (250.0 - proj_z) / 200.0), 1e-6);
  EXPECT_EQ(o.uv.x, 0.25f);
}

TEST(SourceVertexLitVs, ThePixelShaderMultipliesTheAlbedoByTheVertexLighting) {
  // vertexlit_and_unlit_generic_ps2x with DIFFUSELIGHTING: albedo x $color x i.color, tone-mapped.
  const VertexLitVsOutputs<float> o = run<kTwoHL>(test_params());
  constexpr UnlitCombo kLit{UnlitDetail::none, false, UnlitEnvmapMask::none, false, true};
  UnlitGenericParams p;
  p.modulation = glm::vec4(0.9f, 0.8f, 0.6f, 1.0f);
  p.tonemap = ToneMapConstants::for_scale(1.25f);
  UnlitTexels<float> t;
  t.base = float4<float>(0.7f, 0.5f, 0.3f, 0.75f);
  UnlitInputs<float> in;
  in.vertex_color = float4<float>(o.lighting, 1.0f);
  const float4<float> c = unlit_generic_combine<kLit>(t, in, p, [](const float3<float>& r) { return r; });
  const DVec e = expected_lighting(true);
  const double base[3] = {0.7, 0.5, 0.3}, mod[3] = {0.9, 0.8, 0.6};
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k], base[k] * mod[k] * e[k] * 1.25, 1e-5) << k;
  EXPECT_NEAR(c.w, 0.75, 1e-7);
}

TEST(SourceVertexLitVs, AgreesWithThePerPixelPathForAUnitNormal) {
  // The two paths share the attenuation and the cube; their cosine terms differ only for
  // non-unit vectors (the pixel one saturates before squaring).
  const VertexLitVsParams vp = test_params();
  VertexLitParams pp;
  pp.ambient = vp.ambient;
  pp.lights = vp.lights;
  constexpr VertexLitCombo kPerPixel{2, false, false, false, true, true};
  const DVec world = model_apply(kObjectPos, 1.0);
  const DVec n = glm::normalize(model_apply(kObjectNormal, 0.0));
  const float3<float> w(float(world.x), float(world.y), float(world.z));
  const float3<float> nf(float(n.x), float(n.y), float(n.z));
  const float3<float> vertex = vertex_lighting<kTwoHL>(w, normalize(nf), vp);
  VertexLitInputs<float> in;
  in.world_pos = w;
  in.normal = nf;
  const float4<float> pixel = vertexlit_combine<kPerPixel>(VertexLitTexels<float>{}, in, pp);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(vertex[c], pixel[c], 1e-6);
}

TEST(SourceVertexLitVs, EveryComboFitsTheVertexModelsItExistsOn) {
  int measured = 0;
  for_each_combo<kVertexLitVsSpace>([&]<VertexLitVsCombo C>() {
    for (ShaderModel m : kVertexModels) {
      if (!C.valid(m)) continue;
      const Cost cost = measure_vertexlit_vertex_shader<C>(m);
      const Verdict v = fits(cost, caps(m));
      EXPECT_TRUE(v) << C.name() << " on " << caps(m).name << ": " << v.reason;
      EXPECT_EQ(cost.texture_slots, 0);
      std::printf("VertexLitGeneric vs %-14s %s\n", C.name().c_str(), describe(cost).c_str());
      ++measured;
    }
  });
  // NUM_LIGHTS 0..2 on vs20, 0..4 on vs30, each with and without Half-Lambert but for no lights:
  // 1 + 2 x 2 on each model, + 2 x 2 on vs30 alone.
  EXPECT_EQ(measured, 14);
  EXPECT_FALSE((VertexLitVsCombo{4, true}.valid(ShaderModel::vs_2_0))) << "NUM_LIGHTS 0..2 on vs20";
  EXPECT_FALSE((VertexLitVsCombo{2, true}.valid(ShaderModel::ps_2_0)));
  // Each light costs slots: the counts grow with the light count.
  constexpr VertexLitVsCombo kNone{0, true}, kOne{1, true};
  EXPECT_LT(measure_vertexlit_vertex_shader<kNone>(ShaderModel::vs_2_0).arithmetic_slots,
            measure_vertexlit_vertex_shader<kOne>(ShaderModel::vs_2_0).arithmetic_slots);
}

// ---- The hero ambient boost ----------------------------------------------------------------------

double luminance(const DVec& c) { return 0.2125 * c.x + 0.7154 * c.y + 0.0721 * c.z; }

TEST(SourceAmbientBoost, RaisesTheCubeToAFractionOfTheDirectLights) {
  const AmbientCube cube = test_cube();
  double a = 0.0;
  for (const glm::vec3& c : cube.color) a += luminance(DVec(c));
  a /= 6.0;
  const glm::vec3 point(0.0f, 0.0f, 0.0f);
  // Three lights of different strengths: a point light 5 units away (quadratic falloff), a spot
  // on its axis, a directional light.
  LightDesc bulb;
  bulb.position = glm::vec3(3.0f, 4.0f, 0.0f);
  bulb.color = glm::vec3(40.0f, 30.0f, 20.0f);
  bulb.attenuation = glm::vec3(0.0f, 0.0f, 1.0f);
  LightDesc spot;
  spot.type = LightDesc::Type::spot;
  spot.position = glm::vec3(0.0f, 0.0f, 2.0f);
  spot.direction = glm::vec3(0.0f, 0.0f, -1.0f);
  spot.color = glm::vec3(3.0f, 3.0f, 6.0f);
  spot.attenuation = glm::vec3(1.0f, 0.5f, 0.0f);
  LightDesc sun;
  sun.type = LightDesc::Type::directional;
  sun.color = glm::vec3(0.3f, 0.25f, 0.2f);
  const double d_bulb = luminance(DVec(40, 30, 20) / 25.0);
  const double d_spot = luminance(DVec(3, 3, 6) / (1.0 + 0.5 * 2.0));  // on the axis: cone factor 1
  const double d_sun = luminance(DVec(0.3, 0.25, 0.2));
  AmbientBoost boost;
  boost.enabled = true;
  const LightDesc all[] = {bulb, spot, sun};
  const double k = std::max(1.0, 0.25 * (d_bulb + d_spot + d_sun) / a);
  ASSERT_GT(k, 2.0) << "strong lights: a real boost";
  EXPECT_NEAR(ambient_boost_factor(cube, all, point, boost), k, 1e-6 * k);
  const AmbientCube boosted = boost_ambient_cube(cube, all, point, boost);
  for (int j = 0; j < 6; ++j)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(boosted.color[j][c], cube.color[j][c] * k, 1e-6 * k) << j;
  // Only the weak light: 0.25 D < A, no boost.
  const LightDesc weak[] = {sun};
  ASSERT_LT(0.25 * d_sun, a);
  EXPECT_EQ(ambient_boost_factor(cube, weak, point, boost), 1.0);
  // Two lights: in between.
  const LightDesc two[] = {spot, sun};
  EXPECT_NEAR(ambient_boost_factor(cube, two, point, boost), std::max(1.0, 0.25 * (d_spot + d_sun) / a), 1e-6);
  // Off by default (as the QC flag), and a black cube stays black.
  EXPECT_EQ(ambient_boost_factor(cube, all, point, AmbientBoost{}), 1.0);
  EXPECT_EQ(boost_ambient_cube(AmbientCube{}, all, point, boost).color[0], glm::vec3(0.0f));
}

}  // namespace vertex_shader
}  // namespace
}  // namespace luxel::shading::source
