// vbsp's env-map assignment for world surfaces (luxel/frame/world_envmaps.hpp,
// docs/fidelity.md#world-env-maps-vbsp): the nearest sample in front of a face group's plane from
// the mean of its vertices, else the nearest overall, ties to the lower index; no samples, no env
// map. Each case is built so that the rule it checks picks another sample than the rules it
// replaces (the nearest overall, the bounding-box centre, a strict plane test, the sky); in the
// frame, the pixels each face group draws are the colour of its sample's cube as the test computes
// it (the env map's scale, tint and the sRGB write, from docs/fidelity.md#lightmappedgeneric).

#include "frame/frame_support.hpp"

#include "luxel/frame/renderer.hpp"
#include "luxel/frame/world_envmaps.hpp"

#include <glm/gtc/packing.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <array>
#include <string>
#include <vector>

namespace luxel::frame {
namespace {

std::vector<scenes::CubemapSample> samples_at(std::initializer_list<glm::vec3> positions) {
  std::vector<scenes::CubemapSample> s;
  for (const glm::vec3& p : positions) s.push_back(scenes::CubemapSample{p, 16, -1});
  return s;
}

TEST(WorldEnvmaps, TheNearestSampleInFrontOfThePlaneWinsOverANearerOneBehind) {
  const auto samples = samples_at({{0, 0, -1}, {0, 0, 5}});  // 1 behind, 5 in front
  EXPECT_EQ(envmap_sample_for(glm::vec3(0.0f), glm::vec3(0, 0, 1), samples), 1);
  EXPECT_EQ(envmap_sample_for(glm::vec3(0.0f), glm::vec3(0, 0, -1), samples), 0);
}

TEST(WorldEnvmaps, NoSampleInFrontTakesTheNearestOverall) {
  const auto samples = samples_at({{0, 0, -5}, {0, 0, -2}, {0, 3, -4}});
  EXPECT_EQ(envmap_sample_for(glm::vec3(0.0f), glm::vec3(0, 0, 1), samples), 1);
}

TEST(WorldEnvmaps, ASampleInThePlaneIsInFrontAndTiesGoToTheLowerIndex) {
  // dot(normalize(sample - centre), normal) >= 0: the sample in the plane (dot 0) counts.
  EXPECT_EQ(envmap_sample_for(glm::vec3(0.0f), glm::vec3(0, 0, 1), samples_at({{0, 0, 4}, {1, 0, 0}})), 1);
  // A sample at the centre itself: the zero vector, in front.
  EXPECT_EQ(envmap_sample_for(glm::vec3(2.0f), glm::vec3(0, 0, 1), samples_at({{2, 2, 3}, {2, 2, 2}})), 1);
  // Equal distances: the lower index, whichever order the positions come in.
  EXPECT_EQ(envmap_sample_for(glm::vec3(0.0f), glm::vec3(0, 0, 1), samples_at({{3, 0, 4}, {0, 3, 4}, {0, 0, 9}})), 0);
  EXPECT_EQ(envmap_sample_for(glm::vec3(0.0f), glm::vec3(0, 0, 1), samples_at({{0, 0, 9}, {0, 3, 4}, {3, 0, 4}})), 1);
  EXPECT_EQ(envmap_sample_for(glm::vec3(0.0f), glm::vec3(0, 0, 1), {}), -1);
}

/// A floor at z = 0 facing up whose vertices crowd at x in [0, 1] with one reaching x = 10 (vertex
/// mean x 2.4, bounding-box centre x 5), and a wall at x = -1 facing -x behind every sample.
scenes::Mesh floor_and_wall() {
  scenes::Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {10, 0, 0},  // floor
                 {-1, 0, 0}, {-1, 0, 2}, {-1, 2, 0}};                     // wall
  m.indices = std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 1, 4, 2, 5, 6, 7};
  return m;
}

TEST(WorldEnvmaps, FaceGroupsTakeTheirPlanesVertexMeanAndTheFallback) {
  // Sample 0 is 3 above the floor's vertex mean (2.4, 0.4), sample 1 2.9 above its bounding-box
  // centre (5, 0.5): from the vertex mean 0 is nearer (the box centre would pick 1). Sample 2,
  // below the floor, is nearer still (2.98): the plane test leaves it out (the nearest overall
  // would pick it).
  const auto samples = samples_at({{2.4f, 0.4f, 3.0f}, {5.0f, 0.5f, 2.9f}, {-0.5f, 0.7f, -0.6f}});
  const std::vector<EnvmapFaceGroup> groups = envmap_face_groups(floor_and_wall(), samples);
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0].sample, 0);
  EXPECT_EQ(groups[0].indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 1, 4, 2}));
  // The wall (normal -x, vertex mean (-1, 0.67, 0.67)): every sample is behind it, so the nearest
  // overall, sample 2.
  EXPECT_EQ(groups[1].sample, 2);
  EXPECT_EQ(groups[1].indices, (std::vector<uint32_t>{5, 6, 7}));
  EXPECT_TRUE(envmap_face_groups(floor_and_wall(), {}).empty()) << "no samples: no env map";
}

