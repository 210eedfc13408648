// frame::Renderer's contract (renderer.hpp) on small scenes whose every pixel is known: sRGB
// decode of base textures and encode on write, the Source shaders' lighting from an ambient cube,
// a light and lightmaps, what differs per shader model, $linearwrite, the background, culling
// and depth order.

#include "frame/frame_support.hpp"
#include "shading/phong_reference.hpp"

#include "luxel/frame/renderer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <cstdint>

namespace luxel::frame {
namespace {

constexpr int kRendererSize = 32;

rasterizer::Image render(const scenes::Scene& s) {
  Renderer r(s, {kRendererSize, kRendererSize, 4});
  rasterizer::Context ctx(2);
  r.render(ctx);
  return r.image();
}

void expect_everywhere(const rasterizer::Image& image, int x0, int x1, const double (&expected)[3], const char* what) {
  int off = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = x0; x < x1; ++x)
      for (int c = 0; c < 3; ++c) off += std::abs(image.pixel(x, y)[c] - expected[c]) > 1.0;
  EXPECT_EQ(off, 0) << what;
}

/// A 4x4 texture of one texel value.
scenes::Texture solid_texture(const char* name, scenes::ColorSpace space, std::array<uint8_t, 4> texel) {
  scenes::Texture t;
  t.name = name;
  t.color_space = space;
  scenes::PixelImage image;
  image.width = image.height = 4;
  for (int i = 0; i < 16; ++i) image.rgba8.insert(image.rgba8.end(), texel.begin(), texel.end());
  t.faces = {image};
  return t;
}

TEST(Renderer, UnlitBaseTextureRoundTripsThroughSrgb) {
  scenes::Scene s = top_down();
  s.textures = {solid_texture("solid", scenes::ColorSpace::srgb, {200, 100, 50, 255})};
  scenes::Material m;
  m.family = scenes::ShaderFamily::unlit_generic;
  m.base.texture = 0;
  s.materials = {m};
  s.meshes = {square(-1, -1, 1, 1, 0, 0)};
  expect_everywhere(render(s), 0, kRendererSize, {200, 100, 50}, "decoded on read, encoded on write");
}

/// A scene lit only by an irradiance volume of one sample and one directional light.
scenes::Scene lit_by_cube_and_sun(bool half_lambert) {
  scenes::Scene s = top_down();
  scenes::IrradianceVolume v;
  v.min = v.max = glm::vec3(0.0f);
  v.counts = {1, 1, 1};
  v.cubes = {{glm::vec3(9.0f), glm::vec3(9.0f), glm::vec3(9.0f), glm::vec3(9.0f), glm::vec3(0.5f, 0.25f, 0.125f), glm::vec3(9.0f)}};
  s.irradiance_volume = v;
  scenes::Light sun;
  sun.type = scenes::LightType::directional;
  sun.direction = glm::normalize(glm::vec3(-0.6f, 0.0f, -0.8f));  // arrives from (0.6, 0, 0.8): n.l = 0.8
  sun.color = {0.5f, 0.375f, 0.25f};
  s.lights = {sun};
  scenes::Material m;  // VertexLitGeneric, untextured: white
  m.color = {0.8f, 0.6f, 0.4f, 1.0f};
  m.half_lambert = half_lambert;
  s.materials = {m};
  s.meshes = {square(-1, -1, 1, 1, 0, 0)};
  return s;
}

rasterizer::Image render_as(const scenes::Scene& s, shading::ShaderModel model) {
  FrameSettings f{kRendererSize, kRendererSize, 4};
  f.model = model;
  Renderer r(s, f);
  rasterizer::Context ctx(2);
  r.render(ctx);
  return r.image();
}

TEST(Renderer, VertexLitTakesTheAmbientCubeAndTheLight) {
  // Normal +Z: the cube's +Z side, whatever the other five hold; the light by (Half-)Lambert.
  for (bool half_lambert : {false, true}) {
    const double term = half_lambert ? 0.9 * 0.9 : 0.8;
    const double albedo[3] = {0.8, 0.6, 0.4}, cube[3] = {0.5, 0.25, 0.125}, light[3] = {0.5, 0.375, 0.25};
    double expected[3];
    for (int c = 0; c < 3; ++c) expected[c] = 255 * srgb_encode(albedo[c] * (cube[c] + light[c] * term));
    const scenes::Scene s = lit_by_cube_and_sun(half_lambert);
    expect_everywhere(render_as(s, shading::ShaderModel::ps_3_0), 0, kRendererSize, expected, "ps_3_0");
    expect_everywhere(render_as(s, shading::ShaderModel::ps_2_b), 0, kRendererSize, expected, "ps_2_b");
  }
}

TEST(Renderer, AmbientFromTheNearestSampleOrTrilinear) {
  // A 2x3x2 volume whose samples differ on their +Z side only; the square's center (0, 0, 0) sits
  // at grid coordinates (0.25, 0.6, 0.3): nearest is sample (0, 1, 0), trilinear weighs all
  // eight around it. No light: the pixel is albedo x the cube's +Z side.
  scenes::Scene s = lit_by_cube_and_sun(false);
  s.lights.clear();
  scenes::IrradianceVolume v;
  v.min = {-0.5f, -1.2f, -0.6f};
  v.spacing = glm::vec3(2.0f);
  v.counts = {2, 3, 2};
  v.max = v.min + v.spacing * glm::vec3(v.counts - 1);
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 2; ++x) {
        scenes::AmbientCube c;
        c.fill(glm::vec3(9.0f));
        c[4] = glm::vec3(0.1f + 0.3f * x, 0.05f + 0.2f * y, 0.1f + 0.5f * z);
        v.cubes.push_back(c);
      }
  s.irradiance_volume = v;
  const double albedo[3] = {0.8, 0.6, 0.4}, g[3] = {0.25, 0.6, 0.3};
  // The +Z side of sample (x, y, z), channel c, as built above.
  const auto side = [](int x, int y, int z, int c) { return c == 0 ? 0.1 + 0.3 * x : c == 1 ? 0.05 + 0.2 * y : 0.1 + 0.5 * z; };
  double nearest[3], trilinear[3];
  for (int c = 0; c < 3; ++c) {
    nearest[c] = 255 * srgb_encode(albedo[c] * side(0, 1, 0, c));
    double sum = 0;
    for (int z = 0; z < 2; ++z)
      for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x)
          sum += (x ? g[0] : 1 - g[0]) * (y ? g[1] : 1 - g[1]) * (z ? g[2] : 1 - g[2]) * side(x, y, z, c);
    trilinear[c] = 255 * srgb_encode(albedo[c] * sum);
  }
  expect_everywhere(render(s), 0, kRendererSize, nearest, "nearest sample");
  FrameSettings f{kRendererSize, kRendererSize, 4};
  f.ambient = AmbientSampling::trilinear;
  Renderer r(s, f);
  rasterizer::Context ctx(2);
  r.render(ctx);
  expect_everywhere(r.image(), 0, kRendererSize, trilinear, "trilinear");
  EXPECT_GT(std::abs(nearest[1] - trilinear[1]), 3.0) << "the two must differ for the test to mean anything";
}

