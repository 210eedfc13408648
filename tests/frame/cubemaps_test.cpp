// Cube maps rendered by the frame (frame/cubemaps.hpp): the face layout against the world and
// against the rasterizer's cube sampling, the exposure merge against a float render of the same
// faces (its error in stops), the baked cube read by LightmappedGeneric, determinism.

#include "frame/frame_support.hpp"

#include "luxel/frame/cubemaps.hpp"
#include "luxel/frame/exposure_merge.hpp"
#include "luxel/frame/textures.hpp"
#include "luxel/rasterizer/srgb.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace luxel::frame {
namespace {

using rasterizer::CubeFace;

/// Inside the box [-100, 100]^3, unlit, each vertex colored by its position: a texel seeing world
/// direction d shows the color of the point where d meets the box, (p / 200 + 0.5), whatever the
/// wall. The box's faces are made of 2x2 quads so that colors interpolate linearly in world space.
scenes::Scene color_box() {
  scenes::Scene s;
  s.name = "color box";
  scenes::Material m;
  m.name = "unlit";
  m.family = scenes::ShaderFamily::unlit_generic;
  m.double_sided = true;
  s.materials.push_back(m);
  scenes::Mesh mesh;
  mesh.name = "box";
  mesh.material = 0;
  std::vector<uint32_t> indices;
  for (int axis = 0; axis < 3; ++axis)
    for (float sign : {-1.0f, 1.0f}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const auto base = uint32_t(mesh.positions.size());
      for (float a : {-1.0f, 1.0f})
        for (float b : {-1.0f, 1.0f}) {
          glm::vec3 p(0.0f);
          p[axis] = 100.0f * sign, p[u] = 100.0f * a, p[v] = 100.0f * b;
          mesh.positions.push_back(p);
          glm::vec3 n(0.0f);
          n[axis] = -sign;
          mesh.normals.push_back(n);
          mesh.colors.push_back(glm::vec4(p / 200.0f + 0.5f, 1.0f));
        }
      for (uint32_t i : {0u, 1u, 3u, 0u, 3u, 2u}) indices.push_back(base + i);
    }
  mesh.indices = indices;
  s.meshes.push_back(mesh);
  scenes::Camera c;
  s.cameras.push_back(c);
  return s;
}

/// The color the box shows in direction d from its center.
glm::vec3 box_color(glm::vec3 d) {
  const glm::vec3 p = d * (100.0f / glm::max(glm::max(std::abs(d.x), std::abs(d.y)), std::abs(d.z)));
  return p / 200.0f + 0.5f;
}

TEST(Cubemaps, EveryFaceTexelSeesItsWorldDirection) {
  const scenes::Scene scene = color_box();
  rasterizer::Context ctx(2);
  constexpr int n = 8;
  for (int f = 0; f < 6; ++f) {
    const std::vector<glm::vec4> floats = capture_face_float(scene, glm::vec3(0.0f), CubeFace(f), n, shading::ShaderModel::ps_3_0, ctx);
    const rasterizer::Image bytes = capture_face(scene, glm::vec3(0.0f), CubeFace(f), n, 1.0f, shading::ShaderModel::ps_3_0, ctx);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const glm::vec3 want = box_color(rasterizer::cube_direction(CubeFace(f), (x + 0.5f) / n, (y + 0.5f) / n));
        const glm::vec4 got = floats[size_t(y) * n + x];
        for (int c = 0; c < 3; ++c) {
          ASSERT_NEAR(got[c], want[c], 1e-3) << "face " << f << " texel " << x << "," << y << " channel " << c;
          ASSERT_NEAR(rasterizer::kSrgbToLinear[bytes.pixel(x, y)[c]], want[c], 0.01)
              << "8-bit face " << f << " texel " << x << "," << y << " channel " << c;
        }
      }
  }
}

TEST(Cubemaps, TheShadersCubeSamplingReadsWhatTheCaptureSaw) {
  const scenes::Scene scene = color_box();
  rasterizer::Context ctx(2);
  constexpr int n = 16;
  std::vector<scenes::PixelImage> faces;
  for (int f = 0; f < 6; ++f) {
    scenes::PixelImage face;
    face.width = face.height = n;
    for (const glm::vec4& t : capture_face_float(scene, glm::vec3(0.0f), CubeFace(f), n, shading::ShaderModel::ps_3_0, ctx))
      face.rgba32f.insert(face.rgba32f.end(), {t.r, t.g, t.b, t.a});
    faces.push_back(face);
  }
  scenes::Texture cube = cubemap_texture("box", faces);
  cube.mipmaps = false;
  cube.mag = cube.min = scenes::Filter::nearest;
  const GpuTexture gpu = upload(cube);
  // Directions into every face, off its center and off its diagonals (a transposed or mirrored
  // face reads another texel's color).
  for (glm::vec3 d : {glm::vec3(1, 0.3f, -0.6f), glm::vec3(-1, -0.7f, 0.2f), glm::vec3(0.4f, 1, 0.75f),
                      glm::vec3(-0.8f, -1, -0.3f), glm::vec3(0.6f, -0.25f, 1), glm::vec3(-0.2f, 0.7f, -1)}) {
    const glm::vec4 got = rasterizer::sample_reference(gpu.texture, gpu.sampler, d, 0.0f);
    const glm::vec3 want = box_color(d);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1.0f / n) << "direction " << d.x << "," << d.y << "," << d.z;
  }
}