TEST(WorldEnvmaps, EveryTriangleLandsInExactlyOneGroup) {
  scenes::Mesh m = floor_and_wall();
  m.positions.push_back({3, 3, 3});
  std::get<std::vector<uint32_t>>(m.indices).insert(std::get<std::vector<uint32_t>>(m.indices).end(), {8, 8, 8});  // degenerate
  const auto groups = envmap_face_groups(m, samples_at({{0, 0, 5}, {3, 3, 4}, {-3, 0, 0}}));
  std::vector<uint32_t> all;
  for (const EnvmapFaceGroup& g : groups) {
    EXPECT_EQ(g.indices.size() % 3, 0u);
    all.insert(all.end(), g.indices.begin(), g.indices.end());
  }
  EXPECT_EQ(all.size(), std::get<std::vector<uint32_t>>(m.indices).size());
  // The degenerate triangle goes with the sample nearest it (1).
  const auto with_it = std::find_if(groups.begin(), groups.end(), [](const EnvmapFaceGroup& g) {
    return std::find(g.indices.begin(), g.indices.end(), 8u) != g.indices.end();
  });
  ASSERT_NE(with_it, groups.end());
  EXPECT_EQ(with_it->sample, 1);
}

TEST(WorldEnvmaps, WorldWithoutSamplesDrawsNoEnvMap) {
  // The engine drops a LightmappedGeneric `env_cubemap` that vbsp could not assign: with the
  // samples removed, the courtyard's paving and bricks draw as if they had no env map.
  scenes::Scene without_samples = *builtin_scene("courtyard", 160, 90);
  without_samples.cubemap_samples.clear();
  scenes::Scene without_envmaps = without_samples;
  int world_envmaps = 0;
  for (scenes::Material& m : without_envmaps.materials)
    if (m.family == scenes::ShaderFamily::lightmapped_generic && m.envmap != scenes::EnvmapSource::none) {
      m.envmap = scenes::EnvmapSource::none;
      ++world_envmaps;
    }
  ASSERT_GE(world_envmaps, 2);
  FrameSettings f{160, 90, 4};
  f.color_correction = false;
  EXPECT_TRUE(render_frame(without_samples, f).rgba == render_frame(without_envmaps, f).rgba);
}

/// A cube map of one linear colour on every face.
scenes::Texture uniform_cube(const glm::vec3& c) {
  scenes::Texture t;
  t.name = "cube";
  t.shape = scenes::TextureShape::cube;
  t.color_space = scenes::ColorSpace::linear;
  t.mipmaps = false;
  scenes::PixelImage face;
  face.width = face.height = 2;
  for (int i = 0; i < 4; ++i) face.rgba32f.insert(face.rgba32f.end(), {c.r, c.g, c.b, 1.0f});
  t.faces.assign(6, face);
  return t;
}

const glm::vec3 kRed(0.4f, 0.1f, 0.0f), kGreen(0.1f, 0.4f, 0.05f);

/// Looking down at one LightmappedGeneric mesh of black albedo (only its env map shows), drawn
/// from both sides, in two face groups: the left half faces up (+Z), the right half down (-Z).
/// Sample 0 (red) lies below the surface near its centre, sample 1 (green) high above: the left
/// half has only green in front of it, the right half both, red the nearer. The mesh's centre
/// is nearest red.
scenes::Scene two_faced_floor(bool with_samples) {
  scenes::Scene s = top_down();
  const glm::vec3 zero(0.0f), basis[3] = {zero, zero, zero};
  attach_lightmaps(s, zero, basis);
  s.textures.push_back(uniform_cube(kRed));
  s.textures.push_back(uniform_cube(kGreen));
  if (with_samples) {
    s.cubemap_samples.push_back(scenes::CubemapSample{{0.0f, 0.0f, -0.5f}, 16, int(s.textures.size()) - 2});
    s.cubemap_samples.push_back(scenes::CubemapSample{{0.0f, 0.0f, 3.0f}, 16, int(s.textures.size()) - 1});
  }
  scenes::Material m;
  m.family = scenes::ShaderFamily::lightmapped_generic;
  m.color = {0.0f, 0.0f, 0.0f, 1.0f};
  m.envmap = scenes::EnvmapSource::nearest_sample;
  m.double_sided = true;
  s.materials = {m};
  scenes::Mesh left = square(-1, -1, 0, 1, 0, 0), right = square(0, -1, 1, 1, 0, 0, true);
  right.normals.assign(4, {0.0f, 0.0f, -1.0f});
  scenes::Mesh mesh = left;
  auto& indices = std::get<std::vector<uint16_t>>(mesh.indices);
  for (uint16_t i : std::get<std::vector<uint16_t>>(right.indices)) indices.push_back(uint16_t(i + 4));
  mesh.positions.insert(mesh.positions.end(), right.positions.begin(), right.positions.end());
  mesh.normals.insert(mesh.normals.end(), right.normals.begin(), right.normals.end());
  mesh.uv0.insert(mesh.uv0.end(), right.uv0.begin(), right.uv0.end());
  mesh.uv1 = mesh.uv0;
  s.meshes = {mesh};
  return s;
}