// VertexLitGeneric without a bump map is lit per vertex (vertexlit_and_unlit_generic_vs20.fxc): the
// ambient cube and the light at each vertex, interpolated across the triangle, on every model. A
// point light 0.6 above x = 0.5 of the square: each corner's Lambert term over d² (the corners at
// x = ±1 differ, the two at one x are equal), so the frame is the linear ramp between them in x,
// worked out here in double. Lit per pixel, the spot under the light would be ten times brighter.
TEST(Renderer, PlainModelsAreLitPerVertexAndInterpolated) {
  scenes::Scene s = lit_by_cube_and_sun(false);
  scenes::Light bulb;
  bulb.position = {0.5f, 0.0f, 0.6f};
  bulb.color = {0.6f, 0.5f, 0.4f};  // quadratic attenuation 1: color / d²
  s.lights = {bulb};
  const double albedo[3] = {0.8, 0.6, 0.4}, cube[3] = {0.5, 0.25, 0.125}, light[3] = {0.6, 0.5, 0.4};
  auto lighting_at_corner = [&](double x, int c) {
    const double d2 = (x - 0.5) * (x - 0.5) + 1.0 + 0.36;
    return cube[c] + light[c] * (0.6 / std::sqrt(d2)) / d2;
  };
  for (shading::ShaderModel model : {shading::ShaderModel::ps_2_0, shading::ShaderModel::ps_2_b, shading::ShaderModel::ps_3_0}) {
    const rasterizer::Image image = render_as(s, model);
    int off = 0;
    double worst = 0.0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const double t = (x + 0.5) / image.width;  // world x = 2t - 1
        for (int c = 0; c < 3; ++c) {
          const double lit = (1.0 - t) * lighting_at_corner(-1.0, c) + t * lighting_at_corner(1.0, c);
          const double want = 255 * srgb_encode(albedo[c] * lit);
          worst = std::max(worst, std::abs(image.pixel(x, y)[c] - want));
          off += std::abs(image.pixel(x, y)[c] - want) > 1.0;
        }
      }
    EXPECT_EQ(off, 0) << shading::caps(model).name << ": worst " << worst << " steps from the interpolated vertex lighting";
  }
  // Under the light, lit per pixel: (0.6 / 0.36) x the color, far from the ramp's value there.
  const double t = 0.75, ramp = (1.0 - t) * lighting_at_corner(-1.0, 0) + t * lighting_at_corner(1.0, 0);
  EXPECT_GT(255 * srgb_encode(albedo[0] * (cube[0] + light[0] / 0.36)) - 255 * srgb_encode(albedo[0] * ramp), 20.0);
}

/// `s` with a flat normal map (every texel (0, 0, 1)) on its first material.
void add_flat_bump_map(scenes::Scene& s) {
  s.textures.push_back(solid_texture("flat normals", scenes::ColorSpace::linear, {128, 128, 255, 255}));
  s.materials[0].bump.texture = static_cast<int>(s.textures.size()) - 1;
}

