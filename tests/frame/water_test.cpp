// The water (renderer.hpp, frame/src/water_passes.hpp) on a small scene whose pixels are computed
// here: a water plane at z = 0 over a floor, seen from above; what it reflects and refracts, the
// Fresnel blend and the reflection's exposure round trip (docs/fidelity.md#water), the water's
// depth from the refraction view's alpha, determinism, and what a scene without water draws.
//
// Every material is unlit (no bake needed). The normal map is flat with alpha 0, so the
// normal-map offsets vanish and each target is read at the pixel's own place.

#include "frame/frame_support.hpp"

#include "luxel/frame/renderer.hpp"
#include "luxel/scenes/builtin.hpp"

#include <gtest/gtest.h>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_double4x4.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/ext/vector_double3.hpp>
#include <glm/ext/vector_double4.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace luxel::frame {
namespace {

constexpr int kWaterWidth = 96, kWaterHeight = 64;
constexpr glm::dvec3 kEye{0, -100, 50}, kTarget{0, 20, 0};
constexpr double kNear = 1, kFar = 20000, kFov = 1.0;
constexpr double kFloorZ = -40;
/// CBaseWorldView::PushView's spread (water_passes.hpp): the refraction view's fog plane is 2
/// inches above the water.
constexpr double kSpread = 2;

// ---- Reference math ---------------------------------------------------------------------------

/// A [0, 1] value through an 8-bit UNORM channel and back (alpha).
double through_unorm8(double x) { return std::floor(std::clamp(x, 0.0, 1.0) * 255 + 0.5) / 255; }
/// $fogcolor and $reflecttint are gamma-space: mathlib's (i / 255)^2.2 for i = round(255 x).
double gamma_to_linear(int i) { return std::pow(i / 255.0, 2.2); }
double lerp(double a, double b, double t) { return a + (b - a) * t; }

glm::dmat4 camera_view() { return glm::lookAtRH(kEye, kTarget, glm::dvec3(0, 0, 1)); }
glm::dmat4 camera_projection() { return glm::perspectiveRH_ZO(kFov, double(kWaterWidth) / kWaterHeight, kNear, kFar); }

struct Pixel {
  int x, y;
};

/// The pixel whose area a world point projects into.
Pixel pixel_of(const glm::dvec3& p) {
  const glm::dvec4 c = camera_projection() * camera_view() * glm::dvec4(p, 1.0);
  return {static_cast<int>(std::floor((c.x / c.w + 1) * 0.5 * kWaterWidth)),
          static_cast<int>(std::floor((1 - c.y / c.w) * 0.5 * kWaterHeight))};
}

/// Where the ray through a pixel's center meets the plane z = `z`.
glm::dvec3 hit_at_height(const Pixel& px, double z) {
  const glm::dmat4 inverse = glm::inverse(camera_projection() * camera_view());
  const double nx = (px.x + 0.5) / kWaterWidth * 2 - 1, ny = 1 - (px.y + 0.5) / kWaterHeight * 2;
  const glm::dvec4 far = inverse * glm::dvec4(nx, ny, 1, 1);
  const glm::dvec3 dir = glm::normalize(glm::dvec3(far) / far.w - kEye);
  return kEye + dir * ((z - kEye.z) / dir.z);
}

/// Direct3D's projected z of a point: its distance along the view axis, scaled to [0, far].
double proj_z(const glm::dvec3& p) { return (camera_projection() * camera_view() * glm::dvec4(p, 1.0)).z; }

/// The refraction view's alpha at a floor point (fog.hpp's height fog): the part of the
/// eye-to-point segment under the fog plane, times the projected depth over the fog range.
double water_depth(const glm::dvec3& p, double fog_range) {
  const double under = std::clamp((kSpread - p.z) / (kEye.z - p.z), 0.0, 1.0);
  return std::clamp(under * proj_z(p) / fog_range, 0.0, 1.0);
}

// ---- The scene --------------------------------------------------------------------------------

/// The square spanned by `a` + s `u` + t `v` (s, t in [0, 1]), facing u x v.
scenes::Mesh quad(const glm::vec3& a, const glm::vec3& u, const glm::vec3& v, int material, const char* name) {
  scenes::Mesh m;
  m.name = name;
  m.material = material;
  m.positions = {a, a + u, a + u + v, a + v};
  const glm::vec3 n = glm::normalize(glm::cross(u, v));
  m.normals.assign(4, n);
  m.tangents.assign(4, glm::vec4(glm::normalize(u), 1.0f));
  m.uv0 = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.indices = std::vector<uint16_t>{0, 1, 2, 0, 2, 3};
  return m;
}

int add_unlit(scenes::Scene& s, const char* name, const glm::vec3& linear) {
  scenes::Material m;
  m.name = name;
  m.family = scenes::ShaderFamily::unlit_generic;
  m.color = glm::vec4(linear, 1.0f);
  s.materials.push_back(m);
  return static_cast<int>(s.materials.size()) - 1;
}

struct WaterLook {
  glm::ivec3 reflect_tint{255, 255, 255};  ///< gamma, /255
  float refract_amount = 0.5f;             ///< 0: the reflect-only combo
  glm::ivec3 fog_color{51, 102, 153};      ///< gamma, /255
  float fog_end = 64.0f;
};

/// Water at z = 0 over x in [-200, 200], y in [-90, 300]; a floor at kFloorZ below all of it.
scenes::Scene water_scene(const WaterLook& look, const glm::vec3& floor_left, const glm::vec3& floor_right) {
  scenes::Scene s;
  s.name = "water-test";
  scenes::Camera c;
  c.position = glm::vec3(kEye);
  c.target = glm::vec3(kTarget);
  c.vertical_fov = float(kFov);
  c.near_plane = float(kNear);
  c.far_plane = float(kFar);
  s.cameras.push_back(c);
  s.background = glm::vec3(0.0f);

  scenes::Texture normal;
  normal.name = "flat";
  normal.color_space = scenes::ColorSpace::linear;
  normal.mipmaps = false;
  scenes::PixelImage image;
  image.width = image.height = 2;
  image.rgba8 = {128, 128, 255, 0, 128, 128, 255, 0, 128, 128, 255, 0, 128, 128, 255, 0};
  normal.faces = {image};
  s.textures.push_back(normal);

  scenes::Material water;
  water.name = "water";
  water.family = scenes::ShaderFamily::water;
  water.water_normal.texture = 0;
  water.reflect_tint = glm::vec3(look.reflect_tint) / 255.0f;
  water.refract_amount = look.refract_amount;
  water.water_fog_color = glm::vec3(look.fog_color) / 255.0f;
  water.water_fog_start = 0.0f;
  water.water_fog_end = look.fog_end;
  s.materials.push_back(water);

  s.meshes.push_back(quad({-200, -90, 0}, {400, 0, 0}, {0, 390, 0}, 0, "water"));
  const int left = add_unlit(s, "floor-left", floor_left);
  const int right = add_unlit(s, "floor-right", floor_right);
  s.meshes.push_back(quad({-400, -200, float(kFloorZ)}, {400, 0, 0}, {0, 800, 0}, left, "floor-left"));
  s.meshes.push_back(quad({0, -200, float(kFloorZ)}, {400, 0, 0}, {0, 800, 0}, right, "floor-right"));
  return s;
}

/// A ceiling at z = 300 over everything the water reflects, facing down (single-sided: the
/// mirrored view must turn its winding).
void add_ceiling(scenes::Scene& s, const glm::vec3& linear) {
  const int m = add_unlit(s, "ceiling", linear);
  s.meshes.push_back(quad({-8000, -8000, 300}, {0, 16000, 0}, {16000, 0, 0}, m, "ceiling"));
}

/// A square standing at y = 150, x in [20, 40], z in [10, 30], facing the camera (-Y).
void add_post(scenes::Scene& s, const glm::vec3& linear) {
  const int m = add_unlit(s, "post", linear);
  s.meshes.push_back(quad({20, 150, 10}, {20, 0, 0}, {0, 0, 20}, m, "post"));
}

/// Reflect-only water (refract amount 0) over dark floors, and the post in `post`'s color.
scenes::Scene reflecting_a_post(const glm::vec3& post) {
  WaterLook look;
  look.refract_amount = 0.0f;
  scenes::Scene s = water_scene(look, {0.1f, 0.1f, 0.1f}, {0.1f, 0.1f, 0.1f});
  add_post(s, post);
  return s;
}

FrameSettings settings(float exposure = 1.0f) {
  FrameSettings f;
  f.width = kWaterWidth;
  f.height = kWaterHeight;
  f.samples = 4;
  f.exposure = exposure;
  return f;
}

void expect_pixel(const rasterizer::Image& image, const Pixel& p, const double (&linear)[3], int tolerance,
                  const std::string& what) {
  ASSERT_TRUE(p.x >= 0 && p.x < kWaterWidth && p.y >= 0 && p.y < kWaterHeight) << what << ": off screen";
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(image.pixel(p.x, p.y)[c], srgb8(linear[c]), tolerance)
        << what << ", channel " << c << " at (" << p.x << ", " << p.y << ")";
}

// ---- Tests ------------------------------------------------------------------------------------

TEST(Water, ReflectsWhatIsAboveItAtTheMirroredPlace) {
  // Reflect-only water (refract amount 0): the water shows the reflection x tint x 4, the
  // reflection view holding 0.25 x the radiance. The post's mirror image is at z -> -z.
  const glm::vec3 post(0.8f, 0.3f, 0.1f);
  const scenes::Scene s = reflecting_a_post(post);
  const rasterizer::Image image = render_frame(s, settings());
  double reflected[3];
  for (int c = 0; c < 3; ++c) reflected[c] = 4.0 * through_srgb8(0.25 * post[c]);
  // Inside the mirror image, away from its edges (the post's center and two points off it).
  for (const glm::dvec3& p : {glm::dvec3(30, 150, -20), glm::dvec3(24, 150, -13), glm::dvec3(37, 150, -27)})
    expect_pixel(image, pixel_of(p), reflected, 1, "the post's reflection");
  // Where the mirror is not: across x = 0, and above and below the mirror image. The water
  // reflects the black background there.
  const double black[3] = {0, 0, 0};
  for (const glm::dvec3& p : {glm::dvec3(-30, 150, -20), glm::dvec3(30, 150, -40), glm::dvec3(30, 150, -3)})
    expect_pixel(image, pixel_of(p), black, 0, "no reflection");
  // The post itself, seen directly, at the frame's exposure.
  const double direct[3] = {post.r, post.g, post.b};
  expect_pixel(image, pixel_of({30, 150, 20}), direct, 1, "the post");
}

TEST(Water, ReflectionExposureRoundTripsThroughAQuarter) {
  // docs/fidelity.md#water: the reflection renders at 0.25 s into 8 bits and the water multiplies by
  // GammaToLinear(tint) x 4. At s = 0.25 a radiance of 3.2 is stored as 0.2 and comes back as
  // 0.8: above 1 before the exposure, inside the target's range after it.
  WaterLook look;
  look.refract_amount = 0.0f;
  look.reflect_tint = {204, 230, 255};
  scenes::Scene s = water_scene(look, {0, 0, 0}, {0, 0, 0});
  const glm::vec3 sky(3.2f, 2.4f, 1.6f);
  add_ceiling(s, sky);
  const float exposure = 0.25f;
  const rasterizer::Image image = render_frame(s, settings(exposure));
  double expected[3];
  for (int c = 0; c < 3; ++c)
    expected[c] = through_srgb8(0.25 * exposure * sky[c]) * gamma_to_linear(look.reflect_tint[c]) * 4;
  for (const glm::dvec3& at : {glm::dvec3(-40, 60, 0), glm::dvec3(25, 10, 0), glm::dvec3(60, 120, 0)})
    expect_pixel(image, pixel_of(at), expected, 1, "the ceiling's reflection");
}

TEST(Water, FresnelBlendsRefractionAndReflectionByTheViewAngle) {
  // docs/fidelity.md#water: F = (1 - sat(V·N))^5 x sat((depth - 0.05) x 20); result =
  // lerp(refraction, reflection, F), refraction lerped toward the fog color by sat(depth - 0.05).
  // The floor has the water's fog color, so the refraction is that color however deep; the
  // ceiling is what the water reflects. The water is deep here (depth > 0.1): F is the angle's
  // alone.
  WaterLook look;
  const glm::vec3 fog(float(gamma_to_linear(look.fog_color.r)), float(gamma_to_linear(look.fog_color.g)),
                      float(gamma_to_linear(look.fog_color.b)));
  scenes::Scene s = water_scene(look, fog, fog);
  const glm::vec3 ceiling(0.9f, 0.7f, 0.5f);
  add_ceiling(s, ceiling);
  const rasterizer::Image image = render_frame(s, settings());
  const double n[3] = {2 * 128 / 255.0 - 1, 2 * 128 / 255.0 - 1, 1.0};  // the flat normal map's texel
  int checked = 0;
  for (const glm::dvec3& at : {glm::dvec3(15, 10, 0), glm::dvec3(-50, 80, 0), glm::dvec3(40, -20, 0)}) {
    const Pixel px = pixel_of(at);
    const glm::dvec3 p = hit_at_height(px, 0.0);
    const glm::dvec3 floor_point = hit_at_height(px, kFloorZ);
    const double depth = through_unorm8(water_depth(floor_point, look.fog_end));
    ASSERT_GE(depth, 0.1) << "deep water expected at " << px.x << ", " << px.y;
    const glm::dvec3 v = glm::normalize(kEye - p);  // tangent space = world: t = +X, b = +Y, n = +Z
    const double v_dot_n = std::clamp(v.x * n[0] + v.y * n[1] + v.z * n[2], 0.0, 1.0);
    const double fresnel = std::pow(1 - v_dot_n, 5) * std::clamp((depth - 0.05) * 20, 0.0, 1.0);
    ASSERT_GT(fresnel, 0.02);
    ASSERT_LT(fresnel, 0.5);
    double expected[3];
    for (int c = 0; c < 3; ++c) {
      const double refraction = through_srgb8(fog[c]);
      const double reflection = through_srgb8(0.25 * ceiling[c]) * 4;
      const double fogged = lerp(refraction, fog[c], std::clamp(depth - 0.05, 0.0, 1.0));
      expected[c] = lerp(fogged, reflection, fresnel);
    }
    expect_pixel(image, px, expected, 1, "Fresnel blend");
    ++checked;
  }
  EXPECT_EQ(checked, 3);
}

TEST(Water, RefractionShowsTheFloorFadedByTheWatersDepth) {
  // Refract-only water (a black reflect tint): the floor seen through the water, lit by the
  // refraction view's height fog (alpha = its factor, the water's depth), then faded toward the
  // fog color by sat(depth - 0.05) in the water shader. A long fog range keeps the floor visible:
  // green left of x = 0, blue right of it.
  WaterLook look;
  look.reflect_tint = {0, 0, 0};
  look.fog_color = {128, 128, 128};
  look.fog_end = 400.0f;
  const glm::vec3 green(0.1f, 0.6f, 0.1f), blue(0.1f, 0.1f, 0.6f);
  scenes::Scene s = water_scene(look, green, blue);
  const rasterizer::Image image = render_frame(s, settings());
  const double fog = gamma_to_linear(128);
  for (const glm::dvec3& at : {glm::dvec3(-30, 40, kFloorZ), glm::dvec3(45, 90, kFloorZ), glm::dvec3(-70, 160, kFloorZ)}) {
    const Pixel px = pixel_of(at);
    const glm::dvec3 floor_point = hit_at_height(px, kFloorZ);
    const glm::vec3& color = floor_point.x < 0 ? green : blue;
    const double depth = water_depth(floor_point, look.fog_end);
    ASSERT_GT(depth, 0.1);
    ASSERT_LT(depth, 0.6);
    const double stored_depth = through_unorm8(depth);
    double expected[3];
    for (int c = 0; c < 3; ++c) {
      const double refraction = through_srgb8(lerp(color[c], fog, depth));
      expected[c] = lerp(refraction, fog, std::clamp(stored_depth - 0.05, 0.0, 1.0));
    }
    expect_pixel(image, px, expected, 1, floor_point.x < 0 ? "the green floor" : "the blue floor");
  }
}

TEST(Water, SameBytesOnOneAndTwoThreads) {
  WaterLook look;
  scenes::Scene s = water_scene(look, {0.1f, 0.6f, 0.1f}, {0.1f, 0.1f, 0.6f});
  add_ceiling(s, {0.9f, 0.7f, 0.5f});
  add_post(s, {0.8f, 0.3f, 0.1f});
  const rasterizer::Image one = render_frame(s, settings(), 1), two = render_frame(s, settings(), 2);
  EXPECT_EQ(one.rgba, two.rgba);
}

TEST(Water, TheViewsLimitChangesNoPixel) {
  // The views draw only what the water can read (its footprint on screen widened by the largest
  // normal-map offset, inside its rectangle): drawing the whole views must give the same bytes,
  // on the test scene (a flat normal map) and on the courtyard (a bumpy one).
  WaterLook look;
  scenes::Scene s = water_scene(look, {0.1f, 0.6f, 0.1f}, {0.1f, 0.1f, 0.6f});
  add_ceiling(s, {0.9f, 0.7f, 0.5f});
  add_post(s, {0.8f, 0.3f, 0.1f});
  FrameSettings whole = settings();
  whole.limit_water_views = false;
  EXPECT_EQ(render_frame(s, settings(), 2).rgba, render_frame(s, whole, 2).rgba);
  scenes::Scene courtyard = scenes::make_builtin_scene("courtyard", {160, 90});
  attach_test_bake(courtyard);
  for (int camera : {0, 2}) {  // the overview, the fountain
    FrameSettings limited{160, 90, 4, camera};
    FrameSettings whole_views = limited;
    whole_views.limit_water_views = false;
    Renderer a(courtyard, limited), b(courtyard, whole_views);
    rasterizer::Context ctx(2);
    a.render(ctx);
    b.render(ctx);
    EXPECT_EQ(a.image().rgba, b.image().rgba) << "camera " << camera;
  }
}

/// A strip of water from one corner of the screen to the other, over the floors and under the
/// ceiling, its normal map bumpy and its fog thick (offsets of the full amounts where the depth
/// reaches 1: 0.05 of the screen in the reflection, a dozen pixels, 0.03 in the refraction): its
/// rectangle on screen holds nearly the whole screen, its footprint is a diagonal band.
scenes::Scene diagonal_water() {
  WaterLook look;
  look.refract_amount = 0.03f;
  look.fog_end = 4.0f;
  scenes::Scene s = water_scene(look, {0.1f, 0.6f, 0.1f}, {0.1f, 0.1f, 0.6f});
  add_ceiling(s, {0.9f, 0.7f, 0.5f});
  add_post(s, {0.8f, 0.3f, 0.1f});
  scenes::Material& water = s.materials[0];
  water.reflect_amount = 0.05f;
  scenes::PixelImage& normal = s.textures[static_cast<size_t>(water.water_normal.texture)].faces.at(0);
  normal.width = normal.height = 4;
  normal.rgba8.clear();
  for (int i = 0; i < 16; ++i) {
    const uint8_t x = (i * 5) % 3 == 0 ? 0 : 255, y = (i * 7) % 4 < 2 ? 0 : 255;
    normal.rgba8.insert(normal.rgba8.end(), {x, y, 128, 255});
  }
  // The water drawn last, so that the frame's own draws shade the same pixels without it.
  scenes::Mesh strip = quad({-200, -90, 0}, {400, 390, 0}, {-12, 12, 0}, 0, "water");
  s.meshes.erase(s.meshes.begin());
  s.meshes.push_back(std::move(strip));
  return s;
}

/// The pixels the frame's Source shaders shaded, the water's own left out.
uint64_t pixels_shaded_around_water(const scenes::Scene& s, const FrameSettings& f) {
  Renderer r(s, f);
  rasterizer::Context ctx(2);
  r.render(ctx);
  uint64_t pixels = 0;
  for (const ShaderUse& u : r.shader_uses())
    if (u.family != "Water") pixels += u.pixels;
  return pixels;
}

TEST(Water, TheViewsDrawOnlyTheWatersFootprint) {
  // The views draw only where the water's footprint on screen, widened by its normal map's
  // reach, can read them: the same bytes as drawing the whole views, for a fraction of their
  // pixels, where the water's rectangle on screen would have kept nearly all of them.
  const scenes::Scene s = diagonal_water();
  FrameSettings limited{240, 160, 4};
  limited.exposure = 1.0f;
  limited.count_shading = true;
  FrameSettings whole = limited;
  whole.limit_water_views = false;
  EXPECT_EQ(render_frame(s, limited).rgba, render_frame(s, whole).rgba);

  scenes::Scene dry = s;
  dry.meshes.pop_back();
  const uint64_t frame_pixels = pixels_shaded_around_water(dry, limited);
  const uint64_t views_limited = pixels_shaded_around_water(s, limited) - frame_pixels;
  const uint64_t views_whole = pixels_shaded_around_water(s, whole) - frame_pixels;
  EXPECT_GT(views_limited, 0u);
  EXPECT_LT(views_limited * 3, views_whole) << views_limited << " of " << views_whole << " pixels";
}

TEST(Water, BlurredRefractionWhereTheModelHasIt) {
  // $blurrefract: ps_2_b and ps_3_0 draw the BLURRY combo (25 taps of the refraction, with the
  // SDK's overbright), ps_2_0 has none and draws the sharp one; the refraction view's limit
  // reaches as far as the taps.
  WaterLook look;
  scenes::Scene sharp = water_scene(look, {0.1f, 0.6f, 0.1f}, {0.1f, 0.1f, 0.6f});
  add_ceiling(sharp, {0.9f, 0.7f, 0.5f});
  add_post(sharp, {0.8f, 0.3f, 0.1f});
  scenes::Scene blurred = sharp;
  int water = 0;
  for (scenes::Material& m : blurred.materials)
    if (m.family == scenes::ShaderFamily::water) m.water_blur_refract = true, ++water;
  ASSERT_EQ(water, 1);
  auto as = [](shading::ShaderModel model) {
    FrameSettings f = settings();
    f.model = model;
    return f;
  };
  EXPECT_EQ(render_frame(sharp, as(shading::ShaderModel::ps_2_0)).rgba, render_frame(blurred, as(shading::ShaderModel::ps_2_0)).rgba);
  const rasterizer::Image b2b = render_frame(blurred, as(shading::ShaderModel::ps_2_b));
  EXPECT_NE(render_frame(sharp, as(shading::ShaderModel::ps_2_b)).rgba, b2b.rgba);
  EXPECT_EQ(b2b.rgba, render_frame(blurred, as(shading::ShaderModel::ps_3_0)).rgba);
  FrameSettings whole = as(shading::ShaderModel::ps_3_0);
  whole.limit_water_views = false;
  EXPECT_EQ(b2b.rgba, render_frame(blurred, whole).rgba);
  std::vector<ShaderUse> uses;
  Renderer r(blurred, [&] { FrameSettings f = as(shading::ShaderModel::ps_3_0); f.count_shading = true; return f; }());
  rasterizer::Context ctx(2);
  r.render(ctx);
  bool blurry = false;
  for (const ShaderUse& u : r.shader_uses()) blurry = blurry || (u.family == "Water" && u.combo.find("+blurry") != std::string::npos);
  EXPECT_TRUE(blurry);
}

uint64_t triangles(const scenes::Scene& s, const FrameSettings& f, std::vector<ShaderUse>* uses = nullptr) {
  Renderer r(s, f);
  rasterizer::Context ctx(2);
  r.render(ctx);
  if (uses) *uses = r.shader_uses();
  return r.stats().triangles;
}

TEST(Water, ViewsAreDrawnOnlyForVisibleWater) {
  WaterLook look;
  scenes::Scene s = water_scene(look, {0.1f, 0.6f, 0.1f}, {0.1f, 0.1f, 0.6f});
  add_ceiling(s, {0.9f, 0.7f, 0.5f});
  add_post(s, {0.8f, 0.3f, 0.1f});
  FrameSettings f = settings();
  f.count_shading = true;
  f.limit_water_views = false;  // the views' footprints' own triangles left out
  std::vector<ShaderUse> uses;
  // Two triangles a mesh. The camera's view: water, two floors, ceiling, post. The reflection:
  // what lies above z = -2 but the water (ceiling, post). The refraction: what lies below z = 2
  // (the floors).
  EXPECT_EQ(triangles(s, f, &uses), 2u * (5 + 2 + 2));
  auto water = std::find_if(uses.begin(), uses.end(), [](const ShaderUse& u) { return u.family == "Water"; });
  ASSERT_NE(water, uses.end());
  EXPECT_EQ(water->combo, "reflect+refract+above");
  EXPECT_GT(water->pixels, 0u);
  EXPECT_GT(water->slots, 10);
  EXPECT_TRUE(std::any_of(uses.begin(), uses.end(), [](const ShaderUse& u) {
    return u.combo.size() > 10 && u.combo.substr(u.combo.size() - 10) == "+heightfog" && u.pixels > 0;
  })) << "the refraction view's draws are counted";

  // Without the water mesh: the camera's view alone, nothing counted for water.
  scenes::Scene dry = s;
  dry.meshes.erase(dry.meshes.begin());
  EXPECT_EQ(triangles(dry, f, &uses), 2u * 4);
  EXPECT_TRUE(std::none_of(uses.begin(), uses.end(), [](const ShaderUse& u) { return u.family == "Water"; }));

  // Water out of view (the camera turned away) costs nothing either.
  scenes::Scene away = s;
  away.cameras[0].target = glm::vec3(kEye) + glm::vec3(0, -1, 0.5f);
  const uint64_t without_views = triangles(away, f, &uses);
  EXPECT_EQ(without_views, 2u * 4) << "the water mesh is not drawn either";
  EXPECT_TRUE(std::none_of(uses.begin(), uses.end(), [](const ShaderUse& u) { return u.family == "Water"; }));
}

TEST(Water, ViewsAreSquareTargetsOfTheirOwnSize) {
  // The views are drawn into water_texture_size x water_texture_size one-sample targets (the
  // SDK's 1024 x 1024 render targets), the screen stretched onto them, and read bilinear: across
  // a row through the post's reflection, the pixels between the black around it and its color
  // are the blend of its edges' texels. At 1024 texels a side (over 10 per pixel) an edge is at
  // most one such pixel (the reflection is 4 pixels wide); at 16 (6 pixels a texel across) the
  // reflection is less than a texel and spreads over a ramp of a dozen pixels.
  const glm::vec3 post(0.8f, 0.3f, 0.1f);
  const scenes::Scene s = reflecting_a_post(post);
  const int full = srgb8(4.0 * through_srgb8(0.25 * post.r));
  auto ramp_pixels = [&](int side) {
    FrameSettings f = settings();
    f.water_texture_size = side;
    const rasterizer::Image image = render_frame(s, f);
    const int y = pixel_of({30, 150, -20}).y;
    int between = 0, at_full = 0;
    for (int x = 0; x < kWaterWidth; ++x) {
      const int r = image.pixel(x, y)[0];
      if (r > 2 && r < full - 2) ++between;
      if (std::abs(r - full) <= 2) ++at_full;
    }
    if (side >= 64) {
      EXPECT_GT(at_full, 0) << "the reflection's color is reached at " << side << " texels a side";
    }
    return between;
  };
  EXPECT_LE(ramp_pixels(1024), 2);
  EXPECT_GE(ramp_pixels(16), 6);
  // The default: the SDK's 1024 from 640 x 480 up, the frame's larger side in a power of two below.
  FrameSettings f;
  EXPECT_EQ(water_texture_side(f), 1024) << f.width << "x" << f.height;
  f.width = 640, f.height = 480;
  EXPECT_EQ(water_texture_side(f), 1024);
  f.width = 160, f.height = 90;
  EXPECT_EQ(water_texture_side(f), 256);
  f.width = 90, f.height = 300;
  EXPECT_EQ(water_texture_side(f), 512);
  f.water_texture_size = 100;
  EXPECT_EQ(water_texture_side(f), 100);

  for (const int side : {-1, rasterizer::kMaxTargetSize + 1}) {
    FrameSettings f = settings();
    f.water_texture_size = side;
    try {
      Renderer r(s, f);
      FAIL() << "water texture size " << side << " was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("water texture size"), std::string::npos) << e.what();
    }
  }
}

TEST(Water, RejectsWaterItCannotDraw) {
  WaterLook look;
  scenes::Scene no_normal = water_scene(look, {0, 0, 0}, {0, 0, 0});
  no_normal.materials[0].water_normal.texture = -1;
  try {
    Renderer r(no_normal, settings());
    FAIL() << "water without a normal map was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("normal map"), std::string::npos) << e.what();
  }
  scenes::Scene tilted = water_scene(look, {0, 0, 0}, {0, 0, 0});
  tilted.meshes[0].positions[2].z = 5.0f;
  try {
    Renderer r(tilted, settings());
    FAIL() << "a tilted water mesh was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("not horizontal"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace luxel::frame