/// |log2(merged / float)| over the channels the bracket can see, and the range they span.
struct StopError {
  double max = 0, p99 = 0, range = 0;
  size_t count = 0;
};

StopError stop_error(const std::vector<std::vector<glm::vec4>>& merged, const std::vector<std::vector<glm::vec4>>& reference,
                     float floor) {
  std::vector<double> errors;
  double lo = INFINITY, hi = 0;
  for (size_t f = 0; f < merged.size(); ++f)
    for (size_t i = 0; i < merged[f].size(); ++i)
      for (int c = 0; c < 3; ++c) {
        const double want = reference[f][i][c], got = merged[f][i][c];
        if (!(want >= floor)) continue;
        errors.push_back(got > 0 ? std::abs(std::log2(got / want)) : INFINITY);
        lo = std::min(lo, want), hi = std::max(hi, want);
      }
  StopError e;
  if (errors.empty()) return e;
  std::sort(errors.begin(), errors.end());
  e.max = errors.back();
  e.p99 = errors[errors.size() * 99 / 100];
  e.range = std::log2(hi / lo);
  e.count = errors.size();
  return e;
}

TEST(Cubemaps, TheMergeMatchesAFloatRenderOfTheSameFaces) {
  const scenes::Scene scene = baked_courtyard();
  rasterizer::Context ctx(2);
  constexpr int n = 16;
  const auto textures = std::make_shared<const SceneTextures>(scene);
  for (float stops : {2.0f, 4.0f}) {
    const std::vector<float> exposures = exposure_bracket(scene, stops);
    ASSERT_GE(exposures.size(), 3u);
    // Every face of every sample of the scene.
    std::vector<std::vector<glm::vec4>> merged, reference, one_exposure, undivided;
    for (const scenes::CubemapSample& sample : scene.cubemap_samples) {
      const glm::vec3 at = sample.position;
      const scenes::Texture cube = bake_cubemap(scene, at, n, exposures, shading::ShaderModel::ps_3_0, ctx, "test", textures);
      for (int f = 0; f < 6; ++f) {
        reference.push_back(capture_face_float(scene, at, CubeFace(f), n, shading::ShaderModel::ps_3_0, ctx, textures));
        std::vector<glm::vec4> m;
        for (size_t i = 0; i < size_t(n) * n; ++i)
          m.emplace_back(cube.faces[size_t(f)].rgba32f[4 * i], cube.faces[size_t(f)].rgba32f[4 * i + 1],
                         cube.faces[size_t(f)].rgba32f[4 * i + 2], 1.0f);
        merged.push_back(m);
        // Wrong merges the bound must catch: the middle exposure alone, and no division by the exposure.
        std::vector<rasterizer::Image> images;
        for (float e : exposures)
          images.push_back(capture_face(scene, at, CubeFace(f), n, e, shading::ShaderModel::ps_3_0, ctx, textures));
        const size_t mid = exposures.size() / 2;
        one_exposure.push_back(merge_exposures(std::span(&images[mid], 1), std::span(&exposures[mid], 1)));
        const std::vector<float> ones(exposures.size(), 1.0f);
        undivided.push_back(merge_exposures(images, ones));
      }
    }
    // Texels some exposure sees above the dark floor.
    const float floor = rasterizer::kSrgbToLinear[kDarkCode + 1] / exposures.back();
    const StopError e = stop_error(merged, reference, floor);
    std::printf("[ measure  ] %.0f stops apart, %zu exposures, %dx%d faces: %zu channels over %.1f stops, "
                "merge error max %.4f, p99 %.4f stops\n",
                stops, exposures.size(), n, n, e.count, e.range, e.max, e.p99);
    EXPECT_GT(e.range, 10.0) << "the courtyard's faces span the sky's sun to shaded walls";
    const double max_bound = stops <= 2.0f ? 0.03 : 0.05, p99_bound = stops <= 2.0f ? 0.02 : 0.035;
    EXPECT_LE(e.max, max_bound);
    EXPECT_LE(e.p99, p99_bound);
    EXPECT_GT(stop_error(one_exposure, reference, floor).max, max_bound) << "one exposure alone must fail the bound";
    EXPECT_GT(stop_error(undivided, reference, floor).p99, p99_bound) << "a merge without the division must fail it";
  }
}