// The SDK's helper gives a $phong material the Phong ("skin") shader only with a bump map (or
// $basemapalphaphongmask, or a lightwarp), and only from ps_2_b on (docs/fidelity.md#which-shader-a-model-gets).
TEST(Renderer, PhongOnlyForBumpedModelsFromPs2b) {
  scenes::Scene s = lit_by_cube_and_sun(true);
  s.materials[0].phong = true;
  s.materials[0].phong_exponent = 4;
  s.materials[0].phong_boost = 8;
  s.cameras[0].projection = scenes::Projection::perspective;  // a view vector that varies
  s.cameras[0].position = {0.3f, -2.0f, 3.0f};
  s.cameras[0].vertical_fov = 1.0f;
  // Without a bump map, $phong changes nothing, on any model.
  scenes::Scene without = s;
  without.materials[0].phong = false;
  for (shading::ShaderModel model : {shading::ShaderModel::ps_2_0, shading::ShaderModel::ps_2_b, shading::ShaderModel::ps_3_0})
    EXPECT_TRUE(render_as(s, model).rgba == render_as(without, model).rgba)
        << shading::caps(model).name << ": $phong without a bump map got specular";
  // With one: Phong on ps_2_b and ps_3_0 (the same combo), none on ps_2_0.
  add_flat_bump_map(s);
  const rasterizer::Image ps30 = render_as(s, shading::ShaderModel::ps_3_0);
  const rasterizer::Image ps2b = render_as(s, shading::ShaderModel::ps_2_b);
  const rasterizer::Image ps20 = render_as(s, shading::ShaderModel::ps_2_0);
  EXPECT_TRUE(ps30.rgba == ps2b.rgba) << "ps_2_b and ps_3_0 run the same combo";
  EXPECT_FALSE(ps30.rgba == ps20.rgba) << "ps_2_0 has no Phong";
  s.materials[0].phong = false;
  const rasterizer::Image plain30 = render_as(s, shading::ShaderModel::ps_3_0);
  int brighter = 0;
  for (size_t i = 0; i < ps30.rgba.size(); ++i) brighter += ps30.rgba[i] > plain30.rgba[i];
  EXPECT_GT(brighter, 0) << "Phong adds light on ps_3_0";
}

// The skin shader's material parameters reach it: $phongexponent, $phongboost, $phongtint and
// $phongfresnelranges on a flat bumped square under one directional light, seen in perspective
// (the view vector varies), against the Phong reference written from docs/fidelity.md#phong in
// double (tests/shading/phong_reference.hpp) plus the ambient cube along the normal.
/// A Phong material on lit_by_cube_and_sun's square (a flat bump map), seen in perspective with the
/// sun where the square mirrors the eye, against `ref` (its light and normal set here; its base the
/// caller's): every pixel within a step on ps_2_b and ps_3_0, and the specular showing.
void expect_skin_frame(scenes::Scene s, shading::source::testing::PhongReference ref) {
  add_flat_bump_map(s);
  scenes::Camera& c = s.cameras[0];
  c.projection = scenes::Projection::perspective;
  c.position = {0.3f, -2.0f, 3.0f};
  c.vertical_fov = 1.0f;
  // The sun where the square mirrors the eye: a highlight in view.
  const glm::dvec3 to_sun = glm::normalize(glm::dvec3(-0.3, 2.0, 3.0));
  s.lights[0].direction = -glm::vec3(to_sun);
  ref.light_dir = glm::dvec3(glm::normalize(glm::vec3(to_sun)));
  ref.light_color = {0.5, 0.375, 0.25};
  const double t = 2.0 * 128.0 / 255.0 - 1.0;  // the flat normal map's 8-bit texel
  const glm::dvec3 n = glm::normalize(glm::dvec3(t, t, 1.0));
  // The ambient cube along n: the +Z side (0.5, 0.25, 0.125), the x and y sides 9.
  const glm::dvec3 ambient = n.z * n.z * glm::dvec3(0.5, 0.25, 0.125) + (n.x * n.x + n.y * n.y) * glm::dvec3(9.0);
  const glm::dvec3 eye(c.position), forward = glm::normalize(glm::dvec3(c.target) - eye);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(c.up))), up = glm::cross(right, forward);
  const double tan_half = std::tan(0.5 * double(c.vertical_fov));
  for (shading::ShaderModel model : {shading::ShaderModel::ps_2_b, shading::ShaderModel::ps_3_0}) {
    const rasterizer::Image image = render_as(s, model);
    int off = 0, checked = 0;
    double specular_steps = 0.0;  // how much of a pixel the specular is: the test must see it
    for (int y = 0; y < kRendererSize; ++y)
      for (int x = 0; x < kRendererSize; ++x) {
        const double ndc_x = 2.0 * (x + 0.5) / kRendererSize - 1.0, ndc_y = 1.0 - 2.0 * (y + 0.5) / kRendererSize;
        const glm::dvec3 dir = forward + tan_half * (ndc_x * right + ndc_y * up);
        if (dir.z >= 0.0) continue;
        const glm::dvec3 p = eye - (eye.z / dir.z) * dir;
        if (std::abs(p.x) > 0.9 || std::abs(p.y) > 0.9) continue;  // away from the square's edges
        const glm::dvec3 view = glm::normalize(eye - p);
        const glm::dvec3 lit = ref.base * ambient + ref(n, view);
        shading::source::testing::PhongReference dull = ref;
        dull.boost = 0.0;
        const glm::dvec3 unlit_spec = ref.base * ambient + dull(n, view);
        for (int ch = 0; ch < 3; ++ch) {
          const double want = 255 * srgb_encode(lit[ch]);
          off += std::abs(image.pixel(x, y)[ch] - want) > 1.0;
          specular_steps = std::max(specular_steps, want - 255 * srgb_encode(unlit_spec[ch]));
        }
        ++checked;
      }
    EXPECT_EQ(off, 0) << shading::caps(model).name;
    EXPECT_GT(checked, 150) << shading::caps(model).name;
    EXPECT_GT(specular_steps, 10.0) << "the specular must show for the parameters to be tested";
  }
}