/// The 8-bit value the frame writes for linear colour `c` reflected at scale 1: the cube's
/// half-float texel (RGBA16F upload) x ENV_MAP_SCALE 1 x $envmaptint 1, the LINEAR tone map at
/// exposure 1, the sRGB write.
std::array<double, 3> reflected(const glm::vec3& c) {
  std::array<double, 3> out{};
  for (int k = 0; k < 3; ++k) out[size_t(k)] = 255.0 * srgb_encode(double(glm::unpackHalf1x16(glm::packHalf1x16(c[k]))));
  return out;
}

TEST(WorldEnvmaps, EachFaceGroupOfAMeshReflectsItsOwnSampleInTheFrame) {
  FrameSettings f{64, 64, 4};
  f.exposure = 1.0f;
  f.color_correction = false;
  for (shading::ShaderModel card : {shading::ShaderModel::ps_2_0, shading::ShaderModel::ps_3_0}) {
    SCOPED_TRACE(std::string(shading::caps(card).name));
    f.model = card;
    const rasterizer::Image image = render_frame(two_faced_floor(true), f);
    // Two columns either side of the seam are left out (MSAA mixes the groups there).
    EXPECT_EQ(channels_off(image, 0, 30, reflected(kGreen)), 0) << "the left half faces only green";
    EXPECT_EQ(channels_off(image, 34, 64, reflected(kRed)), 0) << "the right half faces both, red nearer";
    const rasterizer::Image none = render_frame(two_faced_floor(false), f);
    EXPECT_EQ(channels_off(none, 0, 64, {0.0, 0.0, 0.0}), 0) << "no samples: no env map, black albedo";
  }
}

TEST(WorldEnvmaps, TheMaterialsEnvMapConstantsReachTheShader) {
  // $envmaptint, $envmapcontrast, $envmapsaturation and $fresnelreflection on the left half (green
  // reflected, normal +Z): LightmappedGeneric's full env-map path (lightmappedgeneric_ps2_3_x.h),
  // written out here: s = cube x tint; s = lerp(s, s^2, contrast); s = lerp(grey(s), s, saturation)
  // with grey the (0.299, 0.587, 0.114) dot; times (1 - N.V)^5 (1 - R0) + R0. Each value changes
  // the answer: tint per channel, contrast by the square, saturation toward grey, R0 as a scale.
  const glm::vec3 tint(0.5f, 1.0f, 0.25f);
  const double contrast = 0.5, saturation = 0.3, r0 = 0.2;
  scenes::Scene s = two_faced_floor(true);
  s.materials[0].envmap_tint = tint;
  s.materials[0].envmap_contrast = float(contrast);
  s.materials[0].envmap_saturation = float(saturation);
  s.materials[0].fresnel_reflection = float(r0);
  FrameSettings f{64, 64, 4};
  f.exposure = 1.0f;
  f.color_correction = false;
  const glm::dvec3 eye(0.0, 0.0, 10.0);  // top_down()'s camera
  for (shading::ShaderModel card : {shading::ShaderModel::ps_2_0, shading::ShaderModel::ps_3_0}) {
    SCOPED_TRACE(std::string(shading::caps(card).name));
    f.model = card;
    const rasterizer::Image image = render_frame(s, f);
    int checked = 0, off = 0;
    for (int py = 2; py < 62; py += 3)
      for (int px = 1; px < 30; px += 3) {
        const glm::dvec3 world(-1.0 + (px + 0.5) / 32.0, 1.0 - (py + 0.5) / 32.0, 0.0);
        double spec[3];
        for (int k = 0; k < 3; ++k) {
          const double c = double(glm::unpackHalf1x16(glm::packHalf1x16(kGreen[k]))) * tint[k];
          spec[k] = c + (c * c - c) * contrast;
        }
        const double grey = 0.299 * spec[0] + 0.587 * spec[1] + 0.114 * spec[2];
        const double n_dot_v = glm::normalize(eye - world).z;
        const double fresnel = std::pow(1.0 - n_dot_v, 5.0) * (1.0 - r0) + r0;
        for (int k = 0; k < 3; ++k) {
          const double want = 255.0 * srgb_encode((grey + (spec[k] - grey) * saturation) * fresnel);
          const int got = image.pixel(px, py)[k];
          if (std::abs(got - want) > 1.0) {
            ++off;
            ADD_FAILURE() << "pixel (" << px << ", " << py << ") channel " << k << ": " << got << ", want " << want;
          }
        }
        ++checked;
        if (off > 5) break;
      }
    EXPECT_GT(checked, 150);
  }
}

}  // namespace
}  // namespace luxel::frame