TEST(Cubemaps, ExposuresArePowersOfTwoSpanningTheScenesRange) {
  const scenes::Scene scene = baked_courtyard();
  const std::vector<float> e = exposure_bracket(scene, 2.0f);
  float sky_max = 0;
  for (const auto& face : scene.textures[size_t(scene.sky_texture)].faces)
    for (float v : face.rgba32f) sky_max = std::max(sky_max, v);
  EXPECT_LE(sky_max * e.front(), 0.9f) << "the darkest exposure keeps the sun under the clip";
  EXPECT_GT(sky_max * e.front(), 0.45f) << "and is the brightest power of two that does";
  for (size_t k = 1; k < e.size(); ++k) EXPECT_EQ(e[k], e[k - 1] * 4.0f);
  EXPECT_THROW(exposure_bracket(scene, 0.0f), std::invalid_argument);
}

TEST(Cubemaps, LightmappedGenericReflectsTheBakedCube) {
  scenes::Scene scene = baked_courtyard();
  FrameSettings settings;
  settings.width = 160, settings.height = 90;
  rasterizer::Context ctx(2);
  auto render = [&](const scenes::Scene& s) {
    Renderer r(s, settings);
    r.render(ctx);
    return r.image();
  };
  const rasterizer::Image sky_reflected = render(scene);
  CubemapSettings cube_settings = CubemapSettings::quick();
  cube_settings.face_size = 8;
  std::vector<scenes::Texture> cubes = bake_cubemaps(scene, cube_settings, ctx);
  std::vector<scenes::Texture> black = cubes;
  for (auto& c : black)
    for (auto& f : c.faces) std::fill(f.rgba32f.begin(), f.rgba32f.end(), 0.0f);
  scenes::Scene with_cubes = scene, with_black = scene;
  attach_cubemaps(with_cubes, cubes);
  attach_cubemaps(with_black, black);
  const rasterizer::Image baked = render(with_cubes), unreflected = render(with_black);
  auto differing = [](const rasterizer::Image& a, const rasterizer::Image& b) {
    size_t n = 0;
    for (size_t i = 0; i < a.rgba.size(); i += 4) n += !std::equal(&a.rgba[i], &a.rgba[i + 3], &b.rgba[i]);
    return n;
  };
  const size_t pixels = size_t(settings.width) * settings.height;
  EXPECT_GT(differing(sky_reflected, baked), pixels / 20) << "the floor and walls reflect the baked cube, not the sky";
  EXPECT_GT(differing(baked, unreflected), pixels / 20) << "what they reflect is the cube's content";
  // A capture never reads the samples' cubes: the same faces with and without them attached.
  const glm::vec3 at = scene.cubemap_samples[1].position;
  EXPECT_EQ(capture_face(scene, at, CubeFace::NegativeZ, 8, 1.0f, shading::ShaderModel::ps_3_0, ctx).rgba,
            capture_face(with_cubes, at, CubeFace::NegativeZ, 8, 1.0f, shading::ShaderModel::ps_3_0, ctx).rgba);
}

TEST(Cubemaps, OneAndTwoThreadsBakeTheSameBytes) {
  const scenes::Scene scene = baked_courtyard();
  CubemapSettings s = CubemapSettings::quick();
  s.face_size = 8;
  rasterizer::Context one(1), two(2);
  const std::vector<scenes::Texture> a = bake_cubemaps(scene, s, one), b = bake_cubemaps(scene, s, two);
  ASSERT_EQ(a.size(), scene.cubemap_samples.size());
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t f = 0; f < 6; ++f) EXPECT_EQ(a[i].faces[f].rgba32f, b[i].faces[f].rgba32f) << "cube " << i << " face " << f;
}

TEST(Cubemaps, BadInputIsOneLine) {
  scenes::Scene scene = baked_courtyard();
  rasterizer::Context ctx(1);
  scene.cubemap_samples[0].size = 0;
  EXPECT_THROW(bake_cubemaps(scene, CubemapSettings{}, ctx), std::invalid_argument);
  EXPECT_THROW(attach_cubemaps(scene, {}), std::invalid_argument);
  const std::vector<rasterizer::Image> images(2, rasterizer::Image(2, 2));
  const float exposures[2] = {1.0f, -1.0f};
  EXPECT_THROW(merge_exposures(images, exposures), std::invalid_argument);
  FrameSettings msaa;
  msaa.cubemap_capture = true;
  msaa.width = msaa.height = 8;
  const scenes::Scene box = color_box();
  Renderer r(box, msaa);
  EXPECT_THROW(r.render_float(ctx), std::invalid_argument);
}

}  // namespace
}  // namespace luxel::frame