TEST(Renderer, PhongParametersReachTheSkinShader) {
  scenes::Scene s = lit_by_cube_and_sun(true);
  scenes::Material& m = s.materials[0];
  m.phong = true;
  m.phong_exponent = 8;
  m.phong_boost = 3;
  m.phong_tint = {1.0f, 0.7f, 0.4f};
  m.phong_fresnel_ranges = {0.2f, 0.6f, 0.9f};
  shading::source::testing::PhongReference ref;
  ref.base = {0.8, 0.6, 0.4};  // $color over a white texel
  ref.exponent_constant = 8;
  ref.boost = 3;
  ref.tint = {1.0, 0.7, 0.4};
  ref.fresnel_min = 0.2, ref.fresnel_mid = 0.6, ref.fresnel_max = 0.9;
  expect_skin_frame(s, ref);
}

// skin_dx9_helper.cpp: $phongexponentfactor scales the exponent texture's r (1 + factor r) over
// $phongexponent, and a $phongtint of zero with $phongalbedotint and an exponent texture tints by
// the albedo where the texture's g says (docs/fidelity.md#phong-defaults).
TEST(Renderer, PhongExponentFactorAndAlbedoTintReachTheSkinShader) {
  scenes::Scene s = lit_by_cube_and_sun(true);
  // The albedo tint reads the base texel (not $color): a coloured base texture, $color white.
  s.textures.push_back(solid_texture("base", scenes::ColorSpace::srgb, {204, 153, 102, 255}));
  s.materials[0].base.texture = static_cast<int>(s.textures.size()) - 1;
  s.materials[0].color = glm::vec4(1.0f);
  s.textures.push_back(solid_texture("exponent", scenes::ColorSpace::linear, {128, 153, 0, 255}));
  scenes::Material& m = s.materials[0];
  m.phong = true;
  m.phong_exponent = 40;  // overridden by the factor
  m.phong_exponent_factor = 16;
  m.phong_exponent_texture.texture = static_cast<int>(s.textures.size()) - 1;
  m.phong_boost = 3;
  m.phong_tint = glm::vec3(0.0f);
  m.phong_albedo_tint = true;
  shading::source::testing::PhongReference ref;
  ref.base = {srgb_decode(204.0 / 255.0), srgb_decode(153.0 / 255.0), srgb_decode(102.0 / 255.0)};
  ref.exponent_factor = 16;
  ref.exponent_texel = glm::dvec4(128.0 / 255.0, 153.0 / 255.0, 0.0, 1.0);
  ref.boost = 3;
  ref.tint = glm::dvec3(-1.0);  // the albedo tint
  expect_skin_frame(s, ref);
  // Without $phongalbedotint the zero tint is white, not black.
  s.materials[0].phong_albedo_tint = false;
  ref.tint = glm::dvec3(1.0);
  expect_skin_frame(s, ref);
}

// $basemapalphaphongmask: the skin shader takes the normal (0, 0, 1) and the mask from the base
// (skin_ps20b.fxc), so on ps_2_b and ps_3_0 a bumped material draws as if it had no normal map;
// ps_2_0, without the skin shader, keeps the normal map's detail.
TEST(Renderer, BaseMapAlphaPhongMaskDropsTheNormalMapFromPs2b) {
  scenes::Scene s = lit_by_cube_and_sun(true);
  s.materials[0].phong = true;
  s.materials[0].phong_exponent = 4;
  s.materials[0].phong_boost = 8;
  s.cameras[0].projection = scenes::Projection::perspective;
  s.cameras[0].position = {0.3f, -2.0f, 3.0f};
  s.cameras[0].vertical_fov = 1.0f;
  // A normal map of two tilts in a checker (z >= 0.8, alpha 1: see below).
  scenes::Texture bumps = solid_texture("tilted normals", scenes::ColorSpace::linear, {200, 90, 230, 255});
  for (int i = 0; i < 16; ++i)
    if ((i + i / 4) % 2) std::copy_n(std::array<uint8_t, 4>{60, 170, 220, 255}.begin(), 4, bumps.faces[0].rgba8.begin() + 4 * i);
  s.textures.push_back(bumps);
  const int bump_map = static_cast<int>(s.textures.size()) - 1;
  scenes::Scene flat = s;  // no normal map: the skin shader's FASTPATH_NOBUMP
  flat.materials[0].base_map_alpha_phong_mask = true;
  s.materials[0].bump.texture = bump_map;
  s.materials[0].base_map_alpha_phong_mask = true;
  // The full path's lerps land exactly on the fast path's values here: a normal-map z whose
  // 1 - z is exact, and the normal map's alpha equal to the base's.
  for (shading::ShaderModel model : {shading::ShaderModel::ps_2_b, shading::ShaderModel::ps_3_0})
    EXPECT_TRUE(render_as(s, model).rgba == render_as(flat, model).rgba)
        << shading::caps(model).name << ": the normal map's detail is still drawn";
  EXPECT_FALSE(render_as(s, shading::ShaderModel::ps_2_0).rgba == render_as(flat, shading::ShaderModel::ps_2_0).rgba)
      << "ps_2_0 draws the bumped path, with the normal map";
  scenes::Scene without_flag = s;
  without_flag.materials[0].base_map_alpha_phong_mask = false;
  EXPECT_FALSE(render_as(without_flag, shading::ShaderModel::ps_2_b).rgba == render_as(flat, shading::ShaderModel::ps_2_b).rgba)
      << "without the flag the normal map shows";
}

/// `s` with four point lights close around the square and its first material bumped (a flat
/// normal map): more lights than the default two local ones.
scenes::Scene four_lights_near(scenes::Scene s) {
  s.lights.clear();
  const glm::vec3 at[4] = {{0.9f, 0.2f, 0.5f}, {-0.8f, 0.3f, 0.6f}, {0.1f, 0.9f, 0.4f}, {-0.2f, -0.9f, 0.7f}};
  const glm::vec3 color[4] = {{0.3f, 0.2f, 0.1f}, {0.1f, 0.2f, 0.3f}, {0.2f, 0.1f, 0.05f}, {0.05f, 0.1f, 0.2f}};
  for (int i = 0; i < 4; ++i) {
    scenes::Light l;
    l.position = at[i];
    l.color = color[i];
    s.lights.push_back(l);
  }
  return s;
}

rasterizer::Image render_with_lights(const scenes::Scene& s, shading::ShaderModel model, int local_lights) {
  FrameSettings f{kRendererSize, kRendererSize, 4};
  f.model = model;
  f.local_lights = local_lights;
  return render_frame(s, f);
}

// FrameSettings::local_lights (--lights 4): the SDK 2013's bumped and skin shaders take up to four
// lights on ps_2_b and ps_3_0; two stay the default, ps_2_0 and the per-vertex path take two.
TEST(Renderer, FourLocalLightsOnBumpedModelsFromPs2b) {
  scenes::Scene bumped = four_lights_near(lit_by_cube_and_sun(false));
  add_flat_bump_map(bumped);
  FrameSettings counted{kRendererSize, kRendererSize, 4};
  counted.model = shading::ShaderModel::ps_2_b;
  counted.local_lights = 4;
  counted.count_shading = true;
  Renderer r(bumped, counted);
  rasterizer::Context ctx(2);
  r.render(ctx);
  ASSERT_FALSE(r.shader_uses().empty());
  EXPECT_EQ(r.shader_uses()[0].combo.rfind("4 lights", 0), 0u) << r.shader_uses()[0].combo;
  const rasterizer::Image& four = r.image();
  int moved = 0;
  const rasterizer::Image two = render_with_lights(bumped, shading::ShaderModel::ps_2_b, 2);
  for (size_t i = 0; i < four.rgba.size(); ++i) moved += std::abs(int(four.rgba[i]) - int(two.rgba[i])) > 2;
  EXPECT_GT(moved, 100) << "the two least significant lights, local instead of folded, light the square differently";
  EXPECT_TRUE(render_with_lights(bumped, shading::ShaderModel::ps_3_0, 4).rgba == four.rgba) << "ps_3_0 as ps_2_b";
  EXPECT_TRUE(render_with_lights(bumped, shading::ShaderModel::ps_2_0, 4).rgba ==
              render_with_lights(bumped, shading::ShaderModel::ps_2_0, 2).rgba)
      << "ps_2_0 takes two";
  const scenes::Scene plain = four_lights_near(lit_by_cube_and_sun(false));
  EXPECT_TRUE(render_with_lights(plain, shading::ShaderModel::ps_2_b, 4).rgba ==
              render_with_lights(plain, shading::ShaderModel::ps_2_b, 2).rgba)
      << "the non-bumped vertex shader takes two";
  EXPECT_THROW(render_with_lights(bumped, shading::ShaderModel::ps_2_b, 5), std::invalid_argument);
}

// The four-light path itself against double math: four directional lights on the flat bumped
// square (the normal map's 8-bit flat texel, as the shader reads it), Lambert, the cube's +Z side.
TEST(Renderer, FourDirectionalLightsSumOnTheBumpedPath) {
  scenes::Scene s = lit_by_cube_and_sun(false);
  add_flat_bump_map(s);
  s.lights.clear();
  const glm::dvec3 from[4] = {{0.6, 0.0, 0.8}, {-0.6, 0.0, 0.8}, {0.0, 0.6, 0.8}, {0.0, -0.48, 0.64}};
  const glm::dvec3 color[4] = {{0.3, 0.2, 0.1}, {0.1, 0.2, 0.3}, {0.2, 0.1, 0.05}, {0.05, 0.1, 0.2}};
  for (int i = 0; i < 4; ++i) {
    scenes::Light l;
    l.type = scenes::LightType::directional;
    l.direction = -glm::normalize(glm::vec3(from[i]));
    l.color = glm::vec3(color[i]);
    s.lights.push_back(l);
  }
  const double t = 2.0 * 128.0 / 255.0 - 1.0;
  const glm::dvec3 n = glm::normalize(glm::dvec3(t, t, 1.0));
  const double albedo[3] = {0.8, 0.6, 0.4}, cube[3] = {0.5, 0.25, 0.125};
  double expected[3];
  for (int c = 0; c < 3; ++c) {
    double lit = cube[c];
    for (int i = 0; i < 4; ++i) lit += color[i][c] * std::max(0.0, glm::dot(n, glm::normalize(from[i])));
    expected[c] = 255 * srgb_encode(albedo[c] * lit);
  }
  for (shading::ShaderModel model : {shading::ShaderModel::ps_2_b, shading::ShaderModel::ps_3_0})
    expect_everywhere(render_with_lights(s, model, 4), 0, kRendererSize, expected, shading::caps(model).name.data());
}

// A point light with constant, linear and quadratic terms and a spot light whose cone edge
// crosses the flat bumped square, against the SDK's formulas in double (docs/fidelity.md#model-lights):
// per light 1 / (a0 + a1 d + a2 d^2), the spot's sat(max(1e-4, (dot(axis, -L) - cos outer) /
// (cos inner - cos outer))^exponent), Lambert per pixel; the attenuation at the square's corners
// interpolated over its two triangles (the SDK's, the default) or at each pixel
// (--pixel-attenuation). The pixels on the triangles' shared diagonal, shaded from both, are
// left out of the per-vertex check.
TEST(Renderer, PointAndSpotLightsEndToEndOnTheBumpedPath) {
  scenes::Scene s = lit_by_cube_and_sun(false);
  add_flat_bump_map(s);
  scenes::Light point, spot;
  point.position = {0.3f, -0.2f, 0.9f};
  point.color = {1.2f, 0.9f, 0.6f};
  point.constant = 0.4f, point.linear = 0.3f, point.quadratic = 0.8f;
  spot.type = scenes::LightType::spot;
  spot.position = {-0.4f, 0.3f, 1.2f};
  spot.direction = glm::normalize(glm::vec3(0.2f, -0.1f, -1.0f));
  spot.color = {0.9f, 1.1f, 1.3f};
  spot.inner_cone = 0.25f, spot.outer_cone = 0.6f, spot.spot_exponent = 2.0f;
  s.lights = {point, spot};
  // Attenuation of light `l` at world point p, in double.
  auto attenuation = [](const scenes::Light& l, const glm::dvec3& p) {
    const glm::dvec3 v = glm::dvec3(l.position) - p;
    const double d = glm::length(v);
    double a = 1.0 / (double(l.constant) + double(l.linear) * d + double(l.quadratic) * d * d);
    if (l.type == scenes::LightType::spot) {
      const double cos_inner = std::cos(double(l.inner_cone)), cos_outer = std::cos(double(l.outer_cone));
      const double c = (glm::dot(glm::dvec3(l.direction), -v / d) - cos_outer) / (cos_inner - cos_outer);
      a *= std::clamp(std::pow(std::max(c, 1e-4), double(l.spot_exponent)), 0.0, 1.0);
    }
    return a;
  };
  const glm::dvec3 corner[4] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  // The attenuation at p interpolated from the corners over square()'s triangles (0, 1, 2), (0, 2, 3).
  auto interpolated = [&](const scenes::Light& l, const glm::dvec3& p) {
    const bool lower = p.x >= p.y;  // (0, 1, 2): below the diagonal from corner 0 to corner 2
    const glm::dvec3 a = corner[0], b = corner[lower ? 1 : 2], c = corner[lower ? 2 : 3];
    const double area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    const double wb = ((p.x - a.x) * (c.y - a.y) - (c.x - a.x) * (p.y - a.y)) / area;
    const double wc = ((b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y)) / area;
    return (1.0 - wb - wc) * attenuation(l, a) + wb * attenuation(l, b) + wc * attenuation(l, c);
  };
  const double t = 2.0 * 128.0 / 255.0 - 1.0;  // the flat normal map's 8-bit texel
  const glm::dvec3 n = glm::normalize(glm::dvec3(t, t, 1.0));
  const double albedo[3] = {0.8, 0.6, 0.4}, cube[3] = {0.5, 0.25, 0.125};
  double gap = 0.0;  // between the two modes' expectations
  for (bool per_pixel : {false, true})
    for (shading::ShaderModel model : {shading::ShaderModel::ps_2_b, shading::ShaderModel::ps_3_0}) {
      FrameSettings f{kRendererSize, kRendererSize, 4};
      f.model = model;
      f.pixel_attenuation = per_pixel;
      const rasterizer::Image image = render_frame(s, f);
      int off = 0, checked = 0;
      for (int y = 0; y < kRendererSize; ++y)
        for (int x = 0; x < kRendererSize; ++x) {
          const glm::dvec3 p(-1.0 + 2.0 * (x + 0.5) / kRendererSize, 1.0 - 2.0 * (y + 0.5) / kRendererSize, 0.0);
          if (!per_pixel && std::abs(p.x - p.y) < 3.0 / kRendererSize) continue;
          glm::dvec3 want_mode[2];
          for (int mode = 0; mode < 2; ++mode) {
            glm::dvec3 lit(cube[0], cube[1], cube[2]);
            for (const scenes::Light& l : s.lights) {
              const double a = mode == 1 ? attenuation(l, p) : interpolated(l, p);
              lit += glm::dvec3(l.color) * a * std::max(0.0, glm::dot(n, glm::normalize(glm::dvec3(l.position) - p)));
            }
            for (int c = 0; c < 3; ++c) want_mode[mode][c] = 255 * srgb_encode(albedo[c] * lit[c]);
          }
          const glm::dvec3& want = want_mode[per_pixel ? 1 : 0];
          for (int c = 0; c < 3; ++c) {
            off += std::abs(image.pixel(x, y)[c] - want[c]) > 1.0;
            gap = std::max(gap, std::abs(want_mode[0][c] - want_mode[1][c]));
          }
          ++checked;
        }
      EXPECT_EQ(off, 0) << shading::caps(model).name << (per_pixel ? ", per pixel" : ", per vertex");
      EXPECT_GT(checked, kRendererSize * kRendererSize * 3 / 4);
    }
  EXPECT_GT(gap, 5.0) << "per-vertex and per-pixel attenuation must differ on this square";
}

TEST(Renderer, LightmappedReadsTheFlatMapOrWeighsTheBasisMaps) {
  scenes::Scene s = top_down();
  const glm::vec3 basis[3] = {{0.3f, 0.1f, 0.2f}, {0.6f, 0.2f, 0.1f}, {0.9f, 0.3f, 0.05f}};
  attach_lightmaps(s, {0.2f, 0.4f, 0.6f}, basis);
  // A tilted normal: (160, 100, 230) -> n = 2 t - 1.
  s.textures.push_back(solid_texture("bump", scenes::ColorSpace::linear, {160, 100, 230, 255}));
  scenes::Material flat, bumped;
  flat.family = bumped.family = scenes::ShaderFamily::lightmapped_generic;
  flat.color = bumped.color = {0.5f, 1.0f, 0.8f, 1.0f};
  bumped.bump.texture = static_cast<int>(s.textures.size()) - 1;
  s.materials = {flat, bumped};
  s.meshes = {square(-1, -1, 0, 1, 0, 0), square(0, -1, 1, 1, 0, 1)};
  for (scenes::Mesh& m : s.meshes) {
    m.uv1 = m.uv0;
    m.tangents.assign(4, {1, 0, 0, 1});
  }
  // The SDK's weights, in double: d_i = sat(n . b_i)^2, diffuse = sum d_i L_i / sum d_i.
  const double n[3] = {2 * 160 / 255.0 - 1, 2 * 100 / 255.0 - 1, 2 * 230 / 255.0 - 1};
  const double b[3][3] = {{std::sqrt(2.0 / 3), 0, 1 / std::sqrt(3.0)},
                          {-1 / std::sqrt(6.0), 1 / std::sqrt(2.0), 1 / std::sqrt(3.0)},
                          {-1 / std::sqrt(6.0), -1 / std::sqrt(2.0), 1 / std::sqrt(3.0)}};
  double d[3], sum = 0;
  for (int i = 0; i < 3; ++i) {
    const double dot = std::clamp(n[0] * b[i][0] + n[1] * b[i][1] + n[2] * b[i][2], 0.0, 1.0);
    d[i] = dot * dot;
    sum += d[i];
  }
  const double tint[3] = {0.5, 1.0, 0.8}, flat_light[3] = {0.2, 0.4, 0.6};
  double expected_flat[3], expected_bump[3];
  for (int c = 0; c < 3; ++c) {
    expected_flat[c] = 255 * srgb_encode(tint[c] * flat_light[c]);
    double weighted = 0;
    for (int i = 0; i < 3; ++i) weighted += d[i] * basis[i][c];
    expected_bump[c] = 255 * srgb_encode(tint[c] * weighted / sum);
  }
  const rasterizer::Image image30 = render_as(s, shading::ShaderModel::ps_3_0);
  expect_everywhere(image30, 0, kRendererSize / 2, expected_flat, "flat lightmap");
  expect_everywhere(image30, kRendererSize / 2, kRendererSize, expected_bump, "RNM");
  s.lightmaps.reset();
  EXPECT_THROW(Renderer(s, {kRendererSize, kRendererSize, 4}), std::invalid_argument) << "no lightmaps: refused, not drawn black";
}

TEST(Renderer, CountsThePixelsEachComboShades) {
  scenes::Scene s = lit_by_cube_and_sun(true);
  FrameSettings f{kRendererSize, kRendererSize, 4};
  f.count_shading = true;
  f.exposure = 1.0f;  // no histogram pass: the 3D draw alone (post_pass_shaders_test.cpp has the others)
  Renderer r(s, f);
  rasterizer::Context ctx(2);
  r.render(ctx);
  ASSERT_EQ(r.shader_uses().size(), 1u);
  EXPECT_EQ(r.shader_uses()[0].family, "VertexLitGeneric");
  EXPECT_EQ(r.shader_uses()[0].combo, "vertexlit") << "no bump map: lit per vertex, the pixel shader multiplies";
  // Every pixel once, and the pixels on the diagonal between the square's two triangles (samples
  // in both) once per triangle: at most one more per row.
  EXPECT_GE(r.shader_uses()[0].pixels, uint64_t(kRendererSize) * kRendererSize);
  EXPECT_LE(r.shader_uses()[0].pixels, uint64_t(kRendererSize) * kRendererSize + kRendererSize);
  EXPECT_GT(r.shader_uses()[0].slots, 3);
}

TEST(Renderer, TimesThePassesTheSceneHas) {
  scenes::Scene s = lit_by_cube_and_sun(true);
  FrameSettings f{kRendererSize, kRendererSize, 4};
  rasterizer::Context ctx(2);
  Renderer untimed(s, f);
  untimed.render(ctx);
  EXPECT_TRUE(untimed.pass_times().empty());
  f.time_passes = true;
  Renderer timed(s, f);
  timed.render(ctx);
  // One opaque mesh, no sky, nothing translucent, an exposure range (auto exposure): four
  // passes (the histogram reads the frame's copy), the image the same bytes.
  ASSERT_EQ(timed.pass_times().size(), 4u);
  EXPECT_EQ(timed.pass_times()[0].pass, "opaque");
  EXPECT_EQ(timed.pass_times()[0].draws, 1);
  EXPECT_EQ(timed.pass_times()[1].pass, "resolve");
  EXPECT_EQ(timed.pass_times()[2].pass, "frame copy");
  EXPECT_EQ(timed.pass_times()[2].draws, 0);
  EXPECT_EQ(timed.pass_times()[3].pass, "histogram");
  for (const PassTime& p : timed.pass_times()) EXPECT_GE(p.ms, 0.0);
  EXPECT_TRUE(timed.image().rgba == untimed.image().rgba);
  // The clock moved: the views' draws are made anew first, a pass of their own (the first frame
  // took no time, so the exposure has not moved: the same bytes).
  timed.set_time(0.5f);
  timed.render(ctx);
  ASSERT_EQ(timed.pass_times().size(), 5u);
  EXPECT_EQ(timed.pass_times()[0].pass, "views");
  EXPECT_EQ(timed.pass_times()[1].pass, "opaque");
  EXPECT_TRUE(timed.image().rgba == untimed.image().rgba);
  // A fixed exposure, given or a range of one value: no histogram pass.
  for (int fixed = 0; fixed < 2; ++fixed) {
    FrameSettings g = f;
    scenes::Scene t = s;
    if (fixed == 0) g.exposure = 1.0f;
    else t.exposure.min_scale = t.exposure.max_scale = 1.0f;
    Renderer r(t, g);
    r.render(ctx);
    ASSERT_EQ(r.pass_times().size(), 2u);
    EXPECT_EQ(r.pass_times()[1].pass, "resolve");
    EXPECT_EQ(r.auto_exposure(), nullptr);
    EXPECT_TRUE(r.image().rgba == untimed.image().rgba);
  }
}

TEST(Renderer, LinearWriteAndTheBackground) {
  scenes::Scene s = top_down();
  s.background = {0.2f, 0.05f, 0.6f};
  scenes::Material m;
  m.family = scenes::ShaderFamily::unlit_generic;
  m.linear_write = true;
  m.color = {0.5f, 1.0f, 1.0f, 1.0f};
  s.materials = {m};
  s.meshes = {square(-1, -1, 0, 1, 0, 0)};  // the left half
  s.meshes[0].colors.assign(4, {0.6f, 0.3f, 0.1f, 1.0f});
  const rasterizer::Image image = render(s);
  expect_everywhere(image, 0, kRendererSize / 2, {255 * 0.3, 255 * 0.3, 255 * 0.1}, "written as it is");
  expect_everywhere(image, kRendererSize / 2, kRendererSize, {255 * srgb_encode(0.2), 255 * srgb_encode(0.05), 255 * srgb_encode(0.6)},
                    "the background, encoded");
}

TEST(Renderer, SingleSidedMaterialsCullTheirBackFaces) {
  scenes::Scene s = top_down();
  s.background = {0, 0, 0};
  scenes::Material one_sided;
  one_sided.family = scenes::ShaderFamily::unlit_generic;
  scenes::Material two_sided = one_sided;
  two_sided.double_sided = true;
  s.materials = {one_sided, two_sided};
  s.meshes = {square(-1, -1, 0, 1, 0, 0, true), square(0, -1, 1, 1, 0, 1, true)};  // both seen from behind
  const rasterizer::Image image = render(s);
  expect_everywhere(image, 0, kRendererSize / 2, {0, 0, 0}, "culled");
  expect_everywhere(image, kRendererSize / 2, kRendererSize, {255, 255, 255}, "double-sided");
}

TEST(Renderer, TheNearerSurfaceWinsWhateverTheOrder) {
  scenes::Scene s = top_down();
  scenes::Material red, blue;
  red.family = blue.family = scenes::ShaderFamily::unlit_generic;
  red.color = {1, 0, 0, 1};
  blue.color = {0, 0, 1, 1};
  s.materials = {red, blue};
  s.meshes = {square(-1, -1, 1, 1, 5, 0), square(-1, -1, 1, 1, 2, 1)};  // red nearer, drawn first
  expect_everywhere(render(s), 0, kRendererSize, {255, 0, 0}, "nearer first");
  std::swap(s.meshes[0], s.meshes[1]);
  expect_everywhere(render(s), 0, kRendererSize, {255, 0, 0}, "nearer last");
}

}  // namespace
}  // namespace luxel::frame
